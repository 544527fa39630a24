//! Synthetic (stochastic) accelerograms for trying the workflow without a record library
//! (`pounding motion synth`, issue 13). **Synthetic records are not a substitute for real
//! records in an assessment.**
//!
//! # Model
//! A stationary Gaussian process `s(t)` — white noise through the Kanai–Tajimi soil filter and
//! the Clough–Penzien high-pass filter — times a deterministic Saragoni–Hart envelope `e(t)`:
//! `a(t) = e(t) s(t)`. The two-sided power spectral density of `s` is
//!
//! ```text
//! S(ω) = S₀ · (ω_g⁴ + 4ζ_g²ω_g²ω²) / ((ω_g² − ω²)² + 4ζ_g²ω_g²ω²)
//!          · ω⁴ / ((ω_f² − ω²)² + 4ζ_f²ω_f²ω²),        E[s²] = ∫ S(ω) dω  (ω over ℝ)
//! ```
//!
//! (Kanai 1957; Tajimi 1960; Clough & Penzien, *Dynamics of Structures*, the filtered white
//! noise model). In state form, with white noise `w` (`E[w(t) w(t')] = 2π S₀ δ(t − t')`):
//!
//! ```text
//! ẍ_g + 2ζ_gω_g ẋ_g + ω_g² x_g = −w,     a₁ = −2ζ_gω_g ẋ_g − ω_g² x_g   (Kanai–Tajimi)
//! ẍ_f + 2ζ_fω_f ẋ_f + ω_f² x_f = a₁,     s = ẍ_f                         (Clough–Penzien)
//! ```
//!
//! **Integration**: the linear stochastic system `dX = A X dt + G dW` is sampled *exactly in
//! distribution*: `X_{k+1} = Φ X_k + η_k`, `Φ = e^{A dt}`, `η_k ~ N(0, Q)`,
//! `Q = ∫₀^dt e^{Aτ} G 2πS₀ Gᵀ e^{Aᵀτ} dτ`, both from one matrix exponential (Van Loan 1978),
//! and the state starts from the stationary covariance (the Lyapunov equation
//! `A P + P Aᵀ + 2πS₀ G Gᵀ = 0`), so `s` is stationary from `t = 0`: no time-step error, no
//! burn-in. `s_k = c·X_k` (no direct noise term: the output is a state readout).
//!
//! **Envelope** (Saragoni & Hart 1974, "Simulation of artificial earthquakes", EESD 2; in the
//! parameterisation of Boore 2003, "Simulation of ground motion using the stochastic method",
//! PAGEOPH 160): `e(t) = A (t/t_n)^b exp(−c t/t_n)` with `b = −ε ln η / (1 + ε (ln ε − 1))`,
//! `c = b/ε`, `A = (e/ε)^b`: the maximum 1 at `t = ε t_n` and `e(t_n) = η`; here `t_n` is the
//! record's duration, `ε = 0.2`, `η = 0.05` (Boore's values).
//!
//! **Baseline**: a linear acceleration baseline `c₀ + c₁ t` is subtracted, chosen so that the
//! final velocity *and* final displacement of the piecewise-linear record are zero (computed
//! exactly on the piecewise-linear samples; the record is thereby physically a motion that ends
//! at rest where it started).
//!
//! **Scaling**: with a target PGA every component is scaled to it (its largest `|a|` equals the
//! target exactly); without one the intensity is `S₀` as given (default
//! [`DEFAULT_S0`]).
//!
//! **Randomness**: component `c` (0 = x, 1 = y) of record `i` draws from
//! `ChaCha8Rng::seed_from_u64(seed)` on stream `2i + c`: each record depends on `(seed, i, c)`
//! only, so the bytes are the same for any thread count and any `--count` (record `i` of a suite
//! of 10 is record `i` of a suite of 20).

use crate::math::Real;
use nalgebra::{DMatrix, DVector, SMatrix, SVector};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use std::f64::consts::PI;
use thiserror::Error;

