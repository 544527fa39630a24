//! `pounding simulate`: default run, outputs, determinism, scenario files, bad input.

use crate::pounding;
use std::path::Path;

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("sim", name)
}

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

#[test]
fn default_run_writes_every_output_deterministically() {
    let dir = tmp("default");
    let out = dir.join("out");
    let o = pounding()
        .args(["simulate", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = summary(&out);
    for key in [
        "impacts",
        "peak_joint_closing_m",
        "peak_joint_opening_m",
        "peak_rotation_deg",
        "peak_slip_m",
        "peak_seat_displacement_m",
        "unseated",
        "unseating_time_s",
        "energy_balance_error",
    ] {
        assert!(s.get(key).is_some(), "summary.json lacks {key}: {s}");
    }
    assert!(s["energy_balance_error"].as_f64().unwrap() < 1e-3);
    assert_eq!(s["peak_rotation_deg"].as_array().unwrap().len(), 2);
    assert_eq!(s["unseated"], false);
    assert!(s["unseating_time_s"].is_null());
    // impacts.csv: one row per impacting contact, impact numbers 1..=impacts
    let imp = std::fs::read_to_string(out.join("impacts.csv")).unwrap();
    let rows: Vec<Vec<&str>> = imp
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let n = s["impacts"].as_u64().unwrap() as usize;
    assert!(n > 0);
    assert_eq!(rows.last().unwrap()[0].parse::<usize>().unwrap(), n);
    for r in &rows {
        // 11 columns, then the rigid law's peak_force_estimate_n, contact_time_estimate_s
        assert_eq!(r.len(), 13);
        assert!(r[11].parse::<f64>().unwrap() > 0.0 && r[12].parse::<f64>().unwrap() > 0.0);
        assert!(
            ["stick", "slip-outward", "slip-inward"].contains(&r[3]),
            "{r:?}"
        );
        assert!(r[8].parse::<f64>().unwrap() > 0.0, "normal impulse > 0");
        assert!(
            r[4].parse::<f64>().unwrap() < -1e-3,
            "closing faster than 1 mm/s"
        );
    }
    // history.csv: every 10th step of 53.71 s plus header; gap columns consistent with the summary
    let hist = std::fs::read_to_string(out.join("history.csv")).unwrap();
    let lines: Vec<&str> = hist.lines().collect();
    assert_eq!(lines.len(), 1 + 5372);
    let header: Vec<&str> = lines[0].split(',').collect();
    let gi = header
        .iter()
        .position(|h| *h == "joint_gap_xplus_m")
        .unwrap();
    let min_gap = lines[1..]
        .iter()
        .map(|l| {
            let c: Vec<&str> = l.split(',').collect();
            c[gi]
                .parse::<f64>()
                .unwrap()
                .min(c[gi + 1].parse::<f64>().unwrap())
        })
        .fold(f64::INFINITY, f64::min);
    let closing = s["peak_joint_closing_m"].as_f64().unwrap();
    assert!(
        0.05 - min_gap <= closing + 1e-12,
        "sampled closing cannot exceed the peak"
    );
    for png in [
        "displacements.png",
        "rotations.png",
        "joint_gap.png",
        "impulses.png",
        "energy.png",
        "layout.png",
    ] {
        let b = std::fs::read(out.join(png)).unwrap();
        assert!(b.len() > 10_000 && b.starts_with(b"\x89PNG"), "{png}");
    }
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("timing.json")).unwrap()).unwrap();
    assert!(t["wall_time_s"].as_f64().unwrap() > 0.0);
    // no temporary files left behind
    for e in std::fs::read_dir(&out).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        assert!(!name.starts_with('.'), "left over {name}");
    }
    // deterministic: the same run gives byte-identical summary, history and impacts
    let out2 = dir.join("out2");
    let o = pounding()
        .args(["simulate", "--out"])
        .arg(&out2)
        .output()
        .unwrap();
    assert!(o.status.success());
    for f in ["summary.json", "history.csv", "impacts.csv"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(out2.join(f)).unwrap(),
            "{f}"
        );
    }
    // the printed default is the built-in default
    let p = pounding()
        .args(["simulate", "--print-default"])
        .output()
        .unwrap();
    assert!(p.status.success());
    let sc = dir.join("default.toml");
    std::fs::write(&sc, &p.stdout).unwrap();
    let out3 = dir.join("out3");
    let o = pounding()
        .arg("simulate")
        .arg(&sc)
        .arg("--out")
        .arg(&out3)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s3 = summary(&out3);
    for k in [
        "impacts",
        "peak_joint_closing_m",
        "peak_seat_displacement_m",
        "energy_J",
    ] {
        assert_eq!(s[k], s3[k], "{k}");
    }
}

