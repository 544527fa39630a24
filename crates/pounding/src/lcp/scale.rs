//! Symmetric diagonal equilibration of an LCP (the cold retry path of Lemke).
//!
//! # Why
//!
//! Lemke's tolerances are relative: the pivot tolerance to the entering column's largest entry,
//! the tie tolerance of the ratio test to `‖B⁻¹q‖∞`. Both mix the rows of the tableau, and the
//! rows carry *different units* when the LCP couples quantities of different physical kinds. The
//! impact LCP of spec §9 is the typical case: with `G` the Delassus matrix (1/kg) and `λ` the
//! impulses (N·s), `w₁, w₂` are velocities, `z₃ = γ` is a velocity and `w₃ = 2μλ_N − λ_T` is an
//! impulse. For a 10⁶-kg deck (`G ~ 10⁻⁶`) the basic variables of one tableau range from 10⁻⁶ to
//! 10⁶, a tie window `10⁻¹¹·‖b‖∞ ≈ 10⁻⁵` swallows genuinely different ratios, `z₀` wins a false tie
//! and the end point fails verification ([`LcpStatus::IllConditioned`](super::LcpStatus)).
//!
//! # The transformation
//!
//! The LCP conditions are componentwise, so any positive diagonal row scaling `R` and column
//! scaling `C` map solutions to solutions: with `z = C z̃` and `w̃ = R w`,
//!
//! ```text
//! w̃ = M̃ z̃ + q̃,     M̃ = R M C,     q̃ = R q,
//! z̃ ≥ 0 ⇔ z ≥ 0,    w̃ ≥ 0 ⇔ w ≥ 0,    z̃ᵢ w̃ᵢ = zᵢ wᵢ / (Cᵢ Rᵢ⁻¹)  (zero iff zero),
//! ```
//!
//! so `(z̃, w̃)` solves the scaled LCP iff `(z, w)` solves the original one (the symmetric choice
//! `R = C = D` is the special case `M̃ = D M D`). `R = 2^x`, `C = 2^y` approximately minimise the
//! log-least-squares imbalance
//!
//! ```text
//! Φ(x, y) = Σ_{Mᵢⱼ ≠ 0} (log₂|Mᵢⱼ| + xᵢ + yⱼ)²
//! ```
//!
//! by alternating sweeps: each row exponent `xᵢ` moves by `−round(mean_j log₂|M̃ᵢⱼ|)` over the
//! nonzeros of row `i` of the current `M̃`, then each column exponent likewise (block coordinate
//! descent on a convex quadratic; geometric-mean, Ruiz-style scaling). Unlike the ∞-norm Ruiz
//! sweep it also balances a block of tiny entries against unit couplings: for the impact LCP it
//! brings the `G` block to ~1 while `±1, 2μ` stay ~1 (the `G/G_NN` normalisation), whereas the
//! ∞-norm sweep sees the unit couplings and does nothing; and it undoes any row/column scaling
//! `R₀ M C₀` of a well-scaled matrix. Every factor is a power of two, so `M̃`, `q̃` and `z = C z̃`
//! are computed **exactly** — the scaled problem is the same LCP, not an approximation of it.
//! Sweeps stop when no exponent moves (at most [`MAX_SWEEPS`]).

/// Maximum number of Gauss–Seidel sweeps of the equilibration.
pub(crate) const MAX_SWEEPS: usize = 32;