#[path = "synth_limits.rs"]
mod limits;
pub use limits::*;

/// Default white-noise intensity `S₀` \[m²/s³\] (two-sided): with the default filters and a
/// 20 s record it gives a PGA of the order of 0.2–0.4 g (used only without a target PGA).
pub const DEFAULT_S0: Real = 0.01;

/// Bad synthesis parameters; the message names the parameter (as the CLI flag where one exists).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SynthError {
    /// A parameter is out of range or not finite.
    #[error("invalid {name} = {value}: {reason}")]
    InvalidParameter {
        /// The parameter (`--count`, `--dt`, `omega_g`, …).
        name: String,
        /// The offending value as text.
        value: String,
        /// What was expected.
        reason: String,
    },
}

/// The model's parameters (defaults: firm soil, see the field docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SynthParams {
    /// Kanai–Tajimi soil frequency `ω_g` \[rad/s\]; default 15.6 (firm ground: Kanai 1957,
    /// Tajimi 1960, as quoted in Clough & Penzien's text).
    pub omega_g: Real,
    /// Kanai–Tajimi soil damping `ζ_g`; default 0.6 (same source).
    pub zeta_g: Real,
    /// Clough–Penzien high-pass frequency `ω_f` \[rad/s\]; default 1.5 (firm soil values quoted
    /// in Der Kiureghian & Neuenhofer 1992, EESD 21).
    pub omega_f: Real,
    /// Clough–Penzien damping `ζ_f`; default 0.6 (same source).
    pub zeta_f: Real,
    /// White-noise intensity `S₀` \[m²/s³\], two-sided; default [`DEFAULT_S0`].
    pub s0: Real,
    /// Saragoni–Hart `ε` (time of the envelope's peak over `t_n`); default 0.2 (Boore 2003).
    pub epsilon: Real,
    /// Saragoni–Hart `η` (the envelope at `t_n`); default 0.05 (Boore 2003).
    pub eta: Real,
    /// Sample interval \[s\]; default 0.01.
    pub dt: Real,
    /// Duration `t_n` \[s\]; default 20.
    pub duration: Real,
    /// Target PGA \[g\] of every component, or `None` (intensity `S₀`).
    pub pga_g: Option<Real>,
}

impl Default for SynthParams {
    fn default() -> Self {
        SynthParams {
            omega_g: 15.6,
            zeta_g: 0.6,
            omega_f: 1.5,
            zeta_f: 0.6,
            s0: DEFAULT_S0,
            epsilon: 0.2,
            eta: 0.05,
            dt: 0.01,
            duration: 20.0,
            pga_g: None,
        }
    }
}

impl SynthParams {
    /// Number of samples: `round(duration / dt) + 1` (t = 0 … duration).
    pub fn samples(&self) -> usize {
        (self.duration / self.dt).round() as usize + 1
    }

    /// The two-sided PSD `S(ω)` of the stationary process (module doc) \[m²/s³\].
    pub fn psd(&self, w: Real) -> Real {
        let (wg, zg, wf, zf) = (self.omega_g, self.zeta_g, self.omega_f, self.zeta_f);
        let w2 = w * w;
        let kt = (wg.powi(4) + 4.0 * zg * zg * wg * wg * w2)
            / ((wg * wg - w2).powi(2) + 4.0 * zg * zg * wg * wg * w2);
        let cp = w2 * w2 / ((wf * wf - w2).powi(2) + 4.0 * zf * zf * wf * wf * w2);
        self.s0 * kt * cp
    }

    /// The Saragoni–Hart envelope `e(t)` (module doc), 1 at `t = ε t_n`.
    pub fn envelope(&self, t: Real) -> Real {
        let (eps, eta) = (self.epsilon, self.eta);
        let b = -eps * eta.ln() / (1.0 + eps * (eps.ln() - 1.0));
        let c = b / eps;
        let x = t / self.duration;
        if x <= 0.0 {
            return 0.0;
        }
        (1f64.exp() / eps).powf(b) * x.powf(b) * (-c * x).exp()
    }
}

