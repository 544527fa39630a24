//! `examples/bridge-p-1d-wave.toml` (the 1-D bridge P on yielding piers, rigid abutments, El
//! Centro 180 travelling along the bridge) against an independent OpenSeesPy 3.7.1 model of the
//! same bridge under `MultipleSupport` excitation: one support node per support line, each
//! driven by the exact displacement, velocity and acceleration of the delayed record
//! (`Transformation` constraints, Newmark average acceleration, dt = 5e-5 s, checked at 2.5e-5 s;
//! its linear version agrees with an exact matrix-exponential solution to 1.4e-7). Figures from
//! that model (not from this code); at 250 m/s they also reproduce, to their quoted digits, the
//! peaks another engineer quoted for this bridge.
//!
//! Contacts make the response after a few seconds chaotic: a peak reached after ~7 s changes by
//! up to 11 % with the time step in either code (and in this one with a 0.06 % change of
//! `v_app`). At 250 m/s every peak falls before 5.6 s and is compared over the whole record;
//! at 125, 500 and 1000 m/s the runs are cut at 7 s and only the peaks OpenSees reaches before
//! then (and that agree between its two time steps) are compared. Impact counts do not
//! converge in either code; they are held to ±3 of OpenSees' at 250 m/s only.

use pounding::sim::bridge::BridgeSolution;
use pounding::sim::scenario::Scenario;

/// `examples/NAME` with its text edited by `edit`, run to completion with a closed balance.
fn run_example(name: &str, edit: impl Fn(String) -> String) -> BridgeSolution {
    let path = format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = edit(std::fs::read_to_string(&path).expect("example"));
    let setup = Scenario::from_toml(&text, &path)
        .expect("reads")
        .build_bridge()
        .expect("builds");
    let sol = pounding::sim::simulate(&setup.problem, &setup.settings).expect("runs");
    assert_eq!(sol.status, pounding::sim::SimStatus::Completed);
    assert!(sol.summary.energy_balance_error < 1e-9);
    sol
}

fn run(v_app: f64, duration: Option<f64>) -> BridgeSolution {
    run_example("bridge-p-1d-wave.toml", |text| {
        assert!(
            text.contains("v_app = 250.0"),
            "the example says v_app = 250"
        );
        let text = text.replace("v_app = 250.0", &format!("v_app = {v_app:.1}"));
        match duration {
            Some(d) => text.replace("[time]\n", &format!("[time]\nduration = {d}\n")),
            None => text,
        }
    })
}

/// One compared peak: its name, this code's value, OpenSees', the relative tolerance.
fn check(name: &str, ours: f64, os: f64, tol: f64, v: f64) {
    let rel = (ours - os).abs() / os.abs();
    assert!(
        rel <= tol,
        "v_app = {v}: {name}: {ours} vs OpenSees {os} ({:.2} %)",
        rel * 100.0
    );
}

/// The peaks of a run: joint forces [MN], abutment forces [MN], pier drifts [m], deck
/// displacements relative to the ground under each deck's start support [m].
fn peaks(s: &BridgeSolution) -> [Vec<f64>; 4] {
    let s = &s.summary;
    [
        s.joints
            .iter()
            .map(|j| j.peak_contact_force.unwrap() / 1e6)
            .collect(),
        s.abutments
            .iter()
            .flatten()
            .map(|a| a.peak_contact_force.unwrap() / 1e6)
            .collect(),
        s.piers.iter().map(|p| p.peak_drift_magnitude).collect(),
        s.segments.iter().map(|g| g.peak_displacement).collect(),
    ]
}

/// 250 m/s, the whole record: forces and closings within 3 %, drifts and displacements within
/// 5 %, impacts within ±3, both piers yield.
#[test]
fn wave_passage_at_250_mps_matches_opensees() {
    let sol = run(250.0, None);
    let [jf, af, drift, deck] = peaks(&sol);
    let s = &sol.summary;
    for (k, os) in [47.96019, 45.05358].into_iter().enumerate() {
        check(&format!("joint {} force", k + 1), jf[k], os, 0.03, 250.0);
    }
    for (k, os) in [0.0252123, 0.0242845].into_iter().enumerate() {
        check(
            &format!("joint {} closing", k + 1),
            s.joints[k].peak_closing,
            os,
            0.03,
            250.0,
        );
    }
    for (k, os) in [48.0086, 40.31371].into_iter().enumerate() {
        check(&format!("abutment {k} force"), af[k], os, 0.03, 250.0);
    }
    for (k, os) in [0.0151914, 0.0155048].into_iter().enumerate() {
        check(&format!("pier {} drift", k + 1), drift[k], os, 0.05, 250.0);
        assert!(s.piers[k].yielded, "pier {} yields", k + 1);
    }
    for (k, os) in [1.2003063, 1.2008077].into_iter().enumerate() {
        let f = s.piers[k].peak_column_force / 1e6;
        check(&format!("pier {} column force", k + 1), f, os, 0.03, 250.0);
    }
    for (k, os) in [0.0843276, 0.1088784, 0.0752032].into_iter().enumerate() {
        check(
            &format!("deck {} displacement", k + 1),
            deck[k],
            os,
            0.05,
            250.0,
        );
    }
    let counts = [
        s.joints[0].impacts,
        s.joints[1].impacts,
        s.abutments[0].as_ref().unwrap().impacts,
        s.abutments[1].as_ref().unwrap().impacts,
    ];
    for (n, os) in counts.into_iter().zip([50, 52, 21, 28]) {
        assert!(
            n.abs_diff(os) <= 3,
            "impacts {counts:?} vs OpenSees [50, 52, 21, 28]"
        );
    }
}

