//! The data of one fragility study ([`pounding::assessment::study`]: what was read before the
//! runs, [`Study`], and the fits after them, [`Fits`]), shared by `cmd_fragility` (which fills
//! them) and `fragility_plot` (which draws and reports them).

pub(crate) use pounding::assessment::study::{Fits, Study};
use pounding::fragility::FragilityRow;

/// `failed/samples` of a row's bootstrap, or `-` (no bootstrap, or no fit).
pub(crate) fn boot_failed(r: &FragilityRow) -> String {
    match (&r.bootstrap, r.bootstrap_failed()) {
        (Some(b), Some(f)) => format!("{f}/{}", b.samples),
        _ => "-".into(),
    }
}
