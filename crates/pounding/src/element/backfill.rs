//! Abutment backfill behind a backwall: OpenSees' `HyperbolicGapMaterial` (Wilson & Elgamal's
//! hyperbolic abutment model), compression-only with a gap, and the Caltrans SDC 2019 preset.
//!
//! # Sign convention
//! The deformation `u` is the backwall's displacement *into the backfill* (metres, positive
//! when the deck end pushes the wall into the soil); the force `F ≥ 0` is the soil's passive
//! resistance (the restoring force on the deck is `−F` along `u`). OpenSees works with the
//! opposite signs (compression negative, `gap` and `Fult` given negative): its strain is `−u`,
//! its stress `−F`, its `gap` and `Fult` are `−gap` and `−fult`, and the tangent is the same
//! number. Our `gap ≥ 0` and `fult > 0` are sizes.

use super::{ElementError, positive};
use crate::math::Real;

const BACKFILL: &str = "hyperbolic backfill";
const CALTRANS: &str = "Caltrans backwall";

/// One kip in newtons.
pub const KIP: Real = 4448.2216152605;
/// One foot in metres.
pub const FOOT: Real = 0.3048;
/// One inch in metres.
pub const INCH: Real = 0.0254;

/// The hyperbolic backfill law: parameters `kmax` (initial stiffness, N/m), `kur`
/// (unloading/reloading stiffness, N/m), `rf` (failure ratio, `0 < rf < 1`), `fult` (ultimate
/// passive force, N) and `gap` (m).
///
/// # Model (OpenSees `HyperbolicGapMaterial`, mirrored to our signs)
/// With the penetration `δ = u − gap` the backbone (envelope) is
/// ```text
/// F_env(u) = δ / (1/kmax + rf δ/fult)               for δ > 0, else 0
/// K_env(u) = 1 / (kmax (1/kmax + rf δ/fult)²)       for δ ≥ 0, else 0
/// ```
/// (so `F → fult/rf` as `δ → ∞`, and `F = fult` at `δ = fult/(kmax (1 − rf))`). The state holds
/// the committed `u_c`, `F_c`, tangent `K_c`, the largest deformation so far `u_max` (starting
/// at 0) and the reload onset `u_r` (starting at 0): the deformation at which the soil is met
/// again after an unloading. The trial at `u`:
/// ```text
/// u ≥ u_max:             F = F_env(u), K = K_env(u), u_max ← u                (envelope)
/// u > u_c  (reloading):  u < u_r:       F = 0, K = 0                          (gap open)
///                        F_c = 0:       F = kur (u − u_r), K = kur
///                        otherwise:     F = F_c + kur (u − u_c), K = kur
/// u < u_c  (unloading):  if u_c = u_max: u_r ← u_max − F_c/kur              (new onset)
///                        F = F_c + kur (u − u_c), K = kur; if F < 0: F = 0, K = 0
/// u = u_c:               F = F_c, K = K_c
/// ```
/// So unloading from the envelope follows the line of slope `kur` to zero force at `u_r`; the
/// gap grows to `u_r` (the soil stays displaced) and reloading follows the same line back to
/// the envelope. The initial state (OpenSees `revertToStart`) has `F = 0` and `K = kmax`.
///
/// # Agreement with OpenSees, and the two deviations
/// On a path where every trial is committed (OpenSees `testUniaxialMaterial` + `setStrain`)
/// the forces and tangents are OpenSees' (bit for bit on the paths the tests take from OpenSees
/// 3.7.1; the arithmetic is the same, mirrored), except:
/// 1. At a reload that lands *exactly* on `u_r` from the open gap (`F_c = 0`, `u = u_r`),
///    OpenSees keeps its provisional `F_c + kur (u − u_c) = kur (u_r − u_c) > 0` (its gap test
///    is strict on both sides), a force jump that then persists as an offset of the reloading
///    line; here `F = kur (u − u_r) = 0`, continuous.
/// 2. OpenSees carries `u_max` and `u_r` from one *trial* to the next within a step (a Newton
///    iterate that touched the envelope changes the later iterates); here the response is a
///    function of `u` and the committed state only, i.e. OpenSees with `revertToLastCommit`
///    before every trial.
///
/// # Energy
/// Stored energy `E = F²/(2 kur)` (what an unloading returns). The work along the envelope is
/// `Φ(δ) = ∫₀^δ F_env = fult²/(rf² kmax) · (z − ln(1 + z))` with `z = rf kmax δ/fult` (see
/// [`HyperbolicGap::envelope_work`]); on the `kur` lines and in the gap the work equals `ΔE`.
/// A step's hysteretic dissipation is `D = Φ(δ) − Φ(δ_max,c) − (F² − F_max,c²)/(2 kur)` when
/// it extends the envelope, else 0, so `W = ΔE + D` holds exactly for every step (`W` the
/// integral of the law's force along the step). `D ≥ 0` when `kur ≥ kmax` (the envelope is
/// never steeper than `kur`); with `kur < kmax` a small loop returns more energy than it
/// received and `D` is negative on the early envelope — the law (OpenSees' too) is then not
/// dissipative, and the value is reported as is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HyperbolicGap {
    kmax: Real,
    kur: Real,
    rf: Real,
    fult: Real,
    gap: Real,
}

