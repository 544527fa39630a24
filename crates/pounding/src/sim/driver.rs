//! The time-stepping driver shared by every contact law.
//!
//! The shape follows an optimisation executor (argmin): the **driver** owns the loop over the
//! steps `t_k = k h`, the ground-motion samples, the monitors (peaks, seats and unseating,
//! abutment closings, the energy bookkeeping and its balance, divergence detection), the
//! history decimation and the run's result ([`RunResult`], made a
//! [`super::bridge::BridgeSolution`] by `bridge.rs`); a **[`Stepper`]** advances the
//! state by one step and owns only what its contact law needs:
//!
//! * [`super::rigid::RigidStepper`]: Moreau–Jean with the impact LCP (module doc of [`super`]);
//! * [`super::compliance::ComplianceStepper`]: trapezoid with Newton on the compliance forces.
//!
//! Each step `k → k+1` the driver evaluates the geometry at `q_k` once ([`Frame`]), monitors and
//! records the state, computes the contact-free velocity
//! `u_free = u_k + A_u u_k + A_q q_k + B_g ā` (`ā = (1−θ) a_g,k + θ a_g,k+1`), asks the stepper
//! for `u_{k+1}` and then updates the smooth energy terms and the position:
//! ```text
//! W_in += h ū·F̄,   D_viscous += h ū_θᵀ C ū_θ,   q_{k+1} = q_k + h ū_θ
//! ```
//! with `ū = (u_k + u_{k+1})/2`, `ū_θ = (1−θ) u_k + θ u_{k+1}`, `F̄ = (1−θ) F_k + θ F_{k+1}`. The
//! contact term `D_contact` belongs to the stepper ([`Stepper::contact_energy`]).
//!
//! The driver knows the bridge only through lists: bodies (3 DOF each, `q = (x_j, y_j, θ_j)_j`),
//! segment ends on seats, abutment faces, the joints' candidates of a [`Frame`]; `M`, `K`, `C`
//! are block diagonal (one `3 × 3` block per segment). The two-deck model is one instance
//! (`BridgeModel::from_pair`). The scheme's matrices are in `scheme.rs`, the bridge's lists in
//! `view.rs`.

use super::contact::State;
use super::excitation::Offsets;
use super::observer::{Observer, Snapshot};
use super::peaks::{Observed, Peaks};
use super::projection::Projector;
use super::scheme::{Scheme, Winv, Work};
use super::table::TableSource;
use super::view::{Bridge, Frame};
use super::{
    Energy, ImpactRecord, SimSettings, SimStatus, balance_error, energies_finite, max_nan,
};
use crate::contact_law::timestep::TimeStepAdvice;
use crate::math::Real;

/// What a stepper gets for one step `k → k+1`.
pub(crate) struct StepInput<'a> {
    /// `t_{k+1}` (the time impacts of this step are reported at), from [`TimeGrid::time`].
    pub t_next: Real,
    /// `q_k`.
    pub q: &'a State,
    /// `u_k`.
    pub u: &'a State,
    /// Contact-free `u_{k+1}`.
    pub u_free: &'a State,
    /// Geometry at `q_k`.
    pub frame: &'a Frame,
    /// The bridge.
    pub bridge: &'a Bridge,
    /// Time grid and matrices.
    pub scheme: &'a Scheme,
    /// The iteration-matrix inverse of this step (the scheme's `Ŵ⁻¹`, or the tangent one where
    /// bearings flow: [`Winv`]).
    pub winv: Winv<'a>,
    /// The supports' offsets and velocities at `t_k` and `t_{k+1}` when they move apart
    /// ([`super::excitation`]).
    pub ground: Option<&'a Offsets>,
}

/// The times `t_k = k·h` of the step grid, as the decimals the user expects: with `h` a short
/// decimal (`1e-3`, `2.5e-4`, a record's `0.005`), `k·h` in floating point is often off by an ulp
/// (`13003 × 0.001 = 13.003000000000002`); it is rounded to the decimal places of `h`, which is
/// `t_k` itself (the nearest double to the exact decimal `k·h`). For an `h` with no short decimal
/// form (more than 12 places) or a product beyond 2⁵³ in those units, `k·h` is kept as computed.
#[derive(Debug, Clone, Copy)]
pub(crate) struct TimeGrid {
    h: Real,
    /// `(m, 10^d)` with `h` the double nearest `m / 10^d` (`m` an integer, `d ≤ 12`), if any.
    decimal: Option<(Real, Real)>,
}

