//! `pounding simulate bridge.toml --records … --scales …`: bridge batches are byte-identical for
//! any thread count, shards merge to the unsharded file, rows equal the single runs'
//! `summary.json`, and bad batch arguments are errors (exit 2, nothing written).

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("bbatch", name)
}

/// Two short synthetic records (CSV, g) in `dir/recs` and a four-segment bridge (curved in the
/// middle, a start abutment, a restrainer) with a coarse step.
fn setup(dir: &Path) -> (PathBuf, PathBuf) {
    let recs = dir.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    for (i, (f, a)) in [(1.0, 0.3), (1.7, 0.25)].iter().enumerate() {
        let mut s = String::from("t,a\n");
        for k in 0..=300 {
            let t = k as f64 * 0.01;
            let v = a * (2.0 * std::f64::consts::PI * f * t).sin() * (-0.3 * t).exp();
            s.push_str(&format!("{t:.2},{v:.6}\n"));
        }
        std::fs::write(recs.join(format!("r{i}.csv")), s).unwrap();
    }
    let seg = |shape: &str| {
        format!("[[segment]]\nshape = \"{shape}\"\nL = 30.0\nR = 150.0\nbeta_deg = 12.0\nperiod_s = 1.0\n")
            .replace(
                if shape == "straight" {
                    "R = 150.0\nbeta_deg = 12.0\n"
                } else {
                    "L = 30.0\n"
                },
                "",
            )
    };
    let sc = dir.join("bridge.toml");
    std::fs::write(
        &sc,
        format!(
            "[bridge]\ngap = 0.01\nmu = 0.2\n{}{}{}{}[[joint]]\nrestrainer_k = 5e7\n[[joint]]\n\
             [[joint]]\n[abutment.start]\ngap = 0.02\n[ground_motion]\nscale_y = -1.5\n\
             incidence_deg = 10.0\n[time]\ndt = 2e-3\n",
            seg("straight"),
            // the curves written out (right, then left: the S this test was built on)
            seg("curved") + "curve = \"right\"\n",
            seg("curved") + "curve = \"left\"\n",
            seg("straight")
        ),
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

#[test]
fn bridge_batch_bytes_do_not_depend_on_threads_and_shards_merge_to_them() {
    let d = tmp("threads");
    let (sc, recs) = setup(&d);
    let run = |out: &Path, extra: &[&str]| {
        let o = pounding()
            .args([
                "simulate",
                s(&sc),
                "--records",
                s(&recs),
                "--scales",
                "0.25,0.5,1",
            ])
            .args(["--out", s(out)])
            .args(extra)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(std::fs::metadata(out.join("batch.png")).unwrap().len() > 10_000);
        assert!(out.join("timing.json").exists());
        std::fs::read_to_string(out.join("batch.csv")).unwrap()
    };
    let a = run(&d.join("t1"), &["--threads", "1"]);
    let b = run(&d.join("t2"), &["--threads", "2"]);
    assert_eq!(a, b);
    let (head, all) = rows(&a);
    assert_eq!(all.len(), 6);
    // bridge order: joints 1..3, both abutments, segments 1..4, error last
    let pos = |n: &str| {
        head.iter()
            .position(|h| h == n)
            .unwrap_or_else(|| panic!("{n}"))
    };
    assert!(pos("joint3_unseated") < pos("abutment_start_impacts"));
    assert!(pos("abutment_end_peak_impulse_ns") < pos("segment1_peak_displacement_m"));
    // the appended columns (issue 12) come after the segments, `error` stays last
    assert_eq!(
        pos("segment4_end_seat_ratio") + 1,
        pos("peak_contact_force_n")
    );
    assert_eq!(
        pos("peak_seat_displacement_m") + 1,
        pos("governing_seat_end")
    );
    assert_eq!(pos("newton_failures") + 3, head.len());
    assert_eq!(pos("warnings") + 2, head.len());
    assert_eq!(head.last().unwrap(), "error");
    for r in &all {
        assert_eq!(r[pos("status")], "Completed");
        assert_eq!(r[pos("abutment_end_impacts")], "", "no end abutment");
        assert_eq!(r[pos("joint1_peak_contact_force_n")], "", "rigid law");
        for c in [
            "peak_contact_force_n",
            "steps_per_contact",
            "newton_failures",
        ] {
            assert_eq!(r[pos(c)], "", "rigid law: {c}");
        }
        assert_ne!(r[pos("joint1_restrainer_peak_force_n")], "");
        assert_eq!(
            r[pos("joint2_restrainer_peak_force_n")],
            "",
            "no restrainer"
        );
    }
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

    // row 4 (record r1, scale 0.5) against the single run's summary.json
    let so = d.join("single");
    let o = pounding()
        .args(["simulate", s(&sc), "--record", s(&recs.join("r1.csv"))])
        .args(["--scale", "0.5", "--out", s(&so)])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let js = std::fs::read_to_string(so.join("summary.json")).unwrap();
    let r = &all[4];
    assert_eq!(r[pos("record")], recs.join("r1.csv").display().to_string());
    // every number of the row equals the single run's, as f64 (both texts are shortest
    // round-trip renderings, parsed here with Rust's correctly rounded parser; serde_json's
    // default float parsing is not exact): the n-th occurrence of a key in summary.json (keys
    // sorted: the abutments first, then the top-level counts, the joints, the segments)
    let cell = |n: &str| r[pos(n)].parse::<f64>().unwrap();
    // column, summary.json key, occurrence
    const PAIRS: &str = "impacts impacts 1; impacting_contacts impacting_contacts 0; steps steps 0; \
        energy_balance_error energy_balance_error 0; max_penetration_m peak_penetration_m 0; \
        joint1_impacts impacts 2; joint2_impacts impacts 3; joint3_impacts impacts 4; \
        abutment_start_impacts impacts 0; joint1_peak_closing_m peak_closing_m 1; \
        joint3_peak_opening_m peak_opening_m 2; abutment_start_peak_impulse_ns peak_impulse_ns 0; \
        joint1_restrainer_peak_force_n restrainer_peak_force_n 0; \
        segment1_peak_displacement_m peak_displacement_m 0; \
        segment4_peak_displacement_m peak_displacement_m 3; \
        segment2_peak_rotation_deg peak_rotation_deg 1; \
        segment3_peak_bearing_deformation_m peak_bearing_deformation_m 2; \
        segment4_final_displacement_m final_displacement_m 3";
    for pair in PAIRS.split(';') {
        let w: Vec<&str> = pair.split_whitespace().collect();
        let n: usize = w[2].parse().unwrap();
        assert_eq!(cell(w[0]), json_number(&js, w[1], n), "column {}", w[0]);
    }
    // every seated end's ratio, and the governing end, as summary.json's seats[] has them
    let mut largest = (String::new(), f64::NEG_INFINITY);
    for i in 1..=4 {
        for face in ["start", "end"] {
            let end = format!("segment{i}-{face}");
            let ratio = seat_ratio(&js, &end);
            assert_eq!(
                cell(&format!("segment{i}_{face}_seat_ratio")),
                ratio,
                "{end}"
            );
            if ratio > largest.1 {
                largest = (end, ratio);
            }
        }
    }
    assert!(largest.1 > 0.0);
    assert_eq!(r[pos("governing_seat_end")], largest.0);
    assert_eq!(cell("governing_seat_ratio"), largest.1);
}

/// `seats[].ratio` of seated end `end` in pretty-printed `summary.json` text (the object's keys
/// are sorted: `end` comes before `ratio`).
fn seat_ratio(text: &str, end: &str) -> f64 {
    let seats = text.find("\"seats\": [").expect("seats");
    let at = seats
        + text[seats..]
            .find(&format!("\"end\": \"{end}\""))
            .unwrap_or_else(|| panic!("no seat {end}"));
    json_number(&text[at..], "ratio", 0)
}

/// The number after the `n`-th occurrence of `"key":` in pretty-printed JSON text.
fn json_number(text: &str, key: &str, n: usize) -> f64 {
    let pat = format!("\"{key}\": ");
    let at = text
        .match_indices(&pat)
        .nth(n)
        .unwrap_or_else(|| panic!("no {key} #{n}"))
        .0;
    let rest = &text[at + pat.len()..];
    let end = rest.find([',', '\n', '}']).unwrap();
    rest[..end].parse().unwrap()
}

#[test]
fn bad_bridge_batch_arguments_are_errors_and_an_unreadable_record_fails_its_rows() {
    let d = tmp("bad");
    let (sc, recs) = setup(&d);
    let empty = d.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let missing = d.join("missing.AT2");
    for (args, needle) in [
        (
            vec!["--records", s(&recs), "--scales", "1,nan"],
            "--scales[2]",
        ),
        (vec!["--records", s(&recs), "--shard", "3/2"], "--shard"),
        (vec!["--records", s(&recs), "--threads", "0"], "--threads"),
        (vec!["--records", s(&empty)], "no .AT2 or .csv"),
        (vec!["--records", s(&recs), "--scale", "2"], "--scale"),
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
        assert!(!out.exists(), "{args:?} wrote output");
    }
    // a bad scenario key is still named with its line in batch mode
    let bad = d.join("bad.toml");
    let text = std::fs::read_to_string(&sc)
        .unwrap()
        .replace("gap = 0.02", "gap = -0.02");
    std::fs::write(&bad, text).unwrap();
    let out = d.join("o2");
    let o = pounding()
        .args(["simulate", s(&bad), "--records", s(&recs), "--out", s(&out)])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("gap") && err.contains("bad.toml"), "{err}");
    assert!(!out.exists());
    // an unreadable record among others: its rows say error and name it, exit 1
    let out = d.join("o3");
    let o = pounding()
        .args([
            "simulate",
            s(&sc),
            "--records",
            s(&missing),
            s(&recs.join("r0.csv")),
        ])
        .args(["--scales", "0.5,1", "--out", s(&out)])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("missing.AT2"), "{err}");
    let (head, rows) = rows(&std::fs::read_to_string(out.join("batch.csv")).unwrap());
    let st = head.iter().position(|h| h == "status").unwrap();
    let status: Vec<&str> = rows.iter().map(|r| r[st].as_str()).collect();
    assert_eq!(status, ["error", "error", "Completed", "Completed"]);
    assert!(rows[0].last().unwrap().contains("missing.AT2"));
    assert_eq!(rows[0].len(), head.len());
}