/// A backfill state (OpenSees' committed variables, mirrored to our signs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HyperbolicGapState {
    /// Deformation `u` into the soil \[m\] (OpenSees `−Cstrain`).
    pub u: Real,
    /// Force `F ≥ 0` \[N\] (OpenSees `−Cstress`).
    pub force: Real,
    /// Tangent `dF/du` \[N/m\] at this state.
    pub tangent: Real,
    /// Largest deformation so far, starting at 0 \[m\] (OpenSees `−CstrainMin`).
    pub u_max: Real,
    /// Reload onset `u_r` \[m\]: where the soil is met again (OpenSees
    /// `−ConsetOfReloadingStrain`).
    pub reload_onset: Real,
}

/// The result of [`HyperbolicGap::response`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HyperbolicGapResponse {
    /// Force `F ≥ 0` \[N\].
    pub force: Real,
    /// Tangent `dF/du` \[N/m\].
    pub tangent: Real,
    /// The trial state; becomes the committed state when the step is accepted.
    pub trial: HyperbolicGapState,
    /// Hysteretic dissipation of the step `W − ΔE` \[J\] (see the type's docs for its sign).
    pub dissipation: Real,
    /// Whether the soil carries a positive force.
    pub in_contact: bool,
}

fn check_rf(element: &'static str, rf: Real) -> Result<Real, ElementError> {
    if rf.is_finite() && rf > 0.0 && rf < 1.0 {
        Ok(rf)
    } else {
        Err(ElementError::InvalidParameter {
            element,
            key: "rf",
            value: rf,
            reason: "must lie in (0, 1)",
        })
    }
}

impl HyperbolicGap {
    /// Validates `kmax > 0`, `kur > 0`, `0 < rf < 1`, `fult > 0`, `gap ≥ 0` (all finite);
    /// errors name the key (`kmax`, `kur`, `rf`, `fult`, `gap`).
    pub fn new(
        kmax: Real,
        kur: Real,
        rf: Real,
        fult: Real,
        gap: Real,
    ) -> Result<Self, ElementError> {
        Ok(HyperbolicGap {
            kmax: positive(BACKFILL, "kmax", kmax)?,
            kur: positive(BACKFILL, "kur", kur)?,
            rf: check_rf(BACKFILL, rf)?,
            fult: positive(BACKFILL, "fult", fult)?,
            gap: super::non_negative(BACKFILL, "gap", gap)?,
        })
    }

