//! Compliance (penalty) contact laws for the normal direction of a pounding joint.
//!
//! The rigid model of this crate resolves an impact instantaneously with Newton's law (spec §8).
//! Most of the pounding literature instead inserts a stiff contact spring between the colliding
//! bodies; this module provides those laws as a standalone, UI-free library so that a time
//! stepper can plug them in and so that rigid and compliance results can be compared.
//!
//! # Sign conventions
//! * `δ` (*penetration*, m) is the signed overlap of the two bodies along the contact normal:
//!   `δ = −g_N` with `g_N` the signed gap. `δ > 0`: the bodies overlap (contact may be closed);
//!   `δ ≤ 0`: the gap is open.
//! * `δ̇` (m/s) is its rate: `δ̇ > 0` approaching (compression), `δ̇ < 0` separating (restitution).
//! * `F` (N) is the **compressive** normal force the law transmits, `F ≥ 0` always; it pushes the
//!   bodies apart. There is no tensile force: `F = 0` for `δ ≤ 0`, and damped laws whose
//!   formula would give `F < 0` during restitution are clamped at `F = 0` (the contact then ends,
//!   *before* `δ` returns to zero).
//! * An *impact* is a maximal interval of positive contact force.
//!
//! # Laws ([`ContactLaw`])
//! | law | force for `δ > 0` | parameters | reference |
//! |---|---|---|---|
//! | [`KelvinVoigt`] | `F = max(0, k δ + c δ̇)` | `k`, `c` | Anagnostopoulos (1988) |
//! | [`Hertz`] | `F = k_h δ^{3/2}` | `k_h` | Hertz (1882); Davis (1992) |
//! | [`HertzDamp`] | `F = max(0, k_h δ^{3/2} + ζ δ^{3/2} δ̇)` | `k_h`, `ζ` (or `χ = ζ v_i / k_h`) | Muthukumar & DesRoches (2006) |
//! | [`BilinearImpact`] | incremental bilinear hysteresis (below) | `K1`, `K2`, `δy` | Muthukumar (2003); OpenSees `ImpactMaterial` |
//! | [`Jankowski`] | `F = β δ^{3/2} + c(δ) δ̇` if `δ̇ > 0`, `β δ^{3/2}` if `δ̇ ≤ 0` | `β`, `ξ`, `m_eff` | Jankowski (2005) |
//!
//! Every law is evaluated through [`ContactLaw::evaluate`], which takes the **committed**
//! [`LawState`] of the previous accepted step, the trial penetration `δ` and rate `δ̇`, and
//! returns an [`Evaluation`]: the force, its partial derivatives (for a Newton iteration of an
//! implicit integrator) and the trial state. The caller commits the trial state (replaces its
//! stored state) when the step is accepted — the commit/revert semantics of OpenSees'
//! `UniaxialMaterial` (`setTrialStrain`/`commitState`). Evaluations are pure functions of
//! `(committed state, δ, δ̇)`, so they may be repeated any number of times within a step.
//! The state matters for the history-dependent laws: [`BilinearImpact`] (committed `δ_c`,
//! `F_c`), and [`HertzDamp`] with a per-impact impact velocity (captured at contact onset).
//! For the bilinear law, evaluate **and commit at every step, also while the gap is open**,
//! so that the committed `δ_c` follows the gap exactly as OpenSees' committed strain does.
//!
//! # Calibrations ([`calibration`])
//! Kelvin and Hertz-damp (and Jankowski) damping from a target coefficient of restitution `e`:
//! numerically, by integrating the isolated two-mass collision and root-finding the damping
//! parameter ([`calibration::kelvin_damping_ratio`], [`calibration::hertz_damp_chi`],
//! [`calibration::jankowski_xi`]), or with the published closed forms (Anagnostopoulos 1988;
//! Muthukumar & DesRoches 2006; Ye, Li & Zhu 2009; Jankowski 2005). The bilinear law is derived
//! from a Hertz stiffness as OpenSees documents ([`BilinearImpact::from_hertz`]).
//!
//! # Two-mass collisions, joints, time steps
//! * [`collision`]: an accurate 1-D integrator for the collision of two masses (free, or on
//!   linear springs to the ground) through any law: rebound velocities, contact duration, peak
//!   force and penetration, and the rigid (Newton) reference in closed form.
//! * [`sharing`]: how a joint law is shared among the corner contacts of one joint.
//! * [`timestep`]: the integrator suited to stiff contact springs and the time-step check.
//!
//! # References
//! * Anagnostopoulos, S. A. (1988). Pounding of buildings in series during earthquakes.
//!   *Earthquake Eng. Struct. Dyn.* 16, 443–456.
//! * Hunt, K. H., Crossley, F. R. E. (1975). Coefficient of restitution interpreted as damping in
//!   vibroimpact. *J. Appl. Mech.* 42, 440–445.
//! * Lankarani, H. M., Nikravesh, P. E. (1990). A contact force model with hysteresis damping for
//!   impact analysis of multibody systems. *J. Mech. Des.* 112, 369–376.
//! * Muthukumar, S. (2003). *A contact element approach with hysteresis damping for the analysis
//!   and design of pounding in bridges*. PhD thesis, Georgia Institute of Technology.
//! * Muthukumar, S., DesRoches, R. (2006). A Hertz contact model with non-linear damping for
//!   pounding simulation. *Earthquake Eng. Struct. Dyn.* 35, 811–828.
//! * Jankowski, R. (2005). Non-linear viscoelastic modelling of earthquake-induced structural
//!   pounding. *Earthquake Eng. Struct. Dyn.* 34, 595–611.
//! * Ye, K., Li, L., Zhu, H. (2009). A note on the Hertz contact model with nonlinear damping for
//!   pounding simulation. *Earthquake Eng. Struct. Dyn.* 38, 1135–1142.
//! * OpenSees `uniaxialMaterial ImpactMaterial` (M. Dryden), wiki page *Impact Material*, and
//!   source `SRC/material/uniaxial/ImpactMaterial.cpp` (behaviour reproduced, not code).

