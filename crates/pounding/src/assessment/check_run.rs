//! A code check beside a run: each seated end's code seats ([`super::check`]) next to the
//! simulated demand on it (`summary.json`'s `seats[]`: the peak and residual displacement off
//! the seat), for `simulate`'s report of a bridge with a `[code_check]` table; and beside the
//! runs of a fragility study ([`against_runs`]), for its report.
//!
//! The codes' seat formulas allow for the design displacement `d_i` given in `[code_check]`
//! (`displacement_m`); where the run's peak seat displacement exceeds it, the simulated demand
//! is beyond what the formulas were given ([`EndVsRun::beyond_design`]).

use super::check::{CheckReport, EndCheck};
use super::run::RunRow;
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

/// One seated end: its code check and the demand of a fragility study's trusted runs on it.
#[derive(Debug, Clone, PartialEq)]
pub struct EndVsRuns<'a> {
    /// The code check of the end.
    pub check: &'a EndCheck,
    /// Trusted runs (status `Completed`) that report this end.
    pub runs: usize,
    /// The largest peak seat displacement over those runs \[m\] and the IM of its run \[g\]
    /// (`None` without a trusted run).
    pub largest: Option<(Real, Real)>,
    /// Runs in which the end left its seat (peak displacement above the provided seat).
    pub unseated: usize,
    /// Runs whose peak displacement exceeds the governing code seat: even the longest seat a
    /// code asks for would not have held the end (`None`: no code evaluated).
    pub beyond_code: Option<usize>,
    /// Runs whose peak exceeds the design displacement the codes were given (`None`: none given).
    pub beyond_design: Option<usize>,
}

/// Each checked end of `report` beside the trusted `rows` of a fragility study, whose
/// [`RunRow::seats`] are in the order of `seat_ends` (the model's
/// [`crate::sim::bridge::BridgeModel::seat_end_names`]): demand = ratio × the end's seat.
pub fn against_runs<'a>(
    report: &'a CheckReport,
    seat_ends: &[String],
    rows: &[RunRow],
) -> Vec<EndVsRuns<'a>> {
    report
        .ends
        .iter()
        .map(|e| {
            let seat = e.at.seat_length;
            let idx = seat_ends.iter().position(|n| *n == e.at.end);
            let peaks: Vec<(Real, Real)> = rows
                .iter()
                .filter(|r| r.trusted())
                .filter_map(|r| Some((idx.and_then(|i| r.seats.get(i))? * seat, r.im_g)))
                .collect();
            let count = |limit: Real| peaks.iter().filter(|(p, _)| *p > limit).count();
            EndVsRuns {
                check: e,
                runs: peaks.len(),
                largest: peaks
                    .iter()
                    .copied()
                    .fold(None, |m: Option<(Real, Real)>, p| match m {
                        Some(q) if q.0 >= p.0 => Some(q),
                        _ => Some(p),
                    }),
                unseated: count(seat),
                beyond_code: e.governing().map(|(_, g)| count(g)),
                beyond_design: e.displacement.map(count),
            }
        })
        .collect()
}
