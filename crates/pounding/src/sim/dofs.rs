//! The DOF map: where each body's generalised coordinates sit in the system's state vectors.
//!
//! A system of `N` bodies has one displacement vector `q` and one velocity vector `u`; body `b`
//! owns the contiguous range [`Dofs::range`]`(b)` of both, laid out by its [`BodyKind`]. Every
//! index into `q`, `u`, a force or a residual of the simulator goes through this map, so that a
//! body with another number of coordinates (a pier cap with two translations, a support with
//! none) changes the map, not the code that reads the state.
//!
//! Today every body is a [`BodyKind::PlanRigid`] deck segment: `(x, y, θ)`, the displacement of
//! its centroid relative to the ground and its rotation about the centroid.

use crate::math::{Real, Vector};
use std::ops::Range;

/// How a body's coordinates are laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyKind {
    /// A rigid body moving in the plan: `(x, y, θ)` \[m, m, rad\].
    PlanRigid,
    /// A body translating in the plan without turning: `(x, y)` \[m\] (a pier cap: its
    /// column holds its rotation). A wrench's moment on it goes into what holds it.
    PlanPoint,
    /// A body sliding along one fixed plan direction `a` (a unit vector, [`Dofs::axis`]): its
    /// one coordinate `s` \[m\], its displacement `s a` (an abutment's backwall, `a` into the
    /// soil). Force across `a` and moments go into what guides it.
    Axial,
}

impl BodyKind {
    /// Number of coordinates of a body of this kind.
    pub const fn len(self) -> usize {
        match self {
            BodyKind::PlanRigid => 3,
            BodyKind::PlanPoint => 2,
            BodyKind::Axial => 1,
        }
    }

    /// Whether this kind has no coordinates (never: every kind has some).
    pub const fn is_empty(self) -> bool {
        self.len() == 0
    }
}

/// One coordinate of a plan body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanDof {
    /// Translation along x \[m\].
    X,
    /// Translation along y \[m\].
    Y,
    /// Rotation about the vertical through the centroid \[rad\].
    Theta,
}

/// The DOF map of a system: body `b` owns `q[range(b)]` and `u[range(b)]`. The default is the
/// map of no body.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Dofs {
    kinds: Vec<BodyKind>,
    /// Per body: the direction of an [`BodyKind::Axial`] body (zero for the others).
    axes: Vec<Vector>,
    /// `start[b]`: the first index of body `b`; `start[N]` the total count (empty for the
    /// default map of no body).
    start: Vec<usize>,
}

impl Dofs {
    /// The map of bodies of the given kinds, in order.
    pub fn new(kinds: impl IntoIterator<Item = BodyKind>) -> Self {
        let kinds: Vec<BodyKind> = kinds.into_iter().collect();
        let axes = vec![Vector::zeros(); kinds.len()];
        let mut start = Vec::with_capacity(kinds.len() + 1);
        let mut at = 0;
        start.push(at);
        for k in &kinds {
            at += k.len();
            start.push(at);
        }
        Dofs { kinds, axes, start }
    }

    /// This map with the directions of its [`BodyKind::Axial`] bodies, in body order.
    pub fn with_axes(mut self, axes: impl IntoIterator<Item = Vector>) -> Self {
        let mut it = axes.into_iter();
        for (k, a) in self.kinds.iter().zip(self.axes.iter_mut()) {
            if *k == BodyKind::Axial {
                *a = it.next().expect("an axis per axial body");
            }
        }
        self
    }

    /// The direction of axial body `b`.
    #[inline]
    pub fn axis(&self, b: usize) -> Vector {
        self.axes[b]
    }

    /// The map of `n` plan rigid bodies (deck segments).
    pub fn plan_rigid(n: usize) -> Self {
        Self::new(std::iter::repeat_n(BodyKind::PlanRigid, n))
    }

    /// Total number of coordinates (the length of `q` and `u`).
    pub fn len(&self) -> usize {
        self.start.last().copied().unwrap_or(0)
    }

    /// No coordinates at all.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of bodies.
    pub fn n_bodies(&self) -> usize {
        self.kinds.len()
    }

    /// The kind of body `b`.
    pub fn kind(&self, b: usize) -> BodyKind {
        self.kinds[b]
    }

    /// The index of plan component `c` (0: x, 1: y, 2: θ) of the plan rigid body `b` (a deck
    /// segment).
    ///
    /// # Panics
    /// If body `b` is not a plan rigid body or `c > 2`.
    #[inline]
    pub fn plan_index(&self, b: usize, c: usize) -> usize {
        assert!(
            self.kinds[b] == BodyKind::PlanRigid && c < 3,
            "plan component {c} of body {b} ({:?})",
            self.kinds[b]
        );
        self.start[b] + c
    }

    /// The first index of body `b`.
    #[inline]
    pub fn start(&self, b: usize) -> usize {
        self.start[b]
    }

    /// The indices of body `b`.
    #[inline]
    pub fn range(&self, b: usize) -> Range<usize> {
        self.start[b]..self.start[b + 1]
    }

