//! The files a `simulate` run writes, as text: `history.csv`, `impacts.csv`, `summary.json` and
//! the batch's `batch.csv`, and those of `pounding compare`. Numbers are shortest round-trip ([`float_token`]: `inf`, `-inf`, `nan`
//! in CSV; [`json_float`]: `null` in JSON), so the bytes are the same for any thread count.

use super::bridge::{BridgeSolution, SeatSummary};
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
pub use batch::{
    BATCH_HEADER, BATCH_TAIL, PAIR_BATCH_COLUMNS, PairBatchCell, batch_csv, batch_set_csv,
    bridge_batch_header,
};
pub(crate) use bridge::bridge_summary_json;
pub use bridge::governing_seat_line;
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
pub use history::{History, PAIR_HISTORY_COLUMNS, PairHistoryColumn};
pub use impacts::{impacts_csv, impacts_table, run_warnings};
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

/// Columns (name, unit) appended to `impacts.csv` for a compliance law ([`super::ImpactPulse`]):
/// `peak_force_n` (newtons, spelled `n` in this file's header), `duration_s`,
/// `max_penetration_m`.
pub const PULSE_COLUMNS: [(&str, &str); 3] = [
    ("peak_force", "n"),
    ("duration", "s"),
    ("max_penetration", "m"),
];
/// Columns (name, unit) appended to `impacts.csv` for the rigid law
/// ([`crate::contact_law::estimate::rigid_peak_force`] with the default `k_h`):
/// `peak_force_estimate_n`, `contact_time_estimate_s`.
pub const ESTIMATE_COLUMNS: [(&str, &str); 2] =
    [("peak_force_estimate", "n"), ("contact_time_estimate", "s")];

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

/// The two-deck file's `summary.json` keys that are the bridge summary's values under another
/// name: `(two-deck key path, bridge summary JSON pointer)`. A key whose bridge value is absent
/// is left out (the compliance keys of a rigid run, the estimate of a compliance run).
const PAIR_KEYS: &[(&str, &str)] = &[
    ("impacts", "/impacts"),
    ("impacting_contacts", "/impacting_contacts"),
    ("peak_joint_closing_m", "/joints/0/peak_closing_m"),
    ("peak_joint_opening_m", "/joints/0/peak_opening_m"),
    ("peak_slip_m", "/joints/0/peak_slip_m"),
    ("peak_contact_force_n", "/joints/0/peak_contact_force_n"),
    ("peak_seat_displacement_m", "/peak_seat_displacement_m"),
    ("seat_length_m", "/joints/0/seat_length_m"),
    ("unseated", "/unseated"),
    ("unseating_time_s", "/unseating_time_s"),
    ("max_penetration_m", "/peak_penetration_m"),
    ("peak_penetration_m", "/peak_penetration_m"),
    ("energy_balance_error", "/energy_balance_error"),
    ("energy_J/input", "/energy_J/input"),
    ("energy_J/kinetic", "/energy_J/kinetic"),
    ("energy_J/strain", "/energy_J/strain"),
    (
        "energy_J/viscous_dissipation",
        "/energy_J/viscous_dissipation",
    ),
    (
        "energy_J/contact_dissipation",
        "/energy_J/contact_dissipation",
    ),
    ("energy_J/max_input", "/energy_J/max_input"),
    ("energy_J/projection", "/energy_J/projection"),
    ("ground_motion", "/ground_motion"),
    ("model/gap_m", "/joints/0/gap_m"),
    ("model/mu", "/joints/0/mu"),
    ("model/eps_n", "/joints/0/eps_n"),
    ("model/damping_ratio", "/model/damping_ratio"),
    ("status", "/status"),
    ("steps", "/steps"),
    ("dt_s", "/dt_s"),
    ("duration_s", "/duration_s"),
    ("lcp_solves", "/lcp_solves"),
    ("lcp_enumeration_fallbacks", "/lcp_enumeration_fallbacks"),
    ("lcp_failures", "/lcp_failures"),
    ("max_overlap_m", "/max_overlap_m"),
    ("projection", "/projection"),
    ("warnings", "/warnings"),
    ("peak_force_estimate_n", "/peak_force_estimate_n"),
    ("time_step", "/time_step"),
    ("newton_failures", "/newton_failures"),
    ("closure_steps", "/closure_steps"),
];

