//! traction-hertz (work in progress).
#![forbid(unsafe_code)]
