//! The contact ends of a compliance step: each joint end and abutment corner evaluated at a
//! trial state (penetration, rate, slip rate → the law's forces and tangents), the generalised
//! force they exert, and the trial pose they are read at.

use super::*;

/// One contact end (a joint end or an abutment corner) evaluated at a trial state.
#[derive(Clone, Copy)]
pub(crate) struct EndEval {
    /// A contact exists at this end (a corner over the other face; always at an abutment).
    pub(crate) present: bool,
    /// The realised candidate of a joint end.
    pub(crate) case: Option<ContactCase>,
    pub(crate) wn: Sparse,
    pub(crate) wt: Sparse,
    pub(crate) delta: Real,
    pub(crate) f_n: Real,
    pub(crate) f_t: Real,
    /// `k_c h θ + c_c` (per end, shared).
    pub(crate) kc: Real,
    /// `μ f_N s'(γ_T)`.
    pub(crate) kt: Real,
    /// `μ s(γ_T)`.
    pub(crate) mus: Real,
    pub(crate) state: LawState,
    /// The velocity `(v_n, v_t)` of the face it strikes when that face moves with a support of
    /// its own ([`super::excitation`]; `None`: a joint, or supports that move together).
    pub(crate) face: Option<(Real, Real)>,
}

impl EndEval {
    /// The normal and tangential velocities of the contact at `u`: `(w_N·u, w_T·u)`, less the
    /// struck face's velocity when it moves.
    #[inline]
    pub(super) fn rel(&self, u: &State) -> (Real, Real) {
        let u = u.as_slice();
        match self.face {
            None => (self.wn.dot(u), self.wt.dot(u)),
            Some((vn, vt)) => (self.wn.dot(u) - vn, self.wt.dot(u) - vt),
        }
    }

    /// A present end open by more than [`CLOSURE_WINDOW`] at penetration `delta < 0`, without
    /// its force directions: what [`ComplianceStepper::end_eval`] gives there (`F = 0`, no
    /// stiffness, the law's open state `δ_c = δ`; every law's evaluation at `δ ≤ 0`, whatever
    /// `δ̇`), with `w_N = w_T = 0`, which only the impact records and the closure step read
    /// (neither reads a lean end: [`ComplianceStepper::may_skip`]).
    pub(super) fn lean(case: Option<ContactCase>, delta: Real, face: Option<(Real, Real)>) -> Self {
        EndEval {
            present: true,
            case,
            delta,
            state: LawState::open_at(delta),
            face,
            ..Self::open()
        }
    }

    /// An end without a contact.
    pub(super) fn open() -> Self {
        EndEval {
            present: false,
            case: None,
            wn: Sparse::ZERO,
            wt: Sparse::ZERO,
            delta: 0.0,
            f_n: 0.0,
            f_t: 0.0,
            kc: 0.0,
            kt: 0.0,
            mus: 0.0,
            state: LawState::default(),
            face: None,
        }
    }
}

/// The closure step's window: ends within this penetration of `δ = 0` \[m\] may be held there
/// ([`ComplianceStepper::closure_step`]).
pub(crate) const CLOSURE_WINDOW: Real = 1e-6;

/// `R = Σ_e (w_N f_N + w_T f_T)` over every end, `n` generalised coordinates.
pub(super) fn gen_force(ends: &[EndEval], n: usize) -> State {
    let mut r = State::zeros(n);
    gen_force_into(ends, &mut r);
    r
}

/// [`gen_force`] into `r` (overwritten; its length is the number of coordinates).
pub(super) fn gen_force_into(ends: &[EndEval], r: &mut State) {
    r.fill(0.0);
    for e in ends {
        if e.f_n == 0.0 && e.f_t == 0.0 {
            // an open end adds nothing (its `+ 0` terms could change only a zero's sign)
            continue;
        }
        e.wn.axpy(e.f_n, r.as_mut_slice());
        e.wt.axpy(e.f_t, r.as_mut_slice());
    }
}

impl ComplianceStepper {
    /// Friction coefficient of end `e`.
    pub(super) fn mu_of(&self, e: usize) -> Real {
        self.sites[e / 2].mu
    }

