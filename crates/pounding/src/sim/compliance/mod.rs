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
//! decks rotate), with a backtracking line search. `∂R/∂u` is a sum of one or two rank-one
//! terms per end in contact, so each Newton correction is solved in contact space by the
//! Sherman–Morrison–Woodbury identity (an `m × m` system, `m` ≤ two per active end; see
//! `ComplianceStepper::correction`) rather than as an `n × n` system of the whole bridge; converged when `|Δu|_∞ ≤ 1e-12 + 1e-10 |u|_∞`
//! (at most 50 iterations). A law whose force jumps at `δ = 0` (Kelvin's dashpot force `c δ̇`
//! at contact onset) can leave a step without a root when it would end within `O(h² c δ̇ / m)`
//! of `δ = 0`; that step is solved in the **closure of the law's graph**: the ends within 1 µm of
//! `δ = 0` are held at `δ_{k+1} = 0` by an unknown force `λ ∈ [0, F(0⁺, δ̇)]` (Newton on
//! `(u, λ)`, [`super::bridge::BridgeSolution::closure_steps`]). If that fails too, the iterate with the
//! smallest residual is kept and the step is counted in [`super::bridge::BridgeSolution::newton_failures`]
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
//! `∫ f dt` (trapezoidal, as the scheme) and the contact work `−∫ γ·f dt` as energy dissipated,
//! and the force pulse ([`super::ImpactPulse`]: the end's peak force, duration of positive force
//! and largest penetration).
//! [`super::bridge::JointSummary::peak_contact_force`] is the largest total joint force,
//! [`super::bridge::BridgeSummary::peak_penetration`] the largest `δ` of an end. The contact term of the
//! energy balance is `D_contact = −Σ h ū·R̄` (`ū` the mean velocity, `R̄ = (1−θ)R_k + θR_{k+1}`):
//! the law's dissipation plus the energy momentarily stored in the contact spring; with θ = ½
//! the discrete balance is exact, as for the rigid scheme.
//!
//! # Time step
//! [`crate::contact_law::timestep::law_time_step_advice`] with `m_eff = m1 m2/(m1 + m2)` (deck
//! masses) and `v_ref = 1 m/s`; the advice is returned in
//! [`super::bridge::BridgeSolution::time_step_advice`] (the CLI warns when it is not adequate).
#![allow(clippy::needless_range_loop)]
mod ends;
mod impacts;
mod newton;

use super::contact::{JointGeom, Pose, Sparse, State, candidates};
use super::driver::{ImpactLog, StepInput, StepOutput, Stepper, StepperStats};
use super::model::SegmentBody;
use super::scheme::{Scheme, Winv};
use super::view::Bridge;
use crate::contact_law::sharing::JointLaw;
use crate::contact_law::timestep::law_time_step_advice;
use crate::contact_law::{LawState, effective_mass};
use crate::geometry::ContactCase;
use crate::math::Real;
pub(crate) use ends::{CLOSURE_WINDOW, EndEval};
use ends::{gen_force, gen_force_into};
use impacts::OpenImpact;

/// The fixed data of one step's iteration: `q_k`, `u_k`, the scheme (for `Ŵ⁻¹`) and
/// `base = u_free + h (1−θ) Ŵ⁻¹ R_k`.
struct Trial<'a> {
    q: &'a State,
    u: &'a State,
    winv: Winv<'a>,
    base: std::borrow::Cow<'a, State>,
    /// The supports' offsets and velocities at `t_{k+1}` (when they move apart).
    ground: Ground<'a>,
}

/// The supports' offsets and velocities at one time, when they move apart
/// ([`super::excitation`]).
type Ground<'a> = Option<(&'a [crate::math::Vector], &'a [crate::math::Vector])>;

/// A compliance law at one contact site (a joint or an abutment), shared by its two ends.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SiteLaw {
    /// The law, shared by the two ends.
    pub law: JointLaw,
    /// Coulomb friction coefficient.
    pub mu: Real,
}