/// A compared peak: which (0 joint force, 1 abutment force, 2 pier drift, 3 deck
/// displacement), its index, OpenSees' value.
type Item = (usize, usize, f64);

/// 125, 500 and 1000 m/s over the first 7 s: the peaks OpenSees reaches by then.
#[test]
fn wave_passage_at_other_velocities_matches_opensees() {
    // (v_app, [(which, index, OpenSees peak)]): which 0 joint force, 1 abutment force, 2 pier
    // drift, 3 deck displacement
    let cases: [(f64, &[Item]); 3] = [
        (
            125.0,
            &[
                (0, 0, 47.39135),
                (0, 1, 50.62604),
                (1, 1, 43.0614),
                (2, 0, 0.01168),
                (2, 1, 0.01207),
                (3, 1, 0.07182),
                (3, 2, 0.07747),
            ],
        ),
        (
            500.0,
            &[
                (0, 1, 43.27798),
                (1, 1, 40.85848),
                (2, 0, 0.0128),
                (2, 1, 0.01321),
                (3, 0, 0.0705),
                (3, 2, 0.06417),
            ],
        ),
        (
            1000.0,
            &[
                (0, 0, 44.41464),
                (0, 1, 43.52065),
                (1, 1, 41.48914),
                (2, 0, 0.01285),
                (2, 1, 0.01414),
            ],
        ),
    ];
    let names = [
        "joint force",
        "abutment force",
        "pier drift",
        "deck displacement",
    ];
    for (v, items) in cases {
        let p = peaks(&run(v, Some(7.0)));
        for &(which, k, os) in items {
            let tol = if which < 2 { 0.03 } else { 0.05 };
            check(&format!("{} {k}", names[which]), p[which][k], os, tol, v);
        }
    }
}

/// The full bridge P (`examples/bridge-piers-1d.toml`: backwalls on backfill and piles) under
/// the same wave at 250 m/s, first 7 s, against the OpenSees model's converged figures
/// (dt = 6.25e-6; in OpenSees the backfill's soil end needs a stiff link to its moving support,
/// else its `HyperbolicGapMaterial` leaves its own law). Forces, closings, backwall and backfill
/// within 3 %, drifts and displacements within 5 %; pier 1 yields, pier 2 does not. Abutment
/// A's contact force is not compared: it is not converged at dt = 5e-5 in either code (OpenSees
/// 37.9 MN at 5e-5, 34.7 MN converged).
#[test]
fn wave_passage_on_the_full_bridge_matches_opensees() {
    let sol = run_example("bridge-piers-1d.toml", |text| {
        assert!(text.contains("scale_y = -1.0\n"));
        text.replace("scale_y = -1.0\n", "scale_y = -1.0\nv_app = 250.0\n")
            .replace("[time]\n", "[time]\nduration = 7.0\n")
    });
    let [jf, _, drift, deck] = peaks(&sol);
    let s = &sol.summary;
    let v = 250.0;
    check("joint 1 force", jf[0], 40.52005, 0.03, v);
    check("joint 2 force", jf[1], 44.11204, 0.03, v);
    check(
        "joint 1 closing",
        s.joints[0].peak_closing,
        0.0228374,
        0.03,
        v,
    );
    check(
        "joint 2 closing",
        s.joints[1].peak_closing,
        0.0239839,
        0.03,
        v,
    );
    let wall = s.abutments[0].as_ref().unwrap().backwall.as_ref().unwrap();
    check("backwall A", wall.peak_displacement, 0.0662746, 0.03, v);
    check(
        "backfill A",
        wall.peak_backfill_force.unwrap() / 1e6,
        4.151492,
        0.03,
        v,
    );
    check(
        "piles A",
        wall.peak_pile_force.unwrap() / 1e6,
        1.071,
        0.03,
        v,
    );
    check("pier 1 drift", drift[0], 0.0179938, 0.05, v);
    check("pier 2 drift", drift[1], 0.0142369, 0.05, v);
    assert!(s.piers[0].yielded && !s.piers[1].yielded);
    check("deck 1", deck[0], 0.1013908, 0.05, v);
    check("deck 3", deck[2], 0.0768684, 0.05, v);
}
