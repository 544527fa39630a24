//! The lagged coherency models of [`super`] (`--coherency`).

use super::{SvgmError, bad};
use crate::math::Real;
use crate::output::float_token as f;

/// The lagged coherency `|γ(ξ, ω)|` between two supports `ξ` metres apart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Coherency {
    /// Harichandran & Vanmarcke (1986), "Stochastic variation of earthquake ground motion in space
    /// and time", J. Eng. Mech. 112(2):
    /// `|γ| = A exp(−2ξ(1 − A + αA)/(α θ(ω))) + (1 − A) exp(−2ξ(1 − A + αA)/θ(ω))`,
    /// `θ(ω) = k [1 + (ω/ω₀)^b]^{−1/2}`. Defaults ([`Coherency::HV_SMART1`]): SMART-1 array,
    /// Event 20: `A = 0.736`, `α = 0.147`, `k = 5210 m`, `ω₀ = 6.85 rad/s`, `b = 2.78`.
    HarichandranVanmarcke {
        /// `A` in (0, 1] (`--hv-a`).
        a: Real,
        /// `α` > 0 (`--hv-alpha`).
        alpha: Real,
        /// `k` > 0 \[m\] (`--hv-k`).
        k: Real,
        /// `ω₀` > 0 \[rad/s\] (`--hv-omega0`).
        omega0: Real,
        /// `b` > 0 (`--hv-b`).
        b: Real,
    },
    /// Luco & Wong (1986), "Response of a rigid foundation to a spatially random ground motion",
    /// EESD 14: `|γ| = exp(−(α ω ξ / v_s)²)`, the parameter `α/v_s` \[s/m\] (`--lw-alpha-vs`, > 0;
    /// default [`Coherency::LW_DEFAULT`]).
    LucoWong {
        /// `α/v_s` \[s/m\].
        alpha_over_vs: Real,
    },
    /// Fully coherent (`|γ| = 1`): the same motion at every support, delayed by wave passage.
    Full,
    /// Independent supports (`γ_jk = 0` for `j ≠ k`): for testing, not a physical model.
    Independent,
}

impl Coherency {
    /// Harichandran–Vanmarcke with the SMART-1 Event 20 parameters (the default model).
    pub const HV_SMART1: Coherency = Coherency::HarichandranVanmarcke {
        a: 0.736,
        alpha: 0.147,
        k: 5210.0,
        omega0: 6.85,
        b: 2.78,
    };
    /// Luco–Wong with `α/v_s = 2.5e-4 s/m` (e.g. `α ≈ 0.1`–`0.5` with `v_s` of several hundred
    /// to 2000 m/s gives values of this order; a mid-range choice, not a site value).
    pub const LW_DEFAULT: Coherency = Coherency::LucoWong {
        alpha_over_vs: 2.5e-4,
    };

    /// The model's CLI name (`--coherency`).
    pub fn name(&self) -> &'static str {
        match self {
            Coherency::HarichandranVanmarcke { .. } => "harichandran-vanmarcke",
            Coherency::LucoWong { .. } => "luco-wong",
            Coherency::Full => "none",
            Coherency::Independent => "independent",
        }
    }

    /// `|γ(ξ, ω)|` for separation `ξ ≥ 0` \[m\] and frequency `ω ≥ 0` \[rad/s\].
    pub fn value(&self, xi: Real, w: Real) -> Real {
        if xi == 0.0 {
            return 1.0;
        }
        match *self {
            Coherency::HarichandranVanmarcke {
                a,
                alpha,
                k,
                omega0,
                b,
            } => {
                let theta = k / (1.0 + (w / omega0).powf(b)).sqrt();
                let c = 2.0 * xi * (1.0 - a + alpha * a) / theta;
                a * (-c / alpha).exp() + (1.0 - a) * (-c).exp()
            }
            Coherency::LucoWong { alpha_over_vs } => (-(alpha_over_vs * w * xi).powi(2)).exp(),
            Coherency::Full => 1.0,
            Coherency::Independent => 0.0,
        }
    }

    /// Checks the parameters (finite; `A` in (0, 1]; `α`, `k`, `ω₀`, `b`, `α/v_s` > 0).
    pub fn check(&self) -> Result<(), SvgmError> {
        let pos = |name: &str, v: Real| {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(bad(name, f(v), "must be finite and > 0"))
            }
        };
        match *self {
            Coherency::HarichandranVanmarcke {
                a,
                alpha,
                k,
                omega0,
                b,
            } => {
                if !(a.is_finite() && a > 0.0 && a <= 1.0) {
                    return Err(bad("--hv-a", f(a), "must lie in (0, 1]"));
                }
                pos("--hv-alpha", alpha)?;
                pos("--hv-k", k)?;
                pos("--hv-omega0", omega0)?;
                pos("--hv-b", b)
            }
            Coherency::LucoWong { alpha_over_vs } => pos("--lw-alpha-vs", alpha_over_vs),
            Coherency::Full | Coherency::Independent => Ok(()),
        }
    }

    /// The model and its parameters as flags (`--coherency harichandran-vanmarcke --hv-a 0.736 …`).
    pub fn flags(&self) -> String {
        let mut s = format!("--coherency {}", self.name());
        match *self {
            Coherency::HarichandranVanmarcke {
                a,
                alpha,
                k,
                omega0,
                b,
            } => s.push_str(&format!(
                " --hv-a {} --hv-alpha {} --hv-k {} --hv-omega0 {} --hv-b {}",
                f(a),
                f(alpha),
                f(k),
                f(omega0),
                f(b)
            )),
            Coherency::LucoWong { alpha_over_vs } => {
                s.push_str(&format!(" --lw-alpha-vs {}", f(alpha_over_vs)))
            }
            Coherency::Full | Coherency::Independent => {}
        }
        s
    }
}