/// Writes `M̃ = R M C` into `ms`, `q̃ = R q` into `qs`, `R` into `rs` and `C` into `cs` (all
/// row-major / length `n`). Returns `false` (outputs unspecified) when the data are not finite
/// or `R = C = I`, i.e. when a retry cannot change anything.
pub(crate) fn equilibrate(
    n: usize,
    m: &[f64],
    q: &[f64],
    ms: &mut [f64],
    qs: &mut [f64],
    rs: &mut [f64],
    cs: &mut [f64],
) -> bool {
    let m = &m[..n * n];
    let q = &q[..n];
    let ms = &mut ms[..n * n];
    let qs = &mut qs[..n];
    let rs = &mut rs[..n];
    let cs = &mut cs[..n];
    if m.iter().chain(q).any(|x| !x.is_finite()) {
        return false;
    }
    ms.copy_from_slice(m);
    // exponents (integers, kept in `rs`, `cs` until the end: no allocation), R = 2^x, C = 2^y
    rs.fill(0.0);
    cs.fill(0.0);
    let mut changed_any = false;
    // mean of log₂|·| over the nonzeros of a row (`row = true`) or column of the current M̃
    let mean = |ms: &[f64], i: usize, row: bool| -> Option<f64> {
        let (mut sum, mut cnt) = (0.0f64, 0usize);
        for j in 0..n {
            let v = if row { ms[i * n + j] } else { ms[j * n + i] };
            if v != 0.0 {
                sum += v.abs().log2();
                cnt += 1;
            }
        }
        (cnt > 0).then(|| sum / cnt as f64)
    };
    for _ in 0..MAX_SWEEPS {
        let mut moved = false;
        for row in [true, false] {
            for i in 0..n {
                let Some(mi) = mean(ms, i, row) else { continue };
                // keep the scaled entries far from overflow/underflow
                let step = (-mi.round()).clamp(-256.0, 256.0) as i32;
                if step == 0 {
                    continue;
                }
                moved = true;
                let f = 2f64.powi(step);
                if row {
                    rs[i] += step as f64;
                    ms[i * n..i * n + n].iter_mut().for_each(|x| *x *= f);
                } else {
                    cs[i] += step as f64;
                    (0..n).for_each(|j| ms[j * n + i] *= f);
                }
            }
        }
        changed_any |= moved;
        if !moved {
            break;
        }
    }
    if !changed_any {
        return false;
    }
    for i in 0..n {
        rs[i] = 2f64.powi(rs[i] as i32);
        cs[i] = 2f64.powi(cs[i] as i32);
        qs[i] = rs[i] * q[i];
    }
    // rescale from the original data (exact: powers of two)
    for i in 0..n {
        for j in 0..n {
            ms[i * n + j] = rs[i] * m[i * n + j] * cs[j];
        }
    }
    ms.iter().chain(qs.iter()).all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impact_lcp_is_balanced() {
        let g = 1e-6;
        let m = [1.2 * g, 0.4 * g, 0.0, 0.4 * g, 3.2 * g, 1.0, 0.0, -1.0, 0.0];
        let q = [-1.5, -0.47, 0.0];
        let (mut ms, mut qs, mut r, mut c) = ([0.0; 9], [0.0; 3], [0.0; 3], [0.0; 3]);
        assert!(equilibrate(3, &m, &q, &mut ms, &mut qs, &mut r, &mut c));
        // the G block is brought to ~1 while the unit couplings stay ~1 (R₁C₃ ≈ R₃C₁ ≈ 1)
        for i in 0..3 {
            for j in 0..3 {
                assert_eq!(ms[i * 3 + j], r[i] * m[i * 3 + j] * c[j]);
                if m[i * 3 + j] != 0.0 {
                    assert!((0.05..20.0).contains(&ms[i * 3 + j].abs()), "{ms:?}");
                }
            }
            assert_eq!(qs[i], r[i] * q[i]);
            assert_eq!(r[i].log2().fract(), 0.0, "power of two");
            assert_eq!(c[i].log2().fract(), 0.0, "power of two");
        }
    }

    #[test]
    fn identity_and_non_finite_need_no_retry() {
        let m = [1.0, 0.75, -1.5, 1.0];
        let (mut ms, mut qs, mut r, mut c) = ([0.0; 4], [0.0; 2], [0.0; 2], [0.0; 2]);
        assert!(!equilibrate(
            2,
            &m,
            &[-1.0, 1.0],
            &mut ms,
            &mut qs,
            &mut r,
            &mut c
        ));
        let m = [1.0, f64::NAN, -0.5, 2e-9];
        assert!(!equilibrate(
            2,
            &m,
            &[-1.0, 1.0],
            &mut ms,
            &mut qs,
            &mut r,
            &mut c
        ));
    }
}
