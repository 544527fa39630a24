//! Spatially variable ground motions (`pounding motion svgm`): acceleration histories at `S`
//! supports along a line (a long bridge's abutments and piers) that differ by **wave passage**
//! and **loss of coherency**, simulated by the spectral representation method. Like
//! [`super::synth`], these are stochastic motions for trying a multi-support analysis, not a
//! substitute for recorded motions. Site response per support is not modelled (every support has
//! the same power spectral density). [`Conditioned`] simulates the motions conditioned on a
//! recorded motion at one support.
//!
//! # Cross-spectral density
//! Support `j` sits at position `x_j` (metres, strictly increasing along the direction the wave
//! travels). The two-sided cross-spectral density matrix (`ω` over ℝ, `E[a_j a_k]` at lag 0 is
//! `∫ Re S_jk dω`) is
//!
//! ```text
//! S_jk(ω) = √(S_j(ω) S_k(ω)) · γ_jk(ω) · exp(−i ω (x_k − x_j) / v_app),     ξ_jk = |x_k − x_j|
//! ```
//!
//! with the Clough–Penzien PSD `S_j = S` of [`super::synth::SynthParams::psd`] (two-sided,
//! intensity `S₀` in m²/s³) at every support and the real, non-negative *lagged* coherency
//! `γ_jk` ([`Coherency`]). **Sign convention**: with `R_jk(τ) = E[a_j(t) a_k(t + τ)]` and
//! `S_jk(ω) = (1/2π) ∫ R_jk(τ) e^{−iωτ} dτ`, the phase `−ω (x_k − x_j)/v_app` means that the wave
//! travels toward increasing position: support `k > j` sees the motion of `j`
//! `(x_k − x_j)/v_app` seconds later. `v_app = ∞` removes wave passage.
//!
//! # Spectral representation (Deodatis 1996)
//! With `D = diag(√S e^{iωτ_j})`, `τ_j = (x_j − x_1)/v_app` (the travel time from the first
//! support; a delay common to all supports changes nothing), `S(ω) = D Γ(ω) D*`, so the lower-triangular factor
//! `H = D L` with `Γ = L Lᵀ` the real Cholesky factor of the coherency matrix. Realisations:
//!
//! ```text
//! a_j(t) = 2 Σ_{m=1..S} Σ_{l=0..N−1} |H_jm(ω_ml)| √Δω cos(ω_ml t − θ_jm(ω_ml) + Φ_ml)
//!        = 2 Σ_m Σ_l √(S(ω_ml) Δω) L_jm(ω_ml) cos(ω_ml (t − τ_j) + Φ_ml),   τ_j = (x_j − x_1)/v_app
//! ω_ml = (l + m/S) Δω,   Δω = 2π/(M Δt),   N = M/2 (ω up to the Nyquist frequency π/Δt)
//! ```
//!
//! with independent phases `Φ_ml` uniform on `[0, 2π)` and `M` the smallest power of two not
//! below the number of samples (period of a realisation `S M Δt` ≥ the duration). Each inner sum
//! over `l` is one FFT of length `M` ([`Fft`]); the double-indexed frequencies make the
//! realisations ergodic in correlation (Deodatis 1996). The process is Gaussian as the sum of
//! many terms.
//!
//! **Semi-definite coherency.** The Cholesky factorisation is the one of a positive
//! *semi*-definite matrix: a pivot below `1e-12` (the diagonal of `Γ` is 1) is taken as zero and
//! its column of `L` set to zero (for a semi-definite matrix the rest of that Schur-complement
//! column is then zero too). So the fully coherent `none` (`Γ = 11ᵀ`, rank 1) gives one process
//! at every support, delayed by `τ_j`. A pivot below `−1e-9` is a matrix that is not
//! positive semi-definite ([`SvgmError::NotPositiveSemiDefinite`]); the models here are
//! positive semi-definite for supports on a line (sums of exponential and Gaussian kernels of the
//! separation), so that is numerical trouble, reported, never silently repaired.
//!
//! # Envelope, baseline, scaling
//! Unless `stationary`, support `j`'s stationary samples are multiplied by the Saragoni–Hart
//! envelope of [`super::synth::SynthParams::envelope`] delayed by the wave's travel time from the
//! first support, `e(t − (x_j − x_1)/v_app)` (zero before the wave arrives), and then each
//! support's linear baseline is removed as in [`super::synth::baseline_correct`] (final velocity
//! and displacement zero). With `stationary` the samples are the stationary process itself (no
//! envelope, no baseline correction).
//!
//! **PGA scaling** (`pga_g`): each realisation is multiplied by **one** factor, common to all
//! supports (the cross-support structure is unchanged), chosen so that the mean over the supports
//! of the peak `|a_j|` equals the target. Without it the intensity is `S₀` as given.
//!
//! # Randomness
//! Realisation `r` (0-based) draws its phases from `ChaCha8Rng::seed_from_u64(seed)` on stream
//! `r`, `Φ_ml` in the order `m = 1..S`, `l = 0..N−1`: a realisation depends on `(seed, r)` and the
//! model only, so the bytes are the same for any thread count and any `count`.

