//! `pounding fragility` (issue 13) end to end on a tiny study (2 records x 3 levels, 2 s):
//! files written, one runs.csv row per run, fractions and counts in fragility.json/csv equal to
//! runs.csv, the same bytes for 1 and 2 threads, bad input exits 2 and writes nothing.

use crate::{run_capture, scratch_with};
use std::path::Path;

/// The tiny study: two segments, three Sa(T1) levels, two limit states (also the base of the
/// trial findings' study in `fragility_trial.rs`).
pub(crate) const SCENARIO: &str = r#"[bridge]
damping = "dashpots"
gap = 0.02
seat_length = 0.1
outer_seat_length = 0.1
[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
period_s = 1.2
[[segment]]
shape = "straight"
L = 30.0
mass = 1.2e6
period_s = 0.5
[ground_motion]
scale_y = -1.0
[time]
dt = 2e-3
duration = 2.0

[fragility]
records = "set.toml"
im = "sa"
period_s = "model"
levels_g = [0.2, 1.0, 3.0]
bootstrap = 50
seed = 3

[[limit_state]]
name = "seat"
kind = "unseating"

[[limit_state]]
name = "impulse"
kind = "joint_force"
capacity_ns = 2.0e5
"#;

const SET: &str = r#"[[record]]
id = "NS"
x = "builtin:ELC180"
[record.meta]
azimuth = 180

[[record]]
id = "EW"
x = "builtin:ELC270"
[record.meta]
azimuth = 270
"#;

/// A fresh scratch directory `pounding-{prefix}-{name}-…` holding `bridge.toml` (`scenario`) and
/// `set.toml` (`set`).
pub(crate) fn study_in(prefix: &str, name: &str, scenario: &str, set: &str) -> crate::Scratch {
    scratch_with(
        prefix,
        name,
        &[("bridge.toml", scenario), ("set.toml", set)],
    )
}

fn study(name: &str, scenario: &str) -> crate::Scratch {
    study_in("fragility", name, scenario, SET)
}

/// The files whose bytes must not depend on the thread count (`timing.json` holds wall times).
const OUTPUTS: [&str; 5] = [
    "runs.csv",
    "fragility.csv",
    "fragility.json",
    "fragility.png",
    "report.html",
];

fn run(d: &Path, out: &str, threads: &str) -> (Option<i32>, String, String) {
    run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        d.join(out).to_str().unwrap(),
        "--threads",
        threads,
    ])
}

#[test]
fn fragility_end_to_end_counts_agree_and_bytes_do_not_depend_on_threads() {
    let d = study("e2e", SCENARIO);
    let (code, stdout, err) = run(&d, "one", "1");
    assert_eq!(code, Some(0), "{err}");
    assert!(
        stdout.contains("period: T1 = 1.2 s") && stdout.contains("segment 1"),
        "{stdout}"
    );
    for f in OUTPUTS.into_iter().chain(["timing.json"]) {
        assert!(d.join("one").join(f).is_file(), "{f} missing");
    }
    let runs = std::fs::read_to_string(d.join("one/runs.csv")).unwrap();
    let mut lines = runs.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        head,
        [
            "record",
            "azimuth",
            "level_g",
            "im_g",
            "scale_factor",
            "status",
            "seat_exceeded",
            "seat_ratio",
            "impulse_exceeded",
            "impulse_ratio",
            "governing_seat_end",
            "governing_seat_ratio",
            "seat_ratio_segment1_start",
            "seat_ratio_segment1_end",
            "seat_ratio_segment2_start",
            "seat_ratio_segment2_end",
            "warnings",
            "error"
        ]
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // per run: the unseating limit state's ratio (the summary's largest seat ratio) is the
    // governing end's, which is the largest of the per-end columns (12..16)
    for r in &rows {
        let f = |i: usize| r[i].parse::<f64>().unwrap();
        let (mut at, mut max) = (0, f64::NEG_INFINITY);
        for i in 12..16 {
            if f(i) > max {
                (at, max) = (i, f(i));
            }
        }
        assert!(max > 0.0, "{r:?}");
        assert_eq!(f(7), max, "{r:?}");
        assert_eq!(f(11), max, "{r:?}");
        assert_eq!(
            r[10].replace('-', "_"),
            head[at].trim_start_matches("seat_ratio_"),
            "{r:?}"
        );
    }
    assert_eq!(rows.len(), 2 * 3);
    assert_eq!(rows[0][0], "NS");
    assert_eq!(rows[3][1], "270");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("one/fragility.json")).unwrap())
            .unwrap();
    let csv = std::fs::read_to_string(d.join("one/fragility.csv")).unwrap();
    for (name, col) in [("seat", 6), ("impulse", 8)] {
        let emp = json["empirical"][name].as_array().unwrap();
        assert_eq!(emp.len(), 3);
        let mut counted = 0;
        for (b, level) in ["0.2", "1", "3"].iter().enumerate() {
            let at: Vec<&Vec<&str>> = rows.iter().filter(|r| r[2] == *level).collect();
            let n = at.iter().filter(|r| !r[col].is_empty()).count();
            let k = at.iter().filter(|r| r[col] == "true").count();
            counted += n;
            assert_eq!(emp[b]["runs"].as_u64().unwrap() as usize, n);
            assert_eq!(emp[b]["fraction"].as_f64().unwrap(), k as f64 / n as f64);
            // the ratio column says the same as the flag for the joint
            if name == "impulse" {
                for r in &at {
                    let ratio: f64 = r[col + 1].parse().unwrap();
                    assert_eq!(r[col] == "true", ratio > 1.0);
                }
            }
        }
        let line = csv
            .lines()
            .find(|l| l.starts_with(&format!("{name},")))
            .unwrap();
        let n_runs = line.split(',').nth(11).unwrap();
        assert_eq!(n_runs, counted.to_string(), "{line}");
    }
    let (code, _, err) = run(&d, "two", "2");
    assert_eq!(code, Some(0), "{err}");
    for f in OUTPUTS {
        let a = std::fs::read(d.join("one").join(f)).unwrap();
        let b = std::fs::read(d.join("two").join(f)).unwrap();
        assert!(a == b, "{f} differs between 1 and 2 threads");
    }
}

