//! Integration tests of the `pounding` library (one test binary; one module per topic).

mod common;
mod ground_motion;
mod sim;
