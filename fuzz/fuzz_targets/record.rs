//! Ground-motion record readers: PEER `.AT2` and two-column CSV (`g` or `m/s2`). A record read
//! must hold only finite samples at strictly increasing times, and interpolating or resampling it
//! must give finite numbers.
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| pounding_fuzz::record(data));
