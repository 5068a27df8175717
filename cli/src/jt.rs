//! `traction jt` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction jt`.
#[derive(Debug, Args)]
pub struct JtArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: JtArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction jt` is not implemented yet".into()))
}
