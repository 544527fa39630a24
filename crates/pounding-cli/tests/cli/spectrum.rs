//! `pounding spectrum` (issue 13): `spectrum.csv` columns and rows, period and damping read back
//! exactly as given, a pair's four components, the same numbers as the library, bad input exits
//! 2 and writes nothing.

use crate::{run_capture, scratch_dir};

#[test]
fn spectrum_writes_rows_that_read_back_as_given() {
    let d = scratch_dir("spectrum", "rows");
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "spectrum",
        "builtin:ELC180",
        "--pair",
        "builtin:ELC180",
        "builtin:ELC270",
        "--periods",
        "0.1,0.3,1.7",
        "--damping",
        "0.02",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(out.join("spectrum.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("record,component,period_s,damping,psa_g,psv_m_s,sd_m")
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 5 * 3);
    let comps: Vec<&str> = rows.iter().map(|r| r[1]).collect();
    assert_eq!(&comps[..3], &["x", "x", "x"]);
    assert_eq!(
        &comps[3..],
        &[
            "x", "x", "x", "y", "y", "y", "rotd50", "rotd50", "rotd50", "rotd100", "rotd100",
            "rotd100"
        ]
    );
    for (r, t) in rows.iter().zip([0.1, 0.3, 1.7].iter().cycle()) {
        assert_eq!(r[2].parse::<f64>().unwrap(), *t);
        assert_eq!(r[3], "0.02");
    }
    // the pair's x equals the single record's x; RotD50 <= RotD100; PSA = ω² S_d / g
    for k in 0..3 {
        assert_eq!(rows[k][4..], rows[3 + k][4..]);
        let (r50, r100): (f64, f64) = (
            rows[9 + k][4].parse().unwrap(),
            rows[12 + k][4].parse().unwrap(),
        );
        assert!(r50 <= r100 && r50 > 0.0);
        let t: f64 = rows[k][2].parse().unwrap();
        let sd: f64 = rows[k][6].parse().unwrap();
        let psa: f64 = rows[k][4].parse().unwrap();
        let w = 2.0 * std::f64::consts::PI / t;
        assert!((psa - w * w * sd / 9.80665).abs() < 1e-12 * psa);
    }
    assert!(out.join("spectrum.png").is_file());
}

#[test]
fn bad_spectrum_input_exits_2_and_writes_nothing() {
    let d = scratch_dir("spectrum", "bad");
    for (i, args) in [
        &[][..],
        &["builtin:ELC180", "--damping", "1"],
        &["builtin:ELC180", "--damping", "-0.1"],
        &["builtin:ELC180", "--periods", "0.1,0"],
        &["builtin:ELC180", "--periods", "0.1,nan"],
        &["builtin:ELC180", "--periods", "1,0.5,1"],
        &["builtin:NOPE"],
        &["/no/such/file.AT2"],
        &["--pair", "builtin:ELC180"],
        &["builtin:ELC180", "--csv-units", "furlongs"],
    ]
    .iter()
    .enumerate()
    {
        let out = d.join(format!("out{i}"));
        let mut a = vec!["spectrum"];
        a.extend_from_slice(args);
        a.extend_from_slice(&["--out", out.to_str().unwrap()]);
        let (code, _, err) = run_capture(&a);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(!err.contains("panicked"));
        assert!(!out.exists(), "{args:?} wrote outputs");
    }
}
