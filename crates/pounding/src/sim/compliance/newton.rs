//! Newton's method on the step's contact forces (module doc of [`super`]): the residual, the
//! corrections solved in contact space, the line search, and the graph-closure step.

use super::{ComplianceStepper, EndEval, Trial, gen_force};
use crate::math::Real;
use crate::sim::contact::{Sparse, State};
use nalgebra::DMatrix;

/// `∂R/∂u` of the ends (module doc) as a dense `n × n` matrix (the closure step's Jacobian).
pub(super) fn force_jacobian(ev: &[EndEval], n: usize) -> DMatrix<Real> {
    let mut dr = DMatrix::<Real>::zeros(n, n);
    for e in ev {
        let (wn, wt) = (e.wn.dense(n), e.wt.dense(n));
        dr -= &wn * wn.transpose() * e.kc;
        dr += &wt * (wn.transpose() * (e.mus * e.kc) - wt.transpose() * e.kt);
    }
    dr
}

/// The rank-one terms `p gᵀ` of `∂R/∂u = Σ_e [(−w_N + μ s w_T) k̂_c w_Nᵀ − k_t w_T w_Tᵀ]` (module
/// doc) of the ends that carry force or stiffness: `(p, g)` with `p` dense (`n` entries).
pub(super) fn jacobian_terms(ev: &[EndEval], n: usize) -> Vec<(State, Sparse)> {
    let mut terms = Vec::new();
    for e in ev {
        if !(e.f_n > 0.0 || e.kc > 0.0) {
            continue;
        }
        let mut p = State::zeros(n);
        e.wn.axpy(-e.kc, p.as_mut_slice());
        e.wt.axpy(e.mus * e.kc, p.as_mut_slice());
        terms.push((p, e.wn));
        if e.kt != 0.0 {
            let mut p = State::zeros(n);
            e.wt.axpy(-e.kt, p.as_mut_slice());
            terms.push((p, e.wt));
        }
    }
    terms
}

/// `S z = y` for the small contact system of a Newton correction. Up to `2 × 2` by Cramer's
/// rule, which treats the two rows alike: the two ends of a joint struck squarely (equal rows)
/// get bit-equal corrections, so a symmetric bridge does not rotate by rounding. Larger: LU.
pub(super) fn solve_small(s: DMatrix<Real>, y: State) -> Option<State> {
    match y.len() {
        1 => (s[(0, 0)] != 0.0).then(|| State::from_element(1, y[0] / s[(0, 0)])),
        2 => {
            let det = s[(0, 0)] * s[(1, 1)] - s[(0, 1)] * s[(1, 0)];
            (det != 0.0 && det.is_finite()).then(|| {
                State::from_vec(vec![
                    (s[(1, 1)] * y[0] - s[(0, 1)] * y[1]) / det,
                    (s[(0, 0)] * y[1] - s[(1, 0)] * y[0]) / det,
                ])
            })
        }
        _ => s.lu().solve(&y),
    }
}

impl ComplianceStepper {
    /// `q_{k+1} = q_k + h ((1−θ) u_k + θ u_{k+1})` for the trial `u_{k+1} = un`, into `out`
    /// (entry by entry the operations of the whole-vector expression).
    pub(super) fn q_of_into(&self, tr: &Trial, un: &State, out: &mut State) {
        let (th, h) = (self.th, self.h);
        for (i, o) in out.iter_mut().enumerate() {
            *o = tr.q[i] + (tr.u[i] * (1.0 - th) + un[i] * th) * h;
        }
    }

    /// The ends at the trial `un` (the far-open ones lean: [`ComplianceStepper::may_skip`]).
    pub(super) fn eval_at(&self, tr: &Trial, un: &State) -> Vec<EndEval> {
        self.eval_with(tr, un, false)
    }

    /// The ends at the trial `un`, each with its force directions if `full`.
    pub(super) fn eval_with(&self, tr: &Trial, un: &State, full: bool) -> Vec<EndEval> {
        let mut q = self.q_trial.borrow_mut();
        self.q_of_into(tr, un, &mut q);
        self.eval_ends(&q, un, &self.states, tr.ground, full)
    }

    /// The residual `r(u) = u − base − hθ Ŵ⁻¹ R(u)`.
    pub(super) fn resid(&self, tr: &Trial, un: &State, ev: &[EndEval]) -> State {
        un - &*tr.base - tr.winv.mul(&gen_force(ev, un.len())) * self.hth
    }

