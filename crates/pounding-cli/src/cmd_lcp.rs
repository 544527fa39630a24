//! `pounding lcp` (filled in by its work item).

use std::process::ExitCode;

/// Arguments of `pounding lcp`.
#[derive(clap::Args)]
pub struct Args {}

/// Runs `pounding lcp`.
pub fn run(_args: Args) -> anyhow::Result<ExitCode> {
    anyhow::bail!("`pounding lcp` is not implemented yet")
}
