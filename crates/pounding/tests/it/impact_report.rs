//! The impact reports of `pounding::impact_report` (the library side of `pounding impact`).

use pounding::geometry::{ContactCase, SigmaMode};
use pounding::impact_report::{
    AbutmentInput, BridgeInput, DeckSection, JointInput, ReportError, ShapeSpec, abutment_report,
    bridge_report, joint_report, parse_problem, problem_report, to_json_pretty,
};

fn bridge(ratio: Option<f64>) -> BridgeInput {
    BridgeInput {
        r1: 100.0,
        r2: 100.0,
        beta1_deg: 60.0,
        beta2_deg: 60.0,
        width: 10.0,
        thickness: 1.0,
        density: 1.0,
        theta1_deg: -5.0,
        theta2_deg: 2.0,
        case: ContactCase::Deck1Inner,
        mu: 0.5,
        eps: 0.5,
        sigma_mode: SigmaMode::Exact,
        ratio,
        opening: None,
    }
}

/// The report's stick interval and its solved mode agree: a ratio inside `[L, U]` sticks
/// (`γ_T⁺ = 0`), one below `L` slips outward, one above `U` slips inward.
#[test]
fn bridge_report_mode_follows_its_stick_interval() {
    let base = bridge_report(&bridge(None)).unwrap();
    assert!(base.degenerate.is_none() && base.impact.is_none());
    let (l, u) = (base.stick_interval.lower, base.stick_interval.upper);
    assert!(l.is_finite() && u.is_finite() && l < u, "{l} {u}");
    for (r, mode) in [
        (0.5 * (l + u), "stick"),
        (l - 0.5 * (u - l) - 0.1, "slip-outward"),
        (u + 0.5 * (u - l) + 0.1, "slip-inward"),
    ] {
        let rep = bridge_report(&bridge(Some(r))).unwrap();
        let i = rep.impact.as_ref().unwrap();
        assert_eq!(i.mode, Some(mode), "r = {r}");
        assert!(rep.trustworthy());
        // Newton's law on the normal velocity: γ_N⁺ = −ε γ_N⁻ = 0.5 for γ_N⁻ = −1
        if mode == "stick" {
            assert!(i.post.gamma_t.abs() < 1e-9, "{}", i.post.gamma_t);
        }
        assert!(i.energy_change <= 1e-12, "{}", i.energy_change);
    }
}

/// Bad numbers are errors naming the parameter, not reports.
#[test]
fn bridge_report_rejects_bad_rotation_and_ratio() {
    let mut a = bridge(None);
    a.theta1_deg = 95.0;
    let err = bridge_report(&a).unwrap_err().to_string();
    assert!(err.contains("theta1") && err.contains("95"), "{err}");
    let err = bridge_report(&bridge(Some(f64::NAN))).unwrap_err();
    assert!(
        matches!(err, ReportError::InvalidParameter { name: "ratio", .. }),
        "{err}"
    );
}

/// The JSON writer sorts keys, writes undefined numbers as `null` and leaves out absent keys.
#[test]
fn report_json_sorts_keys_and_writes_nan_as_null() {
    let rep = bridge_report(&bridge(None)).unwrap();
    let text = to_json_pretty(&rep).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let keys: Vec<&String> = v.as_object().unwrap().keys().collect();
    let mut sorted = keys.clone();
    sorted.sort();
    assert_eq!(keys, sorted);
    assert!(v.get("ratio").is_none() && v.get("detection").is_none());
    let mut degenerate = rep.clone();
    degenerate.h = f64::NAN;
    let v: serde_json::Value = serde_json::from_str(&to_json_pretty(&degenerate).unwrap()).unwrap();
    assert!(v["h"].is_null());
}

/// Errors of the generic reader name the offending key.
#[test]
fn parse_problem_errors_name_the_key() {
    let ok = r#"{"bodies": [{"name": "a", "mass": 1, "inertia": 1, "position": [0, 0],
        "velocity": [0, -1], "omega": 0}],
        "contacts": [{"body_a": "a", "body_b": null, "point": [0, -1], "normal": [0, 1],
        "mu": 0.3, "restitution": 0.5}]}"#;
    assert!(parse_problem(ok).is_ok());
    for (bad, key) in [
        (
            ok.replace("\"mass\": 1", "\"mass\": \"x\""),
            "bodies[0].mass",
        ),
        (
            ok.replace("\"omega\": 0", "\"omega\": 0, \"spin\": 1"),
            "bodies[0].spin",
        ),
        (ok.replace("[0, 1]", "[0]"), "contacts[0].normal"),
        (ok.replace("\"inertia\": 1, ", ""), "bodies[0].inertia"),
    ] {
        let err = parse_problem(&bad).unwrap_err().to_string();
        assert!(err.contains(key), "{key}: {err}");
    }
    let dup = ok.replace("\"mass\": 1", "\"mass\": 1, \"mass\": 2");
    assert!(matches!(parse_problem(&dup), Err(ReportError::Json(_))));
}

