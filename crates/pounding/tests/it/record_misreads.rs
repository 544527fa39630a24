//! Record files that must never be silently misread (issue 12, round 4): the `#` comment lines of
//! every text format are read as headers (kind and units), two values a line with a sample
//! interval is ambiguous, swapped or semicolon-separated columns name the accepted formats,
//! `builtin:` records open anywhere, the scenario's `record_dt` applies to `--record`, and the
//! cosmetics of messages (capped quotes, byte-order marks, a missing NPTS, an empty key).

use crate::record_formats::{dir, opts, write};
use pounding::ground_motion::{AccelUnits, G0, GroundMotionError, ReadOptions, Record};
use pounding::sim::scenario::Scenario;
use std::path::Path;

fn err(p: &Path, o: &ReadOptions) -> String {
    match Record::from_path_with(p, o) {
        Ok(r) => panic!("{} read as {:?}", p.display(), r.values()),
        Err(e) => e.to_string(),
    }
}

#[test]
fn one_column_comment_units_are_checked_against_the_units_in_force() {
    let d = dir("onecol-units");
    let p = write(&d, "a.txt", "# acceleration (m/s^2)\n0.1\n0.2\n-0.3\n");
    // read in g (the default), the comment's m/s² disagrees: refused, naming file, line, the fix
    let e = err(&p, &opts(AccelUnits::G, Some(0.01)));
    assert!(
        e.contains("a.txt:1") && e.contains("M/S^2") && e.contains("csv_units = \"m/s2\""),
        "{e}"
    );
    // read in m/s²: the values are taken as they are (not 9.8 times larger)
    let r =
        Record::from_path_with(&p, &opts(AccelUnits::MetresPerSecondSquared, Some(0.01))).unwrap();
    assert_eq!(r.values(), &[0.1, 0.2, -0.3]);
    // several values a line (OpenSees Path), the same check
    let p = write(
        &d,
        "b.txt",
        "# accelerations in units of g\n0.1 0.2 0.3\n0.4 0.5 0.6\n",
    );
    let e = err(&p, &opts(AccelUnits::MetresPerSecondSquared, Some(0.01)));
    assert!(
        e.contains("b.txt:1") && e.contains("csv_units = \"g\""),
        "{e}"
    );
    let r = Record::from_path_with(&p, &opts(AccelUnits::G, Some(0.01))).unwrap();
    assert_eq!(r.values().len(), 6);
    assert!((r.values()[5] - 0.6 * G0).abs() < 1e-12);
}

#[test]
fn comment_kind_and_unknown_units_are_refused_in_every_text_format() {
    let d = dir("kinds");
    let cases: [(&str, &str, Option<f64>, &str); 7] = [
        (
            "v.txt",
            "# velocity (cm/s)\n0.1\n0.2\n0.3\n",
            Some(0.01),
            "velocity",
        ),
        (
            "w.txt",
            "# a (cm/s)\n0.1\n0.2\n0.3\n",
            Some(0.01),
            "velocity",
        ),
        ("g.txt", "# a (gal)\n1\n2\n3\n", Some(0.01), "convert"),
        (
            "u.txt",
            "# a (furlong/s/s)\n1\n2\n3\n",
            Some(0.01),
            "unknown units",
        ),
        ("c.csv", "# units: gal\n0,0.1\n0.01,0.2\n", None, "convert"),
        (
            "d.csv",
            "# displacement record\nt,x\n0,0.1\n0.01,0.2\n",
            None,
            "displacement",
        ),
        (
            "t.txt",
            "# station 5\n# a in gal\n0 1\n0.01 2\n",
            None,
            "t.txt:2",
        ),
    ];
    for (name, text, dt, want) in cases {
        let p = write(&d, name, text);
        let e = err(&p, &opts(AccelUnits::G, dt));
        assert!(e.contains(want) && e.contains(name), "{name}: {e}");
    }
}

#[test]
fn plain_comments_are_not_taken_for_units() {
    let d = dir("plain");
    let text = "# El Centro 1940, station 117, PGA 0.3 g, 1 component\n0.1\n0.2\n0.3\n";
    let p = write(&d, "a.txt", text);
    for u in [AccelUnits::G, AccelUnits::MetresPerSecondSquared] {
        let r = Record::from_path_with(&p, &opts(u, Some(0.01))).unwrap();
        assert!((r.values()[2] - 0.3 * u.factor()).abs() < 1e-12);
    }
}

