//! Damping calibrations from a target coefficient of restitution `e ∈ (0, 1]`.
//!
//! The *restitution* of a law is the rebound ratio `e = −δ̇⁺/δ̇⁻` of an isolated collision of two
//! free masses through it ([`super::collision`]). By dimensional analysis it depends on a single
//! dimensionless damping parameter per law:
//!
//! | law | parameter | dimensional value | depends on the impact velocity `v_i`? |
//! |---|---|---|---|
//! | Kelvin–Voigt | damping ratio `ξ` | `c = 2 ξ √(k m_eff)` | no (depends on the masses) |
//! | Hertz-damp | `χ = ζ v_i / k_h` | `ζ = χ k_h / v_i` | **yes**: `ζ ∝ 1/v_i` |
//! | Jankowski | damping ratio `ξ` | `c(δ) = 2 ξ √(β √δ m_eff)` | no (depends on the masses) |
//! | bilinear | — (`K1, K2, δy` from `δm`) | [`super::BilinearImpact::from_hertz`] | through the design `δm` |
//!
//! **Numerical** calibration (the default, [`KelvinCalibration::Numerical`] etc.): the
//! dimensionless collision (`m1 = m2 = 2`, so `m_eff = 1`; unit stiffness; approach velocity 1)
//! is integrated with [`super::collision::simulate_collision`] (RK4, 4000 steps per contact,
//! end of contact located by bisection) and the parameter is root-found by a bracketed
//! Illinois (modified regula falsi) iteration on `e(p) − e_target`, `e(p)` decreasing from
//! `e(0) = 1`. The result makes the law rebound with the target `e` (to ~1e-7), **including the
//! no-tension clamp** that ends the contact when the force returns to zero. See
//! [`calibrate`] for the details and status.
//!
//! **Closed forms** (published; approximate for the laws as defined here):
//! * Anagnostopoulos (1988), Kelvin: `ξ = −ln e / √(π² + ln² e)` — exact for a linear oscillator
//!   whose contact ends at `δ = 0` (allowing tension at the end); with the no-tension clamp the
//!   contact ends earlier and the rebound is higher than `e`.
//! * Muthukumar & DesRoches (2006), Hertz-damp: `ζ = 3 k_h (1 − e²) / (4 v_i)`, i.e.
//!   `χ = 3 (1 − e²)/4` (Lankarani–Nikravesh; accurate for `e → 1`).
//! * Ye, Li & Zhu (2009), Hertz-damp: `ζ = 8 k_h (1 − e) / (5 e v_i)`, i.e. `χ = 8 (1 − e)/(5 e)`.
//! * Jankowski (2005): `ξ = 9√5 (1 − e²) / (2 e (e (9π − 16) + 16))`.
//!
//! The tests measure the rebound each closed form really gives (see the README section).

use super::collision::{CollisionSettings, CollisionStatus, TwoMassImpact, simulate_collision};
use super::{
    ContactLaw, ContactLawError, HertzDamp, HertzDamping, Jankowski, KelvinVoigt, restitution,
};
use crate::math::Real;
use std::f64::consts::PI;

/// Calibration of the Kelvin–Voigt damping ratio `ξ`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum KelvinCalibration {
    /// Root-found so that the clamped law rebounds with `e` (module doc).
    #[default]
    Numerical,
    /// Anagnostopoulos (1988): `ξ = −ln e / √(π² + ln² e)`.
    Anagnostopoulos,
}

/// Calibration of the Hertz-damp dimensionless damping `χ = ζ v_i / k_h`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum HertzDampCalibration {
    /// Root-found so that the law rebounds with `e` (module doc).
    #[default]
    Numerical,
    /// Muthukumar & DesRoches (2006): `χ = 3 (1 − e²)/4`.
    MuthukumarDesRoches,
    /// Ye, Li & Zhu (2009): `χ = 8 (1 − e)/(5 e)`.
    YeEtAl,
}

/// Calibration of the Jankowski damping ratio `ξ`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum JankowskiCalibration {
    /// Root-found so that the law rebounds with `e` (module doc).
    #[default]
    Numerical,
    /// Jankowski (2005): `ξ = 9√5 (1 − e²) / (2 e (e (9π − 16) + 16))`.
    Jankowski2005,
}