impl TimeGrid {
    /// The grid of step `h`.
    pub(crate) fn new(h: Real) -> Self {
        let decimal = (0..=12).map(|d| 10f64.powi(d)).find_map(|p| {
            let m = (h * p).round();
            ((1.0..1e15).contains(&m) && (m / p - h).abs() <= 2.0 * Real::EPSILON * h)
                .then_some((m, p))
        });
        Self { h, decimal }
    }

    /// `t_k`: `k·m / 10^d` in exact integer arithmetic then one rounding (the double nearest
    /// the decimal `k·h`), else `k·h`.
    pub(crate) fn time(&self, k: usize) -> Real {
        match self.decimal {
            Some((m, p)) if (k as Real) * m < 9.0e15 => (k as Real * m) / p,
            _ => k as Real * self.h,
        }
    }
}

/// What a stepper returns for one step.
pub(crate) struct StepOutput {
    /// `u_{k+1}`.
    pub u: State,
    /// Largest contact deformation `δ` seen in the step (`−∞` if the law has none).
    pub penetration: Real,
    /// The generalised contact impulse of the step on every coordinate (`None`: none): the
    /// rigid sites' `W P`, the compliance sites' `h ((1−θ) R_k + θ R_{k+1})`. Only reported
    /// ([`super::segment_forces`]); `u` already holds its effect.
    pub impulse: Option<State>,
}

/// The impacts found so far (records and the 1-based count of impacts).
#[derive(Default)]
pub(crate) struct ImpactLog {
    /// Impacting contacts, in time order.
    pub records: Vec<ImpactRecord>,
    /// Number of impacts (of the whole bridge: steps with an impact for the rigid law, onsets
    /// of positive force at a site for compliance laws).
    pub impacts: usize,
    /// Impacts per joint.
    pub joint_impacts: Vec<usize>,
    /// Impacts per abutment side `[start, end]`.
    pub abutment_impacts: [usize; 2],
}

impl ImpactLog {
    /// One more impact at joint `k`.
    pub fn count_joint(&mut self, k: usize) {
        if self.joint_impacts.len() <= k {
            self.joint_impacts.resize(k + 1, 0);
        }
        self.joint_impacts[k] += 1;
    }

    /// One more impact at abutment `side`.
    pub fn count_abutment(&mut self, side: usize) {
        self.abutment_impacts[side] += 1;
    }
}

/// The stepper's counters at the end of a run.
#[derive(Default)]
pub(crate) struct StepperStats {
    pub lcp_solves: usize,
    pub lcp_enumeration_fallbacks: usize,
    pub lcp_failures: usize,
    pub newton_failures: usize,
    pub closure_steps: usize,
    /// Steps in which a contact impulse changed a yielding bearing's branch and the end
    /// velocity was corrected ([`super::yielding`]).
    pub bearing_corrections: usize,
    pub time_step_advice: Option<TimeStepAdvice>,
}

/// One step of a contact law's time integrator.
pub(crate) trait Stepper {
    /// Normal force of each joint end, per joint, in the current state (`None`: impulsive
    /// contact).
    fn contact_forces(&self) -> Option<&[[Real; 2]]>;
    /// The contact term `D_contact` of the energy balance so far.
    fn contact_energy(&self) -> Real;
    /// Adds `delta` to the contact term of the energy balance (the driver's correction of a
    /// step's end velocity with the contact impulse held fixed, [`super::yielding`]).
    fn adjust_contact_energy(&mut self, delta: Real);
    /// Advances `u_k → u_{k+1}`, logging impacts.
    fn step(&mut self, input: &StepInput, log: &mut ImpactLog) -> StepOutput;
    /// Takes back `u_k`, no longer needed once `u_{k+1}` is known, as storage for a later
    /// [`StepOutput::u`] (a stepper that keeps it allocates nothing per step); dropped by
    /// default.
    fn recycle(&mut self, _u: State) {}
    /// Closes what is still open at the end of the run; returns the counters.
    fn finish(&mut self, log: &mut ImpactLog) -> StepperStats;
    /// The sites whose positions a projection corrects: the rigid-law ones (`None`: none).
    fn projected_sites(&self) -> Option<super::projection::Sites> {
        None
    }
}

