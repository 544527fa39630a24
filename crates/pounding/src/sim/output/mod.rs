//! The files a `simulate` run writes, as text: `history.csv`, `impacts.csv`, `summary.json` and
//! the batch's `batch.csv`, and those of `pounding compare`. Numbers are shortest round-trip ([`float_token`]: `inf`, `-inf`, `nan`
//! in CSV; [`json_float`]: `null` in JSON), so the bytes are the same for any thread count.

use super::bridge::{BridgeSolution, SeatSummary};
use super::scenario::SimSetup;
use super::{JointContact, SimModel};

use crate::ground_motion::Record;
use crate::math::Real;
use crate::output::{float_token, json_float};
use crate::shape::DeckShape;
use serde_json::json;

mod batch;
mod bridge;
mod bridge_plan;
mod compare;
mod compare_bridge;
mod estimate;
mod history;
mod impacts;
mod input_warnings;
mod trajectories;
mod verdict;
pub use batch::{BATCH_HEADER, BATCH_TAIL, batch_csv, batch_set_csv, bridge_batch_header};
pub use bridge::governing_seat_line;
pub(crate) use bridge::{bridge_summary_json, bridge_summary_json_text};
pub use bridge_plan::{
    BridgePlan, CornerPaths, bridge_plan, corner_paths, joint_openings, plan_exaggeration,
    segment_displacements,
};
pub use compare::{COMPARE_HEADER, COMPARE_OUTPUTS};
pub use compare_bridge::{
    BRIDGE_COMPARE_HEADER, BRIDGE_COMPARE_OUTPUTS, BRIDGE_COMPARE_SITES_HEADER, CompareTable,
    compare_outputs, compare_tables,
};
pub use estimate::{PeakEstimate, SiteKey, peak_force_estimates};
pub(crate) use estimate::{largest_estimate, peak_estimate_json, rigid_estimate, setup_estimates};
pub use history::History;
pub use impacts::{impacts_csv, run_warnings};
pub use input_warnings::{InputWarning, input_warnings, warning_sentence};
pub use trajectories::{TRAJECTORY_MAX_FRAMES, trajectories_json, trajectory_stride};
pub(crate) use verdict::n3;
pub use verdict::{VerdictLine, verdict};

/// Degrees per radian.
/// How a run's files name its parts: a bridge's layout (`[[segment]]` scenarios: segments,
/// joints and abutments by number and side) or the two-deck model's (its files' own columns and
/// names: `x1`, `deck1-inner`, `abutment_gap2`, …). One solution, one writer per file, two layouts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// The two-deck model's files.
    TwoDecks,
    /// A bridge's files.
    Bridge,
}

pub(crate) const DEG: Real = 180.0 / std::f64::consts::PI;

/// Every file `simulate` writes (single run and batch). A run into a directory first removes all
/// of them, so that no earlier run's plots (e.g. `abutment_gap.png` of a run with abutments) or
/// `timing.json` stay beside the new results. `timing.json` is written last and marks a complete
/// run (as in `pounding study`).
pub const SIM_OUTPUTS: &[&str] = &[
    "timing.json",
    "history.csv",
    "impacts.csv",
    "summary.json",
    "bearings.csv",
    "restrainers.csv",
    "joint_slip.csv",
    "piers.csv",
    "backwalls.csv",
    "shear_keys.csv",
    "segment_forces.csv",
    "displacements.png",
    "layout.png",
    "rotations.png",
    "joint_gap.png",
    "abutment_gap.png",
    "impulses.png",
    "energy.png",
    "batch.csv",
    "batch.png",
    "joint_openings.png",
    "plan.png",
    "joint_zoom.png",
    "hysteresis.png",
    "report.html",
    "trajectories.json",
    "accuracy.csv",
    "accuracy.json",
];

/// The two-deck name of a seated end of the two-deck bridge ([`crate::sim::SEAT_ENDS`]): deck `j` is segment
/// `j`; its end on the joint is `deck<j>-joint`, the other `deck<j>-far`.
pub fn pair_seat_name(seat: &SeatSummary) -> String {
    let side = if seat.support.starts_with("joint") {
        "joint"
    } else {
        "far"
    };
    format!("deck{}-{side}", seat.segment)
}

