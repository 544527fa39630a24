//! Seismic time-history simulation of two decks with rigid-impact pounding.
//!
//! # Model
//! Two rigid decks (by default annular sectors in the S arrangement, spec §2–§4; or straight /
//! skewed decks of [`crate::shape`] meeting face to face, see [`SimModel::shapes`]), optionally
//! with rigid abutments beyond their far ends ([`SimAbutment`]), 3 in-plane DOF each,
//! `q = (x1, y1, θ1, x2, y2, θ2)` (spec §5.1: centroid displacements from the reference pose with
//! `M_1 = (0, g)`, `M_2 = (0, 0)`, rotations about the centroids), `M = diag(m1, m1, I1, m2, m2, I2)`.
//!
//! * **Bearings** ([`Bearing`]): linear springs of equal stiffness in x and y at body points, with
//!   linearised kinematics `u_p = u_G + θ ẑ × r_p`; default: the two corners of each end face.
//! * **Damping**: Rayleigh per deck, `C_j = a_0 M_j + a_1 K_j`, ratio `ζ` at that deck's two lowest
//!   distinct natural frequencies ([`model::rayleigh_coefficients`]).
//! * **Ground motion** ([`GroundMotion`]): effective load `F(t) = −M r a_g(t)` with `r` mapping the
//!   ground acceleration onto both decks' centroid translations (no rotational component).
//!   All displacements are relative to the ground.
//! * **Contacts**: each corner of each deck's joint face against the other deck's face, gaps from
//!   the current pose with exact rotations ([`contact`] module doc); each far-face corner of a
//!   deck with an abutment against the abutment face (body b = the ground, [`SimAbutment`]);
//!   Newton impact law with Coulomb friction in the LCP form of spec §8, the same `ε_N`, `μ` at
//!   every contact. At most 6 contacts (LCP size ≤ 18) are active at once.
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
//! `g_i(q_k) + h γ_N,i(u_k) ≤ 0`. For the active set the impulses `P` solve the LCP of spec §8 with
//! the Delassus matrix `G = Wᵀ Ŵ⁻¹ W`, `γ⁻ := Wᵀ u_k` in the Newton law and `γ_free := Wᵀ u_free`:
//! ```text
//! b = ( γ_N,free + ε min(γ_N⁻, 0) ,  γ_T,free ,  0 )
//! ξ_N = γ_N,{k+1} + ε min(γ_N⁻, 0) ≥ 0 ⊥ P_N ≥ 0,   Coulomb (ε_T = 0) on γ_T,{k+1}
//! ```
//! (Restitution acts only on an approaching contact; an active but receding contact — possible
//! after a small overlap — must merely not start approaching, as in [`crate::impact`].)
//! For an isolated impact (`h → 0`, `γ_free → γ⁻`, `Ŵ → M`) this is exactly the single-impact LCP
//! of spec §8. The smooth part is the trapezoidal rule (θ = ½): second order, A-stable, no numerical
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
//! [`simulate`] validates, builds the time grid and iteration matrices and hands the loop to the
//! time-stepping driver (`driver.rs`: monitors, energy bookkeeping, history, summary), which
//! calls one stepper per step: `rigid.rs` (the scheme above) or [`compliance`] (a compliance
//! contact law with Newton). A new integrator or contact treatment is a new stepper; a new
//! monitored quantity goes into the driver and is then reported for every law.

pub mod accuracy;
pub mod batch;
pub mod bridge;
pub mod compare;
pub mod compliance;
pub mod contact;
mod coupled;
pub mod dofs;
mod driver;
mod elements;
pub mod excitation;
pub(crate) mod integrate;
mod mixed;
pub mod model;
mod observer;
pub mod options;
pub mod output;
mod peaks;
pub mod problem;
mod rigid;
pub mod scenario;
mod scheme;
mod solution;
mod support;
pub mod table;
mod view;
mod yielding;
mod yielding_dense;

use crate::analytic::SlipMode;
use crate::geometry::{ContactCase, GeometryError};
use crate::ground_motion::{GroundMotion, GroundMotionError};
use crate::lcp::LemkeSettings;
use crate::math::{Real, Vector};
use crate::pair::SArrangement;
use crate::shape::DeckShape;
use model::{DeckBody, LinearSystem};
use nalgebra::{Matrix3, Matrix6};
use thiserror::Error;

