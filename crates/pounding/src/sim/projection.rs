//! Position-level projection of the Moreau–Jean scheme (`[time] projection = true`).
//!
//! Moreau–Jean closes the contacts at the *velocity* level: an impact is applied in the step in
//! which the predicted gap `g + h γ_N` closes, and the position `q_{k+1} = q_k + h ū_θ` may end
//! inside the struck body by up to `O(h |γ_N⁻|)`. The combined projection (Acary & Brogliato,
//! *Numerical Methods for Nonsmooth Dynamical Systems*, 2008, §10.4; Acary, "Projected event-capturing
//! time-stepping schemes for nonsmooth mechanical systems with unilateral contact and Coulomb's
//! friction", CMAME 256, 2013) follows each velocity-level step by a correction of the position
//! alone: with the gaps `g(q)` of every rigid-law contact site (joint ends, abutment corners) and
//! their normal directions `w_N,i` (the impact's, `γ_N,i = w_N,iᵀ u`), the correction is the
//! `M`-orthogonal projection of `q_{k+1}` onto the admissible set `{g ≥ 0}` linearised at `q_{k+1}`:
//! ```text
//! Δq = M⁻¹ W_N Δp,   0 ≤ g(q_{k+1}) + G_NN Δp  ⟂  Δp ≥ 0,   G_NN = W_Nᵀ M⁻¹ W_N
//! ```
//! (the KKT conditions of `min ½ Δqᵀ M Δq` subject to `g + W_Nᵀ Δq ≥ 0`). The gaps are nonlinear
//! in `q` (a segment's rotation moves its corners on arcs; a realised candidate can change), so
//! the problem is solved again at `q + Δq`, the contacts of the previous passes kept in the set
//! (their `Δp ≥ 0` may become 0), until every projected gap is `≥ −tol`
//! ([`super::SimSettings::projection_tolerance`], default [`DEFAULT_TOLERANCE`]) or
//! [`MAX_PASSES`] passes are done (then the step counts as a projection failure and the run's
//! status says so). The velocities are not touched; the impacts, the friction and the law checks
//! are those of the velocity-level step.
//!
//! Only the sites of the rigid law are projected: a compliance law's penetration is its
//! deformation (a mixed bridge projects its rigid sites only). A contact with `g < 0` enters the
//! set once some gap is below `−tol` (the others then reach `g ≥ 0` too, to rounding).
//!
//! The energy the correction changes is booked by the driver (`driver.rs`) as the ledger's
//! `projection` term: the work done *on* the structure by the correction, the change of the
//! linear strain energy `½ qᵀ K q` plus the work done on the nonlinear elements over `Δq`.

use super::contact::{Direction, State};
use super::dofs::Dofs;
use super::scheme::Scheme;
use super::view::{Bridge, Frame};
use crate::lcp::{self, LcpStatus, LemkeSettings};
use crate::math::Real;
use nalgebra::{DMatrix, Matrix3};

/// The default tolerance on a projected gap \[m\]: a decade inside the `1e-10` m the projection
/// promises, so that the gaps' rounding never decides it.
pub const DEFAULT_TOLERANCE: Real = 1e-11;

/// Most passes (linearised solves) of one step's projection.
pub const MAX_PASSES: usize = 20;

/// What a run's projection did ([`super::bridge::BridgeSummary::projection`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ProjectionStats {
    /// Steps whose end position was corrected.
    pub corrected_steps: usize,
    /// Largest overlap found before a correction (the velocity-level step's) \[m\].
    pub max_overlap_before: Real,
    /// Largest `|Δq|` of one correction, in the state's units (m, rad).
    pub max_correction: Real,
    /// Most passes one correction needed.
    pub max_passes: usize,
    /// Steps whose correction did not bring every projected gap to `≥ −tol`.
    pub failures: usize,
    /// The tolerance `tol` \[m\].
    pub tolerance: Real,
}

/// The contact sites a projection corrects (the rigid ones).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sites {
    /// Per joint.
    pub joints: Vec<bool>,
    /// Per abutment side.
    pub abutments: [bool; 2],
}

impl Sites {
    /// No site (a bridge without rigid sites).
    pub fn none(joints: usize) -> Self {
        Self {
            joints: vec![false; joints],
            abutments: [false; 2],
        }
    }
}

/// `M⁻¹`: one `3 × 3` block per segment, or dense (a coupled system); `Singular` when `M` has
/// no inverse (no correction is then possible: every step that needs one is a failure).
enum MassInverse {
    Blocks(Vec<Matrix3<Real>>),
    Dense(DMatrix<Real>),
    Singular,
}

/// Which contact a constraint is: `(0, joint, candidate)` or `(1, side, corner)`.
type Key = (u8, usize, usize);

/// One projected contact at the current state: its gap and normal direction.
struct Constraint {
    key: Key,
    gap: Real,
    dir: Direction,
}

