//! The data of a fragility fit from a study's runs: exceedances per entry and stripe, IDA first
//! exceedances, and the fit of one limit state.

use super::run::{Plan, RunRow};
use super::settings::Stripes;
use crate::math::Real;

/// `exceeded[entry][stripe]` of limit state `l` (`None` for excluded runs).
pub fn exceedances(
    rows: &[RunRow],
    entries: usize,
    stripes: usize,
    l: usize,
) -> Vec<Vec<Option<bool>>> {
    let mut out = vec![vec![None; stripes]; entries];
    for r in rows {
        out[r.record][r.stripe] = r.limits[l].0;
    }
    out
}

/// IDA: what the runs of one entry say about its first exceedance of a limit state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FirstExceedance {
    /// Exceeded first at this IM \[g\] (interpolated, [`first_exceedance`]).
    At(Real),
    /// Never exceeded within the scales run (a censored record).
    NotWithin,
    /// An excluded run comes before the first exceedance: the crossing is unknown and the entry
    /// is left out of the fit.
    Unknown,
}

/// IDA: the first exceedance of limit state `l` for each entry, from its runs in increasing
/// scale. Between the last run not exceeding (ratio `r₀` at `IM₀`) and the first exceeding
/// (`r₁` at `IM₁`) the ratio is interpolated linearly in IM to where it reaches 1,
/// `IM₀ + (1 − r₀)/(r₁ − r₀) (IM₁ − IM₀)`, clamped to `[IM₀, IM₁]` (unseating, whose flag is
/// checked per end, may cross outside); exceeded already at the smallest scale: that run's IM
/// (an upper bound of the crossing).
pub fn first_exceedance(
    rows: &[RunRow],
    entries: usize,
    stripes: usize,
    l: usize,
) -> Vec<FirstExceedance> {
    (0..entries)
        .map(|a| {
            let mut prev: Option<(Real, Real)> = None;
            for r in &rows[a * stripes..(a + 1) * stripes] {
                let (ex, r1) = r.limits[l];
                match ex {
                    None => return FirstExceedance::Unknown,
                    Some(false) => prev = Some((r.im_g, r1)),
                    Some(true) => {
                        let im1 = r.im_g;
                        return FirstExceedance::At(match prev {
                            None => im1,
                            Some((im0, r0)) => {
                                let x = im0 + (1.0 - r0) / (r1 - r0) * (im1 - im0);
                                if x.is_finite() {
                                    x.clamp(im0, im1)
                                } else {
                                    im1
                                }
                            }
                        });
                    }
                }
            }
            FirstExceedance::NotWithin
        })
        .collect()
}

/// The fit of one limit state: multiple stripes by maximum likelihood
/// ([`crate::fragility::bootstrap_stripes`]); IDA from the first exceedance of each entry
/// ([`crate::fragility::bootstrap_ida_censored`]): an entry crossing between two scales is an
/// exact observation, one never exceeding is right-censored at its largest IM, one exceeding
/// already at the smallest scale is left-censored at that IM, one with an unknown crossing is
/// left out. Without a censored entry the method of moments, else the censored MLE
/// ([`crate::fragility::censored`]). With `bootstrap.samples = 0` no intervals. `band_im`: the
/// IMs of the bootstrap band.
pub fn fit_limit_state(
    name: &str,
    plan: &Plan,
    rows: &[RunRow],
    l: usize,
    bootstrap: &crate::fragility::BootstrapSettings,
    band_im: &[Real],
) -> Result<crate::fragility::FragilityRow, crate::fragility::FragilityError> {
    use crate::fragility::{
        CensoredIdaData, FragilityRow, IdaRecord, StripeData, bootstrap_ida_censored,
        bootstrap_stripes,
    };
    let (entries, ns) = (plan.entry_im.len(), plan.values().len());
    match &plan.stripes {
        Stripes::Levels(levels) => {
            let d = StripeData {
                im: levels.clone(),
                exceeded: exceedances(rows, entries, ns, l),
            };
            let b = (bootstrap.samples > 0)
                .then(|| bootstrap_stripes(&d, bootstrap, band_im))
                .transpose()?;
            FragilityRow::from_stripes(name, &d, b)
        }
        Stripes::Scales(_) => {
            let d = CensoredIdaData {
                records: first_exceedance(rows, entries, ns, l)
                    .into_iter()
                    .enumerate()
                    .filter_map(|(a, f)| match f {
                        // Exceeded at the smallest scale: that IM is only an upper bound.
                        FirstExceedance::At(x) if rows[a * ns].limits[l].0 == Some(true) => {
                            Some(IdaRecord::ExceededAtFirst(x))
                        }
                        FirstExceedance::At(x) => Some(IdaRecord::Exceeded(x)),
                        FirstExceedance::NotWithin if ns > 0 => {
                            Some(IdaRecord::NotExceeded(plan.point(a, ns - 1).0))
                        }
                        FirstExceedance::NotWithin | FirstExceedance::Unknown => None,
                    })
                    .collect(),
            };
            if d.records.is_empty() {
                return Ok(FragilityRow {
                    limit_state: name.to_string(),
                    method: crate::fragility::Method::MomentsIda,
                    fit: crate::fragility::Fit::NoFiniteMle(crate::fragility::NoMle::TooFewPoints),
                    bootstrap: None,
                    n_records: 0,
                    n_runs: 0,
                });
            }
            let b = (bootstrap.samples > 0)
                .then(|| bootstrap_ida_censored(&d, bootstrap, band_im))
                .transpose()?;
            FragilityRow::from_ida_censored(name, &d, b)
        }
    }
}
