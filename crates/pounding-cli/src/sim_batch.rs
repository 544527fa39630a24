//! Batch mode of `pounding simulate` (`--records … --scales …`): every (record, scale) pair in
//! parallel ([`pounding::sim::batch`]), a progress bar on a terminal, `batch.csv` (one row per
//! run), `batch.png` (peak response against PGA per record) and `timing.json`.
//!
//! A record that cannot be read is reported in its rows (`status = error`, `error` = the message
//! naming the file) and in the final message; every other run is still done and written, and the
//! exit code is 1. A run that ends with a status other than `Completed` (e.g. `Diverged`) is
//! written and also makes the exit code 1.

use super::sim_plots::{self, BatchCurve};
use super::{Args, DEG};
use anyhow::{Context, Result, anyhow, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use pounding::ground_motion::{AccelUnits, G0, Record};
use pounding::math::Real;
use pounding::output::{float_token, write_atomic};
use pounding::sim::batch::{BatchRecord, BatchRow, BatchShard, run_batch};
use pounding::sim::{SEAT_ENDS, SimProblem, SimSettings, SimStatus};
use serde_json::json;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// The record files of `--records`: files as given, directories expanded to their `.AT2` / `.csv`
/// files (any case) sorted by file name.
fn expand_records(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for p in paths {
        if p.is_dir() {
            let mut files: Vec<PathBuf> = std::fs::read_dir(p)
                .with_context(|| format!("--records: cannot list directory {}", p.display()))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| {
                    f.is_file()
                        && f.extension().is_some_and(|x| {
                            x.eq_ignore_ascii_case("at2") || x.eq_ignore_ascii_case("csv")
                        })
                })
                .collect();
            if files.is_empty() {
                bail!(
                    "--records: directory {} contains no .AT2 or .csv record",
                    p.display()
                );
            }
            files.sort();
            out.extend(files);
        } else {
            out.push(p.clone());
        }
    }
    Ok(out)
}

/// CSV field: quoted when it contains a comma, a quote or a line break.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Header of `batch.csv`.
pub const BATCH_HEADER: &str = "index,record,scale,pga_g,pga_mps2,status,impacts,impacting_contacts,\
peak_joint_closing_m,peak_joint_opening_m,peak_rotation1_deg,peak_rotation2_deg,peak_slip_m,\
peak_seat_displacement_m,unseated,unseating_time_s,unseated_end,max_penetration_m,\
energy_balance_error,input_energy_J,viscous_dissipation_J,contact_dissipation_J,duration_s,steps,\
lcp_solves,lcp_failures,error";

fn batch_csv(rows: &[BatchRow]) -> String {
    let mut s = String::from(BATCH_HEADER);
    s.push('\n');
    let ncols = BATCH_HEADER.split(',').count();
    for r in rows {
        let mut c: Vec<String> = vec![r.index.to_string(), field(&r.record), float_token(r.scale)];
        match &r.outcome {
            Err(msg) => {
                c.extend(["".into(), "".into(), "error".into()]);
                c.resize(ncols - 1, String::new());
                c.push(field(msg));
            }
            Ok(o) => {
                let m = &o.summary;
                c.push(float_token(r.pga / G0));
                c.push(float_token(r.pga));
                c.push(format!("{:?}", o.status));
                c.push(m.impacts.to_string());
                c.push(m.impacting_contacts.to_string());
                for v in [
                    m.peak_joint_closing,
                    m.peak_joint_opening,
                    m.peak_rotation[0] * DEG,
                    m.peak_rotation[1] * DEG,
                    m.peak_slip,
                    m.peak_seat_displacement,
                ] {
                    c.push(float_token(v));
                }
                c.push(m.unseated.to_string());
                c.push(m.unseating_time.map_or(String::new(), float_token));
                c.push(m.unseated_end.map_or("", |i| SEAT_ENDS[i]).to_string());
                let e = &m.final_energy;
                for v in [
                    m.max_penetration,
                    m.energy_balance_error,
                    e.input,
                    e.viscous,
                    e.contact,
                    o.steps as Real * o.dt,
                ] {
                    c.push(float_token(v));
                }
                c.push(o.steps.to_string());
                c.push(o.lcp_solves.to_string());
                c.push(o.lcp_failures.to_string());
                c.push(String::new());
            }
        }
        debug_assert_eq!(c.len(), ncols);
        s.push_str(&c.join(","));
        s.push('\n');
    }
    s
}

