//! The elements' force over a step and its bookkeeping: the trapezoidal mean `R̄` of the
//! committed and the predicted force ([`Elements::step_force`]), the work booked on the members
//! ([`Elements::book`]) and the commit of their return mappings ([`Elements::commit`]).

use super::{Elements, cable_points};
use crate::element::restrainer::RestrainerResponse;
use crate::math::{Real, Vector, cross};
use crate::sim::contact::{Pose, State};
use crate::sim::dofs::Dofs;
use crate::sim::model::SegmentBody;

/// The elements' force over one step ([`Elements::step_force`]) and the vectors it is computed
/// with (`3 n_bodies` entries each), allocated once per run: a step allocates nothing.
#[derive(Debug, Clone)]
pub(crate) struct StepForce {
    /// `R̄`.
    pub r: State,
    /// `R̄_b`, the bearings' part of `R̄`.
    pub rb: State,
    /// The predicted state `q_k + h u_k`.
    pred: State,
    /// The pose at `pred` (with cables only).
    pose_pred: Pose,
    /// `R(q_k)` and its bearings' part.
    r0: State,
    rb0: State,
    /// The committed plastic displacements `rb0` was formed from (one per yielding member).
    up0: Vec<Vector>,
    /// `R̃(q_k + h u_k)` and its bearings' part.
    r1: State,
    pub(in crate::sim) rb1: State,
    /// The cables' part `R̄ − R̄_b` (work booking).
    rc: State,
    /// The backfills' part of `R̄`.
    rf: State,
    /// The shear keys' part of `R̄`.
    rk: State,
}

impl StepForce {
    /// Coordinate `i` of the step's force `R̄` split by member: `(bearings, restrainers, shear
    /// keys)` (the yielding bearings' held part `R̄_b`; the cables' `R̄ − R̄_b − R̄_f − R̄_k`, the
    /// backfills' `R̄_f` acting on walls only).
    #[inline]
    pub fn parts(&self, i: usize) -> (Real, Real, Real) {
        let cables = self.r[i] - self.rb[i] - self.rf[i] - self.rk[i];
        (self.rb[i], cables, self.rk[i])
    }

    /// Zeroed vectors for a bridge of the segments of `dofs`.
    pub fn new(dofs: &Dofs) -> Self {
        let n_bodies = dofs.n_bodies();
        let z = || State::zeros(dofs.len());
        StepForce {
            r: z(),
            rb: z(),
            pred: z(),
            pose_pred: Pose {
                d: Vec::with_capacity(n_bodies),
                sc: Vec::with_capacity(n_bodies),
                g: Vec::with_capacity(n_bodies),
            },
            r0: z(),
            rb0: z(),
            up0: Vec::new(),
            r1: z(),
            rb1: z(),
            rc: z(),
            rf: z(),
            rk: z(),
        }
    }
}

