//! The standard normal distribution: `Φ`, `ln Φ`, `Φ⁻¹` and the density, accurate in the tails.
//!
//! `Φ(z) = ½ erfc(−z/√2)`. The complementary error function is the FreeBSD `s_erf.c` algorithm
//! (rational approximations on four intervals, relative error below one ulp; notice below). In the
//! tails `erfc(x)` is evaluated in the form `exp(−x² − 0.5625 + R(1/x²)) / x`, so its logarithm
//! is available without underflow: [`ln_cdf`] is accurate to a few ulps for every `z` (`ln Φ(−40)`
//! ≈ −804.6 where `Φ` itself underflows), and past `x = 28` the asymptotic series of Abramowitz &
//! Stegun 7.1.23 is used.
//!
//! `Φ⁻¹` starts from Abramowitz & Stegun 26.2.23 (error < 4.5·10⁻⁴) and refines it by Halley's
//! method on the accurate `Φ`, to a relative accuracy of a few ulps.
//!
//! ```text
//! ====================================================
//! Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//!
//! Developed at SunPro, a Sun Microsystems, Inc. business.
//! Permission to use, copy, modify, and distribute this
//! software is freely granted, provided that this notice
//! is preserved.
//! ====================================================
//! ```
//! (the notice of the erfc coefficients below, taken from FreeBSD `/usr/src/lib/msun/src/s_erf.c`
//! through the `libm` crate).

// The published coefficients keep their published digits (each rounds to the intended double).
#![allow(clippy::excessive_precision)]

use crate::math::Real;

const ERX: f64 = 8.45062911510467529297e-01;
const PP0: f64 = 1.28379167095512558561e-01;
const PP1: f64 = -3.25042107247001499370e-01;
const PP2: f64 = -2.84817495755985104766e-02;
const PP3: f64 = -5.77027029648944159157e-03;
const PP4: f64 = -2.37630166566501626084e-05;
const QQ1: f64 = 3.97917223959155352819e-01;
const QQ2: f64 = 6.50222499887672944485e-02;
const QQ3: f64 = 5.08130628187576562776e-03;
const QQ4: f64 = 1.32494738004321644526e-04;
const QQ5: f64 = -3.96022827877536812320e-06;
const PA: [f64; 7] = [
    -2.36211856075265944077e-03,
    4.14856118683748331666e-01,
    -3.72207876035701323847e-01,
    3.18346619901161753674e-01,
    -1.10894694282396677476e-01,
    3.54783043256182359371e-02,
    -2.16637559486879084300e-03,
];
const QA: [f64; 7] = [
    1.0,
    1.06420880400844228286e-01,
    5.40397917702171048937e-01,
    7.18286544141962662868e-02,
    1.26171219808761642112e-01,
    1.36370839120290507362e-02,
    1.19844998467991074170e-02,
];
const RA: [f64; 8] = [
    -9.86494403484714822705e-03,
    -6.93858572707181764372e-01,
    -1.05586262253232909814e+01,
    -6.23753324503260060396e+01,
    -1.62396669462573470355e+02,
    -1.84605092906711035994e+02,
    -8.12874355063065934246e+01,
    -9.81432934416914548592e+00,
];
const SA: [f64; 9] = [
    1.0,
    1.96512716674392571292e+01,
    1.37657754143519042600e+02,
    4.34565877475229228821e+02,
    6.45387271733267880336e+02,
    4.29008140027567833386e+02,
    1.08635005541779435134e+02,
    6.57024977031928170135e+00,
    -6.04244152148580987438e-02,
];
const RB: [f64; 7] = [
    -9.86494292470009928597e-03,
    -7.99283237680523006574e-01,
    -1.77579549177547519889e+01,
    -1.60636384855821916062e+02,
    -6.37566443368389627722e+02,
    -1.02509513161107724954e+03,
    -4.83519191608651397019e+02,
];
const SB: [f64; 8] = [
    1.0,
    3.03380607434824582924e+01,
    3.25792512996573918826e+02,
    1.53672958608443695994e+03,
    3.19985821950859553908e+03,
    2.55305040643316442583e+03,
    4.74528541206955367215e+02,
    -2.24409524465858183362e+01,
];

/// `ln √(2π)`.
const LN_SQRT_2PI: Real = 0.918_938_533_204_672_8;

fn poly(c: &[f64], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * s + k)
}

/// `erfc(x)` for `|x| < 0.84375`.
fn erfc_small(x: f64) -> f64 {
    let z = x * x;
    let r = PP0 + z * (PP1 + z * (PP2 + z * (PP3 + z * PP4)));
    let s = 1.0 + z * (QQ1 + z * (QQ2 + z * (QQ3 + z * (QQ4 + z * QQ5))));
    let y = r / s;
    if x < 0.25 {
        1.0 - (x + x * y)
    } else {
        0.5 - (x - 0.5 + x * y)
    }
}

/// `erfc(x)` for `0.84375 ≤ x < 1.25`.
fn erfc_mid(x: f64) -> f64 {
    let s = x - 1.0;
    1.0 - ERX - poly(&PA, s) / poly(&QA, s)
}

/// `ln erfc(x)` for `x ≥ 1.25` (no underflow for any finite `x`).
fn ln_erfc_tail(x: f64) -> f64 {
    // x² split as z² + (x − z)(x + z) with z = x rounded to 21 bits: z² is exact.
    let z = f64::from_bits(x.to_bits() & 0xffff_ffff_0000_0000);
    ln_erfc_tail_sq(x, z * z, (z - x) * (z + x))
}

