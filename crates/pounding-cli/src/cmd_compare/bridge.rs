//! The outputs of `pounding compare` on a bridge of `[[segment]]`s (the runs are the command's,
//! [`super::run`], for either form): each law of `--laws` replaces the law at
//! every joint and abutment (the other keys of the site tables and of `[contact]` apply when the
//! law reads them; a key that no compared law reads is refused first, exit 2). A law that
//! cannot run on this bridge (its build or the model refuses it, e.g. a time step too coarse
//! for its stiffness or a calibration it lacks) is skipped with the reason, on stderr and in
//! `compare.csv`; when every law is refused the first error is reported (exit 2).
//!
//! Its files are written by the one writer of either form ([`super::write_outputs`] over the
//! library's [`pounding::sim::output::compare_tables`]: `compare.csv`, `compare_sites.csv`, the
//! table on stdout, `report.html`, `timing.json` last); this module draws its figure,
//! `joint_gap.png` (one panel per site, in `compare_sites.csv`'s order: each joint's smaller end
//! gap over time, then each abutment's gap, one curve per law). Exit 1 when a law that ran did
//! not complete.

use super::plots::{R, panel};
use anyhow::{Result, anyhow};
use pounding::math::Real;
use pounding::sim::bridge::{ABUTMENT_SIDES, BridgeSolution};
use pounding::sim::compare::LawRun;
use std::path::Path;

/// The bridge's figure, `joint_gap.png`: one panel per site, one curve per law.
pub(super) fn draw(out: &Path, runs: &[LawRun]) -> Result<Vec<(&'static str, String)>> {
    let panels = gap_sites(runs);
    plot_gaps(out, runs, &panels).map_err(|e| anyhow!("plotting: {e}"))?;
    let names: Vec<String> = panels.iter().map(|s| s.name()).collect();
    let caption = format!(
        "The gap of each site by contact law, one panel per site ({}): a joint's is the smaller \
         of its two end gaps, an abutment's the smaller of its corner gaps.",
        names.join(", ")
    );
    Ok(vec![("joint_gap.png", caption)])
}

/// A panel of `joint_gap.png`: a joint (0-based) or an abutment (0 start, 1 end).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Site {
    Joint(usize),
    Abutment(usize),
}

impl Site {
    /// The site's name, as in `compare_sites.csv` and `summary.json`.
    fn name(self) -> String {
        match self {
            Site::Joint(k) => format!("joint{}", k + 1),
            Site::Abutment(side) => format!("abutment-{}", ABUTMENT_SIDES[side]),
        }
    }
}

/// The sites of the bridge in `compare_sites.csv`'s order: its joints, then the abutments
/// present (taken from the first law that ran: every law runs the same bridge).
fn gap_sites(runs: &[LawRun]) -> Vec<Site> {
    let Some(sol) = runs.iter().find_map(|r| r.ran().map(|x| &x.sol)) else {
        return Vec::new();
    };
    let joints = (0..sol.n_segments - 1).map(Site::Joint);
    let abutments = (0..2)
        .filter(|&side| sol.summary.abutments[side].is_some())
        .map(Site::Abutment);
    joints.chain(abutments).collect()
}

/// `(t, gap)` of `site` in a run: a joint's smaller end gap, an abutment's smaller corner gap.
fn gap_series(sol: &BridgeSolution, site: Site) -> Vec<(Real, Real)> {
    let nj = sol.n_segments - 1;
    sol.t
        .iter()
        .enumerate()
        .map(|(i, &t)| {
            let g = match site {
                Site::Joint(k) => {
                    let row = &sol.end_gaps[i * 2 * nj..(i + 1) * 2 * nj];
                    // `min` of a NaN (no corner over the face) and a gap is the gap
                    row[2 * k].min(row[2 * k + 1])
                }
                Site::Abutment(side) => sol.abutment_gaps[i][side],
            };
            (t, g)
        })
        .collect()
}

/// `joint_gap.png`: one panel per site of `panels`, a curve per law that ran.
fn plot_gaps(out: &Path, runs: &[LawRun], panels: &[Site]) -> R {
    crate::plot_style::register();
    let ran: Vec<(&str, &BridgeSolution)> = runs
        .iter()
        .filter_map(|r| r.ran().map(|x| (r.law.as_str(), &x.sol)))
        .collect();
    let t_end = ran
        .iter()
        .filter_map(|(_, s)| s.t.last().copied())
        .fold(0.0, Real::max)
        .max(1e-9);
    let height = (300 * panels.len()).clamp(450, 3000) as u32;
    crate::plot_style::save_white_png(out, "joint_gap.png", (1200, height), |root| {
        let areas = root.split_evenly((panels.len().max(1), 1));
        for (area, site) in areas.iter().zip(panels) {
            let curves: Vec<(&str, Vec<(Real, Real)>)> = ran
                .iter()
                .map(|(l, s)| (*l, gap_series(s, *site)))
                .collect();
            let title = match site {
                Site::Joint(k) => format!(
                    "Joint {} gap (smaller of the two ends) by contact law",
                    k + 1
                ),
                Site::Abutment(_) => format!("{} gap by contact law", site.name()),
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
