//! `pounding fragility` with a site hazard curve (`[hazard]` or `--hazard`): `maf.csv`,
//! `hazard.csv`, `hazard.png`, the `hazard` object of `fragility.json` and the report section;
//! the MAF recomputed here from `fragility.csv`'s θ and β by the closed form; bad hazard input
//! exits 2 naming the file, the key and the line, and writes nothing.

use crate::fragility::SCENARIO;
use crate::{run_capture, scratch_with};

const HAZARD: &str = "\n[hazard]\nim_unit = \"g\"\nmeasure = \"sa\"\nk0 = 1.0e-4\nk = 2.5\n";

/// The tiny study on 8 synthetic pairs at 5 levels, one limit state fitted, with `hazard`.
fn scenario(hazard: &str) -> String {
    let base = SCENARIO.replace(
        "levels_g = [0.2, 1.0, 3.0]",
        "levels_g = [0.1, 0.2, 0.4, 0.8, 1.6]",
    );
    let base = base
        .split("[[limit_state]]")
        .next()
        .unwrap_or_default()
        .to_string();
    base + "[[limit_state]]\nname = \"opening\"\nkind = \"joint_opening\"\nlimit_m = 0.05\n"
        + hazard
}

const SET: &str = "[synth]\ncount = 8\nseed = 1\npairs = true\nduration = 4.0\n";

fn csv_row(text: &str, row: usize) -> std::collections::HashMap<String, String> {
    let mut l = text.lines();
    let head: Vec<&str> = l.next().unwrap().split(',').collect();
    let vals: Vec<&str> = l.nth(row).unwrap().split(',').collect();
    head.iter()
        .map(|h| h.to_string())
        .zip(vals.iter().map(|v| v.to_string()))
        .collect()
}

fn num(m: &std::collections::HashMap<String, String>, k: &str) -> f64 {
    m[k].parse().unwrap_or_else(|_| panic!("{k} = {}", m[k]))
}

#[test]
fn fragility_with_a_power_law_hazard_writes_the_maf() {
    let d = scratch_with(
        "hazard",
        "power",
        &[("bridge.toml", &scenario(HAZARD)), ("set.toml", SET)],
    );
    let out = d.join("out");
    let (code, stdout, err) = run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "2",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(stdout.contains("MAF_per_yr"), "{stdout}");
    let frag = csv_row(
        &std::fs::read_to_string(out.join("fragility.csv")).unwrap(),
        0,
    );
    let maf = csv_row(&std::fs::read_to_string(out.join("maf.csv")).unwrap(), 0);
    assert_eq!(frag["status"], "ok", "the tiny study must fit: {frag:?}");
    let (theta, beta) = (num(&frag, "theta"), num(&frag, "beta"));
    let closed = 1e-4 * theta.powf(-2.5) * (2.5f64 * 2.5 * beta * beta / 2.0).exp();
    let rate = num(&maf, "maf_per_year");
    assert!(
        ((rate - closed) / closed).abs() < 1e-12,
        "{rate} vs {closed}"
    );
    assert!((num(&maf, "return_period_years") * rate - 1.0).abs() < 1e-12);
    let (lo, hi) = (num(&maf, "maf_lo"), num(&maf, "maf_hi"));
    assert!(lo < rate && rate < hi, "{lo} {rate} {hi}");
    // the interval's bounds are the closed form at replicate fits: within the closed form over
    // the θ and β intervals' corners
    let corners: Vec<f64> = [
        ("theta_lo", "beta_lo"),
        ("theta_lo", "beta_hi"),
        ("theta_hi", "beta_lo"),
        ("theta_hi", "beta_hi"),
    ]
    .iter()
    .map(|(t, b)| 1e-4 * num(&frag, t).powf(-2.5) * (3.125 * num(&frag, b).powi(2)).exp())
    .collect();
    assert!(corners.iter().any(|&c| c >= rate) && corners.iter().any(|&c| c <= rate));
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fragility.json")).unwrap())
            .unwrap();
    assert_eq!(j["hazard"]["curve"]["kind"], "power_law");
    assert_eq!(j["hazard"]["maf"][0]["maf_per_year"].as_f64(), Some(rate));
    // the deaggregation integrates (trapezoid over ln IM) to about the MAF
    let h = std::fs::read_to_string(out.join("hazard.csv")).unwrap();
    let pts: Vec<(f64, f64)> = h
        .lines()
        .skip(1)
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            (
                c[1].parse::<f64>().unwrap().ln(),
                c[4].parse::<f64>().unwrap(),
            )
        })
        .collect();
    assert_eq!(pts.len(), 81);
    let integral: f64 = pts
        .windows(2)
        .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
        .sum();
    assert!((integral / rate - 1.0).abs() < 0.05, "{integral} vs {rate}");
    let report = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(report.contains("Mean annual frequency") && report.contains("hazard.png"));
    assert!(out.join("hazard.png").exists());
}

