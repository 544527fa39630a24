//! A built scenario of either form, ready to run: one bridge run ([`BridgeSetup`]) and the
//! [`Form`] its file was written in. A two-deck file (`[decks]` …) is expanded into its bridge of
//! two segments ([`BridgeModel::from_pair`]) when it is built, as a solver expands user sugar into
//! its general form; what is left of the form is how the files name things ([`Layout`]) and the
//! two-deck summary's own keys. Front ends hold a [`Setup`] and never branch on the form to run.

use super::{BridgeSetup, Scenario, ScenarioError, SimSetup};
use crate::ground_motion::GroundMotion;
use crate::math::Real;
use crate::sim::bridge::{BridgeModel, BridgeProblem, BridgeSolution};
use crate::sim::output::{self, History, Layout, RunWarning};
use crate::sim::{Problem, SimError, SimModel, SimSettings};
use std::borrow::Cow;

/// A scenario built for one run: the bridge that runs and the form of the file it came from.
#[derive(Debug, Clone)]
pub struct Setup {
    /// The run: the bridge (a two-deck file: its bridge of two segments), its ground motion,
    /// settings and records.
    pub run: BridgeSetup,
    /// The scenario's form.
    pub form: Form,
}

/// The form of a scenario file: it decides only how the run's files name things.
#[derive(Debug, Clone)]
pub enum Form {
    /// A bridge of `[[segment]]`s.
    Bridge,
    /// The two-deck model (`[decks]`, `[joint]`, `[bearings]`, `[abutments]`): its parameters as
    /// given, for the keys of its `summary.json` (`mass_kg`, `shape`, `bearings`, …) and its
    /// figures.
    TwoDecks(Box<SimModel>),
}

impl Form {
    /// The two-deck model's parameters (`None` for a bridge file).
    pub fn two_decks(&self) -> Option<&SimModel> {
        match self {
            Form::TwoDecks(m) => Some(m),
            Form::Bridge => None,
        }
    }
}

impl Setup {
    /// The run of a two-deck file: its bridge of two segments ([`BridgeModel::from_pair`]) with
    /// the same ground motion, initial state, settings and records.
    pub fn of_two_decks(s: SimSetup) -> Self {
        let p = s.problem;
        let problem = BridgeProblem {
            q0: p.q0.to_vec(),
            u0: p.u0.to_vec(),
            ..BridgeProblem::at_rest(BridgeModel::from_pair(&p.model), p.ground)
        };
        Setup {
            run: BridgeSetup {
                problem,
                settings: s.settings,
                records: s.records,
                units: s.units,
            },
            form: Form::TwoDecks(Box::new(p.model)),
        }
    }

    /// The run of a bridge file.
    pub fn of_bridge(run: BridgeSetup) -> Self {
        Setup {
            run,
            form: Form::Bridge,
        }
    }
}

impl Scenario {
    /// Builds the scenario in its form ([`Scenario::is_bridge`]): [`Scenario::build_bridge`] or
    /// [`Scenario::build`], expanded into the one run.
    pub fn build_setup(&self) -> Result<Setup, ScenarioError> {
        Ok(if self.is_bridge() {
            Setup::of_bridge(self.build_bridge()?)
        } else {
            Setup::of_two_decks(self.build()?)
        })
    }
}

impl Setup {
    /// The run's settings.
    pub fn settings(&self) -> &SimSettings {
        &self.run.settings
    }

    /// The run's settings, to change (progress callback, …).
    pub fn settings_mut(&mut self) -> &mut SimSettings {
        &mut self.run.settings
    }

    /// The names of the records it runs (`[y, x]`, `"none"` for an absent component).
    pub fn records_mut(&mut self) -> &mut [String; 2] {
        &mut self.run.records
    }

    /// Whether the abutment of each side (the two-deck model: of each deck) is present.
    pub fn abutments(&self) -> [bool; 2] {
        self.run
            .problem
            .model
            .abutments
            .each_ref()
            .map(Option::is_some)
    }

    /// Runs it with its settings ([`crate::sim::simulate`]).
    pub fn run(&self) -> Result<BridgeSolution, SimError> {
        self.run.run()
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
        output::impacts_csv(self.layout(), &self.run.problem.model, sol)
    }

    /// The warnings of a run of it about its impacts ([`output::run_warnings`]).
    pub fn run_warnings(&self, sol: &BridgeSolution) -> Vec<RunWarning> {
        output::run_warnings(self.layout(), sol)
    }

    /// `trajectories.json` of a run of it (the plan animation's data).
    pub fn trajectories_json(&self, sol: &BridgeSolution) -> String {
        output::trajectories_json(&self.run.problem.model, self.ground(), sol)
    }

    /// The rigid law's peak-force estimates of a run of it, by site (`None` when no contact site
    /// is rigid; [`output::peak_force_estimates`]): the largest is `summary.json`'s
    /// `peak_force_estimate_n`.
    pub fn peak_force_estimates(
        &self,
        sol: &BridgeSolution,
    ) -> Option<std::collections::BTreeMap<output::SiteKey, output::PeakEstimate>> {
        output::setup_estimates(&self.run.problem.model, sol)
    }

    /// `summary.json` of a run of it, as written.
    pub fn summary_json_text(&self, sol: &BridgeSolution) -> String {
        let mut v = self.summary_json_value(sol);
        crate::output::json_without_negative_zero(&mut v);
        let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
        s.push('\n');
        s
    }

    /// `summary.json` as a value (its text is [`Setup::summary_json_text`]); callers that add
    /// a key (the code check of a run) write it with [`crate::output::json_text`].
    pub fn summary_json_value(&self, sol: &BridgeSolution) -> serde_json::Value {
        match &self.form {
            Form::TwoDecks(m) => output::pair_summary_json(&self.run, m, sol),
            Form::Bridge => output::bridge_summary_json(&self.run, Layout::Bridge, sol),
        }
    }
}

/// The bridge that runs; the two-deck form refuses a motion per support.
impl Problem for Setup {
    fn model(&self) -> Cow<'_, BridgeModel> {
        self.run.problem.model()
    }
    fn ground(&self) -> &GroundMotion {
        &self.run.problem.ground
    }
    fn supports(&self) -> &crate::sim::excitation::SupportExcitation {
        &self.run.problem.supports
    }
    fn initial(&self) -> (&[Real], &[Real]) {
        self.run.problem.initial()
    }
    fn check_model(&self) -> Result<(), SimError> {
        match &self.form {
            // the preset's own names (R1, beta2, …) in its errors
            Form::TwoDecks(m) => m.check().map(|_| ()),
            Form::Bridge => self.run.problem.check_model(),
        }
    }
    fn check_initial(&self) -> Result<(), SimError> {
        self.run.problem.check_initial()
    }
    fn with_ground(&self, ground: GroundMotion) -> Self {
        let mut out = self.clone();
        out.run.problem.ground = ground;
        out
    }
    fn with_motion(
        &self,
        ground: GroundMotion,
        supports: crate::sim::excitation::SupportExcitation,
    ) -> Result<Self, SimError> {
        if self.form.two_decks().is_some() {
            return Err(crate::sim::problem::two_deck_supports_error());
        }
        let mut out = self.clone();
        out.run.problem = out.run.problem.with_motion(ground, supports)?;
        Ok(out)
    }
    fn layout(&self) -> Layout {
        match self.form {
            Form::TwoDecks(_) => Layout::TwoDecks,
            Form::Bridge => Layout::Bridge,
        }
    }
}
