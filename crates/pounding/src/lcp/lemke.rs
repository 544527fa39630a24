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
//! with `w = M z + q` recomputed and `S` the rounding scale of that evaluation,
//!
//! ```text
//! S = max(1, ‖q‖∞, maxᵢ Σⱼ |Mᵢⱼ zⱼ|),
//! maxᵢ |min(zᵢ, wᵢ)| ≤ tol_v·S,     zᵢ ≥ −tol_v·S,     wᵢ ≥ −tol_v·S.
//! ```
//!
//! The reported residual is `maxᵢ |min(zᵢ, wᵢ)| / max(1, ‖q‖∞)`; for well-scaled data
//! `S = max(1, ‖q‖∞)` and the test reads `residual ≤ tol_v`. (When `z` is huge — nearly singular
//! `M` — no floating-point `z` can make `M z + q` smaller than about `ε·S`, hence the scale.)
//!
//! # Implementation
//!
//! The tableau is kept in *compact* form: only the `n + 1` nonbasic columns `B⁻¹A_N` and `b` are
//! stored and each pivot exchanges a basic and a nonbasic variable (`n·(n+2)` multiply-adds per
//! pivot instead of `n·(2n+2)` for the full tableau). A column of `B⁻¹` needed by the
//! lexicographic rule is the stored column of `w_k` when `w_k` is nonbasic and the unit vector of
//! its row when it is basic. The `z₀` column is never needed again after `z₀` enters (it leaves
//! only at the end), so the first pivot is written in closed form.
//!
//! One kernel does the work for every size: it operates on slices and is inlined with a
//! compile-time `n` into [`solve_fixed`] (stack arrays) and into [`Lemke::solve`] for
//! `n ∈ {2, 3, 4, 6, 12}` (loops unrolled and vectorised by the compiler), and with a run-time `n`
//! for the other sizes (heap workspace kept between solves, so a warm solve allocates nothing).

use super::{FixedSolution, LcpProblem, LcpSolution, LcpStatus, LemkeSettings};

/// Result of the kernel (the vectors are written into the caller's buffers).
#[derive(Debug, Clone, Copy)]
pub(crate) struct KernelOut {
    pub status: LcpStatus,
    pub pivots: usize,
    pub residual: f64,
}

/// Mutable workspace of the kernel (every slice at least as long as stated).
pub(crate) struct Work<'a> {
    /// The first `n` nonbasic columns of the compact tableau `B⁻¹A_N`, `n × n` row-major.
    pub t: &'a mut [f64],
    /// The last nonbasic column, length `n`.
    pub tx: &'a mut [f64],
    /// `B⁻¹ q`, length `n`.
    pub b: &'a mut [f64],
    /// Entering column, length `n`.
    pub d: &'a mut [f64],
    /// Integer scratch, length `4n`: basis (row → variable), position of each `w_k` and of each
    /// `z_k`, tied rows.
    pub iw: &'a mut [usize],
}

/// Sizes up to which the kernel prefers (well-predicted) branches to branch-free counting.
const SMALL: usize = 4;

/// Position code: `< ROW` a column index; `≥ ROW` the row `code − ROW`.
const ROW: usize = 1 << 30;

/// Verifies `z` against the original data and writes `w = M z + q`.
///
/// Returns `(passed, residual)` with `residual = maxᵢ |min(zᵢ, wᵢ)| / max(1, ‖q‖∞)`. The test is
/// relative to the rounding scale of `w`,
/// `S = max(1, ‖q‖∞, maxᵢ Σⱼ |Mᵢⱼ zⱼ|)`: it passes when `z ≥ −tol·S`, `w ≥ −tol·S` and
/// `maxᵢ |min(zᵢ, wᵢ)| ≤ tol·S` (for well-scaled data `S = max(1, ‖q‖∞)`, i.e. `residual ≤ tol`;
/// for huge `z` the evaluation of `M z + q` alone loses `ε·S`). A non-finite number anywhere fails.
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
    let mut res = 0.0f64;
    let mut scale = qn;
    let mut lowest = 0.0f64;
    let mut finite = true;
    for i in 0..n {
        let row = &m[i * n..i * n + n];
        let mut wi = q[i];
        let mut si = 0.0;
        for j in 0..n {
            let p = row[j] * z[j];
            wi += p;
            si += p.abs();
        }
        w[i] = wi;
        let zi = z[i];
        let c = zi.min(wi).abs();
        res = res.max(c);
        scale = scale.max(si);
        lowest = lowest.min(zi.min(wi));
        finite &= c.is_finite() && si.is_finite();
    }
    let lim = tol * scale;
    let ok = finite && res <= lim && lowest >= -lim;
    (ok, res / qn)
}

