//! `pounding impact`: bridge form, generic form, bad input.

use crate::pounding;
use serde_json::Value;

const BASE: [(&str, &str); 9] = [
    ("--r1", "100"),
    ("--r2", "100"),
    ("--beta1", "60"),
    ("--beta2", "60"),
    ("--theta1", "-5"),
    ("--theta2", "2"),
    ("--case", "deck1-inner"),
    ("--mu", "0.5"),
    ("--eps", "0.5"),
];

/// Runs the bridge form with `BASE` overridden by `over` (and extra flags).
fn bridge(over: &[(&str, &str)], extra: &[&str]) -> std::process::Output {
    let mut cmd = pounding();
    cmd.arg("impact");
    for (k, v) in BASE {
        let v = over.iter().find(|(o, _)| *o == k).map_or(v, |(_, v)| *v);
        cmd.arg(k).arg(v);
    }
    for (k, v) in over {
        if !BASE.iter().any(|(b, _)| b == k) {
            cmd.arg(k).arg(v);
        }
    }
    cmd.args(extra).output().unwrap()
}

fn json_of(out: &std::process::Output) -> Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Spec §15 row 1 at ρt = 1, plus the mode at three ratios.
#[test]
fn bridge_json_reproduces_spec_row() {
    let unit = [("--thickness", "1"), ("--density", "1")];
    let v = json_of(&bridge(&unit, &["--json"]));
    assert_eq!(v["degenerate"], Value::Null);
    assert_eq!(v["first_contact"], Value::Bool(true));
    assert_eq!(v["end_closes"], Value::Bool(true));
    assert!(rel(f(&v["sigma"]), 4.984009614) < 1e-9);
    assert!(rel(f(&v["delassus"]["nn"]), 2.784789492e-03) < 1e-8);
    assert!(rel(f(&v["delassus"]["nt"]), 2.022511840e-03) < 1e-8);
    assert!(rel(f(&v["delassus"]["tt"]), 6.619671336e-03) < 1e-8);
    assert!(rel(f(&v["stick_interval"]["lower"]), -1.088778793) < 1e-8);
    assert!(rel(f(&v["stick_interval"]["upper"]), 2.107066801) < 1e-8);
    assert!(rel(f(&v["kappa"]), 2.022511840 / 2.784789492) < 1e-8);
    let d = &v["decks"][0];
    assert!(rel(f(&d["area"]), 1047.197551) < 1e-9 && rel(f(&d["inertia"]), 9.329367e5) < 1e-6);
    assert!(rel(f(&d["centroid_radius"]), 95.572543) < 1e-8);
    assert_eq!(f(&d["mass"]), f(&d["area"]));
    assert!(v.get("mode").is_none(), "no --ratio, no impact fields");
    // default ρ t = 2500·0.5: G scales as 1/(ρt), the bounds do not
    let w = json_of(&bridge(&[], &["--json"]));
    assert!(rel(f(&w["delassus"]["nn"]) * 1250.0, f(&v["delassus"]["nn"])) < 1e-12);
    for k in ["lower", "upper"] {
        assert!(rel(f(&w["stick_interval"][k]), f(&v["stick_interval"][k])) < 1e-12);
    }
    for (r, mode) in [
        ("-3", "slip-outward"),
        ("0.5", "stick"),
        ("4", "slip-inward"),
    ] {
        let x = json_of(&bridge(&unit, &["--json", "--ratio", r]));
        assert_eq!(x["mode"], Value::from(mode), "r = {r}");
        assert_eq!(x["status"], Value::from("solved"));
        assert!((f(&x["post"]["gamma_n"]) - 0.5).abs() < 1e-12);
        assert!(f(&x["impulse"]["normal"]) > 0.0);
        let dt = f(&x["energy_change"]);
        let (gn, gt) = (f(&x["post"]["gamma_n"]), f(&x["post"]["gamma_t"]));
        let r: f64 = r.parse().unwrap();
        let expect = 0.5
            * ((gn - 1.0) * f(&x["impulse"]["normal"]) + (gt - r) * f(&x["impulse"]["tangential"]));
        assert!((dt - expect).abs() < 1e-9 * dt.abs());
        assert!(dt < 0.0);
    }
}

