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
//! with `w = M z + q` recomputed and `sᵢ` the rounding scale of row `i` of that evaluation,
//!
//! ```text
//! sᵢ = |qᵢ| + Σⱼ |Mᵢⱼ zⱼ|,
//! zᵢ ≥ 0,     wᵢ ≥ −tol_v·sᵢ,     |wᵢ| ≤ tol_v·sᵢ wherever zᵢ > 0,
//! ```
//!
//! after setting aside entries of `z` that are rounding noise in every row they touch (see
//! `verify`); such entries are then reported as exactly 0, so that the `z` and `w` reported with
//! [`LcpStatus::Solved`] are always the ones verified. Each row is judged in its own units, so the test is invariant under positive row and
//! column scalings of the LCP. The reported residual is `maxᵢ |min(zᵢ, wᵢ)| / max(1, ‖q‖∞)`.
//!
//! # Badly scaled data: the equilibrated retry
//!
//! Pivot and tie tolerances are relative to the entering column and to `‖B⁻¹q‖∞`, which mix rows
//! of different units; when `M` couples quantities of very different magnitudes (an impact LCP
//! with a Delassus matrix in 1/kg of a 10⁶-kg deck) a false tie can end the run on a wrong basis.
//! Whenever an attempt ends [`LcpStatus::IllConditioned`] or [`LcpStatus::RayTermination`], Lemke is
//! re-run once on the exactly equivalent LCP `M̃ = R M C`, `q̃ = R q` (`z = C z̃`, `w̃ = R w`; `R`,
//! `C` powers of two balancing the magnitudes of `M`, see the `scale` module); its `z = C z̃` is
//! verified against the original data, and only a verified `z` replaces the first result (pivots
//! of both attempts are reported). Well-scaled problems never take the retry.

//! # Implementation
//!
//! Two kernels, chosen by size (both measured faster than the other in their range):
//!
//! * **full tableau** (`n ≤ 6`, module `full`): `B⁻¹` (the `w` columns of `B⁻¹[I, −M, −e]`) and
//!   `−B⁻¹M` are kept explicitly, `n·(2n+1)` multiply-adds per pivot, no position bookkeeping;
//! * **compact tableau** (`n > 6`): only the `n + 1` nonbasic columns `B⁻¹A_N` and `b` are stored and
//!   each pivot exchanges a basic and a nonbasic variable (`n·(n+2)` multiply-adds per pivot). A
//!   column of `B⁻¹` needed by the lexicographic rule is the stored column of `w_k` when `w_k` is
//!   nonbasic and the unit vector of its row when it is basic.
//!
//! In both, the `z₀` column is never needed again after `z₀` enters (it leaves only at the end), so
//! the first pivot is written in closed form. Each kernel operates on slices and is inlined with a
//! compile-time `n` into [`solve_fixed`] (stack arrays, loops unrolled and vectorised by the
//! compiler) and into [`Lemke::solve`] for `n ∈ {1, 2, 3, 4, 6, 12}`, and with a run-time `n` for the
//! other sizes (heap workspace kept between solves, so a warm solve allocates nothing).

use super::full::{WorkFull, kernel_full};
use super::scale::equilibrate;
use super::tableau::{
    FULL_MAX, KernelOut, cut_to_size, fail, initial_row, verdict, verify, verify_small,
};
use super::{FixedSolution, LcpProblem, LcpSolution, LcpStatus, LemkeSettings};

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

/// The lexicographic Lemke kernel. `m` is row-major `n × n`; `z`, `w` receive the result
/// (`NaN` unless the status is [`LcpStatus::Solved`]).
///
/// Variables: `w_k = k`, `z_k = n + k`, `z₀ = 2n`. Tableau convention: with `x_N` the nonbasic
/// variables, `x_B = b − T x_N` (`T = B⁻¹A_N` for the system `[I, −M, −e] (w, z, z₀) = q`).
// Longer than 120 lines on purpose: the pivot loop is the solver's hot path, inlined with a
// compile-time `n`; it keeps the tableau, the basis and the entering column in locals across
// iterations. Only the cold paths (ties, failures, verification) are separate functions; a
// split of the loop body would pass that state through `&mut` arguments in every pivot.
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
    let (m, q, z, w) = cut_to_size(n, m, q, z, w);
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
    let r0 = match initial_row(n, q, s, z, w) {
        Ok(r0) => r0,
        Err(out) => return out,
    };

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
        if pivots >= s.pivot_limit(n) {
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
    verdict(ok, pivots, residual, z, w)
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
    solve_fixed_slice::<N>(m.as_flattened(), q, settings)
}