#[test]
fn fragility_hazard_flag_reads_a_csv_table() {
    let d = scratch_with(
        "hazard",
        "csv",
        &[
            ("bridge.toml", &scenario("")),
            ("set.toml", SET),
            (
                "h.csv",
                "# site X\nim_g,rate\n0.01,0.1\n0.05,0.01\n0.1,0.003\n0.2,8e-4\n0.4,2e-4\n0.8,4e-5\n1.6,6e-6\n3.2,8e-7\n",
            ),
        ],
    );
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--hazard",
        d.join("h.csv").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let maf = csv_row(&std::fs::read_to_string(out.join("maf.csv")).unwrap(), 0);
    assert!(maf["hazard"].ends_with("h.csv"));
    assert!(num(&maf, "upper_tail_hi") == 8e-7 && num(&maf, "p_first_im") < 0.5);
}

/// (name, scenario, a `--hazard` file (name, text), what stderr must hold).
type Case = (
    &'static str,
    String,
    Option<(&'static str, &'static str)>,
    &'static [&'static str],
);

#[test]
fn bad_hazard_input_exits_2_naming_file_key_and_line() {
    let cases: [Case; 5] = [
        (
            "decrease",
            scenario(
                "\n[hazard]\nim_unit = \"g\"\nim = [0.1, 0.2, 0.4]\nrate = [1e-2, 2e-2, 1e-3]\n",
            ),
            None,
            &["hazard.rate[1]", "does not decrease", "bridge.toml:"],
        ),
        (
            "unit",
            scenario("\n[hazard]\nim_unit = \"cm/s2\"\nk0 = 1e-4\nk = 2.5\n"),
            None,
            &["hazard.im_unit", "in g", "bridge.toml:"],
        ),
        (
            "measure",
            scenario("\n[hazard]\nim_unit = \"g\"\nmeasure = \"pga\"\nk0 = 1e-4\nk = 2.5\n"),
            None,
            &["hazard.measure", "fragility's IM is Sa"],
        ),
        (
            "csvunit",
            scenario(""),
            Some(("h.csv", "im_m/s2,rate\n1,0.01\n2,0.001\n")),
            &["h.csv:1", "im_m/s2", "in g"],
        ),
        (
            "csvneg",
            scenario(""),
            Some(("h.csv", "im_g,rate\n0.1,0.01\n-0.2,0.001\n")),
            &["h.csv:3", "im_g"],
        ),
    ];
    for (name, sc, file, needles) in cases {
        let mut files = vec![("bridge.toml", sc.as_str()), ("set.toml", SET)];
        if let Some(f) = file {
            files.push(f);
        }
        let d = scratch_with("hazard", name, &files);
        let out = d.join("out");
        let mut args = vec![
            "fragility".to_string(),
            d.join("bridge.toml").display().to_string(),
            "--out".into(),
            out.display().to_string(),
        ];
        if let Some((f, _)) = file {
            args.extend(["--hazard".into(), d.join(f).display().to_string()]);
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, _, err) = run_capture(&args);
        assert_eq!(code, Some(2), "{name}: {err}");
        for n in needles {
            assert!(err.contains(n), "{name}: {n} not in {err}");
        }
        assert!(!out.exists(), "{name}: wrote {}", out.display());
    }
}

/// A table whose rates span the whole floating-point range (1e300 to 1e-300 per year) overflows
/// the integral: the limit state's MAF row says so (`maf_not_finite`), never `ok` with `nan`, and
/// the command exits 1 (a status that is not a number is a failure, not a success).
#[test]
fn an_overflowing_hazard_table_is_not_an_ok_maf() {
    let d = scratch_with(
        "hazard",
        "overflow",
        &[
            ("bridge.toml", &scenario("")),
            ("set.toml", SET),
            ("h.csv", "im_g,rate\n0.1,1e300\n0.5,1e-300\n"),
        ],
    );
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--hazard",
        d.join("h.csv").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("maf_not_finite"), "{err}");
    let text =
        std::fs::read_to_string(out.join("maf.csv")).unwrap_or_else(|e| panic!("{e}: {err}"));
    let rows = text.lines().count() - 1;
    let mut flagged = 0;
    for i in 0..rows {
        let m = csv_row(&text, i);
        let finite = m["maf_per_year"].parse::<f64>().is_ok_and(f64::is_finite);
        assert!(m["status"] != "ok" || finite, "{text}");
        flagged += usize::from(m["status"] == "maf_not_finite");
    }
    assert!(flagged > 0, "the table should overflow: {text}");
}
