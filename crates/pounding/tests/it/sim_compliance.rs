//! `simulate` with compliance contact laws: the OpenSees 1-D benchmark through the full 2-D
//! simulator, the rigid limit of stiff laws, straight decks and dashpot damping, bad input.

use pounding::contact_law::{BilinearImpact, ContactLaw, units};
use pounding::ground_motion::{GroundMotion, el_centro_1940};
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::{
    ComplianceContact, DampingModel, JointContact, SimModel, SimProblem, SimSettings, SimStatus,
    simulate,
};
use std::f64::consts::PI;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Two straight decks of mass `m` (L = 30 m, W = 10 m) with 4 symmetric corner bearings giving
/// translational periods `t1` (deck 1) and `t2` (deck 2), dashpot damping `ζ`, gap `g`.
fn straight_model(m: f64, t1: f64, t2: f64, zeta: f64, gap: f64, law: JointContact) -> SimModel {
    let (l, w, t) = (30.0, 10.0, 0.5);
    let deck = DeckShape::Straight(StraightDeck {
        length: l,
        width: w,
        thickness: t,
        density: m / (l * w * t),
    });
    let k = |p: f64| m * (2.0 * PI / p).powi(2) / 4.0;
    let mut model = SimModel::with_shapes([deck, deck], gap, k(t1), k(t2), zeta, 0.0, 0.5, 0.4);
    model.damping_model = DampingModel::TranslationalDashpots;
    model.contact = law;
    model
}

fn opensees_bilinear() -> ContactLaw {
    BilinearImpact::from_hertz(units::kip_per_in_1_5(25_000.0), 0.6, units::INCH, 0.1)
        .unwrap()
        .law
        .into()
}

fn elc180_only() -> GroundMotion {
    let mut g = el_centro_1940();
    g.along_x = None;
    g
}

#[test]
fn straight_decks_with_dashpots_have_the_requested_periods_and_damping() {
    let m = straight_model(1.0e6, 1.0, 0.5, 0.05, 0.05, JointContact::Rigid);
    let sys = crate::common::two_deck_system(&m);
    // translational frequencies 2π/T (x and y), independent eigen-analysis in the library
    let w1 = sys.frequencies[0];
    let w2 = sys.frequencies[1];
    assert!(
        rel(w1[0], 2.0 * PI) < 1e-12 && rel(w1[1], 2.0 * PI) < 1e-12,
        "{w1:?}"
    );
    assert!(rel(w2[0], 4.0 * PI) < 1e-12, "{w2:?}");
    // c = 2 ζ m 2π/T in x and y, nothing in rotation
    assert!(rel(sys.damping[(1, 1)], 2.0 * 0.05 * 1e6 * 2.0 * PI / 1.0) < 1e-12);
    assert!(rel(sys.damping[(4, 4)], 2.0 * 0.05 * 1e6 * 2.0 * PI / 0.5) < 1e-12);
    assert_eq!(sys.damping[(2, 2)], 0.0);
    // symmetric bearings: no y–θ coupling
    assert!(sys.stiffness[(1, 2)].abs() < 1e-6 * sys.stiffness[(1, 1)]);
    let mp = m.deck_bodies()[0].mass;
    assert!(rel(mp.mass, 1.0e6) < 1e-12);
    assert!(rel(mp.inertia, mp.mass * (900.0 + 100.0) / 12.0) < 1e-12);
}

/// The OpenSees benchmark (OpenSees 3.7.1: 6 impacts, 44.30 MN, closing 0.05404 m)
/// through `simulate` with straight decks and the bilinear law, dt = 1e-4 over 53.71 s.
#[test]
fn opensees_1d_benchmark_in_the_simulator() {
    let model = straight_model(
        1.0e6,
        1.0,
        0.5,
        0.05,
        0.05,
        JointContact::Compliance(ComplianceContact::new(opensees_bilinear())),
    );
    let settings = SimSettings {
        dt: 1e-4,
        history_stride: 1000,
        ..SimSettings::default()
    };
    let sol = simulate(&SimProblem::at_rest(model, elc180_only()), &settings).unwrap();
    let s = &sol.summary;
    let f = s.joints[0].peak_contact_force.unwrap();
    eprintln!(
        "simulator, OpenSees 1-D: impacts {} (6), peak force {:.4} MN (44.30), closing {:.5} m \
         (0.05404), penetration {:.4} mm (4.04), rotation {:e}, newton failures {}",
        s.impacts,
        f / 1e6,
        s.joints[0].peak_closing,
        s.peak_penetration * 1e3,
        s.segments[0].peak_rotation.max(s.segments[1].peak_rotation),
        sol.newton_failures
    );
    for r in &sol.impacts {
        eprintln!(
            "  impact {} at {:.4} s ({}): P_N {:.4e} N s",
            r.impact,
            r.time,
            r.contact.name(),
            r.impulse_n
        );
    }
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(s.impacts, 6);
    assert!(rel(f, 44.30e6) < 0.02, "{f}");
    assert!(
        rel(s.peak_penetration, 4.04e-3) < 0.03,
        "{}",
        s.peak_penetration
    );
    assert!(rel(s.joints[0].peak_closing, 0.05404) < 1e-3);
    // no rotation, both corners carry half the joint force
    assert!(s.segments[0].peak_rotation < 1e-12 && s.segments[1].peak_rotation < 1e-12);
    assert_eq!(sol.impacts.len(), 12);
    let adv = sol.time_step_advice.unwrap();
    assert!(adv.adequate && (adv.contact_duration - 0.01779).abs() < 1e-4);
}

