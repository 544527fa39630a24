//! An estimate of the time-discretisation error of a run's answers, from the same run at
//! `h`, `h/2` and `h/4` (Richardson's idea, with the order observed rather than assumed).
//!
//! A summary quantity `q` (a peak closing, a seat ratio, a contact force, …) of a run at step
//! `h` differs from its limit `q*` as `h → 0` by the discretisation error `e(h) = q(h) − q*`. When
//! the error behaves as `C h^p`, the differences of three runs
//!
//! ```text
//! d₁ = q(h) − q(h/2),     d₂ = q(h/2) − q(h/4),     r = d₁ / d₂ = 2^p,
//! ```
//!
//! give the observed order `p = log₂ r` and, summing the geometric series
//! `e(h) = d₁ + d₂ + d₃ + … = d₁ (1 + 1/r + 1/r² + …)`, the estimate
//!
//! ```text
//! ê(h) = |d₁| · r / (r − 1),      r taken at most 4 (order 2, the scheme's own):
//! ```
//!
//! an observed order above the scheme's is a coincidence of the three runs, not a rate to bank on.
//!
//! The estimate is multiplied by the safety factor [`SAFETY`] = 1.25 of Roache's grid
//! convergence index (Roache 1998, *Verification and Validation in Computational Science and
//! Engineering*), and trusted as asymptotic ([`Trust::Converging`]) where the three runs show
//! that behaviour: `d₁` and `d₂` of the same sign and `r ≥` [`MIN_RATIO`] (the differences shrink
//! at least at order ≈ 0.58). Differences within [`NEGLIGIBLE`] of the quantity's scale are zero
//! (both: [`Trust::Converged`]; only the second: `q(h/2)` has converged and `ê(h) = |d₁|`).
//!
//! Peaks of a rigid-impact response rarely behave so: an impact happens in the step where the
//! gap closes, so event times are rounded to the step and a peak's error changes sign from one
//! step to the next while its size stays of order `h` (Moreau–Jean is of order 1 at impacts). For
//! such a quantity ([`Trust::Erratic`]) the estimate is the envelope `ê(h) = 2 S`, `S` the spread
//! `max − min` of the three values: a magnitude, not an asymptotic estimate. Where that spread
//! exceeds [`CHAOTIC_SPREAD`] of the value, the quantity is [`Trust::NotConverging`] and gets **no
//! error number**: its value depends on the step at the scale of the value itself (a chaotic
//! sequence of impacts that reorders when `h` changes, or a step far too coarse).
//! Impact counts are integers: their spread is reported ([`Trust::Counted`]), never an order.
//!
//! Why three runs and not two: with two runs the order must be assumed (Moreau–Jean is of order 1
//! at impacts and 2 between them), and a chaotic quantity would get a confident, wrong error bar.
//! The third run both measures the order and detects the lack of convergence.
//!
//! [`run_with_estimate`] runs the levels (each with the history interval of the first, so the
//! histories keep their times and size) and, with a tolerance, halves the step until every
//! *governing* quantity ([`quantities`]) is trusted with a relative error below it.

mod quantities;

pub use quantities::{Kind, Quantity, quantities};

use crate::math::Real;
use crate::output::{float_token, json_float};
use crate::sim::bridge::BridgeSolution;
use crate::sim::scenario::Setup;
use crate::sim::{Progress, SimError, SimStatus};
use serde_json::json;

/// The smallest ratio `d₁/d₂` of successive differences that counts as converging (order
/// `log₂ 1.5 ≈ 0.58`).
pub const MIN_RATIO: Real = 1.5;

/// A difference of at most `NEGLIGIBLE · max(|q|, floor)` is zero ([`Kind::floor`]).
pub const NEGLIGIBLE: Real = 1e-9;

/// The largest ratio `d₁/d₂` the series is summed with: order 2, the scheme's between impacts
/// (the trapezoidal rule); an observed order above it is reported but not used.
pub const MAX_RATIO: Real = 4.0;

