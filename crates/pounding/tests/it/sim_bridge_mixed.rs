//! Rigid and compliance contact sites in one bridge ([`pounding::sim`]'s mixed stepper): the
//! three-segment viaduct with rigid joints and compliance-law abutments runs, its energy balance
//! closes, and as the abutments stiffen it tends to the all-rigid run.

use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::{BridgeSetup, Scenario};
use pounding::sim::simulate;
use pounding::sim::{SimContact, SimStatus};

/// `examples/viaduct-rigid-1d.toml` with `abut` appended (each abutment's `contact` table),
/// over `duration` seconds.
fn viaduct(abut: &str, duration: f64) -> BridgeSetup {
    let root = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{root}/../../examples/viaduct-rigid-1d.toml"))
        .unwrap()
        .replace(
            "history_every = 100",
            &format!("history_every = 10\nduration = {duration}"),
        );
    let text = format!("{text}\n{abut}");
    Scenario::from_toml(&text, "viaduct-mixed.toml")
        .and_then(|s| s.build_bridge())
        .unwrap_or_else(|e| panic!("{e}"))
}

fn run(setup: &BridgeSetup) -> BridgeSolution {
    simulate(&setup.problem, &setup.settings).unwrap()
}

/// The contact tables of both abutments with the law text `law`.
fn abutments(law: &str) -> String {
    format!("[abutment.start.contact]\n{law}\n[abutment.end.contact]\n{law}\n")
}

/// The bilinear impact law of `examples/viaduct-1d.toml` at both abutments, rigid joints.
#[test]
fn rigid_joints_with_bilinear_abutments_run_with_a_closed_energy_balance() {
    let bilinear = "law = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3";
    let sol = run(&viaduct(&abutments(bilinear), 20.0));
    assert_eq!(sol.status, SimStatus::Completed);
    let s = &sol.summary;
    assert!(
        s.energy_balance_error < 1e-9,
        "energy balance {:e}",
        s.energy_balance_error
    );
    // both kinds act: rigid joint impacts (impulses, no force) and abutment contact forces
    let joint_impacts: usize = s.joints.iter().map(|j| j.impacts).sum();
    let abut = s
        .abutments
        .iter()
        .flatten()
        .map(|a| a.impacts)
        .sum::<usize>();
    assert!(joint_impacts > 0 && abut > 0, "{joint_impacts} {abut}");
    assert!(s.joints.iter().all(|j| j.peak_contact_force.is_none()));
    for a in s.abutments.iter().flatten() {
        assert!(a.peak_contact_force.is_some());
    }
    let pulses = |abutment: bool| {
        sol.impacts
            .iter()
            .filter(|r| matches!(r.contact, SimContact::Abutment { .. }) == abutment)
            .map(|r| r.pulse.is_some())
            .collect::<Vec<_>>()
    };
    assert!(
        pulses(true).iter().all(|&p| p),
        "abutment records carry force pulses"
    );
    assert!(
        pulses(false).iter().all(|&p| !p),
        "joint records are impulses"
    );
    assert_eq!(sol.newton_failures, 0);
}

/// Kelvin abutments calibrated to the same restitution (0.6) as the rigid abutments: as their
/// stiffness grows from 1e9 to 1e11 N/m the response tends to the all-rigid run (a linear
/// spring–dashpot's restitution does not depend on its stiffness, so the limit is the rigid
/// impact with the same ε).
#[test]
fn stiffening_compliance_abutments_tend_to_the_all_rigid_run() {
    let dur = 8.0;
    let rigid = run(&viaduct("", dur));
    let peak = |s: &BridgeSolution| -> Vec<f64> {
        let mut v: Vec<f64> = s.summary.joints.iter().map(|j| j.peak_closing).collect();
        v.extend(s.summary.segments.iter().map(|g| g.peak_displacement));
        v
    };
    let reference = peak(&rigid);
    let mut errors = Vec::new();
    for k in [1e9, 1e10, 1e11] {
        let law = format!("law = \"kelvin\"\nk = {k:e}\ncalibration = \"numerical\"");
        let sol = run(&viaduct(&abutments(&law), dur));
        assert_eq!(sol.status, SimStatus::Completed, "k = {k:e}");
        assert!(sol.summary.energy_balance_error < 1e-9, "k = {k:e}");
        let err = peak(&sol)
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs() / b.abs())
            .fold(0.0f64, f64::max);
        errors.push(err);
    }
    assert!(
        errors[2] < errors[0] && errors[2] < 0.05,
        "relative differences to the rigid run: {errors:?}"
    );
}

