//! Integration tests of the `pounding` library (one test binary; one module per topic).

mod analytic;
mod common;
mod contact;
mod geometry;
mod impact;
mod lcp;
mod study;
