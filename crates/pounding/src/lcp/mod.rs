//! Linear complementarity problems `w = M z + q, z ≥ 0, w ≥ 0, zᵀw = 0`.
//!
//! CONTRACT (skeleton; the LCP work item replaces every `todo!()` and may add items, but keeps these
//! names and signatures so that `impact` and `study` can build on them).

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
    /// A pivot was too small to trust / the end point failed verification.
    IllConditioned,
}

/// Settings of Lemke's method (validated; see the LCP work item for the exact fields).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LemkeSettings {
    // filled in by the LCP work item
}

/// A solution of an LCP of dynamic size.
#[derive(Debug, Clone, PartialEq)]
pub struct LcpSolution {
    /// The complementary variable `z` (meaningful only when `status == Solved`).
    pub z: Vec<f64>,
    /// `w = M z + q`.
    pub w: Vec<f64>,
    /// Outcome.
    pub status: LcpStatus,
    /// Number of pivots, counting the pivot in which `z0` enters and the one in which it leaves.
    pub pivots: usize,
    /// `max_i |min(z_i, w_i)| / max(1, ‖q‖_∞)`.
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

/// Lexicographic Lemke's method with a reusable workspace (no allocation per solve once warm).
#[derive(Debug, Clone)]
pub struct Lemke {
    /// The settings in force.
    pub settings: LemkeSettings,
}

impl Lemke {
    /// A solver with the given settings.
    pub fn new(settings: LemkeSettings) -> Self {
        Self { settings }
    }
    /// Solves `problem`; never panics on a numerical failure (that is a status).
    pub fn solve(&mut self, problem: &LcpProblem) -> LcpSolution {
        let _ = problem;
        todo!("LCP work item")
    }
}

/// Lexicographic Lemke on a fixed-size LCP given row-major as `m[i][j]`; allocation-free.
pub fn solve_fixed<const N: usize>(
    m: &[[f64; N]; N],
    q: &[f64; N],
    settings: &LemkeSettings,
) -> FixedSolution<N> {
    let _ = (m, q, settings);
    todo!("LCP work item")
}

/// All solutions found by enumerating complementary bases (`n ≤ 12`, else an error).
pub fn enumerate(problem: &LcpProblem) -> Result<Vec<Vec<f64>>, LcpError> {
    let _ = problem;
    todo!("LCP work item")
}
