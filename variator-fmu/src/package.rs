//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml,
//! `binaries/linux64/ToroidalVariator.so` and `documentation/index.html`
//! (traction-fmi-support's `package` writes the archive).

use std::path::Path;

pub use traction_fmi_support::package::PackageError;
use traction_fmi_support::package::{DocumentationRow, Platform, write_fmu as write_archive};

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Kind, VARIABLES};

/// The name of this crate's library: cargo makes `libtraction_variator_fmu.so`.
pub const LIBRARY_NAME: &str = "traction_variator_fmu";

/// documentation/index.html: the variable table for humans.
pub fn documentation_html() -> String {
    let rows = VARIABLES.iter().map(|v| {
        let (unit, start) = match v.kind {
            Kind::Real { unit, start } => (unit, start.map(|s| format!("{s}")).unwrap_or_default()),
            Kind::Integer { start, .. } => ("", start.to_string()),
            Kind::Enumeration { start, .. } => {
                ("", start.map(|s| s.to_string()).unwrap_or_default())
            }
            Kind::Boolean { start } => ("", start.to_string()),
        };
        DocumentationRow {
            name: v.name,
            causality: v.causality,
            unit,
            start,
            description: v.description,
        }
    });
    traction_fmi_support::package::documentation_html(
        MODEL_IDENTIFIER,
        "Toroidal CVT variator between an input and an output shaft: n power rollers, each with two lubricated \
         traction contacts (Hertz contact, Johnson &amp; Tevaarwerk elastic/plastic traction with spin, after the NASA \
         traction report); the roller speed follows from its torque balance. Connect the shaft speeds to \
         <code>omega_in</code>, <code>omega_out</code> and feed <code>torque_in</code>, <code>torque_out</code> back to \
         their inertias; <code>tilt_angle</code> sets the ratio, <code>end_load</code> the clamping.",
        rows,
    )
}

/// Writes the `.fmu` at `out` from the compiled linux64 cdylib at `library`.
///
/// # Errors
/// Unreadable library, unwritable archive.
pub fn write_fmu(library: &Path, out: &Path) -> Result<(), PackageError> {
    let xml = model_description_xml()?;
    write_archive(
        out,
        MODEL_IDENTIFIER,
        &xml,
        &[(Platform::Linux64, library)],
        &documentation_html(),
    )
}
