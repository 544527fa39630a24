//! `trajectories.json` of a bridge run: the plan in its reference pose and each segment's
//! displacement over the run, decimated to at most [`TRAJECTORY_MAX_FRAMES`] frames, with the
//! ground acceleration, every impact and the governing event times. It feeds the plan-view
//! animation of the simulate report and other tools (a 3-D viewer, a notebook).
//!
//! A frame `f` is the kept time `r = f s` of the run (`s` = `"stride"`, the smallest integer
//! with `⌈rows / s⌉ ≤` [`TRAJECTORY_MAX_FRAMES`]); its `q` row holds `x_i, y_i, θ_i` of every
//! segment exactly as `history.csv` writes them (m, m, degrees). A point `p⁰` of segment `i` is at
//!
//! `p(t) = G⁰ᵢ + d + Rot(θ)(p⁰ − G⁰ᵢ)`, `d = (x_i, y_i)`,
//!
//! and a drawing magnified `f` times shows `p⁰ + f (p(t) − p⁰)`.

use super::{DEG, joint_openings};
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector};
use crate::output::json_float;
use crate::sim::SimContact;
use crate::sim::bridge::{BridgeModel, BridgeSolution};
use std::fmt::Write;

/// Most frames a `trajectories.json` holds (a 20-segment run then stays near 2.5 MB).
pub const TRAJECTORY_MAX_FRAMES: usize = 2000;

/// A number as JSON (`null` when not finite).
fn num(x: Real) -> String {
    json_float(x).to_string()
}

/// `[x, y]`.
fn pt(p: &Vector) -> String {
    format!("[{},{}]", num(p.x), num(p.y))
}

/// The decimation stride for `rows` kept times.
pub fn trajectory_stride(rows: usize) -> usize {
    rows.div_ceil(TRAJECTORY_MAX_FRAMES).max(1)
}

/// `trajectories.json` of a run of the bridge `model` under `ground` (module doc; the two-deck
/// model's is its two-segment bridge), one line per frame.
pub fn trajectories_json(
    model: &BridgeModel,
    ground: &GroundMotion,
    sol: &BridgeSolution,
) -> String {
    let n = sol.n_segments;
    let rows = sol.t.len();
    let stride = trajectory_stride(rows);
    let plan = super::bridge_plan(model, 16);
    let mut s = String::with_capacity(64 * n * rows / stride + 4096);
    let _ = writeln!(
        s,
        "{{\"format\":\"pounding-trajectories\",\"version\":1,\"units\":{{\"length\":\"m\",\
         \"time\":\"s\",\"angle\":\"deg\",\"acceleration\":\"m/s2\",\"impulse\":\"N s\",\
         \"force\":\"N\"}},\"segments\":{n},\"rows\":{rows},\"stride\":{stride},"
    );
    let outlines: Vec<String> = plan
        .outlines
        .iter()
        .map(|o| format!("[{}]", o.iter().map(pt).collect::<Vec<_>>().join(",")))
        .collect();
    let _ = writeln!(s, "\"outlines\":[{}],", outlines.join(","));
    let corners: Vec<String> = plan
        .corners
        .iter()
        .map(|c| format!("[{}]", c.iter().map(pt).collect::<Vec<_>>().join(",")))
        .collect();
    let _ = writeln!(s, "\"corners\":[{}],", corners.join(","));
    let cents: Vec<String> = plan.centroids.iter().map(pt).collect();
    let _ = writeln!(s, "\"centroids\":[{}],", cents.join(","));
    let faces: Vec<String> = plan
        .abutment_faces
        .iter()
        .map(|f| f.map_or("null".into(), |[a, b]| format!("[{},{}]", pt(&a), pt(&b))))
        .collect();
    let _ = writeln!(s, "\"abutment_faces\":[{}],", faces.join(","));
    let gaps: Vec<String> = model.joints.iter().map(|j| num(j.gap)).collect();
    let _ = writeln!(s, "\"joint_gaps\":[{}],", gaps.join(","));
    s.push_str("\"frames\":[\n");
    let mut first = true;
    let rot = sol.dofs.rotations();
    for r in (0..rows).step_by(stride) {
        let t = sol.t[r];
        let a = ground.accel(crate::sim::solver_time(t, sol.dt));
        let qs: Vec<String> = sol
            .q_row(r)
            .iter()
            .enumerate()
            .map(|(k, v)| num(if rot[k] { v * DEG } else { *v }))
            .collect();
        let _ = write!(
            s,
            "{}{{\"t\":{},\"ag\":[{},{}],\"q\":[{}]}}",
            if first { "" } else { ",\n" },
            num(t),
            num(a.x),
            num(a.y),
            qs.join(",")
        );
        first = false;
    }
    s.push_str("\n],\n\"impacts\":[\n");
    let imp: Vec<String> = sol
        .impacts
        .iter()
        .map(|i| {
            let kind = match i.contact {
                SimContact::Abutment { .. } => "abutment",
                _ => "joint",
            };
            format!(
                "{{\"t\":{},\"impact\":{},\"site_kind\":\"{kind}\",\"site\":{},\"impulse_n\":{},\
                 \"peak_force\":{}}}",
                num(i.time),
                i.impact,
                i.site,
                num(i.impulse_n),
                i.pulse.map_or("null".into(), |p| num(p.peak_force))
            )
        })
        .collect();
    s.push_str(&imp.join(",\n"));
    let _ = writeln!(s, "\n],\n\"events\":{}}}", events(model, sol));
    s
}

/// The governing event times: first impact, peak closing (smallest joint opening), the peak of
/// the governing seat ratio ([`crate::sim::bridge::BridgeSummary::governing_seat`]), unseating.
fn events(model: &BridgeModel, sol: &BridgeSolution) -> String {
    let first = sol.impacts.first().map(|i| i.time);
    let mut peak: Option<(Real, Real)> = None;
    for op in joint_openings(model, sol) {
        for (r, v) in op.iter().enumerate() {
            if v.is_finite() && peak.is_none_or(|(_, b)| *v < b) {
                peak = Some((sol.t[r], *v));
            }
        }
    }
    let o = |x: Option<Real>| x.map_or("null".into(), num);
    let governing = sol.summary.seats.get(sol.summary.governing_seat);
    format!(
        "{{\"first_impact\":{},\"peak_closing\":{},\"peak_seat_ratio\":{},\"unseating\":{}}}",
        o(first),
        o(peak.map(|p| p.0)),
        o(governing.map(|g| g.peak_time)),
        o(sol.summary.unseating_time)
    )
}