/// The two-deck name ([`pair_seat_name`]) of the end that unseated first.
pub(crate) fn pair_unseated_end(s: &super::bridge::BridgeSummary) -> Option<String> {
    let name = s.unseated_end.as_ref()?;
    s.seats.iter().find(|e| &e.end == name).map(pair_seat_name)
}

/// The numbers of an `impacts.csv` row: velocities before and after, impulses, dissipated
/// energy (shared by the two-deck and the bridge files).
pub(crate) fn impact_numbers(r: &super::ImpactRecord) -> String {
    [
        r.gamma_n_pre,
        r.gamma_t_pre,
        r.gamma_n_post,
        r.gamma_t_post,
        r.impulse_n,
        r.impulse_t,
        r.energy_dissipated,
    ]
    .map(float_token)
    .join(",")
}

/// Columns appended to `impacts.csv` for a compliance law ([`super::ImpactPulse`]).
pub const PULSE_COLUMNS: &str = "peak_force_n,duration_s,max_penetration_m";
/// Columns appended to `impacts.csv` for the rigid law
/// ([`crate::contact_law::estimate::rigid_peak_force`] with the default `k_h`).
pub const ESTIMATE_COLUMNS: &str = "peak_force_estimate_n,contact_time_estimate_s";

/// The appended cells of an `impacts.csv` row: the pulse of a compliance law, or (rigid law,
/// `rigid`) the peak-force estimate from the impulse with restitution `eps`.
pub(crate) fn pulse_cells(r: &super::ImpactRecord, rigid: bool, eps: Real) -> String {
    if rigid {
        let e = rigid_estimate(r, eps);
        return format!(
            "{},{}",
            float_token(e.peak_force),
            float_token(e.contact_time)
        );
    }
    let p = r.pulse.unwrap_or(super::ImpactPulse {
        peak_force: Real::NAN,
        duration: Real::NAN,
        max_penetration: Real::NAN,
    });
    [p.peak_force, p.duration, p.max_penetration]
        .map(float_token)
        .join(",")
}

/// Relative tolerance of [`energy_warnings`] for the rigid law: energy created at a contact
/// counts when it exceeds `1e-6 (|P_N γ_N⁻| + |P_T γ_T⁻|)` of that contact (the energy scale the
/// impulse exchanges), far above rounding (≈ 1e-16 of it) and below any physical creation by
/// Newton + Coulomb (a sizeable fraction of it, spec §11: up to 14 % and more).
pub const ENERGY_WARNING_TOLERANCE: Real = 1e-6;
/// Relative tolerance of [`energy_warnings`] for compliance laws: their contact work is
/// integrated by the trapezoidal rule, whose error is `O((h/T_c)²)` of the exchanged energy
/// (≈ 1e-5 at the project's OpenSees benchmark); a gain beyond `1e-3` of the scale is reported.
pub const COMPLIANCE_ENERGY_WARNING_TOLERANCE: Real = 1e-3;

/// A run warning: something a user must know although the run completed (`summary.json`'s
/// `warnings`, also printed on stderr by the CLI).
#[derive(Debug, Clone, PartialEq)]
pub struct RunWarning {
    /// What: `contact_energy_created` (rigid law: a contact's dissipation in an impact was
    /// negative, Newton's law with Coulomb friction) or `contact_energy_created_numerically`
    /// (compliance law: a contact's work over an impact returned more energy than it absorbed, a
    /// discretisation error: time step or the switching of the contact corner at a joint end).
    pub kind: &'static str,
    /// The impact number (`impacts.csv`'s `impact`).
    pub impact: usize,
    /// Where (the contact as `impacts.csv` names it; a bridge: `site/contact`).
    pub contact: String,
    /// When \[s\] (`impacts.csv`'s `t_s`).
    pub time: Real,
    /// How much energy \[J\] (> 0).
    pub amount: Real,
}

impl RunWarning {
    /// The `summary.json` object: `kind`, `impact`, `contact`, `t_s`, `amount_j`.
    pub fn json(&self) -> serde_json::Value {
        json!({
            "kind": self.kind,
            "impact": self.impact,
            "contact": self.contact,
            "t_s": json_float(self.time),
            "amount_j": json_float(self.amount),
        })
    }
}

