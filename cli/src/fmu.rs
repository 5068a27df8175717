//! `traction fmu`: build and package the FMI 2.0 co-simulation FMU.
//!
//! `traction fmu build --out TractionContact.fmu` runs
//! `cargo build --release -p traction-fmu --lib` in this workspace for
//! linux64 and, cross-compiled, for win64 (`--target x86_64-pc-windows-gnu`
//! with the MinGW-w64 linker `x86_64-w64-mingw32-gcc` unless
//! `CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER` names another), and packs both
//! shared libraries with the generated modelDescription.xml. `--platform`
//! chooses the platforms (repeatable; default both). With `--library PATH`
//! (linux64) and/or `--win64-library PATH` it packs already built libraries
//! instead (for a `traction` binary used outside the source tree); then only
//! the given ones are packed unless `--platform` asks for more.

use std::path::{Path, PathBuf};
use std::process::Command;

use clap::{Args, Subcommand};

use traction_fmu::package::Platform;

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
    /// Pack this prebuilt linux64 library instead of building it
    /// (`cargo build --release -p traction-fmu --lib` makes
    /// `<target-dir>/release/libtraction_fmu.so`).
    #[arg(long)]
    library: Option<PathBuf>,
    /// Pack this prebuilt win64 library instead of building it (`cargo
    /// build --release -p traction-fmu --lib --target x86_64-pc-windows-gnu`
    /// makes `<target-dir>/x86_64-pc-windows-gnu/release/traction_fmu.dll`).
    #[arg(long)]
    win64_library: Option<PathBuf>,
    /// A platform to pack: linux64 or win64 (repeatable; default: both, or
    /// only those of --library/--win64-library when given).
    #[arg(long = "platform")]
    platforms: Vec<Platform>,
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
            if b.win64_library.is_some() || b.platforms.iter().any(|p| *p != Platform::Linux64) {
                return Err(CliError::Usage(
                    "--model variator: ToroidalVariator.fmu is built for linux64 only".into(),
                ));
            }
            crate::fmu_variator::build(&b.out, b.library)
        }
        FmuCommand::Build(b) => {
            let prebuilt = [
                (Platform::Linux64, b.library),
                (Platform::Win64, b.win64_library),
            ];
            let platforms: Vec<Platform> = if !b.platforms.is_empty() {
                b.platforms
            } else if prebuilt.iter().any(|p| p.1.is_some()) {
                prebuilt
                    .iter()
                    .filter(|p| p.1.is_some())
                    .map(|p| p.0)
                    .collect()
            } else {
                Platform::ALL.to_vec()
            };
            let mut libraries = Vec::new();
            for platform in Platform::ALL {
                if !platforms.contains(&platform) {
                    continue;
                }
                let given = prebuilt
                    .iter()
                    .find(|p| p.0 == platform)
                    .and_then(|p| p.1.clone());
                let library = match given {
                    Some(l) => l,
                    None => build_library(CONTACT, platform)?,
                };
                libraries.push((platform, library));
            }
            let binaries: Vec<(Platform, &Path)> =
                libraries.iter().map(|(p, l)| (*p, l.as_path())).collect();
            traction_fmu::package::write_fmu_for(&binaries, &b.out).map_err(CliError::model)?;
            for (platform, library) in &libraries {
                eprintln!(
                    "packed {} ({})",
                    platform.archive_path(traction_fmu::model_description::MODEL_IDENTIFIER),
                    library.display()
                );
            }
            eprintln!("wrote {}", b.out.display());
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

/// The MinGW-w64 linker of the win64 cross build (Debian `gcc-mingw-w64-x86-64`).
const MINGW_LINKER: &str = "x86_64-w64-mingw32-gcc";

/// An FMU crate of this workspace that `traction fmu build` builds with cargo.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FmuCrate {
    /// The cargo package (`traction-fmu`).
    pub package: &'static str,
    /// Its folder in the workspace (`fmu`).
    pub folder: &'static str,
    /// Its library name (`traction_fmu`), which names the cdylib.
    pub lib_name: &'static str,
}

/// traction-fmu: TractionContact.fmu.
const CONTACT: FmuCrate = FmuCrate {
    package: "traction-fmu",
    folder: "fmu",
    lib_name: traction_fmu::package::LIBRARY_NAME,
};

