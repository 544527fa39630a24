//! The runs of a fragility study: every entry of the record set at every stripe, in parallel on
//! the current rayon pool, rows in a fixed order; `runs.csv`; the data of the fit.

use super::AssessmentError;
use super::im::{ImSpec, intensity};
use super::limit::BoundLimit;
use super::settings::Stripes;
use crate::ground_motion::GroundMotion;
use crate::ground_motion::set::RecordSet;
use crate::math::Real;
use crate::output::{csv_field, float_token};
use crate::sim::batch::entry_problem;
use crate::sim::bridge::BridgeProblem;
use crate::sim::simulate;
use crate::sim::{SimSettings, SimStatus};
use rayon::prelude::*;

/// The runs to do: the IM of each entry and the scale factor of each (entry, stripe).
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// The IM of each entry as applied at unit factor \[g\].
    pub entry_im: Vec<Real>,
    /// Stripes: IM levels \[g\] or scale factors.
    pub stripes: Stripes,
}

impl Plan {
    /// Computes every entry's IM (in parallel, deterministic) and refuses an IM of 0 and a
    /// stripe needing a scale factor above [`super::MAX_SCALE_FACTOR`] (naming record and stripe).
    pub fn new(
        set: &RecordSet,
        spec: &ImSpec,
        stripes: &Stripes,
        ground: &GroundMotion,
    ) -> Result<Self, AssessmentError> {
        let entry_im: Vec<Option<Real>> = set
            .records
            .par_iter()
            .map(|r| intensity(spec, r, ground.scale_y, ground.scale_x))
            .collect();
        let mut ims = Vec::with_capacity(entry_im.len());
        for (r, im) in set.records.iter().zip(entry_im) {
            let Some(im) = im else {
                return Err(AssessmentError::Model(format!(
                    "record {}: its accelerations times the scenario's factors (`[ground_motion] \
                     scale_y` = {}, `scale_x` = {}) are not finite; use smaller factors",
                    r.id,
                    float_token(ground.scale_y),
                    float_token(ground.scale_x)
                )));
            };
            ims.push(im);
        }
        let entry_im = ims;
        for (r, &im) in set.records.iter().zip(&entry_im) {
            if !(im.is_finite() && im > 0.0) {
                return Err(AssessmentError::ZeroIm {
                    id: r.id.clone(),
                    im: spec.label(),
                });
            }
        }
        let plan = Self {
            entry_im,
            stripes: stripes.clone(),
        };
        for (a, r) in set.records.iter().enumerate() {
            for (b, v) in plan.values().iter().enumerate() {
                let factor = plan.point(a, b).1;
                if factor > super::MAX_SCALE_FACTOR {
                    return Err(AssessmentError::ScaleFactor {
                        id: r.id.clone(),
                        stripe: match stripes {
                            Stripes::Levels(_) => format!("level_g = {}", float_token(*v)),
                            Stripes::Scales(_) => format!("scale = {}", float_token(*v)),
                        },
                        im: spec.label(),
                        entry_im: plan.entry_im[a],
                        factor,
                    });
                }
            }
        }
        Ok(plan)
    }

    /// The stripe values (levels in g, or scale factors).
    pub fn values(&self) -> &[Real] {
        match &self.stripes {
            Stripes::Levels(v) | Stripes::Scales(v) => v,
        }
    }

    /// `(IM [g], scale factor)` of entry `a` at stripe `b`: at a level `L`, `(L, L / IM_a)`; at a
    /// scale `s`, `(s · IM_a, s)`.
    pub fn point(&self, a: usize, b: usize) -> (Real, Real) {
        let im = self.entry_im[a];
        match &self.stripes {
            Stripes::Levels(l) => (l[b], l[b] / im),
            Stripes::Scales(s) => (s[b] * im, s[b]),
        }
    }
}

