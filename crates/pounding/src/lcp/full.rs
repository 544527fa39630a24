//! Full-tableau variant of the lexicographic Lemke kernel, used for small sizes (`n ≤ 6`).
//!
//! Same method, tie rules and verification as the compact kernel of [`super::lemke`]; it keeps
//! `B⁻¹` explicitly (the `w` columns of the tableau `B⁻¹[I, −M, −e]`) next to `−B⁻¹M`, which costs
//! `n·(2n+1)` multiply-adds per pivot instead of `n·(n+2)` but needs no position bookkeeping: for
//! `n ≤ 6` that bookkeeping costs more than the extra arithmetic (measured).

use super::LcpStatus;
use super::LemkeSettings;
use super::tableau::{KernelOut, cut_to_size, fail, initial_row, verdict, verify_small};

/// Mutable workspace of the kernel (all slices at least as long as stated).
pub(crate) struct WorkFull<'a> {
    /// `B⁻¹` (the `w` columns of the tableau), `n × n` row-major.
    pub binv: &'a mut [f64],
    /// `−B⁻¹ M` (the `z` columns of the tableau), `n × n` row-major.
    pub tz: &'a mut [f64],
    /// `B⁻¹ q`, length `n`.
    pub b: &'a mut [f64],
    /// Basic variable of each row: `0..n` = `wᵢ`, `n..2n` = `z_{i−n}`, `2n` = `z₀`; length `n`.
    pub basis: &'a mut [usize],
    /// Entering column, length `n`.
    pub d: &'a mut [f64],
    /// Tied rows of the ratio test, length `n`.
    pub ties: &'a mut [usize],
}

