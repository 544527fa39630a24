//! The registry of compliance contact laws: for every `[contact] law` name, its keys, a
//! description and the function that builds the validated [`ContactLaw`] from the keys and
//! their defaults. The scenario reader (`sim::scenario`) and `pounding compare` read it.
//!
//! Adding a law: one new file in `contact_law/` (the law, its [`super::ContactForceLaw`] impl,
//! its `ENTRY` and `build` function) plus one line in the `contact_laws!` list of
//! `contact_law/mod.rs`, which generates [`LAWS`]. `rigid` is not a compliance law and is not
//! listed here.

use super::{ContactLaw, ContactLawError, units};
use crate::math::Real;
use thiserror::Error;

/// Default Kelvin (and linear) stiffness \[N/m\] (the order of the bilinear `K1` of the
/// OpenSees benchmark).
pub const DEFAULT_K: f64 = 1.0e10;
/// Default design maximum penetration of the bilinear law, 1 in \[m\].
pub const DEFAULT_DELTA_M: f64 = units::INCH;
/// Default yield ratio of the bilinear law.
pub const DEFAULT_A: f64 = 0.1;
/// Default floor of the impact velocity of Hertz-damp with per-impact damping \[m/s\].
pub const DEFAULT_MIN_VELOCITY: f64 = 0.01;

/// Default Hertz stiffness 25 000 kip/in^1.5 \[N/m^1.5\] (Muthukumar & DesRoches; the OpenSees
/// benchmark).
pub fn default_k_h() -> f64 {
    units::kip_per_in_1_5(25_000.0)
}

/// The inputs of a law's `build`: the numeric `[contact]` keys given, the calibration name, the
/// target restitution and the deck masses.
pub struct LawInputs<'a> {
    /// The value of a numeric `[contact]` key, `None` when not given.
    pub values: &'a dyn Fn(&str) -> Option<Real>,
    /// `[contact] calibration` (default `numerical`).
    pub calibration: &'a str,
    /// Target restitution (`[contact] restitution`, default `[joint] eps_n`).
    pub restitution: Real,
    /// The two deck masses \[kg\] (Kelvin, Jankowski calibrations).
    pub masses: [Real; 2],
}

impl LawInputs<'_> {
    /// The value of the numeric key `key`, if given.
    pub fn get(&self, key: &str) -> Option<Real> {
        (self.values)(key)
    }
}

/// Why a law could not be built from its keys (the scenario reader locates it in the file).
#[derive(Debug, Error, Clone, PartialEq)]
pub enum BuildError {
    /// A parameter out of range.
    #[error(transparent)]
    Law(#[from] ContactLawError),
    /// `[contact] calibration` names no calibration of this law.
    #[error("invalid calibration: use {allowed}")]
    Calibration {
        /// The accepted names, quoted and joined.
        allowed: &'static str,
    },
    /// Some but not all of a group of keys given.
    #[error("give all of {keys:?} ({hint})")]
    Incomplete {
        /// The keys to give together.
        keys: &'static [&'static str],
        /// The alternative.
        hint: &'static str,
    },
}

/// The `[contact]` keys a law reads for one choice of the keys given (see [`LawEntry::reads`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LawReads {
    /// The keys read (a subset of [`LawEntry::keys`]; `friction_velocity`, read by every
    /// compliance law, is not listed).
    pub keys: &'static [&'static str],
    /// How the law was chosen to be set, for messages: e.g. ` with zeta given` (leading
    /// space), or empty when the law has one way only.
    pub how: &'static str,
}

/// Whether a `[contact]` key is given (the argument of [`LawEntry::reads`]).
pub type KeyGiven<'a> = dyn Fn(&str) -> bool + 'a;

/// Shorthand for the `reads` functions of the law files' `ENTRY` ([`LAWS`]).
pub(crate) const fn reads(keys: &'static [&'static str], how: &'static str) -> LawReads {
    LawReads { keys, how }
}

/// One registered law.
pub struct LawEntry {
    /// The `[contact] law` name.
    pub name: &'static str,
    /// Every `[contact]` key the law may read (the union over its ways to be set).
    pub keys: &'static [&'static str],
    /// The keys the law reads when the keys for which `given(key)` is true are given: a law
    /// with several ways to set its damping reads only the keys of the way chosen (e.g.
    /// `hertz-damp` with `zeta` reads neither `chi` nor `restitution`). A given key that no
    /// law reads is refused by the scenario reader (`sim::scenario`) rather than ignored.
    /// Checked against `build` by the test `contact_law_keys` (a key read changes the law, a
    /// key not read does not).
    pub reads: fn(given: &KeyGiven<'_>) -> LawReads,
    /// One-line description.
    pub description: &'static str,
    /// Builds the law from the keys and the defaults.
    pub build: fn(&LawInputs) -> Result<ContactLaw, BuildError>,
}

/// Every compliance law, in the order of the `contact_laws!` list of `contact_law/mod.rs` (each
/// entry is the `ENTRY` constant of the law's file).
pub static LAWS: &[LawEntry] = super::ENTRIES;

/// The one law key whose value is text ([`LawInputs::calibration`]); every other key of
/// [`LawEntry::keys`] is a number ([`LawInputs::get`]).
pub const CALIBRATION_KEY: &str = "calibration";

/// Every key that some registered law reads ([`LawEntry::keys`]), each once, in registry order.
pub fn law_keys() -> &'static [&'static str] {
    static KEYS: std::sync::LazyLock<Vec<&'static str>> = std::sync::LazyLock::new(|| {
        let mut keys: Vec<&'static str> = Vec::new();
        for k in LAWS.iter().flat_map(|e| e.keys.iter()) {
            if !keys.contains(k) {
                keys.push(k);
            }
        }
        keys
    });
    &KEYS
}

/// The entry of law `name`, if registered.
pub fn entry(name: &str) -> Option<&'static LawEntry> {
    LAWS.iter().find(|e| e.name == name)
}

/// Every `[contact] law` name: `rigid`, then the registered compliance laws in order.
pub fn law_names() -> Vec<&'static str> {
    std::iter::once("rigid")
        .chain(LAWS.iter().map(|e| e.name))
        .collect()
}