/// The compliance-law stepper (module doc). Sites are the joints (in order) and then the
/// compliant abutments (start before end); the ends of site `s` are numbered `2 s` and `2 s + 1`
/// (a joint's two ends; an abutment's corners `c0`, `c1`).
pub(crate) struct ComplianceStepper {
    bodies: Vec<SegmentBody>,
    /// The DOF map of the segments.
    dofs: super::dofs::Dofs,
    joints: Vec<super::contact::JointGeom>,
    abutments: Vec<super::view::AbutmentFace>,
    /// Law of each site.
    sites: Vec<SiteLaw>,
    vr: Real,
    h: Real,
    th: Real,
    hth: Real,
    /// Committed law state of each end.
    states: Vec<LawState>,
    /// The ends at `t_k`.
    ends: Vec<EndEval>,
    /// Normal force of each end at `t_k`, per site.
    forces: Vec<[Real; 2]>,
    /// `R_k`.
    r_k: State,
    /// Scratch of [`Self::commit`]: `R_{k+1}` and `ū` (allocated once).
    r_new: State,
    u_mid: State,
    site_in_contact: Vec<bool>,
    open_imp: Vec<Option<OpenImpact>>,
    d_cont: Real,
    stats: StepperStats,
    /// The pose of a trial state (storage reused from one evaluation to the next).
    pose: std::cell::RefCell<Pose>,
    /// Per body: whether a contact end reads its pose (a joint's segments, an abutment's).
    posed: Vec<bool>,
    /// The trial `q_{k+1}` (storage reused likewise).
    q_trial: std::cell::RefCell<State>,
}

/// The time-step advice of a run's compliance sites: per site, its own law at the effective mass
/// of the two bodies it separates (a joint: its two segments; an abutment: its segment against
/// its backwall, or alone against the ground), the advice with the fewest steps per contact —
/// the site whose contact the step resolves worst. `None` without a site (or no valid mass).
fn site_time_step_advice(
    sites: &[SiteLaw],
    (joints, abutments): (&[JointGeom], &[super::view::AbutmentFace]),
    scheme: &Scheme,
    bridge: &Bridge,
) -> Option<crate::contact_law::timestep::TimeStepAdvice> {
    let segment = |b: usize| bridge.bodies[b].mass.mass;
    // a backwall's mass: its one coordinate's diagonal entry of the (coupled) mass matrix
    let wall = |w: usize| {
        let i = bridge.dofs.range(w).start;
        scheme.dense.as_ref().map(|d| d.sys.m[(i, i)])
    };
    let masses = joints
        .iter()
        .map(|j| effective_mass(segment(j.a), segment(j.b)).ok())
        .chain(abutments.iter().map(|a| match a.wall {
            Some(w) => effective_mass(segment(a.body), wall(w)?).ok(),
            None => Some(segment(a.body)),
        }));
    sites
        .iter()
        .zip(masses)
        .filter_map(|(site, m)| law_time_step_advice(site.law.law(), scheme.h, m?, 1.0).ok())
        .min_by(|a, b| a.steps_per_contact.total_cmp(&b.steps_per_contact))
}

impl ComplianceStepper {
    /// The stepper at the initial state `(q0, u0)`: law states open at the initial gaps
    /// (committed `δ = −g_N(q_0)`). `sites` holds the law of every joint of `joints` and then of
    /// every abutment of `abutments` (subsets of the bridge's, in bridge order: the compliance
    /// sites; a mixed bridge's rigid sites are the rigid stepper's). The time-step advice is
    /// that of the site with the fewest steps per contact ([`site_time_step_advice`]).
    pub fn new(
        q0: &State,
        u0: &State,
        sites: Vec<SiteLaw>,
        (joints, abutments): (Vec<JointGeom>, Vec<super::view::AbutmentFace>),
        friction_velocity: Real,
        scheme: &Scheme,
        bridge: &Bridge,
    ) -> Self {
        let (h, th) = (scheme.h, scheme.th);
        let n = bridge.dofs.len();
        let n_ends = 2 * sites.len();
        let advice = site_time_step_advice(&sites, (&joints, &abutments), scheme, bridge);
        let mut posed = vec![false; bridge.bodies.len()];
        for j in &joints {
            (posed[j.a], posed[j.b]) = (true, true);
        }
        for ab in &abutments {
            posed[ab.body] = true;
        }
        let mut s = ComplianceStepper {
            bodies: bridge.bodies.clone(),
            dofs: bridge.dofs.clone(),
            joints,
            abutments,
            vr: friction_velocity,
            h,
            th,
            hth: h * th,
            states: vec![LawState::default(); n_ends],
            ends: vec![EndEval::open(); n_ends],
            forces: vec![[0.0; 2]; sites.len()],
            r_k: State::zeros(n),
            r_new: State::zeros(n),
            u_mid: State::zeros(n),
            site_in_contact: vec![false; sites.len()],
            open_imp: vec![None; n_ends],
            d_cont: 0.0,
            stats: StepperStats {
                time_step_advice: advice,
                ..StepperStats::default()
            },
            pose: std::cell::RefCell::new(Pose::new(&bridge.bodies, &bridge.dofs, q0.as_slice())),
            q_trial: std::cell::RefCell::new(State::zeros(n)),
            posed,
            sites,
        };
        let first = s.eval_ends(q0, u0, &s.states, None, true);
        for (st, f) in s.states.iter_mut().zip(&first) {
            *st = LawState::open_at(f.delta.min(0.0));
        }
        s.ends = s.eval_ends(q0, u0, &s.states, None, true);
        for (st, e) in s.states.iter_mut().zip(&s.ends) {
            *st = e.state;
        }
        s.r_k = gen_force(&s.ends, n);
        s.set_forces();
        s
    }
}