    /// The Caltrans SDC 2019 backwall (see [`CaltransBackwall`]) as a hyperbolic law with
    /// `kmax = kur = K`, `fult = F_ult` and `rf = 0.7` (the values OpenSees'
    /// `HyperbolicGapMaterial` documents as recommended, after Wilson & Elgamal), and the
    /// given gap \[m\].
    pub fn caltrans_sdc_2019(
        height: Real,
        width: Real,
        skew_deg: Real,
        gap: Real,
    ) -> Result<Self, ElementError> {
        let c = CaltransBackwall::new(height, width, skew_deg)?;
        HyperbolicGap::new(c.k, c.k, 0.7, c.f_ult, gap)
    }

    /// `kmax` \[N/m\].
    pub fn kmax(&self) -> Real {
        self.kmax
    }
    /// `kur` \[N/m\].
    pub fn kur(&self) -> Real {
        self.kur
    }
    /// `rf`.
    pub fn rf(&self) -> Real {
        self.rf
    }
    /// `fult` \[N\].
    pub fn fult(&self) -> Real {
        self.fult
    }
    /// `gap` \[m\].
    pub fn gap(&self) -> Real {
        self.gap
    }

    /// The virgin state (OpenSees `revertToStart`): all zero, tangent `kmax`.
    pub fn initial_state(&self) -> HyperbolicGapState {
        HyperbolicGapState {
            u: 0.0,
            force: 0.0,
            tangent: self.kmax,
            u_max: 0.0,
            reload_onset: 0.0,
        }
    }

    /// The backbone force `F_env(u)` \[N\] (0 up to the gap).
    pub fn envelope_force(&self, u: Real) -> Real {
        let d = u - self.gap;
        if d <= 0.0 {
            0.0
        } else {
            d / ((1.0 / self.kmax) + (self.rf * d / self.fult))
        }
    }

    /// The backbone tangent `K_env(u)` \[N/m\] (0 inside the gap, `kmax` at its closure).
    pub fn envelope_tangent(&self, u: Real) -> Real {
        let d = u - self.gap;
        if d < 0.0 {
            0.0
        } else {
            let s = (1.0 / self.kmax) + (self.rf * d / self.fult);
            1.0 / (self.kmax * (s * s))
        }
    }

    /// The work along the backbone from the gap closure to `u`, `Φ = ∫ F_env du` \[J\]:
    /// with `a = 1/kmax`, `b = rf/fult`, `z = b δ/a`, `Φ = (a/b²) (z − ln(1 + z))`.
    pub fn envelope_work(&self, u: Real) -> Real {
        let d = u - self.gap;
        if d <= 0.0 {
            return 0.0;
        }
        let (a, b) = (1.0 / self.kmax, self.rf / self.fult);
        let z = b * d / a;
        a / (b * b) * z_minus_ln_1p(z)
    }

    /// Force, tangent, trial state and dissipation at deformation `u` from the committed state
    /// (pure; commit by storing `trial`).
    pub fn response(&self, u: Real, c: &HyperbolicGapState) -> HyperbolicGapResponse {
        let mut trial = HyperbolicGapState { u, ..*c };
        let mut dissipation = 0.0;
        let du = u - c.u;
        let (force, tangent);
        if u >= c.u_max {
            trial.u_max = u;
            force = self.envelope_force(u);
            tangent = self.envelope_tangent(u);
            let f_m = self.envelope_force(c.u_max);
            dissipation = self.envelope_work(u)
                - self.envelope_work(c.u_max)
                - (force * force - f_m * f_m) / (2.0 * self.kur);
        } else if du > 0.0 {
            if u < c.reload_onset {
                (force, tangent) = (0.0, 0.0);
            } else if c.force == 0.0 {
                (force, tangent) = (self.kur * (u - c.reload_onset), self.kur);
            } else {
                (force, tangent) = (c.force + self.kur * du, self.kur);
            }
        } else if du < 0.0 {
            if c.u == c.u_max {
                trial.reload_onset = c.u_max - c.force / self.kur;
            }
            let f = c.force + self.kur * du;
            (force, tangent) = if f < 0.0 { (0.0, 0.0) } else { (f, self.kur) };
        } else {
            (force, tangent) = (c.force, c.tangent);
        }
        trial.force = force;
        trial.tangent = tangent;
        HyperbolicGapResponse {
            force,
            tangent,
            trial,
            dissipation,
            in_contact: force > 0.0,
        }
    }

