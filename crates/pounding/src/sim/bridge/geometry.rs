//! The bridge model's geometric checks and drawings: the time step against the restrainers,
//! points on a segment, bearing points inside their deck, the plan outlines, overlapping
//! segments, and the placement of a segment's body frame.

use super::*;

impl BridgeModel {
    /// The step must resolve every restrainer: they act over a step as a predictor–corrector
    /// (explicit) force, stable for `ω h` well below 2. For the cables of joint `k` the bound
    /// `ω² ≤ Σ_c k_c w_cᵀ M⁻¹ w_c` is used, `w_c` the generalised direction of cable `c` on its
    /// two segments (`(n, r_a × n)` and `−(n, r_b × n)`, `n` along the cable, `r` the arms
    /// from the centroids): for one cable between the face midpoints of straight segments it is
    /// `k (1/m_a + 1/m_b)`. `h ≤ 1/ω` is required (errors name `dt` and the joint's
    /// `restrainer_k`).
    pub fn check_time_step(&self, dt: Real) -> Result<(), SimError> {
        self.check_backfill_step(dt)?;
        let bodies = self.layout();
        for (k, j) in self.joints.iter().enumerate() {
            if j.restrainers.is_empty() {
                continue;
            }
            let (ba, bb) = (&bodies[k], &bodies[k + 1]);
            let w2: Real = j
                .restrainers
                .iter()
                .map(|r| {
                    let [pa, pb] = restrainer_anchors(&bodies, k, r);
                    let n = (pb - pa)
                        .try_normalize(0.0)
                        .unwrap_or(-bodies[k].end.inward);
                    let (ta, tb) = (
                        cross(&(pa - ba.centroid), &n),
                        cross(&(pb - bb.centroid), &n),
                    );
                    r.k * (1.0 / ba.mass.mass
                        + 1.0 / bb.mass.mass
                        + ta * ta / ba.mass.inertia
                        + tb * tb / bb.mass.inertia)
                })
                .sum();
            let w = w2.sqrt();
            if dt * w > 1.0 {
                let total: Real = j.restrainers.iter().map(|r| r.k).sum();
                return Err(SimError::invalid(
                    crate::sim::param::Setting::Dt,
                    dt,
                    &format!(
                        "the restrainer of {} (k = {} N/m in total between segments of {} and {} \
                         kg, frequency {} rad/s) needs dt <= {} s",
                        joint_key(k, "restrainer_k"),
                        crate::output::float_token(total),
                        crate::output::float_token(ba.mass.mass),
                        crate::output::float_token(bb.mass.mass),
                        crate::output::float_token(w),
                        crate::output::float_token(1.0 / w)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A body-frame point of segment `i` from its **segment-frame** coordinates \[C\]: origin at
    /// the midpoint of the segment's start face (the face toward the start of the bridge),
    /// `along` the segment's axis at that face (straight and skewed segments: the line through
    /// the two face midpoints, parallel to the sides; curved: the tangent of the centreline, the
    /// start face's inward normal), `left` perpendicular to it, to the left of a walk from the
    /// start to the end \[m\]. For a straight segment `(0, ±W/2)` and `(L, ±W/2)` are its
    /// corners; a skewed one has its sides at `left = ±W/2`. The result goes into
    /// [`Bearing::point`].
    pub fn segment_point(&self, i: usize, along: Real, left: Real) -> Vector {
        self.segments[i].frame_point(i == 0, along, left)
    }

    /// The first bearing (segment, bearing; 0-based) that lies outside its segment's plan
    /// outline (64 chords per arc), if any.
    pub(crate) fn bearing_outside(&self) -> Option<(usize, usize)> {
        let outlines = self.outlines(64);
        self.bearing_points()
            .iter()
            .enumerate()
            .find_map(|(i, pts)| {
                let b = pts.iter().position(|p| !on_polygon(*p, &outlines[i]))?;
                Some((i, b))
            })
    }

    /// Every bearing and restrainer anchor must lie on its segment (inside or on its plan
    /// outline, with 64 chords per arc): errors name `segment[i].bearing_points`,
    /// `joint[k].restrainer_offsets` or `joint[k].restrainer_depth`.
    pub(super) fn check_points(&self) -> Result<(), SimError> {
        let outlines = self.outlines(64);
        let bodies = self.layout();
        if let Some((i, b)) = self.bearing_outside() {
            return Err(SimError::argument(
                seg_key(i, "bearing_points"),
                format!("bearing {} lies outside segment[{i}]", b + 1),
            ));
        }
        for (k, j) in self.joints.iter().enumerate() {
            for (c, r) in j.restrainers.iter().enumerate() {
                let half = bodies[k].end.half.min(bodies[k + 1].start.half);
                if r.offset.abs() > half * (1.0 + 1e-12) {
                    return Err(SimError::invalid(
                        joint_key(k, "restrainer_offsets"),
                        r.offset,
                        &format!(
                            "cable {} lies beside the joint: |offset| must be at most half the \
                             face length, {} m",
                            c + 1,
                            crate::output::float_token(half)
                        ),
                    ));
                }
                let [pa, pb] = restrainer_anchors(&bodies, k, r);
                for (p, seg) in [(pa, k), (pb, k + 1)] {
                    if !on_polygon(p, &outlines[seg]) {
                        return Err(SimError::invalid(
                            joint_key(k, "restrainer_depth"),
                            r.depth,
                            &format!(
                                "the anchor of cable {} lies outside segment[{seg}]: the depth \
                                 must stay within the segment",
                                c + 1
                            ),
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}

/// The unit vector to the left of the direction `d` (turned by +90°).
pub(super) fn left_of(d: Vector) -> Vector {
    Vector::new(-d.y, d.x)
}

/// The two anchors (global, reference pose) of cable `r` across joint `k` ([`RestrainerSpec`]).
pub(super) fn restrainer_anchors(
    bodies: &[SegmentBody],
    k: usize,
    r: &RestrainerSpec,
) -> [Vector; 2] {
    // walking direction at the joint: into segment k + 1 through its start face
    let left = left_of(bodies[k + 1].start.inward);
    [bodies[k].end, bodies[k + 1].start].map(|f| {
        let t = if f.dir.dot(&left) >= 0.0 {
            f.dir
        } else {
            -f.dir
        };
        f.mid + t * r.offset + f.inward * r.depth
    })
}

/// `p` lies inside the closed polyline `poly` or within round-off of its boundary.
pub(super) fn on_polygon(p: Vector, poly: &[Vector]) -> bool {
    let scale = poly.iter().fold(1.0, |m: Real, q| m.max(q.norm()));
    let near = poly.windows(2).any(|e| {
        let (a, b) = (e[0], e[1]);
        let ab = b - a;
        let t = ((p - a).dot(&ab) / ab.norm_squared().max(Real::MIN_POSITIVE)).clamp(0.0, 1.0);
        (a + ab * t - p).norm() <= 1e-9 * scale
    });
    near || point_in_polygon(p, poly)
}

/// Even–odd rule for a closed polyline.
pub(super) fn point_in_polygon(p: Vector, poly: &[Vector]) -> bool {
    let mut c = false;
    for e in poly.windows(2) {
        let (u, v) = (e[0], e[1]);
        if (u.y > p.y) != (v.y > p.y) && p.x < u.x + (p.y - u.y) / (v.y - u.y) * (v.x - u.x) {
            c = !c;
        }
    }
    c
}

impl BridgeModel {
    /// Closed plan outline of every segment in the reference pose (first point repeated at the
    /// end): the four end-face corners of a straight or skewed segment; a curved segment's outer
    /// and inner arcs as polylines of `arc_chords` chords (at least 1).
    pub fn outlines(&self, arc_chords: usize) -> Vec<Vec<Vector>> {
        let bodies = self.layout();
        let n = arc_chords.max(1);
        self.segments
            .iter()
            .zip(&bodies)
            .enumerate()
            .map(|(i, (s, b))| {
                let place = placement(b, s, i == 0);
                let body: Vec<Vector> = match s.shape.curved() {
                    Some(d) => {
                        // body points (R − r cos φ, r sin φ): inner corner at φ = 0, the outer
                        // arc φ = 0 → β, the inner arc back β → 0
                        let (ri, ro) = (d.radius - d.width / 2.0, d.radius + d.width / 2.0);
                        let at = |r: Real, k: usize| {
                            let phi = d.angle * k as Real / n as Real;
                            Vector::new(d.radius - r * phi.cos(), r * phi.sin())
                        };
                        let mut v = vec![at(ri, 0)];
                        v.extend((0..=n).map(|k| at(ro, k)));
                        v.extend((0..=n).rev().map(|k| at(ri, k)));
                        v.into_iter().map(|p| s.mirror(p)).collect()
                    }
                    None => {
                        let mut v = s.corner_points().to_vec();
                        v.push(v[0]);
                        v
                    }
                };
                body.into_iter().map(place).collect()
            })
            .collect()
    }

    /// Segments that are not neighbours must not overlap in plan (a curve closing on itself):
    /// an error naming both (outlines with 32 chords per arc).
    pub(super) fn check_overlaps(&self) -> Result<(), SimError> {
        let outlines = self.outlines(32);
        let bbox = |o: &[Vector]| {
            o.iter().fold(
                (
                    Real::INFINITY,
                    Real::INFINITY,
                    Real::NEG_INFINITY,
                    Real::NEG_INFINITY,
                ),
                |(a, b, c, d), p| (a.min(p.x), b.min(p.y), c.max(p.x), d.max(p.y)),
            )
        };
        let boxes: Vec<_> = outlines.iter().map(|o| bbox(o)).collect();
        for i in 0..outlines.len() {
            for j in i + 2..outlines.len() {
                let (a, b) = (boxes[i], boxes[j]);
                if a.2 < b.0 || b.2 < a.0 || a.3 < b.1 || b.3 < a.1 {
                    continue;
                }
                if polygons_overlap(&outlines[i], &outlines[j]) {
                    return Err(SimError::argument(
                        seg_key(j, "shape"),
                        format!(
                            "segment[{j}] overlaps segment[{i}] in plan: the bridge closes on \
                             itself (check the curve angles, radii and curve directions)"
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}

/// Two closed polylines cross, or one lies inside the other.
pub(super) fn polygons_overlap(a: &[Vector], b: &[Vector]) -> bool {
    let orient = |p: Vector, q: Vector, r: Vector| cross(&(q - p), &(r - p));
    let crosses = |p1: Vector, p2: Vector, q1: Vector, q2: Vector| {
        let (d1, d2) = (orient(q1, q2, p1), orient(q1, q2, p2));
        let (d3, d4) = (orient(p1, p2, q1), orient(p1, p2, q2));
        d1 * d2 < 0.0 && d3 * d4 < 0.0
    };
    for e in a.windows(2) {
        for f in b.windows(2) {
            if crosses(e[0], e[1], f[0], f[1]) {
                return true;
            }
        }
    }
    point_in_polygon(a[0], b) || point_in_polygon(b[0], a)
}

/// Maps a point of segment `s`'s (mirrored) body frame to its global reference position, given
/// the placed body `b`.
pub(crate) fn placement(
    b: &SegmentBody,
    s: &Segment,
    first: bool,
) -> impl Fn(Vector) -> Vector + use<> {
    // recover the rigid map from the placed shape face: first segment: translation only
    let jf = s.body_face(DeckEnd::Joint);
    let placed = if first { b.end } else { b.start };
    let a = -jf.inward;
    let bb = -placed.inward;
    let (c, sn) = (a.dot(&bb), cross(&a, &bb));
    let rot = move |p: Vector| Vector::new(c * p.x - sn * p.y, sn * p.x + c * p.y);
    let t = placed.mid - rot(jf.mid);
    move |p: Vector| rot(p) + t
}
