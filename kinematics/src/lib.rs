//! traction-kinematics (work in progress).
#![forbid(unsafe_code)]
