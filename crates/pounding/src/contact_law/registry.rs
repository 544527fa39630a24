//! The registry of compliance contact laws: for every `[contact] law` name, its keys, a
//! description and the function that builds the validated [`ContactLaw`] from the keys and
//! their defaults. The scenario reader (`sim::scenario`) and `pounding compare` read it.
//!
//! Adding a law: one new file in `contact_law/` (the law, its [`super::ContactForceLaw`] impl and its
//! `build` function) plus one line in [`LAWS`] (and its variant line in `contact_laws!` of
//! `contact_law/mod.rs`). `rigid` is not a compliance law and is not listed here.

use super::calibration::{HertzDampCalibration, JankowskiCalibration, KelvinCalibration};
use super::{
    BilinearImpact, ContactLaw, ContactLawError, Hertz, HertzDamp, HertzDamping, Jankowski,
    KelvinVoigt, units,
};
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

/// Shorthand for the `reads` functions of [`LAWS`].
const fn reads(keys: &'static [&'static str], how: &'static str) -> LawReads {
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

/// Every compliance law, one line each.
pub static LAWS: &[LawEntry] = &[
    LawEntry {
        name: "kelvin",
        keys: &["k", "c", "restitution", "calibration"],
        reads: |given| match given("c") {
            true => reads(&["k", "c"], " with c given"),
            false => reads(&["k", "restitution", "calibration"], " without c"),
        },
        description: "linear spring and dashpot (Kelvin-Voigt)",
        build: kelvin,
    },
    LawEntry {
        name: "hertz",
        keys: &["k_h"],
        reads: |_| reads(&["k_h"], ""),
        description: "Hertz elastic k_h d^1.5",
        build: hertz,
    },
    LawEntry {
        name: "hertz-damp",
        keys: &[
            "k_h",
            "zeta",
            "chi",
            "restitution",
            "calibration",
            "design_velocity",
            "min_velocity",
        ],
        reads: |given| {
            if given("zeta") {
                reads(&["k_h", "zeta"], " with zeta given")
            } else if given("chi") {
                reads(&["k_h", "chi", "min_velocity"], " with chi given")
            } else if given("design_velocity") {
                reads(
                    &["k_h", "restitution", "calibration", "design_velocity"],
                    " with design_velocity given (a constant zeta)",
                )
            } else {
                reads(
                    &["k_h", "restitution", "calibration", "min_velocity"],
                    " without zeta, chi or design_velocity",
                )
            }
        },
        description: "Hertz with nonlinear damping (Muthukumar & DesRoches)",
        build: hertz_damp,
    },
    LawEntry {
        name: "bilinear",
        keys: &["k1", "k2", "delta_y", "k_h", "restitution", "delta_m", "a"],
        reads: |given| match given("k1") || given("k2") || given("delta_y") {
            true => reads(&["k1", "k2", "delta_y"], " with k1, k2, delta_y given"),
            false => reads(
                &["k_h", "restitution", "delta_m", "a"],
                " without k1, k2, delta_y",
            ),
        },
        description: "bilinear impact (OpenSees ImpactMaterial)",
        build: bilinear,
    },
    LawEntry {
        name: "jankowski",
        keys: &["beta", "k_h", "xi", "restitution", "calibration"],
        // beta, when given, is the stiffness (k_h is its fallback)
        reads: |given| match (given("beta"), given("xi")) {
            (true, true) => reads(&["beta", "xi"], " with beta and xi given"),
            (true, false) => reads(&["beta", "restitution", "calibration"], " with beta given"),
            (false, true) => reads(&["k_h", "xi"], " with xi given"),
            (false, false) => reads(&["k_h", "restitution", "calibration"], ""),
        },
        description: "Jankowski nonlinear viscoelastic",
        build: jankowski,
    },
    LawEntry {
        name: "linear",
        keys: &["k"],
        reads: |_| reads(&["k"], ""),
        description: "linear elastic spring k d, no damping",
        build: super::linear::build,
    },
];

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

fn kelvin(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let k = p.get("k").unwrap_or(DEFAULT_K);
    Ok(match p.get("c") {
        Some(c) => KelvinVoigt::new(k, c)?.into(),
        None => {
            let m = match p.calibration {
                "numerical" => KelvinCalibration::Numerical,
                "anagnostopoulos" => KelvinCalibration::Anagnostopoulos,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\" or \"anagnostopoulos\"",
                    });
                }
            };
            let [m1, m2] = p.masses;
            KelvinVoigt::from_restitution(k, p.restitution, m1, m2, m)?.into()
        }
    })
}

fn hertz(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    Ok(Hertz::new(p.get("k_h").unwrap_or_else(default_k_h))?.into())
}

fn hertz_damp(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let k_h = p.get("k_h").unwrap_or_else(default_k_h);
    let vmin = p.get("min_velocity").unwrap_or(DEFAULT_MIN_VELOCITY);
    Ok(match (p.get("zeta"), p.get("chi")) {
        (Some(zeta), _) => HertzDamp::new(k_h, HertzDamping::Constant { zeta })?,
        (None, Some(chi)) => HertzDamp::new(
            k_h,
            HertzDamping::PerImpact {
                chi,
                min_velocity: vmin,
            },
        )?,
        (None, None) => {
            let m = match p.calibration {
                "numerical" => HertzDampCalibration::Numerical,
                "muthukumar-desroches" => HertzDampCalibration::MuthukumarDesRoches,
                "ye" => HertzDampCalibration::YeEtAl,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\", \"muthukumar-desroches\" or \"ye\"",
                    });
                }
            };
            HertzDamp::from_restitution(k_h, p.restitution, p.get("design_velocity"), vmin, m)?
        }
    }
    .into())
}

fn bilinear(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    Ok(match (p.get("k1"), p.get("k2"), p.get("delta_y")) {
        (None, None, None) => {
            BilinearImpact::from_hertz(
                p.get("k_h").unwrap_or_else(default_k_h),
                p.restitution,
                p.get("delta_m").unwrap_or(DEFAULT_DELTA_M),
                p.get("a").unwrap_or(DEFAULT_A),
            )?
            .law
        }
        (Some(k1), Some(k2), Some(dy)) => BilinearImpact::new(k1, k2, dy)?,
        _ => {
            return Err(BuildError::Incomplete {
                keys: &["k1", "k2", "delta_y"],
                hint: "or none, to derive them from k_h, restitution, delta_m, a",
            });
        }
    }
    .into())
}

fn jankowski(p: &LawInputs) -> Result<ContactLaw, BuildError> {
    let beta = p.get("beta").or(p.get("k_h")).unwrap_or_else(default_k_h);
    let [m1, m2] = p.masses;
    Ok(match p.get("xi") {
        Some(xi) => super::effective_mass(m1, m2).and_then(|m| Jankowski::new(beta, xi, m))?,
        None => {
            let m = match p.calibration {
                "numerical" => JankowskiCalibration::Numerical,
                "jankowski2005" => JankowskiCalibration::Jankowski2005,
                _ => {
                    return Err(BuildError::Calibration {
                        allowed: "\"numerical\" or \"jankowski2005\"",
                    });
                }
            };
            Jankowski::from_restitution(beta, p.restitution, m1, m2, m)?
        }
    }
    .into())
}
