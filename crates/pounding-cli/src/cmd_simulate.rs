//! `pounding simulate`: seismic time-history simulation of two decks (curved, straight or skewed,
//! optionally with abutments) with pounding.
//!
//! Reads an optional scenario ([`pounding::sim::scenario::Scenario`]: schema, defaults,
//! validation and record loading live in the library), runs [`pounding::sim::simulate`] and
//! writes `history.csv`, `impacts.csv`, `summary.json` ([`pounding::sim::output`]), `timing.json`
//! and PNG plots into the output directory. Every input is validated before anything is written.
//! With `--records` it runs a batch instead ([`sim_batch`]).

use anyhow::{Context, Result, anyhow};
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::output::{
    SIM_OUTPUTS, describe_contact, history_csv, impacts_csv, summary_json_text,
};
use pounding::sim::scenario::{DEFAULT_SCENARIO_TOML, Scenario, SimSetup};
use pounding::sim::{SimSolution, simulate};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

#[path = "sim_plots.rs"]
pub(crate) mod sim_plots;

#[path = "sim_batch.rs"]
pub(crate) mod sim_batch;

#[path = "sim_bridge.rs"]
mod sim_bridge;

/// Arguments of `pounding simulate`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML); without it the built-in default runs (see --print-default).
    pub scenario: Option<PathBuf>,
    /// Use this record (PEER .AT2, or .csv `t, a` in g) as the only ground-motion component,
    /// along y (normal to the joint); replaces the scenario's records.
    #[arg(long, value_name = "FILE")]
    pub record: Option<PathBuf>,
    /// Multiply both ground-motion scale factors by S.
    #[arg(long, value_name = "S")]
    pub scale: Option<f64>,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/simulate")]
    pub out: PathBuf,
    /// Print the built-in default scenario as commented TOML and exit.
    #[arg(long)]
    pub print_default: bool,
    /// Batch mode: run every record (files, or directories whose `.AT2`/`.csv` files are taken
    /// in name order) at every `--scales` factor, each as the only component along y (as
    /// `--record`); writes `batch.csv` and `batch.png`. Put the scenario file before this flag.
    #[arg(long, num_args = 1.., value_name = "DIR_OR_FILE", conflicts_with_all = ["record", "scale"])]
    pub records: Vec<PathBuf>,
    /// Batch mode: scale factors, comma separated (each multiplies the scenario's scale_y, as
    /// `--scale`). Default: 1.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "S1,S2,...",
        requires = "records"
    )]
    pub scales: Vec<f64>,
    /// Batch mode: worker threads (default: all cores). batch.csv is identical for any value.
    #[arg(long, value_name = "N", requires = "records")]
    pub threads: Option<usize>,
    /// Batch mode: run only the runs whose global index i (0-based, record-major) has
    /// i mod N = K − 1.
    #[arg(long, value_name = "K/N", requires = "records")]
    pub shard: Option<String>,
}

/// The scenario file `path`, or the built-in default.
pub(crate) fn load_scenario(path: Option<&Path>) -> Result<Scenario> {
    Ok(match path {
        Some(p) => Scenario::load(p)?,
        None => Scenario::default(),
    })
}

/// The run described by the scenario and the flags, validated.
fn build(args: &Args) -> Result<SimSetup> {
    let mut sc = load_scenario(args.scenario.as_deref())?;
    if let Some(p) = &args.record {
        sc = sc.with_record(p, None);
    }
    if let Some(s) = args.scale {
        sc = sc.with_scale(s);
    }
    if !args.records.is_empty() {
        sc = sc.for_batch();
    }
    Ok(sc.build()?)
}