pub use model::Bearing;
pub use options::{ComplianceContact, DampingModel, JointContact};
pub use problem::{Problem, simulate};

/// Bad simulation input (numerical trouble is reported in [`SimStatus`] instead).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SimError {
    /// A parameter is out of range or not finite; the message names it.
    #[error("invalid {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// Parameter name as the user knows it.
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
    /// A non-numeric argument is malformed (e.g. `--shard K/N`); the message names it.
    #[error("invalid {name}: {reason}")]
    InvalidArgument {
        /// Argument name as the user knows it.
        name: String,
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
    pub(crate) fn invalid(name: impl Into<String>, value: Real, reason: &str) -> Self {
        Self::InvalidParameter {
            name: name.into(),
            value,
            reason: reason.to_string(),
        }
    }
}

/// The structural model: decks, joint, bearings, damping, contact law, seats.
#[derive(Debug, Clone, PartialEq)]
pub struct SimModel {
    /// The two decks (spec §4); both must have the same width.
    pub arrangement: SArrangement,
    /// Joint opening `g ≥ 0` in the reference pose (`M_1 = (0, g)`) \[m\].
    pub gap: Real,
    /// Bearings of deck 1 (points relative to `M_1`, reference pose).
    pub bearings1: Vec<Bearing>,
    /// Bearings of deck 2 (points relative to `M_2`, reference pose).
    pub bearings2: Vec<Bearing>,
    /// Rayleigh damping ratio `ζ ∈ [0, 1)` at each deck's two lowest distinct frequencies.
    pub damping_ratio: Real,
    /// Coulomb friction coefficient `μ ≥ 0` at the joint.
    pub friction: Real,
    /// Newton restitution coefficient `ε_N ∈ [0, 1]`.
    pub restitution: Real,
    /// Seat length `> 0` \[m\]: an end whose seat displacement exceeds it is unseated.
    pub seat_length: Real,
    /// Normal contact law of the joint (default: rigid, the LCP impact law).
    pub contact: JointContact,
    /// Damping model (default: Rayleigh with [`SimModel::damping_ratio`]).
    pub damping_model: DampingModel,
    /// Deck shapes `[deck 1, deck 2]` in the frames of [`crate::shape`] (deck 1 = body frame
    /// moved by `(0, g)`, deck 2 = body frame turned by π); `None` = the curved decks of
    /// `arrangement` (which is then the only geometry used). When set, `arrangement` is ignored;
    /// both joint faces must have the same length so that the decks meet face to face.
    pub shapes: Option<[DeckShape; 2]>,
    /// Optional rigid abutment beyond the far end of deck 1 / deck 2.
    pub abutments: [Option<SimAbutment>; 2],
}

/// A rigid abutment (the ground) beyond the far end face of a deck.
///
/// Its face is the line parallel to the deck's far end face in the reference pose, at distance
/// `gap` along that face's outward normal `n_out`. Each corner `c_k` of the far face is a contact
/// (body a = the deck, body b = the ground) with normal `n = −n_out` (into the deck), tangent
/// `t = perp(n) = (−n_y, n_x)` and signed gap `g_k = (P_k − A)·n`, `A` = far-face midpoint `+ gap
/// n_out` (reference pose), `P_k` the corner in the current pose; the same impact law
/// (ε_N, μ) as the joint. The abutment face is taken long enough for both corners.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimAbutment {
    /// Gap `≥ 0` between the far end face and the abutment face \[m\].
    pub gap: Real,
    /// Seat length `> 0` of that deck end on the abutment \[m\] (replaces
    /// [`SimModel::seat_length`] for the far end of this deck).
    pub seat_length: Real,
}

/// A contact of the simulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimContact {
    /// Corner of one deck's joint face against the other deck's joint face (spec §5.3).
    Joint(ContactCase),
    /// Far-face corner `corner ∈ {0, 1}` (the shape's `c0`, `c1`) of deck `deck ∈ {1, 2}` against
    /// its abutment.
    Abutment {
        /// 1 or 2.
        deck: usize,
        /// 0 or 1.
        corner: usize,
    },
}

