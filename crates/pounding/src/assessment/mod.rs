//! The probabilistic-assessment workflow of `pounding fragility`: a bridge scenario with a
//! `[fragility]` table and `[[limit_state]]` tables ([`settings`]), a record set
//! ([`crate::ground_motion::set`]), intensity measures and stripes ([`im`]), one bridge run per
//! record (pair) and stripe in parallel ([`run`]), and the limit states evaluated on each run's
//! summary ([`limit`]).
//!
//! ```toml
//! [fragility]
//! records = "suite.toml"        # manifest path relative to the scenario (.toml or .csv)
//! im = "sa"                     # "pga" | "sa"
//! period_s = "model"            # for sa: seconds, or "model" (the fundamental period)
//! damping = 0.05                # for sa
//! pair_im = "rotd50"            # for pairs: "geomean" | "rotd50"
//! levels_g = [0.1, 0.2, 0.5]    # multiple stripes; or scales = [0.5, 1.0, 2.0] (IDA)
//! bootstrap = 500               # resamples over records for the intervals
//! seed = 1
//! level = 0.95                  # confidence level of the intervals
//!
//! [[limit_state]]
//! name = "unseating"
//! kind = "unseating"
//! ```
//!
//! **Directions.** A run applies the entry's first component (`x` in the manifest) where a
//! batch run applies its record: along `Rot(α) ŷ` with the scenario's `scale_y` (the direction
//! `record_y` acts along), and a pair's second component (`y`) along `Rot(α) x̂` with `scale_x`
//! (where `record_x` acts). The scenario's own `record_y` / `record_x` are not used. The IM of an
//! entry is that of its components as applied at unit factor (times `|scale_y|`, `|scale_x|`).
//!
//! **Runs.** With `R` entries and `S` stripes, run `i = a S + b` is entry `a` at stripe `b`
//! (deterministic order for any number of threads). A run that fails (an error) or ends with a
//! status other than `Completed` is kept in `runs.csv` with its status, and its limit states
//! are excluded (`None`) from the fit and counted.

pub mod check;
mod check_codes;
pub mod check_input;
pub mod check_run;
pub mod check_summary;
mod check_values;
pub mod check_write;
pub mod code_check;
pub mod design;
pub mod design_file;
pub mod design_out;
pub mod design_search;
pub mod design_write;
mod hazard_csv;
pub mod hazard_input;
pub mod hazard_study;
pub mod im;
pub mod limit;
pub mod run;
mod run_fit;
pub mod settings;
pub mod study;
pub mod svgm;
pub mod variant;

/// Largest factor a record may be scaled by (by a level's `L / IM` or an IDA scale): a record
/// scaled by more is no longer a plausible ground motion of that intensity (practice keeps scale
/// factors within about 0.25–4; 100 only refuses the absurd, such as the 1e8 of a `period_s` at
/// which the record has no spectral content).
pub const MAX_SCALE_FACTOR: crate::math::Real = 100.0;

pub use check::{CheckReport, check_bridge, check_scenario, seated_ends};

/// Checks the assessment tables a scenario may carry, so that no front end runs a scenario with
/// a typo in them (every command and Python call that reads a scenario calls this): a bridge's
/// `[fragility]` and `[[limit_state]]`s, and `[code_check]` — against the bridge of `segments`
/// segments when its model is built (per-segment lists, in-span hinges). `Ok` when absent.
pub fn check_tables(
    sc: &crate::sim::scenario::Scenario,
    segments: Option<usize>,
) -> Result<(), AssessmentError> {
    let (text, origin) = (sc.text(), sc.origin());
    if sc.is_bridge() {
        FragilitySettings::check_if_present(text, origin)?;
    }
    match segments {
        Some(n) => CodeCheckInput::check_against(text, origin, n),
        None => CodeCheckInput::check_if_present(text, origin),
    }
}
pub use check_input::CodeCheckInput;
pub use settings::{
    FragilitySettings, ImKind, LimitKind, LimitState, PairIm, PeriodChoice, Stripes,
};

/// Why a fragility study cannot start (bad input). Nothing has been run or written.
#[derive(Debug, thiserror::Error)]
pub enum AssessmentError {
    /// TOML syntax, an unknown key or a wrong type in `[fragility]` / `[[limit_state]]`.
    #[error("invalid scenario {origin}: {message}")]
    Syntax {
        /// The scenario's name.
        origin: String,
        /// The TOML reader's message (names line and column).
        message: String,
    },
    /// A bad or missing value: the key (e.g. `fragility.levels_g`, `limit_state[1].capacity_n`)
    /// and its line.
    #[error("{message} — `{key}` ({})", match line { Some(l) => format!("{origin}:{l}"), None => format!("not set in {origin}") })]
    Key {
        /// What is wrong.
        message: String,
        /// The key.
        key: String,
        /// The scenario's name.
        origin: String,
        /// 1-based line, `None` when the key is not written.
        line: Option<usize>,
    },
    /// The record set.
    #[error(transparent)]
    Set(#[from] crate::ground_motion::set::SetError),
    /// The bridge scenario itself.
    #[error(transparent)]
    Scenario(#[from] crate::sim::scenario::ScenarioError),
    /// The bridge model (e.g. no fundamental period).
    #[error("{0}")]
    Model(String),
    /// The study cannot be set up: a two-deck scenario, no record set.
    #[error("{0}")]
    Invalid(String),
    /// A stripe that needs a scale factor beyond [`MAX_SCALE_FACTOR`] for an entry: its IM is too
    /// small for the level (or the IDA scale is absurd).
    #[error(
        "record {id}: {stripe} needs a scale factor of {} (its {im} is {} g), beyond the limit of \
         {MAX_SCALE_FACTOR}: the record's IM is too small for that level; remove the record or \
         the level",
        crate::output::float_token(*factor),
        crate::output::float_token(*entry_im)
    )]
    ScaleFactor {
        /// The entry's id.
        id: String,
        /// The stripe, e.g. `level_g = 3` or `scale = 500`.
        stripe: String,
        /// The IM's label.
        im: String,
        /// The entry's IM at unit factor \[g\].
        entry_im: crate::math::Real,
        /// The factor the stripe needs.
        factor: crate::math::Real,
    },
    /// An entry whose IM is zero cannot be scaled to a level.
    #[error(
        "record {id}: its {im} is 0, so it cannot be scaled to an IM level; remove it from the set"
    )]
    ZeroIm {
        /// The entry's id.
        id: String,
        /// The IM's label.
        im: String,
    },
}

impl AssessmentError {
    /// A bad or missing value of `key` set at `line` (`None`: not written) of `origin`.
    pub(crate) fn key(origin: &str, key: &str, line: Option<usize>, message: String) -> Self {
        AssessmentError::Key {
            message,
            key: key.into(),
            origin: origin.into(),
            line,
        }
    }
}
