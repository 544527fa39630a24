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
//! | [`LinearSpring`] | `F = k δ` | `k` | (elastic spring, no damping) |
//!
//! Every law implements [`ContactForceLaw`] in its own file (`kelvin.rs`, `hertz.rs`,
//! `hertz_damp.rs`, `bilinear.rs`, `jankowski.rs`, `linear.rs`), which also holds its registry
//! entry (`ENTRY`: `[contact]` name, keys, the keys read for the keys given, description) and the
//! `build` function that makes it
//! from the `[contact]` keys and their defaults. One invocation of `contact_laws!` in this file,
//! one line per law, generates the rest: the module declarations and re-exports, the `Copy` enum
//! [`ContactLaw`] with its one dispatch ([`ContactLaw::as_law`]), and [`registry::LAWS`].
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
pub mod estimate;
pub mod registry;
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

/// The interface every normal contact law implements (one file per law in this module; the
/// scenario keys and defaults of each law are in [`registry`]).
///
/// Sign conventions and the commit semantics of [`LawState`] are in the module doc.
pub trait ContactForceLaw {
    /// The `[contact] law` name (e.g. `kelvin`).
    fn name(&self) -> &'static str;
    /// Evaluates the law at trial penetration `delta` (`δ`, m) and rate `delta_dot` (`δ̇`, m/s)
    /// from the committed `state`: the force, `∂F/∂δ`, `∂F/∂δ̇` and the trial state.
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation;
    /// `true` if the force depends on more than `(δ, δ̇)` (committed state). Default `false`.
    fn is_history_dependent(&self) -> bool {
        false
    }
    /// Tangent stiffness of the elastic loading backbone at penetration `δ` \[N/m\] (time-step
    /// advice).
    fn backbone_stiffness(&self, delta: Real) -> Real;
    /// The penetration at which the elastic loading backbone stores `½ m_eff v²` (undamped
    /// peak-penetration estimate); `0` for `v = 0`.
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real;
    /// The law and its parameters for `summary.json` (`{"law": name, ...}`).
    fn describe(&self) -> serde_json::Value;
}

/// `δ* = (5 m_eff v² / (4 k))^{2/5}`: the backbone penetration of the `k δ^{3/2}` laws.
pub(crate) fn hertz_backbone_penetration(k: Real, m_eff: Real, v: Real) -> Real {
    let ek = 0.5 * m_eff * v * v;
    (2.5 * ek / k).powf(0.4)
}

/// Declares every compliance law from the one list below: for each entry
/// `module::Variant(Type, extra re-exports…)` it declares the law's file `module.rs` (private),
/// re-exports `Type` (and the extras) as `contact_law::Type`, adds the variant
/// `ContactLaw::Variant(Type)` with its `From<Type>` conversion and its arm of the one dispatch
/// [`ContactLaw::as_law`], and puts the file's `ENTRY` ([`registry::LawEntry`]: `[contact]` name,
/// keys, the keys read ([`registry::LawEntry::reads`]), description, builder) into
/// [`registry::LAWS`], in list order.
///
/// **Adding a law** is therefore one new file `contact_law/<module>.rs` (the law, its
/// [`ContactForceLaw`] impl, its `pub(crate) const ENTRY` and `build`) plus one line in the list.
macro_rules! contact_laws {
    ($($module:ident::$variant:ident($ty:ident $(, $extra:ident)*),)*) => {
        $(mod $module;)*
        $(pub use $module::{$ty $(, $extra)*};)*

        /// A validated normal contact law (see the module doc for the table of laws).
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum ContactLaw {
            $(
                #[doc = concat!("[`", stringify!($ty), "`] (file `contact_law/", stringify!($module), ".rs`).")]
                $variant($ty),
            )*
        }
        $(impl From<$ty> for ContactLaw {
            fn from(l: $ty) -> Self {
                ContactLaw::$variant(l)
            }
        })*
        impl ContactLaw {
            /// The law behind the enum (the single dispatch point).
            pub fn as_law(&self) -> &dyn ContactForceLaw {
                match self {
                    $(ContactLaw::$variant(l) => l,)*
                }
            }
        }

        /// The registry entries of the laws, in list order ([`registry::LAWS`]).
        const ENTRIES: &[registry::LawEntry] = &[$($module::ENTRY,)*];
    };
}

// The registry of compliance laws: one line per law (`module::Variant(Type, re-exports…)`).
contact_laws! {
    kelvin::KelvinVoigt(KelvinVoigt),
    hertz::Hertz(Hertz),
    hertz_damp::HertzDamp(HertzDamp, HertzDamping),
    bilinear::Bilinear(BilinearImpact, BilinearDerivation),
    jankowski::Jankowski(Jankowski),
    linear::Linear(LinearSpring),
}

impl ContactLaw {
    /// Short name: `kelvin`, `hertz`, `hertz-damp`, `bilinear`, `jankowski`, `linear`.
    pub fn name(&self) -> &'static str {
        self.as_law().name()
    }

    /// Evaluates the law at trial penetration `delta` (`δ`, m) and rate `delta_dot` (`δ̇`, m/s)
    /// from the committed `state` (module doc: sign conventions and commit semantics).
    /// Non-finite inputs give a non-finite force (the caller's divergence check sees it).
    pub fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        self.as_law().evaluate(state, delta, delta_dot)
    }

    /// `true` if the force depends on more than `(δ, δ̇)`: the bilinear law (committed `δ_c`,
    /// `F_c`) and Hertz-damp with per-impact damping (impact velocity recorded at onset).
    pub fn is_history_dependent(&self) -> bool {
        self.as_law().is_history_dependent()
    }

    /// Tangent stiffness of the elastic loading backbone at penetration `δ > 0` \[N/m\]: `k`
    /// (Kelvin, linear), `(3/2) k_h δ^{1/2}` (Hertz, Hertz-damp, Jankowski with `β`), `K1`
    /// (bilinear: its stiffest branch, also the unloading slope). Used for time-step advice.
    pub fn backbone_stiffness(&self, delta: Real) -> Real {
        self.as_law().backbone_stiffness(delta)
    }

    /// The penetration at which the law's elastic loading backbone stores the kinetic energy
    /// `½ m_eff v²` of the relative approach: the undamped estimate of the peak penetration.
    /// ```text
    /// Kelvin, linear:              δ* = v √(m_eff / k)
    /// Hertz, Hertz-damp, Jankowski: δ* = (5 m_eff v² / (4 k_h))^{2/5}
    /// bilinear: on the envelope, ½ K1 δy² + K1 δy s + ½ K2 s² = ½ m_eff v², δ* = δy + s
    /// ```
    /// `m_eff > 0`, `v ≥ 0` (returns `0` for `v = 0`).
    pub fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        self.as_law().backbone_penetration(m_eff, v)
    }

    /// The law and its parameters as written in `summary.json`.
    pub fn describe(&self) -> serde_json::Value {
        self.as_law().describe()
    }
}
