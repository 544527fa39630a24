//! `pounding simulate` of bridges of `[[segment]]`s (issue 11): a run writes its files with the
//! per-joint / per-abutment / per-segment summary arrays; bad input is an error naming the key
//! (with its array index) and its line, exit 2, nothing written.

use crate::{run_capture, scratch_dir};

/// A short rigid three-segment bridge (1 s of El Centro).
const BRIDGE: &str = r#"
[bridge]
damping = "dashpots"
gap = 0.02
mu = 0.0
eps_n = 0.6

[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
period_s = 1.2

[[segment]]
shape = "straight"
L = 30.0
mass = 1.2e6
period_s = 0.5

[[segment]]
shape = "straight"
L = 30.0
mass = 0.8e6
period_s = 1.5

[abutment.start]
gap = 0.04

[abutment.end]
gap = 0.04

[ground_motion]
record_y = "builtin:ELC180"
record_x = "none"
scale_y = -3.0

[time]
dt = 1e-3
duration = 3.0
"#;

fn simulate(name: &str, text: &str) -> (Option<i32>, String, crate::InScratch) {
    let d = scratch_dir("bridge", name);
    let f = d.join("bridge.toml");
    std::fs::write(&f, text).unwrap();
    let out = d.join("out");
    let (code, _, err) = run_capture(&[
        "simulate",
        f.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (code, err, d.into_join("out"))
}

#[test]
fn bridge_run_writes_its_files_with_arrays_in_bridge_order() {
    let (code, err, out) = simulate("run", BRIDGE);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("bridge of 3 segments"), "{err}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["joints"].as_array().unwrap().len(), 2);
    assert_eq!(s["segments"].as_array().unwrap().len(), 3);
    assert_eq!(s["abutments"].as_array().unwrap().len(), 2);
    assert!(
        s["joints"][0]["peak_contact_force_n"].is_null(),
        "rigid: no force"
    );
    assert!(
        s["joints"][0]["restrainer_peak_force_n"].is_null(),
        "no restrainer"
    );
    assert!(s["impacts"].as_u64().unwrap() > 0);
    let h = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let head = h.lines().next().unwrap();
    for col in [
        "y3_m",
        "joint2_gap_c1_m",
        "joint2_slip_m",
        "abutment_end_gap_m",
        "element_work_J",
    ] {
        assert!(head.split(',').any(|c| c == col), "{col} in {head}");
    }
    let imp = std::fs::read_to_string(out.join("impacts.csv")).unwrap();
    assert!(
        imp.lines()
            .skip(1)
            .any(|l| l.split(',').nth(2) == Some("joint1"))
    );
    assert!(out.join("timing.json").exists());
    // same input, same bytes
    let (code, _, out2) = simulate("run2", BRIDGE);
    assert_eq!(code, Some(0));
    for f in ["history.csv", "impacts.csv", "summary.json"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(out2.join(f)).unwrap(),
            "{f}"
        );
    }
}

#[test]
fn bad_bridges_name_the_key_and_line_and_write_nothing() {
    let cases: &[(&str, &str, &[&str])] = &[
        // (replace, with, expected fragments)
        (
            "gap = 0.02\nmu",
            "gap = -0.02\nmu",
            &["bridge.gap", "bridge.toml:4", "must lie in [0, 1e3] m"],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing = \"bilinear\"\nfy = 1e5\nb = 1.0",
            &["segment[1].b", "must lie in [0, 1)"],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing = \"bilinear\"\nfy = 0.0\nb = 0.1",
            &["segment[1].fy", "must be > 0"],
        ),
        (
            "period_s = 1.5\n",
            "\n",
            &["segment[2].period_s", "needs its bearings"],
        ),
        (
            "[abutment.start]",
            "[[joint]]\ngap = 0.01\n\n[abutment.start]",
            &["3 segments have 2 joints", "1 [[joint]]"],
        ),
        (
            "mass = 0.8e6",
            "mass = 0.8e6\nwidth = 12.0",
            &["segment[2].width", "same length", "bridge.toml:24"],
        ),
        (
            "mass = 0.8e6",
            "mass = 0.8e6\nlength = 3.0",
            &["unknown field", "length"],
        ),
        (
            "[abutment.start]",
            "[decks]\nR1 = 100.0\n\n[abutment.start]",
            &["[decks] (line ", "refused next to [[segment]]"],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_slack = 0.03",
            &["bridge.restrainer_slack", "restrainer_k"],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_k = -5e7",
            &["bridge.restrainer_k", "must be > 0"],
        ),
        (
            "shape = \"straight\"\nL = 30.0\nmass = 1.2e6",
            "shape = \"curved\"\nL = 30.0\nmass = 1.2e6",
            &["segment[1].R", "required"],
        ),
        (
            "[abutment.end]\ngap = 0.04",
            "[abutment.end]\ngap = 0.04\nseat_length = -1.0",
            &["abutment.end.seat_length", "must lie in (0, 1e3] m"],
        ),
        // hostile-trial findings
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = [[0.0, -5.0, 1.0], [0.0, 5.0], [30.0, 0.0]]",
            &[
                "segment[1].bearing_points",
                "point 1 has 3 coordinates",
                "bridge.toml:19",
            ],
        ),
        (
            "mass = 1.2e6",
            "mass = 1.2e6\ndensity = 2400.0",
            &["segment[1].density", "not both"],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_k = 5e7\nrestrainer_offsets = [1.0, 1.0]",
            &["bridge.restrainer_offsets", "same offset"],
        ),
        // restrainer cables and bearings at given points
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_k = 5e7\nrestrainer_offsets = [-2.0, 6.0]",
            &[
                "invalid bridge.restrainer_offsets = 6 at joint[0]",
                "beside the joint",
                "`bridge.restrainer_offsets` (",
                "bridge.toml:8",
            ],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_k = 5e7\nrestrainer_depth = 31.0",
            &[
                "invalid bridge.restrainer_depth = 31 at joint[0]",
                "outside segment",
                "bridge.toml:8",
            ],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_offsets = [1.0]",
            &["bridge.restrainer_offsets", "restrainer_k", "bridge.toml:7"],
        ),
        (
            "eps_n = 0.6",
            "eps_n = 0.6\nrestrainer_k = 5e7\nrestrainer_offsets = []",
            &["bridge.restrainer_offsets", "one finite offset per cable"],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = [[0.0, 0.0], [31.0, 0.0]]",
            &[
                "segment[1].bearing_points",
                "bearing 2 lies outside",
                "bridge.toml:19",
            ],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = [[15.0, 0.0]]",
            &[
                "segment[1].bearing_points",
                "free to slide or spin",
                "allow_mechanism",
                "bridge.toml:19",
            ],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = []",
            &[
                "segment[1].bearing_points",
                "between 1 and 1000 points",
                "bridge.toml:19",
            ],
        ),
        (
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = [[1.0]]",
            &[
                "segment[1].bearing_points",
                "point 1 has 1 coordinates",
                "bridge.toml:19",
            ],
        ),
    ];
    for (i, (from, to, want)) in cases.iter().enumerate() {
        assert!(BRIDGE.contains(from), "case {i}: {from}");
        let text = BRIDGE.replacen(from, to, 1);
        let (code, err, out) = simulate(&format!("bad{i}"), &text);
        assert_eq!(code, Some(2), "case {i}: {err}");
        for w in *want {
            assert!(err.contains(w), "case {i}: {w:?} not in {err}");
        }
        assert!(!err.contains("panicked"), "{err}");
        assert!(
            !out.exists() || std::fs::read_dir(&out).unwrap().next().is_none(),
            "case {i} wrote files"
        );
    }
}

