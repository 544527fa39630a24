//! Inputs that cannot be misread (issue 12): record formats and units on the command line
//! (`--record-dt`, `--csv-units`), what was used printed and written (`ground_motion.components`),
//! `--records` listing what it skipped, a scenario among the records refused, `--scale -1`.

use crate::{run_capture, scratch_dir};
use std::path::{Path, PathBuf};

const G0: f64 = 9.80665;

/// The first `n` samples (g) of the El Centro 180 record shipped in `data/records`.
fn elc(n: usize) -> Vec<f64> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/records/RSN6_IMPVALL.I_I-ELC180-hor1.AT2");
    std::fs::read_to_string(p)
        .unwrap()
        .lines()
        .skip(4)
        .flat_map(|l| {
            l.split_whitespace()
                .map(|t| t.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .take(n)
        .collect()
}

fn write(d: &Path, name: &str, text: &str) -> PathBuf {
    let p = d.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

/// The same 3 s of motion as an AT2 in cm/s², a CSV in g, columns `t a` in m/s² and one
/// column in g with a dt.
fn same_motion(d: &Path) -> [(PathBuf, Vec<&'static str>, &'static str); 4] {
    let g = elc(300);
    let cm: Vec<String> = g.iter().map(|v| format!("{}", v * G0 * 100.0)).collect();
    let at2 = format!(
        "PEER NGA\nev\nACCELERATION TIME SERIES IN UNITS OF CM/S/S\nNPTS=  300, DT=   .0100 SEC\n{}\n",
        cm.join(" ")
    );
    let t = |i: usize| i as f64 / 100.0;
    let csv: String = g
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{},{v}\n", t(i)))
        .collect();
    let cols: String = g
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{} {}\n", t(i), v * G0))
        .collect();
    let one: String = g.iter().map(|v| format!("{v}\n")).collect();
    [
        (write(d, "m.AT2", &at2), vec![], "CM/S/S header"),
        (write(d, "m.csv", &csv), vec![], "g (csv_units default)"),
        (
            write(d, "m.txt", &cols),
            vec!["--csv-units", "m/s2"],
            "m/s2 (--csv-units)",
        ),
        (
            write(d, "one.txt", &one),
            vec!["--record-dt", "0.01"],
            "g (csv_units default)",
        ),
    ]
}

#[test]
fn a_cm_s2_at2_a_g_csv_m_s2_columns_and_one_column_give_the_same_run() {
    let d = scratch_dir("inputs", "same");
    let mut sums = Vec::new();
    for (k, (p, flags, units)) in same_motion(&d).into_iter().enumerate() {
        let out = d.join(format!("o{k}"));
        let mut args = vec!["simulate", "--record", s(&p), "--out", s(&out)];
        args.extend(flags.iter().copied());
        let (code, _, err) = run_capture(&args);
        assert_eq!(code, Some(0), "{err}");
        let line = err
            .lines()
            .find(|l| l.starts_with("ground motion y:"))
            .unwrap();
        assert!(line.contains(&format!("units {units}")), "{line}");
        assert!(
            line.contains("dt_s 0.01, npts 300, duration_s 2.99"),
            "{line}"
        );
        assert!(!err.contains("ground motion x:"), "{err}");
        assert!(!err.contains("warning: record"), "plausible PGA: {err}");
        let v = summary(&out);
        let c = &v["ground_motion"]["components"];
        assert_eq!(c.as_array().unwrap().len(), 1);
        assert_eq!(c[0]["component"], "y");
        assert_eq!(c[0]["units"], units);
        assert_eq!(c[0]["npts"], 300);
        assert_eq!(c[0]["dt_s"], 0.01);
        sums.push(v);
    }
    let peak = elc(300).iter().fold(0.0f64, |m, v| m.max(v.abs()));
    for v in &sums {
        let pga = v["ground_motion"]["components"][0]["pga_g"]
            .as_f64()
            .unwrap();
        assert!((pga - peak).abs() < 1e-12, "{pga} vs {peak}");
        for key in [
            "peak_joint_closing_m",
            "peak_joint_opening_m",
            "peak_seat_displacement_m",
        ] {
            let (a, b) = (v[key].as_f64().unwrap(), sums[0][key].as_f64().unwrap());
            assert!(
                (a - b).abs() <= 1e-9 * b.abs().max(1e-6),
                "{key}: {a} vs {b}"
            );
        }
        assert_eq!(v["impacts"], sums[0]["impacts"]);
    }
}

#[test]
fn record_flag_errors_exit_2_name_the_file_and_write_nothing() {
    let d = scratch_dir("inputs", "errors");
    let [(at2, ..), (csv, ..), _, (one, ..)] = same_motion(&d);
    let out = d.join("out");
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec!["--record", s(&one)], vec!["one.txt:1", "--record-dt"]),
        (
            vec!["--record", s(&at2), "--record-dt", "0.01"],
            vec!["m.AT2:1", "--record-dt", "remove it"],
        ),
        (
            vec!["--record", s(&csv), "--record-dt", "0.01"],
            vec!["m.csv:1", "remove it"],
        ),
        (
            vec!["--record", s(&one), "--record-dt", "0"],
            vec!["--record-dt", "> 0"],
        ),
        (
            vec!["--record", s(&one), "--record-dt", "-1"],
            vec!["--record-dt", "> 0"],
        ),
        (
            vec!["--csv-units", "m/s2"],
            vec!["--csv-units applies to", "csv_units"],
        ),
        (
            vec!["--record-dt", "0.01"],
            vec!["--record-dt applies to", "record_dt"],
        ),
        (
            vec!["--record", s(&csv), "--csv-units", "furlongs"],
            vec!["furlongs", "g or m/s2"],
        ),
        (
            vec!["--records", s(&csv), "my.toml"],
            vec!["my.toml is a scenario file", "--records last"],
        ),
    ];
    for (flags, want) in cases {
        let mut args = vec!["simulate", "--out", s(&out)];
        args.extend(flags.iter().copied());
        let (code, _, err) = run_capture(&args);
        assert_eq!(code, Some(2), "{flags:?}: {err}");
        for w in want {
            assert!(err.contains(w), "{flags:?}: want {w:?} in {err}");
        }
        assert!(!out.exists(), "{flags:?} wrote {}", out.display());
    }
}

#[test]
fn records_dir_lists_what_it_skipped_and_refuses_a_dir_without_records() {
    let d = scratch_dir("inputs", "dir");
    let recs = d.join("recs");
    std::fs::create_dir_all(recs.join("sub")).unwrap();
    let g = elc(100);
    let csv: String = g
        .iter()
        .enumerate()
        .map(|(i, v)| format!("{},{v}\n", i as f64 / 100.0))
        .collect();
    write(&recs, "a.csv", &csv);
    write(&recs, ".hidden.csv", &csv);
    write(&recs, "notes.md", "x");
    write(&recs, "s.toml", "");
    write(&recs, "v.VT2", "");
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "simulate",
        "--records",
        s(&recs),
        "--threads",
        "1",
        "--out",
        s(&out),
    ]);
    assert_eq!(code, Some(0), "{err}");
    for (f, why) in [
        (".hidden.csv", "hidden file"),
        ("notes.md", "not a record extension"),
        ("s.toml", "scenario file"),
        ("v.VT2", "velocity"),
        ("sub", "a directory"),
    ] {
        assert!(
            err.lines()
                .any(|l| l.starts_with("--records: skipped") && l.contains(f) && l.contains(why)),
            "{f}: {err}"
        );
    }
    assert!(
        err.contains("ground motion y: record") && err.contains("a.csv"),
        "{err}"
    );
    let csv_out = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    assert_eq!(csv_out.lines().count(), 2, "{csv_out}");
    // a directory with nothing usable
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    write(&empty, "readme.md", "x");
    let out2 = d.join("out2");
    let (code, _, err) = run_capture(&["simulate", "--records", s(&empty), "--out", s(&out2)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("contains no .AT2 or .csv record") && err.contains("skipped"),
        "{err}"
    );
    assert!(!out2.exists());
}

