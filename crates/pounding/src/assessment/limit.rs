//! Limit states evaluated on a bridge run's summary: exceeded or not, and the ratio
//! demand / capacity.
//!
//! | kind | demand | capacity | exceeded |
//! |---|---|---|---|
//! | `unseating` | the largest ratio of an end's seat displacement to its own seat length | 1 | the run's own `unseated` flag |
//! | `joint_force` (compliance laws) | largest `peak_contact_force_n` over the joints | `capacity_n` | ratio > 1 |
//! | `joint_force` (rigid law) | largest `peak_impulse_ns` over the joints | `capacity_ns` | ratio > 1 |
//! | `bearing_deformation` | largest `peak_bearing_deformation_m` over the segments | `limit_m` | ratio > 1 |
//! | `rotation` | largest `peak_rotation_deg` over the segments | `limit_deg` | ratio > 1 |
//! | `joint_opening` | largest `peak_opening_m` over the joints | `limit_m` | ratio > 1 |
//!
//! The *margin* is the ratio `r = demand / capacity`; `1 − r` is the remaining fraction of the
//! capacity (for unseating: the remaining seat fraction of the most critical end, each end
//! against its own seat length; `exceeded` is the run's own per-end check).
//! Abutment forces are not part of `joint_force`.

use super::AssessmentError;
use super::settings::{LimitKind, LimitState};
use crate::math::Real;
use crate::sim::JointContact;
use crate::sim::bridge::{BridgeModel, BridgeSummary};

/// A limit state bound to a bridge: its capacity and what it reads.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundLimit {
    /// The limit state as written.
    pub state: LimitState,
    /// The capacity the demand is divided by (unseating: 1, the demand being a ratio).
    pub capacity: Real,
    /// `joint_force` on a rigid bridge reads the impulse.
    pub rigid: bool,
}

/// Checks every limit state against `model` (a joint limit state on a bridge without joints,
/// `capacity_n` on a rigid bridge, …) and binds its capacity.
pub fn bind(
    states: &[LimitState],
    model: &BridgeModel,
    origin: &str,
) -> Result<Vec<BoundLimit>, AssessmentError> {
    let rigid = model
        .joints
        .iter()
        .map(|j| &j.contact)
        .chain(model.abutments.iter().flatten().map(|a| &a.contact))
        .all(|c| matches!(c, JointContact::Rigid));
    let mut out = Vec::new();
    for s in states {
        let err = |key: &str, msg: String| AssessmentError::Key {
            message: msg,
            key: format!("{}.{key}", s.at.0),
            origin: origin.to_string(),
            line: s.at.1,
        };
        let needs_joints = matches!(
            s.kind,
            LimitKind::JointForce { .. } | LimitKind::JointOpening(_)
        );
        let missing = match s.kind {
            LimitKind::PierDrift(_) if model.piers.is_empty() => Some("piers"),
            LimitKind::Backwall(_)
                if !model
                    .abutments
                    .iter()
                    .flatten()
                    .any(|a| a.backwall.is_some()) =>
            {
                Some("abutment backwalls")
            }
            LimitKind::ShearKey
                if !model
                    .abutments
                    .iter()
                    .flatten()
                    .any(|a| a.shear_keys.is_some()) =>
            {
                Some("shear keys")
            }
            _ => None,
        };
        if let Some(what) = missing {
            return Err(err(
                "kind",
                format!("this bridge has no {what}: the limit state has nothing to read"),
            ));
        }
        if needs_joints && model.joints.is_empty() {
            return Err(err(
                "kind",
                "this bridge has one segment and no joint: a joint limit state has nothing to read"
                    .into(),
            ));
        }
        let capacity =
            match s.kind {
                LimitKind::Unseating => 1.0,
                LimitKind::ShearKey => model
                    .abutments
                    .iter()
                    .flatten()
                    .filter_map(|a| a.shear_keys.map(|k| k.fy()))
                    .fold(Real::INFINITY, Real::min),
                LimitKind::JointForce {
                    capacity_n,
                    capacity_ns,
                } => {
                    match (rigid, capacity_n, capacity_ns) {
                        (true, None, Some(c)) | (false, Some(c), None) => c,
                        (true, ..) => {
                            return Err(err(
                        if capacity_n.is_some() { "capacity_n" } else { "kind" },
                        "the bridge's contact law is rigid (impacts, no contact force): give \
                         capacity_ns, the capacity in peak impulse [N s], and no capacity_n"
                            .into(),
                    ));
                        }
                        (false, ..) => {
                            return Err(err(
                        if capacity_ns.is_some() { "capacity_ns" } else { "kind" },
                        "the bridge's contact law is a compliance law: give capacity_n, the \
                         capacity in peak contact force [N], and no capacity_ns"
                            .into(),
                    ));
                        }
                    }
                }
                LimitKind::BearingDeformation(c)
                | LimitKind::Rotation(c)
                | LimitKind::JointOpening(c)
                | LimitKind::PierDrift(c)
                | LimitKind::Backwall(c) => c,
            };
        out.push(BoundLimit {
            state: s.clone(),
            capacity,
            rigid,
        });
    }
    Ok(out)
}

