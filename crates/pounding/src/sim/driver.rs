//! The time-stepping driver shared by every contact law.
//!
//! The shape follows an optimisation executor (argmin): the **driver** owns the loop over the
//! steps `t_k = k h`, the ground-motion samples, the monitors (peaks, seats and unseating,
//! abutment closings, the energy bookkeeping and its balance, divergence detection), the
//! history decimation and the assembly of the [`SimSolution`]; a **[`Stepper`]** advances the
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
//! deck ends on seats, abutment faces, the joint-end gaps of a [`Frame`]. The two-deck model is
//! one instance ([`State`] is its 6-vector).

use super::contact::{Candidate, Pose, candidates};
use super::model::{DeckBody, LinearSystem};
use super::{
    Energy, History, ImpactRecord, SimContact, SimError, SimModel, SimProblem, SimSettings,
    SimSolution, SimStatus, SimSummary, balance_error, energies_finite, max_nan,
};
use crate::contact_law::timestep::TimeStepAdvice;
use crate::math::{Real, Vector};
use nalgebra::{Matrix6, Matrix6x2, Vector2, Vector6};

/// The generalised coordinates (or velocities) of the bridge: `(x_j, y_j, θ_j)` per body.
pub(crate) type State = Vector6<Real>;

/// Validates the settings, the ground motion, the model and the initial state; returns the
/// assembled linear system.
pub(crate) fn checked_system(
    problem: &SimProblem,
    settings: &SimSettings,
) -> Result<LinearSystem, SimError> {
    settings.validate()?;
    problem.ground.validate()?;
    let sys = problem.model.linear_system()?;
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
    Ok(sys)
}

/// The time grid and the iteration matrices of the θ-method.
pub(crate) struct Scheme {
    /// Step `h`.
    pub h: Real,
    /// θ.
    pub th: Real,
    /// Number of steps.
    pub n_steps: usize,
    /// Ground acceleration at `t_0 … t_n`.
    pub ag: Vec<Vector>,
    /// `M`, `K`, `C`, frequencies.
    pub sys: LinearSystem,
    /// `Ŵ⁻¹ = (M + hθC + h²θ²K)⁻¹`.
    pub winv: Matrix6<Real>,
    a_u: Matrix6<Real>,
    a_q: Matrix6<Real>,
    b_g: Matrix6x2<Real>,
    /// `M r`: the effective load is `F = −M r a_g`.
    mr: Matrix6x2<Real>,
}

impl Scheme {
    /// Duration, step count, ground-motion samples and `Ŵ⁻¹` (errors name `duration` / `dt`).
    pub fn new(
        problem: &SimProblem,
        settings: &SimSettings,
        sys: LinearSystem,
    ) -> Result<Self, SimError> {
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
        let th = settings.theta;
        let (mm, kk, cc) = (&sys.mass, &sys.stiffness, &sys.damping);
        // h²θ² as the rigid scheme always computed it; the former compliance copy used (hθ)²,
        // which has the same bits for θ = ½ (scaling by powers of two is exact).
        let what = mm + cc * (h * th) + kk * (h * h * th * th);
        let winv = what
            .try_inverse()
            .ok_or_else(|| SimError::invalid("dt", h, "iteration matrix is singular"))?;
        // u_free = u + A_u u + A_q q + B_g ā,  B_g = −h Ŵ⁻¹ M r
        let a_u = -(winv * (cc + kk * (h * th))) * h;
        let a_q = -(winv * kk) * h;
        let mut mr = Matrix6x2::zeros();
        for j in 0..mm.nrows() / 3 {
            mr[(3 * j, 0)] = mm[(3 * j, 3 * j)];
            mr[(3 * j + 1, 1)] = mm[(3 * j + 1, 3 * j + 1)];
        }
        let b_g = -(winv * mr) * h;
        Ok(Scheme {
            h,
            th,
            n_steps,
            ag,
            sys,
            winv,
            a_u,
            a_q,
            b_g,
            mr,
        })
    }

    /// The effective seismic load `F = −M r a_g`.
    fn load(&self, a: &Vector) -> State {
        -(self.mr * Vector2::new(a.x, a.y))
    }

