//! `pounding simulate --dt / --duration / --law` (issue 12): they replace the scenario's keys
//! exactly as writing them into the file would, and a bad value is an error naming the flag.

use crate::{run_capture, scratch_dir};

/// Runs `simulate` with `args` into `d/out_name`; returns exit code, stderr and the directory.
fn simulate(
    d: &std::path::Path,
    out_name: &str,
    args: &[&str],
) -> (Option<i32>, String, std::path::PathBuf) {
    let out = d.join(out_name);
    let mut a = vec!["simulate"];
    a.extend_from_slice(args);
    a.extend_from_slice(&["--out", out.to_str().unwrap()]);
    let (code, _, err) = run_capture(&a);
    (code, err, out)
}

#[test]
fn flags_run_the_same_as_the_keys_they_replace() {
    let d = scratch_dir("simflags", "same");
    // the built-in default with the keys written into a file
    let (code, text, _) = run_capture(&["simulate", "--print-default"]);
    assert_eq!(code, Some(0));
    let mut file = text.replace("\n[time]\n", "\n[time]\nduration = 1.5\n");
    file = file.replacen("\ndt = ", "\ndt = 2e-4 # was ", 1);
    file.push_str("\n[contact]\nlaw = \"kelvin\"\n");
    assert!(file.contains("duration = 1.5") && file.contains("law = \"kelvin\""));
    let f = d.join("keys.toml");
    std::fs::write(&f, &file).unwrap();
    let (c1, e1, by_keys) = simulate(&d, "keys", &[f.to_str().unwrap()]);
    assert_eq!(c1, Some(0), "{e1}");
    let (c2, e2, by_flags) = simulate(
        &d,
        "flags",
        &["--dt", "2e-4", "--duration", "1.5", "--law", "kelvin"],
    );
    assert_eq!(c2, Some(0), "{e2}");
    for name in ["history.csv", "impacts.csv"] {
        let a = std::fs::read(by_keys.join(name)).unwrap();
        let b = std::fs::read(by_flags.join(name)).unwrap();
        assert!(a == b, "{name} differs");
    }
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(by_flags.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["dt_s"].as_f64(), Some(2e-4), "{s}");
    assert_eq!(s["steps"].as_u64(), Some(7500));
}

#[test]
fn bad_flag_values_name_the_flag() {
    let d = scratch_dir("simflags", "bad");
    for (args, want) in [
        (&["--dt", "0"][..], "--dt (command line"),
        (&["--dt", "-1e-3"], "--dt (command line"),
        (&["--duration", "-1"], "--duration (command line"),
        (&["--duration", "nan"], "--duration (command line"),
        (&["--law", "springy"], "--law (command line"),
        (&["--dt", "abc"], "--dt"),
    ] {
        let (code, err, out) = simulate(&d, "out", args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(want), "{args:?}: {want:?} not in {err}");
        assert!(!err.contains("panicked"));
        assert!(!out.exists(), "{args:?} wrote outputs");
    }
}

#[test]
fn law_flag_on_a_bridge_replaces_every_site_law_and_says_so() {
    let d = scratch_dir("simflags", "bridge");
    let f = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/viaduct-1d.toml"
    );
    let (code, err, out) = simulate(&d, "out", &[f, "--law", "rigid", "--duration", "2"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("--law rigid replaces"), "{err}");
    let s: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    // rigid: no contact force at any joint
    for j in s["joints"].as_array().unwrap() {
        assert!(j["peak_contact_force_n"].is_null(), "{j}");
    }
}
