//! `pounding fragility`'s `report.html` says what was run and what it gave: the scenario, the
//! record set (synthetic or not), every limit state in words, a lead paragraph with the fitted
//! medians, and — for a scenario with `[code_check]` — each seated end's code seats beside the
//! runs' demand, whose counts are recomputed here from `runs.csv` and `pounding check`'s
//! `check.csv`. A bad `[code_check]` key stops the study before any run.

use crate::fragility::{SCENARIO, study_in};
use crate::run_capture;
use std::collections::HashMap;
use std::path::Path;

pub(crate) const CODE_CHECK: &str = "\n[code_check]\nground = \"C\"\na_gr_ms2 = 2.5\nimportance_class = 2\n\
displacement_m = 0.01\npier_height_m = 8.0\naashto_zone = 3\nsdc = \"D\"\njra_ground = \"II\"\n";

pub(crate) const SET: &str = "[[record]]\nid = \"NS\"\nx = \"builtin:ELC180\"\n\
[[record]]\nid = \"EW\"\nx = \"builtin:ELC270\"\n";

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// CSV text as rows of `column → cell`.
fn table(csv: &str) -> Vec<HashMap<String, String>> {
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    lines
        .map(|l| {
            head.iter()
                .zip(l.split(','))
                .map(|(h, c)| (h.to_string(), c.to_string()))
                .collect()
        })
        .collect()
}

/// The cells of the report's table row that starts with `<td>{first}</td>` (tags stripped).
fn report_row(html: &str, first: &str) -> Vec<String> {
    let at = html
        .find(&format!("<tr><td>{first}</td>"))
        .unwrap_or_else(|| panic!("no row {first}"));
    let row = &html[at..at + html[at..].find("</tr>").unwrap()];
    row.split("<td>")
        .skip(1)
        .map(|c| c.trim_end_matches("</td>").to_string())
        .collect()
}

#[test]
fn the_report_states_the_study_and_counts_the_code_check_from_the_runs() {
    let d = study_in("fragrep", "check", &format!("{SCENARIO}{CODE_CHECK}"), SET);
    let (code, _, err) = run_capture(&[
        "fragility",
        s(&d.join("bridge.toml")),
        "--out",
        s(&d.join("out")),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = run_capture(&[
        "check",
        s(&d.join("bridge.toml")),
        "--out",
        s(&d.join("chk")),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(d.join("out/report.html")).unwrap();
    // the study in words
    for want in [
        "bridge.toml",
        "2 segment(s), 1 joint(s), abutments none",
        "contact law</th><td class=\"l\">rigid",
        "2: 0 horizontal pair(s), 2 single component(s)",
        "not marked: no entry carries the `model` metadata",
        "an end leaves its seat",
        "peak impulse of an impact at any joint above 200000 N s",
        "<h2 id=\"answer\">Answer</h2>",
        "6 runs (2 records × 3 IM levels)",
    ] {
        assert!(html.contains(want), "report.html lacks {want:?}");
    }
    // the code check: per end, counts recomputed from runs.csv's per-end ratios × the seat
    // (0.1 m) against the seat, check.csv's governing seat and the design displacement
    let runs = table(&std::fs::read_to_string(d.join("out/runs.csv")).unwrap());
    let check = table(&std::fs::read_to_string(d.join("chk/check.csv")).unwrap());
    assert_eq!(check.len(), 4);
    let mut nonzero = 0;
    for c in &check {
        let end = &c["end"];
        let seat: f64 = c["seat_length_m"].parse().unwrap();
        let governing: f64 = c["governing_m"].parse().unwrap();
        let col = format!("seat_ratio_{}", end.replace('-', "_"));
        let peaks: Vec<f64> = runs
            .iter()
            .filter(|r| r["status"] == "Completed")
            .map(|r| r[&col].parse::<f64>().unwrap() * seat)
            .collect();
        assert_eq!(peaks.len(), 6);
        let count = |limit: f64| peaks.iter().filter(|p| **p > limit).count();
        let cells = report_row(&html, end);
        let n = cells.len();
        assert_eq!(
            cells[n - 3],
            format!("{} of 6", count(seat)),
            "{end} unseated"
        );
        assert_eq!(
            cells[n - 2],
            format!("{} of 6", count(governing)),
            "{end} beyond code"
        );
        assert_eq!(
            cells[n - 1],
            format!("{} of 6", count(0.01)),
            "{end} beyond design"
        );
        let largest = peaks.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(
            cells[n - 4],
            format!("{:.0} %", 100.0 * largest / seat),
            "{end}"
        );
        assert!(
            cells[n - 5].starts_with(&format!("{largest:.3} (")),
            "{end}: {cells:?}"
        );
        assert_eq!(cells[n - 6], c["verdict"], "{end}");
        nonzero += count(0.01) + count(seat);
    }
    assert!(
        nonzero > 0,
        "the counts are all zero: the test checks nothing"
    );
}

#[test]
fn without_code_check_there_is_no_code_section_and_a_bad_key_stops_the_study() {
    let d = study_in("fragrep", "plain", SCENARIO, SET);
    let (code, _, err) = run_capture(&[
        "fragility",
        s(&d.join("bridge.toml")),
        "--out",
        s(&d.join("out")),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let html = std::fs::read_to_string(d.join("out/report.html")).unwrap();
    assert!(!html.contains("id=\"code-check\""));
    // a bad value, and a per-segment list that does not fit the two-segment bridge: both found
    // before any run, naming the key
    for (name, from, to, key, also) in [
        (
            "bad",
            "a_gr_ms2 = 2.5",
            "a_gr_ms2 = -2.5",
            "code_check.a_gr_ms2",
            "bridge.toml:",
        ),
        (
            "len",
            "displacement_m = 0.01",
            "displacement_m = [0.01, 0.02, 0.03]",
            "code_check.displacement_m",
            "2 segments",
        ),
    ] {
        let bad = format!("{SCENARIO}{}", CODE_CHECK.replace(from, to));
        let d = study_in("fragrep", name, &bad, SET);
        let (code, _, err) = run_capture(&[
            "fragility",
            s(&d.join("bridge.toml")),
            "--out",
            s(&d.join("out")),
        ]);
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains(key) && err.contains(also), "{err}");
        assert!(!d.join("out").exists(), "{name}: an output was written");
    }
}
