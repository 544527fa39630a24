//! The variants of a campaign: `[[variant]]` tables (named sets of overrides of the scenario's
//! keys, [`crate::assessment::variant`]) and a `[grid]` of values per key; with both, every
//! listed variant at every grid point. Each variant's scenario is the base scenario's text with
//! its overrides applied, read and built by the scenario's own strict reading (an error names
//! the spec, the variant, the key and its line).
//!
//! ```toml
//! [[variant]]
//! name = "retrofit"
//! [variant.set]
//! "bridge.seat_length" = 0.6
//!
//! [grid]                              # quoted key paths, each a list of values
//! "bridge.restrainer_k" = [2.5e7, 5e7, 1e8]
//! "bridge.gap" = [0.02, 0.05]
//! ```
//!
//! Grid points run in the file's order of the keys, the last key fastest; a grid point's name is
//! `key=value,key=value` (a listed variant's name and the grid point's joined by `+`). The IM and
//! the stripes are the base scenario's (a variant's own period does not move the stripes), so
//! every variant runs at the same scale factors; the limit states are the base's, bound to each
//! variant's bridge. Overrides of `fragility` or `limit_state` keys are refused: a variant
//! changes the bridge, not the study.

use super::{CampaignError, Fnv};
use crate::assessment::limit::{BoundLimit, bind};
use crate::assessment::study::Study;
use crate::assessment::variant::{Override, Variant, Variants, parse_path};
use crate::output::float_token;
use crate::sim::scenario::{BridgeSetup, Scenario};
use crate::toml_schema::{key_span, line_col};
use rayon::prelude::*;
use std::path::Path;

/// Largest number of variants of one campaign.
pub const MAX_VARIANTS: usize = 100_000;
/// The name of the one variant of a campaign without variants.
pub const BASE_VARIANT: &str = "base";

/// One variant, ready to run.
pub struct VariantRun {
    /// Its name (`base` without variants).
    pub name: String,
    /// Its bridge, ground motion and settings.
    pub setup: BridgeSetup,
    /// The limit states bound to its bridge.
    pub limits: Vec<BoundLimit>,
    /// The hash of its scenario text.
    pub fingerprint: u64,
}

fn key_err(origin: &str, text: &str, at: usize, key: &str, message: String) -> CampaignError {
    CampaignError::Key {
        message,
        key: key.to_string(),
        origin: origin.to_string(),
        line: Some(line_col(text, at).0),
    }
}

