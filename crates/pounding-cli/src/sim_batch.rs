//! Batch mode of `pounding simulate` (`--records … --scales …`, or `--set MANIFEST`: the
//! entries of a record-set manifest, pairs along y and x): every (record, scale) pair in
//! parallel ([`pounding::sim::batch`]), a progress bar on a terminal, `batch.csv` (one row per
//! run), `batch.png` (peak response against PGA per record) and `timing.json`.
//!
//! A record that cannot be read is reported in its rows (`status = error`, `error` = the message
//! naming the file) and in the final message; every other run is still done and written, and the
//! exit code is 1. A run that ends with a status other than `Completed` (e.g. `Diverged`) is
//! written and also makes the exit code 1.

use super::Args;
use super::sim_records::count;
use crate::plots::sim_batch::{BatchCurve, batch_plot};
use anyhow::{Context, Result, anyhow};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::ground_motion::set::RecordSet;
use pounding::ground_motion::{ComponentInfo, G0, ReadOptions, Record};
use pounding::math::Real;
use pounding::output::write_atomic;
use pounding::shard::Shard;
use pounding::sim::Problem;
use pounding::sim::batch::{BatchOutcome, BatchRecord, BatchRow, run_batch};
use pounding::sim::output::{batch_csv, batch_set_csv};
use pounding::sim::scenario::Setup;
use pounding::sim::{SimSettings, SimStatus};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Degrees per radian (as in `summary.json`).
const DEG: Real = 180.0 / std::f64::consts::PI;

/// What every batch needs before its runs: the records (read), the record set they come from
/// (`--set`), the scales, the shard, the worker pool and the progress bar (the plan is printed;
/// the output directory is checked).
struct Plan {
    records: Vec<BatchRecord>,
    set: Option<RecordSet>,
    scales: Vec<Real>,
    shard: Shard,
    pool: rayon::ThreadPool,
    pb: ProgressBar,
}

/// The entries of the batch: the records of `--records` (one component each; an unreadable one
/// is kept with its error), or the entries of the `--set` manifest (all read, or an error
/// naming the manifest, key and line) and the set; each component's line printed.
fn entries(args: &Args, reading: &ReadOptions) -> Result<(Vec<BatchRecord>, Option<RecordSet>)> {
    if let Some(m) = &args.set {
        let set = RecordSet::load_with_units(m, reading.units, &reading.units_from)?;
        for e in &set.records {
            super::sim_records::print_component(&ComponentInfo::of("y", &e.x));
            if let Some(y) = &e.y {
                super::sim_records::print_component(&ComponentInfo::of("x", y));
            }
        }
        return Ok((BatchRecord::of_set(&set), Some(set)));
    }
    let paths = super::sim_records::expand_records(&args.records)?;
    let records: Vec<BatchRecord> = paths
        .iter()
        .map(|p| {
            BatchRecord::single(
                p.display().to_string(),
                Record::open_with(p, reading).map_err(|e| e.to_string()),
            )
        })
        .collect();
    for r in &records {
        if let Ok(rec) = &r.record {
            super::sim_records::print_component(&ComponentInfo::of("y", rec));
        }
    }
    Ok((records, None))
}

/// Refuses, before the batch is announced, support-motion entries that no run of `setup` could
/// take (a two-deck scenario, a scenario with its own wave passage, a bridge the supports do not
/// match): the error names the manifest, the entry's `supports` key and its line.
fn check_supports(setup: &Setup, records: &[BatchRecord], manifest: Option<&Path>) -> Result<()> {
    match manifest {
        Some(m) => pounding::sim::batch_supports::check_set_supports(
            setup,
            records,
            m,
            setup_origin(setup),
        ),
        None => pounding::sim::batch::check_support_entries(setup, records),
    }
    .map_err(|e| anyhow!("{e}"))
}

/// The scenario a batch runs, as its messages name it.
fn setup_origin(setup: &Setup) -> &'static str {
    if setup.layout() == pounding::sim::output::Layout::TwoDecks {
        "a two-deck scenario"
    } else {
        "this bridge scenario"
    }
}