    /// `(T, V) = (½ uᵀ M u, ½ qᵀ K q)`.
    fn energies(&self, q: &State, u: &State) -> (Real, Real) {
        let (mm, kk) = (&self.sys.mass, &self.sys.stiffness);
        (0.5 * u.dot(&(mm * u)), 0.5 * q.dot(&(kk * q)))
    }
}

/// An abutment face (the ground) beyond a body's far end ([`super::SimAbutment`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct AbutmentFace {
    /// The body (0-based) whose far face meets it.
    pub body: usize,
    /// Normal into the body.
    pub normal: Vector,
    /// Tangent `perp(n)`.
    pub tangent: Vector,
    /// A point of the face (reference pose).
    pub point: Vector,
    /// Reference gap.
    pub gap: Real,
}

/// A body end resting on a seat.
#[derive(Debug, Clone, Copy)]
struct SeatEnd {
    body: usize,
    corners: [Vector; 2],
    inward: Vector,
    length: Real,
}

/// The bridge as lists: bodies, joint, seated ends, abutments.
pub(crate) struct Bridge {
    /// Reference-pose bodies.
    pub bodies: [DeckBody; 2],
    /// Half the joint-face length.
    pub half_w: Real,
    /// Reference joint gap.
    pub joint_gap: Real,
    /// Abutment faces (only the present ones).
    pub abutments: Vec<AbutmentFace>,
    /// Seated ends in [`super::SEAT_ENDS`] order.
    seats: Vec<SeatEnd>,
}

impl Bridge {
    /// The model's bodies, abutments and seats.
    pub fn new(model: &SimModel) -> Self {
        let bodies = model.bodies();
        let abutments = model
            .abutments
            .iter()
            .enumerate()
            .filter_map(|(j, a)| {
                a.map(|a| {
                    let n = bodies[j].far_inward;
                    AbutmentFace {
                        body: j,
                        normal: n,
                        tangent: Vector::new(-n.y, n.x),
                        point: bodies[j].far_mid() - n * a.gap,
                        gap: a.gap,
                    }
                })
            })
            .collect();
        let mut seats = Vec::with_capacity(2 * bodies.len());
        for (j, b) in bodies.iter().enumerate() {
            let far_seat = model.abutments[j].map_or(model.seat_length, |a| a.seat_length);
            seats.push(SeatEnd {
                body: j,
                corners: b.joint_corners,
                inward: b.joint_inward,
                length: model.seat_length,
            });
            seats.push(SeatEnd {
                body: j,
                corners: b.far_corners,
                inward: b.far_inward,
                length: far_seat,
            });
        }
        Bridge {
            bodies,
            half_w: bodies[0].half_face,
            joint_gap: model.gap,
            abutments,
            seats,
        }
    }

    /// The geometry at `q`.
    pub fn frame(&self, q: &State) -> Frame {
        let qa: [Real; 6] = (*q).into();
        let pose = Pose::new(&self.bodies, &qa);
        let (cands, sel) = candidates(&self.bodies, &pose, self.half_w);
        Frame {
            qa,
            pose,
            cands,
            sel,
        }
    }
}

/// The geometry of one state: pose and joint candidates.
pub(crate) struct Frame {
    /// `q` as an array.
    pub qa: [Real; 6],
    /// The pose.
    pub pose: Pose,
    /// All joint candidates.
    pub cands: [Candidate; 4],
    /// The realised candidate of each joint end.
    pub sel: [Option<usize>; 2],
}

/// What a stepper gets for one step `k → k+1`.
pub(crate) struct StepInput<'a> {
    /// `t_k`.
    pub t: Real,
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
}

/// What a stepper returns for one step.
pub(crate) struct StepOutput {
    /// `u_{k+1}`.
    pub u: State,
    /// Largest contact deformation `δ` seen in the step (`−∞` if the law has none).
    pub penetration: Real,
}

/// The impacts found so far (records and the 1-based count of impacts).
#[derive(Default)]
pub(crate) struct ImpactLog {
    /// Impacting contacts, in time order.
    pub records: Vec<ImpactRecord>,
    /// Number of impacts.
    pub impacts: usize,
}

