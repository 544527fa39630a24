//! Integration tests of the `pounding` library (one test binary; one module per topic).

mod analytic;
mod common;
mod contact;
mod contact_law;
mod geometry;
mod ground_motion;
mod impact;
mod lcp;
mod sim;
mod sim_compliance;
