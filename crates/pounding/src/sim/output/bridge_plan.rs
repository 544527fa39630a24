//! The geometry and derived histories behind the figures of a bridge run (`joint_openings.png`,
//! `displacements.png`, `plan.png`), kept here so that any front end draws the same numbers.
//!
//! All positions are in the global frame of [`BridgeModel::layout`] \[m\]; histories have one
//! value per kept time of the [`BridgeSolution`] (`sol.t`).

use crate::math::{Real, Vector};
use crate::sim::bridge::{BridgeModel, BridgeSolution};

/// Plan of a bridge in its reference pose.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgePlan {
    /// Closed outline of every segment (first point repeated at the end): the four end-face
    /// corners of a straight or skewed segment; a curved segment's inner and outer arcs as
    /// polylines of the requested number of chords.
    pub outlines: Vec<Vec<Vector>>,
    /// Reference corners of every segment: `[start c0, start c1, end c0, end c1]` of its placed
    /// faces ([`crate::sim::model::SegmentBody`]).
    pub corners: Vec<[Vector; 4]>,
    /// Reference centroid of every segment.
    pub centroids: Vec<Vector>,
    /// The abutment faces `[start, end]` (`None` where absent): the segment's outer face moved
    /// outward by the abutment gap, as its two end points.
    pub abutment_faces: [Option<[Vector; 2]>; 2],
}

/// The plan of `model` in its reference pose; curved segments get `arc_chords` chords per arc
/// (at least 1).
pub fn bridge_plan(model: &BridgeModel, arc_chords: usize) -> BridgePlan {
    let bodies = model.layout();
    let outlines = model.outlines(arc_chords);
    let corners = bodies
        .iter()
        .map(|b| {
            [
                b.start.corners[0],
                b.start.corners[1],
                b.end.corners[0],
                b.end.corners[1],
            ]
        })
        .collect();
    let mut abutment_faces = [None, None];
    if let (Some(first), Some(last)) = (bodies.first(), bodies.last()) {
        for (side, f) in [(0, &first.start), (1, &last.end)] {
            if let Some(a) = &model.abutments[side] {
                let out = -f.inward * a.gap;
                abutment_faces[side] = Some([f.corners[0] + out, f.corners[1] + out]);
            }
        }
    }
    BridgePlan {
        outlines,
        corners,
        centroids: bodies.iter().map(|b| b.centroid).collect(),
        abutment_faces,
    }
}

/// The path of each corner of each segment over the run, its displacement from the reference
/// position magnified by `exaggeration`: `p⁰ + f (p(t) − p⁰)` with
/// `p(t) = G⁰ + d + Rot(θ)(p⁰ − G⁰)` ([`crate::sim::model::SegmentBody::place`]). Per segment the four
/// corners in the order of [`BridgePlan::corners`], per corner one point per kept time
/// (non-finite where the state is).
pub type CornerPaths = Vec<[Vec<Vector>; 4]>;

/// [`CornerPaths`] of a run of `model`.
pub fn corner_paths(model: &BridgeModel, sol: &BridgeSolution, exaggeration: Real) -> CornerPaths {
    let bodies = model.layout();
    bodies
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let c0 = [
                b.start.corners[0],
                b.start.corners[1],
                b.end.corners[0],
                b.end.corners[1],
            ];
            c0.map(|p0| {
                sol.q_rows()
                    .map(|q| {
                        let [x, y, th] = sol.dofs.plan_of(i, q);
                        let p = b.place(&p0, &Vector::new(x, y), th.sin_cos());
                        p0 + (p - p0) * exaggeration
                    })
                    .collect()
            })
        })
        .collect()
}

/// The opening of every joint over the run: the smaller of its two end gaps minus its reference
/// gap (`< 0` closing; `−gap` at contact). An end without a realised corner (NaN gap) is
/// ignored; NaN where both are. `[joint][kept time]` \[m\].
pub fn joint_openings(model: &BridgeModel, sol: &BridgeSolution) -> Vec<Vec<Real>> {
    let nj = sol.n_segments.saturating_sub(1);
    (0..nj)
        .map(|k| {
            let g = model.joints[k].gap;
            sol.end_gaps
                .chunks_exact(2 * nj)
                .map(|row| row[2 * k].min(row[2 * k + 1]) - g)
                .collect()
        })
        .collect()
}

/// The magnitude `√(x² + y²)` of every segment's centroid displacement relative to the ground
/// over the run, `[segment][kept time]` \[m\].
pub fn segment_displacements(sol: &BridgeSolution) -> Vec<Vec<Real>> {
    let n = sol.n_segments;
    (0..n)
        .map(|i| {
            sol.q_rows()
                .map(|q| {
                    let [x, y, _] = sol.dofs.plan_of(i, q);
                    x.hypot(y)
                })
                .collect()
        })
        .collect()
}

/// A readable exaggeration factor for a plan of size `extent` \[m\] whose largest corner
/// displacement is `peak` \[m\]: the largest of 1, 2, 5 × 10ᵏ (at least 1) that draws `peak` at
/// most 4 % of `extent`; 1 when either is not positive and finite.
pub fn plan_exaggeration(extent: Real, peak: Real) -> Real {
    if !(extent.is_finite() && peak.is_finite() && extent > 0.0 && peak > 0.0) {
        return 1.0;
    }
    let want = 0.04 * extent / peak;
    if want <= 1.0 {
        return 1.0;
    }
    let decade = (10.0 as Real).powi(want.log10().floor() as i32);
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|f| *f <= want)
        .unwrap_or(decade)
        .max(1.0)
}

#[cfg(test)]
mod tests {
    use super::plan_exaggeration;
    use crate::math::Real;

    #[test]
    fn exaggeration_is_1_2_5_and_bounded() {
        // 4 % of 100 m = 4 m; peak 0.07 m → want 57.1 → 50
        assert_eq!(plan_exaggeration(100.0, 0.07), 50.0);
        assert_eq!(plan_exaggeration(100.0, 0.2), 20.0);
        assert_eq!(plan_exaggeration(100.0, 10.0), 1.0);
        assert_eq!(plan_exaggeration(100.0, 0.0), 1.0);
        assert_eq!(plan_exaggeration(Real::NAN, 0.1), 1.0);
    }
}
