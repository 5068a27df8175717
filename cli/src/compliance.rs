//! `traction compliance` (in progress; the owning issue fills this in).

use clap::Args;

use crate::error::CliError;

/// Arguments of `traction compliance`.
#[derive(Debug, Args)]
pub struct ComplianceArgs {
    /// Input CSV (`-` for stdin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Run the subcommand.
pub fn run(_args: ComplianceArgs) -> Result<(), CliError> {
    Err(CliError::Usage("`traction compliance` is not implemented yet".into()))
}
