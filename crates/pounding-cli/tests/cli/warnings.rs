//! Run warnings reach every output: `summary.json`'s `warnings` (input warnings — an implausible
//! record PGA, a coarse compliance time step — then the per-impact energy warnings),
//! `report.html` (one sentence each) and the `warnings` count of `batch.csv`, equal to the single
//! run's list.

use super::{pounding, scratch_dir};
use serde_json::Value;
use std::path::Path;

fn summary(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap()
}

fn kinds(v: &Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["kind"].as_str().unwrap().to_string())
        .collect()
}

/// A record of 3 g as read: stderr, summary.json and report.html all carry the warning.
#[test]
fn an_implausible_pga_is_in_the_summary_and_the_report() {
    let d = scratch_dir("warn", "pga");
    std::fs::write(d.join("big.csv"), "t,a\n0,0\n0.01,3\n0.02,-3\n0.03,0\n").unwrap();
    let out = pounding()
        .current_dir(&d)
        .args(["simulate", "--record", "big.csv", "--out", "o"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("PGA of 3.000 g"), "{err}");
    let s = summary(&d.join("o"));
    assert_eq!(kinds(&s), ["record_pga_implausible"]);
    assert_eq!(s["warnings"][0]["pga_g"], 3.0);
    let html = std::fs::read_to_string(d.join("o/report.html")).unwrap();
    assert!(
        html.contains("has a PGA of 3.000 g"),
        "report lacks the warning"
    );
    assert!(!html.contains("<p>None.</p>"));
}

/// A compliance law at a coarse step: the time-step warning is in summary.json and the report.
#[test]
fn a_coarse_time_step_is_in_the_summary_and_the_report() {
    let d = scratch_dir("warn", "dt");
    let out = pounding()
        .current_dir(&d)
        .args([
            "simulate",
            "--law",
            "kelvin",
            "--dt",
            "0.01",
            "--duration",
            "6",
            "--out",
            "o",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let s = summary(&d.join("o"));
    let w = &s["warnings"][0];
    assert_eq!(w["kind"], "time_step_coarse");
    assert_eq!(w["dt_s"], 0.01);
    assert_eq!(w["steps_per_contact"], s["time_step"]["steps_per_contact"]);
    let html = std::fs::read_to_string(d.join("o/report.html")).unwrap();
    assert!(html.contains("too coarse for the contact law"));
}

/// Energy created at contacts (μ = 1, ε = 1, a strong motion): the batch's `warnings` column
/// equals the length of the same single run's list, and stderr says how many runs have warnings.
#[test]
fn the_batch_counts_the_warnings_of_each_run_as_the_single_run_lists_them() {
    let d = scratch_dir("warn", "batch");
    std::fs::write(
        d.join("ec.toml"),
        "[joint]\nmu = 1.0\neps_n = 1.0\n[ground_motion]\nscale_y = 3\nscale_x = 3\n",
    )
    .unwrap();
    std::fs::write(
        d.join("elc.AT2"),
        pounding::ground_motion::EL_CENTRO_180_AT2,
    )
    .unwrap();
    let out = pounding()
        .current_dir(&d)
        .args([
            "simulate",
            "ec.toml",
            "--records",
            "elc.AT2",
            "--scales",
            "1,3",
            "--out",
            "b",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("2 of 2 runs have warnings"), "{err}");
    let csv = std::fs::read_to_string(d.join("b/batch.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = head.iter().position(|h| *h == "warnings").unwrap();
    assert_eq!(head.last(), Some(&"error"));
    for (line, scale) in lines.zip(["1", "3"]) {
        let cells: Vec<&str> = line.split(',').collect();
        let o = format!("s{scale}");
        let single = pounding()
            .current_dir(&d)
            .args([
                "simulate", "ec.toml", "--record", "elc.AT2", "--scale", scale, "--out", &o,
            ])
            .output()
            .unwrap();
        assert!(single.status.success());
        let s = summary(&d.join(&o));
        let n = s["warnings"].as_array().unwrap().len();
        assert!(n > 0);
        assert!(kinds(&s).iter().all(|k| k == "contact_energy_created"));
        assert_eq!(cells[col], n.to_string(), "scale {scale}");
    }
}

/// A step longer than the record's sample interval (the built-in El Centro: 0.01 s) skips samples
/// of the excitation: warned, in summary.json with both intervals.
#[test]
fn a_step_beyond_the_record_interval_is_warned() {
    let d = scratch_dir("warn", "beyond");
    let out = pounding()
        .current_dir(&d)
        .args(["simulate", "--dt", "0.02", "--duration", "4", "--out", "o"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(
        err.contains("longer than the sample interval 0.01 s"),
        "{err}"
    );
    let s = summary(&d.join("o"));
    let w = &s["warnings"][0];
    assert_eq!(w["kind"], "time_step_beyond_record");
    assert_eq!(
        (w["dt_s"].as_f64(), w["record_dt_s"].as_f64()),
        (Some(0.02), Some(0.01))
    );
    // at the default dt (1 ms) there is no such warning
    let ok = pounding()
        .current_dir(&d)
        .args(["simulate", "--duration", "1", "--out", "p"])
        .output()
        .unwrap();
    assert!(ok.status.success());
    assert!(!kinds(&summary(&d.join("p"))).contains(&"time_step_beyond_record".to_string()));
}

/// `compare` of three laws on a record of 3 g: the record's warning is listed once in the
/// report (under "Every law"), not once per law; stderr says it once too.
#[test]
fn compare_lists_a_record_warning_once() {
    let d = scratch_dir("warn", "cmp");
    std::fs::write(d.join("big.csv"), "t,a\n0,0\n0.01,3\n0.02,-3\n0.03,0\n").unwrap();
    std::fs::write(
        d.join("s.toml"),
        "[time]\nduration = 0.5\n[ground_motion]\nrecord_y = \"big.csv\"\nrecord_x = \"none\"\n",
    )
    .unwrap();
    let out = pounding()
        .current_dir(&d)
        .args([
            "compare",
            "s.toml",
            "--laws",
            "rigid,kelvin,bilinear",
            "--out",
            "o",
        ])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert_eq!(err.matches("PGA of 3.000 g").count(), 1, "{err}");
    let html = std::fs::read_to_string(d.join("o/report.html")).unwrap();
    let section = crate::report_warnings(&html);
    assert_eq!(section.matches("PGA of 3.000 g").count(), 1, "{section}");
    assert!(section.contains("<h3>Every law</h3>"), "{section}");
}

/// A segment whose bearings give it a natural period of 1 µs (`period_s = 1e-6`: seconds typed for
/// milliseconds, say), far below the step (1e-4 s): the run completes, but the summary, stderr and
/// the report say that segment's mode is not followed; the unmodified example has no such warning.
#[test]
fn an_unresolvable_segment_period_is_warned() {
    let d = scratch_dir("warn", "period");
    let root = env!("CARGO_MANIFEST_DIR");
    let text = std::fs::read_to_string(format!("{root}/../../examples/viaduct-rigid-1d.toml"))
        .unwrap()
        .replace("history_every = 100", "history_every = 100\nduration = 1.0");
    assert!(text.contains("period_s = 0.5\n"));
    std::fs::write(d.join("ok.toml"), &text).unwrap();
    std::fs::write(
        d.join("light.toml"),
        text.replace("period_s = 0.5\n", "period_s = 1e-6\n"),
    )
    .unwrap();
    for (file, dir) in [("ok.toml", "ok"), ("light.toml", "light")] {
        let out = pounding()
            .current_dir(&d)
            .args(["simulate", file, "--out", dir])
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{err}");
        let s = summary(&d.join(dir));
        let period: Vec<&Value> = s["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|w| w["kind"] == "segment_period_unresolved")
            .collect();
        if dir == "ok" {
            assert!(period.is_empty(), "{period:?}");
            continue;
        }
        assert_eq!(period.len(), 1, "{period:?}");
        assert_eq!(period[0]["segment"], 2);
        let t = period[0]["period_s"].as_f64().unwrap();
        assert!(t > 0.0 && t <= 1e-6 * (1.0 + 1e-9), "{t}");
        assert!(err.contains("segment 2's shortest natural period"), "{err}");
        let html = std::fs::read_to_string(d.join(dir).join("report.html")).unwrap();
        assert!(
            html.contains("segment 2&#39;s shortest natural period")
                || html.contains("segment 2's shortest natural period"),
            "report.html lists the warning"
        );
    }
}
