//! The limits of a synthetic suite and the checks against them: every parameter on its own
//! range before anything is generated, the suite's count and size, the seed.

use super::{SynthError, SynthParams};
use crate::math::Real;
use std::f64::consts::PI;

/// Largest number of records of one suite.
pub const MAX_COUNT: usize = 10_000;
/// Largest number of samples of one component.
pub const MAX_SAMPLES: usize = 10_000_000;
/// Largest number of values (records × components × samples) of one suite: the suite is
/// generated in memory (400 MB of `f64`), five times `motion svgm`'s per-realisation bound
/// [`crate::ground_motion::svgm::MAX_VALUES`]; 10000 pairs of the default 20 s at 0.01 s (4.002e7) fit.
pub const MAX_SUITE_VALUES: usize = 5 * crate::ground_motion::svgm::MAX_VALUES;
/// Largest seed: the seed is written as a TOML integer (`[record.meta] seed`), and TOML
/// integers stop at 2^63 − 1.
pub const MAX_SEED: u64 = i64::MAX as u64;
/// Fewest steps of `dt` in `duration` (a record of fewer is refused).
pub const MIN_STEPS: usize = 100;
/// Longest `--duration` \[s\] (about 14 h: half of [`MAX_SAMPLES`] at the default 0.01 s).
pub const MAX_DURATION: Real = 5e4;
/// Smallest `omega_g`, `omega_f` \[rad/s\].
pub const MIN_OMEGA: Real = 0.01;
/// Largest `s0` \[m²/s³\] (with the default filters, a PGA of the order of 100 g).
pub const MAX_S0: Real = 1e3;
/// Smallest `zeta_g`, `zeta_f`.
pub const MIN_ZETA: Real = 0.01;
/// Largest `--pga` \[g\] (the largest recorded PGAs are about 3–4 g).
pub const MAX_PGA_G: Real = 10.0;

fn bad(name: &str, value: impl ToString, reason: &str) -> SynthError {
    SynthError::InvalidParameter {
        name: name.into(),
        value: value.to_string(),
        reason: reason.into(),
    }
}

/// [`bad`] for a number, written as the project writes numbers (`nan`, `inf`, shortest).
fn bad_real(name: &str, value: Real, reason: &str) -> SynthError {
    bad(name, crate::output::float_token(value), reason)
}

/// A parameter's name, value, whether it is in range and the range in words.
type RangeCheck = (&'static str, Real, fn(Real) -> bool, &'static str);

