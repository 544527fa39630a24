//! `pounding study`: the paper's parametric study (built-in default or a scenario file), sharded runs
//! and their merge. Numbers come from `pounding::study`; this module handles files, threads, the
//! progress bar, figures ([`crate::figures`]) and the report ([`crate::report`]).

use crate::cmd_simulate::sim_records::count;
use anyhow::{Context, Result, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::input::{
    SCENARIO_LIMIT, SHARD_MANIFEST_LIMIT, check_threads, read_text, shard_rows_limit,
};
use pounding::output::{OutputLock, lock_output_dir, write_atomic};
use pounding::study::{
    DEFAULT_SCENARIO_TOML, Scenario, Shard, Study,
    run::compute_rows,
    shard::{ShardFiles, manifest_json, merge, shard_rows_csv},
};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `pounding study`.
#[derive(clap::Args)]
#[command(args_conflicts_with_subcommands = true)]
pub struct Args {
    #[command(subcommand)]
    command: Option<Sub>,
    /// Scenario file (TOML); without it the built-in default (the paper's study) runs.
    scenario: Option<PathBuf>,
    #[command(flatten)]
    common: Common,
    /// Compute only the rows whose global index mod N = K − 1 and write a shard (merge with `study merge`).
    #[arg(long, value_name = "K/N")]
    shard: Option<String>,
    /// Print the built-in default scenario (commented TOML) and exit.
    #[arg(long)]
    print_default: bool,
}

#[derive(clap::Args)]
struct Common {
    /// Output directory.
    #[arg(long, default_value = "out/study")]
    out: PathBuf,
    /// Worker threads (default: all cores). Outputs are identical for any value.
    #[arg(long)]
    threads: Option<usize>,
    /// Also write every figure as SVG.
    #[arg(long)]
    svg: bool,
    /// Skip figures (and their section of the report), whatever the scenario says.
    #[arg(long)]
    no_figures: bool,
}

#[derive(clap::Subcommand)]
enum Sub {
    /// Merge shard outputs (`--shard K/N` runs) into the files an unsharded run writes.
    Merge {
        /// Shard output directories (all K = 1..N of one study, any order).
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
        #[command(flatten)]
        common: Common,
    },
}

/// Runs `pounding study`.
pub fn run(args: Args) -> Result<ExitCode> {
    if args.print_default {
        print!("{DEFAULT_SCENARIO_TOML}");
        return Ok(ExitCode::SUCCESS);
    }
    match args.command {
        Some(Sub::Merge { dirs, common }) => run_merge(&dirs, &common),
        None => run_study(
            args.scenario.as_deref(),
            args.shard.as_deref(),
            &args.common,
        ),
    }
}

/// Upper bound of the rows one run (or one shard) holds in memory, about 0.5 KB each.
const MAX_ROWS_PER_RUN: usize = 20_000_000;

fn pool(threads: Option<usize>) -> Result<rayon::ThreadPool> {
    check_threads(threads).map_err(anyhow::Error::msg)?;
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        b = b.num_threads(n);
    }
    b.build().context("cannot start the worker threads")
}

fn load_scenario(path: Option<&Path>) -> Result<(String, Scenario)> {
    match path {
        None => {
            let s = Scenario::from_toml(DEFAULT_SCENARIO_TOML, "built-in default")?;
            Ok((DEFAULT_SCENARIO_TOML.to_string(), s))
        }
        Some(p) => {
            let text = read_text(p, "scenario file", SCENARIO_LIMIT)
                .with_context(|| format!("cannot read scenario file {}", p.display()))?;
            let (s, notes) = Scenario::from_toml_with_notes(&text, &p.display().to_string())?;
            for n in notes {
                eprintln!("note: {n}");
            }
            Ok((text, s))
        }
    }
}

fn progress_bar(total: usize, what: &str) -> ProgressBar {
    let pb = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template(
        "{msg:10} [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta} left)",
    ) {
        pb.set_style(style);
    }
    pb.set_message(what.to_string());
    pb
}

fn write(dir: &Path, name: &str, text: &str) -> Result<()> {
    let p = dir.join(name);
    write_atomic(&p, text.as_bytes()).with_context(|| format!("cannot write {}", p.display()))
}