/// The safety factor of an asymptotic estimate (Roache's grid convergence index for three
/// solutions with an observed order).
pub const SAFETY: Real = 1.25;

/// The relative spread of three values without an observed order above which a quantity is
/// not converging (no error estimate).
pub const CHAOTIC_SPREAD: Real = 0.05;

/// How far an estimate can be trusted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Trust {
    /// The three runs agree within [`NEGLIGIBLE`].
    Converged,
    /// The differences shrink at an observed order: the estimate holds.
    Converging,
    /// The differences change sign or do not shrink, within [`CHAOTIC_SPREAD`]: the error is
    /// estimated from the spread (an order-1 envelope), not certified.
    Erratic,
    /// The three values differ by more than [`CHAOTIC_SPREAD`] without an order: no error
    /// estimate (chaotic, or the step is far too coarse).
    NotConverging,
    /// An integer count: its spread over the runs, no order.
    Counted,
}

impl Trust {
    /// The word in the files: `converged`, `converging`, `erratic`, `not-converging`,
    /// `counted`.
    pub fn name(self) -> &'static str {
        match self {
            Trust::Converged => "converged",
            Trust::Converging => "converging",
            Trust::Erratic => "erratic",
            Trust::NotConverging => "not-converging",
            Trust::Counted => "counted",
        }
    }
}

/// The estimate of one quantity from its values at `h`, `h/2`, `h/4`.
#[derive(Debug, Clone, PartialEq)]
pub struct QuantityEstimate {
    /// The quantity.
    pub quantity: Quantity,
    /// `[q(h), q(h/2), q(h/4)]`.
    pub values: [Real; 3],
    /// `ê(h)` (`None` when [`Trust::NotConverging`]; for a count, the spread).
    pub error: Option<Real>,
    /// `ê(h) / max(|q(h)|, floor)` ([`Kind::floor`]; `None` with `error` or for counts).
    pub relative_error: Option<Real>,
    /// The observed order `log₂(d₁/d₂)` (only when [`Trust::Converging`] with `d₂ ≠ 0`).
    pub order: Option<Real>,
    /// How far it can be trusted.
    pub trust: Trust,
}

impl QuantityEstimate {
    /// `max − min` of the three values.
    pub fn spread(&self) -> Real {
        let [a, b, c] = self.values;
        a.max(b).max(c) - a.min(b).min(c)
    }

    /// Whether the quantity has an error estimate of relative size at most `tol`.
    pub fn meets(&self, tol: Real) -> bool {
        matches!(
            self.trust,
            Trust::Converged | Trust::Converging | Trust::Erratic
        ) && self.relative_error.is_some_and(|e| e <= tol)
    }
}

/// The estimate of one quantity (see the module's equations).
pub fn estimate_one(quantity: Quantity, values: [Real; 3]) -> QuantityEstimate {
    let [q1, q2, q4] = values;
    let scale = q1
        .abs()
        .max(q2.abs())
        .max(q4.abs())
        .max(quantity.kind.floor());
    let relative = |e: Real| e / q1.abs().max(quantity.kind.floor());
    let (d1, d2) = (q1 - q2, q2 - q4);
    let zero = |d: Real| d.abs() <= NEGLIGIBLE * scale;
    let spread = q1.max(q2).max(q4) - q1.min(q2).min(q4);
    let (error, order, trust) = if !values.iter().all(|v| v.is_finite()) {
        (None, None, Trust::NotConverging)
    } else if quantity.kind == Kind::Count {
        (Some(spread), None, Trust::Counted)
    } else if zero(d1) && zero(d2) {
        (Some(d1.abs()), None, Trust::Converged)
    } else if zero(d2) {
        // q(h/2) has converged: the error of q(h) is its difference to it
        (Some(SAFETY * d1.abs()), None, Trust::Converging)
    } else if !zero(d1) && d1.signum() == d2.signum() && d1.abs() >= MIN_RATIO * d2.abs() {
        let r = d1.abs() / d2.abs();
        // an order above the scheme's (2) is a coincidence of three runs, not a rate to bank
        // on: the series is summed at order 2 at most (Roache's advice)
        let rs = r.min(MAX_RATIO);
        let e = SAFETY * d1.abs() * rs / (rs - 1.0);
        (Some(e), Some(r.log2()), Trust::Converging)
    } else if spread <= CHAOTIC_SPREAD * q1.abs().max(quantity.kind.floor()) {
        (Some(2.0 * spread), None, Trust::Erratic)
    } else {
        (None, None, Trust::NotConverging)
    };
    let relative_error = match trust {
        Trust::Counted => None,
        _ => error.map(relative),
    };
    QuantityEstimate {
        quantity,
        values,
        error,
        relative_error,
        order,
        trust,
    }
}

