//! Nonlinear structural elements of a bridge in the time stepping: yielding bearings and
//! restrainers ([`crate::element`]).
//!
//! # Scheme
//! A bilinear bearing's force is `f = k0 u − (1 − b) k0 u_p` (`u` its linearised deformation,
//! `u_p` the plastic displacement of its elastic–perfectly-plastic spring): the linear part
//! `k0 u` is in the segment's stiffness `K` (so `Ŵ`, the periods and the Rayleigh damping use the
//! initial stiffness) and the rest is a generalised force `R_p = Σ_b Bᵀ (1 − b) k0 u_p`. A
//! restrainer pulls its two anchor points together with the tension `F(e)` of its elongation
//! `e = |P_b − P_a| − L_0` (exact positions): `R_r = F (n, r_a × n)` on the first segment and
//! `−F (n, r_b × n)` on the second, `n` the unit vector from `P_a` to `P_b`. Over a step they act
//! as the trapezoidal mean `R̄ = ½ (R(q_k) + R̃(q_k + h u_k))` of the committed force and the trial
//! force at the predicted end of the step (return mappings evaluated there, not committed): a
//! predictor–corrector of second order where the laws are smooth (with `R̄ = R(q_k)` the scheme
//! was first order and `viaduct-1d` differed from OpenSees' implicit Newmark by a few % at
//! dt = 1e-4; with the mean it agrees to 0.1 %). For the bearings this is only the first
//! estimate: [`super::yielding`] then solves their return mapping at the actual end of the step
//! together with the momentum balance (the explicit estimate let a stiff bearing carry many times
//! its yield force at a coarse step). After `q_{k+1}` the return mappings commit the new states.
//!
//! # Energy
//! With `R̄` inside the momentum balance the discrete energy balance stays exact when the work
//! done *on* the elements is booked beside the other terms. A segment with yielding bearings
//! books their whole force: `W_b = Σ h ū·(K q_θ − R̄_b)` (its `K` is their initial stiffness,
//! left out of the strain energy `½ qᵀ K q` of the balance), a sum of terms of the size of the
//! bearings' true forces: booking `½ qᵀ K q` and `−Σ h ū·R̄_b` apart made both grow like
//! `½ k0 |u_p|²` of the plastic slide (1e13 J for a stiff bearing under a 2 kJ input), whose
//! rounding was then reported as an energy error. `W_b` splits into what the bearings store,
//! `V_b = Σ ½ b k0 |u|² + ½ (1 − b) k0 |u − u_p|²`, and their hysteretic dissipation
//! `D_h = W_b − V_b` (which tends to the plastic work `Σ f_p·Δu_p` as `h → 0`). The cables'
//! work is `−Σ h ū·(R̄ − R̄_b)` (their stored energy plus, with yield, their plastic work).

use super::contact::{Pose, State};
use super::dofs::Dofs;
use super::model::SegmentBody;
use super::support::Attachment;
use crate::element::backfill::BackfillElement;
use crate::element::bearing::{BearingState, BilinearBearing};
use crate::element::restrainer::{RestrainerElement, RestrainerResponse};
use crate::element::shear_key::ShearKeyElement;
use crate::math::{Real, Vector, cross};

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
    pub(super) rb1: State,
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

/// One yielding bearing of a segment, or a yielding pier column: a bilinear spring from a point
/// of `body` to a point of `base` (another body: a pier cap) or to the ground.
#[derive(Debug, Clone)]
pub(crate) struct YieldingBearing {
    /// The body it carries (a segment, or the cap of a column).
    pub body: usize,
    /// Its index among the segment's bearings (a column: its pier).
    pub slot: usize,
    /// Lever arm `r = p − G⁰` (reference pose).
    pub arm: Vector,
    /// The body under it and the arm of its point there (`None`: the ground).
    pub base: Option<(usize, Vector)>,
    /// A member acting along one plan direction only (a pier column's yielding per axis, OpenSees
    /// `Steel01` along that axis): its deformation is the projection `(u·a) a` (`None`: the plan
    /// deformation, a yield circle).
    pub axis: Option<Vector>,
    /// Its law.
    pub law: BilinearBearing,
    /// Committed state.
    pub state: BearingState,
    /// The support line under it when it stands on the ground (`None`: on a body, or on ground
    /// that moves with the reference: a backwall's piles).
    pub line: Option<usize>,
    /// That support's current offset from the reference ground (zero when the supports move
    /// together; set per step by the driver, [`Elements::set_ground`]).
    pub ground: Vector,
}

