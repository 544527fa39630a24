//! The rigid law's peak-force estimate of a run (from each impact's impulse and a contact
//! duration, [`crate::contact_law::estimate`]): per impact row of `impacts.csv`, the run's
//! largest in `summary.json` (`peak_force_estimate_n`) and per law in `compare.csv`.

use super::super::{ImpactRecord, SimContact};
use crate::contact_law::estimate::{PeakForceEstimate, rigid_peak_force};
use crate::math::Real;
use crate::output::json_float;
use std::collections::BTreeMap;

/// The peak-force estimate of a rigid impact record at one corner contact: the default joint
/// `k_h` shared by the site's two corner contacts (`k_h / 2` per corner, as the compliance laws
/// share a joint's law, [`crate::contact_law::sharing`]).
pub(crate) fn rigid_estimate(r: &ImpactRecord, eps: Real) -> PeakForceEstimate {
    rigid_peak_force(
        r.impulse_n,
        r.gamma_n_pre,
        eps,
        0.5 * crate::contact_law::registry::default_k_h(),
    )
}

/// A contact site: `(is a joint, index)` (joint `k`, or the abutment of side/deck `k`), ordered
/// joints after abutments (`false < true`).
pub type SiteKey = (bool, usize);

/// The estimate of a site or a run: the largest over its impacts of the sum of the site's corner
/// estimates in that impact (a rigid impact is one step, so its corner pulses coincide), and the
/// contact duration of that impact (the duration of its corner with the largest estimate).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakEstimate {
    /// Estimated peak force \[N\].
    pub peak_force: Real,
    /// Estimated contact duration of that impact \[s\].
    pub contact_time: Real,
}

/// The estimate of every site that had a rigid impact with an estimate (`records`: each rigid
/// impact record with its site's restitution), by site.
pub fn peak_force_estimates<'a>(
    records: impl Iterator<Item = (&'a ImpactRecord, Real)>,
) -> BTreeMap<SiteKey, PeakEstimate> {
    // per (impact, site): the sum of the corner forces, and the largest corner's (force, t_c)
    let mut sums = BTreeMap::<(usize, SiteKey), (Real, Real, Real)>::new();
    for (r, eps) in records {
        let e = rigid_estimate(r, eps);
        if !e.peak_force.is_nan() {
            let site = (matches!(r.contact, SimContact::Joint(_)), r.site);
            let s = sums
                .entry((r.impact, site))
                .or_insert((0.0, Real::NEG_INFINITY, Real::NAN));
            s.0 += e.peak_force;
            if e.peak_force > s.1 {
                (s.1, s.2) = (e.peak_force, e.contact_time);
            }
        }
    }
    let mut out = BTreeMap::<SiteKey, PeakEstimate>::new();
    for ((_, site), (force, _, t_c)) in sums {
        let e = out.entry(site).or_insert(PeakEstimate {
            peak_force: Real::NEG_INFINITY,
            contact_time: Real::NAN,
        });
        if force > e.peak_force {
            *e = PeakEstimate {
                peak_force: force,
                contact_time: t_c,
            };
        }
    }
    out
}

/// The largest of `estimates` (the first of equal forces in site order); `None` when empty.
pub(crate) fn largest_estimate(
    estimates: &BTreeMap<SiteKey, PeakEstimate>,
) -> Option<PeakEstimate> {
    estimates
        .values()
        .copied()
        .reduce(|a, b| if b.peak_force > a.peak_force { b } else { a })
}

/// `summary.json`'s `peak_force_estimate_n` of a rigid run: the largest over the impacts and
/// sites of the sum of the site's corner estimates in that impact ([`peak_force_estimates`]);
/// `null` without impacts.
pub(crate) fn peak_estimate_json<'a>(
    records: impl Iterator<Item = (&'a ImpactRecord, Real)>,
) -> serde_json::Value {
    largest_estimate(&peak_force_estimates(records))
        .map_or(serde_json::Value::Null, |e| json_float(e.peak_force))
}

/// The estimates of a run of `setup` by site, as its `summary.json` computes
/// `peak_force_estimate_n`: `None` when no contact site of the run is rigid (the compliance laws
/// compute their forces), else the rigid sites' estimates (empty without impacts).
pub(crate) fn setup_estimates(
    m: &crate::sim::bridge::BridgeModel,
    sol: &crate::sim::bridge::BridgeSolution,
) -> Option<BTreeMap<SiteKey, PeakEstimate>> {
    let records = sol.impacts.iter().filter(|r| r.pulse.is_none());
    super::impacts::site_kinds(m)
        .0
        .then(|| peak_force_estimates(records.map(|r| (r, super::impacts::site_restitution(m, r)))))
}