    /// The law evaluation of end `e` with penetration `delta`, rate `ddot`, slip rate `gt`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn end_eval(
        &self,
        e: usize,
        states: &[LawState],
        case: Option<ContactCase>,
        wn: Sparse,
        wt: Sparse,
        (delta, u, face): (Real, &State, Option<(Real, Real)>),
    ) -> EndEval {
        let (mu, vr) = (self.mu_of(e), self.vr);
        // relative to a moving face: its velocity `(v_n, v_t)` taken off
        let us = u.as_slice();
        let (ddot, gt) = match face {
            None => (-wn.dot(us), wt.dot(us)),
            Some((vn, vt)) => (vn - wn.dot(us), wt.dot(us) - vt),
        };
        let law = self.sites[e / 2]
            .law
            .corner_evaluate(&states[e], delta, ddot);
        let root = (gt * gt + vr * vr).sqrt();
        let s = gt / root;
        let sp = vr * vr / (root * root * root);
        EndEval {
            present: true,
            case,
            wn,
            wt,
            delta,
            f_n: law.force,
            f_t: -mu * law.force * s,
            kc: law.stiffness * self.hth + law.damping,
            kt: mu * law.force * sp,
            mus: mu * s,
            state: law.state,
            face,
        }
    }

    /// Whether end `e` at penetration `delta` may be evaluated without its force directions
    /// ([`EndEval::lean`]): open by more than the closure step's window (every law gives
    /// `F = 0`, `∂F = 0` and the open state at `δ ≤ 0`, whatever `δ̇`) and no impact of its own
    /// in progress (whose closing reads the end's velocities).
    #[inline]
    pub(super) fn may_skip(&self, e: usize, delta: Real) -> bool {
        delta < -CLOSURE_WINDOW && self.open_imp[e].is_none()
    }

    /// Evaluates every end at `(q, u)` from the committed `states`; an abutment's face moved
    /// with its support by `ground`. `full`: every end with its force directions (else the
    /// ends far open without them, [`Self::may_skip`]: nothing reads them).
    pub(super) fn eval_ends(
        &self,
        q: &State,
        u: &State,
        states: &[LawState],
        ground: Ground<'_>,
        full: bool,
    ) -> Vec<EndEval> {
        let dofs = &self.dofs;
        let mut pose = self.pose.borrow_mut();
        set_pose(&mut pose, (&self.bodies, dofs), q.as_slice(), &self.posed);
        let pose = &*pose;
        let mut out = Vec::with_capacity(states.len());
        for jg in &self.joints {
            let jf = candidates(&self.bodies, pose, jg);
            for e in 0..2 {
                let ev = match jf.sel[e] {
                    Some(i) if !full && self.may_skip(out.len(), -jf.cands[i].gap) => {
                        let c = jf.cands[i];
                        EndEval::lean(Some(c.case), -c.gap, None)
                    }
                    Some(i) => {
                        let c = jf.cands[i];
                        let (wn, wt) = c.force_directions(pose, jg);
                        let (wn, wt) = (wn.sparse(dofs), wt.sparse(dofs));
                        let at = (-c.gap, u, None);
                        self.end_eval(out.len(), states, Some(c.case), wn, wt, at)
                    }
                    None => {
                        // No corner over the other face at this end: open, state reset to the
                        // open gap.
                        let mut ev = EndEval::open();
                        ev.state = LawState::open_at(-jg.half_w.max(1.0));
                        ev
                    }
                };
                out.push(ev);
            }
        }
        for ab in &self.abutments {
            let shift = match ground {
                Some((d, _)) => ab.shift_on(dofs, q.as_slice(), d),
                None => ab.shift(dofs, q.as_slice()),
            };
            // the face's velocity along its normal and tangent
            // a ground face moves with its support; a backwall is a body of its own
            let face = match (ab.wall, ground) {
                (None, Some((_, v))) => {
                    Some((v[ab.line].dot(&ab.normal), v[ab.line].dot(&ab.tangent)))
                }
                _ => None,
            };
            for c0 in &ab.corners {
                let (j, nn, tn) = (ab.body, ab.normal, ab.tangent);
                let pc = pose.place(&self.bodies, j, c0);
                let r = pc - pose.g[j];
                let dir = |v: crate::math::Vector| ab.direction(v, &r);
                let delta = -((pc - ab.point).dot(&nn) + shift);
                if !full && self.may_skip(out.len(), delta) {
                    out.push(EndEval::lean(None, delta, face));
                    continue;
                }
                let (wn, wt) = (dir(nn).sparse(dofs), dir(tn).sparse(dofs));
                out.push(self.end_eval(out.len(), states, None, wn, wt, (delta, u, face)));
            }
        }
        out
    }

    /// Copies the ends' normal forces into [`ComplianceStepper::forces`].
    pub(super) fn set_forces(&mut self) {
        for (k, f) in self.forces.iter_mut().enumerate() {
            *f = [self.ends[2 * k].f_n, self.ends[2 * k + 1].f_n];
        }
    }
}

/// [`Pose::set`] for the bodies with `posed[j]` (the others keep a placeholder: the reference
/// pose, never read).
pub(super) fn set_pose(
    pose: &mut Pose,
    (bodies, dofs): (&[SegmentBody], &crate::sim::dofs::Dofs),
    q: &[Real],
    posed: &[bool],
) {
    pose.d.clear();
    pose.sc.clear();
    pose.g.clear();
    for (j, b) in bodies.iter().enumerate() {
        if !posed[j] {
            pose.d.push(crate::math::Vector::zeros());
            pose.sc.push((0.0, 1.0));
            pose.g.push(b.centroid);
            continue;
        }
        let [x, y, th] = dofs.plan_of(j, q);
        let d = crate::math::Vector::new(x, y);
        pose.d.push(d);
        pose.sc.push(th.sin_cos());
        pose.g.push(b.centroid + d);
    }
}
