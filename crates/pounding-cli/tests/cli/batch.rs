//! `pounding simulate --records … --scales …`: batch rows equal single runs, thread-count
//! independence, sharding, an unreadable record among many, bad input.

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("batch", name)
}

/// Three short synthetic records (CSV, g) in `dir/recs` and a scenario with a coarse step.
fn setup(dir: &Path) -> (PathBuf, PathBuf) {
    let recs = dir.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    for (i, (f, a)) in [(1.0, 0.3), (1.7, 0.25), (0.8, 0.4)].iter().enumerate() {
        let mut s = String::from("t,a\n");
        for k in 0..=300 {
            let t = k as f64 * 0.01;
            let v = a * (2.0 * std::f64::consts::PI * f * t).sin() * (-0.3 * t).exp();
            s.push_str(&format!("{t:.2},{v:.6}\n"));
        }
        std::fs::write(recs.join(format!("r{i}.csv")), s).unwrap();
    }
    let sc = dir.join("scenario.toml");
    std::fs::write(
        &sc,
        "[ground_motion]\nscale_y = 1.5\n[time]\ndt = 2e-3\nhistory_every = 50\n",
    )
    .unwrap();
    (sc, recs)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn rows(csv: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let head: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (head, rows)
}

/// The `k`-th number after `"key":` in pretty-printed JSON text (a scalar: `k = 0`).
fn json_number(text: &str, key: &str, k: usize) -> f64 {
    let at = text
        .find(&format!("\"{key}\":"))
        .unwrap_or_else(|| panic!("no {key}"));
    let rest = &text[at + key.len() + 3..];
    rest.split(|c: char| c == ',' || c == '[' || c == ']' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .nth(k)
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn batch_rows_equal_single_runs_row_for_row() {
    let d = tmp("equal");
    let (sc, recs) = setup(&d);
    let out = d.join("batch");
    let o = pounding()
        .args([
            "simulate",
            s(&sc),
            "--records",
            s(&recs),
            "--scales",
            "0.5,1,2,4",
        ])
        .args(["--threads", "2", "--out", s(&out)])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    // stderr is not a terminal here: no progress bar, just one line per record read and the
    // two summary lines
    assert!(!err.contains("runs ["), "{err}");
    let (records, rest): (Vec<&str>, Vec<&str>) = err
        .lines()
        .partition(|l| l.starts_with("ground motion y: record "));
    assert_eq!((records.len(), rest.len()), (3, 2), "{err}");
    assert!(std::fs::metadata(out.join("batch.png")).unwrap().len() > 10_000);
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    let (head, rows) = rows(&csv);
    assert_eq!(rows.len(), 12);
    let col = |name: &str| head.iter().position(|h| h == name).unwrap();
    let scales = ["0.5", "1", "2", "4"];
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r.len(), head.len());
        let rec = recs.join(format!("r{}.csv", i / 4));
        assert_eq!(r[col("index")], i.to_string());
        assert_eq!(r[col("record")], rec.display().to_string());
        assert_eq!(r[col("scale")], scales[i % 4]);
        assert_eq!(r[col("status")], "Completed");
        // the single run of the same record and scale
        let so = d.join(format!("single{i}"));
        let o = pounding()
            .args([
                "simulate",
                s(&sc),
                "--record",
                s(&rec),
                "--scale",
                scales[i % 4],
            ])
            .args(["--out", s(&so)])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let js = std::fs::read_to_string(so.join("summary.json")).unwrap();
        let cell = |name: &str| r[col(name)].parse::<f64>().unwrap();
        for (c, key, k) in [
            ("impacts", "impacts", 0),
            ("impacting_contacts", "impacting_contacts", 0),
            ("peak_joint_closing_m", "peak_joint_closing_m", 0),
            ("peak_joint_opening_m", "peak_joint_opening_m", 0),
            ("peak_rotation1_deg", "peak_rotation_deg", 0),
            ("peak_rotation2_deg", "peak_rotation_deg", 1),
            ("peak_slip_m", "peak_slip_m", 0),
            ("peak_seat_displacement_m", "peak_seat_displacement_m", 0),
            ("max_penetration_m", "max_penetration_m", 0),
            ("input_energy_J", "input", 0),
            ("contact_dissipation_J", "contact_dissipation", 0),
            ("viscous_dissipation_J", "viscous_dissipation", 0),
            ("steps", "steps", 0),
            ("pga_mps2", "pga_y_mps2", 0),
        ] {
            // both are shortest round-trip renderings of the same f64: exact equality (parsed
            // with Rust's correctly rounded parser; serde_json's default float parsing is not)
            assert_eq!(cell(c), json_number(&js, key, k), "row {i} column {c}");
        }
        assert!(js.contains(&format!("\"unseated\": {},", r[col("unseated")])));
    }
}

#[test]
fn thread_count_does_not_change_the_bytes_and_shards_partition_the_rows() {
    let d = tmp("threads");
    let (sc, recs) = setup(&d);
    let run = |out: &Path, extra: &[&str]| {
        let o = pounding()
            .args(["simulate", s(&sc), "--records", s(&recs), "--scales", "1,3"])
            .args(["--out", s(out)])
            .args(extra)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(out.join("batch.csv")).unwrap()
    };
    let a = run(&d.join("t1"), &["--threads", "1"]);
    let b = run(&d.join("t2"), &["--threads", "2"]);
    assert_eq!(a, b);
    let (head, all) = rows(&a);
    let mut merged = Vec::new();
    for k in 1..=4 {
        let part = run(&d.join(format!("s{k}")), &["--shard", &format!("{k}/4")]);
        let (h, r) = rows(&part);
        assert_eq!(h, head);
        assert!(
            r.iter()
                .all(|r| r[0].parse::<usize>().unwrap() % 4 == k - 1)
        );
        merged.extend(r);
    }
    merged.sort_by_key(|r| r[0].parse::<usize>().unwrap());
    assert_eq!(merged, all);
}

#[test]
fn an_unreadable_record_among_many_is_named_and_the_others_are_reported() {
    let d = tmp("unreadable");
    let (sc, recs) = setup(&d);
    let bad = d.join("broken.AT2");
    std::fs::write(
        &bad,
        "header\nheader\nheader\nNPTS= 3, DT= 0.01 SEC\n0.1 zz 0.3\n",
    )
    .unwrap();
    let missing = d.join("missing.AT2");
    let out = d.join("o");
    let o = pounding()
        .args(["simulate", s(&sc), "--records", s(&recs.join("r0.csv"))])
        .args([s(&bad), s(&missing), s(&recs.join("r2.csv"))])
        .args(["--scales", "1,2", "--out", s(&out)])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("broken.AT2:5"), "{err}");
    assert!(err.contains("missing.AT2"), "{err}");
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    let (head, rows) = rows(&csv);
    let st = head.iter().position(|h| h == "status").unwrap();
    assert_eq!(rows.len(), 8);
    let status: Vec<&str> = rows.iter().map(|r| r[st].as_str()).collect();
    assert_eq!(
        status,
        [
            "Completed",
            "Completed",
            "error",
            "error",
            "error",
            "error",
            "Completed",
            "Completed"
        ]
    );
    assert!(rows[2].last().unwrap().contains("broken.AT2"));
    assert!(rows[4].last().unwrap().contains("missing.AT2"));
}

