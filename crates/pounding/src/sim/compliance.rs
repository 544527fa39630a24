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
use super::{
    ComplianceContact, Energy, History, ImpactRecord, SimContact, SimError, SimProblem,
    SimSettings, SimSolution, SimStatus, SimSummary, balance_error, energies_finite, max_nan,
};
use crate::analytic::SlipMode;
use crate::contact_law::sharing::JointLaw;
use crate::contact_law::timestep::law_time_step_advice;
use crate::contact_law::{LawState, effective_mass};
use crate::math::{Real, Vector};
use nalgebra::{Matrix6, Vector6};

/// One joint end's contact evaluated at a trial state.
#[derive(Clone, Copy)]
struct EndEval {
    case: Option<crate::geometry::ContactCase>,
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

/// Evaluates both ends at `(q, u)`.
#[allow(clippy::too_many_arguments)]
fn eval_ends(
    bodies: &[super::model::DeckBody; 2],
    half_w: Real,
    q: &Vector6<Real>,
    u: &Vector6<Real>,
    states: &[LawState; 2],
    joint: &JointLaw,
    mu: Real,
    vr: Real,
    hth: Real,
) -> [EndEval; 2] {
    let qa: [Real; 6] = (*q).into();
    let pose = Pose::new(bodies, &qa);
    let (cands, sel) = candidates(bodies, &pose, half_w);
    let mut out = [EndEval {
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
    }; 2];
    for e in 0..2 {
        match sel[e] {
            Some(i) => {
                let c = cands[i];
                let (wn, wt) = c.force_directions(&pose);
                let (wn, wt) = (Vector6::from(wn), Vector6::from(wt));
                let delta = -c.gap;
                let ddot = -wn.dot(u);
                let ev = joint.corner_evaluate(&states[e], delta, ddot);
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
                    kc: ev.stiffness * hth + ev.damping,
                    kt: mu * ev.force * sp,
                    mus: mu * s,
                    state: ev.state,
                };
            }
            None => {
                // No corner over the other face at this end: open, state reset to the open gap.
                out[e].state = LawState::open_at(-half_w.max(1.0));
            }
        }
    }
    out
}

fn gen_force(ends: &[EndEval; 2]) -> Vector6<Real> {
    let mut r = Vector6::zeros();
    for e in ends {
        r += e.wn * e.f_n + e.wt * e.f_t;
    }
    r
}

/// What [`closure_step`] needs from the stepper.
struct ClosureCtx<'a> {
    bodies: &'a [super::model::DeckBody; 2],
    half_w: Real,
    states: &'a [LawState; 2],
    joint: &'a JointLaw,
    mu: Real,
    vr: Real,
    hth: Real,
    winv: &'a Matrix6<Real>,
    base: &'a Vector6<Real>,
    q: &'a Vector6<Real>,
    u: &'a Vector6<Real>,
    th: Real,
    h: Real,
}

