//! `trajectories.json` of a bridge run: the plan in its reference pose and each segment's
//! displacement over the run, decimated to at most [`TRAJECTORY_MAX_FRAMES`] frames, with the
//! ground acceleration, every impact and the governing event times. It feeds the plan-view
//! animation of the simulate report and other tools (a 3-D viewer, a notebook).
//!
//! The frames are the kept times `r = 0, s, 2s, …` of the run and its last kept time (`s` =
//! `"stride"`, the smallest integer with `⌈(rows − 1) / s⌉ + 1 ≤` [`TRAJECTORY_MAX_FRAMES`]); a
//! frame's `q` row holds every coordinate of the run exactly as `history.csv` writes them (m, m,
//! degrees); segment `i`'s `x_i, y_i, θ_i` start at index `dof_start[i]` (the DOF map's layout:
//! piers' and backwalls' coordinates follow the segments'). A point `p⁰` of segment `i` is at
//!
//! `p(t) = G⁰ᵢ + d + Rot(θ)(p⁰ − G⁰ᵢ)`, `d = (x_i, y_i)`,
//!
//! and a drawing magnified `f` times shows `p⁰ + f (p(t) − p⁰)`.
//!
//! Beside the plan it holds the seated ends (`seats`: name, segment, support, seat length, the
//! face's corners and inward normal at rest, the run's peak ratio), so that a reader can show
//! each end's remaining seat `L − max_c (p_c(t) − p_c⁰)·n_in` at any frame (the seat displacement
//! the run monitors), the bearings' ground points (`bearings`), and the restrainers (`restrainers`:
//! joint, the two anchors at rest, each cable's largest tension over the kept rows) with their
//! tension in every frame (`rf`, N; present when the bridge has restrainers). `impacts` holds one
//! entry per impact and site (its contacts summed), `ag_peak` the largest `|a_x|`, `|a_y|` over
//! every step of the run.

use super::{DEG, joint_openings};
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector};
use crate::output::json_float;
use crate::sim::SimContact;
use crate::sim::bridge::{BridgeModel, BridgeSolution};
use crate::sim::support::Attachment;
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

/// The decimation stride for `rows` kept times (module doc: with the last row, at most
/// [`TRAJECTORY_MAX_FRAMES`] frames).
pub fn trajectory_stride(rows: usize) -> usize {
    rows.saturating_sub(1)
        .div_ceil(TRAJECTORY_MAX_FRAMES - 1)
        .max(1)
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
    // where segment i's x, y, θ sit in a frame's `q` (the DOF map's, not a multiple of 3)
    let starts: Vec<String> = (0..n)
        .map(|i| sol.dofs.plan_index(i, 0).to_string())
        .collect();
    let _ = writeln!(s, "\"dof_start\":[{}],", starts.join(","));
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
    let bridge = model.bridge();
    write_links(&mut s, &bridge, sol);
    let forces = restrainer_forces(sol);
    s.push_str("\"frames\":[\n");
    let mut first = true;
    let rot = sol.dofs.rotations();
    let last = rows.checked_sub(1).filter(|l| l % stride != 0);
    for r in (0..rows).step_by(stride).chain(last) {
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
            "{}{{\"t\":{},\"ag\":[{},{}],\"q\":[{}]",
            if first { "" } else { ",\n" },
            num(t),
            num(a.x),
            num(a.y),
            qs.join(",")
        );
        if let Some((table, cols)) = &forces {
            let row = table.row(r);
            let rf: Vec<String> = cols.iter().map(|&c| num(row[c])).collect();
            let _ = write!(s, ",\"rf\":[{}]", rf.join(","));
        }
        s.push('}');
        first = false;
    }
    s.push_str("\n],\n\"impacts\":[\n");
    s.push_str(&impacts(sol).join(",\n"));
    let peaks = ground_peaks(ground, sol);
    let _ = write!(
        s,
        "\n],\n\"ag_peak\":[{},{}],",
        num(peaks[0]),
        num(peaks[1])
    );
    let _ = writeln!(s, "\n\"events\":{}}}", events(model, sol));
    s
}

/// One entry per impact and site (the records of one impact at one site are consecutive): its
/// contacts, their summed normal impulse and the sum of their peak forces (compliance laws; the
/// peak of the total force when the contacts peak together, an upper bound otherwise).
fn impacts(sol: &BridgeSolution) -> Vec<String> {
    /// The impact being summed.
    struct Sum<'a> {
        impact: usize,
        kind: &'a str,
        site: usize,
        t: Real,
        impulse: Real,
        force: Option<Real>,
        contacts: usize,
    }
    let entry = |c: &Sum<'_>| {
        format!(
            "{{\"t\":{},\"impact\":{},\"site_kind\":\"{}\",\"site\":{},\"contacts\":{},\
             \"impulse_n\":{},\"peak_force\":{}}}",
            num(c.t),
            c.impact,
            c.kind,
            c.site,
            c.contacts,
            num(c.impulse),
            c.force.map_or("null".into(), num)
        )
    };
    let mut out = Vec::new();
    let mut cur: Option<Sum<'_>> = None;
    for i in &sol.impacts {
        let kind = match i.contact {
            SimContact::Abutment { .. } => "abutment",
            _ => "joint",
        };
        let force = i.pulse.map(|p| p.peak_force);
        match &mut cur {
            Some(c) if (c.impact, c.kind, c.site) == (i.impact, kind, i.site) => {
                c.impulse += i.impulse_n;
                c.force = c.force.zip(force).map(|(a, b)| a + b);
                c.contacts += 1;
            }
            _ => {
                out.extend(cur.as_ref().map(entry));
                cur = Some(Sum {
                    impact: i.impact,
                    kind,
                    site: i.site,
                    t: i.time,
                    impulse: i.impulse_n,
                    force,
                    contacts: 1,
                });
            }
        }
    }
    out.extend(cur.as_ref().map(entry));
    out
}

