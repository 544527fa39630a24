//! The outputs of `pounding compare` on a bridge of `[[segment]]`s (the runs are the command's,
//! [`super::run`], for either form): each law of `--laws` replaces the law at
//! every joint and abutment (the other keys of the site tables and of `[contact]` apply when the
//! law reads them; a key that no compared law reads is refused first, exit 2). A law that
//! cannot run on this bridge (its build or the model refuses it, e.g. a time step too coarse
//! for its stiffness or a calibration it lacks) is skipped with the reason, on stderr and in
//! `compare.csv`; when every law is refused the first error is reported (exit 2).
//!
//! Writes `compare.csv` and `compare_sites.csv` (library writers,
//! [`pounding::sim::output::bridge_compare_csv`]), the table on stdout, `joint_gap.png` (one
//! panel per joint: its smaller end gap over time, one curve per law; the start abutment's
//! gap when the bridge has no joint), `report.html` and `timing.json` (last). Exit 1 when a law that ran did
//! not complete.

use super::plots::{R, panel};
use super::{Job, timing_json, write};
use anyhow::{Result, anyhow};
use pounding::math::Real;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::compare::LawRun;
use pounding::sim::output::{
    BRIDGE_COMPARE_OUTPUTS, COMPARE_OUTPUTS, bridge_compare_csv, bridge_compare_sites_csv,
    bridge_compare_table,
};
use std::path::Path;

/// Writes the CSV files, the table, the plot, `report.html` and `timing.json` into the locked
/// `out`.
pub(super) fn write_outputs(ctx: &Job) -> Result<()> {
    let out = ctx.out;
    let lock = pounding::output::lock_output_dir(out)?;
    pounding::output::remove_previous_outputs(&lock, BRIDGE_COMPARE_OUTPUTS)?;
    pounding::output::remove_previous_outputs(&lock, COMPARE_OUTPUTS)?;
    let csv = bridge_compare_csv(ctx.runs);
    let sites = bridge_compare_sites_csv(ctx.runs);
    write(out, "compare.csv", csv.as_bytes())?;
    write(out, "compare_sites.csv", sites.as_bytes())?;
    print!("{}", bridge_compare_table(ctx.runs));
    plot_gaps(out, ctx.runs).map_err(|e| anyhow!("plotting: {e}"))?;
    let page = crate::compare_report::Page {
        ctx,
        files: &["compare.csv", "compare_sites.csv", "timing.json"],
        tables: vec![
            ("Per law (compare.csv)", csv),
            ("Per joint and abutment (compare_sites.csv)", sites),
        ],
        figures: &[(
            "joint_gap.png",
            "Each joint's gap (the smaller of its two ends) by contact law; the abutments' \
             smaller gap when the bridge has no joint.",
        )],
    };
    write(
        out,
        "report.html",
        crate::compare_report::html(&page).as_bytes(),
    )?;
    write(out, "timing.json", timing_json(ctx, true)?.as_bytes())?;
    eprintln!("outputs in {}", out.display());
    Ok(())
}

/// `(t, smaller end gap of joint k)` of a run (`k = None`: the start abutment's gap).
fn gap_series(sol: &BridgeSolution, k: Option<usize>) -> Vec<(Real, Real)> {
    let nj = sol.n_segments - 1;
    sol.t
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            let g = match k {
                Some(k) => {
                    let row = &sol.end_gaps[i * 2 * nj..(i + 1) * 2 * nj];
                    // `min` of a NaN (no corner over the face) and a gap is the gap
                    row[2 * k].min(row[2 * k + 1])
                }
                None => sol.abutment_gaps[i][0].min(sol.abutment_gaps[i][1]),
            };
            (t, g)
        })
        .collect()
}

/// `joint_gap.png`: one panel per joint (the smaller of its two end gaps), a curve per law that
/// ran; a bridge without joints shows its abutments' smaller gap.
fn plot_gaps(out: &Path, runs: &[LawRun]) -> R {
    crate::plot_style::register();
    let ran: Vec<(&str, &BridgeSolution)> = runs
        .iter()
        .filter_map(|r| r.ran().map(|x| (r.law.as_str(), &x.sol)))
        .collect();
    let nj = ran.first().map_or(0, |(_, s)| s.n_segments - 1);
    let panels: Vec<Option<usize>> = if nj == 0 {
        vec![None]
    } else {
        (0..nj).map(Some).collect()
    };
    let t_end = ran
        .iter()
        .filter_map(|(_, s)| s.t.last().copied())
        .fold(0.0, Real::max)
        .max(1e-9);
    let height = (300 * panels.len()).clamp(450, 3000) as u32;
    crate::plot_style::save_white_png(out, "joint_gap.png", (1200, height), |root| {
        let areas = root.split_evenly((panels.len(), 1));
        for (area, k) in areas.iter().zip(&panels) {
            let curves: Vec<(&str, Vec<(Real, Real)>)> =
                ran.iter().map(|(l, s)| (*l, gap_series(s, *k))).collect();
            let title = match k {
                Some(k) => format!(
                    "Joint {} gap (smaller of the two ends) by contact law",
                    k + 1
                ),
                None => "Abutment gap (smaller of the two) by contact law".to_string(),
            };
            panel(
                area,
                &title,
                "gap [m]",
                (0.0, t_end),
                &curves,
                Some((0.0, "contact")),
            )?;
        }
        Ok(())
    })?;
    Ok(())
}
