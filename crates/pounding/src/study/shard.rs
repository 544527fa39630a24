//! Sharded runs (`--shard K/N`) and their merge (`pounding study merge DIR...`).
//!
//! A shard run writes two texts: a manifest ([`manifest_json`]: format tag, `K`, `N`, the total row
//! count, the row count of this shard, the FNV-1a 64 checksum of the exact bytes of the rows text
//! (`rows_fnv1a64`, [`crate::input::fnv1a64_hex`]) and the scenario text) and the shard's rows
//! ([`shard_rows_csv`]: `row,` + the `bounds.csv` header, then `global_index,` + the row's
//! `bounds.csv` line). [`merge`] checks that the manifest has no duplicate keys, that the rows text
//! matches its checksum (a value edited by hand, or `nan` put in, is refused), that `rows_total`
//! is the scenario's row count and `rows` both the shard's share of it and the number of rows in
//! the file, that the shards come from the same scenario, that every `K = 1..N` is present exactly
//! once and that every row is present exactly once, and returns the rows in global order — parsing
//! is exact (shortest round-trip floats), so the merged outputs equal an unsharded run's byte for
//! byte.

use super::StudyError;
use super::csv::{RowWriter, bounds_header, parse_bounds_line};
use super::run::{Layout, Row, Shard};
use super::scenario::Scenario;
use crate::input::{check_json_duplicate_keys, fnv1a64_hex};
use serde_json::{Value, json};

/// Format tag of shard manifests.
pub const SHARD_FORMAT: &str = "pounding-study-shard 1";

