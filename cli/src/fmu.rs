//! `traction fmu`: build and package the FMI 2.0 co-simulation FMU.
//!
//! `traction fmu build --out TractionContact.fmu` runs
//! `cargo build --release -p traction-fmu --lib` in this workspace and packs
//! the shared library with the generated modelDescription.xml. With
//! `--library PATH` it packs an already built `libtraction_fmu.so` instead
//! (for a `traction` binary used outside the source tree).

use std::path::{Path, PathBuf};
use std::process::Command;

use clap::{Args, Subcommand};

use crate::error::CliError;

/// Arguments of `traction fmu`.
#[derive(Debug, Args)]
pub struct FmuArgs {
    #[command(subcommand)]
    command: FmuCommand,
}

#[derive(Debug, Subcommand)]
enum FmuCommand {
    /// Build the FMU library (cargo, release profile) and package PATH.fmu.
    Build(BuildArgs),
    /// Print the generated modelDescription.xml.
    ModelDescription,
}

#[derive(Debug, Args)]
struct BuildArgs {
    /// Where to write the FMU (e.g. TractionContact.fmu).
    #[arg(long)]
    out: PathBuf,
    /// Which FMU: the traction contact or the toroidal variator (ToroidalVariator.fmu).
    #[arg(long, value_enum, default_value_t = crate::fmu_variator::FmuModel::Contact)]
    model: crate::fmu_variator::FmuModel,
    /// Pack this prebuilt library instead of building it
    /// (`cargo build --release -p traction-fmu --lib` makes
    /// `<target-dir>/release/libtraction_fmu.so`).
    #[arg(long)]
    library: Option<PathBuf>,
}

/// Runs `traction fmu ...`.
pub fn run(args: FmuArgs) -> Result<(), CliError> {
    match args.command {
        FmuCommand::ModelDescription => {
            let xml = traction_fmu::model_description::model_description_xml()
                .map_err(CliError::model)?;
            print!("{xml}");
            Ok(())
        }
        FmuCommand::Build(b) if b.model == crate::fmu_variator::FmuModel::Variator => {
            crate::fmu_variator::build(&b.out, b.library)
        }
        FmuCommand::Build(b) => {
            let library = match b.library {
                Some(l) => l,
                None => build_library()?,
            };
            traction_fmu::package::write_fmu(&library, &b.out).map_err(CliError::model)?;
            eprintln!("wrote {} (library {})", b.out.display(), library.display());
            Ok(())
        }
    }
}

/// The workspace this binary was built from.
fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

fn build_library() -> Result<PathBuf, CliError> {
    let root = workspace_root();
    let hint = "build it with `cargo build --release -p traction-fmu --lib` in the traction workspace and pass \
                `--library <target-dir>/release/libtraction_fmu.so`";
    if !root.join("fmu").join("Cargo.toml").is_file() {
        return Err(CliError::Usage(format!(
            "the traction workspace {} is not available to build the FMU library; {hint}",
            root.display()
        )));
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    eprintln!(
        "running cargo build --release -p traction-fmu --lib in {}",
        root.display()
    );
    let output = Command::new(&cargo)
        .args([
            "build",
            "--release",
            "-p",
            "traction-fmu",
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
            "cargo build of traction-fmu failed ({}); {hint}",
            output.status
        )));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    artifact_path(&stdout)
        .ok_or_else(|| CliError::Usage(format!("cargo did not report libtraction_fmu.so; {hint}")))
}

/// Finds the cdylib in cargo's JSON messages (`"filenames":[..., ".../libtraction_fmu.so"]`).
fn artifact_path(json_lines: &str) -> Option<PathBuf> {
    json_lines
        .lines()
        .filter(|l| l.contains("\"reason\":\"compiler-artifact\""))
        .find_map(|l| {
            let end = l.find("libtraction_fmu.so\"")? + "libtraction_fmu.so".len();
            let start = l[..end].rfind('"')? + 1;
            Some(PathBuf::from(&l[start..end]))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_cdylib_in_cargo_messages() {
        let msg = r#"{"reason":"compiler-artifact","filenames":["/t/release/libtraction_fmu.so","/t/release/libtraction_fmu.rlib"]}
{"reason":"build-finished","success":true}"#;
        assert_eq!(
            artifact_path(msg),
            Some(PathBuf::from("/t/release/libtraction_fmu.so"))
        );
        assert_eq!(artifact_path(r#"{"reason":"build-finished"}"#), None);
    }
}