pub mod calibration;
pub mod collision;
pub mod sharing;
pub mod timestep;

use crate::math::Real;
use thiserror::Error;

/// Bad contact-law input. The message names the parameter and its value.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ContactLawError {
    /// A parameter is not finite or out of its range.
    #[error("invalid contact-law parameter {name} = {}: {reason}", crate::output::float_token(*value))]
    InvalidParameter {
        /// The parameter (e.g. `k`, `restitution`, `delta_y`).
        name: String,
        /// The offending value.
        value: Real,
        /// What was expected.
        reason: String,
    },
}

pub(crate) fn invalid(name: &str, value: Real, reason: &str) -> ContactLawError {
    ContactLawError::InvalidParameter {
        name: name.to_string(),
        value,
        reason: reason.to_string(),
    }
}

/// `Ok(v)` if `v` is finite and `> 0`.
pub(crate) fn positive(name: &str, v: Real) -> Result<Real, ContactLawError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(invalid(name, v, "must be finite and > 0"))
    }
}

/// `Ok(v)` if `v` is finite and `≥ 0`.
pub(crate) fn non_negative(name: &str, v: Real) -> Result<Real, ContactLawError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(invalid(name, v, "must be finite and >= 0"))
    }
}

/// `Ok(e)` if `e ∈ (0, 1]`.
pub(crate) fn restitution(name: &str, e: Real) -> Result<Real, ContactLawError> {
    if e.is_finite() && e > 0.0 && e <= 1.0 {
        Ok(e)
    } else {
        Err(invalid(name, e, "must lie in (0, 1]"))
    }
}

/// Effective (reduced) mass of two colliding bodies, `m_eff = m1 m2 / (m1 + m2)`, validated.
pub fn effective_mass(m1: Real, m2: Real) -> Result<Real, ContactLawError> {
    let m1 = positive("m1", m1)?;
    let m2 = positive("m2", m2)?;
    Ok(m1 * m2 / (m1 + m2))
}

/// US customary units used by the bridge-pounding literature (exact SI definitions).
pub mod units {
    use crate::math::Real;
    /// One inch in metres (exact).
    pub const INCH: Real = 0.0254;
    /// One kip (1000 lbf) in newtons (exact: 1 lbf = 4.4482216152605 N).
    pub const KIP: Real = 4448.2216152605;
    /// A Hertz stiffness in kip/in^1.5 converted to N/m^1.5.
    pub fn kip_per_in_1_5(v: Real) -> Real {
        v * KIP / INCH.powf(1.5)
    }
    /// A linear stiffness in kip/in converted to N/m.
    pub fn kip_per_in(v: Real) -> Real {
        v * KIP / INCH
    }
}

