//! `pounding simulate --error-estimate / --tol / --max-refinements`: the answer is the run at
//! its step (the same bytes as a plain run there), `accuracy.csv` / `accuracy.json` carry the
//! three runs' values, a tolerance not met is an error status, and bad flags exit 2.

use crate::{run_capture, scratch_dir};
use std::path::Path;

fn json(p: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
}

fn simulate(out: &Path, args: &[&str]) -> (Option<i32>, String) {
    let mut a = vec!["simulate"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let (code, _, err) = run_capture(&a);
    (code, err)
}

#[test]
fn the_estimate_is_of_the_run_at_the_given_step() {
    let d = scratch_dir("accuracy", "estimate");
    let (est, plain) = (d.join("est"), d.join("plain"));
    let (code, err) = simulate(&est, &["--duration", "3", "--error-estimate"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("accuracy: estimated from runs at dt = 0.001, 0.0005, 0.00025 s"),
        "{err}"
    );
    let (code, err) = simulate(&plain, &["--duration", "3"]);
    assert_eq!(code, Some(0), "{err}");
    for f in ["history.csv", "impacts.csv"] {
        assert!(
            std::fs::read(est.join(f)).unwrap() == std::fs::read(plain.join(f)).unwrap(),
            "{f} differs from the plain run"
        );
    }
    let a = json(&est.join("accuracy.json"));
    assert_eq!(a["dt_s"].as_f64(), Some(1e-3));
    assert_eq!(a["runs_dt_s"], serde_json::json!([1e-3, 5e-4, 2.5e-4]));
    assert_eq!(a["met"], serde_json::Value::Null);
    let s = json(&plain.join("summary.json"));
    // the governing values are the plain run's peaks
    let table = std::fs::read_to_string(est.join("accuracy.csv")).unwrap();
    let row = |name: &str| -> Vec<String> {
        table
            .lines()
            .find(|l| l.starts_with(&format!("{name},")))
            .unwrap_or_else(|| panic!("no row {name} in\n{table}"))
            .split(',')
            .map(String::from)
            .collect()
    };
    let value = |name: &str| row(name)[3].parse::<f64>().unwrap();
    assert_eq!(
        value("max_joint_opening_m"),
        s["peak_joint_opening_m"].as_f64().unwrap()
    );
    assert_eq!(
        value("peak_seat_displacement_m"),
        s["peak_seat_displacement_m"].as_f64().unwrap()
    );
    assert_eq!(value("impacts"), s["impacts"].as_f64().unwrap());
    assert_eq!(row("max_joint_opening_m")[2], "true");
    assert_eq!(row("joint1.peak_opening_m")[2], "false");
    // every quantity of accuracy.json is a row of accuracy.csv, with the same trust
    for q in a["quantities"].as_array().unwrap() {
        let r = row(q["quantity"].as_str().unwrap());
        assert_eq!(r[9], q["trust"].as_str().unwrap());
    }
    let report = std::fs::read_to_string(est.join("report.html")).unwrap();
    assert!(
        report.contains("accuracy.csv"),
        "the report lists the files"
    );
}

#[test]
fn a_tolerance_picks_the_step_and_its_peaks_are_a_plain_run_at_that_step() {
    let d = scratch_dir("accuracy", "tol");
    let (tol, plain, given) = (d.join("tol"), d.join("plain"), d.join("given"));
    let (code, err) = simulate(&tol, &["--duration", "3", "--dt", "4e-3", "--tol", "2%"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("meets the tolerance 2.000 %"), "{err}");
    let a = json(&tol.join("accuracy.json"));
    let dt = a["dt_s"].as_f64().unwrap();
    assert_eq!(a["met"], serde_json::Value::Bool(true));
    assert!(dt < 4e-3, "this coarse step needs refining: {a}");
    for q in a["quantities"].as_array().unwrap() {
        if q["governing"] == serde_json::Value::Bool(true) {
            assert!(q["relative_error"].as_f64().unwrap() <= 0.02, "{q}");
        }
    }
    let (code, err) = simulate(&plain, &["--duration", "3", "--dt", &dt.to_string()]);
    assert_eq!(code, Some(0), "{err}");
    let (s1, s2) = (
        json(&tol.join("summary.json")),
        json(&plain.join("summary.json")),
    );
    assert_eq!(s1["dt_s"], s2["dt_s"]);
    for k in [
        "peak_joint_opening_m",
        "peak_joint_closing_m",
        "peak_seat_displacement_m",
        "peak_rotation_deg",
        "impacts",
    ] {
        assert_eq!(s1[k], s2[k], "{k}");
    }
    // the history keeps the times of the given step's history
    let (code, err) = simulate(&given, &["--duration", "3", "--dt", "4e-3"]);
    assert_eq!(code, Some(0), "{err}");
    let times = |p: &Path| -> Vec<String> {
        let h = std::fs::read_to_string(p.join("history.csv")).unwrap();
        h.lines()
            .map(|l| l.split(',').next().unwrap().to_string())
            .collect()
    };
    assert_eq!(times(&tol), times(&given));
}

#[test]
fn a_tolerance_not_met_is_an_error_status_with_the_files_written() {
    let d = scratch_dir("accuracy", "notmet");
    let out = d.join("out");
    let (code, err) = simulate(
        &out,
        &["--duration", "2", "--tol", "1e-9", "--max-refinements", "0"],
    );
    assert_eq!(code, Some(1), "{err}");
    assert!(
        err.contains("the tolerance") && err.contains("was not met"),
        "{err}"
    );
    assert_eq!(
        json(&out.join("accuracy.json"))["met"],
        serde_json::Value::Bool(false)
    );
    assert!(out.join("summary.json").is_file());
}

#[test]
fn bad_accuracy_flags_exit_2_and_write_nothing() {
    let d = scratch_dir("accuracy", "bad");
    for (args, want) in [
        (&["--tol", "1"][..], "write 1%"),
        (&["--tol", "0%"], "above 0"),
        (&["--tol", "150%"], "below 100"),
        (&["--tol", "abc"], "invalid tolerance"),
        (&["--max-refinements", "2"], "--tol"),
        (
            &["--tol", "1%", "--max-refinements", "9"],
            "--max-refinements",
        ),
        (
            &["--error-estimate", "--records", "x.csv"],
            "--error-estimate",
        ),
    ] {
        let out = d.join("out");
        let (code, err) = simulate(&out, args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {err}");
        assert!(!out.exists(), "{args:?} wrote {}", out.display());
    }
}
