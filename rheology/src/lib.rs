//! traction-rheology (work in progress).
#![forbid(unsafe_code)]
