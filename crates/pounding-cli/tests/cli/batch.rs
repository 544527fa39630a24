//! `pounding simulate --records … --scales …`: batch rows equal single runs, thread-count
//! independence, sharding, an unreadable record among many, bad input.

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("pounding-batch-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
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
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
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
