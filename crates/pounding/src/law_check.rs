//! Post-solve physics checks: the impact laws verified on the *recovered* post-impact velocities.
//!
//! Lemke's verification ([`crate::lcp`]) checks the LCP in its own variables
//! `x = (Λ_N, Λ_TR, γ_TL)`. Recovering `Λ_T = Λ_TR − μΛ_N` and then `γ⁺ = γ⁻ + GΛ` (or the body
//! velocities `u⁺ = u⁻ + M⁻¹WΛ`) can amplify the rounding of the split variables by `G_TT μΛ_N`:
//! with a tiny moment of inertia (`G_TT ≈ r²/I` huge) an LCP solution that passes Lemke's check
//! can give post-impact velocities that violate Coulomb's law by orders of magnitude. This module
//! checks, per contact `i`, with `ξ_N,i := γ_N,i⁺ + ε_N,i min(γ_N,i⁻, 0)` (spec §8, amended):
//!
//! | law | check |
//! |---|---|
//! | Newton, admissible | `ξ_N,i ≥ −τ s_N,i` |
//! | Newton, complementary | `Λ_N,i ≤ t_N,i` or `|ξ_N,i| ≤ τ s_N,i` |
//! | Coulomb cone | `|Λ_T,i| ≤ μ_i Λ_N,i + t_T,i`, `Λ_N,i ≥ −t_N,i` |
//! | sliding (`|γ_T,i⁺| > τ s_T,i`) | `|Λ_T,i + μ_i Λ_N,i sign(γ_T,i⁺)| ≤ t_T,i` (opposite to the slip, on the cone's edge) |
//!
//! (stick inside the cone, `|Λ_T| < μΛ_N`, therefore requires `|γ_T⁺| ≤ τ s_T`.) The tolerance
//! `τ = `[`LAW_TOLERANCE`] is relative: `s_k` is the rounding scale of the recovered velocity `k`,
//! the sum of the magnitudes of the terms it was computed from (for body velocities
//! `s_k = Σ_d |W_dk| (|u⁻_d| + Σ_j |M⁻¹_d W_dj Λ_j|)`, in contact space
//! `s_k = |γ_k⁻| + Σ_j |G_kj Λ_j|`), plus the pre-impact velocity scale `V = max_k |γ_k⁻|` (so
//! the laws hold to `τ` of the impact's own velocities: the split `Λ_T = Λ_TR − μΛ_N` loses
//! `≈ 1e-16 μΛ_N` to rounding, whose effect `G_TT·1e-16 μΛ_N` is negligible against `V` unless `G`
//! is ill-conditioned). The impulse tolerance `t_k = τ max(‖Λ‖∞, s_k / G_kk)` is
//! relative to the largest impulse or, when every impulse is rounding noise, to the impulse whose
//! effect on velocity `k` is of the order of that velocity's rounding. Every check compares
//! quantities of one unit, so scaling all masses (or lengths, or velocities) by any factor changes
//! nothing. The split `Λ_TR = μΛ_N + Λ_T` is deliberately *not* part of `s_k`: its cancellation is
//! exactly the ill-conditioning to detect.
//!
//! **Energy** ([`energy_bound`]): with the laws above, for every contact
//! `½(γ_N⁺ + γ_N⁻)Λ_N = ½ c_i Λ_N` with `c_i = γ_N⁻ − ε min(γ_N⁻, 0)` and `γ_T⁺Λ_T = −μΛ_N|γ_T⁺| ≤ 0`,
//! so the exact work identity `ΔT = ½ (γ⁺ + γ⁻)ᵀ Λ` (spec §11) gives the provable bound
//! ```text
//! ΔT ≤ ½ Σ_i (c_i Λ_N,i + γ_T,i⁻ Λ_T,i)
//! ```
//! — the Newton–Coulomb allowance is the work `½ γ_T⁻ Λ_T` of the tangential impulse on the
//! pre-impact sliding velocity (for one approaching contact `c_i = (1 − ε)γ_N⁻ < 0`, so energy
//! can be created only through that term, spec §11). [`crate::impact::solve`] checks the kinetic
//! energies computed from the body velocities against this bound.

