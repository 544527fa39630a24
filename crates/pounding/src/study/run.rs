//! Row layout, ordering and the (parallel, deterministic) computation of a study.
//!
//! Rows are ordered by the geometry axes (`β1, β2, R1, R2` for curved decks, `L1, L2, θ_s` for
//! straight and skewed decks; see [`Scenario::geometry_dims`]), then `μ, ε` (each in scenario order), then case (canonical order),
//! then `θ1`, then `θ2` (innermost). The global row index is the position in that order; a row's
//! key is recovered from its index alone ([`Layout::key`]), which is what sharding relies on.

use super::StudyError;
use super::cell::Geometry;
use super::cell::{Cell, compute_cell_in};
use super::scenario::Scenario;
use super::scenario::StudyShape;
use crate::analytic::ImpactLaw;
use crate::geometry::{ContactCase, GeometryError, ShapeParam};
use crate::math::Real;
use crate::pair::{DeckPair, SArrangement};
use crate::shape::{Deck, DeckShape, SkewedDeck, StraightDeck};
use rayon::prelude::*;

pub use crate::shard::Shard;

/// Indices of a row in the scenario's lists. The four geometry indices address the geometry axes
/// of [`Scenario::geometry_dims`]: for straight and skewed decks `beta1` indexes `l1_m`, `beta2`
/// indexes `l2_m`, `r1` indexes `skew_deg` and `r2` is 0.
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

pub use crate::shard::MAX_SHARDS;

/// The mixed-radix layout of the rows of a scenario.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Sizes, outermost first: β1, β2, R1, R2, μ, ε, case, θ1, θ2.
    pub dims: [usize; 9],
}

impl Layout {
    /// The layout of `scenario`.
    pub fn of(scenario: &Scenario) -> Self {
        let g = scenario.geometry_dims();
        Self {
            dims: [
                g[0],
                g[1],
                g[2],
                g[3],
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

/// The parameter values of a row key. For straight and skewed decks `β1, β2, R1, R2` are NaN; for
/// curved decks `L1, L2, skew` are NaN.
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
    /// Deck 1 length `L1` \[m\] (NaN for curved decks).
    pub l1_m: Real,
    /// Deck 2 length `L2` \[m\] (NaN for curved decks).
    pub l2_m: Real,
    /// Common skew angle \[deg\] (NaN for curved decks, 0 for straight decks).
    pub skew_deg: Real,
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
        let nan = Real::NAN;
        let curved = self.shape == StudyShape::Curved;
        let pick = |v: &[Real], i: usize, mine: bool| if mine { v[i] } else { nan };
        RowParams {
            beta1_deg: pick(&self.beta1_deg, key.beta1, curved),
            beta2_deg: pick(&self.beta2_deg, key.beta2, curved),
            r1_m: pick(&self.r1_m, key.r1, curved),
            r2_m: pick(&self.r2_m, key.r2, curved),
            l1_m: pick(&self.l1_m, key.beta1, !curved),
            l2_m: pick(&self.l2_m, key.beta2, !curved),
            skew_deg: pick(&self.skew_deg, key.r1, !curved),
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

    /// The validated geometry of the geometry-axis indices `g` (see [`Scenario::geometry_dims`]):
    /// the S arrangement of curved decks, or the [`DeckPair`] of two straight decks (`L1`, `L2`) or
    /// two skewed decks with the common skew angle.
    pub fn geometry(&self, g: [usize; 4]) -> Result<Geometry, StudyError> {
        Ok(match self.shape {
            StudyShape::Curved => Geometry::Curved(self.arrangement(g[0], g[1], g[2], g[3])?),
            shape => {
                let (w, t, rho) = (self.width, self.thickness, self.density);
                let deck = |l: Real, i: usize| -> Result<DeckShape, StudyError> {
                    // deck i's axis length is `L{i}`; the other names stay the study's
                    let named = |e: GeometryError| match e {
                        GeometryError::InvalidParameter {
                            param: ShapeParam::Length,
                            ..
                        } => e.for_deck(i),
                        e => e,
                    };
                    Ok(if shape == StudyShape::Straight {
                        DeckShape::Straight(StraightDeck::new(l, w, t, rho).map_err(named)?)
                    } else {
                        DeckShape::Skewed(
                            SkewedDeck::new(l, w, self.skew_deg[g[2]].to_radians(), t, rho)
                                .map_err(named)?,
                        )
                    })
                };
                Geometry::Pair(DeckPair::new(
                    deck(self.l1_m[g[0]], 1)?,
                    deck(self.l2_m[g[1]], 2)?,
                )?)
            }
        })
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
    // A scenario built by hand (not read by `from_toml`) may be too large to index.
    scenario.check_size("scenario")?;
    let layout = Layout::of(scenario);
    let [nb1, nb2, nr1, nr2, nmu, neps, ..] = layout.dims;
    let mut arrangements = Vec::with_capacity(nb1 * nb2 * nr1 * nr2);
    for b1 in 0..nb1 {
        for b2 in 0..nb2 {
            for r1 in 0..nr1 {
                for r2 in 0..nr2 {
                    arrangements.push(scenario.geometry([b1, b2, r1, r2])?);
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
                let cell = compute_cell_in(
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
