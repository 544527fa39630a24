//! Hardening: absurd sizes, unchecked claims, overflowing derived quantities, diverged runs.

use std::path::Path;

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("harden", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    crate::run_capture(args)
}

#[test]
fn absurd_at2_npts_is_an_error_row_in_a_batch() {
    let d = tmp("npts");
    let recs = d.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    let mut good = String::from("t,a\n");
    for k in 0..=100 {
        good.push_str(&format!(
            "{:.2},{:.6}\n",
            k as f64 * 0.01,
            0.2 * (k as f64 * 0.1).sin()
        ));
    }
    std::fs::write(recs.join("a.csv"), good).unwrap();
    std::fs::write(
        recs.join("huge.AT2"),
        "h\nh\nh\nNPTS= 99999999999, DT= 0.01 SEC\n0.1 0.2\n",
    )
    .unwrap();
    let sc = d.join("scenario.toml");
    std::fs::write(&sc, "[time]\ndt = 2e-3\nhistory_every = 50\n").unwrap();
    // single run: a clear file:LINE error
    let (code, _, err) = run(&["simulate", s(&sc), "--record", s(&recs.join("huge.AT2"))]);
    assert_ne!(code, Some(0), "{err}");
    assert!(code.is_some(), "killed by a signal: {err}");
    assert!(err.contains("huge.AT2:4") && err.contains("NPTS"), "{err}");
    // batch: an error row, the good record still reported
    let out = d.join("o");
    let (code, _, err) = run(&[
        "simulate",
        s(&sc),
        "--records",
        s(&recs),
        "--scales",
        "1,2",
        "--out",
        s(&out),
    ]);
    assert_eq!(code, Some(1), "{err}");
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    let n_err = csv.lines().filter(|l| l.contains(",error,")).count();
    assert_eq!(n_err, 2, "{csv}");
    assert_eq!(csv.lines().count(), 5, "{csv}");
    assert!(csv.contains("huge.AT2:4"), "{csv}");
}

