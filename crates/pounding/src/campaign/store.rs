//! The campaign store: a directory with `campaign.json` (what the store holds: the campaign's
//! fingerprint, run and part counts, columns) and `parts/part-NNNNNN.parquet`, one Parquet file
//! per finished part, written to a temporary name and renamed (a killed run leaves whole parts
//! and temporaries, never a torn part). A store resumes: the parts present are not run again.
//! [`merge`] streams the parts of one or more stores (shards) into one `runs.parquet` sorted by
//! run, part by part (memory: one row group), refusing a missing or conflicting part.

use super::table::{self, Columns, Reader, Values};
use super::{Campaign, CampaignError};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The store's description file.
pub const META: &str = "campaign.json";
/// The merged file.
pub const MERGED: &str = "runs.parquet";
/// The parts' directory.
pub const PARTS: &str = "parts";
/// Rows per row group of the merged file (whole parts are gathered up to this).
pub const ROW_GROUP_ROWS: usize = 65_536;
const FORMAT: &str = "pounding campaign store 1";

/// `campaign.json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Meta {
    /// `FORMAT`.
    pub format: String,
    /// The campaign's name.
    pub name: String,
    /// The hash of everything the results depend on (hex).
    pub fingerprint: String,
    /// The hash of the scenario's text (hex).
    pub scenario_fingerprint: String,
    /// The number of runs.
    pub runs: usize,
    /// Runs per part.
    pub runs_per_part: usize,
    /// The number of parts.
    pub parts: usize,
    /// The stored columns.
    pub columns: Vec<String>,
    /// The variants' names.
    pub variants: Vec<String>,
}

impl Meta {
    /// The description of `c`'s store.
    pub fn of(c: &Campaign) -> Meta {
        Meta {
            format: FORMAT.into(),
            name: c.name.clone(),
            fingerprint: format!("{:016x}", c.fingerprint),
            scenario_fingerprint: format!("{:016x}", c.scenario_fingerprint),
            runs: c.runs(),
            runs_per_part: c.runs_per_part,
            parts: c.parts(),
            columns: c.column_names(),
            variants: c.variants.clone(),
        }
    }

    /// Reads `DIR/campaign.json`.
    pub fn read(dir: &Path) -> Result<Meta, CampaignError> {
        let path = dir.join(META);
        let text = std::fs::read_to_string(&path).map_err(|cause| CampaignError::Io {
            what: "cannot read the store's description",
            path: path.clone(),
            cause,
        })?;
        let m: Meta = serde_json::from_str(&text).map_err(|e| {
            CampaignError::Store(format!(
                "{}: not a campaign description: {e}",
                path.display()
            ))
        })?;
        if m.format != FORMAT {
            return Err(CampaignError::Store(format!(
                "{}: format {:?}, expected {FORMAT:?}",
                path.display(),
                m.format
            )));
        }
        Ok(m)
    }

    /// The runs of part `p`.
    pub fn part_range(&self, p: usize) -> std::ops::Range<usize> {
        let b = self.runs_per_part;
        (p * b).min(self.runs)..((p + 1) * b).min(self.runs)
    }

    pub(super) fn text(&self) -> String {
        // a struct of strings and numbers always serialises
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }
}

/// The file name of part `p`.
pub fn part_name(p: usize) -> String {
    format!("part-{p:06}.parquet")
}

fn part_index(name: &str) -> Option<usize> {
    name.strip_prefix("part-")?
        .strip_suffix(".parquet")?
        .parse()
        .ok()
}

pub(super) fn io(what: &'static str, path: &Path) -> impl FnOnce(std::io::Error) -> CampaignError {
    let path = path.to_path_buf();
    move |cause| CampaignError::Io { what, path, cause }
}

/// An opened store of one campaign.
pub struct Store {
    /// Its directory.
    pub dir: PathBuf,
    /// Its description.
    pub meta: Meta,
}

impl Store {
    /// Opens (or creates) the store of `c` in `dir`: writes `campaign.json`, or checks that the
    /// one there describes this campaign (else an error: another campaign's results must not be
    /// mixed in); removes the temporaries of an interrupted run.
    pub fn open(dir: &Path, c: &Campaign) -> Result<Store, CampaignError> {
        let meta = Meta::of(c);
        let parts = dir.join(PARTS);
        std::fs::create_dir_all(&parts).map_err(io("cannot create", &parts))?;
        if !dir.join(META).exists()
            && std::fs::read_dir(&parts).is_ok_and(|mut d| d.next().is_some())
        {
            // parts without their description: whose runs they hold cannot be checked
            return Err(CampaignError::Store(format!(
                "{} has part files but no {META}: which campaign they belong to cannot be \
                 checked; give another --out, or remove {} to start again",
                dir.display(),
                parts.display()
            )));
        }
        if dir.join(META).exists() {
            let old = Meta::read(dir)?;
            if old != meta {
                return Err(CampaignError::Store(format!(
                    "{} holds another campaign ({} runs, fingerprint {}; this one: {} runs, \
                     fingerprint {}): the spec, scenario, records or stripes changed; give \
                     another --out, or remove it to start again",
                    dir.display(),
                    old.runs,
                    old.fingerprint,
                    meta.runs,
                    meta.fingerprint
                )));
            }
        } else {
            let path = dir.join(META);
            crate::output::write_atomic(&path, meta.text().as_bytes())
                .map_err(io("cannot write", &path))?;
        }
        for e in std::fs::read_dir(&parts).map_err(io("cannot list", &parts))? {
            let e = e.map_err(io("cannot list", &parts))?;
            let name = e.file_name().to_string_lossy().into_owned();
            if name.starts_with(".part-") && name.ends_with(".tmp") {
                std::fs::remove_file(e.path()).map_err(io("cannot remove", &e.path()))?;
            }
        }
        Ok(Store {
            dir: dir.to_path_buf(),
            meta,
        })
    }

