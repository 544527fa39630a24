//! The bridge model turned into what the integrator runs: the DOF map, the segments placed end
//! to end, the bearings' points, each segment's body system (mass, stiffness, damping), the
//! seated ends, the driver's view ([`Bridge`]), the two-deck preset as a bridge and the yielding
//! elements.

use super::*;

impl BridgeModel {
    /// The contact laws of the joints and the present abutments, in that order.
    pub(crate) fn contacts(&self) -> impl Iterator<Item = (BridgeKey, &JointContact)> {
        let joints = self
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| (joint_key(k, "law"), &j.contact));
        let abuts = self
            .abutments
            .iter()
            .enumerate()
            .filter_map(|(s, a)| a.as_ref().map(|a| (abut_key(s, "law"), &a.contact)));
        joints.chain(abuts)
    }

    /// The DOF map of the bridge: every segment a plan rigid body `(x, y, θ)`, in bridge order,
    /// then every pier's cap `(x, y)` ([`Pier`]).
    pub fn dofs(&self) -> Dofs {
        Dofs::new(self.body_kinds()).with_axes(self.wall_axes())
    }

    /// The segments placed end to end in the global frame (module doc).
    pub fn layout(&self) -> Vec<SegmentBody> {
        let mut out: Vec<SegmentBody> = Vec::with_capacity(self.segments.len());
        for (i, s) in self.segments.iter().enumerate() {
            let mp = s.shape.mass_properties();
            let jf = s.body_face(DeckEnd::Joint);
            let ff = s.body_face(DeckEnd::Far);
            let g0 = s.mirror(mp.centroid);
            let body = if i == 0 {
                let off = Vector::new(0.0, self.joints.first().map_or(0.0, |j| j.gap));
                let t = |p: Vector| off + p;
                let mv = |f: &EndFace| face([t(f.corners[0]), t(f.corners[1])], f.inward);
                SegmentBody {
                    mass: MassProperties { centroid: g0, ..mp },
                    centroid: t(g0),
                    start: mv(&ff),
                    end: mv(&jf),
                }
            } else {
                let prev = out[i - 1].end;
                // (a model with too few joints is refused by `validate`; laid out without them)
                let gap = self.joints.get(i - 1).map_or(0.0, |j| j.gap);
                // turn the joint face's outward normal (−inward) onto the previous face's inward
                // normal, then move its midpoint to the previous midpoint − gap ν
                let (a, b) = (-jf.inward, prev.inward);
                let (c, sn) = (a.dot(&b), cross(&a, &b));
                let rot = |p: Vector| Vector::new(c * p.x - sn * p.y, sn * p.x + c * p.y);
                let t = prev.mid - prev.inward * gap - rot(jf.mid);
                let tr = |p: Vector| rot(p) + t;
                let mv = |f: &EndFace| face([tr(f.corners[0]), tr(f.corners[1])], rot(f.inward));
                SegmentBody {
                    mass: MassProperties { centroid: g0, ..mp },
                    centroid: tr(g0),
                    start: mv(&jf),
                    end: mv(&ff),
                }
            };
            out.push(body);
        }
        out
    }

    /// Bearing points of every segment in the global reference pose.
    pub fn bearing_points(&self) -> Vec<Vec<Vector>> {
        let bodies = self.layout();
        self.segments
            .iter()
            .zip(&bodies)
            .enumerate()
            .map(|(i, (s, b))| {
                let place = placement(b, s, i == 0);
                s.bearings.iter().map(|br| place(br.point)).collect()
            })
            .collect()
    }

    /// Natural frequencies `ω_1 ≤ ω_2 ≤ ω_3` of every segment on its bearings \[rad/s\] (a
    /// mechanism, free to slide or spin, has `ω_1 = 0`).
    pub fn segment_frequencies(&self) -> Result<Vec<[Real; 3]>, SimError> {
        Ok(self.body_systems()?.iter().map(|b| b.frequencies).collect())
    }

    /// Each segment's `3 × 3` blocks of `M`, `K`, `C`, its natural frequencies and Rayleigh
    /// coefficients: the one assembly every run and every check uses (errors name the segment).
    pub fn body_systems(&self) -> Result<Vec<BodySystem>, SimError> {
        let bodies = self.layout();
        let points = self.bearing_points();
        let mut out = Vec::with_capacity(bodies.len());
        for (i, (b, s)) in bodies.iter().zip(&self.segments).enumerate() {
            let mp = b.mass;
            let mj = Matrix3::from_diagonal(&Vector3::new(mp.mass, mp.mass, mp.inertia));
            let mut kj = Matrix3::zeros();
            for (br, p) in s.bearings.iter().zip(&points[i]) {
                let r = p - b.centroid;
                let bm = Matrix2x3::new(1.0, 0.0, -r.y, 0.0, 1.0, r.x);
                kj += br.stiffness * bm.transpose() * bm;
            }
            let om = deck_frequencies(&mp, &kj);
            if om.iter().any(|w| !w.is_finite()) {
                return Err(SimError::invalid(
                    seg_key(i, "mass"),
                    mp.mass,
                    "the bearing stiffness over this mass (or inertia) overflows",
                ));
            }
            // dashpots (c = 2ζmω, zero without stiffness) need no Rayleigh fit
            let fit = match crate::sim::pair_errors::needs_frequencies(self.damping_model) {
                true => rayleigh_coefficients(self.damping_ratio, &om),
                false => Some((0.0, 0.0)),
            };
            let (a0, a1) = fit.ok_or_else(|| {
                SimError::invalid(
                    seg_key(i, "bearings"),
                    0.0,
                    &format!(
                        "segment[{i}] has no bearing stiffness, so Rayleigh damping at its natural \
                         frequencies is undefined; set bridge.damping_ratio = 0 or bridge.damping \
                         = \"dashpots\", or give it bearing stiffness"
                    ),
                )
            })?;
            let (cj, a0, a1) = crate::sim::options::damping_block(
                self.damping_model,
                self.damping_ratio,
                &mj,
                &kj,
                a0,
                a1,
            );
            out.push(BodySystem {
                mass: mj,
                stiffness: kj,
                damping: cj,
                frequencies: om,
                rayleigh: (a0, a1),
            });
        }
        Ok(out)
    }

    /// The names of the seated ends in the order of a run's seat outputs (`summary.json`
    /// `seats[]`): per segment `segment<i>-start`, `segment<i>-end` (1-based), in bridge order.
    pub fn seat_end_names(&self) -> Vec<String> {
        (1..=self.segments.len())
            .flat_map(|i| ["start", "end"].map(|f| format!("segment{i}-{f}")))
            .collect()
    }

    /// The driver's view of the bridge: segments, joints, abutments, seats (per segment
    /// `[start, end]`, named as [`Self::seat_end_names`]).
    pub(crate) fn bridge(&self) -> Bridge {
        let bodies = self.layout();
        let n = bodies.len();
        let joints = self
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| JointGeom::new(&bodies, k, j.gap))
            .collect();
        let supports = Support::of_bridge(self.abutments.map(|a| a.is_some()));
        let abutments = self
            .abutments
            .iter()
            .enumerate()
            .filter_map(|(side, a)| {
                let a = a.as_ref()?;
                let body = if side == 0 { 0 } else { n - 1 };
                let mut face = AbutmentFace::new(&bodies, (body, side), a.gap);
                face.wall = self.wall_body(side);
                Some(face)
            })
            .collect();
        let mut seats = Vec::with_capacity(2 * n);
        for (i, b) in bodies.iter().enumerate() {
            let start = if i == 0 {
                self.abutments[0].map_or(self.outer_seat_length, |a| a.seat_length)
            } else {
                self.joints[i - 1].seat_length
            };
            let end = if i + 1 == n {
                self.abutments[1].map_or(self.outer_seat_length, |a| a.seat_length)
            } else {
                self.joints[i].seat_length
            };
            let start_support = match i {
                0 if self.abutments[0].is_some() => SeatSupport::Abutment(0),
                0 => SeatSupport::Outer(0),
                _ => SeatSupport::Joint(i - 1),
            };
            let end_support = match i + 1 == n {
                true if self.abutments[1].is_some() => SeatSupport::Abutment(1),
                true => SeatSupport::Outer(1),
                false => SeatSupport::Joint(i),
            };
            let caps = self.end_piers(i).map(|p| p.map(|p| self.cap_body(p)));
            for (at_end, f, length, support) in [
                (false, &b.start, start, start_support),
                (true, &b.end, end, end_support),
            ] {
                seats.push(SeatEnd {
                    body: i,
                    at_end,
                    support,
                    corners: f.corners,
                    inward: f.inward,
                    length,
                    base: caps[usize::from(at_end)],
                    line: i + usize::from(at_end),
                });
            }
        }
        let dofs = self.dofs();
        let elements = self.elements(&bodies, &dofs);
        let on = self.bearing_piers().expect("validated");
        let lines = self.bearing_lines();
        Bridge {
            piers: self
                .piers
                .iter()
                .enumerate()
                .map(|(p, pier)| {
                    let body = self.cap_body(p);
                    crate::sim::view::PierAt {
                        joint: pier.joint,
                        body,
                        k0: pier.column.k0,
                        elements: (0..elements.bearings.len())
                            .filter(|&e| elements.bearings[e].body == body)
                            .collect(),
                    }
                })
                .collect(),
            dofs,
            supports,
            bodies,
            joints,
            abutments,
            seats,
            bearings: self
                .bearing_points()
                .into_iter()
                .zip(&self.segments)
                .enumerate()
                .map(|(i, (points, s))| {
                    let at =
                        |(((p, b), on), line): (((Vector, &Bearing), &Option<usize>), &usize)| {
                            crate::sim::view::BearingAt {
                                line: *line,
                                top: Attachment::Body(i, p),
                                bottom: match on {
                                    Some(pier) => Attachment::Body(self.cap_body(*pier), p),
                                    None => Attachment::Support(Support::GROUND, p),
                                },
                                stiffness: b.stiffness,
                            }
                        };
                    points
                        .into_iter()
                        .zip(&s.bearings)
                        .zip(&on[i])
                        .zip(&lines[i])
                        .map(at)
                        .collect()
                })
                .collect(),
            elements,
        }
    }
}

