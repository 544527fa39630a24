//! Typed scenario keys and the errors of reading and building a `simulate` scenario.
//!
//! Every error that bad input can cause names where the value comes from: a [`KeyRef`] (file,
//! `[section] key`, line, or "not set; default") built from a typed [`ParamKey`], so that a front
//! end can point at the key without reading the message.

use crate::ground_motion::GroundMotionError;
use crate::sim::SimError;
use crate::toml_schema::line_of_key;
use std::fmt;

/// A section of a `simulate` scenario file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Section {
    /// `[decks]`: shape, dimensions, density or masses.
    Decks,
    /// `[joint]`: gap, seat length, friction, restitution.
    Joint,
    /// `[abutments]`: the optional rigid abutments.
    Abutments,
    /// `[bearings]`: stiffnesses, damping, custom points.
    Bearings,
    /// `[ground_motion]`: records, scales, incidence, csv units.
    GroundMotion,
    /// `[time]`: step, duration, history stride.
    Time,
    /// `[contact]`: the joint's contact law and its parameters.
    Contact,
}

impl Section {
    /// The section's name in the file (without brackets).
    pub fn name(self) -> &'static str {
        match self {
            Section::Decks => "decks",
            Section::Joint => "joint",
            Section::Abutments => "abutments",
            Section::Bearings => "bearings",
            Section::GroundMotion => "ground_motion",
            Section::Time => "time",
            Section::Contact => "contact",
        }
    }
}

/// One key of a scenario file: its section, its name as written in the file, and the deck it
/// concerns when it is a per-deck key (`mass1`, `stiffness2`, `gap1` of `[abutments]`, …) or a
/// shared key that failed for one deck (`width` of deck 2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct ParamKey {
    /// The section.
    pub section: Section,
    /// The key as written in the file.
    pub key: &'static str,
    /// The deck (1 or 2) the error concerns, if one.
    pub deck: Option<u8>,
}

impl ParamKey {
    /// A key of no particular deck.
    pub const fn new(section: Section, key: &'static str) -> Self {
        Self {
            section,
            key,
            deck: None,
        }
    }

    /// A key concerning deck `deck`.
    pub const fn of_deck(section: Section, key: &'static str, deck: u8) -> Self {
        Self {
            section,
            key,
            deck: Some(deck),
        }
    }

    /// The scenario key that sets the library parameter `name` of a [`SimError`] (as named by
    /// [`crate::sim::SimModel::validate`], [`crate::sim::SimSettings::validate`],
    /// [`crate::ground_motion::GroundMotion::validate`] and the deck geometry checks), or `None`
    /// for parameters that no scenario key sets. Deck masses (`mass (deck J)`) are not mapped
    /// here: they are set by `massJ` or by `density` (see the scenario's `build`).
    ///
    /// For callers that hold only a parameter's name: the scenario itself maps the typed path
    /// every error carries ([`crate::sim::param::ParamPath`], `GeometryError`'s `param`,
    /// `GroundMotionError`'s `param`), never a name read back from a message.
    pub fn of_model_parameter(name: &str) -> Option<ParamKey> {
        use Section::*;
        // "name (deck J[, bearing I])" → ("name", Some(J))
        let (base, deck) = match name.split_once(" (deck ") {
            Some((b, rest)) => (b, rest.chars().next().and_then(|c| c.to_digit(10))),
            None => (name, None),
        };
        let deck = deck.and_then(|d| u8::try_from(d).ok());
        let k = |section, key| Some(ParamKey { section, key, deck });
        let per_deck = |section, k1, k2| match deck {
            Some(1) => Some(ParamKey::of_deck(section, k1, 1)),
            Some(2) => Some(ParamKey::of_deck(section, k2, 2)),
            _ => None,
        };
        let of = |section, key, d| Some(ParamKey::of_deck(section, key, d));
        match base {
            "dt" => k(Time, "dt"),
            "duration" => k(Time, "duration"),
            "history_stride" => k(Time, "history_every"),
            "gap" => k(Joint, "gap"),
            "seat_length" => k(Joint, "seat_length"),
            "mu" => k(Joint, "mu"),
            "eps_n" => k(Joint, "eps_n"),
            "damping_ratio" => k(Bearings, "damping_ratio"),
            "R1" => of(Decks, "R1", 1),
            "R2" => of(Decks, "R2", 2),
            "beta1" => of(Decks, "beta1_deg", 1),
            "beta2" => of(Decks, "beta2_deg", 2),
            "L1" => of(Decks, "L1", 1),
            "L2" => of(Decks, "L2", 2),
            "skew1" => of(Decks, "skew_deg", 1),
            "skew2" => of(Decks, "skew_deg", 2),
            "width" | "joint face length" => k(Decks, "width"),
            "thickness" => k(Decks, "thickness"),
            "density" => k(Decks, "density"),
            "abutment gap" => per_deck(Abutments, "gap1", "gap2"),
            "abutment seat_length" => per_deck(Abutments, "seat_length1", "seat_length2"),
            "bearing stiffness" => per_deck(Bearings, "stiffness1", "stiffness2"),
            "bearing point" => per_deck(Bearings, "points1", "points2"),
            "scale_y" => k(GroundMotion, "scale_y"),
            "scale_x" => k(GroundMotion, "scale_x"),
            "incidence" => k(GroundMotion, "incidence_deg"),
            _ => None,
        }
    }

