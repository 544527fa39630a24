//! `pounding fragility SCENARIO [--set MANIFEST] [--out DIR] [--threads N]`: a bridge scenario
//! with `[fragility]` and `[[limit_state]]` run over a record set at IM stripes
//! ([`pounding::assessment`]); `runs.csv`, the fitted curves, a figure, a report and
//! `timing.json` in `--out`.

use crate::fragility_study::{Fits, Study, boot_failed};
use anyhow::{Context, Result, anyhow};
use clap::Parser;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::assessment::run::{Plan, RunRow};
use pounding::assessment::study::{excluded_message, fit_warnings};
use pounding::math::Real;
use pounding::output::write_atomic;
use pounding::sim::scenario::Scenario;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// The files `fragility` writes (removed from `--out` before writing).
pub const FRAGILITY_OUTPUTS: &[&str] = pounding::assessment::study::OUTPUTS;

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
    /// With a set of support-motion entries (`pounding motion svgm`): also run each entry with
    /// every support on its start support's motion and write `svgm_ratio.csv` (the limit states'
    /// probabilities under the spatially variable motion over the uniform one).
    #[arg(long)]
    pub compare_uniform: bool,
    /// Fit the runs stored by `pounding campaign run` (a store directory or its runs.parquet)
    /// instead of running them; the store must hold this scenario's runs of the same record set
    /// and stripes (checked run by run).
    #[arg(long, conflicts_with = "compare_uniform")]
    pub from_store: Option<PathBuf>,
    /// With --from-store: the campaign variant to fit (default: the only one).
    #[arg(long, requires = "from_store")]
    pub variant: Option<String>,
    /// With --from-store: the campaign spec that made the store; the runs are then read as the
    /// campaign made them (its record set and stripes, the variant's own bridge and limit
    /// states), and the scenario must be the spec's.
    #[arg(
        long,
        value_name = "SPEC",
        requires = "from_store",
        conflicts_with = "set"
    )]
    pub campaign: Option<PathBuf>,
    /// A site hazard curve (a `.csv` table with the header `im_g,rate`, or a `.toml` file with a
    /// `[hazard]` table) instead of the scenario's `[hazard]`: writes the mean annual frequency
    /// of every limit state (`maf.csv`, `hazard.csv`, `hazard.png`).
    #[arg(long)]
    pub hazard: Option<PathBuf>,
}

/// Reads the scenario, its `[fragility]` settings, the record set and binds the limit states
/// ([`Study::read`]); prints the records' warnings.
/// With --from-store, the study the store holds ([`pounding::campaign::from_store::store_study`]).
fn read(args: &Args) -> Result<(Study, u64, Option<Plan>, Option<String>)> {
    let scenario = Scenario::load(&args.scenario)?;
    let (mut st, fingerprint, plan, variant) = match &args.from_store {
        Some(store) => {
            let s = pounding::campaign::from_store::store_study(
                scenario,
                &args.scenario,
                args.set.as_deref(),
                store,
                args.campaign.as_deref(),
                args.variant.as_deref(),
            )?;
            (s.study, s.scenario_fingerprint, s.plan, s.variant)
        }
        None => {
            let fingerprint = pounding::campaign::scenario_fingerprint(scenario.text());
            let st = Study::read(scenario, args.scenario.parent(), args.set.as_deref())?;
            (st, fingerprint, None, None)
        }
    };
    if let Some(h) = &args.hazard {
        st = st.with_hazard(h)?;
    }
    if args.variant.is_some() && args.campaign.is_none() {
        eprintln!(
            "warning: --variant without --campaign: the verdicts are the variant's, but the \
             report and the code check describe the scenario's own bridge (give --campaign SPEC \
             to read the variant's bridge)"
        );
    }
    for w in st.record_warnings() {
        eprintln!("warning: {w}");
    }
    Ok((st, fingerprint, plan, variant))
}

