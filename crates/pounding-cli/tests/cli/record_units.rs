//! One text record, one scenario, every reading path: `simulate`, a `--records` batch,
//! `compare` and a `fragility` manifest entry without `units` all read the record in the
//! scenario's `csv_units` (a manifest used to read it in g whatever the scenario said: IMs and
//! scale factors 9.81 × off, and no implausible-PGA warning).

use crate::{run_capture, scratch_with};

/// `a(t) = 3 sin(2π t)` m/s² for 2 s at 0.01 s: a PGA of 3 m/s² (3 g if misread in g).
fn record() -> String {
    let mut s = String::from("t,a\n");
    for k in 0..=200 {
        let t = k as f64 * 0.01;
        s.push_str(&format!(
            "{t:.2},{}\n",
            3.0 * (2.0 * std::f64::consts::PI * t).sin()
        ));
    }
    s
}

fn scenario(units: &str) -> String {
    let base = crate::fragility::SCENARIO;
    base.replace(
        "[ground_motion]\nscale_y = -1.0",
        &format!(
            "[ground_motion]\nrecord_y = \"rec.csv\"\nrecord_x = \"none\"\ncsv_units = \
             \"{units}\"\nscale_y = -1.0"
        ),
    )
    .replace(
        "im = \"sa\"\nperiod_s = \"model\"\nlevels_g = [0.2, 1.0, 3.0]",
        "im = \"pga\"\nlevels_g = [0.1, 0.2]",
    )
}

#[test]
fn every_path_reads_a_text_record_in_the_scenarios_csv_units() {
    let rec = record();
    let sc = scenario("m/s2");
    assert!(sc.contains("csv_units = \"m/s2\"") && sc.contains("im = \"pga\""));
    let d = scratch_with(
        "units",
        "paths",
        &[
            ("rec.csv", &rec),
            ("bridge.toml", &sc),
            ("set.toml", "[[record]]\nid = \"R\"\nx = \"rec.csv\"\n"),
        ],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    // simulate
    let (_, _, err) = run_capture(&["simulate", &p("bridge.toml"), "--out", &p("sim")]);
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("sim/summary.json")).expect(&err))
            .unwrap();
    let pga = s["ground_motion"]["pga_y_mps2"].as_f64().unwrap();
    assert!((pga - 3.0).abs() < 1e-9, "simulate read PGA {pga} m/s2");
    // a batch over the same file
    let (_, _, err) = run_capture(&[
        "simulate",
        &p("bridge.toml"),
        "--records",
        &p("rec.csv"),
        "--scales",
        "1",
        "--out",
        &p("batch"),
    ]);
    let batch = std::fs::read_to_string(d.join("batch/batch.csv")).expect(&err);
    let head: Vec<&str> = batch.lines().next().unwrap().split(',').collect();
    let row: Vec<&str> = batch.lines().nth(1).unwrap().split(',').collect();
    let col = head.iter().position(|c| *c == "pga_mps2").unwrap();
    assert!(
        (row[col].parse::<f64>().unwrap() - 3.0).abs() < 1e-9,
        "batch: {}",
        row[col]
    );
    // compare prints how it read the record
    let (_, _, err) = run_capture(&["compare", &p("bridge.toml"), "--out", &p("cmp")]);
    assert!(err.contains("units m/s2 (csv_units)"), "{err}");
    // fragility: a manifest entry without units, PGA stripes: scale = level g0 / 3 m/s2
    let (code, _, err) = run_capture(&["fragility", &p("bridge.toml"), "--out", &p("frag")]);
    assert!(code.is_some(), "{err}");
    assert!(!err.contains("PGA of"), "no implausible-PGA warning: {err}");
    let runs = std::fs::read_to_string(d.join("frag/runs.csv")).expect(&err);
    let head: Vec<&str> = runs.lines().next().unwrap().split(',').collect();
    let (lc, sc_col) = (
        head.iter().position(|c| *c == "level_g").unwrap(),
        head.iter().position(|c| *c == "scale_factor").unwrap(),
    );
    for line in runs.lines().skip(1) {
        let r: Vec<&str> = line.split(',').collect();
        let level: f64 = r[lc].parse().unwrap();
        let scale: f64 = r[sc_col].parse().unwrap();
        let want = level * 9.80665 / 3.0;
        assert!(
            (scale - want).abs() <= 1e-12 * want,
            "scale {scale} vs {want}"
        );
    }
    // the same manifest under csv_units = "g" reads 3 g and says so
    std::fs::write(d.join("bridge.toml"), scenario("g")).unwrap();
    let (_, _, err) = run_capture(&["fragility", &p("bridge.toml"), "--out", &p("frag-g")]);
    assert!(
        err.contains("record set entry \"R\"") && err.contains("PGA of 3.000 g"),
        "{err}"
    );
}
