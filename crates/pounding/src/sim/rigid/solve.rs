//! The contact LCP of a rigid step (spec §8) and its solvers: the size-specialised Lemke
//! kernels, the dynamic kernel, enumeration, the block Gauss–Seidel for many contacts and the
//! frictionless LCP as the fallbacks.
#![allow(clippy::needless_range_loop)]

use super::{ActiveContact, Assembled, MAX_FIXED_CONTACTS, RigidStepper};
use crate::analytic::ImpactLaw;
use crate::lcp::{self, LcpStatus, LemkeSettings};
use crate::math::Real;

/// Lemke on the `N × N` row-major `a` (fixed-size kernel).
fn lemke_block<const N: usize>(
    a: &[Real],
    b: &[Real],
    settings: &LemkeSettings,
) -> Option<Vec<Real>> {
    let mut aa = [[0.0; N]; N];
    let mut bb = [0.0; N];
    for i in 0..N {
        aa[i].copy_from_slice(&a[i * N..(i + 1) * N]);
        bb[i] = b[i];
    }
    let s = lcp::solve_fixed::<N>(&aa, &bb, settings);
    (s.status == LcpStatus::Solved).then(|| s.z.to_vec())
}

/// Solves the contact LCP of size `3n` (`a` row-major) for `x = (P_N, P_TR, γ_TL)` (spec §8):
/// the fixed kernels for `n ≤ 6`, the dynamic one above, enumeration as the fallback.
/// Returns `(x, lemke_ok, any_ok)`.
fn solve_contact_lcp(
    n: usize,
    a: &[Real],
    b: &[Real],
    settings: &LemkeSettings,
) -> (Vec<Real>, bool, bool) {
    let m = 3 * n;
    let rows = || a.to_vec();
    let sol = match n {
        1 => lemke_block::<3>(a, b, settings),
        2 => lemke_block::<6>(a, b, settings),
        3 => lemke_block::<9>(a, b, settings),
        4 => lemke_block::<12>(a, b, settings),
        5 => lemke_block::<15>(a, b, settings),
        6 => lemke_block::<18>(a, b, settings),
        _ => lcp::LcpProblem::new(rows(), b[..m].to_vec())
            .ok()
            .map(|p| lcp::Lemke::new(settings.clone()).solve(&p))
            .filter(|s| s.status == LcpStatus::Solved)
            .map(|s| s.z),
    };
    if let Some(z) = sol {
        return (z, true, true);
    }
    // enumeration is exponential: only for the sizes of the two-deck model
    if n <= MAX_FIXED_CONTACTS
        && let Ok(p) = lcp::LcpProblem::new(rows(), b[..m].to_vec())
        && let Ok(sols) = lcp::enumerate(&p)
        && let Some(z) = sols.into_iter().next()
    {
        return (z, false, true);
    }
    (vec![0.0; m], false, false)
}

impl RigidStepper {
    /// The LCP (spec §8) of size `3n` and its solution `z = (P_N, P_TR, γ_TL)`, with the
    /// fallbacks; returns `(z, ok, any)`.
    pub(super) fn solve(
        &mut self,
        asm: &Assembled,
        active: &[ActiveContact],
    ) -> (Vec<Real>, bool, bool) {
        let (n, g) = (asm.n, &asm.g);
        let mu = |j: usize| active[j].law.mu();
        let m = 3 * n;
        // the one assembly of the impact LCP (`impact.rs`), on the step's free velocities
        let laws: Vec<ImpactLaw> = active.iter().map(|a| a.law).collect();
        let g_rows: Vec<Real> = g.iter().flatten().copied().collect();
        let (a, b) = crate::impact::impact_lcp_free(&g_rows, &laws, &asm.gam_pre, &asm.gam_free);
        // many contacts at once: the block Gauss–Seidel, verified (Lemke's dense tableau is
        // O(n²) per pivot and fails on the degenerate problems of permanent contact)
        if n > MAX_FIXED_CONTACTS {
            let mus: Vec<Real> = (0..n).map(mu).collect();
            let mut bb: Vec<Real> = b[..n].to_vec();
            bb.extend_from_slice(&b[n..2 * n]);
            let sol = lcp::fc2d::solve_nsgs(g, &bb, &mus, &lcp::fc2d::Fc2dSettings::default());
            if sol.converged {
                let mut z = vec![0.0; m];
                for i in 0..n {
                    z[i] = sol.p[i];
                    z[n + i] = sol.p[n + i] + mus[i] * sol.p[i];
                }
                return (z, true, true);
            }
        }
        // without friction at every active contact the tangential rows only say `P_T = 0`
        // (with `μ = 0` the friction-cone rows are degenerate: a rounding-level tangential
        // free velocity, e.g. from a yielding bearing's tangent, made Lemke fail on them)
        if active.iter().all(|a| a.law.mu() == 0.0) {
            let (z, ok, any) = self.frictionless(n, g, &b, &mu);
            if !(ok || any) {
                self.stats.lcp_failures += 1;
            } else if !ok {
                self.stats.lcp_enumeration_fallbacks += 1;
            }
            return (z, ok, any);
        }
        let (mut z, ok, any) = solve_contact_lcp(n, &a, &b, &self.lemke);
        if !ok {
            if any {
                self.stats.lcp_enumeration_fallbacks += 1;
            } else {
                self.stats.lcp_failures += 1;
                z = self.frictionless(n, g, &b, &mu).0;
            }
        }
        (z, ok, any)
    }

    /// The frictionless LCP in `P_N` (`G_NN P_N + b_N ≥ 0`), with the tangential rows decoupled
    /// (`z = 0`, `w = 1`); returns `z` with `P_TR = μ P_N`, i.e. `P_T = 0`, and `(ok, any)` as
    /// [`solve_contact_lcp`].
    fn frictionless(
        &self,
        n: usize,
        g: &[Vec<Real>],
        b: &[Real],
        mu: &dyn Fn(usize) -> Real,
    ) -> (Vec<Real>, bool, bool) {
        let m = 3 * n;
        let mut a0 = vec![0.0; m * m];
        let mut b0 = vec![0.0; m];
        for i in 0..n {
            a0[i * m..i * m + n].copy_from_slice(&g[i][..n]);
            b0[i] = b[i];
            // decouple the dummy rows: z = 0, w = 1
            a0[(n + i) * m + n + i] = 1.0;
            a0[(2 * n + i) * m + 2 * n + i] = 1.0;
            b0[n + i] = 1.0;
            b0[2 * n + i] = 1.0;
        }
        let (mut z, ok, any) = solve_contact_lcp(n, &a0, &b0, &self.lemke);
        for i in 0..n {
            z[n + i] = mu(i) * z[i]; // P_T = 0
        }
        (z, ok, any)
    }
}
