//! The comparison of a design's variants with the as-built bridge ([`super::design`]): paired and
//! unpaired bootstrap differences, `variants.csv`, `variants.json` and the recommendation in words.

use super::design::Design;
use super::hazard_study::MAF_NOT_FINITE;
use super::study::Fits;
use crate::fragility::bootstrap::bca;
use crate::fragility::hazard::{HazardCurve, maf};
use crate::fragility::{Bootstrap, FragilityRow};
use crate::math::Real;
use crate::output::{csv_field, float_token, json_float};
use serde_json::{Value, json};

/// The compared statistic of a limit state: the MAF (with a hazard) or the median θ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stat {
    /// Mean annual frequency \[1/yr\] (lower is better).
    Maf,
    /// Fragility median θ \[g\] (higher is better).
    Theta,
}

impl Stat {
    /// `maf` or `theta`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Stat::Maf => "maf",
            Stat::Theta => "theta",
        }
    }
}

/// One variant's limit state against the as-built bridge's.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison {
    /// The member (index into [`Design::members`]; 0 is the as-built bridge).
    pub member: usize,
    /// The limit state's index.
    pub limit: usize,
    /// The statistic of this member (`None` without a fit).
    pub value: Option<Real>,
    /// Its interval.
    pub interval: Option<(Real, Real)>,
    /// `value − as-built value` (`None` for the as-built bridge or without both fits).
    pub diff: Option<Real>,
    /// Interval of the difference from paired replicates (the same records resampled).
    pub paired: Option<(Real, Real)>,
    /// Interval of the difference from independent replicates.
    pub unpaired: Option<(Real, Real)>,
    /// The fit's status, or [`MAF_NOT_FINITE`] when the fit's statistic is not a finite number
    /// (then `value`, `interval` and the differences are `None`).
    pub status: String,
}

/// The statistic of `(θ, β)`.
fn stat_of(h: Option<&HazardCurve>, t: Real, b: Real) -> Real {
    match h {
        Some(h) => maf(h, t, b).rate,
        None => t,
    }
}

/// The bias-corrected percentile interval of the difference `f(v) − f(base)` over replicates
/// `b` of `v` and `pair(b)` of `base`.
fn diff_interval(
    v: &Bootstrap,
    base: &Bootstrap,
    est: Real,
    f: &dyn Fn(Real, Real) -> Real,
    pair: &dyn Fn(usize, usize) -> usize,
) -> Option<(Real, Real)> {
    let n = v.replicates.len();
    if n != base.replicates.len() || n < 2 {
        return None;
    }
    let d: Vec<Real> = (0..n)
        .filter_map(|b| {
            let (tv, bv) = v.replicates[b]?;
            let (t0, b0) = base.replicates[pair(b, n)]?;
            let x = f(tv, bv) - f(t0, b0);
            x.is_finite().then_some(x)
        })
        .collect();
    (d.len() >= 2).then(|| bca(est, d, None, v.level))
}

/// Every member's limit states against the as-built bridge's (member 0).
pub fn compare(design: &Design, fits: &[Fits]) -> (Stat, Vec<Comparison>) {
    let h = design.hazard().map(|h| &h.curve);
    let stat = if h.is_some() { Stat::Maf } else { Stat::Theta };
    let f = |t: Real, b: Real| stat_of(h, t, b);
    let mut out = Vec::new();
    for (m, fm) in fits.iter().enumerate() {
        for (l, r) in fm.rows.iter().enumerate() {
            let base = &fits[0].rows[l];
            let raw = r.fit.params().map(|(t, b)| f(t, b));
            let interval = r.bootstrap.as_ref().and_then(|b| b.interval_of(&f));
            // never a non-finite statistic under the fit's `ok`
            let finite = raw.is_none_or(Real::is_finite)
                && interval.is_none_or(|(a, z)| a.is_finite() && z.is_finite());
            let value = raw.filter(|_| finite);
            let interval = interval.filter(|_| finite);
            let status = if finite {
                r.fit.status().to_string()
            } else {
                MAF_NOT_FINITE.to_string()
            };
            let b0 = base
                .fit
                .params()
                .map(|(t, b)| f(t, b))
                .filter(|v| v.is_finite());
            let diff = (m > 0).then(|| Some(value? - b0?)).flatten();
            let (paired, unpaired) = match (diff, &r.bootstrap, &base.bootstrap) {
                (Some(d), Some(bv), Some(bb)) => (
                    diff_interval(bv, bb, d, &f, &|b, _| b),
                    diff_interval(bv, bb, d, &f, &|b, n| (b + n / 2) % n),
                ),
                _ => (None, None),
            };
            out.push(Comparison {
                member: m,
                limit: l,
                value,
                interval,
                diff,
                paired,
                unpaired,
                status,
            });
        }
    }
    (stat, out)
}

