//! The implicit return mapping of [`super::yielding`] on a coupled system
//! ([`super::coupled`]): the same residual, tangent, convergence test, line search and contact
//! correction, over the whole velocity vector instead of one segment's block, because a yielding
//! element may link two bodies (a bearing on a pier cap) and a linear link couples every body.
//!
//! Each yielding element `e` acts on its deformation `u_e = L_e q` (`L_e = [B_body, −B_base]`,
//! [`super::dofs::Dofs::point_operator`]); its plastic force `f_p,e = (1 − b) k0 u_p` enters as
//! `R = Σ L_eᵀ f_p,e`, its consistent tangent as `J = Σ L_eᵀ (k0 I − K_t,e) L_e`.

use super::contact::State;
use super::elements::{StepForce, YieldingBearing};
use super::scheme::Scheme;
use crate::math::{Real, Vector};
use nalgebra::DMatrix;

/// Newton iterations allowed per step.
const MAX_ITER: usize = 60;

/// One element's operator: `(coordinate, [∂u_x/∂q_i, ∂u_y/∂q_i])`.
type Operator = Vec<(usize, [Real; 2])>;

/// The dense implicit solve and the scratch of one step.
#[derive(Debug, Clone)]
pub(crate) struct DenseImplicit {
    ops: Vec<Operator>,
    /// `|Ŵ|` entrywise (the rounding scale of the residual).
    wabs: DMatrix<Real>,
    /// The total yield force of the members (the residual's force scale).
    fy: Real,
    /// The step's tangent `Ŵ_t`, inverted when a contact needs it (valid when
    /// [`super::yielding::Implicit::tangent`]).
    pub tangent: super::scheme::LazyInverse,
    ub: State,
    xf: State,
    rf: State,
    /// `J` of the contact-free end (`None`: no element flows there, `J = 0`).
    jac: Option<DMatrix<Real>>,
}

/// What one Newton solve returns: `x`, `R̃`, `J` and `Ŵ_t` at it (`None`: no element flows,
/// `J = 0`, `Ŵ_t = Ŵ`) and whether it converged.
type Solved = (State, State, Option<(DMatrix<Real>, DMatrix<Real>)>, bool);

impl DenseImplicit {
    /// The operators of `bearings` on the system of `sc`.
    pub fn new(bearings: &[YieldingBearing], sc: &Scheme) -> Self {
        let dofs = &sc.dofs;
        let ops = bearings
            .iter()
            .map(|b| {
                let mut op = Vec::with_capacity(5);
                let l = dofs.point_operator(b.body, &b.arm);
                for (d, i) in dofs.range(b.body).enumerate() {
                    op.push((i, [l[0][d], l[1][d]]));
                }
                if let Some((c, arm)) = b.base {
                    let l = dofs.point_operator(c, &arm);
                    for (d, i) in dofs.range(c).enumerate() {
                        op.push((i, [-l[0][d], -l[1][d]]));
                    }
                }
                if let Some(a) = b.axis {
                    // the projection (u·a) a of each column
                    for (_, l) in &mut op {
                        let p = a.x * l[0] + a.y * l[1];
                        *l = [a.x * p, a.y * p];
                    }
                }
                op
            })
            .collect();
        let n = dofs.len();
        let wabs = sc
            .dense
            .as_ref()
            .map_or_else(|| DMatrix::zeros(n, n), |d| d.what.abs());
        DenseImplicit {
            ops,
            wabs,
            fy: bearings.iter().map(|b| b.law.fy()).sum(),
            tangent: Default::default(),
            ub: State::zeros(n),
            xf: State::zeros(n),
            rf: State::zeros(n),
            jac: None,
        }
    }

    fn apply(op: &Operator, v: &State) -> Vector {
        op.iter().fold(Vector::zeros(), |u, (i, l)| {
            u + Vector::new(l[0], l[1]) * v[*i]
        })
    }