/// A run whose discrete energy balance (exact to rounding for θ = ½) is off — here a contact law
/// far too stiff for the step — ends `CompletedWithEnergyError`, exit 1, outputs written.
#[test]
fn a_run_whose_energy_balance_does_not_close_is_not_a_success() {
    let text = r#"
[bridge]
eps_n = 1.0
mu = 0.0
[[segment]]
L = 30.0
mass = 1e-12
period_s = 1e6
[abutment.start]
gap = 0.04
[contact]
law = "jankowski"
[ground_motion]
record_y = "builtin:ELC180"
record_x = "builtin:ELC270"
scale_y = 3.0
[time]
dt = 0.02
duration = 2.0
"#;
    let (code, err, out) = simulate("ebe", text);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("CompletedWithEnergyError"), "{err}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["status"], "CompletedWithEnergyError");
    assert!(s["energy_balance_error"].as_f64().unwrap() > 1e-6);
}

/// A curved bridge that closes on itself (segments overlapping in plan) is refused naming the
/// two segments (hostile-trial finding: it used to run as if they passed through each other).
#[test]
fn a_bridge_that_closes_on_itself_is_refused() {
    let seg = "[[segment]]\nshape = \"curved\"\nR = 20.0\nbeta_deg = 120.0\ncurve = \"left\"\nperiod_s = 1.0\n";
    let text = format!(
        "[bridge]\ngap = 0.02\n{}\n[ground_motion]\nrecord_y = \"none\"\nrecord_x = \"none\"\n[time]\nduration = 1.0\n",
        seg.repeat(4)
    );
    let (code, err, out) = simulate("overlap", &text);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("overlaps segment[") && err.contains("closes on itself"),
        "{err}"
    );
    assert!(!out.exists() || std::fs::read_dir(&out).unwrap().next().is_none());
}