/// The energy bookkeeping: input work, viscous dissipation, balance.
struct Ledger {
    e0: Real,
    w_in: Real,
    d_visc: Real,
    max_in: Real,
    max_bal: Real,
    /// The step whose load `F_k` the work buffer `f1` holds (the previous step's `F_{k+1}`).
    loaded: Option<usize>,
    /// The work of the position projection (`None`: no projection, the sums keep their bits).
    proj: Option<Real>,
}

impl Ledger {
    fn new(e0: Real) -> Self {
        Ledger {
            e0,
            w_in: 0.0,
            d_visc: 0.0,
            max_in: e0.abs(),
            max_bal: 0.0,
            loaded: None,
            proj: None,
        }
    }

    /// Energies at one instant; updates the balance monitor. `w_el`: the work done on the
    /// nonlinear elements (`None` without any, so that the two-deck sums keep their bits).
    fn check(&mut self, tk: Real, vk: Real, d_cont: Real, w_el: Option<Real>) -> Energy {
        let other = match w_el {
            Some(w) => d_cont + w,
            None => d_cont,
        };
        let bal = match self.proj {
            None => self.e0 + self.w_in - (tk + vk + self.d_visc + other),
            Some(p) => self.e0 + self.w_in + p - (tk + vk + self.d_visc + other),
        };
        self.max_bal = max_nan(self.max_bal, bal.abs());
        self.max_in = max_nan(self.max_in, (self.e0 + self.w_in).abs());
        self.energy(tk, vk, d_cont)
    }

    fn energy(&self, tk: Real, vk: Real, d_cont: Real) -> Energy {
        Energy {
            input: self.w_in,
            kinetic: tk,
            potential: vk,
            viscous: self.d_visc,
            contact: d_cont,
            elements: 0.0,
            projection: self.proj.unwrap_or(0.0),
        }
    }

    fn finite(&self, e: &Energy) -> bool {
        energies_finite(&[
            e.kinetic,
            e.potential,
            e.input,
            e.viscous,
            e.contact,
            self.e0,
        ])
    }

    /// Input work and viscous dissipation of step `k`; leaves `ū_θ` in `w.u_th` and `ū` in
    /// `w.u_mid`. `offs`: the supports' offsets over the step, when they move apart (their load
    /// is input work). Inlined into the time loop, as the other per-step parts (one stretch of
    /// code per step: the loop's code no longer fitted the instruction cache spread over a dozen
    /// functions).
    #[inline(always)]
    fn advance(
        &mut self,
        sc: &Scheme,
        k: usize,
        (u, u_new): (&State, &State),
        w: &mut Work,
        offs: Option<&Offsets>,
    ) {
        let th = sc.th;
        if self.loaded == Some(k) {
            std::mem::swap(&mut w.f0, &mut w.f1);
        } else {
            sc.load(&sc.ag[k], &mut w.f0);
            if let Some(o) = offs {
                sc.add_support_load(&o.d, &o.v, &mut w.f0);
            }
        }
        sc.load(&sc.ag[k + 1], &mut w.f1);
        if let Some(o) = offs {
            sc.add_support_load(&o.d1, &o.v1, &mut w.f1);
        }
        self.loaded = Some(k + 1);
        // over slices (no per-entry index checks of the matrix type): the same operations
        let (u, u_new) = (u.as_slice(), u_new.as_slice());
        let (u_th, u_mid) = (w.u_th.as_mut_slice(), w.u_mid.as_mut_slice());
        let (f0, f1, fbar) = (w.f0.as_slice(), w.f1.as_slice(), w.fbar.as_mut_slice());
        for i in 0..u.len() {
            u_th[i] = u[i] * (1.0 - th) + u_new[i] * th;
            u_mid[i] = (u[i] + u_new[i]) * 0.5;
            fbar[i] = f0[i] * (1.0 - th) + f1[i] * th;
        }
        self.w_in += sc.h * w.u_mid.dot(&w.fbar);
        self.d_visc += sc.h * sc.damping_power(&w.u_th, &mut w.cv);
    }
}