/// Hostile round 3 campaign (F8): a run's warnings reach a fragility user: a step of 0.02 s
/// skips samples of the 0.01 s records, so every run has a warning, counted in runs.csv's
/// `warnings` column and summarised on stderr (the same run through `simulate` warns too).
#[test]
fn fragility_runs_count_their_warnings() {
    let d = study("warn", &SCENARIO.replace("dt = 2e-3", "dt = 2e-2"));
    let (code, _, err) = run(&d, "w", "1");
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("6 of 6 runs have warnings"), "{err}");
    let runs = std::fs::read_to_string(d.join("w/runs.csv")).unwrap();
    let mut lines = runs.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = head.iter().position(|h| *h == "warnings").unwrap();
    for l in lines {
        let n: usize = l.split(',').nth(col).unwrap().parse().unwrap();
        assert!(n >= 1, "{l}");
    }
    let (code, _, err) = run(&d, "w2", "1");
    assert_eq!(code, Some(0), "{err}");
}

fn refused(name: &str, scenario: &str, needle: &str) {
    let d = study(name, scenario);
    let (code, _, err) = run(&d, "out", "1");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains(needle), "{needle:?} not in {err}");
    assert!(!d.join("out").exists(), "something was written");
}

#[test]
fn fragility_bad_input_exits_2_and_writes_nothing() {
    for (name, from, to, needle) in [
        (
            "level",
            "[0.2, 1.0, 3.0]",
            "[0.2, -1.0]",
            "fragility.levels_g",
        ),
        (
            "damping",
            "seed = 3",
            "seed = 3\ndamping = 1.0",
            "fragility.damping",
        ),
        ("period", "\"model\"", "0.0", "fragility.period_s"),
        (
            "kind",
            "\"unseating\"",
            "\"collapse\"",
            "limit_state[0].kind",
        ),
        (
            "missing",
            "set.toml",
            "none.toml",
            "none.toml: No such file or directory (os error 2) — `fragility.records` (/",
        ),
        ("unknown", "seed = 3", "seed = 3\nstripes = 2", "stripes"),
    ] {
        refused(name, &SCENARIO.replace(from, to), needle);
    }
    // the manifest of `[fragility] records` that cannot be read: named with that key's line
    refused(
        "missing-line",
        &SCENARIO.replace("set.toml", "none.toml"),
        "bridge.toml:23)",
    );
    let two_deck = "[decks]\nshape = \"straight\"\n[fragility]\nrecords = \"set.toml\"\nlevels_g = [0.1]\n[[limit_state]]\nname = \"u\"\nkind = \"unseating\"\n";
    refused("twodeck", two_deck, "two-deck");
    // a record file named by the set that does not exist: the set's key and line, and the file
    let d = study("recfile", SCENARIO);
    std::fs::write(
        d.join("set.toml"),
        SET.replace("builtin:ELC270", "missing.AT2"),
    )
    .unwrap();
    let (code, _, err) = run(&d, "out", "1");
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("record[1].x") && err.contains("set.toml:9") && err.contains("missing.AT2"),
        "{err}"
    );
    assert!(!d.join("out").exists());
}
