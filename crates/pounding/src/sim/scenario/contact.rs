//! `[contact]`: the joint's normal contact law (rigid, or one of the compliance laws with its
//! parameters and calibrations), and the `[decks] mass1`/`mass2` and `[bearings] damping` keys.

use super::Src;
use super::error::{ParamKey, ScenarioError, Section};
use super::sections::DecksSec;
use crate::contact_law::registry::{self, BuildError, LawInputs};
use crate::contact_law::{ContactLaw, ContactLawError};
use crate::output::float_token;
use crate::sim::{ComplianceContact, DampingModel, JointContact, SimModel};
use serde::Deserialize;

/// The default list of `pounding compare --laws`, in order: `rigid` and the five laws of the
/// first release (kept explicit so that `compare`'s output stays as it is when the
/// [`registry`] grows). Every name accepted by `[contact] law`: [`registry::law_names`].
pub const LAW_NAMES: [&str; 6] = [
    "rigid",
    "kelvin",
    "hertz",
    "hertz-damp",
    "bilinear",
    "jankowski",
];

/// `[contact]`: the joint's normal contact law. Every key optional.
#[derive(Deserialize, Default, Clone, Debug)]
#[serde(deny_unknown_fields, default)]
pub struct ContactSec {
    /// `rigid` (default), `kelvin`, `hertz`, `hertz-damp`, `bilinear`, `jankowski`, `linear`.
    pub law: Option<String>,
    /// Kelvin and linear stiffness \\[N/m\\].
    pub k: Option<f64>,
    /// Kelvin damping \\[N s/m\\] (instead of `restitution`).
    pub c: Option<f64>,
    /// Hertz stiffness \\[N/m^1.5\\].
    pub k_h: Option<f64>,
    /// Hertz-damp constant damping ratio.
    pub zeta: Option<f64>,
    /// Hertz-damp per-impact damping factor.
    pub chi: Option<f64>,
    /// Target restitution of the damped laws (default: `\\[joint\\] eps_n`).
    pub restitution: Option<f64>,
    /// How the damping follows from `restitution`.
    pub calibration: Option<String>,
    /// Hertz-damp design impact velocity \\[m/s\\].
    pub design_velocity: Option<f64>,
    /// Hertz-damp floor of the impact velocity \\[m/s\\].
    pub min_velocity: Option<f64>,
    /// Bilinear first stiffness \\[N/m\\].
    pub k1: Option<f64>,
    /// Bilinear second stiffness \\[N/m\\].
    pub k2: Option<f64>,
    /// Bilinear yield penetration \\[m\\].
    pub delta_y: Option<f64>,
    /// Bilinear design maximum penetration \\[m\\].
    pub delta_m: Option<f64>,
    /// Bilinear yield ratio.
    pub a: Option<f64>,
    /// Jankowski stiffness \\[N/m^1.5\\].
    pub beta: Option<f64>,
    /// Jankowski damping ratio.
    pub xi: Option<f64>,
    /// Regularisation velocity of Coulomb friction \\[m/s\\].
    pub friction_velocity: Option<f64>,
}

pub use crate::contact_law::registry::{
    DEFAULT_A, DEFAULT_DELTA_M, DEFAULT_K, DEFAULT_MIN_VELOCITY, default_k_h,
};

/// A contact-law error located at the `[contact]` key that sets the parameter.
fn law_err(src: &Src, e: ContactLawError) -> ScenarioError {
    let ContactLawError::InvalidParameter { name, .. } = &e;
    let Some(key) = ParamKey::of_contact_parameter(name) else {
        return ScenarioError::Law(Box::new(e));
    };
    let at = src.at(key);
    let note = if key.key == "restitution" && at.line.is_none() {
        " (the default is `[joint] eps_n`)".to_string()
    } else {
        String::new()
    };
    ScenarioError::Invalid {
        message: e.to_string(),
        at: vec![at],
        note,
    }
}

const fn contact(key: &'static str) -> ParamKey {
    ParamKey::new(Section::Contact, key)
}