impl Elements {
    /// The force held over the step from `q_k` with velocity `u_k`, first estimate: the mean
    /// `R̄ = (1−θ) R(q_k) + θ R̃(q_k + h u_k)` of the committed force and the trial force at the
    /// predicted end of the step (return mappings evaluated, not committed), second order where
    /// the element laws are smooth. Leaves `R̄` in `f.r` and its bearings' part in `f.rb` (the
    /// rest is the cables'). `pose` is the pose at `q` (its `sin θ_j, cos θ_j` are shared with
    /// the contact geometry of the step); the pose at the predicted state is computed here only
    /// when there are cables (bearings use the linearised deformation).
    #[allow(clippy::too_many_arguments)]
    pub fn step_force(
        &self,
        q: &State,
        u: &State,
        h: Real,
        th: Real,
        bodies: &[SegmentBody],
        pose: &Pose,
        f: &mut StepForce,
    ) {
        // over slices (no per-entry index checks of the matrix type): the same operations
        let pred = f.pred.as_mut_slice();
        for (p, (qi, ui)) in pred.iter_mut().zip(q.as_slice().iter().zip(u.as_slice())) {
            *p = qi + ui * h;
        }
        // `R(q_k)` of the bearings depends on their committed plastic displacements only:
        // formed again when one of them has changed (a member flowed in the last step)
        let fresh = f.up0.len() == self.bearings.len()
            && self
                .bearings
                .iter()
                .zip(&f.up0)
                .all(|(b, u)| b.state.u_p == *u);
        if !fresh {
            self.bearing_force(q, false, &mut f.rb0);
            f.up0.clear();
            f.up0.extend(self.bearings.iter().map(|b| b.state.u_p));
        }
        self.bearing_force(&f.pred, true, &mut f.rb1);
        // the cables' terms are added after the bearings', entry by entry, as one sum
        f.r0.copy_from(&f.rb0);
        f.r1.copy_from(&f.rb1);
        if !self.cables.is_empty() {
            self.add_cable_forces(&mut f.r0, pose, bodies);
            f.pose_pred.set(bodies, &self.dofs, f.pred.as_slice());
            self.add_cable_forces(&mut f.r1, &f.pose_pred, bodies);
        }
        // the backfills' terms after the cables' (their part `R̄_f` apart, for their work)
        if !self.backfills.is_empty() {
            f.rf.fill(0.0);
            for b in &self.backfills {
                let i = self.dofs.start(b.body);
                let f0 = -b.element.committed().force;
                let f1 = -b.element.trial(f.pred[i] - b.ground).force;
                f.r0[i] += f0;
                f.r1[i] += f1;
                f.rf[i] += f0 * (1.0 - th) + f1 * th;
            }
        }
        if !self.keys.is_empty() {
            f.rk.fill(0.0);
            for k in &self.keys {
                let f1 = k
                    .element
                    .trial(k.deformation(&self.dofs, f.pred.as_slice()))
                    .force;
                k.add_force(&self.dofs, k.force, &mut f.r0);
                k.add_force(&self.dofs, f1, &mut f.r1);
                k.add_force(&self.dofs, k.force * (1.0 - th) + f1 * th, &mut f.rk);
            }
        }
        // (1−θ) a + θ b: for θ = ½ the same bits as (a + b)·½ (scaling by ½ is exact)
        let (r, rb) = (f.r.as_mut_slice(), f.rb.as_mut_slice());
        let (r0, r1, rb0, rb1) = (
            f.r0.as_slice(),
            f.r1.as_slice(),
            f.rb0.as_slice(),
            f.rb1.as_slice(),
        );
        for i in 0..r.len() {
            r[i] = r0[i] * (1.0 - th) + r1[i] * th;
            rb[i] = rb0[i] * (1.0 - th) + rb1[i] * th;
        }
    }

    /// The bearings' `R(q)` into `r`; `trial`: their plastic displacement of the return mapping
    /// to `q` (else the committed one).
    fn bearing_force(&self, q: &State, trial: bool, r: &mut State) {
        r.as_mut_slice().fill(0.0);
        for b in &self.bearings {
            let u_p = if trial {
                let u = b.deformation(&self.dofs, q);
                b.law.response(&u, &b.state).trial.u_p
            } else {
                b.state.u_p
            };
            let fp = (1.0 - b.law.b()) * b.law.k0() * u_p;
            let m = -b.arm.y * fp.x + b.arm.x * fp.y;
            self.dofs
                .add_plan(b.body, r.as_mut_slice(), [fp.x, fp.y, m]);
            if let Some((c, arm)) = b.base {
                let m = -arm.y * fp.x + arm.x * fp.y;
                self.dofs.add_plan(c, r.as_mut_slice(), [-fp.x, -fp.y, -m]);
            }
        }
    }

