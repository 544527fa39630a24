//! The scenario of a `simulate` run: a TOML file (every key optional, defaults in
//! [`DEFAULT_SCENARIO_TOML`]) read into a [`Scenario`], which [`Scenario::build`] turns into a
//! validated [`SimSetup`] (the [`SimProblem`] and [`SimSettings`] of [`crate::sim::simulate`]).
//!
//! ```no_run
//! use pounding::sim::scenario::Scenario;
//! let setup = Scenario::load("bridge.toml".as_ref())?.with_law("hertz-damp").build()?;
//! let sol = pounding::sim::simulate(&setup.problem, &setup.settings)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Errors are [`ScenarioError`]s that name the file, the `[section] key` (typed, [`ParamKey`])
//! and the line that sets the bad value, or say that the default applies. Ground-motion record
//! paths are relative to the scenario file; `builtin:ELC180` / `builtin:ELC270` are the embedded
//! El Centro 1940 components.

mod bridge;
mod build;
mod contact;
mod error;
mod forms;
mod ground;
mod model_keys;
mod sections;
mod setup;
mod site_contact;
mod supports;

pub use bridge::BridgeSetup;
pub use contact::{
    DEFAULT_A, DEFAULT_DELTA_M, DEFAULT_K, DEFAULT_MIN_VELOCITY, LAW_NAMES, contact_keys,
    default_k_h,
};
pub use error::{Key, KeyRef, ParamKey, ScenarioError, Section};
pub use sections::DEFAULT_SCENARIO_TOML;
pub use setup::{Form, Setup};

use super::{SimProblem, SimSettings};
use crate::ground_motion::AccelUnits;
use crate::math::Real;
use std::path::{Path, PathBuf};