impl SimContact {
    /// Output name: `deck1-inner`, … (joint, [`ContactCase::name`]) or `abutment1-c0`, ….
    pub fn name(&self) -> &'static str {
        match self {
            Self::Joint(c) => c.name(),
            Self::Abutment { deck, corner } => match (deck, corner) {
                (1, 0) => "abutment1-c0",
                (1, _) => "abutment1-c1",
                (_, 0) => "abutment2-c0",
                _ => "abutment2-c1",
            },
        }
    }
}

impl PartialEq<ContactCase> for SimContact {
    fn eq(&self, other: &ContactCase) -> bool {
        *self == SimContact::Joint(*other)
    }
}

/// The four corners of a deck's two end faces, relative to its face midpoint `M_j`, reference
/// pose (spec §4): joint face `(±W/2, 0)`, far face at the angle `β`.
pub fn end_corner_points(arrangement: &SArrangement, deck: usize) -> [Vector; 4] {
    let d = if deck == 1 {
        &arrangement.deck1
    } else {
        &arrangement.deck2
    };
    let body = DeckBody::new(d, deck, 0.0);
    [
        body.joint_corners[0] - body.face_mid,
        body.joint_corners[1] - body.face_mid,
        body.far_corners[0] - body.face_mid,
        body.far_corners[1] - body.face_mid,
    ]
}

/// The four end-face corners of a deck of any shape relative to its joint-face midpoint `M_j`,
/// reference pose, global orientation (deck 2 turned by π): `[joint c0, joint c1, far c0, far c1]`.
pub fn shape_corner_points(shape: &DeckShape, deck: usize) -> [Vector; 4] {
    let body = DeckBody::from_shape(shape, deck, 0.0);
    [
        body.joint_corners[0] - body.face_mid,
        body.joint_corners[1] - body.face_mid,
        body.far_corners[0] - body.face_mid,
        body.far_corners[1] - body.face_mid,
    ]
}

impl SimModel {
    /// A model with the default bearing layout: one bearing of stiffness `k1` (deck 1) / `k2`
    /// (deck 2) at each of the four end-face corners of each deck.
    #[allow(clippy::too_many_arguments)]
    pub fn with_corner_bearings(
        arrangement: SArrangement,
        gap: Real,
        k1: Real,
        k2: Real,
        damping_ratio: Real,
        friction: Real,
        restitution: Real,
        seat_length: Real,
    ) -> Self {
        let b = |deck: usize, k: Real| {
            end_corner_points(&arrangement, deck)
                .into_iter()
                .map(|point| Bearing {
                    point,
                    stiffness: k,
                })
                .collect()
        };
        SimModel {
            arrangement,
            gap,
            bearings1: b(1, k1),
            bearings2: b(2, k2),
            damping_ratio,
            friction,
            restitution,
            seat_length,
            contact: JointContact::Rigid,
            damping_model: DampingModel::Rayleigh,
            shapes: None,
            abutments: [None, None],
        }
    }

    /// A model of two decks of any shape ([`SimModel::shapes`]) with one bearing of stiffness
    /// `k1` / `k2` at each of the four end-face corners of each deck and no abutments
    /// (`arrangement` is set to the default curved decks and ignored).
    #[allow(clippy::too_many_arguments)]
    pub fn with_shapes(
        shapes: [DeckShape; 2],
        gap: Real,
        k1: Real,
        k2: Real,
        damping_ratio: Real,
        friction: Real,
        restitution: Real,
        seat_length: Real,
    ) -> Self {
        let b = |deck: usize, k: Real| {
            shape_corner_points(&shapes[deck - 1], deck)
                .into_iter()
                .map(|point| Bearing {
                    point,
                    stiffness: k,
                })
                .collect()
        };
        SimModel {
            bearings1: b(1, k1),
            bearings2: b(2, k2),
            gap,
            damping_ratio,
            friction,
            restitution,
            seat_length,
            shapes: Some(shapes),
            ..Self::default_bridge()
        }
    }

    /// Deck masses `[m1, m2]` \[kg\].
    pub fn masses(&self) -> [Real; 2] {
        let b = self.bodies();
        [b[0].mass.mass, b[1].mass.mass]
    }

    /// The decks' reference-pose bodies (global frame of spec §4).
    pub fn deck_bodies(&self) -> [DeckBody; 2] {
        self.bodies()
    }

