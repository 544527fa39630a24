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

/// The two-deck model's `M`, `K`, `C` in `q = (x1, y1, θ1, x2, y2, θ2)` and each deck's natural
/// frequencies, from the one assembly of its bridge of two segments
/// ([`pounding::sim::bridge::BridgeModel::body_systems`]).
pub struct TwoDeckSystem {
    pub mass: nalgebra::Matrix6<f64>,
    pub stiffness: nalgebra::Matrix6<f64>,
    pub damping: nalgebra::Matrix6<f64>,
    pub frequencies: [[f64; 3]; 2],
}

/// [`TwoDeckSystem`] of `model` (which must be valid).
pub fn two_deck_system(model: &pounding::sim::SimModel) -> TwoDeckSystem {
    let blocks = pounding::sim::bridge::BridgeModel::from_pair(model)
        .body_systems()
        .expect("a valid two-deck model");
    let mut s = TwoDeckSystem {
        mass: nalgebra::Matrix6::zeros(),
        stiffness: nalgebra::Matrix6::zeros(),
        damping: nalgebra::Matrix6::zeros(),
        frequencies: [blocks[0].frequencies, blocks[1].frequencies],
    };
    for (j, b) in blocks.iter().enumerate() {
        let o = 3 * j;
        s.mass.fixed_view_mut::<3, 3>(o, o).copy_from(&b.mass);
        s.stiffness
            .fixed_view_mut::<3, 3>(o, o)
            .copy_from(&b.stiffness);
        s.damping.fixed_view_mut::<3, 3>(o, o).copy_from(&b.damping);
    }
    s
}

/// The error of building `text` (file `f.toml`), in its form (`[[segment]]`: a bridge).
pub fn scenario_error(text: &str) -> String {
    let e = match pounding::sim::scenario::Scenario::from_toml(text, "f.toml") {
        Err(e) => return e.to_string(),
        Ok(s) => s,
    };
    let e = if text.contains("[[segment]]") {
        e.build_bridge().err()
    } else {
        e.build().err()
    };
    e.expect("the scenario must be refused").to_string()
}
