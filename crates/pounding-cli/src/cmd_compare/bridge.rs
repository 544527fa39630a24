//! `pounding compare` on a bridge of `[[segment]]`s: each law of `--laws` replaces the law at
//! every joint and abutment (the other keys of the site tables and of `[contact]` apply when the
//! law reads them; a key that no compared law reads is refused first, exit 2). A law that
//! cannot run on this bridge (its build or the model refuses it, e.g. a time step too coarse
//! for its stiffness or a calibration it lacks) is skipped with the reason, on stderr and in
//! `compare.csv`; when every law is refused the first error is reported (exit 2).
//!
//! Writes `compare.csv` and `compare_sites.csv` (library writers,
//! [`pounding::sim::output::bridge_compare_csv`]), the table on stdout, `joint_gap.png` (one
//! panel per joint: its smaller end gap over time, one curve per law; the start abutment's
//! gap when the bridge has no joint) and `timing.json` (last). Exit 1 when a law that ran did
//! not complete.

use super::Args;
use super::plots::{R, panel};
use anyhow::{Context, Result, anyhow, bail};
use pounding::math::Real;
use pounding::output::write_atomic;
use pounding::sim::SimStatus;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output::{
    BRIDGE_COMPARE_OUTPUTS, BridgeCompareRun, COMPARE_OUTPUTS, bridge_compare_csv,
    bridge_compare_sites_csv, bridge_compare_table,
};
use pounding::sim::scenario::{BridgeSetup, Scenario};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// One law: its run and wall time, or why it was skipped.
struct Run {
    law: String,
    outcome: Result<(BridgeSolution, f64), String>,
}

