//! traction-fmu: the FMI 2.0 co-simulation FMU of the lubricated rolling
//! traction contact.
//!
//! Drivetrain simulators load `TractionContact.fmu` and connect two rotating
//! bodies through it: inputs are the normal load and the bodies' angular
//! speeds (plus side slip, spin, inlet temperature); outputs are the traction
//! forces, the torques on each body, the spin moment, losses, the Hertz
//! contact size and pressure and the report's dimensionless groups J1..J7.
//!
//! Layers (one way):
//! * [`physics`] — the only seam to the contact physics: it translates the
//!   FMU's parameters and inputs for `traction-contact` (Hertz, fluid
//!   correlations, compliance, J+T rheology with slip, side slip and spin).
//! * [`variables`] — the variable table: names, value references, units,
//!   causality, variability, start values, dependencies.
//! * [`model_description`] — modelDescription.xml generated from the table.
//! * [`model`] — one safe trait [`model::CoSimulation`] and the instance
//!   [`model::TractionFmu`] with the FMI 2 state machine and FMU states.
//! * [`ffi`] — the 34 exported `fmi2*` functions: pointer checks,
//!   `catch_unwind`, logging through the host. The only module with `unsafe`.
//! * [`package`] — the `.fmu` zip archive.
//!
//! The FMI 2 C types, the guards of the C boundary, the XML document around
//! the variable table and the archive writer are traction-fmi-support's,
//! shared with the variator FMU (docs/decisions/0093).
//!
//! ```
//! use traction_fmu::model::{CoSimulation, NullLogger, TractionFmu};
//! use traction_fmu::variables::vr;
//! let guid = traction_fmu::model_description::guid();
//! let mut fmu = TractionFmu::instantiate("demo", &guid).unwrap();
//! fmu.set_real(&[vr::OMEGA1, vr::OMEGA2], &[600.0, 270.0]).unwrap();
//! fmu.enter_initialization_mode().unwrap();
//! fmu.exit_initialization_mode(&mut NullLogger).unwrap();
//! fmu.do_step(0.0, 1e-3, &mut NullLogger).unwrap();
//! let mut fx = [0.0];
//! fmu.get_real(&[vr::FX], &mut fx, &mut NullLogger).unwrap();
//! assert!(fx[0] > 0.0); // body 1 is faster and drives body 2
//! ```
#![deny(unsafe_code)]

pub mod ffi;
pub mod model;
pub mod model_description;
pub mod package;
pub mod physics;
pub mod variables;
