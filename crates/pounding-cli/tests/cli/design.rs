//! `pounding design` end to end on a tiny design (the design example's viaduct, 6 pairs of 2 s at
//! 4 stripes, one variant): the files written, `variants.csv` consistent with each variant's own
//! `fragility.csv`/`maf.csv`; bad input exits 2 naming the file, the variant, the key and the
//! line, and writes nothing.

use crate::{run_capture, scratch_with};

fn base() -> String {
    include_str!("../../../../examples/design/viaduct5.toml")
        .replace("duration = 15.0", "duration = 3.0")
        .replace(
            "levels_g = [0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.4]",
            "levels_g = [0.2, 0.4, 0.7, 1.2]",
        )
        .replace("bootstrap = 500", "bootstrap = 60")
}

const SUITE: &str = "[synth]\ncount = 6\nseed = 1\npairs = true\nduration = 4.0\n";

fn design(set: &str) -> String {
    format!(
        "[design]\nscenario = \"viaduct5.toml\"\n\n[[variant]]\nname = \"wide\"\n[variant.set]\n{set}\n"
    )
}

#[test]
fn design_writes_the_comparison_and_each_variant() {
    let b = base();
    let dz = design("\"bridge.gap\" = 0.06");
    let d = scratch_with(
        "design",
        "files",
        &[
            ("viaduct5.toml", &b),
            ("suite.toml", SUITE),
            ("design.toml", &dz),
        ],
    );
    let out = d.join("out");
    let (code, stdout, err) = run_capture(&[
        "design",
        d.join("design.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "2",
    ]);
    assert!(code == Some(0) || code == Some(1), "{err}");
    assert!(stdout.contains("paired interval"), "{stdout}");
    for f in [
        "variants.csv",
        "variants.json",
        "design.png",
        "hazard.png",
        "report.html",
        "timing.json",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
    for v in ["as-built", "wide"] {
        for f in [
            "runs.csv",
            "fragility.csv",
            "fragility.json",
            "maf.csv",
            "hazard.csv",
        ] {
            assert!(out.join("variants").join(v).join(f).exists(), "{v}/{f}");
        }
    }
    // variants.csv's value is each variant's own maf.csv value; the change their difference
    let vc = std::fs::read_to_string(out.join("variants.csv")).unwrap();
    let cell = |line: &str, i: usize| line.split(',').nth(i).unwrap().to_string();
    let head: Vec<&str> = vc.lines().next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let value_of = |v: &str, ls: &str| {
        let m = std::fs::read_to_string(out.join("variants").join(v).join("maf.csv")).unwrap();
        m.lines()
            .find(|l| l.starts_with(&format!("{ls},")))
            .map(|l| cell(l, 2))
            .unwrap()
    };
    for line in vc.lines().skip(1) {
        let (v, ls) = (cell(line, 0), cell(line, 1));
        assert_eq!(cell(line, col("value")), value_of(&v, &ls), "{line}");
        if v == "wide" && cell(line, col("status")) == "ok" {
            let x: f64 = cell(line, col("value")).parse().unwrap();
            let x0: f64 = value_of("as-built", &ls).parse().unwrap();
            let dd: f64 = cell(line, col("diff")).parse().unwrap();
            if x0.is_nan() {
                assert!(dd.is_nan(), "no as-built fit, no change: {line}");
            } else {
                assert!(
                    (dd - (x - x0)).abs() <= 1e-12 * x0.abs().max(x.abs()),
                    "{line}"
                );
            }
        }
    }
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("Retrofit comparison") && html.contains("paired"));
}

#[test]
fn design_bad_input_exits_2_and_writes_nothing() {
    let b = base();
    for (name, dz, needles) in [
        (
            "unknown",
            design("\"bridge.gapp\" = 0.06"),
            vec!["design.toml:7", "variant \"wide\"", "bridge.gapp"],
        ),
        (
            "range",
            design("\"bridge.gap\" = -0.06"),
            vec!["design.toml:7", "bridge.gap"],
        ),
        (
            "study",
            design("\"fragility.seed\" = 2"),
            vec!["design.toml:7", "not the study"],
        ),
        (
            "noscenario",
            "[design]\nscenario = \"none.toml\"\n[[variant]]\nname = \"a\"\n".to_string(),
            vec!["design.toml:2", "design.scenario"],
        ),
        (
            "novariant",
            "[design]\nscenario = \"viaduct5.toml\"\n".to_string(),
            vec!["[[variant]]"],
        ),
    ] {
        let d = scratch_with(
            "design",
            name,
            &[
                ("viaduct5.toml", &b),
                ("suite.toml", SUITE),
                ("design.toml", &dz),
            ],
        );
        let out = d.join("out");
        let (code, _, err) = run_capture(&[
            "design",
            d.join("design.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(2), "{name}: {err}");
        for n in needles {
            assert!(err.contains(n), "{name}: {n} not in {err}");
        }
        assert!(!out.exists(), "{name}");
    }
}

/// A second design run into the same `--out` removes the folders of the first run's variants it
/// does not have (the directory never mixes two runs); a folder holding a file `design` does not
/// write is refused before any run (exit 2) and left as it was.
#[test]
fn design_removes_an_earlier_runs_variant_folders() {
    let b = base();
    let first = design("\"bridge.gap\" = 0.06");
    let second = first.replace("name = \"wide\"", "name = \"wider\"");
    let d = scratch_with(
        "design",
        "stale",
        &[
            ("viaduct5.toml", &b),
            ("suite.toml", SUITE),
            ("first.toml", &first),
            ("second.toml", &second),
        ],
    );
    let out = d.join("out");
    let run = |f: &str| {
        run_capture(&[
            "design",
            d.join(f).to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--threads",
            "2",
        ])
    };
    let (code, _, err) = run("first.toml");
    assert!(code == Some(0) || code == Some(1), "{err}");
    assert!(out.join("variants/wide/runs.csv").exists());
    let (code, _, err) = run("second.toml");
    assert!(code == Some(0) || code == Some(1), "{err}");
    assert!(
        !out.join("variants/wide").exists(),
        "the first run's variant stayed"
    );
    let mut names: Vec<String> = std::fs::read_dir(out.join("variants"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["as-built", "wider"]);
    // a foreign file in a stale folder: refused before any run, nothing removed
    std::fs::create_dir_all(out.join("variants/old")).unwrap();
    std::fs::write(out.join("variants/old/notes.txt"), "mine").unwrap();
    std::fs::write(out.join("variants/old/runs.csv"), "x").unwrap();
    let before = std::fs::read(out.join("variants.csv")).unwrap();
    let (code, _, err) = run("first.toml");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("notes.txt") && err.contains("old"), "{err}");
    assert!(out.join("variants/old/runs.csv").exists());
    assert!(out.join("variants/wider/runs.csv").exists());
    assert_eq!(std::fs::read(out.join("variants.csv")).unwrap(), before);
}

/// A hazard table whose rates overflow the MAF integral: `variants.csv` gives the status
/// `maf_not_finite` and no value (never `ok` with `nan`), and the command exits 1.
#[test]
fn design_with_an_overflowing_hazard_exits_1() {
    let b = base();
    let dz = design("\"bridge.gap\" = 0.06");
    let d = scratch_with(
        "design",
        "overflow",
        &[
            ("viaduct5.toml", &b),
            ("suite.toml", SUITE),
            ("design.toml", &dz),
            ("h.csv", "im_g,rate\n0.1,1e300\n0.5,1e-300\n"),
        ],
    );
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "design",
        d.join("design.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--hazard",
        d.join("h.csv").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(1), "{err}");
    let vc = std::fs::read_to_string(out.join("variants.csv")).unwrap();
    let head: Vec<&str> = vc.lines().next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let mut flagged = 0;
    for line in vc.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        let finite = c[col("value")].parse::<f64>().is_ok_and(f64::is_finite);
        assert!(c[col("status")] != "ok" || finite, "{vc}");
        flagged += usize::from(c[col("status")] == "maf_not_finite");
    }
    assert!(flagged > 0, "the table should overflow: {vc}");
    assert!(err.contains("maf_not_finite"), "{err}");
}
