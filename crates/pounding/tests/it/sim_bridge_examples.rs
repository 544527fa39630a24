//! The shipped bridge examples (issue 11 acceptance): `examples/viaduct-1d.toml` against the
//! OpenSees 3.7.1 figures quoted in issue 11 (zeroLength elements, Steel01 bearings,
//! ImpactMaterial contacts, ElasticPPGap restrainers, Newmark average acceleration, dt = 1e-4,
//! converged against 5e-5), the five-segment curved example's energy balance, and the limit of
//! a compliance law as its stiffness grows (N = 3) toward the rigid law.

use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

const VIADUCT_1D: &str = include_str!("../../../../examples/viaduct-1d.toml");
const VIADUCT_RIGID_1D: &str = include_str!("../../../../examples/viaduct-rigid-1d.toml");
const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");

fn run(text: &str, name: &str) -> BridgeSolution {
    let sol = Scenario::from_toml(text, name)
        .unwrap()
        .build_bridge()
        .unwrap()
        .run()
        .unwrap();
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed, "{name}");
    sol
}

fn within(what: &str, ours: f64, reference: f64, rel: f64) {
    let e = (ours - reference).abs() / reference.abs();
    assert!(
        e <= rel,
        "{what}: {ours} vs OpenSees {reference} ({:.1} % > {:.0} %)",
        e * 100.0,
        rel * 100.0
    );
}

/// OpenSees figures of issue 11: per joint (impacts, peak force N, peak closing m, restrainer
/// peak N), per abutment (impacts, peak force N), peak displacements m. (An independent
/// OpenSeesPy 3.7.1 model of the same bridge reproduces them; its restrainer peaks are not yet
/// converged at dt = 1e-4 — 0.562, 0.573, 0.609, 0.607 MN for restrainer 2 at dt = 1e-4, 5e-5,
/// 2.5e-5, 1.25e-5 — so they are compared at the same dt and the same integrator order.)
const OS_JOINTS: [(usize, f64, f64, f64); 2] = [
    (17, 37.48e6, 0.0224, 0.583e6),
    (20, 40.10e6, 0.0227, 0.562e6),
];
const OS_ABUTMENTS: [(usize, f64); 2] = [(7, 41.10e6), (7, 40.66e6)];
const OS_DISPLACEMENTS: [f64; 3] = [0.0430, 0.0609, 0.0713];

#[test]
fn viaduct_1d_matches_opensees() {
    let sol = run(VIADUCT_1D, "viaduct-1d.toml");
    let s = &sol.summary;
    for (k, (imp, f, c, _)) in OS_JOINTS.iter().enumerate() {
        let j = &s.joints[k];
        assert!(
            j.impacts.abs_diff(*imp) <= 2,
            "joint {} impacts {} vs {imp}",
            k + 1,
            j.impacts
        );
        within(
            &format!("joint {} peak force", k + 1),
            j.peak_contact_force.unwrap(),
            *f,
            0.03,
        );
        within(
            &format!("joint {} peak closing", k + 1),
            j.peak_closing,
            *c,
            0.03,
        );
    }
    for (k, j) in s.joints.iter().enumerate() {
        let what = format!("joint {} restrainer peak", k + 1);
        within(
            &what,
            j.restrainer_peak_force.unwrap(),
            OS_JOINTS[k].3,
            0.10,
        );
    }
    for (side, (imp, f)) in OS_ABUTMENTS.iter().enumerate() {
        let a = s.abutments[side].as_ref().unwrap();
        assert!(
            a.impacts.abs_diff(*imp) <= 2,
            "abutment {side} impacts {} vs {imp}",
            a.impacts
        );
        within(
            &format!("abutment {side} peak force"),
            a.peak_contact_force.unwrap(),
            *f,
            0.03,
        );
    }
    for (i, d) in OS_DISPLACEMENTS.iter().enumerate() {
        within(
            &format!("segment {} peak displacement", i + 1),
            s.segments[i].peak_displacement,
            *d,
            0.05,
        );
    }
    // the bearings yield (hysteretic energy) and the energy balance closes
    assert!(s.segments.iter().all(|g| g.hysteretic_energy > 0.0));
    assert!(s.energy_balance_error < 1e-9, "{}", s.energy_balance_error);
    assert!(s.joints.iter().all(|j| j.restrainer_engagements > 0));
}

/// The five-segment curved viaduct under both El Centro components: the bridge turns and slides
/// in plan, restrainers engage, and the discrete energy balance closes to 1e-9 relative.
#[test]
fn curved_five_segment_viaduct_closes_its_energy_balance() {
    let sol = run(CURVED_5, "viaduct-curved-5.toml");
    let s = &sol.summary;
    assert_eq!(s.segments.len(), 5);
    assert!(s.energy_balance_error < 1e-9, "{}", s.energy_balance_error);
    assert!(s.impacts > 0);
    assert!(s.joints.iter().any(|j| j.restrainer_engagements > 0));
    assert!(
        s.segments.iter().all(|g| g.peak_rotation > 0.0),
        "curved segments turn"
    );
    assert_eq!(sol.lcp_failures, 0);
}

/// N = 3: a Kelvin law calibrated to the same restitution (0.6) tends to the rigid law as its
/// stiffness grows: the peak displacements and openings approach the rigid run's (first 4 s,
/// k = 1e10, 1e11, 1e12 N/m).
#[test]
fn compliance_law_tends_to_the_rigid_law_as_its_stiffness_grows() {
    let base =
        VIADUCT_RIGID_1D.replace("history_every = 100", "history_every = 100\nduration = 4.0");
    let rigid = run(&base, "rigid");
    let peaks = |s: &BridgeSolution| -> Vec<f64> {
        let mut v: Vec<f64> = s
            .summary
            .segments
            .iter()
            .map(|g| g.peak_displacement)
            .collect();
        v.extend(s.summary.joints.iter().map(|j| j.peak_opening));
        v
    };
    let r = peaks(&rigid);
    let mut errors = Vec::new();
    for k in [1e10, 1e11, 1e12] {
        let text = format!("{base}\n[contact]\nlaw = \"kelvin\"\nk = {k:e}\nrestitution = 0.6\n");
        let sol = run(&text, "kelvin");
        let e = peaks(&sol)
            .iter()
            .zip(&r)
            .map(|(a, b)| (a - b).abs() / b)
            .fold(0.0f64, f64::max);
        errors.push(e);
    }
    // the penetration, and with it the difference, shrinks like sqrt(m / k)
    assert!(errors[2] < errors[1] && errors[1] < errors[0], "{errors:?}");
    assert!(errors[2] < 0.02, "{errors:?}");
}
