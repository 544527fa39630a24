//! Compliance contact laws through the CLI: the OpenSees 1-D example with `pounding simulate`,
//! bad contact-law parameters, and a `pounding compare` smoke test.

use crate::pounding;
use std::path::{Path, PathBuf};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("cmp", name)
}

fn example() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/opensees-1d.toml")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// `examples/opensees-1d.toml` reproduces OpenSees 3.7.1 (6 impacts, 44.30 MN, 4.04 mm).
#[test]
fn opensees_1d_example_matches_opensees() {
    let dir = tmp("os1d");
    let out = dir.join("out");
    let o = pounding()
        .arg("simulate")
        .arg(example())
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(!err.contains("warning"), "{err}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let f = s["peak_contact_force_n"].as_f64().unwrap();
    let pen = s["peak_penetration_m"].as_f64().unwrap();
    let close = s["peak_joint_closing_m"].as_f64().unwrap();
    eprintln!(
        "example: impacts {}, force {f}, penetration {pen}, closing {close}",
        s["impacts"]
    );
    assert_eq!(s["impacts"], 6);
    assert!(rel(f, 44.30e6) < 0.02, "{f}");
    assert!(rel(pen, 4.04e-3) < 0.03, "{pen}");
    assert!(rel(close, 0.05404) < 1e-3, "{close}");
    assert_eq!(s["contact_law"]["law"], "bilinear");
    assert_eq!(s["time_step"]["adequate"], true);
    assert_eq!(s["newton_failures"], 0);
    // no rotation with symmetric bearings and y-only excitation
    assert_eq!(s["peak_rotation_deg"][0].as_f64().unwrap(), 0.0);
    // the contact forces are in history.csv
    let h = std::fs::read_to_string(out.join("history.csv")).unwrap();
    assert!(
        h.lines()
            .next()
            .unwrap()
            .ends_with("contact_force_xminus_N")
    );
}

#[test]
fn rigid_default_summary_has_null_contact_force() {
    let dir = tmp("rigid");
    let out = dir.join("out");
    std::fs::write(dir.join("s.toml"), "[time]\nduration = 3.0\n").unwrap();
    let o = pounding()
        .arg("simulate")
        .arg(dir.join("s.toml"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(s["peak_contact_force_n"].is_null());
    assert_eq!(s["peak_penetration_m"], s["max_penetration_m"]);
    assert!(s.get("contact_law").is_none());
}

fn fails(name: &str, scenario: &str, needles: &[&str]) {
    let dir = tmp(name);
    std::fs::write(dir.join("s.toml"), scenario).unwrap();
    let out = dir.join("out");
    let o = pounding()
        .arg("simulate")
        .arg(dir.join("s.toml"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "{name}: should fail");
    assert_eq!(o.status.code(), Some(2), "{name}");
    assert!(!err.contains("panicked"), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: error lacks {n:?}: {err}");
    }
    assert!(!out.exists(), "{name}: wrote output on bad input");
}

#[test]
fn bad_contact_law_parameters_name_the_key() {
    fails(
        "k",
        "[contact]\nlaw = \"kelvin\"\nk = -1e9\n",
        &["k = -1000000000", "`[contact] k`", "s.toml:3"],
    );
    fails(
        "e0",
        "[contact]\nlaw = \"hertz-damp\"\nrestitution = 0.0\n",
        &["restitution", "(0, 1]", "s.toml:3"],
    );
    fails(
        "e2",
        "[contact]\nlaw = \"kelvin\"\nrestitution = 1.2\n",
        &["restitution", "(0, 1]"],
    );
    // the default restitution is [joint] eps_n; eps_n = 0 is fine for rigid but not here
    fails(
        "eps0",
        "[joint]\neps_n = 0.0\n[contact]\nlaw = \"jankowski\"\n",
        &["restitution", "eps_n"],
    );
    fails(
        "dy",
        "[contact]\nlaw = \"bilinear\"\nk1 = 1e10\nk2 = 1e9\ndelta_y = 0.0\n",
        &["delta_y", "s.toml:5", "> 0"],
    );
    fails(
        "k2",
        "[contact]\nlaw = \"bilinear\"\nk1 = 1e10\nk2 = -1e9\ndelta_y = 1e-3\n",
        &["k2", "s.toml:4"],
    );
    fails(
        "partial",
        "[contact]\nlaw = \"bilinear\"\nk1 = 1e10\n",
        &["k2", "delta_y"],
    );
    fails(
        "kh",
        "[contact]\nlaw = \"hertz\"\nk_h = -3.0\n",
        &["k_h", "s.toml:3"],
    );
    fails(
        "law",
        "[contact]\nlaw = \"spring\"\n",
        &["spring", "`[contact] law`", "kelvin"],
    );
    fails(
        "cal",
        "[contact]\nlaw = \"kelvin\"\ncalibration = \"ye\"\n",
        &["calibration", "anagnostopoulos"],
    );
    fails(
        "vr",
        "[contact]\nlaw = \"hertz\"\nfriction_velocity = 0.0\n",
        &["friction_velocity", "s.toml:3"],
    );
    fails(
        "shape",
        "[decks]\nshape = \"round\"\n",
        &["round", "`[decks] shape`"],
    );
    fails(
        "mass",
        "[decks]\nshape = \"straight\"\nL1 = 30.0\nL2 = 30.0\nmass1 = -1.0\n",
        &["mass1", "s.toml:5"],
    );
    fails(
        "damping",
        "[bearings]\ndamping = \"modal\"\n",
        &["modal", "`[bearings] damping`"],
    );
}

/// Runs `pounding simulate` on `scenario` (written to a scratch `s.toml`): the scratch directory,
/// the process output and `summary.json` (when written).
fn simulate_in(
    name: &str,
    scenario: &str,
) -> (crate::Scratch, std::process::Output, serde_json::Value) {
    let dir = tmp(name);
    let out = dir.join("out");
    std::fs::write(dir.join("s.toml"), scenario).unwrap();
    let o = pounding()
        .arg("simulate")
        .arg(dir.join("s.toml"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let s = std::fs::read_to_string(out.join("summary.json"))
        .map(|t| serde_json::from_str(&t).unwrap())
        .unwrap_or(serde_json::Value::Null);
    (dir, o, s)
}

#[test]
fn coarse_dt_warns_on_stderr() {
    let (_dir, o, s) = simulate_in(
        "coarse",
        "[contact]\nlaw = \"kelvin\"\nk = 1e12\n[time]\ndt = 2e-3\nduration = 1.0\n",
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("too coarse for the contact law"), "{err}");
    assert_eq!(s["time_step"]["adequate"], false);
    assert_eq!(s["warnings"][0]["kind"], "time_step_coarse");
}

/// `pounding compare` on the OpenSees example (rigid vs bilinear vs kelvin): table, CSV, timing,
/// plots; the bilinear row equals `simulate`'s result; deterministic CSV.
#[test]
fn compare_smoke() {
    let dir = tmp("compare");
    let run = |out: &Path| {
        let o = pounding()
            .arg("compare")
            .arg(example())
            .args(["--laws", "rigid,bilinear,kelvin", "--out"])
            .arg(out)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    let out = dir.join("a");
    let stdout = run(&out);
    for l in ["rigid", "bilinear", "kelvin", "impacts", "force [MN]"] {
        assert!(stdout.contains(l), "{stdout}");
    }
    let csv = std::fs::read_to_string(out.join("compare.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 4);
    assert_eq!(rows[0][0], "law");
    let col = |name: &str| rows[0].iter().position(|c| *c == name).unwrap();
    let (imp, force, pen) = (
        col("impacts"),
        col("peak_contact_force_N"),
        col("peak_penetration_m"),
    );
    assert_eq!(rows[1][0], "rigid");
    assert_eq!(rows[1][force], "nan");
    assert_eq!(rows[2][0], "bilinear");
    assert_eq!(rows[2][imp], "6");
    let f: f64 = rows[2][force].parse().unwrap();
    assert!(rel(f, 44.30e6) < 0.02, "{f}");
    let p: f64 = rows[2][pen].parse().unwrap();
    assert!(rel(p, 4.04e-3) < 0.03);
    // rigid: overlap bounded by the velocity-level scheme, much smaller than the compliance one
    let pr: f64 = rows[1][pen].parse().unwrap();
    assert!(pr < 0.1 * p, "{pr}");
    for f in ["timing.json", "joint_gap.png", "contact_force.png"] {
        assert!(out.join(f).is_file(), "{f}");
    }
    let timing: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("timing.json")).unwrap()).unwrap();
    assert!(timing["laws"]["bilinear"]["simulate_s"].as_f64().unwrap() > 0.0);
    assert!(!csv.contains("simulate_s"));
    // deterministic
    let out2 = dir.join("b");
    run(&out2);
    assert_eq!(
        csv,
        std::fs::read_to_string(out2.join("compare.csv")).unwrap()
    );
    // bad --laws
    let o = pounding()
        .args(["compare", "--laws", "rigid,foo", "--out"])
        .arg(dir.join("c"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("foo"));
    assert!(!dir.join("c").exists());
}

/// `compare` of the two-deck default: `report.html` names every law, answers whether they
/// agree, lists each law's warnings (bilinear's time step is too coarse at the default dt) and
/// shows the figures; the rigid row's `peak_force_estimate_N` is `simulate --law rigid`'s
/// `peak_force_estimate_n` (same token), and the compliance rows have none.
#[test]
fn compare_report_and_the_rigid_estimate() {
    let dir = tmp("report");
    let out = dir.join("cmp");
    let o = pounding()
        .args([
            "compare",
            "--duration",
            "3",
            "--laws",
            "rigid,bilinear,kelvin",
        ])
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    // the warning printed on stderr is also in the report, under its law
    let warning = "too coarse for the contact law";
    assert!(err.contains(warning), "{err}");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let warnings = crate::report_warnings(&html);
    assert!(
        warnings.contains("<h3>bilinear</h3>") && warnings.contains(warning),
        "{warnings}"
    );
    for law in ["rigid", "bilinear", "kelvin"] {
        assert!(
            html.contains(&format!("<li><strong>{law}</strong>: pounded")),
            "{law}"
        );
        assert!(html.contains(&format!("<th>{law}</th>")), "{law} column");
    }
    for needle in [
        "The 3 laws agree that the structure pounds.",
        "src=\"joint_gap.png\"",
        "src=\"contact_force.png\"",
        "<p>Every law ran.</p>",
        "<h2 id=\"timing\">Wall time</h2>",
    ] {
        assert!(html.contains(needle), "report lacks {needle:?}");
    }
    // the estimate column against simulate's summary of the same rigid run
    let sim = dir.join("sim");
    let o = pounding()
        .args(["simulate", "--duration", "3", "--law", "rigid", "--out"])
        .arg(&sim)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let raw = std::fs::read_to_string(sim.join("summary.json")).unwrap();
    let s: serde_json::Value = serde_json::from_str(&raw).unwrap();
    let csv = std::fs::read_to_string(out.join("compare.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    let col = |name: &str| rows[0].iter().position(|c| *c == name).unwrap();
    let (est, t_c, force) = (
        col("peak_force_estimate_N"),
        col("contact_time_estimate_s"),
        col("peak_contact_force_N"),
    );
    assert_eq!(rows[1][0], "rigid");
    let e: f64 = rows[1][est].parse().unwrap();
    assert_eq!(e, s["peak_force_estimate_n"].as_f64().unwrap());
    assert!(raw.contains(&format!("\"peak_force_estimate_n\": {}", rows[1][est])));
    assert!(e > 0.0 && rows[1][force] == "nan");
    let t: f64 = rows[1][t_c].parse().unwrap();
    assert!(t > 0.0 && t < 1.0, "{t}");
    for r in &rows[2..] {
        assert_eq!((r[est], r[t_c]), ("nan", "nan"), "{}", r[0]);
        assert!(r[force].parse::<f64>().unwrap() > 0.0, "{}", r[0]);
    }
}

/// `law = "linear"` (added through the contact-law registry) runs through `pounding simulate`
/// and is reported with its stiffness; an unknown law lists it.
#[test]
fn simulate_with_the_linear_law() {
    let (_dir, o, s) = simulate_in(
        "linear",
        "[time]\nduration = 3.0\n[contact]\nlaw = \"linear\"\nk = 1e9\n",
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(s["contact_law"]["law"], "linear");
    assert_eq!(s["contact_law"]["k"].as_f64(), Some(1e9));
    assert_eq!(s["newton_failures"], 0);
    eprintln!(
        "linear: impacts {}, peak force {}, peak penetration {}",
        s["impacts"], s["peak_contact_force_n"], s["peak_penetration_m"]
    );
    fails(
        "law-list",
        "[contact]\nlaw = \"spring\"\n",
        &["spring", "jankowski, linear"],
    );
}