    /// `R̃(q⁺)`, `J` (`None` when no element flows: `J = 0`), and the entrywise size of `R̃`'s
    /// terms.
    fn end_force(
        &self,
        bearings: &[YieldingBearing],
        qp: &State,
    ) -> (State, Option<DMatrix<Real>>, State) {
        let n = qp.len();
        let (mut r, mut size) = (State::zeros(n), State::zeros(n));
        let mut jac: Option<DMatrix<Real>> = None;
        for (b, op) in bearings.iter().zip(&self.ops) {
            let u = Self::apply(op, qp) - b.ground_offset();
            let resp = b.law.response(&u, &b.state);
            let fp = (1.0 - b.law.b()) * b.law.k0() * resp.trial.u_p;
            for &(i, l) in op {
                r[i] += l[0] * fp.x + l[1] * fp.y;
                size[i] += (l[0] * fp.x).abs() + (l[1] * fp.y).abs();
            }
            if resp.yielding {
                let jac = jac.get_or_insert_with(|| DMatrix::zeros(n, n));
                let d = nalgebra::Matrix2::identity() * b.law.k0() - resp.tangent;
                for &(i, li) in op {
                    for &(j, lj) in op {
                        let dl = d * nalgebra::Vector2::new(lj[0], lj[1]);
                        jac[(i, j)] += li[0] * dl.x + li[1] * dl.y;
                    }
                }
            }
        }
        (r, jac, size)
    }

    fn end_position(sc: &Scheme, q: &State, u: &State, x: &State) -> State {
        let th = sc.th;
        State::from_fn(q.len(), |i, _| {
            q[i] + (u[i] * (1.0 - th) + x[i] * th) * sc.h
        })
    }

    /// Newton on `g(x) = Ŵ (x − base) − hθ (R̃(q⁺(x)) − R̃_pred) − Π = 0` from `x`.
    #[allow(clippy::too_many_arguments)]
    fn newton(
        &self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        (q, u): (&State, &State),
        base: &State,
        r_pred: &State,
        pi: &State,
        mut x: State,
    ) -> Solved {
        let hth = sc.h * sc.th;
        let what = &sc.dense.as_ref().expect("a coupled scheme").what;
        let (fy, wabs) = (self.fy, &self.wabs);
        for it in 0..MAX_ITER {
            let qp = Self::end_position(sc, q, u, &x);
            let (r, jac, r_size) = self.end_force(bearings, &qp);
            // the elastic step from the contact-free estimate: `x = base`, `Π = 0` and the members'
            // force is the predictor's, so `g = 0` with no product formed
            if it == 0
                && jac.is_none()
                && r == *r_pred
                && x == *base
                && pi.iter().all(|p| *p == 0.0)
            {
                return (x, r, None, true);
            }
            let g = what * (&x - base) - (&r - r_pred) * hth - pi;
            // elastic members: J = 0 and Ŵ_t = Ŵ (no product formed)
            let tangent = jac.map(|j| {
                let wt = what - &j * (hth * hth);
                (j, wt)
            });
            let tol = 1e-12 * hth * fy;
            // (the rounding scale is formed only when the plain tolerance does not settle it)
            let converged = g.iter().all(|gi| gi.abs() <= tol) || {
                let size = wabs * (x.abs() + base.abs())
                    + (r_size * 2.0 + r.abs() + r_pred.abs()) * hth
                    + pi.abs();
                (0..x.len()).all(|i| g[i].abs() <= (64.0 * Real::EPSILON * size[i]).max(tol))
            };
            if converged {
                return (x, r, tangent, true);
            }
            let lu = match &tangent {
                Some((_, wt)) => wt.clone().lu(),
                None => what.clone().lu(),
            };
            let Some(d) = lu.solve(&(-&g)) else {
                return (x, r, tangent, false);
            };
            let t = self.damping(sc, bearings, (q, u), &x, &d, &g);
            let next = &x + d * t;
            if next == x {
                return (x, r, tangent, true);
            }
            x = next;
        }
        let qp = Self::end_position(sc, q, u, &x);
        let (r, jac, _) = self.end_force(bearings, &qp);
        let tangent = jac.map(|j| {
            let wt = what - &j * (hth * hth);
            (j, wt)
        });
        (x, r, tangent, false)
    }