/// Largest `|y_j − y_j^rigid|` over the run relative to the largest rigid `|y_j|`, for an isolated
/// central impact of two decks on bearings (T = 1.0 s / 0.5 s, no damping, no ground motion)
/// meeting at the reference pose (gap 0) with ±0.5 m/s, e = 0.6, μ = 0, over 0.2 s.
fn central_impact_deviation(contact: JointContact, dt: f64) -> (f64, usize) {
    let run = |c: JointContact| {
        let mut model = straight_model(1.0e6, 1.0, 0.5, 0.0, 0.0, c);
        model.restitution = 0.6;
        let mut p = SimProblem::at_rest(model, GroundMotion::none());
        p.u0 = [0.0, -0.5, 0.0, 0.0, 0.5, 0.0];
        let settings = SimSettings {
            dt,
            duration: Some(0.2),
            ..SimSettings::default()
        };
        simulate(&p, &settings).unwrap()
    };
    let rigid = run(JointContact::Rigid);
    let comp = run(contact);
    assert_eq!(rigid.summary.impacts, 1);
    let mut dev: f64 = 0.0;
    let mut peak: f64 = 0.0;
    for (a, b) in rigid.q_rows().zip(comp.q_rows()) {
        for j in [1, 4] {
            dev = dev.max((a[j] - b[j]).abs());
            peak = peak.max(a[j].abs());
        }
    }
    (dev / peak, comp.summary.impacts)
}

/// As the contact stiffness grows, the compliance laws' response to an isolated central impact
/// approaches the rigid (Newton) law's: the deviation falls like the contact duration
/// (`∝ k^{-1/2}` for Kelvin, `∝ k_h^{-2/5}` for Hertz-damp).
#[test]
fn stiff_compliance_laws_approach_the_rigid_law() {
    use pounding::contact_law::calibration::{HertzDampCalibration, KelvinCalibration};
    use pounding::contact_law::{HertzDamp, KelvinVoigt};
    let dt = 2e-5;
    let kelvin: Vec<f64> = [1e8, 1e9, 1e10, 1e11]
        .iter()
        .map(|&k| {
            let law = KelvinVoigt::from_restitution(k, 0.6, 1e6, 1e6, KelvinCalibration::Numerical)
                .unwrap();
            let (d, n) = central_impact_deviation(
                JointContact::Compliance(ComplianceContact::new(law.into())),
                dt,
            );
            assert_eq!(n, 1);
            d
        })
        .collect();
    let hd: Vec<f64> = [1e9, 1e10, 1e11, 1e12]
        .iter()
        .map(|&k| {
            let law =
                HertzDamp::from_restitution(k, 0.6, None, 0.01, HertzDampCalibration::Numerical)
                    .unwrap();
            let (d, n) = central_impact_deviation(
                JointContact::Compliance(ComplianceContact::new(law.into())),
                dt,
            );
            assert_eq!(n, 1);
            d
        })
        .collect();
    eprintln!("relative deviation from rigid: kelvin {kelvin:?}, hertz-damp {hd:?}");
    for w in kelvin.windows(2).chain(hd.windows(2)) {
        assert!(w[1] < 0.7 * w[0], "{w:?}");
    }
    assert!(kelvin[3] < 0.06 && hd[3] < 0.08, "{kelvin:?} {hd:?}");
    // last decade: Kelvin ∝ k^{-1/2} (factor 0.316), Hertz-damp ∝ k_h^{-2/5} (0.398)
    let (fk, fh) = (kelvin[3] / kelvin[2], hd[3] / hd[2]);
    assert!((fk - 0.316).abs() < 0.08, "{fk}");
    assert!((fh - 0.398).abs() < 0.08, "{fh}");
}