/// The committed state of a law between steps (see the module doc for the commit semantics).
///
/// [`LawState::default`] is an undeformed, open contact at `δ = 0`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LawState {
    delta: Real,
    force: Real,
    onset_velocity: Option<Real>,
}

impl LawState {
    /// An open contact whose committed signed penetration is `delta` (`≤ 0`: gap `−delta`).
    /// Only the bilinear law uses it: its first closing step increments from this value,
    /// exactly as OpenSees' `ImpactMaterial` increments from its committed strain.
    pub fn open_at(delta: Real) -> Self {
        LawState {
            delta,
            force: 0.0,
            onset_velocity: None,
        }
    }
    /// Committed signed penetration `δ_c` \[m\].
    pub fn delta(&self) -> Real {
        self.delta
    }
    /// Committed force `F_c ≥ 0` \[N\].
    pub fn force(&self) -> Real {
        self.force
    }
    /// `true` while the committed force is positive (an impact is in progress).
    pub fn in_contact(&self) -> bool {
        self.force > 0.0
    }
    /// The approach rate `δ̇` recorded at the onset of the current impact (`None` when the
    /// contact is open). For [`HertzDamp`] with [`HertzDamping::PerImpact`] this (floored) is
    /// the impact velocity `v_i` of the damping constant.
    pub fn onset_velocity(&self) -> Option<Real> {
        self.onset_velocity
    }
}

/// The result of one law evaluation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// Compressive contact force `F ≥ 0` \[N\] (pushes the bodies apart).
    pub force: Real,
    /// Tangent `∂F/∂δ` of the active branch \[N/m\] (0 when open or clamped).
    pub stiffness: Real,
    /// `∂F/∂δ̇` of the active branch \[N s/m\] (0 when open or clamped).
    pub damping: Real,
    /// The trial state; commit it (store it) when the step is accepted.
    pub state: LawState,
}

impl Evaluation {
    fn open(delta: Real) -> Self {
        Evaluation {
            force: 0.0,
            stiffness: 0.0,
            damping: 0.0,
            state: LawState::open_at(delta),
        }
    }
    /// A closed-contact evaluation; the onset velocity is carried over from the committed
    /// state, or recorded now (`delta_dot`) if the committed state was not in contact.
    fn closed(
        prev: &LawState,
        delta: Real,
        delta_dot: Real,
        force: Real,
        stiffness: Real,
        damping: Real,
    ) -> Self {
        if force > 0.0 {
            let onset = if prev.in_contact() {
                prev.onset_velocity.or(Some(delta_dot))
            } else {
                Some(delta_dot)
            };
            Evaluation {
                force,
                stiffness,
                damping,
                state: LawState {
                    delta,
                    force,
                    onset_velocity: onset,
                },
            }
        } else {
            Evaluation::open(delta)
        }
    }
}

/// Linear spring and dashpot in parallel (Kelvin–Voigt), without tension:
/// ```text
/// F = max(0, k δ + c δ̇)   for δ > 0,      F = 0 for δ ≤ 0
/// ```
/// The dashpot gives a force jump `c δ̇` at contact onset, and the clamp ends the contact when
/// `k δ + c δ̇` returns to zero (with `δ > 0`). `c` from a target restitution: see
/// [`KelvinVoigt::from_restitution`] (Anagnostopoulos 1988, or numerically).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KelvinVoigt {
    k: Real,
    c: Real,
}

impl KelvinVoigt {
    /// Validates `k > 0` \[N/m\] and `c ≥ 0` \[N s/m\] (finite).
    pub fn new(k: Real, c: Real) -> Result<Self, ContactLawError> {
        Ok(KelvinVoigt {
            k: positive("k", k)?,
            c: non_negative("c", c)?,
        })
    }
    /// The law whose isolated collision of two free masses `m1`, `m2` rebounds with restitution
    /// `e ∈ (0, 1]`: `c = 2 ξ √(k m_eff)`, `m_eff = m1 m2/(m1 + m2)`, with the damping ratio `ξ`
    /// of [`calibration::kelvin_damping_ratio`]. Independent of the impact velocity (the law is
    /// linear), but dependent on the masses.
    pub fn from_restitution(
        k: Real,
        e: Real,
        m1: Real,
        m2: Real,
        method: calibration::KelvinCalibration,
    ) -> Result<Self, ContactLawError> {
        let k = positive("k", k)?;
        let m = effective_mass(m1, m2)?;
        let xi = calibration::kelvin_damping_ratio(e, method)?;
        KelvinVoigt::new(k, 2.0 * xi * (k * m).sqrt())
    }
    /// Spring stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.k
    }
    /// Dashpot coefficient `c` \[N s/m\].
    pub fn c(&self) -> Real {
        self.c
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let f = self.k * delta + self.c * delta_dot;
        Evaluation::closed(state, delta, delta_dot, f, self.k, self.c)
    }
}

