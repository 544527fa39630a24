//! Piers: a cap on a column under a joint, and the coupled linear system of a bridge that has
//! them.
//!
//! # Model
//! A pier under joint `k` is a cap body of mass `m_c` that translates in the plan without
//! turning (`(x_c, y_c)` relative to the ground; its column holds its rotation) on a column to
//! the ground: a spring of initial stiffness `k0` in each plan direction, linear or bilinear with
//! kinematic hardening (yield force `F_y`, post-yield ratio `b`; the plan return mapping of
//! [`crate::element::bearing::BilinearBearing`], which along one axis is OpenSees `Steel01`
//! exactly), in parallel with a dashpot `c` in each plan direction. The bearings of the two
//! segment ends at the joint sit on the cap: a bearing acts on its *deformation*, the
//! displacement of its point on the segment relative to the cap, `u = B_s q_s − q_c` with
//! `B_s = [[1, 0, −r_y], [0, 1, r_x]]` (`r` its arm). A bearing belongs to the end nearer to it
//! (its distance to each end face's line); one midway between two ends is refused when a pier
//! is at either end. The seats of the two ends are measured relative to the cap: a deck unseats
//! from its pier, not from the ground.
//!
//! # The coupled system
//! A bearing on a cap links two bodies, so `M`, `K`, `C` are no longer block diagonal: the
//! integrator then uses the dense matrices of the whole system (`n = 3 N + 2 P` coordinates,
//! [`Coupled`]), assembled from the links: each bearing (and each bearing dashpot of
//! [`super::Segment::bearing_damping`]) adds `k Lᵀ L` (`c Lᵀ L`) with `L = [B_s, −I]` over the
//! coordinates of its two bodies; each column `k0 I` and `c I` on its cap. The yielding elements'
//! initial stiffness is kept apart (`K_y`): the strain energy of the balance is
//! `½ qᵀ (K − K_y) q`, their work is booked as the yielding bearings' is. Damping: the bearing
//! and column dashpots, plus, with [`super::DampingModel::Rayleigh`] and `ζ > 0`, `a_0 M + a_1 K`
//! of the whole system at its two lowest distinct natural frequencies, or with
//! [`super::DampingModel::TranslationalDashpots`] each segment's dashpots to the ground as
//! without piers.

use super::*;
use crate::sim::coupled::Coupled;
use crate::sim::dofs::BodyKind;
use nalgebra::DMatrix;

/// A pier column: initial stiffness per plan direction, optional yield.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PierColumn {
    /// Initial stiffness `k0 > 0` in each plan direction \[N/m\].
    pub k0: Real,
    /// Yield force `F_y > 0` \[N\] (`None`: elastic).
    pub fy: Option<Real>,
    /// Post-yield stiffness ratio `b ∈ [0, 1)`.
    pub b: Real,
    /// Yield along each of the column's two axes apart (along the joint's face normal and along
    /// the face: OpenSees `Steel01` on each, a square yield surface), else coupled in the plan
    /// (a yield circle of radius `F_y`).
    pub per_axis: bool,
}

/// A pier under a joint (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pier {
    /// The joint it carries (0-based).
    pub joint: usize,
    /// Mass of the cap `m_c > 0` \[kg\].
    pub cap_mass: Real,
    /// The column.
    pub column: PierColumn,
    /// Column dashpot in each plan direction `c ≥ 0` \[N·s/m\].
    pub damping: Real,
}

/// `pier[p].key`.
pub(crate) fn pier_key(p: usize, key: &str) -> BridgeKey {
    BridgeKey::new(BridgeTable::Pier(p), key)
}

