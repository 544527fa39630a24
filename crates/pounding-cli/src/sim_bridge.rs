//! `pounding simulate` of a bridge of `[[segment]]`s: builds the run with the library, writes
//! `history.csv`, `impacts.csv`, `summary.json`, the figures (`joint_openings.png`,
//! `displacements.png`, `plan.png`, `energy.png`; [`crate::plots::bridge`]) and `timing.json`
//! (last) and prints a summary; with `--records`, the batch of
//! [`super::sim_batch::run_bridge`].

use super::{Args, lock_and_clear};
use anyhow::{Context, Result, anyhow};
use pounding::output::{bounded, float_token, write_atomic};
use pounding::sim::SimStatus;
use pounding::sim::output::{
    History, Layout, bridge_summary_json_text, bridge_trajectories_json, impacts_csv,
};
use pounding::sim::scenario::Scenario;
use serde_json::json;
use std::process::ExitCode;
use std::time::Instant;

/// Runs a bridge scenario (single run).
pub fn run(args: &Args, sc: Scenario, t_start: Instant) -> Result<ExitCode> {
    let (origin, text) = (sc.origin().to_string(), sc.text().to_string());
    pounding::assessment::FragilitySettings::check_if_present(&text, &origin)?;
    let sc = super::with_flags(sc, args);
    if !args.records.is_empty() {
        let reading = sc.override_reading(args.csv_units)?;
        let setup = sc.build_bridge()?;
        return super::sim_batch::run_bridge(args, &setup, &reading, t_start);
    }
    let mut setup = sc.build_bridge()?;
    super::sim_records::print_components(&setup.problem.ground);
    pounding::output::check_output_dir_free(&args.out)?;
    super::note_rounded_duration(&setup.settings);
    setup.settings.progress = super::time_estimate();
    let t_sim = Instant::now();
    let sol = setup.run().map_err(|e| anyhow!("{e}"))?;
    let sim_secs = t_sim.elapsed().as_secs_f64();
    super::print_run_warnings(
        &setup.problem.ground,
        sol.dt,
        sol.time_step_advice.as_ref(),
        &pounding::sim::output::run_warnings(Layout::Bridge, &sol),
    );
    let out = &args.out;
    let _lock = lock_and_clear(out)?;
    let t_write = Instant::now();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    let abutments = setup.problem.model.abutments.map(|a| a.is_some());
    let history = History::new(Layout::Bridge, &sol, &setup.problem.ground, abutments);
    wr("history.csv", history.csv().as_bytes())?;
    wr(
        "impacts.csv",
        impacts_csv(Layout::Bridge, &setup.problem.model, &sol).as_bytes(),
    )?;
    let summary = bridge_summary_json_text(&setup, &sol);
    wr("summary.json", summary.as_bytes())?;
    let traj = bridge_trajectories_json(&setup, &sol);
    wr("trajectories.json", traj.as_bytes())?;
    for t in &sol.tables {
        wr(&t.file_name(), t.csv().as_bytes())?;
    }
    crate::plots::bridge::write_all(out, &setup.problem.model, &sol)
        .map_err(|e| anyhow!("plotting: {e}"))?;
    let n = sol.n_segments;
    super::write_report(
        args,
        format!("a bridge of {n} segment{}", if n == 1 { "" } else { "s" }),
        (&origin, &text),
        &summary,
        crate::plots::bridge::FIGURES,
        &[
            "summary.json",
            "history.csv",
            "impacts.csv",
            "trajectories.json",
            "bearings.csv",
            "restrainers.csv",
            "joint_slip.csv",
        ],
        (Some(&traj), &sol.tables),
    )?;
    let timing = json!({
        "simulate_s": sim_secs,
        "write_s": t_write.elapsed().as_secs_f64(),
        "wall_time_s": t_start.elapsed().as_secs_f64(),
        "steps": sol.steps,
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    let s = &sol.summary;
    let joints: Vec<String> = s
        .joints
        .iter()
        .map(|j| format!("{} (closing {} m)", j.impacts, bounded(j.peak_closing, 4)))
        .collect();
    eprintln!(
        "simulated a bridge of {} segments for {} s in {} steps ({:.1} ms): {} impacts; per joint: \
         {}; energy balance error {:.1e}{}; outputs in {}",
        sol.n_segments,
        float_token(pounding::sim::step_time(sol.steps, sol.dt)),
        sol.steps,
        sim_secs * 1e3,
        s.impacts,
        if joints.is_empty() {
            "none".into()
        } else {
            joints.join(", ")
        },
        s.energy_balance_error,
        match (&s.unseated_end, s.unseating_time) {
            (Some(e), Some(t)) => format!(" (UNSEATED: {e} at {t:.3} s)"),
            _ => String::new(),
        },
        out.display()
    );
    if let Some(g) = pounding::sim::output::governing_seat_line(s) {
        eprintln!("governing seat: {g}");
    }
    if sol.status != SimStatus::Completed {
        eprintln!(
            "error: simulation status {:?} after {} s ({} steps): the results are not trustworthy; \
             see summary.json and history.csv in {}",
            sol.status,
            float_token(pounding::sim::step_time(sol.steps, sol.dt)),
            sol.steps,
            out.display()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}
