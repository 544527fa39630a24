//! The hostile fresh-clone trial's scenario messages (issue 22): a two-deck file's errors that
//! come from the bridge it expands into name the two-deck key, its line and the deck; a
//! `k_h`-given Jankowski law names `k_h`; a bad bearing coordinate is the one printed; the two
//! scenario forms refuse each other's tables with the line of the header; a deck or segment
//! without bearing stiffness follows one rule in both forms; the summary's joint peaks skip the
//! end gaps that are NaN in the history.

use crate::common::scenario_error as error;
use pounding::sim::scenario::Scenario;

const HDR: &str = "[decks]\nshape = \"straight\"\nL1 = 30.0\nL2 = 30.0\n";
const SKEW: &str = "[decks]\nshape = \"skew\"\nL1 = 30.0\nL2 = 30.0\nskew_deg = 30.0\n";
const TWO_SEGMENTS: &str = "[[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.0\n\
                            [[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.0\n";
const TIME: &str = "[time]\nduration = 0.2\n";

fn builds(text: &str) -> bool {
    let sc = Scenario::from_toml(text, "f.toml").unwrap();
    if text.contains("[[segment]]") {
        sc.build_bridge().is_ok()
    } else {
        sc.build().is_ok()
    }
}

/// Every two-deck key whose value the bridge expansion checks (bearing points inside their deck,
/// the stiffness over the mass, the Rayleigh fit) is named with its line and deck, for both
/// decks and for straight and skewed decks; never as `segment[i]`.
#[test]
fn expansion_errors_name_the_two_deck_key_line_and_deck() {
    let line = |head: &str| head.lines().count() + 2; // after `[bearings]`
    for head in [HDR, SKEW] {
        for (deck, key) in [(1, "points1"), (2, "points2")] {
            let text = format!("{head}[bearings]\n{key} = [[500.0, 0.0], [-5.0, 0.0]]\n{TIME}");
            let msg = error(&text);
            assert!(
                msg.contains(&format!("`[bearings] {key}` (f.toml:{})", line(head)))
                    && msg.contains(&format!("deck {deck}"))
                    && msg.contains("bearing 1")
                    && msg.contains("500")
                    && !msg.contains("segment["),
                "{msg}"
            );
            // the second point outside: bearing 2 named
            let text = format!("{head}[bearings]\n{key} = [[0.0, 0.0], [0.0, 5000.0]]\n{TIME}");
            let msg = error(&text);
            assert!(msg.contains("bearing 2") && msg.contains(key), "{msg}");
        }
        // a deck without stiffness under Rayleigh damping: damping_ratio, with the deck
        let msg = error(&format!("{head}[bearings]\nstiffness2 = 0.0\n{TIME}"));
        assert!(
            msg.contains("`[bearings] damping_ratio`")
                && msg.contains("deck 2")
                && msg.contains("Rayleigh"),
            "{msg}"
        );
    }
}

/// A two-deck deck with zero stiffness and dashpots: the cause is the mechanism (its bearing key
/// and line), not the Rayleigh damping_ratio; with `allow_mechanism` it runs. The bridge form's
/// `bearing_stiffness = 0` follows the same rule (it was refused as "must be > 0").
#[test]
fn zero_stiffness_is_a_mechanism_in_both_forms() {
    let two = format!("{HDR}[bearings]\nstiffness1 = 0.0\ndamping = \"dashpots\"\n{TIME}");
    let msg = error(&two);
    assert!(
        msg.contains("`[bearings] stiffness1` (f.toml:6)")
            && msg.contains("mechanism")
            && !msg.contains("Rayleigh"),
        "{msg}"
    );
    assert!(builds(&two.replace(
        "[bearings]\n",
        "[bearings]\nallow_mechanism = true\n"
    )));
    let bridge = TWO_SEGMENTS.replacen("period_s = 1.0", "bearing_stiffness = 0.0", 1)
        + "[bridge]\ndamping = \"dashpots\"\n"
        + TIME;
    let msg = error(&bridge);
    assert!(
        msg.contains("segment[0].bearing_stiffness")
            && msg.contains("f.toml:4")
            && msg.contains("mechanism"),
        "{msg}"
    );
    assert!(builds(
        &bridge.replace("[bridge]\n", "[bridge]\nallow_mechanism = true\n")
    ));
    // Rayleigh damping on a segment without stiffness: the damping is named, in both forms
    let msg = error(&bridge.replace("damping = \"dashpots\"", "allow_mechanism = true"));
    assert!(
        msg.contains("segment[0]") && msg.contains("Rayleigh"),
        "{msg}"
    );
    let msg = error(&two.replace("damping = \"dashpots\"", "allow_mechanism = true"));
    assert!(
        msg.contains("`[bearings] damping_ratio`") && msg.contains("deck 1"),
        "{msg}"
    );
}