/// `ln erfc(x)` for `x ≥ 1.25` given `x² = hi − lo` (`hi` the leading, exact part): the caller can
/// supply `x²` more accurately than `x` itself (`x = −z/√2` in [`ln_cdf`] is rounded; `z²/2` is
/// not).
fn ln_erfc_tail_sq(x: f64, hi: f64, lo: f64) -> f64 {
    if x >= 28.0 {
        // A&S 7.1.23: erfc x = e^{−x²}/(x√π) · (1 − 1/(2x²) + 3/(2x²)² − 15/(2x²)³ + …).
        let t = 1.0 / (2.0 * x * x);
        let series =
            1.0 - t * (1.0 - 3.0 * t * (1.0 - 5.0 * t * (1.0 - 7.0 * t * (1.0 - 9.0 * t))));
        return -hi + lo - x.ln() - 0.5 * std::f64::consts::PI.ln() + series.ln();
    }
    let s = 1.0 / (x * x);
    let (r, q) = if x < 1.0 / 0.35 {
        (poly(&RA, s), poly(&SA, s))
    } else {
        (poly(&RB, s), poly(&SB, s))
    };
    -hi - 0.5625 + (lo + r / q) - x.ln()
}

/// The complementary error function `erfc(x) = 1 − erf(x)`, relative error below ~1 ulp.
pub fn erfc(x: Real) -> Real {
    if x.is_nan() {
        return x;
    }
    let a = x.abs();
    let upper = if a < 0.84375 {
        return erfc_small(x);
    } else if a < 1.25 {
        erfc_mid(a)
    } else {
        ln_erfc_tail(a).exp()
    };
    if x < 0.0 { 2.0 - upper } else { upper }
}

/// `ln erfc(x)`, accurate for every `x` (finite for every finite `x`).
pub fn ln_erfc(x: Real) -> Real {
    if x >= 1.25 {
        ln_erfc_tail(x)
    } else {
        erfc(x).ln()
    }
}

/// The standard normal density `φ(z) = e^{−z²/2}/√(2π)`.
pub fn pdf(z: Real) -> Real {
    ln_pdf(z).exp()
}

/// `ln φ(z) = −z²/2 − ln √(2π)`.
pub fn ln_pdf(z: Real) -> Real {
    -0.5 * z * z - LN_SQRT_2PI
}

/// The standard normal distribution function `Φ(z) = ½ erfc(−z/√2)`, with a small relative
/// error in both tails (`Φ(−5) = 2.866515718791939·10⁻⁷`, `1 − Φ(z)` is [`cdf`]`(−z)`).
pub fn cdf(z: Real) -> Real {
    if z < -1.25 * std::f64::consts::SQRT_2 {
        ln_cdf(z).exp()
    } else {
        0.5 * erfc(-z / std::f64::consts::SQRT_2)
    }
}

/// `ln Φ(z)`, accurate for every `z`: through `ln erfc` in the lower tail (no underflow: `ln Φ(−40)
/// ≈ −804.61`), through `ln(1 − Φ(−z))` (`ln_1p`) in the upper tail.
pub fn ln_cdf(z: Real) -> Real {
    if z.is_nan() {
        return z;
    }
    if z < -1.25 * std::f64::consts::SQRT_2 {
        // x = −z/√2 and x² = z²/2, the latter from an exact split of z (x itself is rounded,
        // and erfc's relative sensitivity to x is 2x²).
        let x = -z / std::f64::consts::SQRT_2;
        let h = f64::from_bits(z.to_bits() & 0xffff_ffff_0000_0000);
        ln_erfc_tail_sq(x, 0.5 * (h * h), 0.5 * ((h - z) * (h + z))) - std::f64::consts::LN_2
    } else if z < -1.0 {
        ln_erfc(-z / std::f64::consts::SQRT_2) - std::f64::consts::LN_2
    } else if z > 1.0 {
        (-cdf(-z)).ln_1p()
    } else {
        cdf(z).ln()
    }
}

/// The inverse of the standard normal distribution function, `Φ⁻¹(p)` for `p ∈ (0, 1)`
/// (`−inf` at 0, `inf` at 1, NaN outside `[0, 1]`), e.g. `Φ⁻¹(0.975) = 1.959963984540054`.
pub fn quantile(p: Real) -> Real {
    if !(0.0..=1.0).contains(&p) {
        return Real::NAN;
    }
    if p == 0.0 {
        return Real::NEG_INFINITY;
    }
    if p == 1.0 {
        return Real::INFINITY;
    }
    if p > 0.5 {
        // Solve in the lower tail: Φ⁻¹(p) = −Φ⁻¹(1 − p), 1 − p exact for p > 0.5.
        return -quantile_lower(1.0 - p);
    }
    quantile_lower(p)
}

/// `Φ⁻¹(p)` for `0 < p ≤ 0.5`.
fn quantile_lower(p: Real) -> Real {
    // A&S 26.2.23 start.
    let t = (-2.0 * p.ln()).sqrt();
    let mut z = -(t
        - (2.515517 + t * (0.802853 + t * 0.010328))
            / (1.0 + t * (1.432788 + t * (0.189269 + t * 0.001308))));
    if p == 0.5 {
        return 0.0;
    }
    let ln_p = p.ln();
    for _ in 0..8 {
        // Halley on g(z) = ln Φ(z) − ln p (well scaled in the far tail):
        // g' = λ = φ/Φ, g'' = −λ(z + λ).
        let lc = ln_cdf(z);
        let g = lc - ln_p;
        let lam = (ln_pdf(z) - lc).exp();
        let g2 = -lam * (z + lam);
        let step = g / lam / (1.0 - 0.5 * g * g2 / (lam * lam));
        z -= step;
        if step.abs() <= 4.0 * Real::EPSILON * z.abs().max(1e-300) {
            break;
        }
    }
    z
}
