//! End-to-end tests of the `pounding` binary (one test binary; one module per subcommand).

mod bridge;
mod bridge_compare;
mod impact;
mod substructure;
mod support_motion;

use std::process::Command;

/// Reports a skipped test: `SKIPPED <test>: reason` on stderr (shown by `cargo test`), and a line appended to
/// `$POUNDING_SKIP_LOG` when set (`.ci/run` lists them; see `pounding/tests/it/common.rs`).
pub fn skipped(reason: &str) {
    use std::io::Write;
    let name = std::thread::current().name().unwrap_or("?").to_string();
    // Written to the process's stderr directly, not through `eprintln!`: the test harness
    // captures the macros' output of a passing test, so the note would be hidden; this way
    // `cargo test` prints every skip where it happens.
    let _ = writeln!(
        std::io::stderr().lock(),
        "SKIPPED pounding-cli/cli::{name}: {reason}"
    );
    if let Some(log) = std::env::var_os("POUNDING_SKIP_LOG")
        && let Ok(mut f) = std::fs::OpenOptions::new()
            .create(true)
            .append(true)
            .open(log)
    {
        let _ = writeln!(f, "pounding-cli/cli::{name}\t{reason}");
    }
}

// Scratch directories (shared with the library's integration tests: one copy of the code).
#[path = "../../../pounding/tests/it/scratch.rs"]
mod scratch;
pub use scratch::{InScratch, Scratch, scratch_dir};

/// A fresh scratch directory (as [`scratch_dir`]) holding the given files: (file name, text).
pub fn scratch_with(prefix: &str, name: &str, files: &[(&str, &str)]) -> Scratch {
    let d = scratch_dir(prefix, name);
    for (file, text) in files {
        std::fs::write(d.join(file), text).unwrap();
    }
    d
}

/// Runs `pounding ARGS`: (exit code, stdout, stderr).
pub fn run_capture(args: &[&str]) -> (Option<i32>, String, String) {
    let o = pounding().args(args).output().unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// The built `pounding` binary.
pub fn pounding() -> Command {
    Command::new(env!("CARGO_BIN_EXE_pounding"))
}

#[test]
fn help_lists_subcommands() {
    let out = pounding().arg("--help").output().unwrap();
    assert!(out.status.success());
    let s = String::from_utf8_lossy(&out.stdout);
    for sub in [
        "lcp",
        "impact",
        "study",
        "simulate",
        "compare",
        "spectrum",
        "motion",
        "fragility",
        "check",
        "campaign",
        "design",
    ] {
        assert!(s.contains(sub), "--help lacks {sub}: {s}");
    }
}

mod accuracy;
mod batch;
mod bridge_batch;
mod bridge_plots;
mod campaign;
mod campaign_read;
mod check;
mod compare;
mod compare_energy;
mod design;
mod docs_links;
mod errors_round3;
mod fragility;
mod fragility_censored;
mod fragility_example;
mod fragility_hazard;
mod fragility_report;
mod fragility_trial;
mod fuzz;
mod golden;
mod harden;
mod harden_input;
mod harden_io;
mod harden_round2;
mod inputs;
mod lcp;
mod manifest_csv;
mod memory_guards;
mod motion;
mod motion_limits;
mod motion_svgm;
mod pair_batch;
mod physics_check;
mod record_misreads;
mod record_units;
mod reports_browser;
mod reports_browser_anim;
mod seat_margins;
mod shapes;
mod sim_report;
mod simulate;
mod simulate_flags;
mod simulate_projection;
mod small_things;
mod spectrum;
mod spectrum_limits;
mod study;
mod study_shapes;
mod trial_fixes;
mod vocab;
mod warnings;

/// The warnings section of a `compare` report (between its `warnings` and `skipped` headings).
pub fn report_warnings(html: &str) -> &str {
    html.split("<h2 id=\"warnings\">")
        .nth(1)
        .expect("a warnings section")
        .split("<h2 id=\"skipped\">")
        .next()
        .expect("text")
}