/// Which dimensionless law a numerical calibration acts on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DampedLaw {
    /// Kelvin–Voigt, parameter `ξ` (`k = 1`, `c = 2ξ`).
    Kelvin,
    /// Hertz-damp, parameter `χ` (`k_h = 1`, per-impact damping).
    HertzDamp,
    /// Jankowski, parameter `ξ` (`β = 1`, `m_eff = 1`).
    Jankowski,
}

/// Outcome of a numerical calibration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CalibrationStatus {
    /// `|e(p) − e_target| ≤ 1e-10` or the bracket shrank to rounding.
    Converged,
    /// No parameter up to 1e12 damps the rebound below the target (unreachable target).
    NotBracketed,
    /// The iteration limit (200) was reached; `parameter` is the best iterate.
    MaxIterations,
}

/// A numerical calibration: the parameter, the restitution it gives and the status.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Calibration {
    /// The dimensionless damping parameter (`ξ` or `χ`).
    pub parameter: Real,
    /// The restitution the dimensionless collision gives with `parameter`.
    pub achieved: Real,
    /// Evaluations of `e(p)` (collision integrations).
    pub evaluations: usize,
    /// Outcome.
    pub status: CalibrationStatus,
}

fn dimensionless_law(law: DampedLaw, p: Real) -> Result<ContactLaw, ContactLawError> {
    Ok(match law {
        DampedLaw::Kelvin => KelvinVoigt::new(1.0, 2.0 * p)?.into(),
        DampedLaw::HertzDamp => HertzDamp::new(
            1.0,
            HertzDamping::PerImpact {
                chi: p,
                min_velocity: 1e-12,
            },
        )?
        .into(),
        DampedLaw::Jankowski => Jankowski::new(1.0, p, 1.0)?.into(),
    })
}

/// The restitution `e(p)` of the dimensionless isolated collision (`m_eff = 1`, unit stiffness,
/// approach velocity 1) of `law` with damping parameter `p ≥ 0` (module doc), integrated with
/// `settings`. `NaN` if the integration did not separate.
pub fn restitution_of(
    law: DampedLaw,
    p: Real,
    settings: &CollisionSettings,
) -> Result<Real, ContactLawError> {
    let l = dimensionless_law(law, p)?;
    let problem = TwoMassImpact::new(2.0, 2.0, 1.0, 0.0)?;
    let r = simulate_collision(&l, &problem, settings)?;
    Ok(if r.status == CollisionStatus::Separated {
        r.restitution
    } else {
        Real::NAN
    })
}

/// Root-finds the damping parameter `p ≥ 0` of `law` with `e(p) = e` (module doc), starting the
/// bracket at `guess > 0` (doubled until `e(p) < e`, up to `1e12`), then Illinois iterations.
/// `e = 1` gives `p = 0`. Errors only for `e ∉ (0, 1]` (named `restitution`) or a bad `guess`.
pub fn calibrate(
    law: DampedLaw,
    e: Real,
    guess: Real,
    settings: &CollisionSettings,
) -> Result<Calibration, ContactLawError> {
    let e = restitution("restitution", e)?;
    let guess = super::positive("guess", guess)?;
    if e == 1.0 {
        return Ok(Calibration {
            parameter: 0.0,
            achieved: 1.0,
            evaluations: 0,
            status: CalibrationStatus::Converged,
        });
    }
    let mut evaluations = 0;
    let mut g = |p: Real| -> Result<Real, ContactLawError> {
        evaluations += 1;
        Ok(restitution_of(law, p, settings)? - e)
    };
    let (mut a, mut ga) = (0.0, 1.0 - e);
    let mut b = guess;
    let mut gb = g(b)?;
    while gb.is_nan() || gb >= 0.0 {
        if gb.is_nan() || b > 1e12 {
            return Ok(Calibration {
                parameter: b,
                achieved: gb + e,
                evaluations,
                status: CalibrationStatus::NotBracketed,
            });
        }
        if gb > 0.0 {
            a = b;
            ga = gb;
        }
        b *= 2.0;
        gb = g(b)?;
    }
    // Illinois: regula falsi with halving of the retained end's value.
    let mut side = 0i8;
    for _ in 0..200 {
        let c = (a * gb - b * ga) / (gb - ga);
        let c = if c > a.min(b) && c < a.max(b) {
            c
        } else {
            0.5 * (a + b)
        };
        let gc = g(c)?;
        if gc.abs() <= 1e-10 || (b - a).abs() <= 1e-14 * b.abs().max(a.abs()) {
            return Ok(Calibration {
                parameter: c,
                achieved: gc + e,
                evaluations,
                status: CalibrationStatus::Converged,
            });
        }
        if gc.is_nan() {
            break;
        }
        if gc > 0.0 {
            a = c;
            ga = gc;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        } else {
            b = c;
            gb = gc;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        }
    }
    let c = 0.5 * (a + b);
    let gc = g(c)?;
    Ok(Calibration {
        parameter: c,
        achieved: gc + e,
        evaluations,
        status: CalibrationStatus::MaxIterations,
    })
}