/// Runs the comparison of a bridge scenario `base` (see the module doc).
pub(super) fn run(
    args: &Args,
    laws: &[String],
    base: Scenario,
    t_start: Instant,
) -> Result<ExitCode> {
    let base = base.with_compared_laws(laws);
    base.check_contact_keys()?;
    let mut setups: Vec<Result<BridgeSetup, String>> = Vec::new();
    for l in laws {
        setups.push(match base.clone().with_law(l).build_bridge() {
            Ok(s) => Ok(s),
            Err(e) => Err(e.to_string()),
        });
    }
    if let Some(Err(first)) = setups.first()
        && setups.iter().all(Result::is_err)
    {
        bail!("no law of --laws can run on this bridge: {first}");
    }
    let sizes: Vec<(usize, usize)> = setups
        .iter()
        .flatten()
        .map(|s| {
            let d = s
                .settings
                .duration
                .unwrap_or_else(|| s.problem.ground.end_time());
            let n = s.settings.step_count(d).unwrap_or(usize::MAX);
            (n, s.problem.model.segments.len())
        })
        .collect();
    let dt = setups
        .iter()
        .flatten()
        .next()
        .map_or(1e-3, |s| s.settings.dt);
    let stride = super::fitted_stride(&sizes, dt)?;
    for s in setups.iter_mut().flatten() {
        s.settings.history_stride = stride;
    }
    if let Some(Ok(s)) = setups.iter().find(|s| s.is_ok()) {
        crate::cmd_simulate::sim_records::print_components(&s.problem.ground);
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let mut runs = Vec::new();
    for (l, s) in laws.iter().zip(&setups) {
        let outcome = match s {
            Err(why) => Err(why.clone()),
            Ok(s) => {
                let t = Instant::now();
                // a long law says how long it will take, as a single run does
                let mut s = s.clone();
                s.settings.progress = crate::cmd_simulate::time_estimate();
                s.run()
                    .map(|sol| (sol, t.elapsed().as_secs_f64()))
                    .map_err(|e| e.to_string())
            }
        };
        if let (Ok((sol, _)), Ok(s)) = (&outcome, s) {
            let energy =
                pounding::sim::output::run_warnings(pounding::sim::output::Layout::Bridge, sol);
            if !energy.is_empty() || sol.time_step_advice.is_some_and(|a| !a.adequate) {
                eprintln!("law {l}:");
            }
            crate::cmd_simulate::print_run_warnings(
                &s.problem.ground,
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
    write_outputs(&args.out, &runs, t_start)?;
    let bad: Vec<String> = runs
        .iter()
        .filter_map(|r| match &r.outcome {
            Ok((sol, _)) if sol.status != SimStatus::Completed => {
                Some(format!("{} ({:?})", r.law, sol.status))
            }
            _ => None,
        })
        .collect();
    if !bad.is_empty() {
        eprintln!(
            "error: {} laws ended with a status other than Completed: {}; their results are not \
             trustworthy (see compare.csv, column status)",
            bad.len(),
            bad.join(", ")
        );
        return Ok(ExitCode::FAILURE);
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes the CSV files, the table, the plot and `timing.json` into the locked `out`.
fn write_outputs(out: &Path, runs: &[Run], t_start: Instant) -> Result<()> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, BRIDGE_COMPARE_OUTPUTS)?;
    pounding::output::remove_previous_outputs(&lock, COMPARE_OUTPUTS)?;
    let rows: Vec<(&str, BridgeCompareRun)> = runs
        .iter()
        .map(|r| {
            let run = match &r.outcome {
                Ok((sol, _)) => BridgeCompareRun::Ran(sol),
                Err(why) => BridgeCompareRun::Skipped(why),
            };
            (r.law.as_str(), run)
        })
        .collect();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("compare.csv", bridge_compare_csv(&rows).as_bytes())?;
    wr(
        "compare_sites.csv",
        bridge_compare_sites_csv(&rows).as_bytes(),
    )?;
    print!("{}", bridge_compare_table(&rows));
    plot_gaps(out, runs).map_err(|e| anyhow!("plotting: {e}"))?;
    let mut timing = serde_json::Map::new();
    let mut skipped = serde_json::Map::new();
    for r in runs {
        match &r.outcome {
            Ok((sol, secs)) => {
                timing.insert(
                    r.law.clone(),
                    json!({"simulate_s": secs, "steps": sol.steps}),
                );
            }
            Err(why) => {
                skipped.insert(r.law.clone(), json!(why));
            }
        }
    }
    let timing = json!({
        "laws": timing,
        "skipped": skipped,
        "wall_time_s": t_start.elapsed().as_secs_f64()
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    eprintln!("outputs in {}", out.display());
    Ok(())
}

/// `(t, smaller end gap of joint k)` of a run (`k = None`: the start abutment's gap).
fn gap_series(sol: &BridgeSolution, k: Option<usize>) -> Vec<(Real, Real)> {
    let nj = sol.n_segments - 1;
    sol.t
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            let g = match k {
                Some(k) => {
                    let row = &sol.end_gaps[i * 2 * nj..(i + 1) * 2 * nj];
                    // `min` of a NaN (no corner over the face) and a gap is the gap
                    row[2 * k].min(row[2 * k + 1])
                }
                None => sol.abutment_gaps[i][0].min(sol.abutment_gaps[i][1]),
            };
            (t, g)
        })
        .collect()
}

/// `joint_gap.png`: one panel per joint (the smaller of its two end gaps), a curve per law that
/// ran; a bridge without joints shows its abutments' smaller gap.
fn plot_gaps(out: &Path, runs: &[Run]) -> R {
    crate::plot_style::register();
    let ran: Vec<(&str, &BridgeSolution)> = runs
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok().map(|(s, _)| (r.law.as_str(), s)))
        .collect();
    let nj = ran.first().map_or(0, |(_, s)| s.n_segments - 1);
    let panels: Vec<Option<usize>> = if nj == 0 {
        vec![None]
    } else {
        (0..nj).map(Some).collect()
    };
    let t_end = ran
        .iter()
        .filter_map(|(_, s)| s.t.last().copied())
        .fold(0.0, Real::max)
        .max(1e-9);
    let height = (300 * panels.len()).clamp(450, 3000) as u32;
    crate::plot_style::save_white_png(out, "joint_gap.png", (1200, height), |root| {
        let areas = root.split_evenly((panels.len(), 1));
        for (area, k) in areas.iter().zip(&panels) {
            let curves: Vec<(&str, Vec<(Real, Real)>)> =
                ran.iter().map(|(l, s)| (*l, gap_series(s, *k))).collect();
            let title = match k {
                Some(k) => format!(
                    "Joint {} gap (smaller of the two ends) by contact law",
                    k + 1
                ),
                None => "Abutment gap (smaller of the two) by contact law".to_string(),
            };
            panel(
                area,
                &title,
                "gap [m]",
                (0.0, t_end),
                &curves,
                Some((0.0, "contact")),
            )?;
        }
        Ok(())
    })?;
    Ok(())
}