#[test]
fn negative_scales_parse_as_values() {
    let d = scratch_dir("inputs", "neg");
    let [_, (csv, ..), ..] = same_motion(&d);
    let out = d.join("o");
    let (code, _, err) = run_capture(&[
        "simulate",
        "--record",
        s(&csv),
        "--scale",
        "-1",
        "--out",
        s(&out),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(summary(&out)["ground_motion"]["scale_y"], -1.0);
    let out = d.join("b");
    let (code, _, err) = run_capture(&[
        "simulate",
        "--records",
        s(&csv),
        "--scales",
        "-1,1",
        "--out",
        s(&out),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let b = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    assert_eq!(b.lines().count(), 3, "{b}");
    assert!(b.contains(",-1,") || b.contains(",-1.0,"), "{b}");
}

#[test]
fn a_bridge_run_prints_and_writes_its_components() {
    let d = scratch_dir("inputs", "bridge");
    let [_, _, (cols, ..), _] = same_motion(&d);
    let sc = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-1d.toml");
    let out = d.join("o");
    let (code, _, err) = run_capture(&[
        "simulate",
        s(&sc),
        "--record",
        s(&cols),
        "--csv-units",
        "m/s2",
        "--out",
        s(&out),
    ]);
    assert!(code == Some(0) || code == Some(1), "{err}");
    assert!(
        err.contains("ground motion y: record") && err.contains("m/s2 (--csv-units)"),
        "{err}"
    );
    let c = &summary(&out)["ground_motion"]["components"];
    assert_eq!(c[0]["units"], "m/s2 (--csv-units)");
    assert_eq!(c[0]["npts"], 300);
}

#[test]
fn an_m_s2_file_read_as_g_warns_of_its_pga_and_a_bad_header_exits_2() {
    let d = scratch_dir("inputs", "pga");
    let [_, (csv, ..), (cols, ..), _] = same_motion(&d);
    // the m/s2 columns read in g: PGA 0.28 x 9.81 = 2.75 g, a warning (not an error)
    let out = d.join("o");
    let (code, _, err) = run_capture(&["simulate", "--record", s(&cols), "--out", s(&out)]);
    assert_eq!(code, Some(0), "{err}");
    let w = err
        .lines()
        .find(|l| l.starts_with("warning: record"))
        .unwrap_or_else(|| panic!("no warning in {err}"));
    assert!(
        w.contains("m.txt")
            && w.contains("2.75")
            && w.contains("as read in g")
            && w.contains("--csv-units"),
        "{w}"
    );
    // and in a batch, once per record
    let out = d.join("ob");
    let (code, _, err) = run_capture(&["simulate", "--out", s(&out), "--records", s(&cols)]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err.matches("warning: record").count(), 1, "{err}");
    // headers that would be misread: exit 2, file and line named, nothing written
    let body: String = std::fs::read_to_string(&csv)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| format!("{l}\n"))
        .collect();
    for (header, want) in [
        ("t,a[gal]", "GAL"),
        ("time (s),velocity (cm/s)", "velocity"),
        ("t (min),a (g)", "only seconds"),
        ("t,a (mg)", "unknown units"),
    ] {
        let p = write(&d, "h.csv", &format!("{header}\n{body}"));
        let out = d.join("oh");
        let (code, _, err) = run_capture(&["simulate", "--record", s(&p), "--out", s(&out)]);
        assert_eq!(code, Some(2), "{header}: {err}");
        assert!(
            err.contains("h.csv:1") && err.contains(want),
            "{header}: {err}"
        );
        assert!(!out.exists(), "{header} wrote {}", out.display());
    }
}

/// Trial findings: `--record builtin:ELC180` is the embedded record (as in a scenario's
/// `record_y`); unit words ending a header name (`acc_g`, `acc_mps2`) are checked like bracketed
/// units; `--record-dt` with a built-in record is refused.
#[test]
fn builtin_records_on_the_command_line_and_unit_words_in_headers() {
    let d = crate::scratch_dir("inputs", "builtin-words");
    let run = |name: &str, args: &[&str]| {
        let out = d.join(name);
        let mut a = vec!["simulate", "--duration", "1"];
        a.extend_from_slice(args);
        a.extend_from_slice(&["--out", out.to_str().unwrap()]);
        let (code, _, err) = crate::run_capture(&a);
        (code, err, out)
    };
    let (code, err, out) = run("builtin", &["--record", "builtin:ELC180"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("pga_g 0.2808"), "{err}");
    assert!(out.join("summary.json").is_file());
    let (code, err, _) = run(
        "builtin-dt",
        &["--record", "builtin:ELC180", "--record-dt", "0.01"],
    );
    assert_eq!(code, Some(2), "{err}");
    let g = d.join("acc_g.csv");
    std::fs::write(&g, "time_s,acc_g\n0,0.1\n0.01,0.2\n0.02,0.1\n").unwrap();
    let (code, err, _) = run(
        "word-g",
        &["--record", g.to_str().unwrap(), "--csv-units", "m/s2"],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("acc_g.csv:1"), "{err}");
    let (code, err, _) = run("word-g-ok", &["--record", g.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    let m = d.join("acc_mps2.csv");
    std::fs::write(&m, "t,acc_mps2\n0,1\n0.01,2\n0.02,1\n").unwrap();
    let (code, err, _) = run("word-mps2", &["--record", m.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    let (code, err, _) = run(
        "word-mps2-ok",
        &["--record", m.to_str().unwrap(), "--csv-units", "m/s2"],
    );
    assert_eq!(code, Some(0), "{err}");
}