    /// The `[contact]` key of a contact-law parameter named `name` by
    /// [`crate::contact_law::ContactLawError`]: any key a registered law reads
    /// ([`crate::contact_law::registry::law_keys`]).
    pub fn of_contact_parameter(name: &str) -> Option<ParamKey> {
        crate::contact_law::registry::law_keys()
            .iter()
            .find(|&&k| k == name)
            .map(|&k| ParamKey::new(Section::Contact, k))
    }
}

impl fmt::Display for ParamKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`[{}] {}`", self.section.name(), self.key)
    }
}

/// The key a [`KeyRef`] points at: a key of the two-deck form's sections, or a key path of a
/// bridge scenario (`segment[2].L`, `joint1.contact.k`, `abutment.start.backwall.kmax`: array
/// indices 0-based, in the file's order).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Key {
    /// A `[section] key` of the two-deck form, `[ground_motion]`, `[time]` or `[contact]`.
    Param(ParamKey),
    /// A bridge scenario's key path.
    Path(String),
}

impl Key {
    /// The typed key, if it is one.
    pub fn param(&self) -> Option<ParamKey> {
        match self {
            Key::Param(k) => Some(*k),
            Key::Path(_) => None,
        }
    }
}

impl PartialEq<ParamKey> for Key {
    fn eq(&self, other: &ParamKey) -> bool {
        self.param() == Some(*other)
    }
}

impl fmt::Display for Key {
    /// "`[section] key`" or "`path`".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Key::Param(k) => k.fmt(f),
            Key::Path(p) => write!(f, "`{p}`"),
        }
    }
}

/// Where a key's value comes from: the file and line that set it, or the default.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KeyRef {
    /// The key.
    pub key: Key,
    /// The scenario's name in messages (its path, or `built-in default`).
    pub origin: String,
    /// 1-based line that sets the key, `None` when the file does not set it (the default applies).
    pub line: Option<usize>,
    /// The command-line flag that overrides the key (e.g. `--dt`), if any.
    pub flag: Option<&'static str>,
}

impl KeyRef {
    /// Locates `key` in the scenario `text` named `origin`.
    pub fn locate(key: ParamKey, origin: &str, text: &str) -> Self {
        Self {
            key: Key::Param(key),
            origin: origin.to_string(),
            line: line_of_key(text, key.section.name(), key.key),
            flag: None,
        }
    }

    /// A bridge scenario's key `path`, set at `line` of `origin` (`None`: not set; the default).
    pub fn path(path: String, origin: &str, line: Option<usize>) -> Self {
        Self {
            key: Key::Path(path),
            origin: origin.to_string(),
            line,
            flag: None,
        }
    }
}

