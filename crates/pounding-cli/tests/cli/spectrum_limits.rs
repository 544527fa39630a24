//! `pounding spectrum` at the limits a hostile tester found: a far-off sample time, a huge
//! `--record-dt` and a tiny period finish at once with the quasi-static / near-record numbers,
//! periods beyond the accepted range exit 2 and write nothing, and every record is echoed on
//! stderr as `simulate` does (units, dt, npts, duration, PGA; a warning for an implausible PGA).

use crate::{run_capture, scratch_dir};

/// Runs `pounding spectrum ARGS --out DIR/out` and returns (exit code, stderr, rows of
/// spectrum.csv without the header).
fn run(d: &std::path::Path, args: &[&str]) -> (Option<i32>, String, Vec<Vec<String>>) {
    let out = d.join("out");
    let mut a = vec!["spectrum"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let (code, _, err) = run_capture(&a);
    let rows = std::fs::read_to_string(out.join("spectrum.csv"))
        .map(|t| {
            t.lines()
                .skip(1)
                .map(|l| l.split(',').map(str::to_string).collect())
                .collect()
        })
        .unwrap_or_default();
    (code, err, rows)
}

fn psa(row: &[String]) -> f64 {
    row[4].parse().unwrap()
}

#[test]
fn spectrum_far_off_times_and_huge_record_dt_finish_with_the_right_peak() {
    let d = scratch_dir("spectrum-limits", "far");
    // a step to 0.1 g, then constant: the start's transient is the peak, whether the last
    // sample is 20 s or 1e12 s away (the run used to take hours at 1e12)
    let csv = |end: &str| format!("t,a\n0,0\n0.01,0.1\n{end},0.1\n");
    std::fs::write(d.join("near.csv"), csv("20")).unwrap();
    std::fs::write(d.join("far.csv"), csv("1e12")).unwrap();
    let near = d.join("near.csv");
    let far = d.join("far.csv");
    let (code, err, rows) = run(
        &d,
        &[
            near.to_str().unwrap(),
            far.to_str().unwrap(),
            "--periods",
            "0.5",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    let (a, b) = (psa(&rows[0]), psa(&rows[1]));
    assert!(a > 0.18 && a < 0.19, "{a}");
    assert!((a - b).abs() < 1e-12 * a, "near {a} vs far {b}");
    // 4 values 1e300 s apart: the oscillator follows the slow ramp to 0.4 g, then is released
    std::fs::write(d.join("v.txt"), "0.1\n0.2\n0.3\n0.4\n").unwrap();
    let v = d.join("v.txt");
    let (code, err, rows) = run(
        &d,
        &[
            v.to_str().unwrap(),
            "--record-dt",
            "1e300",
            "--periods",
            "0.5,1",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    for r in &rows {
        assert!((psa(r) - 0.4).abs() < 1e-12, "{r:?}");
    }
    // a period 1e8 times shorter than the sample interval: quasi-static, PSA = PGA
    let (code, err, rows) = run(&d, &["builtin:ELC180", "--periods", "1e-10"]);
    assert_eq!(code, Some(0), "{err}");
    let pga: f64 = err
        .split("pga_g ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        (psa(&rows[0]) - pga).abs() < 1e-4,
        "{} vs {pga}",
        psa(&rows[0])
    );
}

#[test]
fn spectrum_refuses_periods_beyond_the_range() {
    let d = scratch_dir("spectrum-limits", "range");
    for p in ["1e-101", "1,1e101"] {
        let (code, err, _) = run(&d, &["builtin:ELC180", "--periods", p]);
        assert_eq!(code, Some(2), "{p}: {err}");
        assert!(
            err.contains("[1e-100, 1e100]") && err.contains("--periods"),
            "{err}"
        );
        assert!(!d.join("out").exists());
    }
}

#[test]
fn spectrum_prints_how_each_record_was_read() {
    let d = scratch_dir("spectrum-limits", "echo");
    // m/s² values read as g: a PGA of 5 g is doubted, as simulate does
    std::fs::write(d.join("ms2.csv"), "t,a\n0,0\n0.01,5\n0.02,-3\n").unwrap();
    let f = d.join("ms2.csv");
    let (code, err, _) = run(
        &d,
        &[
            f.to_str().unwrap(),
            "--pair",
            "builtin:ELC180",
            "builtin:ELC270",
            "--periods",
            "1",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("ground motion "))
        .collect();
    assert_eq!(lines.len(), 3, "{err}");
    assert!(
        lines[0].starts_with("ground motion x: record ")
            && lines[0].contains("ms2.csv, units g (--csv-units), dt_s 0.01, npts 3")
            && lines[0].ends_with("pga_g 5.0000"),
        "{}",
        lines[0]
    );
    assert!(lines[1].starts_with("ground motion x: ") && lines[1].contains("ELC180"));
    assert!(lines[2].starts_with("ground motion y: ") && lines[2].contains("ELC270"));
    assert!(lines[1].contains("npts 5372") && lines[1].contains("dt_s 0.01"));
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning:")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(warnings[0].contains("ms2.csv") && warnings[0].contains("5.000 g"));
}

#[test]
fn spectrum_refuses_one_sample_records_and_overflowing_numbers() {
    // trial findings: a one-sample record gave an all-zero spectrum with exit 0, `--periods
    // 1e400` was reported as `period = inf`, and a PGA of 1e300 g printed as 301 digits
    let d = scratch_dir("spectrum-limits", "one");
    std::fs::write(d.join("one.csv"), "0,0.5\n").unwrap();
    let one = d.join("one.csv");
    for args in [
        vec![one.to_str().unwrap()],
        vec!["--pair", "builtin:ELC180", one.to_str().unwrap()],
    ] {
        let (code, err, _) = run(&d, &args);
        assert_eq!(code, Some(2), "{err}");
        assert!(
            err.contains("one.csv: 1 sample: a spectrum needs at least two"),
            "{err}"
        );
        assert!(!d.join("out").exists());
    }
    for (flag, value) in [("--periods", "1,1e400"), ("--damping", "1e999")] {
        let (code, err, _) = run(&d, &["builtin:ELC180", flag, value]);
        assert_eq!(code, Some(2), "{err}");
        let token = value.split(',').next_back().unwrap();
        assert!(
            err.contains(&format!("\"{token}\" is not a finite number")),
            "{err}"
        );
        assert!(!d.join("out").exists());
    }
    std::fs::write(d.join("huge.csv"), "t,a\n0,0\n0.01,1e300\n0.02,0\n").unwrap();
    let huge = d.join("huge.csv");
    let (code, err, _) = run(&d, &[huge.to_str().unwrap(), "--periods", "1"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("pga_g 1.0000e300"), "{err}");
    assert!(err.contains("has a PGA of 1.000e300 g"), "{err}");
}