/// One restrainer: a tension-only cable between two attachments (today across a joint, from
/// segment `k` to segment `k + 1`; an end on a support stays put, [`super::support`]).
#[derive(Debug, Clone)]
pub(crate) struct Cable {
    /// The joint it crosses.
    pub joint: usize,
    /// First anchor (reference pose, global).
    pub a: Attachment,
    /// Second anchor.
    pub b: Attachment,
    /// Reference length `L_0 = |P_b⁰ − P_a⁰|`.
    pub length: Real,
    /// The cable.
    pub element: RestrainerElement,
}

impl Cable {
    /// Elongation `e = |P_b − P_a| − L_0` in `pose` (exact anchor positions).
    pub fn elongation(&self, pose: &Pose, bodies: &[SegmentBody]) -> Real {
        let (pa, pb, _, _) = cable_points(self, pose, bodies);
        (pb - pa).norm() - self.length
    }
}

/// The backfill behind an abutment's backwall: a force `−F(s)` on the wall's coordinate `s`
/// (into the soil), held over each step as the cables' forces are.
#[derive(Debug, Clone)]
pub(crate) struct BackfillAt {
    /// The wall's body.
    pub body: usize,
    /// The backfill spring.
    pub element: BackfillElement,
    /// The abutment's support line.
    pub line: usize,
    /// That support's offset along the wall's coordinate (zero when the supports move together;
    /// [`Elements::set_ground`]): the soil behind the wall moves with it.
    pub ground: Real,
}

/// Exterior shear keys at an abutment: a force `−F(v) t` at the segment's outer-face midpoint,
/// `v = u·t` its linearised transverse displacement (relative to the ground), held over each step
/// as the cables' forces are.
#[derive(Debug, Clone)]
pub(crate) struct KeyAt {
    /// The abutment side.
    pub side: usize,
    /// The segment.
    pub body: usize,
    /// Arm `r = M − G⁰` of the face midpoint.
    pub arm: Vector,
    /// The face's tangent `t`.
    pub tangent: Vector,
    /// The keys.
    pub element: ShearKeyElement,
    /// The committed force `F` \[N\].
    pub force: Real,
    /// The abutment's support line.
    pub line: usize,
    /// That support's offset along `t` (zero when the supports move together;
    /// [`Elements::set_ground`]): the keys stand on the abutment.
    pub ground: Real,
}

impl KeyAt {
    /// `v = u·t` at `q`.
    #[inline]
    pub fn deformation(&self, dofs: &Dofs, q: &[Real]) -> Real {
        let [x, y, th] = dofs.plan_of(self.body, q);
        let u = Vector::new(x - th * self.arm.y, y + th * self.arm.x);
        u.dot(&self.tangent) - self.ground
    }

    /// Adds the force `−F t` on the segment to `r`.
    fn add_force(&self, dofs: &Dofs, f: Real, r: &mut State) {
        let t = self.tangent;
        dofs.add_plan(
            self.body,
            r.as_mut_slice(),
            [-f * t.x, -f * t.y, -f * cross(&self.arm, &t)],
        );
    }
}

/// The nonlinear elements and their energy bookkeeping.
#[derive(Debug, Clone, Default)]
pub(crate) struct Elements {
    pub bearings: Vec<YieldingBearing>,
    pub cables: Vec<Cable>,
    /// Backfills behind backwalls.
    pub backfills: Vec<BackfillAt>,
    /// Work done on the backfills.
    pub w_backfill: Real,
    /// Per yielding member: the work done on it, `Σ ½ (f_k + f_{k+1})·(u_{k+1} − u_k)` over the
    /// committed steps (its own share of the bearings' booked work, for reports: on a coupled
    /// system the booking per body splits a bearing on a cap between its two bodies).
    pub w_member: Vec<Real>,
    /// Per yielding member: its committed `(u, f)`.
    pub member_state: Vec<(Vector, Vector)>,
    /// Shear keys at the abutments.
    pub keys: Vec<KeyAt>,
    /// Work done on the shear keys.
    pub w_keys: Real,
    /// Energy absorbed by the yielding bearings (work done on them), per segment.
    pub w_bearings: Vec<Real>,
    /// Work done on the restrainers.
    pub w_cables: Real,
    /// The DOF map of the segments they act on.
    pub dofs: Dofs,
}

