//! The record files of `pounding simulate --record` / `--records`: the flags' checks (a scenario
//! file given among the records, `--csv-units` / `--record-dt` without a record, `--record-dt`
//! with a `--set` manifest), the expansion
//! of `--records` directories (every skipped file listed with the reason) and the printed line
//! per ground-motion component.

use super::Args;
use anyhow::{Result, bail};
use pounding::ground_motion::{ComponentInfo, GroundMotion};
use std::path::{Path, PathBuf};

/// Extensions (any case) of the files a `--records` directory contributes.
const RECORD_EXTENSIONS: &[&str] = &["at2", "csv", "txt", "dat"];

/// Refuses flags that would be misread: a `.toml` among `--records` (the scenario written after
/// the list), `--csv-units` / `--record-dt` without `--record` or `--records`.
pub(crate) fn check_flags(args: &Args) -> Result<()> {
    if let Some(t) = args.record.as_ref().filter(|p| has_ext(p, "toml")) {
        bail!(
            "--record: {} is a scenario file (.toml), not a record: give the scenario first \
             (pounding simulate {} --record RECORD)",
            t.display(),
            t.display()
        );
    }
    if let Some(t) = args.records.iter().find(|p| has_ext(p, "toml")) {
        bail!(
            "--records: {} is a scenario file (.toml), not a record: put the scenario before \
             the flags (pounding simulate {} --records ...) or --records last (a record-set \
             manifest is given with --set MANIFEST)",
            t.display(),
            t.display()
        );
    }
    if let (Some(m), Some(_)) = (&args.set, args.record_dt) {
        bail!(
            "--record-dt applies to the files of --record or --records; with --set, the \
             one-column records of the manifest {} give their sample interval in their entry \
             (dt = SECONDS)",
            m.display()
        );
    }
    let files = args.record.is_some() || super::is_batch(args);
    for (flag, given, key) in [
        ("--csv-units", args.csv_units.is_some(), "csv_units"),
        ("--record-dt", args.record_dt.is_some(), "record_dt"),
    ] {
        if given && !files {
            bail!(
                "{flag} applies to the files of --record or --records; for the scenario's own \
                 records set [ground_motion] {key} in the scenario"
            );
        }
    }
    Ok(())
}

fn has_ext(p: &Path, ext: &str) -> bool {
    p.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// Why the directory entry `f` is not taken as a record, or `None` if it is one.
fn skip_reason(f: &Path) -> Option<String> {
    let name = f.file_name().map(|n| n.to_string_lossy().into_owned());
    if name.as_deref().is_some_and(|n| n.starts_with('.')) {
        return Some("hidden file".into());
    }
    if f.is_dir() {
        return Some("a directory (not searched)".into());
    }
    if !f.is_file() {
        return Some("not a regular file".into());
    }
    if has_ext(f, "toml") {
        return Some("a scenario file (.toml), not a record".into());
    }
    if has_ext(f, "vt2") || has_ext(f, "dt2") {
        return Some(
            "a PEER velocity / displacement series (.VT2/.DT2), not an acceleration".into(),
        );
    }
    if RECORD_EXTENSIONS.iter().any(|e| has_ext(f, e)) {
        return None;
    }
    Some("not a record extension (.AT2, .csv, .txt, .dat)".into())
}

/// The record files of `--records`: files as given, directories expanded to their `.AT2` /
/// `.csv` / `.txt` / `.dat` files (any case) sorted by file name; every other entry is listed on
/// stderr with the reason it is skipped, and a directory without a record is an error. A file
/// given twice (or a directory listed twice) is run twice, with a note on stderr.
pub(crate) fn expand_records(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let out = expand_paths(paths)?;
    note_repeats(&out);
    Ok(out)
}

/// A note on stderr for every record that `paths` name more than once (compared after
/// resolving `.`/`..` and links when the file exists, else as written).
fn note_repeats(paths: &[PathBuf]) {
    let key = |p: &PathBuf| std::fs::canonicalize(p).unwrap_or_else(|_| p.clone());
    let keys: Vec<PathBuf> = paths.iter().map(key).collect();
    for (i, k) in keys.iter().enumerate() {
        let n = keys.iter().filter(|o| *o == k).count();
        if n > 1 && !keys[..i].contains(k) {
            eprintln!(
                "note: --records: {} is given {n} times; it is run {n} times (its rows repeat)",
                paths[i].display()
            );
        }
    }
}

/// `paths` with directories expanded ([`expand_records`]).
fn expand_paths(paths: &[PathBuf]) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for p in paths {
        if !p.is_dir() {
            out.push(p.clone());
            continue;
        }
        let mut entries: Vec<PathBuf> = std::fs::read_dir(p)
            .map_err(|e| anyhow::anyhow!("--records: cannot list directory {}: {e}", p.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        entries.sort();
        let mut files = Vec::new();
        for f in entries {
            match skip_reason(&f) {
                None => files.push(f),
                Some(why) => eprintln!("--records: skipped {}: {why}", f.display()),
            }
        }
        if files.is_empty() {
            bail!(
                "--records: directory {} contains no .AT2 or .csv record (nor .txt, .dat)",
                p.display()
            );
        }
        out.extend(files);
    }
    Ok(out)
}

/// Prints one line per ground-motion component: the record, its units as read, dt, samples,
/// duration and PGA (before the scale factor), and the library's warning for an implausible PGA
/// ([`ComponentInfo::units_warning`]; units probably wrong, not an error).
pub(crate) fn print_components(g: &GroundMotion) {
    for c in g.components() {
        print_component(&c);
    }
}

/// Prints the line of one component ([`ComponentInfo::line`]) and its PGA warning if due.
pub(crate) fn print_component(c: &ComponentInfo) {
    eprintln!("{}", c.line());
    if let Some(w) = c.units_warning() {
        eprintln!("warning: {w}");
    }
}

/// `n word` with the plural `s` when `n != 1` (`1 thread`, `2 threads`).
pub(crate) fn count(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}
