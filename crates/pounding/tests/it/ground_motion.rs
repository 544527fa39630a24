//! Ground-motion readers and evaluation.

use pounding::ground_motion::{
    AccelUnits, G0, GroundMotion, GroundMotionError, Record, el_centro_1940,
};

fn line_of(e: &GroundMotionError) -> usize {
    match e {
        GroundMotionError::Parse { line, .. } => *line,
        other => panic!("expected a parse error, got {other:?}"),
    }
}

const HEAD: &str = "PEER NGA STRONG MOTION DATABASE RECORD\nTest event, 1/1/2000, Station, 000\nACCELERATION TIME SERIES IN UNITS OF G\n";

#[test]
fn embedded_el_centro_matches_the_provenance_table() {
    // Independent evidence: data/records/README.md (PGA values and times, counts, dt).
    let gm = el_centro_1940();
    let y = gm.along_y.as_ref().unwrap();
    let x = gm.along_x.as_ref().unwrap();
    assert_eq!(y.times().len(), 5372);
    assert_eq!(x.times().len(), 5346);
    assert!((y.times()[1] - 0.01).abs() < 1e-15);
    assert!((y.end_time() - 53.71).abs() < 1e-9);
    let (iy, py) = y
        .values()
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .unwrap();
    assert!((py.abs() / G0 - 0.2808).abs() < 5e-5 && *py < 0.0, "{py}");
    assert!((y.times()[iy] - 2.18).abs() < 1e-9);
    assert!((x.pga() / G0 - 0.2107).abs() < 5e-5);
    // first sample of the file: .9984852E-03 g
    assert!((y.values()[0] - 0.9984852e-3 * G0).abs() < 1e-15);
    assert_eq!(gm.end_time(), y.end_time());
}

#[test]
fn embedded_records_are_the_shared_files() {
    let Some(dir) = crate::common::shared_dir() else {
        return;
    };
    for (name, text) in [
        (
            "RSN6_IMPVALL.I_I-ELC180-hor1.AT2",
            pounding::ground_motion::EL_CENTRO_180_AT2,
        ),
        (
            "RSN6_IMPVALL.I_I-ELC270-hor2.AT2",
            pounding::ground_motion::EL_CENTRO_270_AT2,
        ),
    ] {
        let shared = std::fs::read_to_string(dir.join("data/records").join(name)).unwrap();
        assert_eq!(shared, text, "{name}");
    }
}

#[test]
fn both_at2_header_styles_give_the_same_record() {
    let data = "  .1000000E+00  -.2000000E+00  .3000000E+00\n  .4D+00 -.5E+00\n";
    let new = format!("{HEAD}NPTS=      5, DT=   .0200 SEC,\n{data}");
    let old = format!("{HEAD}    5   .0200    NPTS, DT\n{data}");
    let a = Record::from_at2_str(&new, "new").unwrap();
    let b = Record::from_at2_str(&old, "old").unwrap();
    assert_eq!(a.times(), b.times());
    assert_eq!(a.values(), b.values());
    assert_eq!(a.values().len(), 5);
    assert!((a.values()[3] - 0.4 * G0).abs() < 1e-14);
    assert!((a.end_time() - 0.08).abs() < 1e-15);
}

#[test]
fn interpolation_is_linear_and_zero_outside() {
    let r = Record::uniform("r", 0.1, vec![0.0, 1.0, -3.0]).unwrap();
    assert_eq!(r.accel(0.05), 0.5);
    assert!((r.accel(0.125) - 0.0).abs() < 1e-12);
    assert!((r.accel(0.2) + 3.0).abs() < 1e-12);
    assert_eq!(r.accel(0.2000001), 0.0);
    assert_eq!(r.accel(-0.01), 0.0);
    assert_eq!(r.accel(f64::NAN), 0.0);
    // sample_uniform agrees with accel on a grid that does not align with the samples
    let h = 0.013;
    let s = r.sample_uniform(h, 30);
    for (k, v) in s.iter().enumerate() {
        assert!((v - r.accel(k as f64 * h)).abs() < 1e-12, "k = {k}");
    }
}

#[test]
fn csv_reader_units_header_and_nonuniform_times() {
    let text = "time,acc (g)\n# comment\n0, 0.1\n0.02,0.2\n\n0.05,-0.1\n";
    let r = Record::from_csv_str(text, "c.csv", AccelUnits::G).unwrap();
    assert_eq!(r.times(), &[0.0, 0.02, 0.05]);
    assert!((r.accel(0.035) - 0.05 * G0).abs() < 1e-12);
    // The header says g: reading the file in m/s² is refused (it used to be read silently).
    let e = Record::from_csv_str(text, "c.csv", AccelUnits::MetresPerSecondSquared).unwrap_err();
    assert!(e.to_string().contains("c.csv:1"), "{e}");
    let plain = text.replace("acc (g)", "acc");
    let m = Record::from_csv_str(&plain, "c.csv", AccelUnits::MetresPerSecondSquared).unwrap();
    assert!((m.values()[1] - 0.2).abs() < 1e-15);
}

