//! Time integration with stiff contact springs, and the time-step check.
//!
//! # Recommended integrator for the simulator
//! A compliance law adds a very stiff, nonlinear, possibly history-dependent spring between the
//! decks (for the OpenSees cross-check `K1 = 1.56e10 N/m` against `m_eff = 5e5 kg`:
//! contact duration `π √(m_eff/K1) ≈ 17.8 ms`, against bearing periods of 0.5–1 s). The
//! recommended scheme is the one OpenSees uses for that benchmark, and the smooth part of the
//! rigid simulator already uses: **Newmark average acceleration** (trapezoidal rule, `γ = ½`,
//! `β = ¼`), implicit, with a **Newton iteration on the contact forces** at every step:
//! * the residual `M a_{n+1} + C v_{n+1} + K q_{n+1} + W F(δ_{n+1}, δ̇_{n+1}) − P_{n+1} = 0`, with the
//!   contact forces from [`super::ContactLaw::evaluate`] at the trial state (always from the
//!   **committed** law state of step `n`),
//! * the tangent from [`super::Evaluation::stiffness`] and [`super::Evaluation::damping`]
//!   (`K_t = K + W (k_c + γ/(β h) c_c) Wᵀ + …`),
//! * commit the law states only when the step has converged (the OpenSees commit semantics).
//!
//! It is unconditionally stable for the linear part and does not dissipate numerically, so all
//! contact dissipation comes from the law. Stability is not the limit; **accuracy** is: the
//! contact pulse must be resolved, which needs `Δt ≤ T_c / 20` with `T_c = π √(m_eff / K)` the
//! contact duration of the linearised contact (`K` the law's stiffest backbone tangent). An
//! explicit scheme (central differences) would also need `Δt < 2/ω = (2/π) T_c` for stability;
//! the accuracy bound is stricter, so it would work with the same step but without the
//! Newton iteration — at the price of the dashpot's conditional stability. With the bilinear
//! law, note OpenSees' first-step quirk (the closing step's increment starts from the open gap,
//! [`super::BilinearImpact`]): the force overshoot is at most `K1 |δ̇| Δt`, another reason for a
//! small step.
//!
//! [`time_step_advice`] computes `T_c` and the ratio; callers should warn when
//! [`TimeStepAdvice::adequate`] is `false`.

use super::{ContactLaw, ContactLawError, positive};
use crate::math::Real;
use std::f64::consts::PI;

/// Minimum number of steps per contact duration for an adequately resolved contact.
pub const MIN_STEPS_PER_CONTACT: Real = 20.0;

/// The time-step check for one contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeStepAdvice {
    /// Linearised contact duration `T_c = π √(m_eff / K)` \[s\].
    pub contact_duration: Real,
    /// `T_c / Δt`.
    pub steps_per_contact: Real,
    /// Largest adequate step `T_c / 20` \[s\].
    pub max_step: Real,
    /// `Δt ≤ T_c / 20`.
    pub adequate: bool,
}

/// Linearised contact duration `T_c = π √(m_eff / K)` \[s\] (half period of the contact
/// oscillator), `m_eff > 0` \[kg\], `K > 0` \[N/m\].
pub fn contact_duration(m_eff: Real, stiffness: Real) -> Result<Real, ContactLawError> {
    let m = positive("m_eff", m_eff)?;
    let k = positive("stiffness", stiffness)?;
    Ok(PI * (m / k).sqrt())
}

/// Checks `Δt ≤ T_c / 20` with `T_c = π √(m_eff / K)`.
pub fn time_step_advice(
    dt: Real,
    m_eff: Real,
    stiffness: Real,
) -> Result<TimeStepAdvice, ContactLawError> {
    let dt = positive("dt", dt)?;
    let t_c = contact_duration(m_eff, stiffness)?;
    let max_step = t_c / MIN_STEPS_PER_CONTACT;
    Ok(TimeStepAdvice {
        contact_duration: t_c,
        steps_per_contact: t_c / dt,
        max_step,
        adequate: dt <= max_step,
    })
}

/// [`time_step_advice`] for `law`, with `K` its backbone tangent
/// ([`ContactLaw::backbone_stiffness`]) at the undamped peak penetration of an impact at
/// `v_ref > 0` ([`ContactLaw::backbone_penetration`]). For the linear and bilinear laws `K` does
/// not depend on `v_ref` (`k`, `K1`); for the Hertz-type laws it grows like `v_ref^{1/5}`.
pub fn law_time_step_advice(
    law: &ContactLaw,
    dt: Real,
    m_eff: Real,
    v_ref: Real,
) -> Result<TimeStepAdvice, ContactLawError> {
    let m = positive("m_eff", m_eff)?;
    let v = positive("v_ref", v_ref)?;
    let k = law.backbone_stiffness(law.backbone_penetration(m, v));
    time_step_advice(dt, m, k)
}