#[test]
fn bridge_degenerate_and_infinite_bounds_are_null() {
    let v = json_of(&bridge(
        &[("--theta1", "3"), ("--theta2", "3")],
        &["--json", "--ratio", "1"],
    ));
    assert_eq!(v["degenerate"], Value::from("parallel-faces"));
    assert_eq!(v["first_contact"], Value::Bool(false));
    for k in ["sigma", "kappa", "varrho", "mode", "energy_change"] {
        assert_eq!(v[k], Value::Null, "{k}");
    }
    assert_eq!(v["delassus"]["nn"], Value::Null);
    assert_eq!(v["stick_interval"]["lower"], Value::Null);
    let v = json_of(&bridge(
        &[("--theta1", "3"), ("--theta2", "-3")],
        &["--json"],
    ));
    assert_eq!(v["degenerate"], Value::from("corner-corner"));
    // Painlevé-type regime μ G_NT ≥ G_NN: L = −∞ → null, stick for any r below U
    let v = json_of(&bridge(&[("--mu", "5")], &["--json", "--ratio", "-100"]));
    assert_eq!(v["stick_interval"]["lower"], Value::Null);
    assert!(f(&v["stick_interval"]["upper"]).is_finite());
    assert_eq!(v["painleve"], Value::Bool(true));
    assert_eq!(v["mode"], Value::from("stick"));
    assert!(matches!(
        v["status"].as_str(),
        Some("solved" | "solved-by-fallback")
    ));
}

#[test]
fn bridge_readable_summary() {
    let out = bridge(&[("--sigma-mode", "end")], &["--ratio", "0.5"]);
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "deck1-inner",
        "first contact: true",
        "stick interval",
        "stick (solved)",
        "σ mode end",
    ] {
        assert!(s.contains(needle), "summary lacks {needle:?}:\n{s}");
    }
}

#[test]
fn bridge_bad_input_names_the_parameter() {
    for (over, name) in [
        (("--r1", "4"), "R1"),
        (("--r2", "nan"), "R2"),
        (("--beta1", "0"), "beta1"),
        (("--beta2", "400"), "beta2"),
        (("--mu", "-0.1"), "mu"),
        (("--eps", "1.5"), "eps"),
        (("--eps", "NaN"), "eps"),
        (("--theta1", "95"), "theta1"),
        (("--theta2", "inf"), "theta2"),
        (("--case", "deck3-inner"), "case"),
        (("--sigma-mode", "middle"), "sigma-mode"),
        (("--width", "-1"), "width"),
        (("--thickness", "0"), "thickness"),
        (("--density", "nan"), "density"),
        (("--ratio", "nan"), "ratio"),
        (("--r1", "abc"), "--r1"),
    ] {
        let out = bridge(&[over], &[]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{over:?} accepted");
        assert!(err.contains(name), "{over:?}: error {err:?} lacks {name}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // a missing bridge argument
    let out = pounding().args(["impact", "--r1", "100"]).output().unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--r2"));
}

/// Writes `text` to `name` in a fresh scratch directory: (its guard, the file's path).
fn write_tmp(name: &str, text: &str) -> (crate::Scratch, std::path::PathBuf) {
    let dir = crate::scratch_dir("cli-impact", name);
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    (dir, p)
}

/// The spinning disc on a rough floor through the generic form (closed form as in the library test).
#[test]
fn generic_form_disc_on_rough_floor() {
    let (m, rho, vx, vy, w, mu, eps) = (2.0f64, 0.3f64, 1.0f64, -2.0f64, 40.0f64, 0.2f64, 0.5f64);
    let text = format!(
        r#"{{"bodies": [{{"name": "disc", "mass": {m}, "inertia": {i}, "position": [0, {rho}],
             "velocity": [{vx}, {vy}], "omega": {w}}}],
           "contacts": [{{"body_a": "disc", "body_b": null, "point": [0, 0], "normal": [0, 1],
             "mu": {mu}, "restitution": {eps}}}]}}"#,
        i = 0.5 * m * rho * rho
    );
    let (_dir, p) = write_tmp("disc.json", &text);
    let v = json_of(
        &pounding()
            .args(["impact", "--json", "--problem"])
            .arg(&p)
            .output()
            .unwrap(),
    );
    let ln = -(1.0 + eps) * m * vy;
    let s = vx + w * rho; // 13 > 3μ(1+ε)|v_y| = 1.8: slides
    let fx = -mu * ln * s.signum();
    assert_eq!(v["status"], Value::from("solved"));
    assert_eq!(v["solutions"], Value::from(1));
    let c = &v["contacts"][0];
    assert_eq!(c["mode"], Value::from("slip-negative"));
    assert!((f(&c["normal_impulse"]) - ln).abs() < 1e-12);
    assert!((f(&c["tangential_impulse"]) + fx).abs() < 1e-12);
    let b = &v["bodies"][0];
    assert_eq!(b["name"], Value::from("disc"));
    assert!((f(&b["velocity"][0]) - (vx + fx / m)).abs() < 1e-12);
    assert!((f(&b["velocity"][1]) + eps * vy).abs() < 1e-12);
    assert!((f(&b["omega"]) - (w + rho * fx / (0.5 * m * rho * rho))).abs() < 1e-9);
    assert!(f(&v["energy"]["after"]) < f(&v["energy"]["before"]));
    // readable summary
    let out = pounding()
        .args(["impact", "--problem"])
        .arg(&p)
        .output()
        .unwrap();
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(
        s.contains("slip-negative") && s.contains("kinetic energy"),
        "{s}"
    );
}

