//! The observers every bridge run records: one line per output.

use super::bearings::BearingForces;
use super::members::{Backwalls, JointSlip, PierColumns, RestrainerForces, ShearKeys};
use super::observe::Observer;
use super::segment_forces::SegmentForces;
use crate::sim::view::Bridge;

/// The observers every bridge run records (in output order).
pub(crate) fn standard(bridge: &Bridge) -> Vec<Box<dyn Observer>> {
    let mut out: Vec<Box<dyn Observer>> = vec![
        Box::new(BearingForces::new(bridge)),
        Box::new(RestrainerForces::new(bridge)),
        Box::new(JointSlip::new(bridge)),
    ];
    if !bridge.piers.is_empty() {
        out.push(Box::new(PierColumns::new(bridge)));
    }
    if bridge.abutments.iter().any(|a| a.wall.is_some()) {
        out.push(Box::new(Backwalls::new(bridge)));
    }
    if !bridge.elements.keys.is_empty() {
        out.push(Box::new(ShearKeys::new(bridge)));
    }
    out.push(Box::new(SegmentForces::new(bridge)));
    out
}
