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
//! For any diagonal `D > 0`, with `z = D z̃` and `w̃ = D w`,
//!
//! ```text
//! w̃ = M̃ z̃ + q̃,     M̃ = D M D,     q̃ = D q,
//! z̃ᵢ w̃ᵢ = zᵢ wᵢ,    z̃ ≥ 0 ⇔ z ≥ 0,    w̃ ≥ 0 ⇔ w ≥ 0,
//! ```
//!
//! so `(z̃, w̃)` solves the scaled LCP iff `(z, w)` solves the original one. `D` is chosen as the
//! approximate minimiser of the log-least-squares imbalance
//!
//! ```text
//! Φ(x) = Σ_{Mᵢⱼ ≠ 0} (log₂|Mᵢⱼ| + xᵢ + xⱼ)²,      Dᵢ = 2^{xᵢ},
//! ```
//!
//! by Gauss–Seidel sweeps: for each `i` in turn, `xᵢ` moves by `−round(mᵢ/2)` where `mᵢ` is the mean
//! of `log₂|M̃ᵢⱼ|` over the nonzeros of row `i` and column `i` of the current `M̃` (the diagonal
//! counted in both). This is geometric-mean (Ruiz-style) scaling; unlike the ∞-norm Ruiz sweep it
//! also balances a block of tiny entries against unit couplings (for the impact LCP it finds
//! `D ≈ diag(G_NN^{-1/2}, G_NN^{-1/2}, G_NN^{1/2})`, i.e. the `G/G_NN` normalisation, whereas the
//! ∞-norm sweep sees the unit couplings `±1, 2μ` and does nothing). Every `Dᵢ` is a power of two,
//! so `M̃`, `q̃` and `z = D z̃` are computed **exactly** — the scaled problem is the same LCP, not
//! an approximation of it. Sweeps stop when no exponent moves (at most [`MAX_SWEEPS`]).

/// Maximum number of Gauss–Seidel sweeps of the equilibration.
pub(crate) const MAX_SWEEPS: usize = 32;

/// Writes `M̃ = D M D` into `ms`, `q̃ = D q` into `qs` and `D` into `dsc` (all row-major / length
/// `n`). Returns `false` (and leaves the outputs unspecified) when the data are not finite or `D`
/// is the identity, i.e. when a retry cannot change anything.
pub(crate) fn equilibrate(
    n: usize,
    m: &[f64],
    q: &[f64],
    ms: &mut [f64],
    qs: &mut [f64],
    dsc: &mut [f64],
) -> bool {
    let m = &m[..n * n];
    let q = &q[..n];
    let ms = &mut ms[..n * n];
    let qs = &mut qs[..n];
    let dsc = &mut dsc[..n];
    if m.iter().chain(q).any(|x| !x.is_finite()) {
        return false;
    }
    ms.copy_from_slice(m);
    // exponents of D (integers, kept in `dsc` until the end: no allocation), D = 2^e
    dsc.fill(0.0);
    let mut changed_any = false;
    for _ in 0..MAX_SWEEPS {
        let mut moved = false;
        for i in 0..n {
            let mut sum = 0.0f64;
            let mut cnt = 0usize;
            for j in 0..n {
                for v in [ms[i * n + j], ms[j * n + i]] {
                    if v != 0.0 {
                        sum += v.abs().log2();
                        cnt += 1;
                    }
                }
            }
            if cnt == 0 {
                continue;
            }
            let step = -(sum / cnt as f64 / 2.0).round();
            // keep the scaled entries far from overflow/underflow
            let step = step.clamp(-256.0, 256.0) as i32;
            if step == 0 {
                continue;
            }
            moved = true;
            dsc[i] += step as f64;
            let f = 2f64.powi(step);
            for j in 0..n {
                ms[i * n + j] *= f;
                ms[j * n + i] *= f;
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
        dsc[i] = 2f64.powi(dsc[i] as i32);
        qs[i] = dsc[i] * q[i];
    }
    // rescale from the original data (exact: powers of two), so that no sweep's rounding stays
    for i in 0..n {
        for j in 0..n {
            ms[i * n + j] = dsc[i] * m[i * n + j] * dsc[j];
        }
    }
    ms.iter().chain(qs.iter()).all(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impact_lcp_is_normalised_by_g_nn() {
        let g = 1e-6;
        let m = [1.2 * g, 0.4 * g, 0.0, 0.4 * g, 3.2 * g, 1.0, 0.0, -1.0, 0.0];
        let q = [-1.5, -0.47, 0.0];
        let (mut ms, mut qs, mut d) = ([0.0; 9], [0.0; 3], [0.0; 3]);
        assert!(equilibrate(3, &m, &q, &mut ms, &mut qs, &mut d));
        // D = diag(~g^{-1/2}, ~g^{-1/2}, ~g^{1/2}) up to powers of two
        for (i, want) in [(0, 1e3), (1, 1e3), (2, 1e-3)] {
            let r = d[i] / want;
            assert!((0.1..10.0).contains(&r), "D[{i}] = {}", d[i]);
        }
        for i in 0..3 {
            for j in 0..3 {
                assert_eq!(ms[i * 3 + j], d[i] * m[i * 3 + j] * d[j]);
                if m[i * 3 + j] != 0.0 {
                    assert!((0.05..20.0).contains(&ms[i * 3 + j].abs()));
                }
            }
            assert_eq!(qs[i], d[i] * q[i]);
            assert_eq!(d[i].log2().fract(), 0.0, "power of two");
        }
    }

    #[test]
    fn identity_and_non_finite_need_no_retry() {
        let m = [1.0, 0.5, -0.5, 2.0];
        let (mut ms, mut qs, mut d) = ([0.0; 4], [0.0; 2], [0.0; 2]);
        assert!(!equilibrate(2, &m, &[-1.0, 1.0], &mut ms, &mut qs, &mut d));
        let m = [1.0, f64::NAN, -0.5, 2e-9];
        assert!(!equilibrate(2, &m, &[-1.0, 1.0], &mut ms, &mut qs, &mut d));
    }
}