/// Hertz's elastic contact law (no dissipation):
/// ```text
/// F = k_h δ^{3/2}   for δ > 0,      ∂F/∂δ = (3/2) k_h δ^{1/2}
/// ```
/// `k_h` \[N/m^{3/2}\] lumps the contact geometry and the elastic moduli; for bridge decks the
/// literature uses `k_h ≈ 25 000 kip/in^{3/2}` (Muthukumar & DesRoches 2006;
/// [`units::kip_per_in_1_5`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    k_h: Real,
}

impl Hertz {
    /// Validates `k_h > 0` \[N/m^{3/2}\].
    pub fn new(k_h: Real) -> Result<Self, ContactLawError> {
        Ok(Hertz {
            k_h: positive("k_h", k_h)?,
        })
    }
    /// Hertz stiffness `k_h` \[N/m^{3/2}\].
    pub fn k_h(&self) -> Real {
        self.k_h
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let s = delta.sqrt();
        Evaluation::closed(
            state,
            delta,
            delta_dot,
            self.k_h * delta * s,
            1.5 * self.k_h * s,
            0.0,
        )
    }
}

/// How the damping constant `ζ` of [`HertzDamp`] is set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HertzDamping {
    /// A fixed `ζ` \[N s/m^{5/2}\] for every impact (e.g. calibrated for a design impact velocity;
    /// an impact at another velocity then rebounds with another `e`).
    Constant {
        /// `ζ ≥ 0`.
        zeta: Real,
    },
    /// `ζ = χ k_h / v_i` with `v_i` the approach rate recorded at the onset of each impact
    /// (floored at `min_velocity`): every impact rebounds with the `e` the dimensionless `χ` was
    /// calibrated for, whatever its velocity (the intent of Muthukumar & DesRoches 2006).
    PerImpact {
        /// Dimensionless damping `χ = ζ v_i / k_h ≥ 0`.
        chi: Real,
        /// Floor of `v_i` \[m/s\] (`> 0`) for grazing contacts, which would otherwise get an
        /// unbounded damping constant.
        min_velocity: Real,
    },
}

/// Hertz contact with nonlinear (hysteresis) damping, in the form of Muthukumar & DesRoches
/// (2006) (after Hunt & Crossley 1975; Lankarani & Nikravesh 1990):
/// ```text
/// F = max(0, k_h δ^{3/2} + ζ δ^{3/2} δ̇) = max(0, k_h δ^{3/2} (1 + χ δ̇ / v_i))   for δ > 0
/// ```
/// with `χ = ζ v_i / k_h` dimensionless. The damping force vanishes with `δ`, so the force is
/// continuous at contact onset. For two free masses the rebound depends on `χ` only (not on
/// `k_h`, the masses, the exponent or the velocity), through the exact first integral of the
/// Hunt–Crossley equation (used by the tests as independent evidence):
/// `χ (1 + e) = ln((1 + χ) / (1 − χ e))`.
/// Calibrations of `χ` from `e`: [`calibration::hertz_damp_chi`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzDamp {
    k_h: Real,
    damping: HertzDamping,
}

