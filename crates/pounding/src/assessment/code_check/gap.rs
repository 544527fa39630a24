//! Joint gap rules of [`super`]: the SRSS and double-difference (CQC) rules.

use super::{CodeCheckError, non_negative, positive};

/// CQC correlation of two modes of equal damping ratio `ξ` and period ratio `r = T₂/T₁`:
/// `ρ = 8 ξ² (1 + r) r^{3/2} / ((1 − r²)² + 4 ξ² r (1 + r)²)` (Der Kiureghian 1981).
pub fn cqc_rho(t1: f64, t2: f64, xi: f64) -> Result<f64, CodeCheckError> {
    let r = positive("period_2_s", t2)? / positive("period_1_s", t1)?;
    let xi = non_negative("damping", xi)?;
    let den = (1.0 - r * r).powi(2) + 4.0 * xi * xi * r * (1.0 + r).powi(2);
    if den == 0.0 {
        // undamped and equal periods (0/0): the limit along equal periods is 1 — the frames
        // move in phase (the form is 1 at r = 1 for every ξ > 0)
        return Ok(1.0);
    }
    Ok(8.0 * xi * xi * (1.0 + r) * r.powf(1.5) / den)
}

/// Required joint gap by the SRSS rule (m): `√(u₁² + u₂²)`.
pub fn gap_srss(u1: f64, u2: f64) -> Result<f64, CodeCheckError> {
    Ok(non_negative("u_1_m", u1)?.hypot(non_negative("u_2_m", u2)?))
}

/// Required joint gap by the double-difference (CQC) rule (m):
/// `√(u₁² + u₂² − 2 ρ₁₂ u₁ u₂)`, `ρ₁₂` from [`cqc_rho`] of the two frames' periods.
pub fn gap_ddc(u1: f64, u2: f64, t1: f64, t2: f64, xi: f64) -> Result<f64, CodeCheckError> {
    let (u1, u2) = (non_negative("u_1_m", u1)?, non_negative("u_2_m", u2)?);
    let rho = cqc_rho(t1, t2, xi)?;
    // ρ ≤ 1, so the radicand is ≥ (u₁ − u₂)² ≥ 0 but for rounding; `max` would turn a NaN into
    // 0 (a zero gap that passes): a non-finite ρ is an error instead
    if !rho.is_finite() {
        return Err(CodeCheckError::OutOfRange {
            key: "damping",
            what: "a ratio giving a finite correlation for these periods",
            value: xi,
        });
    }
    Ok((u1 * u1 + u2 * u2 - 2.0 * rho * u1 * u2).max(0.0).sqrt())
}
