//! Hardening (issue 15): inputs that used to panic, hang or be silently misread are refused as bad
//! input naming the key and the line.

use pounding::study::scenario::{MAX_GRID_VALUES, MAX_ROWS, Scenario, ScenarioError};

fn invalid(text: &str) -> (usize, String, String) {
    match Scenario::from_toml(text, "t.toml") {
        Err(ScenarioError::Invalid {
            line, key, reason, ..
        }) => (line, key, reason),
        other => panic!("expected Invalid for {text:?}, got {other:?}"),
    }
}

#[test]
fn a_grid_step_too_small_to_count_is_refused_not_wrapped() {
    // 1e-20 over 20 deg is 2e21 values: the count used to saturate, wrap to 0 and divide by zero.
    for step in ["1e-20", "1e-300", "5e-324", "1e-4"] {
        let text =
            format!("[grid]\ntheta1_deg = {{ start = -10.0, stop = 10.0, step = {step} }}\n");
        let (line, key, reason) = invalid(&text);
        assert_eq!((line, key.as_str()), (2, "grid.theta1_deg.step"), "{step}");
        assert!(reason.contains(&MAX_GRID_VALUES.to_string()), "{reason}");
    }
    // The largest admissible grid is still accepted.
    let text = "[grid]\ntheta1_deg = { start = 0.0, stop = 9.9999, step = 1e-4 }\n";
    let s = Scenario::from_toml(text, "t.toml").unwrap();
    assert_eq!(s.theta1.len(), MAX_GRID_VALUES);
}

