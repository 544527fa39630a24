//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::PathBuf;

/// The project's shared data directory: `$POUNDING_SHARED` if set, else `../shared` beside the
/// repository root. `None` (after printing `SKIPPED: ...`) when absent, as in a user's clone.
pub fn shared_dir() -> Option<PathBuf> {
    let p = match std::env::var_os("POUNDING_SHARED") {
        Some(s) => PathBuf::from(s),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared"),
    };
    if p.is_dir() {
        Some(p)
    } else {
        eprintln!(
            "SKIPPED: shared data directory {} is absent (tests that read it are skipped)",
            p.display()
        );
        None
    }
}
