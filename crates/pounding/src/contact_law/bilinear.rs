//! The bilinear impact law (OpenSees `ImpactMaterial`): `law = "bilinear"`.

use super::*;
use crate::math::Real;
use crate::output::json_float;
use registry::{BuildError, DEFAULT_A, DEFAULT_DELTA_M, LawEntry, LawInputs, reads, default_k_h};

/// Bilinear impact law of Muthukumar (2003), exactly as OpenSees' `ImpactMaterial`.
///
/// Parameters: initial stiffness `K1`, secondary stiffness `K2` (`0 < K2 ≤ K1`), yield
/// penetration `δy > 0` (OpenSees takes `δy` and the gap as negative numbers because its
/// material is compression-negative; here they are positive and the gap belongs to the caller).
/// With `F_c`, `δ_c` the committed force and signed penetration and `Δδ = δ − δ_c`:
/// ```text
/// δ ≤ 0:           F = 0
/// Δδ > 0 (load):   F = min(F_c + K1 Δδ,  K1 δy + K2 (δ − δy))
/// Δδ < 0 (unload): F = max(F_c + K1 Δδ,  K2 δ)
/// Δδ = 0:          F = F_c
/// ```
/// The force stays in the band `K2 δ ≤ F ≤ K1 δy + K2 (δ − δy)`, moving with slope `K1` inside it;
/// it is never negative (clamped at 0 as a safeguard; the band already excludes it for `δ > 0`).
/// Loading from rest follows `K1` up to `δy`, then `K2`; unloading from `δm` follows `K1` down to
/// `δm − δy`, then `K2 δ` to zero: a parallelogram loop of area `(K1 − K2) δy (δm − δy)`
/// (for `δm ≥ 2 δy`).
///
/// **OpenSees quirk, reproduced**: `δ_c` is the committed *signed* penetration, also while the gap
/// is open, so the first closing step increments from a negative `δ_c` and gets
/// `F = min(K1 (δ − δ_c), …) > K1 δ`; the excess is at most `K1 |δ̇| Δt` and vanishes with `Δt`.
/// Rate independent (`∂F/∂δ̇ = 0`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BilinearImpact {
    k1: Real,
    k2: Real,
    delta_y: Real,
}

/// The derivation of [`BilinearImpact`] parameters from a Hertz stiffness (OpenSees wiki,
/// *Impact Material*; Muthukumar & DesRoches 2006), all SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BilinearDerivation {
    /// Effective stiffness `K_eff = k_h √δm` \[N/m\].
    pub k_eff: Real,
    /// Energy dissipated by the Hertz-damp law in an impact reaching `δm`:
    /// `ΔE = k_h δm^{n+1} (1 − e²) / (n + 1)`, `n = 3/2` \[J\].
    pub energy: Real,
    /// The law: `K1 = K_eff + ΔE/(a δm²)`, `K2 = K_eff − ΔE/((1 − a) δm²)`, `δy = a δm`.
    pub law: BilinearImpact,
}

impl BilinearImpact {
    /// Validates `K1 > 0`, `0 < K2 ≤ K1` \[N/m\] and `δy > 0` \[m\].
    pub fn new(k1: Real, k2: Real, delta_y: Real) -> Result<Self, ContactLawError> {
        let k1 = positive("k1", k1)?;
        let k2 = positive("k2", k2)?;
        if k2 > k1 {
            return Err(invalid("k2", k2, "must not exceed k1"));
        }
        Ok(BilinearImpact {
            k1,
            k2,
            delta_y: positive("delta_y", delta_y)?,
        })
    }
    /// Derives `K1`, `K2`, `δy` from a Hertz stiffness `k_h` \[N/m^{3/2}\], restitution
    /// `e ∈ (0, 1]`, design maximum penetration `δm > 0` \[m\] and yield ratio `a ∈ (0, 1)`
    /// (typically 0.1), as documented by OpenSees (*Impact Material*; Muthukumar & DesRoches 2006):
    /// ```text
    /// K_eff = k_h √δm,   ΔE = k_h δm^{5/2} (1 − e²) / (5/2),   δy = a δm
    /// K1 = K_eff + ΔE / (a δm²),   K2 = K_eff − ΔE / ((1 − a) δm²)
    /// ```
    /// so that an impact reaching `δm` dissipates `ΔE` (the loop area
    /// `(K1 − K2) δy (δm − δy) = ΔE`). Example (the issue's): `k_h = 25 000 kip/in^{3/2}`, `e = 0.6`,
    /// `δm = 1 in`, `a = 0.1` give `K1 = 89 000 kip/in = 1.5586e7 kN/m`,
    /// `K2 = 17 889 kip/in = 3.1328e6 kN/m`, `δy = 2.54 mm`. Note: the loop dissipates the
    /// Hertz-damp energy loss, but the bilinear loading path stores `½ K_eff δm² + ½ ΔE`, more than
    /// Hertz's `0.4 k_h δm^{5/2}`, so an isolated impact reaching `δm` rebounds with
    /// `e_bl = √(1 − ΔE / (½ K_eff δm² + ½ ΔE))` > `e` (0.770 for `e = 0.6`).
    /// Errors name `k_h`, `restitution`, `delta_m`, `a` (`K2 ≤ 0` happens for
    /// `a ≥ 1 − 0.4 (1 − e²)` and is reported on `a`).
    pub fn from_hertz(
        k_h: Real,
        e: Real,
        delta_m: Real,
        a: Real,
    ) -> Result<BilinearDerivation, ContactLawError> {
        let k_h = positive("k_h", k_h)?;
        let e = restitution("restitution", e)?;
        let dm = positive("delta_m", delta_m)?;
        if !(a.is_finite() && a > 0.0 && a < 1.0) {
            return Err(invalid("a", a, "must lie in (0, 1)"));
        }
        let n = 1.5;
        let k_eff = k_h * dm.sqrt();
        let energy = k_h * dm.powf(n + 1.0) * (1.0 - e * e) / (n + 1.0);
        let k1 = k_eff + energy / (a * dm * dm);
        let k2 = k_eff - energy / ((1.0 - a) * dm * dm);
        if k2.is_nan() || k2 <= 0.0 {
            return Err(invalid(
                "a",
                a,
                "gives a secondary stiffness K2 <= 0 (need a < 1 - 0.4 (1 - e^2))",
            ));
        }
        Ok(BilinearDerivation {
            k_eff,
            energy,
            law: BilinearImpact::new(k1, k2, a * dm)?,
        })
    }
    /// Initial (and unloading) stiffness `K1` \[N/m\].
    pub fn k1(&self) -> Real {
        self.k1
    }
    /// Secondary stiffness `K2` \[N/m\].
    pub fn k2(&self) -> Real {
        self.k2
    }
    /// Yield penetration `δy` \[m\].
    pub fn delta_y(&self) -> Real {
        self.delta_y
    }
    /// Loading envelope `K1 δ` for `δ ≤ δy`, `K1 δy + K2 (δ − δy)` beyond (`0` for `δ ≤ 0`).
    pub fn envelope(&self, delta: Real) -> Real {
        if delta <= 0.0 {
            0.0
        } else if delta <= self.delta_y {
            self.k1 * delta
        } else {
            self.k1 * self.delta_y + self.k2 * (delta - self.delta_y)
        }
    }
}

