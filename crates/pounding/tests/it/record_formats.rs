//! Record formats (issue 12, "inputs that cannot be misread"): the format of a file is decided
//! from its extension and content in one place (`ground_motion::format::detect`); each format
//! reads the same motion to the same accelerations; units and sample intervals are never
//! silently reinterpreted.

use pounding::ground_motion::format::detect;
use pounding::ground_motion::{
    ACCEPTED_FORMATS, AccelUnits, EL_CENTRO_180_AT2, G0, GroundMotionError, ReadOptions, Record,
    RecordFormat,
};
use std::path::{Path, PathBuf};

/// The first `n` samples of the embedded El Centro 180 record, in g, and its dt (0.01 s).
fn elc(n: usize) -> Vec<f64> {
    EL_CENTRO_180_AT2
        .lines()
        .skip(4)
        .flat_map(|l| l.split_whitespace().map(|t| t.parse::<f64>().unwrap()))
        .take(n)
        .collect()
}

pub(crate) fn dir(name: &str) -> crate::scratch::Scratch {
    crate::scratch::scratch_dir("recfmt", name)
}

pub(crate) fn write(d: &Path, name: &str, text: &str) -> PathBuf {
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

pub(crate) fn opts(units: AccelUnits, dt: Option<f64>) -> ReadOptions {
    ReadOptions {
        units,
        units_from: "test".into(),
        dt,
        dt_from: "--record-dt".into(),
        dt_default: false,
    }
}

fn msg(e: GroundMotionError) -> String {
    e.to_string()
}

#[test]
fn every_text_format_of_one_motion_reads_the_same_accelerations_as_the_at2() {
    let g = elc(500);
    let d = dir("same");
    let at2 = format!(
        "PEER NGA STRONG MOTION DATABASE RECORD\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  {}, DT=   .0100 SEC\n{}\n",
        g.len(),
        g.iter()
            .map(|v| format!("{v:e}"))
            .collect::<Vec<_>>()
            .join("\n")
    );
    let at2_cm = at2.replace("UNITS OF G", "UNITS OF CM/S/S");
    let cm: Vec<String> = g.iter().map(|v| format!("{}", v * G0 * 100.0)).collect();
    let at2_cm = format!(
        "{}\n{}\n",
        at2_cm.lines().take(4).collect::<Vec<_>>().join("\n"),
        cm.join("  ")
    );
    let t = |i: usize| format!("{}", i as f64 / 100.0);
    let csv: String = std::iter::once("t_s,a_g\n".to_string())
        .chain(g.iter().enumerate().map(|(i, v)| format!("{},{v}\n", t(i))))
        .collect();
    let cols: String = std::iter::once("# t [s]   a [g]\n".to_string())
        .chain(
            g.iter()
                .enumerate()
                .map(|(i, v)| format!("{}  {v}\n", t(i))),
        )
        .collect();
    let cols_ms2: String = g
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{}\t{}\n", t(i), v * G0))
        .collect();
    // OpenSees Path -dt file: 5 values a line, last line shorter
    let seq: String = g
        .chunks(5)
        .map(|c| {
            c.iter()
                .map(|v| format!("{v}"))
                .collect::<Vec<_>>()
                .join(" ")
                + "\n"
        })
        .collect();
    let reads = [
        (
            write(&d, "r.AT2", &at2),
            opts(AccelUnits::G, None),
            RecordFormat::At2,
            "G header",
        ),
        (
            write(&d, "cm.at2", &at2_cm),
            opts(AccelUnits::G, None),
            RecordFormat::At2,
            "CM/S/S header",
        ),
        (
            write(&d, "r.csv", &csv),
            opts(AccelUnits::G, None),
            RecordFormat::Csv,
            "g (test)",
        ),
        (
            write(&d, "r.txt", &cols),
            opts(AccelUnits::G, None),
            RecordFormat::Columns,
            "g (test)",
        ),
        (
            write(&d, "ms2.dat", &cols_ms2),
            opts(AccelUnits::MetresPerSecondSquared, None),
            RecordFormat::Columns,
            "m/s2 (test)",
        ),
        (
            write(&d, "seq.txt", &seq),
            opts(AccelUnits::G, Some(0.01)),
            RecordFormat::Sequence,
            "g (test)",
        ),
    ];
    let reference = Record::from_path_with(&reads[0].0, &reads[0].1).unwrap();
    assert_eq!(reference.times().len(), 500);
    for (p, o, fmt, units) in &reads {
        let text = std::fs::read_to_string(p).unwrap();
        assert_eq!(
            detect(p, &text, o.dt.is_some()).unwrap(),
            *fmt,
            "{}",
            p.display()
        );
        let r = Record::from_path_with(p, o).unwrap();
        assert_eq!(r.units(), *units, "{}", p.display());
        assert_eq!(r.dt(), Some(0.01), "{}", p.display());
        assert_eq!(r.times().len(), 500);
        for (k, (a, b)) in r.values().iter().zip(reference.values()).enumerate() {
            assert!(
                (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                "{} [{k}]: {a} vs {b}",
                p.display()
            );
            assert!((r.times()[k] - reference.times()[k]).abs() < 1e-12);
        }
        assert!((r.pga() - reference.pga()).abs() <= 1e-12 * reference.pga());
    }
}

#[test]
fn at2_header_variants_are_read() {
    let head = "PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\n";
    for line4 in [
        "NPTS= 1559, DT= .02 SEC",
        "NPTS=  4, DT=   .0200 SEC,",
        "npts = 4 , dt = 0.02 sec",
        "NPTS  =   4,   DT  =  .02  SEC",
        "     4    .0200    NPTS, DT",
        "NPTS=4,DT=.02SEC",
    ] {
        let n = if line4.contains("1559") { 1559 } else { 4 };
        let vals = vec!["1.0D-02"; n].join(" ");
        let text = format!("{head}{line4}\n{vals}\n");
        let r = Record::from_at2_str(&text, "v.AT2");
        let r = match r {
            Ok(r) => r,
            Err(e) if line4 == "NPTS=4,DT=.02SEC" => {
                // a unit glued to the number is refused with the line, not misread
                assert!(msg(e).contains("v.AT2:4"));
                continue;
            }
            Err(e) => panic!("{line4:?}: {e}"),
        };
        assert_eq!(r.times().len(), n, "{line4:?}");
        assert_eq!(r.dt(), Some(0.02), "{line4:?}");
        assert!(
            (r.values()[0] - 0.01 * G0).abs() < 1e-15,
            "Fortran D exponent: {line4:?}"
        );
    }
}

#[test]
fn velocity_and_displacement_files_are_refused_by_extension_and_header() {
    let d = dir("vel");
    let at2 =
        "PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0 1\n".to_string();
    for ext in ["VT2", "dt2"] {
        let p = write(&d, &format!("r.{ext}"), &at2);
        let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
        assert!(
            e.contains(&format!("r.{ext}:1")) && e.contains("velocity or displacement"),
            "{e}"
        );
    }
    let p = write(&d, "v.AT2", &at2.replace("ACCELERATION", "VELOCITY"));
    let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
    assert!(e.contains("v.AT2:3") && e.contains("VELOCITY"), "{e}");
}

#[test]
fn one_column_without_dt_asks_for_record_dt() {
    let d = dir("onecol");
    let p = write(&d, "a.txt", "# accelerations\n0.1\n0.2\n-0.1\n");
    let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
    assert!(
        e.contains("a.txt:2") && e.contains("record_dt") && e.contains("--record-dt"),
        "{e}"
    );
    // also a .csv of one column
    let p = write(&d, "a.csv", "0.1\n0.2\n");
    let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
    assert!(e.contains("a.csv:1") && e.contains("record_dt"), "{e}");
    let r = Record::from_path_with(&p, &opts(AccelUnits::G, Some(0.005))).unwrap();
    assert_eq!(r.times(), &[0.0, 0.005]);
    assert_eq!(r.dt(), Some(0.005));
}

#[test]
fn a_dt_for_a_file_with_its_own_times_is_refused_not_ignored() {
    let d = dir("dtown");
    let at2 = "PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0 1\n";
    for (name, text) in [
        ("r.AT2", at2),
        ("r.csv", "t,a\n0,0.1\n0.01,0.2\n"),
        ("r.txt", "0 0.1\n0.01 0.2\n0.02 0.3\n"),
    ] {
        let p = write(&d, name, text);
        let e = msg(Record::from_path_with(&p, &opts(AccelUnits::G, Some(0.02))).unwrap_err());
        assert!(e.contains(&format!("{name}:1")), "{e}");
        assert!(e.contains("--record-dt") && e.contains("remove"), "{e}");
    }
    // two accelerations on every line that do not increase may be two components: ambiguous,
    // refused (record_misreads::two_values_a_line_with_a_sample_interval_is_ambiguous)
    let p = write(&d, "s.txt", "0.1 -0.2\n-0.3 0.1\n");
    let e = msg(Record::from_path_with(&p, &opts(AccelUnits::G, Some(0.02))).unwrap_err());
    assert!(e.contains("ambiguous"), "{e}");
}

#[test]
fn an_unrecognised_file_lists_the_accepted_formats() {
    let d = dir("unrec");
    for (name, text, line) in [
        ("s.toml", "[decks]\nshape = \"straight\"\n", 1),
        ("x.txt", "# comment\ntime accel\n0 0.1\n", 2),
        ("e.txt", "\n# only comments\n", 1),
    ] {
        let p = write(&d, name, text);
        let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
        assert!(e.contains(&format!("{name}:{line}")), "{e}");
        assert!(e.contains(ACCEPTED_FORMATS), "{e}");
    }
    // three columns without a dt: not silently taken as t a
    let p = write(&d, "three.txt", "0 1 2\n");
    let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
    assert!(
        e.contains("3 values a line") && e.contains(ACCEPTED_FORMATS),
        "{e}"
    );
    // a later line that breaks the two-column layout names its line
    let p = write(&d, "bad.txt", "0 1\n0.01 2\n0.02\n");
    let e = msg(Record::from_path_with(&p, &ReadOptions::default()).unwrap_err());
    assert!(
        e.contains("bad.txt:3") && e.contains("two whitespace-separated"),
        "{e}"
    );
}

#[test]
fn irregular_times_have_no_dt() {
    let r = Record::new("r", vec![0.0, 0.01, 0.03], vec![0.0, 1.0, 0.0]).unwrap();
    assert_eq!(r.dt(), None);
    let r = Record::new("r", vec![0.0, 0.1, 0.2, 0.3], vec![0.0; 4]).unwrap();
    assert_eq!(r.dt(), Some(0.1));
}

mod scenario {
    use super::*;
    use pounding::sim::scenario::Scenario;

    fn load(d: &Path, toml: &str) -> Result<pounding::sim::scenario::SimSetup, String> {
        let p = write(d, "s.toml", toml);
        Scenario::load(&p)
            .and_then(|s| s.build())
            .map_err(|e| e.to_string())
    }

    #[test]
    fn record_dt_reads_a_one_column_scenario_record_in_csv_units() {
        let d = dir("sc-dt");
        let g = elc(300);
        let seq: String = g.iter().map(|v| format!("{}\n", v * G0)).collect();
        write(&d, "a.txt", &seq);
        let s = load(
            &d,
            "[ground_motion]\nrecord_y = \"a.txt\"\nrecord_x = \"none\"\nrecord_dt = 0.01\ncsv_units = \"m/s2\"\n",
        )
        .unwrap();
        let c = s.problem.ground.components();
        assert_eq!(c.len(), 1);
        assert_eq!(c[0].units, "m/s2 (csv_units)");
        assert_eq!((c[0].npts, c[0].dt), (300, Some(0.01)));
        let peak = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(
            (c[0].pga_g - peak).abs() < 1e-12,
            "{} vs {peak}",
            c[0].pga_g
        );
    }

    #[test]
    fn record_dt_errors_name_the_key_and_line() {
        let d = dir("sc-dt-err");
        write(&d, "a.txt", "0.1\n0.2\n");
        write(&d, "r.csv", "0,0.1\n0.01,0.2\n");
        for (toml, want) in [
            // one column, no dt
            (
                "[ground_motion]\nrecord_y = \"a.txt\"\nrecord_x = \"none\"\n",
                vec!["a.txt:1", "record_dt"],
            ),
            // dt for the built-in record
            (
                "[ground_motion]\nrecord_dt = 0.01\n",
                vec!["record_dt", "s.toml:2", "built-in"],
            ),
            // dt for a CSV with its own times
            (
                "[ground_motion]\nrecord_y = \"r.csv\"\nrecord_x = \"none\"\nrecord_dt = 0.01\n",
                vec!["r.csv:1", "s.toml:4", "remove it"],
            ),
            // not a positive interval
            (
                "[ground_motion]\nrecord_y = \"a.txt\"\nrecord_x = \"none\"\nrecord_dt = -0.01\n",
                vec!["record_dt", "s.toml:4", "> 0"],
            ),
            (
                "[ground_motion]\nrecord_y = \"none\"\nrecord_x = \"none\"\nrecord_dt = 0.01\n[time]\nduration = 1.0\n",
                vec!["record_dt", "none"],
            ),
        ] {
            let e = load(&d, toml).unwrap_err();
            for w in want {
                assert!(e.contains(w), "{toml:?}: want {w:?} in {e}");
            }
        }
    }
}

/// An AT2 with `line3` as its 3rd line and 4 samples.
fn at2_with(line3: &str) -> String {
    format!("PEER\nev\n{line3}\nNPTS=  4, DT= .01 SEC\n0.1 0.2 0.3 0.4\n")
}

#[test]
fn an_at2_header_line_naming_two_units_or_a_scaled_unit_is_refused() {
    for (l3, want) in [
        (
            "ACCELERATION TIME SERIES IN UNITS OF G (CM/S/S)",
            "names two different units",
        ),
        ("IN UNITS OF G, CM/S/S", "names two different units"),
        ("UNITS: G AND CM/S/S", "names two different units"),
        (
            "ACC IN UNITS OF G  COMPONENT: GAL",
            "names two different units",
        ),
        (
            "ACCELERATION (CM/S/S) IN UNITS OF G",
            "names two different units",
        ),
        ("IN UNITS OF G X 1000", "a scaled unit is not supported"),
        ("IN UNITS OF G*1000", "a scaled unit is not supported"),
        (
            "IN UNITS OF CM/S/S TIMES 10",
            "a scaled unit is not supported",
        ),
        ("ACCELERATION (G x1000)", "a scaled unit is not supported"),
        ("UNITS OF 1000 X GAL", "a scaled unit is not supported"),
    ] {
        let e = msg(Record::from_at2_str(&at2_with(l3), "u.AT2").unwrap_err());
        assert!(e.contains("u.AT2:3") && e.contains(want), "{l3}: {e}");
    }
    // one unit, written twice or with an azimuth before it, is still read
    for (l3, factor) in [
        ("ACCELERATION IN UNITS OF GAL (CM/S/S)", 0.01),
        ("EL CENTRO 180 (CM/S/S)", 0.01),
        ("ACCELERATION TIME SERIES IN UNITS OF G", G0),
    ] {
        let r = Record::from_at2_str(&at2_with(l3), "u.AT2").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(r.values()[3], 0.4 * factor, "{l3}");
    }
}

#[test]
fn csv_header_units_anywhere_in_a_cell_are_read_and_checked() {
    let body = "0,0.1\n0.01,0.2\n";
    let mps2 = AccelUnits::MetresPerSecondSquared;
    // units glued to the column name: read when they agree, refused (line 1, unit quoted) if not
    for (header, units, ok) in [
        ("t,a[gal]", AccelUnits::G, false),
        ("t,a(gal)", AccelUnits::G, false),
        ("t,a[g]", mps2, false),
        ("t,a[g]", AccelUnits::G, true),
        ("t,acc(m/s2)", mps2, true),
        ("t,acc(m/s2)", AccelUnits::G, false),
        ("t(sec),a(mm/s/s)", AccelUnits::G, false),
        ("t (s),a (cm/s^2)", AccelUnits::G, false),
        ("time_s, accel_g", AccelUnits::G, true),
        ("time,acc", mps2, true),
    ] {
        let r = Record::from_csv_str(&format!("{header}\n{body}"), "h.csv", units);
        match (r, ok) {
            (Ok(r), true) => assert_eq!(r.values()[1], 0.2 * units.factor(), "{header}"),
            (Err(e), false) => {
                let e = msg(e);
                assert!(
                    e.contains("h.csv:1") && e.contains("header names the units"),
                    "{header}: {e}"
                );
                let unit = e.split("units ").nth(1).unwrap().split(' ').next().unwrap();
                assert!(
                    ["GAL", "G", "M/S2", "MM/S/S", "CM/S^2"].contains(&unit),
                    "a unit quoted cleanly: {header}: {e}"
                );
            }
            (r, _) => panic!("{header} in {}: {r:?}", units.name()),
        }
    }
}

#[test]
fn csv_and_columns_headers_of_other_quantities_or_time_units_are_refused() {
    let body = "0,0.1\n0.01,0.2\n";
    for (header, want) in [
        ("time (s),velocity (cm/s)", "is a velocity"),
        ("t,displacement", "is a displacement"),
        ("t,vel", "is a velocity"),
        ("time (s),acc (cm/s)", "a unit of velocity or length"),
        ("t,a (cm)", "a unit of velocity or length"),
        ("t,a (mg)", "unknown units MG"),
        ("time (ms),acc (g)", "only seconds"),
        ("t (min),a (g)", "only seconds"),
        ("time_ms,acc", "only seconds"),
    ] {
        let e = msg(
            Record::from_csv_str(&format!("{header}\n{body}"), "h.csv", AccelUnits::G).unwrap_err(),
        );
        assert!(e.contains("h.csv:1") && e.contains(want), "{header}: {e}");
        if want.starts_with("unknown") || want.contains("velocity or length") {
            assert!(e.contains("accepted: G, CM/S/S"), "{header}: {e}");
        }
    }
    // columns `t a` under a `#` header line: checked the same way, on its line
    let cols = "0 0.1\n0.01 0.2\n";
    for (header, units, want) in [
        (
            "# t (s)   a (gal)",
            AccelUnits::G,
            Some("header names the units GAL"),
        ),
        (
            "# t (s)   a (g)",
            AccelUnits::MetresPerSecondSquared,
            Some("header names the units G"),
        ),
        (
            "# time (s)  velocity (cm/s)",
            AccelUnits::G,
            Some("is a velocity"),
        ),
        ("# t (ms)  a (g)", AccelUnits::G, Some("only seconds")),
        ("# t (s)   a (g)", AccelUnits::G, None),
        ("# El Centro 1940, component 180, in g", AccelUnits::G, None),
    ] {
        let text = format!("# a record\n{header}\n{cols}");
        match (Record::from_columns_str(&text, "c.txt", units), want) {
            (Err(e), Some(w)) => {
                let e = msg(e);
                assert!(e.contains("c.txt:2") && e.contains(w), "{header}: {e}");
            }
            (Ok(r), None) => assert_eq!(r.values()[1], 0.2 * units.factor()),
            (r, _) => panic!("{header}: {r:?}"),
        }
    }
}

/// An AT2 whose header names no units takes the units the user gave (`csv_units` /
/// `--csv-units`); one that names its units keeps them, whatever was given; without either the
/// PEER default g applies. The units label says which.
#[test]
fn an_at2_without_header_units_takes_the_given_units() {
    let d = dir("at2-given-units");
    let bare = write(&d, "bare.AT2", &at2_with("ACCELERATION TIME SERIES"));
    let named = write(
        &d,
        "named.AT2",
        &at2_with("ACCELERATION IN UNITS OF CM/S/S"),
    );
    let ms2 = opts(AccelUnits::MetresPerSecondSquared, None);
    let r = Record::from_path_with(&bare, &ms2).unwrap();
    assert_eq!(r.values(), &[0.1, 0.2, 0.3, 0.4]);
    assert!(
        r.units().contains("m/s2") && r.units().contains("names no units"),
        "{}",
        r.units()
    );
    let r = Record::from_path_with(&bare, &ReadOptions::default()).unwrap();
    assert_eq!(r.values()[3], 0.4 * 9.80665);
    assert!(r.units().contains("PEER default"), "{}", r.units());
    let r = Record::from_path_with(&named, &ms2).unwrap();
    assert_eq!(r.values()[3], 0.4 * 0.01);
    assert!(r.units().contains("CM/S/S header"), "{}", r.units());
}
