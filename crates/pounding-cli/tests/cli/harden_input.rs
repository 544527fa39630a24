//! Hardening (issue 15): scenario and record inputs that used to be silently misread are refused
//! with exit 2, naming the file, the key and the line, and nothing is written.

use crate::pounding;
use std::path::Path;

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("hin", name)
}

/// Runs `pounding ARGS` in `dir`; returns (exit code, stderr).
fn run_in(dir: &Path, args: &[&str]) -> (Option<i32>, String) {
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

#[test]
fn simulate_errors_name_the_key_and_line_for_ground_motion_steps_and_masses() {
    let d = tmp("keys");
    for (text, want) in [
        (
            "[time]\nduration = 0.1\n[ground_motion]\nincidence_deg = 1e308\n",
            vec![
                "[ground_motion] incidence_deg` (s.toml:4)",
                "[-360, 360] deg",
            ],
        ),
        (
            "[time]\nduration = 0.1\n[ground_motion]\nscale_y = inf\n",
            vec!["[ground_motion] scale_y` (s.toml:4)"],
        ),
        (
            "[time]\nduration = 1e12\ndt = 1e-3\n",
            vec![
                "[time] dt` (s.toml:3)",
                "[time] duration` (s.toml:2)",
                "limit",
            ],
        ),
        (
            // A tiny mass used to be blamed on "no bearing stiffness" (its frequencies overflowed to 0).
            "[time]\nduration = 0.1\n[decks]\nmass1 = 1e-300\n",
            vec!["mass (deck 1)", "[decks] mass1` (s.toml:4)", "overflows"],
        ),
    ] {
        std::fs::write(d.join("s.toml"), text).unwrap();
        let (code, err) = run_in(&d, &["simulate", "s.toml", "--out", "o"]);
        assert_eq!(code, Some(2), "{text}: {err}");
        for w in want {
            assert!(err.contains(w), "{text}: want {w:?} in {err}");
        }
        assert!(!err.contains("no bearing stiffness"), "{err}");
        assert!(!d.join("o").exists());
    }
}

#[test]
fn compare_refuses_a_time_step_beyond_the_duration() {
    let d = tmp("cmp");
    std::fs::write(d.join("s.toml"), "[time]\nduration = 1.0\n").unwrap();
    let (code, err) = run_in(&d, &["compare", "s.toml", "--dt", "1e9", "--out", "o"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("must not exceed the duration 1 s") && err.contains("--dt (command line"),
        "{err}"
    );
    assert!(!d.join("o").exists());
}

#[test]
fn impact_reports_a_bad_rotation_in_degrees() {
    let d = tmp("theta");
    let base = [
        "impact",
        "--r1",
        "100",
        "--r2",
        "100",
        "--beta1",
        "60",
        "--beta2",
        "60",
        "--case",
        "deck1-inner",
        "--mu",
        "0.5",
        "--eps",
        "0.5",
        "--theta2",
        "0",
    ];
    for t in ["90", "-95"] {
        let mut a = base.to_vec();
        a.extend(["--theta1", t]);
        let (code, err) = run_in(&d, &a);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains(&format!("--theta1 = {t}:")), "{err}");
    }
}

/// A disc on the ground with the given contact normal, as an `impact --problem` file.
fn disc_with_normal(normal: &str) -> String {
    format!(
        r#"{{"bodies": [{{"name": "disc", "mass": 2.0, "inertia": 0.09, "position": [0, 0.3],
             "velocity": [1.0, -2.0], "omega": 40.0}}],
 "contacts": [{{"body_a": "disc", "body_b": null, "point": [0, 0], "normal": {normal},
               "mu": 0.2, "restitution": 0.5}}]}}"#
    )
}

#[test]
fn a_huge_or_tiny_contact_normal_is_the_same_direction() {
    // [0, 1e200] used to overflow |n| to inf and become (0, 0): "no-impact", exit 0.
    let d = tmp("normal");
    let run = |n: &str| {
        std::fs::write(d.join("p.json"), disc_with_normal(n)).unwrap();
        let o = pounding()
            .current_dir(&d)
            .args(["impact", "--problem", "p.json", "--json"])
            .output()
            .unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{n}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        String::from_utf8(o.stdout).unwrap()
    };
    let unit = run("[0, 1]");
    assert!(unit.contains("\"solved\""), "{unit}");
    for n in ["[0, 1e200]", "[0, 1e-200]", "[0, 5e-324]", "[0, 1.7e308]"] {
        assert_eq!(run(n), unit, "{n}");
    }
}

