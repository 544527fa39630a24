//! The shipped example `examples/fragility/` end to end (a reduced copy: fewer records and
//! stripes, shorter runs, fewer bootstrap resamples, so that it runs in seconds in the test
//! profile), and `[synth]` manifests giving the same bytes as the files `pounding motion synth`
//! writes.

use crate::{run_capture, scratch_dir};
use std::path::Path;

fn example(name: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/fragility")
        .join(name);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Replaces `from` (which must occur) by `to`.
fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "{from:?} not in the example");
    text.replace(from, to)
}

/// A copy of the example in a temp dir: `count` pairs of `duration` s, the first `stripes`
/// levels, runs of `run_s` s and 50 bootstrap resamples.
fn reduced(name: &str, count: usize, stripes: usize, run_s: &str) -> crate::Scratch {
    let d = scratch_dir("fragex", name);
    let scen = example("viaduct.toml");
    let levels_line = scen
        .lines()
        .find(|l| l.starts_with("levels_g = "))
        .expect("levels_g in the example");
    let levels: Vec<&str> = levels_line["levels_g = [".len()..levels_line.len() - 1]
        .split(", ")
        .collect();
    assert_eq!(levels.len(), 8, "the example has 8 stripes");
    let keep = levels[levels.len() - stripes..].join(", ");
    let scen = edit(&scen, levels_line, &format!("levels_g = [{keep}]"));
    let scen = edit(&scen, "duration = 15.0", &format!("duration = {run_s}"));
    let scen = edit(&scen, "bootstrap = 500", "bootstrap = 50");
    std::fs::write(d.join("viaduct.toml"), scen).unwrap();
    let suite = edit(
        &example("suite.toml"),
        "count = 20",
        &format!("count = {count}"),
    );
    std::fs::write(d.join("suite.toml"), suite).unwrap();
    d
}

#[test]
fn fragility_example_runs_end_to_end_and_fits_both_limit_states() {
    // the shipped files as they are: 20 pairs, 8 stripes, two limit states
    let suite = example("suite.toml");
    assert!(suite.contains("count = 20") && suite.contains("pairs = true"));
    let scen = example("viaduct.toml");
    assert_eq!(scen.matches("[[limit_state]]").count(), 2);
    assert!(scen.contains("records = \"suite.toml\"") && scen.contains("im = \"sa\""));

    let (count, stripes) = (6, 5);
    let d = reduced("e2e", count, stripes, "6.0");
    let (code, stdout, err) = run_capture(&[
        "fragility",
        d.join("viaduct.toml").to_str().unwrap(),
        "--out",
        d.join("out").to_str().unwrap(),
        "--threads",
        "2",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(stdout.contains("period: T1 = "), "{stdout}");
    for f in ["fragility.png", "report.html"] {
        let len = std::fs::metadata(d.join("out").join(f)).map(|m| m.len());
        assert!(len.as_ref().is_ok_and(|l| *l > 1000), "{f}: {len:?}");
    }
    let runs = std::fs::read_to_string(d.join("out/runs.csv")).unwrap();
    let mut lines = runs.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(head[0], "record");
    let status = head.iter().position(|h| *h == "status").unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), count * stripes);
    assert_eq!(rows[0][0], "SYN001");
    assert!(rows.iter().all(|r| r[status] == "Completed"), "{runs}");
    let csv = std::fs::read_to_string(d.join("out/fragility.csv")).unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let fits: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let names: Vec<&str> = fits.iter().map(|r| r[col("limit_state")]).collect();
    assert_eq!(names, ["joint_opening", "bearing"], "{csv}");
    for f in &fits {
        assert_eq!(f[col("status")], "ok", "{csv}");
        let theta: f64 = f[col("theta")].parse().unwrap();
        let beta: f64 = f[col("beta")].parse().unwrap();
        assert!(
            theta.is_finite() && theta > 0.0 && beta.is_finite() && beta > 0.0,
            "{csv}"
        );
    }
}

#[test]
fn a_synth_manifest_gives_the_bytes_of_the_files_motion_synth_writes() {
    let d = reduced("same", 2, 2, "2.0");
    let (code, _, err) = run_capture(&[
        "motion",
        "synth",
        "--count",
        "2",
        "--seed",
        "1",
        "--pairs",
        "--dt",
        "0.01",
        "--duration",
        "20",
        "--out",
        d.join("files").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    // the [set] name as motion synth writes it (the figure's title may show it)
    std::fs::write(
        d.join("suite.toml"),
        "[set]\nname = \"synthetic\"\n[synth]\ncount = 2\nseed = 1\npairs = true\ndt = 0.01\nduration = 20.0\n",
    )
    .unwrap();
    let go = |set: &Path, out: &str| {
        let (code, _, err) = run_capture(&[
            "fragility",
            d.join("viaduct.toml").to_str().unwrap(),
            "--set",
            set.to_str().unwrap(),
            "--out",
            d.join(out).to_str().unwrap(),
            "--threads",
            "1",
        ]);
        assert_eq!(code, Some(0), "{err}");
    };
    go(&d.join("suite.toml"), "mem");
    go(&d.join("files/suite.toml"), "files");
    for f in [
        "runs.csv",
        "fragility.csv",
        "fragility.json",
        "fragility.png",
    ] {
        let a = std::fs::read(d.join("mem").join(f)).unwrap();
        let b = std::fs::read(d.join("files").join(f)).unwrap();
        assert!(a == b, "{f} differs between [synth] and the written files");
    }
}
