//! `pounding simulate` of a bridge with piers, backwalls and shear keys: the member tables,
//! `hysteresis.png` in the report, the summary's arrays, and a stale-file check against a plain
//! bridge run; a bad pier is refused (exit 2, key and line, nothing written).

use crate::{run_capture, scratch_with};
use std::collections::BTreeSet;

const PLAN: &str = include_str!("../../../../examples/bridge-piers.toml");
const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");

fn files(dir: &std::path::Path) -> BTreeSet<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

#[test]
fn piers_backwalls_and_keys_write_their_tables_and_loops() {
    let short = PLAN.replace("[time]\n", "[time]\nduration = 3.0\n");
    let plain = CURVED_5.replace("history_every = 10", "history_every = 10\nduration = 2.0");
    let bad = PLAN.replace("cap_mass = 2.0e5", "cap_mass = -2.0e5");
    let d = scratch_with(
        "substructure",
        "run",
        &[
            ("plan.toml", &short),
            ("plain.toml", &plain),
            ("bad.toml", &bad),
        ],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&["simulate", &p("plan.toml"), "--out", &p("o")]);
    assert_eq!(code, Some(0), "{err}");
    let have = files(&d.join("o"));
    for f in [
        "piers.csv",
        "backwalls.csv",
        "shear_keys.csv",
        "hysteresis.png",
        "report.html",
    ] {
        assert!(have.contains(f), "{f} missing: {have:?}");
    }
    let report = std::fs::read_to_string(d.join("o/report.html")).unwrap();
    for f in [
        "hysteresis.png",
        "piers.csv",
        "backwalls.csv",
        "shear_keys.csv",
    ] {
        assert!(report.contains(f), "the report does not show {f}");
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("o/summary.json")).unwrap()).unwrap();
    assert_eq!(summary["piers"].as_array().unwrap().len(), 2);
    assert_eq!(summary["shear_keys"].as_array().unwrap().len(), 2);
    assert!(summary["abutments"][0]["backwall"]["peak_backfill_force_n"].is_number());
    // the whole coupled bridge's ten longest periods, longest first
    let periods: Vec<f64> = summary["model"]["periods_s"]
        .as_array()
        .expect("model.periods_s")
        .iter()
        .map(|t| t.as_f64().unwrap())
        .collect();
    assert_eq!(periods.len(), 10, "{periods:?}");
    assert!(
        periods.windows(2).all(|w| w[0] >= w[1]) && periods[9] > 0.0,
        "{periods:?}"
    );
    // a plain bridge into the same directory leaves none of them behind
    let (code, _, err) = run_capture(&["simulate", &p("plain.toml"), "--out", &p("o")]);
    assert_eq!(code, Some(0), "{err}");
    let have = files(&d.join("o"));
    for f in [
        "piers.csv",
        "backwalls.csv",
        "shear_keys.csv",
        "hysteresis.png",
    ] {
        assert!(!have.contains(f), "stale {f}");
    }
    // segments on the ground are separate systems: their periods are per segment
    let plain: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("o/summary.json")).unwrap()).unwrap();
    assert!(
        plain["model"].get("periods_s").is_none(),
        "{}",
        plain["model"]
    );
    // a bad pier: exit 2, the key and its line, nothing written
    let (code, _, err) = run_capture(&["simulate", &p("bad.toml"), "--out", &p("b")]);
    assert_eq!(code, Some(2), "{err}");
    let line = bad
        .lines()
        .position(|l| l.starts_with("cap_mass = -2.0e5"))
        .unwrap()
        + 1;
    assert!(
        err.contains("pier[0].cap_mass") && err.contains(&format!("bad.toml:{line}")),
        "{err}"
    );
    assert!(!d.join("b").exists());
}

/// A batch of a bridge with piers, backwalls and shear keys has their columns, each row equal to
/// the single run of its record and scale.
#[test]
fn batch_rows_carry_the_members_and_equal_the_single_runs() {
    let short = PLAN.replace("[time]\n", "[time]\nduration = 3.0\n");
    let d = scratch_with("substructure", "batch", &[("plan.toml", &short)]);
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&[
        "simulate",
        &p("plan.toml"),
        "--records",
        "builtin:ELC270",
        "--scales",
        "0.7",
        "--out",
        &p("b"),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(d.join("b/batch.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let cell = |name: &str| {
        row[head
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name}"))]
    };
    let (code, _, err) = run_capture(&[
        "simulate",
        &p("plan.toml"),
        "--record",
        "builtin:ELC270",
        "--scale",
        "0.7",
        "--out",
        &p("s"),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("s/summary.json")).unwrap()).unwrap();
    let num = |v: &serde_json::Value| v.as_f64().unwrap();
    for (k, pier) in s["piers"].as_array().unwrap().iter().enumerate() {
        let j = pier["joint"].as_u64().unwrap();
        assert_eq!(k as u64 + 1, j);
        let got: f64 = cell(&format!("pier{j}_peak_drift_m")).parse().unwrap();
        assert_eq!(got, num(&pier["peak_drift_m"]));
        let got: f64 = cell(&format!("pier{j}_peak_column_force_n"))
            .parse()
            .unwrap();
        assert_eq!(got, num(&pier["peak_column_force_n"]));
    }
    for (side, a) in ["start", "end"]
        .iter()
        .zip(s["abutments"].as_array().unwrap())
    {
        let got: f64 = cell(&format!("abutment_{side}_backfill_peak_n"))
            .parse()
            .unwrap();
        assert_eq!(got, num(&a["backwall"]["peak_backfill_force_n"]));
    }
    for k in s["shear_keys"].as_array().unwrap() {
        let side = k["abutment"].as_str().unwrap();
        let got: f64 = cell(&format!("abutment_{side}_shear_key_peak_force_n"))
            .parse()
            .unwrap();
        assert_eq!(got, num(&k["peak_force_n"]));
    }
}
