//! Pieces shared by the two Lemke kernels ([`super::lemke`]'s compact tableau and
//! [`super::full`]'s full tableau): the kernel result, the trivial shortcut and initial row, the
//! failure exit and the verification of a candidate solution (also used by
//! [`super::enumerate`]). Kept apart so that neither kernel module imports the other's internals.

use super::{LcpStatus, LemkeSettings};

/// Result of the kernel (the vectors are written into the caller's buffers).
#[derive(Debug, Clone, Copy)]
pub(crate) struct KernelOut {
    pub status: LcpStatus,
    pub pivots: usize,
    pub residual: f64,
}

/// Largest size solved by the full-tableau kernel (larger sizes use the compact one).
pub(crate) const FULL_MAX: usize = 6;

/// Verifies `z` against the original data and writes `w = M z + q`.
///
/// Returns `(passed, residual)` with `residual = maxᵢ |min(zᵢ, wᵢ)| / max(1, ‖q‖∞)` (reported
/// only). The test is **row by row**, relative to the rounding scale of each `wᵢ`,
///
/// ```text
/// sᵢ = |qᵢ| + Σⱼ |Mᵢⱼ zⱼ|,
/// wᵢ ≥ −tol·sᵢ   and   ( |wᵢ| ≤ tol·sᵢ   or   zᵢ is negligible ),
/// zᵢ negligible  ⇔  |Mₖᵢ zᵢ| ≤ tol·sₖ for every row k
/// ```
///
/// (`zᵢ` negligible: setting it to 0 moves no `wₖ` beyond its own tolerance; a negative `zᵢ`
/// must be negligible too). Each condition is invariant under positive row scaling `(M, q) →
/// (R M, R q)` and column scaling `M → M C`, `z → C⁻¹ z`, so it means the same for rows of
/// different units (velocities next to impulses) — an absolute or `‖q‖∞`-relative test would
/// accept, e.g., an impulse-row violation of 1e−14 N·s when the impulses themselves are 1e−9. A
/// non-finite number anywhere fails.
#[inline(always)]
pub(crate) fn verify(
    n: usize,
    m: &[f64],
    q: &[f64],
    z: &mut [f64],
    w: &mut [f64],
    tol: f64,
) -> (bool, f64) {
    let m = &m[..n * n];
    let q = &q[..n];
    let z = &mut z[..n];
    let w = &mut w[..n];
    let mut qn = 1.0f64;
    for &qi in q {
        qn = qn.max(qi.abs());
    }
    let mut res = 0.0f64;
    let mut finite = true;
    let mut ok = true;
    for i in 0..n {
        let row = &m[i * n..i * n + n];
        let mut wi = q[i];
        let mut si = q[i].abs();
        for j in 0..n {
            let t = row[j] * z[j];
            wi += t;
            si += t.abs();
        }
        w[i] = wi;
        let zi = z[i];
        let c = zi.min(wi);
        res = res.max(c.abs());
        finite &= c.is_finite() & si.is_finite();
        let lim = tol * si;
        // |wᵢ| ≤ lim ⇔ wᵢ ≤ lim given wᵢ ≥ −lim
        ok &= (wi >= -lim) & (zi >= 0.0) & ((wi <= lim) | (zi == 0.0));
    }
    if !ok && finite {
        // some wᵢ is neither ≈ 0 nor ≥ −tol·sᵢ with zᵢ = 0: the per-component test (cold)
        if let Some(r) = componentwise(n, m, q, z, w, tol) {
            (ok, res) = (true, r);
        }
    }
    (ok && finite, res / qn)
}

