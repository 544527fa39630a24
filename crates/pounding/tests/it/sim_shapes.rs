//! The simulator with straight / skewed decks and abutments: an isolated abutment impact agrees
//! with the generic impact LCP built by `shape::abutment_problem` (independent geometry and
//! solver), the skew rotation condition shows in the simulated motion, the curved default is
//! unchanged by the generic body construction, and bad shape / abutment input is rejected by name.

use pounding::analytic::ImpactLaw;
use pounding::ground_motion::GroundMotion;
use pounding::impact::{self, ImpactSettings, ImpactStatus};
use pounding::math::Vector;
use pounding::shape::Deck;
use pounding::shape::{DeckEnd, DeckShape, SkewedDeck, StraightDeck, abutment_problem};
use pounding::sim::{
    SimAbutment, SimContact, SimError, SimModel, SimProblem, SimSettings, SimStatus, simulate,
};

fn skewed(l: f64, w: f64, deg: f64) -> DeckShape {
    if deg == 0.0 {
        DeckShape::Straight(StraightDeck::new(l, w, 1.0, 2500.0).unwrap())
    } else {
        DeckShape::Skewed(SkewedDeck::new(l, w, deg.to_radians(), 1.0, 2500.0).unwrap())
    }
}

/// Free decks (no bearings, no damping), abutments with gap 0.01 m at both far ends.
fn free_model(shape: DeckShape, mu: f64, eps: f64) -> SimModel {
    let mut m = SimModel::with_shapes([shape, shape], 0.05, 0.0, 0.0, 0.0, mu, eps, 1.0);
    let a = SimAbutment {
        gap: 0.01,
        seat_length: 0.5,
    };
    m.abutments = [Some(a), Some(a)];
    m
}

/// Deck `j` approaches its abutment along its axis at 1.5 m/s (the other deck at rest); after
/// the impact its velocity equals the generic two-corner (or one-corner) impact solution.
#[test]
fn abutment_impact_matches_the_generic_impact_lcp() {
    let mut rotating = 0;
    for deg in [0.0, 15.0, 40.0] {
        let shape = skewed(30.0, 10.0, deg);
        for (mu, eps) in [(0.0, 0.5), (0.3, 0.5), (0.8, 0.0)] {
            let law = ImpactLaw::new(mu, eps).unwrap();
            // body-frame approach velocity and the generic solution
            let v = 1.5 * shape.axis_direction(DeckEnd::Far);
            let pr = abutment_problem(&shape, DeckEnd::Far, &[0, 1], v, 0.0, &law).unwrap();
            let s = impact::solve(&pr, &ImpactSettings::default());
            assert!(matches!(
                s.status,
                ImpactStatus::Solved | ImpactStatus::SolvedByFallback
            ));
            let (vb, wb) = (s.bodies[0].velocity, s.bodies[0].omega);
            for j in 0..2 {
                // deck 2 is the body frame turned by π: velocities change sign, ω does not
                let sg = if j == 0 { 1.0 } else { -1.0 };
                let mut p = SimProblem::at_rest(free_model(shape, mu, eps), GroundMotion::none());
                p.u0[3 * j] = sg * v.x;
                p.u0[3 * j + 1] = sg * v.y;
                let st = SimSettings {
                    dt: 1e-4,
                    // contact after 0.01 m / (1.5 m/s · e·n_out); a little more time after it
                    duration: Some(0.01 / (1.5 * f64::to_radians(deg).cos()) + 0.002),
                    ..SimSettings::default()
                };
                let sol = simulate(&p, &st).unwrap();
                assert_eq!(sol.status, SimStatus::Completed);
                assert_eq!(sol.summary.impacts, 1, "{deg}° μ={mu} deck {}", j + 1);
                assert!(sol.impacts.iter().all(|i| matches!(
                    i.contact,
                    SimContact::Abutment { deck, .. } if deck == j + 1
                )));
                assert_eq!(sol.abutment_impacting_contacts(), sol.impacts.len());
                let u = sol.u_rows().last().unwrap();
                let got = Vector::new(u[3 * j], u[3 * j + 1]) * sg;
                let tol = 1e-9 * 1.5;
                assert!(
                    (got - vb).norm() < tol && (u[3 * j + 2] - wb).abs() < tol / 10.0,
                    "{deg}° μ={mu} ε={eps} deck {}: sim ({got}, {}) vs LCP ({vb}, {wb})",
                    j + 1,
                    u[3 * j + 2]
                );
                // energy lost at the contacts = the LCP's kinetic energy loss
                let dc = sol.summary.final_energy.contact;
                let de = s.energy_before - s.energy_after;
                assert!((dc - de).abs() < 1e-6 * s.energy_before, "{dc} vs {de}");
                // the abutment closing reached the gap to within one step's travel h |γ_N⁻|
                // (the impulse acts in the step whose predicted gap closes)
                let pk = sol.summary.abutments[j].as_ref().unwrap().peak_closing;
                assert!((pk - 0.01).abs() <= 1e-4 * 1.5, "{pk}");
                if j == 0 && wb.abs() > 1e-6 {
                    rotating += 1;
                }
            }
            // frictionless: the deck turns iff sin 2θ > 2W/L (40°: yes; 0°, 15°: no)
            if mu == 0.0 {
                let turns = (2.0 * f64::to_radians(deg)).sin() > 2.0 * 10.0 / 30.0;
                assert_eq!(wb.abs() > 1e-9, turns, "{deg}°: ω⁺ = {wb}");
            }
        }
    }
    assert!(rotating >= 1);
}

