//! Small programs showing the main uses of the traction crates. Run one with
//! `cargo run -p traction-examples --example NAME`:
//!
//! - `hertz_contact`: the Hertz contact of two bodies from their radii and the load
//!   (traction-hertz);
//! - `traction_curve_with_spin`: a traction-versus-slip curve of a spinning
//!   contact (traction-contact);
//! - `contact_time_loop`: a contact stepped through a start-up in a time loop, as a
//!   drivetrain model would call it (traction-contact);
//! - `fmu_import PATH.fmu`: the co-simulation FMU (built by `traction fmu build`)
//!   loaded and stepped from Rust with the `fmi` crate.
//!
//! Each example checks what it prints and exits non-zero if a check fails;
//! `scripts/test.sh` runs them all.
#![forbid(unsafe_code)]
