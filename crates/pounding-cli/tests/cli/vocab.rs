//! One vocabulary across scenario files: `study` takes the `[decks]` keys of `simulate`
//! (`width`, `thickness`, `density`, `R1`, `R2`, `L1`, `L2`); its older names still work with a
//! deprecation note on stderr, and a quantity given under both names is refused.

use crate::{run_capture, scratch_dir};
use std::path::Path;

/// The same small study written with the current and with the deprecated `[decks]` names.
fn study_pair(shape: &str) -> (String, String) {
    let rest = "[impact]\nmu = [0.0, 0.5]\n[grid]\ntheta1_deg = { start = -4.0, stop = 4.0, step = 2.0 }\n\
                theta2_deg = { start = -4.0, stop = 4.0, step = 2.0 }\n[output]\nfigures = false\n";
    let (new, old) = if shape == "curved" {
        (
            "width = 9.0\nthickness = 0.6\ndensity = 2400.0\nbeta1_deg = [60.0]\nbeta2_deg = [90.0]\nR1 = [100.0]\nR2 = [150.0, 200.0]\n",
            "width_m = 9.0\nthickness_m = 0.6\ndensity_kg_m3 = 2400.0\nbeta1_deg = [60.0]\nbeta2_deg = [90.0]\nr1_m = [100.0]\nr2_m = [150.0, 200.0]\n",
        )
    } else {
        (
            "shape = \"skew\"\nwidth = 9.0\nthickness = 0.6\ndensity = 2400.0\nL1 = [30.0]\nL2 = [25.0, 40.0]\nskew_deg = [10.0]\n",
            "shape = \"skew\"\nwidth_m = 9.0\nthickness_m = 0.6\ndensity_kg_m3 = 2400.0\nl1_m = [30.0]\nl2_m = [25.0, 40.0]\nskew_deg = [10.0]\n",
        )
    };
    (
        format!("[decks]\n{new}{rest}"),
        format!("[decks]\n{old}{rest}"),
    )
}

fn study(dir: &Path, name: &str, text: &str) -> (Option<i32>, String) {
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(&file, text).unwrap();
    let out = dir.join(name);
    let (code, _, err) = run_capture(&[
        "study",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (code, err)
}

/// Old and new names give byte-identical numeric outputs (curved and skew decks), the old names
/// print one deprecation note each (with file and line), the new names none.
#[test]
fn study_old_and_new_deck_keys_give_identical_outputs() {
    let dir = scratch_dir("vocab", "same");
    for shape in ["curved", "skew"] {
        let (new, old) = study_pair(shape);
        let (c_new, e_new) = study(&dir, &format!("{shape}-new"), &new);
        let (c_old, e_old) = study(&dir, &format!("{shape}-old"), &old);
        assert_eq!((c_new, c_old), (Some(0), Some(0)), "{e_new}\n{e_old}");
        assert!(!e_new.contains("deprecated"), "{e_new}");
        let pairs: &[(&str, &str, usize)] = if shape == "curved" {
            &[
                ("width_m", "width", 2),
                ("r1_m", "R1", 7),
                ("r2_m", "R2", 8),
            ]
        } else {
            &[
                ("density_kg_m3", "density", 5),
                ("l1_m", "L1", 6),
                ("l2_m", "L2", 7),
            ]
        };
        for (old_key, new_key, line) in pairs {
            let note = format!(
                "note: [decks] {old_key} is deprecated: use {new_key} ({}, line {line})",
                dir.join(format!("{shape}-old.toml")).display()
            );
            assert!(e_old.contains(&note), "missing {note:?} in\n{e_old}");
        }
        assert_eq!(e_old.matches("is deprecated").count(), 5, "{e_old}");
        for f in ["bounds.csv", "summary.csv", "summary.json"] {
            let a = std::fs::read(dir.join(format!("{shape}-new")).join(f)).unwrap();
            let b = std::fs::read(dir.join(format!("{shape}-old")).join(f)).unwrap();
            assert!(
                a == b,
                "{shape}: {f} differs between the old and the new key names"
            );
        }
    }
}

/// A quantity given under both names is bad input: exit 2, both keys and both lines named,
/// nothing written.
#[test]
fn study_refuses_old_and_new_name_of_one_quantity() {
    let dir = scratch_dir("vocab", "both");
    for (text, old, new, old_line, new_line) in [
        (
            "[decks]\nwidth = 9.0\n# comment\nwidth_m = 9.0\n",
            "width_m",
            "width",
            4,
            2,
        ),
        (
            "[decks]\nr2_m = [100.0]\nR2 = [100.0]\n",
            "r2_m",
            "R2",
            2,
            3,
        ),
        (
            "[decks]\nshape = \"straight\"\nL1 = [30.0]\nl1_m = [30.0]\n",
            "l1_m",
            "L1",
            4,
            3,
        ),
    ] {
        let (code, err) = study(&dir, "both", text);
        assert_eq!(code, Some(2), "{err}");
        let want = format!(
            "decks.{old} (line {old_line}) and decks.{new} (line {new_line}) give the same quantity"
        );
        assert!(err.contains(&want), "missing {want:?} in\n{err}");
        assert!(
            err.contains(&format!("both.toml: line {old_line}:")),
            "{err}"
        );
        assert!(
            !dir.join("both").exists(),
            "an output directory was written"
        );
    }
}

/// `--print-default` of `study` shows the current names only, and every one of them is a key of
/// `simulate --print-default` too (the shared vocabulary).
#[test]
fn print_default_of_study_and_simulate_share_the_deck_keys() {
    let (c1, study, _) = run_capture(&["study", "--print-default"]);
    let (c2, simulate, _) = run_capture(&["simulate", "--print-default"]);
    assert_eq!((c1, c2), (Some(0), Some(0)));
    let keys_of = |text: &str| -> Vec<String> {
        text.lines()
            .map(|l| l.trim_start_matches('#').trim())
            .filter_map(|l| l.split_once('=').map(|(k, _)| k.trim().to_string()))
            .filter(|k| !k.is_empty() && !k.contains(' '))
            .collect()
    };
    let (sk, mk) = (keys_of(&study), keys_of(&simulate));
    for (new, old) in pounding::study::scenario::DECK_RENAMES {
        assert!(mk.iter().any(|k| k == new), "simulate lacks {new}");
        assert!(study.contains(new), "study --print-default lacks {new}");
        assert!(
            !sk.iter().any(|k| k == old),
            "study --print-default still sets {old}"
        );
    }
}