/// The largest `|a_x|`, `|a_y|` of the ground acceleration the run used (every step, not only
/// the kept rows) \[m/s²\].
fn ground_peaks(ground: &GroundMotion, sol: &BridgeSolution) -> [Real; 2] {
    let mut peak = [0.0 as Real; 2];
    for k in 0..=sol.steps {
        let a = ground.accel(k as Real * sol.dt);
        peak[0] = peak[0].max(a.x.abs());
        peak[1] = peak[1].max(a.y.abs());
    }
    peak
}

/// The seats, bearings and restrainers of the bridge (module doc), each key on its own line.
fn write_links(s: &mut String, bridge: &crate::sim::view::Bridge, sol: &BridgeSolution) {
    // each cable's largest tension over the kept rows of the restrainers table
    let cable_peaks: Vec<Real> = restrainer_forces(sol).map_or_else(Vec::new, |(t, cols)| {
        cols.iter()
            .map(|&c| (0..t.rows()).map(|r| t.row(r)[c]).fold(0.0, Real::max))
            .collect()
    });
    let seats: Vec<String> = bridge
        .seats
        .iter()
        .map(|e| {
            let name = crate::sim::solution::seat_name(e);
            let summary = sol.summary.seats.iter().find(|x| x.end == name);
            format!(
                "{{\"end\":\"{name}\",\"segment\":{},\"support\":\"{}\",\"length\":{},\
                 \"corners\":[{},{}],\"inward\":{},\"peak_ratio\":{},\"peak_time\":{},\
                 \"unseated\":{}}}",
                e.body,
                summary.map_or("", |x| x.support.as_str()),
                num(e.length),
                pt(&e.corners[0]),
                pt(&e.corners[1]),
                pt(&e.inward),
                summary.map_or("null".into(), |x| num(x.ratio)),
                summary.map_or("null".into(), |x| num(x.peak_time)),
                summary.is_some_and(|x| x.unseated)
            )
        })
        .collect();
    let _ = writeln!(s, "\"seats\":[{}],", seats.join(","));
    let bearings: Vec<String> = bridge
        .bearings
        .iter()
        .flatten()
        .filter_map(|b| match b.top {
            Attachment::Body(i, p) => Some(format!("{{\"segment\":{i},\"point\":{}}}", pt(&p))),
            Attachment::Support(..) => None,
        })
        .collect();
    let _ = writeln!(s, "\"bearings\":[{}],", bearings.join(","));
    let cables: Vec<String> = bridge
        .elements
        .cables
        .iter()
        .enumerate()
        .filter_map(|(i, c)| match (c.a, c.b) {
            (Attachment::Body(a, pa), Attachment::Body(b, pb)) => Some(format!(
                "{{\"joint\":{},\"a\":{a},\"pa\":{},\"b\":{b},\"pb\":{},\"peak_force\":{}}}",
                c.joint,
                pt(&pa),
                pt(&pb),
                cable_peaks.get(i).map_or("null".into(), |f| num(*f))
            )),
            _ => None,
        })
        .collect();
    let _ = writeln!(s, "\"restrainers\":[{}],", cables.join(","));
}

/// The recorded `restrainers` table and the indices of its force columns (`None` without a
/// restrainer).
fn restrainer_forces(sol: &BridgeSolution) -> Option<(&crate::sim::table::Table, Vec<usize>)> {
    sol.table_sources.iter().find_map(|src| match src {
        crate::sim::table::TableSource::Recorded(t) if t.name == "restrainers" => {
            let cols: Vec<usize> = (0..t.columns.len())
                .filter(|&c| t.columns[c].name.ends_with("_force"))
                .collect();
            (!cols.is_empty()).then_some((t, cols))
        }
        _ => None,
    })
}

/// The governing event times: first impact, peak closing (smallest joint opening), the peak of
/// the governing seat ratio ([`crate::sim::bridge::BridgeSummary::governing_seat`]), unseating.
fn events(model: &BridgeModel, sol: &BridgeSolution) -> String {
    let first = sol.impacts.first().map(|i| i.time);
    let mut peak: Option<(Real, Real)> = None;
    for op in joint_openings(model, sol) {
        for (r, v) in op.iter().enumerate() {
            // a closing (opening below the gap by more than a nanometre: the rest pose's
            // gap computes to the gap within rounding) only
            if v.is_finite() && *v < -1e-9 && peak.is_none_or(|(_, b)| *v < b) {
                peak = Some((sol.t[r], *v));
            }
        }
    }
    let o = |x: Option<Real>| x.map_or("null".into(), num);
    let governing = sol
        .summary
        .seats
        .get(sol.summary.governing_seat)
        .filter(|g| g.ratio > 0.0);
    format!(
        "{{\"first_impact\":{},\"peak_closing\":{},\"peak_seat_ratio\":{},\"unseating\":{}}}",
        o(first),
        o(peak.map(|p| p.0)),
        o(governing.map(|g| g.peak_time)),
        o(sol.summary.unseating_time)
    )
}