/// The graph-closure step for a law whose force jumps at `δ = 0` (Kelvin's `c δ̇`): the ends
/// whose penetration is within 1 µm of zero in the best Newton iterate are held at `δ_{k+1} = 0`
/// by an unknown force `λ_e`, which must lie in the closure `[0, F(0⁺, δ̇)]` of the law's graph.
/// Newton on `(u, λ)`; `None` if it does not converge or `λ` leaves the closure.
fn closure_step(
    c: &ClosureCtx,
    u0: &Vector6<Real>,
    ev0: &[EndEval; 2],
) -> Option<(Vector6<Real>, [EndEval; 2])> {
    let held: Vec<usize> = (0..2)
        .filter(|&e| ev0[e].case.is_some() && ev0[e].delta.abs() < 1e-6)
        .collect();
    if held.is_empty() {
        return None;
    }
    let n = 6 + held.len();
    let q_of = |un: &Vector6<Real>| c.q + (c.u * (1.0 - c.th) + un * c.th) * c.h;
    let mut un = *u0;
    let mut lam: Vec<Real> = held.iter().map(|&e| ev0[e].f_n).collect();
    for _ in 0..30 {
        let mut ev = eval_ends(
            c.bodies,
            c.half_w,
            &q_of(&un),
            &un,
            c.states,
            c.joint,
            c.mu,
            c.vr,
            c.hth,
        );
        for (i, &e) in held.iter().enumerate() {
            let gt = ev[e].wt.dot(&un);
            let root = (gt * gt + c.vr * c.vr).sqrt();
            ev[e].f_n = lam[i];
            ev[e].f_t = -c.mu * lam[i] * gt / root;
            ev[e].kc = 0.0;
            ev[e].kt = c.mu * lam[i] * c.vr * c.vr / (root * root * root);
            ev[e].mus = c.mu * gt / root;
        }
        let r_u = un - c.base - c.winv * gen_force(&ev) * c.hth;
        let mut r = nalgebra::DVector::<Real>::zeros(n);
        r.rows_mut(0, 6).copy_from(&r_u);
        for (i, &e) in held.iter().enumerate() {
            r[6 + i] = ev[e].delta;
        }
        let mut dr = Matrix6::<Real>::zeros();
        for e in &ev {
            dr -= e.wn * e.wn.transpose() * e.kc;
            dr += e.wt * (e.wn.transpose() * (e.mus * e.kc) - e.wt.transpose() * e.kt);
        }
        let mut jac = nalgebra::DMatrix::<Real>::zeros(n, n);
        jac.view_mut((0, 0), (6, 6))
            .copy_from(&(Matrix6::identity() - c.winv * dr * c.hth));
        for (i, &e) in held.iter().enumerate() {
            let col = -(c.winv * (ev[e].wn - ev[e].wt * ev[e].mus)) * c.hth;
            jac.view_mut((0, 6 + i), (6, 1)).copy_from(&col);
            // δ = −g_N, ∂g_N/∂q = w_Nᵀ, ∂q/∂u = hθ
            let row = -(ev[e].wn.transpose() * c.hth);
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
            let mut ev = eval_ends(
                c.bodies,
                c.half_w,
                &q_of(&un),
                &un,
                c.states,
                c.joint,
                c.mu,
                c.vr,
                c.hth,
            );
            for (i, &e) in held.iter().enumerate() {
                let ddot = -ev[e].wn.dot(&un);
                let f_hi = c
                    .joint
                    .corner_evaluate(&c.states[e], Real::MIN_POSITIVE, ddot)
                    .force;
                if !(lam[i] >= 0.0 && lam[i] <= f_hi * (1.0 + 1e-9)) {
                    return None;
                }
                let gt = ev[e].wt.dot(&un);
                ev[e].f_n = lam[i];
                ev[e].f_t = -c.mu * lam[i] * gt / (gt * gt + c.vr * c.vr).sqrt();
            }
            return Some((un, ev));
        }
    }
    None
}

/// Per-end bookkeeping of an impact in progress.
#[derive(Clone, Copy)]
struct OpenImpact {
    record: usize,
    impulse_n: Real,
    impulse_t: Real,
    work: Real,
}

