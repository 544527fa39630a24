//! Campaigns: many runs of a bridge over a record set at intensity stripes, described by one
//! spec file ([`spec`]), expanded into runs with stable ids, computed in *parts* of consecutive
//! runs and stored as Parquet files that a killed campaign resumes from ([`store`]).
//!
//! ```toml
//! [campaign]
//! scenario = "viaduct.toml"   # a bridge scenario with [fragility] and [[limit_state]]s
//! records = "suite.toml"      # optional: the record set instead of [fragility] records
//! levels_g = [0.2, 0.4, 0.8]  # optional: stripes instead of the scenario's (or scales = [...])
//! runs_per_part = 64          # runs per part file (and per task of an executor)
//!
//! [outputs]
//! seats = true                # the per-end seat ratios (default true)
//! histories = false           # time histories are not stored (only false is accepted)
//! ```
//!
//! **Runs.** With `V` variants (one today, `base`), `R` record-set entries and `S` stripes, run
//! `i = (v R + a) S + b` is variant `v`, entry `a`, stripe `b`; its id is
//! `VARIANT/RECORD/level_g=L` (or `scale=s`), which does not depend on the executor, the number of
//! threads or a shard. **Parts.** Part `p` holds runs `p B .. (p + 1) B` (`B = runs_per_part`):
//! the unit of work, of storage and of resuming. A part's bytes depend only on its runs'
//! results, so any executor (threads, shards, Dask) stores the same bytes.

pub mod exec;
pub mod from_store;
pub mod read;
pub mod spec;
pub mod store;
mod store_merge;
pub mod table;
pub mod variants;

pub use spec::{Campaign, RunSpec};
pub use store::Store;

use std::path::PathBuf;

/// Why a campaign cannot start or its store cannot be read or written.
#[derive(Debug, thiserror::Error)]
pub enum CampaignError {
    /// TOML syntax, an unknown key or a wrong type in the spec.
    #[error("invalid campaign spec {origin}: {message}")]
    Syntax {
        /// The spec's name.
        origin: String,
        /// The TOML reader's message (names line and column).
        message: String,
    },
    /// A bad or missing value: its key and line.
    #[error("{message} — `{key}` ({})", match line { Some(l) => format!("{origin}:{l}"), None => format!("not set in {origin}") })]
    Key {
        /// What is wrong.
        message: String,
        /// The key, e.g. `campaign.runs_per_part`.
        key: String,
        /// The spec's name.
        origin: String,
        /// 1-based line, `None` when the key is not written.
        line: Option<usize>,
    },
    /// The scenario, its `[fragility]` tables, the record set or the IM plan.
    #[error(transparent)]
    Assessment(#[from] crate::assessment::AssessmentError),
    /// The scenario itself.
    #[error(transparent)]
    Scenario(#[from] crate::sim::scenario::ScenarioError),
    /// A file that cannot be read or written.
    #[error("{what} {}: {cause}", path.display())]
    Io {
        /// What failed.
        what: &'static str,
        /// The path.
        path: PathBuf,
        /// The cause.
        cause: std::io::Error,
    },
    /// A bad `[[variant]]` table or override (file, variant, key, line).
    #[error(transparent)]
    Variant(#[from] crate::assessment::variant::VariantError),
    /// The output directory (lock, kind).
    #[error(transparent)]
    Output(#[from] crate::output::OutputError),
    /// A store that is not the campaign's, is incomplete, or holds a bad file.
    #[error("campaign store: {0}")]
    Store(String),
}

/// The hash of a scenario's text (as stored in `campaign.json`).
pub fn scenario_fingerprint(text: &str) -> u64 {
    let mut h = Fnv::default();
    h.text(text);
    h.0
}

/// FNV-1a (64 bits): a stable hash of the campaign's inputs, the same on every machine.
#[derive(Debug, Clone, Copy)]
pub struct Fnv(pub u64);

impl Default for Fnv {
    fn default() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
}

impl Fnv {
    /// Adds `bytes`.
    pub fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }

    /// Adds a length-prefixed text (so that `"ab","c"` and `"a","bc"` differ).
    pub fn text(&mut self, s: &str) {
        self.bytes(&(s.len() as u64).to_le_bytes());
        self.bytes(s.as_bytes());
    }

    /// Adds the bits of floats.
    pub fn floats(&mut self, v: &[f64]) {
        self.bytes(&(v.len() as u64).to_le_bytes());
        for x in v {
            self.bytes(&x.to_bits().to_le_bytes());
        }
    }
}
