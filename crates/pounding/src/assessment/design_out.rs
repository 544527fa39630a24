//! The data files of a design run and how they replace an earlier run's in the same output
//! directory: `variants.csv`, `variants.json`, `search.csv` (with a `[search]`) and each
//! member's own files under `variants/<name>/` ([`Study::data_files`] and
//! [`Study::hazard_files`]). Shared by the CLI and the Python bindings, so both write the same
//! bytes.
//!
//! **No mixed runs.** A `variants/<name>/` folder of an earlier run whose variant this run does
//! not have is removed before the new files are written ([`stale_variant_dirs`],
//! [`remove_stale`]), so the directory never holds the variants of two designs. Only the files
//! a design writes are removed; a folder holding anything else is refused before any run.

use super::design::Design;
use super::design_search::{SearchResult, SearchSpec, search_csv};
use super::design_write::{compare, variants_csv, variants_json};
use super::run::{Plan, RunRow};
use super::study::{Fits, OUTPUTS as MEMBER_OUTPUTS};
use crate::output::{LOCK_FILE, OutputError, is_temporary_name};
use std::path::{Path, PathBuf};

/// The folder of the members' own files in the output directory.
pub const VARIANTS_DIR: &str = "variants";

/// The files a design run writes in the output directory itself (removed before writing, so
/// none of an earlier run's stays beside the new ones); the figures and the report are the
/// CLI's.
pub const OUTPUTS: &[&str] = &[
    "variants.csv",
    "variants.json",
    "design.png",
    "hazard.png",
    "report.html",
    "timing.json",
    "search.csv",
];

/// The data files of a design run.
pub struct DesignFiles {
    /// Files of the output directory itself: `variants.csv`, `variants.json`, and `search.csv`
    /// with a search.
    pub top: Vec<(&'static str, String)>,
    /// Per member (the as-built bridge first) its name and its files in `variants/<name>/`.
    pub members: Vec<(String, Vec<(&'static str, String)>)>,
}

/// The data files of the design's run: `rows` and `fits` per member, and the search's result.
pub fn data_files(
    design: &Design,
    plan: &Plan,
    rows: &[Vec<RunRow>],
    fits: &[Fits],
    search: Option<(&SearchSpec, &SearchResult)>,
) -> DesignFiles {
    let (stat, comps) = compare(design, fits);
    let mut top = vec![
        ("variants.csv", variants_csv(design, fits, stat, &comps)),
        ("variants.json", variants_json(design, fits, stat, &comps)),
    ];
    if let Some((spec, r)) = search {
        top.push(("search.csv", search_csv(spec, r)));
    }
    let members = design
        .members
        .iter()
        .zip(rows.iter().zip(fits))
        .map(|(m, (r, f))| {
            let mut files: Vec<(&'static str, String)> = m.study.data_files(plan, r, f).into();
            files.extend(m.study.hazard_files(f));
            (m.name.clone(), files)
        })
        .collect();
    DesignFiles { top, members }
}

/// The error of runs that failed or are not trustworthy (excluded from the fits), over every
/// member (`None`: every run completed).
pub fn excluded_message(rows: &[Vec<RunRow>]) -> Option<String> {
    let total: usize = rows.iter().map(Vec::len).sum();
    let excluded = rows.iter().flatten().filter(|r| !r.trusted()).count();
    (excluded > 0).then(|| {
        format!(
            "{excluded} of {total} runs failed or are not trustworthy (status in \
             variants/<name>/runs.csv): excluded from the fits"
        )
    })
}

/// The `variants/<name>/` folders in `out` of members this design does not have (an earlier
/// run's), to be removed by [`remove_stale`] once the directory is locked. Refused (before any
/// run) when such a folder holds anything but the files a design writes there: it is not ours
/// to remove.
pub fn stale_variant_dirs(out: &Path, design: &Design) -> Result<Vec<PathBuf>, OutputError> {
    let dir = out.join(VARIANTS_DIR);
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Ok(Vec::new());
    };
    let refuse = |path: PathBuf, why: String| OutputError::Io {
        what: "cannot replace the earlier design outputs in",
        path,
        cause: std::io::Error::other(why),
    };
    let mut stale = Vec::new();
    for e in entries {
        let e = e.map_err(|cause| OutputError::Io {
            what: "cannot read",
            path: dir.clone(),
            cause,
        })?;
        let name = e.file_name().to_string_lossy().into_owned();
        if design.members.iter().any(|m| m.name == name) {
            continue;
        }
        let path = e.path();
        if !e.file_type().is_ok_and(|t| t.is_dir()) {
            return Err(refuse(
                dir.clone(),
                format!(
                    "{name} is not a variant's folder: remove it or choose another output directory"
                ),
            ));
        }
        let inner = std::fs::read_dir(&path).map_err(|cause| OutputError::Io {
            what: "cannot read",
            path: path.clone(),
            cause,
        })?;
        for f in inner.flatten() {
            let n = f.file_name().to_string_lossy().into_owned();
            let ours =
                MEMBER_OUTPUTS.contains(&n.as_str()) || n == LOCK_FILE || is_temporary_name(&n);
            if !(ours && f.file_type().is_ok_and(|t| t.is_file())) {
                return Err(refuse(
                    path.clone(),
                    format!(
                        "the folder of variant {name:?}, not in this design, holds {n}, which \
                         pounding design does not write: remove it or choose another output \
                         directory"
                    ),
                ));
            }
        }
        stale.push(path);
    }
    stale.sort();
    Ok(stale)
}

/// Removes the stale folders of [`stale_variant_dirs`] (each locked while its files are
/// removed; a folder that gained a foreign file since is left, with an error).
pub fn remove_stale(dirs: &[PathBuf]) -> Result<(), OutputError> {
    for d in dirs {
        let lock = crate::output::lock_output_dir(d)?;
        crate::output::remove_previous_outputs(&lock, MEMBER_OUTPUTS)?;
        drop(lock);
        std::fs::remove_dir(d).map_err(|cause| OutputError::Io {
            what: "cannot remove the earlier variant's folder",
            path: d.clone(),
            cause,
        })?;
    }
    Ok(())
}

/// Writes the members' files into `out/variants/<name>/` (each folder locked, its earlier
/// outputs removed first) and the top files into `out` (atomically), after removing `stale`.
/// The caller holds `out`'s lock.
pub fn write(out: &Path, files: &DesignFiles, stale: &[PathBuf]) -> Result<(), OutputError> {
    remove_stale(stale)?;
    for (name, list) in &files.members {
        super::study::write_data_files(&out.join(VARIANTS_DIR).join(name), list)?;
    }
    for (name, text) in &files.top {
        let path = out.join(name);
        crate::output::write_atomic(&path, text.as_bytes()).map_err(|cause| OutputError::Io {
            what: "cannot write",
            path: path.clone(),
            cause,
        })?;
    }
    Ok(())
}

/// [`write`] under `out`'s lock, after removing the earlier run's [`OUTPUTS`] (the data files
/// only: for callers without the figures and report, e.g. the Python bindings).
pub fn write_locked(out: &Path, files: &DesignFiles, stale: &[PathBuf]) -> Result<(), OutputError> {
    let lock = crate::output::lock_output_dir(out)?;
    crate::output::remove_previous_outputs(&lock, OUTPUTS)?;
    write(out, files, stale)?;
    drop(lock);
    Ok(())
}