fn numerical(law: DampedLaw, e: Real, guess: Real) -> Result<Real, ContactLawError> {
    let c = calibrate(law, e, guess.max(1e-6), &CollisionSettings::default())?;
    if c.status == CalibrationStatus::Converged {
        Ok(c.parameter)
    } else {
        Err(ContactLawError::InvalidParameter {
            name: "restitution".into(),
            value: e,
            reason: format!("not reachable by the law's damping ({:?})", c.status),
        })
    }
}

/// Anagnostopoulos (1988): `ξ = −ln e / √(π² + ln² e)`, `e ∈ (0, 1]`.
pub fn anagnostopoulos_xi(e: Real) -> Result<Real, ContactLawError> {
    let l = restitution("restitution", e)?.ln();
    Ok(-l / (PI * PI + l * l).sqrt())
}

/// Muthukumar & DesRoches (2006): `χ = 3 (1 − e²)/4` (`ζ = χ k_h / v_i`), `e ∈ (0, 1]`.
pub fn muthukumar_desroches_chi(e: Real) -> Result<Real, ContactLawError> {
    let e = restitution("restitution", e)?;
    Ok(0.75 * (1.0 - e * e))
}

/// Ye, Li & Zhu (2009): `χ = 8 (1 − e)/(5 e)` (`ζ = χ k_h / v_i`), `e ∈ (0, 1]`.
pub fn ye_chi(e: Real) -> Result<Real, ContactLawError> {
    let e = restitution("restitution", e)?;
    Ok(1.6 * (1.0 - e) / e)
}

/// Jankowski (2005): `ξ = 9√5 (1 − e²) / (2 e (e (9π − 16) + 16))`, `e ∈ (0, 1]`.
pub fn jankowski2005_xi(e: Real) -> Result<Real, ContactLawError> {
    let e = restitution("restitution", e)?;
    Ok(9.0 * 5f64.sqrt() * (1.0 - e * e) / (2.0 * e * (e * (9.0 * PI - 16.0) + 16.0)))
}

/// Kelvin–Voigt damping ratio `ξ` (`c = 2 ξ √(k m_eff)`) for restitution `e ∈ (0, 1]`.
pub fn kelvin_damping_ratio(e: Real, method: KelvinCalibration) -> Result<Real, ContactLawError> {
    let guess = anagnostopoulos_xi(e)?;
    match method {
        KelvinCalibration::Anagnostopoulos => Ok(guess),
        KelvinCalibration::Numerical => numerical(DampedLaw::Kelvin, e, guess),
    }
}

/// Hertz-damp dimensionless damping `χ = ζ v_i / k_h` for restitution `e ∈ (0, 1]`.
pub fn hertz_damp_chi(e: Real, method: HertzDampCalibration) -> Result<Real, ContactLawError> {
    let guess = muthukumar_desroches_chi(e)?;
    match method {
        HertzDampCalibration::MuthukumarDesRoches => Ok(guess),
        HertzDampCalibration::YeEtAl => ye_chi(e),
        HertzDampCalibration::Numerical => numerical(DampedLaw::HertzDamp, e, guess),
    }
}

/// Jankowski damping ratio `ξ` for restitution `e ∈ (0, 1]`.
pub fn jankowski_xi(e: Real, method: JankowskiCalibration) -> Result<Real, ContactLawError> {
    let guess = jankowski2005_xi(e)?;
    match method {
        JankowskiCalibration::Jankowski2005 => Ok(guess),
        JankowskiCalibration::Numerical => numerical(DampedLaw::Jankowski, e, guess),
    }
}
