//! Model options added for the compliance-law comparison (issue 7): straight rectangular decks,
//! translational dashpot damping, and the joint's contact law.
//!
//! Kept apart from [`super::model`] so that the curved-deck model stays untouched.
#![allow(clippy::needless_range_loop)]

use super::SimError;
use crate::contact_law::ContactLaw;
use crate::math::{Real, Vector};

/// How the decks are damped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DampingModel {
    /// Rayleigh damping per deck, `C_j = a_0 M_j + a_1 K_j`, ratio `ζ` at the deck's two lowest
    /// distinct natural frequencies (the default).
    #[default]
    Rayleigh,
    /// Viscous dashpots from each deck's centroid to the ground in x and y (none in rotation):
    /// `c_j = 2 ζ m_j ω_j` with `ω_j = √(K_j,yy / m_j)` the deck's translational frequency
    /// (`c = 2ζ m 2π/T`, the damping of the OpenSees 1-D benchmark).
    TranslationalDashpots,
}

/// The normal contact law of the joint.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum JointContact {
    /// Rigid contact: the velocity-level Newton impact law with Coulomb friction solved as an LCP
    /// (the default; [`super::simulate`]'s Moreau–Jean scheme).
    #[default]
    Rigid,
    /// A compliance law ([`crate::contact_law`]) shared by the joint's two corner contacts
    /// ([`crate::contact_law::sharing`]), with regularised Coulomb friction
    /// ([`super::compliance`]).
    Compliance(ComplianceContact),
}

/// A compliance contact of the joint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ComplianceContact {
    /// The law of the joint as a whole (each of the 2 corner contacts carries half of it).
    pub law: ContactLaw,
    /// Regularisation velocity `v_r > 0` of the friction law
    /// `f_T = −μ f_N γ_T / √(γ_T² + v_r²)` \[m/s\]. Default 1e-3.
    pub friction_velocity: Real,
}

impl ComplianceContact {
    /// The law with the default friction regularisation velocity 1e-3 m/s.
    pub fn new(law: ContactLaw) -> Self {
        Self {
            law,
            friction_velocity: 1e-3,
        }
    }
}

impl super::SimModel {
    /// The four end-face corners of deck `j ∈ {1, 2}` relative to its joint-face midpoint (the
    /// default bearing points): `[joint c0, joint c1, far c0, far c1]`, for the curved decks of
    /// `arrangement` or the deck [`super::SimModel::shapes`].
    pub fn deck_corner_points(&self, j: usize) -> [Vector; 4] {
        match &self.shapes {
            Some(sh) => super::shape_corner_points(&sh[j - 1], j),
            None => super::end_corner_points(&self.arrangement, j),
        }
    }

    pub(crate) fn validate_options(&self) -> Result<(), SimError> {
        let JointContact::Compliance(c) = &self.contact else {
            return Ok(());
        };
        if self.abutments.iter().any(Option::is_some) {
            return Err(SimError::argument(
                "contact_law",
                "abutments ([abutments]) are only supported with rigid contact \
                         ([contact] law = \"rigid\")",
            ));
        }
        {
            let v = c.friction_velocity;
            if !(v.is_finite() && v > 0.0) {
                return Err(SimError::invalid(
                    "friction_velocity",
                    v,
                    "must be finite and > 0",
                ));
            }
        }
        Ok(())
    }
}

/// `(C_j, a_0, a_1)` of one deck (segment) for the damping model (`a_0`, `a_1` the Rayleigh
/// coefficients; zero for dashpots).
pub(crate) fn damping_block(
    model: DampingModel,
    zeta: Real,
    mj: &nalgebra::Matrix3<Real>,
    kj: &nalgebra::Matrix3<Real>,
    a0: Real,
    a1: Real,
) -> (nalgebra::Matrix3<Real>, Real, Real) {
    match model {
        DampingModel::Rayleigh => (mj * a0 + kj * a1, a0, a1),
        DampingModel::TranslationalDashpots => {
            let m = mj[(0, 0)];
            let c = 2.0 * zeta * m * (kj[(1, 1)] / m).max(0.0).sqrt();
            (
                nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(c, c, 0.0)),
                0.0,
                0.0,
            )
        }
    }
}

/// Largest estimated memory of one run that front ends accept (4 GiB), see [`run_memory_bytes`].
pub const MAX_RUN_MEMORY_BYTES: u64 = 4 << 30;

/// Bytes per time step held for the whole run: the ground acceleration sampled at every step
/// ([`crate::ground_motion::GroundMotion::sample_uniform`]: one [`Vector`], plus the two
/// per-component [`Real`] samples alive while it is built).
pub const GROUND_BYTES_PER_STEP: u64 =
    (std::mem::size_of::<Vector>() + 2 * std::mem::size_of::<Real>()) as u64;