/// A segment on a single bearing point spins freely: refused above; with
/// `bridge.allow_mechanism = true` it runs.
#[test]
fn a_mechanism_runs_when_allowed() {
    let text = BRIDGE
        .replacen(
            "period_s = 0.5",
            "period_s = 0.5\nbearing_points = [[15.0, 0.0]]",
            1,
        )
        .replacen("eps_n = 0.6", "eps_n = 0.6\nallow_mechanism = true", 1);
    let (code, err, out) = simulate("mechanism", &text);
    assert_eq!(code, Some(0), "{err}");
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    assert!(
        s["segments"][1]["natural_periods_s"][0].is_null(),
        "{}",
        s["segments"][1]
    );
}

/// A one-segment bridge has no joint: restrainer keys are refused, not ignored; a `[contact]` key
/// of a bridge without joints and abutments is refused; `[bridge]` without `[[segment]]` says so.
#[test]
fn keys_a_bridge_cannot_use_are_refused() {
    let one = "[bridge]\nrestrainer_k = 5e7\n\n[[segment]]\nshape = \"straight\"\nL = 30.0\n\
               period_s = 1.0\n\n[time]\nduration = 1.0\n";
    let (code, err, _) = simulate("one-restrainer", one);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("bridge.restrainer_k") && err.contains("no joint"),
        "{err}"
    );
    let contact = "[[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.0\n\n[contact]\n\
                   law = \"hertz\"\nk_h = 1e10\n\n[time]\nduration = 1.0\n";
    let (code, err, _) = simulate("one-contact", contact);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("k_h") && err.contains("no joints and no abutments"),
        "{err}"
    );
    let no_segments = "[bridge]\ngap = 0.02\n";
    let (code, err, _) = simulate("no-segments", no_segments);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("[[segment]]"), "{err}");
    // every site has its own law: a [contact] key that none of them reads is refused
    let sites = BRIDGE
        .replacen(
            "[abutment.start]\ngap = 0.04",
            "[[joint]]\n[joint.contact]\nlaw = \"kelvin\"\nk = 1e10\n[[joint]]\n[joint.contact]\n\
         law = \"kelvin\"\nk = 1e10\n\n[abutment.start]\ngap = 0.04\n[abutment.start.contact]\n\
         law = \"kelvin\"\nk = 1e10",
            1,
        )
        .replacen(
            "[abutment.end]\ngap = 0.04",
            "[abutment.end]\ngap = 0.04\n[abutment.end.contact]\nlaw = \"kelvin\"\nk = 1e10\n\n\
         [contact]\nlaw = \"hertz\"\nk_h = 1e10",
            1,
        );
    assert!(sites.contains("k_h = 1e10"));
    let (code, err, _) = simulate("unread-contact", &sites);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("k_h"), "{err}");
    // ... and --law replaces every site's law, the keys it does not read are not used
    let d = crate::scratch_dir("bridge", "law-over-sites");
    let f = d.join("b.toml");
    std::fs::write(
        &f,
        sites.replace("\n[contact]\nlaw = \"hertz\"\nk_h = 1e10", ""),
    )
    .unwrap();
    let (code, _, err) = crate::run_capture(&[
        "simulate",
        f.to_str().unwrap(),
        "--law",
        "hertz",
        "--out",
        d.join("out").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("--law hertz replaces"), "{err}");
}

