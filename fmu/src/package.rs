//! Packaging: the `.fmu` archive (a zip) with modelDescription.xml, the
//! binaries (`binaries/linux64/<modelIdentifier>.so`,
//! `binaries/win64/<modelIdentifier>.dll`) and `documentation/index.html`.

use std::io::Write;
use std::path::Path;

use zip::write::SimpleFileOptions;

use crate::model_description::{MODEL_IDENTIFIER, model_description_xml};
use crate::variables::{Causality, Kind, REAL_TYPES, VARIABLES};

/// A platform of the archive's `binaries/` folder (FMI 2.0 platform names).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Platform {
    /// `linux64`: x86-64 Linux, `<modelIdentifier>.so`.
    Linux64,
    /// `win64`: x86-64 Windows, `<modelIdentifier>.dll` (cross-compiled for
    /// `x86_64-pc-windows-gnu`).
    Win64,
}

impl Platform {
    /// Both platforms, in archive order.
    pub const ALL: [Platform; 2] = [Platform::Linux64, Platform::Win64];

    /// The FMI 2.0 platform folder name.
    pub fn folder(self) -> &'static str {
        match self {
            Platform::Linux64 => "linux64",
            Platform::Win64 => "win64",
        }
    }

    /// The shared library's file extension.
    pub fn extension(self) -> &'static str {
        match self {
            Platform::Linux64 => "so",
            Platform::Win64 => "dll",
        }
    }

    /// The Rust target triple to build for (`None`: the host, x86-64 Linux).
    pub fn rust_target(self) -> Option<&'static str> {
        match self {
            Platform::Linux64 => None,
            Platform::Win64 => Some("x86_64-pc-windows-gnu"),
        }
    }

    /// The file name cargo gives the traction-fmu cdylib on this platform.
    pub fn cargo_library_name(self) -> &'static str {
        match self {
            Platform::Linux64 => "libtraction_fmu.so",
            Platform::Win64 => "traction_fmu.dll",
        }
    }

    /// The path of the binary inside the archive.
    pub fn archive_path(self) -> String {
        format!(
            "binaries/{}/{MODEL_IDENTIFIER}.{}",
            self.folder(),
            self.extension()
        )
    }
}

impl std::str::FromStr for Platform {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Platform::ALL
            .into_iter()
            .find(|p| p.folder() == s)
            .ok_or_else(|| format!("unknown platform {s:?} (known: linux64, win64)"))
    }
}

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
    let libs = binaries
        .iter()
        .map(|&(platform, library)| {
            std::fs::read(library)
                .map(|bytes| (platform, bytes))
                .map_err(|source| PackageError::Io {
                    context: format!(
                        "reading the {} FMU library {}",
                        platform.folder(),
                        library.display()
                    ),
                    source,
                })
        })
        .collect::<Result<Vec<_>, _>>()?;
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
    for (platform, lib) in &libs {
        z.start_file(platform.archive_path(), lib_opts)
            .map_err(zerr)?;
        z.write_all(lib).map_err(ioerr)?;
    }
    z.start_file("documentation/index.html", opts)
        .map_err(zerr)?;
    z.write_all(documentation_html().as_bytes())
        .map_err(ioerr)?;
    z.finish().map_err(zerr)?;
    Ok(())
}