/// Bad model parameters for compliance contacts are errors naming the parameter.
#[test]
fn bad_compliance_parameters_are_errors() {
    use pounding::contact_law::{BilinearImpact, KelvinVoigt};
    use pounding::sim::SimError;
    let e = KelvinVoigt::new(-1.0, 0.0).unwrap_err().to_string();
    assert!(e.contains("k = -1"), "{e}");
    let e = BilinearImpact::new(1e9, 1e8, 0.0).unwrap_err().to_string();
    assert!(e.contains("delta_y"), "{e}");
    let mut cc = ComplianceContact::new(opensees_bilinear());
    cc.friction_velocity = -1.0;
    let m = straight_model(1e6, 1.0, 0.5, 0.05, 0.05, JointContact::Compliance(cc));
    match simulate(
        &SimProblem::at_rest(m, elc180_only()),
        &SimSettings::default(),
    ) {
        Err(SimError::InvalidParameter { name, .. }) => assert_eq!(name, "friction_velocity"),
        other => panic!("{other:?}"),
    }
}

/// Skewed decks (joint face longer than W): the compliance contacts see the whole face, and a
/// stiff Kelvin law gives the rigid run's impact count and nearly its closing.
#[test]
fn skewed_decks_with_a_compliance_law() {
    use pounding::contact_law::KelvinVoigt;
    use pounding::contact_law::calibration::KelvinCalibration;
    use pounding::shape::SkewedDeck;
    let deck = DeckShape::Skewed(SkewedDeck {
        length: 30.0,
        width: 10.0,
        skew: 20f64.to_radians(),
        thickness: 0.5,
        density: 2500.0,
    });
    let mut model = SimModel::with_shapes([deck, deck], 0.05, 2.0e7, 9.0e6, 0.05, 0.5, 0.5, 0.4);
    let settings = SimSettings {
        dt: 5e-4,
        duration: Some(10.0),
        ..SimSettings::default()
    };
    let rigid = simulate(
        &SimProblem::at_rest(model.clone(), el_centro_1940()),
        &settings,
    )
    .unwrap();
    let m = model.masses();
    let law =
        KelvinVoigt::from_restitution(1e11, 0.5, m[0], m[1], KelvinCalibration::Numerical).unwrap();
    model.contact = JointContact::Compliance(ComplianceContact::new(law.into()));
    let comp = simulate(&SimProblem::at_rest(model, el_centro_1940()), &settings).unwrap();
    let (r, c) = (&rigid.summary, &comp.summary);
    eprintln!(
        "skew: rigid {} impacts, closing {}; kelvin {} impacts, closing {}, force {:?}",
        r.impacts,
        r.joints[0].peak_closing,
        c.impacts,
        c.joints[0].peak_closing,
        c.joints[0].peak_contact_force
    );
    assert!(r.impacts >= 1);
    assert_eq!(c.impacts, r.impacts);
    assert!(comp.end_gaps.iter().all(|x| x.is_finite()));
    assert!(c.joints[0].peak_contact_force.unwrap() > 0.0);
    assert!((c.joints[0].peak_closing - r.joints[0].peak_closing).abs() < 2e-3);
}

/// Kelvin's dashpot force jumps at contact onset; on the default bridge one step has no root of
/// the discrete equations and is solved in the closure of the law's graph: no Newton failure, and
/// the discrete energy balance (exact for θ = ½) still holds to rounding.
#[test]
fn kelvin_onset_jump_is_solved_by_the_graph_closure() {
    use pounding::contact_law::KelvinVoigt;
    use pounding::contact_law::calibration::KelvinCalibration;
    let mut model = SimModel::default_bridge();
    let m = model.masses();
    let law =
        KelvinVoigt::from_restitution(1e10, 0.5, m[0], m[1], KelvinCalibration::Numerical).unwrap();
    model.contact = JointContact::Compliance(ComplianceContact::new(law.into()));
    let sol = simulate(
        &SimProblem::at_rest(model, el_centro_1940()),
        &SimSettings {
            history_stride: 100,
            ..SimSettings::default()
        },
    )
    .unwrap();
    eprintln!(
        "kelvin default: closure steps {}, newton failures {}, balance {:e}",
        sol.closure_steps, sol.newton_failures, sol.summary.energy_balance_error
    );
    assert_eq!(sol.status, SimStatus::Completed);
    assert_eq!(sol.newton_failures, 0);
    assert!(sol.closure_steps >= 1);
    assert!(sol.summary.energy_balance_error < 1e-10);
}
