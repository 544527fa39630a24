//! `pounding fragility SCENARIO [--set MANIFEST] [--out DIR] [--threads N]`: a bridge scenario
//! with `[fragility]` and `[[limit_state]]` run over a record set at IM stripes
//! ([`pounding::assessment`]); `runs.csv`, the fitted curves, a figure, a report and
//! `timing.json` in `--out`.

use crate::fragility_study::{Fits, Study, boot_failed};
use anyhow::{Context, Result, anyhow, bail};
use clap::Parser;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::assessment::im::{ImSpec, PeriodInfo, fundamental_period};
use pounding::assessment::limit::bind;
use pounding::assessment::run::{Plan, RunRow, fit_limit_state, run_all, runs_csv};
use pounding::assessment::{CodeCheckInput, check_bridge};
use pounding::assessment::{FragilitySettings, PeriodChoice};
use pounding::fragility::{
    BootstrapSettings, FragilityRow, StudyColumns, fragility_csv_study, fragility_json_study,
};
use pounding::ground_motion::set::RecordSet;
use pounding::math::Real;
use pounding::output::write_atomic;
use pounding::sim::scenario::Scenario;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// The files `fragility` writes (removed from `--out` before writing).
pub const FRAGILITY_OUTPUTS: &[&str] = &[
    "runs.csv",
    "fragility.csv",
    "fragility.json",
    "fragility.png",
    "report.html",
    "timing.json",
];

/// Arguments of `pounding fragility`.
#[derive(Parser, Debug)]
pub struct Args {
    /// A bridge scenario (`[[segment]]`s) with a `[fragility]` table and `[[limit_state]]` tables.
    pub scenario: PathBuf,
    /// The record-set manifest (`.toml`, or `.csv` with a header row), instead of
    /// `[fragility] records`.
    #[arg(long)]
    pub set: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "out/fragility")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// Reads the scenario, its `[fragility]` settings, the record set and binds the limit states.
fn read(args: &Args) -> Result<Study> {
    let scenario = Scenario::load(&args.scenario)?.for_batch();
    if !scenario.is_bridge() {
        bail!(
            "{}: fragility runs bridge scenarios of [[segment]]s; this is a two-deck scenario \
             ([decks]): describe it as a two-segment bridge",
            scenario.origin()
        );
    }
    let setup = scenario.build_bridge()?;
    let settings = FragilitySettings::from_scenario(scenario.text(), scenario.origin())?;
    let set_path = match (&args.set, &settings.records) {
        (Some(p), _) => p.clone(),
        (None, Some(rel)) => args
            .scenario
            .parent()
            .map_or_else(|| rel.clone(), |d| d.join(rel)),
        (None, None) => bail!(
            "{}: no record set: give [fragility] records = \"MANIFEST.toml\" (or .csv) or \
             --set MANIFEST",
            scenario.origin()
        ),
    };
    // text records of entries without `units` are read in the scenario's `csv_units`, as
    // `simulate --records` reads them
    let reading = scenario.override_reading(None)?;
    let set =
        RecordSet::load_with_units(&set_path, reading.units, &reading.units_from).map_err(|e| {
            match (&args.set, e) {
                // a manifest that cannot be read or has no known extension: name the key that gave it
                (
                    None,
                    e @ (pounding::ground_motion::set::SetError::Read { .. }
                    | pounding::ground_motion::set::SetError::Extension { .. }),
                ) => anyhow::Error::from(pounding::assessment::AssessmentError::Key {
                    message: e.to_string(),
                    key: "fragility.records".into(),
                    origin: scenario.origin().to_string(),
                    line: settings.records_line,
                }),
                (_, e) => e.into(),
            }
        })?;
    for w in set_warnings(&set) {
        eprintln!("warning: {w}");
    }
    // a `[code_check]` table is read (and refused, naming its key) before any run
    let code_check = if CodeCheckInput::is_present(scenario.text()) {
        let input = CodeCheckInput::from_scenario(scenario.text(), scenario.origin())?;
        input.check_segments(setup.problem.model.segments.len())?;
        Some(
            check_bridge(&setup.problem.model, &input, scenario.origin())
                .map_err(|e| e.to_string()),
        )
    } else {
        None
    };
    let limits = bind(
        &settings.limit_states,
        &setup.problem.model,
        scenario.origin(),
    )?;
    let (period, info) = match settings.period {
        PeriodChoice::Given(t) => (t, None),
        PeriodChoice::Model => {
            let p = fundamental_period(&setup.problem.model)?;
            (p.period, Some(p))
        }
    };
    let spec = ImSpec {
        kind: settings.im,
        period,
        damping: settings.damping,
        pair: settings.pair_im,
    };
    let period = (settings.im == pounding::assessment::ImKind::Sa)
        .then_some(info)
        .flatten();
    Ok(Study {
        origin: scenario.origin().to_string(),
        setup,
        settings,
        set,
        set_path,
        limits,
        spec,
        period,
        code_check,
    })
}

