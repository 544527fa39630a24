//! Hardening: absurd sizes, unchecked claims, overflowing derived quantities, diverged runs.

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("pounding-harden-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let o = pounding().args(args).output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn absurd_at2_npts_is_an_error_row_in_a_batch() {
    let d = tmp("npts");
    let recs = d.join("recs");
    std::fs::create_dir_all(&recs).unwrap();
    let mut good = String::from("t,a\n");
    for k in 0..=100 {
        good.push_str(&format!(
            "{:.2},{:.6}\n",
            k as f64 * 0.01,
            0.2 * (k as f64 * 0.1).sin()
        ));
    }
    std::fs::write(recs.join("a.csv"), good).unwrap();
    std::fs::write(
        recs.join("huge.AT2"),
        "h\nh\nh\nNPTS= 99999999999, DT= 0.01 SEC\n0.1 0.2\n",
    )
    .unwrap();
    let sc = d.join("scenario.toml");
    std::fs::write(&sc, "[time]\ndt = 2e-3\nhistory_every = 50\n").unwrap();
    // single run: a clear file:LINE error
    let (code, _, err) = run(&["simulate", s(&sc), "--record", s(&recs.join("huge.AT2"))]);
    assert_ne!(code, Some(0), "{err}");
    assert!(code.is_some(), "killed by a signal: {err}");
    assert!(err.contains("huge.AT2:4") && err.contains("NPTS"), "{err}");
    // batch: an error row, the good record still reported
    let out = d.join("o");
    let (code, _, err) = run(&[
        "simulate",
        s(&sc),
        "--records",
        s(&recs),
        "--scales",
        "1,2",
        "--out",
        s(&out),
    ]);
    assert_eq!(code, Some(1), "{err}");
    let csv = std::fs::read_to_string(out.join("batch.csv")).unwrap();
    let n_err = csv.lines().filter(|l| l.contains(",error,")).count();
    assert_eq!(n_err, 2, "{csv}");
    assert_eq!(csv.lines().count(), 5, "{csv}");
    assert!(csv.contains("huge.AT2:4"), "{csv}");
}

#[test]
fn lcp_io_refuses_absurd_sizes_and_empty_sets() {
    let d = tmp("lcpio");
    let c = d.join("c.txt");
    std::fs::write(&c, "LCPSET 1\nCOUNT 99999999999\n").unwrap();
    let (code, _, err) = run(&["lcp", "solve", s(&c)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("COUNT") || err.contains("count"), "{err}");
    let b = d.join("b.dat");
    std::fs::write(&b, "100000000\n0\n100000000\n100000000\n1 2\n").unwrap();
    let (code, _, err) = run(&["lcp", "solve", s(&b)]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("b.dat"), "{err}");
    let e = d.join("e.txt");
    std::fs::write(&e, "LCPSET 1\nCOUNT 0\n").unwrap();
    let (code, _, err) = run(&["lcp", "bench", s(&e)]);
    assert!(code.is_some() && code != Some(101), "panicked: {err}");
    assert!(!err.contains("panicked"), "{err}");
}
