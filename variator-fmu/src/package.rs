//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml,
//! `binaries/linux64/ToroidalVariator.so` and `documentation/index.html`
//! (traction-fmi-support's `package` writes the archive).

use std::path::Path;

pub use traction_fmi_support::package::PackageError;
use traction_fmi_support::package::{
    DOCUMENTATION_TAIL, Platform, documentation_head, documentation_row, write_fmu as write_archive,
};

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Kind, VARIABLES};

/// documentation/index.html: the variable table for humans.
pub fn documentation_html() -> String {
    let mut h = documentation_head(
        MODEL_IDENTIFIER,
        "Toroidal CVT variator between an input and an output shaft: n power rollers, each with two lubricated \
         traction contacts (Hertz contact, Johnson &amp; Tevaarwerk elastic/plastic traction with spin, after the NASA \
         traction report); the roller speed follows from its torque balance. Connect the shaft speeds to \
         <code>omega_in</code>, <code>omega_out</code> and feed <code>torque_in</code>, <code>torque_out</code> back to \
         their inertias; <code>tilt_angle</code> sets the ratio, <code>end_load</code> the clamping.",
    );
    for v in VARIABLES {
        let (unit, start) = match v.kind {
            Kind::Real { unit, start } => (unit, start.map(|s| format!("{s}")).unwrap_or_default()),
            Kind::Integer { start, .. } => ("", start.to_string()),
            Kind::Enumeration { start, .. } => {
                ("", start.map(|s| s.to_string()).unwrap_or_default())
            }
            Kind::Boolean { start } => ("", start.to_string()),
        };
        h.push_str(&documentation_row(
            v.name,
            v.causality.as_str(),
            unit,
            &start,
            v.description,
        ));
    }
    h.push_str(DOCUMENTATION_TAIL);
    h
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