/// The value of the numeric `[contact]` key `key` (`None`: not given, or not a numeric key).
fn numeric_key(sec: &ContactSec, key: &str) -> Option<f64> {
    match key {
        "k" => sec.k,
        "c" => sec.c,
        "k_h" => sec.k_h,
        "zeta" => sec.zeta,
        "chi" => sec.chi,
        "restitution" => sec.restitution,
        "design_velocity" => sec.design_velocity,
        "min_velocity" => sec.min_velocity,
        "k1" => sec.k1,
        "k2" => sec.k2,
        "delta_y" => sec.delta_y,
        "delta_m" => sec.delta_m,
        "a" => sec.a,
        "beta" => sec.beta,
        "xi" => sec.xi,
        "friction_velocity" => sec.friction_velocity,
        _ => None,
    }
}

/// Every parameter key of `[contact]` (all but `law`), in the order of the section.
pub const CONTACT_KEYS: [&str; 17] = [
    "k",
    "c",
    "k_h",
    "zeta",
    "chi",
    "restitution",
    "calibration",
    "design_velocity",
    "min_velocity",
    "k1",
    "k2",
    "delta_y",
    "delta_m",
    "a",
    "beta",
    "xi",
    "friction_velocity",
];

/// Whether the section gives `key`.
fn given(sec: &ContactSec, key: &str) -> bool {
    match key {
        "calibration" => sec.calibration.is_some(),
        _ => numeric_key(sec, key).is_some(),
    }
}

/// The keys a law reads and how its way was chosen (`None`: `rigid` or an unknown law).
type KeysRead = Option<(Vec<&'static str>, &'static str)>;

/// The `[contact]` keys law `name` reads with the keys given in `sec`, and how its way was
/// chosen (for messages); `None` for `rigid` (reads none) and unknown names.
fn keys_read(sec: &ContactSec, name: &str) -> KeysRead {
    let entry = registry::entry(name)?;
    let r = (entry.reads)(&|k| given(sec, k));
    let mut keys = r.keys.to_vec();
    keys.push("friction_velocity");
    Some((keys, r.how))
}

/// Refuses a `[contact]` key that none of `laws` reads with the keys given (it would be
/// ignored silently). `compared`: the laws are those of a comparison, which builds each of
/// them from the one section, so a key is refused only when no compared law reads it.
/// Unknown law names are skipped (reported with the list of laws when built).
pub(super) fn check_contact_keys(
    src: &Src,
    sec: &ContactSec,
    laws: &[&str],
    compared: bool,
) -> Result<(), ScenarioError> {
    let read: Vec<(&str, KeysRead)> = laws.iter().map(|&l| (l, keys_read(sec, l))).collect();
    if read.iter().any(|(l, r)| r.is_none() && *l != "rigid") {
        return Ok(());
    }
    for key in CONTACT_KEYS {
        let is_read = read
            .iter()
            .any(|(_, r)| r.as_ref().is_some_and(|(keys, _)| keys.contains(&key)));
        if !given(sec, key) || is_read {
            continue;
        }
        let at = src.at(contact(key));
        let message = match read.as_slice() {
            [(law, None)] if !compared => {
                let compliance: Vec<&str> = registry::LAWS.iter().map(|e| e.name).collect();
                let default = if src.is_set(contact("law")) || *law != "rigid" {
                    ""
                } else {
                    ", the default"
                };
                format!(
                    "{key} applies to compliance laws ({}), not to law = \"rigid\"{default} (rigid \
                     contact uses `[joint] eps_n` and `[joint] mu`) — set by {at}",
                    compliance.join(", ")
                )
            }
            [(law, Some((keys, how)))] if !compared => format!(
                "{key} is not used by law = \"{law}\"{how} (it reads {}) — set by {at}",
                keys.join(", ")
            ),
            _ => {
                let readers: Vec<String> = registry::LAWS
                    .iter()
                    .filter_map(|e| {
                        let (keys, how) = keys_read(sec, e.name)?;
                        keys.contains(&key).then(|| format!("{}{how}", e.name))
                    })
                    .collect();
                let hint = match readers.is_empty() {
                    true => "no law reads it together with the other keys given".to_string(),
                    false => format!("it is read by {}", readers.join("; ")),
                };
                format!(
                    "{key} is not used by any of the compared laws ({}) — set by {at}; {hint}",
                    laws.join(", ")
                )
            }
        };
        return Err(ScenarioError::Key {
            message,
            at: vec![at],
        });
    }
    Ok(())
}

