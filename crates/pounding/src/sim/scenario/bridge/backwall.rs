//! `[abutment.start.backwall]` / `[abutment.end.backwall]`: an abutment's backwall on backfill
//! and piles ([`crate::sim::bridge::Backwall`]).
//!
//! ```toml
//! [abutment.start.backwall]
//! mass = 1.0e5        # [kg]
//! kmax = 2.436e8      # backfill (OpenSees HyperbolicGapMaterial): initial stiffness [N/m],
//! kur = 2.436e8       #   unloading/reloading stiffness [N/m] (default kmax),
//! rf = 0.7            #   failure ratio in (0, 1) (default 0.7),
//! fult = 3.912e6      #   ultimate passive force [N],
//! backfill_gap = 0.0  #   gap behind the wall [m] (default 0)
//! # or, instead of kmax/kur/fult: Caltrans SDC 2019 from the wall's size
//! # height = 2.0     # [m]
//! # width = 12.0     # [m]
//! # skew_deg = 0.0   # [deg]
//! piles_k = 6.3e7     # piles, elastic-perfectly-plastic both ways: stiffness [N/m]
//! piles_fy = 1.071e6  #   yield force [N]
//!
//! [abutment.start.shear_keys]   # exterior keys across the deck end (OpenSees ElasticPPGap pair)
//! k = 2.0e8           # [N/m]
//! fy = 1.8e6          # capacity of each key [N]
//! gap = 0.015         # on each side [m]
//! after_yield = "permanent"  # a yielded key keeps its set (OpenSees `damage`, the default), or
//!                     # "recentering" (OpenSees' default `noDamage`)
//! ```

use super::{Sp, Val};
use crate::element::backfill::{CaltransBackwall, HyperbolicGap};
use crate::sim::bridge::{Backwall, Piles};
use crate::sim::scenario::ScenarioError;
use serde::Deserialize;
use toml::Spanned;

/// One backwall table as read by `serde`.
#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(super) struct BackwallSec {
    mass: Sp<f64>,
    kmax: Sp<f64>,
    kur: Sp<f64>,
    rf: Sp<f64>,
    fult: Sp<f64>,
    backfill_gap: Sp<f64>,
    height: Sp<f64>,
    width: Sp<f64>,
    skew_deg: Sp<f64>,
    piles_k: Sp<f64>,
    piles_fy: Sp<f64>,
}

/// One shear-keys table as read by `serde`.
#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(super) struct ShearKeysSec {
    k: Sp<f64>,
    fy: Sp<f64>,
    gap: Sp<f64>,
    after_yield: Sp<String>,
}

/// The shear keys of abutment `side` from their table.
pub(super) fn shear_keys(
    v: &Val,
    side: usize,
    t: &Spanned<ShearKeysSec>,
) -> Result<crate::element::shear_key::ShearKey, ScenarioError> {
    let name = crate::sim::bridge::ABUTMENT_SIDES[side];
    let key = |k: &str| format!("abutment.{name}.shear_keys.{k}");
    let s = t.get_ref();
    let pos = |k: &str, x: &Sp<f64>| match x {
        None => Err(v.err(key(k), Some(v.line(t)), format!("{} is required", key(k)))),
        some => v.pos(key(k), some, None),
    };
    let k = pos("k", &s.k)?;
    let fy = pos("fy", &s.fy)?;
    let gap = v.gap(key("gap"), &s.gap, Some(0.0))?;
    use crate::element::restrainer::SlackGrowth;
    let growth = match s
        .after_yield
        .as_ref()
        .map(|r| (r.get_ref().as_str(), v.line(r)))
    {
        None | Some(("permanent", _)) => SlackGrowth::Permanent,
        Some(("recentering", _)) => SlackGrowth::Recentering,
        Some((other, line)) => {
            return Err(v.err(
                key("after_yield"),
                Some(line),
                format!(
                    "invalid {} {other:?}: use \"permanent\" (OpenSees ElasticPPGap damage) or \
                     \"recentering\" (its default, noDamage)",
                    key("after_yield")
                ),
            ));
        }
    };
    crate::element::shear_key::ShearKey::new(k, fy, gap, growth)
        .map_err(|e| v.err(key(e.key()), Some(v.line(t)), e.to_string()))
}

