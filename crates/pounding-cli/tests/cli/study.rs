//! `pounding study`: outputs, bad scenarios, sharding + merge, thread independence, report links.

use crate::pounding;
use std::path::Path;

/// A small study without figures (2 geometries, 2 μ, 5 × 9 cells); also used by
/// `reports_browser.rs`.
pub(crate) const SMALL: &str = r#"
[decks]
beta1_deg = [60.0]
beta2_deg = [90.0, 60.0]
r1_m = [100.0]
r2_m = [200.0]
[impact]
mu = [0.0, 0.5]
[grid]
theta1_deg = { start = -4.0, stop = 4.0, step = 2.0 }
theta2_deg = { start = -4.0, stop = 4.0, step = 1.0 }
[output]
figures = false
"#;

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("cli-study", name)
}

fn run(args: &[&str]) -> std::process::Output {
    pounding().args(args).output().unwrap()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

const OUTPUTS: [&str; 5] = [
    "bounds.csv",
    "summary.csv",
    "summary.json",
    "scenario.toml",
    "report.html",
];

#[test]
fn small_study_writes_every_output() {
    let d = tmp("small");
    let sc = d.join("small.toml");
    std::fs::write(&sc, SMALL).unwrap();
    let out = d.join("out");
    let o = run(&["study", s(&sc), "--out", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in OUTPUTS {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    let bounds = std::fs::read_to_string(out.join("bounds.csv")).unwrap();
    // 2 geometries x 2 mu x 4 cases x 5 x 9 cells + header
    assert_eq!(bounds.lines().count(), 2 * 2 * 4 * 45 + 1);
    assert!(bounds.lines().skip(1).all(|l| l.ends_with(",true")));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        html.contains("contradicted"),
        "the report must say where numbers contradict the paper"
    );
    assert!(html.contains("inward slip is negligible"));
    assert!(html.contains(env!("CARGO_PKG_VERSION")));
    assert_eq!(
        std::fs::read_to_string(out.join("scenario.toml")).unwrap(),
        SMALL
    );
    // no temporary files left behind
    assert!(
        std::fs::read_dir(&out).unwrap().all(|e| !e
            .unwrap()
            .file_name()
            .to_string_lossy()
            .ends_with(".tmp"))
    );
}

#[test]
fn figures_are_drawn_and_every_report_link_resolves() {
    let d = tmp("figs");
    let sc = d.join("figs.toml");
    std::fs::write(
        &sc,
        SMALL.replace("figures = false", "figures = true\nregion_map_samples = 21"),
    )
    .unwrap();
    let out = d.join("out");
    let o = run(&["study", s(&sc), "--out", s(&out), "--svg"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Every page reachable from report.html (the index and one page per geometry).
    let mut links = 0;
    let mut pages = vec![out.join("report.html").canonicalize().unwrap()];
    let mut seen = std::collections::BTreeSet::new();
    while let Some(page) = pages.pop() {
        if !seen.insert(page.clone()) {
            continue;
        }
        let html = std::fs::read_to_string(&page).unwrap();
        let here = page.parent().unwrap().to_path_buf();
        for attr in ["src=\"", "href=\""] {
            for part in html.split(attr).skip(1) {
                let target = &part[..part.find('"').unwrap()];
                if target.starts_with('#') {
                    continue;
                }
                assert!(
                    !target.contains("://") && !target.starts_with('/'),
                    "non-relative link {target}"
                );
                let p = here.join(target);
                assert!(p.is_file(), "{} links to missing {target}", page.display());
                if target.ends_with(".html") {
                    pages.push(p.canonicalize().unwrap());
                }
                links += 1;
            }
        }
    }
    // The index and one page per geometry, each reached (paths normalised by the links).
    let names: std::collections::BTreeSet<String> = seen
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        names,
        [
            "report.html",
            "b1-60_b2-60_r1-100_r2-200.html",
            "b1-60_b2-90_r1-100_r2-200.html"
        ]
        .map(String::from)
        .into()
    );
    // 2 geometries x 2 mu surfaces + 2 region maps + 3 overviews, PNG img+href and SVG href
    let pngs = std::fs::read_dir(out.join("figures"))
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "png")
        })
        .count();
    assert_eq!(pngs, 4 + 2 + 3);
    assert!(links >= 3 * pngs);
    let png = std::fs::read(out.join("figures/overview_mu.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn bad_scenarios_fail_naming_key_and_line_and_write_nothing() {
    let d = tmp("bad");
    let cases: [(&str, &str, &str); 5] = [
        ("[impact]\nmu = [0.1,\n", "line 2", "`impact.mu`"),
        ("[decks]\nwidht_m = 10.0\n", "line 2", "`decks.widht_m`"),
        (
            "[decks]\nr1_m = [100.0]\nr2_m = [4.0]\n",
            "line 3",
            "decks.r2_m[0]",
        ),
        ("\n[impact]\neps = []\n", "line 3", "impact.eps"),
        (
            "[grid]\ntheta1_deg = { start = -1.0, stop = 1.0, step = 0.0 }\n",
            "line 2",
            "grid.theta1_deg.step",
        ),
    ];
    for (k, (text, line, key)) in cases.iter().enumerate() {
        let sc = d.join(format!("bad{k}.toml"));
        std::fs::write(&sc, text).unwrap();
        let out = d.join(format!("out{k}"));
        let o = run(&["study", s(&sc), "--out", s(&out)]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(line) && err.contains(key), "case {k}: {err}");
        assert!(err.contains(&format!("bad{k}.toml")), "{err}");
        assert!(!out.exists(), "case {k}: output directory was created");
    }
    // An unreadable file and a bad shard spec are errors too.
    let o = run(&["study", s(&d.join("nope.toml")), "--out", s(&d.join("o"))]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["study", "--shard", "4/3", "--out", s(&d.join("o"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!d.join("o").exists());
}

#[test]
fn sharded_then_merged_equals_unsharded_byte_for_byte() {
    let d = tmp("shard");
    let sc = d.join("small.toml");
    // with figures: the merged run draws them from the parsed rows
    std::fs::write(
        &sc,
        SMALL.replace("figures = false", "figures = true\nregion_map_samples = 11"),
    )
    .unwrap();
    let whole = d.join("whole");
    assert!(run(&["study", s(&sc), "--out", s(&whole)]).status.success());
    let mut dirs = Vec::new();
    for k in 1..=3 {
        let sd = d.join(format!("shard{k}"));
        let o = run(&[
            "study",
            s(&sc),
            "--shard",
            &format!("{k}/3"),
            "--out",
            s(&sd),
            "--threads",
            "1",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(
            !sd.join("bounds.csv").exists(),
            "a shard must not look like a complete run"
        );
        dirs.push(sd);
    }
    let merged = d.join("merged");
    let mut args = vec!["study", "merge"];
    // any order
    args.extend([s(&dirs[2]), s(&dirs[0]), s(&dirs[1])]);
    args.extend(["--out", s(&merged)]);
    let o = run(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut files: Vec<String> = OUTPUTS.iter().map(|f| f.to_string()).collect();
    for e in std::fs::read_dir(whole.join("figures")).unwrap() {
        files.push(format!(
            "figures/{}",
            e.unwrap().file_name().to_string_lossy()
        ));
    }
    assert!(files.len() > OUTPUTS.len() + 5);
    for f in &files {
        let a = std::fs::read(whole.join(f)).unwrap();
        let b = std::fs::read(merged.join(f)).unwrap();
        assert!(a == b, "{f} differs between merged and unsharded runs");
    }
    // an incomplete set of shards is refused
    let o = run(&[
        "study",
        "merge",
        s(&dirs[0]),
        s(&dirs[1]),
        "--out",
        s(&d.join("m2")),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("missing"));
}

#[test]
fn outputs_do_not_depend_on_threads() {
    let d = tmp("threads");
    let sc = d.join("small.toml");
    std::fs::write(&sc, SMALL).unwrap();
    let (a, b) = (d.join("t1"), d.join("t2"));
    assert!(
        run(&["study", s(&sc), "--out", s(&a), "--threads", "1"])
            .status
            .success()
    );
    assert!(
        run(&["study", s(&sc), "--out", s(&b), "--threads", "2"])
            .status
            .success()
    );
    for f in OUTPUTS {
        assert!(
            std::fs::read(a.join(f)).unwrap() == std::fs::read(b.join(f)).unwrap(),
            "{f} depends on --threads"
        );
    }
    let o = run(&["study", s(&sc), "--out", s(&d.join("t0")), "--threads", "0"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn print_default_is_the_built_in_scenario() {
    let o = run(&["study", "--print-default"]);
    assert!(o.status.success());
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("mu = [0.0, 0.25, 0.5, 1.0]"));
    // Edited copy runs: a user can start from it.
    let d = tmp("default");
    let sc = d.join("edited.toml");
    let edited = text
        .replace("beta1_deg = [60.0, 90.0, 120.0]", "beta1_deg = [90.0]")
        .replace("beta2_deg = [60.0, 90.0, 120.0]", "beta2_deg = [90.0]")
        .replace("R1 = [100.0, 200.0]", "R1 = [100.0]")
        .replace("figures = true", "figures = false");
    std::fs::write(&sc, &edited).unwrap();
    let out = d.join("out");
    let o = run(&["study", s(&sc), "--out", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = std::fs::read_to_string(out.join("bounds.csv"))
        .unwrap()
        .lines()
        .count()
        - 1;
    assert_eq!(rows, 2 * 4 * 4 * 441);
}

#[test]
fn absurd_thread_counts_and_row_counts_are_refused() {
    let dir = tmp("limits");
    let sc = dir.join("s.toml");
    std::fs::write(&sc, SMALL).unwrap();
    let out = dir.join("out");
    let o = run(&["study", s(&sc), "--out", s(&out), "--threads", "100000"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--threads 100000"));
    assert!(!out.exists(), "nothing may be written");
    // 20 001 x 20 001 cells x 4 cases x 1 configuration: far beyond one run's memory bound.
    let huge = SMALL
        .replace(
            "theta1_deg = { start = -4.0, stop = 4.0, step = 2.0 }",
            "theta1_deg = { start = -10.0, stop = 10.0, step = 0.001 }",
        )
        .replace(
            "theta2_deg = { start = -4.0, stop = 4.0, step = 1.0 }",
            "theta2_deg = { start = -10.0, stop = 10.0, step = 0.001 }",
        );
    std::fs::write(&sc, huge).unwrap();
    let o = run(&["study", s(&sc), "--out", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--shard"), "{err}");
    assert!(!out.exists(), "nothing may be written");
}

#[test]
fn a_new_run_removes_the_previous_runs_markers_and_figures() {
    let dir = tmp("stale");
    let sc = dir.join("s.toml");
    std::fs::write(&sc, SMALL).unwrap();
    let out = dir.join("out");
    std::fs::create_dir_all(out.join("figures")).unwrap();
    let stale = out.join("figures").join("surface_old.png");
    std::fs::write(&stale, b"old").unwrap();
    std::fs::create_dir_all(out.join("report")).unwrap();
    let stale_page = out.join("report").join("b1-1_b2-1_r1-1_r2-1.html");
    std::fs::write(&stale_page, b"old").unwrap();
    std::fs::write(out.join("timing.json"), b"{}").unwrap();
    let o = run(&["study", s(&sc), "--out", s(&out)]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!stale.exists(), "a stale figure of an earlier run survived");
    assert!(
        !stale_page.exists(),
        "a stale geometry page of an earlier run survived"
    );
    let timing = std::fs::read_to_string(out.join("timing.json")).unwrap();
    assert!(timing.contains("total_s"), "timing.json is not this run's");
}
