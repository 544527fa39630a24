//! Running the parts of a campaign and the stored row of a run: its columns
//! ([`Campaign::column_names`]), from and to [`RunRow`]s.

use super::table::{Columns, Values};
use super::{Campaign, CampaignError, RunSpec};
use crate::assessment::run::{RunRow, run_one, seat_ratio_column, summary_settings};
use rayon::prelude::*;

impl Campaign {
    /// The stored columns, in order: `run` (the global index), `id`, `variant`, `record`,
    /// `entry`, `stripe` (indices), `level_g` or `scale` (the stripe's value), `im_g`,
    /// `scale_factor`, `status`, `warnings`, `error`, per limit state `<name>_exceeded` and
    /// `<name>_ratio`, and with `[outputs] seats`: `governing_seat_end`,
    /// `governing_seat_ratio` and per seated end `seat_ratio_<end>`.
    pub fn column_names(&self) -> Vec<String> {
        let mut c: Vec<String> = ["run", "id", "variant", "record", "entry", "stripe"]
            .map(String::from)
            .to_vec();
        c.push(self.stripe_column().into());
        c.extend(["im_g", "scale_factor", "status", "warnings", "error"].map(String::from));
        for l in &self.study.limits {
            c.push(format!("{}_exceeded", l.state.name));
            c.push(format!("{}_ratio", l.state.name));
        }
        if self.seats {
            c.push("governing_seat_end".into());
            c.push("governing_seat_ratio".into());
            c.extend(self.seat_ends().iter().map(|e| seat_ratio_column(e)));
        }
        c
    }

    /// The seated ends of the bridge.
    pub fn seat_ends(&self) -> Vec<String> {
        self.study.setup.problem.model.seat_end_names()
    }

    /// Computes the runs of part `p` on the current rayon pool (in parallel, rows in run
    /// order), `progress()` after each run.
    pub fn run_part(&self, p: usize, progress: &(dyn Fn() + Sync)) -> Vec<(RunSpec, RunRow)> {
        let st = &self.study;
        let settings: Vec<_> = self
            .variant_runs
            .iter()
            .map(|v| summary_settings(&v.setup.settings))
            .collect();
        self.part_range(p)
            .into_par_iter()
            .map(|i| {
                let spec = self.run_spec(i);
                let v = &self.variant_runs[spec.variant];
                let row = run_one(
                    &v.setup.problem,
                    &settings[spec.variant],
                    &st.set,
                    &self.plan,
                    &v.limits,
                    (spec.entry, spec.stripe),
                );
                progress();
                (spec, row)
            })
            .collect()
    }

    /// The columns of `runs`.
    pub fn columns(&self, runs: &[(RunSpec, RunRow)]) -> Columns {
        let ends = self.seat_ends();
        let int = |f: &dyn Fn(&RunSpec, &RunRow) -> i64| {
            Values::Int(runs.iter().map(|(s, r)| Some(f(s, r))).collect())
        };
        let float = |f: &dyn Fn(&RunSpec, &RunRow) -> Option<f64>| {
            Values::Float(runs.iter().map(|(s, r)| f(s, r)).collect())
        };
        let text = |f: &dyn Fn(&RunSpec, &RunRow) -> Option<String>| {
            Values::Text(runs.iter().map(|(s, r)| f(s, r)).collect())
        };
        let recs = &self.study.set.records;
        let values = self.plan.values();
        let mut c = vec![
            int(&|s, _| s.index as i64),
            text(&|s, _| Some(s.id.clone())),
            text(&|s, _| Some(self.variants[s.variant].clone())),
            text(&|s, _| Some(recs[s.entry].id.clone())),
            int(&|s, _| s.entry as i64),
            int(&|s, _| s.stripe as i64),
            float(&|s, _| Some(values[s.stripe])),
            float(&|_, r| Some(r.im_g)),
            float(&|_, r| Some(r.scale_factor)),
            text(&|_, r| Some(r.status.clone())),
            int(&|_, r| r.warnings as i64),
            text(&|_, r| Some(r.error.clone())),
        ];
        for l in 0..self.study.limits.len() {
            c.push(Values::Bool(
                runs.iter().map(|(_, r)| r.limits[l].0).collect(),
            ));
            c.push(float(&|_, r| Some(r.limits[l].1)));
        }
        if self.seats {
            c.push(text(&|_, r| {
                r.governing_seat.and_then(|g| ends.get(g).cloned())
            }));
            c.push(float(&|_, r| r.governing_seat.map(|g| r.seats[g])));
            for e in 0..ends.len() {
                c.push(float(&|_, r| r.seats.get(e).copied()));
            }
        }
        Columns {
            cols: self.column_names().into_iter().zip(c).collect(),
        }
    }
}

