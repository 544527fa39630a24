//! The hostile fresh-clone trial (issue 22): a support-motion manifest entry on a two-deck
//! scenario is refused before the batch is announced, naming the manifest, the entry's key and
//! its line; the report of a diverged run prints its seat percentage with a bounded width and
//! does not send the reader to an empty Warnings section.

use crate::{run_capture, scratch_with};

const TWO_DECK: &str = "[decks]\nshape = \"straight\"\nL1 = 30.0\nL2 = 30.0\n[joint]\ngap = 0.02\n\
                        [time]\nduration = 0.5\n";

#[test]
fn a_support_entry_on_a_two_deck_file_names_the_manifest_key_and_line() {
    let support: String = std::iter::once("t,start,joint1,end\n".to_string())
        .chain((0..60).map(|i| format!("{},0.1,0.2,0.1\n", i as f64 * 0.01)))
        .collect();
    let d = scratch_with(
        "trial22",
        "supports",
        &[
            ("s.toml", TWO_DECK),
            ("sup.csv", &support),
            (
                "set.toml",
                "# a support motion\n[[record]]\nid = \"s1\"\nsupports = \"sup.csv\"\n",
            ),
        ],
    );
    let (code, _, err) = run_capture(&[
        "simulate",
        d.join("s.toml").to_str().unwrap(),
        "--set",
        d.join("set.toml").to_str().unwrap(),
        "--out",
        d.join("o").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{err}");
    for needle in [
        "set.toml",
        "`record[0].supports`",
        "set.toml:4",
        "\"s1\"",
        "two-deck",
    ] {
        assert!(err.contains(needle), "no {needle:?} in {err}");
    }
    assert!(
        !err.contains("batch:"),
        "announced before the refusal: {err}"
    );
    assert!(!d.join("o").exists());
}

#[test]
fn a_diverged_report_bounds_its_percentages_and_explains_no_warnings() {
    let d = scratch_with("trial22", "diverged", &[("s.toml", TWO_DECK)]);
    let out = d.join("o");
    let (code, _, err) = run_capture(&[
        "simulate",
        d.join("s.toml").to_str().unwrap(),
        "--scale",
        "1e300",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(1), "{err}");
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(summary.contains("\"status\": \"Diverged\""), "{summary}");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let longest = html
        .split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0);
    assert!(longest < 20, "a {longest}-digit number in report.html");
    let seats = html
        .lines()
        .find(|l| l.contains("Governing seat"))
        .expect("the seats verdict");
    let pct = seats
        .split(" seat (")
        .nth(1)
        .and_then(|s| s.split(" %)").next())
        .expect("the percentage");
    assert!(pct.contains('e') && pct.len() < 16, "{seats}");
    // the status line sends the reader to the warnings: they say why there are none
    assert!(html.contains("see the warnings"));
    let warnings = &html[html.find("<h2 id=\"warnings\">").unwrap()..];
    assert!(
        !warnings.starts_with("<h2 id=\"warnings\">Warnings</h2>\n<p>None.</p>")
            && warnings.contains("Diverged"),
        "{}",
        &warnings[..200.min(warnings.len())]
    );
}
