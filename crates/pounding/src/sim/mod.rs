//! Time-history simulation (stage 2+).
