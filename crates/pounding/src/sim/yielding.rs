//! Yielding bearings inside the step: the return mapping at the end of the step, solved
//! together with the momentum balance, so that the force a bearing exerts never leaves its
//! yield surface, whatever the step.
//!
//! # Why
//! [`super::elements`] keeps a bilinear bearing's linear part `k0 u` in `K` (implicit) and its
//! plastic correction `R_p = Σ Bᵀ (1 − b) k0 u_p` as a held force. Evaluating `u_p` at a
//! *predicted* end state `q_k + h u_k` is explicit in the plastic flow: when `h` does not
//! resolve the bearing's elastic period (`h² k0 / m ≳ 1`) the implicit `k0 u` and the explicit
//! `u_p` disagree and the bearing carries many times its yield force (a deck on bearings of
//! `k0 = 1e12 N/m`, `fy = 1e4 N` at `h = 5e-3` s carried 100 `fy`).
//!
//! # Scheme (backward Euler in the plastic flow)
//! Per segment `j` with yielding bearings, with the end velocity `x = u_{k+1,j}`, the end
//! position `q⁺(x) = q_k + h ((1−θ) u_k + θ x)` and each bearing's deformation `u_b = B_b q⁺`
//! (`B_b = [[1, 0, −r_y], [0, 1, r_x]]`, `r` its arm), the step's bearing force is
//! `R̄ = (1−θ) R_k + θ R̃(q⁺(x))` with `R̃` the return mapping at `q⁺` from the committed state.
//! The driver's contact-free velocity `u_free` already holds `h Ŵ⁻¹ θ R̃(q_k + h u_k)`; the
//! residual of the contact-free step is therefore
//! ```text
//! g(x) = Ŵ (x − u_free) − h θ (R̃(q⁺(x)) − R̃(q_k + h u_k)) = 0,
//! ∂g/∂x = Ŵ_t = Ŵ − h² θ² Σ_b B_bᵀ (k0 I − K_t,b) B_b = M + hθ C + h²θ² K_t
//! ```
//! (`K_t,b` the bearing's consistent tangent: `k0 I` elastic, `b k0 I + …` plastic), solved by
//! Newton's method. `R̃` is monotone (its elastic–perfectly-plastic part is the identity minus a
//! projection onto the yield disc), so `g` is a monotone piecewise-smooth map and Newton's
//! method converges in a few iterations (one where no bearing changes branch). A bearing that
//! stays elastic gives `g = 0` at the first estimate: such steps keep their bits.
//!
//! # Contacts in the same step
//! The contact stepper sees the tangent `Ŵ_t⁻¹` ([`super::scheme::Winv`]), so its impulses move
//! each segment with its bearings on the branch they are on: the end force is the linearisation
//! `R̃(q_f) + J (q⁺ − q_f)` about the contact-free end `q_f`, exact while no bearing changes
//! branch (1-D flow). Where the impulse does change a branch (or turns the flow of a 2-D
//! bearing), the end velocity is corrected with the impulse held fixed (Newton on
//! `g(x) = Π`, `Π = Ŵ_t (u_{k+1} − x_f)`), so that momentum, the yield surface and the energy
//! booking hold exactly; the contact law then holds to the size of that linearisation error,
//! and such steps are counted ([`Implicit::corrections`]).
//!
//! With `θ = ½` the force in the momentum balance is `½ (f_k + f_{k+1})` per bearing, the mean
//! of two forces on or inside the yield surface: it is on or inside it too (the surface bounds
//! a convex set).

use super::contact::State;
use super::elements::{StepForce, YieldingBearing};
use super::line_search::{armijo, psi_change};
use super::scheme::{Scheme, Winv};
use crate::math::{Real, Vector};
use nalgebra::{Matrix2x3, Matrix3, Vector3};

/// Newton iterations allowed per segment and step.
const MAX_ITER: usize = 60;

/// The implicit solve of the segments that carry yielding bearings, with the scratch of one
/// step (allocated once per run).
#[derive(Debug, Clone, Default)]
pub(crate) struct Implicit {
    /// Per segment with yielding bearings: the segment and its bearings' indices.
    groups: Vec<(usize, Vec<usize>)>,
    /// The step's iteration-matrix inverses (the scheme's, with tangents where bearings flow).
    pub winv: Vec<Matrix3<Real>>,
    /// Whether any block of [`Self::winv`] differs from the scheme's in this step.
    pub tangent: bool,
    /// Per group: the contact-free end velocity `x_f`, `R̃(q⁺(x_f))`, `J = ∂R̃/∂q` there, and
    /// `Ŵ_t`.
    xf: Vec<Vector3<Real>>,
    /// Per group: `u_free` before the solve (the first estimate's contact-free velocity).
    ub: Vec<Vector3<Real>>,
    rf: Vec<Vector3<Real>>,
    jac: Vec<Matrix3<Real>>,
    wt: Vec<Matrix3<Real>>,
    /// Steps whose Newton iteration did not converge (a status is reported).
    pub failures: usize,
    /// Steps in which a contact impulse changed a bearing's branch and the end velocity was
    /// corrected.
    pub corrections: usize,
    /// The whole-system solve of a coupled scheme (then [`Self::groups`] is empty).
    dense: Option<Box<super::yielding_dense::DenseImplicit>>,
}

