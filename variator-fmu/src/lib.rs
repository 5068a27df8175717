//! traction-variator-fmu: the FMI 2.0 co-simulation FMU of the toroidal CVT
//! variator (`ToroidalVariator.fmu`).
//!
//! A drivetrain simulator drops the variator between an engine and a
//! vehicle: inputs are the two disc speeds `omega_in`, `omega_out` (rad/s,
//! each positive in its own sense of rotation), the roller tilt
//! `tilt_angle` (rad), the clamping `end_load` (N) and the
//! `inlet_temperature` (°C); outputs are the torques on both discs
//! (`torque_in`, `torque_out`, N·m, positive in the sense of each disc's
//! omega), the kinematic `speed_ratio`, `power_loss`, `efficiency`, the
//! `roller_side_force` the ratio controller reacts, and per contact
//! (`_in`: input disc–roller, `_out`: roller–output disc) the normal load,
//! slip, spin, traction coefficient, losses, pressure and regime. The
//! physics is `traction-variator` (rollers solved from their torque balance,
//! contacts by `traction-contact`); this crate adds no physics.
//!
//! Layers (one way): [`variables`] (the table) → [`model_description`]
//! (XML from the table) → [`model`] (safe instance, FMI state machine, FMU
//! states) → [`ffi`] (the only `unsafe`: the exported `fmi2*` functions) and
//! [`package`] (the `.fmu` zip). The FMI 2 C types and guards, the XML
//! document around the table and the archive writer are
//! traction-fmi-support's, shared with traction-fmu (docs/decisions/0093).
//!
//! ```
//! use traction_variator_fmu::model::{NullLogger, VariatorFmu};
//! use traction_variator_fmu::variables::vr;
//! let mut fmu = VariatorFmu::instantiate(&traction_variator_fmu::model_description::guid()).unwrap();
//! fmu.set_real(&[vr::OMEGA_IN, vr::OMEGA_OUT], &[300.0, 295.0]).unwrap();
//! fmu.enter_initialization_mode().unwrap();
//! fmu.exit_initialization_mode(&mut NullLogger).unwrap();
//! fmu.do_step(0.0, 1e-3, &mut NullLogger).unwrap();
//! let mut t = [0.0; 2];
//! fmu.get_real(&[vr::TORQUE_IN, vr::TORQUE_OUT], &mut t, &mut NullLogger).unwrap();
//! assert!(t[0] < 0.0 && t[1] > 0.0); // the input drives the output
//! ```
#![deny(unsafe_code)]

pub mod ffi;
pub mod model;
pub mod model_description;
pub mod package;
pub mod variables;
