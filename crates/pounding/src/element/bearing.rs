//! Bearings: a linear spring, or a bilinear spring with kinematic hardening in the plane
//! (a 2-D generalisation of OpenSees' `Steel01` with no isotropic hardening).
//!
//! The deformation `u` is the bearing's total in-plane deformation (deck point displacement
//! minus the support's, in metres); the force `f` is the force the bearing exerts *on the
//! support side by the deck*, i.e. the restoring force on the deck is `−f`, exactly as a linear
//! spring `f = k u`.

use super::{ElementError, non_negative, positive};
use crate::math::{Matrix2, Real, Vector};

const BILINEAR: &str = "bilinear bearing";
const LINEAR: &str = "linear bearing";

/// Bilinear bearing with kinematic hardening in 2-D: parameters `k0` (initial stiffness, N/m),
/// `fy` (yield force, N), `b` (post-yield stiffness ratio, `0 ≤ b < 1`).
///
/// # Model
/// A linear spring `k_h = b k0` in parallel with an elastic–perfectly-plastic spring of stiffness
/// `k_e = (1 − b) k0` whose force `f_p` stays in the disc `|f_p| ≤ R = (1 − b) fy` (von Mises in
/// the plane; the centre of the elastic domain of the *total* force moves with `k_h u`, which is
/// linear kinematic hardening). With the plastic displacement `u_p` as internal variable:
/// ```text
/// f   = k_h u + f_p,        f_p = k_e (u − u_p),        |f_p| ≤ R
/// E   = ½ k_h |u|² + ½ k_e |u − u_p|²                  (stored energy)
/// u_y = fy / k0 = R / k_e                                (yield deformation)
/// ```
///
/// # Return mapping (backward Euler, exact for this model)
/// From the committed `u_p,c`, the trial force `f_tr = k_e (u − u_p,c)`:
/// ```text
/// |f_tr| ≤ R:   f_p = f_tr,  u_p = u_p,c,                            K = k0 I
/// |f_tr| > R:   n = f_tr/|f_tr|,  f_p = R n,
///               u_p = u_p,c + (|f_tr| − R)/k_e · n,
///               K = k_h I + k_e (R/|f_tr|) (I − n nᵀ)               (consistent tangent)
/// D = f_p · Δu_p = R (|f_tr| − R) / k_e ≥ 0                          (plastic dissipation)
/// ```
/// Along one fixed line (`u = ε d`, `|d| = 1`) this is OpenSees `Steel01` with `E0 = k0`,
/// `Fy = fy`, `b = b` and `a1..a4` at their defaults (no isotropic hardening):
/// `σ = max(b E0 ε − (1−b) Fy, min(b E0 ε + (1−b) Fy, σ_c + E0 Δε))`, tangent `E0` inside the
/// band and `b E0` on it (`f_p` clamped to `[−R, R]` is the same clamp written for `σ`).
///
/// # Piles and piers: `b = 0`
/// With `b = 0` ([`BilinearBearing::elastic_perfectly_plastic`]) and along one fixed line this
/// is OpenSees `ElasticPP` with `E = k0`, `epsyP = −epsyN = fy/k0`, `eps0 = 0`:
/// `f = clamp(f_c + k0 Δu, −fy, fy)`, tangent `k0` inside and 0 on the yield force, plastic
/// offset `u_p` growing by the excess. OpenSees declares a trial plastic already when
/// `|σ_tr| > fy − E·2.2e-16` (its `DBL_EPSILON` tolerance), which changes the returned force
/// by at most `E·2.2e-16` and the tangent only inside that sliver; elsewhere the two agree to
/// rounding (the tests compare OpenSees 3.7.1). In the plane the yield set is a disc
/// `|f| ≤ fy`, i.e. a pile group equally strong in every direction.
///
/// # Energy and the trapezoidal rule
/// Over one plastic step from the force `f_p,k` (inside the disc), the trapezoidal work of the
/// plastic spring minus its stored-energy change is
/// ```text
/// ½ (f_p,k + f_p,k+1)·Δu − ΔE_p = ½ (|f_tr| − R)(R + f_p,k · n)/k_e  ∈ [0, D]
/// ```
/// (because `|f_p,k| ≤ R`; the hardening spring's trapezoidal work equals its energy change
/// exactly). So a driver booking hysteretic energy as `W − ΔE` gets a non-negative dissipation
/// that falls short of `D` by `½ (|f_tr| − R)(R − f_p,k · n)/k_e`: zero in 1-D continued plastic
/// flow, first order in the step at a yield onset, and second order per step while the flow
/// direction turns; the two converge as the step shrinks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BilinearBearing {
    k0: Real,
    fy: Real,
    b: Real,
}