/// Straight decks meet face to face: a head-on approach gives a central double-corner impact
/// with Newton's law, no rotation, no transverse motion.
#[test]
fn straight_decks_meet_face_to_face() {
    let shape = skewed(40.0, 10.0, 0.0);
    let eps = 0.6;
    let m = SimModel::with_shapes([shape, shape], 0.05, 0.0, 0.0, 0.0, 0.4, eps, 1.0);
    let mut p = SimProblem::at_rest(m, GroundMotion::none());
    p.u0[1] = -0.5; // deck 1 toward −y
    p.u0[4] = 0.3; // deck 2 toward +y
    let st = SimSettings {
        dt: 1e-4,
        duration: Some(0.1),
        ..SimSettings::default()
    };
    let sol = simulate(&p, &st).unwrap();
    assert_eq!(sol.summary.impacts, 1);
    assert_eq!(sol.impacts.len(), 2, "both corners strike");
    let u = sol.u_rows().last().unwrap();
    // equal masses: velocities after a central impact
    let g = -0.8; // γ⁻ = v1 − v2
    let v1 = -0.5 - (1.0 + eps) * g / 2.0;
    let v2 = 0.3 + (1.0 + eps) * g / 2.0;
    assert!(
        (u[1] - v1).abs() < 1e-10 && (u[4] - v2).abs() < 1e-10,
        "{u:?}"
    );
    for k in [0, 2, 3, 5] {
        assert!(u[k].abs() < 1e-12, "{u:?}");
    }
}

/// The generic body of a curved deck (from `DeckShape::Curved`) is the spec §4 body: the run
/// equals the `arrangement` run to rounding.
#[test]
fn curved_shape_equals_the_arrangement_path() {
    let m0 = SimModel::default_bridge();
    let d = m0.arrangement.deck1;
    let mut m1 = m0.clone();
    m1.shapes = Some([DeckShape::Curved(d), DeckShape::Curved(d)]);
    let gm = pounding::ground_motion::el_centro_1940();
    let st = SimSettings {
        duration: Some(8.0),
        ..SimSettings::default()
    };
    let a = simulate(&SimProblem::at_rest(m0, gm.clone()), &st).unwrap();
    let b = simulate(&SimProblem::at_rest(m1, gm), &st).unwrap();
    assert_eq!(a.summary.impacts, b.summary.impacts);
    for (qa, qb) in a.q_rows().zip(b.q_rows()) {
        for k in 0..6 {
            assert!((qa[k] - qb[k]).abs() < 1e-9, "{qa:?} {qb:?}");
        }
    }
}

#[test]
fn bad_shape_and_abutment_input_is_rejected_by_name() {
    let good = skewed(30.0, 10.0, 20.0);
    let name_of = |m: &SimModel| match m.validate().unwrap_err() {
        SimError::InvalidParameter { name, .. } => name,
        SimError::Geometry(pounding::geometry::GeometryError::InvalidParameter {
            name, ..
        }) => name,
        e => panic!("{e}"),
    };
    let with = |s1: DeckShape, s2: DeckShape| {
        SimModel::with_shapes([s1, s2], 0.05, 1e6, 1e6, 0.05, 0.0, 0.5, 1.0)
    };
    // skew ≥ 90°, L ≤ 0 (constructed directly: the constructors refuse them)
    let mut bad = SkewedDeck::new(30.0, 10.0, 0.3, 1.0, 2500.0).unwrap();
    bad.skew = 90f64.to_radians();
    assert_eq!(name_of(&with(DeckShape::Skewed(bad), good)), "skew1");
    let mut bad = StraightDeck::new(30.0, 10.0, 1.0, 2500.0).unwrap();
    bad.length = 0.0;
    assert_eq!(name_of(&with(good, DeckShape::Straight(bad))), "L2");
    // joint faces of different length
    assert_eq!(
        name_of(&with(good, skewed(30.0, 10.0, 25.0))),
        "joint face length (deck 2)"
    );
    // abutment gap < 0, seat length <= 0
    let mut m = with(good, good);
    m.abutments[1] = Some(SimAbutment {
        gap: -0.01,
        seat_length: 0.5,
    });
    assert_eq!(name_of(&m), "abutment gap (deck 2)");
    m.abutments[1] = Some(SimAbutment {
        gap: 0.01,
        seat_length: 0.0,
    });
    assert_eq!(name_of(&m), "abutment seat_length (deck 2)");
    // curved shapes are validated too
    let mut d = Deck {
        radius: 100.0,
        angle: 1.0,
        width: 10.0,
        thickness: 0.5,
        density: 2500.0,
    };
    d.radius = 3.0;
    let c = DeckShape::Curved(d);
    assert_eq!(name_of(&with(c, c)), "R1");
}
