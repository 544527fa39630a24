//! Batch runs for fragility studies and incremental dynamic analysis (IDA): one simulation per
//! `(record, scale)` pair, in parallel, in a deterministic row order.
//!
//! # Runs and rows
//! With records `r_0 … r_{R−1}` and scale factors `s_0 … s_{S−1}`, run `i = a S + b` uses record
//! `r_a` as the **only** ground-motion component, acting along `Rot(α) ŷ` (normal to the joint for
//! the incidence `α = 0` of the base problem), with scale factor `s_b · scale_y` where `scale_y`
//! is the base problem's factor. This is exactly the single run of `pounding simulate --record r_a
//! --scale s_b` ([`run_problem`] builds it), so a batch row equals that run's summary bit for bit.
//!
//! An entry may instead be a horizontal **pair** ([`BatchRecord::along_x`], the entries of a
//! record-set manifest, [`BatchRecord::of_set`]): its first record acts along `Rot(α) ŷ` with
//! `s_b · scale_y` and its second along `Rot(α) x̂` with `s_b · scale_x`, as in a fragility run
//! ([`entry_ground`], shared with [`crate::assessment`]): the single run of a scenario naming the
//! first as `record_y` and the second as `record_x`, with `--scale s_b`.
//!
//! Rows come back in increasing `i` whatever the number of threads (rayon's ordered collect; each
//! run is sequential and deterministic). A [`BatchShard`] `K/N` keeps only the runs with
//! `i mod N = K − 1`, so the union of the rows of all `N` shards, sorted by `i`, is the unsharded
//! result.
//!
//! Any [`Problem`] runs this way: a bridge of `N` segments ([`crate::sim::bridge::BridgeProblem`]),
//! the two-deck preset ([`crate::sim::SimProblem`]) or a [`crate::sim::scenario::Setup`] of
//! either form: the same runs, row order and shards.
//!
//! A record that could not be read does not stop the batch: its rows carry the error
//! ([`BatchRow::outcome`]) and every other run is still done.

use super::bridge::{BridgeSolution, BridgeSummary};
use super::excitation::{SupportExcitation, SupportRecord};
use super::problem::{Problem, simulate};
use super::{SimError, SimSettings, SimStatus};
use crate::ground_motion::set::RecordSet;
use crate::ground_motion::{GroundMotion, Record};
use crate::math::Real;
use rayon::prelude::*;

/// Which runs a batch computes (the shard type shared with `study`).
pub type BatchShard = crate::shard::Shard;

/// One entry of a batch: a ground-motion record (or a horizontal pair), or the reason it could
/// not be read.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchRecord {
    /// Name in the output (the path as given, or a manifest entry's id).
    pub name: String,
    /// The record (accelerations in m/s²), or the error message that names the file: the only
    /// component, or the first of a pair, along `Rot(α) ŷ` with `scale_y`.
    pub record: Result<Record, String>,
    /// The second horizontal component of a pair, along `Rot(α) x̂` with `scale_x` (`None`: the
    /// record is the only component).
    pub along_x: Option<Record>,
    /// A motion per support of a bridge (a set's `supports` entry), each along `Rot(α) ŷ` with
    /// `scale_y`; `record` is then the `start` support's. Empty for a record or a pair.
    pub supports: Vec<(String, Record)>,
}

impl BatchRecord {
    /// A one-component entry named `name`.
    pub fn single(name: impl Into<String>, record: Result<Record, String>) -> Self {
        Self {
            name: name.into(),
            record,
            along_x: None,
            supports: Vec::new(),
        }
    }

    /// The entries of a record set, in its order: each named by its id, a pair's `x` record
    /// first (along `Rot(α) ŷ`) and its `y` record second (along `Rot(α) x̂`), as a fragility
    /// run applies them.
    pub fn of_set(set: &RecordSet) -> Vec<Self> {
        set.records
            .iter()
            .map(|e| Self {
                name: e.id.clone(),
                record: Ok(e.x.clone()),
                along_x: e.y.clone(),
                supports: e.supports.clone(),
            })
            .collect()
    }
}