    /// The built-in default of `pounding simulate`: R = 100 m, β = 60°, W = 10 m, t = 0.5 m,
    /// ρ = 2500 kg/m³ (1309 t per deck) for both decks; 4 corner bearings of 2.02e7 N/m (deck 1)
    /// and 8.97e6 N/m (deck 2); ζ = 5 %; g = 0.05 m; seat 0.4 m; μ = 0.5; ε_N = 0.5.
    pub fn default_bridge() -> Self {
        let deck = crate::shape::Deck {
            radius: 100.0,
            angle: 60f64.to_radians(),
            width: 10.0,
            thickness: 0.5,
            density: 2500.0,
        };
        let arr = SArrangement {
            deck1: deck,
            deck2: deck,
        };
        Self::with_corner_bearings(arr, 0.05, 2.02e7, 8.97e6, 0.05, 0.5, 0.5, 0.4)
    }

    /// Validates every parameter (errors name it).
    pub fn validate(&self) -> Result<(), SimError> {
        self.validate_options()?;
        match &self.shapes {
            None => {
                model::validate_deck(&self.arrangement.deck1, 1)?;
                model::validate_deck(&self.arrangement.deck2, 2)?;
                let (w1, w2) = (self.arrangement.deck1.width, self.arrangement.deck2.width);
                if w1 != w2 {
                    return Err(SimError::invalid(
                        "width (deck 2)",
                        w2,
                        &format!("both decks must have the same width (deck 1: {w1})"),
                    ));
                }
            }
            Some(shapes) => {
                for (j, sh) in shapes.iter().enumerate() {
                    validate_shape(sh, j + 1)?;
                }
                let b = self.bodies();
                let (h1, h2) = (b[0].half_face, b[1].half_face);
                if (h1 - h2).abs() > 1e-9 * h1.max(h2) {
                    return Err(SimError::invalid(
                        "joint face length (deck 2)",
                        2.0 * h2,
                        &format!(
                            "the joint faces must have the same length to meet face to face \
                             (deck 1: {})",
                            2.0 * h1
                        ),
                    ));
                }
            }
        }
        for (j, a) in self.abutments.iter().enumerate() {
            if let Some(a) = a {
                if !(a.gap.is_finite() && a.gap >= 0.0) {
                    return Err(SimError::invalid(
                        format!("abutment gap (deck {})", j + 1),
                        a.gap,
                        "must be finite and >= 0",
                    ));
                }
                if !(a.seat_length.is_finite() && a.seat_length > 0.0) {
                    return Err(SimError::invalid(
                        format!("abutment seat_length (deck {})", j + 1),
                        a.seat_length,
                        "must be finite and > 0",
                    ));
                }
            }
        }
        let chk = |name: &str, v: Real, ok: bool, reason: &str| {
            if ok && v.is_finite() {
                Ok(())
            } else {
                Err(SimError::invalid(name, v, reason))
            }
        };
        chk("gap", self.gap, self.gap >= 0.0, "must be >= 0")?;
        chk(
            "damping_ratio",
            self.damping_ratio,
            (0.0..1.0).contains(&self.damping_ratio),
            "must lie in [0, 1)",
        )?;
        chk("mu", self.friction, self.friction >= 0.0, "must be >= 0")?;
        chk(
            "eps_n",
            self.restitution,
            (0.0..=1.0).contains(&self.restitution),
            "must lie in [0, 1]",
        )?;
        chk(
            "seat_length",
            self.seat_length,
            self.seat_length > 0.0,
            "must be > 0",
        )?;
        for (j, bs) in [(1, &self.bearings1), (2, &self.bearings2)] {
            for (i, b) in bs.iter().enumerate() {
                chk(
                    &format!("bearing stiffness (deck {j}, bearing {})", i + 1),
                    b.stiffness,
                    b.stiffness >= 0.0,
                    "must be >= 0",
                )?;
                // the rotational stiffness k r² must stay finite (1e300 m would overflow it)
                let kr2 = b.stiffness * (b.point.x * b.point.x + b.point.y * b.point.y);
                for v in [b.point.x, b.point.y] {
                    chk(
                        &format!("bearing point (deck {j}, bearing {})", i + 1),
                        v,
                        kr2.is_finite() && v * v < 1e100,
                        "must be finite, with |coordinate| < 1e50 m and k r² finite",
                    )?;
                }
            }
        }
        Ok(())
    }