/// One warning per impacting contact whose dissipation `energy_dissipated` is negative beyond
/// the tolerance: `contact_energy_created` for the rigid law (Newton's law with Coulomb friction
/// and `ε_T = 0` can create energy, spec §11; [`ENERGY_WARNING_TOLERANCE`]),
/// `contact_energy_created_numerically` for a compliance law (`rigid = false`;
/// [`COMPLIANCE_ENERGY_WARNING_TOLERANCE`]). `name` names a record's contact.
pub fn energy_warnings(
    impacts: &[super::ImpactRecord],
    rigid: bool,
    name: impl Fn(&super::ImpactRecord) -> String,
) -> Vec<RunWarning> {
    let (tol, kind) = if rigid {
        (ENERGY_WARNING_TOLERANCE, "contact_energy_created")
    } else {
        (
            COMPLIANCE_ENERGY_WARNING_TOLERANCE,
            "contact_energy_created_numerically",
        )
    };
    impacts
        .iter()
        .filter(|r| {
            let scale = (r.impulse_n * r.gamma_n_pre).abs() + (r.impulse_t * r.gamma_t_pre).abs();
            r.energy_dissipated < -tol * scale
        })
        .map(|r| RunWarning {
            kind,
            impact: r.impact,
            contact: name(r),
            time: r.time,
            amount: -r.energy_dissipated,
        })
        .collect()
}

/// The stderr line of a run's warnings (`None` without any): their number, total and the largest.
pub fn warnings_message(w: &[RunWarning]) -> Option<String> {
    let largest = w.iter().max_by(|a, b| a.amount.total_cmp(&b.amount))?;
    let total: Real = w.iter().map(|x| x.amount).sum();
    let why = if largest.kind == "contact_energy_created" {
        "Newton's law with Coulomb friction (tangential restitution 0) can create energy"
    } else {
        "the compliance contact returned more energy than it absorbed (a discretisation error: \
         check with a smaller dt)"
    };
    Some(format!(
        "warning: energy was created at a contact in {} impacting contact{} (total {} J; largest {} J \
         at {} in impact {}, t = {} s): {why}; every one is listed in the run's warnings (simulate: \
         summary.json \"warnings\"; compare: report.html)",
        w.len(),
        if w.len() == 1 { "" } else { "s" },
        float_token(total),
        float_token(largest.amount),
        largest.contact,
        largest.impact,
        float_token(largest.time)
    ))
}

