//! Record files on the command line that must never be silently misread (issue 12, round 4):
//! comment units of one-column files, two values a line with `--record-dt`, `builtin:` records
//! in `--records`, the scenario's `record_dt` for `--record`, a scenario given as `--record`,
//! records given twice, and a byte-order mark on the shared El Centro CSV.

use crate::{run_capture, scratch_dir, skipped};
use std::path::{Path, PathBuf};

fn write(d: &Path, name: &str, text: &str) -> PathBuf {
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Runs `pounding` with the whitespace-separated words of `cmd` (scratch paths have no
/// spaces): (exit code, stderr).
fn run(cmd: &str) -> (Option<i32>, String) {
    let words: Vec<&str> = cmd.split_whitespace().collect();
    let (code, _, err) = run_capture(&words);
    (code, err)
}

/// Runs `pounding simulate --record RECORD FLAGS --out OUT`: (exit code, stderr).
fn simulate_record(record: &Path, flags: &str, out: &Path) -> (Option<i32>, String) {
    run(&format!(
        "simulate --record {} {flags} --out {}",
        s(record),
        s(out)
    ))
}

/// `n` samples of a small decaying sine (in g), one a line.
fn one_column(n: usize) -> String {
    (0..n)
        .map(|k| {
            let t = k as f64 * 0.01;
            format!("{:.6}\n", 0.2 * (7.0 * t).sin() * (-0.5 * t).exp())
        })
        .collect()
}

#[test]
fn a_one_column_record_whose_comment_names_other_units_exits_2_and_writes_nothing() {
    let d = scratch_dir("misreads", "comment");
    let p = write(
        &d,
        "a.txt",
        &format!("# acceleration (m/s^2)\n{}", one_column(50)),
    );
    let out = d.join("o");
    let (code, err) = simulate_record(&p, "--record-dt 0.01", &out);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("a.txt:1") && err.contains("--csv-units m/s2"),
        "{err}"
    );
    assert!(!out.exists(), "an error wrote {}", out.display());
    // the units the comment names, given: read and run
    let (code, err) = simulate_record(&p, "--record-dt 0.01 --csv-units m/s2", &out);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("units m/s2 (--csv-units), dt_s 0.01, npts 50"),
        "{err}"
    );
}

#[test]
fn two_values_a_line_with_record_dt_exits_2() {
    let d = scratch_dir("misreads", "twoval");
    let p = write(&d, "ta.txt", "0 0.1\n0.01 0.2\n0.02 -0.1\n");
    let out = d.join("o");
    let (code, err) = simulate_record(&p, "--record-dt 0.01", &out);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("ta.txt:1")
            && err.contains("ambiguous")
            && err.contains("--record-dt")
            && err.contains("split the file"),
        "{err}"
    );
    assert!(!out.exists());
}

#[test]
fn builtin_records_run_in_a_batch_and_repeats_get_a_note() {
    let d = scratch_dir("misreads", "builtin");
    let out = d.join("o");
    let (code, err) = run(&format!(
        "simulate --records builtin:ELC180 builtin:ELC270 builtin:ELC180 --duration 0.3 --out {}",
        s(&out)
    ));
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("note: --records: builtin:ELC180 is given 2 times"),
        "{err}"
    );
    assert!(!err.contains("builtin:ELC270 is given"), "{err}");
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let st = head.iter().position(|h| *h == "status").unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 3, "{csv}");
    assert!(rows.iter().all(|r| r[st] == "Completed"), "{csv}");
    // a directory listed twice: noted too
    let recs = d.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    write(&recs, "r.csv", "t,a\n0,0\n0.01,0.1\n0.02,0\n");
    let (code, err) = run(&format!(
        "simulate --records {} {} --duration 0.05 --out {}",
        s(&recs),
        s(&recs),
        s(&d.join("o2"))
    ));
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("r.csv is given 2 times"), "{err}");
}

#[test]
fn the_scenarios_record_dt_reads_the_record_flag_file() {
    let d = scratch_dir("misreads", "scdt");
    write(&d, "own.txt", &one_column(20));
    let other = write(&d, "other.txt", &one_column(40));
    let sc = write(
        &d,
        "s.toml",
        "[ground_motion]\nrecord_y = \"own.txt\"\nrecord_x = \"none\"\nrecord_dt = 0.02\n",
    );
    let out = d.join("o");
    // the scenario's record_dt, then --record-dt replacing it
    for (flag, want) in [
        ("", "dt_s 0.02, npts 40"),
        ("--record-dt 0.01", "dt_s 0.01, npts 40"),
    ] {
        let (code, err) = run(&format!(
            "simulate {} --record {} {flag} --out {}",
            s(&sc),
            s(&other),
            s(&out)
        ));
        assert_eq!(code, Some(0), "{err}");
        assert!(err.contains(want), "{err}");
    }
}

#[test]
fn a_scenario_given_as_the_record_is_named() {
    let d = scratch_dir("misreads", "toml");
    let sc = write(&d, "my.toml", "[ground_motion]\nscale_y = 1\n");
    let (code, err) = simulate_record(&sc, "", &d.join("o"));
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("my.toml is a scenario file (.toml)") && err.contains("first"),
        "{err}"
    );
    assert!(!err.contains("cannot recognise"), "{err}");
}

#[test]
fn the_shared_el_centro_csv_with_a_byte_order_mark_reads_the_same() {
    let Some(shared) = std::env::var_os("POUNDING_SHARED").map(PathBuf::from) else {
        skipped("POUNDING_SHARED is not set: the shared El Centro CSV is absent");
        return;
    };
    let src = shared.join("data/records/elcentro_chopra.csv");
    let Ok(text) = std::fs::read_to_string(&src) else {
        skipped(&format!("{} is absent", src.display()));
        return;
    };
    let d = scratch_dir("misreads", "bom");
    let plain = write(&d, "plain.csv", &text);
    let bom = write(&d, "bom.csv", &format!("\u{feff}{text}"));
    let mut lines = Vec::new();
    for p in [&plain, &bom] {
        let (code, err) = simulate_record(p, "--duration 0.2", &d.join("o"));
        assert_eq!(code, Some(0), "{err}");
        let line = err
            .lines()
            .find(|l| l.starts_with("ground motion y:"))
            .unwrap()
            .to_string();
        lines.push(line.replace(s(p), "FILE"));
    }
    assert_eq!(lines[0], lines[1]);
}
