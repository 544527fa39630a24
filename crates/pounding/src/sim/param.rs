//! Typed parameter paths: which input a [`super::SimError`] concerns, so that a front end maps it
//! to its own key (a scenario's `[time] dt`, `segment[2].L` and its line) by matching a value,
//! never by reading the message back.
//!
//! The text of a path ([`ParamPath`]'s `Display`) is the error's `name`, as the messages have
//! always shown it: `dt`, `mass (deck 1)`, `bearing stiffness (deck 2, bearing 3)`,
//! `segment[0].fy`, `abutment.end.backwall.mass`.

use std::fmt;

/// Which abutment: the names of the two sides, `start` and `end`, in keys and files.
pub const ABUTMENT_SIDES: [&str; 2] = ["start", "end"];

/// A run setting of [`super::SimSettings`] that a scenario sets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Setting {
    /// The time step `dt`.
    Dt,
    /// The duration of the run.
    Duration,
    /// The history stride.
    HistoryStride,
}

impl Setting {
    /// The setting's name in errors (`dt`, `duration`, `history_stride`).
    pub const fn name(self) -> &'static str {
        match self {
            Self::Dt => "dt",
            Self::Duration => "duration",
            Self::HistoryStride => "history_stride",
        }
    }
}

/// A parameter of the two-deck model ([`super::SimModel`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TwoDeckParam {
    /// The joint gap.
    Gap,
    /// The seat length of every deck end.
    SeatLength,
    /// The joint's friction coefficient.
    Mu,
    /// The joint's restitution coefficient.
    EpsN,
    /// The bearings' damping ratio.
    DampingRatio,
    /// A deck's width (both decks share it).
    Width,
    /// A deck's joint face (skewed decks: the face's length).
    JointFace,
    /// A deck's mass.
    Mass,
    /// The gap of a deck's abutment.
    AbutmentGap,
    /// The seat length of a deck's abutment end.
    AbutmentSeat,
    /// A bearing's stiffness.
    BearingStiffness,
    /// A bearing's point.
    BearingPoint,
}

impl TwoDeckParam {
    /// The parameter's name in errors (before the deck and bearing).
    pub const fn name(self) -> &'static str {
        match self {
            Self::Gap => "gap",
            Self::SeatLength => "seat_length",
            Self::Mu => "mu",
            Self::EpsN => "eps_n",
            Self::DampingRatio => "damping_ratio",
            Self::Width => "width",
            Self::JointFace => "joint face length",
            Self::Mass => "mass",
            Self::AbutmentGap => "abutment gap",
            Self::AbutmentSeat => "abutment seat_length",
            Self::BearingStiffness => "bearing stiffness",
            Self::BearingPoint => "bearing point",
        }
    }
}

/// The table of a bridge parameter, as a bridge scenario writes it (0-based array indices).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BridgeTable {
    /// `[bridge]`.
    Bridge,
    /// `[[segment]]` number `i`.
    Segment(usize),
    /// `[[joint]]` number `k`.
    Joint(usize),
    /// `[abutment.start]` (0) or `[abutment.end]` (1).
    Abutment(usize),
    /// `[[pier]]` number `p`.
    Pier(usize),
}

/// A bridge parameter: its table and its key inside it (`fy`, `bearing[1].stiffness`,
/// `backwall.mass`); shown as `segment[0].fy`, `abutment.end.backwall.mass`, `bridge.damping`.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct BridgeKey {
    /// The table.
    pub table: BridgeTable,
    /// The key inside the table.
    pub key: String,
}

impl BridgeKey {
    /// `key` of `table`.
    pub fn new(table: BridgeTable, key: impl Into<String>) -> Self {
        Self {
            table,
            key: key.into(),
        }
    }

    /// The last part of the key (`stiffness` of `bearing[1].stiffness`).
    pub fn leaf(&self) -> &str {
        self.key.rsplit('.').next().unwrap_or_default()
    }
}

impl fmt::Display for BridgeKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let key = &self.key;
        match self.table {
            BridgeTable::Bridge => write!(f, "bridge.{key}"),
            BridgeTable::Segment(i) => write!(f, "segment[{i}].{key}"),
            BridgeTable::Joint(k) => write!(f, "joint[{k}].{key}"),
            BridgeTable::Abutment(s) => {
                write!(f, "abutment.{}.{key}", ABUTMENT_SIDES[s])
            }
            BridgeTable::Pier(p) => write!(f, "pier[{p}].{key}"),
        }
    }
}

/// Which input a [`super::SimError`] concerns.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum ParamPath {
    /// A parameter known by its name only: no scenario key sets it (`theta`, `q0[3]`,
    /// `--scales[2]`, …).
    Named(String),
    /// A run setting.
    Setting(Setting),
    /// A parameter of the two-deck model: shared (`deck` `None`), of deck 1 or 2, or of one of
    /// its bearings (1-based).
    TwoDeck {
        /// The parameter.
        param: TwoDeckParam,
        /// The deck (1 or 2), if one.
        deck: Option<u8>,
        /// The bearing of that deck (1-based), if one.
        bearing: Option<usize>,
    },
    /// A parameter of a bridge of segments.
    Bridge(BridgeKey),
}

impl ParamPath {
    /// A shared parameter of the two-deck model.
    pub const fn pair(param: TwoDeckParam) -> Self {
        Self::TwoDeck {
            param,
            deck: None,
            bearing: None,
        }
    }

    /// A parameter of deck `deck` (1 or 2) of the two-deck model.
    pub const fn deck(param: TwoDeckParam, deck: u8) -> Self {
        Self::TwoDeck {
            param,
            deck: Some(deck),
            bearing: None,
        }
    }
}

impl fmt::Display for ParamPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Named(n) => f.write_str(n),
            Self::Setting(s) => f.write_str(s.name()),
            Self::TwoDeck {
                param,
                deck,
                bearing,
            } => {
                f.write_str(param.name())?;
                match (deck, bearing) {
                    (Some(d), Some(b)) => write!(f, " (deck {d}, bearing {b})"),
                    (Some(d), None) => write!(f, " (deck {d})"),
                    _ => Ok(()),
                }
            }
            Self::Bridge(k) => k.fmt(f),
        }
    }
}

impl From<&str> for ParamPath {
    fn from(name: &str) -> Self {
        Self::Named(name.to_string())
    }
}

impl From<String> for ParamPath {
    fn from(name: String) -> Self {
        Self::Named(name)
    }
}

impl From<Setting> for ParamPath {
    fn from(s: Setting) -> Self {
        Self::Setting(s)
    }
}

impl From<BridgeKey> for ParamPath {
    fn from(k: BridgeKey) -> Self {
        Self::Bridge(k)
    }
}
