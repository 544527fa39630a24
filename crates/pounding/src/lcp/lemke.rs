//! Lexicographic Lemke's method (complementary pivoting with covering vector `e = (1, …, 1)`).
//!
//! # The method
//!
//! Lemke augments the LCP `w = M z + q, 0 ≤ z ⟂ w ≥ 0` with an artificial variable `z₀ ≥ 0` and the
//! covering vector `e`:
//!
//! ```text
//! w − M z − e z₀ = q,      w, z, z₀ ≥ 0,      wᵢ zᵢ = 0  (i = 1..n).
//! ```
//!
//! The tableau is `B⁻¹ [I, −M, −e | q]` for the current basis `B` (initially `B = I`, basic `w = q`).
//! When `q ≥ 0`, `z = 0, w = q` already solves the LCP (the *trivial shortcut*, 0 pivots).
//! Otherwise `z₀` enters at level `−min qᵢ` and replaces the `w_r` of the row `r` with the
//! lexicographic minimum of `[q_r | e_rᵀ]` (the most negative `q_r`; among ties within the tolerance,
//! the largest index). Then, repeatedly, the complement of the variable that just left enters
//! (`wᵢ ↔ zᵢ`) and the leaving row is chosen by the **lexicographic minimum ratio test** over the
//! rows with a positive entry `dᵢ` of the entering column `d`:
//!
//! ```text
//! r = lexmin { [bᵢ, (B⁻¹)ᵢ] / dᵢ : dᵢ > 0 },      b = B⁻¹ q.
//! ```
//!
//! Ratios `bᵢ/dᵢ` that agree within the tie tolerance count as equal; if `z₀`'s row is among the
//! tied rows it leaves (the artificial variable wins ties); otherwise the rows of `B⁻¹/dᵢ` break
//! the tie column by column. Because the rows of `B⁻¹` are linearly independent the lexicographic
//! minimum is unique, which rules out cycling on degenerate problems. The method stops when `z₀`
//! leaves (a complementary basis: a solution) or when no entry of `d` is positive (a *secondary
//! ray*: [`LcpStatus::RayTermination`], no solution found by this method).
//!
//! Every end point is **verified** against the original data before it is reported as solved:
//! with `w = M z + q` recomputed,
//!
//! ```text
//! residual = maxᵢ |min(zᵢ, wᵢ)| / max(1, ‖q‖∞) ≤ tol_v,     zᵢ ≥ −tol_v·max(1, ‖q‖∞),     wᵢ ≥ −tol_v·max(1, ‖q‖∞).
//! ```
//!
//! # Implementation
//!
//! One kernel does the work for every size: it operates on slices, and is inlined into
//! [`solve_fixed`] with a compile-time `n = N` (stack arrays, loops unrolled) and into
//! [`Lemke::solve`] with a run-time `n` (heap workspace kept between solves). [`Lemke::solve`]
//! dispatches `n ∈ {2, 3, 4, 6, 12}` to the fixed-size kernels.

use super::{FixedSolution, LcpProblem, LcpSolution, LcpStatus, LemkeSettings};

/// Result of the kernel (the vectors are written into the caller's buffers).
#[derive(Debug, Clone, Copy)]
pub(crate) struct KernelOut {
    pub status: LcpStatus,
    pub pivots: usize,
    pub residual: f64,
}

/// Mutable workspace of the kernel (all slices at least as long as stated).
pub(crate) struct Work<'a> {
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

/// Verifies `z` against the original data and writes `w = M z + q`.
/// Returns `(passed, residual)`; a non-finite number anywhere fails.
#[inline(always)]
pub(crate) fn verify(
    n: usize,
    m: &[f64],
    q: &[f64],
    z: &[f64],
    w: &mut [f64],
    tol: f64,
) -> (bool, f64) {
    let m = &m[..n * n];
    let q = &q[..n];
    let z = &z[..n];
    let w = &mut w[..n];
    let mut qn = 1.0f64;
    for &qi in q {
        qn = qn.max(qi.abs());
    }
    let lo = -tol * qn;
    let mut res = 0.0f64;
    let mut ok = true;
    for i in 0..n {
        let row = &m[i * n..i * n + n];
        let mut wi = q[i];
        for j in 0..n {
            wi += row[j] * z[j];
        }
        w[i] = wi;
        let zi = z[i];
        let c = zi.min(wi).abs();
        // `max` ignores NaN, so test finiteness explicitly through the comparisons below.
        res = if c > res { c } else { res };
        ok &= wi >= lo && zi >= lo && c.is_finite();
    }
    let residual = res / qn;
    ok &= residual <= tol;
    (ok, residual)
}

