//! The result of a run of a bridge (or of the two-deck model, its two-segment bridge): the
//! histories, the impacts, the peaks per joint, abutment, segment and seated end
//! ([`BridgeSummary`]) and the observers' tables, assembled from the driver's run.
//!
//! `summary.rs` holds the peaks' types, `assemble.rs` builds a [`BridgeSolution`] from a run.

mod assemble;
mod summary;

pub(crate) use assemble::{seat_name, solution};
pub use summary::{
    AbutmentSummary, BackwallSummary, BridgeSummary, JointSummary, PierSummary, SeatSummary,
    SegmentSummary, ShearKeySummary,
};

use super::dofs::Dofs;
use super::{Energy, ImpactRecord, SimContact, SimStatus};
use crate::contact_law::timestep::TimeStepAdvice;
use crate::math::Real;

/// Result of [`super::bridge::simulate`] and of [`super::simulate`].
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeSolution {
    /// Outcome.
    pub status: SimStatus,
    /// Steps taken.
    pub steps: usize,
    /// Step size \[s\].
    pub dt: Real,
    /// Number of segments.
    pub n_segments: usize,
    /// Where each segment's coordinates sit in the rows of [`Self::q`] and [`Self::u`].
    pub dofs: Dofs,
    /// Kept times \[s\].
    pub t: Vec<Real>,
    /// `q` rows ([`Self::dofs`]`.len()` per kept time).
    pub q: Vec<Real>,
    /// `u` rows.
    pub u: Vec<Real>,
    /// Signed gaps of each joint's four corner-against-face candidates in
    /// [`crate::geometry::ContactCase::ALL`] order (`4 (N − 1)` per kept time; corner to the other
    /// face's *line*, meaningful only for a corner over that face) \[m\].
    pub gaps: Vec<Real>,
    /// End gaps of each joint (`2 (N − 1)` per kept time; NaN where no corner is over the face) \[m\].
    pub end_gaps: Vec<Real>,
    /// Slip of each joint (`N − 1` per kept time): the displacement of segment `k`'s end-face
    /// midpoint relative to segment `k + 1`'s start-face midpoint along the joint's reference
    /// tangent `τ⁰` \[m\].
    pub slip: Vec<Real>,
    /// Normal force of each joint end (compliance; `2 (N − 1)` per kept time) \[N\].
    pub contact_force: Vec<Real>,
    /// Smaller abutment corner gap `[start, end]` per kept time (NaN where absent) \[m\].
    pub abutment_gaps: Vec<[Real; 2]>,
    /// Energies per kept time.
    pub energy: Vec<Energy>,
    /// Impacting contacts in time order ([`ImpactRecord::site`] names the joint or abutment).
    pub impacts: Vec<ImpactRecord>,
    /// Peaks.
    pub summary: BridgeSummary,
    /// The supports moved apart (wave passage, a motion per support): the histories' `q` are
    /// relative to the reference ground motion, not to each support.
    pub supports_apart: bool,
    /// LCP solves / enumeration fallbacks / failures (rigid law).
    pub lcp_solves: usize,
    /// Steps where Lemke failed but enumeration succeeded.
    pub lcp_enumeration_fallbacks: usize,
    /// Steps whose LCP failed or whose solution failed the post-solve checks.
    pub lcp_failures: usize,
    /// Newton failures (compliance laws).
    pub newton_failures: usize,
    /// Closure steps (compliance laws).
    pub closure_steps: usize,
    /// Time-step adequacy of the compliance law.
    pub time_step_advice: Option<TimeStepAdvice>,
    /// The observers' tables at the history steps — `bearings`, `restrainers`, `joint_slip`, the
    /// substructures', `segment_forces` —,
    /// recorded or derived from the histories when asked for ([`Self::tables`]).
    pub table_sources: Vec<super::table::TableSource>,
}

impl BridgeSolution {
    /// Number of kept times (rows of the histories).
    pub fn rows(&self) -> usize {
        self.t.len()
    }

    /// `q` at kept time `r` (laid out by [`Self::dofs`]: `x_j, y_j, θ_j` per segment) \[m, rad\].
    pub fn q_row(&self, r: usize) -> &[Real] {
        let n = self.dofs.len();
        &self.q[n * r..n * (r + 1)]
    }

    /// The rows of `q`, one per kept time.
    pub fn q_rows(&self) -> std::slice::ChunksExact<'_, Real> {
        self.q.chunks_exact(self.dofs.len())
    }

    /// The rows of `u`, one per kept time.
    pub fn u_rows(&self) -> std::slice::ChunksExact<'_, Real> {
        self.u.chunks_exact(self.dofs.len())
    }

    /// `u` at kept time `r` \[m/s, rad/s\].
    pub fn u_row(&self, r: usize) -> &[Real] {
        let n = self.dofs.len();
        &self.u[n * r..n * (r + 1)]
    }

    /// The joints' end gaps at kept time `r` (two per joint) \[m\].
    pub fn end_gaps_row(&self, r: usize) -> &[Real] {
        let n = 2 * self.n_segments.saturating_sub(1);
        &self.end_gaps[n * r..n * (r + 1)]
    }

    /// The joints' end forces at kept time `r` (two per joint; empty for rigid contact) \[N\].
    pub fn contact_force_row(&self, r: usize) -> &[Real] {
        let n = 2 * self.n_segments.saturating_sub(1);
        self.contact_force.get(n * r..n * (r + 1)).unwrap_or(&[])
    }

    /// The observers' tables ([`super::table::Table`]; written as `<name>.csv`), in order:
    /// `bearings` (derived here from `q` and the recorded plastic displacements of yielding
    /// bearings), `restrainers`, `joint_slip`, with piers, backwalls or shear keys `piers`,
    /// `backwalls`, `shear_keys`, and last `segment_forces` (every force on each segment).
    pub fn tables(&self) -> Vec<super::table::Table> {
        self.table_sources
            .iter()
            .map(|s| s.table(&self.t, &self.q, &self.dofs))
            .collect()
    }

    /// Impacting contacts at the abutments.
    pub fn abutment_impacting_contacts(&self) -> usize {
        self.impacts
            .iter()
            .filter(|r| matches!(r.contact, SimContact::Abutment { .. }))
            .count()
    }
}
