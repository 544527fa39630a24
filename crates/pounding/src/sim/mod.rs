//! Seismic time-history simulation of bridges of rigid deck segments with pounding.
//!
//! # Model
//! A bridge ([`bridge::BridgeModel`]) is a chain of rigid deck segments (straight, skewed or
//! curved plan shapes of [`crate::shape`]), each with 3 in-plane DOF `(x, y, θ)` (centroid
//! displacements from the reference pose, rotation about the centroid), meeting at joints, with
//! optional abutments at the two ends; substructure bodies with other DOF counts (pier caps,
//! backwalls) join it through one DOF map ([`dofs::Dofs`]). The two-deck model of the original
//! study is a preset that expands into the bridge of two segments ([`SimModel`],
//! [`bridge::BridgeModel::from_pair`]).
//!
//! * **Links** between two attachments, each a body point or a support (`support.rs`): bearings
//!   (linear or yielding, with linearised kinematics `u_p = u_G + θ ẑ × r_p`), dashpots,
//!   restrainers, pier columns, backfill, piles, shear keys ([`crate::element`]).
//! * **Damping**: Rayleigh per segment (or of the whole coupled system), or dashpots.
//! * **Ground motion** ([`crate::ground_motion::GroundMotion`]): effective load `F(t) = −M r a_g(t)`;
//!   displacements are relative to a reference motion, and supports may move apart from it
//!   ([`excitation`]).
//! * **Contact sites**: each joint (the corners of each end face against the other face, gaps
//!   from the current pose with exact rotations, [`contact`]) and each abutment, each with its own
//!   law: the rigid Newton–Coulomb impact law (an LCP over every active contact) or a compliance
//!   law of [`crate::contact_law`]; rigid and compliance sites mix in one bridge.
//!
//! # Scheme: Moreau–Jean time stepping (θ-method + velocity-level LCP)
//! With step `h`, `t_k = k h`, and `θ = ½` by default:
//! ```text
//! q_{k+1} = q_k + h ((1−θ) u_k + θ u_{k+1})
//! M (u_{k+1} − u_k) = h ((1−θ) f_k + θ f_{k+1}) + Σ_i (w_N,i P_N,i + w_T,i P_T,i)
//! f = −K q − C u + F(t)
//! ```
//! Eliminating `q_{k+1}`: `Ŵ = M + hθC + h²θ²K`, the free velocity
//! `u_free = u_k + Ŵ⁻¹ h (−C u_k − K (q_k + hθ u_k) + (1−θ)F_k + θF_{k+1})` and
//! `u_{k+1} = u_free + Ŵ⁻¹ W P`. The force directions `W = [w_N, w_T]` are evaluated at `q_k`.
//! Contact `i` is *active* if its corner lies over the other face and its predicted gap
//! `g_i(q_k) + h γ_N,i(u_k) ≤ 0`. For the active set the impulses `P` solve the impact LCP of [`crate::impact`] with
//! the Delassus matrix `G = Wᵀ Ŵ⁻¹ W`, `γ⁻ := Wᵀ u_k` in the Newton law and `γ_free := Wᵀ u_free`:
//! ```text
//! b = ( γ_N,free + ε min(γ_N⁻, 0) ,  γ_T,free ,  0 )
//! ξ_N = γ_N,{k+1} + ε min(γ_N⁻, 0) ≥ 0 ⊥ P_N ≥ 0,   Coulomb (ε_T = 0) on γ_T,{k+1}
//! ```
//! (Restitution acts only on an approaching contact; an active but receding contact — possible
//! after a small overlap — must merely not start approaching, as in [`crate::impact`].)
//! For an isolated impact (`h → 0`, `γ_free → γ⁻`, `Ŵ → M`) this is exactly the single-impact LCP
//! of [`crate::impact`]. The smooth part is the trapezoidal rule (θ = ½): second order, A-stable, no numerical
//! damping; with impacts the scheme is first order in the event time.
//!
//! # Energy
//! `T = ½ uᵀ M u`, `V = ½ qᵀ K q`; per step `W_in += h ū·F̄`, `D_viscous += h ū_θᵀ C ū_θ`,
//! `D_contact −= ½ (u_k + u_{k+1})ᵀ W P` (spec §11: `ΔT = ½ (γ⁺ + γ⁻)ᵀ Λ` at an impact; may be
//! negative), with `ū = (u_k + u_{k+1})/2`, `ū_θ = (1−θ) u_k + θ u_{k+1}`, `F̄ = (1−θ)F_k + θF_{k+1}`.
//! For `θ = ½` the discrete balance `E_0 + W_in = T + V + D_viscous + D_contact` holds to rounding,
//! so [`bridge::BridgeSummary::energy_balance_error`] checks the implementation's bookkeeping (a sign or
//! scaling slip shows at O(1)); for `θ > ½` it measures the scheme's numerical dissipation.
//!
//! # Code layout
//! [`simulate`] checks a [`Problem`] and hands the whole run to an integrator
//! (`integrate.rs`: the `Integrator` trait, Moreau–Jean today). Its loop (`driver.rs`:
//! energy bookkeeping, divergence, history; monitors in `peaks.rs`) calls one stepper per step —
//! `rigid/` (the scheme above), [`compliance`] (trapezoid + Newton over the contact sites) or
//! `mixed.rs` (both) — and hands each kept step to the observers (`observer/`), whose typed
//! tables ([`table::Table`]) the front ends write. A new output is an observer; a new integrator
//! implements the trait; `docs/architecture.md` lists the files each addition touches.