#[test]
fn bad_batch_arguments_are_errors_naming_them() {
    let d = tmp("bad");
    let (sc, recs) = setup(&d);
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    for (args, needle) in [
        (
            vec!["--records", s(&recs), "--scales", "1,nan"],
            "--scales[2]",
        ),
        (vec!["--records", s(&recs), "--shard", "3/2"], "--shard"),
        (vec!["--records", s(&recs), "--threads", "0"], "--threads"),
        (vec!["--records", s(&empty)], "no .AT2 or .csv"),
        (vec!["--records", s(&recs), "--scale", "2"], "--scale"),
        (vec!["--shard", "1/2"], "--records"),
    ] {
        let out = d.join("o");
        let o = pounding()
            .args(["simulate", s(&sc)])
            .args(&args)
            .args(["--out", s(&out)])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(needle), "{args:?}: {err}");
        assert!(!out.join("batch.csv").exists(), "{args:?} wrote output");
    }
}

/// The shipped 1-D example: straight decks, central impacts only (no rotation, no motion along
/// the joint), six impacts of both corners each under the unscaled record; `--scale` applies.
#[test]
fn straight_1d_example_runs_and_scales() {
    let d = tmp("example");
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/straight-1d.toml");
    let mut impacts = Vec::new();
    for scale in ["1", "2"] {
        let out = d.join(format!("x{scale}"));
        let o = pounding()
            .args(["simulate", s(&ex), "--scale", scale, "--out", s(&out)])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let js = std::fs::read_to_string(out.join("summary.json")).unwrap();
        assert!(js.contains("\"straight\""), "{js}");
        assert_eq!(json_number(&js, "mass_kg", 0), 1.0e6);
        assert_eq!(json_number(&js, "mass_kg", 1), 1.0e6);
        // natural periods: deck 1 translational 1.0 s, deck 2 0.5 s
        let t1 = json_number(&js, "natural_periods_s", 0);
        let t2 = json_number(&js, "natural_periods_s", 3);
        assert!(
            (t1 - 1.0).abs() < 1e-9 && (t2 - 0.5).abs() < 1e-9,
            "{t1} {t2}"
        );
        // (rounding only: the two corner impulses agree to the last bits)
        assert!(json_number(&js, "peak_rotation_deg", 0) < 1e-12);
        assert!(json_number(&js, "peak_rotation_deg", 1) < 1e-12);
        assert!(json_number(&js, "peak_slip_m", 0) < 1e-12);
        let n = json_number(&js, "impacts", 0);
        assert_eq!(json_number(&js, "impacting_contacts", 0), 2.0 * n);
        assert!(json_number(&js, "pga_y_mps2", 0) > 2.7 * scale.parse::<f64>().unwrap());
        impacts.push(n);
    }
    assert_eq!(
        impacts[0], 6.0,
        "El Centro unscaled: 6 impacts (event-exact reference)"
    );
    assert!(impacts[1] > impacts[0]);
}