impl BilinearBearing {
    /// Validates `k0 > 0`, `fy > 0` (finite) and `0 ≤ b < 1`; errors name the key
    /// (`k0`, `fy`, `b`).
    pub fn new(k0: Real, fy: Real, b: Real) -> Result<Self, ElementError> {
        let k0 = positive(BILINEAR, "k0", k0)?;
        let fy = positive(BILINEAR, "fy", fy)?;
        if !(b.is_finite() && (0.0..1.0).contains(&b)) {
            return Err(ElementError::InvalidParameter {
                element: BILINEAR,
                key: "b",
                value: b,
                reason: "must lie in [0, 1)",
            });
        }
        Ok(BilinearBearing { k0, fy, b })
    }

    /// An elastic–perfectly-plastic spring (`b = 0`): stiffness `k0`, yield force `fy`
    /// (piles, piers); validates like [`BilinearBearing::new`].
    pub fn elastic_perfectly_plastic(k0: Real, fy: Real) -> Result<Self, ElementError> {
        BilinearBearing::new(k0, fy, 0.0)
    }

    /// Initial stiffness `k0` \[N/m\].
    pub fn k0(&self) -> Real {
        self.k0
    }

    /// Yield force `fy` \[N\].
    pub fn fy(&self) -> Real {
        self.fy
    }

    /// Post-yield stiffness ratio `b`.
    pub fn b(&self) -> Real {
        self.b
    }

    /// Yield deformation `u_y = fy / k0` \[m\].
    pub fn yield_deformation(&self) -> Real {
        self.fy / self.k0
    }

    /// Hardening stiffness `k_h = b k0`.
    fn k_h(&self) -> Real {
        self.b * self.k0
    }

    /// Stiffness of the elastic–perfectly-plastic spring `k_e = (1 − b) k0`.
    fn k_e(&self) -> Real {
        (1.0 - self.b) * self.k0
    }

    /// Radius of the elastic domain of the plastic spring's force, `R = (1 − b) fy`.
    pub fn plastic_force_radius(&self) -> Real {
        (1.0 - self.b) * self.fy
    }

    /// The force of the elastic–perfectly-plastic spring, `f_p = k_e (u − u_p)`.
    pub fn plastic_spring_force(&self, state: &BearingState) -> Vector {
        self.k_e() * (state.u - state.u_p)
    }

    /// The return mapping from the committed state to the total deformation `u` (pure).
    pub fn response(&self, u: &Vector, committed: &BearingState) -> BearingResponse {
        let (k_h, k_e, r) = (self.k_h(), self.k_e(), self.plastic_force_radius());
        let f_tr = k_e * (u - committed.u_p);
        let norm = f_tr.norm();
        if norm <= r {
            return BearingResponse {
                force: k_h * u + f_tr,
                tangent: Matrix2::identity() * self.k0,
                trial: BearingState {
                    u: *u,
                    u_p: committed.u_p,
                },
                dissipation: 0.0,
                yielding: false,
            };
        }
        let n = f_tr / norm;
        let excess = norm - r;
        let f_p = r * n;
        let ratio = r / norm;
        let tangent =
            Matrix2::identity() * (k_h + k_e * ratio) - (k_e * ratio) * (n * n.transpose());
        BearingResponse {
            force: k_h * u + f_p,
            tangent,
            trial: BearingState {
                u: *u,
                u_p: committed.u_p + (excess / k_e) * n,
            },
            dissipation: r * excess / k_e,
            yielding: true,
        }
    }

    /// Stored (elastic) energy `½ k_h |u|² + ½ k_e |u − u_p|²` \[J\].
    pub fn stored_energy(&self, state: &BearingState) -> Real {
        0.5 * self.k_h() * state.u.norm_squared()
            + 0.5 * self.k_e() * (state.u - state.u_p).norm_squared()
    }

    /// The force at a (committed or trial) state, `k_h u + k_e (u − u_p)`.
    pub fn force(&self, state: &BearingState) -> Vector {
        self.k_h() * state.u + self.plastic_spring_force(state)
    }
}

/// Linear bearing `f = k u` (equal stiffness in x and y), `k ≥ 0` \[N/m\]. Tangent `k I`,
/// stored energy `½ k |u|²`, no dissipation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearBearing {
    k: Real,
}