impl HertzDamp {
    /// Validates `k_h > 0`, and `ζ ≥ 0`, or `χ ≥ 0` and `min_velocity > 0`.
    pub fn new(k_h: Real, damping: HertzDamping) -> Result<Self, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let damping = match damping {
            HertzDamping::Constant { zeta } => HertzDamping::Constant {
                zeta: non_negative("zeta", zeta)?,
            },
            HertzDamping::PerImpact { chi, min_velocity } => HertzDamping::PerImpact {
                chi: non_negative("chi", chi)?,
                min_velocity: positive("min_velocity", min_velocity)?,
            },
        };
        Ok(HertzDamp { k_h, damping })
    }
    /// The law with `χ` calibrated for restitution `e` by `method`
    /// ([`calibration::hertz_damp_chi`]). With `design_velocity = Some(v)` the damping is the
    /// constant `ζ = χ k_h / v` (the published formulas' form: it depends on the impact
    /// velocity); with `None` it is [`HertzDamping::PerImpact`] with `min_velocity`.
    pub fn from_restitution(
        k_h: Real,
        e: Real,
        design_velocity: Option<Real>,
        min_velocity: Real,
        method: calibration::HertzDampCalibration,
    ) -> Result<Self, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let chi = calibration::hertz_damp_chi(e, method)?;
        let damping = match design_velocity {
            Some(v) => HertzDamping::Constant {
                zeta: chi * k_h / positive("design_velocity", v)?,
            },
            None => HertzDamping::PerImpact { chi, min_velocity },
        };
        HertzDamp::new(k_h, damping)
    }
    /// Hertz stiffness `k_h` \[N/m^{3/2}\].
    pub fn k_h(&self) -> Real {
        self.k_h
    }
    /// The damping setting.
    pub fn damping(&self) -> HertzDamping {
        self.damping
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let zeta = match self.damping {
            HertzDamping::Constant { zeta } => zeta,
            HertzDamping::PerImpact { chi, min_velocity } => {
                let onset = if state.in_contact() {
                    state.onset_velocity.unwrap_or(delta_dot)
                } else {
                    delta_dot
                };
                chi * self.k_h / onset.max(min_velocity)
            }
        };
        let s = delta.sqrt();
        let d15 = delta * s;
        let g = self.k_h + zeta * delta_dot;
        Evaluation::closed(state, delta, delta_dot, g * d15, 1.5 * g * s, zeta * d15)
    }
}

/// Bilinear impact law of Muthukumar (2003), exactly as OpenSees' `ImpactMaterial`.
///
/// Parameters: initial stiffness `K1`, secondary stiffness `K2` (`0 < K2 ≤ K1`), yield
/// penetration `δy > 0` (OpenSees takes `δy` and the gap as negative numbers because its
/// material is compression-negative; here they are positive and the gap belongs to the caller).
/// With `F_c`, `δ_c` the committed force and signed penetration and `Δδ = δ − δ_c`:
/// ```text
/// δ ≤ 0:           F = 0
/// Δδ > 0 (load):   F = min(F_c + K1 Δδ,  K1 δy + K2 (δ − δy))
/// Δδ < 0 (unload): F = max(F_c + K1 Δδ,  K2 δ)
/// Δδ = 0:          F = F_c
/// ```
/// The force stays in the band `K2 δ ≤ F ≤ K1 δy + K2 (δ − δy)`, moving with slope `K1` inside it;
/// it is never negative (clamped at 0 as a safeguard; the band already excludes it for `δ > 0`).
/// Loading from rest follows `K1` up to `δy`, then `K2`; unloading from `δm` follows `K1` down to
/// `δm − δy`, then `K2 δ` to zero: a parallelogram loop of area `(K1 − K2) δy (δm − δy)`
/// (for `δm ≥ 2 δy`).
///
/// **OpenSees quirk, reproduced**: `δ_c` is the committed *signed* penetration, also while the gap
/// is open, so the first closing step increments from a negative `δ_c` and gets
/// `F = min(K1 (δ − δ_c), …) > K1 δ`; the excess is at most `K1 |δ̇| Δt` and vanishes with `Δt`.
/// Rate independent (`∂F/∂δ̇ = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BilinearImpact {
    k1: Real,
    k2: Real,
    delta_y: Real,
}

/// The derivation of [`BilinearImpact`] parameters from a Hertz stiffness (OpenSees wiki,
/// *Impact Material*; Muthukumar & DesRoches 2006), all SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BilinearDerivation {
    /// Effective stiffness `K_eff = k_h √δm` \[N/m\].
    pub k_eff: Real,
    /// Energy dissipated by the Hertz-damp law in an impact reaching `δm`:
    /// `ΔE = k_h δm^{n+1} (1 − e²) / (n + 1)`, `n = 3/2` \[J\].
    pub energy: Real,
    /// The law: `K1 = K_eff + ΔE/(a δm²)`, `K2 = K_eff − ΔE/((1 − a) δm²)`, `δy = a δm`.
    pub law: BilinearImpact,
}

