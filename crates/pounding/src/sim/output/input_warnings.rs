//! Warnings about what a run was given, as opposed to what happened in it: an implausible record
//! PGA (units probably wrong), a time step too coarse for a compliance law, and a segment whose
//! natural period on its bearings the step cannot resolve (an implausible mass or stiffness). They head
//! `summary.json`'s `warnings` (before the per-impact [`super::RunWarning`]s), are printed on
//! stderr and listed in `report.html`.

use crate::contact_law::timestep::TimeStepAdvice;
use crate::ground_motion::GroundMotion;
use crate::math::Real;
use crate::output::json_float;
use serde_json::{Value, json};

/// A warning about a run's input or resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct InputWarning {
    /// `record_pga_implausible`, `time_step_beyond_record`, `time_step_coarse` or
    /// `segment_period_unresolved`.
    pub kind: &'static str,
    /// The sentence printed on stderr and in `report.html`.
    pub message: String,
    /// The `summary.json` entry: `kind`, the figures and `message`.
    pub json: Value,
}

/// The warnings of a run on `ground` with step `dt` and the compliance law's time-step advice
/// (`None` for the rigid law): one per record component whose PGA as read exceeds
/// [`crate::ground_motion::PLAUSIBLE_PGA_G`], one per uniformly sampled record whose sample
/// interval is shorter than `dt` (the run skips samples), and one when `dt` exceeds the advice's
/// largest adequate step (`T_c/20`); then one per segment whose shortest natural period on its
/// bearings, `T = 2π/ω_3` from `frequencies` (per segment `ω_1 ≤ ω_2 ≤ ω_3`, the summary's), is
/// shorter than [`STEPS_PER_PERIOD`] steps: the θ-method stays stable there but does not follow
/// that mode (with θ = ½ it lengthens its period by about `(ω h)²/12`, 0.8 % at 20 steps), and
/// so short a period usually means a mass or stiffness in the wrong units.
pub fn input_warnings(
    ground: &GroundMotion,
    dt: Real,
    advice: Option<&TimeStepAdvice>,
    frequencies: &[[Real; 3]],
) -> Vec<InputWarning> {
    let mut out: Vec<InputWarning> = ground
        .components()
        .iter()
        .filter_map(|c| {
            let message = c.units_warning()?;
            Some(InputWarning {
                kind: "record_pga_implausible",
                json: json!({
                    "kind": "record_pga_implausible",
                    "component": c.component,
                    "record": c.record,
                    "pga_g": json_float(c.pga_g),
                    "message": message,
                }),
                message,
            })
        })
        .collect();
    for c in ground.components() {
        // a step longer than the record's sample interval skips samples of the excitation
        if let Some(rdt) = c.dt.filter(|&rdt| dt > rdt * (1.0 + 1e-9)) {
            let f = crate::output::float_token;
            let message = format!(
                "dt = {} s is longer than the sample interval {} s of record {} (component {}): \
                 the run sees the record only at its step times and skips samples in between; \
                 use dt <= {} s",
                f(dt),
                f(rdt),
                c.record,
                c.component,
                f(rdt)
            );
            out.push(InputWarning {
                kind: "time_step_beyond_record",
                json: json!({
                    "kind": "time_step_beyond_record",
                    "component": c.component,
                    "record": c.record,
                    "dt_s": json_float(dt),
                    "record_dt_s": json_float(rdt),
                    "message": message,
                }),
                message,
            });
        }
    }
    if let Some(a) = advice.filter(|a| !a.adequate) {
        let f = crate::output::float_token;
        let message = format!(
            "dt = {} s is too coarse for the contact law: about {} steps per contact (contact \
             duration {} s); use dt <= {} s (20 steps per contact)",
            f(dt),
            f(a.steps_per_contact.round()),
            f(a.contact_duration),
            f(a.max_step)
        );
        out.push(InputWarning {
            kind: "time_step_coarse",
            json: json!({
                "kind": "time_step_coarse",
                "dt_s": json_float(dt),
                "steps_per_contact": json_float(a.steps_per_contact),
                "max_step_s": json_float(a.max_step),
                "message": message,
            }),
            message,
        });
    }
    out.extend(period_warnings(dt, frequencies));
    out
}

/// Steps per natural period below which a segment's mode is not resolved.
pub const STEPS_PER_PERIOD: Real = 20.0;

/// The `segment_period_unresolved` warnings of [`input_warnings`].
fn period_warnings(dt: Real, frequencies: &[[Real; 3]]) -> Vec<InputWarning> {
    let f = crate::output::float_token;
    let mut out = Vec::new();
    for (i, w) in frequencies.iter().enumerate() {
        let t = 2.0 * std::f64::consts::PI / w[2];
        if t.is_nan() || t >= STEPS_PER_PERIOD * dt {
            continue;
        }
        let message = format!(
            "segment {}'s shortest natural period on its bearings is {} s, less than {} steps of \
             dt = {} s: the run does not follow that mode; check the segment's mass and inertia \
             and its bearings' stiffness (units?), or use dt <= {} s",
            i + 1,
            f(t),
            STEPS_PER_PERIOD,
            f(dt),
            f(t / STEPS_PER_PERIOD)
        );
        out.push(InputWarning {
            kind: "segment_period_unresolved",
            json: json!({
                "kind": "segment_period_unresolved",
                "segment": i + 1,
                "period_s": json_float(t),
                "dt_s": json_float(dt),
                "message": message,
            }),
            message,
        });
    }
    out
}

/// One readable sentence for an entry of `summary.json`'s `warnings`: its `message` (input
/// warnings), or for a per-impact energy warning (`kind`, `impact`, `contact`, `t_s`,
/// `amount_j`) `energy created at contact C in impact N (t = T s): A J (kind)`.
pub fn warning_sentence(w: &Value) -> String {
    if let Some(m) = w["message"].as_str() {
        return m.to_string();
    }
    let num = |k: &str| {
        w[k].as_f64()
            .map_or("null".to_string(), crate::output::float_token)
    };
    match (w["kind"].as_str(), w["contact"].as_str()) {
        (Some(kind), Some(contact)) => format!(
            "energy created at contact {contact} in impact {} (t = {} s): {} J ({kind})",
            w["impact"],
            num("t_s"),
            num("amount_j")
        ),
        _ => w.to_string(),
    }
}
