//! Time stepping with a compliance contact law at the joint (issue 7).
//!
//! # Scheme: trapezoidal rule (Newmark average acceleration) with Newton on the contact forces
//! The same θ-method as the rigid scheme (θ = ½ by default, i.e. Newmark `γ = ½`, `β = ¼`, the
//! integrator of the OpenSees benchmark), with the contact forces inside the smooth forces:
//! ```text
//! q_{k+1} = q_k + h ((1−θ) u_k + θ u_{k+1})
//! M (u_{k+1} − u_k) = h ((1−θ) f_k + θ f_{k+1}),   f = −K q − C u + F(t) + R(q, u)
//! R = Σ_e ( w_N,e f_N,e + w_T,e f_T,e )             (e = the two joint ends)
//! ```
//! so `u_{k+1} = u_free + h Ŵ⁻¹ ((1−θ) R_k + θ R_{k+1})` with `Ŵ`, `u_free` of the rigid scheme.
//! `R_{k+1}` depends on `u_{k+1}` through the gaps and rates at `q_{k+1}`; the residual
//! `r(u) = u − u_free − h Ŵ⁻¹((1−θ) R_k + θ R(u))` is solved by Newton's method with the
//! Jacobian `J = I − h θ Ŵ⁻¹ ∂R/∂u`,
//! `∂R/∂u = Σ_e [ −w_N (k_c h θ + c_c) w_Nᵀ + w_T (μ s (k_c h θ + c_c) w_Nᵀ − μ f_N s' w_Tᵀ) ]`
//! (`k_c = ∂f_N/∂δ`, `c_c = ∂f_N/∂δ̇` from [`crate::contact_law::Evaluation`]; the geometric
//! stiffness of the rotating normals is left out of `J`, which only slows convergence when the
//! decks rotate), with a backtracking line search; converged when `|Δu|_∞ ≤ 1e-12 + 1e-10 |u|_∞`
//! (at most 50 iterations). A law whose force jumps at `δ = 0` (Kelvin's dashpot force `c δ̇`
//! at contact onset) can leave a step without a root when it would end within `O(h² c δ̇ / m)`
//! of `δ = 0`; that step is solved in the **closure of the law's graph**: the ends within 1 µm of
//! `δ = 0` are held at `δ_{k+1} = 0` by an unknown force `λ ∈ [0, F(0⁺, δ̇)]` (Newton on
//! `(u, λ)`, [`super::SimSolution::closure_steps`]). If that fails too, the iterate with the
//! smallest residual is kept and the step is counted in [`super::SimSolution::newton_failures`]
//! (status [`super::SimStatus::CompletedWithNewtonFailures`]).
//!
//! # Contacts
//! Per joint end the realised candidate corner (as in the rigid scheme) carries the contact, with
//! penetration `δ = −g_N` (exact geometry at `q_{k+1}`) and rate `δ̇ = −w_Nᵀ u_{k+1}`. The joint
//! law is shared equally between the two ends ([`crate::contact_law::sharing::JointLaw`], `N = 2`):
//! a joint closing uniformly carries exactly the law's force. Each end has its own committed law
//! state, which is **evaluated and committed at every step, open or closed** (the OpenSees
//! semantics of the bilinear `ImpactMaterial`: its increment at the closing step starts from the
//! committed open gap). Initial state: open at `δ = −g_N(q_0)`.
//!
//! # Friction (regularised Coulomb)
//! `f_T = −μ f_N s(γ_T)`, `s(γ) = γ / √(γ² + v_r²)`, `γ_T = w_Tᵀ u` the tangential slip rate;
//! `v_r` = [`super::ComplianceContact::friction_velocity`] (default 1 mm/s): below `v_r` the
//! friction force is roughly viscous (`μ f_N γ_T / v_r`), above it within `(1 − ½(v_r/γ_T)²)` of
//! Coulomb's `μ f_N`. There is no true stick: a tangentially loaded closed contact creeps at a
//! rate of order `v_r`.
//!
//! # Outputs
//! An *impact* is a maximal interval of positive total joint force. Per end and impact, one
//! [`super::ImpactRecord`]: onset time, pre-contact velocities `w_Nᵀ u_k`, `w_Tᵀ u_k` of the step
//! the force appears in, post-contact velocities when the force returns to zero, the impulses
//! `∫ f dt` (trapezoidal, as the scheme) and the contact work `−∫ γ·f dt` as energy dissipated.
//! [`super::SimSummary::peak_contact_force`] is the largest total joint force,
//! [`super::SimSummary::peak_penetration`] the largest `δ` of an end. The contact term of the
//! energy balance is `D_contact = −Σ h ū·R̄` (`ū` the mean velocity, `R̄ = (1−θ)R_k + θR_{k+1}`):
//! the law's dissipation plus the energy momentarily stored in the contact spring; with θ = ½
//! the discrete balance is exact, as for the rigid scheme.
//!
//! # Time step
//! [`crate::contact_law::timestep::law_time_step_advice`] with `m_eff = m1 m2/(m1 + m2)` (deck
//! masses) and `v_ref = 1 m/s`; the advice is returned in
//! [`super::SimSolution::time_step_advice`] (the CLI warns when it is not adequate).
#![allow(clippy::needless_range_loop)]
use super::contact::{Pose, candidates};

