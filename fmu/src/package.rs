//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml,
//! `binaries/linux64/<modelIdentifier>.so` and `documentation/index.html`.

use std::io::Write;
use std::path::Path;

use zip::write::SimpleFileOptions;

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Causality, Kind, REAL_TYPES, VARIABLES};

/// Why packaging failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PackageError {
    /// Reading the library or writing the archive failed.
    #[error("{context}: {source}")]
    Io {
        /// What was being read or written.
        context: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The zip writer failed.
    #[error("writing {path}: {source}")]
    Zip {
        /// The archive.
        path: String,
        /// The underlying error.
        source: zip::result::ZipError,
    },
    /// The XML writer failed.
    #[error("generating modelDescription.xml: {0}")]
    Xml(#[from] quick_xml::Error),
}

/// documentation/index.html: the variable table for humans.
pub fn documentation_html() -> String {
    let esc = |s: &str| {
        s.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    let mut h = String::from(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>TractionContact</title></head><body>\n\
         <h1>TractionContact FMU (FMI 2.0 co-simulation)</h1>\n\
         <p>Lubricated rolling traction contact between two rotating bodies, after the NASA traction report \
         (Hertz contact, Johnson &amp; Tevaarwerk elastic/plastic traction). Connect the angular speeds of the \
         two bodies to <code>omega1</code>, <code>omega2</code> and feed <code>torque1</code>, <code>torque2</code> \
         back to their inertias. Fluids: Santotrac 50 and TDF-88 through the report's correlations, or user m and &mu;.</p>\n\
         <table border=\"1\"><tr><th>name</th><th>causality</th><th>unit</th><th>start</th><th>description</th></tr>\n",
    );
    for v in VARIABLES {
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
        let c = match v.causality {
            Causality::Parameter => "parameter",
            Causality::Input => "input",
            Causality::Output => "output",
        };
        h.push_str(&format!(
            "<tr><td>{}</td><td>{c}</td><td>{}</td><td>{start}</td><td>{}</td></tr>\n",
            v.name,
            esc(unit),
            esc(v.description)
        ));
    }
    h.push_str("</table></body></html>\n");
    h
}

/// Writes the `.fmu` at `out` from the compiled cdylib at `library`.
///
/// # Errors
/// Unreadable library, unwritable archive.
pub fn write_fmu(library: &Path, out: &Path) -> Result<(), PackageError> {
    let lib = std::fs::read(library).map_err(|source| PackageError::Io {
        context: format!("reading the FMU library {}", library.display()),
        source,
    })?;
    let xml = model_description_xml()?;
    let file = std::fs::File::create(out).map_err(|source| PackageError::Io {
        context: format!("creating {}", out.display()),
        source,
    })?;
    let zerr = |source| PackageError::Zip {
        path: out.display().to_string(),
        source,
    };
    let ioerr = |source| PackageError::Io {
        context: format!("writing {}", out.display()),
        source,
    };
    let mut z = zip::ZipWriter::new(file);
    let opts = SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    let lib_opts = opts.unix_permissions(0o755);
    z.start_file("modelDescription.xml", opts).map_err(zerr)?;
    z.write_all(xml.as_bytes()).map_err(ioerr)?;
    z.start_file(format!("binaries/linux64/{MODEL_IDENTIFIER}.so"), lib_opts)
        .map_err(zerr)?;
    z.write_all(&lib).map_err(ioerr)?;
    z.start_file("documentation/index.html", opts)
        .map_err(zerr)?;
    z.write_all(documentation_html().as_bytes())
        .map_err(ioerr)?;
    z.finish().map_err(zerr)?;
    Ok(())
}