/// Sampled time histories of a bridge of any size, flat row-major arrays (one row per kept step).
#[derive(Debug, Clone, Default)]
pub(crate) struct Trace {
    /// Times.
    pub t: Vec<Real>,
    /// `q`, `3 n_bodies` per row.
    pub q: Vec<Real>,
    /// `u`, `3 n_bodies` per row.
    pub u: Vec<Real>,
    /// Gaps of the four candidates of each joint, `4 n_joints` per row.
    pub gaps: Vec<Real>,
    /// End gaps of each joint, `2 n_joints` per row.
    pub end_gaps: Vec<Real>,
    /// Slip of each joint, `n_joints` per row.
    pub slip: Vec<Real>,
    /// Energies.
    pub energy: Vec<Energy>,
    /// Normal force of each joint end (compliance laws), `2 n_joints` per row.
    pub contact_force: Vec<Real>,
    /// Smaller abutment corner gap `[start, end]` (NaN without that abutment).
    pub abutment_gaps: Vec<[Real; 2]>,
    /// The support lines' offsets `(d_x, d_y)` from the reference ground, `2 (N + 1)` per row
    /// (empty when the supports move together).
    pub ground: Vec<Real>,
}

impl Trace {
    /// Room for `rows` rows of a system of `n_dofs` coordinates and `n_joints` joints (the
    /// front ends' memory guard has checked the size; exact room spares the copies and the
    /// doubled pages of growing vectors).
    fn reserve(&mut self, rows: usize, n_dofs: usize, n_joints: usize) {
        let per = |k: usize| rows.saturating_mul(k);
        self.t.reserve(rows);
        self.q.reserve(per(n_dofs));
        self.u.reserve(per(n_dofs));
        self.gaps.reserve(per(4 * n_joints));
        self.end_gaps.reserve(per(2 * n_joints));
        self.slip.reserve(per(n_joints));
        self.energy.reserve(rows);
        self.abutment_gaps.reserve(rows);
    }

    /// Appends the state at `t`.
    #[allow(clippy::too_many_arguments)] // one argument per recorded series
    fn record(
        &mut self,
        t: Real,
        q: &State,
        fr: &Frame,
        u: &State,
        obs: &Observed,
        energy: Energy,
        forces: Option<&[[Real; 2]]>,
    ) {
        self.t.push(t);
        self.q.extend_from_slice(q.as_slice());
        self.u.extend_from_slice(u.as_slice());
        for jf in &fr.joints {
            self.gaps.extend(jf.cands.iter().map(|c| c.gap));
        }
        self.end_gaps.extend(obs.end_gaps.iter().flatten());
        self.slip.extend(&obs.slip);
        self.energy.push(energy);
        if let Some(f) = forces {
            self.contact_force.extend(f.iter().flatten());
        }
        self.abutment_gaps.push(obs.abut_gaps);
        self.ground
            .extend(fr.ground.iter().flat_map(|g| [g.x, g.y]));
    }
}

/// The outcome of [`run`] for a bridge of any size.
pub(crate) struct RunResult {
    pub status: SimStatus,
    pub trace: Trace,
    pub log: ImpactLog,
    pub peaks: Peaks,
    pub stats: StepperStats,
    pub steps: usize,
    pub final_q: State,
    /// The support lines' offsets at `final_q` (empty when the supports move together).
    pub final_ground: Vec<crate::math::Vector>,
    pub elements: super::elements::Elements,
    pub energy_balance_error: Real,
    pub final_energy: Energy,
    pub max_input_energy: Real,
    /// The observers' tables (or what they are derived from).
    pub tables: Vec<TableSource>,
    /// What the position projection did (`None`: not asked for).
    pub projection: Option<super::projection::ProjectionStats>,
}