/// The full-tableau lexicographic Lemke kernel (`B⁻¹[I, −M]` and `b` kept; the `z₀` column is
/// dropped after the first pivot). `m` is row-major `n × n`; `z`, `w` receive the result
/// (`NaN` unless the status is [`LcpStatus::Solved`]).
// Longer than 120 lines on purpose, like the compact kernel: the inlined pivot loop keeps the
// tableau and the basis in locals; only the cold paths are separate functions.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn kernel_full(
    n: usize,
    m: &[f64],
    q: &[f64],
    s: &LemkeSettings,
    wk: WorkFull<'_>,
    z: &mut [f64],
    w: &mut [f64],
) -> KernelOut {
    let (m, q, z, w) = cut_to_size(n, m, q, z, w);
    let binv = &mut wk.binv[..n * n];
    let tz = &mut wk.tz[..n * n];
    let b = &mut wk.b[..n];
    let basis = &mut wk.basis[..n];
    let d = &mut wk.d[..n];
    let ties = &mut wk.ties[..n];
    let tie_tol = s.tie_tol();
    let pivot_tol = s.pivot_tol();

    // ---- trivial shortcut and the initial row (lexicographic minimum of [q_r | e_rᵀ]) ----
    let r0 = match initial_row(n, q, s, z, w) {
        Ok(r0) => r0,
        Err(out) => return out,
    };

    // ---- tableau after the first pivot (z₀ enters in row r0; its column −e is not kept) ----
    let qr = q[r0];
    for i in 0..n {
        let bi = &mut binv[i * n..i * n + n];
        let ti = &mut tz[i * n..i * n + n];
        if i == r0 {
            for j in 0..n {
                bi[j] = if j == r0 { -1.0 } else { 0.0 };
                ti[j] = m[r0 * n + j];
            }
            b[i] = -qr;
            basis[i] = 2 * n;
        } else {
            for j in 0..n {
                bi[j] = if j == i {
                    1.0
                } else if j == r0 {
                    -1.0
                } else {
                    0.0
                };
                ti[j] = m[r0 * n + j] - m[i * n + j];
            }
            b[i] = q[i] - qr;
            basis[i] = i;
        }
    }
    let z0_row = r0;
    let mut pivots = 1usize;
    let mut entering = n + r0; // the complement of w_{r0}

    loop {
        if pivots >= s.pivot_limit(n) {
            return fail(LcpStatus::MaxPivots, pivots, z, w);
        }
        // entering column
        if entering < n {
            for i in 0..n {
                d[i] = binv[i * n + entering];
            }
        } else {
            let j = entering - n;
            for i in 0..n {
                d[i] = tz[i * n + j];
            }
        }
        // ratio test: strict minimum of max(bᵢ,0)/dᵢ over dᵢ > thr (cross-multiplied)
        let mut dmax = 0.0f64;
        let mut bscale = 0.0f64;
        for i in 0..n {
            dmax = dmax.max(d[i].abs());
            bscale = bscale.max(b[i].abs());
        }
        let thr = pivot_tol * dmax;
        let mut best = usize::MAX;
        let mut best_b = 0.0;
        let mut best_d = 1.0;
        for i in 0..n {
            let di = d[i];
            if di > thr {
                let bi = b[i].max(0.0);
                if best == usize::MAX || bi * best_d < best_b * di {
                    best = i;
                    best_b = bi;
                    best_d = di;
                }
            }
        }
        if best == usize::MAX {
            let st = if dmax.is_finite() && bscale.is_finite() {
                LcpStatus::RayTermination
            } else {
                LcpStatus::IllConditioned
            };
            return fail(st, pivots, z, w);
        }
        // ties within tolerance: (bᵢ/dᵢ − b*/d*) ≤ tie_tol · ‖b‖∞ · (1/dᵢ + 1/d*)
        let tol_b = tie_tol * bscale;
        let mut nt = 0usize;
        let mut z0_tied = false;
        for i in 0..n {
            let di = d[i];
            if di > thr {
                let bi = b[i].max(0.0);
                if bi * best_d - best_b * di <= tol_b * (di + best_d) {
                    ties[nt] = i;
                    nt += 1;
                    z0_tied |= i == z0_row;
                }
            }
        }
        let r = if nt <= 1 {
            best
        } else if z0_tied {
            z0_row
        } else {
            lexmin_full(n, binv, d, &mut ties[..nt], tie_tol)
        };

        // pivot on (r, entering)
        let inv = 1.0 / d[r];
        {
            let br = &mut binv[r * n..r * n + n];
            for x in br.iter_mut() {
                *x *= inv;
            }
            let tr = &mut tz[r * n..r * n + n];
            for x in tr.iter_mut() {
                *x *= inv;
            }
            b[r] *= inv;
        }
        for i in 0..n {
            if i == r {
                continue;
            }
            let f = d[i];
            if f == 0.0 {
                continue;
            }
            for j in 0..n {
                binv[i * n + j] -= f * binv[r * n + j];
                tz[i * n + j] -= f * tz[r * n + j];
            }
            b[i] -= f * b[r];
        }
        let leaving = basis[r];
        basis[r] = entering;
        pivots += 1;
        if leaving == 2 * n {
            break;
        }
        entering = if leaving < n {
            leaving + n
        } else {
            leaving - n
        };
    }

    // ---- z₀ left: read z off the basis and verify ----
    // z_j is the value of the row where z_j is basic (0 if nonbasic), gathered by selection
    // rather than scattered by index: a store at a run-time index followed by the (vectorised)
    // loads of the verification stalls store-to-load forwarding (measured on impact3)
    for (j, zj) in z.iter_mut().enumerate() {
        let mut v = 0.0f64;
        for i in 0..n {
            v = if basis[i] == n + j { b[i].max(0.0) } else { v };
        }
        *zj = v;
    }
    let (ok, residual) = verify_small(n, m, q, z, w, s.verify_tol());
    verdict(ok, pivots, residual, z, w)
}

/// Lexicographic tie-break among the tied rows: the lexicographic minimum of `(B⁻¹)ᵢ / dᵢ`,
/// column by column, entries within `tie_tol` (relative to the rows' scale) counting as equal.
#[cold]
#[inline(never)]
fn lexmin_full(n: usize, binv: &[f64], d: &[f64], ties: &mut [usize], tie_tol: f64) -> usize {
    let mut scale = 0.0f64;
    for &i in ties.iter() {
        for j in 0..n {
            scale = scale.max((binv[i * n + j] / d[i]).abs());
        }
    }
    let tol = tie_tol * scale.max(f64::MIN_POSITIVE);
    let mut len = ties.len();
    for col in 0..n {
        let mut vmin = f64::INFINITY;
        for &i in &ties[..len] {
            vmin = vmin.min(binv[i * n + col] / d[i]);
        }
        let mut k = 0;
        for t in 0..len {
            let i = ties[t];
            if binv[i * n + col] / d[i] <= vmin + tol {
                ties[k] = i;
                k += 1;
            }
        }
        if k == 0 {
            // only possible with NaN entries: keep the first candidate
            return ties[0];
        }
        len = k;
        if len == 1 {
            break;
        }
    }
    ties[0]
}