impl Elements {
    /// Sets the offsets of the supports under the members on the ground (the time of the
    /// states their deformations are next evaluated at).
    pub fn set_ground(&mut self, ground: &[Vector]) {
        for b in &mut self.bearings {
            if let Some(s) = b.line {
                // a backwall's piles act along its coordinate only
                b.ground = match self.dofs.kind(b.body) {
                    super::dofs::BodyKind::Axial => {
                        let a = self.dofs.axis(b.body);
                        a * ground[s].dot(&a)
                    }
                    _ => ground[s],
                };
            }
        }
        for b in &mut self.backfills {
            b.ground = ground[b.line].dot(&self.dofs.axis(b.body));
        }
        for k in &mut self.keys {
            k.ground = ground[k.line].dot(&k.tangent);
        }
    }

    /// Nothing to do.
    pub fn is_empty(&self) -> bool {
        self.bearings.is_empty()
            && self.cables.is_empty()
            && self.backfills.is_empty()
            && self.keys.is_empty()
    }

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
    /// left out of the strain energy [`super::driver`] books), so that the energy they absorb is
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

    /// The energy yielding member `i` dissipated: the work done on it less what it stores.
    pub fn member_dissipation(&self, i: usize) -> Real {
        let b = &self.bearings[i];
        self.w_member.get(i).copied().unwrap_or(0.0) - b.law.stored_energy(&b.state)
    }

    /// The energy the yielding elements of each of the first `bodies` bodies store in their
    /// committed state (the rest of what they absorbed, [`Elements::w_bearings`], they
    /// dissipated).
    pub fn bearing_stored_energy(&self, bodies: usize) -> Vec<Real> {
        let mut out = vec![0.0; bodies];
        for b in &self.bearings {
            if let Some(e) = out.get_mut(b.body) {
                *e += b.law.stored_energy(&b.state);
            }
        }
        out
    }
}

/// Linearised deformation `u = (x − θ r_y, y + θ r_x)` of a bearing with arm `r` on `body`.
pub(crate) fn deformation(dofs: &Dofs, q: &State, body: usize, r: &Vector) -> Vector {
    let [x, y, th] = dofs.plan_of(body, q.as_slice());
    Vector::new(x - th * r.y, y + th * r.x)
}

impl YieldingBearing {
    /// The part of its deformation that its support's offset takes away: the offset (on its
    /// axis, for a member along one), zero on a body or on ground that moves with the reference.
    #[inline]
    pub fn ground_offset(&self) -> Vector {
        match (self.line, self.base, self.axis) {
            (Some(_), None, None) => self.ground,
            (Some(_), None, Some(a)) => a * self.ground.dot(&a),
            _ => Vector::zeros(),
        }
    }

    /// Its linearised deformation at `q`: its point on [`Self::body`] relative to its point on
    /// [`Self::base`] (or the ground).
    #[inline]
    pub fn deformation(&self, dofs: &Dofs, q: &State) -> Vector {
        let u = deformation(dofs, q, self.body, &self.arm);
        let u = match self.base {
            None if self.line.is_some() => u - self.ground,
            None => u,
            Some((c, arm)) => u - deformation(dofs, q, c, &arm),
        };
        match self.axis {
            None => u,
            Some(a) => a * u.dot(&a),
        }
    }
}

/// The cable's anchors and the current centroids of their bodies in `pose`.
fn cable_points(
    c: &Cable,
    pose: &Pose,
    bodies: &[SegmentBody],
) -> (Vector, Vector, Vector, Vector) {
    let ((pa, ga), (pb, gb)) = (c.a.place(pose, bodies), c.b.place(pose, bodies));
    (pa, pb, ga, gb)
}