/// Runs the time loop with `stepper` from `(q0, u0)` (module doc).
pub(crate) fn run<S: Stepper>(
    q0: State,
    u0: State,
    settings: &SimSettings,
    sc: &Scheme,
    bridge: &Bridge,
    stepper: &mut S,
    mut observers: Vec<Box<dyn Observer>>,
) -> RunResult {
    let (h, th) = (sc.h, sc.th);
    let (mut q, mut u) = (q0, u0);
    let mut work = Work::new(q.len());
    let el0 = &bridge.elements;
    // the bodies whose elements' work is booked (block diagonal: the yielding segments, whose
    // strain energy the balance leaves out; coupled: every body a yielding element acts on)
    let mut yield_body = vec![false; sc.dofs.n_bodies()];
    for b in &el0.bearings {
        yield_body[b.body] = true;
        if let Some((c, _)) = b.base {
            yield_body[c] = true;
        }
    }
    let (t0, v0) = sc.energies(&q, &u, &mut work, &yield_body);
    let mut ledger = Ledger::new(t0 + v0);
    let mut peaks = Peaks::new(bridge);
    let mut trace = Trace::default();
    let rows = super::options::history_rows(sc.n_steps, settings.history_stride);
    let rows = usize::try_from(rows).unwrap_or(0);
    trace.reserve(rows, q.len(), bridge.joints.len());
    for o in &mut observers {
        o.reserve(rows);
    }
    let mut log = ImpactLog::default();
    // a run without rigid sites projects nothing, and says so
    let mut projector = settings.projection.then(|| {
        let sites = stepper.projected_sites();
        let sites = sites.unwrap_or_else(|| super::projection::Sites::none(bridge.joints.len()));
        Projector::new(sc, sites, settings.projection_tolerance, &settings.lemke)
    });
    if projector.is_some() {
        ledger.proj = Some(0.0);
    }
    let mut status = SimStatus::Completed;
    let mut steps_done = 0usize;
    let abut_sides: Vec<usize> = bridge.abutments.iter().map(|a| a.side).collect();
    let mut el = bridge.elements.clone();
    let nb = sc.dofs.n_bodies();
    let has_elements = !el.is_empty();
    let mut el_force = super::elements::StepForce::new(&sc.dofs);
    let mut yielding = super::yielding::Implicit::new(&el.bearings, sc);
    // the geometry at q_k: computed once per state, after q_{k+1} is known, so that the
    // elements' commit at q_{k+1} and the next step share its sin θ_j, cos θ_j
    let mut frame = bridge.frame(&q);
    // the supports' offsets at both ends of the step, when they move apart
    let mut offs = sc.motion.as_ref().map(|m| {
        let mut o = Offsets::new(m.len());
        sc.support_offsets(0, &mut o.d, &mut o.v);
        o
    });
    if let Some(o) = &offs {
        frame.ground.clone_from(&o.d);
    }
    let mut obs = Observed::default();
    let mut loads = super::step_loads::StepLoads::new(bridge);
    let clock = TimeGrid::new(h);
    for k in 0..=sc.n_steps {
        if k % super::PROGRESS_EVERY == 0 {
            settings.progress.report(k, sc.n_steps);
        }
        let t = clock.time(k);
        peaks.observe(t, &q, &frame, bridge, &mut obs);
        peaks.observe_segments(&q, bridge, &frame.ground);
        if !bridge.piers.is_empty() {
            peaks.observe_piers(&q, bridge, &el, &frame.ground);
        }
        if peaks.wall.iter().any(Option::is_some) {
            peaks.observe_walls(&q, bridge, &el, &frame.ground);
        }
        for k in &el.keys {
            if let Some((f, v)) = peaks.keys[k.side].as_mut() {
                *f = f.max(k.force.abs());
                *v = v.max(k.deformation(&bridge.dofs, q.as_slice()).abs());
            }
        }
        let forces = stepper.contact_forces();
        if let Some(f) = forces {
            peaks.observe_forces(f, &abut_sides);
        }
        let (tk, vk) = sc.energies(&q, &u, &mut work, &yield_body);
        let w_el = (!el.is_empty())
            .then(|| el.w_bearings.iter().sum::<Real>() + el.w_cables + el.w_backfill + el.w_keys);
        let mut energy = ledger.check(tk, vk, stepper.contact_energy(), w_el);
        energy.elements = w_el.unwrap_or(0.0);
        if k % settings.history_stride == 0 || k == sc.n_steps {
            loads.close(sc);
            let nj = bridge.joints.len();
            trace.record(t, &q, &frame, &u, &obs, energy, forces.map(|f| &f[..nj]));
            let snapshot = Snapshot {
                t,
                frame: &frame,
                bridge,
                elements: &el,
                slip: &obs.slip,
                q: q.as_slice(),
                loads: &loads,
            };
            for o in &mut observers {
                o.observe(&snapshot);
            }
        }
        if !ledger.finite(&energy) {
            status = SimStatus::Diverged;
            break;
        }
        if k == sc.n_steps {
            break;
        }
        let abar = sc.ag[k] * (1.0 - th) + sc.ag[k + 1] * th;
        sc.u_free(&q, &u, &abar, &mut work.u_free);
        if let Some(o) = &mut offs {
            sc.support_offsets(k + 1, &mut o.d1, &mut o.v1);
            sc.add_support_free(o, &mut work.u_free);
            el.set_ground(&o.d1);
        }
        if has_elements {
            el.step_force(&q, &u, h, th, &bridge.bodies, &frame.pose, &mut el_force);
            sc.winv_into(&el_force.r, &mut work.wr);
            for (uf, wr) in work
                .u_free
                .as_mut_slice()
                .iter_mut()
                .zip(work.wr.as_slice())
            {
                *uf += wr * h;
            }
            if !yielding.is_empty() {
                yielding.solve_free(sc, &el.bearings, &q, &u, &mut work.u_free, &el_force);
            }
        }
        let winv = yielding.winv(sc);
        let input = StepInput {
            t_next: clock.time(k + 1),
            q: &q,
            u: &u,
            u_free: &work.u_free,
            frame: &frame,
            bridge,
            scheme: sc,
            winv,
            ground: offs.as_ref(),
        };
        let mut out = stepper.step(&input, &mut log);
        if !yielding.is_empty() {
            let d_contact =
                yielding.finish_step(sc, &el.bearings, &q, &u, &mut out.u, &mut el_force);
            if d_contact != 0.0 {
                stepper.adjust_contact_energy(d_contact);
            }
        }
        peaks.pen = peaks.pen.max(out.penetration);
        ledger.advance(sc, k, (&u, &out.u), &mut work, offs.as_ref());
        if has_elements {
            if !yielding.is_empty() {
                for i in 0..q.len() {
                    work.q_th[i] = q[i] + work.u_th[i] * (th * h);
                }
                sc.yield_stiffness_into(&work.q_th, &mut work.kq_th);
            }
            let kq = (&work.kq_th, yield_body.as_slice());
            el.book(h, &work.u_mid, kq, &mut el_force, nb);
        }
        let el_step = has_elements.then_some(&el_force);
        loads.add_step(&q, &work.u_th);
        if has_elements || out.impulse.is_some() || offs.is_some() {
            loads.add_members(sc, el_step, out.impulse.as_ref(), offs.as_ref());
        }
        for (qi, vi) in q.as_mut_slice().iter_mut().zip(work.u_th.as_slice()) {
            *qi += vi * h;
        }
        stepper.recycle(std::mem::replace(&mut u, out.u));
        bridge.update_frame(&q, &mut frame);
        if let Some(o) = &mut offs {
            o.advance();
            frame.ground.clone_from(&o.d);
        }
        if has_elements {
            el.commit(&q, &frame.pose, &bridge.bodies);
        }
        if let Some(p) = projector.as_mut()
            && let Some(dq) = p.project(&mut q, &mut frame, bridge)
        {
            let (el, f, w) = (&mut el, &mut el_force, &mut work);
            let wp = super::projection::book(sc, (&q, &dq), &frame, bridge, el, f, w, &yield_body);
            ledger.proj = ledger.proj.map(|p| p + wp);
        }
        steps_done = k + 1;
        let finite = |v: &State| v.as_slice().iter().all(|x| x.is_finite());
        if !(finite(&q) && finite(&u)) {
            status = SimStatus::Diverged;
            break;
        }
    }
    peaks.finish(bridge, &frame.ground);
    let mut stats = stepper.finish(&mut log);
    stats.newton_failures += yielding.failures;
    stats.bearing_corrections = yielding.corrections;
    let projection = projector.map(|p| p.stats);
    let projection_failures = projection.map_or(0, |p| p.failures);
    if status == SimStatus::Completed && stats.lcp_failures + projection_failures > 0 {
        status = SimStatus::CompletedWithLcpFailures;
    } else if status == SimStatus::Completed && stats.newton_failures > 0 {
        status = SimStatus::CompletedWithNewtonFailures;
    }
    let energy_balance_error = balance_error(ledger.max_bal, ledger.max_in);
    // θ = ½: the balance closes to rounding; a larger error is a result not to trust
    if status == SimStatus::Completed && th == 0.5 && energy_balance_error > 1e-6 {
        status = SimStatus::CompletedWithEnergyError;
    }
    let (tf, vf) = sc.energies(&q, &u, &mut work, &yield_body);
    let mut final_energy = ledger.energy(tf, vf, stepper.contact_energy());
    final_energy.elements =
        el.w_bearings.iter().sum::<Real>() + el.w_cables + el.w_backfill + el.w_keys;
    RunResult {
        status,
        trace,
        peaks,
        stats,
        steps: steps_done,
        final_q: q,
        final_ground: frame.ground,
        elements: el,
        energy_balance_error,
        final_energy,
        max_input_energy: ledger.max_in,
        log,
        tables: observers.into_iter().map(|o| o.into_source()).collect(),
        projection,
    }
}