impl LinearBearing {
    /// Validates `k ≥ 0` and finite; the error names the key `k`.
    pub fn new(k: Real) -> Result<Self, ElementError> {
        Ok(LinearBearing {
            k: non_negative(LINEAR, "k", k)?,
        })
    }

    /// The stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.k
    }
}

/// A bearing's state: total deformation `u` and plastic displacement `u_p` (zero for a linear
/// bearing), both in metres. The virgin state is [`BearingState::default`] (all zero).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingState {
    /// Total deformation `u` \[m\].
    pub u: Vector,
    /// Plastic displacement `u_p` \[m\] (always zero for a linear bearing).
    pub u_p: Vector,
}

/// The result of [`BearingLaw::force_and_tangent`] (and of the laws' `response`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingResponse {
    /// Force `f(u)` \[N\] (the restoring force on the deck is `−f`).
    pub force: Vector,
    /// Consistent tangent `∂f/∂u` \[N/m\] (symmetric positive definite).
    pub tangent: Matrix2,
    /// The trial state; becomes the committed state when the step is accepted.
    pub trial: BearingState,
    /// Plastic dissipation of the step `f_p · Δu_p ≥ 0` \[J\] (zero for a linear bearing).
    pub dissipation: Real,
    /// Whether the step is plastic (return mapping active).
    pub yielding: bool,
}

/// The constitutive law a driver holds per bearing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BearingLaw {
    /// Linear spring `f = k u`.
    Linear(LinearBearing),
    /// Bilinear spring with kinematic hardening (2-D `Steel01`).
    Bilinear(BilinearBearing),
}

impl BearingLaw {
    /// Force, consistent tangent, trial state and step dissipation at total deformation `u`
    /// from the committed state (pure; commit by storing `trial`).
    pub fn force_and_tangent(&self, u: &Vector, committed: &BearingState) -> BearingResponse {
        match self {
            BearingLaw::Linear(l) => BearingResponse {
                force: l.k * u,
                tangent: Matrix2::identity() * l.k,
                trial: BearingState {
                    u: *u,
                    u_p: Vector::zeros(),
                },
                dissipation: 0.0,
                yielding: false,
            },
            BearingLaw::Bilinear(bl) => bl.response(u, committed),
        }
    }

    /// Stored (elastic) energy at a state \[J\].
    pub fn stored_energy(&self, state: &BearingState) -> Real {
        match self {
            BearingLaw::Linear(l) => 0.5 * l.k * state.u.norm_squared(),
            BearingLaw::Bilinear(bl) => bl.stored_energy(state),
        }
    }

    /// The force at a state (e.g. the committed force `f_k` for the trapezoidal work) \[N\].
    pub fn force(&self, state: &BearingState) -> Vector {
        match self {
            BearingLaw::Linear(l) => l.k * state.u,
            BearingLaw::Bilinear(bl) => bl.force(state),
        }
    }

    /// Initial (elastic) stiffness: `k` or `k0` \[N/m\] (for Rayleigh damping, periods).
    pub fn initial_stiffness(&self) -> Real {
        match self {
            BearingLaw::Linear(l) => l.k,
            BearingLaw::Bilinear(bl) => bl.k0,
        }
    }
}

/// A bearing as a driver holds it: the law, the committed state and the accumulated plastic
/// dissipation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingElement {
    law: BearingLaw,
    committed: BearingState,
    dissipated: Real,
}

impl BearingElement {
    /// A virgin bearing (zero deformation, no plastic displacement).
    pub fn new(law: BearingLaw) -> Self {
        BearingElement {
            law,
            committed: BearingState::default(),
            dissipated: 0.0,
        }
    }

    /// The law.
    pub fn law(&self) -> &BearingLaw {
        &self.law
    }

    /// The committed state.
    pub fn committed(&self) -> &BearingState {
        &self.committed
    }

    /// Trial response at total deformation `u` (pure).
    pub fn trial(&self, u: &Vector) -> BearingResponse {
        self.law.force_and_tangent(u, &self.committed)
    }

    /// Accepts a trial response computed from the current committed state: stores its state
    /// and adds its dissipation.
    pub fn commit(&mut self, response: &BearingResponse) {
        self.committed = response.trial;
        self.dissipated += response.dissipation;
    }

    /// Stored energy at the committed state \[J\].
    pub fn stored_energy(&self) -> Real {
        self.law.stored_energy(&self.committed)
    }

    /// Plastic dissipation accumulated over the committed steps \[J\].
    pub fn dissipated(&self) -> Real {
        self.dissipated
    }

    /// The committed force \[N\].
    pub fn force(&self) -> Vector {
        self.law.force(&self.committed)
    }
}