use super::synth::{SynthError, SynthParams};
use crate::math::Real;
use crate::output::float_token as f;
use thiserror::Error;

#[path = "svgm_coherency.rs"]
mod coherency;
#[path = "svgm_condition.rs"]
mod condition;
#[path = "svgm_files.rs"]
mod files;
#[path = "svgm_gen.rs"]
mod generator;
pub use coherency::Coherency;
pub use condition::{Conditioned, MIN_WINDOW_SAMPLES};
pub use files::{
    MotionStats, Realiser, WriteSetError, csv_text, manifest_toml, readme_text, record_id,
    write_set,
};
pub use generator::{Fft, Generator};

/// Largest number of supports.
pub const MAX_SUPPORTS: usize = 64;
/// Largest number of values (samples × supports) of one realisation (80 MB of `f64`, about
/// 200 MB of CSV text).
pub const MAX_VALUES: usize = 10_000_000;

/// Bad parameters or numerical trouble of a spatially variable simulation; the message names the
/// CLI flag.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SvgmError {
    /// A parameter is out of range or not finite.
    #[error("invalid {name} = {value}: {reason}")]
    InvalidParameter {
        /// The flag (`--supports`, `--hv-a`, …).
        name: String,
        /// The offending value as text.
        value: String,
        /// What was expected.
        reason: String,
    },
    /// The coherency matrix at some frequency is not positive semi-definite (a Cholesky pivot
    /// below `−1e-9`).
    #[error(
        "the coherency matrix at omega = {omega} rad/s is not positive semi-definite (pivot {pivot} \
         at support {support}); the cross-spectral density cannot be factored"
    )]
    NotPositiveSemiDefinite {
        /// Frequency \[rad/s\].
        omega: Real,
        /// 0-based support index of the pivot.
        support: usize,
        /// The pivot.
        pivot: Real,
    },
}

fn bad(name: &str, value: impl ToString, reason: &str) -> SvgmError {
    SvgmError::InvalidParameter {
        name: name.into(),
        value: value.to_string(),
        reason: reason.into(),
    }
}

/// The parameters of a set of spatially variable motions.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgmParams {
    /// Support positions along the wave's direction \[m\], finite, strictly increasing
    /// (`--supports`); 1 to [`MAX_SUPPORTS`].
    pub positions: Vec<Real>,
    /// Support ids, one per position, `[A-Za-z0-9_-]+`, distinct (`--ids`; [`default_ids`]).
    pub ids: Vec<String>,
    /// The coherency model (`--coherency`).
    pub coherency: Coherency,
    /// Apparent wave velocity \[m/s\], > 0, `inf` for no wave passage (`--v-app`).
    pub v_app: Real,
    /// The Clough–Penzien PSD (`omega_g`, `zeta_g`, `omega_f`, `zeta_f`, `s0`: `--wg --zg --wf
    /// --zf --s0`), the envelope (`epsilon`, `eta`), `dt`, `duration` and `pga_g` (`--pga`), as
    /// `motion synth` uses them.
    pub psd: SynthParams,
    /// No envelope and no baseline correction: samples of the stationary process (`--stationary`).
    pub stationary: bool,
}

