//! `traction fit` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: FitArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction fit` is not implemented yet".into()))
}
