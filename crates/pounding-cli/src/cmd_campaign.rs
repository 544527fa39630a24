//! `pounding campaign run SPEC --out DIR [--threads N] [--shard K/N]` and
//! `pounding campaign merge DIR... --out DIR`: campaigns of many runs stored as Parquet parts,
//! resumable ([`pounding::campaign`]).

use anyhow::{Context, Result};
use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::campaign::{Campaign, Store, exec, store};
use pounding::shard::Shard;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

/// Arguments of `pounding campaign`.
#[derive(Parser, Debug)]
pub struct Args {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand, Debug)]
enum Cmd {
    /// Run a campaign (or one shard of it) into a store; a store that holds parts already resumes.
    Run(RunArgs),
    /// Merge the parts of one or more stores (the shards of one campaign) into one sorted runs.parquet.
    Merge(MergeArgs),
}

/// Arguments of `pounding campaign run`.
#[derive(Parser, Debug)]
struct RunArgs {
    /// The campaign spec (TOML: [campaign] scenario, records, stripes; [outputs]).
    spec: PathBuf,
    /// The store directory (created; resumed when it holds parts of the same campaign).
    #[arg(long, default_value = "out/campaign")]
    out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Run only the parts whose index mod N = K − 1 (a Slurm array task); merge the shards'
    /// stores with `pounding campaign merge`.
    #[arg(long)]
    shard: Option<String>,
}

/// Arguments of `pounding campaign merge`.
#[derive(Parser, Debug)]
struct MergeArgs {
    /// The stores to merge (e.g. one per shard).
    #[arg(required = true)]
    stores: Vec<PathBuf>,
    /// Where runs.parquet and campaign.json are written.
    #[arg(long)]
    out: PathBuf,
}

/// Runs the command.
pub fn run(args: Args) -> Result<ExitCode> {
    match args.command {
        Cmd::Run(a) => run_campaign(a),
        Cmd::Merge(a) => {
            pounding::output::check_output_dir_free(&a.out)?;
            // every store is a store before `out` is created (a bad path leaves nothing behind)
            for s in &a.stores {
                store::Meta::read(s)?;
            }
            // the stores merged may include `out` itself (then its lock is taken once, here)
            let _lock = pounding::output::lock_output_dir(&a.out)?;
            let m = store::merge(&a.stores, &a.out)?;
            println!("{}", merged_line(&m));
            Ok(exit_of(&m))
        }
    }
}

fn merged_line(m: &store::Merged) -> String {
    let st: Vec<String> = m.statuses.iter().map(|(k, n)| format!("{k} {n}")).collect();
    format!(
        "merged {} runs into {} ({})",
        m.rows,
        m.path.display(),
        st.join(", ")
    )
}

/// 1 when some run did not complete (its status is stored), else 0.
fn exit_of(m: &store::Merged) -> ExitCode {
    exit_of_statuses(&m.statuses, m.rows)
}

/// Exit 1 when some of `rows` runs did not complete (`statuses`: runs per status).
fn exit_of_statuses(statuses: &std::collections::BTreeMap<String, usize>, rows: usize) -> ExitCode {
    let bad: usize = statuses
        .iter()
        .filter(|(k, _)| k.as_str() != "Completed")
        .map(|(_, n)| n)
        .sum();
    if bad > 0 {
        eprintln!("error: {bad} of {rows} runs failed or are not trustworthy (status column)");
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// A progress bar with rate and ETA when stderr is a terminal; otherwise a plain line every
/// 10 % of the runs.
struct Bar {
    what: &'static str,
    bar: Option<ProgressBar>,
    done: AtomicUsize,
    total: usize,
    t0: Instant,
}

impl Bar {
    /// A bar of `total` steps of `what` (`runs`, `variants`).
    fn new(total: usize, what: &'static str) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let pb =
                ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::stderr());
            if let Ok(style) = ProgressStyle::with_template(&format!(
                "{what} [{{elapsed_precise}}] {{wide_bar}} {{pos}}/{{len}} {{per_sec}} ({{eta}} left)"
            )) {
                pb.set_style(style);
            }
            pb
        });
        Bar {
            what,
            bar,
            done: AtomicUsize::new(0),
            total,
            t0: Instant::now(),
        }
    }

    fn inc(&self) {
        let n = self.done.fetch_add(1, Ordering::Relaxed) + 1;
        match &self.bar {
            Some(b) => b.inc(1),
            None => {
                let step = self.total.div_ceil(10).max(1);
                if n.is_multiple_of(step) || n == self.total {
                    let s = self.t0.elapsed().as_secs_f64();
                    let rate = n as f64 / s.max(1e-9);
                    eprintln!(
                        "{}: {n}/{} ({rate:.1}/s, {:.0} s left)",
                        self.what,
                        self.total,
                        (self.total - n) as f64 / rate
                    );
                }
            }
        }
    }

    fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

fn run_campaign(a: RunArgs) -> Result<ExitCode> {
    pounding::input::check_threads(a.threads).map_err(anyhow::Error::msg)?;
    let shard = match &a.shard {
        Some(s) => Shard::parse(s)?,
        None => Shard::ALL,
    };
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = a.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    // a large grid takes a while to build (each variant's scenario is read and built): shown
    // from 100 variants on
    let variants = std::sync::OnceLock::new();
    let c = pool.install(|| {
        Campaign::load_with_progress(&a.spec, &|_, total| {
            if total >= 100 {
                variants.get_or_init(|| Bar::new(total, "variants")).inc();
            }
        })
    })?;
    if let Some(b) = variants.get() {
        b.finish();
    }
    for w in c.study.record_warnings() {
        eprintln!("warning: {w}");
    }
    pounding::output::check_output_dir_free(&a.out)?;
    let _lock = pounding::output::lock_output_dir(&a.out)?;
    let st = Store::open(&a.out, &c)?;
    let (todo, before) = exec::pending(&c, &st, shard)?;
    let runs: usize = todo.iter().map(|p| c.part_range(*p).len()).sum();
    eprintln!(
        "campaign {}: {} runs in {} parts of {}{}; {} parts stored, {} to run ({} runs) on {}",
        c.name,
        c.runs(),
        c.parts(),
        c.runs_per_part,
        if shard == Shard::ALL {
            String::new()
        } else {
            format!("; shard {}/{}", shard.index, shard.count)
        },
        before,
        todo.len(),
        runs,
        crate::cmd_simulate::sim_records::count(pool.current_num_threads(), "thread")
    );
    let bar = Bar::new(runs, "runs");
    let done = pool.install(|| exec::run_parts(&c, &st, &todo, &|| bar.inc()));
    bar.finish();
    done?;
    if st.stored()?.len() == c.parts() {
        let m = store::merge(std::slice::from_ref(&a.out), &a.out)?;
        println!("{}", merged_line(&m));
        Ok(exit_of(&m))
    } else {
        println!(
            "shard {}/{} stored in {}; merge the shards' stores with `pounding campaign merge`",
            shard.index,
            shard.count,
            a.out.display()
        );
        // this shard's runs (stored now or before): a Slurm task whose runs failed fails
        let mine: Vec<usize> = (0..c.parts()).filter(|p| shard.contains(*p)).collect();
        let statuses = st.part_statuses(&mine)?;
        let rows = statuses.values().sum();
        Ok(exit_of_statuses(&statuses, rows))
    }
}
