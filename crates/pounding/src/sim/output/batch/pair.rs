//! The two-deck `batch.csv` ([`BATCH_HEADER`]): the bridge row of the same run, translated
//! column by column ([`PAIR_BATCH_COLUMNS`]).

use super::{BATCH_HEADER, Grid, bridge_grid, with_set};
use crate::ground_motion::set::RecordSet;
use crate::sim::batch::BatchRow;

/// Where a column of the two-deck `batch.csv` ([`BATCH_HEADER`]) takes its cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairBatchCell {
    /// The cell of this column of the bridge row of the same run (the two-deck model is the
    /// bridge of two segments: one joint, decks 1 and 2 are segments 1 and 2).
    Bridge(&'static str),
    /// Only the form knows: the end that unseated first by its two-deck name
    /// ([`crate::sim::output::pair_seat_name`]: `deck1-joint`, …), the bridge's `unseated_end` renamed.
    UnseatedEnd,
}

/// The two-deck `batch.csv` as a translation of the bridge's ([`super::bridge_batch_header`]): each
/// column of [`BATCH_HEADER`], in its order, and the cell it takes. A record set's columns
/// (`record_y`, `record_x`, `meta_*`) keep their names in both.
pub const PAIR_BATCH_COLUMNS: [(&str, PairBatchCell); 31] = {
    use PairBatchCell::{Bridge as B, UnseatedEnd};
    [
        ("index", B("index")),
        ("record", B("record")),
        ("scale", B("scale")),
        ("pga_g", B("pga_g")),
        ("pga_mps2", B("pga_mps2")),
        ("status", B("status")),
        ("impacts", B("impacts")),
        ("impacting_contacts", B("impacting_contacts")),
        ("peak_joint_closing_m", B("joint1_peak_closing_m")),
        ("peak_joint_opening_m", B("joint1_peak_opening_m")),
        ("peak_rotation1_deg", B("segment1_peak_rotation_deg")),
        ("peak_rotation2_deg", B("segment2_peak_rotation_deg")),
        ("peak_slip_m", B("joint1_peak_slip_m")),
        ("peak_seat_displacement_m", B("peak_seat_displacement_m")),
        ("unseated", B("unseated")),
        ("unseating_time_s", B("unseating_time_s")),
        ("unseated_end", UnseatedEnd),
        ("max_penetration_m", B("max_penetration_m")),
        ("energy_balance_error", B("energy_balance_error")),
        ("input_energy_J", B("input_energy_J")),
        ("viscous_dissipation_J", B("viscous_dissipation_J")),
        ("contact_dissipation_J", B("contact_dissipation_J")),
        ("duration_s", B("duration_s")),
        ("steps", B("steps")),
        ("lcp_solves", B("lcp_solves")),
        ("lcp_failures", B("lcp_failures")),
        // the joint's (the bridge's column is the largest over joints and abutments)
        ("peak_contact_force_n", B("joint1_peak_contact_force_n")),
        ("steps_per_contact", B("steps_per_contact")),
        ("newton_failures", B("newton_failures")),
        ("warnings", B("warnings")),
        ("error", B("error")),
    ]
};

/// The two-deck `batch.csv` ([`BATCH_HEADER`], with a record `set` its columns after `record`):
/// the bridge table of the same rows translated by [`PAIR_BATCH_COLUMNS`].
pub(super) fn two_deck_batch_csv(rows: &[BatchRow], set: Option<&RecordSet>) -> String {
    let bridge = bridge_grid(2, rows, set);
    let header = with_set(BATCH_HEADER, set).0;
    // per column: the bridge column it reads, and whether it is the unseated end's two-deck name
    let src: Vec<(usize, bool)> = header
        .iter()
        .map(
            |name| match PAIR_BATCH_COLUMNS.iter().find(|(n, _)| n == name) {
                Some((_, PairBatchCell::Bridge(b))) => (bridge.col(b), false),
                Some((_, PairBatchCell::UnseatedEnd)) => (bridge.col("unseated_end"), true),
                None => (bridge.col(name), false),
            },
        )
        .collect();
    let rows = bridge.rows.iter().zip(rows).map(|(b, r)| {
        src.iter()
            .map(|&(i, end)| match &r.outcome {
                Ok(o) if end => super::super::pair_unseated_end(&o.summary).unwrap_or_default(),
                _ => b[i].clone(),
            })
            .collect()
    });
    Grid {
        header,
        rows: rows.collect(),
    }
    .csv()
}