/// The implausible-PGA warnings of the records of `set` (units probably wrong), one per
/// component, naming the entry.
fn set_warnings(set: &RecordSet) -> Vec<String> {
    use pounding::ground_motion::ComponentInfo;
    set.records
        .iter()
        .flat_map(|r| {
            [("x", Some(&r.x)), ("y", r.y.as_ref())]
                .into_iter()
                .filter_map(move |(c, rec)| {
                    let w = ComponentInfo::of(c, rec?).units_warning()?;
                    Some(format!("record set entry {:?}: {w}", r.id))
                })
        })
        .collect()
}

/// Runs the command.
pub fn run(args: Args) -> Result<ExitCode> {
    let t0 = Instant::now();
    pounding::input::check_threads(args.threads).map_err(anyhow::Error::msg)?;
    let st = read(&args)?;
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = args.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let ground = &st.setup.problem.ground;
    let plan = pool.install(|| Plan::new(&st.set, &st.spec, &st.settings.stripes, ground))?;
    pounding::output::check_output_dir_free(&args.out)?;
    let total = st.set.records.len() * plan.values().len();
    use crate::cmd_simulate::sim_records::count;
    let what = match &st.settings.stripes {
        pounding::assessment::Stripes::Levels(_) => "stripe",
        pounding::assessment::Stripes::Scales(_) => "IDA scale",
    };
    eprintln!(
        "fragility: {} of {} x {} = {} on {}; IM = {}",
        count(st.set.records.len(), "entry").replace("entrys", "entries"),
        st.set_path.display(),
        count(plan.values().len(), what),
        count(total, "run"),
        count(pool.current_num_threads(), "thread"),
        st.spec.label()
    );
    if let Some(p) = &st.period {
        println!("period: {}", p.describe());
    }
    let pb = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("runs [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta} left)")
    {
        pb.set_style(style);
    }
    let t_runs = Instant::now();
    let rows = pool.install(|| {
        run_all(
            &st.setup.problem,
            &st.setup.settings,
            &st.set,
            &plan,
            &st.limits,
            &|| pb.inc(1),
        )
    });
    pb.finish_and_clear();
    let runs_s = t_runs.elapsed().as_secs_f64();
    let seat_ends = st.setup.problem.model.seat_end_names();
    let csv = runs_csv(&st.set, &plan, &st.limits, &seat_ends, &rows);
    let excluded = rows.iter().filter(|r| !r.trusted()).count();
    let fits = pool.install(|| fit_all(&st, &plan, &rows))?;
    write_outputs(
        &args.out,
        &st,
        &plan,
        &rows,
        &fits,
        &csv,
        (runs_s, t0, total, &pool),
    )?;
    print_table(&fits);
    for w in fits.rows.iter().flat_map(FragilityRow::interval_warnings) {
        eprintln!("warning: {w}");
    }
    let warned = rows.iter().filter(|r| r.warnings > 0).count();
    if warned > 0 {
        eprintln!(
            "warning: {warned} of {total} runs have warnings (a time step coarser than the \
             record's samples, energy created at a contact, ...): the warnings column of \
             runs.csv counts them; run one with `pounding simulate --record` to read them"
        );
    }
    if excluded > 0 {
        eprintln!(
            "error: {excluded} of {total} runs failed or are not trustworthy (status in runs.csv): \
             excluded from the fit"
        );
        return Ok(ExitCode::from(1));
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes every output into `out` (each file atomically, after the lock).
fn write_outputs(
    out: &Path,
    st: &Study,
    plan: &Plan,
    rows: &[RunRow],
    fits: &Fits,
    csv: &str,
    (runs_s, t0, runs, pool): (f64, Instant, usize, &rayon::ThreadPool),
) -> Result<()> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, FRAGILITY_OUTPUTS)?;
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("runs.csv", csv.as_bytes())?;
    let label = st.spec.label();
    let cols = StudyColumns {
        im: &label,
        im_unit: "g",
        level: st.settings.level,
    };
    wr(
        "fragility.csv",
        fragility_csv_study(&fits.rows, &cols).as_bytes(),
    )?;
    let mut j = fragility_json_study(&fits.rows, &cols);
    if let Some(o) = j.as_object_mut() {
        o.insert("im".into(), json!(st.spec.label()));
        o.insert(
            "period".into(),
            json!(st.period.as_ref().map(PeriodInfo::describe)),
        );
        o.insert("records".into(), json!(st.set.records.len()));
        o.insert("runs".into(), json!(rows.len()));
        o.insert(
            "runs_excluded".into(),
            json!(rows.iter().filter(|r| !r.trusted()).count()),
        );
        let emp: serde_json::Map<String, serde_json::Value> = st
            .limits
            .iter()
            .enumerate()
            .map(|(l, lim)| {
                let pts: Vec<serde_json::Value> = crate::fragility_plot::empirical(plan, rows, l)
                    .into_iter()
                    .map(|(im, p, n)| json!({"im_g": im, "runs": n, "fraction": p}))
                    .collect();
                (lim.state.name.clone(), json!(pts))
            })
            .collect();
        o.insert("empirical".into(), serde_json::Value::Object(emp));
    }
    pounding::output::json_without_negative_zero(&mut j);
    wr(
        "fragility.json",
        (serde_json::to_string_pretty(&j)? + "\n").as_bytes(),
    )?;
    crate::fragility_plot::plot(&out.join("fragility.png"), st, plan, rows, fits)
        .map_err(|e| anyhow!("plotting: {e}"))?;
    wr(
        "report.html",
        crate::fragility_report::report(st, plan, rows, fits).as_bytes(),
    )?;
    let timing = json!({
        "runs_s": runs_s,
        "wall_time_s": t0.elapsed().as_secs_f64(),
        "runs": runs,
        "threads": pool.current_num_threads(),
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )
    .map_err(|e| anyhow!("{e:#}"))
}

/// Fits every limit state ([`fit_limit_state`]); the band spans the IMs run, 60 points evenly
/// spaced in log IM.
fn fit_all(st: &Study, plan: &Plan, rows: &[RunRow]) -> Result<Fits> {
    let (lo, hi) = rows
        .iter()
        .fold((Real::INFINITY, 0.0 as Real), |(a, b), r| {
            (a.min(r.im_g), b.max(r.im_g))
        });
    let band_im: Vec<Real> = (0..60)
        .map(|k| (lo.ln() + (hi / lo).ln() * k as Real / 59.0).exp())
        .filter(|x| x.is_finite() && *x > 0.0)
        .collect();
    let b = BootstrapSettings {
        samples: st.settings.bootstrap,
        seed: st.settings.seed,
        level: st.settings.level,
    };
    let fits = st
        .limits
        .iter()
        .enumerate()
        .map(|(l, lim)| fit_limit_state(&lim.state.name, plan, rows, l, &b, &band_im))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| anyhow!("fitting: {e}"))?;
    Ok(Fits {
        rows: fits,
        band_im,
    })
}

/// `lo–hi` of an interval, or `-`.
fn interval(i: Option<(Real, Real)>) -> String {
    i.map_or("-".into(), |(a, b)| format!("{a:.4}-{b:.4}"))
}

/// Stdout: per limit state θ, β, their intervals, the failed bootstrap replicates and the counts.
fn print_table(fits: &Fits) {
    println!(
        "{:<20} {:<20} {:>9} {:>7} {:>17} {:>15} {:>11} {:>7} {:>5}",
        "limit state",
        "status",
        "theta_g",
        "beta",
        "theta interval",
        "beta interval",
        "boot failed",
        "records",
        "runs"
    );
    for r in &fits.rows {
        let (t, b) = r.fit.params().map_or(("-".into(), "-".into()), |(t, b)| {
            (format!("{t:.4}"), format!("{b:.3}"))
        });
        let bs = r.bootstrap.as_ref();
        println!(
            "{:<20} {:<20} {t:>9} {b:>7} {:>17} {:>15} {:>11} {:>7} {:>5}",
            r.limit_state,
            r.fit.status(),
            interval(bs.and_then(|b| b.theta)),
            interval(bs.and_then(|b| b.beta)),
            boot_failed(r),
            r.n_records,
            r.n_runs
        );
    }
}
