//! The files of `pounding compare` on a bridge of `[[segment]]`s (one bridge, several contact
//! laws, each replacing the law at every joint and abutment): `compare.csv` (one row per law:
//! the headline figures of the bridge summary, or why the law was skipped),
//! `compare_sites.csv` (one row per law and site: the figures an engineer compares joint by
//! joint) and the readable table printed on stdout.
//!
//! Empty fields mean "not applicable": the contact force of rigid contact (impulses only; its
//! estimate from the impulse has columns of its own), the estimate of a compliance law, a
//! joint's opening at an abutment, the figures of a skipped law. Numbers are [`float_token`]s.

use super::batch::field;
use super::compare::{COMPARE_OUTPUTS, ESTIMATE_NOTE, compare_csv, compare_table, estimate_cell};
use super::{PeakEstimate, SiteKey};
use crate::math::Real;
use crate::output::{fixed, float_token};
use crate::sim::bridge::ABUTMENT_SIDES;
use crate::sim::compare::{LawRun, Ran};
use std::collections::BTreeMap;

/// Every file `compare` writes for a bridge; removed before a new run writes. `timing.json` is
/// written last and marks a complete run.
pub const BRIDGE_COMPARE_OUTPUTS: &[&str] = &[
    "timing.json",
    "report.html",
    "compare.csv",
    "compare_sites.csv",
    "joint_gap.png",
];

/// A CSV table of `pounding compare`: its file name, its title in `report.html` and its bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct CompareTable {
    /// The file name (`compare.csv`, `compare_sites.csv`).
    pub name: &'static str,
    /// The table's title in the report.
    pub title: &'static str,
    /// The CSV text.
    pub csv: String,
}

/// The one writer of a comparison's tables, either form: its CSV tables in the order written
/// and the readable table printed on stdout. A bridge has `compare.csv` (its own columns,
/// [`BRIDGE_COMPARE_HEADER`]) and `compare_sites.csv`; the two-deck preset keeps its
/// `compare.csv` columns ([`super::COMPARE_HEADER`]).
pub fn compare_tables(runs: &[LawRun], bridge: bool) -> (Vec<CompareTable>, String) {
    let per_law = |csv| CompareTable {
        name: "compare.csv",
        title: "Per law (compare.csv)",
        csv,
    };
    if !bridge {
        return (vec![per_law(compare_csv(runs))], compare_table(runs));
    }
    let sites = CompareTable {
        name: "compare_sites.csv",
        title: "Per joint and abutment (compare_sites.csv)",
        csv: bridge_compare_sites_csv(runs),
    };
    (
        vec![per_law(bridge_compare_csv(runs)), sites],
        bridge_compare_table(runs),
    )
}

/// Every file a comparison of either form may have written, cleared before a new one writes.
pub fn compare_outputs() -> impl Iterator<Item = &'static str> {
    BRIDGE_COMPARE_OUTPUTS
        .iter()
        .chain(
            COMPARE_OUTPUTS
                .iter()
                .filter(|f| !BRIDGE_COMPARE_OUTPUTS.contains(f)),
        )
        .copied()
}

/// Columns of the bridge `compare.csv`: per law its status (`Completed`, … or `skipped`), steps,
/// impacts of the whole bridge, the largest contact force computed by a compliance law over all
/// joints and abutments, the rigid law's largest peak-force estimate from the impulse and the
/// contact duration it assumes ([`crate::contact_law::estimate`]), the largest impulse, the
/// largest joint closing and opening, the largest penetration, segment
/// displacement and seat displacement, the governing seated end and its ratio (peak over its own
/// seat, as `summary.json`'s `governing_seat`), unseating, the energy-balance error, and the
/// reason a skipped law could not run.
pub const BRIDGE_COMPARE_HEADER: &str = "law,status,steps,impacts,peak_contact_force_n,\
peak_force_estimate_n,contact_time_estimate_s,peak_impulse_ns,peak_closing_m,peak_opening_m,peak_penetration_m,peak_displacement_m,\
peak_seat_displacement_m,governing_seat_end,governing_seat_ratio,unseated,energy_balance_error,skipped_reason";

/// Columns of `compare_sites.csv`: one row per law that ran and site (`joint1`, … in bridge
/// order, then `abutment-start`, `abutment-end` where present, the names of `summary.json`'s
/// `seats[]` and `impacts.csv`), as the `joints` /
/// `abutments` arrays of a bridge `summary.json`, and the site's rigid peak-force estimate
/// (empty for a compliance law).
pub const BRIDGE_COMPARE_SITES_HEADER: &str = "law,site,impacts,peak_contact_force_n,\
peak_force_estimate_n,contact_time_estimate_s,peak_impulse_ns,peak_closing_m,peak_opening_m,\
restrainer_peak_force_n";

/// `Some(x)` as its token, `None` as an empty field.
fn opt(x: Option<Real>) -> String {
    x.map_or(String::new(), float_token)
}

/// The largest of `xs` (`None` when empty or all `None`).
fn max_of(xs: impl Iterator<Item = Option<Real>>) -> Option<Real> {
    xs.flatten().reduce(Real::max)
}

/// One site's figures: `(site, impacts, force, impulse, closing, opening, restrainer force,
/// estimate)`.
type SiteRow = (
    String,
    usize,
    Option<Real>,
    Real,
    Real,
    Option<Real>,
    Option<Real>,
    Option<PeakEstimate>,
);

