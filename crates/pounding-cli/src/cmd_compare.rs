//! `pounding compare`: one scenario, several joint contact laws, side by side.
//!
//! Builds the scenario exactly as `pounding simulate` does (same TOML, same validation), replaces
//! its `[contact] law` by each law of `--laws` in turn (the other `[contact]` keys apply to every
//! law that reads them; one section serves all laws, so a key is refused only when no law of
//! `--laws` reads it: `Scenario::with_compared_laws`), runs [`pounding::sim::simulate`] and
//! writes `compare.csv`, a readable table on stdout, `timing.json` (wall time per law) and two
//! overlay plots: `joint_gap.png` (the smaller joint gap of the two ends) and `contact_force.png`
//! (total joint force of the compliance laws), each with a full-duration panel and a zoom around
//! the largest contact event.
//!
//! A bridge file (`[[segment]]` tables) runs the same way (one [`Setup`] per law, one loop): each
//! law replaces the law at every joint and abutment; a law that cannot run on the bridge is
//! skipped with its reason; its files are written by [`bridge`].

mod bridge;
mod plots;

use crate::cmd_simulate;
use anyhow::{Context, Result, anyhow, bail};
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::Problem;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output::{COMPARE_OUTPUTS, compare_csv, compare_table};
use pounding::sim::scenario::{Scenario, Setup};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `pounding compare`.
#[derive(clap::Args)]
pub struct Args {
    /// Scenario file (TOML, as for `pounding simulate`); without it the built-in default runs.
    pub scenario: Option<PathBuf>,
    /// Contact laws to run, comma separated: `rigid` or any law of `[contact] law` (the registry;
    /// an unknown name is an error listing them). Default: the six of the first release.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "LAW,...",
        default_value = "rigid,kelvin,hertz,hertz-damp,bilinear,jankowski"
    )]
    pub laws: Vec<String>,
    /// Override the scenario's time step `[time] dt` for every law, in seconds.
    #[arg(long, value_name = "DT", allow_hyphen_values = true)]
    pub dt: Option<f64>,
    /// Multiply the scenario's ground-motion scale factors by S for every law (as `simulate
    /// --scale`).
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    pub scale: Option<f64>,
    /// Simulated duration in seconds for every law (as `simulate --duration`; default: the
    /// scenario's `[time] duration`, else the record's length).
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true)]
    pub duration: Option<f64>,
    /// Output directory.
    #[arg(long, value_name = "DIR", default_value = "out/compare")]
    pub out: PathBuf,
}

/// One law: its run and wall time, or why it was skipped (a bridge only: a law that cannot
/// run on it).
struct Run {
    law: String,
    outcome: Result<(BridgeSolution, f64), String>,
}

/// A law that ran (the two-deck outputs: every law runs).
pub(crate) struct Ran<'a> {
    law: &'a str,
    sol: &'a BridgeSolution,
    secs: f64,
}

