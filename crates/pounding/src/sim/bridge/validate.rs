//! The validation of a [`BridgeModel`] (segments, joints, abutments; the substructures' checks
//! are in their own modules) and the parameter names its errors carry.

use super::*;

/// `segment[i].key`, `joint[k].key`, `abutment.start.key` (0-based indices, as in the arrays of
/// a scenario).
pub(super) fn seg_key(i: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Segment(i), key)
}
pub(in crate::sim) fn joint_key(k: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Joint(k), key)
}
pub(in crate::sim) fn abut_key(side: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Abutment(side), key)
}

pub(in crate::sim) fn check(
    name: impl Into<ParamPath>,
    v: Real,
    ok: bool,
    reason: &str,
) -> Result<(), SimError> {
    if ok && v.is_finite() {
        Ok(())
    } else if v.is_finite() {
        Err(SimError::invalid(name, v, reason))
    } else {
        Err(SimError::invalid(
            name,
            v,
            &crate::sim::finite_reason(reason),
        ))
    }
}

impl BridgeModel {
    /// Validates every parameter; errors name `segment[i].key`, `joint[k].key`,
    /// `abutment.start.key`, ….
    pub fn validate(&self) -> Result<(), SimError> {
        let n = self.segments.len();
        if n == 0 {
            return Err(SimError::argument(
                "segment",
                "a bridge needs at least one segment",
            ));
        }
        if self.joints.len() + 1 != n {
            return Err(SimError::argument(
                "joint",
                format!(
                    "{n} segments need {} joints, found {}",
                    n - 1,
                    self.joints.len()
                ),
            ));
        }
        self.validate_segments()?;
        self.validate_joints()?;
        self.validate_abutments()?;
        self.validate_backwalls()?;
        self.validate_piers()?;
        check(
            "outer_seat_length",
            self.outer_seat_length,
            self.outer_seat_length > 0.0,
            "must be > 0",
        )?;
        check(
            "damping_ratio",
            self.damping_ratio,
            (0.0..1.0).contains(&self.damping_ratio),
            "must lie in [0, 1)",
        )?;
        self.contact_kinds()?;
        self.check_overlaps()?;
        self.check_points()?;
        Ok(())
    }

    /// Shapes, bearings and yield of every segment.
    fn validate_segments(&self) -> Result<(), SimError> {
        for (i, s) in self.segments.iter().enumerate() {
            s.shape.validate().map_err(|e| {
                SimError::argument(seg_key(i, "shape"), format!("invalid shape: {e}"))
            })?;
            for (b, br) in s.bearings.iter().enumerate() {
                let kr2 = br.stiffness * br.point.norm_squared();
                check(
                    seg_key(i, &format!("bearing[{b}].stiffness")),
                    br.stiffness,
                    br.stiffness >= 0.0 && kr2.is_finite(),
                    "must be finite and >= 0",
                )?;
            }
        }
        for (i, s) in self.segments.iter().enumerate() {
            if let Some(y) = &s.bearing_yield {
                check(seg_key(i, "fy"), y.fy, y.fy > 0.0, "must be finite and > 0")?;
                // each bearing yields at fy k_b / Σk: finite and > 0 too (fy = 1e305 or 5e-324
                // would overflow or underflow there)
                let total: Real = s.bearings.iter().map(|b| b.stiffness).sum();
                for b in s.bearings.iter().filter(|b| b.stiffness > 0.0) {
                    let fb = y.fy * (b.stiffness / total);
                    check(
                        seg_key(i, "fy"),
                        y.fy,
                        fb.is_normal() && fb > 0.0,
                        "gives a per-bearing yield force that is not a normal number; use a \
                         physical magnitude",
                    )?;
                }
                check(
                    seg_key(i, "b"),
                    y.b,
                    (0.0..1.0).contains(&y.b),
                    "must lie in [0, 1)",
                )?;
                if s.bearings.iter().all(|b| b.stiffness == 0.0) {
                    return Err(SimError::invalid(
                        seg_key(i, "fy"),
                        y.fy,
                        "yielding bearings need a positive stiffness",
                    ));
                }
            }
        }
        Ok(())
    }

    /// Gap, friction, restitution, seat, restrainer and matching face widths of every joint.
    fn validate_joints(&self) -> Result<(), SimError> {
        for (k, j) in self.joints.iter().enumerate() {
            for r in &j.restrainers {
                check(
                    joint_key(k, "restrainer_offsets"),
                    r.offset,
                    true,
                    "must be finite",
                )?;
                check(
                    joint_key(k, "restrainer_depth"),
                    r.depth,
                    r.depth >= 0.0,
                    "must be finite and >= 0",
                )?;
                crate::element::restrainer::Restrainer::new(
                    r.k,
                    r.slack,
                    r.fy,
                    crate::element::restrainer::SlackGrowth::Permanent,
                )
                .map_err(|e| {
                    SimError::argument(
                        joint_key(k, &format!("restrainer_{}", e.key())),
                        e.to_string(),
                    )
                })?;
            }
            check(joint_key(k, "gap"), j.gap, j.gap >= 0.0, "must be >= 0")?;
            check(
                joint_key(k, "mu"),
                j.friction,
                j.friction >= 0.0,
                "must be >= 0",
            )?;
            check(
                joint_key(k, "eps_n"),
                j.restitution,
                (0.0..=1.0).contains(&j.restitution),
                "must lie in [0, 1]",
            )?;
            check(
                joint_key(k, "seat_length"),
                j.seat_length,
                j.seat_length > 0.0,
                "must be > 0",
            )?;
            let (a, b) = (&self.segments[k], &self.segments[k + 1]);
            let (wa, wb) = (
                a.shape.end_face(DeckEnd::Joint).length(),
                b.shape.end_face(DeckEnd::Joint).length(),
            );
            let wa = if k == 0 {
                wa
            } else {
                a.shape.end_face(DeckEnd::Far).length()
            };
            if (wa - wb).abs() > 1e-9 * wa.max(wb) {
                return Err(SimError::argument(
                    seg_key(k + 1, "width"),
                    format!(
                        "segment[{}] meets segment[{k}] at joint[{k}] with a face {} m long, but \
                         segment[{k}]'s face there is {} m long: the two faces of a joint must have \
                         the same length (a skewed segment's end faces are width / cos(skew) long; \
                         adjust the widths so the faces match)",
                        k + 1,
                        crate::output::float_token(wb),
                        crate::output::float_token(wa)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Gap, seat, friction and restitution of each abutment.
    fn validate_abutments(&self) -> Result<(), SimError> {
        for (side, a) in self.abutments.iter().enumerate() {
            if let Some(a) = a {
                check(abut_key(side, "gap"), a.gap, a.gap >= 0.0, "must be >= 0")?;
                check(
                    abut_key(side, "seat_length"),
                    a.seat_length,
                    a.seat_length > 0.0,
                    "must be > 0",
                )?;
                check(
                    abut_key(side, "mu"),
                    a.friction,
                    a.friction >= 0.0,
                    "must be >= 0",
                )?;
                check(
                    abut_key(side, "eps_n"),
                    a.restitution,
                    (0.0..=1.0).contains(&a.restitution),
                    "must lie in [0, 1]",
                )?;
            }
        }
        Ok(())
    }
}
