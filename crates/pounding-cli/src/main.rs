//! `pounding` — command-line interface. Each subcommand lives in its own module.

#![warn(missing_docs)]

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cmd_campaign;
mod cmd_check;
mod cmd_compare;
mod cmd_design;
mod cmd_fragility;
mod cmd_impact;
mod cmd_lcp;
mod cmd_motion;
mod cmd_simulate;
mod cmd_spectrum;
mod cmd_study;
mod compare_report;
mod design_plot;
mod design_report;
mod figures;
mod fragility_plot;
mod fragility_report;
mod fragility_study;
mod hazard_plot;
mod hazard_report;
mod plot_style;
mod plots;
mod report;
mod report_pages;
mod sim_anim;
mod sim_report;
mod sim_report_check;
mod sim_report_verdict;

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
    /// Elastic response spectra (PSA, PSV, SD) of records, and RotD50/RotD100 of horizontal pairs.
    Spectrum(cmd_spectrum::Args),
    /// Ground-motion tools: `motion synth` writes synthetic accelerogram suites (for trying the workflow), `motion svgm` spatially variable motions at several supports.
    Motion(cmd_motion::Args),
    /// Fragility study of a bridge: a record set at IM stripes, limit states, fitted lognormal curves.
    Fragility(cmd_fragility::Args),
    /// Retrofit comparison: variants of one bridge on the same records and stripes, their fragility, MAF and paired differences.
    Design(cmd_design::Args),
    /// Code check of seat lengths (EC8-2, AASHTO LRFD and Guide Spec, Caltrans, JRA) and joint gaps (SRSS, DDC) of a scenario.
    Check(cmd_check::Args),
    /// Campaigns of many runs (a bridge × a record set × stripes) stored as resumable Parquet parts; local threads, Slurm shards, merge.
    Campaign(cmd_campaign::Args),
}

/// The message of a panic raised by `print!`/`eprint!` when standard output or error cannot be
/// written (`/dev/full`, a closed pipe), e.g. `failed printing to stdout: Broken pipe`.
fn stdio_failure(payload: &(dyn std::any::Any + Send)) -> Option<String> {
    let msg = payload
        .downcast_ref::<String>()
        .map(String::as_str)
        .or_else(|| payload.downcast_ref::<&str>().copied())?;
    msg.starts_with("failed printing to std")
        .then(|| msg.to_string())
}

fn run(cli: Cli) -> ExitCode {
    let result = match cli.command {
        Command::Lcp(a) => cmd_lcp::run(a),
        Command::Impact(a) => cmd_impact::run(a),
        Command::Study(a) => cmd_study::run(a),
        Command::Simulate(a) => cmd_simulate::run(a),
        Command::Compare(a) => cmd_compare::run(a),
        Command::Spectrum(a) => cmd_spectrum::run(a),
        Command::Motion(a) => cmd_motion::run(a),
        Command::Fragility(a) => cmd_fragility::run(a),
        Command::Design(a) => cmd_design::run(a),
        Command::Check(a) => cmd_check::run(a),
        Command::Campaign(a) => cmd_campaign::run(a),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn main() -> ExitCode {
    // A failed write to standard output or error (`> /dev/full`, `| head`) makes `print!` panic;
    // it is an I/O error, reported as one (exit 2), never a panic with a backtrace.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if stdio_failure(info.payload()).is_none() {
            default_hook(info);
        }
    }));
    let cli = Cli::parse();
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run(cli))) {
        Ok(code) => code,
        Err(payload) => match stdio_failure(payload.as_ref()) {
            Some(msg) => {
                use std::io::Write;
                let _ = writeln!(std::io::stderr(), "error: {msg}");
                ExitCode::from(2)
            }
            None => std::panic::resume_unwind(payload),
        },
    }
}
