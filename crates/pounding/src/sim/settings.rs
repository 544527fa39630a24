//! The settings of a run's time stepper ([`SimSettings`]) and its progress observer
//! ([`Progress`]).

use super::SimError;
use super::param::Setting;
use crate::lcp::LemkeSettings;
use crate::math::Real;

/// Settings of the time stepper (validated by [`SimSettings::validate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SimSettings {
    /// Time step `h > 0` \[s\]. Default 1e-3.
    pub dt: Real,
    /// Simulated duration \[s\]; `None` = the ground motion's last sample time. Default `None`.
    pub duration: Option<Real>,
    /// θ of the smooth part, in `[0.5, 1]`. Default 0.5 (trapezoidal rule).
    pub theta: Real,
    /// A step is an *impact* if some contact with `γ_N⁻ < −impact_velocity` gets `P_N > 0`
    /// \[m/s\]. Default 1e-3.
    pub impact_velocity: Real,
    /// Keep every `history_stride`-th step in [`super::bridge::BridgeSolution::t`] and the other histories (the last step always).
    /// Peaks are taken over every step regardless. Default 1.
    pub history_stride: usize,
    /// Settings of Lemke's method for the contact LCPs.
    pub lemke: LemkeSettings,
    /// Project the end position of every Moreau–Jean step onto the rigid sites' admissible set
    /// (combined projection, [`super::projection`]): every rigid-law gap `≥ −projection_tolerance`
    /// at every `t_k`. Default `false`.
    pub projection: bool,
    /// The gap a projection tolerates \[m\]. Default [`super::projection::DEFAULT_TOLERANCE`].
    pub projection_tolerance: Real,
    /// An observer of the run's progress (none by default): it sees, never changes, the run.
    pub progress: Progress,
}

impl Default for SimSettings {
    fn default() -> Self {
        Self {
            dt: super::defaults::DT,
            duration: None,
            theta: super::defaults::THETA,
            impact_velocity: super::defaults::IMPACT_VELOCITY,
            history_stride: super::defaults::HISTORY_STRIDE,
            lemke: LemkeSettings::default(),
            projection: false,
            projection_tolerance: super::projection::DEFAULT_TOLERANCE,
            progress: Progress::default(),
        }
    }
}

/// Steps between two calls of a [`Progress`] observer.
pub const PROGRESS_EVERY: usize = 64;

/// An observer of a run's progress: `f(steps done, total steps)`, called by the time loop before
/// the first step and every [`PROGRESS_EVERY`] steps (a front end's progress bar or time
/// estimate). Observers do not take part in the results: two settings that differ only in
/// their observer compare equal.
#[derive(Clone, Default)]
pub struct Progress(Option<std::sync::Arc<dyn Fn(usize, usize) + Send + Sync>>);

impl Progress {
    /// An observer calling `f`.
    pub fn new(f: impl Fn(usize, usize) + Send + Sync + 'static) -> Self {
        Self(Some(std::sync::Arc::new(f)))
    }

    /// Reports `done` of `total` steps (nothing without an observer).
    pub fn report(&self, done: usize, total: usize) {
        if let Some(f) = &self.0 {
            f(done, total);
        }
    }
}

impl std::fmt::Debug for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "Progress(observer)"
        } else {
            "Progress(none)"
        })
    }
}

impl PartialEq for Progress {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl SimSettings {
    /// The one check of a time step `dt`: finite and `> 0` (the error's path is
    /// [`Setting::Dt`], its message `invalid dt = …: must be finite and > 0`). Every entry that
    /// takes a step calls it: [`SimSettings::validate`] (so [`super::simulate`], a scenario's
    /// `[time] dt` and `simulate --dt`) and `compare --dt` ([`super::compare::CompareFlags`]).
    pub fn check_dt(dt: Real) -> Result<(), SimError> {
        if dt.is_finite() && dt > 0.0 {
            Ok(())
        } else {
            Err(SimError::invalid(Setting::Dt, dt, "must be finite and > 0"))
        }
    }

    /// Validates the settings (errors name the parameter).
    pub fn validate(&self) -> Result<(), SimError> {
        Self::check_dt(self.dt)?;
        if let Some(d) = self.duration
            && !(d.is_finite() && d > 0.0)
        {
            return Err(SimError::invalid(
                Setting::Duration,
                d,
                "must be finite and > 0",
            ));
        }
        if !(self.theta.is_finite() && (0.5..=1.0).contains(&self.theta)) {
            return Err(SimError::invalid(
                "theta",
                self.theta,
                "must lie in [0.5, 1]",
            ));
        }
        if !(self.impact_velocity.is_finite() && self.impact_velocity >= 0.0) {
            return Err(SimError::invalid(
                "impact_velocity",
                self.impact_velocity,
                "must be finite and >= 0",
            ));
        }
        let tol = self.projection_tolerance;
        if !(tol.is_finite() && tol > 0.0) {
            return Err(SimError::invalid(
                "projection_tolerance",
                tol,
                "must be finite and > 0",
            ));
        }
        if self.history_stride == 0 {
            return Err(SimError::invalid(
                Setting::HistoryStride,
                0.0,
                "must be >= 1",
            ));
        }
        Ok(())
    }

    /// Number of steps `⌈duration/dt⌉` (at least 1) of a run of `duration` seconds, refused beyond
    /// [`MAX_STEPS`].
    pub fn step_count(&self, duration: Real) -> Result<usize, SimError> {
        let n = ((duration / self.dt) - 1e-9).ceil().max(1.0);
        if n.is_nan() || n > MAX_STEPS as Real {
            return Err(SimError::invalid(
                Setting::Dt,
                self.dt,
                &format!(
                    "duration / dt = {} s / {} s = {} steps is more than the limit {MAX_STEPS}",
                    crate::output::float_token(duration),
                    crate::output::float_token(self.dt),
                    crate::output::float_token(n)
                ),
            ));
        }
        Ok(n as usize)
    }
}

/// Largest number of time steps of one run (each step stores its ground acceleration).
pub const MAX_STEPS: usize = 200_000_000;
