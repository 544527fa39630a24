//! Peak-force estimate of a rigid-law impact from its impulse (a documented contact-duration
//! model; labelled an *estimate* wherever it is written).
//!
//! The rigid law resolves an impact instantaneously: it yields the normal impulse `P` and the
//! approach velocity `v = |γ_N⁻|`, not a force. A force follows only with a contact duration. The
//! model here takes it from **Hertz's elastic impact** of the two colliding bodies:
//! ```text
//! F = k_h δ^{3/2}                                   (Hertz contact, k_h = (4/3) E* √R*)
//! m_eff = P / ((1 + ε_N) v)                         (the effective mass the impulse implies)
//! δ_max = (5 m_eff v² / (4 k_h))^{2/5}              (undamped peak penetration)
//! t_c   = 2 δ_max/v ∫₀¹ (1 − x^{5/2})^{−1/2} dx = C_H δ_max / v,   C_H = (4/5) B(2/5, 1/2) ≈ 2.94327
//! F_est = π P / (2 t_c)                             (a half-sine pulse of impulse P and duration t_c)
//! ```
//! For two bodies of the same material with Young's modulus `E` and Poisson's ratio `ν`,
//! `E* = E / (2 (1 − ν²))`; for two spheres of radius `R`, `R* = R/2`. The default
//! `k_h = 25 000 kip/in^{3/2} ≈ 2.75e10 N/m^{3/2}` ([`super::registry::default_k_h`],
//! Muthukumar & DesRoches 2006, the same default as the compliance law `hertz`) corresponds to
//! concrete (`E = 30 GPa`, `ν = 0.2`, `E* ≈ 15.6 GPa`) and `R* ≈ 1.74 m` (deck ends idealised as
//! spheres of radius ≈ 3.5 m).
//!
//! In the simulator's outputs `k_h` is the stiffness of a whole joint (or abutment face), shared
//! equally by its two corner contacts as the compliance laws share it
//! ([`super::sharing`]): each corner's row uses `k_h / 2` with that corner's `P` and `v`, so a
//! joint closing uniformly gets the same `t_c` as the joint as a whole and half its force per
//! corner.
//!
//! # Accuracy
//! * For an elastic impact (`ε_N = 1`, `P = 2 m_eff v`) the exact Hertz peak force is
//!   `k_h δ_max^{3/2}`; the half-sine gives `π (4/5) / C_H ≈ 0.8539` of it, i.e. the estimate is
//!   **14.6 % below** the Hertz peak (the Hertz pulse is more peaked than a half-sine of the same
//!   impulse and duration). Check it with a run of the compliance law `hertz` of the same `k_h`
//!   (`pounding compare`), which resolves the pulse.
//! * For `ε_N < 1` the duration is that of the elastic impact of the same `m_eff` and `v`; a
//!   dissipative pulse (e.g. `hertz_damp`) has a somewhat different duration.
//! * The estimate scales like `v^{6/5} m_eff^{3/5} k_h^{2/5}` (at fixed `ε_N`): a factor 2 error in
//!   `k_h` is a factor `2^{2/5} ≈ 1.32` in the estimate.
use crate::math::Real;
use std::f64::consts::PI;

/// `C_H = 2 ∫₀¹ (1 − x^{5/2})^{−1/2} dx = (4/5) B(2/5, 1/2)`: Hertz contact time `t_c = C_H δ_max / v`.
pub const HERTZ_CONTACT_TIME_FACTOR: Real = 2.943_275_4;

/// The peak-force estimate of one rigid impact (module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakForceEstimate {
    /// Estimated contact duration `t_c` \[s\].
    pub contact_time: Real,
    /// Estimated peak force `π P / (2 t_c)` \[N\].
    pub peak_force: Real,
}

/// The estimate (module doc) for a rigid impact of normal impulse `impulse_n = P ≥ 0` \[N s\],
/// pre-impact normal velocity `gamma_n_pre = γ_N⁻` (`< 0`, closing) \[m/s\], restitution
/// `restitution = ε_N ∈ [0, 1]` and Hertz stiffness `k_h > 0` \[N/m^{3/2}\]. NaN fields when
/// the inputs admit no estimate (no approach, no impulse).
pub fn rigid_peak_force(
    impulse_n: Real,
    gamma_n_pre: Real,
    restitution: Real,
    k_h: Real,
) -> PeakForceEstimate {
    let v = -gamma_n_pre;
    if !(v > 0.0 && impulse_n > 0.0 && k_h > 0.0 && restitution >= 0.0) {
        return PeakForceEstimate {
            contact_time: Real::NAN,
            peak_force: Real::NAN,
        };
    }
    let m_eff = impulse_n / ((1.0 + restitution) * v);
    let d_max = (5.0 * m_eff * v * v / (4.0 * k_h)).powf(0.4);
    let t_c = HERTZ_CONTACT_TIME_FACTOR * d_max / v;
    PeakForceEstimate {
        contact_time: t_c,
        peak_force: PI * impulse_n / (2.0 * t_c),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `C_H` by quadrature (substitution `x = 1 − s²` removes the endpoint singularity).
    #[test]
    fn contact_time_factor_by_quadrature() {
        let n = 200_000;
        let mut sum = 0.0;
        for i in 0..n {
            let s = (i as Real + 0.5) / n as Real;
            let x: Real = 1.0 - s * s;
            // dx = 2 s ds; 1 − x^{5/2} ~ (5/2) s² near s = 0
            sum += 2.0 * s / (1.0 - x.powf(2.5)).sqrt() / n as Real;
        }
        assert!(
            (2.0 * sum - HERTZ_CONTACT_TIME_FACTOR).abs() < 1e-5,
            "{}",
            2.0 * sum
        );
    }

    #[test]
    fn no_approach_gives_nan() {
        assert!(rigid_peak_force(1.0, 0.1, 0.5, 1e10).peak_force.is_nan());
        assert!(rigid_peak_force(0.0, -0.1, 0.5, 1e10).contact_time.is_nan());
    }
}
