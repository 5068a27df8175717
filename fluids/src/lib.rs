//! traction-fluids (work in progress).
#![forbid(unsafe_code)]