#[test]
fn scenario_paths_are_relative_to_the_scenario_and_scale_applies() {
    let dir = tmp("relative");
    let sub = dir.join("sc");
    std::fs::create_dir_all(&sub).unwrap();
    // a strong 1 Hz pulse along y as a CSV record (in g)
    let mut csv = String::from("time,acc (g)\n");
    for i in 0..=300 {
        let t = i as f64 * 0.01;
        let a = if t <= 2.0 {
            0.4 * (2.0 * std::f64::consts::PI * t).sin()
        } else {
            0.0
        };
        csv.push_str(&format!("{t},{a}\n"));
    }
    std::fs::write(sub.join("pulse.csv"), csv).unwrap();
    std::fs::write(
        sub.join("s.toml"),
        "[ground_motion]\nrecord_y = \"pulse.csv\"\nrecord_x = \"none\"\n[time]\nduration = 4.0\nhistory_every = 5\n",
    )
    .unwrap();
    let run = |scale: &str, name: &str| {
        let out = dir.join(name);
        let o = pounding()
            .current_dir(&dir) // not the scenario's directory
            .args(["simulate", "sc/s.toml", "--scale", scale, "--out"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        summary(&out)
    };
    let s0 = run("0", "o0");
    assert_eq!(s0["impacts"], 0);
    assert_eq!(s0["peak_seat_displacement_m"].as_f64().unwrap(), 0.0);
    let s1 = run("1", "o1");
    let s2 = run("2", "o2");
    assert!(s1["impacts"].as_u64().unwrap() >= 1, "{s1}");
    assert!(
        s2["peak_joint_opening_m"].as_f64().unwrap() > s1["peak_joint_opening_m"].as_f64().unwrap()
    );
    assert_eq!(s1["ground_motion"]["record_x"], "none");
}

/// Runs with a scenario text; asserts failure, that the message contains every `needle`, and
/// that the output directory was not created.
fn fails(name: &str, scenario: &str, extra: &[&str], needles: &[&str]) {
    let dir = tmp(name);
    std::fs::write(dir.join("s.toml"), scenario).unwrap();
    let out = dir.join("out");
    let o = pounding()
        .arg("simulate")
        .arg(dir.join("s.toml"))
        .args(extra)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "{name}: should fail");
    assert!(!err.contains("panicked"), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: error lacks {n:?}: {err}");
    }
    assert!(!out.exists(), "{name}: wrote output on bad input");
}

#[test]
fn bad_input_fails_cleanly_and_writes_nothing() {
    fails("dt", "[time]\n\ndt = 0.0\n", &[], &["dt", "s.toml:3"]);
    fails("dtneg", "[time]\ndt = -1e-3\n", &[], &["dt"]);
    fails(
        "stiff",
        "[bearings]\nstiffness2 = -5.0\n",
        &[],
        &["stiffness2", "s.toml:2", "must be >= 0"],
    );
    fails(
        "seat",
        "[joint]\nseat_length = 0\n",
        &[],
        &["seat_length", "s.toml:2"],
    );
    fails("eps", "[joint]\neps_n = 1.5\n", &[], &["eps_n"]);
    fails("mu", "[joint]\nmu = nan\n", &[], &["mu"]);
    fails("R", "[decks]\nR2 = 3.0\n", &[], &["R2", "s.toml:2"]);
    fails("unknown", "[joint]\ngapp = 0.1\n", &[], &["gapp", "line 2"]);
    fails("section", "[jiont]\ngap = 0.1\n", &[], &["jiont"]);
    fails(
        "missing",
        "[ground_motion]\nrecord_y = \"nope.AT2\"\n",
        &[],
        &["nope.AT2", "record_y"],
    );
    fails(
        "missingflag",
        "",
        &["--record", "/nonexistent/rec.AT2"],
        &["rec.AT2"],
    );
    fails(
        "builtin",
        "[ground_motion]\nrecord_x = \"builtin:ELC999\"\n",
        &[],
        &["ELC999"],
    );
    fails(
        "units",
        "[ground_motion]\ncsv_units = \"furlongs\"\n",
        &[],
        &["csv_units"],
    );
    fails(
        "every",
        "[time]\nhistory_every = 0\n",
        &[],
        &["history_every"],
    );
    fails("scale", "", &["--scale", "inf"], &["scale"]);
    // malformed AT2: the error names the file and the line
    let dir = tmp("at2");
    let at2 = "PEER NGA STRONG MOTION DATABASE RECORD\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  3, DT= .01 SEC\n .1 .2\n .3x\n";
    std::fs::write(dir.join("bad.AT2"), at2).unwrap();
    let out = dir.join("out");
    let o = pounding()
        .args(["simulate", "--record"])
        .arg(dir.join("bad.AT2"))
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains("bad.AT2:6"), "{err}");
    assert!(!out.exists());
}