impl BridgeModel {
    /// The two-deck model as a bridge of two segments (deck 1 = segment 1, deck 2 = segment 2,
    /// abutment of deck 1 = start, of deck 2 = end); the same physics, laid out by
    /// [`BridgeModel::layout`].
    pub fn from_pair(model: &crate::sim::SimModel) -> Self {
        let shapes = model.shapes.unwrap_or([
            DeckShape::Curved(model.arrangement.deck1),
            DeckShape::Curved(model.arrangement.deck2),
        ]);
        // two-deck bearing points are relative to M_j in the global orientation: deck 2 is its
        // body frame turned by π
        let seg = |j: usize, bs: &[Bearing]| Segment {
            shape: shapes[j],
            mirrored: false,
            bearings: bs
                .iter()
                .map(|b| Bearing {
                    point: if j == 0 { b.point } else { -b.point },
                    stiffness: b.stiffness,
                })
                .collect(),
            bearing_yield: None,
            bearing_damping: 0.0,
        };
        let abut = |a: Option<crate::sim::SimAbutment>| {
            a.map(|a| BridgeAbutment {
                gap: a.gap,
                seat_length: a.seat_length,
                friction: model.friction,
                restitution: model.restitution,
                contact: model.contact,
                backwall: None,
                shear_keys: None,
            })
        };
        BridgeModel {
            segments: vec![seg(0, &model.bearings1), seg(1, &model.bearings2)],
            joints: vec![Joint {
                gap: model.gap,
                friction: model.friction,
                restitution: model.restitution,
                seat_length: model.seat_length,
                contact: model.contact,
                restrainers: Vec::new(),
            }],
            abutments: [abut(model.abutments[0]), abut(model.abutments[1])],
            outer_seat_length: model.seat_length,
            damping_ratio: model.damping_ratio,
            damping_model: model.damping_model,
            piers: Vec::new(),
        }
    }
}