impl BoundLimit {
    /// The demand of a run \[the capacity's units\].
    pub fn demand(&self, s: &BridgeSummary) -> Real {
        let max = |it: &mut dyn Iterator<Item = Real>| it.fold(Real::NEG_INFINITY, Real::max);
        match self.state.kind {
            LimitKind::Unseating => s.peak_seat_ratio,
            LimitKind::JointForce { .. } if self.rigid => {
                max(&mut s.joints.iter().map(|j| j.peak_impulse))
            }
            LimitKind::JointForce { .. } => {
                let forces: Option<Vec<Real>> =
                    s.joints.iter().map(|j| j.peak_contact_force).collect();
                forces.map_or(Real::NAN, |f| max(&mut f.into_iter()))
            }
            LimitKind::BearingDeformation(_) => {
                max(&mut s.segments.iter().map(|g| g.peak_bearing_deformation))
            }
            LimitKind::Rotation(_) => {
                max(&mut s.segments.iter().map(|g| g.peak_rotation.to_degrees()))
            }
            LimitKind::JointOpening(_) => max(&mut s.joints.iter().map(|j| j.peak_opening)),
            LimitKind::PierDrift(_) => max(&mut s.piers.iter().map(|p| p.peak_drift_magnitude)),
            LimitKind::Backwall(_) => max(&mut s
                .abutments
                .iter()
                .flatten()
                .filter_map(|a| a.backwall.as_ref().map(|w| w.peak_displacement))),
            // the largest key force over the smallest capacity (1 when a key yields)
            LimitKind::ShearKey => max(&mut s.shear_keys.iter().map(|k| k.peak_force)),
        }
    }

    /// The limit state in words, with its capacity, for reports: what is measured, over which
    /// elements, and when it counts as exceeded (the module table, one row).
    pub fn definition(&self) -> String {
        let f = crate::output::float_token;
        match self.state.kind {
            LimitKind::Unseating => "an end leaves its seat: ratio = the largest over the seated \
                ends of peak seat displacement / that end's own seat length; exceeded when an end \
                unseats (ratio > 1)"
                .into(),
            LimitKind::JointForce { .. } if self.rigid => format!(
                "peak impulse of an impact at any joint above {} N s (rigid contact: impacts have \
                 impulses, not forces); ratio = largest joint peak impulse / capacity",
                f(self.capacity)
            ),
            LimitKind::JointForce { .. } => format!(
                "peak contact force at any joint above {} N; ratio = largest joint peak force / \
                 capacity (abutments not included)",
                f(self.capacity)
            ),
            LimitKind::BearingDeformation(c) => format!(
                "peak bearing deformation of any segment above {} m; ratio = largest / limit",
                f(c)
            ),
            LimitKind::Rotation(c) => format!(
                "peak plan rotation of any segment above {} deg; ratio = largest / limit",
                f(c)
            ),
            LimitKind::JointOpening(c) => format!(
                "peak opening of any joint above {} m; ratio = largest / limit",
                f(c)
            ),
            LimitKind::PierDrift(c) => format!(
                "peak drift (cap displacement √(x² + y²)) of any pier above {} m; ratio = \
                 largest / limit",
                f(c)
            ),
            LimitKind::Backwall(c) => format!(
                "peak displacement of any backwall into the soil above {} m; ratio = largest / \
                 limit",
                f(c)
            ),
            LimitKind::ShearKey => format!(
                "a shear key reaches its capacity and yields; ratio = largest key force / {} N \
                 (the smallest capacity)",
                f(self.capacity)
            ),
        }
    }

    /// `(exceeded, ratio)` of a run: `exceeded` is `None` when the demand is not a finite
    /// number (the run is then excluded from the fit).
    pub fn evaluate(&self, s: &BridgeSummary) -> (Option<bool>, Real) {
        let ratio = self.demand(s) / self.capacity;
        if !ratio.is_finite() {
            return (None, ratio);
        }
        let exceeded = match self.state.kind {
            LimitKind::Unseating => s.unseated,
            LimitKind::ShearKey => s.shear_keys.iter().any(|k| k.yielded),
            _ => ratio > 1.0,
        };
        (Some(exceeded), ratio)
    }
}
