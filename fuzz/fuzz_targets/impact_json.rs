//! The generic impact problem JSON (`pounding impact --problem FILE.json`), read by the library's
//! `pounding::impact_report::parse_problem`. A problem read is
//! solved (`pounding::impact::solve`); a solved impact must carry finite velocities and impulses
//! within the Coulomb cone `Λ_N ≥ 0`, `|Λ_T| ≤ μ Λ_N` (tolerance 1e-6 of the largest impulse).
#![no_main]
use libfuzzer_sys::fuzz_target;
use pounding::impact::{self, ImpactSettings};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(p) = pounding::impact_report::parse_problem(text) else {
        return;
    };
    if p.contacts().len() > 4 || p.bodies().len() > 6 {
        return;
    }
    let s = impact::solve(&p, &ImpactSettings::default());
    pounding_fuzz::check_impact(&p, &s);
});