    /// The Armijo step length on the convex potential of [`super::yielding`]'s line search.
    fn damping(
        &self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        (q, u): (&State, &State),
        x: &State,
        d: &State,
        g: &State,
    ) -> Real {
        let hth = sc.h * sc.th;
        let slope = g.dot(d);
        if slope >= 0.0 {
            return 1.0;
        }
        let what = &sc.dense.as_ref().expect("a coupled scheme").what;
        let quad = d.dot(&(what * d));
        let q0 = Self::end_position(sc, q, u, x);
        super::line_search::armijo(slope, quad, |t| {
            let dq = d * (hth * t);
            let mut dpsi = 0.0;
            for (b, op) in bearings.iter().zip(&self.ops) {
                let u0 = Self::apply(op, &q0) - b.ground_offset();
                dpsi += super::line_search::psi_change(b, u0, Self::apply(op, &dq));
            }
            dpsi
        })
    }

    /// The contact-free step ([`super::yielding::Implicit::solve_free`]); returns whether the
    /// step's tangent differs from `Ŵ` and whether Newton failed.
    pub fn solve_free(
        &mut self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        (q, u): (&State, &State),
        u_free: &mut State,
        f: &StepForce,
    ) -> (bool, bool) {
        let base = u_free.clone();
        let pi = State::zeros(base.len());
        let (x, r, tangent, ok) =
            self.newton(sc, bearings, (q, u), &base, &f.rb1, &pi, base.clone());
        u_free.copy_from(&x);
        self.ub = base;
        self.xf = x;
        self.rf = r;
        // a flowing element whose tangent equals its elastic stiffness leaves `J = 0`
        let flows = tangent
            .as_ref()
            .is_some_and(|(j, _)| j.iter().any(|v| *v != 0.0));
        match tangent {
            Some((j, wt)) if flows => {
                self.jac = Some(j);
                self.tangent.set(wt);
            }
            _ => self.jac = None,
        }
        (flows, !ok)
    }

    /// After the contact step ([`super::yielding::Implicit::finish_step`]); returns the change
    /// of the contact energy term, whether the end velocity was corrected and whether Newton
    /// failed.
    pub fn finish_step(
        &mut self,
        sc: &Scheme,
        bearings: &[YieldingBearing],
        (q, u): (&State, &State),
        u_new: &mut State,
        f: &mut StepForce,
    ) -> (Real, bool, bool) {
        let r_pred = f.rb1.clone();
        let (mut d_contact, mut corrected, mut failed) = (0.0, false, false);
        let r_end = if *u_new == self.xf {
            self.rf.clone()
        } else {
            let qp = Self::end_position(sc, q, u, u_new);
            let (r_true, _, _) = self.end_force(bearings, &qp);
            let qf = Self::end_position(sc, q, u, &self.xf);
            let r_lin = match &self.jac {
                Some(j) => &self.rf + j * (qp - qf),
                None => self.rf.clone(),
            };
            let scale = r_true.amax().max(r_pred.amax()).max(self.rf.amax());
            if (&r_true - r_lin).amax() <= 1e-9 * scale {
                r_true
            } else {
                let wt = match &self.jac {
                    Some(_) => &self.tangent.wt,
                    None => &sc.dense.as_ref().expect("a coupled scheme").what,
                };
                let pi = wt * (&*u_new - &self.xf);
                let (x, r, _, ok) =
                    self.newton(sc, bearings, (q, u), &self.ub, &r_pred, &pi, u_new.clone());
                failed = !ok;
                corrected = true;
                d_contact -= 0.5 * pi.dot(&(&x - &*u_new));
                u_new.copy_from(&x);
                r
            }
        };
        let d = (r_end - r_pred) * sc.th;
        f.rb += &d;
        f.r += &d;
        (d_contact, corrected, failed)
    }
}
