//! The 2-D frictional contact problem of many simultaneous contacts, by a nonsmooth Gauss–Seidel
//! over contact blocks (as Siconos' `fc2d_nsgs`; Jean 1999, "The non-smooth contact dynamics
//! method", *Comput. Methods Appl. Mech. Engrg.* 177; Acary & Brogliato 2008, §13.4).
//!
//! With `n` contacts, impulses `P = (P_N,1..P_N,n, P_T,1..P_T,n)`, the Delassus matrix `G`
//! (`2n × 2n`, symmetric positive semi-definite, rows in the same order) and `b` (the free
//! relative velocities, `b_N` already shifted by Newton's restitution), the velocities are
//! `γ = G P + b` and each contact `i` obeys Signorini and Coulomb:
//!
//! ```text
//! 0 ≤ P_N,i ⊥ γ_N,i ≥ 0,      |P_T,i| ≤ μ_i P_N,i,
//! |P_T,i| < μ_i P_N,i ⇒ γ_T,i = 0,      γ_T,i ≠ 0 ⇒ P_T,i = −μ_i P_N,i sign(γ_T,i).
//! ```
//!
//! One sweep solves each contact's block exactly with the others held: `v = b_i + Σ_{j≠i} G_ij
//! P_j` (a 2-vector) and the 2 × 2 block `G_ii`; the local solution is *separation* (`v_N ≥ 0`:
//! `P_i = 0`), else *stick* (`P_i = −G_ii⁻¹ v` inside the cone), else *slip* (`P_T = s μ P_N`
//! with `s = ±1`, `P_N` from the normal row, `s γ_T ≤ 0`). Sweeps alternate forward and backward
//! (symmetric Gauss–Seidel: an impulse crosses a chain of contacts in one sweep whichever way it
//! travels). Redundant contacts — two corners of aligned faces, a singular `G` — share the
//! impulse but give one velocity, which is what the dynamics needs.
//!
//! The answer is verified, not assumed: [`solve_nsgs`] stops when a sweep changes no impulse by
//! more than `tol` of the largest, then measures every condition above on `γ = G P + b`
//! ([`Fc2dSolution::residual`], relative to the velocity and impulse scales); only a residual
//! within `tol_verify` is `converged`.

use crate::math::Real;

/// Settings of [`solve_nsgs`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fc2dSettings {
    /// A sweep whose largest impulse change is at most `tol` times the largest impulse ends the
    /// iteration.
    pub tol: Real,
    /// The largest relative residual of an accepted answer.
    pub tol_verify: Real,
    /// The most sweeps of a round (see [`solve_nsgs`]).
    pub max_sweeps: usize,
}

impl Default for Fc2dSettings {
    fn default() -> Self {
        Self {
            tol: 1e-13,
            tol_verify: 1e-8,
            max_sweeps: 30,
        }
    }
}

/// The answer of [`solve_nsgs`].
#[derive(Debug, Clone, PartialEq)]
pub struct Fc2dSolution {
    /// `P = (P_N, P_T)`.
    pub p: Vec<Real>,
    /// `γ = G P + b`.
    pub gamma: Vec<Real>,
    /// Sweeps made.
    pub sweeps: usize,
    /// The largest violation of a condition, relative to the problem's scales (see
    /// [`residual`]).
    pub residual: Real,
    /// The residual is within `tol_verify`.
    pub converged: bool,
}

/// One contact's block solution with the others held: `v` its velocity without its own impulse,
/// `(a, c, d)` its block `[[G_NN, G_NT], [G_TN, G_TT]]` (`c = G_NT = G_TN`).
fn local(v: [Real; 2], a: Real, c: Real, d: Real, mu: Real) -> [Real; 2] {
    let [vn, vt] = v;
    if vn >= 0.0 || a <= 0.0 {
        return [0.0, 0.0];
    }
    if mu == 0.0 {
        return [-vn / a, 0.0];
    }
    let det = a * d - c * c;
    if det > 0.0 {
        let pn = -(d * vn - c * vt) / det;
        let pt = -(a * vt - c * vn) / det;
        if pn >= 0.0 && pt.abs() <= mu * pn {
            return [pn, pt];
        }
    }
    for s in [1.0, -1.0] {
        let den = a + s * mu * c;
        if den > 0.0 {
            let pn = -vn / den;
            let gt = c * pn + d * s * mu * pn + vt;
            if s * gt <= 0.0 {
                return [pn, s * mu * pn];
            }
        }
    }
    // a degenerate block (no consistent slip): no friction rather than no answer; the
    // verification below decides
    [-vn / a, 0.0]
}