impl SynthParams {
    /// Checks every parameter (finite, in range; `--duration` at most [`MAX_DURATION`]; `--pga` in
    /// (0, [`MAX_PGA_G`]] g; `omega_g`, `omega_f` in [[`MIN_OMEGA`], π/dt) (below the Nyquist
    /// frequency); `zeta_g`, `zeta_f` in [[`MIN_ZETA`], 1); `epsilon` in (0, 0.5]; `eta` in
    /// [1e-6, 1); `s0` in (0, [`MAX_S0`]]; `duration` a whole number of at least [`MIN_STEPS`] steps of `dt`; fewer than [`MAX_SAMPLES`] samples).
    pub fn check(&self) -> Result<(), SynthError> {
        let pos = |name: &str, v: Real| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(bad_real(name, v, "must be finite and > 0"))
            }
        };
        pos("--dt", self.dt)?;
        pos("--duration", self.duration)?;
        if self.duration > MAX_DURATION {
            return Err(bad_real(
                "--duration",
                self.duration,
                &format!("must not exceed {MAX_DURATION} s"),
            ));
        }
        if let Some(p) = self.pga_g {
            pos("--pga", p)?;
            if p > MAX_PGA_G {
                return Err(bad_real(
                    "--pga",
                    p,
                    &format!("must lie in (0, {MAX_PGA_G}] g"),
                ));
            }
        }
        if self.dt > self.duration {
            return Err(bad_real(
                "--dt",
                self.dt,
                &format!(
                    "must not exceed --duration = {}",
                    crate::output::float_token(self.duration)
                ),
            ));
        }
        let steps = self.duration / self.dt;
        if steps >= MAX_SAMPLES as Real {
            return Err(bad_real(
                "--dt",
                self.dt,
                &format!(
                    "with --duration = {} gives {} samples; --duration / --dt must stay below \
                     {MAX_SAMPLES} samples",
                    crate::output::float_token(self.duration),
                    crate::output::float_token(steps.round())
                ),
            ));
        }
        if (steps - steps.round()).abs() > 1e-9 * steps {
            let (lo, hi) = (steps.floor() * self.dt, steps.ceil() * self.dt);
            return Err(bad_real(
                "--duration",
                self.duration,
                &format!(
                    "is not a whole number of steps of --dt = {} ({} steps); give e.g. \
                     --duration {} or {}",
                    crate::output::float_token(self.dt),
                    crate::output::float_token(steps),
                    crate::output::float_token((lo * 1e9).round() / 1e9),
                    crate::output::float_token((hi * 1e9).round() / 1e9)
                ),
            ));
        }
        // the step count rounded as the whole-number check above allows (0.7 / 0.007 is
        // 100.00000000000001 steps in floating point, 0.007 × 100 is 0.7000000000000001)
        if steps.round() < MIN_STEPS as Real {
            return Err(bad_real(
                "--duration",
                self.duration,
                &format!(
                    "must be at least {MIN_STEPS} steps of --dt = {} ({} s): a shorter record \
                     is not a ground motion (it could even be all zeros)",
                    crate::output::float_token(self.dt),
                    crate::output::float_token(MIN_STEPS as Real * self.dt)
                ),
            ));
        }
        // The model's parameters, each on its own range (after dt, on which the Nyquist bound
        // depends), so that no combination overflows: a filter frequency at or above the
        // Nyquist frequency π/dt is not represented by the samples (its one-step matrix
        // exponential overflows long before 1e6 rad/s); below 0.01 rad/s (a period over 600 s),
        // with a damping below 0.01 or an `s0` above 1e3 m²/s³ the stationary covariance
        // overflows or is singular in floating point; ε above 0.5 or η below 1e-6 overflow the
        // envelope's factor (e/ε)^b.
        let nyquist = PI / self.dt;
        for (n, v) in [("omega_g", self.omega_g), ("omega_f", self.omega_f)] {
            if !(v.is_finite() && (MIN_OMEGA..nyquist).contains(&v)) {
                return Err(bad_real(
                    n,
                    v,
                    &format!(
                        "must lie in [{MIN_OMEGA}, π / dt) rad/s, below the Nyquist frequency \
                         π / dt = {} rad/s of dt = {}",
                        crate::output::float_token(nyquist),
                        crate::output::float_token(self.dt)
                    ),
                ));
            }
        }
        pos("s0", self.s0)?;
        if self.s0 > MAX_S0 {
            return Err(bad_real(
                "s0",
                self.s0,
                &format!("must lie in (0, {MAX_S0}] m²/s³"),
            ));
        }
        let ranges: [RangeCheck; 4] = [
            (
                "zeta_g",
                self.zeta_g,
                |v| (MIN_ZETA..1.0).contains(&v),
                "[0.01, 1)",
            ),
            (
                "zeta_f",
                self.zeta_f,
                |v| (MIN_ZETA..1.0).contains(&v),
                "[0.01, 1)",
            ),
            ("epsilon", self.epsilon, |v| v > 0.0 && v <= 0.5, "(0, 0.5]"),
            ("eta", self.eta, |v| (1e-6..1.0).contains(&v), "[1e-6, 1)"),
        ];
        for (n, v, ok, what) in ranges {
            if !(v.is_finite() && ok(v)) {
                return Err(bad_real(n, v, &format!("must lie in {what}")));
            }
        }
        Ok(())
    }
}

/// Checks `1 ≤ count ≤` [`MAX_COUNT`].
pub fn check_count(count: usize) -> Result<(), SynthError> {
    if count == 0 || count > MAX_COUNT {
        return Err(bad(
            "--count",
            count,
            &format!("must lie in 1..={MAX_COUNT}"),
        ));
    }
    Ok(())
}

/// Checks `seed ≤` [`MAX_SEED`] (`--seed`): a larger seed could not be read back from the
/// files that record it.
pub fn check_seed(seed: u64) -> Result<(), SynthError> {
    if seed > MAX_SEED {
        return Err(bad(
            "--seed",
            seed,
            &format!(
                "must lie in 0..={MAX_SEED} (2^63 - 1, the largest integer a TOML file holds: \
                 the seed is written to the suite's manifest)"
            ),
        ));
    }
    Ok(())
}

/// Checks that the suite of `count` records (two components each with `pairs`) of the checked
/// parameters `p` holds at most [`MAX_SUITE_VALUES`] values (`--count`): the whole suite is
/// generated in memory.
pub fn check_suite_size(p: &SynthParams, count: usize, pairs: bool) -> Result<(), SynthError> {
    let components = if pairs { 2 } else { 1 };
    let samples = p.samples();
    let values = count.saturating_mul(components).saturating_mul(samples);
    if values > MAX_SUITE_VALUES {
        return Err(bad(
            "--count",
            count,
            &format!(
                "with --dt = {} and --duration = {} gives {count} records x {components} \
                 component(s) x {samples} samples = {values} values in the suite (generated in \
                 memory); keep count x components x samples at most {MAX_SUITE_VALUES} (fewer \
                 records, a shorter --duration or a larger --dt)",
                crate::output::float_token(p.dt),
                crate::output::float_token(p.duration)
            ),
        ));
    }
    Ok(())
}
