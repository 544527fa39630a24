//! N-segment bridges (`pounding::sim::bridge`, issue 11): the two-deck model as a bridge of two
//! segments, one segment between two abutments against its closed form, a Newton's cradle of
//! three segments, and the validation of bad input.

use pounding::ground_motion::{GroundMotion, el_centro_1940};
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::bridge::{BridgeAbutment, BridgeModel, BridgeProblem, Joint, Segment};
use pounding::sim::{
    DampingModel, JointContact, SimAbutment, SimContact, SimModel, SimProblem, SimSettings,
    simulate,
};

fn straight(l: f64) -> DeckShape {
    DeckShape::Straight(StraightDeck::new(l, 10.0, 0.5, 2500.0).unwrap())
}

fn joint(gap: f64, eps: f64) -> Joint {
    Joint {
        gap,
        friction: 0.0,
        restitution: eps,
        seat_length: 0.4,
        contact: JointContact::Rigid,
        restrainers: Vec::new(),
    }
}

fn abutment(gap: f64, eps: f64) -> Option<BridgeAbutment> {
    Some(BridgeAbutment {
        gap,
        seat_length: 0.4,
        friction: 0.0,
        restitution: eps,
        contact: JointContact::Rigid,
        backwall: None,
        shear_keys: None,
    })
}

fn chain(n: usize, k: f64, gap: f64, eps: f64) -> BridgeModel {
    BridgeModel {
        segments: (0..n)
            .map(|_| Segment::with_corner_bearings(straight(30.0), false, k))
            .collect(),
        joints: (1..n).map(|_| joint(gap, eps)).collect(),
        abutments: [None, None],
        outer_seat_length: 0.4,
        damping_ratio: 0.0,
        damping_model: DampingModel::Rayleigh,
        piers: Vec::new(),
    }
}

/// The default curved S bridge with both abutments under El Centro, run as a two-deck model
/// and as a bridge of two segments: the same motion to rounding (the layouts agree to the last
/// bits up to the order of a few operations).
#[test]
fn two_segment_bridge_reproduces_the_two_deck_model() {
    for with_shapes in [false, true] {
        let mut m = SimModel::default_bridge();
        if with_shapes {
            m = SimModel::with_shapes(
                [straight(40.0), straight(30.0)],
                0.03,
                2.0e7,
                9.0e6,
                0.05,
                0.3,
                0.5,
                0.4,
            );
        }
        m.abutments = [
            Some(SimAbutment {
                gap: 0.04,
                seat_length: 0.5,
            }),
            Some(SimAbutment {
                gap: 0.06,
                seat_length: 0.5,
            }),
        ];
        let settings = SimSettings {
            duration: Some(8.0),
            ..SimSettings::default()
        };
        let pair = simulate(&SimProblem::at_rest(m.clone(), el_centro_1940()), &settings).unwrap();
        let bp = BridgeProblem::at_rest(BridgeModel::from_pair(&m), el_centro_1940());
        let br = simulate(&bp, &settings).unwrap();
        assert_eq!(pair.status, br.status);
        assert!(pair.summary.impacts > 3, "the run must pound");
        assert_eq!(pair.summary.impacts, br.summary.impacts);
        assert_eq!(pair.impacts.len(), br.impacts.len());
        let scale = pair.q.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        for (row, qp) in pair.q_rows().enumerate() {
            for (i, v) in qp.iter().enumerate() {
                let vb = br.q[6 * row + i];
                let tol = if i % 3 == 2 { 1e-9 } else { 1e-9 * scale };
                assert!((v - vb).abs() <= tol, "row {row} q[{i}]: {v} vs {vb}");
            }
        }
        let s = &br.summary;
        assert!((s.joints[0].peak_closing - pair.summary.joints[0].peak_closing).abs() < 1e-9);
        assert!((s.joints[0].peak_opening - pair.summary.joints[0].peak_opening).abs() < 1e-9);
        for side in 0..2 {
            let a = s.abutments[side].as_ref().unwrap();
            let pc = pair.summary.abutments[side].as_ref().unwrap().peak_closing;
            assert!(
                (a.peak_closing - pc).abs() < 1e-9,
                "{} vs {pc}",
                a.peak_closing
            );
        }
        let abut_rows = pair
            .impacts
            .iter()
            .filter(|r| matches!(r.contact, SimContact::Abutment { .. }))
            .count();
        assert_eq!(abut_rows, pair.abutment_impacting_contacts());
        assert!((s.energy_balance_error - pair.summary.energy_balance_error).abs() < 1e-9);
        assert_eq!(s.segments.len(), 2);
        for j in 0..2 {
            assert_eq!(
                s.segments[j].frequencies,
                pair.summary.segments[j].frequencies
            );
            let rot = pair.summary.segments[j].peak_rotation;
            assert!((s.segments[j].peak_rotation - rot).abs() <= 1e-9 * rot.max(1e-12));
        }
    }
}