    /// The existing store of `c` in `dir`, as a worker of a distributed run joins it: its
    /// `campaign.json` must describe `c`; nothing is removed (other workers may be writing).
    pub fn attach(dir: &Path, c: &Campaign) -> Result<Store, CampaignError> {
        let s = Store::existing(dir)?;
        if s.meta != Meta::of(c) {
            return Err(CampaignError::Store(format!(
                "{} holds another campaign (fingerprint {}, this one {:016x}): every worker must \
                 read the same spec, scenario and records",
                dir.display(),
                s.meta.fingerprint,
                c.fingerprint
            )));
        }
        Ok(s)
    }

    /// An existing store (`campaign.json` read, nothing changed).
    pub fn existing(dir: &Path) -> Result<Store, CampaignError> {
        Ok(Store {
            dir: dir.to_path_buf(),
            meta: Meta::read(dir)?,
        })
    }

    /// The path of part `p`.
    pub fn part_path(&self, p: usize) -> PathBuf {
        self.dir.join(PARTS).join(part_name(p))
    }

    /// The parts stored, each checked: a readable Parquet file holding exactly its runs.
    pub fn stored(&self) -> Result<BTreeMap<usize, PathBuf>, CampaignError> {
        let parts = self.dir.join(PARTS);
        let mut out = BTreeMap::new();
        let list = match std::fs::read_dir(&parts) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(out),
            r => r.map_err(io("cannot list", &parts))?,
        };
        for e in list {
            let e = e.map_err(io("cannot list", &parts))?;
            let name = e.file_name().to_string_lossy().into_owned();
            let Some(p) = part_index(&name) else { continue };
            if p >= self.meta.parts {
                return Err(CampaignError::Store(format!(
                    "{}: part {p} of a campaign of {} parts",
                    e.path().display(),
                    self.meta.parts
                )));
            }
            self.check_part(p, &e.path())?;
            out.insert(p, e.path());
        }
        Ok(out)
    }

    /// Checks that the file of part `p` holds exactly that part's runs in order.
    fn check_part(&self, p: usize, path: &Path) -> Result<(), CampaignError> {
        let r = Reader::open(path)?;
        let want = self.meta.part_range(p);
        let mut got = Vec::with_capacity(want.len());
        for g in 0..r.row_groups() {
            if let Some(Values::Int(v)) = r.row_group(g, Some(&["run"]))?.get("run") {
                got.extend(v.iter().map(|x| x.unwrap_or(-1)));
            }
        }
        let ok =
            got.len() == want.len() && got.iter().zip(want.clone()).all(|(a, b)| *a == b as i64);
        if !ok || r.names() != self.meta.columns {
            return Err(CampaignError::Store(format!(
                "{}: does not hold runs {}..{} of this campaign with its columns; remove the \
                 file to run that part again",
                path.display(),
                want.start,
                want.end
            )));
        }
        Ok(())
    }

    /// How many runs of the stored parts `parts` have each status (the `status` column).
    pub fn part_statuses(&self, parts: &[usize]) -> Result<BTreeMap<String, usize>, CampaignError> {
        let mut out = BTreeMap::new();
        for &p in parts {
            let path = self.part_path(p);
            let r = Reader::open(&path)?;
            for g in 0..r.row_groups() {
                if let Some(Values::Text(v)) = r.row_group(g, Some(&["status"]))?.get("status") {
                    for x in v {
                        *out.entry(x.clone().unwrap_or_default()).or_insert(0) += 1;
                    }
                }
            }
        }
        Ok(out)
    }

    /// Writes part `p` (its Parquet bytes, atomically).
    pub fn write_part(&self, p: usize, cols: &Columns) -> Result<(), CampaignError> {
        let bytes = table::to_bytes(cols)?;
        let path = self.part_path(p);
        crate::output::write_atomic(&path, &bytes).map_err(io("cannot write", &path))
    }
}

pub use super::store_merge::{Merged, merge};