/// Builds the cdylib of `fmu` for `platform` (`cargo build --release -p
/// <package> --lib`, with `--target` and the MinGW-w64 linker for win64) and
/// returns its path from cargo's messages.
pub(crate) fn build_library(fmu: FmuCrate, platform: Platform) -> Result<PathBuf, CliError> {
    let root = workspace_root();
    let package = fmu.package;
    let file = platform.cargo_library_name(fmu.lib_name);
    let target_args = platform
        .rust_target()
        .map(|t| format!(" --target {t}"))
        .unwrap_or_default();
    let mut hint = format!(
        "build it with `cargo build --release -p {package} --lib{target_args}` in the traction workspace and pass `--{}library <target-dir>/{}release/{file}`",
        if platform == Platform::Win64 {
            "win64-"
        } else {
            ""
        },
        platform
            .rust_target()
            .map(|t| format!("{t}/"))
            .unwrap_or_default(),
    );
    if platform == Platform::Win64 {
        hint.push_str(
            ", install the cross toolchain (`rustup target add x86_64-pc-windows-gnu`, Debian `gcc-mingw-w64-x86-64`; scripts/fmu_setup.sh does both), or pack linux64 only with `--platform linux64`",
        );
    }
    if !root.join(fmu.folder).join("Cargo.toml").is_file() {
        return Err(CliError::Usage(format!(
            "the traction workspace {} is not available to build the {} FMU library; {hint}",
            root.display(),
            platform.folder()
        )));
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(&cargo);
    command.args([
        "build",
        "--release",
        "-p",
        package,
        "--lib",
        "--message-format=json-render-diagnostics",
    ]);
    if let Some(target) = platform.rust_target() {
        command.args(["--target", target]);
        let linker = "CARGO_TARGET_X86_64_PC_WINDOWS_GNU_LINKER";
        if std::env::var_os(linker).is_none() {
            command.env(linker, MINGW_LINKER);
        }
    }
    eprintln!(
        "running cargo build --release -p {package} --lib{target_args} in {}",
        root.display()
    );
    let output = command
        .current_dir(&root)
        .stderr(std::process::Stdio::inherit())
        .output()
        .map_err(|source| CliError::Io {
            context: format!("running {}", Path::new(&cargo).display()),
            source,
        })?;
    if !output.status.success() {
        return Err(CliError::Usage(format!(
            "cargo build of {package} for {} failed ({}); {hint}",
            platform.folder(),
            output.status
        )));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    artifact_path(&stdout, &file)
        .ok_or_else(|| CliError::Usage(format!("cargo did not report {file}; {hint}")))
}

/// Finds the cdylib `file` in cargo's JSON messages
/// (`"filenames":[..., ".../libtraction_fmu.so"]`).
fn artifact_path(json_lines: &str, file: &str) -> Option<PathBuf> {
    let quoted = format!("/{file}\"");
    json_lines
        .lines()
        .filter(|l| l.contains("\"reason\":\"compiler-artifact\""))
        .find_map(|l| {
            let end = l.find(&quoted)? + quoted.len() - 1;
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
            artifact_path(msg, "libtraction_fmu.so"),
            Some(PathBuf::from("/t/release/libtraction_fmu.so"))
        );
        assert_eq!(
            artifact_path(r#"{"reason":"build-finished"}"#, "libtraction_fmu.so"),
            None
        );
        // The variator's library among the contact's (a whole-workspace build).
        let both = r#"{"reason":"compiler-artifact","filenames":["/t/release/libtraction_fmu.so"]}
{"reason":"compiler-artifact","filenames":["/t/release/libtraction_variator_fmu.so","/t/release/libtraction_variator_fmu.rlib"]}"#;
        assert_eq!(
            artifact_path(both, "libtraction_variator_fmu.so"),
            Some(PathBuf::from("/t/release/libtraction_variator_fmu.so"))
        );
        // The win64 build reports the DLL beside its import library.
        let win = r#"{"reason":"compiler-artifact","filenames":["/t/x86_64-pc-windows-gnu/release/traction_fmu.dll","/t/x86_64-pc-windows-gnu/release/libtraction_fmu.dll.a","/t/x86_64-pc-windows-gnu/release/libtraction_fmu.rlib"]}"#;
        assert_eq!(
            artifact_path(win, "traction_fmu.dll"),
            Some(PathBuf::from(
                "/t/x86_64-pc-windows-gnu/release/traction_fmu.dll"
            ))
        );
    }
}
