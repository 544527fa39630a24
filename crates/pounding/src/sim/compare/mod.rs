//! `compare`: one scenario run under several contact laws, side by side (the CLI's `pounding
//! compare`, Python's `pounding.compare`).
//!
//! [`CompareFlags::check`] checks the law list and the time step; [`Comparison::prepare`] builds
//! one [`Setup`] per law from the scenario exactly as `simulate` does (same validation; the law
//! replaces `[contact] law`, on a bridge the law at every joint and abutment, and a `[contact]`
//! key is refused only when no compared law reads it, [`Scenario::with_compared_laws`]) and
//! fits the history sampling of all runs into memory; [`Comparison::run`] runs them in turn.
//! The two-deck model runs every law or none (a law it refuses is an error); a bridge skips a
//! law it refuses, with the reason, unless it refuses every law. The files are written by
//! [`crate::sim::output::compare_tables`]; [`agreement`] answers "do the laws
//! agree?" in a few sentences.

mod agree;

pub use agree::{Agreement, Headline, agreement, headline};

use super::output::{InputWarning, PeakEstimate, SiteKey, input_warnings, warnings_message};
use super::scenario::{Form, Scenario, ScenarioError, Setup};
use super::{Problem, Progress, SimStatus};
use crate::math::Real;
use crate::sim::bridge::BridgeSolution;
use std::collections::BTreeMap;
use std::time::Instant;

/// The laws `compare` runs when none are given (`rigid` and the five compliance laws of the
/// first release).
pub const DEFAULT_LAWS: &[&str] = &super::scenario::LAW_NAMES;

/// Why a comparison cannot run. Nothing has been run or written. The messages name the CLI's
/// flags (`--laws`, `--dt`), as the Python front end's do.
#[derive(Debug, thiserror::Error)]
pub enum CompareError {
    /// A name of `--laws` that is not a registered law.
    #[error("unknown contact law {law:?} in --laws: use one of {known}")]
    UnknownLaw {
        /// The name given.
        law: String,
        /// The registered names, comma separated.
        known: String,
    },
    /// A law given twice.
    #[error("contact law {0:?} is given twice in --laws")]
    Twice(String),
    /// No law.
    #[error("--laws is empty")]
    Empty,
    /// The scenario (a `[contact]` key no compared law reads, …).
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// The two-deck model refuses a law (the message with its causes).
    #[error("contact law {law:?}: {message}")]
    Law {
        /// The law.
        law: String,
        /// Why (the scenario error and its causes, `: `-separated).
        message: String,
    },
    /// A bridge refuses every law: the first law's reason.
    #[error("no law of --laws can run on this bridge: {0}")]
    NoLaw(String),
    /// Too many steps, or the histories of all runs do not fit in memory.
    #[error("{0}")]
    Size(String),
    /// Every law refused for one reason that is not the laws' (a flag or the scenario).
    #[error("{0}")]
    Input(String),
    /// A law of the two-deck model failed to run (`law "x": reason`).
    #[error("{0}")]
    Run(String),
}

/// An error and its causes, `: `-separated (as the CLI prints an error chain).
fn chain(e: &dyn std::error::Error) -> String {
    let mut s = e.to_string();
    let mut src = e.source();
    while let Some(c) = src {
        s.push_str(": ");
        s.push_str(&c.to_string());
        src = c.source();
    }
    s
}

/// The command-line choices of a comparison (the other flags of `simulate` change the scenario).
#[derive(Debug, Clone, Default)]
pub struct CompareFlags {
    /// The laws, as given (names are trimmed; empty: an error).
    pub laws: Vec<String>,
    /// The time step of every law (`--dt`).
    pub dt: Option<Real>,
    /// The multiplier of the scenario's ground-motion scales (`--scale`).
    pub scale: Option<Real>,
    /// The simulated duration (`--duration`).
    pub duration: Option<Real>,
}

impl CompareFlags {
    /// The law list checked (every name registered, none twice, not empty; names trimmed), then
    /// `dt` (finite and > 0). The scale and duration are checked with the scenario.
    pub fn check(&self) -> Result<Vec<String>, CompareError> {
        let names = crate::contact_law::registry::law_names();
        let mut laws: Vec<String> = Vec::new();
        for l in &self.laws {
            let l = l.trim().to_string();
            if !names.contains(&l.as_str()) {
                return Err(CompareError::UnknownLaw {
                    law: l,
                    known: names.join(", "),
                });
            }
            if laws.contains(&l) {
                return Err(CompareError::Twice(l));
            }
            laws.push(l);
        }
        if laws.is_empty() {
            return Err(CompareError::Empty);
        }
        if let Some(dt) = self.dt {
            Scenario::check_dt_flag(dt)?;
        }
        Ok(laws)
    }