#[cfg(test)]
mod tests {
    use super::super::{
        ComplianceContact, JointContact, SimModel, SimProblem, SimSettings, simulate,
    };
    use crate::contact_law::{ContactLaw, Hertz};
    use crate::ground_motion::el_centro_1940;
    use crate::sim::bridge::BridgeSolution;

    /// Step times read back as the decimal `k·h` (no `13.003000000000002`), for short decimal
    /// steps; other steps keep `k·h`.
    #[test]
    fn step_times_are_the_decimals_of_k_h() {
        use super::TimeGrid;
        use crate::output::float_token;
        assert_eq!(float_token(9.0 * 1e-3), "0.009000000000000001");
        assert_eq!(float_token(TimeGrid::new(1e-3).time(9)), "0.009");
        for (h, d) in [
            (1e-3, 3),
            (2.5e-4, 5),
            (0.005, 3),
            (0.02, 2),
            (1e-5, 5),
            (0.1, 1),
        ] {
            let grid = TimeGrid::new(h);
            for k in (0..200_000usize).step_by(7) {
                let exact = format!("{:.*}", d, k as f64 * h);
                let t = grid.time(k);
                assert_eq!(t, exact.parse::<f64>().unwrap(), "h = {h}, k = {k}");
                assert!(
                    (t - k as f64 * h).abs() <= 4.0 * f64::EPSILON * t,
                    "h = {h}, k = {k}"
                );
                assert!(float_token(t).len() <= exact.len(), "{}", float_token(t));
            }
        }
        let third = 1.0 / 3.0 * 1e-3;
        let grid = TimeGrid::new(third);
        assert_eq!(grid.time(12_345), 12_345.0 * third);
    }

