//! One run of `pounding simulate`, of either scenario form (two decks or a bridge of
//! `[[segment]]`s; [`pounding::sim::scenario::Setup`]): runs it with the library, writes
//! `history.csv`, `impacts.csv`, `summary.json`, the force tables, the figures (the two-deck
//! model's [`crate::plots::two_deck`], a bridge's [`crate::plots::bridge`] and its
//! `trajectories.json`), `report.html` and `timing.json` (last), and prints a summary.

use super::{Args, lock_and_clear};
use crate::plots::two_deck;
use anyhow::{Context, Result, anyhow};
use pounding::output::{bounded, float_token, write_atomic};
use pounding::sim::Problem;
use pounding::sim::SimStatus;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output::describe_contact;
use pounding::sim::scenario::{Form, Setup};
use serde_json::json;
use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

/// Runs `setup` (single run) and writes its files; `scenario` is its name and text.
pub fn run(
    args: &Args,
    mut setup: Setup,
    scenario: (&str, &str),
    t_start: Instant,
) -> Result<ExitCode> {
    super::sim_records::print_components(setup.ground());
    pounding::output::check_output_dir_free(&args.out)?;
    super::note_rounded_duration(setup.settings());
    setup.settings_mut().progress = super::time_estimate();
    let t_sim = Instant::now();
    let (sol, accuracy) = match super::accuracy_settings(args) {
        None => (setup.run().map_err(|e| anyhow!("{e}"))?, None),
        Some(a) => {
            let (sol, run) = pounding::sim::accuracy::run_with_estimate(&setup, a, |dt| {
                eprintln!("accuracy: running dt = {} s", float_token(dt));
                super::time_estimate()
            })
            .map_err(|e| anyhow!("{e}"))?;
            // the answer's step and history interval, for the files written from `setup`
            let k = run.chosen;
            setup.settings_mut().dt = run.dts[k];
            setup.settings_mut().history_stride <<= k;
            (sol, Some(run))
        }
    };
    let sim_secs = t_sim.elapsed().as_secs_f64();
    super::print_run_warnings(
        setup.ground(),
        sol.dt,
        sol.time_step_advice.as_ref(),
        &setup.run_warnings(&sol),
    );
    let out = &args.out;
    let _lock = lock_and_clear(out)?;
    let t_write = Instant::now();
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("history.csv", setup.history(&sol).csv().as_bytes())?;
    wr("impacts.csv", setup.impacts_csv(&sol).as_bytes())?;
    // a bridge with [code_check]: the check of its scenario, in summary.json, on stderr and in
    // the report beside the run's seat demand
    let check = match &setup.form {
        Form::Bridge => {
            pounding::assessment::check_summary::scenario_check(&setup.run.problem.model, scenario)
        }
        Form::TwoDecks(_) => None,
    };
    let summary =
        pounding::assessment::check_summary::run_summary_json_text(&setup, &sol, scenario);
    wr("summary.json", summary.as_bytes())?;
    if let Some(run) = &accuracy {
        wr("accuracy.csv", run.csv().as_bytes())?;
        let text = serde_json::to_string_pretty(&run.json())? + "\n";
        wr("accuracy.json", text.as_bytes())?;
    }
    let tables = sol.tables();
    for t in &tables {
        wr(&t.file_name(), t.csv().as_bytes())?;
    }
    let mut files: Vec<String> = ["summary.json", "history.csv", "impacts.csv"]
        .map(String::from)
        .into();
    if accuracy.is_some() {
        files.extend(["accuracy.csv", "accuracy.json"].map(String::from));
    }
    // the plan animation of either form (the two-deck model's is its two-segment bridge)
    let traj = setup.trajectories_json(&sol);
    wr("trajectories.json", traj.as_bytes())?;
    files.push("trajectories.json".into());
    let (what, figures) = match &setup.form {
        Form::TwoDecks(model) => {
            let run = two_deck::TwoDeckRun {
                model,
                bridge: &setup.run.problem.model,
                ground: &setup.run.problem.ground,
            };
            two_deck::write_all(out, &run, &sol).map_err(|e| anyhow!("plotting: {e}"))?;
            ("two decks".to_string(), two_deck::FIGURES.to_vec())
        }
        Form::Bridge => {
            let figures = crate::plots::bridge::write_all(out, &setup.run.problem.model, &sol)
                .map_err(|e| anyhow!("plotting: {e}"))?;
            let n = sol.n_segments;
            let what = format!("a bridge of {n} segment{}", if n == 1 { "" } else { "s" });
            (what, figures)
        }
    };
    let code_check = crate::sim_report_check::section(check.as_ref(), &sol.summary.seats);
    // every table of the run, as written above
    files.extend(tables.iter().map(|t| t.file_name()));
    let files: Vec<&str> = files.iter().map(String::as_str).collect();
    super::write_report(
        args,
        what,
        scenario,
        &summary,
        &figures,
        &files,
        (
            Some(&traj),
            &tables,
            code_check,
            &pounding::sim::output::verdict(setup.layout(), &sol),
        ),
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
    print_summary(&setup, &sol, sim_secs, out);
    match &check {
        Some(Ok(r)) => eprintln!(
            "code check: {}",
            pounding::assessment::check_summary::verdict_sentence(r, &sol.summary.seats)
        ),
        Some(Err(e)) => eprintln!("code check: not evaluated: {e}"),
        None => {}
    }
    if let Some(run) = &accuracy
        && let Some(code) = super::sim_accuracy::print(run, out)
    {
        return Ok(code);
    }
    if sol.status != SimStatus::Completed {
        // outputs are written (they show where the run went wrong), but the run did not succeed
        let hint = match sol.status {
            SimStatus::CompletedWithLcpFailures
                if sol.summary.projection.is_some_and(|p| p.failures > 0) =>
            {
                "summary.json (lcp_failures, projection.failures)"
            }
            SimStatus::CompletedWithLcpFailures => "summary.json (lcp_failures)",
            _ => "summary.json (energies, peaks)",
        };
        eprintln!(
            "error: simulation status {:?} after {} s ({} steps): the results are not trustworthy; \
             see {hint} and history.csv in {}",
            sol.status,
            float_token(pounding::sim::step_time(sol.steps, sol.dt)),
            sol.steps,
            out.display()
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// The summary lines on stderr: the two-deck model's joint, or every joint of a bridge and its
/// governing seat.
fn print_summary(setup: &Setup, sol: &BridgeSolution, sim_secs: f64, out: &Path) {
    let s = &sol.summary;
    let duration = float_token(pounding::sim::step_time(sol.steps, sol.dt));
    match &setup.form {
        Form::TwoDecks(pair) => {
            eprintln!(
                "simulated {duration} s in {} steps ({:.1} ms): {} impacts, peak closing {} m, \
                 opening {} m, seat displacement {} m{}, energy balance error {:.1e}; outputs in {}",
                sol.steps,
                sim_secs * 1e3,
                s.impacts,
                bounded(s.joints[0].peak_closing, 4),
                bounded(s.joints[0].peak_opening, 4),
                bounded(s.peak_seat_displacement, 4),
                match s.unseating_time {
                    Some(t) => format!(" (UNSEATED at {} s)", bounded(t, 3)),
                    None => String::new(),
                },
                s.energy_balance_error,
                out.display()
            );
            if let Some(f) = s.joints[0].peak_contact_force {
                eprintln!(
                    "contact law {}: peak contact force {} MN, peak penetration {} mm",
                    describe_contact(&pair.contact)["law"],
                    bounded(f / 1e6, 4),
                    bounded(s.peak_penetration * 1e3, 4)
                );
            }
        }
        Form::Bridge => {
            // at most the first 8 joints on the line (a 200-segment bridge's 199 joints are in
            // summary.json)
            const SHOWN: usize = 8;
            let mut joints: Vec<String> = s
                .joints
                .iter()
                .take(SHOWN)
                .map(|j| format!("{} (closing {} m)", j.impacts, bounded(j.peak_closing, 4)))
                .collect();
            if s.joints.len() > SHOWN {
                joints.push(format!("… {} more in summary.json", s.joints.len() - SHOWN));
            }
            eprintln!(
                "simulated a bridge of {} segments for {duration} s in {} steps ({:.1} ms): {} \
                 impacts; per joint: {}{}; energy balance error {:.1e}{}; outputs in {}",
                sol.n_segments,
                sol.steps,
                sim_secs * 1e3,
                s.impacts,
                if joints.is_empty() {
                    "none".into()
                } else {
                    joints.join(", ")
                },
                abutment_impacts(s),
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
        }
    }
}

/// `; per abutment: start 8, end 9` (the impacts at the bridge's abutments), or nothing.
fn abutment_impacts(s: &pounding::sim::bridge::BridgeSummary) -> String {
    let sites: Vec<String> = s
        .abutments
        .iter()
        .zip(["start", "end"])
        .filter_map(|(a, side)| a.as_ref().map(|a| format!("{side} {}", a.impacts)))
        .collect();
    if sites.is_empty() {
        String::new()
    } else {
        format!("; per abutment: {}", sites.join(", "))
    }
}