impl ContactForceLaw for BilinearImpact {
    fn evaluate(&self, state: &LawState, delta: Real, delta_dot: Real) -> Evaluation {
        if delta <= 0.0 {
            return Evaluation::open(delta);
        }
        let dd = delta - state.delta;
        let elastic = state.force + self.k1 * dd;
        let (f, kt) = if dd > 0.0 {
            let env = self.k1 * self.delta_y + self.k2 * (delta - self.delta_y);
            if elastic < env {
                (elastic, self.k1)
            } else {
                (env, self.k2)
            }
        } else if dd < 0.0 {
            let lower = self.k2 * delta;
            if elastic > lower {
                (elastic, self.k1)
            } else {
                (lower, self.k2)
            }
        } else {
            (state.force, self.k1)
        };
        let mut ev = Evaluation::closed(state, delta, delta_dot, f.max(0.0), kt, 0.0);
        // The committed δ is the signed penetration whatever the force (OpenSees' strain).
        ev.state.delta = delta;
        ev
    }
    fn name(&self) -> &'static str {
        "bilinear"
    }
    fn is_history_dependent(&self) -> bool {
        true
    }
    fn backbone_stiffness(&self, _delta: Real) -> Real {
        self.k1
    }
    fn backbone_penetration(&self, m_eff: Real, v: Real) -> Real {
        let ek = 0.5 * m_eff * v * v;
        let e_y = 0.5 * self.k1 * self.delta_y * self.delta_y;
        if ek <= e_y {
            v.abs() * (m_eff / self.k1).sqrt()
        } else {
            let r = ek - e_y;
            let b = self.k1 * self.delta_y;
            let s = 2.0 * r / (b + (b * b + 2.0 * self.k2 * r).sqrt());
            self.delta_y + s
        }
    }
    fn describe(&self) -> serde_json::Value {
        serde_json::json!({
            "law": "bilinear", "k1": json_float(self.k1()), "k2": json_float(self.k2()),
            "delta_y": json_float(self.delta_y())
        })
    }
}

/// The law's entry in [`registry::LAWS`] (name, `[contact]` keys and those read, description,
/// builder).
pub(crate) const ENTRY: LawEntry = LawEntry {
    name: "bilinear",
    keys: &["k1", "k2", "delta_y", "k_h", "restitution", "delta_m", "a"],
    reads: |given| match given("k1") || given("k2") || given("delta_y") {
        true => reads(&["k1", "k2", "delta_y"], " with k1, k2, delta_y given"),
        false => reads(
            &["k_h", "restitution", "delta_m", "a"],
            " without k1, k2, delta_y",
        ),
    },
    description: "bilinear impact (OpenSees ImpactMaterial)",
    build,
};

/// Builds the law from `[contact] k1`, `k2`, `delta_y` (all three), or none of them and the
/// law derived from `k_h`, `restitution`, `delta_m`, `a` ([`BilinearImpact::from_hertz`]).
fn build(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    Ok(match (p.get("k1"), p.get("k2"), p.get("delta_y")) {
        (None, None, None) => {
            BilinearImpact::from_hertz(
                p.get("k_h").unwrap_or_else(default_k_h),
                p.restitution,
                p.get("delta_m").unwrap_or(DEFAULT_DELTA_M),
                p.get("a").unwrap_or(DEFAULT_A),
            )?
            .law
        }
        (Some(k1), Some(k2), Some(dy)) => BilinearImpact::new(k1, k2, dy)?,
        _ => {
            return Err(BuildError::Incomplete {
                keys: &["k1", "k2", "delta_y"],
                hint: "or none, to derive them from k_h, restitution, delta_m, a",
            });
        }
    }
    .into())
}