/// What one run produced (of the two-deck model or a bridge: both are bridges).
#[derive(Debug, Clone, PartialEq)]
pub struct BatchOutcome {
    /// How the run ended.
    pub status: SimStatus,
    /// Peaks, unseating and energies (as in a single run).
    pub summary: BridgeSummary,
    /// Impacting contacts (the rows of a single run's `impacts.csv`).
    pub impacting_contacts: usize,
    /// Steps taken.
    pub steps: usize,
    /// Step size \[s\].
    pub dt: Real,
    /// Steps with an LCP solve (rigid law).
    pub lcp_solves: usize,
    /// LCP solves that fell back to enumeration.
    pub lcp_enumeration_fallbacks: usize,
    /// LCP solves that failed.
    pub lcp_failures: usize,
    /// Compliance laws: steps whose Newton iteration did not converge.
    pub newton_failures: usize,
    /// Compliance laws: the time-step check of the contact (`None` for rigid contact).
    pub time_step_advice: Option<crate::contact_law::timestep::TimeStepAdvice>,
    /// The number of the run's warnings (the length of the same single run's `summary.json`
    /// `warnings` list; 0 until set by the batch, which knows the run's ground motion).
    pub warnings: usize,
}

/// One row of a batch (one run).
#[derive(Debug, Clone, PartialEq)]
pub struct BatchRow {
    /// Global run index `i = record_index · (number of scales) + scale_index`.
    pub index: usize,
    /// Index of the record.
    pub record_index: usize,
    /// Record name.
    pub record: String,
    /// Index of the scale factor.
    pub scale_index: usize,
    /// Scale factor `s` of this run (multiplies the base problem's `scale_y`).
    pub scale: Real,
    /// Peak ground acceleration of the applied (scaled) component, `|s · scale_y| · max|a|`
    /// \[m/s²\] (of a pair: the larger of its two components', the second's with `scale_x`);
    /// NaN when the record could not be read.
    pub pga: Real,
    /// The run's result, or the error (an unreadable record, or a simulation input error).
    pub outcome: Result<BatchOutcome, String>,
}

/// The ground motion of one run of an entry (a batch's or a fragility study's): `ground` with
/// `first` along `Rot(α) ŷ` and `second` (a pair's other component; `None`: no component)
/// along `Rot(α) x̂`, the incidence kept and both scale factors multiplied by `scale`.
pub fn entry_ground(
    ground: &GroundMotion,
    first: &Record,
    second: Option<&Record>,
    scale: Real,
) -> GroundMotion {
    GroundMotion {
        along_y: Some(first.clone()),
        scale_y: ground.scale_y * scale,
        along_x: second.cloned(),
        scale_x: ground.scale_x * scale,
        incidence: ground.incidence,
    }
}

/// The problem of one run of an entry: `base` under [`entry_ground`] (a pair: the single run of
/// the scenario naming `first` as `record_y` and `second` as `record_x`, with `--scale S`).
pub fn entry_problem<P: Problem>(
    base: &P,
    first: &Record,
    second: Option<&Record>,
    scale: Real,
) -> P {
    base.with_ground(entry_ground(base.ground(), first, second, scale))
}

/// The problem of one run of a support-motion entry: `base` with each support's record along
/// `Rot(α) ŷ` (scale factors multiplied by `scale`), the `start` support's as the reference
/// (the single run of the scenario naming the file as `supports_y`, with `--scale S`). A
/// two-deck problem has no supports of its own: an error.
pub fn supports_problem<P: Problem>(
    base: &P,
    supports: &[(String, Record)],
    scale: Real,
) -> Result<P, SimError> {
    if *base.supports() != SupportExcitation::Uniform {
        return Err(SimError::argument(
            "ground_motion.v_app",
            "the scenario's own support motion (wave passage) cannot be combined with a \
                     support-motion entry, which gives every support its motion",
        ));
    }
    let ground = |r: &Record| entry_ground(base.ground(), r, None, scale);
    let start = supports
        .iter()
        .find(|(id, _)| id == "start")
        .unwrap_or(&supports[0]);
    let records = supports
        .iter()
        .map(|(id, r)| SupportRecord {
            id: id.clone(),
            ground: ground(r),
        })
        .collect();
    base.with_motion(ground(&start.1), SupportExcitation::Records(records))
}

/// The problem of one run: `base` with `record` as its only component along `Rot(α) ŷ`, scale
/// factors multiplied by `scale` (the single run `pounding simulate --record R --scale S`).
pub fn run_problem<P: Problem>(base: &P, record: &Record, scale: Real) -> P {
    entry_problem(base, record, None, scale)
}

/// Checks the batch lists: at least one record and one scale, every scale finite.
pub fn validate_lists(records: &[BatchRecord], scales: &[Real]) -> Result<(), SimError> {
    if records.is_empty() {
        return Err(SimError::invalid(
            "--records",
            0.0,
            "need at least one record",
        ));
    }
    if scales.is_empty() {
        return Err(SimError::invalid(
            "--scales",
            0.0,
            "need at least one scale",
        ));
    }
    for (i, &s) in scales.iter().enumerate() {
        if !s.is_finite() {
            return Err(SimError::invalid(
                format!("--scales[{}]", i + 1),
                s,
                "must be finite",
            ));
        }
    }
    Ok(())
}