pub mod accuracy;
pub mod batch;
pub mod batch_supports;
pub mod bridge;
pub mod compare;
pub mod compliance;
pub mod contact;
mod coupled;
pub mod defaults;
pub mod dofs;
mod driver;
mod elements;
pub mod excitation;
pub(crate) mod integrate;
mod line_search;
mod mixed;
pub mod model;
mod observer;
pub mod options;
pub mod output;
mod pair_errors;
pub mod param;
mod peaks;
pub mod problem;
pub mod projection;
mod rigid;
pub mod scenario;
mod scheme;
mod settings;
mod solution;
mod step_loads;
mod support;
pub mod table;
mod two_deck;
mod view;
mod yielding;
mod yielding_dense;

use crate::analytic::SlipMode;
use crate::geometry::GeometryError;
use crate::ground_motion::GroundMotionError;
use crate::math::Real;
use thiserror::Error;

pub use model::Bearing;
pub use options::{ComplianceContact, DampingModel, JointContact};
pub use problem::{Problem, simulate};
pub use scheme::BodySystem;
pub use settings::{MAX_STEPS, PROGRESS_EVERY, Progress, SimSettings};
pub use two_deck::{
    SimAbutment, SimContact, SimModel, SimProblem, end_corner_points, shape_corner_points,
};