    /// `base` with the flags' replacements (checked when the setups are built).
    fn apply(&self, mut base: Scenario) -> Scenario {
        if let Some(dt) = self.dt {
            // the scenario's own checks (step within the run, step count, restrainers) apply
            base = base.with_dt(dt);
        }
        if let Some(x) = self.scale {
            base = base.with_scale(x);
        }
        if let Some(d) = self.duration {
            base = base.with_duration(d);
        }
        base
    }
}

/// A comparison ready to run: the laws and each law's validated setup, or (a bridge) why the
/// law cannot run on it.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The laws, in the order given.
    pub laws: Vec<String>,
    /// Each law's setup, or the reason a bridge refuses it.
    pub setups: Vec<Result<Setup, String>>,
    /// Whether the scenario is a bridge of `[[segment]]`s.
    pub bridge: bool,
    /// The history stride of every run (a sample per 0.5 ms for the overlay plots, or coarser to
    /// fit every run's history in memory together).
    pub history_stride: usize,
    /// Whether [`Self::history_stride`] is coarser than a sample per 0.5 ms (memory).
    pub stride_coarsened: bool,
}

/// A law's run.
#[derive(Debug, Clone)]
pub struct Ran {
    /// The setup that ran (either form: it names the files' parts).
    pub setup: Setup,
    /// The solution (whatever its status).
    pub sol: BridgeSolution,
    /// Wall time of the run \[s\].
    pub seconds: f64,
    /// The run's warnings: its input's ([`input_warnings`]: an implausible record PGA, a step
    /// longer than the record's, a step too coarse for the law), then energy created at
    /// contacts in one sentence ([`warnings_message`]).
    pub warnings: Vec<LawWarning>,
    /// The rigid law's peak-force estimates by site (`None` for a compliance law, which
    /// computes its force).
    pub estimates: Option<BTreeMap<SiteKey, PeakEstimate>>,
}

/// A warning of one law's run.
#[derive(Debug, Clone, PartialEq)]
pub struct LawWarning {
    /// `record_pga_implausible`, `time_step_beyond_record`, `time_step_coarse` (the input's,
    /// [`InputWarning::kind`]) or `energy_created` (the run's).
    pub kind: &'static str,
    /// The sentence.
    pub message: String,
}

impl Ran {
    /// The largest of [`Self::estimates`] (`None`: a compliance law, or no rigid impact).
    pub fn peak_estimate(&self) -> Option<PeakEstimate> {
        self.estimates
            .as_ref()
            .and_then(super::output::largest_estimate)
    }
}

/// One law of a comparison: its run, or why it was skipped (a bridge only).
#[derive(Debug, Clone)]
pub struct LawRun {
    /// The law.
    pub law: String,
    /// The run, or the reason the bridge refuses the law.
    pub outcome: Result<Ran, String>,
}

impl LawRun {
    /// The run, if the law ran.
    pub fn ran(&self) -> Option<&Ran> {
        self.outcome.as_ref().ok()
    }
}

/// The warnings of a run of `setup` (see [`Ran::warnings`]).
fn law_warnings(setup: &Setup, sol: &BridgeSolution) -> Vec<LawWarning> {
    let input: Vec<InputWarning> = input_warnings(
        setup.ground(),
        sol.dt,
        sol.time_step_advice.as_ref(),
        &sol.summary.segment_frequencies(),
    );
    let mut out: Vec<LawWarning> = input
        .into_iter()
        .map(|w| LawWarning {
            kind: w.kind,
            message: w.message,
        })
        .collect();
    if let Some(m) = warnings_message(&setup.run_warnings(sol)) {
        let m = m.strip_prefix("warning: ").unwrap_or(&m).to_string();
        out.push(LawWarning {
            kind: "energy_created",
            message: m,
        });
    }
    out
}

