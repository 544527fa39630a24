//! `pounding compare` on a bridge file and the per-site contact tables of bridge scenarios
//! (issue 11): the comparison's figures are those of `pounding simulate` of the same bridge
//! with that law (the rigid law's peak-force estimate too); a law that cannot run is skipped
//! with its reason (also in `report.html`); bad site tables exit 2 naming
//! `joint[k].contact.KEY` and its line, writing nothing.

use crate::{run_capture, scratch_dir};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// `examples/viaduct-1d.toml` (bilinear impact law at every site) for 4 s, with `[contact]`
/// replaced by `contact` when given.
fn viaduct(contact: Option<&str>) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-1d.toml");
    let text = std::fs::read_to_string(root).unwrap();
    let mut text = text.replace("history_every = 100", "history_every = 100\nduration = 4.0");
    if let Some(c) = contact {
        let start = text.find("[contact]").unwrap();
        let end = text.find("[ground_motion]").unwrap();
        text.replace_range(start..end, c);
    }
    text
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let f = dir.join(name);
    std::fs::write(&f, text).unwrap();
    f
}

fn summary(file: &Path, out: &Path) -> Value {
    summary_text(file, out).0
}

/// `summary.json` of `simulate FILE` parsed, and as text.
fn summary_text(file: &Path, out: &Path) -> (Value, String) {
    let (code, _, err) = run_capture(&[
        "simulate",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(out.join("summary.json")).unwrap();
    (serde_json::from_str(&text).unwrap(), text)
}

/// A CSV as rows of fields (no quoted fields in these files).
fn csv(path: &Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

/// A CSV number field against a JSON number (`null` ↔ empty field): the same `f64` (both
/// parsed by `serde_json`, whose parser may be 1 ulp off but is the same for both), and the
/// same token (`raw`: the JSON text, which must contain it).
fn same(field: &str, v: &Value, what: &str, raw: &str) {
    match v {
        Value::Null => assert_eq!(field, "", "{what}"),
        v => {
            assert_eq!(
                serde_json::from_str::<f64>(field).unwrap(),
                v.as_f64().unwrap(),
                "{what}: {field} vs {v}"
            );
            assert!(raw.contains(&format!(": {field}")), "{what}: token {field}");
        }
    }
}

/// The rows of `law` in `compare_sites.csv` against the `joints` and `abutments` of a
/// `summary.json`.
fn sites_match(rows: &[Vec<String>], law: &str, s: &Value, raw: &str) {
    let rows: Vec<&Vec<String>> = rows.iter().filter(|r| r[0] == law).collect();
    let joints = s["joints"].as_array().unwrap();
    let abuts = s["abutments"].as_array().unwrap();
    assert_eq!(rows.len(), joints.len() + 2, "{law}");
    let mut any_impact = false;
    for (k, j) in joints.iter().enumerate() {
        let r = rows[k];
        assert_eq!(r[1], format!("joint{}", k + 1));
        assert_eq!(r[2], j["impacts"].to_string(), "{law} joint {k}");
        any_impact |= j["impacts"].as_u64().unwrap() > 0;
        same(&r[3], &j["peak_contact_force_n"], "force", raw);
        same(&r[6], &j["peak_impulse_ns"], "impulse", raw);
        same(&r[7], &j["peak_closing_m"], "closing", raw);
        same(&r[8], &j["peak_opening_m"], "opening", raw);
        same(&r[9], &j["restrainer_peak_force_n"], "restrainer", raw);
    }
    for (side, a) in abuts.iter().enumerate() {
        let r = rows[joints.len() + side];
        // the names of summary.json's seats[] and impacts.csv
        assert_eq!(r[1], ["abutment-start", "abutment-end"][side]);
        assert_eq!(r[2], a["impacts"].to_string());
        same(&r[3], &a["peak_contact_force_n"], "abutment force", raw);
        same(&r[6], &a["peak_impulse_ns"], "abutment impulse", raw);
        same(&r[7], &a["peak_closing_m"], "abutment closing", raw);
    }
    assert!(any_impact, "{law}: the test bridge must pound");
}

/// `compare viaduct --laws rigid,bilinear` writes its files; the bilinear rows equal `simulate`
/// of the file, the rigid rows `simulate` of the file with `law = "rigid"`, site by site and in
/// the headline row (same numbers, to the last bit).
#[test]
fn bridge_compare_rows_equal_simulate_of_each_law() {
    let d = scratch_dir("bridge_compare", "rows");
    let file = write(&d, "v.toml", &viaduct(None));
    let rigid = write(
        &d,
        "r.toml",
        &viaduct(Some("[contact]\nlaw = \"rigid\"\n\n")),
    );
    let out = d.join("cmp");
    let (code, table, err) = run_capture(&[
        "compare",
        file.to_str().unwrap(),
        "--laws",
        "rigid,bilinear",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    for f in [
        "compare.csv",
        "compare_sites.csv",
        "joint_gap.png",
        "timing.json",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
    assert!(
        table.contains("abutment-end") && table.contains("joint2") && !table.contains("abutment."),
        "{table}"
    );
    let sites = csv(&out.join("compare_sites.csv"));
    let head = csv(&out.join("compare.csv"));
    for (law, f) in [("bilinear", &file), ("rigid", &rigid)] {
        let (s, raw) = summary_text(f, &d.join(format!("sim-{law}")));
        let raw = raw.as_str();
        sites_match(&sites, law, &s, raw);
        let row = head.iter().find(|r| r[0] == law).unwrap();
        assert_eq!(row[1], s["status"].as_str().unwrap());
        assert_eq!(row[2], s["steps"].to_string());
        assert_eq!(row[3], s["impacts"].to_string());
        let col = |name: &str| head[0].iter().position(|h| h == name).unwrap();
        same(
            &row[col("peak_penetration_m")],
            &s["peak_penetration_m"],
            "penetration",
            raw,
        );
        same(
            &row[col("energy_balance_error")],
            &s["energy_balance_error"],
            "energy",
            raw,
        );
        assert_eq!(row[col("skipped_reason")], "", "not skipped");
        // the rigid law's estimate is the summary's, labelled apart from the computed force
        let est = s.get("peak_force_estimate_n").unwrap_or(&Value::Null);
        same(&row[col("peak_force_estimate_n")], est, "estimate", raw);
        if law == "rigid" {
            assert!(est.as_f64().unwrap() > 0.0, "the rigid bridge pounds");
            assert_eq!(row[col("peak_contact_force_n")], "", "no computed force");
            let t_c: f64 = row[col("contact_time_estimate_s")].parse().unwrap();
            assert!(t_c > 0.0 && t_c < 1.0, "{t_c}");
            // the largest site estimate of compare_sites.csv is the run's
            let e = sites
                .iter()
                .filter(|r| r[0] == "rigid" && !r[4].is_empty())
                .map(|r| r[4].parse::<f64>().unwrap())
                .fold(f64::NAN, f64::max);
            assert_eq!(e, est.as_f64().unwrap());
        } else {
            assert_eq!(row[col("contact_time_estimate_s")], "");
            assert!(
                sites
                    .iter()
                    .filter(|r| r[0] == law)
                    .all(|r| r[4].is_empty())
            );
        }
    }
    // the report: the laws, the agreement paragraph and both tables, the figure
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    for needle in [
        "Do the laws agree?",
        "<strong>rigid</strong>: pounded",
        "<strong>bilinear</strong>: pounded",
        "compare_sites.csv",
        "peak_force_estimate_n",
        "src=\"joint_gap.png\"",
        "<h2 id=\"skipped\">Skipped laws</h2>\n<p>Every law ran.</p>",
    ] {
        assert!(html.contains(needle), "report lacks {needle:?}");
    }
    let timing: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("timing.json")).unwrap()).unwrap();
    assert!(timing["laws"]["bilinear"]["steps"].as_u64().unwrap() > 0);
    // joint_gap.png: one 300-px panel per site, the two joints and both abutments, named in
    // the caption in compare_sites.csv's order
    let png = std::fs::read(out.join("joint_gap.png")).unwrap();
    let height = u32::from_be_bytes(png[20..24].try_into().unwrap());
    let site_names: Vec<&str> = {
        let mut v: Vec<&str> = sites[1..]
            .iter()
            .filter(|r| r[0] == "rigid")
            .map(|r| r[1].as_str())
            .collect();
        v.dedup();
        v
    };
    assert_eq!(
        site_names,
        ["joint1", "joint2", "abutment-start", "abutment-end"]
    );
    assert_eq!(height, 300 * site_names.len() as u32);
    assert!(
        html.contains(&format!("one panel per site ({})", site_names.join(", "))),
        "the caption lists the panels"
    );
}

/// A law that cannot run on the bridge (hertz-damp has no "anagnostopoulos" calibration) is
/// skipped, with its reason on stderr, in `compare.csv` and `timing.json`; the others run.
#[test]
fn bridge_compare_skips_a_law_that_cannot_run_and_says_why() {
    let d = scratch_dir("bridge_compare", "skip");
    let c = "[contact]\nlaw = \"kelvin\"\ncalibration = \"anagnostopoulos\"\n\n";
    let file = write(&d, "v.toml", &viaduct(Some(c)));
    let out = d.join("cmp");
    let (code, _, err) = run_capture(&[
        "compare",
        file.to_str().unwrap(),
        "--laws",
        "kelvin,hertz-damp",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("skipped law hertz-damp") && err.contains("calibration"),
        "{err}"
    );
    let head = csv(&out.join("compare.csv"));
    assert_eq!(head[1][0], "kelvin");
    assert_eq!(head[1][1], "Completed");
    assert_eq!(head[2][0], "hertz-damp");
    assert_eq!(head[2][1], "skipped");
    let text = std::fs::read_to_string(out.join("compare.csv")).unwrap();
    let line = text.lines().nth(2).unwrap();
    assert!(
        line.starts_with("hertz-damp,skipped,,,,,,,,,,,,,,,,\"invalid calibration"),
        "{line}"
    );
    // the report lists the skipped law with its reason, and the warnings of the laws that ran
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let skipped = html.split("<h2 id=\"skipped\">").nth(1).unwrap();
    assert!(
        skipped.contains("<li><strong>hertz-damp</strong>: ")
            && skipped.contains("invalid calibration"),
        "{skipped}"
    );
    assert!(html.contains("<strong>hertz-damp</strong>: skipped: "));
    let sites = csv(&out.join("compare_sites.csv"));
    assert!(sites.iter().skip(1).all(|r| r[0] == "kelvin"));
    // every law refused: an error, exit 2, nothing written
    let out2 = d.join("cmp2");
    let (code, _, err) = run_capture(&[
        "compare",
        file.to_str().unwrap(),
        "--laws",
        "hertz-damp",
        "--out",
        out2.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    assert!(!out2.exists());
}

/// Bad site contact tables: exit 2, the key `joint[k].contact.KEY` (or the abutment's) with
/// its line, nothing written; a good one runs.
#[test]
fn bad_site_contact_tables_exit_2_naming_key_and_line() {
    let d = scratch_dir("bridge_compare", "sites");
    let base = viaduct(None);
    // line of "[abutment.end]" + 2: the site table's key goes after "gap = 0.04"
    let at_end = |extra: &str| {
        base.replace(
            "[abutment.end]\ngap = 0.04\n",
            &format!("[abutment.end]\ngap = 0.04\n{extra}"),
        )
    };
    let line_of =
        |text: &str, needle: &str| text.lines().position(|l| l.starts_with(needle)).unwrap() + 1;
    let joint = |table: &str| {
        base.replace(
            "[abutment.start]",
            &format!("[[joint]]\n[[joint]]\n{table}\n[abutment.start]"),
        )
    };
    let cases: Vec<(String, &str, &str)> = vec![
        (
            joint("contact = { stiffness = 1e9 }"),
            "joint[1].contact.stiffness",
            "contact = {",
        ),
        (
            joint("[joint.contact]\nk_h = 1e10"),
            "joint[1].contact.k_h",
            "k_h = 1e10",
        ),
        (
            joint("[joint.contact]\nk1 = -5.0"),
            "joint[1].contact.k1",
            "k1 = -5.0",
        ),
        (
            at_end("[abutment.end.contact]\nzeta = 0.1\n"),
            "abutment.end.contact.zeta",
            "zeta = 0.1",
        ),
    ];
    for (i, (text, key, needle)) in cases.iter().enumerate() {
        let f = write(&d, &format!("bad{i}.toml"), text);
        let out = d.join(format!("out{i}"));
        let (code, _, err) = run_capture(&[
            "simulate",
            f.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        let line = line_of(text, needle);
        assert_eq!(code, Some(2), "{key}: {err}");
        assert!(
            err.contains(key) && err.contains(&format!("bad{i}.toml:{line}")),
            "{key} line {line}: {err}"
        );
        assert!(!out.exists(), "{key}: nothing written");
    }
    // a stiffer law at the end abutment only runs, and its force differs from the file's
    let f = write(
        &d,
        "good.toml",
        &at_end("[abutment.end.contact]\nk1 = 3.0e10\n"),
    );
    let s = summary(&f, &d.join("good"));
    let plain = summary(&write(&d, "plain.toml", &base), &d.join("plain"));
    let force = |s: &Value| s["abutments"][1]["peak_contact_force_n"].as_f64().unwrap();
    assert!(
        force(&s) > force(&plain),
        "{} vs {}",
        force(&s),
        force(&plain)
    );
    assert_eq!(
        s["abutments"][1]["contact_law"]["k1"].as_f64(),
        Some(3.0e10)
    );
}

#[test]
fn scale_and_duration_apply_to_every_law_as_in_simulate() {
    // `compare --scale --duration` runs what `simulate --scale --duration` runs, for each law
    let work = scratch_dir("bridge_compare", "scale");
    let f = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-rigid-1d.toml");
    let f = f.to_str().unwrap();
    let cmp = work.join("cmp");
    let (code, _, err) = run_capture(&[
        "compare",
        f,
        "--laws",
        "rigid",
        "--scale",
        "2",
        "--duration",
        "3",
        "--out",
        cmp.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let sim = work.join("sim");
    let (code, _, err) = run_capture(&[
        "simulate",
        f,
        "--scale",
        "2",
        "--duration",
        "3",
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let s: Value =
        serde_json::from_str(&std::fs::read_to_string(sim.join("summary.json")).unwrap()).unwrap();
    let rows = csv(&cmp.join("compare.csv"));
    let col = |name: &str| rows[0].iter().position(|h| h == name).unwrap();
    let row = &rows[1];
    assert_eq!(row[col("law")], "rigid");
    assert_eq!(row[col("steps")], s["steps"].to_string());
    assert_eq!(row[col("impacts")], s["impacts"].to_string());
    assert!(
        s["impacts"].as_u64().unwrap() > 0,
        "scaled ×2 the bridge pounds"
    );
    let seat: f64 = row[col("peak_seat_displacement_m")].parse().unwrap();
    assert_eq!(seat, s["peak_seat_displacement_m"].as_f64().unwrap());
    let gov = &s["governing_seat"];
    assert_eq!(row[col("governing_seat_end")], gov["end"].as_str().unwrap());
    let ratio: f64 = row[col("governing_seat_ratio")].parse().unwrap();
    assert_eq!(ratio, gov["ratio"].as_f64().unwrap());
    // a bad value names the flag and writes nothing
    let bad = work.join("bad");
    let (code, _, err) = run_capture(&[
        "compare",
        f,
        "--scale",
        "nan",
        "--out",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2));
    assert!(err.contains("--scale"), "{err}");
    // the flag's fault, not the laws' (a hostile trial read 'no law of --laws can run')
    assert!(!err.contains("no law of --laws"), "{err}");
    assert!(!bad.exists());
}
