//! traction-compliance (work in progress).
#![forbid(unsafe_code)]
