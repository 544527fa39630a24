//! `pounding study` (filled in by its work item).

use std::process::ExitCode;

/// Arguments of `pounding study`.
#[derive(clap::Args)]
pub struct Args {}

/// Runs `pounding study`.
pub fn run(_args: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`pounding study` is not implemented yet")
}
