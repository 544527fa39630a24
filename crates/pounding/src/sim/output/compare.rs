//! The files of `pounding compare` (one scenario, several contact laws): `compare.csv` and the
//! readable table printed on stdout.

use super::DEG;
use crate::math::Real;
use crate::output::{fixed, float_token};
use crate::sim::bridge::BridgeSolution;

/// Every file `compare` writes; removed before a new run writes. `timing.json` is written last
/// and marks a complete run (as in `pounding study`).
pub const COMPARE_OUTPUTS: &[&str] = &[
    "timing.json",
    "compare.csv",
    "joint_gap.png",
    "contact_force.png",
];

/// Columns of `compare.csv` (the stdout table shows a subset).
pub const COMPARE_HEADER: &str = "law,impacts,impacting_contacts,peak_contact_force_N,peak_penetration_m,\
peak_joint_closing_m,peak_joint_opening_m,peak_rotation1_deg,peak_rotation2_deg,peak_slip_m,\
peak_seat_displacement_m,unseated,unseating_time_s,contact_dissipation_J,steps_per_contact,status";

/// `compare.csv`: [`COMPARE_HEADER`], then one row per `(law, solution)`.
pub fn compare_csv(runs: &[(&str, &BridgeSolution)]) -> String {
    let mut s = String::from(COMPARE_HEADER);
    s.push('\n');
    for &(law, sol) in runs {
        let m = &sol.summary;
        let joint = &m.joints[0];
        let row = [
            law.to_string(),
            m.impacts.to_string(),
            sol.impacts.len().to_string(),
            float_token(joint.peak_contact_force.unwrap_or(Real::NAN)),
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

/// The readable table `pounding compare` prints: one line per `(law, solution)`.
pub fn compare_table(runs: &[(&str, &BridgeSolution)]) -> String {
    let mut s = format!(
        "{:<11} {:>7} {:>11} {:>10} {:>11} {:>17} {:>9} {:>9}\n",
        "law",
        "impacts",
        "force [MN]",
        "pen. [mm]",
        "closing [m]",
        "rotation [deg]",
        "seat [m]",
        "unseated"
    );
    for &(law, sol) in runs {
        let m = &sol.summary;
        let f = m.joints[0]
            .peak_contact_force
            .map_or("-".to_string(), |f| format!("{:.3}", f / 1e6));
        s.push_str(&format!(
            "{:<11} {:>7} {:>11} {:>10} {:>11} {:>8}/{:<8} {:>9} {:>9}\n",
            law,
            m.impacts,
            f,
            fixed(m.peak_penetration * 1e3, 3),
            fixed(m.joints[0].peak_closing, 5),
            fixed(m.segments[0].peak_rotation * DEG, 4),
            fixed(m.segments[1].peak_rotation * DEG, 4),
            fixed(m.peak_seat_displacement, 4),
            if m.unseated { "YES" } else { "no" }
        ));
    }
    s.push_str("(rigid contact has impulses, no force: its force column is '-')\n");
    s
}
