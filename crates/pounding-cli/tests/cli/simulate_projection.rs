//! `pounding simulate --projection` / `[time] projection` (issue 24, item 2): the flag runs as the
//! key does, `summary.json` reports the overlap and the projection's work only when it is on, and
//! a key that is no boolean is refused with its line, nothing written.

use crate::{run_capture, scratch_dir};

fn summary(dir: &std::path::Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap()
}

#[test]
fn projection_flag_and_key_keep_the_rigid_gaps_closed() {
    let d = scratch_dir("simproj", "runs");
    let out = |n: &str| d.join(n);
    let run = |args: &[&str], n: &str| {
        let o = out(n);
        let mut a = vec!["simulate", "--duration", "20"];
        a.extend_from_slice(args);
        a.extend_from_slice(&["--out", o.to_str().unwrap()]);
        let (code, _, err) = run_capture(&a);
        assert_eq!(code, Some(0), "{err}");
        summary(&o)
    };
    let plain = run(&[], "plain");
    for key in ["max_overlap_m", "projection"] {
        assert!(plain.get(key).is_none(), "{key} without --projection");
    }
    assert!(plain["energy_J"].get("projection").is_none());
    assert!(
        plain["max_penetration_m"].as_f64().unwrap() > 1e-10,
        "{plain}"
    );
    let flag = run(&["--projection"], "flag");
    assert!(flag["max_overlap_m"].as_f64().unwrap() <= 1e-10, "{flag}");
    let w = flag["energy_J"]["projection"].as_f64().unwrap();
    let input = flag["energy_J"]["max_input"].as_f64().unwrap();
    assert!(w != 0.0 && w.abs() < 1e-4 * input, "{w} {input}");
    assert!(flag["energy_balance_error"].as_f64().unwrap() < 1e-12);
    let p = &flag["projection"];
    assert!(p["corrected_steps"].as_u64().unwrap() > 0, "{p}");
    assert_eq!(p["failures"].as_u64(), Some(0));
    assert!(p["max_overlap_before_m"].as_f64().unwrap() > 1e-10);
    // history.csv carries the projection's work, and its last row's balance closes with it
    let hist = std::fs::read_to_string(out("flag").join("history.csv")).unwrap();
    let head: Vec<&str> = hist.lines().next().unwrap().split(',').collect();
    let last: Vec<f64> = hist
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    let col = |name: &str| last[head.iter().position(|c| *c == name).expect(name)];
    assert_eq!(col("projection_work_J"), w);
    let balance = col("input_energy_J") + col("projection_work_J")
        - (col("kinetic_energy_J")
            + col("strain_energy_J")
            + col("viscous_dissipation_J")
            + col("contact_dissipation_J"));
    assert!(balance.abs() < 1e-10 * input, "{balance}");
    let plain_hist = std::fs::read_to_string(out("plain").join("history.csv")).unwrap();
    assert!(!plain_hist.lines().next().unwrap().contains("projection"));
    // the key: the same files as the flag
    let (code, text, _) = run_capture(&["simulate", "--print-default"]);
    assert_eq!(code, Some(0));
    let file = d.join("key.toml");
    let text = text.replace("\n[time]\n", "\n[time]\nprojection = true\n");
    std::fs::write(&file, text).unwrap();
    let key = run(&[file.to_str().unwrap()], "key");
    assert_eq!(key, flag);
    for name in ["history.csv", "impacts.csv"] {
        let a = std::fs::read(out("key").join(name)).unwrap();
        let b = std::fs::read(out("flag").join(name)).unwrap();
        assert!(a == b, "{name} differs");
    }
}

#[test]
fn projection_key_must_be_a_boolean() {
    let d = scratch_dir("simproj", "bad");
    let file = d.join("bad.toml");
    std::fs::write(&file, "[time]\ndt = 1e-3\nprojection = \"yes\"\n").unwrap();
    let o = d.join("out");
    let (code, _, err) = run_capture(&[
        "simulate",
        file.to_str().unwrap(),
        "--out",
        o.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("line 3") && err.contains("projection"),
        "{err}"
    );
    assert!(err.contains("boolean"), "{err}");
    assert!(!o.exists());
}

#[test]
fn a_batch_runs_with_the_projection() {
    let d = scratch_dir("simproj", "batch");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let rec = root.join("data/records/RSN6_IMPVALL.I_I-ELC180-hor1.AT2");
    let pen = |flag: Option<&str>, n: &str| -> Vec<f64> {
        let o = d.join(n);
        let mut a = vec!["simulate", "--duration", "20", "--records"];
        a.push(rec.to_str().unwrap());
        a.extend_from_slice(&["--scales", "1,1.5", "--out", o.to_str().unwrap()]);
        a.extend(flag);
        let (code, _, err) = run_capture(&a);
        assert_eq!(code, Some(0), "{err}");
        let text = std::fs::read_to_string(o.join("batch.csv")).unwrap();
        let mut lines = text.lines();
        let head: Vec<&str> = lines.next().unwrap().split(',').collect();
        let col = head.iter().position(|c| *c == "max_penetration_m").unwrap();
        lines
            .map(|l| l.split(',').nth(col).unwrap().parse().unwrap())
            .collect()
    };
    let plain = pen(None, "plain");
    let projected = pen(Some("--projection"), "projected");
    assert_eq!(plain.len(), 2);
    assert!(plain.iter().all(|p| *p > 1e-10), "{plain:?}");
    assert!(projected.iter().all(|p| *p <= 1e-10), "{projected:?}");
}