/// `B = [[1, 0, −r_y], [0, 1, r_x]]`: the linearised deformation of a bearing of arm `r`.
fn b_matrix(r: &Vector) -> Matrix2x3<Real> {
    Matrix2x3::new(1.0, 0.0, -r.y, 0.0, 1.0, r.x)
}

impl Implicit {
    /// The groups of `bearings` by segment, for a bridge of `n_bodies` segments.
    pub fn new(bearings: &[YieldingBearing], sc: &Scheme) -> Self {
        let mut groups: Vec<(usize, Vec<usize>)> = Vec::new();
        let dense = (sc.dense.is_some() && !bearings.is_empty())
            .then(|| Box::new(super::yielding_dense::DenseImplicit::new(bearings, sc)));
        for (i, b) in bearings.iter().enumerate().filter(|_| dense.is_none()) {
            debug_assert!(b.base.is_none() && b.axis.is_none(), "a block-path member");
            match groups.iter_mut().find(|g| g.0 == b.body) {
                Some(g) => g.1.push(i),
                None => groups.push((b.body, vec![i])),
            }
        }
        let n = groups.len();
        Implicit {
            groups,
            winv: sc.winv.clone(),
            tangent: false,
            xf: vec![Vector3::zeros(); n],
            ub: vec![Vector3::zeros(); n],
            rf: vec![Vector3::zeros(); n],
            jac: vec![Matrix3::zeros(); n],
            wt: vec![Matrix3::zeros(); n],
            failures: 0,
            corrections: 0,
            dense,
        }
    }

    /// Nothing to solve.
    pub fn is_empty(&self) -> bool {
        self.groups.is_empty() && self.dense.is_none()
    }

    /// The iteration-matrix inverse of the step: the scheme's, or the tangent's where elements
    /// flow.
    pub fn winv<'a>(&'a self, sc: &'a Scheme) -> Winv<'a> {
        match (&self.dense, &sc.dense) {
            (Some(d), Some(sd)) if self.tangent => Winv::Tangent(&d.tangent, &sd.winv),
            (_, Some(sd)) => Winv::Dense(&sd.winv),
            _ if self.tangent => Winv::Blocks(&self.winv, &sc.dofs),
            _ => Winv::Blocks(&sc.winv, &sc.dofs),
        }
    }

    /// `R̃(q⁺)` of one segment's bearings (the same operations as the driver's first estimate,
    /// so an elastic step reproduces it bit for bit), `J = Σ Bᵀ (k0 I − K_t) B`, whether any
    /// bearing flows, and the sum of the magnitudes of the terms of `R̃` (its rounding scale:
    /// the moments of opposite bearings cancel in `R̃_θ`, not in its rounding).
    fn end_force(
        bearings: &[YieldingBearing],
        idx: &[usize],
        qj: &Vector3<Real>,
    ) -> (Vector3<Real>, Matrix3<Real>, bool, Vector3<Real>) {
        let mut r = Vector3::zeros();
        let mut jac = Matrix3::zeros();
        let mut flows = false;
        let mut size = Vector3::zeros();
        for &i in idx {
            let b = &bearings[i];
            let u = Vector::new(qj.x - qj.z * b.arm.y, qj.y + qj.z * b.arm.x);
            let resp = b.law.response(&u, &b.state);
            let fp = (1.0 - b.law.b()) * b.law.k0() * resp.trial.u_p;
            r.x += fp.x;
            r.y += fp.y;
            r.z += -b.arm.y * fp.x + b.arm.x * fp.y;
            size += Vector3::new(
                fp.x.abs(),
                fp.y.abs(),
                (b.arm.y * fp.x).abs() + (b.arm.x * fp.y).abs(),
            );
            if resp.yielding {
                flows = true;
                let bm = b_matrix(&b.arm);
                let d = nalgebra::Matrix2::identity() * b.law.k0() - resp.tangent;
                jac += bm.transpose() * d * bm;
            }
        }
        (r, jac, flows, size)
    }

    /// `q⁺ = q_k + h ((1−θ) u_k + θ x)` of segment `j`, as the driver forms it.
    fn end_position(
        sc: &Scheme,
        q: &State,
        u: &State,
        j: usize,
        x: &Vector3<Real>,
    ) -> Vector3<Real> {
        let (th, o) = (sc.th, sc.dofs.start(j));
        Vector3::from_fn(|i, _| q[o + i] + (u[o + i] * (1.0 - th) + x[i] * th) * sc.h)
    }