fn run_study(path: Option<&Path>, shard: Option<&str>, common: &Common) -> Result<ExitCode> {
    let t0 = Instant::now();
    let (text, scenario) = load_scenario(path)?;
    let shard = shard.map(Shard::parse).transpose()?;
    let pool = pool(common.threads)?;
    let total = scenario.row_count();
    let per_run = match shard {
        Some(s) => total.div_ceil(s.count),
        None => total,
    };
    if per_run > MAX_ROWS_PER_RUN {
        bail!(
            "the scenario gives {total} rows ({per_run} in this run); one run holds at most \
             {MAX_ROWS_PER_RUN} rows in memory (about 0.5 KB each): use a coarser grid, fewer \
             parameter values, or split the study with --shard K/N"
        );
    }
    pounding::output::check_output_dir_free(&common.out)?;
    eprintln!(
        "study: {} x {} x {} = {} on {}",
        count(scenario.configuration_count(), "configuration"),
        count(scenario.cases.len(), "case"),
        count(scenario.cell_count(), "cell"),
        count(total, "row"),
        count(pool.current_num_threads(), "thread")
    );
    let pb = progress_bar(total, "cells");
    let tick = |n: usize| pb.inc(n as u64);
    if let Some(shard) = shard {
        let rows = pool.install(|| compute_rows(&scenario, shard, &tick))?;
        pb.finish_and_clear();
        let csv = pool.install(|| shard_rows_csv(&scenario, &rows));
        let manifest = manifest_json(shard, &text, total, rows.len(), &csv);
        let _lock = lock_output_dir(&common.out)?;
        refuse_mixed_outputs(&common.out, true)?;
        write(&common.out, "rows.csv", &csv)?;
        write(&common.out, "shard.json", &manifest)?;
        eprintln!(
            "shard {}/{}: wrote {} rows to {} in {:.2} s (merge all shards with `pounding study merge`)",
            shard.index,
            shard.count,
            rows.len(),
            common.out.display(),
            t0.elapsed().as_secs_f64()
        );
        let bad = rows.iter().filter(|r| !r.cell.lcp_agrees).count();
        return Ok(exit_for(bad));
    }
    let study = pool.install(|| Study::compute(text, scenario, &tick))?;
    pb.finish_and_clear();
    finish(study, &pool, common, t0)
}

fn run_merge(dirs: &[PathBuf], common: &Common) -> Result<ExitCode> {
    let t0 = Instant::now();
    refuse_out_inside_shards(&common.out, dirs)?;
    pounding::output::check_output_dir_free(&common.out)?;
    let mut parts = Vec::with_capacity(dirs.len());
    for d in dirs {
        let read = |name: &str, what: &str, limit: u64| {
            let p = d.join(name);
            read_text(&p, what, limit).with_context(|| format!("cannot read {}", p.display()))
        };
        let manifest = read("shard.json", "shard manifest", SHARD_MANIFEST_LIMIT)?;
        // rows.csv may hold about SHARD_ROW_BYTES per row the manifest declares (merge checks
        // the count and the checksum).
        let declared = serde_json::from_str::<serde_json::Value>(&manifest)
            .ok()
            .and_then(|v| v["rows"].as_u64())
            .unwrap_or(0);
        let rows = read("rows.csv", "shard rows file", shard_rows_limit(declared))?;
        parts.push(ShardFiles {
            origin: d.display().to_string(),
            manifest,
            rows,
        });
    }
    let merged = merge(&parts)?;
    let pool = pool(common.threads)?;
    let study = Study::from_rows(merged.scenario_text, merged.scenario, merged.rows);
    finish(study, &pool, common, t0)
}

/// Refuses an output directory equal to or inside one of the shard directories being merged
/// (the merged files would land beside a shard's `shard.json` and `rows.csv`).
fn refuse_out_inside_shards(out: &Path, dirs: &[PathBuf]) -> Result<()> {
    for d in dirs {
        if pounding::output::path_is_within(out, d)
            .with_context(|| format!("cannot resolve {}", d.display()))?
        {
            bail!(
                "--out {} is inside (or equal to) the shard directory {}: the merged study \
                 would be written among the shard's files; choose another --out",
                out.display(),
                d.display()
            );
        }
    }
    Ok(())
}

/// Refuses to mix a shard and a complete study in one directory: a shard run into a directory
/// that holds a study's `bounds.csv`, or a complete run (or merge) into one that holds a
/// `shard.json`.
fn refuse_mixed_outputs(out: &Path, shard: bool) -> Result<()> {
    let (other, what) = if shard {
        ("bounds.csv", "a complete study")
    } else {
        ("shard.json", "a shard")
    };
    let p = out.join(other);
    if p.exists() {
        bail!(
            "--out {} holds {what} ({} exists): write {} into another directory",
            out.display(),
            p.display(),
            if shard {
                "the shard"
            } else {
                "the complete study"
            }
        );
    }
    Ok(())
}