/// The default ids of `s` supports: `start`, `joint1` … `joint{s−2}`, `end` (`start` alone for
/// one support).
pub fn default_ids(s: usize) -> Vec<String> {
    match s {
        0 => vec![],
        1 => vec!["start".into()],
        _ => std::iter::once("start".to_string())
            .chain((1..s - 1).map(|i| format!("joint{i}")))
            .chain(std::iter::once("end".to_string()))
            .collect(),
    }
}

/// [`SynthError`] renamed to the flags of `motion svgm` (`omega_g` → `--wg`, …).
fn from_synth(e: SynthError) -> SvgmError {
    let SynthError::InvalidParameter {
        name,
        value,
        reason,
    } = e;
    let name = match name.as_str() {
        "omega_g" => "--wg",
        "zeta_g" => "--zg",
        "omega_f" => "--wf",
        "zeta_f" => "--zf",
        "s0" => "--s0",
        other => other,
    };
    bad(name, value, &reason)
}

impl SvgmParams {
    /// Checks every parameter (the support positions and ids, the coherency, `v_app`, and the
    /// PSD, duration, dt and PGA as [`SynthParams::check`] does).
    pub fn check(&self) -> Result<(), SvgmError> {
        let xs = &self.positions;
        let list = || xs.iter().map(|&x| f(x)).collect::<Vec<_>>().join(",");
        if xs.is_empty() || xs.len() > MAX_SUPPORTS {
            return Err(bad(
                "--supports",
                list(),
                &format!("give 1 to {MAX_SUPPORTS} positions"),
            ));
        }
        if let Some(x) = xs.iter().find(|x| !x.is_finite()) {
            return Err(bad(
                "--supports",
                list(),
                &format!("{} is not finite", f(*x)),
            ));
        }
        if let Some(w) = xs.windows(2).find(|w| w[1] <= w[0]) {
            return Err(bad(
                "--supports",
                list(),
                &format!(
                    "positions must increase strictly ({} then {})",
                    f(w[0]),
                    f(w[1])
                ),
            ));
        }
        let ids = self.ids.join(",");
        if self.ids.len() != xs.len() {
            return Err(bad(
                "--ids",
                ids,
                &format!(
                    "{} id(s) for {} support(s): give one id per position of --supports",
                    self.ids.len(),
                    xs.len()
                ),
            ));
        }
        for (i, id) in self.ids.iter().enumerate() {
            let ok = !id.is_empty()
                && id
                    .bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-');
            if !ok {
                return Err(bad(
                    "--ids",
                    &ids,
                    &format!("id {:?} must be non-empty letters, digits, '_' or '-'", id),
                ));
            }
            if id == "t" {
                return Err(bad("--ids", &ids, "id \"t\" is the time column's name"));
            }
            if self.ids[..i].contains(id) {
                return Err(bad("--ids", &ids, &format!("id {id:?} is given twice")));
            }
        }
        if self.v_app.is_nan() || self.v_app <= 0.0 {
            return Err(bad(
                "--v-app",
                f(self.v_app),
                "must be > 0 (m/s), or inf for no wave passage",
            ));
        }
        self.coherency.check()?;
        self.psd.check().map_err(from_synth)?;
        let travel = self.delay(xs.len() - 1);
        if travel.is_nan() || travel >= self.psd.duration {
            return Err(bad(
                "--v-app",
                f(self.v_app),
                &format!(
                    "the wave needs {} s to cross the supports, not less than --duration = {} s \
                     (the far supports would see no motion)",
                    f(travel),
                    f(self.psd.duration)
                ),
            ));
        }
        let values = self.samples() * xs.len();
        if values > MAX_VALUES {
            return Err(bad(
                "--duration",
                f(self.psd.duration),
                &format!(
                    "with --dt = {} and {} supports gives {values} values per realisation; \
                     keep samples x supports at most {MAX_VALUES}",
                    f(self.psd.dt),
                    xs.len()
                ),
            ));
        }
        Ok(())
    }