type M4 = SMatrix<Real, 4, 4>;
type V4 = SVector<Real, 4>;

/// The exact one-step sampler of the filter state: `X ← Φ X + L z`, `z ~ N(0, I)`,
/// `L Lᵀ = Q`; `P0` a factor of the stationary covariance; `c` the output row.
struct Sampler {
    phi: M4,
    l: M4,
    p0: M4,
    c: V4,
}

/// A symmetric positive semi-definite `m`'s factor `V √Λ` (negative rounding clamped to 0).
fn psd_factor(m: &M4) -> M4 {
    let e = (0.5 * (m + m.transpose())).symmetric_eigen();
    let mut l = e.eigenvectors;
    for (j, &lam) in e.eigenvalues.iter().enumerate() {
        let s = lam.max(0.0).sqrt();
        for i in 0..4 {
            l[(i, j)] *= s;
        }
    }
    l
}

impl Sampler {
    fn new(p: &SynthParams) -> Self {
        let (wg, zg, wf, zf) = (p.omega_g, p.zeta_g, p.omega_f, p.zeta_f);
        // X = (x_g, ẋ_g, x_f, ẋ_f)
        let a = M4::new(
            0.0,
            1.0,
            0.0,
            0.0,
            -wg * wg,
            -2.0 * zg * wg,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            1.0,
            -wg * wg,
            -2.0 * zg * wg,
            -wf * wf,
            -2.0 * zf * wf,
        );
        let mut qc = M4::zeros();
        qc[(1, 1)] = 2.0 * PI * p.s0;
        // Van Loan: exp([[−A, Qc], [0, Aᵀ]] h) = [[·, F12], [0, F22]], Φ = F22ᵀ, Q = Φ F12
        let mut big = DMatrix::<Real>::zeros(8, 8);
        for i in 0..4 {
            for j in 0..4 {
                big[(i, j)] = -a[(i, j)] * p.dt;
                big[(i, j + 4)] = qc[(i, j)] * p.dt;
                big[(i + 4, j + 4)] = a[(j, i)] * p.dt;
            }
        }
        let e = big.exp();
        let f12 = M4::from_fn(|i, j| e[(i, j + 4)]);
        let phi = M4::from_fn(|i, j| e[(j + 4, i + 4)]);
        let q = phi * f12;
        // stationary covariance: (I ⊗ A + A ⊗ I) vec P = −vec Qc
        let mut k = DMatrix::<Real>::zeros(16, 16);
        for i in 0..4 {
            for j in 0..4 {
                for m in 0..4 {
                    // row (i, j) of vec P (column-major index i + 4j)
                    k[(i + 4 * j, m + 4 * j)] += a[(i, m)];
                    k[(i + 4 * j, i + 4 * m)] += a[(j, m)];
                }
            }
        }
        let rhs = DVector::from_iterator(16, (0..16).map(|r| -qc[(r % 4, r / 4)]));
        let vp = k
            .lu()
            .solve(&rhs)
            .expect("the filters are stable: A ⊕ A is regular");
        let pst = M4::from_fn(|i, j| vp[i + 4 * j]);
        let c = V4::new(-wg * wg, -2.0 * zg * wg, -wf * wf, -2.0 * zf * wf);
        Sampler {
            phi,
            l: psd_factor(&q),
            p0: psd_factor(&pst),
            c,
        }
    }

    /// `n` samples of the stationary process `s` from `rng`.
    fn run(&self, rng: &mut ChaCha8Rng, n: usize) -> Vec<Real> {
        let mut z = || V4::from_fn(|_, _| StandardNormal.sample(rng));
        let mut x = self.p0 * z();
        let mut out = Vec::with_capacity(n);
        for _ in 0..n {
            out.push(self.c.dot(&x));
            x = self.phi * x + self.l * z();
        }
        out
    }
}