/// Two equal discs in a head-on frictionless impact: momentum is conserved and the post-impact
/// velocities follow Newton's law (independent closed form: v⁺ = ∓ε/2·… for equal masses).
#[test]
fn problem_report_conserves_momentum_in_a_two_body_impact() {
    let text = r#"{"bodies": [
        {"name": "a", "mass": 2, "inertia": 1, "position": [0, 0], "velocity": [1, 0], "omega": 0},
        {"name": "b", "mass": 2, "inertia": 1, "position": [2, 0], "velocity": [-1, 0], "omega": 0}],
        "contacts": [{"body_a": "a", "body_b": "b", "point": [1, 0], "normal": [-1, 0],
        "mu": 0, "restitution": 0.5}]}"#;
    let rep = problem_report(&parse_problem(text).unwrap());
    assert!(rep.trustworthy(), "{}", rep.status);
    let p: f64 = rep.bodies.iter().map(|b| 2.0 * b.velocity[0]).sum();
    assert!(p.abs() < 1e-12, "{p}");
    // equal masses, closing speed 2, ε = 0.5: each rebounds at 0.5
    assert!(
        (rep.bodies[0].velocity[0] + 0.5).abs() < 1e-12,
        "{:?}",
        rep.bodies[0]
    );
    assert!(
        (rep.bodies[1].velocity[0] - 0.5).abs() < 1e-12,
        "{:?}",
        rep.bodies[1]
    );
    assert!(rep.energy.after < rep.energy.before);
    assert_eq!(rep.solutions, Some(1));
}

fn section() -> DeckSection {
    DeckSection {
        width: 10.0,
        thickness: 0.5,
        density: 2500.0,
    }
}

/// The abutment form: both corners of a straight deck strike squarely (no rotation, equal
/// impulses); a ratio needs a single corner; unknown corner names are rejected.
#[test]
fn abutment_report_straight_deck_and_input_checks() {
    let input = AbutmentInput {
        shape: ShapeSpec::Straight { length: 30.0 },
        section: section(),
        mu: 0.0,
        eps: 0.5,
        gap: 0.0,
        corner: "both".into(),
        ratio: None,
        speed: 2.0,
    };
    let rep = abutment_report(&input).unwrap();
    let both = rep.both.as_ref().unwrap();
    assert!(rep.single.is_none() && rep.trustworthy());
    assert!(!both.rotation.rotates, "{}", both.rotation.omega);
    let (a, b) = (
        both.contacts[0].normal_impulse,
        both.contacts[1].normal_impulse,
    );
    assert!((a - b).abs() <= 1e-9 * a.abs(), "{a} {b}");
    // rebound at ε·v along the axis
    let v = both.post.velocity;
    assert!(
        ((v[0] * v[0] + v[1] * v[1]).sqrt() - 1.0).abs() < 1e-9,
        "{v:?}"
    );
    let err = abutment_report(&AbutmentInput {
        ratio: Some(0.1),
        ..input.clone()
    })
    .unwrap_err();
    assert!(matches!(
        err,
        ReportError::InvalidParameter { name: "ratio", .. }
    ));
    let err = abutment_report(&AbutmentInput {
        corner: "acute".into(),
        ..input
    })
    .unwrap_err()
    .to_string();
    assert!(err.contains("corner") && err.contains("acute"), "{err}");
}

/// The joint form: equal straight decks, deck 1 at 1 m/s: momentum conserved along the axis;
/// a curved shape is refused (it is the bridge form).
#[test]
fn joint_report_conserves_momentum() {
    let input = JointInput {
        shape: ShapeSpec::Straight { length: 30.0 },
        section: section(),
        length2: None,
        mu: 0.2,
        eps: 0.5,
        speed: 1.0,
    };
    let rep = joint_report(&input).unwrap();
    assert!(rep.trustworthy());
    let p = |k: usize| -> [f64; 2] {
        let d = &rep.decks[0];
        let e = &rep.decks[1];
        if k == 0 {
            [
                d.mass * d.velocity_pre[0] + e.mass * e.velocity_pre[0],
                d.mass * d.velocity_pre[1] + e.mass * e.velocity_pre[1],
            ]
        } else {
            [
                d.mass * d.velocity[0] + e.mass * e.velocity[0],
                d.mass * d.velocity[1] + e.mass * e.velocity[1],
            ]
        }
    };
    let (before, after) = (p(0), p(1));
    let scale = before[0].abs().max(before[1].abs());
    for k in 0..2 {
        assert!(
            (before[k] - after[k]).abs() <= 1e-9 * scale,
            "{before:?} {after:?}"
        );
    }
    let err = joint_report(&JointInput {
        shape: ShapeSpec::Curved {
            radius: 100.0,
            angle_deg: 60.0,
        },
        ..input
    })
    .unwrap_err();
    assert!(matches!(
        err,
        ReportError::InvalidParameter { name: "shape", .. }
    ));
}
