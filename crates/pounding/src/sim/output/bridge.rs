//! The files of a bridge run (`[[segment]]` scenarios): `history.csv`, `impacts.csv` and
//! `summary.json` with per-joint, per-abutment and per-segment entries in bridge order.

use super::impacts::{site_kinds, site_restitution};
use super::{DEG, describe_contact};
use crate::math::Real;
use crate::output::json_float;
use crate::sim::bridge::BridgeSolution;
use crate::sim::scenario::BridgeSetup;
use serde_json::{Value, json};

fn opt(v: Option<Real>) -> Value {
    v.map_or(Value::Null, json_float)
}

/// The `joints`, `abutments` and `segments` arrays of a bridge's `summary.json`.
fn bridge_arrays(
    setup: &BridgeSetup,
    sol: &BridgeSolution,
) -> (Vec<Value>, Vec<Value>, Vec<Value>) {
    let s = &sol.summary;
    let m = &setup.problem.model;
    let joints: Vec<Value> = s
        .joints
        .iter()
        .zip(&m.joints)
        .map(|(j, mj)| {
            json!({
                "impacts": j.impacts,
                "peak_contact_force_n": opt(j.peak_contact_force),
                "peak_impulse_ns": json_float(j.peak_impulse),
                "peak_closing_m": json_float(j.peak_closing),
                "peak_opening_m": json_float(j.peak_opening),
                "peak_slip_m": json_float(j.peak_slip),
                "restrainer_engagements": j.restrainer_engagements,
                "restrainer_peak_force_n": opt(j.restrainer_peak_force),
                "unseated": j.unseated,
                "gap_m": json_float(mj.gap),
                "mu": json_float(mj.friction),
                "eps_n": json_float(mj.restitution),
                "seat_length_m": json_float(mj.seat_length),
                "contact_law": describe_contact(&mj.contact),
            })
        })
        .collect();
    let abutments: Vec<Value> = (0..2)
        .map(|side| match (&s.abutments[side], &m.abutments[side]) {
            (Some(a), Some(ma)) => json!({
                "impacts": a.impacts,
                "peak_contact_force_n": opt(a.peak_contact_force),
                "peak_impulse_ns": json_float(a.peak_impulse),
                "peak_closing_m": json_float(a.peak_closing),
                "gap_m": json_float(ma.gap),
                "seat_length_m": json_float(ma.seat_length),
                "contact_law": describe_contact(&ma.contact),
                "backwall": a.backwall.as_ref().zip(ma.backwall.as_ref()).map(|(w, mw)| json!({
                    "peak_backwall_displacement_m": json_float(w.peak_displacement),
                    "residual_backwall_displacement_m": json_float(w.residual_displacement),
                    "peak_backfill_force_n": opt(w.peak_backfill_force),
                    "peak_pile_force_n": opt(w.peak_pile_force),
                    "pile_hysteretic_energy_j": json_float(w.pile_hysteretic_energy),
                    "mass_kg": json_float(mw.mass),
                    "backfill": mw.backfill.map(|b| json!({
                        "kmax_n_per_m": json_float(b.kmax()),
                        "kur_n_per_m": json_float(b.kur()),
                        "rf": json_float(b.rf()),
                        "fult_n": json_float(b.fult()),
                        "gap_m": json_float(b.gap()),
                    })),
                    "piles": mw.piles.map(|p| json!({
                        "k_n_per_m": json_float(p.k),
                        "fy_n": json_float(p.fy),
                    })),
                })),
            }),
            _ => Value::Null,
        })
        .collect();
    let segments: Vec<Value> = s
        .segments
        .iter()
        .zip(&m.segments)
        .map(|(g, ms)| {
            let mp = ms.shape.mass_properties();
            json!({
                "peak_displacement_m": json_float(g.peak_displacement),
                "final_displacement_m": json_float(g.final_displacement),
                "peak_rotation_deg": json_float(g.peak_rotation * DEG),
                "peak_bearing_deformation_m": json_float(g.peak_bearing_deformation),
                "hysteretic_energy_j": json_float(g.hysteretic_energy),
                "shape": ms.shape.name(),
                "mass_kg": json_float(mp.mass),
                "natural_periods_s": g.frequencies.map(|w| json_float(2.0 * std::f64::consts::PI / w)),
            })
        })
        .collect();
    (joints, abutments, segments)
}

/// How many of the whole coupled bridge's natural periods `summary.json` lists (longest first).
pub(crate) const BRIDGE_PERIODS: usize = 10;