/// Two decks with parallel faces touching at both corners: solutions > 1 (tangential split not
/// unique), post-impact velocities unique.
#[test]
fn generic_form_double_contact() {
    let text = r#"{"bodies": [
        {"name": "deck1", "mass": 1047.2, "inertia": 932936.7, "position": [17.232, 47.786], "velocity": [0.5, -1.0], "omega": 0.0},
        {"name": "deck2", "mass": 1047.2, "inertia": 932936.7, "position": [-17.232, -47.786], "velocity": [0, 0], "omega": 0.0}],
      "contacts": [
        {"body_a": "deck1", "body_b": "deck2", "point": [5, 0], "normal": [0, 1], "mu": 1.0, "restitution": 0.5},
        {"body_a": "deck1", "body_b": "deck2", "point": [-5, 0], "normal": [0, 1], "mu": 1.0, "restitution": 0.5}]}"#;
    let (_dir, p) = write_tmp("double.json", text);
    let v = json_of(
        &pounding()
            .args(["impact", "--json", "--problem"])
            .arg(&p)
            .output()
            .unwrap(),
    );
    assert_eq!(v["status"], Value::from("solved"));
    assert!(v["solutions"].as_u64().unwrap() > 1, "{v}");
    assert_eq!(v["post_velocity_unique"], Value::Bool(true));
    assert_eq!(v["impulse_unique"], Value::Bool(false));
    for c in v["contacts"].as_array().unwrap() {
        assert_eq!(c["mode"], Value::from("stick"));
    }
}

