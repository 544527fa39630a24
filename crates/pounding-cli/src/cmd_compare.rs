//! `pounding compare`: one scenario, several joint contact laws, side by side.
//!
//! The comparison is the library's ([`pounding::sim::compare`]): the scenario is built exactly as
//! `pounding simulate` builds it (same TOML, same validation), its `[contact] law` replaced by
//! each law of `--laws` in turn, and every law runs through [`pounding::sim::simulate`]. This
//! front end prints each law's progress and warnings, writes `compare.csv`, a readable table on
//! stdout, two overlay plots — `joint_gap.png` (the smaller joint gap of the two ends) and
//! `contact_force.png` (total joint force of the compliance laws), each with a full-duration
//! panel and a zoom around the largest contact event —, `report.html` ([`crate::compare_report`])
//! and `timing.json` (wall time per law, last).
//!
//! A bridge file (`[[segment]]` tables) runs the same way: each law replaces the law at every
//! joint and abutment; a law that cannot run on the bridge is skipped with its reason; its files
//! are written by [`bridge`].

mod bridge;
mod plots;

use crate::cmd_simulate;
use crate::compare_report::Job;
use anyhow::{Context, Result, anyhow};
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::compare::{CompareFlags, Comparison, LawRun, not_completed};
use pounding::sim::output::{compare_outputs, compare_tables};
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

impl Args {
    /// The command-line replacements as given (for the report).
    fn flag_list(&self) -> Vec<String> {
        let mut out = vec![format!("--laws {}", self.laws.join(","))];
        for (name, v) in [
            ("--dt", self.dt),
            ("--scale", self.scale),
            ("--duration", self.duration),
        ] {
            if let Some(v) = v {
                out.push(format!("{name} {}", float_token(v)));
            }
        }
        out
    }
}

/// A law that ran (the plots' view).
pub(crate) struct Ran<'a> {
    law: &'a str,
    sol: &'a BridgeSolution,
}