impl BridgeModel {
    /// The yielding bearings and restrainers (validated parameters).
    pub(super) fn elements(
        &self,
        bodies: &[SegmentBody],
        dofs: &Dofs,
    ) -> crate::sim::elements::Elements {
        use crate::element::bearing::{BearingState, BilinearBearing};
        use crate::element::restrainer::{Restrainer, RestrainerElement, SlackGrowth};
        let mut el = crate::sim::elements::Elements {
            dofs: dofs.clone(),
            ..Default::default()
        };
        let points = self.bearing_points();
        let on = self.bearing_piers().expect("validated");
        let lines = self.bearing_lines();
        for (i, s) in self.segments.iter().enumerate() {
            let Some(y) = s.bearing_yield else { continue };
            let total: Real = s.bearings.iter().map(|b| b.stiffness).sum();
            for (slot, (b, p)) in s.bearings.iter().zip(&points[i]).enumerate() {
                if b.stiffness == 0.0 {
                    continue;
                }
                let law = BilinearBearing::new(b.stiffness, y.fy * (b.stiffness / total), y.b)
                    .expect("validated");
                el.bearings.push(crate::sim::elements::YieldingBearing {
                    body: i,
                    slot,
                    arm: p - bodies[i].centroid,
                    base: on[i][slot].map(|p| (self.cap_body(p), Vector::zeros())),
                    axis: None,
                    law,
                    state: BearingState::default(),
                    line: on[i][slot].is_none().then_some(lines[i][slot]),
                    ground: Vector::zeros(),
                });
            }
        }
        for side in 0..2 {
            let (Some(wb), Some(w)) = (
                self.wall_body(side),
                self.abutments[side].and_then(|a| a.backwall),
            ) else {
                continue;
            };
            if let Some(p) = w.piles {
                el.bearings.push(crate::sim::elements::YieldingBearing {
                    body: wb,
                    slot: side,
                    arm: Vector::zeros(),
                    base: None,
                    axis: None,
                    law: BilinearBearing::elastic_perfectly_plastic(p.k, p.fy).expect("validated"),
                    state: BearingState::default(),
                    line: Some(if side == 0 { 0 } else { self.segments.len() }),
                    ground: Vector::zeros(),
                });
            }
            if let Some(b) = w.backfill {
                el.backfills.push(crate::sim::elements::BackfillAt {
                    body: wb,
                    element: crate::element::backfill::BackfillElement::new(b),
                    line: if side == 0 { 0 } else { self.segments.len() },
                    ground: 0.0,
                });
            }
        }
        let n = bodies.len();
        for (side, a) in self.abutments.iter().enumerate() {
            let Some(law) = a.and_then(|a| a.shear_keys) else {
                continue;
            };
            let body = if side == 0 { 0 } else { n - 1 };
            let face = if side == 0 {
                &bodies[0].start
            } else {
                &bodies[n - 1].end
            };
            el.keys.push(crate::sim::elements::KeyAt {
                side,
                body,
                arm: face.mid - bodies[body].centroid,
                tangent: Vector::new(-face.inward.y, face.inward.x),
                element: crate::element::shear_key::ShearKeyElement::new(law),
                force: 0.0,
                line: if side == 0 { 0 } else { n },
                ground: 0.0,
            });
        }
        for (p, pier) in self.piers.iter().enumerate() {
            let Some(fy) = pier.column.fy else { continue };
            let law = BilinearBearing::new(pier.column.k0, fy, pier.column.b).expect("validated");
            // per axis: along the joint's face normal and along the face (one member each);
            // coupled: one member with a yield circle
            let along = bodies[pier.joint].end.inward;
            let axes = match pier.column.per_axis {
                true => vec![Some(along), Some(Vector::new(-along.y, along.x))],
                false => vec![None],
            };
            for axis in axes {
                el.bearings.push(crate::sim::elements::YieldingBearing {
                    body: self.cap_body(p),
                    slot: p,
                    arm: Vector::zeros(),
                    base: None,
                    axis,
                    law,
                    state: BearingState::default(),
                    line: Some(pier.joint + 1),
                    ground: Vector::zeros(),
                });
            }
        }
        for (k, j) in self.joints.iter().enumerate() {
            for r in &j.restrainers {
                let law =
                    Restrainer::new(r.k, r.slack, r.fy, SlackGrowth::Permanent).expect("validated");
                let [pa, pb] = restrainer_anchors(bodies, k, r);
                el.cables.push(crate::sim::elements::Cable {
                    joint: k,
                    a: Attachment::Body(k, pa),
                    b: Attachment::Body(k + 1, pb),
                    length: (pb - pa).norm(),
                    element: RestrainerElement::new(law),
                });
            }
        }
        el
    }
}
