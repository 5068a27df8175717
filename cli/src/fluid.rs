//! `traction fluid` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction fluid`.
#[derive(Debug, Args)]
pub struct FluidArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: FluidArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction fluid` is not implemented yet".into()))
}
