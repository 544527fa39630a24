//! Lemke (dynamic and fixed-size kernels) and enumeration on structured random LCPs of every scale;
//! the oracle of `check_lcp` on every `Solved`.
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| pounding_fuzz::lcp_solve(data));
