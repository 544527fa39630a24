//! Bearings at given points and restrainer cables at given anchors (issue 11): the segment frame
//! of [`BridgeModel::segment_point`] on every shape, closed-form bearing frequencies, cables at
//! offsets against one central cable, and points off their segment refused.

use pounding::ground_motion::el_centro_1940;
use pounding::math::Vector;
use pounding::shape::{Deck, DeckShape, SkewedDeck, StraightDeck};
use pounding::sim::bridge::{
    BridgeAbutment, BridgeModel, BridgeProblem, Joint, RestrainerSpec, Segment,
};
use pounding::sim::simulate;
use pounding::sim::{Bearing, DampingModel, JointContact, SimError, SimSettings};

const W: f64 = 10.0;

fn straight(l: f64) -> DeckShape {
    DeckShape::Straight(StraightDeck::new(l, W, 0.5, 2500.0).unwrap())
}

fn joint(gap: f64, restrainers: Vec<RestrainerSpec>) -> Joint {
    Joint {
        gap,
        friction: 0.0,
        restitution: 0.6,
        seat_length: 0.4,
        contact: JointContact::Rigid,
        restrainers,
    }
}

fn model(segments: Vec<Segment>, joints: Vec<Joint>) -> BridgeModel {
    BridgeModel {
        segments,
        joints,
        abutments: [None, None],
        outer_seat_length: 0.4,
        damping_ratio: 0.05,
        damping_model: DampingModel::TranslationalDashpots,
        piers: Vec::new(),
    }
}

/// Left of a walking direction `d`.
fn left(d: Vector) -> Vector {
    Vector::new(-d.y, d.x)
}

/// On straight, skewed and curved segments (curving and skewed both ways), a bearing placed at
/// `segment_point(i, a, l)` sits, in the placed bridge, at `M + a e + l t` with `M` the
/// midpoint of the segment's start face, `e` its axis (curved: the face's inward normal;
/// straight and skewed: toward the end face's midpoint) and `t` to the left of `e`.
#[test]
fn segment_points_follow_the_documented_frame_on_every_shape() {
    let curved = DeckShape::Curved(Deck::new(100.0, 0.3, W, 0.5, 2500.0).unwrap());
    let skew = DeckShape::Skewed(SkewedDeck::new(30.0, W, 0.4, 0.5, 2500.0).unwrap());
    let chains = [
        vec![
            (straight(30.0), false),
            (curved, false),
            (curved, true),
            (curved, false),
        ],
        // skewed faces are longer than W: skewed segments meet skewed ones
        vec![(skew, false), (skew, true), (skew, false)],
    ];
    for shapes in chains {
        check_frame(&shapes);
    }
}

fn check_frame(shapes: &[(DeckShape, bool)]) {
    let coords = [(0.0, 0.0), (2.0, 3.0), (5.0, -4.0), (3.0, 4.5)];
    let mut m = model(
        shapes
            .iter()
            .map(|(s, mir)| Segment::with_corner_bearings(*s, *mir, 1e7))
            .collect(),
        (1..shapes.len()).map(|_| joint(0.03, Vec::new())).collect(),
    );
    for i in 0..shapes.len() {
        let pts: Vec<Bearing> = coords
            .iter()
            .map(|&(a, l)| Bearing {
                point: m.segment_point(i, a, l),
                stiffness: 1e7,
            })
            .collect();
        m.segments[i].bearings = pts;
    }
    m.validate().unwrap();
    let bodies = m.layout();
    let placed = m.bearing_points();
    for (i, b) in bodies.iter().enumerate() {
        let f = b.start;
        let axis = match shapes[i].0.curved() {
            Some(_) => f.inward,
            None => (b.end.mid - f.mid).normalize(),
        };
        for (k, &(a, l)) in coords.iter().enumerate() {
            let want = f.mid + axis * a + left(axis) * l;
            assert!(
                (placed[i][k] - want).norm() < 1e-9,
                "segment {i} point {k}: {} vs {want}",
                placed[i][k]
            );
        }
    }
    // the walking direction is the same through a joint: the start face of segment i + 1 faces
    // the end face of segment i
    for i in 0..bodies.len() - 1 {
        assert!((bodies[i + 1].start.inward + bodies[i].end.inward).norm() < 1e-12);
    }
}