/// `law = "jankowski"` with a bad `k_h` (beta not given) names `k_h`, in both forms.
#[test]
fn jankowski_stiffness_from_k_h_is_named_k_h() {
    for v in ["inf", "-1.0", "nan"] {
        let msg = error(&format!(
            "{HDR}[contact]\nlaw = \"jankowski\"\nk_h = {v}\n{TIME}"
        ));
        assert!(
            msg.contains("`[contact] k_h` (f.toml:7)") && !msg.contains("beta"),
            "{v}: {msg}"
        );
        let msg = error(&format!(
            "{TWO_SEGMENTS}[contact]\nlaw = \"jankowski\"\nk_h = {v}\n{TIME}"
        ));
        assert!(msg.contains("k_h") && !msg.contains("beta"), "{v}: {msg}");
    }
    // beta given: beta is the stiffness and is named
    let msg = error(&format!(
        "{HDR}[contact]\nlaw = \"jankowski\"\nbeta = -1.0\n{TIME}"
    ));
    assert!(msg.contains("`[contact] beta` (f.toml:7)"), "{msg}");
}

/// A non-finite bearing coordinate is the value printed (it printed the other, finite one).
#[test]
fn the_bad_bearing_coordinate_is_printed() {
    for (pts, bad) in [
        ("[[0.0, nan], [0.0, 5.0]]", "nan"),
        ("[[0.0, inf], [0.0, 5.0]]", "inf"),
        ("[[-inf, 1.0], [0.0, 5.0]]", "-inf"),
    ] {
        let msg = error(&format!("{HDR}[bearings]\npoints1 = {pts}\n{TIME}"));
        assert!(
            msg.contains(&format!("(deck 1, bearing 1) = {bad}:"))
                && msg.contains("`[bearings] points1` (f.toml:6)"),
            "{msg}"
        );
    }
}

/// The two forms refuse each other's tables naming the table and its header's line.
#[test]
fn mixed_forms_name_the_table_and_its_line() {
    let cases = [
        (format!("{HDR}{TIME}[bridge]\ngap = 0.02\n"), "[bridge]", 7),
        (
            format!("{HDR}{TIME}[[joint]]\ngap = 0.02\n"),
            "[[joint]]",
            7,
        ),
        (
            format!("{HDR}{TIME}[abutment.start]\ngap = 0.02\n"),
            "[abutment.start]",
            7,
        ),
        (format!("{TWO_SEGMENTS}{HDR}{TIME}"), "[decks]", 9),
        (
            format!("{TWO_SEGMENTS}[bearings]\nstiffness1 = 1e7\n{TIME}"),
            "[bearings]",
            9,
        ),
        (
            format!("{TWO_SEGMENTS}[abutments]\ngap1 = 0.02\n{TIME}"),
            "[abutments]",
            9,
        ),
        (
            format!("{TWO_SEGMENTS}[joint]\ngap = 0.02\n{TIME}"),
            "`[joint]`",
            9,
        ),
    ];
    for (text, table, line) in cases {
        let msg = error(&text);
        assert!(
            msg.contains(table) && msg.contains(&format!("(line {line})")),
            "{table}: {msg}"
        );
        assert!(
            !msg.contains("unknown field") && !msg.contains("invalid type"),
            "{msg}"
        );
    }
    let msg = error(&format!("{TWO_SEGMENTS}[decks]\nL1 = 30.0\n{TIME}"));
    assert!(msg.contains("refused next to [[segment]]"), "{msg}");
    let msg = error(&format!("{TWO_SEGMENTS}[joint]\ngap = 0.02\n{TIME}"));
    assert!(msg.contains("uses `[[joint]]`"), "{msg}");
}

/// After a corner leaves the other face the history's end gaps are NaN; the summary's joint
/// peaks are the maxima over the finite ones (every step kept, so they are the same numbers).
#[test]
fn joint_peaks_skip_the_nan_end_gaps() {
    let text = "[[segment]]\nshape = \"straight\"\nL = 30.0\nbearing_stiffness = 2.02e7\n\
                [[segment]]\nshape = \"straight\"\nL = 30.0\nbearing_stiffness = 8.97e6\n\
                [bridge]\ngap = 0.02\n[ground_motion]\nscale_y = 1000.0\nscale_x = 1000.0\n\
                [time]\nduration = 2.0\nhistory_every = 1\n";
    let sol = Scenario::from_toml(text, "f.toml")
        .unwrap()
        .build_bridge()
        .unwrap()
        .run()
        .unwrap();
    let n = sol.t.len();
    assert_eq!(sol.end_gaps.len(), 2 * n);
    let (mut closing, mut opening, mut nan_rows) = (f64::NEG_INFINITY, f64::NEG_INFINITY, 0);
    for row in sol.end_gaps.chunks(2) {
        let finite: Vec<f64> = row.iter().copied().filter(|g| !g.is_nan()).collect();
        if finite.len() < 2 {
            nan_rows += 1;
        }
        if let (Some(lo), Some(hi)) = (
            finite.iter().copied().reduce(f64::min),
            finite.iter().copied().reduce(f64::max),
        ) {
            closing = closing.max(0.02 - lo);
            opening = opening.max(hi - 0.02);
        }
    }
    assert!(
        nan_rows > 0,
        "the run never left the face: the test shows nothing ({n} rows, {:?}, {:?})",
        sol.summary.unseated_end,
        sol.end_gaps.iter().rev().take(4).collect::<Vec<_>>()
    );
    let j = &sol.summary.joints[0];
    assert!(j.peak_closing.is_finite() && j.peak_opening.is_finite());
    assert!(
        (j.peak_closing - closing).abs() <= 1e-12 * closing.abs(),
        "{j:?} {closing}"
    );
    assert!(
        (j.peak_opening - opening).abs() <= 1e-12 * opening.abs(),
        "{j:?} {opening}"
    );
}