/// [`verify`] for `n ≤ FULL_MAX` (the full-tableau sizes), with the same result bit for bit:
/// `wᵢ` and `sᵢ` are accumulated column by column into stack arrays (`wᵢ = qᵢ + Mᵢ₀z₀ + Mᵢ₁z₁ + …`,
/// the same summation order as the row loop of [`verify`], so the same rounding), which lets the
/// compiler vectorise across rows; the row tests are then evaluated branch-free on the arrays.
/// Falls back to [`verify`] for larger `n`.
#[inline(always)]
pub(crate) fn verify_small(
    n: usize,
    m: &[f64],
    q: &[f64],
    z: &mut [f64],
    w: &mut [f64],
    tol: f64,
) -> (bool, f64) {
    if n > FULL_MAX {
        return verify(n, m, q, z, w, tol);
    }
    let m = &m[..n * n];
    let q = &q[..n];
    let z = &mut z[..n];
    let w = &mut w[..n];
    let mut wa = [0.0f64; FULL_MAX];
    let mut sa = [0.0f64; FULL_MAX];
    let mut qn = 1.0f64;
    for i in 0..n {
        wa[i] = q[i];
        sa[i] = q[i].abs();
        qn = qn.max(q[i].abs());
    }
    for j in 0..n {
        let zj = z[j];
        for i in 0..n {
            let t = m[i * n + j] * zj;
            wa[i] += t;
            sa[i] += t.abs();
        }
    }
    let mut res = 0.0f64;
    let mut finite = true;
    let mut ok = true;
    for i in 0..n {
        let wi = wa[i];
        let si = sa[i];
        w[i] = wi;
        let zi = z[i];
        let c = zi.min(wi);
        res = res.max(c.abs());
        finite &= c.is_finite() & si.is_finite();
        let lim = tol * si;
        // |wᵢ| ≤ lim ⇔ wᵢ ≤ lim given wᵢ ≥ −lim
        ok &= (wi >= -lim) & (zi >= 0.0) & ((wi <= lim) | (zi == 0.0));
    }
    if !ok
        && finite
        && let Some(r) = componentwise(n, m, q, z, w, tol)
    {
        (ok, res) = (true, r);
    }
    (ok && finite, res / qn)
}

/// The full test of [`verify`] (cold path: only when the plain row test fails). Entries of `z`
/// that are rounding noise are set aside first: `zⱼ` is *negligible* when, in every row `k` that
/// has other content (`rₖ = sₖ − |Mₖⱼ zⱼ| > 0`), `|Mₖⱼ zⱼ| ≤ tol·rₖ`, and there is such a row.
/// With `z'` = `z` without its negligible entries, `w' = M z' + q`, `s'ᵢ = |qᵢ| + Σⱼ |Mᵢⱼ z'ⱼ|`,
/// the test passes when `z' ≥ 0`, `w'ᵢ ≥ −tol·s'ᵢ` and `|w'ᵢ| ≤ tol·s'ᵢ` wherever `z'ᵢ ≠ 0`.
/// (A row that only a noise entry touches — `w₃ = 2μΛ_N − Λ_TR` with `μ = 0` and `Λ_TR ≈ 1e−17` —
/// has no scale of its own; it is judged without that entry.) When the test passes, the verified
/// `z'`, `w'` are what is reported (`z`, `w` overwritten) and the returned value is the raw residual
/// `maxᵢ |min(z'ᵢ, w'ᵢ)|`; `None` when it fails. (Reporting `z` itself was wrong: an entry that is
/// noise in every row with other content can be the *only* content of another row, e.g. `z₁ = 1e−3`
/// against `q₂ = 1e18` and `M₁₁ = 1e−299`, `q₁ = 0.16`, yet alone in a row with `q₀ = 0`; the full
/// `z` then broke `z₁ w₁ = 0` by far while `z'` = 0 is the true solution. Found by fuzzing.)
#[cold]
#[inline(never)]
fn componentwise(
    n: usize,
    m: &[f64],
    q: &[f64],
    z: &mut [f64],
    w: &mut [f64],
    tol: f64,
) -> Option<f64> {
    let s = |k: usize, zz: &dyn Fn(usize) -> f64| -> f64 {
        q[k].abs() + (0..n).map(|j| (m[k * n + j] * zz(j)).abs()).sum::<f64>()
    };
    let full = |j: usize| z[j];
    let negligible = |j: usize| -> bool {
        if z[j] == 0.0 {
            return true;
        }
        let mut any = false;
        for k in 0..n {
            let own = (m[k * n + j] * z[j]).abs();
            let rest = s(k, &full) - own;
            if rest > 0.0 {
                any = true;
                if own > tol * rest {
                    return false;
                }
            }
        }
        any
    };
    let keep: Vec<bool> = (0..n).map(|j| !negligible(j)).collect();
    let zc = |j: usize| if keep[j] { z[j] } else { 0.0 };
    for i in 0..n {
        let zi = zc(i);
        if zi < 0.0 {
            return None;
        }
        let wi = q[i] + (0..n).map(|j| m[i * n + j] * zc(j)).sum::<f64>();
        let lim = tol * s(i, &zc);
        if wi < -lim || (zi != 0.0 && wi.abs() > lim) {
            return None;
        }
    }
    let zv: Vec<f64> = (0..n).map(zc).collect();
    let mut res = 0.0f64;
    for i in 0..n {
        w[i] = q[i] + (0..n).map(|j| m[i * n + j] * zv[j]).sum::<f64>();
        z[i] = zv[i];
        res = res.max(z[i].min(w[i]).abs());
    }
    Some(res)
}