/// Where a scenario came from: its name in messages, its text (to locate keys) and the directory
/// that relative record paths start from.
#[derive(Debug, Clone)]
struct Src {
    origin: String,
    text: String,
    dir: PathBuf,
    /// The built-in default scenario (messages name its values as defaults, not by line).
    builtin: bool,
    /// Keys replaced on the command line, with their flags (`--dt`, `--duration`).
    flags: Vec<(ParamKey, &'static str)>,
}

impl Src {
    /// Where `key` is set (or that it is not), or the flag that replaces it.
    fn at(&self, key: ParamKey) -> KeyRef {
        let mut r = KeyRef::locate(key, &self.origin, &self.text);
        r.flag = self.flags.iter().find(|(k, _)| *k == key).map(|(_, f)| *f);
        r
    }
    /// Whether the file sets `key`.
    fn is_set(&self, key: ParamKey) -> bool {
        self.at(key).line.is_some()
    }
    /// An out-of-range value of `key`.
    fn invalid(&self, message: String, key: ParamKey) -> ScenarioError {
        ScenarioError::Invalid {
            message,
            at: vec![self.at(key)],
            note: String::new(),
        }
    }
    /// A message that names `keys` itself.
    fn key_error(&self, message: String, keys: &[ParamKey]) -> ScenarioError {
        ScenarioError::Key {
            message,
            at: keys.iter().map(|&k| self.at(k)).collect(),
        }
    }
}

/// A `simulate` scenario as read (not yet validated), with the overrides a front end may apply
/// before [`Scenario::build`].
#[derive(Debug, Clone)]
pub struct Scenario {
    src: Src,
    raw: sections::Raw,
    law: Option<String>,
    compared: Option<Vec<String>>,
    /// The law was replaced on the command line (`--law`): contact keys its law does not read
    /// are not used, not refused.
    law_replaced: bool,
    record: Option<(PathBuf, Option<AccelUnits>)>,
    record_dt: Option<Real>,
    scale: Option<Real>,
    batch: bool,
    /// A bridge of `[[segment]]`s (then `raw` holds only its `[ground_motion]`, `[time]` and
    /// `[contact]`).
    bridge: Option<Box<bridge::BridgeRaw>>,
}

/// A validated run of a problem `P`: everything [`crate::sim::simulate`] needs, and what the
/// writers of [`crate::sim::output`] report about the input. Either form has one
/// ([`SimSetup`]: the two-deck preset, [`BridgeSetup`]: a bridge of `[[segment]]`s).
#[derive(Debug, Clone)]
pub struct RunSetup<P> {
    /// The model, the ground motion and the (rest) initial state.
    pub problem: P,
    /// Step size, duration, history stride.
    pub settings: SimSettings,
    /// The ground-motion specifications as given (`summary.json`'s `record_y`, `record_x`):
    /// the scenario's values, the `--record` path and `none`, or `batch` and `none`.
    pub records: [String; 2],
    /// Units of `.csv` records (`[ground_motion] csv_units`).
    pub units: AccelUnits,
}

impl<P: super::Problem> RunSetup<P> {
    /// Runs it ([`crate::sim::simulate`]).
    pub fn run(&self) -> Result<super::bridge::BridgeSolution, super::SimError> {
        super::simulate(&self.problem, &self.settings)
    }
}

/// The run of a two-deck scenario.
pub type SimSetup = RunSetup<SimProblem>;

impl Default for Scenario {
    /// The built-in default ([`DEFAULT_SCENARIO_TOML`], named `built-in default` in messages).
    fn default() -> Self {
        let mut sc = Self::from_toml(DEFAULT_SCENARIO_TOML, "built-in default")
            .expect("the built-in default scenario is valid TOML (tested)");
        sc.src.builtin = true;
        sc
    }
}

impl Scenario {
    /// Reads a scenario from TOML `text`; `origin` names it in error messages. Relative record
    /// paths start from the current directory (see [`Scenario::with_base_dir`]).
    ///
    /// Errors: syntax, unknown keys, wrong types and sections written as arrays
    /// ([`ScenarioError::Syntax`]). Values are checked by [`Scenario::build`].
    pub fn from_toml(text: &str, origin: &str) -> Result<Self, ScenarioError> {
        let syntax = |e: toml::de::Error| ScenarioError::Syntax {
            origin: origin.to_string(),
            // a 400 KB offending line is not echoed whole
            message: crate::input::shorten_lines(&e.to_string(), 200),
        };
        let table = toml::from_str::<toml::Table>(text).map_err(syntax)?;
        forms::refuse_mixed(text, &table, origin)?;
        let is_bridge = table.contains_key("segment");
        let (raw, bridge) = if is_bridge {
            let b: bridge::BridgeRaw = toml::from_str(text).map_err(syntax)?;
            let raw = sections::Raw {
                ground_motion: b.ground_motion.clone(),
                time: b.time.clone(),
                contact: b.contact.clone(),
                ..Default::default()
            };
            (raw, Some(Box::new(b)))
        } else {
            (toml::from_str(text).map_err(syntax)?, None)
        };
        Ok(Self {
            src: Src {
                origin: origin.to_string(),
                text: text.to_string(),
                dir: PathBuf::from("."),
                builtin: false,
                flags: Vec::new(),
            },
            raw,
            law: None,
            compared: None,
            law_replaced: false,
            record: None,
            record_dt: None,
            scale: None,
            batch: false,
            bridge,
        })
    }

    /// Reads the scenario file `path` (within [`crate::input::SCENARIO_LIMIT`]); record paths are
    /// relative to its directory.
    pub fn load(path: &Path) -> Result<Self, ScenarioError> {
        let text = crate::input::read_text(path, "scenario file", crate::input::SCENARIO_LIMIT)
            .map_err(|e| ScenarioError::Read {
                path: path.display().to_string(),
                message: e.to_string(),
            })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(Self::from_toml(&text, &path.display().to_string())?.with_base_dir(dir))
    }

    /// Relative record paths start from `dir` (an empty path means the current directory).
    pub fn with_base_dir(mut self, dir: PathBuf) -> Self {
        self.src.dir = if dir.as_os_str().is_empty() {
            PathBuf::from(".")
        } else {
            dir
        };
        self
    }