    /// Newton on `g(x) = Ŵ (x − u_free) − hθ (R̃(q⁺(x)) − R̃_pred) − Π = 0` from `x`; returns
    /// the solution, `R̃`, `J` and `Ŵ_t` at it, and whether it converged.
    #[allow(clippy::too_many_arguments)]
    fn newton(
        sc: &Scheme,
        bearings: &[YieldingBearing],
        idx: &[usize],
        j: usize,
        q: &State,
        u: &State,
        base: &Vector3<Real>,
        r_pred: &Vector3<Real>,
        pi: &Vector3<Real>,
        mut x: Vector3<Real>,
    ) -> (
        Vector3<Real>,
        Vector3<Real>,
        Matrix3<Real>,
        Matrix3<Real>,
        bool,
    ) {
        let hth = sc.h * sc.th;
        let what = &sc.what[j];
        // the force scale of the residual: the group's yield forces over the step
        let fy: Real = idx.iter().map(|&i| bearings[i].law.fy()).sum();
        for _ in 0..MAX_ITER {
            let qp = Self::end_position(sc, q, u, j, &x);
            let (r, jac, _, r_size) = Self::end_force(bearings, idx, &qp);
            let g = what * (x - base) - (r - r_pred) * hth - pi;
            let wt = what - jac * (hth * hth);
            // converged: each entry of `g` (an impulse) below 1e-12 of the yield impulse
            // `hθ fy`, or at its rounding floor: the size of its terms (`Ŵ` times the
            // resolution of `x` and `base`, the bearings' forces and moments term by term),
            // entry by entry, times a few ulps
            let size = what.abs() * (x.abs() + base.abs())
                + (r_size * 2.0 + r.abs() + r_pred.abs()) * hth
                + pi.abs();
            let tol = 1e-12 * hth * fy;
            if (0..3).all(|i| g[i].abs() <= (64.0 * Real::EPSILON * size[i]).max(tol)) {
                return (x, r, jac, wt, true);
            }
            let Some(d) = wt.lu().solve(&(-g)) else {
                return (x, r, jac, wt, false);
            };
            let next = x + d * Self::damping(sc, bearings, idx, j, (q, u), &x, &d, &g);
            if next == x {
                // no representable change: `x` is as close as doubles get
                return (x, r, jac, wt, true);
            }
            x = next;
        }
        let qp = Self::end_position(sc, q, u, j, &x);
        let (r, jac, _, _) = Self::end_force(bearings, idx, &qp);
        (x, r, jac, what - jac * (hth * hth), false)
    }

    /// The Newton step's length `t ∈ (0, 1]` by Armijo backtracking on the potential `Φ` whose
    /// gradient is `g`: with `ψ_b(u) = k_e u_p,c·u + dist(k_e (u − u_p,c), D_R)² / (2 k_e)`
    /// (`∇ψ_b = k_e u_p`, convex), `Φ(x) = ½ (x − base)ᵀ Ŵ (x − base) − Σ_b ψ_b(B_b q⁺(x)) +
    /// (hθ R̃_pred − Π)·x` is convex (its Hessian is `Ŵ_t`), so the damped iteration converges
    /// from any start; the full step is taken where it decreases `Φ` enough (near the
    /// solution, always). Undamped Newton cycles here: with a stiff `k0` the elastic band
    /// `fy/k0` is tiny and `g` is shallow–steep–shallow. `ΔΦ` is formed as a difference of
    /// like terms, not of two values of `Φ`, so rounding does not swamp it.
    #[allow(clippy::too_many_arguments)]
    fn damping(
        sc: &Scheme,
        bearings: &[YieldingBearing],
        idx: &[usize],
        j: usize,
        (q, u): (&State, &State),
        x: &Vector3<Real>,
        d: &Vector3<Real>,
        g: &Vector3<Real>,
    ) -> Real {
        let hth = sc.h * sc.th;
        let slope = g.dot(d);
        if slope >= 0.0 {
            return 1.0;
        }
        let what = &sc.what[j];
        let quad = d.dot(&(what * d));
        let q0 = Self::end_position(sc, q, u, j, x);
        armijo(slope, quad, |t| {
            let dq = d * (hth * t);
            let mut dpsi = 0.0;
            for &i in idx {
                let b = &bearings[i];
                let du = Vector::new(dq.x - dq.z * b.arm.y, dq.y + dq.z * b.arm.x);
                let u0 = Vector::new(q0.x - q0.z * b.arm.y, q0.y + q0.z * b.arm.x);
                dpsi += psi_change(b, u0, du);
            }
            dpsi
        })
    }