impl BilinearImpact {
    /// Validates `K1 > 0`, `0 < K2 ≤ K1` \[N/m\] and `δy > 0` \[m\].
    pub fn new(k1: Real, k2: Real, delta_y: Real) -> Result<Self, ContactLawError> {
        let k1 = positive("k1", k1)?;
        let k2 = positive("k2", k2)?;
        if k2 > k1 {
            return Err(invalid("k2", k2, "must not exceed k1"));
        }
        Ok(BilinearImpact {
            k1,
            k2,
            delta_y: positive("delta_y", delta_y)?,
        })
    }
    /// Derives `K1`, `K2`, `δy` from a Hertz stiffness `k_h` \[N/m^{3/2}\], restitution
    /// `e ∈ (0, 1]`, design maximum penetration `δm > 0` \[m\] and yield ratio `a ∈ (0, 1)`
    /// (typically 0.1), as documented by OpenSees (*Impact Material*; Muthukumar & DesRoches 2006):
    /// ```text
    /// K_eff = k_h √δm,   ΔE = k_h δm^{5/2} (1 − e²) / (5/2),   δy = a δm
    /// K1 = K_eff + ΔE / (a δm²),   K2 = K_eff − ΔE / ((1 − a) δm²)
    /// ```
    /// so that an impact reaching `δm` dissipates `ΔE` (the loop area
    /// `(K1 − K2) δy (δm − δy) = ΔE`). Example (the issue's): `k_h = 25 000 kip/in^{3/2}`, `e = 0.6`,
    /// `δm = 1 in`, `a = 0.1` give `K1 = 89 000 kip/in = 1.5586e7 kN/m`,
    /// `K2 = 17 889 kip/in = 3.1328e6 kN/m`, `δy = 2.54 mm`. Note: the loop dissipates the
    /// Hertz-damp energy loss, but the bilinear loading path stores `½ K_eff δm² + ½ ΔE`, more than
    /// Hertz's `0.4 k_h δm^{5/2}`, so an isolated impact reaching `δm` rebounds with
    /// `e_bl = √(1 − ΔE / (½ K_eff δm² + ½ ΔE))` > `e` (0.770 for `e = 0.6`).
    /// Errors name `k_h`, `restitution`, `delta_m`, `a` (`K2 ≤ 0` happens for
    /// `a ≥ 1 − 0.4 (1 − e²)` and is reported on `a`).
    pub fn from_hertz(
        k_h: Real,
        e: Real,
        delta_m: Real,
        a: Real,
    ) -> Result<BilinearDerivation, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let e = restitution("restitution", e)?;
        let dm = positive("delta_m", delta_m)?;
        if !(a.is_finite() && a > 0.0 && a < 1.0) {
            return Err(invalid("a", a, "must lie in (0, 1)"));
        }
        let n = 1.5;
        let k_eff = k_h * dm.sqrt();
        let energy = k_h * dm.powf(n + 1.0) * (1.0 - e * e) / (n + 1.0);
        let k1 = k_eff + energy / (a * dm * dm);
        let k2 = k_eff - energy / ((1.0 - a) * dm * dm);
        if k2.is_nan() || k2 <= 0.0 {
            return Err(invalid(
                "a",
                a,
                "gives a secondary stiffness K2 <= 0 (need a < 1 - 0.4 (1 - e^2))",
            ));
        }
        Ok(BilinearDerivation {
            k_eff,
            energy,
            law: BilinearImpact::new(k1, k2, a * dm)?,
        })
    }
    /// Initial (and unloading) stiffness `K1` \[N/m\].
    pub fn k1(&self) -> Real {
        self.k1
    }
    /// Secondary stiffness `K2` \[N/m\].
    pub fn k2(&self) -> Real {
        self.k2
    }
    /// Yield penetration `δy` \[m\].
    pub fn delta_y(&self) -> Real {
        self.delta_y
    }
    /// Loading envelope `K1 δ` for `δ ≤ δy`, `K1 δy + K2 (δ − δy)` beyond (`0` for `δ ≤ 0`).
    pub fn envelope(&self, delta: Real) -> Real {
        if delta <= 0.0 {
            0.0
        } else if delta <= self.delta_y {
            self.k1 * delta
        } else {
            self.k1 * self.delta_y + self.k2 * (delta - self.delta_y)
        }
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let dd = delta - state.delta;
        let elastic = state.force + self.k1 * dd;
        let (f, kt) = if dd > 0.0 {
            let env = self.k1 * self.delta_y + self.k2 * (delta - self.delta_y);
            if elastic < env {
                (elastic, self.k1)
            } else {
                (env, self.k2)
            }
        } else if dd < 0.0 {
            let lower = self.k2 * delta;
            if elastic > lower {
                (elastic, self.k1)
            } else {
                (lower, self.k2)
            }
        } else {
            (state.force, self.k1)
        };
        let mut ev = Evaluation::closed(state, delta, delta_dot, f.max(0.0), kt, 0.0);
        // The committed δ is the signed penetration whatever the force (OpenSees' strain).
        ev.state.delta = delta;
        ev
    }
}

