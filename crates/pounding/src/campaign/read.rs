//! Reading a store: its row groups in run order ([`for_each_group`]) and the rows of one
//! variant as a fragility study's runs ([`study_rows`], `pounding fragility --from-store`).

use super::CampaignError;
use super::store::{MERGED, Meta, Store};
use super::table::{Columns, Reader};
use std::path::{Path, PathBuf};

/// Reads the runs of a store or a merged file for the fit: `path` is a `runs.parquet`, or a
/// store directory (its `runs.parquet` when merged, else its parts, which must be complete).
/// Calls `each` with every row group in run order.
pub fn for_each_group(
    path: &Path,
    each: &mut dyn FnMut(Columns) -> Result<(), CampaignError>,
) -> Result<Meta, CampaignError> {
    let (dir, files): (PathBuf, Vec<PathBuf>) = if path.is_dir() {
        let merged = path.join(MERGED);
        if merged.exists() {
            (path.to_path_buf(), vec![merged])
        } else {
            let s = Store::existing(path)?;
            let parts = s.stored()?;
            if parts.len() != s.meta.parts {
                return Err(CampaignError::Store(format!(
                    "{}: {} of {} parts stored: the campaign is not complete (resume it, or merge \
                     its shards)",
                    path.display(),
                    parts.len(),
                    s.meta.parts
                )));
            }
            (path.to_path_buf(), parts.into_values().collect())
        }
    } else {
        let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        (dir, vec![path.to_path_buf()])
    };
    let meta = Meta::read(&dir)?;
    for f in files {
        let r = Reader::open(&f)?;
        for g in 0..r.row_groups() {
            each(r.row_group(g, None)?)?;
        }
    }
    Ok(meta)
}

/// The runs of variant `variant` (`None`: the only one) of a stored campaign, as the rows a
/// fragility study of the same scenario (text hash `scenario_fingerprint`), record set and
/// stripes would run ([`crate::assessment::study::Study::run`]): checked run by run against the
/// study's plan (entry, stripe, IM and scale factor to the bit), so that a store of another
/// study is refused, never fitted.
pub fn study_rows(
    path: &Path,
    study: &crate::assessment::study::Study,
    plan: &crate::assessment::run::Plan,
    scenario_fingerprint: u64,
    variant: Option<&str>,
) -> Result<Vec<crate::assessment::run::RunRow>, CampaignError> {
    if !path.exists() {
        return Err(CampaignError::Store(format!(
            "no campaign store at {} (give the --out directory of `pounding campaign run`, or its \
             runs.parquet)",
            path.display()
        )));
    }
    let names: Vec<String> = study.limits.iter().map(|l| l.state.name.clone()).collect();
    let ends = study.setup.problem.model.seat_end_names();
    let (r, s) = (study.set.records.len(), plan.values().len());
    let meta = Meta::read(&if path.is_dir() {
        path.to_path_buf()
    } else {
        path.parent().unwrap_or(Path::new(".")).to_path_buf()
    })?;
    let v = match variant {
        // a campaign without variants: its runs are the scenario's own bridge
        None if meta.variants == [super::spec::BASE_VARIANT] => 0,
        None => {
            return Err(CampaignError::Store(format!(
                "the store holds the campaign's variants ({}), not the scenario's own bridge: give \
                 --campaign SPEC (the spec that made it) and --variant NAME",
                super::from_store::shortened(&meta.variants)
            )));
        }
        Some(name) => meta
            .variants
            .iter()
            .position(|x| x == name)
            .ok_or_else(|| {
                CampaignError::Store(format!(
                    "no variant {name:?} in the store (it has {})",
                    meta.variants.join(", ")
                ))
            })?,
    };
    // the campaign's base scenario, also with variants: its limit states decided the stored
    // verdicts (a variant's runs are fitted through the base's file and --variant)
    if meta.scenario_fingerprint != format!("{scenario_fingerprint:016x}") {
        return Err(CampaignError::Store(format!(
            "{}: its runs are of another scenario text (fingerprint {}, this scenario's {:016x}); \
             give the campaign's own scenario file (with --variant for a variant's runs)",
            path.display(),
            meta.scenario_fingerprint,
            scenario_fingerprint
        )));
    }
    let range = v * r * s..(v + 1) * r * s;
    if meta.runs < range.end {
        return Err(CampaignError::Store(format!(
            "{}: {} runs per variant, this study has {} ({} records × {} stripes)",
            path.display(),
            meta.runs / meta.variants.len().max(1),
            r * s,
            r,
            s
        )));
    }
    let mut rows = Vec::with_capacity(r * s);
    for_each_group(path, &mut |cols| {
        for (i, row) in super::exec::decode_rows(&cols, &names, &ends)? {
            if range.contains(&i) {
                rows.push((i, row));
            }
        }
        Ok(())
    })?;
    if rows.len() != r * s {
        return Err(CampaignError::Store(format!(
            "{}: {} runs of the variant stored, the study has {}",
            path.display(),
            rows.len(),
            r * s
        )));
    }
    rows.into_iter()
        .enumerate()
        .map(|(k, (i, row))| {
            let (a, b) = (k / s, k % s);
            let (im, sf) = plan.point(a, b);
            let same = i == range.start + k
                && row.record == a
                && row.stripe == b
                && row.im_g.to_bits() == im.to_bits()
                && row.scale_factor.to_bits() == sf.to_bits();
            if !same {
                return Err(CampaignError::Store(format!(
                    "{}: run {i} does not match this study's run of record {} at stripe {b} \
                     (scale factor {} stored, {} here): another record set, IM or stripes",
                    path.display(),
                    study.set.records[a].id,
                    crate::output::float_token(row.scale_factor),
                    crate::output::float_token(sf)
                )));
            }
            Ok(row)
        })
        .collect()
}