use super::driver::{Bridge, ImpactLog, Scheme, StepInput, StepOutput, Stepper, StepperStats};
use super::model::DeckBody;
use super::{ComplianceContact, ImpactRecord, SimContact, SimError, SimProblem};
use crate::analytic::SlipMode;
use crate::contact_law::sharing::JointLaw;
use crate::contact_law::timestep::law_time_step_advice;
use crate::contact_law::{LawState, effective_mass};
use crate::geometry::ContactCase;
use crate::math::Real;
use nalgebra::{Matrix6, Vector6};

/// One joint end's contact evaluated at a trial state.
#[derive(Clone, Copy)]
struct EndEval {
    case: Option<ContactCase>,
    wn: Vector6<Real>,
    wt: Vector6<Real>,
    delta: Real,
    f_n: Real,
    f_t: Real,
    /// `k_c h θ + c_c` (per end, shared).
    kc: Real,
    /// `μ f_N s'(γ_T)`.
    kt: Real,
    /// `μ s(γ_T)`.
    mus: Real,
    state: LawState,
}

impl EndEval {
    /// An end without a contact.
    fn open() -> Self {
        EndEval {
            case: None,
            wn: Vector6::zeros(),
            wt: Vector6::zeros(),
            delta: 0.0,
            f_n: 0.0,
            f_t: 0.0,
            kc: 0.0,
            kt: 0.0,
            mus: 0.0,
            state: LawState::default(),
        }
    }
}

fn gen_force(ends: &[EndEval; 2]) -> Vector6<Real> {
    let mut r = Vector6::zeros();
    for e in ends {
        r += e.wn * e.f_n + e.wt * e.f_t;
    }
    r
}

/// `∂R/∂u` of the ends (module doc); `all = false` skips ends without force and stiffness.
fn force_jacobian(ev: &[EndEval; 2], all: bool) -> Matrix6<Real> {
    let mut dr = Matrix6::<Real>::zeros();
    for e in ev {
        if all || e.f_n > 0.0 || e.kc > 0.0 {
            dr -= e.wn * e.wn.transpose() * e.kc;
            dr += e.wt * (e.wn.transpose() * (e.mus * e.kc) - e.wt.transpose() * e.kt);
        }
    }
    dr
}

/// Per-end bookkeeping of an impact in progress.
#[derive(Clone, Copy)]
struct OpenImpact {
    record: usize,
    impulse_n: Real,
    impulse_t: Real,
    work: Real,
}

/// The fixed data of one step's iteration: `q_k`, `u_k`, `Ŵ⁻¹` and
/// `base = u_free + h (1−θ) Ŵ⁻¹ R_k`.
struct Trial<'a> {
    q: &'a Vector6<Real>,
    u: &'a Vector6<Real>,
    winv: &'a Matrix6<Real>,
    base: Vector6<Real>,
}

/// The compliance-law stepper (module doc).
pub(crate) struct ComplianceStepper {
    bodies: [DeckBody; 2],
    half_w: Real,
    joint: JointLaw,
    mu: Real,
    vr: Real,
    h: Real,
    th: Real,
    hth: Real,
    /// Committed law state of each end.
    states: [LawState; 2],
    /// The ends at `t_k`.
    ends: [EndEval; 2],
    /// `R_k`.
    r_k: Vector6<Real>,
    joint_in_contact: bool,
    open_imp: [Option<OpenImpact>; 2],
    d_cont: Real,
    stats: StepperStats,
}

impl ComplianceStepper {
    /// The joint law shared by the two ends (checked before the time grid is built).
    pub fn joint_law(cc: &ComplianceContact) -> Result<JointLaw, SimError> {
        JointLaw::new(cc.law, 2).map_err(|e| SimError::invalid("corners", 2.0, &e.to_string()))
    }