/// The error of comparisons whose statistic is not finite (`None`: every fitted one is).
pub fn not_finite(design: &Design, fits: &[Fits], comps: &[Comparison]) -> Option<String> {
    let bad: Vec<String> = comps
        .iter()
        .filter(|c| c.status == MAF_NOT_FINITE)
        .map(|c| {
            format!(
                "{} / {}",
                design.members[c.member].name, fits[c.member].rows[c.limit].limit_state
            )
        })
        .collect();
    (!bad.is_empty()).then(|| {
        format!(
            "the mean annual frequency of {} is not a finite number (status {MAF_NOT_FINITE}: \
             the hazard curve's rates overflow the integral); no MAF is given",
            bad.join(", ")
        )
    })
}

/// `variants.csv` columns.
pub const VARIANTS_COLUMNS: &str = "variant,limit_state,status,theta,beta,theta_lo,theta_hi,\
beta_lo,beta_hi,stat,value,value_lo,value_hi,return_period_years,diff,paired_lo,paired_hi,\
unpaired_lo,unpaired_hi,paired_excludes_zero";

fn fit_numbers(r: &FragilityRow) -> [Real; 6] {
    let (t, b) = r.fit.params().unwrap_or((Real::NAN, Real::NAN));
    let bs = r.bootstrap.as_ref();
    let (tl, th) = bs.and_then(|b| b.theta).unwrap_or((Real::NAN, Real::NAN));
    let (bl, bh) = bs.and_then(|b| b.beta).unwrap_or((Real::NAN, Real::NAN));
    [t, b, tl, th, bl, bh]
}

fn excludes_zero(i: Option<(Real, Real)>) -> Option<bool> {
    i.map(|(lo, hi)| lo > 0.0 || hi < 0.0)
}

/// `variants.csv`: one row per member and limit state (the as-built bridge's `diff` columns
/// `nan`, `paired_excludes_zero` empty).
pub fn variants_csv(design: &Design, fits: &[Fits], stat: Stat, comps: &[Comparison]) -> String {
    let mut out = String::from(VARIANTS_COLUMNS);
    out.push('\n');
    let nan2 = (Real::NAN, Real::NAN);
    for c in comps {
        let r = &fits[c.member].rows[c.limit];
        let (vl, vh) = c.interval.unwrap_or(nan2);
        let (pl, ph) = c.paired.unwrap_or(nan2);
        let (ul, uh) = c.unpaired.unwrap_or(nan2);
        let value = c.value.unwrap_or(Real::NAN);
        let rp = if stat == Stat::Maf {
            1.0 / value
        } else {
            Real::NAN
        };
        let nums: Vec<String> = fit_numbers(r).iter().map(|&x| float_token(x)).collect();
        let rest = [
            value,
            vl,
            vh,
            rp,
            c.diff.unwrap_or(Real::NAN),
            pl,
            ph,
            ul,
            uh,
        ]
        .map(float_token);
        out.push_str(&format!(
            "{},{},{},{},{},{},{}\n",
            csv_field(&design.members[c.member].name),
            csv_field(&r.limit_state),
            c.status,
            nums.join(","),
            stat.as_str(),
            rest.join(","),
            excludes_zero(c.paired).map_or(String::new(), |b| b.to_string())
        ));
    }
    out
}

