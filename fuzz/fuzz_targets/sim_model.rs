//! The simulate model through the library API: `SimModel` (curved, straight or skewed decks,
//! bearings, damping model, abutments), `GroundMotion`, `SimSettings`, validation, the linear
//! system and a short rigid-contact run (≤ 120 steps).
//!
//! The simulate scenario TOML itself is parsed in the CLI binary (`cmd_simulate.rs`, with the
//! plotting modules); until it moves into the library (issue 10) this target fuzzes the library
//! pieces the scenario feeds. Each parameter is either drawn within its valid range or, when the
//! input says so, as an arbitrary float (validation must then refuse it or run without panic).
//! Oracle: when every parameter was drawn from its valid range, a run that ends `Completed` or
//! `CompletedWithLcpFailures` has only finite histories, impacts and summary numbers.
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| pounding_fuzz::sim_model(data));