/// Parses and checks the batch flags, reads the records and prints the plan.
fn plan(args: &Args, setup: &Setup, reading: &ReadOptions) -> Result<Plan> {
    let scales = if args.scales.is_empty() {
        vec![1.0]
    } else {
        args.scales.clone()
    };
    let shard = match &args.shard {
        Some(s) => Shard::parse(s)?,
        None => Shard::ALL,
    };
    pounding::input::check_threads(args.threads).map_err(anyhow::Error::msg)?;
    let (records, set) = entries(args, reading)?;
    pounding::sim::batch::validate_lists(&records, &scales).map_err(|e| anyhow!("{e}"))?;
    check_supports(setup, &records, args.set.as_deref())?;
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = args.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let total = records.len() * scales.len();
    let todo = (0..total).filter(|&i| shard.contains(i)).count();
    let what = match (&set, &args.set) {
        (Some(set), Some(m)) => format!(
            "{} ({} pairs) of {}",
            count(set.records.len(), "entry").replace("entrys", "entries"),
            set.records.iter().filter(|e| e.y.is_some()).count(),
            m.display()
        ),
        _ => count(records.len(), "record"),
    };
    eprintln!(
        "batch: {} x {} = {}{} on {}",
        what,
        count(scales.len(), "scale"),
        count(total, "run"),
        if shard == Shard::ALL {
            String::new()
        } else {
            format!(
                " (shard {}/{}: {})",
                shard.index,
                shard.count,
                count(todo, "run")
            )
        },
        count(pool.current_num_threads(), "thread")
    );
    // indicatif draws nothing when stderr is not a terminal.
    let pb = ProgressBar::with_draw_target(Some(todo as u64), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("runs [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta} left)")
    {
        pb.set_style(style);
    }
    pounding::output::check_output_dir_free(&args.out)?;
    Ok(Plan {
        records,
        set,
        scales,
        shard,
        pool,
        pb,
    })
}

/// Writes `batch.csv` (`csv`), `batch.png` (`curves`; the seat panel is each run's governing
/// seat ratio, its unseating line at 1) and `timing.json` into `--out`.
fn write_outputs(
    args: &Args,
    plan: &Plan,
    csv: &str,
    curves: &[BatchCurve],
    (runs, runs_secs, t_start): (usize, f64, Instant),
) -> Result<()> {
    let out = &args.out;
    let _lock = super::lock_and_clear(out)?;
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("batch.csv", csv.as_bytes())?;
    batch_plot(out, "batch.png", curves, 1.0).map_err(|e| anyhow!("plotting: {e}"))?;
    let timing = json!({
        "runs_s": runs_secs,
        "wall_time_s": t_start.elapsed().as_secs_f64(),
        "runs": runs,
        "threads": plan.pool.current_num_threads(),
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )
}

/// Runs the batch of a scenario of either form (after it has been built for a batch and
/// validated): every (record, scale) run, `batch.csv` in the form's layout, `batch.png` with the
/// largest response over the joints and segments against PGA and the smallest seat length of the
/// bridge dashed, `timing.json`; the exit code.
pub fn run(
    args: &Args,
    setup: &Setup,
    reading: &ReadOptions,
    t_start: Instant,
) -> Result<ExitCode> {
    let plan = plan(args, setup, reading)?;
    let (rows, runs_secs) = execute(&plan, setup, setup.settings())?;
    let curves = curves(&plan.records, plan.set.as_ref(), &rows);
    let model = setup.model();
    let (layout, n) = (setup.layout(), model.segments.len());
    let csv = match &plan.set {
        Some(set) => batch_set_csv(layout, n, &rows, set),
        None => batch_csv(layout, n, &rows),
    };
    write_outputs(args, &plan, &csv, &curves, (rows.len(), runs_secs, t_start))?;
    Ok(report(&rows, runs_secs, &args.out))
}

/// Runs the plan's batch of `base` on its pool with its progress bar: the rows and the seconds
/// the runs took.
fn execute<P: Problem>(
    plan: &Plan,
    base: &P,
    settings: &SimSettings,
) -> Result<(Vec<BatchRow>, f64)> {
    let t_runs = Instant::now();
    // without a terminal the bar is hidden: say once how long a long batch will take, as a
    // single run does (`time_estimate`)
    let said = std::sync::atomic::AtomicBool::new(!plan.pb.is_hidden());
    let progress = |n: usize| {
        plan.pb.inc(n as u64);
        let (done, total) = (plan.pb.position(), plan.pb.length().unwrap_or(0));
        let elapsed = t_runs.elapsed().as_secs_f64();
        if done == 0 || elapsed < 2.0 || said.load(std::sync::atomic::Ordering::Relaxed) {
            return;
        }
        let rest = elapsed * total.saturating_sub(done) as f64 / done as f64;
        if rest > 30.0 && !said.swap(true, std::sync::atomic::Ordering::Relaxed) {
            eprintln!(
                "note: {done} of {total} runs in {elapsed:.0} s; at the rate so far the batch \
                 needs about {rest:.0} s more"
            );
        }
    };
    let rows = plan
        .pool
        .install(|| {
            run_batch(
                base,
                settings,
                &plan.records,
                &plan.scales,
                plan.shard,
                &progress,
            )
        })
        .map_err(|e| anyhow!("{e}"))?;
    plan.pb.finish_and_clear();
    Ok((rows, t_runs.elapsed().as_secs_f64()))
}

/// The curves of `batch.png`: per record (or manifest entry), the peak responses of its completed runs against PGA
/// (the largest seat displacement, the largest joint opening and segment rotation, the impacts).
fn curves(records: &[BatchRecord], set: Option<&RecordSet>, rows: &[BatchRow]) -> Vec<BatchCurve> {
    let values = |o: &BatchOutcome| {
        let m = &o.summary;
        let max = |v: &mut dyn Iterator<Item = Real>| v.fold(Real::NAN, Real::max);
        [
            m.peak_seat_ratio,
            max(&mut m.joints.iter().map(|j| j.peak_opening)),
            max(&mut m.segments.iter().map(|g| g.peak_rotation)) * DEG,
            m.impacts as Real,
        ]
    };
    records
        .iter()
        .enumerate()
        .map(|(a, rec)| {
            let mut pts: Vec<(Real, [Real; 4])> = rows
                .iter()
                .filter(|r| r.record_index == a)
                .filter_map(|r| {
                    let o = r.outcome.as_ref().ok()?;
                    Some((r.pga / G0, values(o)))
                })
                .collect();
            pts.sort_by(|p, q| p.0.total_cmp(&q.0));
            // a file's name without its directory; a manifest entry's id as written
            let label = match set {
                Some(_) => rec.name.clone(),
                None => PathBuf::from(&rec.name)
                    .file_name()
                    .map_or(rec.name.clone(), |f| f.to_string_lossy().into_owned()),
            };
            BatchCurve { label, pts }
        })
        .filter(|c| !c.pts.is_empty())
        .collect()
}

/// Prints the batch's summary and errors; exit code 1 when a run failed or is not trustworthy.
fn report(rows: &[BatchRow], runs_secs: f64, out: &Path) -> ExitCode {
    let status = |o: &BatchOutcome| (o.status, o.summary.unseated, o.warnings);
    let failed: Vec<&BatchRow> = rows.iter().filter(|r| r.outcome.is_err()).collect();
    let unseated = rows
        .iter()
        .filter(|r| r.outcome.as_ref().is_ok_and(|o| status(o).1))
        .count();
    let untrusted_n = rows
        .iter()
        .filter(|r| {
            r.outcome
                .as_ref()
                .is_ok_and(|o| status(o).0 != SimStatus::Completed)
        })
        .count();
    eprintln!(
        "batch: {} in {:.2} s, {} unseated, {} could not run, {} not trustworthy; outputs in {}",
        count(rows.len(), "run"),
        runs_secs,
        unseated,
        failed.len(),
        untrusted_n,
        out.display()
    );
    let warned = rows
        .iter()
        .filter(|r| r.outcome.as_ref().is_ok_and(|o| status(o).2 > 0))
        .count();
    if warned > 0 {
        eprintln!(
            "warning: {} of {} runs have warnings (energy created at a contact, a coarse time step \
             or an implausible record PGA): see batch.csv, column warnings, and run one alone (--record \
             and --scale, or --set with a manifest of that entry) for its summary.json",
            warned,
            rows.len()
        );
    }
    // runs that finished but are not trustworthy (diverged, LCP/law-check or Newton failures)
    let untrusted: Vec<(&BatchRow, SimStatus)> = rows
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok().map(|o| (r, status(o).0)))
        .filter(|(_, st)| *st != SimStatus::Completed)
        .collect();
    if let Some((_, st)) = untrusted.first() {
        eprintln!(
            "error: {} of {} runs ended with a status other than Completed (first: {:?}); their rows in \
             batch.csv are not trustworthy",
            untrusted.len(),
            rows.len(),
            st
        );
    }
    if failed.is_empty() {
        return if untrusted.is_empty() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        };
    }
    // One message per distinct error (an unreadable record fails all its scales alike).
    let mut msgs: Vec<&str> = failed
        .iter()
        .map(|r| r.outcome.as_ref().err().map_or("", |m| m.as_str()))
        .collect();
    msgs.dedup();
    for m in &msgs {
        eprintln!("error: {m}");
    }
    eprintln!(
        "error: {} of {} runs failed (rows with status = error in batch.csv); the other runs are reported",
        failed.len(),
        rows.len()
    );
    ExitCode::from(1)
}
