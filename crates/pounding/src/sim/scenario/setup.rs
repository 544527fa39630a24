//! A built scenario of either form, ready to run: the two-deck model's (`[decks]` …) or a
//! bridge's (`[[segment]]` …). Both run as a bridge to the one [`BridgeSolution`]; the form only
//! decides the files' [`Layout`] and the two-deck summary's own keys. Front ends hold a [`Setup`]
//! and never branch on the form to run or to write.

use super::{BridgeSetup, Scenario, ScenarioError, SimSetup};
use crate::ground_motion::GroundMotion;
use crate::math::Real;
use crate::sim::bridge::{BridgeModel, BridgeSolution};
use crate::sim::output::{self, History, Layout, RunWarning};
use crate::sim::{Problem, SimError, SimSettings};
use std::borrow::Cow;

/// A scenario built for one run.
#[derive(Debug, Clone)]
pub enum Setup {
    /// The two-deck model (the bridge of two segments [`BridgeModel::from_pair`]).
    TwoDecks(Box<SimSetup>),
    /// A bridge of `[[segment]]`s.
    Bridge(Box<BridgeSetup>),
}

impl Scenario {
    /// Builds the scenario in its form ([`Scenario::is_bridge`]): [`Scenario::build_bridge`] or
    /// [`Scenario::build`].
    pub fn build_setup(&self) -> Result<Setup, ScenarioError> {
        Ok(if self.is_bridge() {
            Setup::Bridge(Box::new(self.build_bridge()?))
        } else {
            Setup::TwoDecks(Box::new(self.build()?))
        })
    }
}

impl Setup {
    /// The run's settings.
    pub fn settings(&self) -> &SimSettings {
        match self {
            Setup::TwoDecks(s) => &s.settings,
            Setup::Bridge(s) => &s.settings,
        }
    }

    /// The run's settings, to change (progress callback, …).
    pub fn settings_mut(&mut self) -> &mut SimSettings {
        match self {
            Setup::TwoDecks(s) => &mut s.settings,
            Setup::Bridge(s) => &mut s.settings,
        }
    }

    /// The names of the records it runs (`[y, x]`, `"none"` for an absent component).
    pub fn records_mut(&mut self) -> &mut [String; 2] {
        match self {
            Setup::TwoDecks(s) => &mut s.records,
            Setup::Bridge(s) => &mut s.records,
        }
    }

    /// Whether the abutment of each side (the two-deck model: of each deck) is present.
    pub fn abutments(&self) -> [bool; 2] {
        match self {
            Setup::TwoDecks(s) => s.problem.model.abutments.map(|a| a.is_some()),
            Setup::Bridge(s) => s.problem.model.abutments.map(|a| a.is_some()),
        }
    }

    /// Runs it with its settings ([`crate::sim::simulate`]).
    pub fn run(&self) -> Result<BridgeSolution, SimError> {
        crate::sim::simulate(self, self.settings())
    }

    /// `history.csv` of a run of it.
    pub fn history<'a>(&'a self, sol: &'a BridgeSolution) -> History<'a> {
        History::new(self.layout(), sol, self.ground(), self.abutments())
    }

    /// `impacts.csv` of a run of it, as a typed table ([`output::impacts_table`]).
    pub fn impacts(&self, sol: &BridgeSolution) -> crate::sim::table::TypedTable {
        output::impacts_table(self.layout(), &self.model(), sol)
    }

    /// The text of `impacts.csv` of a run of it.
    pub fn impacts_csv(&self, sol: &BridgeSolution) -> String {
        output::impacts_csv(self.layout(), &self.model(), sol)
    }

    /// The warnings of a run of it about its impacts ([`output::run_warnings`]).
    pub fn run_warnings(&self, sol: &BridgeSolution) -> Vec<RunWarning> {
        output::run_warnings(self.layout(), sol)
    }

    /// `trajectories.json` of a run of it (the plan animation's data).
    pub fn trajectories_json(&self, sol: &BridgeSolution) -> String {
        output::trajectories_json(&self.model(), self.ground(), sol)
    }

    /// The rigid law's peak-force estimates of a run of it, by site (`None` when no contact site
    /// is rigid; [`output::peak_force_estimates`]): the largest is `summary.json`'s
    /// `peak_force_estimate_n`.
    pub fn peak_force_estimates(
        &self,
        sol: &BridgeSolution,
    ) -> Option<std::collections::BTreeMap<output::SiteKey, output::PeakEstimate>> {
        output::setup_estimates(self, sol)
    }

    /// `summary.json` of a run of it, as written.
    pub fn summary_json_text(&self, sol: &BridgeSolution) -> String {
        match self {
            Setup::TwoDecks(s) => output::pair_summary_json_text(s, sol),
            Setup::Bridge(s) => output::bridge_summary_json_text(s, sol),
        }
    }

    /// `summary.json` as a value (its text is [`Setup::summary_json_text`]); callers that add
    /// a key (the code check of a run) write it with [`crate::output::json_text`].
    pub fn summary_json_value(&self, sol: &BridgeSolution) -> serde_json::Value {
        match self {
            Setup::TwoDecks(s) => output::pair_summary_json(s, sol),
            Setup::Bridge(s) => output::bridge_summary_json(s, sol),
        }
    }
}

/// Delegates to the problem of its form (a batch over a setup runs its problem).
impl Problem for Setup {
    fn model(&self) -> Cow<'_, BridgeModel> {
        match self {
            Setup::TwoDecks(s) => s.problem.model(),
            Setup::Bridge(s) => s.problem.model(),
        }
    }
    fn ground(&self) -> &GroundMotion {
        match self {
            Setup::TwoDecks(s) => &s.problem.ground,
            Setup::Bridge(s) => &s.problem.ground,
        }
    }
    fn supports(&self) -> &crate::sim::excitation::SupportExcitation {
        match self {
            Setup::TwoDecks(s) => s.problem.supports(),
            Setup::Bridge(s) => s.problem.supports(),
        }
    }
    fn initial(&self) -> (&[Real], &[Real]) {
        match self {
            Setup::TwoDecks(s) => s.problem.initial(),
            Setup::Bridge(s) => s.problem.initial(),
        }
    }
    fn check_model(&self) -> Result<(), SimError> {
        match self {
            Setup::TwoDecks(s) => s.problem.check_model(),
            Setup::Bridge(s) => s.problem.check_model(),
        }
    }
    fn check_initial(&self) -> Result<(), SimError> {
        match self {
            Setup::TwoDecks(s) => s.problem.check_initial(),
            Setup::Bridge(s) => s.problem.check_initial(),
        }
    }
    fn with_ground(&self, ground: GroundMotion) -> Self {
        let mut out = self.clone();
        match &mut out {
            Setup::TwoDecks(s) => s.problem.ground = ground,
            Setup::Bridge(s) => s.problem.ground = ground,
        }
        out
    }
    fn with_motion(
        &self,
        ground: GroundMotion,
        supports: crate::sim::excitation::SupportExcitation,
    ) -> Result<Self, SimError> {
        Ok(match self {
            Setup::TwoDecks(s) => {
                s.problem.with_motion(ground, supports)?;
                unreachable!("a two-deck problem refuses")
            }
            Setup::Bridge(s) => {
                let mut out = s.clone();
                out.problem = out.problem.with_motion(ground, supports)?;
                Setup::Bridge(out)
            }
        })
    }
    fn layout(&self) -> Layout {
        match self {
            Setup::TwoDecks(_) => Layout::TwoDecks,
            Setup::Bridge(_) => Layout::Bridge,
        }
    }
}