/// Bad simulation input (numerical trouble is reported in [`SimStatus`] instead).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SimError {
    /// A parameter is out of range or not finite; the message names it.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// Parameter name as the user knows it (the text of `path`).
        name: String,
        /// The parameter, typed ([`param::ParamPath`]): what a front end maps to its key.
        path: param::ParamPath,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
    /// A non-numeric argument is malformed (e.g. `--shard K/N`); the message names it.
    #[error("invalid {name}: {reason}")]
    InvalidArgument {
        /// Argument name as the user knows it (the text of `path`).
        name: String,
        /// The argument, typed ([`param::ParamPath`]).
        path: param::ParamPath,
        /// What is wrong and what was expected.
        reason: String,
    },
    /// Bad ground-motion input.
    #[error(transparent)]
    GroundMotion(#[from] GroundMotionError),
    /// Invalid deck geometry (names `R1`, `beta2`, ...).
    #[error(transparent)]
    Geometry(#[from] GeometryError),
}

impl SimError {
    /// An invalid parameter `path` of value `value`.
    pub(crate) fn invalid(path: impl Into<param::ParamPath>, value: Real, reason: &str) -> Self {
        let path = path.into();
        Self::InvalidParameter {
            name: path.to_string(),
            path,
            value,
            reason: reason.to_string(),
        }
    }

    /// A malformed argument `path`.
    pub(crate) fn argument(path: impl Into<param::ParamPath>, reason: impl Into<String>) -> Self {
        let path = path.into();
        Self::InvalidArgument {
            name: path.to_string(),
            path,
            reason: reason.into(),
        }
    }

    /// The parameter the error concerns, if it is one of [`SimError::InvalidParameter`] or
    /// [`SimError::InvalidArgument`].
    pub fn path(&self) -> Option<&param::ParamPath> {
        match self {
            Self::InvalidParameter { path, .. } | Self::InvalidArgument { path, .. } => Some(path),
            _ => None,
        }
    }
}

/// The reason an input check gives for a value that is not finite (NaN, ±inf): the check's own
/// `reason` (`must be >= 0`, `must lie in [0, 1]`) made to say so first (`must be finite and >=
/// 0`); a reason that already says it is kept.
pub(crate) fn finite_reason(reason: &str) -> String {
    if reason.contains("finite") {
        reason.to_string()
    } else if let Some(rest) = reason.strip_prefix("must be ") {
        format!("must be finite and {rest}")
    } else if let Some(rest) = reason.strip_prefix("must ") {
        format!("must be finite and {rest}")
    } else {
        format!("must be finite ({reason})")
    }
}

/// One impacting contact in one impact step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactRecord {
    /// 1-based number of the impact (step) this contact belongs to.
    pub impact: usize,
    /// End time `t_{k+1}` of the step \[s\].
    pub time: Real,
    /// The contact (striking corner at the joint, or a far-face corner at an abutment).
    pub contact: SimContact,
    /// Where: the joint index `k` (0-based, between segments `k` and `k + 1`) of a
    /// [`SimContact::Joint`], the abutment side (0 start, 1 end) of a [`SimContact::Abutment`].
    pub site: usize,
    /// Tangential outcome (spec §10, `|γ_T⁺| ≤ 1e-9 |γ_N⁻|` is stick).
    pub mode: SlipMode,
    /// Pre-impact normal velocity `γ_N⁻ = w_Nᵀ u_k` (< 0, closing) \[m/s\].
    pub gamma_n_pre: Real,
    /// Pre-impact tangential velocity `γ_T⁻` (+ along τ: deck 1 relative to deck 2 toward deck 1's
    /// radially outward side; at an abutment: the corner along `t = perp(n)`, from `c0` toward
    /// `c1` of the deck's far face) \[m/s\].
    pub gamma_t_pre: Real,
    /// Post-step normal velocity `γ_N,{k+1}` \[m/s\].
    pub gamma_n_post: Real,
    /// Post-step tangential velocity `γ_T,{k+1}` \[m/s\].
    pub gamma_t_post: Real,
    /// Normal impulse `P_N ≥ 0` (pushes the decks apart) \[N s\].
    pub impulse_n: Real,
    /// Tangential impulse `P_T` (on deck 1 along +τ, on deck 2 along −τ) \[N s\].
    pub impulse_t: Real,
    /// Energy dissipated at this contact, `−½ (γ_k + γ_{k+1})·P` \[J\] (negative = gained, spec §11).
    pub energy_dissipated: Real,
    /// Compliance laws: the force pulse of this contact during the impact; `None` for the rigid
    /// law (impulses, no force: see [`crate::contact_law::estimate`] for its estimate).
    pub pulse: Option<ImpactPulse>,
}

/// The normal-force pulse of one contact during one compliance-law impact (an interval of
/// positive force at that contact, [`compliance`] module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactPulse {
    /// Largest normal force of this contact over the steps of the impact \[N\].
    pub peak_force: Real,
    /// Duration of positive force \[s\]: from the zero crossing of the penetration `δ` at onset
    /// to the zero crossing of `δ` at separation, both linearly interpolated within their step
    /// (`O(h²)` for a law whose force vanishes with `δ`); where the force ends with `δ > 0` (a
    /// dashpot pulling the decks apart) the end is the end of the step in which it vanished
    /// (within one step). NaN for an impact still in progress at the end of the run.
    pub duration: Real,
    /// Largest penetration `δ` of this contact over the steps of the impact \[m\].
    pub max_penetration: Real,
}

