//! `traction fmu build --model variator`: build and package the toroidal
//! variator FMU (`ToroidalVariator.fmu`, crate traction-variator-fmu).
//!
//! Runs `cargo build --release -p traction-variator-fmu --lib` in this
//! workspace and packs `libtraction_variator_fmu.so` with its generated
//! modelDescription.xml; `--library PATH` packs a prebuilt library instead.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::error::CliError;

/// The FMUs `traction fmu build` can make.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FmuModel {
    /// The lubricated rolling traction contact (TractionContact.fmu).
    Contact,
    /// The toroidal CVT variator (ToroidalVariator.fmu).
    Variator,
}

const LIB: &str = "libtraction_variator_fmu.so";

/// Builds (unless `library` is given) and packages the variator FMU at `out`.
pub fn build(out: &Path, library: Option<PathBuf>) -> Result<(), CliError> {
    let library = match library {
        Some(l) => l,
        None => build_library()?,
    };
    traction_variator_fmu::package::write_fmu(&library, out).map_err(CliError::model)?;
    eprintln!("wrote {} (library {})", out.display(), library.display());
    Ok(())
}

fn build_library() -> Result<PathBuf, CliError> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let hint = format!(
        "build it with `cargo build --release -p traction-variator-fmu --lib` in the traction workspace and pass \
         `--library <target-dir>/release/{LIB}`"
    );
    if !root.join("variator-fmu").join("Cargo.toml").is_file() {
        return Err(CliError::Usage(format!(
            "the traction workspace {} is not available to build the FMU library; {hint}",
            root.display()
        )));
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    eprintln!(
        "running cargo build --release -p traction-variator-fmu --lib in {}",
        root.display()
    );
    let output = Command::new(&cargo)
        .args([
            "build",
            "--release",
            "-p",
            "traction-variator-fmu",
            "--lib",
            "--message-format=json-render-diagnostics",
        ])
        .current_dir(&root)
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|source| CliError::Io {
            context: format!("running {}", Path::new(&cargo).display()),
            source,
        })?;
    if !output.status.success() {
        return Err(CliError::Usage(format!(
            "cargo build of traction-variator-fmu failed ({}); {hint}",
            output.status
        )));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    artifact_path(&stdout)
        .ok_or_else(|| CliError::Usage(format!("cargo did not report {LIB}; {hint}")))
}

/// Finds the cdylib in cargo's JSON messages.
fn artifact_path(json_lines: &str) -> Option<PathBuf> {
    let quoted = format!("{LIB}\"");
    json_lines
        .lines()
        .filter(|l| l.contains("\"reason\":\"compiler-artifact\""))
        .find_map(|l| {
            let end = l.find(&quoted)? + LIB.len();
            let start = l[..end].rfind('"')? + 1;
            Some(PathBuf::from(&l[start..end]))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_variator_cdylib_in_cargo_messages() {
        let msg = r#"{"reason":"compiler-artifact","filenames":["/t/release/libtraction_fmu.so"]}
{"reason":"compiler-artifact","filenames":["/t/release/libtraction_variator_fmu.so","/t/release/libtraction_variator_fmu.rlib"]}"#;
        assert_eq!(
            artifact_path(msg),
            Some(PathBuf::from("/t/release/libtraction_variator_fmu.so"))
        );
        assert_eq!(artifact_path(r#"{"reason":"build-finished"}"#), None);
    }
}
