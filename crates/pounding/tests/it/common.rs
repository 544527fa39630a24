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
        skipped(&format!(
            "shared data directory {} is absent (tests that read it are skipped)",
            p.display()
        ));
        None
    }
}

/// Reports a skipped test (or skipped part of one): `SKIPPED <test>: reason` on stderr (shown by `cargo test`), and one line
/// `test-name<TAB>reason` appended to the file `$POUNDING_SKIP_LOG` when set, so that `.ci/run`
/// can list every skip in its summary.
pub fn skipped(reason: &str) {
    use std::io::Write;
    let name = std::thread::current().name().unwrap_or("?").to_string();
    // Written to the process's stderr directly, not through `eprintln!`: the test harness
    // captures the macros' output of a passing test, so the note would be hidden; this way
    // `cargo test` prints every skip where it happens.
    let _ = writeln!(
        std::io::stderr().lock(),
        "SKIPPED pounding/it::{name}: {reason}"
    );
    if let Some(log) = std::env::var_os("POUNDING_SKIP_LOG")
        && let Ok(mut f) = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(log)
    {
        let _ = writeln!(f, "pounding/it::{name}\t{reason}");
    }
}