use crate::analytic::ImpactLaw;
use crate::math::Real;
use std::fmt;

/// Relative tolerance `τ` of the post-solve checks (see the module documentation). Rounding
/// errors of well-conditioned problems are of order 1e-15 relative; `τ` leaves seven orders of
/// magnitude for moderately ill-conditioned but trustworthy results.
pub const LAW_TOLERANCE: Real = 1e-8;

/// Which law a post-impact state violates (contact indices in input order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LawViolation {
    /// A number is not finite.
    NotFinite {
        /// Contact index.
        contact: usize,
    },
    /// The contact approaches after the impact: `ξ_N < 0`.
    NewtonAdmissible {
        /// Contact index.
        contact: usize,
        /// `ξ_N / s_N`.
        relative: Real,
    },
    /// `Λ_N > 0` but `ξ_N ≠ 0` (Newton's restitution not met).
    NewtonComplementarity {
        /// Contact index.
        contact: usize,
        /// `ξ_N / s_N`.
        relative: Real,
    },
    /// `|Λ_T| > μ Λ_N` or `Λ_N < 0`.
    CoulombCone {
        /// Contact index.
        contact: usize,
    },
    /// Sliding, but the tangential impulse is not `−μ Λ_N sign(γ_T⁺)` (wrong direction, or inside
    /// the cone: a stick impulse with a sliding velocity).
    SlipDirection {
        /// Contact index.
        contact: usize,
        /// `γ_T⁺ / s_T`.
        relative_slip: Real,
    },
    /// The kinetic energy after the impact exceeds the Newton–Coulomb bound ([`energy_bound`]).
    EnergyCreated {
        /// `T⁺ − T⁻` \[J\].
        gain: Real,
        /// The bound \[J\].
        bound: Real,
    },
}

impl fmt::Display for LawViolation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotFinite { contact } => write!(f, "contact {contact}: non-finite result"),
            Self::NewtonAdmissible { contact, relative } => write!(
                f,
                "contact {contact}: approaches after the impact (xi_N / scale = {relative:e})"
            ),
            Self::NewtonComplementarity { contact, relative } => write!(
                f,
                "contact {contact}: normal impulse with xi_N != 0 (xi_N / scale = {relative:e})"
            ),
            Self::CoulombCone { contact } => {
                write!(f, "contact {contact}: impulse outside the Coulomb cone")
            }
            Self::SlipDirection {
                contact,
                relative_slip,
            } => write!(
                f,
                "contact {contact}: slides (gamma_T+ / scale = {relative_slip:e}) but Lambda_T != -mu Lambda_N sign(gamma_T+)"
            ),
            Self::EnergyCreated { gain, bound } => write!(
                f,
                "kinetic energy gain {gain:e} J exceeds the Newton-Coulomb bound {bound:e} J"
            ),
        }
    }
}

