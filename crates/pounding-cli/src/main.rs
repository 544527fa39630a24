//! `pounding` — command-line interface. Each subcommand lives in its own module.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cmd_compare;
mod cmd_impact;
mod cmd_lcp;
mod cmd_simulate;
mod cmd_study;
mod figures;
mod plot_style;
mod plots;
mod report;

/// Nonsmooth rigid-impact analysis of pounding between bridge deck segments.
#[derive(Parser)]
#[command(name = "pounding", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Solve or benchmark linear complementarity problems (Siconos .dat, LCPSET 1 files).
    Lcp(cmd_lcp::Args),
    /// One oblique frictional impact: two S-curved decks (bridge form) or generic rigid bodies (--problem).
    Impact(cmd_impact::Args),
    /// The paper's parametric stick/slip study (built-in default or a scenario file).
    Study(cmd_study::Args),
    /// Seismic time-history simulation of two decks with pounding (curved/straight/skew, abutments, batch runs; default: El Centro 1940).
    Simulate(cmd_simulate::Args),
    /// Run one scenario with several joint contact laws (rigid and compliance) side by side.
    Compare(cmd_compare::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Lcp(a) => cmd_lcp::run(a),
        Command::Impact(a) => cmd_impact::run(a),
        Command::Study(a) => cmd_study::run(a),
        Command::Simulate(a) => cmd_simulate::run(a),
        Command::Compare(a) => cmd_compare::run(a),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}