/// Nonlinear viscoelastic law of Jankowski (2005):
/// ```text
/// F = β δ^{3/2} + c(δ) δ̇   for δ > 0, δ̇ > 0   (approach)
/// F = β δ^{3/2}            for δ > 0, δ̇ ≤ 0   (restitution)
/// c(δ) = 2 ξ √(β √δ m_eff),   m_eff = m1 m2 / (m1 + m2)
/// ```
/// Damping acts only during approach, so the force is never negative. By scaling, the rebound of
/// two free masses depends on `ξ` only (not on `β`, the masses or the velocity). Jankowski's
/// closed-form `ξ(e)` and a numerical calibration: [`calibration::jankowski_xi`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jankowski {
    beta: Real,
    xi: Real,
    m_eff: Real,
}

impl Jankowski {
    /// Validates `β > 0` \[N/m^{3/2}\], `ξ ≥ 0`, `m_eff > 0` \[kg\].
    pub fn new(beta: Real, xi: Real, m_eff: Real) -> Result<Self, ContactLawError> {
        Ok(Jankowski {
            beta: positive("beta", beta)?,
            xi: non_negative("xi", xi)?,
            m_eff: positive("m_eff", m_eff)?,
        })
    }
    /// The law for colliding masses `m1`, `m2` with `ξ` calibrated for restitution `e` by `method`.
    pub fn from_restitution(
        beta: Real,
        e: Real,
        m1: Real,
        m2: Real,
        method: calibration::JankowskiCalibration,
    ) -> Result<Self, ContactLawError> {
        let beta = positive("beta", beta)?;
        let m = effective_mass(m1, m2)?;
        Jankowski::new(beta, calibration::jankowski_xi(e, method)?, m)
    }
    /// Stiffness `β` \[N/m^{3/2}\].
    pub fn beta(&self) -> Real {
        self.beta
    }
    /// Damping ratio `ξ`.
    pub fn xi(&self) -> Real {
        self.xi
    }
    /// Effective mass `m_eff` \[kg\].
    pub fn m_eff(&self) -> Real {
        self.m_eff
    }
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let s = delta.sqrt();
        let fe = self.beta * delta * s;
        let ke = 1.5 * self.beta * s;
        if delta_dot > 0.0 {
            let c = 2.0 * self.xi * (self.beta * s * self.m_eff).sqrt();
            // dc/dδ = c / (4 δ)
            Evaluation::closed(
                state,
                delta,
                delta_dot,
                fe + c * delta_dot,
                ke + c / (4.0 * delta) * delta_dot,
                c,
            )
        } else {
            Evaluation::closed(state, delta, delta_dot, fe, ke, 0.0)
        }
    }
}

/// A validated normal contact law (see the module doc for the table of laws).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactLaw {
    /// Linear spring + dashpot.
    KelvinVoigt(KelvinVoigt),
    /// Elastic Hertz.
    Hertz(Hertz),
    /// Hertz with nonlinear damping.
    HertzDamp(HertzDamp),
    /// Bilinear impact (OpenSees `ImpactMaterial`).
    Bilinear(BilinearImpact),
    /// Jankowski nonlinear viscoelastic.
    Jankowski(Jankowski),
}

impl From<KelvinVoigt> for ContactLaw {
    fn from(l: KelvinVoigt) -> Self {
        ContactLaw::KelvinVoigt(l)
    }
}
impl From<Hertz> for ContactLaw {
    fn from(l: Hertz) -> Self {
        ContactLaw::Hertz(l)
    }
}
impl From<HertzDamp> for ContactLaw {
    fn from(l: HertzDamp) -> Self {
        ContactLaw::HertzDamp(l)
    }
}
impl From<BilinearImpact> for ContactLaw {
    fn from(l: BilinearImpact) -> Self {
        ContactLaw::Bilinear(l)
    }
}
impl From<Jankowski> for ContactLaw {
    fn from(l: Jankowski) -> Self {
        ContactLaw::Jankowski(l)
    }
}

