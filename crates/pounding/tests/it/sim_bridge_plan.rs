//! The geometry and histories behind the bridge figures (`pounding::sim::output::bridge_plan`):
//! outlines against the segments' areas, abutment faces at their gaps, corner paths as rigid
//! motions, joint openings against the chain's kinematics, displacement magnitudes against the
//! summary's peaks.

use pounding::math::Vector;
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output::{
    bridge_plan, corner_paths, joint_openings, plan_exaggeration, segment_displacements,
};
use pounding::sim::scenario::{BridgeSetup, Scenario};

const RIGID_1D: &str = include_str!("../../../../examples/viaduct-rigid-1d.toml");
const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");

/// The example with every step kept and a short duration.
fn short(text: &str, every: &str, duration: f64) -> String {
    let from = format!("history_every = {every}");
    assert!(text.contains(&from), "the example lost `{from}`");
    text.replace(&from, &format!("history_every = 1\nduration = {duration}"))
}

fn setup(text: &str) -> BridgeSetup {
    Scenario::from_toml(text, "test.toml")
        .unwrap()
        .build_bridge()
        .unwrap()
}

fn run(s: &BridgeSetup) -> BridgeSolution {
    let sol = s.run().unwrap();
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    sol
}

/// Shoelace area of a closed polyline.
fn area(p: &[Vector]) -> f64 {
    0.5 * p
        .windows(2)
        .map(|w| w[0].x * w[1].y - w[1].x * w[0].y)
        .sum::<f64>()
        .abs()
}

/// Outlines are closed, pass through the placed corners, and enclose the segment's plan area
/// (mass / (ρ t) of the shape: β R W for the curved segments, L W for the straight ones); the
/// abutment faces lie at the abutment gap beyond the outer faces.
#[test]
fn plan_outlines_enclose_the_segments_and_abutments_sit_at_their_gaps() {
    for (text, name) in [(CURVED_5, "curved-5"), (RIGID_1D, "rigid-1d")] {
        let s = setup(text);
        let m = &s.problem.model;
        let plan = bridge_plan(m, 60);
        assert_eq!(plan.outlines.len(), m.segments.len(), "{name}");
        for (i, (o, seg)) in plan.outlines.iter().zip(&m.segments).enumerate() {
            assert!(
                (o[0] - o[o.len() - 1]).norm() < 1e-12,
                "{name}: {i} not closed"
            );
            for c in &plan.corners[i] {
                let d = o.iter().map(|p| (p - c).norm()).fold(f64::MAX, f64::min);
                assert!(
                    d < 1e-9,
                    "{name}: segment {i} corner {c:?} off its outline by {d}"
                );
            }
            let expected = match seg.shape {
                pounding::shape::DeckShape::Curved(d) => d.angle * d.radius * d.width,
                _ => seg.shape.length().unwrap() * seg.shape.width(),
            };
            let a = area(o);
            // 60 chords of 12 degrees: the inscribed polygon loses (Δφ)²/6 ≈ 1.2e-6 relative
            assert!(
                (a - expected).abs() <= 1e-5 * expected,
                "{name}: segment {i} area {a} vs {expected}"
            );
        }
        let bodies = m.layout();
        let faces = [bodies[0].start, bodies[bodies.len() - 1].end];
        for (side, face) in faces.iter().enumerate() {
            let (Some(ab), Some(f)) = (&m.abutments[side], plan.abutment_faces[side]) else {
                panic!("{name}: abutment {side} missing");
            };
            for (k, p) in f.iter().enumerate() {
                // signed distance outward from the segment's face line
                let d = -(p - face.corners[k]).dot(&face.inward);
                assert!((d - ab.gap).abs() < 1e-12, "{name}: abutment {side}: {d}");
            }
        }
    }
}

