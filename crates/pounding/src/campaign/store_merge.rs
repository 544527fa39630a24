//! The merge of stores into one canonical `runs.parquet` (`pounding campaign merge`; the end of
//! every complete `campaign run`), streamed part by part.

use super::CampaignError;
use super::store::{MERGED, META, Meta, ROW_GROUP_ROWS, Store, io, part_name};
use super::table::{self, Columns, Reader, Values};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// What a merge wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Merged {
    /// The merged file.
    pub path: PathBuf,
    /// Its rows.
    pub rows: usize,
    /// How many runs have each status.
    pub statuses: BTreeMap<String, usize>,
}

/// Merges the parts in the stores `dirs` (one campaign: the same `campaign.json`) into
/// `out/runs.parquet` (and `out/campaign.json`), streaming part by part in run order. Refused:
/// stores of different campaigns, a part missing from every store (the count and the first
/// missing parts are named), and a part present in two stores with different bytes.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<Merged, CampaignError> {
    let Some(first) = dirs.first() else {
        return Err(CampaignError::Store("no store to merge".into()));
    };
    let meta = Meta::read(first)?;
    let mut found: BTreeMap<usize, PathBuf> = BTreeMap::new();
    for d in dirs {
        let s = Store::existing(d)?;
        if s.meta != meta {
            return Err(CampaignError::Store(format!(
                "{} and {} hold different campaigns (fingerprints {} and {})",
                first.display(),
                d.display(),
                meta.fingerprint,
                s.meta.fingerprint
            )));
        }
        for (p, path) in s.stored()? {
            if let Some(other) = found.get(&p) {
                let same = std::fs::read(other).map_err(io("cannot read", other))?
                    == std::fs::read(&path).map_err(io("cannot read", &path))?;
                if !same {
                    return Err(CampaignError::Store(format!(
                        "part {p} is in {} and {} with different contents",
                        other.display(),
                        path.display()
                    )));
                }
                continue;
            }
            found.insert(p, path);
        }
    }
    let missing: Vec<usize> = (0..meta.parts).filter(|p| !found.contains_key(p)).collect();
    if !missing.is_empty() {
        let first: Vec<String> = missing.iter().take(5).map(|p| part_name(*p)).collect();
        return Err(CampaignError::Store(format!(
            "{} of {} parts are missing (first: {}); run the missing shards or resume the \
             campaign first",
            missing.len(),
            meta.parts,
            first.join(", ")
        )));
    }
    // `out` may be one of the stores merged, or a new directory; never another campaign's store
    if out.join(META).exists() {
        let there = Meta::read(out)?;
        if there != meta {
            return Err(CampaignError::Store(format!(
                "{} holds another campaign (fingerprint {}; the stores merged: {}): give another \
                 --out",
                out.display(),
                there.fingerprint,
                meta.fingerprint
            )));
        }
    }
    std::fs::create_dir_all(out).map_err(io("cannot create", out))?;
    let path = out.join(MERGED);
    let tmp = crate::output::TempFile::new(&path).map_err(io("cannot write", &path))?;
    let file = std::fs::File::create(tmp.path()).map_err(io("cannot create", tmp.path()))?;
    let mut statuses = BTreeMap::new();
    let mut w: Option<table::Writer<std::io::BufWriter<std::fs::File>>> = None;
    let mut file = Some(file);
    let mut pending = Columns::default();
    let mut rows = 0;
    let mut flush = |w: &mut Option<table::Writer<_>>, cols: &mut Columns| {
        if cols.rows() == 0 {
            return Ok::<(), CampaignError>(());
        }
        if w.is_none() {
            let f = file
                .take()
                .ok_or_else(|| CampaignError::Store("writer".into()))?;
            *w = Some(table::Writer::new(
                std::io::BufWriter::new(f),
                cols.schema()?,
            )?);
        }
        if let Some(w) = w.as_mut() {
            w.write(cols)?;
        }
        *cols = Columns::default();
        Ok(())
    };
    for path in found.values() {
        let r = Reader::open(path)?;
        for g in 0..r.row_groups() {
            let cols = r.row_group(g, None)?;
            if let Some(Values::Text(s)) = cols.get("status") {
                for x in s {
                    *statuses.entry(x.clone().unwrap_or_default()).or_insert(0) += 1;
                }
            }
            rows += cols.rows();
            pending.append(cols)?;
        }
        if pending.rows() >= ROW_GROUP_ROWS {
            flush(&mut w, &mut pending)?;
        }
    }
    flush(&mut w, &mut pending)?;
    let Some(w) = w else {
        return Err(CampaignError::Store("no rows to merge".into()));
    };
    let f = w
        .finish()?
        .into_inner()
        .map_err(|e| CampaignError::Store(format!("{}: {e}", path.display())))?;
    f.sync_all().map_err(io("cannot write", &path))?;
    drop(f);
    tmp.commit().map_err(io("cannot write", &path))?;
    let mp = out.join(META);
    crate::output::write_atomic(&mp, meta.text().as_bytes()).map_err(io("cannot write", &mp))?;
    Ok(Merged {
        path,
        rows,
        statuses,
    })
}