#[test]
fn a_gal_header_says_to_convert_not_to_set_an_impossible_csv_units() {
    let d = dir("galhdr");
    for (name, text) in [
        ("a.csv", "t,a (gal)\n0,1\n0.01,2\n"),
        ("b.csv", "t [s],acc [cm/s^2]\n0,1\n0.01,2\n"),
    ] {
        let p = write(&d, name, text);
        let e = err(&p, &opts(AccelUnits::G, None));
        assert!(
            e.contains(&format!("{name}:1"))
                && e.contains("g or m/s2 only")
                && e.contains("convert")
                && !e.contains("set csv_units to match"),
            "{e}"
        );
    }
}

#[test]
fn two_values_a_line_with_a_sample_interval_is_ambiguous() {
    let d = dir("twoval");
    // increasing first column (t a) and not (two components): both refused
    for (name, text) in [
        ("ta.txt", "0 0.1\n0.01 0.2\n0.02 0.3\n"),
        ("xy.txt", "0.1 -0.2\n-0.3 0.05\n0.2 0.1\n"),
    ] {
        let p = write(&d, name, text);
        let e = err(&p, &opts(AccelUnits::G, Some(0.01)));
        assert!(
            e.contains(name)
                && e.contains("ambiguous")
                && e.contains("remove the interval (--record-dt)")
                && e.contains("split the file"),
            "{e}"
        );
    }
    // three values on a line: a sequence, read
    let p = write(&d, "seq.txt", "0.1 -0.2\n-0.3 0.05 0.4\n");
    let r = Record::from_path_with(&p, &opts(AccelUnits::G, Some(0.01))).unwrap();
    assert_eq!(r.values().len(), 5);
}

#[test]
fn non_increasing_times_swapped_headers_and_semicolons_list_the_formats() {
    let d = dir("swap");
    let p = write(&d, "x.txt", "0.1 0\n-0.2 0.01\n");
    let e = err(&p, &opts(AccelUnits::G, None));
    assert!(
        e.contains("x.txt:2")
            && e.contains("does not increase")
            && e.contains("accepted record formats"),
        "{e}"
    );
    for (name, text) in [
        ("s.csv", "a,t\n0.1,0\n-0.2,0.01\n"),
        ("s.txt", "# acc time\n0.1 0\n-0.2 0.01\n"),
    ] {
        let p = write(&d, name, text);
        let e = err(&p, &opts(AccelUnits::G, None));
        assert!(
            e.contains(&format!("{name}:1")) && e.contains("swapped"),
            "{e}"
        );
    }
    let p = write(&d, "semi.csv", "t;a\n0;0.1\n0.01;0.2\n");
    let e = err(&p, &opts(AccelUnits::G, None));
    assert!(
        e.contains("semi.csv:2")
            && e.contains("semicolons")
            && e.contains("accepted record formats"),
        "{e}"
    );
}

#[test]
fn builtin_records_open_like_files() {
    let r = Record::open_with(Path::new("builtin:ELC180"), &ReadOptions::default()).unwrap();
    assert_eq!(r.times().len(), 5372);
    assert!((r.pga() / G0 - 0.281).abs() < 0.005, "{}", r.pga() / G0);
    let e = Record::open_with(Path::new("builtin:ELC999"), &ReadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("builtin:ELC999") && e.contains("builtin:ELC180"),
        "{e}"
    );
    // an explicit interval is refused, the scenario's default is not applied
    let explicit = opts(AccelUnits::G, Some(0.01));
    let e = Record::open_with(Path::new("builtin:ELC270"), &explicit)
        .unwrap_err()
        .to_string();
    assert!(e.contains("does not apply"), "{e}");
    let default = ReadOptions {
        dt_default: true,
        ..explicit
    };
    let r = Record::open_with(Path::new("builtin:ELC270"), &default).unwrap();
    assert_eq!(r.dt(), Some(0.01));
}

