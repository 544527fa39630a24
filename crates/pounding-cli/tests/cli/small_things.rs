//! Small things an engineer trips over: no rustdoc escapes in `--help`, `1 thread` grammar,
//! step times that read as the decimals of `k·dt`, no negative zero in reports.

use crate::{run_capture, scratch_dir};

/// clap prints doc comments literally: `\[s\]` (a rustdoc escape) must not reach `--help`.
#[test]
fn help_texts_have_no_rustdoc_escapes() {
    for sub in [
        &[][..],
        &["lcp"],
        &["impact"],
        &["study"],
        &["study", "merge"],
        &["simulate"],
        &["compare"],
    ] {
        let mut args = sub.to_vec();
        args.push("--help");
        let (code, out, err) = run_capture(&args);
        assert_eq!(code, Some(0), "{args:?}: {err}");
        assert!(
            !out.contains('\\'),
            "{args:?} --help shows a backslash:\n{out}"
        );
    }
}

/// `--threads 1`: the study says `on 1 thread`, and `1 configuration x 1 case`.
#[test]
fn study_message_is_singular_for_one() {
    let dir = scratch_dir("small", "threads");
    let sc = dir.join("s.toml");
    std::fs::write(
        &sc,
        "[decks]\nbeta1_deg = [60.0]\nbeta2_deg = [90.0]\nR1 = [100.0]\nR2 = [200.0]\n\
         [impact]\nmu = [0.5]\n[grid]\ncases = [\"deck1-inner\"]\n\
         theta1_deg = { start = 0.0, stop = 0.0, step = 1.0 }\n\
         theta2_deg = { start = 0.0, stop = 0.0, step = 1.0 }\n[output]\nfigures = false\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, _, err) = run_capture(&[
        "study",
        sc.to_str().unwrap(),
        "--threads",
        "1",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("study: 1 configuration x 1 case x 1 cell = 1 row on 1 thread\n"),
        "{err}"
    );
}

/// With `dt = 1e-3`, every `t_s` in `history.csv` and `impacts.csv` has at most three decimals
/// (`0.009`, not `0.009000000000000001`) and equals `k·dt` to a few ulps; the stderr summary's
/// duration likewise.
#[test]
fn step_times_read_as_decimals_of_the_step() {
    let dir = scratch_dir("small", "times");
    let out = dir.join("out");
    let example = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/straight-1d.toml"
    );
    let (code, _, err) = run_capture(&[
        "simulate",
        example,
        "--duration",
        "8",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("simulated 8 s in 8000 steps"), "{err}");
    let mut checked = 0;
    for (file, col) in [("history.csv", 0), ("impacts.csv", 1)] {
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        for line in text.lines().skip(1) {
            let t = line.split(',').nth(col).unwrap();
            let decimals = t.split_once('.').map_or(0, |(_, d)| d.len());
            assert!(decimals <= 3, "{file}: t_s = {t}");
            let x: f64 = t.parse().unwrap();
            let k = (x / 1e-3).round();
            assert!(
                (x - k * 1e-3).abs() <= 4.0 * f64::EPSILON * x,
                "{file}: {t}"
            );
            checked += 1;
        }
    }
    assert!(checked > 800, "{checked}");
}

/// An impact whose report has exact zeros of either sign shows no `-0.0` (JSON) and the compare
/// table no `-0.0000`.
#[test]
fn reports_show_no_negative_zero() {
    let (code, out, err) = run_capture(&[
        "impact",
        "--shape",
        "straight",
        "--length",
        "30",
        "--length2",
        "50",
        "--mu",
        "0.3",
        "--eps",
        "0.5",
        "--json",
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("\"centroid\""), "{out}");
    assert!(!out.contains("-0.0,") && !out.contains("-0.0\n"), "{out}");
}