/// One run: entry `record` at stripe `stripe`.
#[derive(Debug, Clone, PartialEq)]
pub struct RunRow {
    /// Entry index.
    pub record: usize,
    /// Stripe index.
    pub stripe: usize,
    /// The run's IM \[g\].
    pub im_g: Real,
    /// The factor both components were multiplied by.
    pub scale_factor: Real,
    /// `Completed`, another status (untrustworthy), or `error`.
    pub status: String,
    /// The error message of a run that failed (empty otherwise).
    pub error: String,
    /// The number of the run's warnings (as the same single run's `summary.json` lists them:
    /// a coarse time step for the record, energy created at a contact, ...).
    pub warnings: usize,
    /// Per limit state: exceeded (`None`: excluded) and the ratio demand / capacity.
    pub limits: Vec<(Option<bool>, Real)>,
    /// Per seated end, in the order of [`crate::sim::bridge::BridgeModel::seat_end_names`]: the peak seat
    /// displacement over the end's own seat length (`summary.json` `seats[].ratio`); empty for a
    /// run that is not trusted.
    pub seats: Vec<Real>,
    /// The governing seated end (the largest ratio; an index into `seats`).
    pub governing_seat: Option<usize>,
}

impl RunRow {
    /// Whether the run counts in the fit (`Completed`).
    pub fn trusted(&self) -> bool {
        self.status == "Completed"
    }
}

/// Runs every entry at every stripe on the current rayon pool (rows in order `a S + b`, the
/// same bytes for any number of threads); `progress()` after each run.
pub fn run_all(
    base: &BridgeProblem,
    settings: &SimSettings,
    set: &RecordSet,
    plan: &Plan,
    limits: &[BoundLimit],
    progress: &(dyn Fn() + Sync),
) -> Vec<RunRow> {
    let settings = summary_settings(settings);
    let ns = plan.values().len();
    (0..set.records.len() * ns)
        .into_par_iter()
        .map(|i| {
            let row = run_one(base, &settings, set, plan, limits, (i / ns, i % ns));
            progress();
            row
        })
        .collect()
}

/// The settings of runs that keep only their summary (no history rows).
pub fn summary_settings(settings: &SimSettings) -> SimSettings {
    SimSettings {
        history_stride: usize::MAX,
        ..settings.clone()
    }
}

/// Halvings of the time step tried when a run's compliance contact ends with Newton failures.
pub const NEWTON_REFINEMENTS: u32 = 2;

/// A run whose compliance Newton iteration failed in some step
/// ([`SimStatus::CompletedWithNewtonFailures`]: the step kept its best iterate, not a solution)
/// is run again, whole, at `dt/2`, then at `dt/4` ([`NEWTON_REFINEMENTS`]); the first of those
/// that completes replaces it (`true`: refined). The failures are single steps where several
/// contacts are closed at once (measured on the design example: one step in 7,500, residual
/// 3e-6 to 1e-2 m/s), and a smaller step resolves them; a run that still fails at `dt/4` keeps
/// its status and is excluded from the fit.
fn refine_newton_failures(
    p: &BridgeProblem,
    settings: &SimSettings,
    sol: crate::sim::bridge::BridgeSolution,
) -> Result<(crate::sim::bridge::BridgeSolution, bool), crate::sim::SimError> {
    if sol.status != SimStatus::CompletedWithNewtonFailures {
        return Ok((sol, false));
    }
    for i in 1..=NEWTON_REFINEMENTS {
        let finer = SimSettings {
            dt: settings.dt / Real::from(2u32.pow(i)),
            ..settings.clone()
        };
        let s = simulate(p, &finer)?;
        if s.status == SimStatus::Completed {
            return Ok((s, true));
        }
    }
    Ok((sol, false))
}

/// One run: entry `a` at stripe `b` (`settings` as [`summary_settings`] gives them), its
/// status, limit states, seat ratios and warnings.
pub fn run_one(
    base: &BridgeProblem,
    settings: &SimSettings,
    set: &RecordSet,
    plan: &Plan,
    limits: &[BoundLimit],
    (a, b): (usize, usize),
) -> RunRow {
    let (im_g, sf) = plan.point(a, b);
    let e = &set.records[a];
    let p: Result<BridgeProblem, _> = if e.supports.is_empty() {
        Ok(entry_problem(base, &e.x, e.y.as_ref(), sf))
    } else {
        crate::sim::batch::supports_problem(base, &e.supports, sf)
    };
    let mut seats = (Vec::new(), None);
    let mut refined = false;
    let (status, error, lim, warnings) = match p.and_then(|p| {
        let sol = simulate(&p, settings)?;
        let (sol, r) = refine_newton_failures(&p, settings, sol)?;
        refined = r;
        Ok((p, sol))
    }) {
        Err(err) => (
            "error".to_string(),
            err.to_string(),
            vec![(None, Real::NAN); limits.len()],
            0,
        ),
        Ok((p, sol)) => {
            let ok = sol.status == SimStatus::Completed;
            if ok {
                let s = &sol.summary;
                seats = (
                    s.seats.iter().map(|e| e.ratio).collect(),
                    (s.governing_seat < s.seats.len()).then_some(s.governing_seat),
                );
            }
            let lim = limits
                .iter()
                .map(|l| {
                    if ok {
                        l.evaluate(&sol.summary)
                    } else {
                        (None, Real::NAN)
                    }
                })
                .collect();
            let advice = sol.time_step_advice.as_ref();
            let warnings = crate::sim::output::input_warnings(
                &p.ground,
                sol.dt,
                advice,
                &sol.summary.segment_frequencies(),
            )
            .len()
                + crate::sim::output::run_warnings(crate::sim::output::Layout::Bridge, &sol).len()
                + usize::from(refined);
            (format!("{:?}", sol.status), String::new(), lim, warnings)
        }
    };
    RunRow {
        record: a,
        stripe: b,
        im_g,
        scale_factor: sf,
        status,
        error,
        limits: lim,
        warnings,
        seats: seats.0,
        governing_seat: seats.1,
    }
}