/// `examples/viaduct-rigid-1d.toml` with the bilinear law of `examples/viaduct-1d.toml` at both
/// abutments (rigid joints): exit 0, the energy balance closed, `impacts.csv` with the pulse
/// columns filled at the abutments and the estimate columns at the joints, `summary.json` with
/// both kinds' keys, `history.csv`'s joint forces `nan` (rigid joints).
#[test]
fn mixed_sites_run_from_the_command_line() {
    let root = env!("CARGO_MANIFEST_DIR");
    let base = std::fs::read_to_string(format!("{root}/../../examples/viaduct-rigid-1d.toml"))
        .unwrap()
        .replace(
            "history_every = 100",
            "history_every = 100\nduration = 12.0",
        );
    let law = "law = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3\n";
    let text = format!("{base}\n[abutment.start.contact]\n{law}[abutment.end.contact]\n{law}");
    let (code, err, out) = simulate("mixed", &text);
    assert_eq!(code, Some(0), "{err}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["status"], "Completed");
    assert!(s["energy_balance_error"].as_f64().unwrap() < 1e-9, "{s}");
    assert!(s["joints"][0]["peak_contact_force_n"].is_null());
    assert!(s["abutments"][0]["peak_contact_force_n"].as_f64().unwrap() > 0.0);
    assert_eq!(s["newton_failures"], 0);
    assert!(!s["peak_force_estimate_n"].is_null(), "{s}");
    let impacts = std::fs::read_to_string(out.join("impacts.csv")).unwrap();
    let head: Vec<&str> = impacts.lines().next().unwrap().split(',').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let (pulse, est, site) = (
        col("peak_force_n"),
        col("peak_force_estimate_n"),
        col("site"),
    );
    let (mut joints, mut abuts) = (0, 0);
    for line in impacts.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        if c[site].starts_with("abutment") {
            abuts += 1;
            assert!(c[pulse] != "nan" && c[est] == "nan", "{line}");
        } else {
            joints += 1;
            assert!(c[pulse] == "nan" && c[est] != "nan", "{line}");
        }
    }
    assert!(joints > 0 && abuts > 0, "{impacts}");
    let history = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let head: Vec<&str> = history.lines().next().unwrap().split(',').collect();
    let f = head.iter().position(|h| *h == "joint1_force_N").unwrap();
    assert!(
        history
            .lines()
            .skip(1)
            .all(|l| l.split(',').nth(f) == Some("nan"))
    );
}

/// A long bridge's summary line names the first 8 joints and says where the others are (a
/// 200-segment bridge printed all 199 on one line).
#[test]
fn a_long_bridge_summary_line_names_the_first_joints_only() {
    let mut text = String::from("[bridge]\ndamping = \"dashpots\"\ngap = 0.02\n");
    for _ in 0..11 {
        text.push_str(
            "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1.0e6\nperiod_s = 1.0\n",
        );
    }
    text.push_str(
        "[ground_motion]\nrecord_y = \"builtin:ELC180\"\nrecord_x = \"none\"\n[time]\ndt = 1e-3\n\
         duration = 0.2\n",
    );
    let (code, err, out) = simulate("long", &text);
    assert_eq!(code, Some(0), "{err}");
    let line = err.lines().find(|l| l.contains("per joint:")).unwrap();
    assert_eq!(line.matches("(closing").count(), 8, "{line}");
    assert!(line.contains("… 2 more in summary.json"), "{line}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["joints"].as_array().unwrap().len(), 10);
}
