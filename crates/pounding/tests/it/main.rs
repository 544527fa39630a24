//! Integration tests of the `pounding` library (one test binary; one module per topic).

mod analytic;
mod batch;
mod common;
mod contact;
mod contact_law;
mod event_exact;
mod geometry;
mod ground_motion;
mod harden;
mod harden_input;
mod harden_io;
mod harden_round2;
mod impact;
mod lcp;
mod lemke_degenerate;
mod physics_check;
mod shapes;
mod sim;
mod sim_bearings;
mod sim_compliance;
mod sim_friction;
mod sim_shapes;
mod study;
mod study_shapes;