/// The `summary.json` of a bridge run: `joints`, `abutments` (`[start, end]`, `null` where
/// absent) and `segments` arrays in bridge order, the whole-bridge figures, status, ground motion
/// and model; its warnings name the contacts as the files of `layout` do.
pub(crate) fn bridge_summary_json(
    setup: &BridgeSetup,
    layout: super::Layout,
    sol: &BridgeSolution,
) -> Value {
    let s = &sol.summary;
    let m = &setup.problem.model;
    let e = &s.final_energy;
    let (joints, abutments, segments) = bridge_arrays(setup, sol);
    let hyst: Real = s.segments.iter().map(|g| g.hysteretic_energy).sum::<Real>()
        + s.piers.iter().map(|p| p.hysteretic_energy).sum::<Real>()
        + s.abutments
            .iter()
            .flatten()
            .filter_map(|a| a.backwall.as_ref())
            .map(|w| w.pile_hysteretic_energy)
            .sum::<Real>();
    let (rigid, compliant) = site_kinds(m);
    let piers: Vec<Value> = s
        .piers
        .iter()
        .zip(&m.piers)
        .map(|(p, mp)| {
            json!({
                "joint": p.joint,
                "peak_drift_x_m": json_float(p.peak_drift[0]),
                "peak_drift_y_m": json_float(p.peak_drift[1]),
                "peak_drift_m": json_float(p.peak_drift_magnitude),
                "residual_drift_x_m": json_float(p.residual_drift[0]),
                "residual_drift_y_m": json_float(p.residual_drift[1]),
                "residual_drift_m": json_float(p.residual_drift[0].hypot(p.residual_drift[1])),
                "peak_column_force_n": json_float(p.peak_column_force),
                "yielded": p.yielded,
                "hysteretic_energy_j": json_float(p.hysteretic_energy),
                "cap_mass_kg": json_float(mp.cap_mass),
                "column_k0_n_per_m": json_float(mp.column.k0),
                "column_fy_n": opt(mp.column.fy),
                "column_b": json_float(mp.column.b),
                "damping_ns_per_m": json_float(mp.damping),
            })
        })
        .collect();
    let mut out = json!({
        "impacts": s.impacts,
        "impacting_contacts": sol.impacts.len(),
        "joints": joints,
        "abutments": abutments,
        "segments": segments,
        "piers": piers,
        "shear_keys": s.shear_keys.iter().map(|k| json!({
            "abutment": k.side,
            "peak_force_n": json_float(k.peak_force),
            "peak_deformation_m": json_float(k.peak_deformation),
            "yielded": k.yielded,
            "dissipated_j": json_float(k.dissipated),
        })).collect::<Vec<_>>(),
        "peak_seat_displacement_m": json_float(s.peak_seat_displacement),
        "governing_seat": governing_seat_json(s),
        "seats": s.seats.iter().map(seat_json).collect::<Vec<_>>(),
        "unseated": s.unseated,
        "unseating_time_s": opt(s.unseating_time),
        "unseated_end": s.unseated_end,
        "peak_penetration_m": json_float(s.peak_penetration),
        "energy_balance_error": json_float(s.energy_balance_error),
        "energy_J": {
            "input": json_float(e.input),
            "kinetic": json_float(e.kinetic),
            "strain": json_float(
                e.potential
                    + (e.elements - hyst - s.restrainer_work - s.backfill_work - s.shear_key_work)
            ),
            "viscous_dissipation": json_float(e.viscous),
            "contact_dissipation": json_float(e.contact),
            "hysteretic_dissipation": json_float(hyst),
            "restrainer_work": json_float(s.restrainer_work),
            "backfill_work": json_float(s.backfill_work),
            "shear_key_work": json_float(s.shear_key_work),
            "max_input": json_float(s.max_input_energy),
        },
        "ground_motion": super::ground_json(&setup.records, &setup.problem.ground),
        "model": {
            "segments": m.segments.len(),
            "damping": format!("{:?}", m.damping_model),
            "damping_ratio": json_float(m.damping_ratio),
            "outer_seat_length_m": json_float(m.outer_seat_length),
        },
    });
    if let Ok(Some(w)) = m.system_frequencies() {
        // piers or backwalls couple the segments: the whole bridge's longest periods
        out["model"]["periods_s"] = w
            .iter()
            .take(BRIDGE_PERIODS)
            .map(|w| json_float(2.0 * std::f64::consts::PI / w))
            .collect();
    }
    super::add_run_keys(&mut out, &super::RunKeys::of(sol));
    super::add_projection_keys(&mut out, &sol.summary);
    out["warnings"] = super::input_warnings(
        &setup.problem.ground,
        sol.dt,
        sol.time_step_advice.as_ref(),
        &sol.summary.segment_frequencies(),
    )
    .into_iter()
    .map(|w| w.json)
    .chain(
        super::run_warnings(layout, sol)
            .iter()
            .map(super::RunWarning::json),
    )
    .collect();
    if rigid {
        // the rigid sites' impacts (a compliance record has its measured pulse instead)
        let records = sol.impacts.iter().filter(|r| r.pulse.is_none());
        out["peak_force_estimate_n"] =
            super::peak_estimate_json(records.map(|r| (r, site_restitution(m, r))));
    }
    if compliant {
        out["newton_failures"] = json!(sol.newton_failures);
        out["closure_steps"] = json!(sol.closure_steps);
        if let Some(a) = &sol.time_step_advice {
            out["time_step"] = json!({
                "contact_duration_s": json_float(a.contact_duration),
                "steps_per_contact": json_float(a.steps_per_contact),
                "max_step_s": json_float(a.max_step),
                "adequate": a.adequate,
            });
        }
    }
    if let Some(sup) = supports_json(setup) {
        out["ground_motion"]["supports"] = sup;
    }
    out
}

