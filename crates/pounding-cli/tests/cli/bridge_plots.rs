//! `pounding simulate` of a bridge of `[[segment]]`s: the figures, atomic and cleared between
//! runs (a bridge run after a two-deck run and the reverse leave only the new run's files).

use crate::{pounding, scratch_dir};
use std::collections::BTreeSet;
use std::path::Path;

const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");

const BRIDGE_FILES: [&str; 15] = [
    "bearings.csv",
    "displacements.png",
    "energy.png",
    "history.csv",
    "impacts.csv",
    "joint_openings.png",
    "joint_slip.csv",
    "joint_zoom.png",
    "plan.png",
    "report.html",
    "restrainers.csv",
    "segment_forces.csv",
    "summary.json",
    "timing.json",
    "trajectories.json",
];

const BRIDGE_PNGS: [&str; 5] = [
    "joint_openings.png",
    "displacements.png",
    "plan.png",
    "energy.png",
    "joint_zoom.png",
];

fn files(dir: &Path) -> BTreeSet<String> {
    std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

fn simulate(args: &[&str], out: &Path) {
    let o = pounding()
        .arg("simulate")
        .args(args)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// PNG signature, IHDR width × height, and size.
fn png(path: &Path) -> (u32, u32, usize) {
    let b = std::fs::read(path).unwrap();
    assert_eq!(
        &b[..8],
        b"\x89PNG\r\n\x1a\n",
        "{} is not a PNG",
        path.display()
    );
    assert_eq!(&b[12..16], b"IHDR");
    let be = |i: usize| u32::from_be_bytes(b[i..i + 4].try_into().unwrap());
    (be(16), be(20), b.len())
}

/// A bridge run writes its four figures (valid PNGs of the documented sizes, with content: a
/// blank white 1400 × 600 PNG compresses to a few kB), deterministically; a second run into the
/// same directory rewrites them; a two-deck run's figures (`layout.png`, `joint_gap.png`, …) are
/// cleared by a bridge run into the same directory and the bridge's by a two-deck run.
#[test]
fn bridge_run_writes_figures_and_reruns_leave_no_stale_files() {
    let dir = scratch_dir("bplots", "figures");
    let scenario = dir.join("curved.toml");
    let short = CURVED_5.replace("history_every = 10", "history_every = 10\nduration = 8.0");
    assert_ne!(short, CURVED_5, "the example lost `history_every = 10`");
    std::fs::write(&scenario, short).unwrap();
    let sc = scenario.to_str().unwrap();
    let out = dir.join("out");
    // a two-deck run first: its figures must not survive the bridge run
    simulate(&[], &out);
    assert!(files(&out).contains("layout.png"));
    simulate(&[sc], &out);
    let want: BTreeSet<String> = BRIDGE_FILES.iter().map(|s| s.to_string()).collect();
    assert_eq!(
        files(&out),
        want,
        "stale or missing files after the bridge run"
    );
    // joint_zoom: 4 joints × 2 corner pairs + 2 abutments × 2 corners = 12 panels, 3 rows of 4
    let sizes = [
        (1400, 900),
        (1400, 600),
        (1000, 1300),
        (1400, 600),
        (1400, 60 + 340 * 3),
    ];
    let mut first = Vec::new();
    for (name, size) in BRIDGE_PNGS.iter().zip(sizes) {
        let (w, h, len) = png(&out.join(name));
        assert_eq!((w, h), size, "{name}");
        assert!(len > 20_000, "{name} is only {len} bytes: nothing drawn?");
        first.push(std::fs::read(out.join(name)).unwrap());
    }
    // the same run again: the same files, byte for byte
    simulate(&[sc], &out);
    assert_eq!(files(&out), want);
    for (name, bytes) in BRIDGE_PNGS.iter().zip(&first) {
        assert!(
            std::fs::read(out.join(name)).unwrap() == *bytes,
            "{name} differs between two identical runs"
        );
    }
    // and a two-deck run clears the bridge-only figures
    simulate(&[], &out);
    let after = files(&out);
    for name in ["joint_openings.png", "plan.png"] {
        assert!(
            !after.contains(name),
            "{name} left by the bridge run: {after:?}"
        );
    }
}

/// One segment (no joint) with and without an abutment: every figure is still written (the joint
/// panel is left out, not drawn empty) and `summary.json` has no joints.
#[test]
fn single_segment_bridge_writes_every_figure() {
    let dir = scratch_dir("bplots", "single");
    let base = "[bridge]\ndamping_ratio = 0.05\n\n[[segment]]\nshape = \"straight\"\nL = 30.0\n\
                mass = 1.0e6\nperiod_s = 1.2\n\n[ground_motion]\nrecord_y = \"builtin:ELC180\"\n\
                record_x = \"none\"\n\n[time]\ndt = 1e-3\nduration = 4.0\n";
    for (name, extra) in [
        ("free", ""),
        ("abutment", "\n[abutment.start]\ngap = 0.04\n"),
    ] {
        let scenario = dir.join(format!("{name}.toml"));
        std::fs::write(&scenario, format!("{base}{extra}")).unwrap();
        let out = dir.join(name);
        simulate(&[scenario.to_str().unwrap()], &out);
        let want: BTreeSet<String> = BRIDGE_FILES.iter().map(|s| s.to_string()).collect();
        assert_eq!(files(&out), want, "{name}");
        for png_name in BRIDGE_PNGS {
            let (_, _, len) = png(&out.join(png_name));
            assert!(len > 5_000, "{name}: {png_name} is only {len} bytes");
        }
        let s: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap();
        assert_eq!(s["joints"].as_array().map(Vec::len), Some(0), "{name}: {s}");
    }
}
