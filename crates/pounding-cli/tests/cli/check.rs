//! `pounding check`: the printed table, the files written, exit codes, and `[code_check]` errors
//! naming the file, the key and the line.

use crate::{run_capture, scratch_with};

const CURVED_5: &str = include_str!("../../../../examples/viaduct-curved-5.toml");

fn with_check(table: &str) -> String {
    CURVED_5.replace(
        "[ground_motion]",
        &format!("[code_check]\n{table}\n[ground_motion]"),
    )
}

/// The line of the first key of `[code_check]` in [`with_check`]'s text.
fn first_key_line() -> usize {
    with_check("")
        .lines()
        .position(|l| l == "[code_check]")
        .unwrap()
        + 2
}

#[test]
fn check_prints_the_table_and_writes_its_files() {
    let table = "ground = \"C\"\na_gr_ms2 = 3.0\ndisplacement_m = 0.12\npier_height_m = 8.0\n";
    let d = scratch_with("check", "files", &[("s.toml", &with_check(table))]);
    let out = d.join("out");
    let (code, stdout, stderr) = run_capture(&[
        "check",
        d.join("s.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    for i in 1..=5 {
        for end in ["start", "end"] {
            assert!(stdout.contains(&format!("segment{i}-{end}")), "{stdout}");
        }
    }
    for col in [
        "EC8",
        "LRFD",
        "Guide",
        "Caltr",
        "JRA",
        "governs",
        "margin",
        "Joint gaps",
    ] {
        assert!(stdout.contains(col), "{col}: {stdout}");
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("check.json")).unwrap()).unwrap();
    let csv = std::fs::read_to_string(out.join("check.csv")).unwrap();
    let gaps = std::fs::read_to_string(out.join("check_gaps.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    let head = &rows[0];
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    assert_eq!(rows.len(), 11);
    assert_eq!(gaps.lines().count(), 5);
    let ends = json["ends"].as_array().unwrap();
    let mut fails = 0;
    for (row, e) in rows[1..].iter().zip(ends) {
        assert_eq!(row[col("end")], e["end"].as_str().unwrap());
        let governing: f64 = row[col("governing_m")].parse().unwrap();
        assert_eq!(governing, e["governing_m"].as_f64().unwrap());
        // the governing requirement is the largest code's, the margin the provided seat minus it
        let codes = [
            "ec8_m",
            "aashto_lrfd_m",
            "aashto_guide_m",
            "caltrans_m",
            "jra_m",
        ];
        let max = codes
            .iter()
            .map(|c| row[col(c)].parse::<f64>().unwrap())
            .fold(f64::MIN, f64::max);
        assert_eq!(governing, max);
        let seat: f64 = row[col("seat_length_m")].parse().unwrap();
        let margin: f64 = row[col("margin_m")].parse().unwrap();
        assert!((margin - (seat - max)).abs() < 1e-12);
        let verdict = if margin >= 0.0 { "PASS" } else { "FAIL" };
        assert_eq!(row[col("verdict")], verdict);
        fails += usize::from(verdict == "FAIL");
        // and the printed row says the same
        let line = stdout.lines().find(|l| l.starts_with(row[0])).unwrap();
        assert!(line.ends_with(verdict), "{line}");
    }
    assert_eq!(json["failing_ends"].as_u64(), Some(fails as u64));
    if fails > 0 {
        assert_eq!(json["verdict"], "FAIL");
        assert!(stdout.contains("The check ran (exit 0)"), "{stdout}");
    }
    // the inputs the file did not set are listed as defaults
    let defaults = json["inputs"]["at_default"].as_array().unwrap();
    assert!(defaults.iter().any(|k| k == "aashto_zone"));
    assert!(!defaults.iter().any(|k| k == "ground"));
}

#[test]
fn check_of_a_bad_value_names_file_key_and_line() {
    let d = scratch_with(
        "check",
        "bad",
        &[("s.toml", &with_check("importance_class = 7"))],
    );
    let (code, stdout, stderr) = run_capture(&["check", d.join("s.toml").to_str().unwrap()]);
    assert_eq!(code, Some(2), "{stdout}");
    assert!(stderr.contains("code_check.importance_class"), "{stderr}");
    assert!(
        stderr.contains(&format!("s.toml:{}", first_key_line())),
        "{stderr}"
    );
    // simulate refuses it too, before running
    let (code, _, stderr) = run_capture(&["simulate", d.join("s.toml").to_str().unwrap()]);
    assert_eq!(code, Some(2));
    assert!(stderr.contains("code_check.importance_class"), "{stderr}");
    // a per-segment list that does not fit the bridge, or a hinge it lacks, is found against
    // the model: simulate (a run and a batch) refuses it before running, writing nothing
    for (name, table, key) in [
        (
            "len",
            "displacement_m = [0.1, 0.2]",
            "code_check.displacement_m",
        ),
        ("hinge", "in_span_hinges = [9]", "code_check.in_span_hinges"),
    ] {
        let d = scratch_with("check", name, &[("s.toml", &with_check(table))]);
        let s = d.join("s.toml");
        let out = d.join("out");
        for extra in [&[][..], &["--records", "builtin:ELC180"][..]] {
            let mut args = vec![
                "simulate",
                s.to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
            ];
            args.extend_from_slice(extra);
            let (code, _, stderr) = run_capture(&args);
            assert_eq!(code, Some(2), "{table} {extra:?}: {stderr}");
            assert!(
                stderr.contains(key) && stderr.contains(&format!("s.toml:{}", first_key_line())),
                "{stderr}"
            );
            assert!(!out.exists(), "{table}: an output was written");
        }
    }
}

/// An unusable `--out` (a regular file) is an error before the table is printed (a hostile trial
/// saw the whole table and verdict, then exit 2).
#[test]
fn an_unusable_out_is_refused_before_anything_is_printed() {
    let d = scratch_with(
        "check",
        "outfile",
        &[("s.toml", &with_check("")), ("f", "x")],
    );
    let (code, stdout, stderr) = run_capture(&[
        "check",
        d.join("s.toml").to_str().unwrap(),
        "--out",
        d.join("f").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stdout.is_empty(), "{stdout}");
    assert_eq!(std::fs::read_to_string(d.join("f")).unwrap(), "x");
}

#[test]
fn check_refuses_an_unknown_key_with_its_line() {
    let d = scratch_with(
        "check",
        "unknown",
        &[("s.toml", &with_check("ground_type = \"A\""))],
    );
    let (code, _, stderr) = run_capture(&["check", d.join("s.toml").to_str().unwrap()]);
    assert_eq!(code, Some(2));
    assert!(stderr.contains("s.toml"), "{stderr}");
    assert!(
        stderr.contains(&format!("line {}", first_key_line())),
        "{stderr}"
    );
    assert!(stderr.contains("ground_type"), "{stderr}");
    // every accepted key is listed, none cut off
    for (key, _) in pounding::assessment::check_input::DEFAULTS {
        assert!(stderr.contains(&format!("`{key}`")), "{key}: {stderr}");
    }
    assert!(!stderr.contains("more characters"), "{stderr}");
}

/// The guide's example run prints what the guide shows (its rows are copied from a run).
#[test]
fn the_guide_example_is_what_the_command_prints() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let guide = std::fs::read_to_string(root.join("docs/guide/check.md")).unwrap();
    let (code, stdout, stderr) = run_capture(&[
        "check",
        root.join("examples/viaduct-curved-5-check.toml")
            .to_str()
            .unwrap(),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    let block = guide
        .split("```text\n")
        .nth(1)
        .unwrap()
        .split("```")
        .next()
        .unwrap();
    let shown: Vec<&str> = block
        .lines()
        .filter(|l| {
            l.starts_with("segment") || l.starts_with("joint1 ") || l.starts_with("Verdict")
        })
        .collect();
    assert!(shown.len() >= 4, "{shown:?}");
    for l in shown {
        assert!(
            stdout.lines().any(|o| o == l),
            "guide line not printed: {l}\n{stdout}"
        );
    }
}

/// `simulate` of a bridge with `[code_check]`: report.html has the code-check table, each end's
/// simulated peak there is summary.json's, and its code seats are `pounding check`'s.
#[test]
fn simulate_report_puts_code_seats_beside_the_run() {
    let table = "ground = \"C\"\na_gr_ms2 = 3.0\ndisplacement_m = 0.01\n";
    let d = scratch_with("check", "report", &[("s.toml", &with_check(table))]);
    let (out, chk) = (d.join("out"), d.join("chk"));
    let s = d.join("s.toml");
    let (code, _, stderr) = run_capture(&[
        "simulate",
        s.to_str().unwrap(),
        "--duration",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{stderr}");
    let (code, _, _) = run_capture(&["check", s.to_str().unwrap(), "--out", chk.to_str().unwrap()]);
    assert_eq!(code, Some(0));
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let check: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(chk.join("check.json")).unwrap()).unwrap();
    let section = html
        .split("<h2 id=\"code-check\">")
        .nth(1)
        .expect("code-check section");
    let section = section.split("</table>").next().unwrap();
    let mut beyond = 0;
    for seat in summary["seats"].as_array().unwrap() {
        let end = seat["end"].as_str().unwrap();
        let row = section
            .split("<tr>")
            .find(|r| r.starts_with(&format!("<td>{end}</td>")))
            .unwrap_or_else(|| panic!("{end}"));
        let cells: Vec<&str> = row
            .split("<td>")
            .skip(1)
            .map(|c| c.split("</td>").next().unwrap())
            .collect();
        let peak = seat["peak_seat_displacement_m"].as_f64().unwrap();
        assert_eq!(cells[10], format!("{peak:.3}"), "{end}");
        let e = check["ends"]
            .as_array()
            .unwrap()
            .iter()
            .find(|e| e["end"] == end)
            .unwrap();
        assert_eq!(
            cells[3],
            format!("{:.3}", e["required_m"]["ec8"].as_f64().unwrap())
        );
        let over = peak > 0.01;
        assert_eq!(cells[14].contains("exceeds"), over, "{end}: {row}");
        beyond += usize::from(over);
    }
    assert_eq!(
        html.contains("the simulated peak seat displacement exceeds"),
        beyond > 0
    );
    // the Verdict states the code verdict and its counts (check.json's), in red when it fails
    let verdict = html.split("<h2 id=\"verdict\">").nth(1).unwrap();
    let verdict = verdict.split("</table>").next().unwrap();
    let row = verdict
        .split("<tr>")
        .find(|r| r.starts_with("<th>code check</th>"))
        .expect("code check row");
    let n = check["ends"].as_array().unwrap().len();
    let failing = check["failing_ends"].as_u64().unwrap();
    let overall = check["verdict"].as_str().unwrap();
    assert!(
        row.contains(&format!(
            "{overall}: {failing} of {n} seated ends are shorter than a code requires"
        )),
        "{row}"
    );
    assert_eq!(row.contains("v-contradicted"), overall == "FAIL", "{row}");
    assert_eq!(
        row.contains("exceeds the design displacement"),
        beyond > 0,
        "{row}"
    );
    // without [code_check] there is no such section
    let d2 = scratch_with("check", "plain", &[("s.toml", CURVED_5)]);
    let out2 = d2.join("out");
    let (code, _, _) = run_capture(&[
        "simulate",
        d2.join("s.toml").to_str().unwrap(),
        "--duration",
        "1",
        "--out",
        out2.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0));
    let html = std::fs::read_to_string(out2.join("report.html")).unwrap();
    assert!(!html.contains("code-check"));
}
