//! `pounding study` with straight and skewed decks: outputs, figures, report and bad input.

use crate::pounding;
use std::path::Path;

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("cli-study-shapes", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The example straight-deck scenario (with a coarser grid and fewer region samples to stay fast):
/// every output, the shape columns, figures whose titles name the shape, every report link resolves.
#[test]
fn straight_example_study_runs_with_figures() {
    let d = tmp("straight");
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/straight-study.toml"),
    )
    .unwrap()
    .replace("step = 2.0", "step = 5.0")
    .replace("region_map_samples = 41", "region_map_samples = 11");
    let sc = d.join("straight.toml");
    std::fs::write(&sc, &text).unwrap();
    let out = d.join("out");
    let o = pounding()
        .args(["study", s(&sc), "--out", s(&out)])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let bounds = std::fs::read_to_string(out.join("bounds.csv")).unwrap();
    let mut lines = bounds.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .ends_with(",lcp_agrees,shape,l1_m,l2_m,skew_deg")
    );
    // 2 geometries x 2 mu x 4 cases x 5 x 5 cells
    assert_eq!(lines.clone().count(), 2 * 2 * 4 * 25);
    assert!(lines.all(|l| l.starts_with("nan,nan,nan,nan,") && l.contains(",true,straight,")));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("between straight bridge decks"));
    assert!(html.contains("straight decks, L1 = 60 m, L2 = 30 m"));
    assert!(
        out.join("figures/surface_straight_l1-60_l2-30_mu-1_eps-0.5.png")
            .is_file()
    );
    assert!(
        out.join("figures/regions_straight_l1-30_l2-30_eps-0.5.png")
            .is_file()
    );
    for part in html.split("src=\"").skip(1) {
        let target = &part[..part.find('"').unwrap()];
        assert!(
            out.join(target).is_file(),
            "report links to missing {target}"
        );
    }
}

#[test]
fn skew_of_90_degrees_fails_naming_key_and_line() {
    let d = tmp("skew90");
    let sc = d.join("bad.toml");
    std::fs::write(&sc, "[decks]\nshape = \"skew\"\nskew_deg = [30.0, 90.0]\n").unwrap();
    let out = d.join("out");
    let o = pounding()
        .args(["study", s(&sc), "--out", s(&out)])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains("line 3") && err.contains("decks.skew_deg[1]"),
        "{err}"
    );
    assert!(!out.join("bounds.csv").exists());
}