/// The largest violation of the conditions of the module's problem by `(p, γ)`, each relative to
/// its scale: `P_N < 0`, `γ_N < 0`, `P_N γ_N ≠ 0`, `|P_T| > μ P_N`, `γ_T ≠ 0` with `|P_T| <
/// μ P_N`, `P_T γ_T > 0`. The scales are the largest `|γ|`, `|b|` (velocities) and `|P|`
/// (impulses), each at least the smallest positive normal.
pub fn residual(p: &[Real], gamma: &[Real], b: &[Real], mu: &[Real]) -> Real {
    let n = mu.len();
    let amax = |x: &[Real]| x.iter().fold(0.0, |m: Real, v| m.max(v.abs()));
    let sv = amax(gamma).max(amax(b)).max(Real::MIN_POSITIVE);
    let sp = amax(p).max(Real::MIN_POSITIVE);
    let mut r: Real = 0.0;
    for i in 0..n {
        let (pn, pt, gn, gt) = (p[i], p[n + i], gamma[i], gamma[n + i]);
        r = r.max((-pn).max(0.0) / sp);
        r = r.max((-gn).max(0.0) / sv);
        r = r.max((pn / sp).min(gn.abs() / sv));
        r = r.max((pt.abs() - mu[i] * pn).max(0.0) / sp);
        // sticking (strictly inside the cone) needs γ_T = 0; on the cone's edge friction opposes
        let inside = (mu[i] * pn - pt.abs()) / sp;
        r = r.max(inside.min(gt.abs() / sv));
        r = r.max((pt * gt).max(0.0) / (sp * sv));
    }
    if r.is_nan() { Real::INFINITY } else { r }
}

/// How a contact is taken by [`solve_modes`]: open, sticking, or slipping with `P_T = s μ P_N`.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    Open,
    Stick,
    Slip(Real),
}

/// The modes that `p` shows.
fn modes_of(p: &[Real], mu: &[Real]) -> Vec<Mode> {
    let n = mu.len();
    let scale = p.iter().fold(0.0, |m: Real, v| m.max(v.abs()));
    (0..n)
        .map(|i| {
            let (pn, pt) = (p[i], p[n + i]);
            if pn <= 1e-12 * scale {
                Mode::Open
            } else if mu[i] == 0.0 {
                Mode::Slip(0.0)
            } else if mu[i] * pn - pt.abs() > 1e-9 * pn {
                Mode::Stick
            } else {
                Mode::Slip(pt.signum())
            }
        })
        .collect()
}

