//! `report.html` of `pounding simulate` (issue 12): written with every run, two decks and
//! bridges; it shows the status, the warnings, every summary key, the replacements given on the
//! command line and every figure the run drew, and links only to files that exist.

use crate::{run_capture, scratch_dir};

fn run(name: &str, args: &[&str]) -> (Option<i32>, crate::InScratch, String) {
    let d = scratch_dir("simreport", name);
    let out = d.join("out");
    let mut a = vec!["simulate"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let (code, _, err) = run_capture(&a);
    let html = std::fs::read_to_string(out.join("report.html")).unwrap_or_default();
    (code, d.into_join("out"), html + &err)
}

/// Every `src="..."`/`href="..."` target of the page exists beside it.
fn links_resolve(out: &std::path::Path, html: &str) {
    for attr in ["src=\"", "href=\""] {
        for part in html.split(attr).skip(1) {
            let target = &part[..part.find('"').unwrap()];
            if target.starts_with('#') {
                continue;
            }
            assert!(out.join(target).is_file(), "{target} does not exist");
        }
    }
}

#[test]
fn two_deck_report_shows_the_run() {
    let (code, out, html) = run(
        "two",
        &["--duration", "4", "--law", "hertz-damp", "--dt", "1e-4"],
    );
    assert_eq!(code, Some(0), "{html}");
    assert!(html.contains("Status: <strong class=\"v-reproduced\">Completed</strong>"));
    assert!(
        html.contains("--dt 0.0001 --duration 4 --law hertz-damp"),
        "flags missing"
    );
    // the plan animation of the two decks (their two-segment bridge) and its data
    assert!(html.contains("id=\"an-plan\""), "no plan animation");
    let traj: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("trajectories.json")).unwrap()).unwrap();
    assert_eq!(traj["segments"], 2);
    // each frame's q is the history row at its time (x1, y1, theta1, x2, y2, theta2)
    let hist = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let rows: Vec<Vec<f64>> = hist
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    let frames = traj["frames"].as_array().unwrap();
    let stride = traj["stride"].as_u64().unwrap() as usize;
    for (k, f) in frames.iter().enumerate().step_by(97) {
        let row = &rows[k * stride];
        assert_eq!(f["t"].as_f64().unwrap(), row[0]);
        let q: Vec<f64> = f["q"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        // serde_json reads floats to within an ulp (as the trajectories test of the library)
        for (a, b) in q.iter().zip(&row[3..9]) {
            assert!((a - b).abs() <= 1e-15 * b.abs(), "frame {k}: {a} vs {b}");
        }
    }
    let summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    for (k, v) in summary.as_object().unwrap() {
        // ground_motion has its own section; its keys are rows there
        // ground_motion and warnings have their own sections; ground_motion's keys are rows
        let keys: Vec<&String> = match (k.as_str(), v.as_object()) {
            ("ground_motion", Some(o)) => o.keys().collect(),
            ("warnings", _) => vec![],
            _ => vec![k],
        };
        for k in keys {
            assert!(html.contains(&format!(">{k}<")), "summary key {k} missing");
        }
    }
    for f in [
        "displacements.png",
        "layout.png",
        "joint_gap.png",
        "energy.png",
    ] {
        assert!(html.contains(&format!("src=\"{f}\"")), "{f} missing");
    }
    links_resolve(&out, &html);
}

#[test]
fn bridge_report_shows_the_arrays_and_the_warnings() {
    let f = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/viaduct-1d.toml"
    );
    // a step too coarse for the contact law: a warning on stderr and in the report
    let (code, out, html) = run("bridge", &[f, "--duration", "3", "--dt", "2e-3"]);
    assert_eq!(code, Some(0), "{html}");
    assert!(html.contains("a bridge of 3 segments"));
    let warn = html.find("id=\"warnings\"").unwrap();
    let body = &html[warn..html.find("id=\"ground\"").unwrap()];
    assert!(body.contains("too coarse for the contact law"), "{body}");
    for t in ["<h3>joints</h3>", "<h3>segments</h3>", "<h3>abutments</h3>"] {
        assert!(html.contains(t), "{t} missing");
    }
    for f in ["joint_openings.png", "plan.png"] {
        assert!(html.contains(&format!("src=\"{f}\"")), "{f} missing");
    }
    links_resolve(&out, &html);
}