/// A straight segment's corners are `(0, ±W/2)` and `(L, ±W/2)` in its segment frame, so
/// bearings given there run the same bridge as the default corner bearings.
#[test]
fn corner_bearing_points_reproduce_the_default_corner_bearings() {
    let build = |explicit: bool| {
        let mut segs: Vec<Segment> = [30.0, 40.0, 25.0]
            .iter()
            .map(|&l| Segment::with_corner_bearings(straight(l), false, 2e7))
            .collect();
        if explicit {
            for (i, l) in [30.0, 40.0, 25.0].into_iter().enumerate() {
                let f = segs[i].clone();
                segs[i].bearings = [(0.0, -W / 2.0), (0.0, W / 2.0), (l, -W / 2.0), (l, W / 2.0)]
                    .iter()
                    .map(|&(a, s)| Bearing {
                        point: f.frame_point(i == 0, a, s),
                        stiffness: 2e7,
                    })
                    .collect();
            }
        }
        let mut m = model(segs, vec![joint(0.02, Vec::new()), joint(0.02, Vec::new())]);
        m.abutments = [abutment(), abutment()];
        m
    };
    let settings = SimSettings {
        dt: 1e-3,
        duration: Some(10.0),
        ..SimSettings::default()
    };
    let run =
        |m: BridgeModel| simulate(&BridgeProblem::at_rest(m, el_centro_1940()), &settings).unwrap();
    let (a, b) = (run(build(false)), run(build(true)));
    assert!(a.summary.impacts > 3, "the run must pound");
    assert_eq!(a.summary.impacts, b.summary.impacts);
    for (x, y) in a.summary.segments.iter().zip(&b.summary.segments) {
        let rel = (x.peak_displacement - y.peak_displacement).abs() / x.peak_displacement;
        assert!(rel < 1e-9, "{rel}");
        for (p, q) in x.frequencies.iter().zip(&y.frequencies) {
            assert!((p - q).abs() < 1e-9 * p, "{p} {q}");
        }
    }
}

fn abutment() -> Option<BridgeAbutment> {
    Some(BridgeAbutment {
        gap: 0.04,
        seat_length: 0.4,
        friction: 0.0,
        restitution: 0.6,
        contact: JointContact::Rigid,
        backwall: None,
        shear_keys: None,
    })
}

/// Two bearings of stiffness `k` on the axis at the two ends of a straight segment: translation
/// `ω² = 2k/m` in both directions, rotation `ω² = 2k (L/2)² / I` with `I = m (L² + W²)/12`.
#[test]
fn bearings_on_the_axis_give_the_closed_form_frequencies() {
    let (l, k) = (30.0, 3e7);
    let mut s = Segment::with_corner_bearings(straight(l), false, k);
    s.bearings = [(0.0, 0.0), (l, 0.0)]
        .iter()
        .map(|&(a, t)| Bearing {
            point: s.frame_point(true, a, t),
            stiffness: k,
        })
        .collect();
    let mp = s.shape.mass_properties();
    let m = model(vec![s], Vec::new());
    let settings = SimSettings {
        dt: 1e-3,
        duration: Some(0.5),
        ..SimSettings::default()
    };
    let sol = simulate(&BridgeProblem::at_rest(m, el_centro_1940()), &settings).unwrap();
    let w_t = (2.0 * k / mp.mass).sqrt();
    let w_r = (2.0 * k * (l / 2.0) * (l / 2.0) / mp.inertia).sqrt();
    let i_box = mp.mass * (l * l + W * W) / 12.0;
    assert!((mp.inertia - i_box).abs() < 1e-9 * i_box);
    let mut want = [w_t, w_t, w_r];
    want.sort_by(f64::total_cmp);
    for (g, w) in sol.summary.segments[0].frequencies.iter().zip(want) {
        assert!((g - w).abs() < 1e-9 * w, "{g} vs {w}");
    }
}