/// Bytes per kept row of the `history.csv` text a front end builds in memory before writing it
/// atomically: at most 31 columns of at most 25 bytes (a shortest round-trip token such as
/// `-1.2345678901234567e-100` and its separator).
pub const HISTORY_TEXT_BYTES_PER_ROW: u64 = 31 * 25;

/// Number of rows a run's histories keep for `n_steps` steps at `history_stride`: steps
/// `0, s, 2s, …` and the last one, `⌊n/s⌋ + 1` plus 1 when `s` does not divide `n`.
pub fn history_rows(n_steps: usize, history_stride: usize) -> u64 {
    let s = history_stride.max(1) as u64;
    let n = n_steps as u64;
    (n / s).saturating_add(1 + u64::from(!n.is_multiple_of(s)))
}

/// Bytes per kept history row of a bridge of `n_segments` segments (`J = N − 1` joints): the
/// driver's trace (`t`, `q` and `u` of `3N` each, four candidate gaps, two end gaps, a slip and
/// two end forces per joint, two abutment gaps, the energies) and the observers' tables
/// (`bearings`: four values per bearing, counted for [`ESTIMATED_BEARINGS`] per segment;
/// `restrainers`: two per restrainer, counted for two per joint; `joint_slip`: one per joint;
/// `segment_forces`: three per member kind and segment, shear keys included; a time each; the substructures' coordinates and tables — `piers`, `backwalls`,
/// `shear_keys` — counted as if every joint had a pier and both ends a backwall and keys),
/// counted twice (a growing vector may hold twice its length), and the text of
/// the largest file, built and written one at a time (`history.csv`: at most `11 + 6N + 3J`
/// columns, at least the two-deck file's 31; `bearings.csv`: `1 + 4 b N`; `segment_forces.csv`:
/// `1 + 15 N`), 25 bytes a column.
pub fn history_row_bytes(size: impl Into<RunSize>) -> u64 {
    let size = size.into();
    let n = size.segments.max(1) as u64;
    let j = n - 1;
    let b = size.bearings as u64;
    let real = std::mem::size_of::<Real>() as u64;
    let forces = super::observer::values_per_row(size.segments.max(1), true) as u64;
    // the observers' tables, values per kept row, one term per table: the times of `bearings`,
    // `restrainers`, `joint_slip` and `segment_forces` (4); `bearings` (4 per bearing); 5 per
    // joint: its slip and two restrainers' elongation and force; `segment_forces`
    let tables = 4 + 4 * b + 5 * j + forces;
    // substructures, counted as if every joint had a pier and both ends a backwall and keys:
    // a cap's q and u (4) and `piers` (4) per joint; a wall's q and u (2) and `backwalls` (3)
    // and a key pair's `shear_keys` (2) per end; the three tables' times
    let substructure = 8 * j + 2 * (2 + 3 + 2) + 3;
    let trace = real * (1 + 6 * n + 9 * j + 2 + tables + substructure)
        + std::mem::size_of::<super::Energy>() as u64;
    let columns = (11 + 6 * n + 3 * j).max(31).max(1 + 4 * b).max(1 + forces);
    (2 * trace).saturating_add(columns.saturating_mul(25))
}

/// Bearings per segment assumed by [`history_row_bytes`] when only the number of segments is
/// given (four corner bearings, the default).
pub const ESTIMATED_BEARINGS: u64 = 4;

/// The size of a run's bridge for the memory estimate: its bodies (segments, and pier caps
/// counted as segments) and its bearings. A bare `usize` is that many segments with
/// [`ESTIMATED_BEARINGS`] each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunSize {
    /// Segments (pier caps counted as segments).
    pub segments: usize,
    /// Bearings of the whole bridge.
    pub bearings: usize,
}

impl From<usize> for RunSize {
    fn from(segments: usize) -> Self {
        RunSize {
            segments,
            bearings: segments.saturating_mul(ESTIMATED_BEARINGS as usize),
        }
    }
}

/// Estimated peak memory \[bytes\] of a run of a bridge of `n_segments` segments (the two-deck
/// model is `n_segments = 2`) over `n_steps` steps keeping every `history_stride`-th step: the
/// ground motion's samples and the kept rows of [`history_row_bytes`]. Impact records (one per
/// impact, not bounded by the step count) and allocator slack are not counted.
pub fn run_memory_bytes(n_steps: usize, history_stride: usize, size: impl Into<RunSize>) -> u64 {
    (n_steps as u64)
        .saturating_add(1)
        .saturating_mul(GROUND_BYTES_PER_STEP)
        .saturating_add(
            history_rows(n_steps, history_stride).saturating_mul(history_row_bytes(size)),
        )
}

