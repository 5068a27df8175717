//! Packaging: the `.fmu` archive (a zip, deflate) with modelDescription.xml,
//! one shared library per platform under `binaries/<platform>/` and
//! `documentation/index.html`.

use std::io::Write;
use std::path::Path;

use zip::write::SimpleFileOptions;

use crate::xml::Causality;

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

    /// The file name cargo gives the cdylib of the library crate `lib_name`
    /// (its name with underscores, e.g. `traction_fmu`) on this platform.
    pub fn cargo_library_name(self, lib_name: &str) -> String {
        match self {
            Platform::Linux64 => format!("lib{lib_name}.so"),
            Platform::Win64 => format!("{lib_name}.dll"),
        }
    }

    /// The path of the binary of `model_identifier` inside the archive.
    pub fn archive_path(self, model_identifier: &str) -> String {
        format!(
            "binaries/{}/{model_identifier}.{}",
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

/// `&`, `<`, `>` escaped for HTML text.
pub fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// One row of the documentation page's variable table.
#[derive(Debug, Clone, PartialEq)]
pub struct DocumentationRow<'a> {
    /// Variable name.
    pub name: &'a str,
    /// Causality.
    pub causality: Causality,
    /// Unit (empty for Integer, Enumeration, Boolean).
    pub unit: &'a str,
    /// Start value as text (empty for none).
    pub start: String,
    /// Description.
    pub description: &'a str,
}

/// documentation/index.html: title and heading `model_identifier`,
/// `introduction` (HTML) and the variable table (text escaped).
pub fn documentation_html<'a>(
    model_identifier: &str,
    introduction: &str,
    rows: impl IntoIterator<Item = DocumentationRow<'a>>,
) -> String {
    let mut h = format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{model_identifier}</title></head><body>\n\
         <h1>{model_identifier} FMU (FMI 2.0 co-simulation)</h1>\n\
         <p>{introduction}</p>\n\
         <table border=\"1\"><tr><th>name</th><th>causality</th><th>unit</th><th>start</th><th>description</th></tr>\n"
    );
    for r in rows {
        h.push_str(&format!(
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
            r.name,
            r.causality.as_str(),
            html_escape(r.unit),
            r.start,
            html_escape(r.description)
        ));
    }
    h.push_str("</table></body></html>\n");
    h
}

/// Writes the `.fmu` at `out`: `model_description`, the compiled cdylib of
/// each platform (read from its path, stored as
/// [`Platform::archive_path`] of `model_identifier`, mode 755) and
/// `documentation`.
///
/// # Errors
/// Unreadable library, unwritable archive.
pub fn write_fmu(
    out: &Path,
    model_identifier: &str,
    model_description: &str,
    binaries: &[(Platform, &Path)],
    documentation: &str,
) -> Result<(), PackageError> {
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
    z.write_all(model_description.as_bytes()).map_err(ioerr)?;
    for (platform, lib) in &libs {
        z.start_file(platform.archive_path(model_identifier), lib_opts)
            .map_err(zerr)?;
        z.write_all(lib).map_err(ioerr)?;
    }
    z.start_file("documentation/index.html", opts)
        .map_err(zerr)?;
    z.write_all(documentation.as_bytes()).map_err(ioerr)?;
    z.finish().map_err(zerr)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    #[test]
    fn platform_names_and_paths() {
        assert_eq!(
            Platform::Linux64.archive_path("TractionContact"),
            "binaries/linux64/TractionContact.so"
        );
        assert_eq!(
            Platform::Win64.archive_path("TractionContact"),
            "binaries/win64/TractionContact.dll"
        );
        assert_eq!(
            Platform::Linux64.cargo_library_name("traction_fmu"),
            "libtraction_fmu.so"
        );
        assert_eq!(
            Platform::Win64.cargo_library_name("traction_fmu"),
            "traction_fmu.dll"
        );
        assert_eq!("win64".parse::<Platform>(), Ok(Platform::Win64));
        assert!("win32".parse::<Platform>().unwrap_err().contains("win32"));
    }

    #[test]
    fn the_documentation_page_escapes_text() {
        let row = DocumentationRow {
            name: "x",
            causality: Causality::Input,
            unit: "W/(m.K)",
            start: "1".into(),
            description: "a <b> & c",
        };
        let h = documentation_html("M", "<b>intro</b>", [row]);
        assert!(
            h.starts_with("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>M</title>")
        );
        assert!(h.contains("<h1>M FMU (FMI 2.0 co-simulation)</h1>\n<p><b>intro</b></p>\n"));
        assert!(h.ends_with(
            "<tr><td>x</td><td>input</td><td>W/(m.K)</td><td>1</td><td>a &lt;b&gt; &amp; c</td></tr>\n</table></body></html>\n"
        ));
    }

    #[test]
    fn the_archive_holds_the_description_binaries_and_documentation() {
        let dir = std::env::temp_dir().join(format!("fmi-support-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (so, dll, fmu) = (dir.join("a.so"), dir.join("a.dll"), dir.join("M.fmu"));
        std::fs::write(&so, b"ELF").unwrap();
        std::fs::write(&dll, b"MZ").unwrap();
        let binaries = [
            (Platform::Linux64, so.as_path()),
            (Platform::Win64, dll.as_path()),
        ];
        write_fmu(&fmu, "M", "<xml/>", &binaries, "<html/>").unwrap();
        let mut z = zip::ZipArchive::new(std::fs::File::open(&fmu).unwrap()).unwrap();
        let names: Vec<String> = z.file_names().map(str::to_owned).collect();
        let mut read = |name: &str| {
            let mut s = String::new();
            z.by_name(name).unwrap().read_to_string(&mut s).unwrap();
            s
        };
        assert_eq!(read("modelDescription.xml"), "<xml/>");
        assert_eq!(read("binaries/linux64/M.so"), "ELF");
        assert_eq!(read("binaries/win64/M.dll"), "MZ");
        assert_eq!(read("documentation/index.html"), "<html/>");
        assert_eq!(names.len(), 4);
        let missing = write_fmu(
            &fmu,
            "M",
            "",
            &[(Platform::Linux64, &dir.join("none.so"))],
            "",
        );
        assert!(
            missing
                .unwrap_err()
                .to_string()
                .contains("reading the linux64 FMU library")
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