    /// The travel time `τ_j = (x_j − x_1)/v_app` of the wave from the first support to support
    /// `j` \[s\] (0 for `v_app = ∞`).
    pub fn delay(&self, j: usize) -> Real {
        if self.v_app.is_infinite() {
            0.0
        } else {
            (self.positions[j] - self.positions[0]) / self.v_app
        }
    }

    /// Number of samples per support, `round(duration/dt) + 1`.
    pub fn samples(&self) -> usize {
        self.psd.samples()
    }

    /// The command that writes a set, every model flag with its value (the `source` of the
    /// manifest): `pounding motion svgm --supports … --ids … --coherency … --v-app … --psd
    /// clough-penzien --wg … --zg … --wf … --zf … --s0 … [--pga G] [--stationary] --duration …
    /// --dt … --count N --seed S`.
    pub fn source(&self, count: usize, seed: u64) -> String {
        let p = &self.psd;
        let xs: Vec<String> = self.positions.iter().map(|&x| f(x)).collect();
        let mut s = format!(
            "pounding motion svgm --supports {} --ids {} {} --v-app {} --psd clough-penzien \
             --wg {} --zg {} --wf {} --zf {} --s0 {}",
            xs.join(","),
            self.ids.join(","),
            self.coherency.flags(),
            f(self.v_app),
            f(p.omega_g),
            f(p.zeta_g),
            f(p.omega_f),
            f(p.zeta_f),
            f(p.s0)
        );
        if let Some(g) = p.pga_g {
            s.push_str(&format!(" --pga {}", f(g)));
        }
        if self.stationary {
            s.push_str(" --stationary");
        }
        s.push_str(&format!(
            " --duration {} --dt {} --count {count} --seed {seed}",
            f(p.duration),
            f(p.dt)
        ));
        s
    }
}

/// One realisation: the accelerations \[m/s²\] at each support (outer index: support, in the
/// order of the positions), `samples` values at `t = k dt`.
#[derive(Debug, Clone, PartialEq)]
pub struct Realisation {
    /// `real_0001`, … ([`record_id`]).
    pub id: String,
    /// Per support, the accelerations \[m/s²\].
    pub supports: Vec<Vec<Real>>,
}

/// `count` realisations (in parallel; the same for any thread count): checks the count and the
/// parameters, factors the coherency matrices, then generates.
pub fn realisations(
    p: &SvgmParams,
    count: usize,
    seed: u64,
) -> Result<Vec<Realisation>, SvgmError> {
    use rayon::prelude::*;
    check_count(count)?;
    let g = Generator::new(p)?;
    Ok((0..count)
        .into_par_iter()
        .map(|r| Realisation {
            id: record_id(r, count),
            supports: g.realisation(seed, r),
        })
        .collect())
}

/// Checks `1 ≤ count ≤` [`super::synth::MAX_COUNT`] (`--count`).
pub fn check_count(count: usize) -> Result<(), SvgmError> {
    super::synth::check_count(count).map_err(from_synth)
}

/// Checks `seed ≤` [`super::synth::MAX_SEED`] (`--seed`): the manifest records the seed as a
/// TOML integer.
pub fn check_seed(seed: u64) -> Result<(), SvgmError> {
    super::synth::check_seed(seed).map_err(from_synth)
}
