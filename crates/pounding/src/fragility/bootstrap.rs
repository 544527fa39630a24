//! Bootstrap confidence intervals over records.
//!
//! The records are the independent units of a fragility study (one record's outcomes at different
//! stripes are correlated: the same record drives every run). Each bootstrap replicate draws
//! `n_records` records **with replacement** (a record drawn twice counts twice), refits the same
//! way as the data ([`super::fit_stripes`] or [`super::fit_ida`]) and keeps `(θ_b, β_b)`. The
//! intervals are **BCa** (bias-corrected and accelerated) percentile intervals (Efron 1987;
//! Efron & Tibshirani 1993, §14.3, see [`bca`]) of the replicates with a finite fit: percentiles of
//! the replicates (linear interpolation between order statistics, Hyndman & Fan type 7) at levels
//! shifted from `(1 ∓ level)/2` by the median bias `z₀` of the replicates and the acceleration `a`
//! from a leave-one-record-out jackknife. Plain percentile intervals undercover the dispersion
//! with tens of records (β̂ is biased low, the percentiles inherit it): in the coverage test
//! (40 records, β = 0.4, 200 data sets) they held the true β in 89 % of data sets, BCa in more.
//! The band is the same, pointwise, for `Φ((ln x − ln θ_b)/β_b)` at each requested IM `x`.
//!
//! Replicates without a finite fit (e.g. a resample that happens to be perfectly separated) are
//! excluded and **counted** ([`Bootstrap::failed`]); the intervals describe the others. No intervals
//! are given when the data themselves have no fit, or when fewer than two replicates have one.
//!
//! Determinism: replicate `b` draws from `ChaCha8Rng::seed_from_u64(seed)` switched to stream `b`
//! (`set_stream`), so each replicate's draws depend only on `(seed, b)`, and the replicates are
//! collected in order: the result is identical for any number of threads.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::censored::{IdaRecord, fit_by};
use super::mle::fit_counts;
use super::moments::fit_values;
use super::normal::{cdf, quantile};
use super::{Fit, FragilityError, IdaData, StripeData, check_positive};
use crate::math::Real;

/// How to bootstrap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BootstrapSettings {
    /// Number of replicates (≥ 1; 1,000 is usual).
    pub samples: usize,
    /// Seed of the random draws.
    pub seed: u64,
    /// Confidence level of the intervals, in (0, 1) (0.95 for 95 %).
    pub level: Real,
}

impl Default for BootstrapSettings {
    fn default() -> Self {
        BootstrapSettings {
            samples: 1000,
            seed: 1,
            level: 0.95,
        }
    }
}

impl BootstrapSettings {
    /// Refuses `samples = 0` and a level outside (0, 1).
    pub fn validate(&self) -> Result<(), FragilityError> {
        if self.samples == 0 {
            return Err(FragilityError::BadSetting {
                field: "samples",
                value: "0".into(),
                reason: "must be at least 1",
            });
        }
        if !(self.level > 0.0 && self.level < 1.0) {
            return Err(FragilityError::BadSetting {
                field: "level",
                value: crate::output::float_token(self.level),
                reason: "must be strictly between 0 and 1 (0.95 for 95 %)",
            });
        }
        Ok(())
    }
}

/// One IM of the pointwise band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandPoint {
    /// The IM.
    pub im: Real,
    /// `P(exceed | im)` of the fit to the data (`None` without a fit).
    pub p: Option<Real>,
    /// Lower and upper percentile of the replicates' `P(exceed | im)` (`None` without intervals).
    pub interval: Option<(Real, Real)>,
}

/// The result of a bootstrap.
#[derive(Debug, Clone, PartialEq)]
pub struct Bootstrap {
    /// The fit to the data themselves.
    pub fit: Fit,
    /// Number of replicates drawn.
    pub samples: usize,
    /// Replicates without a finite fit (excluded from the intervals).
    pub failed: usize,
    /// The confidence level.
    pub level: Real,
    /// Percentile interval of `θ` (`None` when the data have no fit or fewer than two replicates do).
    pub theta: Option<(Real, Real)>,
    /// Percentile interval of `β` (same condition).
    pub beta: Option<(Real, Real)>,
    /// Pointwise band of `P(exceed | IM)` at the requested IMs, in the order given.
    pub band: Vec<BandPoint>,
    /// `(θ_b, β_b)` of every replicate, in replicate order (`None`: no finite fit). Replicate
    /// `b` resamples the records drawn from stream `b` of the seed: two bootstraps with the same
    /// seed over the same number of records resample the same record indices (paired).
    pub replicates: Vec<Option<(Real, Real)>>,
    /// `(θ, β)` with each record left out in turn (the jackknife of the BCa acceleration).
    pub jackknife: Vec<Option<(Real, Real)>>,
}

