//! Errors that named a key the file does not have, or no line: a bearing stiffness too small or
//! too large to assemble, an empty segment list, bridge tables in a file without segments; and
//! numbers of a diverged run printed with a bounded width.

use crate::{run_capture, scratch_with};

fn refused(name: &str, text: &str, needles: &[&str]) {
    let d = scratch_with("errors3", name, &[("s.toml", text)]);
    let (code, _, err) = run_capture(&[
        "simulate",
        d.join("s.toml").to_str().unwrap(),
        "--out",
        d.join("o").to_str().unwrap(),
    ]);
    assert_eq!(code, Some(2), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: no {n:?} in {err}");
    }
    assert!(!d.join("o").exists(), "{name}: nothing written");
}

const SEG: &str = "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1e6\n";

#[test]
fn errors_name_the_key_and_line_the_file_has() {
    refused(
        "tiny",
        &format!("{SEG}bearing_stiffness = 5e-324\n"),
        &[
            "segment[0].bearing_stiffness = 5e-324",
            "smallest normal",
            "s.toml:5",
        ],
    );
    refused(
        "huge",
        &format!("{SEG}bearing_stiffness = 1e308\n"),
        &[
            "segment[0].bearing_stiffness = 1e308",
            "overflow",
            "s.toml:5",
        ],
    );
    refused(
        "empty",
        "segment = []\n[bridge]\ngap = 0.1\n",
        &["at least one [[segment]]", "empty", "s.toml:1"],
    );
    refused(
        "joints",
        "[[joint]]\ngap = 0.1\n",
        &["[[joint]] tables belong to a bridge file", "s.toml"],
    );
    refused(
        "abutment",
        "[abutment.start]\ngap = 0.1\n",
        &["[abutment.start] / [abutment.end]", "s.toml"],
    );
}

#[test]
fn a_diverged_number_is_printed_in_exponent_form() {
    use pounding::output::bounded;
    assert_eq!(bounded(1e300, 4), "1.0000e300");
    assert_eq!(bounded(-2.5e7, 4), "-2.5000e7");
    assert_eq!(bounded(0.02244, 4), "0.0224");
    assert_eq!(bounded(f64::INFINITY, 4), "inf");
}

/// Hostile round 3 campaign (F11): seat lengths and restrainer slack have the range other
/// lengths have (9.2e18 m was accepted), and `simulate` of a scenario with a `[fragility]` table
/// checks that table too (a typo in it went unnoticed until `fragility` ran).
#[test]
fn seat_lengths_and_fragility_tables_are_checked_by_simulate() {
    let two = format!("{SEG}period_s = 1.0\n{SEG}period_s = 0.8\n");
    refused(
        "seat",
        &format!("[bridge]\nseat_length = 9.2e18\n{two}"),
        &["bridge.seat_length = 9.2e18", "(0, 1e3] m", "s.toml:2"],
    );
    refused(
        "outer",
        &format!("[bridge]\nouter_seat_length = 2e3\n{two}"),
        &["bridge.outer_seat_length", "s.toml:2"],
    );
    refused(
        "slack",
        &format!("[bridge]\nrestrainer_k = 1e7\nrestrainer_slack = 9.2e18\n{two}"),
        &["restrainer_slack", "[0, 1e3] m"],
    );
    refused(
        "fragility",
        &format!(
            "{two}[fragility]\nrecords = \"set.toml\"\nlevels_g = [0.1]\nbootstrap = \"many\"\n"
        ),
        &["bootstrap"],
    );
}