/// The estimates of every quantity of three runs at `h`, `h/2`, `h/4` of the same model (the
/// same quantities in the same order, as [`quantities`] lists them for one model).
///
/// # Panics
/// If the three lists differ in length or names (runs of different models).
pub fn estimate(levels: [&[(Quantity, Real)]; 3]) -> Vec<QuantityEstimate> {
    assert!(
        levels[1].len() == levels[0].len() && levels[2].len() == levels[0].len(),
        "the three runs must be of one model"
    );
    (0..levels[0].len())
        .map(|i| {
            let q = &levels[0][i].0;
            assert!(levels[1][i].0.name == q.name && levels[2][i].0.name == q.name);
            estimate_one(q.clone(), [levels[0][i].1, levels[1][i].1, levels[2][i].1])
        })
        .collect()
}

/// Reads a relative tolerance: `1%` (a percentage) or `0.01` (a fraction), in (0, 1). A bare
/// number of 1 or more is refused (is `1` one percent or one hundred?).
pub fn parse_tol(s: &str) -> Result<Real, String> {
    let t = s.trim();
    let (num, percent) = match t.strip_suffix('%') {
        Some(n) => (n.trim(), true),
        None => (t, false),
    };
    let v: Real = num.parse().map_err(|_| {
        format!("invalid tolerance {s:?}: write a percentage (1%) or a fraction (0.01)")
    })?;
    let frac = if percent { v / 100.0 } else { v };
    if !percent && v >= 1.0 {
        return Err(format!(
            "invalid tolerance {s:?}: a bare number is a fraction in (0, 1); for {v} percent write {v}%"
        ));
    }
    if !(frac.is_finite() && frac > 0.0 && frac < 1.0) {
        return Err(format!(
            "invalid tolerance {s:?}: must be above 0 and below 100 % (0 < tol < 1)"
        ));
    }
    Ok(frac)
}

/// What [`run_with_estimate`] does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AccuracySettings {
    /// The relative error every governing quantity must meet (`None`: estimate the error of the
    /// run at the given step only).
    pub tol: Option<Real>,
    /// With `tol`: the most halvings of the step for the answer (the finest run is at
    /// `h / 2^(max_refinements + 2)`).
    pub max_refinements: usize,
}

impl Default for AccuracySettings {
    fn default() -> Self {
        Self {
            tol: None,
            max_refinements: 3,
        }
    }
}

/// Why the runs gave no estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelFailure {
    /// The step of the run that did not complete \[s\].
    pub dt: Real,
    /// Its status.
    pub status: SimStatus,
}

/// The answer of [`run_with_estimate`].
#[derive(Debug, Clone)]
pub struct AccuracyRun {
    /// The steps of every run made, coarsest first \[s\].
    pub dts: Vec<Real>,
    /// The index in [`Self::dts`] of the answer's run (its step is the answer's).
    pub chosen: usize,
    /// The estimates of its quantities (from the runs `chosen`, `chosen + 1`, `chosen + 2`);
    /// empty when [`Self::failure`] is set.
    pub estimates: Vec<QuantityEstimate>,
    /// With a tolerance: whether every governing quantity met it.
    pub met: Option<bool>,
    /// A refined run that did not complete (no estimate is given then).
    pub failure: Option<LevelFailure>,
    /// The settings.
    pub settings: AccuracySettings,
}

