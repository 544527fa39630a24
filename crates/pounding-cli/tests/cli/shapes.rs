//! `pounding impact --shape straight|skew|curved --abutment`: deck against a rigid abutment.
//!
//! Expected values are computed here from closed forms (parallelogram mass properties, corner lever
//! arms, spec §9 bounds, the frictionless double-impact solution), independently of the library.

use crate::pounding;
use serde_json::Value;

fn run(args: &[&str]) -> std::process::Output {
    pounding().arg("impact").args(args).output().unwrap()
}

fn json_of(args: &[&str]) -> Value {
    let mut a = args.to_vec();
    a.push("--json");
    let out = run(&a);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// Parallelogram (ρt = 1): mass, inertia and the far-face lever arms `A_k = r_k × n`,
/// `B = r × t` (`n = (0, −1)`, `t = (1, 0)`).
fn skew_closed_form(l: f64, w: f64, deg: f64) -> (f64, f64, [f64; 2], f64) {
    let (s, c) = deg.to_radians().sin_cos();
    let m = l * w;
    let i = m * (l * l + w * w / (c * c)) / 12.0;
    let a = [w / (2.0 * c) + l / 2.0 * s, l / 2.0 * s - w / (2.0 * c)];
    (m, i, a, -l / 2.0 * c)
}

/// Rotation about the obtuse corner iff sin 2θ_s > 2W/L (frictionless, longitudinal approach, both
/// corners striking), on both sides of the threshold θ* = ½ asin(2W/L) = 20.905° for L = 30, W = 10;
/// the post-impact ω equals the single-contact closed form when rotating and vanishes otherwise.
#[test]
fn skew_rotation_condition_by_the_cli() {
    let (l, w) = (30.0, 10.0);
    let threshold = 0.5 * (2.0f64 * w / l).asin().to_degrees();
    assert!((threshold - 20.905).abs() < 1e-3);
    for (deg, eps) in [
        (20.0, 0.0),
        (22.0, 0.0),
        (20.5, 0.7),
        (21.5, 0.7),
        (45.0, 1.0),
        (10.0, 1.0),
    ] {
        let above = (2.0 * f64::to_radians(deg)).sin() > 2.0 * w / l;
        assert_eq!(above, deg > threshold);
        let (ds, es) = (deg.to_string(), eps.to_string());
        let v = json_of(&[
            "--shape",
            "skew",
            "--length",
            "30",
            "--width",
            "10",
            "--skew",
            &ds,
            "--abutment",
            "--mu",
            "0",
            "--eps",
            &es,
            "--speed",
            "2",
            "--thickness",
            "1",
            "--density",
            "1",
        ]);
        let rot = &v["rotation"];
        assert_eq!(rot["condition_holds"], Value::Bool(above), "{deg}");
        assert_eq!(rot["rotates"], Value::Bool(above), "{deg}: {rot}");
        let (m, i, a, _) = skew_closed_form(l, w, deg);
        assert!(rel(f(&v["deck"]["mass"]), m) < 1e-12);
        assert!(rel(f(&v["deck"]["inertia"]), i) < 1e-12);
        let n0 = 2.0 * deg.to_radians().cos();
        let omega = f(&v["post"]["omega"]);
        if above {
            assert_eq!(rot["pivot"], "obtuse");
            assert_eq!(rot["predicted_pivot"], "obtuse");
            assert_eq!(v["contacts"][0]["mode"], "open");
            let lam = (1.0 + eps) * n0 / (1.0 / m + a[1] * a[1] / i);
            assert!(rel(f(&v["contacts"][1]["normal_impulse"]), lam) < 1e-9);
            assert!(rel(omega, a[1] * lam / i) < 1e-9, "{omega}");
        } else {
            assert_eq!(rot["pivot"], Value::Null);
            assert_eq!(rot["predicted_pivot"], Value::Null);
            assert!(omega.abs() < 1e-9 * n0 / l);
            let total =
                f(&v["contacts"][0]["normal_impulse"]) + f(&v["contacts"][1]["normal_impulse"]);
            assert!(rel(total, m * (1.0 + eps) * n0) < 1e-9);
        }
        for c in v["contacts"].as_array().unwrap() {
            assert!(rel(-f(&c["gamma_n_pre"]), n0) < 1e-12);
        }
    }
}

/// One skew corner against the abutment: Delassus entries and the stick interval against the
/// closed forms and spec §9; the mode at ratios below, inside and above it.
#[test]
fn skew_corner_stick_interval_by_the_cli() {
    let (l, w, deg, mu, eps) = (30.0, 10.0, 35.0, 0.5, 0.6);
    let (m, i, a, b) = skew_closed_form(l, w, deg);
    for (k, name) in ["acute", "obtuse"].into_iter().enumerate() {
        let args = [
            "--shape",
            "skew",
            "--length",
            "30",
            "--width",
            "10",
            "--skew",
            "35",
            "--abutment",
            "--corner",
            name,
            "--mu",
            "0.5",
            "--eps",
            "0.6",
            "--thickness",
            "1",
            "--density",
            "1",
        ];
        let v = json_of(&args);
        let (nn, nt, tt) = (1.0 / m + a[k] * a[k] / i, a[k] * b / i, 1.0 / m + b * b / i);
        assert!(rel(f(&v["delassus"]["nn"]), nn) < 1e-12);
        assert!(rel(f(&v["delassus"]["nt"]), nt) < 1e-12);
        assert!(rel(f(&v["delassus"]["tt"]), tt) < 1e-12);
        let lo = (1.0 + eps) * (nt - mu * tt) / (nn - mu * nt);
        let hi = (1.0 + eps) * (nt + mu * tt) / (nn + mu * nt);
        assert!(rel(f(&v["stick_interval"]["lower"]), lo) < 1e-10);
        assert!(rel(f(&v["stick_interval"]["upper"]), hi) < 1e-10);
        assert!(rel(f(&v["longitudinal"]["ratio"]), deg.to_radians().tan()) < 1e-12);
        for (r, want) in [
            (lo - 0.5, "slip-positive"),
            (0.5 * (lo + hi), "stick"),
            (hi + 0.5, "slip-negative"),
        ] {
            let rs = r.to_string();
            let mut a2 = args.to_vec();
            a2.extend(["--ratio", &rs]);
            let v = json_of(&a2);
            assert_eq!(v["mode"], want, "{name} r = {r}");
            assert!((f(&v["post"]["gamma_n"]) - eps).abs() < 1e-9);
        }
    }
}

/// Readable output of the abutment form, and the straight and curved variants.
#[test]
fn readable_output_and_other_shapes() {
    let out = run(&[
        "--shape",
        "skew",
        "--length",
        "30",
        "--skew",
        "30",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0.5",
    ]);
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(s.contains("rotates about its obtuse corner"), "{s}");
    assert!(s.contains("sin 2θ_s = 0.866025 > 2W/L = 0.666667"), "{s}");
    // a straight deck never rotates in a frictionless longitudinal impact
    let v = json_of(&[
        "--shape",
        "straight",
        "--length",
        "30",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0.5",
    ]);
    assert_eq!(v["rotation"]["rotates"], Value::Bool(false));
    assert!(
        rel(
            f(&v["deck"]["inertia"]),
            f(&v["deck"]["mass"]) * (900.0 + 100.0) / 12.0
        ) < 1e-12
    );
    // curved deck 1 against an abutment at its far end: the foot of the centroid lies beyond the
    // face for β = 90° (R − X_m = 36.3 m > W/2), within it for β = 20°
    let v = json_of(&[
        "--r1",
        "100",
        "--beta1",
        "90",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0.5",
    ]);
    assert_eq!(v["rotation"]["pivot"], "inner");
    let v = json_of(&[
        "--shape",
        "curved",
        "--r1",
        "100",
        "--beta1",
        "20",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0.5",
    ]);
    assert_eq!(v["rotation"]["rotates"], Value::Bool(false));
    // the gap is reported as the travel along the axis: g / cos θ_s
    let v = json_of(&[
        "--shape",
        "skew",
        "--length",
        "30",
        "--skew",
        "60",
        "--abutment",
        "--gap",
        "0.05",
        "--mu",
        "0",
        "--eps",
        "0.5",
    ]);
    assert!(rel(f(&v["abutment"]["travel_to_contact"]), 0.1) < 1e-12);
}

#[test]
fn bad_shape_input_is_named() {
    let base = ["--abutment", "--mu", "0.2", "--eps", "0.5"];
    for (args, name) in [
        (
            vec!["--shape", "skew", "--length", "30", "--skew", "90"],
            "skew",
        ),
        (
            vec!["--shape", "skew", "--length", "30", "--skew", "120"],
            "skew",
        ),
        (
            vec!["--shape", "skew", "--length", "30", "--skew", "-5"],
            "skew",
        ),
        (
            vec!["--shape", "skew", "--length", "30", "--skew", "nan"],
            "skew",
        ),
        (
            vec!["--shape", "skew", "--length", "0", "--skew", "10"],
            "length",
        ),
        (vec!["--shape", "straight", "--length", "-2"], "length"),
        (vec!["--shape", "straight", "--length", "nan"], "length"),
        (
            vec!["--shape", "straight", "--length", "20", "--width", "0"],
            "width",
        ),
        (vec!["--shape", "skew", "--skew", "10"], "--length"),
        (vec!["--shape", "skew", "--length", "30"], "--skew"),
        (
            vec!["--shape", "straight", "--length", "30", "--gap", "-0.1"],
            "gap",
        ),
        (
            vec!["--shape", "straight", "--length", "30", "--gap", "nan"],
            "gap",
        ),
        (
            vec!["--shape", "straight", "--length", "30", "--speed", "0"],
            "speed",
        ),
        (vec!["--shape", "oval", "--length", "30"], "shape"),
        (
            vec![
                "--shape", "skew", "--length", "30", "--skew", "5", "--corner", "left",
            ],
            "corner",
        ),
        (
            vec![
                "--shape", "skew", "--length", "30", "--skew", "5", "--ratio", "0.1",
            ],
            "--ratio",
        ),
        (
            vec!["--shape", "straight", "--length", "30", "--theta1", "2"],
            "--theta1",
        ),
        (
            vec!["--shape", "straight", "--length", "30", "--r1", "100"],
            "--r1",
        ),
        (
            vec!["--shape", "straight", "--length", "30", "--mu", "-1"],
            "mu",
        ),
    ] {
        let mut a = args.clone();
        if args.contains(&"--mu") {
            a.extend(["--abutment", "--eps", "0.5"]);
        } else {
            a.extend(base);
        }
        let out = run(&a);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{a:?} accepted: {err}");
        assert!(err.contains(name), "{a:?}: error {err:?} lacks {name}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // --length2 (deck 2) makes no sense against an abutment
    let out = run(&[
        "--shape",
        "skew",
        "--length",
        "30",
        "--length2",
        "40",
        "--skew",
        "10",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--length2"));
    // shape options with the curved deck-to-deck form are rejected, not ignored
    let out = run(&[
        "--r1",
        "100",
        "--r2",
        "100",
        "--beta1",
        "60",
        "--beta2",
        "60",
        "--theta1",
        "-5",
        "--theta2",
        "2",
        "--case",
        "deck1-inner",
        "--mu",
        "0.5",
        "--eps",
        "0.5",
        "--gap",
        "0.1",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--gap"));
}

/// Two decks face to face (no --abutment): straight decks obey the 1-D collision law
/// `v1⁺ = v − (1+ε) m2/(m1+m2) v`, `v2⁺ = (1+ε) m1/(m1+m2) v` (v along −y); skew decks conserve the
/// total momentum; a bad deck-2 length names `length2`.
#[test]
fn two_decks_face_to_face() {
    for (l2, eps) in [("30", 1.0), ("45", 0.5)] {
        let es = eps.to_string();
        let v = json_of(&[
            "--shape",
            "straight",
            "--length",
            "30",
            "--length2",
            l2,
            "--mu",
            "0",
            "--eps",
            &es,
            "--speed",
            "2",
        ]);
        let (m1, m2) = (f(&v["decks"][0]["mass"]), f(&v["decks"][1]["mass"]));
        assert!(rel(m2 / m1, l2.parse::<f64>().unwrap() / 30.0) < 1e-12);
        let v1 = -2.0 + (1.0 + eps) * m2 / (m1 + m2) * 2.0;
        let v2 = -(1.0 + eps) * m1 / (m1 + m2) * 2.0;
        assert!((f(&v["decks"][0]["velocity"][1]) - v1).abs() < 1e-9);
        assert!((f(&v["decks"][1]["velocity"][1]) - v2).abs() < 1e-9);
        assert!(f(&v["decks"][0]["omega"]).abs() < 1e-12);
    }
    let v = json_of(&[
        "--shape",
        "skew",
        "--length",
        "30",
        "--length2",
        "50",
        "--skew",
        "30",
        "--mu",
        "0.2",
        "--eps",
        "0.5",
    ]);
    let mut p = [0.0; 2];
    for d in v["decks"].as_array().unwrap() {
        for k in 0..2 {
            p[k] += f(&d["mass"]) * (f(&d["velocity"][k]) - f(&d["velocity_pre"][k]));
        }
    }
    let scale = f(&v["decks"][0]["mass"]);
    assert!(
        p[0].abs() < 1e-9 * scale && p[1].abs() < 1e-9 * scale,
        "{p:?}"
    );
    let out = run(&[
        "--shape",
        "skew",
        "--length",
        "30",
        "--length2",
        "0",
        "--skew",
        "5",
        "--mu",
        "0",
        "--eps",
        "0",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("length2"));
    let out = run(&[
        "--shape", "skew", "--length", "30", "--skew", "5", "--corner", "acute", "--mu", "0",
        "--eps", "0",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--corner"));
}

/// With friction the CLI's `friction_condition_holds` (sin 2θ_s − μ_eff (1 + cos 2θ_s) > 2W/L,
/// μ_eff = min(μ, tan θ_s/(1+ε))) matches the LCP outcome, in the sliding and the sticking regime.
#[test]
fn skew_rotation_with_friction_by_the_cli() {
    let mut seen = [0; 2];
    for (deg, mu, eps) in [
        ("45", "0.3", "0.5"),
        ("45", "0.5", "0.5"),
        ("30", "0.1", "0.5"),
        ("25", "0.1", "0.5"),
        ("30", "1", "0"),
        ("60", "1", "0.9"),
        ("60", "1", "0.1"),
    ] {
        let v = json_of(&[
            "--shape",
            "skew",
            "--length",
            "30",
            "--width",
            "10",
            "--skew",
            deg,
            "--abutment",
            "--mu",
            mu,
            "--eps",
            eps,
        ]);
        let r = &v["rotation"];
        let (th, mu_f, eps_f) = (
            deg.parse::<f64>().unwrap().to_radians(),
            mu.parse::<f64>().unwrap(),
            eps.parse::<f64>().unwrap(),
        );
        let mu_eff = mu_f.min(th.tan() / (1.0 + eps_f));
        let want = (2.0 * th).sin() - mu_eff * (1.0 + (2.0 * th).cos()) > 2.0 * 10.0 / 30.0;
        assert_eq!(
            r["friction_condition_holds"],
            Value::Bool(want),
            "{deg} {mu} {eps}"
        );
        assert_eq!(r["rotates"], Value::Bool(want), "{deg} {mu} {eps}: {r}");
        seen[usize::from(want)] += 1;
    }
    assert!(seen[0] > 0 && seen[1] > 0);
}