impl ContactLaw {
    /// Short name: `kelvin`, `hertz`, `hertz-damp`, `bilinear`, `jankowski`.
    pub fn name(&self) -> &'static str {
        match self {
            ContactLaw::KelvinVoigt(_) => "kelvin",
            ContactLaw::Hertz(_) => "hertz",
            ContactLaw::HertzDamp(_) => "hertz-damp",
            ContactLaw::Bilinear(_) => "bilinear",
            ContactLaw::Jankowski(_) => "jankowski",
        }
    }

    /// Evaluates the law at trial penetration `delta` (`δ`, m) and rate `delta_dot` (`δ̇`, m/s)
    /// from the committed `state` (module doc: sign conventions and commit semantics).
    /// Non-finite inputs give a non-finite force (the caller's divergence check sees it).
    pub fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        match self {
            ContactLaw::KelvinVoigt(l) => l.evaluate(state, delta, delta_dot),
            ContactLaw::Hertz(l) => l.evaluate(state, delta, delta_dot),
            ContactLaw::HertzDamp(l) => l.evaluate(state, delta, delta_dot),
            ContactLaw::Bilinear(l) => l.evaluate(state, delta, delta_dot),
            ContactLaw::Jankowski(l) => l.evaluate(state, delta, delta_dot),
        }
    }

    /// `true` if the force depends on more than `(δ, δ̇)`: the bilinear law (committed `δ_c`,
    /// `F_c`) and Hertz-damp with per-impact damping (impact velocity recorded at onset).
    pub fn is_history_dependent(&self) -> bool {
        matches!(
            self,
            ContactLaw::Bilinear(_)
                | ContactLaw::HertzDamp(HertzDamp {
                    damping: HertzDamping::PerImpact { .. },
                    ..
                })
        )
    }

    /// Tangent stiffness of the elastic loading backbone at penetration `δ > 0` \[N/m\]: `k`
    /// (Kelvin), `(3/2) k_h δ^{1/2}` (Hertz, Hertz-damp, Jankowski with `β`), `K1` (bilinear:
    /// its stiffest branch, also the unloading slope). Used for time-step advice.
    pub fn backbone_stiffness(&self, delta: Real) -> Real {
        let d = delta.max(0.0);
        match self {
            ContactLaw::KelvinVoigt(l) => l.k,
            ContactLaw::Hertz(l) => 1.5 * l.k_h * d.sqrt(),
            ContactLaw::HertzDamp(l) => 1.5 * l.k_h * d.sqrt(),
            ContactLaw::Bilinear(l) => l.k1,
            ContactLaw::Jankowski(l) => 1.5 * l.beta * d.sqrt(),
        }
    }

    /// The penetration at which the law's elastic loading backbone stores the kinetic energy
    /// `½ m_eff v²` of the relative approach: the undamped estimate of the peak penetration.
    /// ```text
    /// Kelvin:                      δ* = v √(m_eff / k)
    /// Hertz, Hertz-damp, Jankowski: δ* = (5 m_eff v² / (4 k_h))^{2/5}
    /// bilinear: on the envelope, ½ K1 δy² + K1 δy s + ½ K2 s² = ½ m_eff v², δ* = δy + s
    /// ```
    /// `m_eff > 0`, `v ≥ 0` (returns `0` for `v = 0`).
    pub fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        let ek = 0.5 * m_eff * v * v;
        let hertz = |k: Real| (2.5 * ek / k).powf(0.4);
        match self {
            ContactLaw::KelvinVoigt(l) => v.abs() * (m_eff / l.k).sqrt(),
            ContactLaw::Hertz(l) => hertz(l.k_h),
            ContactLaw::HertzDamp(l) => hertz(l.k_h),
            ContactLaw::Jankowski(l) => hertz(l.beta),
            ContactLaw::Bilinear(l) => {
                let e_y = 0.5 * l.k1 * l.delta_y * l.delta_y;
                if ek <= e_y {
                    v.abs() * (m_eff / l.k1).sqrt()
                } else {
                    let r = ek - e_y;
                    let b = l.k1 * l.delta_y;
                    let s = 2.0 * r / (b + (b * b + 2.0 * l.k2 * r).sqrt());
                    l.delta_y + s
                }
            }
        }
    }
}