impl Bootstrap {
    /// The BCa interval ([`bca`]) of any statistic `f(θ, β)` of the fit, from the same replicates
    /// and jackknife as the intervals of `θ` and `β` (`None` when the data have no fit or fewer
    /// than two replicates do; replicates or jackknife fits where `f` is not finite are left out).
    pub fn interval_of(&self, f: &dyn Fn(Real, Real) -> Real) -> Option<(Real, Real)> {
        let (t, b) = self.fit.params()?;
        let boot: Vec<Real> = self
            .replicates
            .iter()
            .flatten()
            .map(|&(t, b)| f(t, b))
            .filter(|v| v.is_finite())
            .collect();
        let jack: Option<Vec<Real>> = self
            .jackknife
            .iter()
            .map(|p| p.map(|(t, b)| f(t, b)).filter(|v| v.is_finite()))
            .collect();
        let est = f(t, b);
        (boot.len() >= 2 && est.is_finite()).then(|| bca(est, boot, jack.as_deref(), self.level))
    }
}

/// Bootstraps a multiple-stripe fit over records (rows of `exceeded`); `band_im` are the IMs of
/// the pointwise band (finite, > 0; may be empty).
pub fn bootstrap_stripes(
    d: &StripeData,
    settings: &BootstrapSettings,
    band_im: &[Real],
) -> Result<Bootstrap, FragilityError> {
    d.validate()?;
    settings.validate()?;
    check_positive("band_im", band_im)?;
    let fit = fit_counts(&d.counts());
    let rows = d.exceeded.len();
    let refit = |pick: &[usize]| {
        let mut counts: Vec<(Real, usize, usize)> = d.im.iter().map(|&x| (x, 0, 0)).collect();
        for &r in pick {
            for (c, o) in counts.iter_mut().zip(&d.exceeded[r]) {
                if let Some(e) = o {
                    c.1 += 1;
                    c.2 += usize::from(*e);
                }
            }
        }
        fit_counts(&counts)
    };
    Ok(resample(fit, settings, band_im, rows, &refit))
}

/// Bootstraps an IDA (method-of-moments) fit over records; `band_im` as in [`bootstrap_stripes`].
pub fn bootstrap_ida(
    d: &IdaData,
    settings: &BootstrapSettings,
    band_im: &[Real],
) -> Result<Bootstrap, FragilityError> {
    d.validate()?;
    settings.validate()?;
    check_positive("band_im", band_im)?;
    let fit = fit_values(&d.im_at_exceedance);
    let refit = |pick: &[usize]| {
        let sample: Vec<Option<Real>> = pick.iter().map(|&r| d.im_at_exceedance[r]).collect();
        fit_values(&sample)
    };
    Ok(resample(
        fit,
        settings,
        band_im,
        d.im_at_exceedance.len(),
        &refit,
    ))
}

/// Bootstraps an IDA fit with censoring bounds over records; `band_im` as in
/// [`bootstrap_stripes`]. The estimator is chosen once, from the data
/// ([`super::CensoredIdaData::method`]), and every replicate and jackknife fit uses it: data with a
/// censored record refit every resample by the censored MLE, also a resample that happens to
/// draw no censored record (mixing estimators would mix their biases into one interval). Without
/// a censored record this is [`bootstrap_ida`] on the exceedance IMs (the same numbers).
pub fn bootstrap_ida_censored(
    d: &super::CensoredIdaData,
    settings: &BootstrapSettings,
    band_im: &[Real],
) -> Result<Bootstrap, FragilityError> {
    d.validate()?;
    settings.validate()?;
    check_positive("band_im", band_im)?;
    let method = d.method();
    let fit = fit_by(method, &d.records);
    let refit = |pick: &[usize]| {
        let sample: Vec<IdaRecord> = pick.iter().map(|&r| d.records[r]).collect();
        fit_by(method, &sample)
    };
    Ok(resample(fit, settings, band_im, d.records.len(), &refit))
}

/// The bootstrap of `fit`: `refit` applied to the resamples and the leave-one-out sets of `rows`
/// records, summarised.
fn resample<F>(
    fit: Fit,
    settings: &BootstrapSettings,
    band_im: &[Real],
    rows: usize,
    refit: &F,
) -> Bootstrap
where
    F: Fn(&[usize]) -> Fit + Sync,
{
    let fits = replicates(settings, rows, refit);
    let jack = jackknife(rows, refit);
    summarise(fit, settings, band_im, &fits, &jack)
}

/// Fits of `settings.samples` resamples of `rows` records, in replicate order.
fn replicates<F>(settings: &BootstrapSettings, rows: usize, refit: &F) -> Vec<Fit>
where
    F: Fn(&[usize]) -> Fit + Sync,
{
    (0..settings.samples)
        .into_par_iter()
        .map_init(Vec::new, |pick: &mut Vec<usize>, b| {
            let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
            rng.set_stream(b as u64);
            pick.clear();
            pick.extend((0..rows).map(|_| rng.random_range(0..rows)));
            refit(pick)
        })
        .collect()
}