#[test]
fn the_scenarios_record_dt_reads_a_record_override() {
    let d = dir("scdt");
    write(&d, "own.txt", "0.1\n0.2\n0.3\n");
    let other = write(&d, "other.txt", "0.1\n-0.1\n0.2\n0.05\n");
    let at2 = write(
        &d,
        "r.AT2",
        "PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 3, DT= .005 SEC\n0 0.1 0\n",
    );
    let sc = write(
        &d,
        "s.toml",
        "[ground_motion]\nrecord_y = \"own.txt\"\nrecord_x = \"none\"\nrecord_dt = 0.02\n",
    );
    let setup = Scenario::load(&sc)
        .unwrap()
        .with_record(&other, None)
        .build()
        .unwrap();
    let c = setup.problem.ground.components();
    assert_eq!((c.len(), c[0].npts, c[0].dt), (1, 4, Some(0.02)));
    // a file with its own times keeps them (the scenario's record_dt is a default)
    let setup = Scenario::load(&sc)
        .unwrap()
        .with_record(&at2, None)
        .build()
        .unwrap();
    let c = setup.problem.ground.components();
    assert_eq!((c[0].npts, c[0].dt), (3, Some(0.005)));
    // a two-column file: ambiguous, and the message says where the interval came from
    let two = write(&d, "two.txt", "0 0.1\n0.01 0.2\n");
    let e = Scenario::load(&sc)
        .unwrap()
        .with_record(&two, None)
        .build()
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("ambiguous") && e.contains("record_dt (") && e.contains("s.toml"),
        "{e}"
    );
}

#[test]
fn quoted_text_is_capped() {
    let d = dir("cap");
    let p = write(&d, "nul.txt", &"\0".repeat(1 << 20));
    let e = err(&p, &ReadOptions::default());
    assert!(
        e.contains("nul.txt:1") && e.contains('…') && e.len() < 1000,
        "{} bytes",
        e.len()
    );
    let long = format!("0 0.1\n0.01 {}\n", "x".repeat(5000));
    let p = write(&d, "long.txt", &long);
    let e = err(&p, &ReadOptions::default());
    assert!(e.contains("long.txt:2") && e.len() < 1000, "{e}");
}

#[test]
fn a_leading_byte_order_mark_is_ignored() {
    let d = dir("bom");
    for (name, text, dt) in [
        ("a.csv", "\u{feff}0,0.1\n0.01,0.2\n", None),
        ("h.csv", "\u{feff}t,a\n0,0.1\n0.01,0.2\n", None),
        ("c.txt", "\u{feff}0 0.1\n0.01 0.2\n", None),
        ("s.txt", "\u{feff}0.1\n0.2\n0.3\n", Some(0.01)),
        (
            "r.AT2",
            "\u{feff}PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 2, DT= .01 SEC\n0.1 0.2\n",
            None,
        ),
    ] {
        let p = write(&d, name, text);
        let r = Record::from_path_with(&p, &opts(AccelUnits::G, dt))
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!((r.values()[1] - 0.2 * G0).abs() < 1e-12, "{name}");
    }
    let r = Record::from_csv_str("\u{feff}0,0.1\n0.01,0.2\n", "x", AccelUnits::G).unwrap();
    assert_eq!(r.times().len(), 2);
}

#[test]
fn an_at2_without_npts_says_npts_is_missing() {
    let text = "PEER\nev\nACCELERATION TIME SERIES IN UNITS OF G\nDT= .01 SEC\n0.1 0.2\n";
    let e = Record::from_at2_str(text, "r.AT2").unwrap_err();
    let GroundMotionError::Parse { line, message, .. } = &e else {
        panic!("{e}")
    };
    assert_eq!(*line, 4);
    assert!(
        message.contains("NPTS is missing") && !message.contains("\"DT=\""),
        "{e}"
    );
}

#[test]
fn an_empty_record_key_is_named() {
    let d = dir("empty-key");
    let sc = write(
        &d,
        "s.toml",
        "[ground_motion]\nrecord_y = \"\"\nrecord_x = \"none\"\n",
    );
    let e = Scenario::load(&sc)
        .and_then(|s| s.build())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("record_y is empty") && e.contains("s.toml") && !e.contains("directory"),
        "{e}"
    );
}
