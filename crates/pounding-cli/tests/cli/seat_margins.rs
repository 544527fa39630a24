//! The governing seat of a curved four-segment viaduct is a joint end, and every report says so:
//! `summary.json` (`governing_seat`, `seats[]`), stderr, `report.html`'s Verdict and code check.
//! Each end's peak seat displacement and ratio are recomputed here from `history.csv` (every
//! step) and the reference geometry in `trajectories.json`: the end's corners `p⁰` placed by the
//! segment's `(x, y, θ)` about its centroid, the displacement `(p − p⁰)·n_in`, the larger of the
//! two corners, the largest over the run, divided by the end's own seat.

use crate::run_capture;
use serde_json::Value;
use std::path::Path;

const SCENARIO: &str = "tests/data/curved-4-joint-governs.toml";

fn v2(v: &Value) -> [f64; 2] {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

#[test]
fn a_joint_end_governs_and_each_ratio_follows_from_the_history() {
    let d = crate::scratch_dir("seats", "curved4");
    let out = d.join("out");
    let sc = Path::new(env!("CARGO_MANIFEST_DIR")).join(SCENARIO);
    let (code, _, stderr) = run_capture(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    let read = |f: &str| std::fs::read_to_string(out.join(f)).unwrap();
    let summary: Value = serde_json::from_str(&read("summary.json")).unwrap();
    let traj: Value = serde_json::from_str(&read("trajectories.json")).unwrap();
    let history = read("history.csv");
    let mut lines = history.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 8001, "every step of 8 s at 1 ms");
    let seats = summary["seats"].as_array().unwrap();
    assert_eq!(seats.len(), 8);
    let mut largest = (String::new(), f64::NEG_INFINITY);
    for (e, seat) in seats.iter().enumerate() {
        let geo = &traj["seats"][e];
        assert_eq!(geo["end"], seat["end"]);
        let i = geo["segment"].as_u64().unwrap() as usize;
        let g = v2(&traj["centroids"][i]);
        let n = v2(&geo["inward"]);
        let (cx, cy, ct) = (
            col(&format!("x{}_m", i + 1)),
            col(&format!("y{}_m", i + 1)),
            col(&format!("theta{}_deg", i + 1)),
        );
        let mut peak = f64::NEG_INFINITY;
        for r in &rows {
            let (s, c) = r[ct].to_radians().sin_cos();
            for p in geo["corners"].as_array().unwrap().iter().map(v2) {
                let (rx, ry) = (p[0] - g[0], p[1] - g[1]);
                let moved = [
                    g[0] + r[cx] + c * rx - s * ry - p[0],
                    g[1] + r[cy] + s * rx + c * ry - p[1],
                ];
                peak = peak.max(moved[0] * n[0] + moved[1] * n[1]);
            }
        }
        let length = seat["seat_length_m"].as_f64().unwrap();
        let got = seat["peak_seat_displacement_m"].as_f64().unwrap();
        // history.csv holds θ in degrees, rounded to its shortest text: 1e-9 m is far below it
        assert!(
            (got - peak).abs() < 1e-9,
            "{}: {got} vs {peak}",
            seat["end"]
        );
        let ratio = seat["ratio"].as_f64().unwrap();
        assert!((ratio - peak / length).abs() < 1e-9, "{}", seat["end"]);
        if ratio > largest.1 {
            largest = (seat["end"].as_str().unwrap().to_string(), ratio);
        }
    }
    // the governing end is a joint end, the largest ratio, not the largest displacement's end
    // by accident: the abutments' seats are 1 m
    let gov = &summary["governing_seat"];
    assert_eq!(gov["end"], largest.0.as_str());
    assert!(
        gov["support"].as_str().unwrap().starts_with("joint"),
        "{gov}"
    );
    let line = format!(
        "governing seat: {} on {}: {} % of its 0.4 m seat",
        largest.0,
        gov["support"].as_str().unwrap(),
        (100.0 * largest.1).round()
    );
    assert!(stderr.contains(&line), "{line:?} not in {stderr}");
    // summary.json's code_check: its sentence is stderr's, its counts are its ends' and gaps'
    let cc = &summary["code_check"];
    let sentence = cc["sentence"].as_str().unwrap();
    assert!(
        stderr.contains(&format!("code check: {sentence}")),
        "{stderr}"
    );
    let ends = cc["ends"].as_array().unwrap();
    assert_eq!(ends.len(), 8);
    let failing = ends
        .iter()
        .filter(|e| e["seat_length_m"].as_f64() < e["governing_m"].as_f64())
        .count();
    assert_eq!(cc["failing_ends"].as_u64().unwrap() as usize, failing);
    assert!(sentence.starts_with(&format!(
        "{}: {failing} of 8 seated ends",
        cc["verdict"].as_str().unwrap()
    )));
    let gaps = cc["gaps"].as_array().unwrap();
    assert_eq!(gaps.len(), 3);
    let failing_gaps = gaps.iter().filter(|g| g["pass"] == false).count();
    assert_eq!(cc["failing_gaps"].as_u64().unwrap() as usize, failing_gaps);
    for (e, seat) in ends.iter().zip(seats) {
        assert_eq!(e["end"], seat["end"]);
        assert_eq!(
            e["peak_seat_displacement_m"],
            seat["peak_seat_displacement_m"]
        );
    }
    // curved segments: the JRA curve term is named as left out
    assert!(cc["omissions"][0].as_str().unwrap().contains("JRA"), "{cc}");
    // report.html: the Verdict names it, and the code check lists every end
    let html = read("report.html");
    let verdict = html.split("<h2 id=\"verdict\">").nth(1).unwrap();
    let verdict = verdict.split("</table>").next().unwrap();
    assert!(
        verdict.contains(&format!(
            "Governing seat: {} on {}",
            largest.0,
            gov["support"].as_str().unwrap()
        )),
        "{verdict}"
    );
    assert!(verdict.contains("<th>code check</th>"), "{verdict}");
    let check = html.split("<h2 id=\"code-check\">").nth(1).unwrap();
    for seat in seats {
        assert!(
            check.contains(&format!("<td>{}</td>", seat["end"].as_str().unwrap())),
            "{}",
            seat["end"]
        );
    }
}

/// A diverged bridge run (both components ×1e300) ends with its status and exit 1, its files
/// written, and no panic: its corners lie ~1e300 m away, which the plan figures once handed to
/// the plotting library (an integer overflow panic, found in a final hostile check).
#[test]
fn a_diverged_bridge_run_draws_its_figures_without_a_panic() {
    let d = crate::scratch_dir("seats", "diverged");
    let out = d.join("out");
    let sc = Path::new(env!("CARGO_MANIFEST_DIR")).join(SCENARIO);
    let (code, _, stderr) = run_capture(&[
        "simulate",
        sc.to_str().unwrap(),
        "--scale",
        "1e300",
        "--duration",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    for f in ["plan.png", "joint_zoom.png", "summary.json", "report.html"] {
        assert!(out.join(f).is_file(), "{f}");
    }
    let s: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_ne!(s["status"], "Completed");
}