impl AccuracyRun {
    /// The governing estimates ([`Quantity::governing`]).
    pub fn governing(&self) -> impl Iterator<Item = &QuantityEstimate> {
        self.estimates.iter().filter(|e| e.quantity.governing)
    }

    /// The governing quantities without a trusted estimate.
    pub fn untrusted(&self) -> Vec<&str> {
        self.governing()
            .filter(|e| e.trust == Trust::NotConverging)
            .map(|e| e.quantity.name.as_str())
            .collect()
    }

    /// The largest relative error of a trusted governing quantity, and its name.
    pub fn worst(&self) -> Option<(&str, Real)> {
        self.governing()
            .filter_map(|e| e.relative_error.map(|r| (e.quantity.name.as_str(), r)))
            .fold(None, |acc, (n, r)| match acc {
                Some((_, m)) if m >= r => acc,
                _ => Some((n, r)),
            })
    }

    /// `accuracy.csv`: a row per quantity.
    pub fn csv(&self) -> String {
        let mut s = String::from(
            "quantity,unit,governing,value,value_half_dt,value_quarter_dt,error,relative_error,\
             order,trust\n",
        );
        let opt = |x: Option<Real>| x.map(float_token).unwrap_or_default();
        for e in &self.estimates {
            let [a, b, c] = e.values;
            s.push_str(&format!(
                "{},{},{},{},{},{},{},{},{},{}\n",
                e.quantity.name,
                e.quantity.unit,
                e.quantity.governing,
                float_token(a),
                float_token(b),
                float_token(c),
                opt(e.error),
                opt(e.relative_error),
                opt(e.order),
                e.trust.name()
            ));
        }
        s
    }

    /// `accuracy.json`: the steps, the verdict and every estimate.
    pub fn json(&self) -> serde_json::Value {
        let opt = |x: Option<Real>| x.map(json_float).unwrap_or(serde_json::Value::Null);
        let worst = self.worst();
        json!({
            "dt_s": json_float(self.dts[self.chosen]),
            "runs_dt_s": self.dts.iter().map(|d| json_float(*d)).collect::<Vec<_>>(),
            "estimate_dt_s": self.dts.iter().skip(self.chosen).take(3)
                .map(|d| json_float(*d)).collect::<Vec<_>>(),
            "tol": opt(self.settings.tol),
            "max_refinements": self.settings.max_refinements,
            "met": self.met,
            "failure": self.failure.as_ref().map(|f| json!({
                "dt_s": json_float(f.dt),
                "status": format!("{:?}", f.status),
            })),
            "governing_worst": worst.map(|(n, r)| json!({"quantity": n, "relative_error": json_float(r)})),
            "governing_untrusted": self.untrusted(),
            "quantities": self.estimates.iter().map(|e| json!({
                "quantity": e.quantity.name,
                "unit": e.quantity.unit,
                "governing": e.quantity.governing,
                "values": e.values.iter().map(|v| json_float(*v)).collect::<Vec<_>>(),
                "error": opt(e.error),
                "relative_error": opt(e.relative_error),
                "order": opt(e.order),
                "trust": e.trust.name(),
            })).collect::<Vec<_>>(),
        })
    }
}