/// The projection of a run (module doc).
pub(crate) struct Projector {
    sites: Sites,
    minv: MassInverse,
    lemke: LemkeSettings,
    /// What it did.
    pub stats: ProjectionStats,
}

impl Projector {
    /// The projection of the sites `sites` with the scheme's mass matrix.
    pub fn new(sc: &Scheme, sites: Sites, tolerance: Real, lemke: &LemkeSettings) -> Self {
        let minv = match &sc.dense {
            Some(d) => d.sys.m.clone().lu().try_inverse().map(MassInverse::Dense),
            None => sc
                .bodies
                .iter()
                .map(|b| b.mass.try_inverse())
                .collect::<Option<_>>()
                .map(MassInverse::Blocks),
        };
        Self {
            minv: minv.unwrap_or(MassInverse::Singular),
            sites,
            lemke: lemke.clone(),
            stats: ProjectionStats {
                tolerance,
                ..ProjectionStats::default()
            },
        }
    }

    /// `M⁻¹ v` (`None`: `M` is singular).
    fn minv(&self, dofs: &Dofs, v: &State) -> Option<State> {
        match &self.minv {
            MassInverse::Blocks(b) => Some(Scheme::apply(dofs, b, v)),
            MassInverse::Dense(m) => Some(m * v),
            MassInverse::Singular => None,
        }
    }

    /// Every projected contact at the state of `frame` (`q` its coordinates).
    fn constraints(&self, q: &State, frame: &Frame, br: &Bridge) -> Vec<Constraint> {
        let mut out = Vec::new();
        for (k, (jg, jf)) in br.joints.iter().zip(&frame.joints).enumerate() {
            if !self.sites.joints.get(k).copied().unwrap_or(true) {
                continue;
            }
            for &s in jf.sel.iter().flatten() {
                let c = &jf.cands[s];
                out.push(Constraint {
                    key: (0, k, s),
                    gap: c.gap,
                    dir: c.direction(&frame.pose, jg, c.normal),
                });
            }
        }
        for ab in br.abutments.iter().filter(|a| self.sites.abutments[a.side]) {
            let shift = ab.shift_on(&br.dofs, q.as_slice(), &frame.ground);
            for (i, c0) in ab.corners.iter().enumerate() {
                let pc = frame.pose.place(&br.bodies, ab.body, c0);
                out.push(Constraint {
                    key: (1, ab.side, i),
                    gap: (pc - ab.point).dot(&ab.normal) + shift,
                    dir: ab.direction(ab.normal, &(pc - frame.pose.g[ab.body])),
                });
            }
        }
        out
    }

    /// The largest overlap `max(0, −g)` of the projected contacts at the state of `frame` (`q`
    /// its coordinates), allocating nothing: the test of every step.
    fn overlap(&self, q: &State, frame: &Frame, br: &Bridge) -> Real {
        let mut worst: Real = 0.0;
        for (k, jf) in frame.joints.iter().enumerate() {
            if self.sites.joints.get(k).copied().unwrap_or(true) {
                for &s in jf.sel.iter().flatten() {
                    worst = worst.max(-jf.cands[s].gap);
                }
            }
        }
        for ab in br.abutments.iter().filter(|a| self.sites.abutments[a.side]) {
            let shift = ab.shift_on(&br.dofs, q.as_slice(), &frame.ground);
            for c0 in &ab.corners {
                let pc = frame.pose.place(&br.bodies, ab.body, c0);
                worst = worst.max(-((pc - ab.point).dot(&ab.normal) + shift));
            }
        }
        worst
    }

    /// Projects `q` (module doc), updating `frame` to it; returns the correction `Δq` if there
    /// was one.
    pub fn project(&mut self, q: &mut State, frame: &mut Frame, br: &Bridge) -> Option<State> {
        let tol = self.stats.tolerance;
        if self.overlap(q, frame, br) <= tol {
            return None;
        }
        let mut q0 = None;
        let mut set: Vec<Key> = Vec::new();
        for pass in 0..=MAX_PASSES {
            let all = self.constraints(q, frame, br);
            let worst = all.iter().fold(0.0, |m: Real, c| m.max(-c.gap));
            if pass == 0 {
                if worst <= tol {
                    return None;
                }
                q0 = Some(q.clone());
                self.stats.corrected_steps += 1;
                self.stats.max_overlap_before = self.stats.max_overlap_before.max(worst);
            }
            if worst <= tol || pass == MAX_PASSES {
                if worst > tol {
                    self.stats.failures += 1;
                }
                self.stats.max_passes = self.stats.max_passes.max(pass);
                break;
            }
            for c in all.iter().filter(|c| c.gap < 0.0) {
                if !set.contains(&c.key) {
                    set.push(c.key);
                }
            }
            let act: Vec<&Constraint> = all.iter().filter(|c| set.contains(&c.key)).collect();
            let Some(dq) = self.correction(&act, &br.dofs) else {
                self.stats.failures += 1;
                self.stats.max_passes = self.stats.max_passes.max(pass + 1);
                break;
            };
            *q += dq;
            br.update_frame(q, frame);
        }
        let dq = &*q - q0.as_ref().expect("set in the first pass");
        self.stats.max_correction = self.stats.max_correction.max(dq.amax());
        Some(dq)
    }

