//! The paper's parametric stick/slip study (`pounding study`), UI-free.
//!
//! * [`scenario`] — the scenario file (TOML), validation with key and line, the built-in default.
//! * [`cell`] — one cell: configuration flags, Delassus matrix, stick interval `[L, U]`, LCP check.
//! * [`run`] — row layout and order, sharding, the parallel deterministic computation.
//! * [`csv`] — `bounds.csv` text and its exact inverse.
//! * [`summary`] — `summary.csv` / `summary.json`.
//! * [`shard`] — shard manifests and the merge of shard outputs.
//! * [`claims`] — the paper's claims next to this run's metrics (for the report).
//!
//! [`Study`] ties them together: compute (or merge) rows, then derive every text output.

pub mod cell;
pub mod claims;
pub mod csv;
pub mod run;
pub mod scenario;
pub mod shard;
pub mod summary;

pub use cell::Cell;
pub use claims::{ClaimCheck, Verdict};
pub use run::{Layout, Row, RowKey, Shard, compute_rows};
pub use scenario::{AngleRange, DEFAULT_SCENARIO_TOML, Scenario, ScenarioError, StudyShape};
pub use summary::SummaryRow;

use thiserror::Error;

/// Errors of the study (bad input only).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum StudyError {
    /// The scenario is invalid.
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// A deck geometry is invalid.
    #[error(transparent)]
    Geometry(#[from] crate::geometry::GeometryError),
    /// An impact law is invalid.
    #[error(transparent)]
    Law(#[from] crate::analytic::LawError),
    /// A bad `--shard K/N`.
    #[error(transparent)]
    Shard(#[from] crate::shard::ShardError),
    /// A `bounds.csv` line that cannot be parsed back.
    #[error("cannot parse bounds row: {0}")]
    Parse(String),
    /// Shard outputs that cannot be merged.
    #[error("cannot merge shards: {0}")]
    Merge(String),
}

/// A complete study: scenario (and its text) plus every row, in order.
#[derive(Debug, Clone)]
pub struct Study {
    /// The scenario text (file contents, or [`DEFAULT_SCENARIO_TOML`]).
    pub scenario_text: String,
    /// The scenario.
    pub scenario: Scenario,
    /// All rows in global order.
    pub rows: Vec<Row>,
    /// Per-(configuration, case) summaries, in row order.
    pub summaries: Vec<SummaryRow>,
}

impl Study {
    /// Computes the whole study on the current rayon pool (see [`run::compute_rows`]).
    pub fn compute(
        scenario_text: String,
        scenario: Scenario,
        progress: &(dyn Fn(usize) + Sync),
    ) -> Result<Self, StudyError> {
        let rows = run::compute_rows(&scenario, Shard::ALL, progress)?;
        Ok(Self::from_rows(scenario_text, scenario, rows))
    }

    /// Wraps complete, ordered rows (e.g. from [`shard::merge`]) and computes the summaries.
    pub fn from_rows(scenario_text: String, scenario: Scenario, rows: Vec<Row>) -> Self {
        let summaries = summary::summarize(&scenario, &rows);
        Self {
            scenario_text,
            scenario,
            rows,
            summaries,
        }
    }

    /// `bounds.csv`.
    pub fn bounds_csv(&self) -> String {
        csv::bounds_csv(&self.scenario, &self.rows)
    }
    /// `summary.csv`.
    pub fn summary_csv(&self) -> String {
        summary::summary_csv(&self.summaries)
    }
    /// `summary.json`.
    pub fn summary_json(&self) -> String {
        summary::summary_json(&self.scenario, &self.summaries)
    }
    /// Total number of cells whose `lcp_agrees` is false.
    pub fn lcp_disagreements(&self) -> usize {
        self.summaries.iter().map(|s| s.lcp_disagreements).sum()
    }
    /// The paper's claims with this run's metrics.
    pub fn claims(&self) -> Vec<ClaimCheck> {
        claims::check_claims(&self.scenario, &self.rows, &self.summaries)
    }
}