    /// The stepper at the initial state: law states open at the initial gaps (committed
    /// `δ = −g_N(q_0)`).
    pub fn new(
        problem: &SimProblem,
        cc: &ComplianceContact,
        joint: JointLaw,
        scheme: &Scheme,
        bridge: &Bridge,
    ) -> Self {
        let (h, th) = (scheme.h, scheme.th);
        let (m1, m2) = (bridge.bodies[0].mass.mass, bridge.bodies[1].mass.mass);
        let advice = effective_mass(m1, m2)
            .and_then(|m| law_time_step_advice(&cc.law, h, m, 1.0))
            .ok();
        let mut s = ComplianceStepper {
            bodies: bridge.bodies,
            half_w: bridge.half_w,
            joint,
            mu: problem.model.friction,
            vr: cc.friction_velocity,
            h,
            th,
            hth: h * th,
            states: [LawState::default(); 2],
            ends: [EndEval::open(); 2],
            r_k: Vector6::zeros(),
            joint_in_contact: false,
            open_imp: [None, None],
            d_cont: 0.0,
            stats: StepperStats {
                time_step_advice: advice,
                ..StepperStats::default()
            },
        };
        let (q, u) = (Vector6::from(problem.q0), Vector6::from(problem.u0));
        let first = s.eval_ends(&q, &u, &s.states);
        for e in 0..2 {
            s.states[e] = LawState::open_at(first[e].delta.min(0.0));
        }
        s.ends = s.eval_ends(&q, &u, &s.states);
        for e in 0..2 {
            s.states[e] = s.ends[e].state;
        }
        s.r_k = gen_force(&s.ends);
        s
    }

    /// Evaluates both ends at `(q, u)` from the committed `states`.
    fn eval_ends(
        &self,
        q: &Vector6<Real>,
        u: &Vector6<Real>,
        states: &[LawState; 2],
    ) -> [EndEval; 2] {
        let (mu, vr) = (self.mu, self.vr);
        let qa: [Real; 6] = (*q).into();
        let pose = Pose::new(&self.bodies, &qa);
        let (cands, sel) = candidates(&self.bodies, &pose, self.half_w);
        let mut out = [EndEval::open(); 2];
        for e in 0..2 {
            match sel[e] {
                Some(i) => {
                    let c = cands[i];
                    let (wn, wt) = c.force_directions(&pose);
                    let (wn, wt) = (Vector6::from(wn), Vector6::from(wt));
                    let delta = -c.gap;
                    let ddot = -wn.dot(u);
                    let ev = self.joint.corner_evaluate(&states[e], delta, ddot);
                    let gt = wt.dot(u);
                    let root = (gt * gt + vr * vr).sqrt();
                    let s = gt / root;
                    let sp = vr * vr / (root * root * root);
                    out[e] = EndEval {
                        case: Some(c.case),
                        wn,
                        wt,
                        delta,
                        f_n: ev.force,
                        f_t: -mu * ev.force * s,
                        kc: ev.stiffness * self.hth + ev.damping,
                        kt: mu * ev.force * sp,
                        mus: mu * s,
                        state: ev.state,
                    };
                }
                None => {
                    // No corner over the other face at this end: open, state reset to the open gap.
                    out[e].state = LawState::open_at(-self.half_w.max(1.0));
                }
            }
        }
        out
    }

    /// `q_{k+1}` for the trial `u_{k+1} = un`.
    fn q_of(&self, tr: &Trial, un: &Vector6<Real>) -> Vector6<Real> {
        tr.q + (tr.u * (1.0 - self.th) + un * self.th) * self.h
    }

    /// The ends at the trial `un`.
    fn eval_at(&self, tr: &Trial, un: &Vector6<Real>) -> [EndEval; 2] {
        self.eval_ends(&self.q_of(tr, un), un, &self.states)
    }

    /// The residual `r(u) = u − base − hθ Ŵ⁻¹ R(u)`.
    fn resid(&self, tr: &Trial, un: &Vector6<Real>, ev: &[EndEval; 2]) -> Vector6<Real> {
        un - tr.base - tr.winv * gen_force(ev) * self.hth
    }

