//! Linear complementarity problems `w = M z + q, z ≥ 0, w ≥ 0, zᵀw = 0`.
//!
//!
//! * [`LcpProblem`] — the data (dense `M`, any `n`); [`LemkeSettings`] — validated settings;
//!   [`Lemke`] / [`solve_fixed`] — lexicographic Lemke (dynamic size with a reusable workspace /
//!   const-generic allocation-free kernel); [`enumerate()`] — every solution by enumerating
//!   complementary bases (`n ≤ 12`); [`LcpSolution`] / [`FixedSolution`] with an [`LcpStatus`].
//! * [`io`] — Siconos `.dat` (dense and sparse-block), `LCPSET 1` reader, `LCPSOL 1` writer.
//!
//! ```
//! use pounding::lcp::{LcpProblem, LcpStatus, Lemke, LemkeSettings, enumerate, solve_fixed};
//! // Murty's example: M = [[2, 1], [1, 2]], q = (−5, −6), solution z = (4/3, 7/3), w = 0
//! let p = LcpProblem::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
//! let sol = Lemke::new(LemkeSettings::default()).solve(&p);
//! assert_eq!(sol.status, LcpStatus::Solved);
//! assert!((sol.z[0] - 4.0 / 3.0).abs() < 1e-12 && (sol.z[1] - 7.0 / 3.0).abs() < 1e-12);
//! assert_eq!(enumerate(&p).unwrap().len(), 1); // unique
//! let f = solve_fixed(&[[2.0, 1.0], [1.0, 2.0]], &[-5.0, -6.0], &LemkeSettings::default());
//! assert_eq!((f.status, f.z), (sol.status, [sol.z[0], sol.z[1]]));
//! ```
//!
//! Bad input is an [`LcpError`]; numerical outcomes (ray termination, pivot limit, failed
//! verification) are statuses, never panics. Only [`LcpStatus::Solved`] carries a `z` that passed
//! a verification of all LCP conditions against the original data.

pub mod enumerate;
pub mod fc2d;
mod full;
pub mod io;
pub mod lemke;
mod scale;
mod tableau;

pub use enumerate::{EnumSettings, enumerate, enumerate_with};
pub use lemke::{Lemke, solve_fixed};

use thiserror::Error;

/// Bad LCP input (never a numerical outcome: those are [`LcpStatus`]).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum LcpError {
    /// A problem description is inconsistent or contains non-finite numbers.
    #[error("invalid LCP: {0}")]
    Invalid(String),
}

/// A dense LCP of any size `n` (`M` stored row-major).
#[derive(Debug, Clone, PartialEq)]
pub struct LcpProblem {
    n: usize,
    m: Vec<f64>,
    q: Vec<f64>,
}

impl LcpProblem {
    /// Builds a problem from a row-major `n × n` matrix and an `n`-vector; rejects size mismatches,
    /// `n = 0` and non-finite entries.
    pub fn new(m_row_major: Vec<f64>, q: Vec<f64>) -> Result<Self, LcpError> {
        let n = q.len();
        if n == 0 {
            return Err(LcpError::Invalid("empty problem (n = 0)".into()));
        }
        if m_row_major.len() != n * n {
            return Err(LcpError::Invalid(format!(
                "M has {} entries, expected n*n = {} for n = {n}",
                m_row_major.len(),
                n * n
            )));
        }
        if let Some(i) = m_row_major.iter().position(|x| !x.is_finite()) {
            return Err(LcpError::Invalid(format!(
                "M[{}][{}] is not finite",
                i / n,
                i % n
            )));
        }
        if let Some(i) = q.iter().position(|x| !x.is_finite()) {
            return Err(LcpError::Invalid(format!("q[{i}] is not finite")));
        }
        Ok(Self {
            n,
            m: m_row_major,
            q,
        })
    }
    /// Problem size `n`.
    pub fn dim(&self) -> usize {
        self.n
    }
    /// Entry `M[i][j]`.
    pub fn m(&self, i: usize, j: usize) -> f64 {
        self.m[i * self.n + j]
    }
    /// The row-major entries of `M`.
    pub fn m_row_major(&self) -> &[f64] {
        &self.m
    }
    /// The vector `q`.
    pub fn q(&self) -> &[f64] {
        &self.q
    }
}