/// Runs `pounding compare`: checks `--laws` and `--dt`, builds and validates every law's run
/// before running any, runs them, writes the outputs, and exits 1 if a run did not complete.
pub fn run(args: Args) -> Result<ExitCode> {
    let t_start = Instant::now();
    let flags = CompareFlags {
        laws: args.laws.clone(),
        dt: args.dt,
        scale: args.scale,
        duration: args.duration,
    };
    flags.check()?;
    let base = cmd_simulate::load_scenario(args.scenario.as_deref())?;
    let (origin, text) = (base.origin().to_string(), base.text().to_string());
    pounding::assessment::check_tables(&base, None)?;
    let tables = base.clone();
    let cmp = Comparison::prepare(base, &flags)?;
    if let Some(s) = cmp.first_setup() {
        // [code_check] against the bridge before any run, as simulate does
        pounding::assessment::check_tables(
            &tables,
            Some(pounding::sim::Problem::model(s).segments.len()),
        )?;
    }
    if cmp.stride_coarsened {
        let dt = cmp.first_setup().map_or(1e-3, |s| s.settings().dt);
        eprintln!(
            "note: the {} runs keep a history sample every {} s (not every 0.5 ms) to fit in memory",
            cmp.setups.iter().flatten().count(),
            float_token(cmp.history_stride as Real * dt)
        );
    }
    if let Some(s) = cmp.first_setup() {
        crate::cmd_simulate::sim_records::print_components(pounding::sim::Problem::ground(s));
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let runs = cmp.run(cmd_simulate::time_estimate, report_law)?;
    let ctx = Job {
        out: &args.out,
        runs: &runs,
        scenario: (&origin, &text),
        flags: args.flag_list(),
        t_start,
    };
    if cmp.bridge {
        write_outputs(&ctx, true, |out| bridge::draw(out, &runs))?;
    } else {
        let gap0 = cmp
            .first_setup()
            .and_then(|s| s.form.two_decks())
            .map_or(0.0, |m| m.gap);
        write_outputs(&ctx, false, |out| draw(out, &runs, gap0))?;
    }
    // Like `simulate`: a law whose run did not complete is written, then reported with exit 1.
    let bad = not_completed(&runs);
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

/// Reports a law on stderr: its warnings (but the record's PGA, said once with the records),
/// then its steps, time and status, or why it was skipped.
fn report_law(r: &LawRun) {
    let l = &r.law;
    match &r.outcome {
        Ok(ran) => {
            let shown: Vec<_> = ran
                .warnings
                .iter()
                .filter(|w| w.kind != "record_pga_implausible")
                .collect();
            let energy = shown.iter().any(|w| w.kind == "energy_created");
            let coarse = shown.iter().any(|w| w.kind == "time_step_coarse");
            if energy || coarse {
                eprintln!("law {l}:");
            }
            for w in shown {
                eprintln!("warning: {}", w.message);
            }
            eprintln!(
                "{l}: {} steps in {:.1} ms ({:?})",
                ran.sol.steps,
                ran.seconds * 1e3,
                ran.sol.status
            );
        }
        Err(why) => eprintln!("skipped law {l}: {why}"),
    }
}

/// `timing.json`: the wall time and steps of each law that ran, the skipped laws (a bridge) and
/// the whole command's wall time.
pub(crate) fn timing_json(ctx: &Job, with_skipped: bool) -> Result<String> {
    let mut timing = serde_json::Map::new();
    let mut skipped = serde_json::Map::new();
    for r in ctx.runs {
        match &r.outcome {
            Ok(ran) => {
                timing.insert(
                    r.law.clone(),
                    json!({"simulate_s": ran.seconds, "steps": ran.sol.steps}),
                );
            }
            Err(why) => {
                skipped.insert(r.law.clone(), json!(why));
            }
        }
    }
    let mut t = json!({"laws": timing});
    if with_skipped {
        t["skipped"] = json!(skipped);
    }
    t["wall_time_s"] = json!(ctx.t_start.elapsed().as_secs_f64());
    Ok(serde_json::to_string_pretty(&t)? + "\n")
}

/// Writes `name` into `out` atomically.
pub(crate) fn write(out: &Path, name: &str, bytes: &[u8]) -> Result<()> {
    write_atomic(&out.join(name), bytes)
        .with_context(|| format!("cannot write {}", out.join(name).display()))
}

/// The one writer of a comparison's files, either form: locks `out`, clears every file a
/// comparison of either form writes, writes the library's tables ([`compare_tables`]: the
/// CSV files and the table on stdout), then the figures `draw` makes (file, caption), then
/// `report.html` and `timing.json` (last; with the skipped laws for a bridge).
fn write_outputs(
    ctx: &Job,
    bridge: bool,
    draw: impl FnOnce(&Path) -> Result<Vec<(&'static str, String)>>,
) -> Result<()> {
    let out = ctx.out;
    let lock = pounding::output::lock_output_dir(out)?;
    let previous: Vec<&str> = compare_outputs().collect();
    pounding::output::remove_previous_outputs(&lock, &previous)?;
    let (tables, text) = compare_tables(ctx.runs, bridge);
    for t in &tables {
        write(out, t.name, t.csv.as_bytes())?;
    }
    print!("{text}");
    let figures = draw(out)?;
    let figures: Vec<(&str, &str)> = figures.iter().map(|(f, c)| (*f, c.as_str())).collect();
    let mut files: Vec<&str> = tables.iter().map(|t| t.name).collect();
    files.push("timing.json");
    let page = crate::compare_report::Page {
        ctx,
        files: &files,
        tables: tables.into_iter().map(|t| (t.title, t.csv)).collect(),
        figures: &figures,
    };
    write(
        out,
        "report.html",
        crate::compare_report::html(&page).as_bytes(),
    )?;
    write(out, "timing.json", timing_json(ctx, bridge)?.as_bytes())?;
    eprintln!("outputs in {}", out.display());
    drop(lock);
    Ok(())
}

/// The two-deck figures, `joint_gap.png` and `contact_force.png`, of every law that ran.
fn draw(out: &Path, runs: &[LawRun], gap0: Real) -> Result<Vec<(&'static str, String)>> {
    let ran: Vec<Ran> = runs
        .iter()
        .filter_map(|r| {
            Some(Ran {
                law: &r.law,
                sol: &r.ran()?.sol,
            })
        })
        .collect();
    plots::plots(out, &ran, gap0).map_err(|e| anyhow!("plotting: {e}"))?;
    Ok(vec![
        (
            "joint_gap.png",
            "Joint gap (the smaller of the two ends) by contact law: the whole run and a zoom \
             around the largest contact event."
                .into(),
        ),
        (
            "contact_force.png",
            "Total joint contact force of the compliance laws (rigid contact has impulses only: \
             its estimate is in the table)."
                .into(),
        ),
    ])
}