/// A three-segment chain with restrainers pounds under El Centro along the chain; `cables` per
/// joint.
fn restrained(cables: &[RestrainerSpec]) -> pounding::sim::bridge::BridgeSolution {
    let segs = [(1.0e6, 1.2), (1.2e6, 0.5), (0.8e6, 1.5)]
        .iter()
        .map(|&(mass, t)| {
            let mut shape = straight(30.0);
            let f = mass / shape.mass_properties().mass;
            shape.scale_density(f);
            let w = 2.0 * std::f64::consts::PI / t;
            Segment::with_corner_bearings(shape, false, mass * w * w / 4.0)
        })
        .collect();
    let mut m = model(
        segs,
        vec![joint(0.02, cables.to_vec()), joint(0.02, cables.to_vec())],
    );
    m.abutments = [abutment(), abutment()];
    let mut g = el_centro_1940();
    g.scale_y = -1.0;
    g.scale_x = 0.0;
    let settings = SimSettings {
        dt: 1e-3,
        duration: Some(15.0),
        ..SimSettings::default()
    };
    simulate(&BridgeProblem::at_rest(m, g), &settings).unwrap()
}

/// Two cables of stiffness k/2 at ±3 m across each joint of a straight chain shaken along its
/// axis act as one cable of stiffness k between the face midpoints (the chain does not turn);
/// each of the two carries half the force. One cable off the axis turns the segments.
#[test]
fn cables_at_offsets_act_as_their_resultant_and_an_offset_cable_turns_the_segments() {
    let k = 5.0e7;
    let one = restrained(&[RestrainerSpec::at_midpoints(k, 0.005, None)]);
    let two = restrained(&[-3.0, 3.0].map(|offset| RestrainerSpec {
        offset,
        ..RestrainerSpec::at_midpoints(k / 2.0, 0.005, None)
    }));
    assert!(one.summary.impacts > 3);
    assert_eq!(one.summary.impacts, two.summary.impacts);
    for (a, b) in one.summary.joints.iter().zip(&two.summary.joints) {
        let (pa, pb) = (
            a.restrainer_peak_force.unwrap(),
            b.restrainer_peak_force.unwrap(),
        );
        assert!(pa > 0.0);
        assert!((pa - 2.0 * pb).abs() < 1e-6 * pa, "{pa} vs 2 x {pb}");
        // one engagement episode per cable: the two cables engage together
        assert_eq!(2 * a.restrainer_engagements, b.restrainer_engagements);
        assert!((a.peak_opening - b.peak_opening).abs() < 1e-9 * a.peak_opening.abs().max(1e-3));
    }
    for (a, b) in one.summary.segments.iter().zip(&two.summary.segments) {
        assert!(a.peak_rotation < 1e-12 && b.peak_rotation < 1e-12);
        assert!((a.peak_displacement - b.peak_displacement).abs() < 1e-9 * a.peak_displacement);
    }
    let turn = |offset: f64| {
        restrained(&[RestrainerSpec {
            offset,
            ..RestrainerSpec::at_midpoints(k, 0.005, None)
        }])
    };
    let (left, right) = (turn(4.0), turn(-4.0));
    for (a, b) in left.summary.segments.iter().zip(&right.summary.segments) {
        assert!(
            a.peak_rotation > 1e-6,
            "an offset cable must turn the segment"
        );
        // mirror symmetry of the straight chain: the same motion, turned the other way
        assert!((a.peak_rotation - b.peak_rotation).abs() < 1e-6 * a.peak_rotation);
    }
}