    /// The default bridge under El Centro (6 s) with a joint so wide that it never closes.
    fn open_run(law: JointContact, seat_length: f64) -> BridgeSolution {
        let mut model = SimModel::default_bridge();
        model.gap = 2.0;
        model.seat_length = seat_length;
        model.contact = law;
        let problem = SimProblem::at_rest(model, el_centro_1940());
        let settings = SimSettings {
            duration: Some(6.0),
            ..SimSettings::default()
        };
        simulate(&problem, &settings).unwrap()
    }

    /// Without any contact both steppers return `u_free`, so the one driver must produce the
    /// same histories, monitors and energies bit for bit for both laws (the two copied loops
    /// had already drifted apart).
    #[test]
    fn rigid_and_compliance_runs_share_every_monitor_without_contact() {
        let hertz = || {
            let law = ContactLaw::Hertz(Hertz::new(1e10).unwrap());
            JointContact::Compliance(ComplianceContact::new(law))
        };
        for seat in [5.0, 1e-3] {
            let r = open_run(JointContact::Rigid, seat);
            let c = open_run(hertz(), seat);
            assert_eq!(r.status, c.status);
            assert_eq!(r.summary.impacts + c.summary.impacts, 0);
            assert_eq!(c.summary.joints[0].peak_contact_force, Some(0.0));
            assert_eq!(r.summary.joints[0].peak_contact_force, None);
            let mut cs = c.summary.clone();
            cs.joints[0].peak_contact_force = None;
            assert_eq!(format!("{:?}", r.summary), format!("{cs:?}"));
            assert_eq!(r.summary.unseated, seat < 1.0);
            assert!(r.summary.energy_balance_error < 1e-12);
            let mut c = c.clone();
            assert_eq!(c.contact_force.len(), 2 * c.t.len());
            assert!(c.contact_force.iter().all(|f| *f == 0.0));
            c.contact_force.clear();
            // the histories of both runs; Debug text compares NaN (no abutment gap) bit for bit
            let history = |s: &BridgeSolution| {
                format!(
                    "{:?}",
                    (&s.t, &s.q, &s.u, &s.gaps, &s.end_gaps, &s.slip, &s.energy)
                ) + &format!("{:?}", (&s.contact_force, &s.abutment_gaps, s.tables()))
            };
            assert!(history(&r) == history(&c), "the histories differ");
            assert!(r.t.len() == 6001 && r.summary.joints[0].peak_opening > 0.0);
        }
    }
}
