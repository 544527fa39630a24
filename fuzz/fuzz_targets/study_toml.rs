//! The study scenario TOML (`Scenario::from_toml`). A scenario read with at most 256 rows is
//! run, and every claimed-valid number checked: a non-degenerate cell has finite geometry and
//! Delassus entries (`G_NN > 0`) and a stick interval `L ≤ U` (bounds may be infinite in the
//! Painlevé regime, never NaN); a block with first-contact cells has finite shares in `[0, 1]`
//! summing to 1. The CSV/JSON writers and the claim checks must not panic.
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| pounding_fuzz::study_toml(data));
