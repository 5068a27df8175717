//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml,
//! `binaries/linux64/ToroidalVariator.so` and `documentation/index.html`.

use std::io::Write;
use std::path::Path;

use zip::write::SimpleFileOptions;

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Causality, Kind, VARIABLES};

/// Why packaging failed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum PackageError {
    /// Reading the library or writing the archive failed.
    #[error("{context}")]
    Io {
        /// What was being read or written.
        context: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The zip writer failed.
    #[error("writing {path}")]
    Zip {
        /// The archive.
        path: String,
        /// The underlying error.
        source: zip::result::ZipError,
    },
    /// The XML writer failed.
    #[error("generating modelDescription.xml")]
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
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>ToroidalVariator</title></head><body>\n\
         <h1>ToroidalVariator FMU (FMI 2.0 co-simulation)</h1>\n\
         <p>Toroidal CVT variator between an input and an output shaft: n power rollers, each with two lubricated \
         traction contacts (Hertz contact, Johnson &amp; Tevaarwerk elastic/plastic traction with spin, after the NASA \
         traction report); the roller speed follows from its torque balance. Connect the shaft speeds to \
         <code>omega_in</code>, <code>omega_out</code> and feed <code>torque_in</code>, <code>torque_out</code> back to \
         their inertias; <code>tilt_angle</code> sets the ratio, <code>end_load</code> the clamping.</p>\n\
         <table border=\"1\"><tr><th>name</th><th>causality</th><th>unit</th><th>start</th><th>description</th></tr>\n",
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
    z.start_file("modelDescription.xml", opts).map_err(zerr)?;
    z.write_all(xml.as_bytes()).map_err(ioerr)?;
    z.start_file(
        format!("binaries/linux64/{MODEL_IDENTIFIER}.so"),
        opts.unix_permissions(0o755),
    )
    .map_err(zerr)?;
    z.write_all(&lib).map_err(ioerr)?;
    z.start_file("documentation/index.html", opts)
        .map_err(zerr)?;
    z.write_all(documentation_html().as_bytes())
        .map_err(ioerr)?;
    z.finish().map_err(zerr)?;
    Ok(())
}
