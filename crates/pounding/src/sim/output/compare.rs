//! The files of `pounding compare` (one scenario, several contact laws): `compare.csv` and the
//! readable table printed on stdout.

use super::{DEG, PeakEstimate};
use crate::math::Real;
use crate::output::{fixed, float_token};
use crate::sim::compare::LawRun;

/// Every file `compare` writes; removed before a new run writes. `timing.json` is written last
/// and marks a complete run (as in `pounding study`).
pub const COMPARE_OUTPUTS: &[&str] = &[
    "timing.json",
    "report.html",
    "compare.csv",
    "joint_gap.png",
    "contact_force.png",
];

/// Columns of `compare.csv` (the stdout table shows a subset). `peak_contact_force_N` is the
/// force a compliance law computes (`nan` for rigid contact, which has impulses only);
/// `peak_force_estimate_N` and `contact_time_estimate_s` are the rigid law's estimate from the
/// impulse and the contact duration it assumes ([`crate::contact_law::estimate`]; `nan` for the
/// compliance laws and without impacts).
pub const COMPARE_HEADER: &str = "law,impacts,impacting_contacts,peak_contact_force_N,\
peak_force_estimate_N,contact_time_estimate_s,peak_penetration_m,\
peak_joint_closing_m,peak_joint_opening_m,peak_rotation1_deg,peak_rotation2_deg,peak_slip_m,\
peak_seat_displacement_m,unseated,unseating_time_s,contact_dissipation_J,steps_per_contact,status";

/// The estimate's `(force, duration)`, NaN for none.
fn estimate_pair(e: Option<PeakEstimate>) -> (Real, Real) {
    e.map_or((Real::NAN, Real::NAN), |e| (e.peak_force, e.contact_time))
}

/// `compare.csv`: [`COMPARE_HEADER`], then one row per law that ran (the two-deck model runs
/// every law).
pub(super) fn compare_csv(runs: &[LawRun]) -> String {
    let mut s = String::from(COMPARE_HEADER);
    s.push('\n');
    for r in runs {
        let Some(ran) = r.ran() else { continue };
        let (law, sol) = (&r.law, &ran.sol);
        let m = &sol.summary;
        let joint = &m.joints[0];
        let (est, t_c) = estimate_pair(ran.peak_estimate());
        let row = [
            law.to_string(),
            m.impacts.to_string(),
            sol.impacts.len().to_string(),
            float_token(joint.peak_contact_force.unwrap_or(Real::NAN)),
            float_token(est),
            float_token(t_c),
            float_token(m.peak_penetration),
            float_token(joint.peak_closing),
            float_token(joint.peak_opening),
            float_token(m.segments[0].peak_rotation * DEG),
            float_token(m.segments[1].peak_rotation * DEG),
            float_token(joint.peak_slip),
            float_token(m.peak_seat_displacement),
            m.unseated.to_string(),
            float_token(m.unseating_time.unwrap_or(Real::NAN)),
            float_token(m.final_energy.contact),
            float_token(
                sol.time_step_advice
                    .map_or(Real::NAN, |a| a.steps_per_contact),
            ),
            format!("{:?}", sol.status),
        ];
        s.push_str(&row.join(","));
        s.push('\n');
    }
    s
}

/// The readable table `pounding compare` prints: one line per law that ran.
pub(super) fn compare_table(runs: &[LawRun]) -> String {
    let mut s = format!(
        "{:<11} {:>7} {:>11} {:>14} {:>10} {:>11} {:>17} {:>9} {:>9}\n",
        "law",
        "impacts",
        "force [MN]",
        "estimate [MN]",
        "pen. [mm]",
        "closing [m]",
        "rotation [deg]",
        "seat [m]",
        "unseated"
    );
    for r in runs {
        let Some(ran) = r.ran() else { continue };
        let (law, sol) = (&r.law, &ran.sol);
        let m = &sol.summary;
        let f = m.joints[0]
            .peak_contact_force
            .map_or("-".to_string(), |f| format!("{:.3}", f / 1e6));
        s.push_str(&format!(
            "{:<11} {:>7} {:>11} {:>14} {:>10} {:>11} {:>8}/{:<8} {:>9} {:>9}\n",
            law,
            m.impacts,
            f,
            estimate_cell(ran.peak_estimate()),
            fixed(m.peak_penetration * 1e3, 3),
            fixed(m.joints[0].peak_closing, 5),
            fixed(m.segments[0].peak_rotation * DEG, 4),
            fixed(m.segments[1].peak_rotation * DEG, 4),
            fixed(m.peak_seat_displacement, 4),
            if m.unseated { "YES" } else { "no" }
        ));
    }
    s.push_str(ESTIMATE_NOTE);
    s
}

/// The estimate in MN, `-` for none (a table cell).
pub(crate) fn estimate_cell(e: Option<PeakEstimate>) -> String {
    e.map_or("-".to_string(), |e| format!("~{:.3}", e.peak_force / 1e6))
}

/// The footnote of the printed tables on the two force columns.
pub(crate) const ESTIMATE_NOTE: &str = "(force: computed by a compliance law; rigid contact has \
impulses, no force: its estimate ~ is the peak of a half-sine pulse of the impulse over the Hertz \
contact duration, compare.csv column contact_time_estimate_s)\n";