/// Outcome of a solve. Only `Solved` carries a verified solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LcpStatus {
    /// `z` passed verification of all LCP conditions.
    Solved,
    /// Lemke stopped on a secondary ray: no solution found by this method.
    RayTermination,
    /// The pivot limit was reached.
    MaxPivots,
    /// The end point failed verification (rounding made the pivots untrustworthy), or the data
    /// given to [`solve_fixed`] contained non-finite numbers.
    IllConditioned,
}

/// Work bound of one Lemke solve, in units of `n²` pivot operations (see
/// [`LemkeSettings::pivot_limit`]).
pub const PIVOT_WORK: u128 = 20_000_000_000;

/// Settings of Lemke's method, validated (every constructor and setter returns
/// `Err(LcpError::Invalid)` for a value out of range).
///
/// | field | default | meaning |
/// |---|---|---|
/// | `max_pivots` | 100 000 | pivot limit (counting the pivots in which `z₀` enters and leaves), further capped at `2·10¹⁰/n²` for large `n` ([`pivot_limit`](LemkeSettings::pivot_limit)); reaching it gives [`LcpStatus::MaxPivots`] |
/// | `pivot_tol` | 1e-12 | an entry `dᵢ` of the entering column takes part in the ratio test only if `dᵢ > pivot_tol · maxₖ |dₖ|` (relative to the column, hence scale-free) |
/// | `tie_tol` | 1e-11 | two ratios `bᵢ/dᵢ`, `bⱼ/dⱼ` tie when they differ by at most `tie_tol · ‖b‖∞ · (1/dᵢ + 1/dⱼ)` (the rounding scale of the ratios, relative to the current right-hand side); tied `B⁻¹` entries likewise relative to the tied rows' scale; the initial row ties when `qᵢ ≤ min q + tie_tol·‖q‖∞` |
/// | `verify_tol` | 1e-9 | [`LcpStatus::Solved`] requires, with `w = M z + q` recomputed from the data and `sᵢ = |qᵢ| + Σⱼ |Mᵢⱼ zⱼ|` (the rounding scale of row `i`): `z ≥ 0`, `wᵢ ≥ −verify_tol·sᵢ` and `|wᵢ| ≤ verify_tol·sᵢ` wherever `zᵢ > 0` (rounding-noise entries of `z` set aside; see the [`lemke`] module) |
#[derive(Debug, Clone, PartialEq)]
pub struct LemkeSettings {
    max_pivots: usize,
    pivot_tol: f64,
    tie_tol: f64,
    verify_tol: f64,
}

impl Default for LemkeSettings {
    fn default() -> Self {
        Self {
            max_pivots: 100_000,
            pivot_tol: 1e-12,
            tie_tol: 1e-11,
            verify_tol: 1e-9,
        }
    }
}

fn check_tol(name: &str, v: f64, max: f64) -> Result<f64, LcpError> {
    if v.is_finite() && v >= 0.0 && v < max {
        Ok(v)
    } else {
        Err(LcpError::Invalid(format!(
            "LemkeSettings::{name} = {v} must be finite and in [0, {max})"
        )))
    }
}