/// The compliance-law counterpart of [`super::simulate`] (module doc).
pub(crate) fn simulate_compliance(
    problem: &SimProblem,
    settings: &SimSettings,
    cc: &ComplianceContact,
) -> Result<SimSolution, SimError> {
    settings.validate()?;
    problem.ground.validate()?;
    let model = &problem.model;
    let sys = model.linear_system()?;
    for (i, v) in problem.q0.iter().chain(problem.u0.iter()).enumerate() {
        if !v.is_finite() {
            let name = if i < 6 {
                format!("q0[{i}]")
            } else {
                format!("u0[{}]", i - 6)
            };
            return Err(SimError::invalid(name, *v, "must be finite"));
        }
    }
    let joint =
        JointLaw::new(cc.law, 2).map_err(|e| SimError::invalid("corners", 2.0, &e.to_string()))?;
    let h = settings.dt;
    let duration = match settings.duration {
        Some(d) => d,
        None => {
            let d = problem.ground.end_time();
            if d <= 0.0 {
                return Err(SimError::invalid(
                    "duration",
                    d,
                    "must be given when the ground motion has no samples after t = 0",
                ));
            }
            d
        }
    };
    let n_steps = settings.step_count(duration)?;
    let ag = problem.ground.sample_uniform(h, n_steps);
    let bodies = model.bodies();
    let m1 = bodies[0].mass.mass;
    let m2 = bodies[1].mass.mass;
    let advice = effective_mass(m1, m2)
        .and_then(|m| law_time_step_advice(&cc.law, h, m, 1.0))
        .ok();

    let th = settings.theta;
    let hth = h * th;
    let (mm, kk, cmat) = (&sys.mass, &sys.stiffness, &sys.damping);
    let what = mm + cmat * hth + kk * (hth * hth);
    let winv = what
        .try_inverse()
        .ok_or_else(|| SimError::invalid("dt", h, "iteration matrix is singular"))?;
    let a_u = -(winv * (cmat + kk * hth)) * h;
    let a_q = -(winv * kk) * h;
    let mut mr = nalgebra::Matrix6x2::zeros();
    for j in 0..2 {
        mr[(3 * j, 0)] = mm[(3 * j, 3 * j)];
        mr[(3 * j + 1, 1)] = mm[(3 * j + 1, 3 * j + 1)];
    }
    let b_g = -(winv * mr) * h;
    let f_of = |a: &Vector| -> Vector6<Real> { -(mr * nalgebra::Vector2::new(a.x, a.y)) };

    let half_w = bodies[0].half_face;
    let (mu, vr) = (model.friction, cc.friction_velocity);
    let g0 = model.gap;

    let mut q = Vector6::from(problem.q0);
    let mut u = Vector6::from(problem.u0);
    // Initial law states: open at the initial gaps (committed δ = −g_N(q_0)).
    let mut states = [LawState::default(); 2];
    {
        let first = eval_ends(&bodies, half_w, &q, &u, &states, &joint, mu, vr, hth);
        for e in 0..2 {
            states[e] = LawState::open_at(first[e].delta.min(0.0));
        }
    }
    let mut ends = eval_ends(&bodies, half_w, &q, &u, &states, &joint, mu, vr, hth);
    for e in 0..2 {
        states[e] = ends[e].state;
    }
    let mut r_k = gen_force(&ends);

    let energy_of =
        |q: &Vector6<Real>, u: &Vector6<Real>| (0.5 * u.dot(&(mm * u)), 0.5 * q.dot(&(kk * q)));
    let (t0, v0) = energy_of(&q, &u);
    let e0 = t0 + v0;
    let (mut w_in, mut d_visc, mut d_cont) = (0.0, 0.0, 0.0);
    let mut max_in: Real = e0.abs();
    let mut max_bal: Real = 0.0;

    let mut hist = History::default();
    let mut impacts: Vec<ImpactRecord> = Vec::new();
    let mut n_impacts = 0usize;
    let mut joint_in_contact = false;
    let mut open_imp: [Option<OpenImpact>; 2] = [None, None];
    let mut peak_close = Real::NEG_INFINITY;
    let mut peak_open = Real::NEG_INFINITY;
    let mut peak_rot = [0.0f64; 2];
    let mut peak_slip: Real = 0.0;
    let mut peak_seat = [Real::NEG_INFINITY; 4];
    let mut unseat: Option<(Real, usize)> = None;
    let mut max_pen: Real = 0.0;
    let mut peak_force: Real = 0.0;
    let mut status = SimStatus::Completed;
    let mut newton_failures = 0usize;
    let mut closure_steps = 0usize;
    let mut steps_done = 0usize;
    let seat_pts: [(usize, [Vector; 2], Vector); 4] = [
        (0, bodies[0].joint_corners, bodies[0].joint_inward),
        (0, bodies[0].far_corners, bodies[0].far_inward),
        (1, bodies[1].joint_corners, bodies[1].joint_inward),
        (1, bodies[1].far_corners, bodies[1].far_inward),
    ];

    for k in 0..=n_steps {
        let t = k as Real * h;
        let qa: [Real; 6] = q.into();
        let pose = Pose::new(&bodies, &qa);
        let (cands, sel) = candidates(&bodies, &pose, half_w);
        // ---- monitoring at t_k (as the rigid scheme) ----
        let end_gaps = sel.map(|s| s.map_or(Real::NAN, |i| cands[i].gap));
        let mut gmin = Real::INFINITY;
        let mut gmax = Real::NEG_INFINITY;
        for g in end_gaps.iter().filter(|g| !g.is_nan()) {
            gmin = gmin.min(*g);
            gmax = gmax.max(*g);
        }
        peak_close = peak_close.max(g0 - gmin);
        max_pen = max_pen.max(-gmin);
        peak_open = peak_open.max(gmax - g0);
        peak_rot[0] = peak_rot[0].max(q[2].abs());
        peak_rot[1] = peak_rot[1].max(q[5].abs());
        let fm1 = pose.place(&bodies, 0, &bodies[0].face_mid) - bodies[0].face_mid;
        let fm2 = pose.place(&bodies, 1, &bodies[1].face_mid) - bodies[1].face_mid;
        let slip = (fm2.x - fm1.x) + 0.0;
        peak_slip = peak_slip.max(slip.abs());
        for (e, (j, pts, n_in)) in seat_pts.iter().enumerate() {
            let s = pts
                .iter()
                .map(|p| (pose.place(&bodies, *j, p) - p).dot(n_in))
                .fold(Real::NEG_INFINITY, Real::max);
            peak_seat[e] = peak_seat[e].max(s);
            if unseat.is_none() && s > model.seat_length {
                unseat = Some((t, e));
            }
        }
        let f_joint = ends[0].f_n + ends[1].f_n;
        peak_force = peak_force.max(f_joint);
        let (tk, vk) = energy_of(&q, &u);
        let bal = e0 + w_in - (tk + vk + d_visc + d_cont);
        max_bal = max_nan(max_bal, bal.abs());
        max_in = max_nan(max_in, (e0 + w_in).abs());
        if k % settings.history_stride == 0 || k == n_steps {
            hist.t.push(t);
            hist.q.push(qa);
            hist.u.push(u.into());
            hist.gaps.push(cands.map(|c| c.gap));
            hist.end_gaps.push(end_gaps);
            hist.slip.push(slip);
            hist.energy.push(Energy {
                input: w_in,
                kinetic: tk,
                potential: vk,
                viscous: d_visc,
                contact: d_cont,
            });
            hist.contact_force.push([ends[0].f_n, ends[1].f_n]);
            hist.abutment_gaps.push([Real::NAN; 2]);
        }
        if !energies_finite(&[tk, vk, w_in, d_visc, d_cont, e0]) {
            status = SimStatus::Diverged;
            break;
        }
        if k == n_steps {
            break;
        }
        // ---- step k → k+1 ----
        let abar = ag[k] * (1.0 - th) + ag[k + 1] * th;
        let u_free = u + a_u * u + a_q * q + b_g * nalgebra::Vector2::new(abar.x, abar.y);
        let base = u_free + winv * r_k * (h * (1.0 - th));
        let q_of = |un: &Vector6<Real>| q + (u * (1.0 - th) + un * th) * h;
        let resid = |un: &Vector6<Real>, ev: &[EndEval; 2]| un - base - winv * gen_force(ev) * hth;
        let mut un = base + winv * r_k * hth;
        let mut ev = eval_ends(
            &bodies,
            half_w,
            &q_of(&un),
            &un,
            &states,
            &joint,
            mu,
            vr,
            hth,
        );
        let mut r = resid(&un, &ev);
        let mut converged = false;
        let mut best = (r.amax(), un, ev);
        // open contacts (no force now or before): the first guess is exact
        if r.amax() <= 1e-12 + 1e-10 * un.amax() {
            converged = true;
        }
        for _ in 0..if converged { 0 } else { 50 } {
            let mut dr = Matrix6::<Real>::zeros();
            for e in &ev {
                if e.f_n > 0.0 || e.kc > 0.0 {
                    dr -= e.wn * e.wn.transpose() * e.kc;
                    dr += e.wt * (e.wn.transpose() * (e.mus * e.kc) - e.wt.transpose() * e.kt);
                }
            }
            let jac = Matrix6::identity() - winv * dr * hth;
            let Some(du) = jac.lu().solve(&(-r)) else {
                break;
            };
            // backtracking line search on |r|
            let r0 = r.amax();
            let mut step = 1.0;
            let mut accepted = false;
            for _ in 0..12 {
                let trial = un + du * step;
                let ev_t = eval_ends(
                    &bodies,
                    half_w,
                    &q_of(&trial),
                    &trial,
                    &states,
                    &joint,
                    mu,
                    vr,
                    hth,
                );
                let r_t = resid(&trial, &ev_t);
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
                converged = true;
                break;
            }
        }
        if !converged {
            (_, un, ev) = best;
            let ctx = ClosureCtx {
                bodies: &bodies,
                half_w,
                states: &states,
                joint: &joint,
                mu,
                vr,
                hth,
                winv: &winv,
                base: &base,
                q: &q,
                u: &u,
                th,
                h,
            };
            match closure_step(&ctx, &un, &ev) {
                Some((u2, ev2)) => {
                    un = u2;
                    ev = ev2;
                    closure_steps += 1;
                }
                // keep the iterate with the smallest residual
                None => newton_failures += 1,
            }
        }
        let r_new = gen_force(&ev);
        let rbar = r_k * (1.0 - th) + r_new * th;
        let u_th = u * (1.0 - th) + un * th;
        let u_mid = (u + un) * 0.5;
        let fbar = f_of(&ag[k]) * (1.0 - th) + f_of(&ag[k + 1]) * th;
        w_in += h * u_mid.dot(&fbar);
        d_visc += h * u_th.dot(&(cmat * u_th));
        d_cont -= h * u_mid.dot(&rbar);
        // impacts: intervals of positive total joint force
        let f_now = ev[0].f_n + ev[1].f_n;
        if f_now > 0.0 && !joint_in_contact {
            n_impacts += 1;
        }
        joint_in_contact = f_now > 0.0;
        for e in 0..2 {
            let (fn0, ft0) = (ends[e].f_n, ends[e].f_t);
            let (fn1, ft1) = (ev[e].f_n, ev[e].f_t);
            if fn1 > 0.0 && open_imp[e].is_none() {
                let wn = ev[e].wn;
                let wt = ev[e].wt;
                impacts.push(ImpactRecord {
                    impact: n_impacts,
                    time: t + h,
                    contact: SimContact::Joint(
                        ev[e]
                            .case
                            .unwrap_or(crate::geometry::ContactCase::Deck1Inner),
                    ),
                    mode: SlipMode::Stick,
                    gamma_n_pre: wn.dot(&u),
                    gamma_t_pre: wt.dot(&u),
                    gamma_n_post: Real::NAN,
                    gamma_t_post: Real::NAN,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    energy_dissipated: 0.0,
                });
                open_imp[e] = Some(OpenImpact {
                    record: impacts.len() - 1,
                    impulse_n: 0.0,
                    impulse_t: 0.0,
                    work: 0.0,
                });
            }
            if let Some(oi) = open_imp[e].as_mut() {
                let pn = h * ((1.0 - th) * fn0 + th * fn1);
                let pt = h * ((1.0 - th) * ft0 + th * ft1);
                oi.impulse_n += pn;
                oi.impulse_t += pt;
                let wn = if ev[e].case.is_some() {
                    ev[e].wn
                } else {
                    ends[e].wn
                };
                let wt = if ev[e].case.is_some() {
                    ev[e].wt
                } else {
                    ends[e].wt
                };
                oi.work -= u_mid.dot(&wn) * pn + u_mid.dot(&wt) * pt;
                if fn1 <= 0.0 {
                    let rec = &mut impacts[oi.record];
                    rec.gamma_n_post = wn.dot(&un);
                    rec.gamma_t_post = wt.dot(&un);
                    rec.impulse_n = oi.impulse_n;
                    rec.impulse_t = oi.impulse_t;
                    rec.energy_dissipated = oi.work;
                    rec.mode = SlipMode::classify(rec.gamma_t_post, rec.gamma_n_pre);
                    open_imp[e] = None;
                }
            }
            states[e] = ev[e].state;
        }
        for e in &ev {
            max_pen = max_pen.max(e.delta);
        }
        q = q_of(&un);
        u = un;
        r_k = r_new;
        ends = ev;
        steps_done = k + 1;
        if !(q.iter().all(|x| x.is_finite()) && u.iter().all(|x| x.is_finite())) {
            status = SimStatus::Diverged;
            break;
        }
    }
    // impacts still in progress at the end of the run
    for oi in open_imp.iter().flatten() {
        let rec = &mut impacts[oi.record];
        rec.impulse_n = oi.impulse_n;
        rec.impulse_t = oi.impulse_t;
        rec.energy_dissipated = oi.work;
    }
    if status == SimStatus::Completed && newton_failures > 0 {
        status = SimStatus::CompletedWithNewtonFailures;
    }
    let (tf, vf) = energy_of(&q, &u);
    let summary = SimSummary {
        impacts: n_impacts,
        impacting_contacts: impacts.len(),
        peak_joint_closing: peak_close,
        peak_joint_opening: peak_open,
        peak_rotation: peak_rot,
        peak_slip,
        peak_seat_displacement: peak_seat
            .iter()
            .copied()
            .fold(Real::NEG_INFINITY, Real::max),
        peak_seat_by_end: peak_seat,
        unseated: unseat.is_some(),
        unseating_time: unseat.map(|u| u.0),
        unseated_end: unseat.map(|u| u.1),
        max_penetration: max_pen,
        energy_balance_error: balance_error(max_bal, max_in),
        final_energy: Energy {
            input: w_in,
            kinetic: tf,
            potential: vf,
            viscous: d_visc,
            contact: d_cont,
        },
        max_input_energy: max_in,
        peak_abutment_closing: [None, None],
        abutment_impacting_contacts: 0,
        peak_contact_force: Some(peak_force),
        peak_penetration: max_pen,
    };
    Ok(SimSolution {
        status,
        history: hist,
        impacts,
        summary,
        steps: steps_done,
        dt: h,
        lcp_solves: 0,
        lcp_enumeration_fallbacks: 0,
        lcp_failures: 0,
        frequencies: sys.frequencies,
        rayleigh: sys.rayleigh,
        time_step_advice: advice,
        newton_failures,
        closure_steps,
    })
}