/// Runs the batch (after the scenario has been built and validated).
pub fn run(
    args: &Args,
    base: &SimProblem,
    settings: &SimSettings,
    units: AccelUnits,
    t_start: Instant,
) -> Result<ExitCode> {
    let paths = expand_records(&args.records)?;
    let scales = if args.scales.is_empty() {
        vec![1.0]
    } else {
        args.scales.clone()
    };
    let shard = match &args.shard {
        Some(s) => BatchShard::parse(s).map_err(|e| anyhow!("{e}"))?,
        None => BatchShard::ALL,
    };
    pounding::input::check_threads(args.threads).map_err(anyhow::Error::msg)?;
    let records: Vec<BatchRecord> = paths
        .iter()
        .map(|p| BatchRecord {
            name: p.display().to_string(),
            record: Record::from_path(p, units).map_err(|e| e.to_string()),
        })
        .collect();
    pounding::sim::batch::validate_lists(&records, &scales).map_err(|e| anyhow!("{e}"))?;
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = args.threads {
        pool = pool.num_threads(n);
    }
    let pool = pool.build().context("cannot start the worker threads")?;
    let total = records.len() * scales.len();
    let todo = (0..total).filter(|&i| shard.contains(i)).count();
    eprintln!(
        "batch: {} records x {} scales = {} runs{} on {} threads",
        records.len(),
        scales.len(),
        total,
        if shard == BatchShard::ALL {
            String::new()
        } else {
            format!(" (shard {}/{}: {todo} runs)", shard.index, shard.count)
        },
        pool.current_num_threads()
    );
    // indicatif draws nothing when stderr is not a terminal.
    let pb = ProgressBar::with_draw_target(Some(todo as u64), ProgressDrawTarget::stderr());
    if let Ok(style) =
        ProgressStyle::with_template("runs [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta} left)")
    {
        pb.set_style(style);
    }
    pounding::output::check_output_dir_free(&args.out)?;
    let t_runs = Instant::now();
    let rows = pool
        .install(|| {
            run_batch(base, settings, &records, &scales, shard, &|n| {
                pb.inc(n as u64)
            })
        })
        .map_err(|e| anyhow!("{e}"))?;
    pb.finish_and_clear();
    let runs_secs = t_runs.elapsed().as_secs_f64();

    let out = &args.out;
    let _lock = super::lock_and_clear(out)?;
    let wr = |name: &str, bytes: &[u8]| {
        write_atomic(&out.join(name), bytes)
            .with_context(|| format!("cannot write {}", out.join(name).display()))
    };
    wr("batch.csv", batch_csv(&rows).as_bytes())?;
    let curves: Vec<BatchCurve> = records
        .iter()
        .enumerate()
        .map(|(a, rec)| {
            let mut pts: Vec<(Real, [Real; 4])> = rows
                .iter()
                .filter(|r| r.record_index == a)
                .filter_map(|r| {
                    let o = r.outcome.as_ref().ok()?;
                    let m = &o.summary;
                    Some((
                        r.pga / G0,
                        [
                            m.peak_seat_displacement,
                            m.peak_joint_opening,
                            m.peak_rotation[0].max(m.peak_rotation[1]) * DEG,
                            m.impacts as Real,
                        ],
                    ))
                })
                .collect();
            pts.sort_by(|p, q| p.0.total_cmp(&q.0));
            let label = PathBuf::from(&rec.name)
                .file_name()
                .map_or(rec.name.clone(), |f| f.to_string_lossy().into_owned());
            BatchCurve { label, pts }
        })
        .filter(|c| !c.pts.is_empty())
        .collect();
    sim_plots::batch_plot(out, "batch.png", &curves, base.model.seat_length)
        .map_err(|e| anyhow!("plotting: {e}"))?;
    let timing = json!({
        "runs_s": runs_secs,
        "wall_time_s": t_start.elapsed().as_secs_f64(),
        "runs": rows.len(),
        "threads": pool.current_num_threads(),
    });
    wr(
        "timing.json",
        (serde_json::to_string_pretty(&timing)? + "\n").as_bytes(),
    )?;

    let failed: Vec<&BatchRow> = rows.iter().filter(|r| r.outcome.is_err()).collect();
    let unseated = rows
        .iter()
        .filter(|r| r.outcome.as_ref().is_ok_and(|o| o.summary.unseated))
        .count();
    eprintln!(
        "batch: {} runs in {:.2} s, {} unseated, {} failed; outputs in {}",
        rows.len(),
        runs_secs,
        unseated,
        failed.len(),
        out.display()
    );
    // runs that finished but are not trustworthy (diverged, LCP/law-check or Newton failures)
    let untrusted: Vec<(&BatchRow, SimStatus)> = rows
        .iter()
        .filter_map(|r| r.outcome.as_ref().ok().map(|o| (r, o.status)))
        .filter(|(_, st)| *st != SimStatus::Completed)
        .collect();
    if let Some((_, st)) = untrusted.first() {
        eprintln!(
            "error: {} of {} runs ended with a status other than Completed (first: {:?}); their rows in              batch.csv are not trustworthy",
            untrusted.len(),
            rows.len(),
            st
        );
    }
    if failed.is_empty() {
        return Ok(if untrusted.is_empty() {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        });
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
    Ok(ExitCode::from(1))
}