/// The lexicographic Lemke kernel. `m` is row-major `n × n`; `z`, `w` receive the result
/// (`NaN` unless the status is [`LcpStatus::Solved`]).
///
/// Variables: `w_k = k`, `z_k = n + k`, `z₀ = 2n`. Tableau convention: with `x_N` the nonbasic
/// variables, `x_B = b − T x_N` (`T = B⁻¹A_N` for the system `[I, −M, −e] (w, z, z₀) = q`).
#[inline(always)]
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
    let t = &mut wk.t[..n * n];
    let tx = &mut wk.tx[..n];
    let b = &mut wk.b[..n];
    let d = &mut wk.d[..n];
    let (basis, rest) = wk.iw[..4 * n].split_at_mut(n);
    // pos[v] for v = w_k (k < n) and v = z_k (n + k): column index, or ROW + row if basic
    let (pos, ties) = rest.split_at_mut(2 * n);
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
        r0 = if qi <= qtie { i } else { r0 }; // the largest index among the tied minima
    }
    if s.max_pivots() == 0 {
        return fail(LcpStatus::MaxPivots, 0, z, w);
    }

    // ---- compact tableau after the first pivot: z₀ (column n, entries −1) replaces w_{r0} ----
    // row r0: T = M_{r0,·}, b = −q_{r0}; rows i ≠ r0: T = M_{r0,·} − M_{i,·}, b = q_i − q_{r0};
    // column n now holds w_{r0}: entries −1.
    let qr = q[r0];
    let mr = &m[r0 * n..r0 * n + n];
    for i in 0..n {
        let ti = &mut t[i * n..i * n + n];
        let mi = &m[i * n..i * n + n];
        if i == r0 {
            ti.copy_from_slice(mr);
            b[i] = -qr;
            basis[i] = 2 * n;
        } else {
            for j in 0..n {
                ti[j] = mr[j] - mi[j];
            }
            b[i] = q[i] - qr;
            basis[i] = i;
        }
        tx[i] = -1.0;
        pos[i] = ROW + i;
        pos[n + i] = i;
    }
    pos[r0] = n;
    let z0_row = r0;
    let mut pivots = 1usize;
    let mut entering = n + r0; // the complement of w_{r0}
    let last = n.saturating_sub(1);

    loop {
        if pivots >= s.max_pivots() {
            return fail(LcpStatus::MaxPivots, pivots, z, w);
        }
        // entering column (the entering variable is always nonbasic), with the scales of the
        // column and of the right-hand side
        let c = pos[entering];
        let in_tx = c == n;
        let cc = c.min(last);
        let mut dmax = 0.0f64;
        let mut bscale = 0.0f64;
        for i in 0..n {
            let di = if in_tx { tx[i] } else { t[i * n + cc] };
            d[i] = di;
            dmax = dmax.max(di.abs());
            bscale = bscale.max(b[i].abs());
        }
        // ratio test: strict minimum of max(bᵢ,0)/dᵢ over dᵢ > thr (cross-multiplied, first row
        // on exact equality), written with selects rather than branches
        let thr = pivot_tol * dmax;
        let mut best = usize::MAX;
        let mut best_b = f64::INFINITY;
        let mut best_d = 1.0;
        for i in 0..n {
            let di = d[i];
            if di > thr {
                let bi = b[i].max(0.0);
                if bi * best_d < best_b * di {
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
        // ties within tolerance: (bᵢ/dᵢ − b*/d*) ≤ tie_tol · ‖b‖∞ · (1/dᵢ + 1/d*), counted
        // without branches and resolved in the cold path
        let tol_b = tie_tol * bscale;
        let mut nt = 0usize;
        if n <= SMALL {
            // tiny n: branches predict well enough and are cheaper than the full count
            for i in 0..n {
                let di = d[i];
                if di > thr && i != best {
                    let bi = b[i].max(0.0);
                    if bi * best_d - best_b * di <= tol_b * (di + best_d) {
                        nt = 2;
                    }
                }
            }
        } else {
            for i in 0..n {
                let di = d[i];
                let bi = b[i].max(0.0);
                let tie = (di > thr) & (bi * best_d - best_b * di <= tol_b * (di + best_d));
                nt += tie as usize;
            }
        }
        let r = if nt <= 1 {
            best
        } else {
            resolve_ties(
                n,
                t,
                tx,
                b,
                &pos[..n],
                d,
                thr,
                (best_b, best_d, tol_b),
                z0_row,
                ties,
                tie_tol,
            )
        };

        // exchange pivot on (r, c): the entering variable becomes basic in row r, the leaving
        // one takes column c. Row r is divided by the pivot; every other row loses f·(row r)
        // (f = 0 for row r itself, so that no branch depends on r); column c becomes
        // (1/p in row r, −dᵢ/p elsewhere).
        let inv = 1.0 / d[r];
        for j in 0..n {
            t[r * n + j] *= inv;
        }
        tx[r] *= inv;
        b[r] *= inv;
        let (txr, br) = (tx[r], b[r]);
        for i in 0..n {
            if i == r {
                continue;
            }
            let f = d[i];
            for j in 0..n {
                t[i * n + j] -= f * t[r * n + j];
            }
            tx[i] -= f * txr;
            b[i] -= f * br;
        }
        for i in 0..n {
            let v = if i == r { inv } else { -d[i] * inv };
            if in_tx {
                tx[i] = v;
            } else {
                t[i * n + cc] = v;
            }
        }
        let leaving = basis[r];
        basis[r] = entering;
        pos[entering] = ROW + r;
        pivots += 1;
        if leaving == 2 * n {
            break;
        }
        pos[leaving] = c;
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

/// The tied rows of the ratio test: `z₀`'s row if it is among them (the artificial variable
/// wins ties), else the lexicographic minimum.
#[cold]
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn resolve_ties(
    n: usize,
    t: &[f64],
    tx: &[f64],
    b: &[f64],
    pos_w: &[usize],
    d: &[f64],
    thr: f64,
    (best_b, best_d, tol_b): (f64, f64, f64),
    z0_row: usize,
    ties: &mut [usize],
    tie_tol: f64,
) -> usize {
    let mut nt = 0;
    for i in 0..n {
        let di = d[i];
        let bi = b[i].max(0.0);
        if di > thr && bi * best_d - best_b * di <= tol_b * (di + best_d) {
            if i == z0_row {
                return z0_row;
            }
            ties[nt] = i;
            nt += 1;
        }
    }
    lexmin(n, t, tx, pos_w, d, &mut ties[..nt], tie_tol)
}

/// Lexicographic tie-break among the tied rows: the lexicographic minimum of `(B⁻¹)ᵢ / dᵢ`,
/// column by column, entries within `tie_tol` (relative to the rows' scale) counting as equal.
/// Column `k` of `B⁻¹` is the tableau column of `w_k` if `w_k` is nonbasic, else a unit vector.
#[cold]
#[inline(never)]
fn lexmin(
    n: usize,
    t: &[f64],
    tx: &[f64],
    pos_w: &[usize],
    d: &[f64],
    ties: &mut [usize],
    tie_tol: f64,
) -> usize {
    let binv = |i: usize, k: usize| -> f64 {
        let p = pos_w[k];
        if p >= ROW {
            if p - ROW == i { 1.0 } else { 0.0 }
        } else if p == n {
            tx[i]
        } else {
            t[i * n + p]
        }
    };
    let mut scale = 0.0f64;
    for &i in ties.iter() {
        for k in 0..n {
            scale = scale.max((binv(i, k) / d[i]).abs());
        }
    }
    let tol = tie_tol * scale.max(f64::MIN_POSITIVE);
    let mut len = ties.len();
    for k in 0..n {
        let mut vmin = f64::INFINITY;
        for &i in &ties[..len] {
            vmin = vmin.min(binv(i, k) / d[i]);
        }
        let mut kept = 0;
        for j in 0..len {
            let i = ties[j];
            if binv(i, k) / d[i] <= vmin + tol {
                ties[kept] = i;
                kept += 1;
            }
        }
        if kept == 0 {
            // only possible with NaN entries: keep the first candidate
            return ties[0];
        }
        len = kept;
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
    let mut t = [[0.0f64; N]; N];
    let mut v = [[0.0f64; N]; 3];
    let mut iw = [[0usize; N]; 4];
    let mut z = [0.0f64; N];
    let mut w = [0.0f64; N];
    let [tx, b, d] = &mut v;
    let out = kernel(
        N,
        m.as_flattened(),
        q,
        settings,
        Work {
            t: t.as_flattened_mut(),
            tx,
            b,
            d,
            iw: iw.as_flattened_mut(),
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
/// guards [`LcpStatus::Solved`]. Sizes `n ∈ {2, 3, 4, 6, 12}` run size-specialised copies of
/// the kernel (compile-time `n`); every size uses the heap workspace kept in the solver.
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
        let nn = n * n;
        if self.ws.len() < nn + 3 * n {
            self.ws.resize(nn + 3 * n, 0.0);
        }
        if self.wsi.len() < 4 * n {
            self.wsi.resize(4 * n, 0);
        }
        let (t, rest) = self.ws.split_at_mut(nn);
        let (tx, rest) = rest.split_at_mut(n);
        let (b, d) = rest.split_at_mut(n);
        macro_rules! run {
            ($k:expr) => {
                kernel(
                    $k,
                    m,
                    q,
                    &self.settings,
                    Work {
                        t,
                        tx,
                        b,
                        d,
                        iw: &mut self.wsi,
                    },
                    &mut out.z,
                    &mut out.w,
                )
            };
        }
        let k = match n {
            2 => run!(2),
            3 => run!(3),
            4 => run!(4),
            6 => run!(6),
            12 => run!(12),
            _ => run!(n),
        };
        out.status = k.status;
        out.pivots = k.pivots;
        out.residual = k.residual;
    }
}
