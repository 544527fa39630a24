//! End-to-end tests of the `pounding` binary (one test binary; one module per subcommand).

mod impact;

use std::process::Command;

/// The built `pounding` binary.
pub fn pounding() -> Command {
    Command::new(env!("CARGO_BIN_EXE_pounding"))
}

#[test]
fn help_lists_subcommands() {
    let out = pounding().arg("--help").output().unwrap();
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    for sub in ["lcp", "impact", "study", "simulate", "compare"] {
        assert!(s.contains(sub), "--help lacks {sub}: {s}");
    }
}

mod batch;
mod compare;
mod fuzz;
mod harden;
mod lcp;
mod shapes;
mod simulate;
mod study;
mod study_shapes;