/// Energies at one instant \[J\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Energy {
    /// Work of the effective seismic load since t = 0.
    pub input: Real,
    /// Kinetic energy `½ uᵀ M u` (relative to the ground).
    pub kinetic: Real,
    /// Bearing strain energy `½ qᵀ K q`.
    pub potential: Real,
    /// Energy dissipated by Rayleigh damping since t = 0.
    pub viscous: Real,
    /// Energy dissipated by the contacts since t = 0 (may decrease, spec §11).
    pub contact: Real,
    /// Work done on the nonlinear elements of a bridge (yielding bearings beyond `½ qᵀ K q`,
    /// restrainers) since t = 0 (`sim::bridge`; 0 without any).
    pub elements: Real,
    /// Work done on the structure by the position projection since t = 0
    /// ([`projection`]; 0 without it): the change of `½ qᵀ K q` plus the work done on the
    /// nonlinear elements over the corrections `Δq`. The balance reads
    /// `E_0 + W_in + W_proj = T + V + D_viscous + D_contact + W_elements`.
    pub projection: Real,
}

/// The two-deck names of the four seated ends ([`output::pair_seat_name`]).
pub const SEAT_ENDS: [&str; 4] = ["deck1-joint", "deck1-far", "deck2-joint", "deck2-far"];

/// How the run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimStatus {
    /// All steps done, every contact LCP solved.
    Completed,
    /// All steps done, but some contact LCPs were not solved by Lemke nor by enumeration (in those
    /// steps the frictionless LCP was used), or a solution failed the post-solve checks of the
    /// impact laws on the recovered velocities (see [`bridge::BridgeSolution::lcp_failures`]),
    /// or a step's position projection left a gap below its tolerance
    /// ([`projection::ProjectionStats::failures`]).
    CompletedWithLcpFailures,
    /// The state or an energy of the bookkeeping became non-finite; the run stopped.
    Diverged,
    /// All steps done with a compliance law, but the Newton iteration on the contact forces
    /// did not converge in some steps (see [`bridge::BridgeSolution::newton_failures`]).
    CompletedWithNewtonFailures,
    /// All steps done, but the discrete energy balance (exact to rounding for θ = ½) is off by
    /// more than 1e-6 of the input energy: some force was not resolved consistently (e.g. an
    /// element or contact too stiff for the step); see [`bridge::BridgeSummary::energy_balance_error`].
    CompletedWithEnergyError,
}

/// `a.max(b)` that propagates NaN (`f64::max` drops it, which once made a NaN energy balance
/// read as 0).
#[inline]
pub(crate) fn max_nan(a: Real, b: Real) -> Real {
    if a.is_nan() || b.is_nan() {
        Real::NAN
    } else {
        a.max(b)
    }
}

/// [`bridge::BridgeSummary::energy_balance_error`] from `max |balance|` and `max |E_0 + W_in|`: NaN when
/// either is NaN (never 0), `0` only for an exact balance of a run without energy.
pub(crate) fn balance_error(max_bal: Real, max_in: Real) -> Real {
    if max_bal.is_nan() || max_in.is_nan() {
        Real::NAN
    } else if max_in > 0.0 {
        max_bal / max_in
    } else if max_bal == 0.0 {
        0.0
    } else {
        Real::INFINITY
    }
}

/// All energies of the bookkeeping finite (a run whose energies overflow has diverged even when
/// the state itself is still finite, e.g. under a ground motion of 1e300 g).
#[inline]
pub(crate) fn energies_finite(e: &[Real]) -> bool {
    e.iter().all(|x| x.is_finite())
}

/// The time `t_k = k·dt` of step `k` as the decimal the user expects: for a step with a short
/// decimal form (`1e-3`, `2.5e-4`, `0.005`) the double nearest the exact decimal `k·dt`
/// (`0.009`, not `9 × 0.001 = 0.009000000000000001`), else `k·dt` as computed. Every time a run
/// reports (history `t_s`, impact times, the simulated duration) is on this grid.
pub fn step_time(k: usize, dt: Real) -> Real {
    driver::TimeGrid::new(dt).time(k)
}

/// The time `k·dt` as the solver computed it (the ground motion it used at step `k` was sampled
/// there), for a reported step time `t` ([`step_time`]): `history.csv`'s `ag_*` columns are the
/// accelerations the run used, not a re-interpolation at the rounded time.
pub(crate) fn solver_time(t: Real, dt: Real) -> Real {
    (t / dt).round() * dt
}