/// `ground_motion.supports` of a run whose supports move apart: how (`wave-passage` with its
/// apparent velocity and direction, or `per-support` records), and per support line its id,
/// plan position and the record's arrival delay (`null` without wave passage). `None` for a
/// uniform excitation (the key is absent).
fn supports_json(setup: &BridgeSetup) -> Option<Value> {
    use crate::sim::excitation::SupportExcitation as E;
    let lines = setup.problem.model.support_lines();
    let (kind, v_app, dir, delays): (&str, _, _, Vec<Option<Real>>) = match &setup.problem.supports
    {
        E::Uniform => return None,
        E::WavePassage { v_app, .. } => {
            let (e, d) = setup.problem.supports.wave_delays(&lines)?;
            let d = d.into_iter().map(Some).collect();
            (
                "wave-passage",
                json_float(*v_app),
                // the direction as an angle to 1e-9°, not the last bits of its sine and cosine
                json_float((e.y.atan2(e.x).to_degrees() * 1e9).round() / 1e9),
                d,
            )
        }
        E::Records(_) => (
            "per-support",
            Value::Null,
            Value::Null,
            vec![None; lines.len()],
        ),
    };
    // the support whose motion the histories are relative to: the first the wave reaches, or
    // `start` (the reference of a motion per support)
    let reference = delays
        .iter()
        .position(|d| *d == Some(0.0))
        .map_or("start", |i| lines[i].id.as_str());
    Some(json!({
        "kind": kind,
        "reference": reference,
        "v_app_mps": v_app,
        "wave_direction_deg": dir,
        "lines": lines.iter().zip(delays).map(|(l, d)| json!({
            "id": l.id,
            "position_m": [json_float(l.position.x), json_float(l.position.y)],
            "arrival_delay_s": d.map_or(Value::Null, json_float),
        })).collect::<Vec<_>>(),
    }))
}

/// One seated end's margin in `summary.json`.
fn seat_json(s: &crate::sim::bridge::SeatSummary) -> serde_json::Value {
    json!({
        "end": s.end,
        "segment": s.segment,
        "support": s.support,
        "seat_length_m": json_float(s.seat_length),
        "peak_seat_displacement_m": json_float(s.peak_displacement),
        "ratio": json_float(s.ratio),
        "peak_time_s": json_float(s.peak_time),
        "residual_seat_displacement_m": json_float(s.residual_displacement),
        "unseated": s.unseated,
    })
}

/// The governing seated end (the largest ratio of displacement to its own seat) in
/// `summary.json`: which end, its support, ratio and seat.
fn governing_seat_json(s: &crate::sim::bridge::BridgeSummary) -> serde_json::Value {
    match s.seats.get(s.governing_seat) {
        Some(g) => json!({
            "end": g.end,
            "support": g.support,
            "ratio": json_float(g.ratio),
            "peak_seat_displacement_m": json_float(g.peak_displacement),
            "seat_length_m": json_float(g.seat_length),
        }),
        None => serde_json::Value::Null,
    }
}

/// The governing seated end in words, for the terminal: `segment3-end on joint3: 97 % of its
/// 0.4 m seat`.
pub fn governing_seat_line(s: &crate::sim::bridge::BridgeSummary) -> Option<String> {
    let g = s.seats.get(s.governing_seat)?;
    Some(format!(
        "{} on {}: {} % of its {} m seat",
        g.end,
        g.support,
        crate::output::bounded(100.0 * g.ratio, 0),
        crate::output::float_token(g.seat_length)
    ))
}
