//! `traction hertz` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction hertz`.
#[derive(Debug, Args)]
pub struct HertzArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: HertzArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction hertz` is not implemented yet".into()))
}
