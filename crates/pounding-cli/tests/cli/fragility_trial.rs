//! Findings of a fresh-clone trial of `pounding fragility` / `motion synth` (issue 13), each
//! pinned end to end: an `--out` that cannot be a directory is refused before any run (one
//! message, not a doubled os error), the bootstrap's failed replicates and unreliable intervals
//! are shown, absurd periods, levels and synthetic-record flags are refused naming the key or flag.

use crate::motion::synth;
use crate::{run_capture, scratch_dir};
use std::path::Path;

/// The study of `fragility.rs` with a fixed period, 1.5 s, for Sa (same lines).
fn scenario() -> String {
    crate::fragility::SCENARIO.replace("period_s = \"model\"", "period_s = 1.5")
}

const SET: &str = r#"[[record]]
id = "NS"
x = "builtin:ELC180"

[[record]]
id = "EW"
x = "builtin:ELC270"
"#;

fn study(name: &str, scenario: &str) -> crate::Scratch {
    crate::fragility::study_in("fragtrial", name, scenario, SET)
}

fn run(d: &Path, out: &Path) -> (Option<i32>, String, String) {
    run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "1",
    ])
}

#[test]
fn an_out_that_is_a_regular_file_is_refused_before_any_run_in_one_message() {
    let d = study("outfile", &scenario());
    let file = d.join("taken");
    std::fs::write(&file, "keep me").unwrap();
    for out in [file.clone(), file.join("sub")] {
        let (code, stdout, err) = run(&d, &out);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains("is not a directory"), "{err}");
        // refused up front: no run was announced, no table printed
        assert!(!err.contains("runs on"), "{err}");
        assert!(stdout.is_empty(), "{stdout}");
        assert!(err.matches("os error").count() <= 1, "doubled: {err}");
    }
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep me");
}

#[test]
fn bootstrap_failures_and_unreliable_intervals_are_shown() {
    let d = study("boot", &scenario());
    let (code, stdout, err) = run(&d, &d.join("out"));
    assert_eq!(code, Some(0), "{err}");
    assert!(
        stdout.contains("boot failed") && stdout.contains("records"),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(d.join("out/fragility.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        &head[head.len() - 3..],
        ["bootstrap_failed", "im", "im_unit"]
    );
    let report = std::fs::read_to_string(d.join("out/report.html")).unwrap();
    assert!(report.contains("<th>bootstrap failed</th>"));
    let failed_col = head.iter().position(|c| *c == "bootstrap_failed").unwrap();
    for line in lines {
        let c: Vec<&str> = line.split(',').collect();
        assert!(line.ends_with(",\"Sa(1.5 s, 5 %)\",g"), "{line}");
        let (name, status) = (c[0], c[2]);
        if status == "ok" {
            // two records: the intervals are flagged on stderr and in the report
            let w = format!("limit state {name}: intervals unreliable");
            assert!(err.contains(&w), "{err}");
            assert!(report.contains(&w), "no warning in report.html");
            assert!(c[failed_col].parse::<usize>().is_ok(), "{line}");
        } else {
            assert_eq!(c[failed_col], "nan", "{line}");
        }
    }
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("out/fragility.json")).unwrap())
            .unwrap();
    assert_eq!(j["fits"][0]["im_unit"], "g");

    // bootstrap = 0: the level asked for is written, not nan
    let d = study(
        "noboot",
        &scenario().replace("bootstrap = 50", "bootstrap = 0"),
    );
    let (code, _, err) = run(&d, &d.join("out"));
    assert_eq!(code, Some(0), "{err}");
    let csv = std::fs::read_to_string(d.join("out/fragility.csv")).unwrap();
    let head: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let lv = head.iter().position(|c| *c == "level").unwrap();
    for line in csv.lines().skip(1) {
        assert_eq!(line.split(',').nth(lv), Some("0.95"), "{line}");
    }
}

fn refused(name: &str, scenario: &str, needles: &[&str]) {
    let d = study(name, scenario);
    let (code, _, err) = run(&d, &d.join("out"));
    assert_eq!(code, Some(2), "{err}");
    for n in needles {
        assert!(err.contains(n), "{n:?} not in {err}");
    }
    assert!(!d.join("out").exists(), "something was written");
}

#[test]
fn absurd_periods_and_scale_factors_are_refused() {
    refused(
        "period",
        &scenario().replace("period_s = 1.5", "period_s = 1e6"),
        &["fragility.period_s", "bridge.toml:25", "(0, 20] s"],
    );
    refused(
        "level",
        &scenario().replace("[0.2, 1.0, 3.0]", "[0.2, 1.0, 5000.0]"),
        &["record NS", "level_g = 5000", "scale factor", "too small"],
    );
    refused(
        "scale",
        &scenario().replace("levels_g = [0.2, 1.0, 3.0]", "scales = [1.0, 500.0]"),
        &["record NS", "scale = 500", "beyond the limit of 100"],
    );
}

#[test]
fn absurd_synth_flags_are_refused_naming_the_flag() {
    let d = scratch_dir("fragtrial", "synth");
    for (i, (args, needle)) in [
        (
            &["--count", "1", "--pga", "1e300"][..],
            "invalid --pga = 1e300",
        ),
        (&["--count", "1", "--pga", "10.5"], "(0, 10] g"),
        (
            &["--count", "2", "--duration", "0.01"],
            "invalid --duration = 0.01",
        ),
        (
            &["--count", "1", "--dt", "0.3", "--duration", "1"],
            "whole number of steps",
        ),
        (&["--count", "1", "--dt", "1e-9"], "invalid --dt = 1e-9"),
    ]
    .into_iter()
    .enumerate()
    {
        let (code, err, out) = synth(&d, &format!("o{i}"), args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {needle:?} not in {err}");
        assert!(!out.exists(), "{args:?}: something was written");
    }
    // the largest PGA allowed and a whole number of steps still work
    let (code, err, out) = synth(
        &d,
        "ok",
        &[
            "--count",
            "1",
            "--pga",
            "10",
            "--dt",
            "0.02",
            "--duration",
            "2",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(out.join("suite.toml").is_file());
}
