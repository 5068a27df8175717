//! `traction kinematics` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction kinematics`.
#[derive(Debug, Args)]
pub struct KinematicsArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: KinematicsArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction kinematics` is not implemented yet".into()))
}