#[test]
fn too_many_contacts_are_refused_before_solving() {
    let d = tmp("contacts");
    let c = r#"{"body_a": "b", "body_b": null, "point": [0, 0], "normal": [0, 1], "mu": 0.5, "restitution": 0}"#;
    let text = format!(
        r#"{{"bodies": [{{"name": "b", "mass": 1, "inertia": 0.5, "position": [0, 0.1], "velocity": [0.3, -1], "omega": 0}}], "contacts": [{}]}}"#,
        vec![c; 257].join(",")
    );
    std::fs::write(d.join("p.json"), text).unwrap();
    let (code, err) = run_in(&d, &["impact", "--problem", "p.json"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("257 contacts") && err.contains("256"), "{err}");
}

#[test]
fn compare_exits_1_when_a_law_does_not_complete() {
    let d = tmp("cmpdiv");
    std::fs::write(
        d.join("s.toml"),
        "[time]\nduration = 0.5\n[ground_motion]\nscale_y = 1e200\n",
    )
    .unwrap();
    let (code, err) = run_in(&d, &["compare", "s.toml", "--laws", "rigid", "--out", "o"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("rigid (Diverged)"), "{err}");
    assert!(d.join("o/compare.csv").is_file() && d.join("o/timing.json").is_file());
}

#[test]
fn a_huge_shard_count_is_refused_not_a_panic() {
    let d = tmp("shards");
    for n in ["18446744073709551615", "1000000000000", "100001"] {
        let (code, err) = run_in(&d, &["study", "--shard", &format!("1/{n}"), "--out", "s"]);
        assert_eq!(code, Some(2), "{n}: {err}");
        assert!(err.contains("100000"), "{err}");
    }
}

#[test]
fn a_failed_write_to_stdout_is_an_error_not_a_panic() {
    let d = tmp("stdout");
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full");
    let Ok(full) = full else {
        crate::skipped("/dev/full is absent");
        return;
    };
    for args in [
        vec!["simulate", "--print-default"],
        vec!["study", "--print-default"],
        vec![
            "impact",
            "--shape",
            "straight",
            "--length",
            "30",
            "--length2",
            "50",
            "--mu",
            "0.5",
            "--eps",
            "0.5",
            "--json",
        ],
    ] {
        let o = pounding()
            .current_dir(&d)
            .args(&args)
            .stdout(full.try_clone().unwrap())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("error: failed printing to stdout"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn lcp_solve_exits_1_when_a_problem_is_not_solved_and_2_for_an_empty_set() {
    let d = tmp("lcpexit");
    // M = [[0]], q = [-1]: no solution (Lemke ends on a ray).
    std::fs::write(d.join("ray.dat"), "1\n0\n1\n1\n1 1\n0\n-1\n").unwrap();
    let (code, err) = run_in(&d, &["lcp", "solve", "ray.dat"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("1 of 1 problems not solved"), "{err}");
    std::fs::write(d.join("empty.txt"), "LCPSET 1\nCOUNT 0\n").unwrap();
    let (code, err) = run_in(&d, &["lcp", "solve", "empty.txt"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("COUNT 0"), "{err}");
}

#[test]
fn a_repeated_block_column_in_a_sparse_block_file_is_refused() {
    let d = tmp("dupblk");
    // 2 block rows x 2 block columns of size 2; block row 0 lists block column 0 twice (the
    // second block would silently overwrite the first).
    let text = "4\n1\n4\n4\n3\n2\n2\n2 4\n2 4\n3\n3\n0 2 3\n0 0 1\n";
    std::fs::write(d.join("dup.dat"), text).unwrap();
    let (code, err) = run_in(&d, &["lcp", "solve", "dup.dat"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("not already used in this block row"), "{err}");
}