    /// Replaces `[contact] law` by `law` (`rigid` or a law of the registry,
    /// [`crate::contact_law::registry::law_names`]; an unknown name is refused by
    /// [`Scenario::build`]); the other `[contact]` keys and their defaults still apply.
    pub fn with_law(mut self, law: &str) -> Self {
        self.law = Some(law.to_string());
        self
    }

    /// Replaces the contact law at every site by `law` as a command-line override (`pounding
    /// simulate --law`): like [`Scenario::with_law`], but `[contact]` and site keys that `law`
    /// does not read are not used instead of refused (the front end says so); unknown keys and
    /// bad values are still errors.
    pub fn with_law_replacing(mut self, law: &str) -> Self {
        self.law_replaced = true;
        self.with_law(law)
    }

    /// Declares that this scenario is run with each of `laws` in turn (`pounding compare`, with
    /// [`Scenario::with_law`] per run): a given `[contact]` key is then refused only when none
    /// of `laws` reads it, since one section serves them all (see
    /// [`Scenario::check_contact_keys`]).
    pub fn with_compared_laws<S: AsRef<str>>(mut self, laws: &[S]) -> Self {
        self.compared = Some(laws.iter().map(|l| l.as_ref().to_string()).collect());
        self
    }

    /// Refuses a `[contact]` key that would be ignored: one that the law of the run
    /// ([`Scenario::law`]) does not read with the other keys given (e.g. `k` with `law =
    /// "hertz"`, `chi` with `law = "hertz-damp"` and `zeta`, any key with `law = "rigid"`), or,
    /// after [`Scenario::with_compared_laws`], one that no compared law reads. The error
    /// ([`ScenarioError::Key`]) names the key and its line and the keys the law reads.
    /// [`Scenario::build`] calls it; the laws' keys are those of
    /// [`crate::contact_law::registry::LawEntry::reads`].
    pub fn check_contact_keys(&self) -> Result<(), ScenarioError> {
        if self.law_replaced {
            return Ok(());
        }
        let (laws, compared): (Vec<&str>, bool) = match &self.compared {
            Some(list) => (list.iter().map(String::as_str).collect(), true),
            None => (vec![self.law()], false),
        };
        contact::check_contact_keys(
            &self.src,
            &self.raw.contact,
            &laws,
            compared.then_some("the compared laws"),
        )
    }

    /// Uses the record file `path` (PEER `.AT2`, or `.csv` in `units`, by default the scenario's
    /// `csv_units`) as the only ground-motion component, along `y`, instead of the scenario's
    /// records (`pounding simulate --record`).
    pub fn with_record(mut self, path: &Path, units: Option<AccelUnits>) -> Self {
        self.record = Some((path.to_path_buf(), units));
        self
    }

    /// Multiplies both ground-motion scale factors by `s` (`pounding simulate --scale`; must be
    /// finite).
    pub fn with_scale(mut self, s: Real) -> Self {
        self.scale = Some(s);
        self
    }

    /// Replaces `[time] dt` by `dt` (`pounding simulate --dt`); errors about it then name the
    /// flag. Checked by [`Scenario::build`] / [`Scenario::build_bridge`] like the key.
    pub fn with_dt(mut self, dt: Real) -> Self {
        self.raw.time.0.dt = dt;
        self.with_flag(model_keys::time("dt"), "--dt")
    }

    /// The one check of a time step `dt` given on the command line as `--dt`
    /// ([`SimSettings::check_dt`]), said as `simulate --dt` says it (`invalid dt = 0: must be
    /// finite and > 0 — set by --dt (command line, in place of `[time] dt`)`), before any
    /// scenario is built (`pounding compare --dt`).
    pub fn check_dt_flag(dt: Real) -> Result<(), ScenarioError> {
        let src = Src {
            origin: String::new(),
            text: String::new(),
            dir: PathBuf::new(),
            builtin: false,
            flags: vec![(model_keys::time("dt"), "--dt")],
        };
        SimSettings::check_dt(dt).map_err(|e| build::sim_error(&src, e))
    }