/// The backwall of abutment `side` from its table.
pub(super) fn backwall(
    v: &Val,
    side: usize,
    t: &Spanned<BackwallSec>,
) -> Result<Backwall, ScenarioError> {
    let name = crate::sim::bridge::ABUTMENT_SIDES[side];
    let key = |k: &str| format!("abutment.{name}.backwall.{k}");
    let w = t.get_ref();
    // a required key left out: the error names the table's line
    let pos = |k: &str, x: &Sp<f64>| match x {
        None => Err(v.err(key(k), Some(v.line(t)), format!("{} is required", key(k)))),
        some => v.pos(key(k), some, None),
    };
    let mass = pos("mass", &w.mass)?;
    let line = |x: &Sp<f64>| x.as_ref().map(|x| v.line(x));
    let explicit = w.kmax.is_some() || w.fult.is_some() || w.kur.is_some();
    let caltrans = w.height.is_some() || w.width.is_some() || w.skew_deg.is_some();
    if explicit && caltrans {
        let (k, at) = [
            ("height", &w.height),
            ("width", &w.width),
            ("skew_deg", &w.skew_deg),
        ]
        .into_iter()
        .find_map(|(k, x)| line(x).map(|l| (k, l)))
        .expect("a Caltrans key");
        return Err(v.err(
            key(k),
            Some(at),
            format!(
                "give the backfill either by {} and {} or by the wall's {} and {} (Caltrans), not \
                 both",
                key("kmax"),
                key("fult"),
                key("height"),
                key("width")
            ),
        ));
    }
    let gap = v.gap(key("backfill_gap"), &w.backfill_gap, Some(0.0))?;
    let rf = v.num(
        key("rf"),
        &w.rf,
        Some(0.7),
        |x| x > 0.0 && x < 1.0,
        "must lie in (0, 1)",
    )?;
    let element_error = |e: crate::element::ElementError, at: Option<usize>| {
        v.err(key(e.key()), at.or(Some(v.line(t))), e.to_string())
    };
    let backfill = if explicit {
        let kmax = pos("kmax", &w.kmax)?;
        let kur = v.pos(key("kur"), &w.kur, Some(kmax))?;
        if kur < kmax {
            return Err(v.err(
                key("kur"),
                line(&w.kur),
                format!(
                    "invalid {} = {}: must be >= {} ({}): with a softer unloading the backfill \
                     law gives back more energy than it took (it is not dissipative)",
                    key("kur"),
                    crate::output::float_token(kur),
                    key("kmax"),
                    crate::output::float_token(kmax)
                ),
            ));
        }
        let fult = pos("fult", &w.fult)?;
        Some(HyperbolicGap::new(kmax, kur, rf, fult, gap).map_err(|e| element_error(e, None))?)
    } else if caltrans {
        let h = pos("height", &w.height)?;
        let b = pos("width", &w.width)?;
        let skew = v.num(
            key("skew_deg"),
            &w.skew_deg,
            Some(0.0),
            |x| (0.0..90.0).contains(&x),
            "must lie in [0, 90) deg",
        )?;
        let c = CaltransBackwall::new(h, b, skew).map_err(|e| element_error(e, line(&w.height)))?;
        Some(HyperbolicGap::new(c.k, c.k, rf, c.f_ult, gap).map_err(|e| element_error(e, None))?)
    } else {
        for (k, x) in [("rf", &w.rf), ("backfill_gap", &w.backfill_gap)] {
            if let Some(x) = x {
                return Err(v.err(
                    key(k),
                    Some(v.line(x)),
                    format!(
                        "{} applies to a backfill: give {} and {} (or height and width)",
                        key(k),
                        key("kmax"),
                        key("fult")
                    ),
                ));
            }
        }
        None
    };
    let piles = match (&w.piles_k, &w.piles_fy) {
        (None, None) => None,
        (k, fy) => Some(Piles {
            k: pos("piles_k", k)?,
            fy: pos("piles_fy", fy)?,
        }),
    };
    if backfill.is_none() && piles.is_none() {
        return Err(v.err(
            key("mass"),
            Some(v.line(t)),
            format!(
                "a backwall needs something behind it: its backfill ({} and {}) or its piles ({} and {})",
                key("kmax"),
                key("fult"),
                key("piles_k"),
                key("piles_fy")
            ),
        ));
    }
    Ok(Backwall {
        mass,
        backfill,
        piles,
    })
}