/// The sites of a run in bridge order.
fn sites(ran: &Ran) -> Vec<SiteRow> {
    let s = &ran.sol.summary;
    let empty = BTreeMap::new();
    let est: &BTreeMap<SiteKey, PeakEstimate> = ran.estimates.as_ref().unwrap_or(&empty);
    let mut rows: Vec<SiteRow> = s
        .joints
        .iter()
        .enumerate()
        .map(|(k, j)| {
            (
                format!("joint{}", k + 1),
                j.impacts,
                j.peak_contact_force,
                j.peak_impulse,
                j.peak_closing,
                Some(j.peak_opening),
                j.restrainer_peak_force,
                est.get(&(true, k)).copied(),
            )
        })
        .collect();
    for (side, a) in s.abutments.iter().enumerate() {
        if let Some(a) = a {
            rows.push((
                format!("abutment-{}", ABUTMENT_SIDES[side]),
                a.impacts,
                a.peak_contact_force,
                a.peak_impulse,
                a.peak_closing,
                None,
                None,
                est.get(&(false, side)).copied(),
            ));
        }
    }
    rows
}

/// The bridge `compare.csv`: [`BRIDGE_COMPARE_HEADER`], then one row per `(law, run)`.
pub(super) fn bridge_compare_csv(runs: &[LawRun]) -> String {
    let mut out = String::from(BRIDGE_COMPARE_HEADER);
    out.push('\n');
    for run in runs {
        let law = run.law.as_str();
        let row: Vec<String> = match &run.outcome {
            Err(why) => {
                let mut r = vec![field(law), "skipped".into()];
                r.extend(std::iter::repeat_n(String::new(), 15));
                r.push(field(why));
                r
            }
            Ok(ran) => {
                let sol = &ran.sol;
                let s = &sol.summary;
                let site = sites(ran);
                let e = ran.peak_estimate();
                vec![
                    field(law),
                    format!("{:?}", sol.status),
                    sol.steps.to_string(),
                    s.impacts.to_string(),
                    opt(max_of(site.iter().map(|r| r.2))),
                    opt(e.map(|e| e.peak_force)),
                    opt(e.map(|e| e.contact_time)),
                    opt(max_of(site.iter().map(|r| Some(r.3)))),
                    opt(max_of(s.joints.iter().map(|j| Some(j.peak_closing)))),
                    opt(max_of(s.joints.iter().map(|j| Some(j.peak_opening)))),
                    float_token(s.peak_penetration),
                    opt(max_of(s.segments.iter().map(|g| Some(g.peak_displacement)))),
                    float_token(s.peak_seat_displacement),
                    s.seats
                        .get(s.governing_seat)
                        .map_or(String::new(), |g| g.end.clone()),
                    s.seats
                        .get(s.governing_seat)
                        .map_or(String::new(), |g| float_token(g.ratio)),
                    s.unseated.to_string(),
                    float_token(s.energy_balance_error),
                    String::new(),
                ]
            }
        };
        out.push_str(&row.join(","));
        out.push('\n');
    }
    out
}

/// `compare_sites.csv`: [`BRIDGE_COMPARE_SITES_HEADER`], then one row per site of every law
/// that ran (skipped laws have no rows; `compare.csv` says why).
pub(super) fn bridge_compare_sites_csv(runs: &[LawRun]) -> String {
    let mut out = String::from(BRIDGE_COMPARE_SITES_HEADER);
    out.push('\n');
    for run in runs {
        let Some(ran) = run.ran() else {
            continue;
        };
        for (site, impacts, force, impulse, closing, opening, restrainer, est) in sites(ran) {
            let row = [
                field(&run.law),
                site,
                impacts.to_string(),
                opt(force),
                opt(est.map(|e| e.peak_force)),
                opt(est.map(|e| e.contact_time)),
                float_token(impulse),
                float_token(closing),
                opt(opening),
                opt(restrainer),
            ];
            out.push_str(&row.join(","));
            out.push('\n');
        }
    }
    out
}

/// The readable table `pounding compare` prints for a bridge: one line per law and site
/// (forces in MN, `-` for rigid contact), then the skipped laws with their reasons.
pub(super) fn bridge_compare_table(runs: &[LawRun]) -> String {
    let mut s = format!(
        "{:<11} {:<15} {:>7} {:>11} {:>14} {:>13} {:>11} {:>11}\n",
        "law",
        "site",
        "impacts",
        "force [MN]",
        "estimate [MN]",
        "impulse [kNs]",
        "closing [m]",
        "opening [m]"
    );
    let mut skipped = Vec::new();
    for run in runs {
        let law = run.law.as_str();
        let ran = match &run.outcome {
            Ok(ran) => ran,
            Err(why) => {
                skipped.push(format!("{law}: {why}"));
                continue;
            }
        };
        let sol = &ran.sol;
        for (site, impacts, force, impulse, closing, opening, _, est) in sites(ran) {
            let f = force.map_or("-".to_string(), |f| format!("{:.3}", f / 1e6));
            let o = opening.map_or("-".to_string(), |o| fixed(o, 5));
            s.push_str(&format!(
                "{:<11} {:<15} {:>7} {:>11} {:>14} {:>13} {:>11} {:>11}\n",
                law,
                site,
                impacts,
                f,
                estimate_cell(est),
                fixed(impulse / 1e3, 3),
                fixed(closing, 5),
                o
            ));
        }
        if sol.status != crate::sim::SimStatus::Completed {
            s.push_str(&format!("{law:<11} status {:?}\n", sol.status));
        }
    }
    s.push_str(ESTIMATE_NOTE);
    for k in skipped {
        s.push_str(&format!("skipped {k}\n"));
    }
    s
}
