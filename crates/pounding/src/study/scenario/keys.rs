//! One vocabulary for `study` and `simulate`: the study's `[decks]` keys are the simulator's
//! (`width`, `thickness`, `density`, `R1`, `R2`, `L1`, `L2`; `beta1_deg`, `beta2_deg` and
//! `skew_deg` were already shared). The study's earlier names (`width_m`, `thickness_m`,
//! `density_kg_m3`, `r1_m`, `r2_m`, `l1_m`, `l2_m`) keep working: each one used gives a
//! [`DeprecatedKey`] note, and a file that gives a quantity under both names is refused naming
//! both keys and their lines (which one should win cannot be guessed).

use super::{Ctx, S, ScenarioError};
use crate::toml_schema::line_col;
use std::fmt;

/// A deprecated key found in a study scenario: the file still works, the caller should tell the
/// user (the CLI prints `note: [decks] width_m is deprecated: use width (file, line N)`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeprecatedKey {
    /// Section of the key, e.g. `decks`.
    pub section: &'static str,
    /// The deprecated key as written, e.g. `width_m`.
    pub old: &'static str,
    /// The key to use instead, e.g. `width`.
    pub new: &'static str,
    /// Where the file came from (as given to [`super::Scenario::from_toml`]).
    pub origin: String,
    /// 1-based line of the deprecated key.
    pub line: usize,
}

impl fmt::Display for DeprecatedKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "[{}] {} is deprecated: use {} ({}, line {})",
            self.section, self.old, self.new, self.origin, self.line
        )
    }
}

/// `(current, deprecated)` names of the renamed `[decks]` keys, in the order of the file's
/// documentation.
pub const DECK_RENAMES: [(&str, &str); 7] = [
    ("width", "width_m"),
    ("thickness", "thickness_m"),
    ("density", "density_kg_m3"),
    ("R1", "r1_m"),
    ("R2", "r2_m"),
    ("L1", "l1_m"),
    ("L2", "l2_m"),
];

/// The full key (`decks.width` or `decks.width_m`) under which each renamed quantity was given,
/// for error messages that must name the key the user wrote.
pub(super) struct DeckKeys {
    pub width: String,
    pub thickness: String,
    pub density: String,
    pub r1: String,
    pub r2: String,
    pub l1: String,
    pub l2: String,
}

impl Ctx<'_> {
    /// Moves a deprecated value `old` into `new` (noting it) and returns the full key that was
    /// written; both given is an error naming both keys and their lines.
    fn fold<T>(
        &self,
        new: &mut S<T>,
        old: S<T>,
        (new_name, old_name): (&'static str, &'static str),
        notes: &mut Vec<DeprecatedKey>,
    ) -> Result<String, ScenarioError> {
        let Some(old) = old else {
            return Ok(format!("decks.{new_name}"));
        };
        let old_line = line_col(self.text, old.span().start).0;
        if let Some(n) = new {
            let new_line = line_col(self.text, n.span().start).0;
            return Err(ScenarioError::Invalid {
                origin: self.origin.to_string(),
                line: old_line,
                key: format!("decks.{old_name}"),
                value: "(set)".into(),
                reason: format!(
                    "decks.{old_name} (line {old_line}) and decks.{new_name} (line {new_line}) \
                     give the same quantity; keep only decks.{new_name} \
                     ({old_name} is its deprecated name)"
                ),
            });
        }
        notes.push(DeprecatedKey {
            section: "decks",
            old: old_name,
            new: new_name,
            origin: self.origin.to_string(),
            line: old_line,
        });
        *new = Some(old);
        Ok(format!("decks.{old_name}"))
    }
}

/// Folds the deprecated `[decks]` keys into the current ones: returns the keys as written and
/// appends a note for each deprecated key used.
pub(super) fn fold_deprecated(
    cx: &Ctx,
    d: &mut super::RawDecks,
    notes: &mut Vec<DeprecatedKey>,
) -> Result<DeckKeys, ScenarioError> {
    let [w, t, rho, r1, r2, l1, l2] = DECK_RENAMES;
    // In the order of the file's documentation, so that a file with several conflicts reports
    // the first; the notes are then sorted by line (the order the user reads the file in).
    let first = notes.len();
    let keys = DeckKeys {
        width: cx.fold(&mut d.width, d.width_m.take(), w, notes)?,
        thickness: cx.fold(&mut d.thickness, d.thickness_m.take(), t, notes)?,
        density: cx.fold(&mut d.density, d.density_kg_m3.take(), rho, notes)?,
        l1: cx.fold(&mut d.l1, d.l1_m.take(), l1, notes)?,
        l2: cx.fold(&mut d.l2, d.l2_m.take(), l2, notes)?,
        r1: cx.fold(&mut d.r1, d.r1_m.take(), r1, notes)?,
        r2: cx.fold(&mut d.r2, d.r2_m.take(), r2, notes)?,
    };
    notes[first..].sort_by_key(|n| n.line);
    Ok(keys)
}
