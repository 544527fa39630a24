//! The peaks of a bridge run ([`BridgeSummary`]): per joint, abutment (with its backwall and
//! shear keys), segment, pier and seated end, and the energy check.

use crate::math::Real;
use crate::sim::Energy;

/// Peaks of one joint.
#[derive(Debug, Clone, PartialEq)]
pub struct JointSummary {
    /// Impacts: rigid law, steps in which a contact of this joint approaching at ≥
    /// [`crate::sim::SimSettings::impact_velocity`] gets a positive normal impulse; compliance laws, the
    /// maximal intervals of positive total force.
    pub impacts: usize,
    /// Largest total normal force of the joint's contacts \[N\] (`None` for rigid contact).
    pub peak_contact_force: Option<Real>,
    /// Largest normal impulse of one impact (the sum over the joint's contacts) \[N s\].
    pub peak_impulse: Real,
    /// `max_t (g − smallest end gap)` \[m\].
    pub peak_closing: Real,
    /// `max_t (largest end gap − g)` \[m\].
    pub peak_opening: Real,
    /// `max_t |slip|`: the relative tangential displacement of the two face midpoints along the
    /// joint's reference tangent ([`super::BridgeSolution::slip`]) \[m\].
    pub peak_slip: Real,
    /// Either end at this joint exceeded its seat length.
    pub unseated: bool,
    /// Episodes of positive restrainer force (0 without a restrainer).
    pub restrainer_engagements: usize,
    /// Largest restrainer force \[N\] (`None` without a restrainer).
    pub restrainer_peak_force: Option<Real>,
}

/// Peaks of one abutment.
#[derive(Debug, Clone, PartialEq)]
pub struct AbutmentSummary {
    /// Impacts (as for a joint).
    pub impacts: usize,
    /// Largest total normal force \[N\] (`None` for rigid contact).
    pub peak_contact_force: Option<Real>,
    /// Largest normal impulse of one impact \[N s\].
    pub peak_impulse: Real,
    /// `max_t (gap − smaller corner gap)` \[m\].
    pub peak_closing: Real,
    /// The backwall's peaks (`None` without a backwall).
    pub backwall: Option<BackwallSummary>,
}

/// The peaks of an abutment's exterior shear keys.
#[derive(Debug, Clone, PartialEq)]
pub struct ShearKeySummary {
    /// `start` or `end`.
    pub side: &'static str,
    /// `max_t |F|` \[N\].
    pub peak_force: Real,
    /// `max_t |v|`: the deck end's largest transverse displacement relative to the abutment \[m\].
    pub peak_deformation: Real,
    /// Whether a key yielded.
    pub yielded: bool,
    /// Energy the keys dissipated by yielding \[J\].
    pub dissipated: Real,
}

/// The peaks of an abutment's backwall ([`crate::sim::bridge::Backwall`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BackwallSummary {
    /// `max_t s`: the farthest the wall was pushed into the soil \[m\].
    pub peak_displacement: Real,
    /// `max_t F` of the backfill \[N\] (`None` without backfill).
    pub peak_backfill_force: Option<Real>,
    /// `max_t |f|` of the piles \[N\] (`None` without piles).
    pub peak_pile_force: Option<Real>,
    /// `s` at the end \[m\].
    pub residual_displacement: Real,
    /// Energy dissipated by the piles' yielding \[J\].
    pub pile_hysteretic_energy: Real,
}

/// Peaks of one segment.
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentSummary {
    /// `max_t |(x, y)|` of the centroid relative to the ground \[m\].
    pub peak_displacement: Real,
    /// `|(x, y)|` at the end \[m\].
    pub final_displacement: Real,
    /// `max_t |θ|` \[rad\].
    pub peak_rotation: Real,
    /// Largest bearing deformation `max_t max_b |u_b|` (linearised) \[m\].
    pub peak_bearing_deformation: Real,
    /// Energy dissipated by yielding bearings \[J\] (0 for linear bearings).
    pub hysteretic_energy: Real,
    /// Natural frequencies `ω_1 ≤ ω_2 ≤ ω_3` on the bearings \[rad/s\].
    pub frequencies: [Real; 3],
    /// Rayleigh coefficients `(a_0, a_1)` of the segment's damping (`(0, 0)` with dashpots).
    pub rayleigh: (Real, Real),
}