#[test]
fn lcp_io_refuses_absurd_sizes_and_empty_sets() {
    let d = tmp("lcpio");
    let c = d.join("c.txt");
    std::fs::write(&c, "LCPSET 1\nCOUNT 99999999999\n").unwrap();
    let (code, _, err) = run(&["lcp", "solve", s(&c)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("COUNT") || err.contains("count"), "{err}");
    let b = d.join("b.dat");
    std::fs::write(&b, "100000000\n0\n100000000\n100000000\n1 2\n").unwrap();
    let (code, _, err) = run(&["lcp", "solve", s(&b)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("b.dat"), "{err}");
    let e = d.join("e.txt");
    std::fs::write(&e, "LCPSET 1\nCOUNT 0\n").unwrap();
    let (code, _, err) = run(&["lcp", "bench", s(&e)]);
    assert!(code.is_some() && code != Some(101), "panicked: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

fn disc_problem(n_contacts: usize) -> String {
    let c = r#"{"body_a": "disc", "body_b": null, "point": [0, 0], "normal": [0, 1], "mu": 0.2, "restitution": 0.5}"#;
    let cs = vec![c; n_contacts].join(", ");
    format!(
        r#"{{"bodies": [{{"name": "disc", "mass": 2.0, "inertia": 0.09, "position": [0, 0.3], "velocity": [1.0, -2.0], "omega": 40.0}}], "contacts": [{cs}]}}"#
    )
}

#[test]
fn impact_uniqueness_is_null_when_enumeration_did_not_run() {
    let d = tmp("uniq");
    // 6 duplicated contacts: 3n = 18 > 12, no enumeration; the impulse split is in fact not unique
    let p6 = d.join("p6.json");
    std::fs::write(&p6, disc_problem(6)).unwrap();
    let (code, out, err) = run(&["impact", "--problem", s(&p6), "--json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    for k in ["solutions", "impulse_unique", "post_velocity_unique"] {
        assert!(v[k].is_null(), "{k} = {} (not checked)", v[k]);
    }
    let (_, out, _) = run(&["impact", "--problem", s(&p6)]);
    assert!(out.contains("not checked"), "{out}");
    // 2 duplicated contacts: enumerated, the split is found to be non-unique, velocities unique
    let p2 = d.join("p2.json");
    std::fs::write(&p2, disc_problem(2)).unwrap();
    let (code, out, err) = run(&["impact", "--problem", s(&p2), "--json"]);
    assert_eq!(code, Some(0), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v["solutions"].as_u64().unwrap() > 1, "{out}");
    assert_eq!(v["impulse_unique"], serde_json::json!(false), "{out}");
    assert_eq!(v["post_velocity_unique"], serde_json::json!(true), "{out}");
}

#[test]
fn overflowing_derived_mass_properties_are_errors_naming_the_parameter() {
    let base = [
        "impact",
        "--r2",
        "100",
        "--beta1",
        "60",
        "--beta2",
        "60",
        "--width",
        "10",
        "--density",
        "2500",
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
    ];
    for (extra, want) in [
        (["--r1", "1e300", "--thickness", "1"], "R1"),
        (["--r1", "100", "--thickness", "1e-320"], "thickness"),
    ] {
        let mut a = base.to_vec();
        a.extend(extra);
        let (code, out, err) = run(&a);
        assert_eq!(code, Some(2), "{want}: {out} {err}");
        assert!(err.contains(want), "{want}: {err}");
        assert!(!out.contains("NaN") && !out.contains("nan"), "{out}");
    }
    // simulate: a bearing point at 1e300 m names the key, not "no bearing stiffness"
    let d = tmp("bearing");
    let sc = d.join("s.toml");
    std::fs::write(
        &sc,
        "[bearings]\npoints1 = [[1e300, 0]]\n[time]\nduration = 0.1\n",
    )
    .unwrap();
    let (code, _, err) = run(&["simulate", s(&sc), "--out", s(&d.join("o"))]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("points1") && !err.contains("no bearing stiffness"),
        "{err}"
    );
    assert!(err.len() < 400, "number printed in full: {err}");
}

#[test]
fn simulate_rejects_dt_beyond_the_duration_and_fails_on_divergence() {
    let d = tmp("dt");
    let sc = d.join("s.toml");
    std::fs::write(&sc, "[time]\ndt = 1e300\n").unwrap();
    let (code, _, err) = run(&["simulate", s(&sc), "--out", s(&d.join("o1"))]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("time") && err.contains("dt") && err.contains("1e300"),
        "{err}"
    );
    // dt = duration = 1e300 passes validation but diverges: outputs written, non-zero exit
    std::fs::write(&sc, "[time]\ndt = 1e300\nduration = 1e300\n").unwrap();
    let o2 = d.join("o2");
    let (code, _, err) = run(&["simulate", s(&sc), "--out", s(&o2)]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("Diverged"), "{err}");
    assert!(
        err.contains("simulated 1e300 s"),
        "duration not float_token: {err}"
    );
    let js = std::fs::read_to_string(o2.join("summary.json")).unwrap();
    assert!(js.contains("\"status\": \"Diverged\""), "{js}");
}

#[test]
fn near_90_degree_skew_rounding_noise_is_not_a_rotation() {
    let a = [
        "impact",
        "--shape",
        "skew",
        "--skew",
        "89.9999999",
        "--abutment",
        "--mu",
        "0",
        "--eps",
        "0.5",
        "--length",
        "30",
        "--width",
        "10",
    ];
    let (code, out, err) = run(&a);
    assert_eq!(code, Some(0), "{err}");
    assert!(!out.contains("the deck rotates"), "{out}");
    let mut j = a.to_vec();
    j.push("--json");
    let (_, out, _) = run(&j);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["rotation"]["rotates"], serde_json::json!(false), "{out}");
    // criterion satisfied (sin 2θ_s > 2W/L): a real rotation is still reported
    let mut r = a.to_vec();
    r[4] = "30";
    r.push("--json");
    let (_, out, _) = run(&r);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        v["rotation"]["condition_holds"],
        serde_json::json!(true),
        "{out}"
    );
    assert_eq!(v["rotation"]["rotates"], serde_json::json!(true), "{out}");
}
