//! Siconos `.dat`, `LCPSET 1` and `LCPSOL 1` readers; every problem read is solved with Lemke and
//! checked by the oracle of `check_lcp`; `LCPSOL` round-trips through its writer.
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| pounding_fuzz::lcp_io(data));