impl BridgeModel {
    /// Checks every pier: its joint exists and carries no other pier, positive finite mass and
    /// stiffness, a yield force `> 0` and `b ∈ [0, 1)`, a dashpot `≥ 0`, and some bearing on it.
    pub(super) fn validate_piers(&self) -> Result<(), SimError> {
        for (p, pier) in self.piers.iter().enumerate() {
            let j = pier.joint;
            if j >= self.joints.len() {
                return Err(SimError::argument(
                    pier_key(p, "joint"),
                    format!(
                        "there is no joint {} (the bridge has {}); a pier carries a joint between \
                         two segments",
                        j + 1,
                        self.joints.len()
                    ),
                ));
            }
            if let Some(q) = self.piers[..p].iter().position(|o| o.joint == j) {
                return Err(SimError::argument(
                    pier_key(p, "joint"),
                    format!("joint {} already has a pier (pier[{q}])", j + 1),
                ));
            }
            let m = pier.cap_mass;
            check(
                pier_key(p, "cap_mass"),
                m,
                m > 0.0,
                "must be finite and > 0",
            )?;
            let c = &pier.column;
            check(
                pier_key(p, "k0"),
                c.k0,
                c.k0 > 0.0,
                "must be finite and > 0",
            )?;
            if let Some(fy) = c.fy {
                check(pier_key(p, "fy"), fy, fy > 0.0, "must be finite and > 0")?;
                crate::element::bearing::BilinearBearing::new(c.k0, fy, c.b)
                    .map_err(|e| SimError::argument(pier_key(p, e.key()), e.to_string()))?;
            }
            check(
                pier_key(p, "b"),
                c.b,
                (0.0..1.0).contains(&c.b),
                "must lie in [0, 1)",
            )?;
            let d = pier.damping;
            check(
                pier_key(p, "damping"),
                d,
                d >= 0.0,
                "must be finite and >= 0",
            )?;
        }
        for (i, s) in self.segments.iter().enumerate() {
            let d = s.bearing_damping;
            check(
                seg_key(i, "bearing_damping"),
                d,
                d >= 0.0,
                "must be finite and >= 0",
            )?;
        }
        let on = self.bearing_piers()?;
        for (p, pier) in self.piers.iter().enumerate() {
            let carried = on.iter().flatten().any(|b| *b == Some(p));
            if !carried {
                return Err(SimError::argument(
                    pier_key(p, "joint"),
                    format!(
                        "no bearing sits on this pier: give the segments at joint {} bearings \
                         near that joint",
                        pier.joint + 1
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The pier under each end `[start, end]` of segment `i`.
    pub(crate) fn end_piers(&self, i: usize) -> [Option<usize>; 2] {
        let at = |joint: usize| self.piers.iter().position(|p| p.joint == joint);
        let n = self.segments.len();
        [
            if i > 0 { at(i - 1) } else { None },
            if i + 1 < n { at(i) } else { None },
        ]
    }

    /// Per segment, per bearing: the pier it sits on (`None`: the ground). Errors name a
    /// bearing midway between a segment's two ends when a pier is at either end.
    pub(crate) fn bearing_piers(&self) -> Result<Vec<Vec<Option<usize>>>, SimError> {
        let bodies = self.layout();
        let points = self.bearing_points();
        let mut out = Vec::with_capacity(bodies.len());
        for (i, b) in bodies.iter().enumerate() {
            let ends = self.end_piers(i);
            let mut seg = Vec::with_capacity(points[i].len());
            for (k, p) in points[i].iter().enumerate() {
                if ends == [None, None] {
                    seg.push(None);
                    continue;
                }
                let ds = (p - b.start.mid).dot(&b.start.inward).abs();
                let de = (p - b.end.mid).dot(&b.end.inward).abs();
                if (ds - de).abs() <= 1e-9 * (ds + de) {
                    return Err(SimError::argument(
                        seg_key(i, "bearing_points"),
                        format!(
                            "bearing {} is as far from the segment's start as from its end, so \
                             it belongs to neither end's pier; place it nearer one end",
                            k + 1
                        ),
                    ));
                }
                seg.push(if ds < de { ends[0] } else { ends[1] });
            }
            out.push(seg);
        }
        Ok(out)
    }

    /// The body index of pier `p`'s cap (after the segments).
    pub(crate) fn cap_body(&self, p: usize) -> usize {
        self.segments.len() + p
    }

    /// The kinds of the bodies: the segments, then one cap per pier.
    pub(crate) fn body_kinds(&self) -> Vec<BodyKind> {
        let segs = std::iter::repeat_n(BodyKind::PlanRigid, self.segments.len());
        let walls = (0..2).filter(|&s| self.wall_body(s).is_some()).count();
        segs.chain(std::iter::repeat_n(BodyKind::PlanPoint, self.piers.len()))
            .chain(std::iter::repeat_n(BodyKind::Axial, walls))
            .collect()
    }

    /// The dense `M`, `K`, `K_y`, `C` and load map of a bridge with piers (module doc); `None`
    /// without piers (the block-diagonal systems `systems` of the segments are the system)
    /// unless `always`.
    ///
    /// With `supports`, also the links' coupling to the support lines (`P_K`, `P_C`,
    /// [`crate::sim::excitation`]): a link from body point `B` to support line `s` adds `x Bᵀ` to
    /// the columns `2s, 2s+1` of `P_K` (`x` its stiffness) or `P_C` (its dashpot), and a Rayleigh
    /// damping adds `a_1` times the links' `P_K` to `P_C` (per segment, or of the whole system).
    pub(crate) fn coupled_system(
        &self,
        systems: &[BodySystem],
        always: bool,
        supports: bool,
    ) -> Result<Option<Coupled>, SimError> {
        if self.piers.is_empty() && !self.has_backwalls() && !always && !supports {
            return Ok(None);
        }
        let dofs = self.dofs();
        let n = dofs.len();
        let bodies = self.layout();
        let points = self.bearing_points();
        let on = self.bearing_piers()?;
        let mut m = DMatrix::zeros(n, n);
        let mut k = DMatrix::zeros(n, n);
        let mut ky = DMatrix::zeros(n, n);
        let mut c = DMatrix::zeros(n, n);
        let mut r = DMatrix::zeros(n, 2);
        let n_lines = if supports { self.segments.len() + 1 } else { 0 };
        let mut pk = DMatrix::zeros(n, 2 * n_lines);
        let mut pc = DMatrix::zeros(n, 2 * n_lines);
        let lines = self.bearing_lines();
        let coupled = !self.piers.is_empty() || self.has_backwalls();
        let rayleigh = self.damping_model == DampingModel::Rayleigh && self.damping_ratio > 0.0;
        for (i, sys) in systems.iter().enumerate() {
            let s = dofs.start(i);
            m.view_mut((s, s), (3, 3)).copy_from(&sys.mass);
            r[(s, 0)] = 1.0;
            r[(s + 1, 1)] = 1.0;
            // each segment's own damping block, unless Rayleigh damping of a coupled system
            if !coupled || self.damping_model == DampingModel::TranslationalDashpots {
                c.view_mut((s, s), (3, 3)).copy_from(&sys.damping);
            }
        }
        // a link between two body points: `x L^T L` with `L = [B_a, −B_b]`
        let add_link = |mat: &mut DMatrix<Real>, x: Real, a: (usize, Vector), b: Option<usize>| {
            let mut rows: Vec<(usize, [Real; 2])> = Vec::with_capacity(5);
            let ba = dofs.point_operator(a.0, &a.1);
            for (d, i) in dofs.range(a.0).enumerate() {
                rows.push((i, [ba[0][d], ba[1][d]]));
            }
            if let Some(cb) = b {
                let bb = dofs.point_operator(cb, &Vector::zeros());
                for (d, i) in dofs.range(cb).enumerate() {
                    rows.push((i, [-bb[0][d], -bb[1][d]]));
                }
            }
            for &(i, li) in &rows {
                for &(j, lj) in &rows {
                    mat[(i, j)] += x * (li[0] * lj[0] + li[1] * lj[1]);
                }
            }
        };
        // a link from a body point to support line `s`: `x Bᵀ` into its columns of `P`
        let add_support = |mat: &mut DMatrix<Real>, x: Real, a: (usize, Vector), s: usize| {
            let ba = dofs.point_operator(a.0, &a.1);
            for (d, i) in dofs.range(a.0).enumerate() {
                mat[(i, 2 * s)] += x * ba[0][d];
                mat[(i, 2 * s + 1)] += x * ba[1][d];
            }
        };
        for (i, s) in self.segments.iter().enumerate() {
            // the segment's own Rayleigh stiffness part on its links' deformation rates
            let a1 = if rayleigh && !coupled {
                systems[i].rayleigh.1
            } else {
                0.0
            };
            for (bi, (br, p)) in s.bearings.iter().zip(&points[i]).enumerate() {
                let arm = (i, p - bodies[i].centroid);
                let base = on[i][bi].map(|p| self.cap_body(p));
                if supports && base.is_none() {
                    add_support(&mut pk, br.stiffness, arm, lines[i][bi]);
                    add_support(
                        &mut pc,
                        s.bearing_damping + a1 * br.stiffness,
                        arm,
                        lines[i][bi],
                    );
                }
                add_link(&mut k, br.stiffness, arm, base);
                if s.bearing_yield.is_some() && br.stiffness > 0.0 {
                    add_link(&mut ky, br.stiffness, arm, base);
                }
                if s.bearing_damping > 0.0 {
                    add_link(&mut c, s.bearing_damping, arm, base);
                }
            }
        }
        for (p, pier) in self.piers.iter().enumerate() {
            let cb = self.cap_body(p);
            let s = dofs.start(cb);
            for d in 0..2 {
                m[(s + d, s + d)] = pier.cap_mass;
                r[(s + d, d)] = 1.0;
                k[(s + d, s + d)] += pier.column.k0;
                c[(s + d, s + d)] += pier.damping;
                if supports {
                    // the column stands on the joint's support line
                    let line = 2 * (pier.joint + 1) + d;
                    pk[(s + d, line)] += pier.column.k0;
                    pc[(s + d, line)] += pier.damping;
                }
                if pier.column.fy.is_some() {
                    ky[(s + d, s + d)] += pier.column.k0;
                }
            }
        }
        for side in 0..2 {
            let (Some(wb), Some(w)) = (
                self.wall_body(side),
                self.abutments[side].and_then(|a| a.backwall),
            ) else {
                continue;
            };
            let (s, a) = (dofs.start(wb), dofs.axis(wb));
            m[(s, s)] = w.mass;
            r[(s, 0)] = a.x;
            r[(s, 1)] = a.y;
            if let Some(p) = w.piles {
                k[(s, s)] += p.k;
                ky[(s, s)] += p.k;
                if supports {
                    // the piles stand on the abutment's support line
                    let line = if side == 0 { 0 } else { self.segments.len() };
                    pk[(s, 2 * line)] += p.k * a.x;
                    pk[(s, 2 * line + 1)] += p.k * a.y;
                }
            }
        }
        if coupled && rayleigh {
            let om = system_frequencies(&m, &k);
            let lowest = [
                om[0],
                om.get(1).copied().unwrap_or(0.0),
                om.get(2).copied().unwrap_or(0.0),
            ];
            let (a0, a1) = rayleigh_coefficients(self.damping_ratio, &lowest).ok_or_else(|| {
                SimError::invalid(
                    "damping_ratio",
                    self.damping_ratio,
                    "the bridge has no stiffness, so its Rayleigh damping is undefined",
                )
            })?;
            c += &m * a0 + &k * a1;
            pc += &pk * a1;
        }
        let support = supports.then_some((pk, pc));
        Ok(Some(Coupled {
            m,
            k,
            ky,
            c,
            r,
            support,
        }))
    }
}

impl BridgeModel {
    /// The natural frequencies of the whole coupled system (segments, pier caps and backwalls on
    /// the bearings, columns and piles at their initial stiffness; the backfill, compression only,
    /// and the contacts left out), in increasing order \[rad/s\]; `None` for a bridge without
    /// piers or backwalls (its segments are separate systems:
    /// [`BridgeModel::segment_frequencies`]).
    pub fn system_frequencies(&self) -> Result<Option<Vec<Real>>, SimError> {
        let systems = self.body_systems()?;
        Ok(self
            .coupled_system(&systems, false, false)?
            .map(|c| system_frequencies(&c.m, &c.k)))
    }
}

/// Natural frequencies of `(M, K)` in increasing order \[rad/s\] (`M` diagonal, positive).
pub(crate) fn system_frequencies(m: &DMatrix<Real>, k: &DMatrix<Real>) -> Vec<Real> {
    let n = m.nrows();
    let s = DMatrix::from_fn(n, n, |i, j| k[(i, j)] / (m[(i, i)] * m[(j, j)]).sqrt());
    let mut w: Vec<Real> = s
        .symmetric_eigenvalues()
        .iter()
        .map(|l| l.max(0.0).sqrt())
        .collect();
    w.sort_by(|a, b| a.total_cmp(b));
    w
}