/// The slices of a kernel call cut to the problem size `n`: `M` (`n × n`), `q`, and the results
/// `z`, `w` (one bounds check here instead of one per access in the pivot loop).
#[inline(always)]
#[allow(clippy::type_complexity)]
pub(crate) fn cut_to_size<'p, 'r>(
    n: usize,
    m: &'p [f64],
    q: &'p [f64],
    z: &'r mut [f64],
    w: &'r mut [f64],
) -> (&'p [f64], &'p [f64], &'r mut [f64], &'r mut [f64]) {
    (&m[..n * n], &q[..n], &mut z[..n], &mut w[..n])
}

#[cold]
#[inline(never)]
pub(crate) fn fail(status: LcpStatus, pivots: usize, z: &mut [f64], w: &mut [f64]) -> KernelOut {
    z.fill(f64::NAN);
    w.fill(f64::NAN);
    KernelOut {
        status,
        pivots,
        residual: f64::NAN,
    }
}

/// The common prologue of both kernels: the trivial shortcut and the row of the first pivot.
///
/// Returns `Err(out)` when the kernel is done before any pivot — a non-finite `q`
/// ([`LcpStatus::IllConditioned`]), `q ≥ 0` (`z = 0`, `w = q`, solved with no pivot) or a pivot
/// budget of zero — and otherwise `Ok(r0)`, the row where `z₀` enters: the lexicographic minimum
/// of `[q_r | e_rᵀ]`, i.e. the largest index among the minima of `q` tied within
/// `tie_tol·‖q‖∞`.
#[inline(always)]
pub(crate) fn initial_row(
    n: usize,
    q: &[f64],
    s: &LemkeSettings,
    z: &mut [f64],
    w: &mut [f64],
) -> Result<usize, KernelOut> {
    let q = &q[..n];
    let mut qmin = f64::INFINITY;
    let mut qscale = 0.0f64;
    let mut finite = true;
    for &qi in q {
        qmin = qmin.min(qi);
        qscale = qscale.max(qi.abs());
        finite &= qi.is_finite();
    }
    if !finite {
        return Err(fail(LcpStatus::IllConditioned, 0, z, w));
    }
    if qmin >= 0.0 {
        for i in 0..n {
            z[i] = 0.0;
            w[i] = q[i];
        }
        return Err(KernelOut {
            status: LcpStatus::Solved,
            pivots: 0,
            residual: 0.0,
        });
    }
    let qtie = qmin + s.tie_tol() * qscale;
    let mut r0 = 0;
    for (i, &qi) in q.iter().enumerate() {
        r0 = if qi <= qtie { i } else { r0 }; // the largest index among the tied minima
    }
    if s.max_pivots() == 0 {
        return Err(fail(LcpStatus::MaxPivots, 0, z, w));
    }
    Ok(r0)
}

/// The kernels' exit once `z₀` has left: [`LcpStatus::Solved`] when the verification passed,
/// else [`LcpStatus::IllConditioned`] with `z`, `w` set to `NaN` (never a wrong number with a
/// success status).
#[inline(always)]
pub(crate) fn verdict(
    ok: bool,
    pivots: usize,
    residual: f64,
    z: &mut [f64],
    w: &mut [f64],
) -> KernelOut {
    if ok {
        KernelOut {
            status: LcpStatus::Solved,
            pivots,
            residual,
        }
    } else {
        z.fill(f64::NAN);
        w.fill(f64::NAN);
        KernelOut {
            status: LcpStatus::IllConditioned,
            pivots,
            residual,
        }
    }
}
