//! `[[pier]]` tables of a bridge scenario: a pier under a joint ([`crate::sim::bridge::Pier`]).
//!
//! ```toml
//! [[pier]]
//! joint = 1           # the joint it carries (1 = between segments 1 and 2)
//! cap_mass = 2.0e5    # [kg]
//! k0 = 8.0e7          # column stiffness in each plan direction [N/m]
//! fy = 1.2e6          # optional: column yield force [N] (bilinear, kinematic hardening)
//! b = 0.02            # post-yield stiffness ratio (with fy; default 0)
//! yield = "per-axis"  # Steel01 along and across the joint apart (default), or "plan": a circle
//! damping = 1.0e6     # column dashpot in each plan direction [N s/m] (default 0)
//! ```

use super::{Sp, Val};
use crate::sim::bridge::{Pier, PierColumn};
use crate::sim::scenario::ScenarioError;
use serde::Deserialize;
use toml::Spanned;

/// One `[[pier]]` table as read by `serde`.
#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub(super) struct PierSec {
    joint: Sp<i64>,
    cap_mass: Sp<f64>,
    k0: Sp<f64>,
    fy: Sp<f64>,
    b: Sp<f64>,
    damping: Sp<f64>,
    #[serde(rename = "yield")]
    yield_rule: Sp<String>,
}

/// The piers of the `[[pier]]` tables; `joints`: the bridge's joint count.
pub(super) fn piers(
    v: &Val,
    tables: &[Spanned<PierSec>],
    joints: usize,
) -> Result<Vec<Pier>, ScenarioError> {
    let mut out: Vec<Pier> = Vec::with_capacity(tables.len());
    for (p, t) in tables.iter().enumerate() {
        let pk = |key: &str| format!("pier[{p}].{key}");
        let s = t.get_ref();
        let joint = match &s.joint {
            None => {
                return Err(v.err(
                    pk("joint"),
                    Some(v.line(t)),
                    format!(
                        "{} is required: the joint the pier carries (1 to {joints})",
                        pk("joint")
                    ),
                ));
            }
            Some(j) => {
                let k = *j.get_ref();
                if k < 1 || k as u64 > joints as u64 {
                    let why = if joints == 0 {
                        "this bridge has one segment and no joint".to_string()
                    } else {
                        format!("joints are numbered 1 to {joints}")
                    };
                    return Err(v.err(
                        pk("joint"),
                        Some(v.line(j)),
                        format!("invalid {} = {k}: {why}", pk("joint")),
                    ));
                }
                if let Some(q) = out.iter().position(|o| o.joint + 1 == k as usize) {
                    return Err(v.err(
                        pk("joint"),
                        Some(v.line(j)),
                        format!("joint {k} already has a pier (pier[{q}])"),
                    ));
                }
                k as usize - 1
            }
        };
        // a required key left out: the error names the table's line
        let pos = |k: &str, x: &Sp<f64>| match x {
            None => Err(v.err(pk(k), Some(v.line(t)), format!("{} is required", pk(k)))),
            some => v.pos(pk(k), some, None),
        };
        let cap_mass = pos("cap_mass", &s.cap_mass)?;
        let k0 = pos("k0", &s.k0)?;
        let fy = match &s.fy {
            None => None,
            some => Some(v.pos(pk("fy"), some, None)?),
        };
        if fy.is_none()
            && let Some(b) = &s.b
        {
            return Err(v.err(
                pk("b"),
                Some(v.line(b)),
                format!(
                    "{} applies to a yielding column: give {} too",
                    pk("b"),
                    pk("fy")
                ),
            ));
        }
        let b = v.num(
            pk("b"),
            &s.b,
            Some(0.0),
            |x| (0.0..1.0).contains(&x),
            "must lie in [0, 1)",
        )?;
        let damping = v.nonneg(pk("damping"), &s.damping, Some(0.0))?;
        let per_axis = match s
            .yield_rule
            .as_ref()
            .map(|r| (r.get_ref().as_str(), v.line(r)))
        {
            None | Some(("per-axis", _)) => true,
            Some(("plan", _)) => false,
            Some((other, line)) => {
                return Err(v.err(
                    pk("yield"),
                    Some(line),
                    format!(
                        "invalid {} {other:?}: use \"per-axis\" or \"plan\"",
                        pk("yield")
                    ),
                ));
            }
        };
        if fy.is_none()
            && let Some(r) = &s.yield_rule
        {
            return Err(v.err(
                pk("yield"),
                Some(v.line(r)),
                format!(
                    "{} applies to a yielding column: give {} too",
                    pk("yield"),
                    pk("fy")
                ),
            ));
        }
        out.push(Pier {
            joint,
            cap_mass,
            column: PierColumn {
                k0,
                fy,
                b,
                per_axis,
            },
            damping,
        });
    }
    Ok(out)
}

/// The line of `pier[p].key` in the tables (the table's own line for a key it does not set).
pub(super) fn pier_line(
    v: &Val,
    tables: &[Spanned<PierSec>],
    p: usize,
    key: &str,
) -> Option<usize> {
    let t = tables.get(p)?;
    let s = t.get_ref();
    let own = match key {
        "joint" => s.joint.as_ref().map(|x| v.line(x)),
        "cap_mass" => s.cap_mass.as_ref().map(|x| v.line(x)),
        "k0" => s.k0.as_ref().map(|x| v.line(x)),
        "fy" => s.fy.as_ref().map(|x| v.line(x)),
        "b" => s.b.as_ref().map(|x| v.line(x)),
        "damping" => s.damping.as_ref().map(|x| v.line(x)),
        "yield" => s.yield_rule.as_ref().map(|x| v.line(x)),
        _ => None,
    };
    own.or(Some(v.line(t)))
}