/// The two-deck file's `summary.json`: the summary of its bridge of two segments
/// ([`bridge_summary_json`], with the two-deck names in its warnings) translated to the keys of
/// the two-deck form — [`PAIR_KEYS`], per-deck pairs (`peak_rotation_deg`, `natural_periods_s`,
/// `model.mass_kg`), the seats by deck end (`deck1-joint`, …), the abutments by deck — plus what
/// only the form knows: its bearing counts and deck shapes (`m`, the preset's parameters) and
/// the Rayleigh coefficients per deck.
pub(crate) fn pair_summary_json(
    setup: &crate::sim::scenario::BridgeSetup,
    m: &SimModel,
    sol: &BridgeSolution,
) -> serde_json::Value {
    use serde_json::Value;
    let b = bridge::bridge_summary_json(setup, Layout::TwoDecks, sol);
    let s = &sol.summary;
    let mut out = json!({});
    for (key, pointer) in PAIR_KEYS {
        if let Some(v) = b.pointer(pointer) {
            set_path(&mut out, key, v.clone());
        }
    }
    let decks = |key: &str| json!([b["segments"][0][key], b["segments"][1][key]]);
    out["peak_rotation_deg"] = decks("peak_rotation_deg");
    out["natural_periods_s"] = decks("natural_periods_s");
    out["model"]["mass_kg"] = decks("mass_kg");
    out["rayleigh_a0_a1"] = [0, 1]
        .map(|j| {
            let (a0, a1) = s.segments[j].rayleigh;
            [json_float(a0), json_float(a1)]
        })
        .into();
    out["peak_seat_displacement_by_end_m"] = s
        .seats
        .iter()
        .map(|end| (pair_seat_name(end), json_float(end.peak_displacement)))
        .collect::<serde_json::Map<_, _>>()
        .into();
    out["unseated_end"] = pair_unseated_end(s).into();
    out["model"]["bearings"] = json!([m.bearings1.len(), m.bearings2.len()]);
    // keys for straight / skewed decks and abutments only when used (the curved default's
    // summary stays as it was)
    if let Some(sh) = &m.shapes {
        let len = |d: &DeckShape| d.length().map_or(Value::Null, json_float);
        let skew = |d: &DeckShape| json_float(d.skew() * DEG);
        out["model"]["shape"] = json!([sh[0].name(), sh[1].name()]);
        out["model"]["length_m"] = json!([len(&sh[0]), len(&sh[1])]);
        out["model"]["skew_deg"] = json!([skew(&sh[0]), skew(&sh[1])]);
    }
    if m.abutments.iter().any(Option::is_some) {
        let mut ab = serde_json::Map::new();
        for (j, a) in b["abutments"].as_array().into_iter().flatten().enumerate() {
            if a.is_object() {
                let keys = ["gap_m", "seat_length_m", "peak_closing_m"];
                let entry = keys.iter().map(|k| (k.to_string(), a[*k].clone()));
                ab.insert(format!("deck{}", j + 1), Value::Object(entry.collect()));
            }
        }
        ab.insert(
            "impacting_contacts".into(),
            json!(sol.abutment_impacting_contacts()),
        );
        out["abutments"] = Value::Object(ab);
    }
    if let JointContact::Compliance(_) = m.contact {
        out["contact_law"] = b["joints"][0]["contact_law"].clone();
        out["model"]["damping"] = b["model"]["damping"].clone();
    }
    out
}

/// Sets `v[a][b]…` for the key path `a/b/…`, creating the objects on the way.
fn set_path(v: &mut serde_json::Value, path: &str, x: serde_json::Value) {
    let mut cur = v;
    for part in path.split('/') {
        cur = &mut cur[part];
    }
    *cur = x;
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