/// Refuses, before any run, a refinement whose finest level (`dt / 2^last`, its history stride
/// `2^last` times the given one) would be refused: beyond [`crate::sim::MAX_STEPS`] steps, or
/// beyond the memory limit.
fn check_finest(setup: &Setup, last: usize) -> Result<(), SimError> {
    use crate::sim::options::{MAX_RUN_MEMORY_BYTES, run_memory_bytes};
    let s = setup.settings();
    let factor = 1u64.checked_shl(last as u32).unwrap_or(u64::MAX);
    let mut fine = s.clone();
    fine.dt = s.dt / factor as Real;
    let duration = s
        .duration
        .unwrap_or_else(|| crate::sim::Problem::ground(setup).end_time());
    let n = fine.step_count(duration)?;
    let stride = s.history_stride.saturating_mul(factor as usize);
    let segments = crate::sim::Problem::model(setup).segments.len();
    let bytes = run_memory_bytes(n, stride, segments);
    if bytes > MAX_RUN_MEMORY_BYTES {
        return Err(SimError::argument(
            crate::sim::param::Setting::Dt,
            format!(
                "the finest run of the estimate (dt / {factor} = {} s, {n} steps) needs an \
                 estimated {:.1} GiB of memory, more than the limit {:.0} GiB; use fewer \
                 refinements, a larger dt or a shorter run",
                crate::output::float_token(fine.dt),
                bytes as Real / (1u64 << 30) as Real,
                MAX_RUN_MEMORY_BYTES as Real / (1u64 << 30) as Real
            ),
        ));
    }
    Ok(())
}

/// Runs `setup` at its step `h`, `h/2` and `h/4` and estimates the error of the run at `h`; with
/// [`AccuracySettings::tol`], halves `h` (one more run each time) until every governing quantity
/// is trusted within it, at most [`AccuracySettings::max_refinements`] times. `on_run(dt)` is
/// called before each run and gives its progress observer. A run that does not complete ends the refinement: the answer is the
/// coarsest run, with [`AccuracyRun::failure`] and no estimates (a failed run of the first level
/// is the answer itself, with its status). Returns the answer's run and the estimate.
pub fn run_with_estimate(
    setup: &Setup,
    settings: AccuracySettings,
    mut on_run: impl FnMut(Real) -> Progress,
) -> Result<(BridgeSolution, AccuracyRun), SimError> {
    let h0 = setup.settings().dt;
    let stride0 = setup.settings().history_stride;
    let mut dts = Vec::new();
    let mut solutions: Vec<Option<BridgeSolution>> = Vec::new();
    let mut values: Vec<Vec<(Quantity, Real)>> = Vec::new();
    let last_first = if settings.tol.is_some() {
        settings.max_refinements
    } else {
        0
    };
    check_finest(setup, last_first + 2)?;
    let mut run_level = |k: usize,
                         dts: &mut Vec<Real>,
                         solutions: &mut Vec<Option<BridgeSolution>>,
                         values: &mut Vec<Vec<(Quantity, Real)>>|
     -> Result<Option<LevelFailure>, SimError> {
        let mut s = setup.clone();
        let dt = h0 / (1u64 << k) as Real;
        s.settings_mut().dt = dt;
        s.settings_mut().history_stride = stride0 << k;
        s.settings_mut().progress = on_run(dt);
        let sol = s.run()?;
        dts.push(dt);
        let status = sol.status;
        values.push(quantities(&sol));
        solutions.push(Some(sol));
        Ok((status != SimStatus::Completed).then_some(LevelFailure { dt, status }))
    };
    for k in 0..=last_first + 2 {
        if let Some(failure) = run_level(k, &mut dts, &mut solutions, &mut values)? {
            let first = solutions[0].take().expect("run kept");
            let run = AccuracyRun {
                dts,
                chosen: 0,
                estimates: Vec::new(),
                met: settings.tol.map(|_| false),
                failure: Some(failure),
                settings,
            };
            return Ok((first, run));
        }
        if k < 2 {
            continue;
        }
        let first = k - 2;
        let estimates = estimate([&values[first], &values[first + 1], &values[first + 2]]);
        let met = settings.tol.map(|tol| {
            estimates
                .iter()
                .filter(|e| e.quantity.governing)
                .all(|e| e.meets(tol))
        });
        if met != Some(false) || first == last_first {
            let solution = solutions[first].take().expect("run kept");
            let run = AccuracyRun {
                dts,
                chosen: first,
                estimates,
                met,
                failure: None,
                settings,
            };
            return Ok((solution, run));
        }
        // the run `first` will not be the answer: drop its histories
        solutions[first] = None;
    }
    unreachable!("the loop returns at its last level")
}