/// `variants.json`: the members (name, description, overrides) with, per limit state, the fit,
/// the statistic and the differences; the recommendation's sentences.
pub fn variants_json(design: &Design, fits: &[Fits], stat: Stat, comps: &[Comparison]) -> String {
    let members: Vec<Value> = design
        .members
        .iter()
        .enumerate()
        .map(|(m, mem)| {
            let ls: Vec<Value> = comps
                .iter()
                .filter(|c| c.member == m)
                .map(|c| {
                    let r = &fits[m].rows[c.limit];
                    let [t, b, tl, th, bl, bh] = fit_numbers(r).map(json_float);
                    let pair = |i: Option<(Real, Real)>| {
                        i.map_or(Value::Null, |(a, z)| json!([json_float(a), json_float(z)]))
                    };
                    json!({
                        "limit_state": r.limit_state, "status": c.status,
                        "theta": t, "beta": b, "theta_interval": [tl, th], "beta_interval": [bl, bh],
                        "value": json_float(c.value.unwrap_or(Real::NAN)),
                        "interval": pair(c.interval),
                        "diff": json_float(c.diff.unwrap_or(Real::NAN)),
                        "paired": pair(c.paired), "unpaired": pair(c.unpaired),
                        "paired_excludes_zero": excludes_zero(c.paired),
                    })
                })
                .collect();
            json!({
                "name": mem.name, "description": mem.description, "overrides": mem.overrides,
                "limit_states": ls,
            })
        })
        .collect();
    let mut j = json!({
        "design": design.origin,
        "scenario": design.scenario_path.display().to_string(),
        "baseline": design.members[0].name,
        "stat": stat.as_str(),
        "level": design.members[0].study.settings.level,
        "im": design.members[0].study.spec.label(),
        "members": members,
        "recommendation": recommendation(design, fits, stat, comps),
    });
    crate::output::json_without_negative_zero(&mut j);
    serde_json::to_string_pretty(&j).unwrap_or_default() + "\n"
}

fn fmt(stat: Stat, x: Real) -> String {
    match stat {
        Stat::Maf => format!("{x:.3e} per year"),
        Stat::Theta => format!("{x:.3} g"),
    }
}

/// The recommendation in words: per limit state, the variant that improves it most (the lowest
/// MAF, or the highest median), with its paired interval and whether it excludes 0.
pub fn recommendation(
    design: &Design,
    fits: &[Fits],
    stat: Stat,
    comps: &[Comparison],
) -> Vec<String> {
    let level = design.members[0].study.settings.level;
    let pct = format!("{} %", crate::output::float_token(100.0 * level));
    let base = &design.members[0].name;
    let mut out = Vec::new();
    for (l, r) in fits[0].rows.iter().enumerate() {
        let name = &r.limit_state;
        let what = match stat {
            Stat::Maf => format!("the mean annual frequency of {name}"),
            Stat::Theta => format!("the median IM of {name}"),
        };
        let better = |d: Real| if stat == Stat::Maf { -d } else { d };
        let best = comps
            .iter()
            .filter(|c| c.limit == l && c.member > 0)
            .filter_map(|c| c.diff.map(|d| (c, d)))
            .max_by(|a, b| better(a.1).total_cmp(&better(b.1)));
        let b0 = comps
            .iter()
            .find(|c| c.limit == l && c.member == 0)
            .and_then(|c| c.value);
        let Some(b0) = b0 else {
            out.push(format!(
                "{name}: the {base} bridge has no fit ({}): no comparison",
                r.fit.status()
            ));
            continue;
        };
        let Some((c, d)) = best else {
            out.push(format!(
                "{name}: no variant has a fit to compare with the {base} bridge"
            ));
            continue;
        };
        let v = &design.members[c.member].name;
        let lead = if better(d) > 0.0 {
            let verb = if stat == Stat::Maf {
                "lowers"
            } else {
                "raises"
            };
            format!("variant {v} {verb} {what} most")
        } else {
            format!("no variant improves {what}; the best of them, {v}, changes it")
        };
        let interval = c
            .paired
            .map_or("no interval (no bootstrap)".into(), |(lo, hi)| {
                format!(
                    "paired {pct} interval of the change {} to {}; the interval {}",
                    fmt(stat, lo),
                    fmt(stat, hi),
                    if lo > 0.0 || hi < 0.0 {
                        "excludes 0: the records distinguish it from the as-built bridge"
                    } else {
                        "contains 0: these records do not distinguish it from the as-built bridge"
                    }
                )
            });
        out.push(format!(
            "{name}: {lead} from {} ({base}) to {} (change {}; {interval})",
            fmt(stat, b0),
            fmt(stat, c.value.unwrap_or(Real::NAN)),
            fmt(stat, d),
        ));
    }
    out
}
