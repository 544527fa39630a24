//! Exterior shear keys: the pair of keys that stops a deck end moving transversely across its
//! abutment or bent cap, each a gap followed by an elastic–perfectly-plastic spring (OpenSees
//! `ElasticPPGap` with `eta = 0`).
//!
//! # Sign convention
//! The deformation `v` is the deck end's transverse displacement relative to the support
//! (metres, either sign); the force `F` is the force the keys exert on the *support* side, so
//! the restoring force on the deck is `−F` (like a linear spring `F = k v`). The key on the
//! positive side is met at `v = +gap`, the one on the negative side at `v = −gap`.
//!
//! # One symmetric element, two independent keys
//! [`ShearKey`] is the two keys in parallel, each with its own state: the positive key is the
//! [`Restrainer`] law (an `ElasticPPGap` with positive gap and yield force) driven by `v`, the
//! negative key the same law driven by `−v`:
//! ```text
//! F(v) = F₊(v) − F₋(−v),     dF/dv = K₊ + K₋,     E = E₊ + E₋,     D = D₊ + D₋
//! ```
//! which is OpenSees `uniaxialMaterial Parallel` of `ElasticPPGap k fy gap 0 [damage]` and
//! `ElasticPPGap k −fy −gap 0 [damage]` (the tests compare OpenSees 3.7.1 on cyclic paths).
//! A key that has yielded keeps its plastic deformation as extra gap ([`SlackGrowth::Permanent`],
//! OpenSees `damage`), or follows OpenSees' default re-centering ([`SlackGrowth::Recentering`],
//! `noDamage`; see that variant for its step dependence). Within a step the two keys cannot
//! both carry force (one needs `v > 0`, the other `v < 0`).
//!
//! No degrading or failing backbone (a key that breaks off after its capacity, e.g. Megally et
//! al. 2002): the force stays at `fy` however far the key is pushed.

use super::restrainer::{Restrainer, RestrainerResponse, RestrainerState, SlackGrowth};
use super::{ElementError, non_negative, positive};
use crate::math::Real;

const SHEAR_KEY: &str = "shear key";

/// A symmetric pair of exterior shear keys: stiffness `k > 0` \[N/m\], yield force (capacity)
/// `fy > 0` \[N\] and gap `gap ≥ 0` \[m\] on each side, and the [`SlackGrowth`] rule after
/// yield.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearKey {
    side: Restrainer,
}

/// The two keys' states: the positive key's (elongation `v`) and the negative key's
/// (elongation `−v`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearKeyState {
    /// The key met at `v = +gap`, in its own coordinate `v`.
    pub positive: RestrainerState,
    /// The key met at `v = −gap`, in its own coordinate `−v` (its force is `≥ 0`, acting
    /// in `−v`).
    pub negative: RestrainerState,
}

impl ShearKeyState {
    /// The transverse deformation `v` \[m\].
    pub fn v(&self) -> Real {
        self.positive.e
    }
}

/// The result of [`ShearKey::response`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearKeyResponse {
    /// Force on the support side `F = F₊ − F₋` \[N\].
    pub force: Real,
    /// Tangent `dF/dv` \[N/m\].
    pub tangent: Real,
    /// The trial state; becomes the committed state when the step is accepted.
    pub trial: ShearKeyState,
    /// Plastic dissipation of the step (both keys) `≥ 0` \[J\].
    pub dissipation: Real,
    /// Whether either key carries a positive force.
    pub engaged: bool,
}

impl ShearKey {
    /// Validates `k > 0`, `fy > 0`, `gap ≥ 0` (finite); errors name the key (`k`, `fy`, `gap`).
    pub fn new(k: Real, fy: Real, gap: Real, growth: SlackGrowth) -> Result<Self, ElementError> {
        let k = positive(SHEAR_KEY, "k", k)?;
        let fy = positive(SHEAR_KEY, "fy", fy)?;
        let gap = non_negative(SHEAR_KEY, "gap", gap)?;
        Ok(ShearKey {
            side: Restrainer::new(k, gap, Some(fy), growth)?,
        })
    }

    /// Stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.side.k()
    }

    /// Yield force `fy` \[N\].
    pub fn fy(&self) -> Real {
        self.side.fy().unwrap_or(Real::INFINITY)
    }

    /// Initial gap on each side \[m\].
    pub fn gap(&self) -> Real {
        self.side.slack()
    }

    /// The slack growth rule after yield.
    pub fn growth(&self) -> SlackGrowth {
        self.side.growth()
    }

    /// The law of one key in its own coordinate (the positive key's at `v`, the negative
    /// key's at `−v`).
    pub fn side(&self) -> &Restrainer {
        &self.side
    }

    /// The virgin state at `v = 0`.
    pub fn initial_state(&self) -> ShearKeyState {
        let s = self.side.initial_state();
        ShearKeyState {
            positive: s,
            negative: s,
        }
    }

    /// Force, tangent, trial state and dissipation at deformation `v` from the committed state
    /// (pure; commit by storing `trial`).
    pub fn response(&self, v: Real, committed: &ShearKeyState) -> ShearKeyResponse {
        let p: RestrainerResponse = self.side.response(v, &committed.positive);
        let n: RestrainerResponse = self.side.response(-v, &committed.negative);
        ShearKeyResponse {
            force: p.force - n.force,
            tangent: p.tangent + n.tangent,
            trial: ShearKeyState {
                positive: p.trial,
                negative: n.trial,
            },
            dissipation: p.dissipation + n.dissipation,
            engaged: p.engaged || n.engaged,
        }
    }

    /// Stored (elastic) energy of both keys at a state \[J\].
    pub fn stored_energy(&self, state: &ShearKeyState) -> Real {
        self.side.stored_energy(&state.positive) + self.side.stored_energy(&state.negative)
    }
}

/// A shear-key pair as a driver holds it: the law, the committed state and the accumulated
/// plastic dissipation.
pub type ShearKeyElement = super::Held<ShearKey>;

uniaxial_law!(ShearKey, ShearKeyState, ShearKeyResponse);