    /// Stored (recoverable) energy `F²/(2 kur)` at a state \[J\].
    pub fn stored_energy(&self, state: &HyperbolicGapState) -> Real {
        0.5 * state.force * state.force / self.kur
    }
}

/// `z − ln(1 + z)` for `z ≥ 0` without cancellation at small `z` (series below 0.1).
fn z_minus_ln_1p(z: Real) -> Real {
    if z >= 0.1 {
        return z - z.ln_1p();
    }
    // z²/2 − z³/3 + z⁴/4 − …; 0.1^18/18 is below the double precision of z²/2.
    let (mut sum, mut p) = (0.0, z * z);
    for n in 2..20 {
        let term = p / n as Real;
        sum += if n % 2 == 0 { term } else { -term };
        p *= z;
    }
    sum
}

/// The Caltrans SDC 2019 (§6.3.1.2) backwall and backfill for a backwall of height `h` and
/// width `w` (feet) and skew `θ` (degrees), in US units
/// ```text
/// F_ult = w · 5.5 h^2.5 / (1 + 2.37 h) · e^(−θ/45)   [kip]
/// K     = w · (5.5 h + 20) · e^(−θ/45)               [kip/in]
/// ```
/// held here in SI (`f_ult` in N, `k` in N/m; 1 kip = 4448.2216152605 N, 1 ft = 0.3048 m,
/// 1 in = 0.0254 m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaltransBackwall {
    /// Ultimate passive force `F_ult` \[N\].
    pub f_ult: Real,
    /// Abutment stiffness `K` \[N/m\].
    pub k: Real,
}

impl CaltransBackwall {
    /// From the backwall height and width (metres) and the skew (degrees, `0 ≤ θ < 90`);
    /// errors name `height`, `width`, `skew`.
    pub fn new(height: Real, width: Real, skew_deg: Real) -> Result<Self, ElementError> {
        let h = positive(CALTRANS, "height", height)? / FOOT;
        let w = positive(CALTRANS, "width", width)? / FOOT;
        if !(skew_deg.is_finite() && (0.0..90.0).contains(&skew_deg)) {
            return Err(ElementError::InvalidParameter {
                element: CALTRANS,
                key: "skew",
                value: skew_deg,
                reason: "must lie in [0, 90) degrees",
            });
        }
        let r_sk = (-skew_deg / 45.0).exp();
        let f_kip = w * 5.5 * h.powf(2.5) / (1.0 + 2.37 * h) * r_sk;
        let k_kip_in = w * (5.5 * h + 20.0) * r_sk;
        Ok(CaltransBackwall {
            f_ult: f_kip * KIP,
            k: k_kip_in * KIP / INCH,
        })
    }
}

/// A backfill spring as a driver holds it: the law, the committed state and the accumulated
/// dissipation.
pub type BackfillElement = super::Held<HyperbolicGap>;

uniaxial_law!(HyperbolicGap, HyperbolicGapState, HyperbolicGapResponse);

#[cfg(test)]
mod tests {
    use super::*;

    /// The series branch of `z − ln(1 + z)` meets the direct formula at its switch point and
    /// keeps full relative precision where the direct formula cancels (z = 1e-6: z²/2 − z³/3 + z⁴/4).
    #[test]
    fn z_minus_ln_1p_is_accurate_on_both_branches() {
        let z: Real = 0.1 - 1e-12;
        let (series, direct) = (z_minus_ln_1p(z), z - z.ln_1p());
        assert!((series - direct).abs() <= 1e-13 * direct);
        let z: Real = 1e-6;
        let series = z * z / 2.0 - z * z * z / 3.0 + z * z * z * z / 4.0;
        assert!((z_minus_ln_1p(z) - series).abs() <= 1e-14 * series);
        assert_eq!(z_minus_ln_1p(0.0), 0.0);
    }
}