/// A value as written in a grid point's name.
fn value_label(v: &toml::Value) -> String {
    match v {
        toml::Value::Float(x) => float_token(*x),
        toml::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// The grid's points as variants (empty without a `[grid]`).
fn grid(spec: &str, origin: &str) -> Result<Vec<Variant>, CampaignError> {
    #[derive(serde::Deserialize)]
    struct G {
        grid: Option<toml::Spanned<toml::Table>>,
    }
    let g: G = toml::from_str(spec).map_err(|e| CampaignError::Syntax {
        origin: origin.to_string(),
        message: crate::input::shorten_lines(&e.to_string(), 200),
    })?;
    let Some(t) = g.grid else {
        return Ok(Vec::new());
    };
    if t.get_ref().is_empty() {
        return Err(key_err(
            origin,
            spec,
            t.span().start,
            "grid",
            "an empty [grid]: give a quoted key path and its values (\"bridge.gap\" = [0.02, 0.05]), \
             or remove the table"
                .into(),
        ));
    }
    // the keys in the file's order (the table is sorted): by the position of their line
    let mut axes: Vec<(usize, String, Vec<toml::Value>)> = Vec::new();
    for (k, v) in t.get_ref() {
        // the key's own place (a comment or a value that mentions it does not count)
        let at = key_span(spec, &["grid", k]).map_or(t.span().start, |s| s.start);
        let key = format!("grid.\"{k}\"");
        let toml::Value::Array(vals) = v else {
            return Err(key_err(
                origin,
                spec,
                at,
                &key,
                "give a list of values, and write the key path quoted (\"bridge.gap\" = [0.02, \
                 0.05])"
                    .into(),
            ));
        };
        if vals.is_empty() {
            return Err(key_err(
                origin,
                spec,
                at,
                &key,
                "give at least one value".into(),
            ));
        }
        parse_path(k).map_err(|m| key_err(origin, spec, at, &key, m.to_string()))?;
        // two equal values would be two variants of one name (and the same runs twice)
        let labels: Vec<String> = vals.iter().map(value_label).collect();
        if let Some((i, l)) = labels
            .iter()
            .enumerate()
            .find(|(i, l)| labels[..*i].contains(l))
        {
            return Err(key_err(
                origin,
                spec,
                at,
                &key,
                format!(
                    "the value {l} is listed twice (values {} and {})",
                    labels[..i].iter().position(|x| x == l).map_or(0, |j| j + 1),
                    i + 1
                ),
            ));
        }
        axes.push((at, k.clone(), vals.clone()));
    }
    axes.sort_by_key(|a| a.0);
    let points: usize = axes.iter().map(|a| a.2.len()).product();
    if points > MAX_VARIANTS {
        return Err(key_err(
            origin,
            spec,
            t.span().start,
            "grid",
            format!("{points} grid points, more than {MAX_VARIANTS}"),
        ));
    }
    Ok((0..points)
        .map(|mut i| {
            let mut pick = vec![0; axes.len()];
            for (j, a) in axes.iter().enumerate().rev() {
                pick[j] = i % a.2.len();
                i /= a.2.len();
            }
            let overrides: Vec<Override> = axes
                .iter()
                .zip(&pick)
                .map(|((at, k, vals), &p)| Override {
                    key: k.clone(),
                    path: parse_path(k).unwrap_or_default(),
                    value: vals[p].clone(),
                    line: line_col(spec, *at).0,
                })
                .collect();
            let name = overrides
                .iter()
                .map(|o| format!("{}={}", o.key, value_label(&o.value)))
                .collect::<Vec<_>>()
                .join(",");
            Variant {
                name,
                description: String::new(),
                line: overrides.first().map_or(0, |o| o.line),
                overrides,
            }
        })
        .collect())
}

/// The variants of the spec `spec` (named `origin`) over the base `scenario` at `path`, whose
/// study is `base`: one `base` variant when the spec has neither `[[variant]]` nor `[grid]`.
/// The variants are built in parallel on the current rayon pool, `progress(built, total)` after
/// each; the first failing variant in the spec's order is the error, whatever the threads.
pub fn variants(
    spec: &str,
    origin: &str,
    path: &Path,
    scenario: &Scenario,
    base: &Study,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<Vec<VariantRun>, CampaignError> {
    let has_list = toml::from_str::<toml::Table>(spec).is_ok_and(|t| t.contains_key("variant"));
    let list = if has_list {
        Variants::parse(spec, origin)?.list
    } else {
        Vec::new()
    };
    let grid = grid(spec, origin)?;
    let base_text = scenario.text();
    let sc_origin = scenario.origin().to_string();
    if list.is_empty() && grid.is_empty() {
        let mut h = Fnv::default();
        h.text(base_text);
        return Ok(vec![VariantRun {
            name: BASE_VARIANT.into(),
            setup: base.setup.clone(),
            limits: base.limits.clone(),
            fingerprint: h.0,
        }]);
    }
    let combos: Vec<Variant> = match (list.is_empty(), grid.is_empty()) {
        (false, true) => list,
        (true, false) => grid,
        _ => list
            .iter()
            .flat_map(|l| {
                grid.iter().map(move |g| Variant {
                    name: format!("{}+{}", l.name, g.name),
                    description: l.description.clone(),
                    line: l.line,
                    overrides: l.overrides.iter().chain(&g.overrides).cloned().collect(),
                })
            })
            .collect(),
    };
    if let Some(v) = combos.iter().find(|v| v.name == BASE_VARIANT) {
        return Err(CampaignError::Key {
            message: format!(
                "the name {:?} is reserved for the runs of a campaign without variants (a store \
                 of them is read as the scenario's own bridge): name the variant otherwise",
                v.name
            ),
            key: "variant.name".into(),
            origin: origin.to_string(),
            line: Some(v.line),
        });
    }
    if combos.len() > MAX_VARIANTS {
        return Err(CampaignError::Store(format!(
            "{origin}: {} variants, more than {MAX_VARIANTS}",
            combos.len()
        )));
    }
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let ends = base.setup.problem.model.seat_end_names();
    let read = |t: &str| -> Result<BridgeSetup, CampaignError> {
        let sc = Scenario::from_toml(t, &sc_origin)?
            .with_base_dir(dir.clone())
            .for_batch();
        crate::assessment::check_tables(&sc, None)?;
        Ok(sc.build_bridge()?)
    };
    let built = std::sync::atomic::AtomicUsize::new(0);
    let total = combos.len();
    let runs: Vec<Result<VariantRun, CampaignError>> = combos
        .par_iter()
        .map(|v| {
            if let Some(o) = v.overrides.iter().find(|o| {
                matches!(o.path.first(), Some(crate::assessment::variant::Step::Key(k))
                    if crate::assessment::design::STUDY_TABLES.contains(&k.as_str()))
            }) {
                return Err(CampaignError::Key {
                    message: format!(
                        "variant {:?}: a variant changes the bridge, not the study (its ground \
                         motions, IM, stripes, time step and limit states are the campaign's: \
                         [{}] cannot be overridden)",
                        v.name,
                        o.key.split(['.', '[']).next().unwrap_or_default()
                    ),
                    key: o.key.clone(),
                    origin: origin.to_string(),
                    line: Some(o.line),
                });
            }
            // the first check reads the whole variant: keep its setup (read once, not twice)
            let first = std::sync::Mutex::new(None);
            let applied = v.apply_checked(base_text, &sc_origin, origin, |t| {
                read(t).map(|s| {
                    let mut f = first.lock().unwrap_or_else(|e| e.into_inner());
                    f.get_or_insert(s);
                })
            })?;
            let setup = match first.into_inner().unwrap_or_else(|e| e.into_inner()) {
                Some(s) => s,
                None => read(&applied.text)?,
            };
            let limits = bind(
                &base.settings.limit_states,
                &setup.problem.model,
                &sc_origin,
            )?;
            if setup.problem.model.seat_end_names() != ends {
                return Err(CampaignError::Key {
                    message: format!(
                        "variant {:?} has other seated ends than the base bridge (segments \
                         added or removed): every variant must store the same columns",
                        v.name
                    ),
                    key: "variant".into(),
                    origin: origin.to_string(),
                    line: Some(v.line),
                });
            }
            let mut h = Fnv::default();
            h.text(&applied.text);
            progress(
                built.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1,
                total,
            );
            Ok(VariantRun {
                name: v.name.clone(),
                setup,
                limits,
                fingerprint: h.0,
            })
        })
        .collect();
    runs.into_iter().collect()
}