/// The estimated memory of several runs held at once (a comparison keeps every law's history
/// until it writes): each `(n_steps, history_stride, n_segments)` by
/// [`run_memory_bytes`]. An error message (naming the limit and the ways around it) when
/// the sum exceeds [`MAX_RUN_MEMORY_BYTES`].
pub fn check_runs_memory(runs: &[(usize, usize, usize)]) -> Result<u64, String> {
    let bytes = runs_memory_bytes(runs);
    if bytes <= MAX_RUN_MEMORY_BYTES {
        return Ok(bytes);
    }
    let gib = |b: u64| b as Real / (1u64 << 30) as Real;
    Err(format!(
        "run too large: the {} runs need an estimated {:.1} GiB of memory even keeping only the \
         first and last step of each, more than the limit {:.0} GiB: shorten [time] duration, \
         compare fewer laws or use a larger --dt",
        runs.len(),
        gib(bytes),
        gib(MAX_RUN_MEMORY_BYTES)
    ))
}

fn runs_memory_bytes(runs: &[(usize, usize, usize)]) -> u64 {
    runs.iter().fold(0u64, |acc, &(n, s, segs)| {
        acc.saturating_add(run_memory_bytes(n, s, segs))
    })
}

/// The history stride of runs held at once (`(n_steps, n_segments)` each, all kept at one
/// stride): `from` when they fit in [`MAX_RUN_MEMORY_BYTES`], else the smallest larger stride
/// that fits; the error of [`check_runs_memory`] when even the first and last steps do not.
pub fn runs_history_stride(runs: &[(usize, usize)], from: usize) -> Result<usize, String> {
    let at = |s: usize| -> Vec<(usize, usize, usize)> {
        runs.iter().map(|&(n, segs)| (n, s, segs)).collect()
    };
    let fits = |s: usize| runs_memory_bytes(&at(s)) <= MAX_RUN_MEMORY_BYTES;
    let from = from.max(1);
    if fits(from) {
        return Ok(from);
    }
    let longest = runs.iter().map(|r| r.0).max().unwrap_or(1);
    match smallest_stride(longest, fits) {
        Some(s) => Ok(s.max(from)),
        None => check_runs_memory(&at(longest.max(1))).map(|_| longest.max(1)),
    }
}

/// The smallest history stride whose [`run_memory_bytes`] is at most
/// [`MAX_RUN_MEMORY_BYTES`] (`None` if even keeping only the first and last step is too much;
/// the estimate does not increase with the stride).
pub fn min_history_stride(n_steps: usize, size: impl Into<RunSize>) -> Option<usize> {
    let size = size.into();
    smallest_stride(n_steps, |s| {
        run_memory_bytes(n_steps, s, size) <= MAX_RUN_MEMORY_BYTES
    })
}

/// The smallest stride in `1..=n_steps` for which `ok` holds, `ok` being monotone (false then
/// true as the stride grows): bisection. `None` if even the largest fails.
fn smallest_stride(n_steps: usize, ok: impl Fn(usize) -> bool) -> Option<usize> {
    let hi = n_steps.max(1);
    if !ok(hi) {
        return None;
    }
    let (mut lo, mut hi) = (1usize, hi);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if ok(mid) { hi = mid } else { lo = mid + 1 }
    }
    Some(lo)
}

impl super::SimSettings {
    /// Refuses a run of `duration` seconds whose [`run_memory_bytes`] exceeds
    /// [`MAX_RUN_MEMORY_BYTES`] (an error naming `history_stride` with the smallest stride that
    /// fits); also refuses what [`super::SimSettings::step_count`] refuses. Returns the estimate.
    pub fn check_memory(&self, duration: Real, n_segments: usize) -> Result<u64, SimError> {
        let n = self.step_count(duration)?;
        let bytes = run_memory_bytes(n, self.history_stride, n_segments);
        if bytes <= MAX_RUN_MEMORY_BYTES {
            return Ok(bytes);
        }
        let gib = |b: u64| b as Real / (1u64 << 30) as Real;
        let advice = match min_history_stride(n, n_segments) {
            Some(s) => format!("keep fewer history rows: a history stride of at least {s}"),
            None => "shorten the run or use a larger dt".to_string(),
        };
        Err(SimError::invalid(
            super::param::Setting::HistoryStride,
            self.history_stride as Real,
            &format!(
                "a run of {n} steps keeping every {}-th step needs an estimated {:.1} GiB, more \
                 than the limit {:.0} GiB; {advice}",
                self.history_stride,
                gib(bytes),
                gib(MAX_RUN_MEMORY_BYTES)
            ),
        ))
    }
}