/// [`solve_fixed`] on row-major slices (`m.len() ≥ N·N`, `q.len() ≥ N`): one attempt on the data
/// as given and, only if it ends in [`LcpStatus::IllConditioned`] or [`LcpStatus::RayTermination`],
/// the equilibrated retry of [`retry_fixed`].
#[inline(always)]
fn solve_fixed_slice<const N: usize>(
    m: &[f64],
    q: &[f64],
    settings: &LemkeSettings,
) -> FixedSolution<N> {
    let first = attempt_fixed::<N>(m, q, settings);
    if needs_retry(first.status) {
        retry_fixed::<N>(m, q, settings, first)
    } else {
        first
    }
}

/// Whether a failed attempt is worth the equilibrated retry (see [`super::scale`]): a failed
/// verification or a ray (a ray of a P-matrix LCP is always numerical). Pivot exhaustion is not.
#[inline(always)]
fn needs_retry(status: LcpStatus) -> bool {
    matches!(
        status,
        LcpStatus::IllConditioned | LcpStatus::RayTermination
    )
}

/// The equilibrated retry (cold path): solves `M̃ = R M C`, `q̃ = R q` (see [`super::scale`]), maps
/// back `z = C z̃` (exact, `C` holds powers of two) and verifies `z` against the **original** data.
/// Only a verified `z` replaces `first` (its pivots are added to those of `first`); otherwise
/// `first` is returned unchanged.
#[cold]
#[inline(never)]
fn retry_fixed<const N: usize>(
    m: &[f64],
    q: &[f64],
    settings: &LemkeSettings,
    first: FixedSolution<N>,
) -> FixedSolution<N> {
    let mut ms = [[0.0f64; N]; N];
    let mut qs = [0.0f64; N];
    let mut rs = [0.0f64; N];
    let mut dsc = [0.0f64; N];
    if !equilibrate(N, m, q, ms.as_flattened_mut(), &mut qs, &mut rs, &mut dsc) {
        return first;
    }
    let mut sol = attempt_fixed::<N>(ms.as_flattened(), &qs, settings);
    if sol.status != LcpStatus::Solved {
        return first;
    }
    for (zi, di) in sol.z.iter_mut().zip(&dsc) {
        *zi *= di;
    }
    let (ok, residual) = verify_small(N, m, q, &mut sol.z, &mut sol.w, settings.verify_tol());
    if !ok {
        return first;
    }
    sol.residual = residual;
    sol.pivots += first.pivots;
    sol
}