impl fmt::Display for KeyRef {
    /// "`[section] key` (FILE:LINE)" or "`[section] key` (not set in FILE; default)".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(flag) = self.flag {
            // a keyword argument of a Python call (`dt=`, [`super::Scenario::with_keyword_flags`])
            if flag.ends_with('=') {
                return write!(f, "the `{flag}` argument (in place of {})", self.key);
            }
            return write!(f, "{flag} (command line, in place of {})", self.key);
        }
        match self.line {
            // the built-in scenario's lines are not a file the user has
            Some(_) if self.origin == "built-in default" => {
                write!(f, "{} (the built-in default)", self.key)
            }
            Some(l) => write!(f, "{} ({}:{l})", self.key, self.origin),
            None => write!(f, "{} (not set in {}; default)", self.key, self.origin),
        }
    }
}

/// Key references joined by " and ".
struct Joined<'a>(&'a [KeyRef]);

impl fmt::Display for Joined<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, k) in self.0.iter().enumerate() {
            if i > 0 {
                f.write_str(" and ")?;
            }
            write!(f, "{k}")?;
        }
        Ok(())
    }
}

/// Why a `simulate` scenario cannot be read or built. Nothing has been computed or written.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioError {
    /// The file cannot be read (missing, too large, not UTF-8, …).
    #[error("cannot read scenario file {path}: {message}")]
    Read {
        /// The path as given.
        path: String,
        /// The reason.
        message: String,
    },
    /// TOML syntax, an unknown key or a wrong type (the message names line and column).
    #[error("invalid scenario {origin}: {message}")]
    Syntax {
        /// The scenario's name.
        origin: String,
        /// The TOML reader's message.
        message: String,
    },
    /// A value is out of range: `message` says which and why, `at` which keys set it.
    #[error("{message} — set by {}{note}", Joined(at))]
    Invalid {
        /// What is wrong, e.g. `invalid gap = -1: must be >= 0`.
        message: String,
        /// The keys that set the value (at least one).
        at: Vec<KeyRef>,
        /// A remark after the keys (may be empty), e.g. where a default comes from.
        note: String,
    },
    /// A key is missing, misplaced or has an unknown name; the message names every key in `at`.
    #[error("{message}")]
    Key {
        /// The whole message (naming the keys).
        message: String,
        /// The keys concerned.
        at: Vec<KeyRef>,
    },
    /// A ground-motion record named by a scenario key cannot be read.
    #[error("ground-motion record given by {at}: {error}")]
    Record {
        /// The key that names the record.
        at: KeyRef,
        /// Why it cannot be read (names the file and line).
        error: Box<GroundMotionError>,
    },
    /// The record given instead of the scenario's ([`super::Scenario::with_record`]) cannot be read.
    #[error("--record {path}: {error}")]
    RecordOverride {
        /// The path as given.
        path: String,
        /// Why it cannot be read.
        error: Box<GroundMotionError>,
    },
    /// A scale multiplier ([`super::Scenario::with_scale`]) that is not finite.
    #[error("invalid --scale {0}: must be finite")]
    Scale(f64),
    /// A contact-law error of a parameter that no `[contact]` key sets.
    #[error(transparent)]
    Law(Box<crate::contact_law::ContactLawError>),
    /// A model error of a parameter that no scenario key sets.
    #[error(transparent)]
    Model(Box<SimError>),
}

impl ScenarioError {
    /// The typed keys the error points at (empty for errors of the file as a whole or of flags,
    /// and for a bridge's key paths: see [`ScenarioError::key_refs`]).
    pub fn keys(&self) -> Vec<ParamKey> {
        self.key_refs()
            .iter()
            .filter_map(|k| k.key.param())
            .collect()
    }

    /// Every key the error points at, with where it is set.
    pub fn key_refs(&self) -> &[KeyRef] {
        match self {
            ScenarioError::Invalid { at, .. } | ScenarioError::Key { at, .. } => at,
            ScenarioError::Record { at, .. } => std::slice::from_ref(at),
            _ => &[],
        }
    }
}
