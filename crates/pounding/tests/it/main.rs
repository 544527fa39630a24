//! Integration tests of the `pounding` library (one test binary; one module per topic).

mod analytic;
mod batch;
mod common;
mod contact;
mod contact_law;
mod event_exact;
mod fuzz;
mod geometry;
mod ground_motion;
mod harden;
mod impact;
mod lcp;
mod props;
mod shapes;
mod sim;
mod sim_compliance;
mod sim_shapes;
mod study;
mod study_shapes;