/// The lexicographic Lemke kernel. `m` is row-major `n × n`; `z`, `w` receive the result
/// (`NaN` unless the status is [`LcpStatus::Solved`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn kernel(
    n: usize,
    m: &[f64],
    q: &[f64],
    s: &LemkeSettings,
    wk: Work<'_>,
    z: &mut [f64],
    w: &mut [f64],
) -> KernelOut {
    let m = &m[..n * n];
    let q = &q[..n];
    let z = &mut z[..n];
    let w = &mut w[..n];
    let binv = &mut wk.binv[..n * n];
    let tz = &mut wk.tz[..n * n];
    let b = &mut wk.b[..n];
    let basis = &mut wk.basis[..n];
    let d = &mut wk.d[..n];
    let ties = &mut wk.ties[..n];
    let tie_tol = s.tie_tol();
    let pivot_tol = s.pivot_tol();

    // ---- trivial shortcut and the initial row (lexicographic minimum of [q_r | e_rᵀ]) ----
    let mut qmin = f64::INFINITY;
    let mut qscale = 0.0f64;
    let mut finite = true;
    for &qi in q {
        qmin = qmin.min(qi);
        qscale = qscale.max(qi.abs());
        finite &= qi.is_finite();
    }
    if !finite {
        return fail(LcpStatus::IllConditioned, 0, z, w);
    }
    if qmin >= 0.0 {
        for i in 0..n {
            z[i] = 0.0;
            w[i] = q[i];
        }
        return KernelOut {
            status: LcpStatus::Solved,
            pivots: 0,
            residual: 0.0,
        };
    }
    let qtie = qmin + tie_tol * qscale;
    let mut r0 = 0;
    for (i, &qi) in q.iter().enumerate() {
        if qi <= qtie {
            r0 = i; // the largest index among the tied minima
        }
    }
    if s.max_pivots() == 0 {
        return fail(LcpStatus::MaxPivots, 0, z, w);
    }

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
        if pivots >= s.max_pivots() {
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
            lexmin(n, binv, d, &mut ties[..nt], tie_tol)
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
    for x in z.iter_mut() {
        *x = 0.0;
    }
    for i in 0..n {
        let v = basis[i];
        if v >= n && v < 2 * n {
            z[v - n] = b[i].max(0.0);
        }
    }
    let (ok, residual) = verify(n, m, q, z, w, s.verify_tol());
    if ok {
        KernelOut {
            status: LcpStatus::Solved,
            pivots,
            residual,
        }
    } else {
        for i in 0..n {
            z[i] = f64::NAN;
            w[i] = f64::NAN;
        }
        KernelOut {
            status: LcpStatus::IllConditioned,
            pivots,
            residual,
        }
    }
}

#[cold]
#[inline(never)]
fn fail(status: LcpStatus, pivots: usize, z: &mut [f64], w: &mut [f64]) -> KernelOut {
    z.fill(f64::NAN);
    w.fill(f64::NAN);
    KernelOut {
        status,
        pivots,
        residual: f64::NAN,
    }
}

/// Lexicographic tie-break among the tied rows: the lexicographic minimum of `(B⁻¹)ᵢ / dᵢ`,
/// column by column, entries within `tie_tol` (relative to the rows' scale) counting as equal.
#[cold]
#[inline(never)]
fn lexmin(n: usize, binv: &[f64], d: &[f64], ties: &mut [usize], tie_tol: f64) -> usize {
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

/// Lexicographic Lemke on a fixed-size LCP `w = M z + q` given row-major as `m[i][j]`;
/// allocation-free (the tableau lives on the stack).
///
/// Same method, settings and statuses as [`Lemke::solve`]; see the [module documentation](crate::lcp::lemke)
/// for the algorithm. Non-finite data give [`LcpStatus::IllConditioned`] (or, when `q ≥ 0`, the
/// trivial solution `z = 0`, which is valid whatever `M`).
pub fn solve_fixed<const N: usize>(
    m: &[[f64; N]; N],
    q: &[f64; N],
    settings: &LemkeSettings,
) -> FixedSolution<N> {
    solve_fixed_slice::<N>(m.as_flattened(), q, settings)
}

/// Fixed-size kernel on a row-major slice of length `N·N` (checked by the caller).
#[inline]
pub(crate) fn solve_fixed_slice<const N: usize>(
    m: &[f64],
    q: &[f64],
    settings: &LemkeSettings,
) -> FixedSolution<N> {
    let mut binv = [[0.0f64; N]; N];
    let mut tz = [[0.0f64; N]; N];
    let mut b = [0.0f64; N];
    let mut basis = [0usize; N];
    let mut d = [0.0f64; N];
    let mut ties = [0usize; N];
    let mut z = [0.0f64; N];
    let mut w = [0.0f64; N];
    let out = kernel(
        N,
        m,
        q,
        settings,
        Work {
            binv: binv.as_flattened_mut(),
            tz: tz.as_flattened_mut(),
            b: &mut b,
            basis: &mut basis,
            d: &mut d,
            ties: &mut ties,
        },
        &mut z,
        &mut w,
    );
    FixedSolution {
        z,
        w,
        status: out.status,
        pivots: out.pivots,
        residual: out.residual,
    }
}

/// Lexicographic Lemke's method with a reusable workspace (no allocation per solve once warm).
///
/// See the [module documentation](crate::lcp::lemke) for the algorithm, the tie rules and the verification that
/// guards [`LcpStatus::Solved`]. Sizes `n ∈ {2, 3, 4, 6, 12}` run size-specialised kernels
/// ([`solve_fixed`]); other sizes run the same kernel on the heap workspace.
#[derive(Debug, Clone, Default)]
pub struct Lemke {
    /// The settings in force.
    pub settings: LemkeSettings,
    ws: Vec<f64>,
    wsi: Vec<usize>,
}

impl Lemke {
    /// A solver with the given settings.
    pub fn new(settings: LemkeSettings) -> Self {
        Self {
            settings,
            ws: Vec::new(),
            wsi: Vec::new(),
        }
    }

    /// Solves `problem`; never panics on a numerical failure (that is a status). Allocates only
    /// the returned vectors; see [`Lemke::solve_into`] to reuse them.
    pub fn solve(&mut self, problem: &LcpProblem) -> LcpSolution {
        let mut sol = LcpSolution {
            z: Vec::new(),
            w: Vec::new(),
            status: LcpStatus::IllConditioned,
            pivots: 0,
            residual: f64::NAN,
        };
        self.solve_into(problem, &mut sol);
        sol
    }

    /// Solves `problem` into `out`, reusing its vectors (no allocation once `out` and the solver's
    /// workspace have reached the problem size).
    pub fn solve_into(&mut self, problem: &LcpProblem, out: &mut LcpSolution) {
        let n = problem.dim();
        out.z.resize(n, 0.0);
        out.w.resize(n, 0.0);
        let m = problem.m_row_major();
        let q = problem.q();
        macro_rules! fixed {
            ($k:literal) => {{
                let f = solve_fixed_slice::<$k>(m, q, &self.settings);
                out.z.copy_from_slice(&f.z);
                out.w.copy_from_slice(&f.w);
                out.status = f.status;
                out.pivots = f.pivots;
                out.residual = f.residual;
                return;
            }};
        }
        match n {
            2 => fixed!(2),
            3 => fixed!(3),
            4 => fixed!(4),
            6 => fixed!(6),
            12 => fixed!(12),
            _ => {}
        }
        let nn = n * n;
        if self.ws.len() < 2 * nn + 2 * n {
            self.ws.resize(2 * nn + 2 * n, 0.0);
        }
        if self.wsi.len() < 2 * n {
            self.wsi.resize(2 * n, 0);
        }
        let (binv, rest) = self.ws.split_at_mut(nn);
        let (tz, rest) = rest.split_at_mut(nn);
        let (b, d) = rest.split_at_mut(n);
        let (basis, ties) = self.wsi.split_at_mut(n);
        let k = kernel(
            n,
            m,
            q,
            &self.settings,
            Work {
                binv,
                tz,
                b,
                basis,
                d,
                ties,
            },
            &mut out.z,
            &mut out.w,
        );
        out.status = k.status;
        out.pivots = k.pivots;
        out.residual = k.residual;
    }
}