impl LemkeSettings {
    /// Settings with every field given; see the type documentation for their meaning.
    pub fn new(
        max_pivots: usize,
        pivot_tol: f64,
        tie_tol: f64,
        verify_tol: f64,
    ) -> Result<Self, LcpError> {
        Self::default()
            .with_max_pivots(max_pivots)?
            .with_pivot_tol(pivot_tol)?
            .with_tie_tol(tie_tol)?
            .with_verify_tol(verify_tol)
    }
    /// Sets the pivot limit (any value, `0` makes every non-trivial problem end in
    /// [`LcpStatus::MaxPivots`]).
    pub fn with_max_pivots(mut self, max_pivots: usize) -> Result<Self, LcpError> {
        self.max_pivots = max_pivots;
        Ok(self)
    }
    /// Sets the relative pivot tolerance (finite, in `[0, 1)`).
    pub fn with_pivot_tol(mut self, pivot_tol: f64) -> Result<Self, LcpError> {
        self.pivot_tol = check_tol("pivot_tol", pivot_tol, 1.0)?;
        Ok(self)
    }
    /// Sets the relative tie tolerance of the ratio test (finite, in `[0, 1e-3)`).
    pub fn with_tie_tol(mut self, tie_tol: f64) -> Result<Self, LcpError> {
        self.tie_tol = check_tol("tie_tol", tie_tol, 1e-3)?;
        Ok(self)
    }
    /// Sets the verification tolerance (finite, in `[0, 1e-2)`).
    pub fn with_verify_tol(mut self, verify_tol: f64) -> Result<Self, LcpError> {
        self.verify_tol = check_tol("verify_tol", verify_tol, 1e-2)?;
        Ok(self)
    }
    /// Pivot limit.
    pub fn max_pivots(&self) -> usize {
        self.max_pivots
    }

    /// The pivot limit for a problem of size `n`: `max_pivots`, but at most
    /// `⌈PIVOT_WORK / n²⌉` (each pivot costs about `n²` operations), so that no problem runs for
    /// more than seconds. Nothing changes for `n ≤ 447` with the default `max_pivots`; a 1000 × 1000
    /// problem that needs more (Murty's example needs `2ⁿ`) ends `MaxPivots` after 20 000 pivots.
    pub fn pivot_limit(&self, n: usize) -> usize {
        let n2 = (n.max(1) as u128) * (n.max(1) as u128);
        let cap = PIVOT_WORK.div_ceil(n2).min(usize::MAX as u128) as usize;
        self.max_pivots.min(cap)
    }
    /// Relative pivot tolerance.
    pub fn pivot_tol(&self) -> f64 {
        self.pivot_tol
    }
    /// Relative tie tolerance.
    pub fn tie_tol(&self) -> f64 {
        self.tie_tol
    }
    /// Verification tolerance.
    pub fn verify_tol(&self) -> f64 {
        self.verify_tol
    }
}

impl LcpStatus {
    /// `true` for [`LcpStatus::Solved`].
    pub fn is_solved(self) -> bool {
        self == LcpStatus::Solved
    }
    /// A short lower-case name (`solved`, `ray`, `max_pivots`, `ill_conditioned`).
    pub fn name(self) -> &'static str {
        match self {
            LcpStatus::Solved => "solved",
            LcpStatus::RayTermination => "ray",
            LcpStatus::MaxPivots => "max_pivots",
            LcpStatus::IllConditioned => "ill_conditioned",
        }
    }
}

/// A solution of an LCP of dynamic size.
#[derive(Debug, Clone, PartialEq)]
pub struct LcpSolution {
    /// The complementary variable `z` (`NaN` unless `status == Solved`).
    pub z: Vec<f64>,
    /// `w = M z + q`, recomputed from the original data (`NaN` unless `status == Solved`).
    pub w: Vec<f64>,
    /// Outcome.
    pub status: LcpStatus,
    /// Number of pivots, counting the pivot in which `z0` enters and the one in which it leaves.
    pub pivots: usize,
    /// `max_i |min(z_i, w_i)| / max(1, ‖q‖_∞)` (`NaN` when no end point was reached).
    pub residual: f64,
}

/// A solution of a fixed-size LCP (see [`solve_fixed`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixedSolution<const N: usize> {
    /// The complementary variable `z`.
    pub z: [f64; N],
    /// `w = M z + q`.
    pub w: [f64; N],
    /// Outcome.
    pub status: LcpStatus,
    /// Pivot count (as in [`LcpSolution::pivots`]).
    pub pivots: usize,
    /// Residual (as in [`LcpSolution::residual`]).
    pub residual: f64,
}