#[test]
fn a_study_with_too_many_rows_is_refused_naming_the_grid() {
    // Two fine θ ranges and long lists multiply past the row limit without overflowing any one size.
    let many = |n: usize, lo: f64| {
        (0..n)
            .map(|i| format!("{}", lo + i as f64))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let text = format!(
        "[decks]\nbeta1_deg = [{}]\nbeta2_deg = [{}]\n[impact]\nmu = [{}]\n[grid]\n\
         theta1_deg = {{ start = -5.0, stop = 4.9999, step = 1e-4 }}\n\
         theta2_deg = {{ start = -5.0, stop = 4.9999, step = 1e-4 }}\n",
        many(100, 1.0),
        many(100, 1.0),
        many(100, 0.0)
    );
    let (line, key, reason) = invalid(&text);
    assert_eq!((line, key.as_str()), (8, "grid"));
    assert!(reason.contains(&MAX_ROWS.to_string()), "{reason}");
    let s = Scenario::default();
    assert_eq!(s.checked_row_count(), Some(254_016));
    assert!(s.check_size("x").is_ok());
}

#[test]
fn a_hand_built_oversized_scenario_is_an_error_in_compute_rows() {
    let mut s = Scenario::default();
    s.theta1.step = 1e-20; // bypasses from_toml's checks
    assert_eq!(s.theta1.len(), usize::MAX, "saturates, never wraps");
    assert_eq!(s.checked_row_count(), None);
    let shard = pounding::study::Shard::new(1, 1).unwrap();
    let e = pounding::study::compute_rows(&s, shard, &|_| {}).unwrap_err();
    assert!(e.to_string().contains("grid"), "{e}");
}

#[test]
fn a_ratio_range_whose_width_is_not_finite_is_refused() {
    for (lo, hi) in [("-1e308", "1e308"), ("-1e200", "1e200"), ("-6e11", "6e11")] {
        let text = format!("[grid]\nratio_min = {lo}\nratio_max = {hi}\n");
        let (line, key, reason) = invalid(&text);
        assert_eq!((line, key.as_str()), (3, "grid.ratio_max"), "{lo} {hi}");
        assert!(reason.contains("ratio_max - ratio_min"), "{reason}");
    }
    let s = Scenario::from_toml("[grid]\nratio_min = -5e11\nratio_max = 5e11\n", "t").unwrap();
    assert_eq!(s.ratio_max - s.ratio_min, 1e12);
}

#[test]
fn a_list_where_a_range_table_is_expected_is_an_error() {
    // Used to be read as { start = -1, stop = 0, step = 1 }.
    for text in [
        "[grid]\ntheta1_deg = [-1, 0, 1]\n",
        "[grid]\ntheta2_deg = [-1.0, 1.0, 0.5]\n",
        "grid = [1, 2]\n",
        "decks = [10.0, 0.5]\n",
        "impact = [[0.5], [0.5]]\n",
        "output = [true]\n",
    ] {
        match Scenario::from_toml(text, "t.toml") {
            Err(ScenarioError::Syntax { line, message, .. }) => {
                assert_eq!(line, text.lines().count(), "{text}");
                assert!(message.contains("expected a table"), "{text}: {message}");
            }
            other => panic!("{text:?}: {other:?}"),
        }
    }
    // Tables still work, inline and as sections.
    let s = Scenario::from_toml(
        "[grid]\ntheta1_deg = { start = -1, stop = 1, step = 1 }\n[grid.theta2_deg]\nstart = 0\nstop = 0\nstep = 1\n",
        "t",
    )
    .unwrap();
    assert_eq!(
        (s.theta1.values(), s.theta2.values()),
        (vec![-1.0, 0.0, 1.0], vec![0.0])
    );
}

mod records {
    use pounding::ground_motion::{AccelUnits, GroundMotionError, Record};

    const G0: f64 = 9.80665;

    fn at2(line3: &str, npts_line: &str) -> String {
        format!(
            "PEER NGA STRONG MOTION DATABASE RECORD\nSome event, station\n{line3}\n{npts_line}\n  .1E+00  -.2E+00\n"
        )
    }

    fn parse_line(e: GroundMotionError) -> (usize, String) {
        match e {
            GroundMotionError::Parse { line, message, .. } => (line, message),
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    #[test]
    fn velocity_and_displacement_series_are_refused_whatever_the_name() {
        for (l3, word) in [
            ("VELOCITY TIME SERIES IN UNITS OF CM/S", "VELOCITY"),
            ("DISPLACEMENT TIME SERIES IN UNITS OF CM", "DISPLACEMENT"),
            ("velocity time series in units of cm/s", "VELOCITY"),
        ] {
            let text = at2(l3, "NPTS=      2, DT=   .0100 SEC,");
            let (line, msg) = parse_line(Record::from_at2_str(&text, "x.AT2").unwrap_err());
            assert_eq!(line, 3, "{msg}");
            assert!(
                msg.contains(word) && msg.contains("not an acceleration"),
                "{msg}"
            );
        }
        // Through the file reader, a .VT2/.DT2 name is refused before anything else.
        let dir = crate::scratch::scratch_dir("vt2", "names");
        for ext in ["VT2", "dt2"] {
            let p = dir.join(format!("r.{ext}"));
            let text = at2(
                "ACCELERATION TIME SERIES IN UNITS OF G",
                "NPTS= 2, DT= .01 SEC",
            );
            std::fs::write(&p, text).unwrap();
            let e = Record::from_path(&p, AccelUnits::G).unwrap_err();
            assert!(e.to_string().contains("not an"), "{e}");
        }
    }

    #[test]
    fn header_units_are_converted_or_refused() {
        for (unit, factor) in [
            ("G", G0),
            ("CM/S/S", 0.01),
            ("CM/S^2", 0.01),
            ("GAL", 0.01),
            ("M/S/S", 1.0),
            ("M/S^2", 1.0),
        ] {
            let l3 = format!("ACCELERATION TIME SERIES IN UNITS OF {unit}");
            let r = Record::from_at2_str(&at2(&l3, "NPTS= 2, DT= .01 SEC"), "x.AT2").unwrap();
            assert_eq!(r.values(), &[0.1 * factor, -0.2 * factor], "{unit}");
        }
        let l3 = "ACCELERATION TIME SERIES IN UNITS OF FURLONG/S/S";
        let (line, msg) = parse_line(
            Record::from_at2_str(&at2(l3, "NPTS= 2, DT= .01 SEC"), "x.AT2").unwrap_err(),
        );
        assert_eq!(line, 3);
        assert!(
            msg.contains("FURLONG/S/S") && msg.contains("accepted"),
            "{msg}"
        );
    }

    #[test]
    fn a_repeated_npts_or_dt_is_refused() {
        let l3 = "ACCELERATION TIME SERIES IN UNITS OF G";
        for hdr in [
            "NPTS=      2, NPTS=      1, DT=   .0100 SEC,",
            "NPTS=      2, DT=   .0100 SEC, DT= .02",
        ] {
            let (line, msg) = parse_line(Record::from_at2_str(&at2(l3, hdr), "x.AT2").unwrap_err());
            assert_eq!(line, 4);
            assert!(msg.contains("given 2 times"), "{msg}");
        }
    }

    #[test]
    fn a_csv_record_starting_before_zero_is_refused() {
        let e =
            Record::from_csv_str("t,a\n-0.01,0.1\n0,0.2\n", "r.csv", AccelUnits::G).unwrap_err();
        assert!(e.to_string().contains("t >= 0"), "{e}");
        // Starting at or after zero is fine (zero acceleration before the first sample).
        let r = Record::from_csv_str("0.5,0.1\n0.6,0.2\n", "r.csv", AccelUnits::G).unwrap();
        assert_eq!(r.accel(0.2), 0.0);
    }
}

mod records_round2 {
    //! Found by the fresh-clone hostile trial: units written other than `UNITS OF`, DT in other
    //! units, a malformed first CSV row taken for a header.
    use pounding::ground_motion::{AccelUnits, Record};

    fn rec(line3: &str, line4: &str) -> Result<Record, String> {
        let text = format!("PEER\nTest\n{line3}\n{line4}\n100 200 300 400 500\n");
        Record::from_at2_str(&text, "x.AT2").map_err(|e| e.to_string())
    }

    #[test]
    fn units_are_recognised_wherever_the_header_writes_them() {
        let n5 = "NPTS=   5, DT=   .0100 SEC,";
        for (l3, l4, factor) in [
            ("ACCELERATION (CM/SEC**2)", n5, 0.01),
            ("ACCELERATION TIME SERIES, UNITS: CM/S/S", n5, 0.01),
            (
                "ACCELERATION",
                "NPTS=   5, DT=   .0100 SEC, UNITS OF CM/S/S",
                0.01,
            ),
            ("ACCELERATION IN G", n5, 9.80665),
            ("ACCELERATION (G)", n5, 9.80665),
            ("ACCELERATION IN M/S^2", n5, 1.0),
            ("ACCELERATION IN FT/SEC/SEC", n5, 0.3048),
            ("ACCELERATION TIME SERIES", n5, 9.80665), // none named: PEER's g
        ] {
            let r = rec(l3, l4).unwrap_or_else(|e| panic!("{l3} / {l4}: {e}"));
            assert_eq!(r.values()[0], 100.0 * factor, "{l3} / {l4}");
        }
    }

    #[test]
    fn unreadable_or_conflicting_units_and_dt_units_are_refused() {
        let n5 = "NPTS=   5, DT=   .0100 SEC,";
        for (l3, l4, want) in [
            ("ACCELERATION, UNITS: FURLONG", n5, "cannot read the units"),
            ("ACCELERATION IN KM/S/S", n5, "unknown units"),
            (
                "ACCELERATION IN CM/S/S",
                "NPTS= 5, DT= .01 SEC, UNITS OF G",
                "two different units",
            ),
            (
                "ACCELERATION IN G",
                "NPTS=   5, DT=   10 MSEC,",
                "only seconds",
            ),
        ] {
            let e = rec(l3, l4).unwrap_err();
            assert!(e.contains(want), "{l3} / {l4}: {e}");
        }
    }

    #[test]
    fn a_malformed_first_csv_row_is_an_error_not_a_header() {
        for text in [
            "0,0.1g\n0.01,0.2\n0.02,0.3\n",
            "0,nan\n0.01,0.2\n",
            "0.1g,0\n0.01,0.2\n",
        ] {
            let e = Record::from_csv_str(text, "r.csv", AccelUnits::G).unwrap_err();
            assert!(
                e.to_string().contains("r.csv") && e.to_string().contains("1"),
                "{text}: {e}"
            );
        }
        // A real header is still skipped.
        let r = Record::from_csv_str("time_s, accel_g\n0,0.1\n0.01,0.2\n", "r.csv", AccelUnits::G)
            .unwrap();
        assert_eq!(r.times().len(), 2);
    }
}

mod round2_more {
    use pounding::ground_motion::{AccelUnits, Record};
    use pounding::lcp::LemkeSettings;

    #[test]
    fn a_csv_header_naming_other_units_than_csv_units_is_refused() {
        let text = "time,acc (m/s^2)\n0,1.0\n0.01,2.0\n";
        let e = Record::from_csv_str(text, "m.csv", AccelUnits::G).unwrap_err();
        assert!(
            e.to_string().contains("m.csv") && e.to_string().contains("M/S^2"),
            "{e}"
        );
        let r = Record::from_csv_str(text, "m.csv", AccelUnits::MetresPerSecondSquared).unwrap();
        assert_eq!(r.values(), &[1.0, 2.0]);
        // a header in g read in g is fine
        assert!(Record::from_csv_str("t, a (g)\n0,0.1\n", "g.csv", AccelUnits::G).is_ok());
    }

    #[test]
    fn the_pivot_limit_bounds_the_work_of_large_problems() {
        let s = LemkeSettings::default();
        assert_eq!(
            s.pivot_limit(12),
            100_000,
            "impact-sized problems keep the full limit"
        );
        assert_eq!(s.pivot_limit(447), 100_000);
        assert_eq!(s.pivot_limit(1000), 20_000);
        assert!(s.pivot_limit(4096) * 4096 * 4096 <= 2 * pounding::lcp::PIVOT_WORK as usize);
        assert!(s.pivot_limit(usize::MAX) >= 1);
    }

    #[test]
    fn murty_ends_max_pivots_with_a_status() {
        // Murty's example needs 2^n pivots; it must end with a status, not run for hours.
        let n = 300;
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                m[i * n + j] = if i == j {
                    1.0
                } else if i > j {
                    2.0
                } else {
                    0.0
                };
            }
        }
        let p = pounding::lcp::LcpProblem::new(m, vec![-1.0; n]).unwrap();
        let s = LemkeSettings::default().with_max_pivots(5_000).unwrap();
        let sol = pounding::lcp::Lemke::new(s).solve(&p);
        assert_eq!(sol.status, pounding::lcp::LcpStatus::MaxPivots);
    }
}
