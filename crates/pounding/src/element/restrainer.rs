//! Cable restrainers: tension-only springs with slack and an optional yield force
//! (OpenSees `ElasticPPGap` with a positive gap and `eta = 0`).
//!
//! The element is one-dimensional in the elongation `e` (current cable length minus its
//! reference length, metres; negative when the two anchor points come closer). The driver maps
//! the anchor points to `e` and the scalar force to the two bodies along the cable.

use super::{ElementError, non_negative, positive};
use crate::math::Real;

const RESTRAINER: &str = "restrainer";

/// What happens to the slack after the cable has yielded (OpenSees' `damage` flag).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SlackGrowth {
    /// The yielded elongation is permanent: the slack only grows (OpenSees `ElasticPPGap …
    /// damage`). A yielded steel cable stays longer; the default here.
    #[default]
    Permanent,
    /// OpenSees' default (`noDamage`): when the committed elongation falls below the current
    /// slack but stays above the initial one, the slack is reset to that elongation
    /// ("re-centering"), so the permanent elongation is recovered at zero force. As in OpenSees
    /// the reset happens only at commits whose elongation lies strictly between the initial
    /// and the current slack, so how much is recovered depends on the step (a step that jumps
    /// below the initial slack recovers nothing).
    Recentering,
}

/// Restrainer parameters: stiffness `k > 0` \[N/m\], slack `s ≥ 0` \[m\], optional yield force
/// `fy > 0` \[N\] and the [`SlackGrowth`] rule.
///
/// # Model (OpenSees `ElasticPPGap E=k Fy=fy gap=s eta=0`)
/// With the state's current slack `s_c` (initially `s`) and yield elongation `e_y,c`
/// (initially `s + fy/k`; `+∞` without yield), the force at elongation `e` is
/// ```text
/// e > e_y,c:          F = fy,            tangent 0,   then s ← e − fy/k, e_y ← e   (yielding)
/// e < s_c:            F = 0,             tangent 0    (slack; Recentering: s ← e, e_y ← e + fy/k
///                                                      if s < e, s the initial slack)
/// s_c ≤ e ≤ e_y,c:    F = k (e − s_c),   tangent k
/// ```
/// Stored energy `E = F²/(2k)` (`½ k (e − s)²` while elastic and taut); plastic dissipation of a
/// yielding step `D = fy · Δs ≥ 0` (the slack grows by the plastic elongation), zero otherwise.
/// Without `fy` the law is elastic: `F = k max(e − s, 0)`, `D = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restrainer {
    k: Real,
    slack: Real,
    fy: Option<Real>,
    growth: SlackGrowth,
}

/// A restrainer's state: the elongation, the force, the current slack and yield elongation
/// (OpenSees' `commitStrain`, `commitStress`, `minElasticYieldStrain`, `maxElasticYieldStrain`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestrainerState {
    /// Elongation `e` \[m\].
    pub e: Real,
    /// Force `F ≥ 0` \[N\] (tension).
    pub force: Real,
    /// Current slack `s_c` \[m\]: the elongation at which the cable becomes taut.
    pub slack: Real,
    /// Current yield elongation `e_y,c = s_c + fy/k` \[m\] (`+∞` without yield).
    pub yield_elongation: Real,
}

/// The result of [`Restrainer::response`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestrainerResponse {
    /// Tension force `F ≥ 0` \[N\].
    pub force: Real,
    /// Tangent `dF/de` \[N/m\]: `k` while taut and elastic (also at `e = s_c`), else 0.
    pub tangent: Real,
    /// The trial state; becomes the committed state when the step is accepted.
    pub trial: RestrainerState,
    /// Plastic dissipation of the step `fy · Δs ≥ 0` \[J\].
    pub dissipation: Real,
    /// Whether the cable carries a positive force.
    pub engaged: bool,
}

impl Restrainer {
    /// Validates `k > 0`, `slack ≥ 0` (finite) and `fy > 0` (finite) if given; errors name the
    /// key (`k`, `slack`, `fy`).
    pub fn new(
        k: Real,
        slack: Real,
        fy: Option<Real>,
        growth: SlackGrowth,
    ) -> Result<Self, ElementError> {
        let k = positive(RESTRAINER, "k", k)?;
        let slack = non_negative(RESTRAINER, "slack", slack)?;
        let fy = match fy {
            Some(f) => Some(positive(RESTRAINER, "fy", f)?),
            None => None,
        };
        Ok(Restrainer {
            k,
            slack,
            fy,
            growth,
        })
    }

