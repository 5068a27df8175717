//! traction-fmi-support: the FMI 2.0 co-simulation scaffolding shared by the
//! workspace's two FMUs, `TractionContact.fmu` (traction-fmu) and
//! `ToroidalVariator.fmu` (traction-variator-fmu).
//!
//! It holds what is the same in both by meaning, not only by shape:
//! * [`status`] — the safe side's call result: [`Status`] (mirroring
//!   `fmi2Status`), [`FmuError`], [`FmuResult`] and the [`Logger`] an
//!   instance sends warnings to; the FMI 2 co-simulation states [`Mode`]
//!   with the check of which calls each allows.
//! * [`ffi`] — the hand-written FMI 2 C types and constants and the guards
//!   every exported function uses: pointer-to-slice and string checks, the
//!   tagged boxes behind `fmi2Component` and `fmi2FMUstate`, `catch_unwind`
//!   with the panic's message, and the host's logging callback (`%` escaped).
//!   The only module with `unsafe`.
//! * [`xml`] — the pieces of modelDescription.xml that do not depend on a
//!   model's variables: the root element, `<CoSimulation>` capabilities,
//!   units, enumeration types, log categories, default experiment, the
//!   `<ModelStructure>` sections, the GUID (FNV-1a 128 of the XML).
//! * [`package`] — the `.fmu` zip: layout, `binaries/<platform>/`, the
//!   documentation page.
//!
//! It exports no C symbols: each FMU crate keeps its own `fmi2*` functions,
//! its variable table, its state machine and its messages, and calls these
//! pieces. Both FMU crates link it, and the CLI links both FMU crates.
//!
//! ```
//! use traction_fmi_support::xml::{fnv1a_128, guid_of};
//! assert_eq!(fnv1a_128(b"a"), 0xd228cb696f1a8caf78912b704e4a8964);
//! assert_eq!(guid_of(b"").len(), 38); // {8-4-4-4-12}
//! ```
#![deny(unsafe_code)]

pub mod ffi;
pub mod package;
pub mod status;
pub mod xml;

pub use status::{FmuError, FmuResult, Logger, Mode, NullLogger, Status};