/// `runs.csv`: `record`, the metadata columns (sorted names), `level_g` (stripes) or `scale`
/// (IDA), `im_g`, `scale_factor`, `status`, then per limit state `<name>_exceeded` (`true`,
/// `false`, empty when excluded) and `<name>_ratio` (demand / capacity; `nan` when excluded),
/// `governing_seat_end` and `governing_seat_ratio` (the seated end of the largest ratio of peak
/// seat displacement to its own seat length, and that ratio), per seated end
/// `seat_ratio_<end>` (`seat_ratio_segment3_end`: [`crate::sim::bridge::BridgeModel::seat_end_names`] with `-` as
/// `_`; these cells are empty for a run that is not trusted), `warnings` (the number of the
/// run's warnings) and `error` last (the message of a failed run).
pub fn runs_csv(
    set: &RecordSet,
    plan: &Plan,
    limits: &[BoundLimit],
    seat_ends: &[String],
    rows: &[RunRow],
) -> String {
    let meta = set.meta_keys();
    let mut head: Vec<String> = vec!["record".into()];
    head.extend(meta.iter().cloned());
    head.push(match plan.stripes {
        Stripes::Levels(_) => "level_g".into(),
        Stripes::Scales(_) => "scale".into(),
    });
    head.extend(["im_g", "scale_factor", "status"].map(String::from));
    for l in limits {
        head.push(format!("{}_exceeded", l.state.name));
        head.push(format!("{}_ratio", l.state.name));
    }
    head.push("governing_seat_end".into());
    head.push("governing_seat_ratio".into());
    head.extend(seat_ends.iter().map(|e| seat_ratio_column(e)));
    head.push("warnings".into());
    head.push("error".into());
    let mut out = head.join(",") + "\n";
    for r in rows {
        let e = &set.records[r.record];
        let mut c: Vec<String> = vec![csv_field(&e.id)];
        for k in &meta {
            c.push(
                e.meta
                    .iter()
                    .find(|(n, _)| n == k)
                    .map_or(String::new(), |(_, v)| v.csv_cell()),
            );
        }
        c.push(float_token(plan.values()[r.stripe]));
        c.push(float_token(r.im_g));
        c.push(float_token(r.scale_factor));
        c.push(r.status.clone());
        for (ex, ratio) in &r.limits {
            c.push(ex.map_or(String::new(), |b| b.to_string()));
            c.push(float_token(*ratio));
        }
        match r.governing_seat {
            Some(g) => {
                c.push(seat_ends.get(g).cloned().unwrap_or_default());
                c.push(float_token(r.seats[g]));
            }
            None => c.extend([String::new(), String::new()]),
        }
        c.extend(
            (0..seat_ends.len()).map(|e| r.seats.get(e).map_or(String::new(), |x| float_token(*x))),
        );
        c.push(r.warnings.to_string());
        c.push(csv_field(&r.error));
        out += &(c.join(",") + "\n");
    }
    out
}

/// The `runs.csv` column of seated end `end` (`segment3-end` → `seat_ratio_segment3_end`).
pub fn seat_ratio_column(end: &str) -> String {
    format!("seat_ratio_{}", end.replace('-', "_"))
}

pub use super::run_fit::{FirstExceedance, exceedances, first_exceedance, fit_limit_state};
