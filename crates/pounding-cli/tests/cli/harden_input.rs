//! Hardening (issue 15): scenario and record inputs that used to be silently misread are refused
//! with exit 2, naming the file, the key and the line, and nothing is written.

use crate::pounding;
use std::path::PathBuf;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("pounding-hin-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `pounding ARGS` in `dir`; returns (exit code, stderr).
fn run_in(dir: &PathBuf, args: &[&str]) -> (Option<i32>, String) {
    let o = pounding().current_dir(dir).args(args).output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn simulate_refuses_three_coordinate_bearing_points_and_sections_as_arrays() {
    let d = tmp("sim");
    for (text, line, what) in [
        (
            "[time]\nduration = 0.1\n[bearings]\npoints1 = [[0, 1, 2], [1, 2, 3]]\n",
            "line 4",
            "exactly 2 numbers",
        ),
        (
            "joint = [0.1, 0.4, 0.5, 0.5]\n",
            "line 1",
            "expected a table",
        ),
        (
            "[time]\nduration = 0.1\n[bearings]\npoints2 = [[0]]\n",
            "line 4",
            "exactly 2",
        ),
    ] {
        std::fs::write(d.join("s.toml"), text).unwrap();
        let (code, err) = run_in(&d, &["simulate", "s.toml", "--out", "o"]);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(
            err.contains("s.toml") && err.contains(line) && err.contains(what),
            "{err}"
        );
        assert!(!d.join("o").exists(), "nothing may be written: {text}");
    }
}

#[test]
fn study_refuses_a_list_as_a_range_and_a_step_too_fine_to_count() {
    let d = tmp("study");
    for (text, want) in [
        ("[grid]\ntheta1_deg = [-1, 0, 1]\n", "line 2"),
        (
            "[grid]\ntheta2_deg = { start = -10.0, stop = 10.0, step = 1e-300 }\n",
            "grid.theta2_deg.step",
        ),
        (
            "[grid]\nratio_min = -1e308\nratio_max = 1e308\n",
            "grid.ratio_max",
        ),
    ] {
        std::fs::write(d.join("s.toml"), text).unwrap();
        let (code, err) = run_in(&d, &["study", "s.toml", "--out", "o"]);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(err.contains("s.toml") && err.contains(want), "{err}");
        assert!(!d.join("o").exists());
    }
}

#[test]
fn simulate_refuses_a_velocity_record_named_at2() {
    let d = tmp("vel");
    std::fs::write(
        d.join("v.AT2"),
        "PEER NGA STRONG MOTION DATABASE RECORD\nev\nVELOCITY TIME SERIES IN UNITS OF CM/S\nNPTS= 3, DT= .01 SEC\n 1.0 2.0 3.0\n",
    )
    .unwrap();
    std::fs::write(d.join("s.toml"), "[time]\nduration = 0.1\n").unwrap();
    let (code, err) = run_in(
        &d,
        &["simulate", "s.toml", "--record", "v.AT2", "--out", "o"],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("v.AT2") && err.contains("VELOCITY"), "{err}");
    assert!(!d.join("o").exists());
}