/// The manifest of shard `shard` of the study described by `scenario_text`, whose rows text
/// ([`shard_rows_csv`]) is `rows_csv` and holds `rows` rows of the study's `rows_total`.
pub fn manifest_json(
    shard: Shard,
    scenario_text: &str,
    rows_total: usize,
    rows: usize,
    rows_csv: &str,
) -> String {
    let v = json!({
        "format": SHARD_FORMAT,
        "shard": shard.index,
        "of": shard.count,
        "rows_total": rows_total,
        "rows": rows,
        "rows_fnv1a64": fnv1a64_hex(rows_csv.as_bytes()),
        "scenario": scenario_text,
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
    s.push('\n');
    s
}

/// The rows of a shard: header `row,<bounds header>`, then `index,<bounds line>`.
pub fn shard_rows_csv(scenario: &Scenario, rows: &[Row]) -> String {
    let mut s = String::with_capacity(rows.len() * 260 + 300);
    s.push_str("row,");
    s.push_str(&bounds_header(scenario));
    s.push('\n');
    let mut w = RowWriter::new(scenario);
    for r in rows {
        s.push_str(&r.index.to_string());
        s.push(',');
        w.push(&mut s, r);
    }
    s
}

/// One shard's files as read from disk.
#[derive(Debug, Clone)]
pub struct ShardFiles {
    /// Where the shard came from (for error messages), e.g. its directory: errors name
    /// `ORIGIN/shard.json` and `ORIGIN/rows.csv`.
    pub origin: String,
    /// The manifest text.
    pub manifest: String,
    /// The rows text.
    pub rows: String,
}

/// The merged study: the scenario text, the parsed scenario and all rows in global order.
#[derive(Debug, Clone)]
pub struct Merged {
    /// The scenario text shared by all shards.
    pub scenario_text: String,
    /// The parsed scenario.
    pub scenario: Scenario,
    /// Every row, in global order.
    pub rows: Vec<Row>,
}

fn err(origin: &str, msg: impl std::fmt::Display) -> StudyError {
    StudyError::Merge(format!("{origin}: {msg}"))
}

/// Merges shard outputs (in any order) into the rows of the unsharded study.
pub fn merge(parts: &[ShardFiles]) -> Result<Merged, StudyError> {
    if parts.is_empty() {
        return Err(StudyError::Merge("no shard directories given".into()));
    }
    let mut scenario_text: Option<String> = None;
    let mut count: Option<usize> = None;
    let mut seen: Vec<Option<String>> = Vec::new();
    let mut parsed = Vec::with_capacity(parts.len());
    for p in parts {
        let mf = format!("{}/shard.json", p.origin);
        let Manifest {
            shard,
            k,
            n,
            text,
            rows_total,
            rows_declared,
        } = read_manifest(p, &mf)?;
        let text = text.as_str();
        match (&scenario_text, count) {
            (None, None) => {
                scenario_text = Some(text.to_string());
                count = Some(n);
                seen = vec![None; n];
            }
            (Some(t), Some(c)) => {
                if t != text {
                    return Err(scenario_mismatch(&mf, &parts[0].origin, t, text));
                }
                if c != n {
                    return Err(err(&p.origin, format!("shard count {n} differs from {c}")));
                }
            }
            _ => unreachable!("set together"),
        }
        if let Some(prev) = &seen[k - 1] {
            return Err(err(
                &p.origin,
                format!("shard {k}/{n} also given as {prev}"),
            ));
        }
        seen[k - 1] = Some(p.origin.clone());
        parsed.push((shard, p, rows_total, rows_declared));
    }
    if let Some(k) = seen.iter().position(Option::is_none) {
        return Err(StudyError::Merge(format!(
            "shard {}/{} is missing",
            k + 1,
            count.unwrap_or(0)
        )));
    }
    let scenario_text = scenario_text.unwrap_or_default();
    let scenario = Scenario::from_toml(&scenario_text, "scenario stored in the shard manifest")?;
    let layout = Layout::of(&scenario);
    let total = layout.total();
    let mut rows: Vec<Option<Row>> = vec![None; total];
    for (shard, p, rows_total, rows_declared) in parsed {
        fill_rows(&scenario, shard, p, rows_total, rows_declared, &mut rows)?;
    }
    let rows: Vec<Row> = rows
        .into_iter()
        .enumerate()
        .map(|(i, r)| {
            r.ok_or_else(|| StudyError::Merge(format!("row {i} is missing (truncated shard?)")))
        })
        .collect::<Result<_, _>>()?;
    Ok(Merged {
        scenario_text,
        scenario,
        rows,
    })
}

/// What a shard's manifest declares (checked against its `rows.csv`).
struct Manifest {
    shard: Shard,
    /// The shard's number `k` (1-based) and the shard count `n`.
    k: usize,
    n: usize,
    /// The scenario text the shard was computed from.
    text: String,
    rows_total: u64,
    rows_declared: u64,
}

/// Reads the manifest of `p` (named `mf` in messages): JSON without duplicate keys, format
/// [`SHARD_FORMAT`], `shard`/`of`, `scenario`, `rows_total`, `rows`, `rows_fnv1a64`; and checks
/// that `rows.csv` holds the declared number of rows with the declared checksum.
fn read_manifest(p: &ShardFiles, mf: &str) -> Result<Manifest, StudyError> {
    check_json_duplicate_keys(&p.manifest)
        .map_err(|e| err(mf, format!("manifest is not valid JSON: {e}")))?;
    let v: Value = serde_json::from_str(&p.manifest)
        .map_err(|e| err(mf, format!("manifest is not valid JSON: {e}")))?;
    if v["format"] != SHARD_FORMAT {
        return Err(err(
            &p.origin,
            format!("manifest format is not {SHARD_FORMAT:?}"),
        ));
    }
    let k = v["shard"]
        .as_u64()
        .ok_or_else(|| err(&p.origin, "manifest lacks `shard`"))? as usize;
    let n = v["of"]
        .as_u64()
        .ok_or_else(|| err(&p.origin, "manifest lacks `of`"))? as usize;
    let text = v["scenario"]
        .as_str()
        .ok_or_else(|| err(&p.origin, "manifest lacks `scenario`"))?;
    let shard = Shard::new(k, n).map_err(|e| err(&p.origin, e))?;
    let declared = |key: &str| {
        v[key]
            .as_u64()
            .ok_or_else(|| err(mf, format!("manifest lacks `{key}`")))
    };
    let rows_total = declared("rows_total")?;
    let rows_declared = declared("rows")?;
    let sum = v["rows_fnv1a64"].as_str().ok_or_else(|| {
        err(
            mf,
            "manifest lacks `rows_fnv1a64` (the checksum of rows.csv; shards written before \
             it existed must be computed again)",
        )
    })?;
    let lines = p.rows.lines().count().saturating_sub(1) as u64;
    if lines != rows_declared {
        return Err(err(
            &format!("{}/rows.csv", p.origin),
            format!("holds {lines} rows but {mf} declares rows = {rows_declared}"),
        ));
    }
    let actual = fnv1a64_hex(p.rows.as_bytes());
    if actual != sum {
        return Err(err(
            &format!("{}/rows.csv", p.origin),
            format!(
                "checksum {actual} differs from rows_fnv1a64 = {sum} in {mf}: the rows were \
                 edited or corrupted after the shard run; compute the shard again"
            ),
        ));
    }
    Ok(Manifest {
        shard,
        k,
        n,
        text: text.to_string(),
        rows_total,
        rows_declared,
    })
}

/// The error of a shard (manifest `mf`) whose scenario `text` differs from the first shard's `t`
/// (from `first`): the first differing line, both versions.
fn scenario_mismatch(mf: &str, first: &str, t: &str, text: &str) -> StudyError {
    let (line, a, b) = t
        .lines()
        .chain(std::iter::repeat(""))
        .zip(text.lines().chain(std::iter::repeat("")))
        .take(t.lines().count().max(text.lines().count()))
        .enumerate()
        .find(|(_, (a, b))| a != b)
        .map_or((0, "(line endings or final newline)", ""), |(i, (a, b))| {
            (i + 1, a, b)
        });
    err(
        mf,
        format!(
            "its scenario text differs from that of {first} at line {line}: {b:?} vs \
             {a:?} (shards must come from the same scenario file, comments \
             included: merge writes it to scenario.toml)"
        ),
    )
}

/// Checks one shard's counts against the scenario and places its rows (global index order) into
/// `rows`, refusing rows that do not belong to the shard or appear twice.
fn fill_rows(
    scenario: &Scenario,
    shard: Shard,
    p: &ShardFiles,
    rows_total: u64,
    rows_declared: u64,
    rows: &mut [Option<Row>],
) -> Result<(), StudyError> {
    let total = rows.len();
    let mf = format!("{}/shard.json", p.origin);
    if rows_total != total as u64 {
        return Err(err(
            &mf,
            format!("rows_total = {rows_total}, but its scenario has {total} rows"),
        ));
    }
    let share = shard.share(total) as u64;
    if rows_declared != share {
        return Err(err(
            &mf,
            format!(
                "rows = {rows_declared}, but shard {}/{} of {total} rows has {share}",
                shard.index, shard.count
            ),
        ));
    }
    let rf = format!("{}/rows.csv", p.origin);
    let mut lines = p.rows.lines();
    let header = lines.next().unwrap_or("");
    if header.strip_prefix("row,") != Some(bounds_header(scenario).as_str()) {
        return Err(err(&rf, "rows file has the wrong header"));
    }
    for line in lines {
        let (idx, rest) = line
            .split_once(',')
            .ok_or_else(|| err(&rf, "malformed row line"))?;
        let idx: usize = idx
            .parse()
            .map_err(|_| err(&rf, format!("bad row index {idx:?}")))?;
        if idx >= total || !shard.contains(idx) {
            return Err(err(
                &rf,
                format!(
                    "row {idx} does not belong to shard {}/{}",
                    shard.index, shard.count
                ),
            ));
        }
        if rows[idx].is_some() {
            return Err(err(&rf, format!("row {idx} appears twice")));
        }
        rows[idx] = Some(parse_bounds_line(scenario, idx, rest).map_err(|e| err(&rf, e))?);
    }
    Ok(())
}