/// The `summary.json` value: peaks, unseating, energies, status and counters, the ground motion
/// and the model (keys for straight/skewed decks, abutments and compliance laws only when used).
pub(crate) fn pair_summary_json(setup: &SimSetup, sol: &BridgeSolution) -> serde_json::Value {
    let s = &sol.summary;
    let e = &s.final_energy;
    let m = &setup.problem.model;
    let joint = &s.joints[0];
    let seat: serde_json::Map<String, serde_json::Value> = s
        .seats
        .iter()
        .map(|end| (pair_seat_name(end), json_float(end.peak_displacement)))
        .collect();
    let unseated_end = pair_unseated_end(s);
    let deck = |j: usize| &s.segments[j];
    let period = |w: Real| json_float(2.0 * std::f64::consts::PI / w);
    let periods = [0, 1].map(|j| deck(j).frequencies.map(period));
    let rayleigh = [0, 1].map(|j| {
        let (a0, a1) = deck(j).rayleigh;
        [json_float(a0), json_float(a1)]
    });
    let mut out = json!({
        "impacts": s.impacts,
        "impacting_contacts": sol.impacts.len(),
        "peak_joint_closing_m": json_float(joint.peak_closing),
        "peak_joint_opening_m": json_float(joint.peak_opening),
        "peak_rotation_deg": [json_float(deck(0).peak_rotation * DEG), json_float(deck(1).peak_rotation * DEG)],
        "peak_slip_m": json_float(joint.peak_slip),
        "peak_seat_displacement_m": json_float(s.peak_seat_displacement),
        "peak_seat_displacement_by_end_m": seat,
        "seat_length_m": json_float(m.seat_length),
        "unseated": s.unseated,
        "unseating_time_s": s.unseating_time.map_or(serde_json::Value::Null, json_float),
        "unseated_end": unseated_end,
        "max_penetration_m": json_float(s.peak_penetration),
        "peak_contact_force_n": joint.peak_contact_force.map_or(serde_json::Value::Null, json_float),
        "peak_penetration_m": json_float(s.peak_penetration),
        "energy_balance_error": json_float(s.energy_balance_error),
        "energy_J": {
            "input": json_float(e.input),
            "kinetic": json_float(e.kinetic),
            "strain": json_float(e.potential),
            "viscous_dissipation": json_float(e.viscous),
            "contact_dissipation": json_float(e.contact),
            "max_input": json_float(s.max_input_energy),
        },
        "natural_periods_s": periods,
        "rayleigh_a0_a1": rayleigh,
        "ground_motion": ground_json(&setup.records, &setup.problem.ground),
        "model": {
            "mass_kg": m.masses().map(json_float),
            "gap_m": json_float(m.gap),
            "mu": json_float(m.friction),
            "eps_n": json_float(m.restitution),
            "damping_ratio": json_float(m.damping_ratio),
            "bearings": [m.bearings1.len(), m.bearings2.len()],
        },
    });
    // Keys for straight / skewed decks and abutments only when used (the curved default's
    // summary stays as it was).
    if let Some(sh) = &m.shapes {
        let len = |d: &DeckShape| d.length().map_or(serde_json::Value::Null, json_float);
        let skew = |d: &DeckShape| json_float(d.skew() * DEG);
        out["model"]["shape"] = json!([sh[0].name(), sh[1].name()]);
        out["model"]["length_m"] = json!([len(&sh[0]), len(&sh[1])]);
        out["model"]["skew_deg"] = json!([skew(&sh[0]), skew(&sh[1])]);
    }
    if m.abutments.iter().any(Option::is_some) {
        let mut ab = serde_json::Map::new();
        for (j, a) in m.abutments.iter().enumerate() {
            if let Some(a) = a {
                ab.insert(
                    format!("deck{}", j + 1),
                    json!({
                        "gap_m": json_float(a.gap),
                        "seat_length_m": json_float(a.seat_length),
                        "peak_closing_m": s.abutments[j].as_ref().map_or(serde_json::Value::Null, |a| json_float(a.peak_closing)),
                    }),
                );
            }
        }
        ab.insert(
            "impacting_contacts".into(),
            json!(sol.abutment_impacting_contacts()),
        );
        out["abutments"] = serde_json::Value::Object(ab);
    }
    add_run_keys(&mut out, &RunKeys::of(sol));
    add_projection_keys(&mut out, &sol.summary);
    add_compliance_summary(&mut out, m, sol);
    out["warnings"] = input_warnings(&setup.problem.ground, sol.dt, sol.time_step_advice.as_ref())
        .into_iter()
        .map(|w| w.json)
        .chain(
            run_warnings(Layout::TwoDecks, sol)
                .iter()
                .map(RunWarning::json),
        )
        .collect();
    if matches!(m.contact, JointContact::Rigid) {
        out["peak_force_estimate_n"] =
            peak_estimate_json(sol.impacts.iter().map(|r| (r, m.restitution)));
    }
    out
}

/// The `ground_motion` object of a `summary.json`: the records as written, scales, incidence,
/// the scaled PGA of each component, and `components` (y then x, the present ones): each
/// record as read ([`crate::ground_motion::ComponentInfo`]: record, units, dt_s (null if
/// irregular), npts, duration_s, pga_g before the scale).
pub(crate) fn ground_json(
    records: &[String; 2],
    gm: &crate::ground_motion::GroundMotion,
) -> serde_json::Value {
    let pga = |r: &Option<Record>, sc: f64| r.as_ref().map_or(0.0, |r| r.pga() * sc.abs());
    json!({
        "record_y": records[0],
        "record_x": records[1],
        "scale_y": json_float(gm.scale_y),
        "scale_x": json_float(gm.scale_x),
        "incidence_deg": json_float(gm.incidence * DEG),
        "pga_y_mps2": json_float(pga(&gm.along_y, gm.scale_y)),
        "pga_x_mps2": json_float(pga(&gm.along_x, gm.scale_x)),
        "components": gm.components().iter().map(|c| json!({
            "component": c.component,
            "record": c.record,
            "units": c.units,
            "dt_s": c.dt.map_or(serde_json::Value::Null, json_float),
            "npts": c.npts,
            "duration_s": json_float(c.duration),
            "pga_g": json_float(c.pga_g),
        })).collect::<Vec<_>>(),
    })
}

