//! Exhaustive enumeration of complementary bases (`n ≤ 12`).
//!
//! For every support `α ⊆ {1..n}` (all `2ⁿ` of them, in increasing bit-mask order) the principal
//! system
//!
//! ```text
//! M_αα z_α = −q_α,      z_ᾱ = 0
//! ```
//!
//! is solved by Gaussian elimination with partial pivoting (skipped when `M_αα` is numerically
//! singular: a pivot `≤ singular_tol · max|M_αα|`). The candidate is kept when it passes the same
//! verification as Lemke's end points (`w = M z + q` recomputed; row by row,
//! relative to each row's rounding scale, see [`crate::lcp::lemke`]). Every *basic* solution of the LCP is found this way
//! (a basic solution is exactly a nonnegative solution of such a system for some nonsingular
//! `M_αα`); duplicates (degenerate solutions reached from several supports) are merged when they
//! agree to `dedup_tol · max(1, ‖z‖∞)`. A continuum of solutions is represented by its vertices.

use super::tableau::verify;
use super::{LcpError, LcpProblem};

/// Largest size accepted by [`enumerate`] (`2¹²` = 4096 supports).
pub const MAX_ENUM_DIM: usize = 12;

/// Tolerances of [`enumerate_with`].
#[derive(Debug, Clone, PartialEq)]
pub struct EnumSettings {
    /// Relative pivot size below which `M_αα` counts as singular (default 1e-12).
    pub singular_tol: f64,
    /// Verification tolerance, as `LemkeSettings::verify_tol` (default 1e-9).
    pub verify_tol: f64,
    /// Two solutions are the same when `‖z − z'‖∞ ≤ dedup_tol · max(1, ‖z‖∞)` (default 1e-8).
    pub dedup_tol: f64,
}

impl Default for EnumSettings {
    fn default() -> Self {
        Self {
            singular_tol: 1e-12,
            verify_tol: 1e-9,
            dedup_tol: 1e-8,
        }
    }
}

/// All distinct solutions found by enumerating complementary bases (`n ≤ 12`, else an error),
/// with the default [`EnumSettings`]. An empty vector means the LCP has no (basic) solution.
pub fn enumerate(problem: &LcpProblem) -> Result<Vec<Vec<f64>>, LcpError> {
    enumerate_with(problem, &EnumSettings::default())
}

/// [`enumerate`] with explicit tolerances (each must be finite and in `[0, 1)`).
pub fn enumerate_with(
    problem: &LcpProblem,
    settings: &EnumSettings,
) -> Result<Vec<Vec<f64>>, LcpError> {
    let n = problem.dim();
    if n > MAX_ENUM_DIM {
        return Err(LcpError::Invalid(format!(
            "enumeration needs n <= {MAX_ENUM_DIM}, got n = {n}"
        )));
    }
    for (name, v) in [
        ("singular_tol", settings.singular_tol),
        ("verify_tol", settings.verify_tol),
        ("dedup_tol", settings.dedup_tol),
    ] {
        if !(v.is_finite() && (0.0..1.0).contains(&v)) {
            return Err(LcpError::Invalid(format!(
                "EnumSettings::{name} = {v} must be finite and in [0, 1)"
            )));
        }
    }
    let m = problem.m_row_major();
    let q = problem.q();
    let mut out: Vec<Vec<f64>> = Vec::new();
    let mut a = vec![0.0; n * n];
    let mut rhs = vec![0.0; n];
    let mut idx = vec![0usize; n];
    let mut z = vec![0.0; n];
    let mut w = vec![0.0; n];
    for mask in 0u32..(1u32 << n) {
        let mut k = 0;
        for i in 0..n {
            if mask & (1 << i) != 0 {
                idx[k] = i;
                k += 1;
            }
        }
        z.iter_mut().for_each(|x| *x = 0.0);
        if k > 0 {
            for (r, &i) in idx[..k].iter().enumerate() {
                for (c, &j) in idx[..k].iter().enumerate() {
                    a[r * k + c] = m[i * n + j];
                }
                rhs[r] = -q[i];
            }
            if !gauss_solve(k, &mut a[..k * k], &mut rhs[..k], settings.singular_tol) {
                continue;
            }
            for (r, &i) in idx[..k].iter().enumerate() {
                z[i] = rhs[r];
            }
        }
        // nonnegativity within tolerance, then clean rounding negatives
        let qn = q.iter().fold(1.0f64, |a, &x| a.max(x.abs()));
        if !z.iter().all(|&x| x >= -settings.verify_tol * qn) {
            continue;
        }
        z.iter_mut().for_each(|x| *x = x.max(0.0));
        let (ok, _) = verify(n, m, q, &mut z, &mut w, settings.verify_tol);
        if !ok {
            continue;
        }
        let zn = z.iter().fold(1.0f64, |a, &x| a.max(x.abs()));
        let dup = out.iter().any(|s| {
            s.iter()
                .zip(&z)
                .all(|(a, b)| (a - b).abs() <= settings.dedup_tol * zn)
        });
        if !dup {
            out.push(z.clone());
        }
    }
    Ok(out)
}

/// Solves `A x = rhs` in place (`A` row-major `k × k`, overwritten); `false` when a pivot is
/// `≤ tol · max|A|` (numerically singular) or the result is not finite.
fn gauss_solve(k: usize, a: &mut [f64], rhs: &mut [f64], tol: f64) -> bool {
    let amax = a.iter().fold(0.0f64, |m, &x| m.max(x.abs()));
    if amax == 0.0 {
        return false;
    }
    let thr = tol * amax;
    for c in 0..k {
        let mut p = c;
        for r in c + 1..k {
            if a[r * k + c].abs() > a[p * k + c].abs() {
                p = r;
            }
        }
        if a[p * k + c].abs() <= thr || a[p * k + c].is_nan() {
            return false;
        }
        if p != c {
            for j in 0..k {
                a.swap(p * k + j, c * k + j);
            }
            rhs.swap(p, c);
        }
        let piv = a[c * k + c];
        for r in c + 1..k {
            let f = a[r * k + c] / piv;
            if f != 0.0 {
                for j in c..k {
                    a[r * k + j] -= f * a[c * k + j];
                }
                rhs[r] -= f * rhs[c];
            }
        }
    }
    for c in (0..k).rev() {
        let mut s = rhs[c];
        for j in c + 1..k {
            s -= a[c * k + j] * rhs[j];
        }
        rhs[c] = s / a[c * k + c];
    }
    rhs.iter().all(|x| x.is_finite())
}
