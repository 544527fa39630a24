//! `pounding impact` (filled in by its work item).

use std::process::ExitCode;

/// Arguments of `pounding impact`.
#[derive(clap::Args)]
pub struct Args {}

/// Runs `pounding impact`.
pub fn run(_args: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`pounding impact` is not implemented yet")
}