    /// Adds the cables' `R(q)` to `r`, `pose` the pose at `q`.
    fn add_cable_forces(&self, r: &mut State, pose: &Pose, bodies: &[SegmentBody]) {
        for c in &self.cables {
            let (pa, pb, ga, gb) = cable_points(c, pose, bodies);
            let d = pb - pa;
            let len = d.norm();
            let f = c.element.trial(len - c.length).force;
            if f == 0.0 || len == 0.0 {
                continue;
            }
            let n = d / len;
            for (end, p, g, s) in [(c.a, pa, ga, f), (c.b, pb, gb, -f)] {
                // an end on a support takes its force into the support
                let Some(j) = end.body() else { continue };
                let fv = n * s;
                let m = cross(&(p - g), &fv);
                self.dofs.add_plan(j, r.as_mut_slice(), [fv.x, fv.y, m]);
            }
        }
    }

    /// Books the work of the step done on the elements (`f` from [`Elements::step_force`]):
    /// on a segment with yielding bearings (`yielding[j]`) the work of their whole force,
    /// `h ū·(K q_θ − R̄_b)` (`kq_th = K q_θ`; the linear part `K q` is their initial stiffness,
    /// left out of the strain energy [`crate::sim::driver`] books), so that the energy they absorb is
    /// summed from forces of their own size (never from `½ k0 |u|²` of a plastic slide, which
    /// for a stiff bearing is many orders above the input); on the cables `−h ū·(R̄ − R̄_b)`.
    pub fn book(
        &mut self,
        h: Real,
        u_mid: &State,
        (kq_th, yielding): (&State, &[bool]),
        f: &mut StepForce,
        bodies: usize,
    ) {
        let (r, rb) = (&f.r, &f.rb);
        if self.w_bearings.len() < bodies {
            self.w_bearings.resize(bodies, 0.0);
        }
        for (j, w) in self.w_bearings.iter_mut().enumerate() {
            if !yielding[j] {
                continue;
            }
            let s: Real = self
                .dofs
                .range(j)
                .map(|i| u_mid[i] * (kq_th[i] - rb[i]))
                .sum();
            *w += h * s;
        }
        let (r, rb) = (r.as_slice(), rb.as_slice());
        for (c, (ri, bi)) in f.rc.as_mut_slice().iter_mut().zip(r.iter().zip(rb)) {
            *c = ri - bi;
        }
        if self.backfills.is_empty() && self.keys.is_empty() {
            self.w_cables -= h * u_mid.dot(&f.rc);
        } else {
            let wf = if self.backfills.is_empty() {
                0.0
            } else {
                h * u_mid.dot(&f.rf)
            };
            let wk = if self.keys.is_empty() {
                0.0
            } else {
                h * u_mid.dot(&f.rk)
            };
            self.w_backfill -= wf;
            self.w_keys -= wk;
            self.w_cables -= h * u_mid.dot(&f.rc) - wf - wk;
        }
    }

    /// Commits the return mappings at the new state `q` (`pose`: the pose at `q`).
    pub fn commit(&mut self, q: &State, pose: &Pose, bodies: &[SegmentBody]) {
        if self.w_member.len() != self.bearings.len() {
            self.w_member = vec![0.0; self.bearings.len()];
            self.member_state = vec![(Vector::zeros(), Vector::zeros()); self.bearings.len()];
        }
        for (i, b) in self.bearings.iter_mut().enumerate() {
            let u = b.deformation(&self.dofs, q);
            b.state = b.law.response(&u, &b.state).trial;
            let f = u * b.law.k0() - b.state.u_p * ((1.0 - b.law.b()) * b.law.k0());
            let (u0, f0) = self.member_state[i];
            self.w_member[i] += 0.5 * (f0 + f).dot(&(u - u0));
            self.member_state[i] = (u, f);
        }
        for b in &mut self.backfills {
            let resp = b.element.trial(q[self.dofs.start(b.body)] - b.ground);
            b.element.commit(&resp);
        }
        for k in &mut self.keys {
            let resp = k.element.trial(k.deformation(&self.dofs, q.as_slice()));
            k.element.commit(&resp);
            k.force = resp.force;
        }
        for i in 0..self.cables.len() {
            let (pa, pb, _, _) = cable_points(&self.cables[i], pose, bodies);
            let c = &mut self.cables[i];
            let resp: RestrainerResponse = c.element.trial((pb - pa).norm() - c.length);
            c.element.commit(&resp);
        }
    }
}