    /// `Δq = M⁻¹ W_N Δp` of the linearised problem over the contacts `act`; `None` if its LCP
    /// has no solution to the solvers.
    fn correction(&self, act: &[&Constraint], dofs: &Dofs) -> Option<State> {
        let n = act.len();
        let w: Vec<State> = act.iter().map(|c| c.dir.dense(dofs)).collect();
        let mw: Vec<State> = w
            .iter()
            .map(|w| self.minv(dofs, w))
            .collect::<Option<_>>()?;
        // G scaled by its largest diagonal entry (the LCP solvers' tolerances are absolute)
        let mut g = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                g[i * n + j] = w[i].dot(&mw[j]);
            }
        }
        let d = (0..n).map(|i| g[i * n + i]).fold(0.0, Real::max);
        if !(d > 0.0 && d.is_finite()) {
            return None;
        }
        g.iter_mut().for_each(|x| *x /= d);
        let b: Vec<Real> = act.iter().map(|c| c.gap).collect();
        let p = solve(&g, &b, &self.lemke)?;
        let mut dq = State::zeros(dofs.len());
        for (mw, p) in mw.iter().zip(&p) {
            if *p != 0.0 {
                dq.axpy(*p / d, mw, 1.0);
            }
        }
        Some(dq)
    }
}

/// The LCP `0 ≤ G p + b ⟂ p ≥ 0` (`G` row-major, symmetric positive semidefinite): Lemke, then a
/// projected Gauss–Seidel for the degenerate sets Lemke refuses (more contacts than a segment
/// has coordinates: four abutment corners of one segment); `None` if neither converges.
fn solve(g: &[Real], b: &[Real], lemke: &LemkeSettings) -> Option<Vec<Real>> {
    let n = b.len();
    if let Ok(p) = lcp::LcpProblem::new(g.to_vec(), b.to_vec()) {
        let s = lcp::Lemke::new(lemke.clone()).solve(&p);
        if s.status == LcpStatus::Solved {
            return Some(s.z);
        }
    }
    let scale = b.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
    let mut p = vec![0.0; n];
    for _ in 0..10_000 {
        let mut change: Real = 0.0;
        for i in 0..n {
            let r: Real = b[i] + (0..n).map(|j| g[i * n + j] * p[j]).sum::<Real>();
            let new = (p[i] - r / g[i * n + i]).max(0.0);
            change = change.max((new - p[i]).abs());
            p[i] = new;
        }
        if change <= 1e-14 * scale {
            return Some(p);
        }
    }
    None
}

/// Books the correction `Δq` that moved the state to `q` (`frame` its geometry) and returns the
/// work it did on the structure ([`super::Energy::projection`]): the change of the strain energy
/// `½ qᵀ K q` of the balance (`yield_body`: the segments left out of it) plus the work done on the
/// nonlinear elements, which it also books in their own terms.
///
/// The elements take the correction as a kinematic increment of their own: committed at the
/// step's end `q − Δq`, their return mappings run from there to `q` and commit (a bearing at its
/// yield surface can flow over the correction, as over any displacement), and their work is the
/// trapezoidal `Δq·R̄` of a step with `h ū = Δq` ([`super::elements::Elements::book`]), so the
/// balance keeps closing to rounding.
#[allow(clippy::too_many_arguments)]
pub(crate) fn book(
    sc: &Scheme,
    (q, dq): (&State, &State),
    frame: &Frame,
    br: &Bridge,
    el: &mut super::elements::Elements,
    force: &mut super::elements::StepForce,
    work: &mut super::scheme::Work,
    yield_body: &[bool],
) -> Real {
    let q0 = q - dq;
    let v0 = sc.energies(&q0, q, work, yield_body).1;
    let v1 = sc.energies(q, q, work, yield_body).1;
    let mut w = v1 - v0;
    if !el.is_empty() {
        let total = |el: &super::elements::Elements| {
            el.w_bearings.iter().sum::<Real>() + el.w_cables + el.w_backfill + el.w_keys
        };
        let before = total(el);
        let mut pose0 = frame.pose.clone();
        pose0.set(&br.bodies, &br.dofs, q0.as_slice());
        el.step_force(&q0, dq, 1.0, 0.5, &br.bodies, &pose0, force);
        for i in 0..q.len() {
            work.q_th[i] = q0[i] + 0.5 * dq[i];
        }
        sc.yield_stiffness_into(&work.q_th, &mut work.kq_th);
        el.book(
            1.0,
            dq,
            (&work.kq_th, yield_body),
            force,
            sc.dofs.n_bodies(),
        );
        el.commit(q, &frame.pose, &br.bodies);
        w += total(el) - before;
    }
    w
}
