//! The data of one fragility study as the CLI holds it: what was read before the runs
//! ([`Study`]) and the fits after them ([`Fits`]), shared by `cmd_fragility` (which fills them)
//! and `fragility_plot` (which draws and reports them).

use pounding::assessment::FragilitySettings;
use pounding::assessment::im::{ImSpec, PeriodInfo};
use pounding::assessment::limit::BoundLimit;
use pounding::fragility::FragilityRow;
use pounding::ground_motion::set::RecordSet;
use pounding::math::Real;
use std::path::PathBuf;

/// Everything read and checked before any run.
pub(crate) struct Study {
    pub origin: String,
    pub setup: pounding::sim::scenario::BridgeSetup,
    pub settings: FragilitySettings,
    pub set: RecordSet,
    pub set_path: PathBuf,
    pub limits: Vec<BoundLimit>,
    pub spec: ImSpec,
    pub period: Option<PeriodInfo>,
    /// The code check of a scenario with a `[code_check]` table (its input validated before
    /// any run; `Err`: the check could not be evaluated, with the reason).
    pub code_check: Option<Result<pounding::assessment::CheckReport, String>>,
}

impl Study {
    /// The scenario's name.
    pub fn scenario_origin(&self) -> &str {
        &self.origin
    }
}

/// The fits of every limit state and the IMs of the bootstrap band.
pub(crate) struct Fits {
    pub rows: Vec<FragilityRow>,
    pub band_im: Vec<Real>,
}

/// `failed/samples` of a row's bootstrap, or `-` (no bootstrap, or no fit).
pub(crate) fn boot_failed(r: &FragilityRow) -> String {
    match (&r.bootstrap, r.bootstrap_failed()) {
        (Some(b), Some(f)) => format!("{f}/{}", b.samples),
        _ => "-".into(),
    }
}