#[test]
fn shared_chopra_csv_reads() {
    let Some(dir) = crate::common::shared_dir() else {
        return;
    };
    let p = dir.join("data/records/elcentro_chopra.csv");
    let r = Record::from_path(&p, AccelUnits::G).unwrap();
    assert_eq!(r.times().len(), 1560);
    assert!((r.pga() / G0 - 0.3188).abs() < 5e-4, "{}", r.pga() / G0);
}

#[test]
fn malformed_at2_files_report_the_line() {
    // bad token on line 6
    let t = format!("{HEAD}NPTS= 4, DT= .01 SEC\n .1 .2\n .3 x.4\n");
    let e = Record::from_at2_str(&t, "bad.AT2").unwrap_err();
    assert_eq!(line_of(&e), 6);
    assert!(e.to_string().contains("bad.AT2:6"), "{e}");
    // too few values
    let t = format!("{HEAD}NPTS= 4, DT= .01 SEC\n .1 .2\n .3\n");
    let e = Record::from_at2_str(&t, "short").unwrap_err();
    assert!(e.to_string().contains("NPTS = 4"), "{e}");
    // too many values: error on the line of the 5th value
    let t = format!("{HEAD}NPTS= 4, DT= .01 SEC\n .1 .2\n .3 .4 .5\n");
    assert_eq!(line_of(&Record::from_at2_str(&t, "long").unwrap_err()), 6);
    // dt <= 0 and NaN dt
    for dt in ["0.0", "-.01", "nan"] {
        let t = format!("{HEAD}NPTS= 2, DT= {dt} SEC\n .1 .2\n");
        let e = Record::from_at2_str(&t, "dt").unwrap_err();
        assert_eq!(line_of(&e), 4, "{e}");
    }
    // missing NPTS line
    let e = Record::from_at2_str("only\ntwo lines\n", "hdr").unwrap_err();
    assert!(e.to_string().contains("header"), "{e}");
    // non-numeric old-style header
    let t = format!("{HEAD}abc def\n .1\n");
    assert_eq!(line_of(&Record::from_at2_str(&t, "h").unwrap_err()), 4);
}

#[test]
fn malformed_csv_files_report_the_line() {
    let e = Record::from_csv_str("t,a\n0,1\n0.1,2\n0.1,3\n", "c", AccelUnits::G).unwrap_err();
    assert_eq!(line_of(&e), 4);
    let e = Record::from_csv_str("0,1\n0.1,zz\n", "c", AccelUnits::G).unwrap_err();
    assert_eq!(line_of(&e), 2);
    let e = Record::from_csv_str("0,1\n0.1,2,3\n", "c", AccelUnits::G).unwrap_err();
    assert_eq!(line_of(&e), 2);
    assert!(Record::from_csv_str("t,a\n", "c", AccelUnits::G).is_err());
    let e =
        Record::from_path(std::path::Path::new("/nonexistent/x.AT2"), AccelUnits::G).unwrap_err();
    assert!(matches!(e, GroundMotionError::Io { .. }), "{e}");
}

#[test]
fn incidence_angle_and_scales_rotate_the_components() {
    let ry = Record::uniform("y", 1.0, vec![1.0, 1.0]).unwrap();
    let rx = Record::uniform("x", 1.0, vec![2.0, 2.0]).unwrap();
    let mut gm = GroundMotion {
        along_y: Some(ry),
        scale_y: 0.5,
        along_x: Some(rx),
        scale_x: -1.0,
        incidence: 0.0,
    };
    let a = gm.accel(0.5);
    assert!((a.x + 2.0).abs() < 1e-15 && (a.y - 0.5).abs() < 1e-15);
    gm.incidence = std::f64::consts::FRAC_PI_2; // y-component now along −x, x-component along +y
    let a = gm.accel(0.5);
    assert!(
        (a.x + 0.5).abs() < 1e-12 && (a.y + 2.0).abs() < 1e-12,
        "{a:?}"
    );
    let s = gm.sample_uniform(0.25, 8);
    assert_eq!(s.len(), 9);
    assert!((s[2] - a).norm() < 1e-12);
    assert_eq!(s[8], pounding::math::Vector::zeros()); // t = 2 > last sample
    gm.scale_x = f64::NAN;
    assert!(gm.validate().is_err());
}