/// Runs `pounding compare`: checks `--laws` and `--dt`, builds and validates every law's run
/// before running any, runs them, writes the outputs, and exits 1 if a run did not complete.
pub fn run(args: Args) -> Result<ExitCode> {
    let t_start = Instant::now();
    let laws = parse_laws(&args.laws)?;
    if let Some(dt) = args.dt
        && !(dt.is_finite() && dt > 0.0)
    {
        bail!("invalid --dt {}: must be finite and > 0", float_token(dt));
    }
    let mut base = cmd_simulate::load_scenario(args.scenario.as_deref())?;
    if let Some(dt) = args.dt {
        // the scenario's own checks (step within the run, step count, restrainers) apply to it
        base = base.with_dt(dt);
    }
    // checked with the scenario, naming the flags, as for `simulate`
    if let Some(x) = args.scale {
        base = base.with_scale(x);
    }
    if let Some(d) = args.duration {
        base = base.with_duration(d);
    }
    let bridge = base.is_bridge();
    let setups = build_setups(&laws, base)?;
    if let Some(Ok(s)) = setups.iter().find(|s| s.is_ok()) {
        crate::cmd_simulate::sim_records::print_components(s.ground());
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let runs = run_laws(&laws, &setups);
    // the two-deck model runs every law or none (a bridge skips a law it refuses)
    if let (false, Some(Err(why))) = (bridge, runs.iter().map(|r| &r.outcome).find(|o| o.is_err()))
    {
        bail!("{why}");
    }
    if bridge {
        bridge::write_outputs(&args.out, &runs, t_start)?;
    } else {
        let ran: Vec<Ran> = runs
            .iter()
            .filter_map(|r| {
                let (sol, secs) = r.outcome.as_ref().ok()?;
                Some(Ran {
                    law: &r.law,
                    sol,
                    secs: *secs,
                })
            })
            .collect();
        let gap0 = match setups.iter().flatten().next() {
            Some(Setup::TwoDecks(s)) => s.problem.model.gap,
            _ => 0.0,
        };
        write_outputs(&args.out, &ran, gap0, t_start)?;
    }
    // Like `simulate`: a law whose run did not complete is written, then reported with exit 1.
    let bad: Vec<String> = runs
        .iter()
        .filter_map(|r| match &r.outcome {
            Ok((sol, _)) if sol.status != pounding::sim::SimStatus::Completed => {
                Some(format!("{} ({:?})", r.law, sol.status))
            }
            _ => None,
        })
        .collect();
    if !bad.is_empty() {
        eprintln!(
            "error: {} of {} laws ended with a status other than Completed: {}; their results are not \
             trustworthy (see compare.csv, column status)",
            bad.len(),
            runs.len(),
            bad.join(", ")
        );
        return Ok(ExitCode::FAILURE);
    }
    Ok(ExitCode::SUCCESS)
}

/// The `--laws` list, trimmed: every name registered, none twice, not empty.
fn parse_laws(given: &[String]) -> Result<Vec<String>> {
    let names = pounding::contact_law::registry::law_names();
    let mut laws: Vec<String> = Vec::new();
    for l in given {
        let l = l.trim().to_string();
        if !names.contains(&l.as_str()) {
            bail!(
                "unknown contact law {l:?} in --laws: use one of {}",
                names.join(", ")
            );
        }
        if laws.contains(&l) {
            bail!("contact law {l:?} is given twice in --laws");
        }
        laws.push(l);
    }
    if laws.is_empty() {
        bail!("--laws is empty");
    }
    Ok(laws)
}

/// Every law's validated setup (scenario with the law, `--dt`, a history sample per 0.5 ms for
/// the plots), with the rules of `simulate` (a step no longer than the run, not too many steps)
/// and the memory of all histories together within the limit. A `[contact]` key that no law of
/// `laws` reads is refused first (`Scenario::check_contact_keys` after `with_compared_laws`).
/// A law that cannot be built is an error for the two-deck model; on a bridge it is skipped with
/// its reason (its sites may refuse it: a time step too coarse for its stiffness, a calibration
/// it lacks), unless every law is.
fn build_setups(laws: &[String], base: Scenario) -> Result<Vec<Result<Setup, String>>> {
    let bridge = base.is_bridge();
    let base = base.with_compared_laws(laws);
    base.check_contact_keys()?;
    let mut setups = Vec::new();
    for l in laws {
        setups.push(match base.clone().with_law(l).build_setup() {
            Ok(s) => Ok(s),
            Err(e) if bridge => Err(e.to_string()),
            Err(e) => return Err(anyhow::Error::new(e).context(format!("contact law {l:?}"))),
        });
    }
    if let Some(Err(first)) = setups.first()
        && setups.iter().all(Result::is_err)
    {
        bail!("no law of --laws can run on this bridge: {first}");
    }
    let mut sizes = Vec::new();
    for s in setups.iter().flatten() {
        let d = s
            .settings()
            .duration
            .unwrap_or_else(|| s.ground().end_time());
        let n = match s {
            Setup::TwoDecks(_) => s.settings().step_count(d).map_err(|e| anyhow!("{e}"))?,
            Setup::Bridge(_) => s.settings().step_count(d).unwrap_or(usize::MAX),
        };
        sizes.push((n, s.model().segments.len()));
    }
    let dt = setups
        .iter()
        .flatten()
        .next()
        .map_or(1e-3, |s| s.settings().dt);
    let stride = fitted_stride(&sizes, dt)?;
    for s in setups.iter_mut().flatten() {
        s.settings_mut().history_stride = stride;
    }
    Ok(setups)
}

/// The history stride of the compared runs: a sample per 0.5 ms ([`plot_stride`]) when every
/// law's history fits in memory together, else the finest that fits (said on stderr; the
/// scenario's `history_every` is not used: the overlay plots need their own sampling).
pub(crate) fn fitted_stride(sizes: &[(usize, usize)], dt: Real) -> Result<usize> {
    let fine = plot_stride(dt);
    let stride =
        pounding::sim::options::runs_history_stride(sizes, fine).map_err(|e| anyhow!(e))?;
    if stride > fine {
        eprintln!(
            "note: the {} runs keep a history sample every {} s (not every 0.5 ms) to fit in memory",
            sizes.len(),
            float_token(stride as Real * dt)
        );
    }
    Ok(stride)
}

/// A history sample per 0.5 ms (the overlay plots).
pub(crate) fn plot_stride(dt: Real) -> usize {
    ((5e-4 / dt).floor() as usize).max(1)
}

/// Runs every law in turn, reporting each on stderr (steps, time, status, time-step warnings,
/// or why it was skipped).
fn run_laws(laws: &[String], setups: &[Result<Setup, String>]) -> Vec<Run> {
    let mut runs = Vec::new();
    for (l, s) in laws.iter().zip(setups) {
        let outcome = match s {
            Err(why) => Err(why.clone()),
            Ok(s) => {
                let t = Instant::now();
                // a long law says how long it will take, as a single run does
                let mut s = s.clone();
                s.settings_mut().progress = cmd_simulate::time_estimate();
                s.run()
                    .map(|sol| (sol, t.elapsed().as_secs_f64()))
                    .map_err(|e| format!("law {l:?}: {e}"))
            }
        };
        if let (Ok((sol, _)), Ok(s)) = (&outcome, s) {
            let energy = s.run_warnings(sol);
            if !energy.is_empty() || sol.time_step_advice.is_some_and(|a| !a.adequate) {
                eprintln!("law {l}:");
            }
            cmd_simulate::print_run_warnings(
                s.ground(),
                sol.dt,
                sol.time_step_advice.as_ref(),
                &energy,
            );
        }
        match &outcome {
            Ok((sol, secs)) => eprintln!(
                "{l}: {} steps in {:.1} ms ({:?})",
                sol.steps,
                secs * 1e3,
                sol.status
            ),
            Err(why) => eprintln!("skipped law {l}: {why}"),
        }
        runs.push(Run {
            law: l.clone(),
            outcome,
        });
    }
    runs
}

/// Writes `compare.csv`, the table on stdout, the plots and `timing.json` into the locked `out`.
fn write_outputs(out: &Path, runs: &[Ran], gap0: Real, t_start: Instant) -> Result<()> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, COMPARE_OUTPUTS)?;
    let rows: Vec<(&str, &BridgeSolution)> = runs.iter().map(|r| (r.law, r.sol)).collect();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("compare.csv", compare_csv(&rows).as_bytes())?;
    print!("{}", compare_table(&rows));
    plots::plots(out, runs, gap0).map_err(|e| anyhow!("plotting: {e}"))?;
    let mut timing = serde_json::Map::new();
    for r in runs {
        timing.insert(
            r.law.to_string(),
            json!({"simulate_s": r.secs, "steps": r.sol.steps}),
        );
    }
    let timing = json!({"laws": timing, "wall_time_s": t_start.elapsed().as_secs_f64()});
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    eprintln!("outputs in {}", out.display());
    Ok(())
}