/// One run of a batch: `base` under `record` (and a pair's `second`) scaled by `scale` →
/// `(PGA [m/s²], outcome)`; the PGA of a pair is the larger of its scaled components'.
fn run_one<P: Problem>(
    base: &P,
    (record, second): (&Record, Option<&Record>),
    scale: Real,
    settings: &SimSettings,
) -> (Real, Result<BatchOutcome, SimError>) {
    let p = entry_problem(base, record, second, scale);
    let g = p.ground();
    let pga = record.pga() * g.scale_y.abs();
    let pga = second.map_or(pga, |x| pga.max(x.pga() * g.scale_x.abs()));
    let out = simulate(&p, settings).map(|sol| {
        let w = crate::sim::output::run_warnings(p.layout(), &sol).len();
        counted(BatchOutcome::from(sol), p.ground(), w)
    });
    (pga, out)
}

/// `o` with its [`BatchOutcome::warnings`]: the input warnings of a run on `ground`
/// ([`crate::sim::output::input_warnings`]) and `impact_warnings` per-impact ones.
fn counted(mut o: BatchOutcome, ground: &GroundMotion, impact_warnings: usize) -> BatchOutcome {
    let input = crate::sim::output::input_warnings(
        ground,
        o.dt,
        o.time_step_advice.as_ref(),
        &o.summary.segment_frequencies(),
    );
    o.warnings = input.len() + impact_warnings;
    o
}