/// The response of one pier ([`crate::sim::bridge::Pier`]): its cap relative to the ground
/// (the column's deformation) and its column.
#[derive(Debug, Clone, PartialEq)]
pub struct PierSummary {
    /// The joint it carries (1-based).
    pub joint: usize,
    /// `max_t |x_c|`, `max_t |y_c|` of the cap \[m\].
    pub peak_drift: [Real; 2],
    /// `max_t |(x_c, y_c)|` \[m\].
    pub peak_drift_magnitude: Real,
    /// `(x_c, y_c)` at the end \[m\].
    pub residual_drift: [Real; 2],
    /// `max_t |f|` of the column's spring force (its dashpot's left out) \[N\].
    pub peak_column_force: Real,
    /// Whether the column yielded.
    pub yielded: bool,
    /// Energy dissipated by the column's yielding \[J\].
    pub hysteretic_energy: Real,
}

/// The seat margin of one seated end (a segment's start or end, on an abutment seat, a joint's
/// seat, or an outer seat without abutment).
#[derive(Debug, Clone, PartialEq)]
pub struct SeatSummary {
    /// `segment<i>-start` / `segment<i>-end` (1-based, as `unseated_end`).
    pub end: String,
    /// The segment (1-based).
    pub segment: usize,
    /// What the end sits on: `abutment-start`, `abutment-end`, `joint<k>` (1-based), or
    /// `outer-start` / `outer-end` (an outer end without abutment).
    pub support: String,
    /// The seat length \[m\].
    pub seat_length: Real,
    /// The largest displacement of the end off its seat (along the face's outward normal; the
    /// larger of its two corners) \[m\].
    pub peak_displacement: Real,
    /// `peak_displacement / seat_length` (above 1: unseated) \[-\].
    pub ratio: Real,
    /// When the peak was first reached \[s\].
    pub peak_time: Real,
    /// The displacement at the end of the run (residual) \[m\].
    pub residual_displacement: Real,
    /// The end left its seat.
    pub unseated: bool,
}

/// Peaks and the energy check of a bridge run.
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeSummary {
    /// Impacts of the whole bridge (rigid: steps with an impact; compliance: the sum over sites).
    pub impacts: usize,
    /// Per joint.
    pub joints: Vec<JointSummary>,
    /// `[start, end]`; `None` where absent.
    pub abutments: [Option<AbutmentSummary>; 2],
    /// Per segment.
    pub segments: Vec<SegmentSummary>,
    /// Per pier (none without piers).
    pub piers: Vec<PierSummary>,
    /// Per abutment with shear keys, start before end.
    pub shear_keys: Vec<ShearKeySummary>,
    /// Largest seat displacement over all seated ends (joint ends and outer ends, as the
    /// two-deck `peak_seat_displacement_m`) \[m\].
    pub peak_seat_displacement: Real,
    /// Largest ratio of an end's seat displacement to its own seat length, over all seated
    /// ends: the unseating margin (above 1 where an end unseated) \[-\].
    pub peak_seat_ratio: Real,
    /// Some end exceeded its seat length.
    pub unseated: bool,
    /// First time an end exceeded its seat length \[s\].
    pub unseating_time: Option<Real>,
    /// Which end first: `segment<i>-start` / `segment<i>-end` (1-based).
    pub unseated_end: Option<String>,
    /// Every seated end's margin, in bridge order (segment 1 start, segment 1 end, …).
    pub seats: Vec<SeatSummary>,
    /// The index in [`Self::seats`] of the governing end: the largest ratio (the first of equal
    /// ones).
    pub governing_seat: usize,
    /// Largest penetration at a joint (rigid: the scheme's overlap; compliance: the law's
    /// deformation) \[m\].
    pub peak_penetration: Real,
    /// Largest overlap `max(0, −g)` of a rigid-law site (a joint end or an abutment corner) at
    /// the steps' end states `t_k`, from the peak closings: `max(peak_closing − gap)` \[m\] (0
    /// without rigid sites). With the position projection ([`Self::projection`]) it is at most
    /// its tolerance.
    pub max_overlap: Real,
    /// What the position projection did (`None`: run without it, [`crate::sim::SimSettings::projection`]).
    pub projection: Option<crate::sim::projection::ProjectionStats>,
    /// `max_t |E_0 + W_in − (T + V + D_viscous + D_contact)| / max_t |E_0 + W_in|`.
    pub energy_balance_error: Real,
    /// Energies at the end.
    pub final_energy: Energy,
    /// `max_t |E_0 + W_in|` \[J\].
    pub max_input_energy: Real,
    /// Work done on the restrainers (stored plus plastic) at the end \[J\].
    pub restrainer_work: Real,
    /// Work done on the backfills (stored plus dissipated) \[J\].
    pub backfill_work: Real,
    /// Work done on the shear keys (stored plus dissipated) \[J\].
    pub shear_key_work: Real,
}
