//! Support-motion entries of a record-set manifest (`supports = "FILE"`) checked against the
//! scenario of a batch before any run, with errors that name the manifest, the entry, the line
//! of its `supports` key and the scenario (`pounding simulate --set`, Python `batch(record_set=)`).

use super::batch::{BatchRecord, check_support_entries};
use super::{Problem, SimError};
use std::path::Path;

/// [`check_support_entries`] of the entries read from the manifest `manifest`; `scenario` names
/// the scenario in the message (`a two-deck scenario`, `f.toml`). The error names the manifest,
/// the entry's id and `record[i].supports (FILE:LINE)`.
pub fn check_set_supports<P: Problem>(
    base: &P,
    records: &[BatchRecord],
    manifest: &Path,
    scenario: &str,
) -> Result<(), SimError> {
    let Err(e) = check_support_entries(base, records) else {
        return Ok(());
    };
    let text = e.to_string();
    let named = |r: &BatchRecord| text.contains(&format!("record {:?}", r.name));
    let with_supports = |r: &BatchRecord| !r.supports.is_empty();
    let Some(i) = records
        .iter()
        .position(|r| with_supports(r) && named(r))
        .or_else(|| records.iter().position(with_supports))
    else {
        return Err(e);
    };
    Err(SimError::argument(
        format!("record set {}", manifest.display()),
        format!(
            "entry {:?} ({}) cannot run on {scenario}: {text}",
            records[i].name,
            supports_at(manifest, i)
        ),
    ))
}

/// `` `record[i].supports` (FILE:LINE) `` of a TOML manifest (the key in its `i`-th `[[record]]`
/// table), else `` `supports` of entry i+1 in FILE `` (a CSV manifest, or a key not found).
pub fn supports_at(manifest: &Path, i: usize) -> String {
    let text = std::fs::read_to_string(manifest).unwrap_or_default();
    let squash = |l: &str| -> String {
        let l = l.split('#').next().unwrap_or_default();
        l.chars().filter(|c| !c.is_whitespace()).collect()
    };
    // the number of `[[record]]` headers so far, and whether the current table is one
    let (mut seen, mut in_entry) = (0usize, false);
    for (n, line) in text.lines().enumerate() {
        let l = squash(line);
        if l == "[[record]]" {
            seen += 1;
            in_entry = true;
        } else if l.starts_with('[') {
            in_entry = false; // a `[set]` or `[synth]` table: its keys are not an entry's
        } else if in_entry && seen == i + 1 && l.starts_with("supports=") {
            return format!("`record[{i}].supports` ({}:{})", manifest.display(), n + 1);
        }
    }
    format!("`supports` of entry {} in {}", i + 1, manifest.display())
}
