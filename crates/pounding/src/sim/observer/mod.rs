//! Observers: what a run records besides its state, one [`Table`] each.
//!
//! The driver owns the loop; at every kept step (the `history.csv` rows) it hands each observer
//! a [`Snapshot`] of the committed state, and at the end it returns what each kept, in order: a
//! recorded table, or what its table is derived from when asked for ([`TableSource`]: the
//! bearings' table is a function of the kept `q` rows and of the yielding bearings' plastic
//! displacements, the only part recorded). A new
//! output is one type in a file of this folder implementing [`Observer`] and one line in
//! [`standard`] (`standard.rs`); the CLI and Python write or convert every table without knowing
//! it.
//!
//! The files, each importing only those below it: `observe.rs` (the [`Snapshot`], the
//! [`Observer`] trait, what a run keeps of each: [`TableSource`]), `bearings_table.rs` (the
//! derived [`BearingsTable`]), one file per kind of observer (`bearings.rs`, `members.rs`: the
//! restrainers, the joints' slip, the substructures; `segment_forces.rs`), and `standard.rs`, the
//! list.
//!
//! The standard observers of a bridge:
//! - [`BearingForces`](bearings::BearingForces) (`bearings.csv`): each bearing's deformation `u_b = (x − θ r_y, y + θ r_x)`
//!   (`r` its arm from the segment's centroid, the linearised rotation the stiffness `K` uses;
//!   minus the cap's `(x_c, y_c)` for a bearing on a pier) and the force it exerts on its segment, `f = −k u_b` for a linear bearing and
//!   `f = −(k₀ u_b − (1 − b) k₀ u_p)` for a bilinear one (`u_p` its committed plastic
//!   displacement);
//! - [`RestrainerForces`](members::RestrainerForces) (`restrainers.csv`): each restrainer's elongation
//!   `e = |P_b − P_a| − L₀` (exact anchor positions) and its committed tension;
//! - [`JointSlip`](members::JointSlip) (`joint_slip.csv`): each joint's tangential slip, as the two-deck
//!   `history.csv` reports it;
//! - [`PierColumns`](members::PierColumns) (`piers.csv`, only for a bridge with piers): each pier's cap displacement
//!   and its column's force on the cap (named `pier<k>` by the joint `k` it carries);
//! - [`Backwalls`](members::Backwalls) (`backwalls.csv`) and [`ShearKeys`](members::ShearKeys) (`shear_keys.csv`), for a bridge with
//!   them;
//! - [`SegmentForces`](segment_forces::SegmentForces) (`segment_forces.csv`, last): every force on each
//!   segment by member kind, as the integrator applies it over the steps (the load path; its
//!   sum is the segment's mass times its absolute acceleration).

mod bearings;
mod bearings_table;
mod members;
mod observe;
mod segment_forces;
mod standard;

pub use bearings_table::{BearingRecipe, BearingsTable};
pub use observe::TableSource;
pub(crate) use observe::{Observer, Snapshot};
pub(crate) use segment_forces::values_per_row;
pub(crate) use standard::standard;