    /// Newton with backtracking on `r(u) = 0` from `un`; returns the converged iterate or, if
    /// none, the one with the smallest residual (`converged = false`).
    pub(super) fn newton(&self, tr: &Trial, mut un: State) -> (bool, State, Vec<EndEval>) {
        let mut ev = self.eval_at(tr, &un);
        // no force at the first guess `base` (an open step): `r = 0` exactly, no product formed
        if un == *tr.base
            && un.iter().all(|x| x.is_finite())
            && ev.iter().all(|e| e.f_n == 0.0 && e.f_t == 0.0)
        {
            return (true, un, ev);
        }
        let mut r = self.resid(tr, &un, &ev);
        // the iterate with the smallest residual so far: the current one (`None`) until a worse
        // one replaces it, and only then copied
        let mut best_r = r.amax();
        let mut best: Option<(State, Vec<EndEval>)> = None;
        // open contacts (no force now or before): the first guess is exact
        if r.amax() <= 1e-12 + 1e-10 * un.amax() {
            return (true, un, ev);
        }
        for _ in 0..50 {
            let Some(du) = self.correction(tr, &ev, &r) else {
                break;
            };
            // backtracking line search on |r|
            let r0 = r.amax();
            let mut step = 1.0;
            let mut accepted = false;
            for _ in 0..12 {
                let trial = &un + &du * step;
                let ev_t = self.eval_at(tr, &trial);
                let r_t = self.resid(tr, &trial, &ev_t);
                if r_t.amax() <= r0 || step < 1e-3 {
                    // not better than the best (NaN included): keep the best before moving on
                    let better = r_t.amax() < best_r;
                    if best.is_none() && !better {
                        best = Some((un.clone(), ev.clone()));
                    }
                    un = trial;
                    ev = ev_t;
                    r = r_t;
                    accepted = true;
                    break;
                }
                step *= 0.5;
            }
            if !accepted {
                break;
            }
            if r.amax() < best_r {
                best_r = r.amax();
                best = None;
            }
            if (&du * step).amax() <= 1e-12 + 1e-10 * un.amax() {
                return (true, un, ev);
            }
        }
        match best {
            Some((u, e)) => (false, u, e),
            None => (false, un, ev),
        }
    }

    /// Newton's correction: `du` with `J du = −r`, `J = I − hθ Ŵ⁻¹ ∂R/∂u`, solved through the
    /// contacts. `∂R/∂u = Σ_c p_c g_cᵀ` has one term per active end (two with friction), so
    /// with `A = hθ Ŵ⁻¹ [p_c]` (`n × m`) and `G = [g_c]`, Sherman–Morrison–Woodbury gives
    /// `J⁻¹ = I + A (I_m − GᵀA)⁻¹ Gᵀ`:
    /// ```text
    /// (I_m − GᵀA) z = Gᵀ r,    du = −r − A z
    /// ```
    /// an `m × m` solve (`m` ≤ two per active end) instead of the `n × n` one, and `m` products
    /// with `Ŵ⁻¹` instead of `n`. `None` if `I_m − GᵀA` is singular.
    pub(super) fn correction(&self, tr: &Trial, ev: &[EndEval], r: &State) -> Option<State> {
        let n = r.len();
        let terms = jacobian_terms(ev, n);
        let m = terms.len();
        let mut du = -r;
        if m == 0 {
            return Some(du);
        }
        let a: Vec<State> = terms
            .iter()
            .map(|(p, _)| tr.winv.mul(p) * self.hth)
            .collect();
        let s = DMatrix::<Real>::from_fn(m, m, |i, j| {
            let gi_aj = terms[i].1.dot(a[j].as_slice());
            if i == j { 1.0 - gi_aj } else { -gi_aj }
        });
        let y = State::from_fn(m, |i, _| terms[i].1.dot(r.as_slice()));
        let z = solve_small(s, y)?;
        for (aj, zj) in a.iter().zip(z.iter()) {
            du.axpy(-zj, aj, 1.0);
        }
        Some(du)
    }