impl Comparison {
    /// Every law's validated setup: `base` with `flags` (checked by [`CompareFlags::check`]
    /// first) and the law, with the rules of `simulate` (a step no longer than the run, not too
    /// many steps) and the memory of all histories together within the limit. A `[contact]`
    /// key that no law reads is refused first. A law that cannot be built is an error for the
    /// two-deck model; on a bridge it is skipped with its reason (its sites may refuse it: a
    /// time step too coarse for its stiffness, a calibration it lacks), unless every law is.
    pub fn prepare(base: Scenario, flags: &CompareFlags) -> Result<Self, CompareError> {
        let laws = flags.check()?;
        let base = flags.apply(base);
        let bridge = base.is_bridge();
        let base = base.with_compared_laws(&laws);
        base.check_contact_keys()?;
        let mut setups = Vec::new();
        for l in &laws {
            setups.push(match base.clone().with_law(l).build_setup() {
                Ok(s) => Ok(s),
                Err(e) if bridge => Err(e.to_string()),
                Err(e) => {
                    return Err(CompareError::Law {
                        law: l.clone(),
                        message: chain(&e),
                    });
                }
            });
        }
        if let Some(Err(first)) = setups.first()
            && setups.iter().all(Result::is_err)
        {
            // every law refused for the same reason: it is not the laws' (a flag or the scenario,
            // e.g. --scale nan), so say it as itself
            if setups.iter().all(|s| s.as_ref().err() == Some(first)) && laws.len() > 1 {
                return Err(CompareError::Input(first.clone()));
            }
            return Err(CompareError::NoLaw(first.clone()));
        }
        let mut sizes = Vec::new();
        for s in setups.iter().flatten() {
            let d = s
                .settings()
                .duration
                .unwrap_or_else(|| s.ground().end_time());
            let n = match s.form {
                Form::TwoDecks(_) => s
                    .settings()
                    .step_count(d)
                    .map_err(|e| CompareError::Size(e.to_string()))?,
                Form::Bridge => s.settings().step_count(d).unwrap_or(usize::MAX),
            };
            sizes.push((n, s.model().segments.len()));
        }
        let dt = setups
            .iter()
            .flatten()
            .next()
            .map_or(1e-3, |s| s.settings().dt);
        let fine = plot_stride(dt);
        let stride =
            super::options::runs_history_stride(&sizes, fine).map_err(CompareError::Size)?;
        for s in setups.iter_mut().flatten() {
            s.settings_mut().history_stride = stride;
        }
        Ok(Self {
            laws,
            setups,
            bridge,
            history_stride: stride,
            stride_coarsened: stride > fine,
        })
    }

    /// The first setup that was built (its ground motion is every law's).
    pub fn first_setup(&self) -> Option<&Setup> {
        self.setups.iter().flatten().next()
    }

    /// Runs every law in turn; `progress` gives each run its progress observer, and `done` is
    /// called after each law (ran or skipped). A two-deck law that fails to run is an error once
    /// every law has run; a bridge's is a skipped law with the reason.
    pub fn run(
        &self,
        mut progress: impl FnMut() -> Progress,
        mut done: impl FnMut(&LawRun),
    ) -> Result<Vec<LawRun>, CompareError> {
        let mut runs = Vec::new();
        for (l, s) in self.laws.iter().zip(&self.setups) {
            let outcome = match s {
                Err(why) => Err(why.clone()),
                Ok(s) => {
                    let t = Instant::now();
                    let mut s = s.clone();
                    s.settings_mut().progress = progress();
                    match s.run() {
                        Ok(sol) => {
                            let seconds = t.elapsed().as_secs_f64();
                            s.settings_mut().progress = Progress::default();
                            Ok(Ran {
                                warnings: law_warnings(&s, &sol),
                                estimates: s.peak_force_estimates(&sol),
                                setup: s,
                                sol,
                                seconds,
                            })
                        }
                        Err(e) => Err(format!("law {l:?}: {e}")),
                    }
                }
            };
            let run = LawRun {
                law: l.clone(),
                outcome,
            };
            done(&run);
            runs.push(run);
        }
        if !self.bridge
            && let Some(Err(why)) = runs.iter().map(|r| &r.outcome).find(|o| o.is_err())
        {
            return Err(CompareError::Run(why.clone()));
        }
        Ok(runs)
    }
}

/// A history sample per 0.5 ms (the overlay plots).
pub fn plot_stride(dt: Real) -> usize {
    ((5e-4 / dt).floor() as usize).max(1)
}

/// The laws of `runs` that ran and did not complete, as `law (Status)`.
pub fn not_completed(runs: &[LawRun]) -> Vec<String> {
    runs.iter()
        .filter_map(|r| {
            let ran = r.ran()?;
            (ran.sol.status != SimStatus::Completed)
                .then(|| format!("{} ({:?})", r.law, ran.sol.status))
        })
        .collect()
}