    /// The contact-free step: solves `g(x) = 0` per segment, replaces `u_free`'s entries by the
    /// solution and sets [`Self::winv`] (tangent blocks where bearings flow). `f.rb1` holds
    /// `R̃(q_k + h u_k)` (from [`super::elements::Elements::step_force`]).
    pub fn solve_free(
        &mut self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        q: &State,
        u: &State,
        u_free: &mut State,
        f: &StepForce,
    ) {
        if let Some(d) = &mut self.dense {
            let (tangent, failed) = d.solve_free(sc, bearings, (q, u), u_free, f);
            self.tangent = tangent;
            self.failures += usize::from(failed);
            return;
        }
        if self.tangent {
            self.winv.copy_from_slice(&sc.winv);
            self.tangent = false;
        }
        for (g, (j, idx)) in self.groups.iter().enumerate() {
            let j = *j;
            let base: Vector3<Real> = u_free.fixed_rows::<3>(sc.dofs.start(j)).into_owned();
            let r_pred: Vector3<Real> = f.rb1.fixed_rows::<3>(sc.dofs.start(j)).into_owned();
            let (x, r, jac, wt, ok) = Self::newton(
                sc,
                bearings,
                idx,
                j,
                q,
                u,
                &base,
                &r_pred,
                &Vector3::zeros(),
                base,
            );
            if !ok {
                self.failures += 1;
            }
            u_free.fixed_rows_mut::<3>(sc.dofs.start(j)).copy_from(&x);
            self.ub[g] = base;
            self.xf[g] = x;
            self.rf[g] = r;
            self.jac[g] = jac;
            self.wt[g] = wt;
            if jac.iter().any(|v| *v != 0.0)
                && let Some(inv) = wt.lu().try_inverse()
            {
                self.winv[j] = inv;
                self.tangent = true;
            }
        }
    }

    /// After the contact step: makes each segment's end velocity `u_new` consistent with its
    /// bearings' return mapping at the end position (correcting it with the impulse held fixed
    /// where the linearisation does not hold) and books the end force into `f`
    /// (`R̄ += θ (R̃(q_{k+1}) − R̃_pred)`, bearings' part and whole).
    ///
    /// Returns the change of the contact term of the energy balance that a correction makes:
    /// the contact impulse `Π` does the work `−½ Πᵀ (u_k + u_{k+1})`, so moving `u_{k+1}` by
    /// `Δu` with `Π` fixed changes it by `−½ Πᵀ Δu` (to be added to the stepper's
    /// [`super::driver::Stepper::contact_energy`]).
    #[allow(clippy::too_many_arguments)]
    pub fn finish_step(
        &mut self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        q: &State,
        u: &State,
        u_new: &mut State,
        f: &mut StepForce,
    ) -> Real {
        if let Some(d) = &mut self.dense {
            let (d_contact, corrected, failed) = d.finish_step(sc, bearings, (q, u), u_new, f);
            self.failures += usize::from(failed);
            self.corrections += usize::from(corrected);
            return d_contact;
        }
        let mut corrected = false;
        let mut d_contact = 0.0;
        for (g, (j, idx)) in self.groups.iter().enumerate() {
            let j = *j;
            let x_new: Vector3<Real> = u_new.fixed_rows::<3>(sc.dofs.start(j)).into_owned();
            let r_pred: Vector3<Real> = f.rb1.fixed_rows::<3>(sc.dofs.start(j)).into_owned();
            let r_end = if x_new == self.xf[g] {
                self.rf[g]
            } else {
                let qp = Self::end_position(sc, q, u, j, &x_new);
                let (r_true, _, _, _) = Self::end_force(bearings, idx, &qp);
                let qf = Self::end_position(sc, q, u, j, &self.xf[g]);
                let r_lin = self.rf[g] + self.jac[g] * (qp - qf);
                let scale = r_true.amax().max(r_pred.amax()).max(self.rf[g].amax());
                if (r_true - r_lin).amax() <= 1e-9 * scale {
                    r_true
                } else {
                    // the impulse the stepper applied, held fixed
                    let pi = self.wt[g] * (x_new - self.xf[g]);
                    let (x, r, _, _, ok) =
                        Self::newton(sc, bearings, idx, j, q, u, &self.ub[g], &r_pred, &pi, x_new);
                    if !ok {
                        self.failures += 1;
                    }
                    corrected = true;
                    d_contact -= 0.5 * pi.dot(&(x - x_new));
                    u_new.fixed_rows_mut::<3>(sc.dofs.start(j)).copy_from(&x);
                    r
                }
            };
            let d = (r_end - r_pred) * sc.th;
            for (k, i) in sc.dofs.range(j).enumerate() {
                f.rb[i] += d[k];
                f.r[i] += d[k];
            }
        }
        if corrected {
            self.corrections += 1;
        }
        d_contact
    }
}
