//! `traction fmu build --model variator`: build and package the toroidal
//! variator FMU (`ToroidalVariator.fmu`, crate traction-variator-fmu).
//!
//! Runs `cargo build --release -p traction-variator-fmu --lib` in this
//! workspace (the same build as the contact's, [`crate::fmu`]) and packs
//! `libtraction_variator_fmu.so` with its generated modelDescription.xml;
//! `--library PATH` packs a prebuilt library instead.

use std::path::{Path, PathBuf};

use traction_fmu::package::Platform;

use crate::error::CliError;
use crate::fmu::{FmuCrate, build_library};

/// The FMUs `traction fmu build` can make.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FmuModel {
    /// The lubricated rolling traction contact (TractionContact.fmu).
    Contact,
    /// The toroidal CVT variator (ToroidalVariator.fmu).
    Variator,
}

/// traction-variator-fmu: ToroidalVariator.fmu (linux64).
const VARIATOR: FmuCrate = FmuCrate {
    package: "traction-variator-fmu",
    folder: "variator-fmu",
    lib_name: traction_variator_fmu::package::LIBRARY_NAME,
};

/// Builds (unless `library` is given) and packages the variator FMU at `out`.
pub fn build(out: &Path, library: Option<PathBuf>) -> Result<(), CliError> {
    let library = match library {
        Some(l) => l,
        None => build_library(VARIATOR, Platform::Linux64)?,
    };
    traction_variator_fmu::package::write_fmu(&library, out).map_err(CliError::model)?;
    eprintln!("wrote {} (library {})", out.display(), library.display());
    Ok(())
}