/// Runs the command.
pub fn run(args: Args) -> Result<ExitCode> {
    let t0 = Instant::now();
    pounding::input::check_threads(args.threads).map_err(anyhow::Error::msg)?;
    let (st, fingerprint, planned, variant) = read(&args)?;
    let uniform = match args.compare_uniform {
        false => None,
        true => Some(st.uniform_counterpart().ok_or_else(|| {
            anyhow!(
                "--compare-uniform: the record set {} has no support-motion entries \
                 (`supports = \"FILE\"`, as pounding motion svgm writes them)",
                st.set_path.display()
            )
        })?),
    };
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = args.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let plan = match planned {
        Some(p) => p,
        None => pool.install(|| st.plan())?,
    };
    pounding::output::check_output_dir_free(&args.out)?;
    let per = st.set.records.len() * plan.values().len();
    let total = per * if uniform.is_some() { 2 } else { 1 };
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
    let rows = match &args.from_store {
        Some(store) => pounding::campaign::read::study_rows(
            store,
            &st,
            &plan,
            fingerprint,
            variant.as_deref(),
        )?,
        None => pool.install(|| st.run(&plan, &|| pb.inc(1))),
    };
    // the uniform counterpart over the same stripes
    let rows_u = uniform
        .as_ref()
        .map(|u| pool.install(|| u.run(&plan, &|| pb.inc(1))));
    pb.finish_and_clear();
    let runs_s = t_runs.elapsed().as_secs_f64();
    let fits = pool
        .install(|| st.fit(&plan, &rows))
        .map_err(|e| anyhow!("fitting: {e}"))?;
    let compared = match (&uniform, &rows_u) {
        (Some(u), Some(rows_u)) => {
            let fits_u = pool
                .install(|| u.fit(&plan, rows_u))
                .map_err(|e| anyhow!("fitting the uniform runs: {e}"))?;
            // the uniform runs' own runs.csv and fragility.csv beside the comparison
            let files = u.data_files(&plan, rows_u, &fits_u);
            let own = |name: &str| {
                files
                    .iter()
                    .find(|(n, _)| *n == name)
                    .map(|(_, t)| t.clone())
                    .unwrap_or_default()
            };
            Some([
                pounding::assessment::svgm::svgm_ratio_csv((&rows, &fits), (rows_u, &fits_u)),
                own("runs.csv"),
                own("fragility.csv"),
            ])
        }
        _ => None,
    };
    write_outputs(
        &args.out,
        &st,
        &plan,
        (&rows, &fits, compared.as_ref()),
        (runs_s, t0, total, &pool),
    )?;
    print_table(&fits);
    let mut failed = false;
    if let Some(m) = st.maf(&fits) {
        print_maf(&m);
        for w in pounding::assessment::hazard_study::maf_warnings(&m) {
            eprintln!("warning: {w}");
        }
        if let Some(e) = pounding::assessment::hazard_study::maf_failure(&m) {
            eprintln!("error: {e}");
            failed = true;
        }
    }
    for w in fit_warnings(&rows, &fits) {
        eprintln!("warning: {w}");
    }
    if let Some(m) = excluded_message(&rows) {
        eprintln!("error: {m}");
        failed = true;
    }
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Writes every output into `out` (each file atomically, after the lock): the data files of
/// [`Study::data_files`], the figure, the report and `timing.json`.
fn write_outputs(
    out: &Path,
    st: &Study,
    plan: &Plan,
    (rows, fits, compared): (&[RunRow], &Fits, Option<&[String; 3]>),
    (runs_s, t0, runs, pool): (f64, Instant, usize, &rayon::ThreadPool),
) -> Result<()> {
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, FRAGILITY_OUTPUTS)?;
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    for (name, text) in st.data_files(plan, rows, fits) {
        wr(name, text.as_bytes())?;
    }
    if let Some([ratio, runs, fragility]) = compared {
        wr(pounding::assessment::svgm::SVGM_RATIO, ratio.as_bytes())?;
        wr("runs_uniform.csv", runs.as_bytes())?;
        wr("fragility_uniform.csv", fragility.as_bytes())?;
    }
    crate::fragility_plot::plot(&out.join("fragility.png"), st, plan, rows, fits)
        .map_err(|e| anyhow!("plotting: {e}"))?;
    for (name, text) in st.hazard_files(fits) {
        wr(name, text.as_bytes())?;
    }
    if let (Some(h), Some(m)) = (&st.hazard, st.maf(fits)) {
        let curves = crate::hazard_plot::curves(&h.curve, &fits.rows, &m, "");
        crate::hazard_plot::plot(&out.join("hazard.png"), &st.spec.label(), &curves)
            .map_err(|e| anyhow!("plotting: {e}"))?;
    }
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

/// Stdout: per limit state the MAF, its interval and the return period.
fn print_maf(rows: &[pounding::assessment::hazard_study::MafRow]) {
    use crate::hazard_report::{sci, years};
    println!(
        "{:<20} {:>11} {:>23} {:>14}",
        "limit state", "MAF_per_yr", "MAF interval", "return_period"
    );
    for r in rows {
        let rate = r.maf.map_or(Real::NAN, |m| m.rate);
        let i = r
            .interval
            .map_or("-".into(), |(a, b)| format!("{}-{}", sci(a), sci(b)));
        println!(
            "{:<20} {:>11} {:>23} {:>14}",
            r.limit_state,
            sci(rate),
            i,
            years(1.0 / rate)
        );
    }
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