/// Runs every `(record, scale)` pair of `shard` in parallel on the current rayon pool and returns
/// the rows in increasing global index (module docs). `progress(1)` is called after each run.
/// Each row equals [`simulate`] of [`run_problem`] bit for bit.
///
/// Errors (bad input for the whole batch: the model, the settings, the lists) are returned before
/// any run starts; per-run problems are in [`BatchRow::outcome`]. The settings' history stride
/// is ignored (no history is kept; the summary does not depend on it).
pub fn run_batch<P: Problem>(
    base: &P,
    settings: &SimSettings,
    records: &[BatchRecord],
    scales: &[Real],
    shard: BatchShard,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Vec<BatchRow>, SimError> {
    let settings = batch_settings(records, scales, settings)?;
    base.check_model()?;
    check_support_entries(base, records)?;
    check_batch_memory(base, records, &settings)?;
    Ok(run_pairs(
        records,
        scales,
        shard,
        progress,
        &|rec, r, scale| {
            if rec.supports.is_empty() {
                return run_one(base, (r, rec.along_x.as_ref()), scale, &settings);
            }
            let p = match supports_problem(base, &rec.supports, scale) {
                Ok(p) => p,
                Err(e) => return (Real::NAN, Err(e)),
            };
            // the start support's, as its single run's summary.json gives it (and its IM)
            let pga = r.pga() * p.ground().scale_y.abs();
            let out = simulate(&p, &settings).map(|sol| {
                let w = crate::sim::output::run_warnings(p.layout(), &sol).len();
                counted(BatchOutcome::from(sol), p.ground(), w)
            });
            (pga, out)
        },
    ))
}

/// Refuses, before any run, a batch whose runs held at once (one per thread of the current rayon
/// pool) would need more than [`crate::sim::options::MAX_RUN_MEMORY_BYTES`]: a run of a batch
/// keeps no history but its ground motion's samples (its step count: `[time] duration`, or its
/// record's length) and the first and last step.
fn check_batch_memory<P: Problem>(
    base: &P,
    records: &[BatchRecord],
    settings: &SimSettings,
) -> Result<(), SimError> {
    use crate::sim::options::{MAX_RUN_MEMORY_BYTES, run_memory_bytes};
    let segments = base.model().segments.len();
    let mut longest = 0usize;
    for rec in records {
        let Ok(r) = &rec.record else { continue };
        let end = rec
            .along_x
            .iter()
            .chain(rec.supports.iter().map(|s| &s.1))
            .map(Record::end_time)
            .fold(r.end_time(), Real::max);
        let n = settings.step_count(settings.duration.unwrap_or(end))?;
        longest = longest.max(n);
    }
    let at_once = rayon::current_num_threads().min(records.len()).max(1) as u64;
    let bytes = run_memory_bytes(longest, usize::MAX, segments).saturating_mul(at_once);
    if bytes <= MAX_RUN_MEMORY_BYTES {
        return Ok(());
    }
    let gib = |b: u64| b as Real / (1u64 << 30) as Real;
    Err(SimError::argument(
        super::param::Setting::Duration,
        format!(
            "run too large: the batch runs {at_once} runs at once of up to {longest} steps each, \
             an estimated {:.1} GiB of memory, more than the limit {:.0} GiB; shorten the \
             duration, use a larger dt or fewer threads",
            gib(bytes),
            gib(MAX_RUN_MEMORY_BYTES)
        ),
    ))
}

/// Refuses, before any run, support-motion entries that no run of `base` could take (a two-deck
/// model, a scenario with its own wave passage, a bridge the supports' motions do not reach:
/// [`crate::sim::integrate::check_apart`]).
pub fn check_support_entries<P: Problem>(
    base: &P,
    records: &[BatchRecord],
) -> Result<(), SimError> {
    let Some(r) = records.iter().find(|r| !r.supports.is_empty()) else {
        return Ok(());
    };
    let p = supports_problem(base, &r.supports, 1.0)?;
    let model = p.model();
    crate::sim::integrate::check_apart(&model)?;
    let lines: Vec<String> = model.support_lines().into_iter().map(|l| l.id).collect();
    for r in records.iter().filter(|r| !r.supports.is_empty()) {
        let has = |id: &String| r.supports.iter().any(|(c, _)| c == id);
        let missing = lines.iter().find(|l| !has(l));
        let extra = r.supports.iter().find(|(c, _)| !lines.contains(c));
        let problem = match (missing, extra) {
            (Some(l), _) => format!("has no column for support `{l}`"),
            (None, Some((c, _))) => format!("has a column `{c}`, which is not a support"),
            (None, None) => continue,
        };
        return Err(SimError::argument(
            format!("record {:?}", r.name),
            format!(
                "its support-motion file {problem} of the bridge (its supports: {})",
                lines.join(", ")
            ),
        ));
    }
    Ok(())
}

/// Checks the lists and the settings of a batch; the settings of its runs keep no history (the
/// summary does not depend on it).
fn batch_settings(
    records: &[BatchRecord],
    scales: &[Real],
    settings: &SimSettings,
) -> Result<SimSettings, SimError> {
    validate_lists(records, scales)?;
    settings.validate()?;
    Ok(SimSettings {
        history_stride: usize::MAX,
        ..settings.clone()
    })
}

/// One run of a batch: `((record, a pair's second record), scale)` → the PGA of the applied
/// component(s) and the outcome.
type RunOne<'a> =
    dyn Fn(&BatchRecord, &Record, Real) -> (Real, Result<BatchOutcome, SimError>) + Sync + 'a;

/// The rows of every `(record, scale)` pair of `shard`, in parallel on the current rayon pool, in
/// increasing global index; `run(record, scale)` gives the PGA of the applied component and the
/// outcome (its error is prefixed with the record's name).
fn run_pairs(
    records: &[BatchRecord],
    scales: &[Real],
    shard: BatchShard,
    progress: &(dyn Fn(usize) + Sync),
    run: &RunOne<'_>,
) -> Vec<BatchRow> {
    let ns = scales.len();
    let todo: Vec<usize> = (0..records.len() * ns)
        .filter(|&i| shard.contains(i))
        .collect();
    todo.par_iter()
        .map(|&i| {
            let (a, b) = (i / ns, i % ns);
            let rec = &records[a];
            let scale = scales[b];
            let (pga, outcome) = match &rec.record {
                Err(msg) => (Real::NAN, Err(msg.clone())),
                Ok(r) => {
                    let (pga, out) = run(rec, r, scale);
                    (pga, out.map_err(|e| format!("{}: {e}", rec.name)))
                }
            };
            progress(1);
            BatchRow {
                index: i,
                record_index: a,
                record: rec.name.clone(),
                scale_index: b,
                scale,
                pga,
                outcome,
            }
        })
        .collect()
}

impl From<BridgeSolution> for BatchOutcome {
    fn from(s: BridgeSolution) -> Self {
        Self {
            status: s.status,
            impacting_contacts: s.impacts.len(),
            summary: s.summary,
            steps: s.steps,
            dt: s.dt,
            lcp_solves: s.lcp_solves,
            lcp_enumeration_fallbacks: s.lcp_enumeration_fallbacks,
            lcp_failures: s.lcp_failures,
            newton_failures: s.newton_failures,
            time_step_advice: s.time_step_advice,
            warnings: 0,
        }
    }
}
