//! Row layout, ordering and the (parallel, deterministic) computation of a study.
//!
//! Rows are ordered by `β1, β2, R1, R2, μ, ε` (each in scenario order), then case (canonical order),
//! then `θ1`, then `θ2` (innermost). The global row index is the position in that order; a row's
//! key is recovered from its index alone ([`Layout::key`]), which is what sharding relies on.

use super::StudyError;
use super::cell::{Cell, compute_cell};
use super::scenario::Scenario;
use crate::analytic::ImpactLaw;
use crate::geometry::{ContactCase, Deck, SArrangement};
use crate::math::Real;
use rayon::prelude::*;

/// Which rows a run computes: those whose global index `i` satisfies `i mod count = index − 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Shard {
    /// `K`, 1-based.
    pub index: usize,
    /// `N ≥ 1`.
    pub count: usize,
}

impl Shard {
    /// The whole study (`1/1`).
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Validated shard `K/N` with `1 ≤ K ≤ N`.
    pub fn new(index: usize, count: usize) -> Result<Self, StudyError> {
        if count == 0 || index == 0 || index > count {
            return Err(StudyError::Shard(format!(
                "shard {index}/{count}: need 1 <= K <= N"
            )));
        }
        Ok(Self { index, count })
    }

    /// Parses `K/N`.
    pub fn parse(s: &str) -> Result<Self, StudyError> {
        let bad = || StudyError::Shard(format!("--shard {s:?}: expected K/N with 1 <= K <= N"));
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse::<usize>().map_err(|_| bad())?;
        let n = n.trim().parse::<usize>().map_err(|_| bad())?;
        Self::new(k, n).map_err(|_| bad())
    }

    /// Whether global row `i` belongs to this shard.
    pub fn contains(&self, i: usize) -> bool {
        i % self.count == self.index - 1
    }
}

/// Indices of a row in the scenario's lists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct RowKey {
    /// Index into `beta1_deg`.
    pub beta1: usize,
    /// Index into `beta2_deg`.
    pub beta2: usize,
    /// Index into `r1_m`.
    pub r1: usize,
    /// Index into `r2_m`.
    pub r2: usize,
    /// Index into `mu`.
    pub mu: usize,
    /// Index into `eps`.
    pub eps: usize,
    /// Index into the scenario's `cases`.
    pub case: usize,
    /// Index of `θ1` in its grid.
    pub i: usize,
    /// Index of `θ2` in its grid.
    pub j: usize,
}

/// The mixed-radix layout of the rows of a scenario.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Sizes, outermost first: β1, β2, R1, R2, μ, ε, case, θ1, θ2.
    pub dims: [usize; 9],
}

impl Layout {
    /// The layout of `scenario`.
    pub fn of(scenario: &Scenario) -> Self {
        Self {
            dims: [
                scenario.beta1_deg.len(),
                scenario.beta2_deg.len(),
                scenario.r1_m.len(),
                scenario.r2_m.len(),
                scenario.mu.len(),
                scenario.eps.len(),
                scenario.cases.len(),
                scenario.theta1.len(),
                scenario.theta2.len(),
            ],
        }
    }
    /// Total number of rows.
    pub fn total(&self) -> usize {
        self.dims.iter().product()
    }
    /// Rows per block (one block = one configuration and case: the `θ1 × θ2` grid).
    pub fn block_len(&self) -> usize {
        self.dims[7] * self.dims[8]
    }
    /// Number of blocks.
    pub fn blocks(&self) -> usize {
        self.total() / self.block_len()
    }
    /// The key of global row `index` (`< total()`).
    pub fn key(&self, index: usize) -> RowKey {
        let mut k = [0usize; 9];
        let mut rest = index;
        for d in (0..9).rev() {
            k[d] = rest % self.dims[d];
            rest /= self.dims[d];
        }
        RowKey {
            beta1: k[0],
            beta2: k[1],
            r1: k[2],
            r2: k[3],
            mu: k[4],
            eps: k[5],
            case: k[6],
            i: k[7],
            j: k[8],
        }
    }
    /// The global index of `key`.
    pub fn index(&self, key: &RowKey) -> usize {
        let k = [
            key.beta1, key.beta2, key.r1, key.r2, key.mu, key.eps, key.case, key.i, key.j,
        ];
        k.iter()
            .zip(self.dims.iter())
            .fold(0, |acc, (&x, &d)| acc * d + x)
    }
}

/// One row of `bounds.csv`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Global index in the study's order.
    pub index: usize,
    /// The row's position in the scenario's lists.
    pub key: RowKey,
    /// The computed cell.
    pub cell: Cell,
}