/// One free segment (no bearing stiffness, no damping) between two abutments, thrown toward the
/// end abutment: it bounces back and forth with its speed multiplied by ε at every impact; the
/// impact times are `t_1 = g_e/v`, then `+ (g_s + g_e)/(ε^k v)`.
#[test]
fn one_segment_between_two_abutments_bounces_as_the_closed_form() {
    let (ge, gs, v, eps) = (0.04, 0.03, 0.5, 0.8);
    let mut m = chain(1, 0.0, 0.0, eps);
    m.abutments = [abutment(gs, eps), abutment(ge, eps)];
    let mut p = BridgeProblem::at_rest(m, GroundMotion::none());
    // segment 1 lies in y ≥ 0 with its end face on y = 0: toward the end abutment is −y
    p.u0[1] = -v;
    let h = 1e-5;
    let settings = SimSettings {
        dt: h,
        duration: Some(1.0),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &settings).unwrap();
    // closed-form impact times within 1 s
    let mut times = vec![ge / v];
    let mut speed = v * eps;
    while times.last().unwrap() + (gs + ge) / speed < 1.0 {
        times.push(times.last().unwrap() + (gs + ge) / speed);
        speed *= eps;
    }
    let s = &sol.summary;
    let (a0, a1) = (
        s.abutments[0].as_ref().unwrap(),
        s.abutments[1].as_ref().unwrap(),
    );
    assert_eq!(a0.impacts + a1.impacts, times.len(), "{:?}", sol.impacts);
    assert_eq!(a1.impacts, times.len().div_ceil(2));
    assert_eq!(s.impacts, times.len());
    let mut seen = Vec::new();
    for rec in &sol.impacts {
        if !seen.contains(&rec.impact) {
            seen.push(rec.impact);
            let i = rec.impact - 1;
            assert!(
                (rec.time - times[i]).abs() <= 2.0 * h,
                "impact {i}: {} vs {}",
                rec.time,
                times[i]
            );
            let side = if i % 2 == 0 { 1 } else { 0 };
            assert_eq!(rec.site, side);
            // normal velocity into the abutment before, ε times it away after
            let pre = v * eps.powi(i as i32);
            assert!((rec.gamma_n_pre + pre).abs() < 1e-9 * pre, "{rec:?}");
            assert!((rec.gamma_n_post - eps * pre).abs() < 1e-9 * pre, "{rec:?}");
        }
    }
    assert!(s.energy_balance_error < 1e-12, "{}", s.energy_balance_error);
    // the segment never moves sideways nor turns
    assert!(s.segments[0].peak_rotation < 1e-12);
    assert!((s.abutments[1].as_ref().unwrap().peak_closing - ge).abs() < v * h);
}

/// Newton's cradle: three equal free segments in a line, ε = 1, the first thrown at the second:
/// momentum passes down the chain and the last one leaves with the first one's velocity.
#[test]
fn three_segment_cradle_passes_the_momentum_down_the_chain() {
    let m = chain(3, 0.0, 0.02, 1.0);
    let mut p = BridgeProblem::at_rest(m, GroundMotion::none());
    p.u0[1] = -0.4; // segment 1 toward segment 2 (−y)
    let settings = SimSettings {
        dt: 1e-5,
        duration: Some(0.5),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &settings).unwrap();
    let s = &sol.summary;
    assert_eq!(s.joints[0].impacts, 1);
    assert_eq!(s.joints[1].impacts, 1);
    let n = sol.t.len();
    let u = &sol.u[9 * (n - 1)..];
    assert!(u[1].abs() < 1e-12 && u[4].abs() < 1e-12, "{u:?}");
    assert!((u[7] + 0.4).abs() < 1e-12, "{u:?}");
    assert!(s.energy_balance_error < 1e-12);
    // the joints close to contact (rigid: at most the scheme's overlap)
    for j in &s.joints {
        assert!((j.peak_closing - 0.02).abs() < 0.4 * 1e-5, "{j:?}");
        assert!(j.peak_contact_force.is_none());
        assert!(j.peak_impulse > 0.0);
    }
}