    pub(crate) fn bodies(&self) -> [DeckBody; 2] {
        match &self.shapes {
            None => [
                DeckBody::new(&self.arrangement.deck1, 1, self.gap),
                DeckBody::new(&self.arrangement.deck2, 2, self.gap),
            ],
            Some(sh) => [
                DeckBody::from_shape(&sh[0], 1, self.gap),
                DeckBody::from_shape(&sh[1], 2, self.gap),
            ],
        }
    }

    /// Assembles `M`, `K`, `C` and the natural frequencies (errors if `ζ > 0` and a deck has no
    /// stiffness at all).
    pub fn linear_system(&self) -> Result<LinearSystem, SimError> {
        self.validate()?;
        let bodies = self.bodies();
        let mut mass = Matrix6::zeros();
        let mut stiffness = Matrix6::zeros();
        let mut damping = Matrix6::zeros();
        let mut frequencies = [[0.0; 3]; 2];
        let mut rayleigh = [(0.0, 0.0); 2];
        let dofs = dofs::Dofs::plan_rigid(2);
        for (j, bs) in [&self.bearings1, &self.bearings2].into_iter().enumerate() {
            let mp = bodies[j].mass;
            let mj = Matrix3::from_diagonal(&nalgebra::Vector3::new(mp.mass, mp.mass, mp.inertia));
            let kj = model::bearing_stiffness(&bodies[j], bs);
            let om = model::deck_frequencies(&mp, &kj);
            if om.iter().any(|w| !w.is_finite()) {
                return Err(SimError::invalid(
                    format!("mass (deck {})", j + 1),
                    mp.mass,
                    "the bearing stiffness over this mass (or inertia) overflows; use physical magnitudes",
                ));
            }
            let (a0, a1) =
                model::rayleigh_coefficients(self.damping_ratio, &om).ok_or_else(|| {
                    SimError::invalid(
                        "damping_ratio",
                        self.damping_ratio,
                        &format!(
                            "deck {} has no bearing stiffness, so Rayleigh damping is undefined",
                            j + 1
                        ),
                    )
                })?;
            let (cj, a0, a1) = self.damping_of(&mj, &kj, a0, a1);
            let o = dofs.start(j);
            mass.fixed_view_mut::<3, 3>(o, o).copy_from(&mj);
            stiffness.fixed_view_mut::<3, 3>(o, o).copy_from(&kj);
            damping.fixed_view_mut::<3, 3>(o, o).copy_from(&cj);
            frequencies[j] = om;
            rayleigh[j] = (a0, a1);
        }
        Ok(LinearSystem {
            mass,
            stiffness,
            damping,
            frequencies,
            rayleigh,
        })
    }
}

/// Re-validates one deck shape through its constructor; parameter names get the deck number
/// (`L1`, `skew2`, `R1`, …; `width`, `thickness`, `density` keep their name).
fn validate_shape(shape: &DeckShape, j: usize) -> Result<(), SimError> {
    shape
        .validate()
        .map_err(|e| SimError::Geometry(e.for_deck(j)))
}

/// Everything a run needs besides the settings: model, ground motion, initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct SimProblem {
    /// The structure.
    pub model: SimModel,
    /// The ground acceleration.
    pub ground: GroundMotion,
    /// Initial displacements `q(0)` (spec §5.1 order) \[m, rad\].
    pub q0: [Real; 6],
    /// Initial velocities `u(0)` relative to the ground \[m/s, rad/s\].
    pub u0: [Real; 6],
}

impl SimProblem {
    /// At rest in the reference pose.
    pub fn at_rest(model: SimModel, ground: GroundMotion) -> Self {
        Self {
            model,
            ground,
            q0: [0.0; 6],
            u0: [0.0; 6],
        }
    }
}