/// `n` samples at `dt` of the stationary Kanai–Tajimi–Clough–Penzien process \[m/s²\] (no
/// envelope, no baseline, no scaling) for record `index`, component `comp` (0 = x, 1 = y).
pub fn stationary(p: &SynthParams, seed: u64, index: usize, comp: u64) -> Vec<Real> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(2 * index as u64 + comp);
    Sampler::new(p).run(&mut rng, p.samples())
}

/// Subtracts the linear baseline `c₀ + c₁ t` that makes the final velocity and displacement of
/// the piecewise-linear record `a` (sample interval `dt`, from rest) zero (module doc).
pub fn baseline_correct(dt: Real, a: &mut [Real]) {
    // end velocity and displacement of a piecewise-linear record, exactly
    let ends = |f: &dyn Fn(usize) -> Real| {
        let (mut v, mut d) = (0.0, 0.0);
        for k in 0..a.len().saturating_sub(1) {
            let (a0, a1) = (f(k), f(k + 1));
            d += v * dt + dt * dt * (2.0 * a0 + a1) / 6.0;
            v += 0.5 * dt * (a0 + a1);
        }
        (v, d)
    };
    let (v, d) = ends(&|k| a[k]);
    let (v0, d0) = ends(&|_| 1.0);
    let (v1, d1) = ends(&|k| k as Real * dt);
    let det = v0 * d1 - v1 * d0;
    if det == 0.0 {
        return;
    }
    let c0 = (v * d1 - v1 * d) / det;
    let c1 = (v0 * d - v * d0) / det;
    for (k, x) in a.iter_mut().enumerate() {
        *x -= c0 + c1 * k as Real * dt;
    }
}

/// One component in g: the stationary process times the envelope, baseline-corrected, scaled
/// to the target PGA when one is given (its largest `|a|` then equals the target exactly).
pub fn component_g(p: &SynthParams, seed: u64, index: usize, comp: u64) -> Vec<Real> {
    let mut a = stationary(p, seed, index, comp);
    for (k, x) in a.iter_mut().enumerate() {
        *x *= p.envelope(k as Real * p.dt);
    }
    baseline_correct(p.dt, &mut a);
    let mut g: Vec<Real> = a.iter().map(|x| x / crate::ground_motion::G0).collect();
    if let Some(target) = p.pga_g {
        let (imax, peak) =
            g.iter().enumerate().fold(
                (0, 0.0),
                |(i, m), (k, x)| if x.abs() > m { (k, x.abs()) } else { (i, m) },
            );
        if peak > 0.0 {
            let f = target / peak;
            g.iter_mut().for_each(|x| *x *= f);
            g[imax] = target.copysign(g[imax]);
        }
    }
    g
}

/// One synthetic record: id and its one or two components in g.
#[derive(Debug, Clone, PartialEq)]
pub struct SynthRecord {
    /// `SYN001`, … (zero-padded to the width of the count, at least 3 digits).
    pub id: String,
    /// The first horizontal component \[g\].
    pub x: Vec<Real>,
    /// The second horizontal component \[g\] (pairs only).
    pub y: Option<Vec<Real>>,
}

/// The suite of `count` records (in parallel; the result is independent of the thread count).
pub fn suite(
    p: &SynthParams,
    count: usize,
    seed: u64,
    pairs: bool,
) -> Result<Vec<SynthRecord>, SynthError> {
    use rayon::prelude::*;
    check_count(count)?;
    check_seed(seed)?;
    p.check()?;
    check_suite_size(p, count, pairs)?;
    let width = count.to_string().len().max(3);
    Ok((0..count)
        .into_par_iter()
        .map(|i| SynthRecord {
            id: format!("SYN{:0width$}", i + 1),
            x: component_g(p, seed, i, 0),
            y: pairs.then(|| component_g(p, seed, i, 1)),
        })
        .collect())
}

#[path = "synth_files.rs"]
mod files;
pub use files::{WriteSuiteError, at2_text, readme_text, suite_toml, synth_source, write_suite};