/// One lexicographic Lemke run on the data as given (no retry).
#[inline(always)]
fn attempt_fixed<const N: usize>(
    m: &[f64],
    q: &[f64],
    settings: &LemkeSettings,
) -> FixedSolution<N> {
    let mut z = [0.0f64; N];
    let mut w = [0.0f64; N];
    let out = if N <= FULL_MAX {
        let mut binv = [[0.0f64; N]; N];
        let mut tz = [[0.0f64; N]; N];
        let mut v = [[0.0f64; N]; 2];
        let mut iw = [[0usize; N]; 2];
        let [b, d] = &mut v;
        let [basis, ties] = &mut iw;
        kernel_full(
            N,
            m,
            q,
            settings,
            WorkFull {
                binv: binv.as_flattened_mut(),
                tz: tz.as_flattened_mut(),
                b,
                basis,
                d,
                ties,
            },
            &mut z,
            &mut w,
        )
    } else {
        let mut t = [[0.0f64; N]; N];
        let mut v = [[0.0f64; N]; 3];
        let mut iw = [[0usize; N]; 4];
        let [tx, b, d] = &mut v;
        kernel(
            N,
            m,
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
        )
    };
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
/// guards [`LcpStatus::Solved`]. Sizes `n ∈ {1, 2, 3, 4, 6, 12}` run size-specialised copies of
/// the kernels (compile-time `n`; `n ≤ 6` on the stack); the other sizes use the heap workspace
/// kept in the solver.
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
        let mut k = self.attempt(n, m, q, out);
        if needs_retry(k.status) {
            k = self.retry(n, m, q, out, k);
        }
        out.status = k.status;
        out.pivots = k.pivots;
        out.residual = k.residual;
    }

    /// The equilibrated retry of [`Lemke::solve_into`] (cold path, allocates): as [`retry_fixed`].
    #[cold]
    #[inline(never)]
    fn retry(
        &mut self,
        n: usize,
        m: &[f64],
        q: &[f64],
        out: &mut LcpSolution,
        first: KernelOut,
    ) -> KernelOut {
        let mut ms = vec![0.0f64; n * n];
        let mut qs = vec![0.0f64; n];
        let mut rs = vec![0.0f64; n];
        let mut dsc = vec![0.0f64; n];
        if !equilibrate(n, m, q, &mut ms, &mut qs, &mut rs, &mut dsc) {
            return first;
        }
        let z_first = out.z.clone();
        let w_first = out.w.clone();
        let k = self.attempt(n, &ms, &qs, out);
        let mut ok = false;
        let mut residual = f64::NAN;
        if k.status == LcpStatus::Solved {
            for (zi, di) in out.z.iter_mut().zip(&dsc) {
                *zi *= di;
            }
            (ok, residual) = verify(n, m, q, &mut out.z, &mut out.w, self.settings.verify_tol());
        }
        if ok {
            KernelOut {
                status: LcpStatus::Solved,
                pivots: first.pivots + k.pivots,
                residual,
            }
        } else {
            out.z.copy_from_slice(&z_first);
            out.w.copy_from_slice(&w_first);
            first
        }
    }

    /// One Lemke run on `(m, q)` into `out.z`, `out.w` (no retry).
    #[inline(always)]
    fn attempt(&mut self, n: usize, m: &[f64], q: &[f64], out: &mut LcpSolution) -> KernelOut {
        let nn = n * n;
        if self.ws.len() < 2 * nn + 3 * n {
            self.ws.resize(2 * nn + 3 * n, 0.0);
        }
        if self.wsi.len() < 4 * n {
            self.wsi.resize(4 * n, 0);
        }
        macro_rules! full {
            ($k:expr) => {{
                let (binv, rest) = self.ws.split_at_mut(nn);
                let (tz, rest) = rest.split_at_mut(nn);
                let (b, d) = rest.split_at_mut(n);
                let (basis, ties) = self.wsi.split_at_mut(n);
                kernel_full(
                    $k,
                    m,
                    q,
                    &self.settings,
                    WorkFull {
                        binv,
                        tz,
                        b,
                        basis,
                        d,
                        ties,
                    },
                    &mut out.z,
                    &mut out.w,
                )
            }};
        }
        macro_rules! compact {
            ($k:expr) => {{
                let (t, rest) = self.ws.split_at_mut(nn);
                let (tx, rest) = rest.split_at_mut(n);
                let (b, d) = rest.split_at_mut(n);
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
            }};
        }
        macro_rules! stack {
            ($k:literal) => {{
                let f = attempt_fixed::<$k>(m, q, &self.settings);
                out.z.copy_from_slice(&f.z);
                out.w.copy_from_slice(&f.w);
                KernelOut {
                    status: f.status,
                    pivots: f.pivots,
                    residual: f.residual,
                }
            }};
        }
        match n {
            1 => full!(1),
            2 => stack!(2),
            3 => stack!(3),
            4 => stack!(4),
            6 => stack!(6),
            12 => compact!(12),
            _ => compact!(n),
        }
    }
}