#[test]
fn bad_shape_and_abutment_scenarios_are_errors_naming_the_key() {
    let d = tmp("badshape");
    let cases = [
        (
            "[decks]\nshape = \"skew\"\nL1 = 30.0\nL2 = 30.0\nskew_deg = 90.0\n",
            "skew_deg",
        ),
        ("[decks]\nshape = \"straight\"\nL1 = 30.0\nL2 = 0.0\n", "L2"),
        (
            "[decks]\nshape = \"straight\"\nL1 = -3.0\nL2 = 30.0\n",
            "L1",
        ),
        ("[decks]\nshape = \"straight\"\nL1 = 30.0\n", "L2"),
        ("[decks]\nshape = \"round\"\n", "shape"),
        (
            "[decks]\nshape = \"straight\"\nL1 = 30.0\nL2 = 30.0\nR1 = 50.0\n",
            "R1",
        ),
        ("[abutments]\ngap1 = -0.01\n", "gap1"),
        (
            "[abutments]\ngap2 = 0.01\nseat_length2 = 0.0\n",
            "seat_length2",
        ),
        ("[abutments]\nseat_length1 = 0.3\n", "gap1"),
    ];
    for (i, (text, key)) in cases.iter().enumerate() {
        let sc = d.join(format!("s{i}.toml"));
        std::fs::write(&sc, text).unwrap();
        let out = d.join(format!("o{i}"));
        let o = pounding()
            .args(["simulate", s(&sc), "--out", s(&out)])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{text}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(key), "{text}: {err}");
        assert!(err.contains(&format!("s{i}.toml")), "{text}: {err}");
        assert!(!out.exists(), "{text}: output written");
    }
}

/// Skewed decks with abutments: abutment impacts are reported (impacts.csv, summary.json,
/// history.csv columns, abutment_gap.png) and the energy balance still closes.
#[test]
fn skew_decks_with_abutments_report_abutment_impacts() {
    let d = tmp("abut");
    let sc = d.join("skew.toml");
    std::fs::write(
        &sc,
        "[decks]\nshape = \"skew\"\nL1 = 30.0\nL2 = 40.0\nskew_deg = 40.0\nwidth = 10.0\n\
         thickness = 0.5\n[abutments]\ngap1 = 0.03\ngap2 = 0.04\nseat_length2 = 0.3\n\
         [ground_motion]\nscale_y = 2.0\nscale_x = 2.0\n[time]\nduration = 10.0\n",
    )
    .unwrap();
    let out = d.join("o");
    let o = pounding()
        .args(["simulate", s(&sc), "--out", s(&out)])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let js = std::fs::read_to_string(out.join("summary.json")).unwrap();
    let n_ab = json_number(&js, "impacting_contacts", 0); // the first occurrence: abutments
    assert!(js.contains("\"abutments\""), "{js}");
    assert!(json_number(&js, "energy_balance_error", 0) < 1e-9);
    assert_eq!(json_number(&js, "seat_length_m", 0), 0.4); // [joint], first in the abutment map
    let imp = std::fs::read_to_string(out.join("impacts.csv")).unwrap();
    let ab_rows = imp.lines().filter(|l| l.contains(",abutment")).count();
    assert!(ab_rows > 0);
    assert_eq!(ab_rows as f64, n_ab, "{js}");
    let hist = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let head = hist.lines().next().unwrap();
    assert!(head.ends_with(",abutment_gap1_m,abutment_gap2_m"), "{head}");
    // the abutment gaps never go much below 0 (overlap bounded by one step's travel)
    let gi = head.split(',').count() - 2;
    for l in hist.lines().skip(1) {
        let c: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
        assert!(c[gi] > -1e-3 && c[gi + 1] > -1e-3, "{l}");
    }
    assert!(out.join("abutment_gap.png").exists());
}