    /// The index of coordinate `d` of plan body `b` (a [`BodyKind::PlanPoint`] has no
    /// [`PlanDof::Theta`]).
    #[inline]
    pub fn plan(&self, b: usize, d: PlanDof) -> usize {
        debug_assert!(self.kinds[b] == BodyKind::PlanRigid || d != PlanDof::Theta);
        self.start[b]
            + match d {
                PlanDof::X => 0,
                PlanDof::Y => 1,
                PlanDof::Theta => 2,
            }
    }

    /// `(x, y, θ)` of plan body `b` in the state `v` (`θ = 0` for a [`BodyKind::PlanPoint`]).
    ///
    /// Read several times per body and step by the monitors and the contact steppers: the deck
    /// segment's triple is read in place, the other kinds out of line (the time loop's code
    /// stays small).
    #[inline(always)]
    pub fn plan_of(&self, b: usize, v: &[Real]) -> [Real; 3] {
        let s = self.start[b];
        if self.kinds[b] == BodyKind::PlanRigid {
            let x = &v[s..s + 3];
            return [x[0], x[1], x[2]];
        }
        self.plan_of_other(b, s, v)
    }

    /// [`Self::plan_of`] of a body that is not a [`BodyKind::PlanRigid`] (first index `s`).
    #[inline(never)]
    fn plan_of_other(&self, b: usize, s: usize, v: &[Real]) -> [Real; 3] {
        match self.kinds[b] {
            BodyKind::PlanRigid => [v[s], v[s + 1], v[s + 2]],
            BodyKind::PlanPoint => [v[s], v[s + 1], 0.0],
            BodyKind::Axial => {
                let a = self.axes[b];
                [v[s] * a.x, v[s] * a.y, 0.0]
            }
        }
    }

    /// Adds the plan wrench `(f_x, f_y, m)` on body `b` to the generalised force `f` (a
    /// [`BodyKind::PlanPoint`] takes `(f_x, f_y)`; its moment goes into what holds it).
    #[inline]
    pub fn add_plan(&self, b: usize, f: &mut [Real], w: [Real; 3]) {
        let s = self.start[b];
        if self.kinds[b] == BodyKind::Axial {
            let a = self.axes[b];
            f[s] += w[0] * a.x + w[1] * a.y;
            return;
        }
        let n = self.kinds[b].len();
        for (fi, wi) in f[s..s + n].iter_mut().zip(w) {
            *fi += wi;
        }
    }

    /// The linearised plan displacement operator of the body point with arm `r` (from the
    /// body's reference centroid): `u = B q_b` with `B = [[1, 0, −r_y], [0, 1, r_x]]` for a
    /// [`BodyKind::PlanRigid`] and `B = I` for a [`BodyKind::PlanPoint`]; returned as its
    /// columns `(B_x, B_y)` over the body's coordinates (unused entries zero).
    #[inline]
    pub fn point_operator(&self, b: usize, r: &Vector) -> [[Real; 3]; 2] {
        match self.kinds[b] {
            BodyKind::PlanRigid => [[1.0, 0.0, -r.y], [0.0, 1.0, r.x]],
            BodyKind::PlanPoint => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            BodyKind::Axial => {
                let a = self.axes[b];
                [[a.x, 0.0, 0.0], [a.y, 0.0, 0.0]]
            }
        }
    }

    /// Whether every body is a [`BodyKind::PlanRigid`] (the segments of a bridge on the ground).
    pub fn all_plan_rigid(&self) -> bool {
        self.kinds.iter().all(|k| *k == BodyKind::PlanRigid)
    }

    /// Which body and which coordinate index `k` of the state is.
    pub fn which(&self, k: usize) -> (usize, PlanDof) {
        let b = self.start.partition_point(|&s| s <= k) - 1;
        let d = match k - self.start[b] {
            0 => PlanDof::X,
            1 => PlanDof::Y,
            _ => PlanDof::Theta,
        };
        (b, d)
    }

    /// Whether index `k` of the state is a rotation (reported in degrees at the interfaces).
    pub fn is_rotation(&self, k: usize) -> bool {
        self.which(k).1 == PlanDof::Theta
    }

    /// The displacement `s a` of axial body `b` in `v` as a plan vector (zero for another kind).
    #[inline]
    pub fn axial_displacement(&self, b: usize, v: &[Real]) -> Real {
        debug_assert_eq!(self.kinds[b], BodyKind::Axial);
        v[self.start[b]]
    }

    /// [`Self::is_rotation`] of every index, in order (for writers that convert whole rows).
    pub fn rotations(&self) -> Vec<bool> {
        (0..self.len()).map(|k| self.is_rotation(k)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_bodies_own_consecutive_triples() {
        let d = Dofs::plan_rigid(3);
        assert_eq!(d.len(), 9);
        assert_eq!(d.range(1), 3..6);
        assert_eq!(d.plan(2, PlanDof::Theta), 8);
        assert_eq!(d.which(4), (1, PlanDof::Y));
        assert!(d.is_rotation(5) && !d.is_rotation(6));
        let q: Vec<Real> = (0..9).map(|i| i as Real).collect();
        assert_eq!(d.plan_of(1, &q), [3.0, 4.0, 5.0]);
        let mut f = vec![0.0; 9];
        d.add_plan(2, &mut f, [1.0, 2.0, 3.0]);
        assert_eq!(&f[6..], &[1.0, 2.0, 3.0]);
    }
}