/// The stepper's counters at the end of a run.
#[derive(Default)]
pub(crate) struct StepperStats {
    pub lcp_solves: usize,
    pub lcp_enumeration_fallbacks: usize,
    pub lcp_failures: usize,
    pub newton_failures: usize,
    pub closure_steps: usize,
    pub time_step_advice: Option<TimeStepAdvice>,
}

/// One step of a contact law's time integrator.
pub(crate) trait Stepper {
    /// Normal force of each joint end in the current state (`None`: impulsive contact).
    fn contact_forces(&self) -> Option<[Real; 2]>;
    /// The contact term `D_contact` of the energy balance so far.
    fn contact_energy(&self) -> Real;
    /// Advances `u_k → u_{k+1}`, logging impacts.
    fn step(&mut self, input: &StepInput, log: &mut ImpactLog) -> StepOutput;
    /// Closes what is still open at the end of the run; returns the counters.
    fn finish(&mut self, log: &mut ImpactLog) -> StepperStats;
}

/// Peaks over time.
struct Peaks {
    close: Real,
    open: Real,
    rot: [Real; 2],
    slip: Real,
    seat: [Real; 4],
    unseat: Option<(Real, usize)>,
    pen: Real,
    abut: [Option<Real>; 2],
    force: Option<Real>,
}

/// What [`Peaks::observe`] measured for the history.
struct Observed {
    end_gaps: [Real; 2],
    slip: Real,
    abut_gaps: [Real; 2],
}

impl Peaks {
    fn new() -> Self {
        Peaks {
            close: Real::NEG_INFINITY,
            open: Real::NEG_INFINITY,
            rot: [0.0; 2],
            slip: 0.0,
            seat: [Real::NEG_INFINITY; 4],
            unseat: None,
            pen: 0.0,
            abut: [None, None],
            force: None,
        }
    }

    /// Monitors the state at `t`.
    fn observe(&mut self, t: Real, q: &State, fr: &Frame, br: &Bridge) -> Observed {
        let (bodies, pose) = (&br.bodies, &fr.pose);
        let end_gaps = fr.sel.map(|s| s.map_or(Real::NAN, |i| fr.cands[i].gap));
        let mut gmin = Real::INFINITY;
        let mut gmax = Real::NEG_INFINITY;
        for g in end_gaps.iter().filter(|g| !g.is_nan()) {
            gmin = gmin.min(*g);
            gmax = gmax.max(*g);
        }
        self.close = self.close.max(br.joint_gap - gmin);
        self.pen = self.pen.max(-gmin);
        self.open = self.open.max(gmax - br.joint_gap);
        for (j, r) in self.rot.iter_mut().enumerate() {
            *r = r.max(q[3 * j + 2].abs());
        }
        let m1 = pose.place(bodies, 0, &bodies[0].face_mid) - bodies[0].face_mid;
        let m2 = pose.place(bodies, 1, &bodies[1].face_mid) - bodies[1].face_mid;
        let slip = (m2.x - m1.x) + 0.0; // `+ 0.0` turns −0 into +0
        self.slip = self.slip.max(slip.abs());
        for (e, s_end) in br.seats.iter().enumerate() {
            let s = s_end
                .corners
                .iter()
                .map(|p| (pose.place(bodies, s_end.body, p) - p).dot(&s_end.inward))
                .fold(Real::NEG_INFINITY, Real::max);
            self.seat[e] = self.seat[e].max(s);
            if self.unseat.is_none() && s > s_end.length {
                self.unseat = Some((t, e));
            }
        }
        let mut abut_gaps = [Real::NAN; 2];
        for a in &br.abutments {
            let j = a.body;
            let gm = bodies[j]
                .far_corners
                .iter()
                .map(|c| (pose.place(bodies, j, c) - a.point).dot(&a.normal))
                .fold(Real::INFINITY, Real::min);
            abut_gaps[j] = gm;
            let pk = self.abut[j].get_or_insert(Real::NEG_INFINITY);
            *pk = pk.max(a.gap - gm);
        }
        Observed {
            end_gaps,
            slip,
            abut_gaps,
        }
    }
}