/// The time-step advice of a bridge whose compliance sites differ is that of the site the step
/// resolves worst, each with its own law and mass: soft Kelvin joints (1e9 N/m between
/// 1.2e6/0.8e6 kg segments: `T_c` = π √(4.8e5 / 1e9) ≈ 69 ms) and stiff Kelvin abutments
/// (1e13 N/m against the 1.0e6 and 0.8e6 kg end segments alone): the end abutment's
/// `T_c = π √(0.8e6 / 1e13)` ≈ 0.89 ms, 8.9 steps of 1e-4 s, not adequate (it once took the
/// first site's law at the joints' smallest mass pair: 688 steps, "adequate").
#[test]
fn the_time_step_advice_is_the_worst_compliance_site() {
    let text = "[contact]\nlaw = \"kelvin\"\nk = 1e9\nrestitution = 0.6\n";
    let stiff = abutments("law = \"kelvin\"\nk = 1e13");
    let sol = run(&viaduct(&format!("{text}{stiff}"), 0.5));
    let a = sol.time_step_advice.expect("compliance sites give advice");
    let expected = std::f64::consts::PI * (0.8e6_f64 / 1e13).sqrt();
    assert!(
        (a.contact_duration - expected).abs() < 1e-12 * expected,
        "T_c {} s, expected {expected} s (the end abutment's)",
        a.contact_duration
    );
    assert!((a.steps_per_contact - expected / 1e-4).abs() < 1e-9);
    assert!(!a.adequate, "{a:?}");
}

/// Why the bilinear abutments do not tend to the all-rigid run (restitution 0.6) as they
/// stiffen: the bilinear law dissipates only past its yield penetration `δy`, which the scaled
/// law keeps, while a stiffer contact penetrates less (`δ_max ≈ v √(m/K1)`), so the impact turns
/// elastic. The isolated collision of the viaduct's end segment (1.0e6 kg) at 0.5 m/s against
/// an equal mass with the law of `examples/viaduct-1d.toml` scaled by 1, 10, 100: its
/// restitution is about 0.92 at ×1 (it barely yields) and rises to 1 (elastic: below `δy`, the
/// law is one spring), never approaching 0.6.
#[test]
fn a_stiffening_bilinear_law_tends_to_an_elastic_impact_not_to_restitution_0_6() {
    use pounding::contact_law::collision::{CollisionSettings, TwoMassImpact, simulate_collision};
    use pounding::contact_law::{BilinearImpact, ContactLaw};
    let e = |s: f64| {
        let law: ContactLaw = BilinearImpact::new(1.5586e10 * s, 3.1328e9 * s, 2.54e-3)
            .unwrap()
            .into();
        let p = TwoMassImpact::new(1.0e6, 1.0e6, 0.5, 0.0).unwrap();
        let r = simulate_collision(&law, &p, &CollisionSettings::default()).unwrap();
        (r.restitution, r.peak_penetration)
    };
    let (e1, d1) = e(1.0);
    let (e10, _) = e(10.0);
    let (e100, d100) = e(100.0);
    assert!(d1 > 2.54e-3 && e1 < 0.95, "yields at ×1: e {e1}, δ {d1}");
    assert!(e1 > 0.9, "far from 0.6 already at ×1: e {e1}");
    assert!(e10 > e1, "stiffer, less dissipation: {e1} -> {e10}");
    assert!(d100 < 2.54e-3, "no yield at ×100: δ {d100}");
    assert!((e100 - 1.0).abs() < 1e-6, "elastic at ×100: e {e100}");
}