/// Bad input is an error naming the key: no segment, a missing joint, faces of different
/// widths, a negative gap, rigid and compliance contact mixed.
#[test]
fn bad_bridges_are_errors_naming_the_key() {
    let err = |m: BridgeModel| {
        let p = BridgeProblem::at_rest(m, GroundMotion::none());
        simulate(&p, &SimSettings::default())
            .unwrap_err()
            .to_string()
    };
    let mut m = chain(3, 1e7, 0.02, 0.5);
    m.segments.clear();
    m.joints.clear();
    assert!(err(m).contains("at least one segment"));
    let mut m = chain(3, 1e7, 0.02, 0.5);
    m.joints.pop();
    assert!(err(m).contains("3 segments need 2 joints"));
    let mut m = chain(3, 1e7, 0.02, 0.5);
    m.segments[2].shape = DeckShape::Straight(StraightDeck::new(30.0, 12.0, 0.5, 2500.0).unwrap());
    let e = err(m);
    assert!(
        e.contains("segment[2].width") && e.contains("same length"),
        "{e}"
    );
    let mut m = chain(3, 1e7, 0.02, 0.5);
    m.joints[1].gap = -0.01;
    assert!(err(m).contains("joint[1].gap"));
    let mut m = chain(3, 1e7, 0.02, 0.5);
    m.abutments[1] = abutment(-1.0, 0.5);
    assert!(err(m).contains("abutment.end.gap"));
    let mut m = chain(3, 1e7, 0.02, 0.5);
    let law =
        pounding::contact_law::ContactLaw::Hertz(pounding::contact_law::Hertz::new(1e10).unwrap());
    m.joints[1].contact = JointContact::Compliance(pounding::sim::ComplianceContact::new(law));
    // rigid and compliance sites mix (tests/it/sim_bridge_mixed.rs)
    assert!(m.validate().is_ok());
}

#[test]
fn the_unseating_ratio_reads_each_end_against_its_own_seat() {
    // Three segments on bearings under El Centro; only the two outer seats are short enough
    // to matter. `peak_seat_ratio` must put its flag and its ratio on the same side of 1 (the
    // fragility `unseating` margin): dividing the largest displacement of any end by the
    // shortest seat (as before) breaks that whenever another end moves more.
    let settings = SimSettings {
        duration: Some(8.0),
        ..SimSettings::default()
    };
    let run = |seat_j0: f64| {
        let mut m = chain(3, 2.0e7, 0.03, 0.5);
        // a softer middle segment moves more than the outer two
        m.segments[1] = Segment::with_corner_bearings(straight(30.0), false, 4.0e6);
        m.outer_seat_length = seat_j0;
        m.joints[0].seat_length = 1e3;
        m.joints[1].seat_length = 1e3;
        let bp = BridgeProblem::at_rest(m, el_centro_1940());
        simulate(&bp, &settings).unwrap().summary
    };
    let long = run(10.0);
    assert!(!long.unseated);
    // the outer ends' own seat displacement (every other seat is 100x longer)
    let d = long.peak_seat_ratio * 10.0;
    assert!(
        d > 1e-4 && long.peak_seat_displacement / 1e3 < d / 10.0,
        "{d}"
    );
    // the middle segment's ends (at the joints) move more: the old ratio would be off
    assert!(
        long.peak_seat_displacement > d * 1.01,
        "{} vs {d}",
        long.peak_seat_displacement
    );
    for (seat, unseats) in [(d * (1.0 + 1e-9), false), (d * (1.0 - 1e-9), true)] {
        let s = run(seat);
        assert_eq!(s.unseated, unseats, "seat {seat}");
        assert_eq!(s.peak_seat_ratio > 1.0, unseats, "{}", s.peak_seat_ratio);
        assert!(
            (s.peak_seat_ratio - d / seat).abs() < 1e-9,
            "{}",
            s.peak_seat_ratio
        );
    }
}