    /// Turns on the position projection of the rigid sites (`[time] projection = true`,
    /// `pounding simulate --projection`; [`crate::sim::projection`]).
    pub fn with_projection(mut self) -> Self {
        self.raw.time.0.projection = true;
        self.with_flag(model_keys::time("projection"), "--projection")
    }

    /// Replaces `[time] duration` by `duration` \[s\] (`pounding simulate --duration`).
    pub fn with_duration(mut self, duration: Real) -> Self {
        self.raw.time.0.duration = Some(duration);
        self.with_flag(model_keys::time("duration"), "--duration")
    }

    /// Errors about `key` name the command-line `flag` that replaced it (e.g. after
    /// [`Scenario::with_law`] from `--law`).
    pub fn with_flag(mut self, key: ParamKey, flag: &'static str) -> Self {
        self.src.flags.push((key, flag));
        self
    }

    /// Names the replacements as the keyword arguments of a Python call (`dt=`, `duration=`,
    /// `law=`, …) instead of the command-line flags (`--dt`, …): messages then say "set by the
    /// `dt=` argument (in place of `[time] dt`)". Call it after the replacements.
    pub fn with_keyword_flags(mut self) -> Self {
        for (_, f) in &mut self.src.flags {
            *f = match *f {
                "--dt" => "dt=",
                "--duration" => "duration=",
                "--scale" => "scale=",
                "--law" => "law=",
                "--record" => "record=",
                "--record-dt" => "record_dt=",
                "--csv-units" => "csv_units=",
                "--projection" => "projection=",
                other => other,
            };
        }
        self
    }

    /// The base problem of a batch: no records are loaded (each run brings its own, see
    /// [`crate::sim::batch`]) and a missing `duration` means each record's length.
    pub fn for_batch(mut self) -> Self {
        self.batch = true;
        self
    }

    /// The scenario's name in messages.
    pub fn origin(&self) -> &str {
        &self.src.origin
    }

    /// The scenario's TOML text as read.
    pub fn text(&self) -> &str {
        &self.src.text
    }

    /// The contact law that [`Scenario::build`] will use: the override, else `[contact] law`,
    /// else `rigid`.
    pub fn law(&self) -> &str {
        self.law
            .as_deref()
            .or(self.raw.contact.law.as_deref())
            .unwrap_or("rigid")
    }

    /// Where `key` is set in this scenario (file and line), or that the default applies.
    pub fn key_ref(&self, key: ParamKey) -> KeyRef {
        self.src.at(key)
    }

    /// Validates every value and builds the run (nothing is simulated). Errors name the file,
    /// key and line ([`ScenarioError`]).
    pub fn build(&self) -> Result<SimSetup, ScenarioError> {
        if self.bridge.is_some() {
            return Err(ScenarioError::Key {
                message: format!(
                    "{} describes a bridge of [[segment]]s: this command runs the two-deck model \
                     ([decks], [joint], [bearings]) only",
                    self.src.origin
                ),
                at: Vec::new(),
            });
        }
        build::build(self)
    }

    /// `true` when the file describes a bridge of `[[segment]]`s ([`Scenario::build_bridge`]).
    pub fn is_bridge(&self) -> bool {
        self.bridge.is_some()
    }

    /// The bridge of a `[[segment]]` scenario, validated (errors name `segment[i].key` and its
    /// line); an error for a two-deck scenario.
    pub fn build_bridge(&self) -> Result<BridgeSetup, ScenarioError> {
        match &self.bridge {
            Some(b) => bridge::build(self, b),
            None => Err(ScenarioError::Key {
                message: format!(
                    "{} has no [[segment]] tables: it is a two-deck scenario",
                    self.src.origin
                ),
                at: Vec::new(),
            }),
        }
    }
}