/// The parameter values of a row key.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowParams {
    /// `β1` \[deg\].
    pub beta1_deg: Real,
    /// `β2` \[deg\].
    pub beta2_deg: Real,
    /// `R1` \[m\].
    pub r1_m: Real,
    /// `R2` \[m\].
    pub r2_m: Real,
    /// `μ`.
    pub mu: Real,
    /// `ε_N`.
    pub eps: Real,
    /// Candidate case.
    pub case: ContactCase,
    /// `θ1 = start + i·step` \[deg\].
    pub theta1_deg: Real,
    /// `θ2 = start + j·step` \[deg\].
    pub theta2_deg: Real,
}

impl Scenario {
    /// The parameter values of `key`.
    pub fn params(&self, key: &RowKey) -> RowParams {
        RowParams {
            beta1_deg: self.beta1_deg[key.beta1],
            beta2_deg: self.beta2_deg[key.beta2],
            r1_m: self.r1_m[key.r1],
            r2_m: self.r2_m[key.r2],
            mu: self.mu[key.mu],
            eps: self.eps[key.eps],
            case: self.cases[key.case],
            theta1_deg: self.theta1.value(key.i),
            theta2_deg: self.theta2.value(key.j),
        }
    }

    /// Tolerance (degrees) for recognising the degenerate diagonals `θ1 = ±θ2` on the grid.
    pub fn degeneracy_tolerance_deg(&self) -> Real {
        1e-9 * self.theta1.step.min(self.theta2.step)
    }

    /// The validated arrangement of geometry `(β1, β2, R1, R2)` (list indices).
    pub fn arrangement(
        &self,
        beta1: usize,
        beta2: usize,
        r1: usize,
        r2: usize,
    ) -> Result<SArrangement, StudyError> {
        let deck = |r: Real, b: Real| {
            Deck::new(r, b.to_radians(), self.width, self.thickness, self.density)
        };
        let d1 = deck(self.r1_m[r1], self.beta1_deg[beta1])?;
        let d2 = deck(self.r2_m[r2], self.beta2_deg[beta2])?;
        Ok(SArrangement::new(d1, d2)?)
    }

    /// The validated impact law `(μ, ε)` (list indices).
    pub fn law(&self, mu: usize, eps: usize) -> Result<ImpactLaw, StudyError> {
        Ok(ImpactLaw::new(self.mu[mu], self.eps[eps])?)
    }
}

/// Computes the rows of `shard` in global order. Runs on the current rayon pool (install an explicit
/// pool to choose the thread count); the result does not depend on the number of threads.
/// `progress(n)` is called (from worker threads) after each block with its number of rows.
pub fn compute_rows(
    scenario: &Scenario,
    shard: Shard,
    progress: &(dyn Fn(usize) + Sync),
) -> Result<Vec<Row>, StudyError> {
    let layout = Layout::of(scenario);
    let [nb1, nb2, nr1, nr2, nmu, neps, ..] = layout.dims;
    let mut arrangements = Vec::with_capacity(nb1 * nb2 * nr1 * nr2);
    for b1 in 0..nb1 {
        for b2 in 0..nb2 {
            for r1 in 0..nr1 {
                for r2 in 0..nr2 {
                    arrangements.push(scenario.arrangement(b1, b2, r1, r2)?);
                }
            }
        }
    }
    let mut laws = Vec::with_capacity(nmu * neps);
    for m in 0..nmu {
        for e in 0..neps {
            laws.push(scenario.law(m, e)?);
        }
    }
    let tol = scenario.degeneracy_tolerance_deg();
    let block_len = layout.block_len();
    let blocks: Vec<Vec<Row>> = (0..layout.blocks())
        .into_par_iter()
        .map(|b| {
            let first = b * block_len;
            let mut out = Vec::with_capacity(block_len / shard.count + 1);
            let k0 = layout.key(first);
            let geom = ((k0.beta1 * nb2 + k0.beta2) * nr1 + k0.r1) * nr2 + k0.r2;
            let arr = &arrangements[geom];
            let law = &laws[k0.mu * neps + k0.eps];
            let case = scenario.cases[k0.case];
            for index in first..first + block_len {
                if !shard.contains(index) {
                    continue;
                }
                let key = layout.key(index);
                let cell = compute_cell(
                    arr,
                    law,
                    case,
                    scenario.theta1.value(key.i),
                    scenario.theta2.value(key.j),
                    scenario.sigma_mode,
                    tol,
                );
                out.push(Row { index, key, cell });
            }
            progress(block_len);
            out
        })
        .collect();
    Ok(blocks.into_iter().flatten().collect())
}