/// The compliance law `name` (not `rigid`) from the `[contact]` keys and their defaults,
/// built by its [`registry`] entry.
fn compliance_law(
    src: &Src,
    sec: &ContactSec,
    name: &str,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<ContactLaw, ScenarioError> {
    let Some(entry) = registry::entry(name) else {
        return Err(src.key_error(
            format!(
                "unknown contact law {name:?} at {}: use one of {}",
                src.at(contact("law")),
                registry::law_names().join(", ")
            ),
            &[contact("law")],
        ));
    };
    let cal = sec.calibration.as_deref().unwrap_or("numerical");
    let values = |key: &str| numeric_key(sec, key);
    let inputs = LawInputs {
        values: &values,
        calibration: cal,
        restitution: sec.restitution.unwrap_or(eps_n),
        masses,
    };
    (entry.build)(&inputs).map_err(|e| match e {
        BuildError::Law(e) => law_err(src, e),
        BuildError::Calibration { allowed } => src.key_error(
            format!(
                "invalid calibration {cal:?} for law {name:?} at {}: use {allowed}",
                src.at(contact("calibration"))
            ),
            &[contact("calibration")],
        ),
        BuildError::Incomplete { keys, hint } => {
            let keys: Vec<ParamKey> = keys.iter().map(|k| contact(k)).collect();
            let at: Vec<String> = keys.iter().map(|k| src.at(*k).to_string()).collect();
            let list = match at.split_last() {
                Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
                _ => at.join(""),
            };
            src.key_error(format!("law {name:?}: give all of {list} ({hint})"), &keys)
        }
    })
}

/// Builds the joint contact for `law` (overriding `[contact] law` when given) from the section;
/// `eps_n` is the default restitution, `masses` the deck masses (Kelvin, Jankowski calibrations).
pub(super) fn build_contact(
    src: &Src,
    sec: &ContactSec,
    law: Option<&str>,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<JointContact, ScenarioError> {
    let name = law
        .map(str::to_string)
        .or_else(|| sec.law.clone())
        .unwrap_or_else(|| "rigid".into());
    if name == "rigid" {
        return Ok(JointContact::Rigid);
    }
    let law = compliance_law(src, sec, &name, eps_n, masses)?;
    let mut cc = ComplianceContact::new(law);
    if let Some(v) = sec.friction_velocity {
        if !(v.is_finite() && v > 0.0) {
            return Err(src.invalid(
                format!(
                    "invalid friction_velocity = {}: must be finite and > 0",
                    float_token(v)
                ),
                contact("friction_velocity"),
            ));
        }
        cc.friction_velocity = v;
    }
    Ok(JointContact::Compliance(cc))
}

/// `[decks] mass1`, `mass2` (the deck's mass given directly: its density becomes
/// `ρ m / m(ρ)`, any shape) and `[bearings] damping = "rayleigh" | "dashpots"`.
pub(super) fn apply_shape_and_damping(
    src: &Src,
    d: &DecksSec,
    damping: &str,
    model: &mut SimModel,
) -> Result<(), ScenarioError> {
    let current = model.masses();
    for (j, m, key) in [(0, d.mass1, "mass1"), (1, d.mass2, "mass2")] {
        let Some(m) = m else { continue };
        if !(m.is_finite() && m > 0.0) {
            return Err(src.invalid(
                format!("invalid {key} = {}: must be finite and > 0", float_token(m)),
                ParamKey::of_deck(Section::Decks, key, j as u8 + 1),
            ));
        }
        let f = m / current[j];
        match &mut model.shapes {
            Some(sh) => sh[j].scale_density(f),
            None => {
                if j == 0 {
                    model.arrangement.deck1.density *= f;
                } else {
                    model.arrangement.deck2.density *= f;
                }
            }
        }
    }
    model.damping_model = match damping {
        "rayleigh" => DampingModel::Rayleigh,
        "dashpots" => DampingModel::TranslationalDashpots,
        other => {
            let key = ParamKey::new(Section::Bearings, "damping");
            return Err(src.key_error(
                format!(
                    "unknown damping {other:?} at {}: use \"rayleigh\" or \"dashpots\"",
                    src.at(key)
                ),
                &[key],
            ));
        }
    };
    Ok(())
}