/// The energy bookkeeping: input work, viscous dissipation, balance.
struct Ledger {
    e0: Real,
    w_in: Real,
    d_visc: Real,
    max_in: Real,
    max_bal: Real,
}

impl Ledger {
    fn new(e0: Real) -> Self {
        Ledger {
            e0,
            w_in: 0.0,
            d_visc: 0.0,
            max_in: e0.abs(),
            max_bal: 0.0,
        }
    }

    /// Energies at one instant; updates the balance monitor.
    fn check(&mut self, tk: Real, vk: Real, d_cont: Real) -> Energy {
        let bal = self.e0 + self.w_in - (tk + vk + self.d_visc + d_cont);
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

    /// Input work and viscous dissipation of step `k`; returns `ū_θ`.
    fn advance(&mut self, sc: &Scheme, k: usize, u: &State, u_new: &State) -> State {
        let th = sc.th;
        let u_th = u * (1.0 - th) + u_new * th;
        let u_mid = (u + u_new) * 0.5;
        let fbar = sc.load(&sc.ag[k]) * (1.0 - th) + sc.load(&sc.ag[k + 1]) * th;
        self.w_in += sc.h * u_mid.dot(&fbar);
        self.d_visc += sc.h * u_th.dot(&(sc.sys.damping * u_th));
        u_th
    }
}

/// Appends the state at `t` to the history.
fn record(
    hist: &mut History,
    t: Real,
    fr: &Frame,
    u: &State,
    obs: &Observed,
    energy: Energy,
    forces: Option<[Real; 2]>,
) {
    hist.t.push(t);
    hist.q.push(fr.qa);
    hist.u.push((*u).into());
    hist.gaps.push(fr.cands.map(|c| c.gap));
    hist.end_gaps.push(obs.end_gaps);
    hist.slip.push(obs.slip);
    hist.energy.push(energy);
    if let Some(f) = forces {
        hist.contact_force.push(f);
    }
    hist.abutment_gaps.push(obs.abut_gaps);
}

/// Runs the time loop with `stepper` (module doc).
pub(crate) fn run<S: Stepper>(
    problem: &SimProblem,
    settings: &SimSettings,
    scheme: Scheme,
    bridge: &Bridge,
    stepper: &mut S,
) -> SimSolution {
    let sc = &scheme;
    let (h, th) = (sc.h, sc.th);
    let mut q = State::from(problem.q0);
    let mut u = State::from(problem.u0);
    let (t0, v0) = sc.energies(&q, &u);
    let mut ledger = Ledger::new(t0 + v0);
    let mut peaks = Peaks::new();
    let mut hist = History::default();
    let mut log = ImpactLog::default();
    let mut status = SimStatus::Completed;
    let mut steps_done = 0usize;
    for k in 0..=sc.n_steps {
        let t = k as Real * h;
        let frame = bridge.frame(&q);
        let obs = peaks.observe(t, &q, &frame, bridge);
        let forces = stepper.contact_forces();
        if let Some(f) = forces {
            let total = f.iter().copied().reduce(|a, b| a + b).unwrap_or(0.0);
            let pk = peaks.force.get_or_insert(0.0);
            *pk = pk.max(total);
        }
        let (tk, vk) = sc.energies(&q, &u);
        let energy = ledger.check(tk, vk, stepper.contact_energy());
        if k % settings.history_stride == 0 || k == sc.n_steps {
            record(&mut hist, t, &frame, &u, &obs, energy, forces);
        }
        if !ledger.finite(&energy) {
            status = SimStatus::Diverged;
            break;
        }
        if k == sc.n_steps {
            break;
        }
        let abar = sc.ag[k] * (1.0 - th) + sc.ag[k + 1] * th;
        let u_free = u + sc.a_u * u + sc.a_q * q + sc.b_g * Vector2::new(abar.x, abar.y);
        let input = StepInput {
            t,
            q: &q,
            u: &u,
            u_free: &u_free,
            frame: &frame,
            bridge,
            scheme: sc,
        };
        let out = stepper.step(&input, &mut log);
        peaks.pen = peaks.pen.max(out.penetration);
        let u_th = ledger.advance(sc, k, &u, &out.u);
        q += u_th * h;
        u = out.u;
        steps_done = k + 1;
        if !(q.iter().all(|x| x.is_finite()) && u.iter().all(|x| x.is_finite())) {
            status = SimStatus::Diverged;
            break;
        }
    }
    let stats = stepper.finish(&mut log);
    if status == SimStatus::Completed && stats.lcp_failures > 0 {
        status = SimStatus::CompletedWithLcpFailures;
    } else if status == SimStatus::Completed && stats.newton_failures > 0 {
        status = SimStatus::CompletedWithNewtonFailures;
    }
    let (tf, vf) = sc.energies(&q, &u);
    let final_energy = ledger.energy(tf, vf, stepper.contact_energy());
    let summary = summarize(&peaks, &ledger, &log, final_energy);
    SimSolution {
        status,
        history: hist,
        impacts: log.records,
        summary,
        steps: steps_done,
        dt: h,
        lcp_solves: stats.lcp_solves,
        lcp_enumeration_fallbacks: stats.lcp_enumeration_fallbacks,
        lcp_failures: stats.lcp_failures,
        frequencies: scheme.sys.frequencies,
        rayleigh: scheme.sys.rayleigh,
        time_step_advice: stats.time_step_advice,
        newton_failures: stats.newton_failures,
        closure_steps: stats.closure_steps,
    }
}

/// The [`SimSummary`] of a run.
fn summarize(peaks: &Peaks, ledger: &Ledger, log: &ImpactLog, final_energy: Energy) -> SimSummary {
    SimSummary {
        impacts: log.impacts,
        impacting_contacts: log.records.len(),
        peak_joint_closing: peaks.close,
        peak_joint_opening: peaks.open,
        peak_rotation: peaks.rot,
        peak_slip: peaks.slip,
        peak_seat_displacement: peaks
            .seat
            .iter()
            .copied()
            .fold(Real::NEG_INFINITY, Real::max),
        peak_seat_by_end: peaks.seat,
        unseated: peaks.unseat.is_some(),
        unseating_time: peaks.unseat.map(|u| u.0),
        unseated_end: peaks.unseat.map(|u| u.1),
        max_penetration: peaks.pen,
        energy_balance_error: balance_error(ledger.max_bal, ledger.max_in),
        final_energy,
        max_input_energy: ledger.max_in,
        peak_contact_force: peaks.force,
        peak_penetration: peaks.pen,
        peak_abutment_closing: peaks.abut,
        abutment_impacting_contacts: log
            .records
            .iter()
            .filter(|r| matches!(r.contact, SimContact::Abutment { .. }))
            .count(),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{
        ComplianceContact, JointContact, SimModel, SimProblem, SimSettings, SimSolution, simulate,
    };
    use crate::contact_law::{ContactLaw, Hertz};
    use crate::ground_motion::el_centro_1940;

    /// The default bridge under El Centro (6 s) with a joint so wide that it never closes.
    fn open_run(law: JointContact, seat_length: f64) -> SimSolution {
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
            assert_eq!(c.summary.peak_contact_force, Some(0.0));
            assert_eq!(r.summary.peak_contact_force, None);
            let mut cs = c.summary.clone();
            cs.peak_contact_force = None;
            assert_eq!(format!("{:?}", r.summary), format!("{cs:?}"));
            assert_eq!(r.summary.unseated, seat < 1.0);
            assert!(r.summary.energy_balance_error < 1e-12);
            let mut ch = c.history.clone();
            assert_eq!(ch.contact_force.len(), ch.t.len());
            assert!(ch.contact_force.iter().all(|f| *f == [0.0, 0.0]));
            ch.contact_force.clear();
            // Debug text compares NaN (no abutment gap) bit for bit, unlike `==`
            let same = format!("{:?}", r.history) == format!("{ch:?}");
            assert!(same, "the histories differ");
            assert!(r.history.t.len() == 6001 && r.summary.peak_joint_opening > 0.0);
        }
    }
}