fn exit_for(disagreements: usize) -> ExitCode {
    if disagreements > 0 {
        eprintln!(
            "error: {disagreements} cells where Lemke's solution of the impact LCP does not give the analytic mode (lcp_agrees = false)"
        );
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Removes what an earlier run may have left in `out` (every file a study writes: `report.html`
/// and `timing.json`, which are written last and so mark a complete run, the tables, the
/// figures and the geometry pages `report/*.html`), so that an interrupted run never leaves an
/// earlier run's results beside its own.
fn remove_previous_outputs(lock: &OutputLock) -> Result<()> {
    pounding::output::remove_previous_outputs(
        lock,
        &[
            "report.html",
            "timing.json",
            "bounds.csv",
            "summary.csv",
            "summary.json",
            "scenario.toml",
        ],
    )?;
    let out = lock.dir();
    let remove = |p: &Path| match std::fs::remove_file(p) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(e).with_context(|| format!("cannot remove the earlier output {}", p.display()))
        }
        _ => Ok(()),
    };
    for (dir, exts) in [("figures", &["png", "svg"][..]), ("report", &["html"][..])] {
        let Ok(entries) = std::fs::read_dir(out.join(dir)) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            let temporary = pounding::output::is_temporary_name(&e.file_name().to_string_lossy());
            let ext = p.extension().and_then(|x| x.to_str()).unwrap_or("");
            if temporary || exts.contains(&ext) {
                remove(&p)?;
            }
        }
    }
    Ok(())
}

/// Writes every output of a complete study.
fn finish(
    study: Study,
    pool: &rayon::ThreadPool,
    common: &Common,
    t0: Instant,
) -> Result<ExitCode> {
    let out = &common.out;
    let t_rows = t0.elapsed().as_secs_f64();
    let bounds = pool.install(|| study.bounds_csv());
    let summary_csv = study.summary_csv();
    let summary_json = study.summary_json();
    let t_text = t0.elapsed().as_secs_f64();
    let lock = lock_output_dir(out)?;
    refuse_mixed_outputs(out, false)?;
    remove_previous_outputs(&lock)?;
    write(out, "bounds.csv", &bounds)?;
    write(out, "summary.csv", &summary_csv)?;
    write(out, "summary.json", &summary_json)?;
    write(out, "scenario.toml", &study.scenario_text)?;
    let t_numeric = t0.elapsed().as_secs_f64();
    eprintln!(
        "wrote bounds.csv ({} rows), summary.csv, summary.json to {} in {:.2} s",
        study.rows.len(),
        out.display(),
        t_numeric
    );
    let draw = study.scenario.output.figures && !common.no_figures;
    let svg = study.scenario.output.svg || common.svg;
    let figures = if draw {
        let t = Instant::now();
        let pb = progress_bar(0, "figures");
        let tick = |n: usize, total: usize| {
            pb.set_length(total as u64);
            pb.inc(n as u64);
        };
        let figs = crate::figures::draw_all(&study, out, svg, pool, &tick)?;
        pb.finish_and_clear();
        eprintln!(
            "drew {} figures in {:.2} s",
            figs.iter().map(|g| g.figures.len()).sum::<usize>(),
            t.elapsed().as_secs_f64()
        );
        figs
    } else {
        Vec::new()
    };
    // The geometry pages first: report.html, the entry point, is written last but timing.json.
    let pages = crate::report_pages::geometry_pages(&study, &figures);
    if !pages.is_empty() {
        let dir = out.join("report");
        std::fs::create_dir_all(&dir)
            .with_context(|| format!("cannot create {}", dir.display()))?;
    }
    for (rel, html) in &pages {
        write(out, rel, html)?;
    }
    let html = crate::report::report_html(&study, &figures, draw);
    write(out, "report.html", &html)?;
    let total = t0.elapsed().as_secs_f64();
    let timing = serde_json::json!({
        "threads": pool.current_num_threads(),
        "rows": study.rows.len(),
        "rows_s": t_rows,
        "text_s": t_text - t_rows,
        "write_s": t_numeric - t_text,
        "numeric_s": t_numeric,
        "figures_and_report_s": total - t_numeric,
        "total_s": total,
    });
    write(out, "timing.json", &format!("{timing:#}\n"))?;
    eprintln!(
        "wrote report.html and {} geometry page{}; total {:.2} s; open {}",
        pages.len(),
        if pages.len() == 1 { "" } else { "s" },
        total,
        out.join("report.html").display()
    );
    Ok(exit_for(study.lcp_disagreements()))
}
