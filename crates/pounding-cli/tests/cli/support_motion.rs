//! `pounding simulate` with supports that move apart: the wave-passage example (cut short)
//! writes `ground_motion.supports` with each line's arrival delay; a support-motion file runs;
//! bad input is refused with exit 2, naming the key and its line, nothing written.

use crate::{run_capture, scratch_with};

const WAVE: &str = include_str!("../../../../examples/bridge-p-1d-wave.toml");

#[test]
fn wave_passage_and_support_files_from_the_command_line() {
    let short = WAVE.replace("[time]\n", "[time]\nduration = 1.0\n");
    let neg = WAVE.replace("v_app = 250.0", "v_app = -250.0");
    let (mut csv, mut missing) = (
        String::from("t,start,joint1,joint2,end\n"),
        String::from("t,start,joint1,end\n"),
    );
    for i in 0..=100 {
        let t = i as f64 * 0.01;
        let a = |lag: f64| {
            if t > lag {
                (6.0 * (t - lag)).sin()
            } else {
                0.0
            }
        };
        csv += &format!("{t},{},{},{},{}\n", a(0.0), a(0.1), a(0.2), a(0.3));
        missing += &format!("{t},{},{},{}\n", a(0.0), a(0.1), a(0.3));
    }
    let file = WAVE
        .replace(
            "record_y = \"builtin:ELC180\"\n",
            "supports_y = \"real.csv\"\n",
        )
        .replace("record_x = \"none\"\n", "")
        .replace("v_app = 250.0", "")
        .replace("[time]\n", "[time]\nduration = 1.0\n");
    let d = scratch_with(
        "support_motion",
        "run",
        &[
            ("wave.toml", &short),
            ("neg.toml", &neg),
            ("file.toml", &file),
            ("real.csv", &csv),
        ],
    );
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&["simulate", &p("wave.toml"), "--out", &p("o")]);
    assert_eq!(code, Some(0), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("o/summary.json")).unwrap()).unwrap();
    let sup = &summary["ground_motion"]["supports"];
    assert_eq!(sup["kind"], "wave-passage");
    assert_eq!(sup["v_app_mps"], 250.0);
    let delays: Vec<f64> = sup["lines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["arrival_delay_s"].as_f64().unwrap())
        .collect();
    // 30 m spans (and the 0.02 m joint gaps) at 250 m/s
    for (k, d) in delays.iter().enumerate() {
        assert!((d - 0.12 * k as f64).abs() < 2e-4, "{delays:?}");
    }
    let (code, _, err) = run_capture(&["simulate", &p("file.toml"), "--out", &p("f")]);
    assert_eq!(code, Some(0), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(d.join("f/summary.json")).unwrap()).unwrap();
    assert_eq!(summary["ground_motion"]["supports"]["kind"], "per-support");
    assert_eq!(summary["ground_motion"]["record_y"], "real.csv");
    // bad input: exit 2, the key and its line, nothing written
    let (code, _, err) = run_capture(&["simulate", &p("neg.toml"), "--out", &p("n")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("v_app") && err.contains("neg.toml:"), "{err}");
    assert!(!d.join("n").exists());
    std::fs::write(d.join("real.csv"), missing).unwrap();
    let (code, _, err) = run_capture(&["simulate", &p("file.toml"), "--out", &p("m")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("joint2") && err.contains("supports_y"),
        "{err}"
    );
    assert!(!d.join("m").exists());
}

const VIADUCT: &str = include_str!("../../../../examples/fragility/viaduct.toml");

/// `motion svgm` → `fragility --compare-uniform`: the realisations run with every support on
/// its own column and again on their start column; `svgm_ratio.csv` has a row per limit state
/// and stripe with the runs counted under both. A dashpot-damped bridge refuses such a set
/// before any run (exit 2, nothing written), and `--compare-uniform` without support entries is
/// refused.
#[test]
fn svgm_set_through_fragility_with_the_uniform_ratio() {
    let d = scratch_with("support_motion", "frag", &[]);
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&[
        "motion",
        "svgm",
        "--supports",
        "0,30.01,60.03,90.04",
        "--count",
        "3",
        "--seed",
        "2",
        "--v-app",
        "250",
        "--duration",
        "10",
        "--out",
        &p("sv"),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let scenario = |damping: &str| {
        VIADUCT
            .replace(
                "records = \"suite.toml\"",
                &format!("records = \"{}\"", p("sv/manifest.toml")),
            )
            .replace("damping = \"dashpots\"", damping)
            .replace("bootstrap = 500", "bootstrap = 0")
            .replace("[0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.4]", "[0.4, 1.0]")
    };
    std::fs::write(d.join("r.toml"), scenario("damping = \"rayleigh\"")).unwrap();
    std::fs::write(d.join("dash.toml"), scenario("damping = \"dashpots\"")).unwrap();
    let (code, _, err) = run_capture(&[
        "fragility",
        &p("r.toml"),
        "--out",
        &p("o"),
        "--compare-uniform",
    ]);
    assert_eq!(code, Some(0), "{err}");
    let ratio = std::fs::read_to_string(d.join("o/svgm_ratio.csv")).unwrap();
    let lines: Vec<&str> = ratio.lines().collect();
    assert!(lines[0].starts_with("limit_state,stripe,im_g,exceeded_svgm,runs_svgm"));
    assert_eq!(lines.len(), 1 + 2 * 2, "{ratio}");
    for l in &lines[1..] {
        let c: Vec<&str> = l.split(',').collect();
        assert_eq!((c[4], c[7]), ("3", "3"), "{l}");
    }
    for f in ["runs_uniform.csv", "fragility_uniform.csv"] {
        assert!(d.join("o").join(f).exists(), "{f}");
    }
    let (code, _, err) = run_capture(&["fragility", &p("dash.toml"), "--out", &p("n")]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("dashpots") && err.contains("manifest.toml"),
        "{err}"
    );
    assert!(!d.join("n").exists());
    let plain = VIADUCT.replace("bootstrap = 500", "bootstrap = 0");
    std::fs::write(d.join("plain.toml"), plain).unwrap();
    std::fs::copy(
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../examples/fragility/suite.toml"
        ),
        d.join("suite.toml"),
    )
    .unwrap();
    let (code, _, err) = run_capture(&[
        "fragility",
        &p("plain.toml"),
        "--out",
        &p("u"),
        "--compare-uniform",
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--compare-uniform"), "{err}");
}

/// `motion svgm --bridge`: the bridge's support ids and distances (bridge P: 30 m spans, 0.02 m
/// joint gaps: each joint line midway across its gap), refused beside --supports.
#[test]
fn svgm_takes_the_supports_of_a_bridge_file() {
    let d = scratch_with("support_motion", "bridge", &[("wave.toml", WAVE)]);
    let p = |f: &str| d.join(f).to_str().unwrap().to_string();
    let (code, _, err) = run_capture(&[
        "motion",
        "svgm",
        "--bridge",
        &p("wave.toml"),
        "--count",
        "1",
        "--seed",
        "1",
        "--v-app",
        "250",
        "--duration",
        "5",
        "--out",
        &p("sv"),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let manifest = std::fs::read_to_string(d.join("sv/manifest.toml")).unwrap();
    assert!(
        manifest.contains("--supports 0,30.01,60.03,90.04 --ids start,joint1,joint2,end"),
        "{manifest}"
    );
    let csv = std::fs::read_to_string(d.join("sv/real_0001.csv")).unwrap();
    assert!(csv.starts_with("t,start,joint1,joint2,end\n"));
    let (code, _, err) = run_capture(&[
        "motion",
        "svgm",
        "--bridge",
        &p("wave.toml"),
        "--supports",
        "0,1",
        "--count",
        "1",
        "--seed",
        "1",
        "--v-app",
        "250",
        "--out",
        &p("x"),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(!d.join("x").exists());
}