/// How a step's contact forces were found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Solved {
    /// Newton converged.
    Newton,
    /// In the closure of the law's graph.
    Closure,
    /// Neither: the iterate with the smallest residual.
    Failed,
}

impl ComplianceStepper {
    /// `u_{k+1}` of the step from `inp` and the ends there, without committing anything.
    pub(crate) fn solve_step(&self, inp: &StepInput) -> (State, Vec<EndEval>, Solved) {
        let (h, th, hth) = (self.h, self.th, self.hth);
        // no force at t_k (most steps): the base and the first guess are `u_free`
        let (base, guess) = if self.r_k.iter().all(|r| *r == 0.0) {
            (std::borrow::Cow::Borrowed(inp.u_free), inp.u_free.clone())
        } else {
            let wr = inp.winv.mul(&self.r_k);
            let base = inp.u_free + &wr * (h * (1.0 - th));
            let guess = &base + &wr * hth;
            (std::borrow::Cow::Owned(base), guess)
        };
        let tr = Trial {
            q: inp.q,
            u: inp.u,
            winv: inp.winv,
            base,
            ground: inp.ground.map(|o| (&o.d1[..], &o.v1[..])),
        };
        let (converged, un, ev) = self.newton(&tr, guess);
        if converged {
            return (un, ev, Solved::Newton);
        }
        match self.closure_step(&tr, &un, &ev) {
            Some((u2, ev2)) => (u2, ev2, Solved::Closure),
            None => (un, ev, Solved::Failed),
        }
    }

    /// Commits the step solved by [`Self::solve_step`]: counters, contact work
    /// `−h ū·R̄`, impact records, law states.
    pub(crate) fn commit(
        &mut self,
        inp: &StepInput,
        un: State,
        ev: Vec<EndEval>,
        solved: Solved,
        log: &mut ImpactLog,
    ) -> StepOutput {
        let (h, th) = (self.h, self.th);
        match solved {
            Solved::Newton => {}
            Solved::Closure => self.stats.closure_steps += 1,
            // the iterate with the smallest residual was kept
            Solved::Failed => self.stats.newton_failures += 1,
        }
        let mut r_new = std::mem::take(&mut self.r_new);
        gen_force_into(&ev, &mut r_new);
        let mut u_mid = std::mem::take(&mut self.u_mid);
        for (m, (a, b)) in u_mid.iter_mut().zip(inp.u.iter().zip(un.iter())) {
            *m = (a + b) * 0.5;
        }
        // no force at either end of the step (most steps): no contact work
        let mut impulse = None;
        if !(r_new.iter().all(|r| *r == 0.0) && self.r_k.iter().all(|r| *r == 0.0)) {
            let rbar = &self.r_k * (1.0 - th) + &r_new * th;
            self.d_cont -= h * u_mid.dot(&rbar);
            impulse = Some(rbar * h);
        }
        self.track_impacts(log, inp.t_next, inp.u, &un, &u_mid, &ev);
        self.u_mid = u_mid;
        // the old `R_k` is the next step's scratch
        self.r_new = std::mem::replace(&mut self.r_k, r_new);
        let penetration = ev
            .iter()
            .map(|e| e.delta)
            .fold(Real::NEG_INFINITY, Real::max);
        self.ends = ev;
        self.set_forces();
        StepOutput {
            u: un,
            penetration,
            impulse,
        }
    }
}

impl Stepper for ComplianceStepper {
    fn contact_forces(&self) -> Option<&[[Real; 2]]> {
        Some(&self.forces)
    }

    fn contact_energy(&self) -> Real {
        self.d_cont
    }

    fn adjust_contact_energy(&mut self, delta: Real) {
        self.d_cont += delta;
    }

    fn step(&mut self, inp: &StepInput, log: &mut ImpactLog) -> StepOutput {
        let (un, ev, solved) = self.solve_step(inp);
        self.commit(inp, un, ev, solved, log)
    }

    fn finish(&mut self, log: &mut ImpactLog) -> StepperStats {
        // impacts still in progress at the end of the run
        for oi in self.open_imp.iter().flatten() {
            let rec = &mut log.records[oi.record];
            rec.impulse_n = oi.impulse_n;
            rec.impulse_t = oi.impulse_t;
            rec.energy_dissipated = oi.work;
            rec.pulse = Some(oi.pulse(Real::NAN));
        }
        std::mem::take(&mut self.stats)
    }
}
