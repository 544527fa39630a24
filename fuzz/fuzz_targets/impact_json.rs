//! The generic impact problem JSON (`pounding impact --problem FILE.json`). Its reader lives in
//! the CLI binary (`crates/pounding-cli/src/cmd_impact.rs`, `parse_problem`), which is compiled
//! into this target as a module until it moves into the library (issue 10). A problem read is
//! solved (`pounding::impact::solve`); a solved impact must carry finite velocities and impulses
//! within the Coulomb cone `Λ_N ≥ 0`, `|Λ_T| ≤ μ Λ_N` (tolerance 1e-6 of the largest impulse).
#![no_main]
use libfuzzer_sys::fuzz_target;
use pounding::impact::{self, ImpactSettings};

#[allow(dead_code, unused_imports, clippy::all)]
#[path = "../../crates/pounding-cli/src/cmd_impact.rs"]
mod cmd_impact;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(p) = cmd_impact::parse_problem(text) else {
        return;
    };
    if p.contacts().len() > 4 || p.bodies().len() > 6 {
        return;
    }
    let s = impact::solve(&p, &ImpactSettings::default());
    pounding_fuzz::check_impact(&p, &s);
});
