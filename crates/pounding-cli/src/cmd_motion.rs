//! `pounding motion synth`: synthetic (stochastic) accelerogram suites for trying the workflow
//! ([`pounding::ground_motion::synth`]); writes `SYNnnn_x.AT2` (and `_y` with `--pairs`),
//! `SYNTHETIC.txt` and the record-set manifest `suite.toml` (last); `pounding motion svgm`
//! ([`svgm`]): spatially variable motions at several supports.

use anyhow::{Context, Result};
use pounding::ground_motion::synth::{
    SynthParams, check_count, check_seed, check_suite_size, synth_source, write_suite,
};
use pounding::output::float_token;
use std::path::PathBuf;
use std::process::ExitCode;

#[path = "cmd_motion_svgm.rs"]
mod svgm;

/// Arguments of `pounding motion`.
#[derive(clap::Args)]
pub struct Args {
    #[command(subcommand)]
    command: MotionCommand,
}

#[derive(clap::Subcommand)]
enum MotionCommand {
    /// Synthetic accelerograms: Kanai-Tajimi/Clough-Penzien filtered white noise times a
    /// Saragoni-Hart envelope (for trying the workflow; real assessments need real records).
    Synth(SynthArgs),
    /// Spatially variable ground motions at several supports of a long bridge: wave passage and
    /// loss of coherency (spectral representation; Clough-Penzien PSD, Saragoni-Hart envelope).
    Svgm(Box<svgm::SvgmArgs>),
}

/// Arguments of `pounding motion synth`.
#[derive(clap::Args)]
struct SynthArgs {
    /// Number of records (1 to 10000).
    #[arg(long, value_name = "N")]
    count: usize,
    /// Random seed, 0 to 9223372036854775807 (2^63 - 1, the largest integer suite.toml can
    /// hold): the same seed gives the same files (any thread count).
    #[arg(long, value_name = "S")]
    seed: u64,
    /// Output directory (created if needed).
    #[arg(long, value_name = "DIR")]
    out: PathBuf,
    /// Scale every component to this PGA in g (default: unscaled, white-noise intensity S0).
    #[arg(long, value_name = "G", allow_hyphen_values = true)]
    pga: Option<f64>,
    /// Sample interval in seconds.
    #[arg(
        long,
        value_name = "SECONDS",
        default_value_t = 0.01,
        allow_hyphen_values = true
    )]
    dt: f64,
    /// Duration in seconds (the envelope reaches 5 % of its peak at the end).
    #[arg(
        long,
        value_name = "SECONDS",
        default_value_t = 20.0,
        allow_hyphen_values = true
    )]
    duration: f64,
    /// Write two independent horizontal components per record (x and y).
    #[arg(long)]
    pairs: bool,
}

/// Runs `pounding motion ...`.
pub fn run(args: Args) -> Result<ExitCode> {
    match args.command {
        MotionCommand::Synth(a) => synth(a),
        MotionCommand::Svgm(a) => svgm::svgm(*a),
    }
}

fn synth(a: SynthArgs) -> Result<ExitCode> {
    let p = SynthParams {
        dt: a.dt,
        duration: a.duration,
        pga_g: a.pga,
        ..SynthParams::default()
    };
    // every flag is checked before the directory is created or locked
    check_count(a.count)?;
    check_seed(a.seed)?;
    p.check()?;
    check_suite_size(&p, a.count, a.pairs)?;
    let source = synth_source(&p, a.count, a.seed, a.pairs);
    let _lock = pounding::output::lock_output_dir(&a.out)?;
    let records = write_suite(&a.out, &p, a.count, a.seed, a.pairs, &source)
        .with_context(|| format!("writing the suite to {}", a.out.display()))?;
    let pgas: Vec<f64> = records
        .iter()
        .flat_map(|r| std::iter::once(&r.x).chain(r.y.as_ref()))
        .map(|g| g.iter().fold(0.0f64, |m, x| m.max(x.abs())))
        .collect();
    let (lo, hi) = pgas
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
    eprintln!(
        "{} synthetic record{} ({} file{}, PGA {}..{} g) written to {}: suite.toml, \
         SYNTHETIC.txt. Synthetic records are for trying the workflow; real assessments need \
         real records.",
        records.len(),
        if records.len() == 1 { "" } else { "s" },
        pgas.len(),
        if pgas.len() == 1 { "" } else { "s" },
        float_token((lo * 1e4).round() / 1e4),
        float_token((hi * 1e4).round() / 1e4),
        a.out.display()
    );
    Ok(ExitCode::SUCCESS)
}
