//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml, the
//! binaries (`binaries/linux64/<modelIdentifier>.so`,
//! `binaries/win64/<modelIdentifier>.dll`) and `documentation/index.html`
//! (traction-fmi-support's `package` writes the archive).

use std::path::Path;

use traction_fmi_support::package::{DocumentationRow, write_fmu as write_archive};
pub use traction_fmi_support::package::{PackageError, Platform};

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Kind, REAL_TYPES, VARIABLES};

/// The name of this crate's library: cargo makes
/// [`Platform::cargo_library_name`] of it (`libtraction_fmu.so`,
/// `traction_fmu.dll`).
pub const LIBRARY_NAME: &str = "traction_fmu";

/// documentation/index.html: the variable table for humans.
pub fn documentation_html() -> String {
    let rows = VARIABLES.iter().map(|v| {
        let (unit, start) = match v.kind {
            Kind::Real {
                declared, start, ..
            } => (
                REAL_TYPES
                    .iter()
                    .find(|t| t.0 == declared)
                    .map_or("1", |t| t.2),
                start.map(|s| format!("{s}")).unwrap_or_default(),
            ),
            Kind::Enumeration { start, .. } => {
                ("", start.map(|s| s.to_string()).unwrap_or_default())
            }
            Kind::Boolean { start } => ("", start.map(|s| s.to_string()).unwrap_or_default()),
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
        "Lubricated rolling traction contact between two rotating bodies, after the NASA traction report \
         (Hertz contact, Johnson &amp; Tevaarwerk elastic/plastic traction). Connect the angular speeds of the \
         two bodies to <code>omega1</code>, <code>omega2</code> and feed <code>torque1</code>, <code>torque2</code> \
         back to their inertias. Fluids: Santotrac 50 and TDF-88 through the report's correlations, or user m and &mu;.",
        rows,
    )
}

/// Writes the `.fmu` at `out` with the linux64 binary only, from the
/// compiled cdylib at `library`.
///
/// # Errors
/// Unreadable library, unwritable archive.
pub fn write_fmu(library: &Path, out: &Path) -> Result<(), PackageError> {
    write_fmu_for(&[(Platform::Linux64, library)], out)
}

/// Writes the `.fmu` at `out` with one compiled cdylib per platform.
///
/// # Errors
/// Unreadable library, unwritable archive.
pub fn write_fmu_for(binaries: &[(Platform, &Path)], out: &Path) -> Result<(), PackageError> {
    let xml = model_description_xml()?;
    write_archive(out, MODEL_IDENTIFIER, &xml, binaries, &documentation_html())
}