/// The run's status and counters shared by the two-deck and bridge `summary.json`.
pub(crate) struct RunKeys {
    pub status: super::SimStatus,
    pub steps: usize,
    pub dt: Real,
    pub lcp: [usize; 3],
}

impl RunKeys {
    pub(crate) fn of(sol: &BridgeSolution) -> Self {
        RunKeys {
            status: sol.status,
            steps: sol.steps,
            dt: sol.dt,
            lcp: [
                sol.lcp_solves,
                sol.lcp_enumeration_fallbacks,
                sol.lcp_failures,
            ],
        }
    }
}

/// Adds `status`, `steps`, `dt_s`, `duration_s` and the LCP counters (the objects are key-sorted,
/// so the bytes do not depend on the order of insertion).
pub(crate) fn add_run_keys(v: &mut serde_json::Value, r: &RunKeys) {
    v["status"] = json!(format!("{:?}", r.status));
    v["steps"] = json!(r.steps);
    v["dt_s"] = json_float(r.dt);
    v["duration_s"] = json_float(crate::sim::step_time(r.steps, r.dt));
    v["lcp_solves"] = json!(r.lcp[0]);
    v["lcp_enumeration_fallbacks"] = json!(r.lcp[1]);
    v["lcp_failures"] = json!(r.lcp[2]);
}

/// With the position projection on ([`crate::sim::projection`]): `max_overlap_m` (the rigid
/// sites' largest overlap at the steps' ends), `energy_J.projection` (the work the corrections
/// did on the structure) and the `projection` object (tolerance, corrected steps, the largest
/// overlap before a correction and correction, passes, failures). Nothing without it, so that
/// the files of a run without projection keep their bytes.
pub(crate) fn add_projection_keys(
    v: &mut serde_json::Value,
    s: &crate::sim::bridge::BridgeSummary,
) {
    let Some(p) = &s.projection else { return };
    v["max_overlap_m"] = json_float(s.max_overlap);
    v["energy_J"]["projection"] = json_float(s.final_energy.projection);
    v["projection"] = json!({
        "tolerance_m": json_float(p.tolerance),
        "corrected_steps": p.corrected_steps,
        "max_overlap_before_m": json_float(p.max_overlap_before),
        "max_correction": json_float(p.max_correction),
        "max_passes": p.max_passes,
        "failures": p.failures,
    });
}

/// `summary.json` as written: [`pair_summary_json`] pretty-printed, with a final newline.
pub(crate) fn pair_summary_json_text(setup: &SimSetup, sol: &BridgeSolution) -> String {
    let mut v = pair_summary_json(setup, sol);
    crate::output::json_without_negative_zero(&mut v);
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
    s.push('\n');
    s
}

/// Short description of a joint contact for summaries.
pub fn describe_contact(c: &JointContact) -> serde_json::Value {
    match c {
        JointContact::Rigid => serde_json::json!({"law": "rigid"}),
        JointContact::Compliance(cc) => {
            let mut v = cc.law.describe();
            v["friction_velocity"] = json_float(cc.friction_velocity);
            v
        }
    }
}

/// Adds the compliance-law fields to a `summary.json` value (nothing for rigid contact, so the
/// rigid summary keeps its keys): `contact_law` (parameters), `time_step` (contact duration,
/// steps per contact, adequate), `newton_failures`.
fn add_compliance_summary(v: &mut serde_json::Value, m: &SimModel, sol: &BridgeSolution) {
    if matches!(m.contact, JointContact::Rigid) {
        return;
    }
    v["contact_law"] = describe_contact(&m.contact);
    v["model"]["damping"] = serde_json::json!(format!("{:?}", m.damping_model));
    if let Some(a) = &sol.time_step_advice {
        v["time_step"] = serde_json::json!({
            "contact_duration_s": json_float(a.contact_duration),
            "steps_per_contact": json_float(a.steps_per_contact),
            "max_step_s": json_float(a.max_step),
            "adequate": a.adequate,
        });
    }
    v["newton_failures"] = serde_json::json!(sol.newton_failures);
    v["closure_steps"] = serde_json::json!(sol.closure_steps);
}