    /// Stiffness `k` \[N/m\].
    pub fn k(&self) -> Real {
        self.k
    }

    /// Initial slack `s` \[m\].
    pub fn slack(&self) -> Real {
        self.slack
    }

    /// Yield force, if any \[N\].
    pub fn fy(&self) -> Option<Real> {
        self.fy
    }

    /// The slack growth rule.
    pub fn growth(&self) -> SlackGrowth {
        self.growth
    }

    /// The virgin state at zero elongation.
    pub fn initial_state(&self) -> RestrainerState {
        RestrainerState {
            e: 0.0,
            force: 0.0,
            slack: self.slack,
            yield_elongation: self.yield_from(self.slack),
        }
    }

    fn yield_from(&self, slack: Real) -> Real {
        match self.fy {
            Some(fy) => slack + fy / self.k,
            None => Real::INFINITY,
        }
    }

    /// Force, tangent, trial state and dissipation at elongation `e` from the committed state
    /// (pure; commit by storing `trial`).
    pub fn response(&self, e: Real, committed: &RestrainerState) -> RestrainerResponse {
        let mut trial = RestrainerState { e, ..*committed };
        let (force, tangent, dissipation);
        if e > committed.yield_elongation {
            let fy = self.fy.unwrap_or(Real::INFINITY);
            force = fy;
            tangent = 0.0;
            trial.slack = e - fy / self.k;
            trial.yield_elongation = e;
            dissipation = (fy * (trial.slack - committed.slack)).max(0.0);
        } else if e < committed.slack {
            force = 0.0;
            tangent = 0.0;
            dissipation = 0.0;
            if self.growth == SlackGrowth::Recentering && e > self.slack {
                trial.slack = e;
                trial.yield_elongation = self.yield_from(e);
            }
        } else {
            force = self.k * (e - committed.slack);
            tangent = self.k;
            dissipation = 0.0;
        }
        trial.force = force;
        RestrainerResponse {
            force,
            tangent,
            trial,
            dissipation,
            engaged: force > 0.0,
        }
    }

    /// Stored (elastic) energy `F²/(2k)` at a state \[J\].
    pub fn stored_energy(&self, state: &RestrainerState) -> Real {
        0.5 * state.force * state.force / self.k
    }
}

/// A restrainer as a driver holds it: the law, the committed state, the accumulated
/// dissipation and the number of engagements (episodes of positive force).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestrainerElement {
    law: Restrainer,
    committed: RestrainerState,
    dissipated: Real,
    engagements: usize,
    peak_force: Real,
}

impl RestrainerElement {
    /// A virgin restrainer at zero elongation.
    pub fn new(law: Restrainer) -> Self {
        RestrainerElement {
            law,
            committed: law.initial_state(),
            dissipated: 0.0,
            engagements: 0,
            peak_force: 0.0,
        }
    }

    /// The law.
    pub fn law(&self) -> &Restrainer {
        &self.law
    }

    /// The committed state.
    pub fn committed(&self) -> &RestrainerState {
        &self.committed
    }

    /// Trial response at elongation `e` (pure).
    pub fn trial(&self, e: Real) -> RestrainerResponse {
        self.law.response(e, &self.committed)
    }

    /// Accepts a trial response computed from the current committed state: stores its state,
    /// adds its dissipation, counts a new engagement when the force becomes positive and
    /// tracks the peak force.
    pub fn commit(&mut self, response: &RestrainerResponse) {
        if response.engaged && self.committed.force <= 0.0 {
            self.engagements += 1;
        }
        self.peak_force = self.peak_force.max(response.force);
        self.committed = response.trial;
        self.dissipated += response.dissipation;
    }

    /// Whether the committed force is positive.
    pub fn engaged(&self) -> bool {
        self.committed.force > 0.0
    }

    /// Episodes of positive force so far.
    pub fn engagements(&self) -> usize {
        self.engagements
    }

    /// Largest committed force so far \[N\].
    pub fn peak_force(&self) -> Real {
        self.peak_force
    }

    /// Stored energy at the committed state \[J\].
    pub fn stored_energy(&self) -> Real {
        self.law.stored_energy(&self.committed)
    }

    /// Plastic dissipation accumulated over the committed steps \[J\].
    pub fn dissipated(&self) -> Real {
        self.dissipated
    }
}
