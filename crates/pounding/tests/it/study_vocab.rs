//! Study scenarios read the `[decks]` keys of `simulate` (`width`, `R1`, …); the deprecated names
//! (`width_m`, `r1_m`, …) give the same scenario plus a note, and both names together are refused.

use pounding::study::scenario::{DECK_RENAMES, DeprecatedKey};
use pounding::study::{DEFAULT_SCENARIO_TOML, Scenario, ScenarioError};

/// Every renamed key, old and new, gives the same validated scenario; only the old names are
/// noted, each with its line.
#[test]
fn deprecated_deck_keys_give_the_same_scenario_with_notes() {
    let values = [
        "9.5",
        "0.45",
        "2450.0",
        "[120.0, 80.0]",
        "[90.0]",
        "[33.0]",
        "[21.0, 44.0]",
    ];
    for shape in ["curved", "straight"] {
        let curved = shape == "curved";
        let pick = |i: usize| curved == (i < 5) || i < 3;
        let text = |old: bool| {
            let mut t = format!("[decks]\nshape = \"{shape}\"\n");
            for (i, ((new, dep), v)) in DECK_RENAMES.iter().zip(values).enumerate() {
                if pick(i) {
                    t.push_str(&format!("{} = {v}\n", if old { dep } else { new }));
                }
            }
            t
        };
        let (a, notes_new) = Scenario::from_toml_with_notes(&text(false), "new.toml").unwrap();
        let (b, notes_old) = Scenario::from_toml_with_notes(&text(true), "old.toml").unwrap();
        assert_eq!(a, b, "{shape}");
        assert!(notes_new.is_empty());
        assert_eq!(a.width, 9.5);
        if curved {
            assert_eq!(
                (a.r1_m.clone(), a.r2_m.clone()),
                (vec![120.0, 80.0], vec![90.0])
            );
        } else {
            assert_eq!(
                (a.l1_m.clone(), a.l2_m.clone()),
                (vec![33.0], vec![21.0, 44.0])
            );
        }
        let noted: Vec<(&str, &str, usize)> =
            notes_old.iter().map(|n| (n.old, n.new, n.line)).collect();
        let want: Vec<(&str, &str, usize)> = DECK_RENAMES
            .iter()
            .enumerate()
            .filter(|(i, _)| pick(*i))
            .enumerate()
            .map(|(k, (_, (new, old)))| (*old, *new, k + 3))
            .collect();
        // The notes come in the order width, thickness, density, L1, L2, R1, R2; compare as sets.
        let (mut noted, mut want) = (noted, want);
        noted.sort();
        want.sort();
        assert_eq!(noted, want, "{shape}");
    }
}

/// The note's text is what the CLI prints after `note: `.
#[test]
fn deprecation_note_names_section_old_and_new_key_and_line() {
    let (_, notes) =
        Scenario::from_toml_with_notes("[decks]\n\nthickness_m = 0.4\n", "f.toml").unwrap();
    assert_eq!(
        notes,
        vec![DeprecatedKey {
            section: "decks",
            old: "thickness_m",
            new: "thickness",
            origin: "f.toml".into(),
            line: 3,
        }]
    );
    assert_eq!(
        notes[0].to_string(),
        "[decks] thickness_m is deprecated: use thickness (f.toml, line 3)"
    );
}

/// Both names of one quantity: an error naming both keys and lines; errors about a value name
/// the key as written (old or new).
#[test]
fn both_names_refused_and_errors_name_the_key_as_written() {
    let e = Scenario::from_toml("[decks]\nR1 = [100.0]\nr1_m = [100.0]\n", "f.toml").unwrap_err();
    let msg = e.to_string();
    assert!(matches!(e, ScenarioError::Invalid { line: 3, .. }), "{msg}");
    assert!(
        msg.contains("decks.r1_m (line 3) and decks.R1 (line 2) give the same quantity"),
        "{msg}"
    );
    for (text, key) in [
        ("[decks]\nr2_m = [4.0]\n", "invalid decks.r2_m[0] = 4"),
        ("[decks]\nR2 = [4.0]\n", "invalid decks.R2[0] = 4"),
        ("[decks]\nwidth = -1.0\n", "invalid decks.width = -1"),
        ("[decks]\nwidth_m = -1.0\n", "invalid decks.width_m = -1"),
        ("[decks]\nL1 = [30.0]\n", "invalid decks.L1 = (set)"),
    ] {
        let msg = Scenario::from_toml(text, "f.toml").unwrap_err().to_string();
        assert!(msg.contains(key), "{text:?}: {msg}");
    }
    // The built-in default uses the current names only.
    let (_, notes) = Scenario::from_toml_with_notes(DEFAULT_SCENARIO_TOML, "default").unwrap();
    assert!(notes.is_empty());
}

/// The notes come in the order of their lines in the file (the reading order), whatever the
/// order of the keys' documentation.
#[test]
fn deprecation_notes_follow_the_lines_of_the_file() {
    let text = "[decks]\nr1_m = [100.0]\nr2_m = [100.0]\nwidth_m = 10.0\nthickness_m = 0.5\n";
    let (_, notes) = Scenario::from_toml_with_notes(text, "order.toml").unwrap();
    let lines: Vec<usize> = notes.iter().map(|n| n.line).collect();
    assert_eq!(lines, vec![2, 3, 4, 5], "{notes:?}");
}

/// A study list key written as one number, the way a `simulate` scenario writes it (`R1 = 100.0`),
/// is a list of one: the same scenario as `R1 = [100.0]`. A string is refused naming the key.
#[test]
fn a_list_key_written_as_one_number_is_a_list_of_one() {
    let one = "[decks]\nR1 = 100.0\nR2 = 80\nbeta1_deg = 60.0\n[impact]\nmu = 0.5\neps = 0.5\n";
    let many =
        "[decks]\nR1 = [100.0]\nR2 = [80]\nbeta1_deg = [60.0]\n[impact]\nmu = [0.5]\neps = [0.5]\n";
    let a = Scenario::from_toml(one, "one.toml").unwrap();
    let b = Scenario::from_toml(many, "many.toml").unwrap();
    assert_eq!(a, b);
    let e = Scenario::from_toml("[decks]\nR1 = \"100\"\n", "s.toml").unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("a number or a list of numbers")
            && msg.contains("line 2")
            && msg.contains("decks.R1"),
        "{msg}"
    );
}