/// Fits of the data with each record left out in turn (the jackknife of the BCa acceleration).
fn jackknife<F>(rows: usize, refit: &F) -> Vec<Fit>
where
    F: Fn(&[usize]) -> Fit + Sync,
{
    (0..rows)
        .into_par_iter()
        .map(|left_out| {
            let pick: Vec<usize> = (0..rows).filter(|&r| r != left_out).collect();
            refit(&pick)
        })
        .collect()
}

fn summarise(
    fit: Fit,
    settings: &BootstrapSettings,
    band_im: &[Real],
    fits: &[Fit],
    jack: &[Fit],
) -> Bootstrap {
    let ok: Vec<(Real, Real)> = fits.iter().filter_map(Fit::params).collect();
    let failed = fits.len() - ok.len();
    let jack_all = jack;
    // The acceleration needs every leave-one-out fit; without them it is 0 (bias-corrected only).
    let jack: Option<Vec<(Real, Real)>> = jack_all.iter().map(Fit::params).collect();
    let have = ok.len() >= 2;
    let stat = |f: &dyn Fn((Real, Real)) -> Real| -> Option<(Real, Real)> {
        let (t, b) = fit.params()?;
        let boot: Vec<Real> = ok.iter().map(|&p| f(p)).collect();
        let jk: Option<Vec<Real>> = jack.as_ref().map(|j| j.iter().map(|&p| f(p)).collect());
        have.then(|| bca(f((t, b)), boot, jk.as_deref(), settings.level))
    };
    let theta = stat(&|p| p.0);
    let beta = stat(&|p| p.1);
    let band = band_im
        .iter()
        .map(|&x| BandPoint {
            im: x,
            p: fit.probability(x),
            interval: stat(&|(t, b)| cdf((x.ln() - t.ln()) / b)),
        })
        .collect();
    Bootstrap {
        fit,
        samples: settings.samples,
        failed,
        level: settings.level,
        theta,
        beta,
        band,
        replicates: fits.iter().map(Fit::params).collect(),
        jackknife: jack_all.iter().map(Fit::params).collect(),
    }
}

/// The BCa interval (Efron & Tibshirani 1993, §14.3) of a statistic with estimate `est`,
/// bootstrap values `boot` and leave-one-out values `jack`:
///
/// ```text
/// z₀ = Φ⁻¹( (#{θ*_b < θ̂} + ½ #{θ*_b = θ̂}) / B ),
/// a  = Σ (θ̄₍·₎ − θ₍ᵢ₎)³ / (6 [Σ (θ̄₍·₎ − θ₍ᵢ₎)²]^{3/2}),
/// α₁,₂ = Φ( z₀ + (z₀ + z_q) / (1 − a (z₀ + z_q)) ),   q = (1 ∓ level)/2,
/// ```
///
/// the interval being the `α₁` and `α₂` percentiles of `boot`. `a = 0` without jackknife values
/// (or when they do not vary); `z₀` uses a proportion kept within `[½/B, 1 − ½/B]`.
pub fn bca(est: Real, mut boot: Vec<Real>, jack: Option<&[Real]>, level: Real) -> (Real, Real) {
    boot.sort_by(Real::total_cmp);
    let nb = boot.len() as Real;
    let below = boot.iter().filter(|&&v| v < est).count() as Real;
    let equal = boot.iter().filter(|&&v| v == est).count() as Real;
    let frac = ((below + 0.5 * equal) / nb).clamp(0.5 / nb, 1.0 - 0.5 / nb);
    let z0 = quantile(frac);
    let a = jack.map_or(0.0, |j| {
        let mean = j.iter().sum::<Real>() / j.len() as Real;
        let (s2, s3) = j.iter().fold((0.0, 0.0), |(s2, s3), &v| {
            let d = mean - v;
            (s2 + d * d, s3 + d * d * d)
        });
        let a = s3 / (6.0 * s2.powf(1.5));
        if a.is_finite() { a } else { 0.0 }
    });
    let adjusted = |q: Real| {
        let zq = quantile(q);
        let w = z0 + zq;
        let alpha = cdf(z0 + w / (1.0 - a * w));
        // A denominator ≤ 0 (extreme acceleration) would flip the tail: keep the plain quantile.
        if alpha.is_finite() && 1.0 - a * w > 0.0 {
            alpha
        } else {
            q
        }
    };
    let lo = adjusted(0.5 * (1.0 - level));
    let hi = adjusted(0.5 * (1.0 + level));
    (percentile(&boot, lo), percentile(&boot, hi))
}

/// The `q`-quantile of sorted values, linear interpolation between order statistics (type 7).
pub fn percentile(sorted: &[Real], q: Real) -> Real {
    let h = (sorted.len() - 1) as Real * q;
    let i = h.floor() as usize;
    let f = h - i as Real;
    match sorted.get(i + 1) {
        Some(&next) if f > 0.0 => sorted[i] + f * (next - sorted[i]),
        _ => sorted[i],
    }
}
