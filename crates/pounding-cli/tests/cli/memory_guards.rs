//! Run-size guards that know the bridge: the history of 200 segments is ~40 times the two-deck
//! row, so a run the two-deck estimate let through aborted allocating (exit 134, an empty
//! output directory); `compare` on such a bridge had no guard at all.

use crate::{run_capture, scratch_with};

fn bridge(n: usize, time: &str) -> String {
    let mut s = String::from("[bridge]\ngap = 0.05\n");
    for _ in 0..n {
        s.push_str("[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1e6\nperiod_s = 1.0\n");
    }
    s + "[ground_motion]\nrecord_y = \"builtin:ELC180\"\n[time]\n" + time
}

#[test]
fn a_bridge_run_or_comparison_too_large_for_memory_is_refused_naming_the_way_around() {
    let d = scratch_with(
        "memory",
        "bridge",
        &[
            ("sim.toml", &bridge(200, "dt = 5e-4\nhistory_every = 1\n")),
            (
                "cmp.toml",
                &bridge(2, "dt = 1e-5\nduration = 300\nhistory_every = 1000000\n"),
            ),
            (
                "ok.toml",
                &bridge(200, "dt = 5e-4\nhistory_every = 6\nduration = 0.01\n"),
            ),
        ],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&["simulate", &p("sim.toml"), "--out", &p("o1")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("run too large") && err.contains("history_every >= 7"),
        "{err}"
    );
    assert!(!d.join("o1").exists(), "nothing written");
    let (code, _, err) = run_capture(&["compare", &p("cmp.toml"), "--out", &p("o2")]);
    assert_eq!(code, Some(2), "{err}");
    // compare coarsens its own history to fit; here even the ground samples of the 6 laws
    // (30 M steps each) do not fit
    assert!(
        err.contains("run too large") && err.contains("GiB") && err.contains("first and last"),
        "{err}"
    );
    assert!(!d.join("o2").exists(), "nothing written");
    // the stride it advises is accepted
    let (code, _, err) = run_capture(&["simulate", &p("ok.toml"), "--out", &p("o3")]);
    assert_eq!(code, Some(0), "{err}");
}

/// The estimate bounds what a run writes: `history.csv` of a 12-segment bridge is below the
/// text part of the estimate, and the estimate per row grows with the segments.
#[test]
fn the_history_estimate_bounds_the_written_history_of_a_bridge() {
    use pounding::sim::options::history_row_bytes;
    let d = scratch_with(
        "memory",
        "rows",
        &[(
            "b.toml",
            &bridge(12, "dt = 1e-3\nduration = 0.5\nhistory_every = 1\n"),
        )],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&["simulate", &p("b.toml"), "--out", &p("o")]);
    assert_eq!(code, Some(0), "{err}");
    let csv = std::fs::read_to_string(d.join("o/history.csv")).unwrap();
    let rows = csv.lines().count() as u64 - 1;
    assert_eq!(rows, 501);
    assert!(
        (csv.len() as u64) < rows * history_row_bytes(12),
        "{} bytes written for {rows} rows",
        csv.len()
    );
    assert!(history_row_bytes(200) > 30 * history_row_bytes(2));
}

/// Hostile-trial findings: a batch whose runs at once exceed the memory limit, a bridge with
/// many bearings per segment (`bearings.csv` grows with them) and an error estimate whose finest
/// refinement is beyond the step limit are refused before any run, naming the way around, and
/// nothing is written.
#[test]
fn batches_many_bearings_and_deep_refinements_are_checked_before_running() {
    let points: Vec<String> = (0..25)
        .flat_map(|i| {
            [
                format!("[{}, -4.0]", 1.2 * i as f64),
                format!("[{}, 4.0]", 1.2 * i as f64),
            ]
        })
        .collect();
    let many = format!(
        "[bridge]\ngap = 0.05\n[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1e6\n\
         bearing_stiffness = 1e6\nbearing_points = [{}]\n\
         [ground_motion]\nrecord_y = \"builtin:ELC180\"\n[time]\ndt = 1e-4\nhistory_every = 1\n\
         duration = 100\n",
        points.join(", ")
    );
    let d = scratch_with(
        "memory",
        "checked",
        &[
            (
                "long.toml",
                &bridge(3, "dt = 1e-4\nduration = 9000\nhistory_every = 1000000\n"),
            ),
            ("many.toml", &many),
        ],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    // one run of 9e7 steps fits (its history is coarse); four at once of the batch do not
    let (code, _, err) = run_capture(&[
        "simulate",
        &p("long.toml"),
        "--records",
        "builtin:ELC180",
        "builtin:ELC270",
        "--threads",
        "2",
        "--out",
        &p("o1"),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("run too large") && err.contains("fewer threads"),
        "{err}"
    );
    assert!(!d.join("o1").exists());
    // 50 bearings on one segment: 200 bearing values a row, not the 16 of four bearings (10⁶
    // rows: about 1.9 GB with four bearings, which would pass; about 9.1 GB with 50)
    let (code, _, err) = run_capture(&["simulate", &p("many.toml"), "--out", &p("o2")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("run too large"), "{err}");
    assert!(!d.join("o2").exists());
    let four = pounding::sim::options::history_row_bytes(1);
    let fifty = pounding::sim::options::history_row_bytes(pounding::sim::options::RunSize {
        segments: 1,
        bearings: 50,
    });
    assert!(fifty > 4 * four, "{fifty} vs {four}");
    // --tol with 8 refinements of a 300 s run at dt 1e-3: dt/1024 is beyond the step limit
    let (code, _, err) = run_capture(&[
        "simulate",
        &p("long.toml"),
        "--duration",
        "300",
        "--dt",
        "1e-3",
        "--tol",
        "1%",
        "--max-refinements",
        "8",
        "--out",
        &p("o3"),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("more than the limit"), "{err}");
    assert!(!d.join("o3").exists());
}