/// Checks the Newton and Coulomb laws of `n = laws.len()` contacts on recovered post-impact
/// velocities (module documentation). Slices have length `2n` (blocks `[N…, T…]`):
/// `gamma_pre` (the `γ⁻` of the Newton law), `lambda` (`Λ_N`, `Λ_T`), `gamma_post` (recovered
/// `γ⁺`), `scale` (their rounding scales `s_k`, without `V`, which is added here) and `g_diag`
/// (the Delassus diagonal `G_kk > 0`).
pub fn check_laws(
    laws: &[ImpactLaw],
    gamma_pre: &[Real],
    lambda: &[Real],
    gamma_post: &[Real],
    scale: &[Real],
    g_diag: &[Real],
) -> Result<(), LawViolation> {
    let n = laws.len();
    let lmax = lambda[..2 * n]
        .iter()
        .fold(0.0, |m: Real, &x| m.max(x.abs()));
    let vmax = gamma_pre[..2 * n]
        .iter()
        .fold(0.0, |m: Real, &x| m.max(x.abs()));
    let sc = |k: usize| scale[k] + vmax;
    let tol_impulse = |k: usize| {
        let by_velocity = if g_diag[k] > 0.0 {
            sc(k) / g_diag[k]
        } else {
            0.0
        };
        LAW_TOLERANCE * lmax.max(by_velocity)
    };
    for (i, law) in laws.iter().enumerate() {
        let (tn, tt) = (tol_impulse(i), tol_impulse(n + i));
        let (ln, lt) = (lambda[i], lambda[n + i]);
        let (gnp, gtp) = (gamma_post[i], gamma_post[n + i]);
        let (sn, st) = (sc(i), sc(n + i));
        if ![ln, lt, gnp, gtp, sn, st, gamma_pre[i]]
            .iter()
            .all(|x| x.is_finite())
        {
            return Err(LawViolation::NotFinite { contact: i });
        }
        let xi = gnp + law.eps() * gamma_pre[i].min(0.0);
        let rel = |v: Real, s: Real| {
            if s > 0.0 {
                v / s
            } else {
                v.signum() * Real::INFINITY
            }
        };
        if xi < -LAW_TOLERANCE * sn {
            return Err(LawViolation::NewtonAdmissible {
                contact: i,
                relative: rel(xi, sn),
            });
        }
        if ln > tn && xi.abs() > LAW_TOLERANCE * sn {
            return Err(LawViolation::NewtonComplementarity {
                contact: i,
                relative: rel(xi, sn),
            });
        }
        let mu = law.mu();
        if ln < -tn || lt.abs() > mu * ln.max(0.0) + tt {
            return Err(LawViolation::CoulombCone { contact: i });
        }
        if gtp.abs() > LAW_TOLERANCE * st && (lt + mu * ln.max(0.0) * gtp.signum()).abs() > tt {
            return Err(LawViolation::SlipDirection {
                contact: i,
                relative_slip: rel(gtp, st),
            });
        }
    }
    Ok(())
}

/// Contact-space version of [`check_laws`] with `γ⁺ = γ_ref + GΛ` recomputed here: `g` is the
/// `2n × 2n` Delassus matrix (row-major, blocks `[N…, T…]`), `gamma_ref` the velocity the impulses
/// act on (`γ⁻` for an impact, the free velocity for a time step), `gamma_pre` the `γ⁻` of the
/// Newton law. Returns the recomputed `γ⁺` on success.
pub fn check_laws_contact_space(
    g: &[Real],
    laws: &[ImpactLaw],
    gamma_pre: &[Real],
    gamma_ref: &[Real],
    lambda: &[Real],
) -> Result<Vec<Real>, LawViolation> {
    let k = 2 * laws.len();
    let mut post = vec![0.0; k];
    let mut scale = vec![0.0; k];
    let diag: Vec<Real> = (0..k).map(|r| g[r * k + r]).collect();
    for r in 0..k {
        let (mut v, mut s) = (gamma_ref[r], gamma_ref[r].abs());
        for c in 0..k {
            let t = g[r * k + c] * lambda[c];
            v += t;
            s += t.abs();
        }
        post[r] = v;
        scale[r] = s;
    }
    check_laws(laws, gamma_pre, lambda, &post, &scale, &diag)?;
    Ok(post)
}

/// The Newton–Coulomb energy bound `½ Σ_i (c_i Λ_N,i + γ_T,i⁻ Λ_T,i)`,
/// `c_i = γ_N,i⁻ − ε_i min(γ_N,i⁻, 0)` (module documentation), and the sum of the magnitudes of
/// its terms (its rounding scale).
pub fn energy_bound(laws: &[ImpactLaw], gamma_pre: &[Real], lambda: &[Real]) -> (Real, Real) {
    let n = laws.len();
    let (mut b, mut s) = (0.0, 0.0);
    for (i, law) in laws.iter().enumerate() {
        let c = gamma_pre[i] - law.eps() * gamma_pre[i].min(0.0);
        let tn = 0.5 * c * lambda[i];
        let tt = 0.5 * gamma_pre[n + i] * lambda[n + i];
        b += tn + tt;
        s += tn.abs() + tt.abs();
    }
    (b, s)
}