    /// Holds the ends in `held` with the unknown forces `lam` (closure step).
    pub(super) fn hold(&self, ev: &mut [EndEval], held: &[usize], lam: &[Real], un: &State) {
        let vr = self.vr;
        for (i, &e) in held.iter().enumerate() {
            let mu = self.mu_of(e);
            let gt = ev[e].rel(un).1;
            let root = (gt * gt + vr * vr).sqrt();
            ev[e].f_n = lam[i];
            ev[e].f_t = -mu * lam[i] * gt / root;
            ev[e].kc = 0.0;
            ev[e].kt = mu * lam[i] * vr * vr / (root * root * root);
            ev[e].mus = mu * gt / root;
        }
    }

    /// The graph-closure step for a law whose force jumps at `δ = 0` (Kelvin's `c δ̇`): the ends
    /// whose penetration is within 1 µm of zero in the best Newton iterate are held at
    /// `δ_{k+1} = 0` by an unknown force `λ_e`, which must lie in the closure `[0, F(0⁺, δ̇)]` of
    /// the law's graph. Newton on `(u, λ)`; `None` if it does not converge or `λ` leaves the
    /// closure.
    pub(super) fn closure_step(
        &self,
        tr: &Trial,
        u0: &State,
        ev0: &[EndEval],
    ) -> Option<(State, Vec<EndEval>)> {
        let held: Vec<usize> = (0..ev0.len())
            .filter(|&e| ev0[e].present && ev0[e].delta.abs() < super::CLOSURE_WINDOW)
            .collect();
        if held.is_empty() {
            return None;
        }
        let nq = u0.len();
        let (n, hth) = (nq + held.len(), self.hth);
        let mut un = u0.clone();
        let mut lam: Vec<Real> = held.iter().map(|&e| ev0[e].f_n).collect();
        for _ in 0..30 {
            let mut ev = self.eval_with(tr, &un, true);
            self.hold(&mut ev, &held, &lam, &un);
            let r_u = &un - &*tr.base - tr.winv.mul(&gen_force(&ev, nq)) * hth;
            let mut r = State::zeros(n);
            r.rows_mut(0, nq).copy_from(&r_u);
            for (i, &e) in held.iter().enumerate() {
                r[nq + i] = ev[e].delta;
            }
            let dr = force_jacobian(&ev, nq);
            let mut jac = nalgebra::DMatrix::<Real>::zeros(n, n);
            jac.view_mut((0, 0), (nq, nq))
                .copy_from(&(DMatrix::identity(nq, nq) - tr.winv.mul_mat(&dr) * hth));
            for (i, &e) in held.iter().enumerate() {
                let (wn, wt) = (ev[e].wn.dense(nq), ev[e].wt.dense(nq));
                let col = -(tr.winv.mul(&(&wn - &wt * ev[e].mus))) * hth;
                jac.view_mut((0, nq + i), (nq, 1)).copy_from(&col);
                // δ = −g_N, ∂g_N/∂q = w_Nᵀ, ∂q/∂u = hθ
                let row = -(wn.transpose() * hth);
                jac.view_mut((nq + i, 0), (1, nq)).copy_from(&row);
            }
            let dx = jac.lu().solve(&(-&r))?;
            let du: State = dx.rows(0, nq).into_owned();
            un += &du;
            for i in 0..held.len() {
                lam[i] += dx[nq + i];
            }
            let small = du.amax() <= 1e-12 + 1e-10 * un.amax()
                && (0..held.len()).all(|i| dx[nq + i].abs() <= 1e-6 * lam[i].abs().max(1.0));
            if small {
                return self.closure_accept(tr, un, &held, &lam);
            }
        }
        None
    }

    /// The converged closure iterate if every `λ` lies in the closure of the law's graph.
    pub(super) fn closure_accept(
        &self,
        tr: &Trial,
        un: State,
        held: &[usize],
        lam: &[Real],
    ) -> Option<(State, Vec<EndEval>)> {
        let mut ev = self.eval_with(tr, &un, true);
        for (i, &e) in held.iter().enumerate() {
            let ddot = -ev[e].rel(&un).0;
            let f_hi = self.sites[e / 2]
                .law
                .corner_evaluate(&self.states[e], Real::MIN_POSITIVE, ddot)
                .force;
            if !(lam[i] >= 0.0 && lam[i] <= f_hi * (1.0 + 1e-9)) {
                return None;
            }
            let gt = ev[e].rel(&un).1;
            ev[e].f_n = lam[i];
            ev[e].f_t = -self.mu_of(e) * lam[i] * gt / (gt * gt + self.vr * self.vr).sqrt();
        }
        Some((un, ev))
    }
}
