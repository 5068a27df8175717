//! traction-regression (work in progress).
#![forbid(unsafe_code)]