/// The runs of stored columns as `(run index, RunRow)`, the inverse of
/// [`Campaign::columns`]: `limits` are the limit states' names, `ends` the seated ends (a store
/// without the seat columns gives rows without seat ratios).
pub fn decode_rows(
    cols: &Columns,
    limit_names: &[String],
    ends: &[String],
) -> Result<Vec<(usize, RunRow)>, CampaignError> {
    let missing = |n: &str| CampaignError::Store(format!("no column {n:?}"));
    let int = |n: &str| match cols.get(n) {
        Some(Values::Int(v)) => Ok(v),
        _ => Err(missing(n)),
    };
    let float = |n: &str| match cols.get(n) {
        Some(Values::Float(v)) => Ok(v),
        _ => Err(missing(n)),
    };
    let text = |n: &str| match cols.get(n) {
        Some(Values::Text(v)) => Ok(v),
        _ => Err(missing(n)),
    };
    let (run, entry, stripe, warn) = (int("run")?, int("entry")?, int("stripe")?, int("warnings")?);
    let (im, sf) = (float("im_g")?, float("scale_factor")?);
    let (status, error) = (text("status")?, text("error")?);
    let mut limits = Vec::new();
    for name in limit_names {
        let ex = match cols.get(&format!("{name}_exceeded")) {
            Some(Values::Bool(v)) => v,
            _ => return Err(missing(&format!("{name}_exceeded"))),
        };
        limits.push((ex, float(&format!("{name}_ratio"))?));
    }
    let seats = cols.get("governing_seat_end").is_some();
    let seat_cols: Option<Vec<&Vec<Option<f64>>>> = seats
        .then(|| ends.iter().map(|e| float(&seat_ratio_column(e))).collect())
        .transpose()?;
    let gov = if seats {
        Some(text("governing_seat_end")?)
    } else {
        None
    };
    let n = cols.rows();
    let idx = |v: Option<i64>| v.and_then(|x| usize::try_from(x).ok());
    (0..n)
        .map(|k| {
            let bad = || CampaignError::Store(format!("row {k}: a missing index"));
            let seats: Vec<f64> = match &seat_cols {
                Some(sc) => sc.iter().filter_map(|c| c[k]).collect(),
                None => Vec::new(),
            };
            let governing = gov
                .and_then(|g| g[k].as_ref())
                .and_then(|name| ends.iter().position(|e| e == name));
            Ok((
                idx(run[k]).ok_or_else(bad)?,
                RunRow {
                    record: idx(entry[k]).ok_or_else(bad)?,
                    stripe: idx(stripe[k]).ok_or_else(bad)?,
                    im_g: im[k].unwrap_or(f64::NAN),
                    scale_factor: sf[k].unwrap_or(f64::NAN),
                    status: status[k].clone().unwrap_or_default(),
                    error: error[k].clone().unwrap_or_default(),
                    warnings: idx(warn[k]).unwrap_or(0),
                    limits: limits
                        .iter()
                        .map(|(ex, ra)| (ex[k], ra[k].unwrap_or(f64::NAN)))
                        .collect(),
                    seats,
                    governing_seat: governing,
                },
            ))
        })
        .collect()
}

/// The parts of shard `shard` (parts `p` with `p mod N = K − 1`) not yet in `store`.
pub fn pending(
    c: &Campaign,
    store: &super::Store,
    shard: crate::shard::Shard,
) -> Result<(Vec<usize>, usize), CampaignError> {
    let stored = store.stored()?;
    let mine: Vec<usize> = (0..c.parts()).filter(|p| shard.contains(*p)).collect();
    let before = mine.iter().filter(|p| stored.contains_key(p)).count();
    Ok((
        mine.into_iter()
            .filter(|p| !stored.contains_key(p))
            .collect(),
        before,
    ))
}

/// Runs the `parts` of `c` on the current rayon pool (parts and their runs in parallel) and
/// stores each part as it finishes; `progress()` after each run. The first error (a part
/// that cannot be written) stops the parts not yet started.
pub fn run_parts(
    c: &Campaign,
    store: &super::Store,
    parts: &[usize],
    progress: &(dyn Fn() + Sync),
) -> Result<usize, CampaignError> {
    parts
        .par_iter()
        .map(|&p| {
            let runs = c.run_part(p, progress);
            store.write_part(p, &c.columns(&runs))?;
            Ok(runs.len())
        })
        .try_reduce(|| 0, |a, b| Ok(a + b))
}