/// A cable beside the joint or anchored beyond its segment, and a bearing off its segment, are
/// errors naming the key.
#[test]
fn points_off_their_segment_are_refused() {
    let cable = |offset: f64, depth: f64| RestrainerSpec {
        offset,
        depth,
        ..RestrainerSpec::at_midpoints(5e7, 0.0, None)
    };
    let base = || {
        model(
            vec![
                Segment::with_corner_bearings(straight(30.0), false, 1e7),
                Segment::with_corner_bearings(straight(20.0), false, 1e7),
            ],
            vec![joint(0.02, Vec::new())],
        )
    };
    let name = |m: &BridgeModel| match m.validate() {
        Err(SimError::InvalidArgument { name, .. } | SimError::InvalidParameter { name, .. }) => {
            name
        }
        other => panic!("{other:?}"),
    };
    for (c, want) in [
        (cable(5.0 + 1e-6, 0.0), "joint[0].restrainer_offsets"),
        (cable(-6.0, 1.0), "joint[0].restrainer_offsets"),
        // 25 m deep: inside the 30 m segment 1, beyond the 20 m segment 2
        (cable(0.0, 25.0), "joint[0].restrainer_depth"),
        (cable(0.0, -0.1), "joint[0].restrainer_depth"),
        (cable(f64::NAN, 0.0), "joint[0].restrainer_offsets"),
    ] {
        let mut m = base();
        m.joints[0].restrainers = vec![c];
        assert_eq!(name(&m), want, "{c:?}");
    }
    // on the edge is on the segment
    let mut m = base();
    m.joints[0].restrainers = vec![cable(5.0, 20.0), cable(-5.0, 0.0)];
    m.validate().unwrap();
    let mut m = base();
    let p = m.segment_point(1, 20.5, 0.0);
    m.segments[1].bearings.push(Bearing {
        point: p,
        stiffness: 1e7,
    });
    assert_eq!(name(&m), "segment[1].bearing_points");
}

/// The scenario keys: `bearing_points` in the segment frame (period spread over them),
/// `restrainer_offsets` one cable each with the joint's `restrainer_k`, `restrainer_depth`.
#[test]
fn scenario_keys_build_the_points_and_cables() {
    use pounding::sim::scenario::Scenario;
    let text = r#"
[bridge]
restrainer_k = 4e7
restrainer_slack = 0.01
restrainer_offsets = [-3.0, 3.0]
restrainer_depth = 1.5

[[segment]]
shape = "skew"
L = 30.0
skew_deg = 20.0
mass = 1.0e6
period_s = 1.0
bearing_points = [[2.0, -4.0], [2.0, 4.0], [28.0, 0.0]]

[[segment]]
shape = "skew"
L = 30.0
skew_deg = 20.0
mass = 1.0e6
period_s = 1.0

[[joint]]
restrainer_offsets = [0.5]

[time]
dt = 1e-3
duration = 1.0
"#;
    let setup = Scenario::from_toml(text, "points.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    let m = &setup.problem.model;
    let s0 = &m.segments[0];
    assert_eq!(s0.bearings.len(), 3);
    let w = 2.0 * std::f64::consts::PI;
    for (b, (a, l)) in s0
        .bearings
        .iter()
        .zip([(2.0, -4.0), (2.0, 4.0), (28.0, 0.0)])
    {
        assert!((b.stiffness - 1.0e6 * w * w / 3.0).abs() < 1e-6 * b.stiffness);
        assert_eq!(b.point, m.segment_point(0, a, l));
    }
    assert_eq!(m.segments[1].bearings.len(), 4);
    // the joint's own offsets replace the [bridge] default; the other keys are inherited
    let cables = &m.joints[0].restrainers;
    assert_eq!(cables.len(), 1);
    assert_eq!(
        cables[0],
        RestrainerSpec {
            offset: 0.5,
            depth: 1.5,
            ..RestrainerSpec::at_midpoints(4e7, 0.01, None)
        }
    );
    setup.run().unwrap();
}