    /// Newton with backtracking on `r(u) = 0` from `un`; returns the converged iterate or, if
    /// none, the one with the smallest residual (`converged = false`).
    fn newton(&self, tr: &Trial, mut un: Vector6<Real>) -> (bool, Vector6<Real>, [EndEval; 2]) {
        let mut ev = self.eval_at(tr, &un);
        let mut r = self.resid(tr, &un, &ev);
        let mut best = (r.amax(), un, ev);
        // open contacts (no force now or before): the first guess is exact
        if r.amax() <= 1e-12 + 1e-10 * un.amax() {
            return (true, un, ev);
        }
        for _ in 0..50 {
            let jac = Matrix6::identity() - tr.winv * force_jacobian(&ev, false) * self.hth;
            let Some(du) = jac.lu().solve(&(-r)) else {
                break;
            };
            // backtracking line search on |r|
            let r0 = r.amax();
            let mut step = 1.0;
            let mut accepted = false;
            for _ in 0..12 {
                let trial = un + du * step;
                let ev_t = self.eval_at(tr, &trial);
                let r_t = self.resid(tr, &trial, &ev_t);
                if r_t.amax() <= r0 || step < 1e-3 {
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
            if r.amax() < best.0 {
                best = (r.amax(), un, ev);
            }
            if (du * step).amax() <= 1e-12 + 1e-10 * un.amax() {
                return (true, un, ev);
            }
        }
        (false, best.1, best.2)
    }

    /// Holds the ends in `held` with the unknown forces `lam` (closure step).
    fn hold(&self, ev: &mut [EndEval; 2], held: &[usize], lam: &[Real], un: &Vector6<Real>) {
        let (mu, vr) = (self.mu, self.vr);
        for (i, &e) in held.iter().enumerate() {
            let gt = ev[e].wt.dot(un);
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
    fn closure_step(
        &self,
        tr: &Trial,
        u0: &Vector6<Real>,
        ev0: &[EndEval; 2],
    ) -> Option<(Vector6<Real>, [EndEval; 2])> {
        let held: Vec<usize> = (0..2)
            .filter(|&e| ev0[e].case.is_some() && ev0[e].delta.abs() < 1e-6)
            .collect();
        if held.is_empty() {
            return None;
        }
        let (n, hth) = (6 + held.len(), self.hth);
        let mut un = *u0;
        let mut lam: Vec<Real> = held.iter().map(|&e| ev0[e].f_n).collect();
        for _ in 0..30 {
            let mut ev = self.eval_at(tr, &un);
            self.hold(&mut ev, &held, &lam, &un);
            let r_u = un - tr.base - tr.winv * gen_force(&ev) * hth;
            let mut r = nalgebra::DVector::<Real>::zeros(n);
            r.rows_mut(0, 6).copy_from(&r_u);
            for (i, &e) in held.iter().enumerate() {
                r[6 + i] = ev[e].delta;
            }
            let dr = force_jacobian(&ev, true);
            let mut jac = nalgebra::DMatrix::<Real>::zeros(n, n);
            jac.view_mut((0, 0), (6, 6))
                .copy_from(&(Matrix6::identity() - tr.winv * dr * hth));
            for (i, &e) in held.iter().enumerate() {
                let col = -(tr.winv * (ev[e].wn - ev[e].wt * ev[e].mus)) * hth;
                jac.view_mut((0, 6 + i), (6, 1)).copy_from(&col);
                // δ = −g_N, ∂g_N/∂q = w_Nᵀ, ∂q/∂u = hθ
                let row = -(ev[e].wn.transpose() * hth);
                jac.view_mut((6 + i, 0), (1, 6)).copy_from(&row);
            }
            let dx = jac.lu().solve(&(-&r))?;
            let du = Vector6::from_iterator(dx.rows(0, 6).iter().copied());
            un += du;
            for i in 0..held.len() {
                lam[i] += dx[6 + i];
            }
            let small = du.amax() <= 1e-12 + 1e-10 * un.amax()
                && (0..held.len()).all(|i| dx[6 + i].abs() <= 1e-6 * lam[i].abs().max(1.0));
            if small {
                return self.closure_accept(tr, un, &held, &lam);
            }
        }
        None
    }

    /// The converged closure iterate if every `λ` lies in the closure of the law's graph.
    fn closure_accept(
        &self,
        tr: &Trial,
        un: Vector6<Real>,
        held: &[usize],
        lam: &[Real],
    ) -> Option<(Vector6<Real>, [EndEval; 2])> {
        let mut ev = self.eval_at(tr, &un);
        for (i, &e) in held.iter().enumerate() {
            let ddot = -ev[e].wn.dot(&un);
            let f_hi = self
                .joint
                .corner_evaluate(&self.states[e], Real::MIN_POSITIVE, ddot)
                .force;
            if !(lam[i] >= 0.0 && lam[i] <= f_hi * (1.0 + 1e-9)) {
                return None;
            }
            let gt = ev[e].wt.dot(&un);
            ev[e].f_n = lam[i];
            ev[e].f_t = -self.mu * lam[i] * gt / (gt * gt + self.vr * self.vr).sqrt();
        }
        Some((un, ev))
    }

    /// Impacts (intervals of positive total joint force) and the per-end impact records of the
    /// step ending at `time` with velocity `un`, mean velocity `u_mid`, ends `ev`.
    fn track_impacts(
        &mut self,
        log: &mut ImpactLog,
        time: Real,
        u: &Vector6<Real>,
        un: &Vector6<Real>,
        u_mid: &Vector6<Real>,
        ev: &[EndEval; 2],
    ) {
        let (h, th) = (self.h, self.th);
        let f_now = ev[0].f_n + ev[1].f_n;
        if f_now > 0.0 && !self.joint_in_contact {
            log.impacts += 1;
        }
        self.joint_in_contact = f_now > 0.0;
        for e in 0..2 {
            let (fn0, ft0) = (self.ends[e].f_n, self.ends[e].f_t);
            let (fn1, ft1) = (ev[e].f_n, ev[e].f_t);
            if fn1 > 0.0 && self.open_imp[e].is_none() {
                log.records.push(ImpactRecord {
                    impact: log.impacts,
                    time,
                    contact: SimContact::Joint(ev[e].case.unwrap_or(ContactCase::Deck1Inner)),
                    mode: SlipMode::Stick,
                    gamma_n_pre: ev[e].wn.dot(u),
                    gamma_t_pre: ev[e].wt.dot(u),
                    gamma_n_post: Real::NAN,
                    gamma_t_post: Real::NAN,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    energy_dissipated: 0.0,
                });
                self.open_imp[e] = Some(OpenImpact {
                    record: log.records.len() - 1,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    work: 0.0,
                });
            }
            if let Some(oi) = self.open_imp[e].as_mut() {
                let pn = h * ((1.0 - th) * fn0 + th * fn1);
                let pt = h * ((1.0 - th) * ft0 + th * ft1);
                oi.impulse_n += pn;
                oi.impulse_t += pt;
                let src = if ev[e].case.is_some() {
                    &ev[e]
                } else {
                    &self.ends[e]
                };
                let (wn, wt) = (src.wn, src.wt);
                oi.work -= u_mid.dot(&wn) * pn + u_mid.dot(&wt) * pt;
                if fn1 <= 0.0 {
                    let rec = &mut log.records[oi.record];
                    rec.gamma_n_post = wn.dot(un);
                    rec.gamma_t_post = wt.dot(un);
                    rec.impulse_n = oi.impulse_n;
                    rec.impulse_t = oi.impulse_t;
                    rec.energy_dissipated = oi.work;
                    rec.mode = SlipMode::classify(rec.gamma_t_post, rec.gamma_n_pre);
                    self.open_imp[e] = None;
                }
            }
            self.states[e] = ev[e].state;
        }
    }
}

impl Stepper for ComplianceStepper {
    fn contact_forces(&self) -> Option<[Real; 2]> {
        Some([self.ends[0].f_n, self.ends[1].f_n])
    }

    fn contact_energy(&self) -> Real {
        self.d_cont
    }

    fn step(&mut self, inp: &StepInput, log: &mut ImpactLog) -> StepOutput {
        let (h, th, hth) = (self.h, self.th, self.hth);
        let winv = &inp.scheme.winv;
        let r_k = self.r_k;
        let tr = Trial {
            q: inp.q,
            u: inp.u,
            winv,
            base: inp.u_free + winv * r_k * (h * (1.0 - th)),
        };
        let (converged, mut un, mut ev) = self.newton(&tr, tr.base + winv * r_k * hth);
        if !converged {
            match self.closure_step(&tr, &un, &ev) {
                Some((u2, ev2)) => {
                    un = u2;
                    ev = ev2;
                    self.stats.closure_steps += 1;
                }
                // keep the iterate with the smallest residual
                None => self.stats.newton_failures += 1,
            }
        }
        let r_new = gen_force(&ev);
        let rbar = r_k * (1.0 - th) + r_new * th;
        let u_mid = (inp.u + un) * 0.5;
        self.d_cont -= h * u_mid.dot(&rbar);
        self.track_impacts(log, inp.t + h, inp.u, &un, &u_mid, &ev);
        self.r_k = r_new;
        self.ends = ev;
        StepOutput {
            u: un,
            penetration: ev
                .iter()
                .map(|e| e.delta)
                .fold(Real::NEG_INFINITY, Real::max),
        }
    }

    fn finish(&mut self, log: &mut ImpactLog) -> StepperStats {
        // impacts still in progress at the end of the run
        for oi in self.open_imp.iter().flatten() {
            let rec = &mut log.records[oi.record];
            rec.impulse_n = oi.impulse_n;
            rec.impulse_t = oi.impulse_t;
            rec.energy_dissipated = oi.work;
        }
        std::mem::take(&mut self.stats)
    }
}
