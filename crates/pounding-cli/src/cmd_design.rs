//! `pounding design DESIGN.toml [--set MANIFEST] [--hazard FILE] [--out DIR] [--threads N]`:
//! retrofit variants of one bridge run on the same records and stripes
//! ([`pounding::assessment::design`]), each fitted, compared with the as-built bridge by paired
//! bootstrap differences; `variants.csv`, `variants.json`, each variant's own fragility files
//! under `variants/<name>/`, `design.png` and `report.html` in `--out`.

use anyhow::{Context, Result, anyhow};
use clap::Parser;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::assessment::design::Design;
use pounding::assessment::design_out;
use pounding::assessment::design_write::{compare, recommendation};
use pounding::output::write_atomic;
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// The files `design` writes in `--out` (removed before writing); each variant's own files go to
/// `variants/<name>/`.
pub const DESIGN_OUTPUTS: &[&str] = design_out::OUTPUTS;

/// Arguments of `pounding design`.
#[derive(Parser, Debug)]
pub struct Args {
    /// A design file: `[design] scenario = "BRIDGE.toml"` (a fragility scenario) and
    /// `[[variant]]` tables of overrides of its keys.
    pub design: PathBuf,
    /// The record-set manifest, instead of the scenario's `[fragility] records`.
    #[arg(long)]
    pub set: Option<PathBuf>,
    /// A site hazard curve (`.csv` with header `im_g,rate`, or `.toml` with `[hazard]`), instead
    /// of the scenario's `[hazard]`: the variants are compared by their mean annual frequency.
    #[arg(long)]
    pub hazard: Option<PathBuf>,
    /// Output directory.
    #[arg(long, default_value = "out/design")]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<ExitCode> {
    let t0 = Instant::now();
    pounding::input::check_threads(args.threads).map_err(anyhow::Error::msg)?;
    let design = Design::read(&args.design, args.set.as_deref(), args.hazard.as_deref())?;
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = args.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let plan = pool.install(|| design.plan())?;
    pounding::output::check_output_dir_free(&args.out)?;
    // an earlier run's variants not in this design: refused now if not ours, removed at writing
    let stale = design_out::stale_variant_dirs(&args.out, &design)?;
    use crate::cmd_simulate::sim_records::count;
    let base = &design.members[0].study;
    let per = base.set.records.len() * plan.values().len();
    let total = per * design.members.len();
    eprintln!(
        "design: {} bridges ({} and {}) x {} x {} = {total} runs on {}; IM = {}",
        design.members.len(),
        design.members[0].name,
        count(design.members.len() - 1, "variant"),
        count(base.set.records.len(), "entry").replace("entrys", "entries"),
        count(plan.values().len(), "stripe"),
        count(pool.current_num_threads(), "thread"),
        base.spec.label()
    );
    let pb = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("runs [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta} left)")
    {
        pb.set_style(style);
    }
    let t_runs = Instant::now();
    let rows = pool.install(|| design.run(&plan, &|| pb.inc(1)));
    pb.finish_and_clear();
    let runs_s = t_runs.elapsed().as_secs_f64();
    let fits = pool
        .install(|| design.fit(&plan, &rows))
        .map_err(|e| anyhow!("fitting: {e}"))?;
    let (stat, comps) = compare(&design, &fits);
    let searched = match &design.search {
        None => None,
        Some(spec) => {
            eprintln!(
                "search: {} over {}..{} (each value a full set of runs)",
                spec.key, spec.range.0, spec.range.1
            );
            let r = pool.install(|| {
                pounding::assessment::design_search::search(&design, spec, &plan, &|| {})
            })?;
            Some((spec, r))
        }
    };
    let out = &args.out;
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, DESIGN_OUTPUTS)?;
    let files = design_out::data_files(
        &design,
        &plan,
        &rows,
        &fits,
        searched.as_ref().map(|(s, r)| (*s, r)),
    );
    design_out::write(out, &files, &stale)?;
    let wr = |path: PathBuf, bytes: &[u8]| {
        write_atomic(&path, bytes).with_context(|| format!("cannot write {}", path.display()))
    };
    crate::design_plot::plot(&out.join("design.png"), &design, &fits)
        .map_err(|e| anyhow!("plotting: {e}"))?;
    if let Some(h) = design.hazard() {
        let curves: Vec<_> = design
            .members
            .iter()
            .zip(&fits)
            .flat_map(|(m, f)| {
                let rows = pounding::assessment::hazard_study::maf_rows(&h.curve, &f.rows);
                crate::hazard_plot::curves(&h.curve, &f.rows, &rows, &format!("{}: ", m.name))
            })
            .collect();
        crate::hazard_plot::plot(&out.join("hazard.png"), &base.spec.label(), &curves)
            .map_err(|e| anyhow!("plotting: {e}"))?;
    }
    wr(
        out.join("report.html"),
        crate::design_report::report(
            &design,
            &fits,
            (stat, &comps),
            searched.as_ref().map(|x| &x.1),
        )
        .as_bytes(),
    )?;
    let timing = json!({
        "runs_s": runs_s,
        "wall_time_s": t0.elapsed().as_secs_f64(),
        "runs": total,
        "threads": pool.current_num_threads(),
    });
    wr(
        out.join("timing.json"),
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;
    drop(lock);
    print_table(&design, &fits, stat, &comps);
    for s in recommendation(&design, &fits, stat, &comps) {
        println!("{s}");
    }
    if let Some((_, r)) = &searched {
        println!("search: {}", r.verdict);
    }
    let mut failed = false;
    if let Some(e) = pounding::assessment::design_write::not_finite(&design, &fits, &comps) {
        eprintln!("error: {e}");
        failed = true;
    }
    if let Some(m) = design_out::excluded_message(&rows) {
        eprintln!("error: {m}");
        failed = true;
    }
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Stdout: per member and limit state the statistic, the change and its paired and unpaired
/// intervals.
fn print_table(
    design: &Design,
    fits: &[pounding::assessment::study::Fits],
    stat: pounding::assessment::design_write::Stat,
    comps: &[pounding::assessment::design_write::Comparison],
) {
    let g = |x: Option<f64>| x.map_or("-".into(), |v| format!("{v:.4e}"));
    let i = |x: Option<(f64, f64)>| x.map_or("-".into(), |(a, b)| format!("{a:.3e}..{b:.3e}"));
    println!(
        "{:<20} {:<18} {:<10} {:>11} {:>11} {:>23} {:>23}",
        "variant",
        "limit state",
        "status",
        stat.as_str(),
        "change",
        "paired interval",
        "unpaired interval"
    );
    for c in comps {
        println!(
            "{:<20} {:<18} {:<10} {:>11} {:>11} {:>23} {:>23}",
            design.members[c.member].name,
            fits[c.member].rows[c.limit].limit_state,
            fits[c.member].rows[c.limit].fit.status(),
            g(c.value),
            g(c.diff),
            i(c.paired),
            i(c.unpaired)
        );
    }
}
