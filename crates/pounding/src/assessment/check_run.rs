//! A code check beside a run: each seated end's code seats ([`super::check`]) next to the
//! simulated demand on it (`summary.json`'s `seats[]`: the peak and residual displacement off
//! the seat), for `simulate`'s report of a bridge with a `[code_check]` table.
//!
//! The codes' seat formulas allow for the design displacement `d_i` given in `[code_check]`
//! (`displacement_m`); where the run's peak seat displacement exceeds it, the simulated demand
//! is beyond what the formulas were given ([`EndVsRun::beyond_design`]).

use super::check::{CheckReport, EndCheck};
use crate::math::Real;
use crate::sim::bridge::SeatSummary;

/// One seated end: its code check and the run's demand on it.
#[derive(Debug, Clone, PartialEq)]
pub struct EndVsRun<'a> {
    /// The code check of the end.
    pub check: &'a EndCheck,
    /// Peak displacement off the seat in the run \[m\].
    pub peak: Real,
    /// Displacement off the seat at the end of the run \[m\].
    pub residual: Real,
    /// `peak / provided seat`.
    pub ratio: Real,
    /// Provided seat minus the peak \[m\] (negative: unseated).
    pub seat_left: Real,
    /// `Some(true)` when the peak exceeds the design displacement the codes were given at this
    /// end (`None`: none given).
    pub beyond_design: Option<bool>,
}

/// The ends of `report` with the run's seat summaries `seats` (matched by end name; an end the
/// run does not report is left out).
pub fn against_run<'a>(report: &'a CheckReport, seats: &[SeatSummary]) -> Vec<EndVsRun<'a>> {
    report
        .ends
        .iter()
        .filter_map(|e| {
            let s = seats.iter().find(|s| s.end == e.at.end)?;
            Some(EndVsRun {
                check: e,
                peak: s.peak_displacement,
                residual: s.residual_displacement,
                ratio: s.ratio,
                seat_left: e.at.seat_length - s.peak_displacement,
                beyond_design: e.displacement.map(|d| s.peak_displacement > d),
            })
        })
        .collect()
}