/// Runs `pounding simulate`.
pub fn run(args: Args) -> Result<ExitCode> {
    if args.print_default {
        print!("{DEFAULT_SCENARIO_TOML}");
        return Ok(ExitCode::SUCCESS);
    }
    let t_start = Instant::now();
    if let Some(p) = args.scenario.as_deref() {
        let sc = Scenario::load(p)?;
        if sc.is_bridge() {
            return sim_bridge::run(&args, sc, t_start);
        }
    }
    let setup = build(&args)?;
    if !args.records.is_empty() {
        return sim_batch::run(&args, &setup.problem, &setup.settings, setup.units, t_start);
    }
    pounding::output::check_output_dir_free(&args.out)?;
    note_rounded_duration(&setup.settings);
    let t_sim = Instant::now();
    let sol = simulate(&setup.problem, &setup.settings).map_err(|e| anyhow!("{e}"))?;
    let sim_secs = t_sim.elapsed().as_secs_f64();
    warn_time_step(&sol);
    if let Some(w) =
        pounding::sim::output::warnings_message(&pounding::sim::output::run_warnings(&sol))
    {
        eprintln!("{w}");
    }

    let out = &args.out;
    let _lock = lock_and_clear(out)?;
    let t_write = Instant::now();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("history.csv", history_csv(&setup.problem, &sol).as_bytes())?;
    wr(
        "impacts.csv",
        impacts_csv(&setup.problem.model, &sol).as_bytes(),
    )?;
    wr("summary.json", summary_json_text(&setup, &sol).as_bytes())?;
    sim_plots::write_all(out, &setup.problem, &sol).map_err(|e| anyhow!("plotting: {e}"))?;
    let write_secs = t_write.elapsed().as_secs_f64();
    let timing = json!({
        "simulate_s": sim_secs,
        "write_s": write_secs,
        "wall_time_s": t_start.elapsed().as_secs_f64(),
        "steps": sol.steps,
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    let s = &sol.summary;
    eprintln!(
        "simulated {} s in {} steps ({:.1} ms): {} impacts, peak closing {} m, opening {} m, \
         seat displacement {} m{}, energy balance error {:.1e}; outputs in {}",
        float_token(sol.steps as Real * sol.dt),
        sol.steps,
        sim_secs * 1e3,
        s.impacts,
        bounded(s.peak_joint_closing, 4),
        bounded(s.peak_joint_opening, 4),
        bounded(s.peak_seat_displacement, 4),
        match s.unseating_time {
            Some(t) => format!(" (UNSEATED at {} s)", bounded(t, 3)),
            None => String::new(),
        },
        s.energy_balance_error,
        out.display()
    );
    if let Some(f) = s.peak_contact_force {
        eprintln!(
            "contact law {}: peak contact force {} MN, peak penetration {} mm",
            describe_contact(&setup.problem.model.contact)["law"],
            bounded(f / 1e6, 4),
            bounded(s.peak_penetration * 1e3, 4)
        );
    }
    if sol.status != pounding::sim::SimStatus::Completed {
        // outputs are written (they show where the run went wrong), but the run did not succeed
        let hint = match sol.status {
            pounding::sim::SimStatus::CompletedWithLcpFailures => "summary.json (lcp_failures)",
            _ => "summary.json (energies, peaks)",
        };
        eprintln!(
            "error: simulation status {:?} after {} s ({} steps): the results are not trustworthy; \
             see {hint} and history.csv in {}",
            sol.status,
            float_token(sol.steps as Real * sol.dt),
            sol.steps,
            out.display()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// Locks the output directory `out` (creating it) and removes the earlier run's [`SIM_OUTPUTS`].
pub(crate) fn lock_and_clear(out: &Path) -> Result<pounding::output::OutputLock> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, SIM_OUTPUTS)?;
    Ok(lock)
}

/// Prints a warning to stderr when a compliance law's contact is not resolved by `dt`.
pub(crate) fn warn_time_step(sol: &SimSolution) {
    if let Some(a) = &sol.time_step_advice
        && !a.adequate
    {
        eprintln!(
            "warning: dt = {} s is too coarse for the contact stiffness: the linearised contact \
             lasts {:.3e} s = {:.1} steps; use dt <= {:.2e} s (20 steps per contact)",
            sol.dt, a.contact_duration, a.steps_per_contact, a.max_step
        );
    }
}

/// `x` with `decimals` decimals for `|x| < 1e6`, in exponent form (`1.2346e190`) beyond, and
/// `inf`/`-inf`/`nan` when not finite: a bounded width for the summary line of a diverged run.
fn bounded(x: Real, decimals: usize) -> String {
    if !x.is_finite() {
        float_token(x)
    } else if x.abs() < 1e6 {
        format!("{x:.decimals$}")
    } else {
        format!("{x:.4e}")
    }
}

/// A one-line note on stderr when the given `[time] duration` is not a whole number of steps:
/// the run takes `⌈duration/dt⌉` steps, so it ends after the duration.
fn note_rounded_duration(settings: &pounding::sim::SimSettings) {
    let Some(d) = settings.duration else { return };
    let Ok(n) = settings.step_count(d) else {
        return;
    };
    let end = n as Real * settings.dt;
    if (end - d).abs() > 1e-9 * d {
        // 13 significant digits: 4 × 0.3 reads as 1.2
        let end: Real = format!("{end:.12e}").parse().unwrap_or(end);
        eprintln!(
            "note: duration = {} s is not a multiple of dt = {} s: the run takes {n} steps, to \
             t = {} s",
            float_token(d),
            float_token(settings.dt),
            float_token(end)
        );
    }
}