/// Settings of the time stepper (validated by [`SimSettings::validate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SimSettings {
    /// Time step `h > 0` \[s\]. Default 1e-3.
    pub dt: Real,
    /// Simulated duration \[s\]; `None` = the ground motion's last sample time. Default `None`.
    pub duration: Option<Real>,
    /// θ of the smooth part, in `[0.5, 1]`. Default 0.5 (trapezoidal rule).
    pub theta: Real,
    /// A step is an *impact* if some contact with `γ_N⁻ < −impact_velocity` gets `P_N > 0`
    /// \[m/s\]. Default 1e-3.
    pub impact_velocity: Real,
    /// Keep every `history_stride`-th step in [`bridge::BridgeSolution::t`] and the other histories (the last step always).
    /// Peaks are taken over every step regardless. Default 1.
    pub history_stride: usize,
    /// Settings of Lemke's method for the contact LCPs.
    pub lemke: LemkeSettings,
    /// An observer of the run's progress (none by default): it sees, never changes, the run.
    pub progress: Progress,
}

impl Default for SimSettings {
    fn default() -> Self {
        Self {
            dt: 1e-3,
            duration: None,
            theta: 0.5,
            impact_velocity: 1e-3,
            history_stride: 1,
            lemke: LemkeSettings::default(),
            progress: Progress::default(),
        }
    }
}

/// Steps between two calls of a [`Progress`] observer.
pub const PROGRESS_EVERY: usize = 64;

/// An observer of a run's progress: `f(steps done, total steps)`, called by the time loop before
/// the first step and every [`PROGRESS_EVERY`] steps (a front end's progress bar or time
/// estimate). Observers do not take part in the results: two settings that differ only in
/// their observer compare equal.
#[derive(Clone, Default)]
pub struct Progress(Option<std::sync::Arc<dyn Fn(usize, usize) + Send + Sync>>);

impl Progress {
    /// An observer calling `f`.
    pub fn new(f: impl Fn(usize, usize) + Send + Sync + 'static) -> Self {
        Self(Some(std::sync::Arc::new(f)))
    }

    /// Reports `done` of `total` steps (nothing without an observer).
    pub fn report(&self, done: usize, total: usize) {
        if let Some(f) = &self.0 {
            f(done, total);
        }
    }
}

impl std::fmt::Debug for Progress {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "Progress(observer)"
        } else {
            "Progress(none)"
        })
    }
}

impl PartialEq for Progress {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl SimSettings {
    /// Validates the settings (errors name the parameter).
    pub fn validate(&self) -> Result<(), SimError> {
        if !(self.dt.is_finite() && self.dt > 0.0) {
            return Err(SimError::invalid("dt", self.dt, "must be finite and > 0"));
        }
        if let Some(d) = self.duration
            && !(d.is_finite() && d > 0.0)
        {
            return Err(SimError::invalid("duration", d, "must be finite and > 0"));
        }
        if !(self.theta.is_finite() && (0.5..=1.0).contains(&self.theta)) {
            return Err(SimError::invalid(
                "theta",
                self.theta,
                "must lie in [0.5, 1]",
            ));
        }
        if !(self.impact_velocity.is_finite() && self.impact_velocity >= 0.0) {
            return Err(SimError::invalid(
                "impact_velocity",
                self.impact_velocity,
                "must be finite and >= 0",
            ));
        }
        if self.history_stride == 0 {
            return Err(SimError::invalid("history_stride", 0.0, "must be >= 1"));
        }
        Ok(())
    }

    /// Number of steps `⌈duration/dt⌉` (at least 1) of a run of `duration` seconds, refused beyond
    /// [`MAX_STEPS`].
    pub fn step_count(&self, duration: Real) -> Result<usize, SimError> {
        let n = ((duration / self.dt) - 1e-9).ceil().max(1.0);
        if n.is_nan() || n > MAX_STEPS as Real {
            return Err(SimError::invalid(
                "dt",
                self.dt,
                &format!(
                    "duration / dt = {} s / {} s = {} steps is more than the limit {MAX_STEPS}",
                    crate::output::float_token(duration),
                    crate::output::float_token(self.dt),
                    crate::output::float_token(n)
                ),
            ));
        }
        Ok(n as usize)
    }
}

/// Largest number of time steps of one run (each step stores its ground acceleration).
pub const MAX_STEPS: usize = 200_000_000;

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
    /// impact laws on the recovered velocities (see [`bridge::BridgeSolution::lcp_failures`]).
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