/// The exact answer for given contact modes: open contacts carry no impulse, closed ones have
/// `γ_N = 0`, sticking ones `γ_T = 0`, slipping ones `P_T = s μ P_N`. The linear system of the
/// closed contacts is solved in the least-squares sense with the smallest norm (a singular value
/// decomposition), so redundant contacts share their impulse. `None` when the system has no
/// finite solution.
fn solve_modes(g: &[Vec<Real>], b: &[Real], mu: &[Real], modes: &[Mode]) -> Option<Vec<Real>> {
    let n = mu.len();
    // unknowns: P_N of each closed contact, then P_T of each sticking one
    let closed: Vec<usize> = (0..n).filter(|&i| modes[i] != Mode::Open).collect();
    let stick: Vec<usize> = (0..n).filter(|&i| modes[i] == Mode::Stick).collect();
    let m = closed.len() + stick.len();
    if m == 0 {
        return Some(vec![0.0; 2 * n]);
    }
    // the impulse column of unknown k: P_N,i (with its slip friction), or P_T,i
    let column = |k: usize, row: usize| -> Real {
        if k < closed.len() {
            let i = closed[k];
            let s = match modes[i] {
                Mode::Slip(s) => s * mu[i],
                _ => 0.0,
            };
            g[row][i] + s * g[row][n + i]
        } else {
            g[row][n + stick[k - closed.len()]]
        }
    };
    let rows: Vec<usize> = closed
        .iter()
        .copied()
        .chain(stick.iter().map(|&i| n + i))
        .collect();
    let a = nalgebra::DMatrix::from_fn(m, m, |r, k| column(k, rows[r]));
    let rhs = nalgebra::DVector::from_iterator(m, rows.iter().map(|&r| -b[r]));
    let svd = a.svd(true, true);
    let eps = 1e-12 * svd.singular_values.max();
    let x = svd.solve(&rhs, eps).ok()?;
    let mut out = vec![0.0; 2 * n];
    for (k, &i) in closed.iter().enumerate() {
        out[i] = x[k];
        if let Mode::Slip(s) = modes[i] {
            out[n + i] = s * mu[i] * x[k];
        }
    }
    for (k, &i) in stick.iter().enumerate() {
        out[n + i] = x[closed.len() + k];
    }
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// The primal-dual active-set iteration from the modes that `p` shows (a semismooth Newton
/// method on the block conditions): solve for the modes ([`solve_modes`]), then change the mode of
/// every contact that violates its conditions — a closed contact pulling (`P_N < 0`) opens, an
/// open one penetrating (`γ_N < 0`) closes, a sticking one outside the cone slips, a slipping
/// one whose friction does not oppose its slip sticks — until the answer verifies or the modes
/// repeat. Returns the best answer found with its `γ` and residual.
fn active_set(
    g: &[Vec<Real>],
    b: &[Real],
    mu: &[Real],
    p: &[Real],
    tol: Real,
) -> Option<(Vec<Real>, Vec<Real>, Real)> {
    let n = mu.len();
    let mut modes = modes_of(p, mu);
    let mut best: Option<(Vec<Real>, Vec<Real>, Real)> = None;
    let mut seen: Vec<Vec<Mode>> = Vec::new();
    for _ in 0..MAX_ACTIVE_SET_STEPS {
        let q = solve_modes(g, b, mu, &modes)?;
        let gq = velocities(g, b, &q);
        let r = residual(&q, &gq, b, mu);
        if best.as_ref().is_none_or(|x| r < x.2) {
            best = Some((q.clone(), gq.clone(), r));
        }
        if r <= tol {
            break;
        }
        seen.push(modes.clone());
        let sv = gq.iter().chain(b).fold(0.0, |m: Real, v| m.max(v.abs()));
        let small = 1e-12 * sv;
        for i in 0..n {
            let (pn, pt, gn, gt) = (q[i], q[n + i], gq[i], gq[n + i]);
            modes[i] = match modes[i] {
                Mode::Open if gn < -small => {
                    if mu[i] == 0.0 {
                        Mode::Slip(0.0)
                    } else {
                        Mode::Stick
                    }
                }
                Mode::Open => Mode::Open,
                _ if pn < 0.0 => Mode::Open,
                Mode::Stick if pt.abs() > mu[i] * pn => Mode::Slip(pt.signum()),
                Mode::Slip(s) if s != 0.0 && s * gt > small => Mode::Stick,
                m => m,
            };
        }
        if seen.contains(&modes) {
            break;
        }
    }
    best
}

/// The most active-set steps of [`active_set`].
const MAX_ACTIVE_SET_STEPS: usize = 30;

/// `γ = G P + b`.
fn velocities(g: &[Vec<Real>], b: &[Real], p: &[Real]) -> Vec<Real> {
    g.iter()
        .zip(b)
        .map(|(gr, bi)| bi + gr.iter().zip(p).map(|(x, y)| x * y).sum::<Real>())
        .collect()
}

/// Solves the module's problem for `G` (`2n × 2n`, rows `N_1..N_n, T_1..T_n`), `b` (`2n`) and
/// `μ` (`n`): rounds of at most `max_sweeps` block sweeps, each followed — when the sweeps have
/// not reached a verified answer — by the active-set correction of the modes they found
/// ([`active_set`]), the next round starting from its best answer. Never panics on finite data
/// of consistent sizes; an answer that fails the verification is returned with `converged =
/// false`.
///
/// # Panics
/// If the sizes are inconsistent.
pub fn solve_nsgs(g: &[Vec<Real>], b: &[Real], mu: &[Real], s: &Fc2dSettings) -> Fc2dSolution {
    let n = mu.len();
    assert!(b.len() == 2 * n && g.len() == 2 * n && g.iter().all(|r| r.len() == 2 * n));
    let mut p = vec![0.0; 2 * n];
    let mut sweeps = 0;
    let mut best: Option<(Vec<Real>, Vec<Real>, Real)> = None;
    for _ in 0..ROUNDS {
        sweeps += sweep(g, b, mu, s, &mut p);
        // the velocities from scratch (no drift of the running update)
        let gamma = velocities(g, b, &p);
        let r = residual(&p, &gamma, b, mu);
        let (q, gq, rq) = if r <= s.tol_verify {
            (p.clone(), gamma, r)
        } else {
            // the iteration crawls (a stiff chain of contacts, redundant contacts): the exact
            // answer for the modes it has found, corrected mode by mode
            match active_set(g, b, mu, &p, s.tol_verify) {
                Some(x) if x.2 < r => x,
                _ => (p.clone(), gamma, r),
            }
        };
        if best.as_ref().is_none_or(|x| rq < x.2) {
            best = Some((q.clone(), gq, rq));
        }
        if rq <= s.tol_verify || !rq.is_finite() {
            break;
        }
        // the next round from the best answer, back in the cones
        p = q;
        for i in 0..n {
            p[i] = p[i].max(0.0);
            p[n + i] = p[n + i].clamp(-mu[i] * p[i], mu[i] * p[i]);
        }
    }
    let (p, gamma, residual) = best.expect("one round made");
    Fc2dSolution {
        converged: residual <= s.tol_verify,
        p,
        gamma,
        sweeps,
        residual,
    }
}

/// Rounds of sweeps and active-set corrections of [`solve_nsgs`].
const ROUNDS: usize = 4;

/// At most `max_sweeps` symmetric block Gauss–Seidel sweeps on `p` (stopping when one changes no
/// impulse by more than `tol` of the largest); returns the sweeps made.
fn sweep(g: &[Vec<Real>], b: &[Real], mu: &[Real], s: &Fc2dSettings, p: &mut [Real]) -> usize {
    let n = mu.len();
    // γ = G P + b, kept up to date as impulses change
    let mut gamma = velocities(g, b, p);
    let mut sweeps = 0;
    while sweeps < s.max_sweeps {
        let mut change: Real = 0.0;
        let forward = sweeps % 2 == 0;
        for k in 0..n {
            let i = if forward { k } else { n - 1 - k };
            let (ni, ti) = (i, n + i);
            let (a, c, d) = (g[ni][ni], g[ni][ti], g[ti][ti]);
            let old = [p[ni], p[ti]];
            let v = [
                gamma[ni] - a * old[0] - c * old[1],
                gamma[ti] - g[ti][ni] * old[0] - d * old[1],
            ];
            let new = local(v, a, c, d, mu[i]);
            let dp = [new[0] - old[0], new[1] - old[1]];
            if dp != [0.0, 0.0] {
                for (r, gr) in gamma.iter_mut().zip(g) {
                    *r += gr[ni] * dp[0] + gr[ti] * dp[1];
                }
                p[ni] = new[0];
                p[ti] = new[1];
                change = change.max(dp[0].abs()).max(dp[1].abs());
            }
        }
        sweeps += 1;
        let scale = p.iter().fold(0.0, |m: Real, v| m.max(v.abs()));
        if !change.is_finite() || change <= s.tol * scale {
            break;
        }
    }
    sweeps
}