#[test]
fn generic_bad_input_names_the_parameter() {
    let good_body = r#"{"name": "a", "mass": 1, "inertia": 1, "position": [0, 0], "velocity": [0, -1], "omega": 0}"#;
    let contact = |over: &str| {
        format!(
            r#"{{"bodies": [{good_body}], "contacts": [{{"body_a": "a", "body_b": null, "point": [0, 0], {over}}}]}}"#
        )
    };
    for (text, name) in [
        (contact(r#""normal": [0, 0], "mu": 0.5, "restitution": 0.5"#), "contacts[0].normal"),
        (contact(r#""normal": [0, 1], "mu": -1, "restitution": 0.5"#), "contacts[0].mu"),
        (contact(r#""normal": [0, 1], "mu": 0.5, "restitution": 2"#), "contacts[0].restitution"),
        (contact(r#""normal": [0, 1], "mu": null, "restitution": 0.5"#), "contacts[0].mu"),
        (contact(r#""normal": [0, 1], "restitution": 0.5"#), "contacts[0].mu"),
        (contact(r#""normal": [0, 1], "mu": 0.5, "restitution": 0.5, "extra": 1"#), "contacts[0].extra"),
        (
            format!(r#"{{"bodies": [{good_body}], "contacts": [{{"body_b": null, "point": [0, 0], "normal": [0, 1], "mu": 0.5, "restitution": 0.5}}]}}"#),
            "contacts[0].body_a",
        ),
        (
            format!(r#"{{"bodies": [{good_body}], "contacts": [{{"body_a": "zz", "body_b": null, "point": [0, 0], "normal": [0, 1], "mu": 0.5, "restitution": 0.5}}]}}"#),
            "contacts[0].body_a",
        ),
        (
            r#"{"bodies": [{"mass": 1, "inertia": 1, "position": [0, 0], "velocity": [0, 0], "omega": 0}], "contacts": []}"#.to_string(),
            "bodies[0].name",
        ),
        (
            r#"{"bodies": [{"name": "a", "mass": -1, "inertia": 1, "position": [0, 0], "velocity": [0, 0], "omega": 0}], "contacts": []}"#.to_string(),
            "bodies[0].mass",
        ),
        ("{\"bodies\": [], \"contacts\": [".to_string(), "not valid JSON"),
        ("{\"contacts\": []}".to_string(), "bodies"),
    ] {
        let (_dir, p) = write_tmp("bad.json", &text);
        let out = pounding().args(["impact", "--json", "--problem"]).arg(&p).output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{text} accepted");
        assert!(err.contains(name), "{text}: error {err:?} lacks {name}");
        assert!(!err.contains("panicked"));
    }
    let out = pounding()
        .args(["impact", "--problem", "/nonexistent/problem.json"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--problem"));
}

/// Contact detection at an opening (spec §5.5): h ≈ 0.6097 m for θ = (−5°, 2°).
#[test]
fn bridge_contact_detection_at_an_opening() {
    let v = json_of(&bridge(&[("--opening", "1.0")], &["--json"]));
    let d = &v["detection"];
    assert_eq!(d["first_contact_case"], Value::from("deck1-inner"));
    assert!((f(&d["closing_distance"]) - (1.0 - f(&v["h"]))).abs() < 1e-12);
    assert_eq!(d["overlap"], Value::Null);
    let v = json_of(&bridge(&[("--opening", "0.05")], &["--json"]));
    assert!((f(&v["detection"]["overlap"]) - (f(&v["h"]) - 0.05)).abs() < 1e-12);
    let out = bridge(&[("--opening", "nan")], &[]);
    assert!(!out.status.success() && String::from_utf8_lossy(&out.stderr).contains("opening"));
}

/// `normal` is a direction: a non-unit normal gives the same impulses as the unit one, and the
/// output echoes the unit normal and tangent the impulses are measured along (nothing silent).
#[test]
fn generic_form_normal_is_a_direction_and_is_echoed() {
    let run = |normal: &str, name: &str| {
        let text = format!(
            r#"{{"bodies": [{{"name": "disc", "mass": 2, "inertia": 0.09, "position": [0, 0.3],
                 "velocity": [1, -2], "omega": 40}}],
               "contacts": [{{"body_a": "disc", "body_b": null, "point": [0, 0], "normal": {normal},
                 "mu": 0.2, "restitution": 0.5}}]}}"#
        );
        let (_dir, p) = write_tmp(name, &text);
        json_of(
            &pounding()
                .args(["impact", "--json", "--problem"])
                .arg(&p)
                .output()
                .unwrap(),
        )
    };
    let unit = run("[0, 1]", "unit.json");
    let long = run("[0, 3]", "long.json");
    assert_eq!(unit, long);
    let c = &long["contacts"][0];
    assert_eq!(c["normal"], serde_json::json!([0.0, 1.0]));
    assert_eq!(c["tangent"], serde_json::json!([-1.0, 0.0]));
    // an oblique direction: echoed at unit length
    let oblique = run("[3, 4]", "oblique.json");
    let n = &oblique["contacts"][0]["normal"];
    assert!((f(&n[0]) - 0.6).abs() < 1e-15 && (f(&n[1]) - 0.8).abs() < 1e-15);
}