/// Corner paths are rigid motions of the reference corners (the face length is kept at every
/// step), start at the reference pose, and scale linearly with the exaggeration; the largest
/// magnitude of `segment_displacements` is the summary's peak displacement (every step kept).
#[test]
fn corner_paths_are_rigid_motions_and_displacements_match_the_summary() {
    let s = setup(&short(CURVED_5, "10", 8.0));
    let sol = run(&s);
    let m = &s.problem.model;
    let plan = bridge_plan(m, 8);
    let (p1, p20) = (corner_paths(m, &sol, 1.0), corner_paths(m, &sol, 20.0));
    let nt = sol.t.len();
    let mut moved: f64 = 0.0;
    for (i, seg) in p1.iter().enumerate() {
        let c0 = plan.corners[i];
        let l0 = (c0[1] - c0[0]).norm();
        for r in 0..nt {
            let l = (seg[1][r] - seg[0][r]).norm();
            assert!(
                (l - l0).abs() < 1e-9 * l0,
                "segment {i} face length {l} vs {l0}"
            );
            for k in 0..4 {
                let (d1, d20) = (seg[k][r] - c0[k], p20[i][k][r] - c0[k]);
                assert!(
                    (d20 - d1 * 20.0).norm() < 1e-9,
                    "segment {i} corner {k} scale"
                );
                moved = moved.max(d1.norm());
            }
        }
        for k in 0..4 {
            assert!((seg[k][0] - c0[k]).norm() < 1e-12, "starts at rest");
        }
    }
    assert!(
        moved > 1e-3,
        "the example hardly moved ({moved} m): the test shows nothing"
    );
    for (i, d) in segment_displacements(&sol).iter().enumerate() {
        let peak = d.iter().copied().fold(0.0, f64::max);
        let want = sol.summary.segments[i].peak_displacement;
        assert!(
            (peak - want).abs() <= 1e-12 * want.max(1e-12),
            "segment {i}: history peak {peak} vs summary {want}"
        );
    }
}

/// On the straight chain (laid out along −y, motion only along it) the opening of joint k is
/// `y_k − y_{k+1}`, and its minimum is `−peak_closing` of the summary.
#[test]
fn joint_openings_follow_the_chain_kinematics() {
    let s = setup(&short(RIGID_1D, "100", 5.0));
    let sol = run(&s);
    let n = sol.n_segments;
    let open = joint_openings(&s.problem.model, &sol);
    assert_eq!(open.len(), n - 1);
    for (k, o) in open.iter().enumerate() {
        assert_eq!(o.len(), sol.t.len());
        for (r, v) in o.iter().enumerate() {
            let q = &sol.q[3 * n * r..3 * n * (r + 1)];
            let want = q[3 * k + 1] - q[3 * (k + 1) + 1];
            assert!(
                (v - want).abs() < 1e-9,
                "joint {k} t = {}: {v} vs {want}",
                sol.t[r]
            );
        }
        let min = o.iter().copied().fold(f64::MAX, f64::min);
        let closing = sol.summary.joints[k].peak_closing;
        assert!(
            closing > 1e-3,
            "joint {k} never closed: the test shows nothing"
        );
        assert!(
            (min + closing).abs() < 1e-9,
            "joint {k}: {min} vs −{closing}"
        );
    }
}

#[test]
fn exaggeration_is_a_round_factor_of_at_least_one() {
    assert_eq!(plan_exaggeration(130.0, 0.095), 50.0);
    assert_eq!(plan_exaggeration(100.0, 5.0), 1.0);
    assert_eq!(plan_exaggeration(f64::INFINITY, 0.1), 1.0);
    for peak in [1e-6, 3e-4, 0.01, 0.07, 0.3] {
        let f = plan_exaggeration(100.0, peak);
        assert!(
            f * peak <= 4.0 + 1e-9 && f * peak >= 4.0 / 2.5 - 1e-9,
            "{peak}: {f}"
        );
        let m = f / 10f64.powi(f.log10().floor() as i32);
        assert!([1.0, 2.0, 5.0].iter().any(|x| (m - x).abs() < 1e-9), "{f}");
    }
}
