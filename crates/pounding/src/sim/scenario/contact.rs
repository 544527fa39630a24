//! `[contact]`: the joint's normal contact law (rigid, or one of the compliance laws with its
//! parameters and calibrations), and the `[decks] mass1`/`mass2` and `[bearings] damping` keys.

use super::Src;
use super::error::{ParamKey, ScenarioError, Section};
use crate::contact_law::registry::{self, BuildError, LawInputs};
use crate::contact_law::{ContactLaw, ContactLawError};
use crate::output::float_token;
use crate::sim::{ComplianceContact, JointContact};
use serde::de::{self, Deserialize, Deserializer, MapAccess, Visitor};
use std::collections::BTreeMap;
use std::fmt;
use std::sync::LazyLock;

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
///
/// The section is read generically from the [`registry`], so that a new law with a new key
/// needs no change here: its keys are `law`, `friction_velocity` (every compliance law) and
/// every key that some registered law lists ([`registry::law_keys`]); all are numbers but `law`
/// and `calibration` ([`registry::CALIBRATION_KEY`]), which are text. Any other key, or a value
/// of the wrong type, is refused while the TOML is read (the message names the line).
#[derive(Default, Clone, Debug)]
pub struct ContactSec {
    /// `rigid` (default) or a [`registry`] name (`kelvin`, `hertz`, …).
    pub law: Option<String>,
    /// How the damping follows from `restitution` (the law's [`registry::LawInputs::calibration`]).
    pub calibration: Option<String>,
    /// Regularisation velocity of Coulomb friction \\[m/s\\].
    pub friction_velocity: Option<f64>,
    /// The numeric law keys given, by name ([`registry::law_keys`]).
    pub values: BTreeMap<&'static str, f64>,
}

impl ContactSec {
    /// The value of the numeric law key `key` (`None`: not given).
    fn value(&self, key: &str) -> Option<f64> {
        self.values.get(key).copied()
    }
}

/// Every key of `[contact]`: `law`, the registered laws' keys, `friction_velocity`.
pub(super) fn section_keys() -> &'static [&'static str] {
    static KEYS: LazyLock<Vec<&'static str>> = LazyLock::new(|| {
        let mut keys = vec!["law"];
        keys.extend_from_slice(registry::law_keys());
        keys.push("friction_velocity");
        keys
    });
    &KEYS
}

/// A `[contact]` key, checked against [`section_keys`] as it is read (so that the TOML reader's
/// message points at it).
struct Key(&'static str);

impl<'de> Deserialize<'de> for Key {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        let keys = section_keys();
        match keys.iter().find(|&&k| k == name) {
            Some(k) => Ok(Key(k)),
            None => Err(de::Error::unknown_field(&name, keys)),
        }
    }
}

impl<'de> Deserialize<'de> for ContactSec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ContactSec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("the [contact] table")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<ContactSec, A::Error> {
                let mut sec = ContactSec::default();
                while let Some(Key(key)) = map.next_key()? {
                    match key {
                        "law" => sec.law = Some(map.next_value()?),
                        registry::CALIBRATION_KEY => sec.calibration = Some(map.next_value()?),
                        "friction_velocity" => sec.friction_velocity = Some(map.next_value()?),
                        _ => {
                            sec.values.insert(key, map.next_value()?);
                        }
                    }
                }
                Ok(sec)
            }
        }
        d.deserialize_map(V)
    }
}

pub use crate::contact_law::registry::{
    DEFAULT_A, DEFAULT_DELTA_M, DEFAULT_K, DEFAULT_MIN_VELOCITY, default_k_h,
};

/// Where the keys of one contact section are set, for the messages of [`build_contact`]: the
/// file's `[contact]` ([`FileKeys`]) or a bridge site's `contact` table (`sim::scenario::bridge`).
pub(super) trait ContactKeys {
    /// `key` and where it is set, as named in messages (e.g. "`[contact] k` (FILE:3)").
    fn at(&self, key: &'static str) -> String;
    /// An out-of-range value of `key` (`message` says which and why).
    fn invalid(&self, message: String, key: &'static str) -> ScenarioError;
    /// A message that names `keys` itself (with [`ContactKeys::at`]).
    fn key_error(&self, message: String, keys: &[&'static str]) -> ScenarioError;
}

/// The keys of the file's `[contact]` section.
pub(super) struct FileKeys<'a>(pub(super) &'a Src);

impl ContactKeys for FileKeys<'_> {
    fn at(&self, key: &'static str) -> String {
        self.0.at(contact(key)).to_string()
    }
    fn invalid(&self, message: String, key: &'static str) -> ScenarioError {
        let at = self.0.at(contact(key));
        let note = if key == "restitution" && at.line.is_none() {
            " (the default is `[joint] eps_n`)".to_string()
        } else {
            String::new()
        };
        ScenarioError::Invalid {
            message,
            at: vec![at],
            note,
        }
    }
    fn key_error(&self, message: String, keys: &[&'static str]) -> ScenarioError {
        let keys: Vec<ParamKey> = keys.iter().map(|k| contact(k)).collect();
        self.0.key_error(message, &keys)
    }
}

/// A contact-law error located at the key that sets the parameter.
fn law_err(loc: &dyn ContactKeys, e: ContactLawError) -> ScenarioError {
    let ContactLawError::InvalidParameter { name, .. } = &e;
    let Some(key) = ParamKey::of_contact_parameter(name) else {
        return ScenarioError::Law(Box::new(e));
    };
    loc.invalid(e.to_string(), key.key)
}

pub(super) const fn contact(key: &'static str) -> ParamKey {
    ParamKey::new(Section::Contact, key)
}

/// Every parameter key of `[contact]` (all but `law`): the registered laws' keys
/// ([`registry::law_keys`], in registry order) and `friction_velocity`.
pub fn contact_keys() -> &'static [&'static str] {
    &section_keys()[1..]
}

/// Whether the section gives `key`.
pub(super) fn given(sec: &ContactSec, key: &str) -> bool {
    match key {
        registry::CALIBRATION_KEY => sec.calibration.is_some(),
        "friction_velocity" => sec.friction_velocity.is_some(),
        _ => sec.value(key).is_some(),
    }
}

/// The keys a law reads and how its way was chosen (`None`: `rigid` or an unknown law).
pub(super) type KeysRead = Option<(Vec<&'static str>, &'static str)>;

/// The `[contact]` keys law `name` reads with the keys given in `sec`, and how its way was
/// chosen (for messages); `None` for `rigid` (reads none) and unknown names.
pub(super) fn keys_read(sec: &ContactSec, name: &str) -> KeysRead {
    let entry = registry::entry(name)?;
    let r = (entry.reads)(&|k| given(sec, k));
    let mut keys = r.keys.to_vec();
    keys.push("friction_velocity");
    Some((keys, r.how))
}

/// Refuses a `[contact]` key that none of `laws` reads with the keys given (it would be
/// ignored silently). `group`: the laws are several uses of the one section (`Some("the
/// compared laws")` for a comparison, which builds each of them from it; a bridge whose sites
/// use different laws), so a key is refused only when no law of the group reads it.
/// Unknown law names are skipped (reported with the list of laws when built).
pub(super) fn check_contact_keys(
    src: &Src,
    sec: &ContactSec,
    laws: &[&str],
    group: Option<&str>,
) -> Result<(), ScenarioError> {
    let compared = group.is_some();
    let read: Vec<(&str, KeysRead)> = laws.iter().map(|&l| (l, keys_read(sec, l))).collect();
    if read.iter().any(|(l, r)| r.is_none() && *l != "rigid") {
        return Ok(());
    }
    for &key in contact_keys() {
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
                    "{key} is not used by any of {} ({}) — set by {at}; {hint}",
                    group.unwrap_or("the compared laws"),
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
    loc: &dyn ContactKeys,
    sec: &ContactSec,
    name: &str,
    eps_n: f64,
    masses: [f64; 2],
) -> Result<ContactLaw, ScenarioError> {
    let Some(entry) = registry::entry(name) else {
        return Err(loc.key_error(
            format!(
                "unknown contact law {name:?} at {}: use one of {}",
                loc.at("law"),
                registry::law_names().join(", ")
            ),
            &["law"],
        ));
    };
    let cal = sec.calibration.as_deref().unwrap_or("numerical");
    let values = |key: &str| sec.value(key);
    let inputs = LawInputs {
        values: &values,
        calibration: cal,
        restitution: sec.value("restitution").unwrap_or(eps_n),
        masses,
    };
    (entry.build)(&inputs).map_err(|e| match e {
        BuildError::Law(e) => law_err(loc, e),
        BuildError::Calibration { allowed } => loc.key_error(
            format!(
                "invalid calibration {cal:?} for law {name:?} at {}: use {allowed}",
                loc.at("calibration")
            ),
            &["calibration"],
        ),
        BuildError::Incomplete { keys, hint } => {
            let at: Vec<String> = keys.iter().map(|k| loc.at(k)).collect();
            let list = match at.split_last() {
                Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
                _ => at.join(""),
            };
            loc.key_error(format!("law {name:?}: give all of {list} ({hint})"), keys)
        }
    })
}

/// Builds the joint contact for `law` (overriding `[contact] law` when given) from the section;
/// `eps_n` is the default restitution, `masses` the deck masses (Kelvin, Jankowski calibrations).
pub(super) fn build_contact(
    loc: &dyn ContactKeys,
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
    let law = compliance_law(loc, sec, &name, eps_n, masses)?;
    let mut cc = ComplianceContact::new(law);
    if let Some(v) = sec.friction_velocity {
        if !(v.is_finite() && v > 0.0) {
            return Err(loc.invalid(
                format!(
                    "invalid friction_velocity = {}: must be finite and > 0",
                    float_token(v)
                ),
                "friction_velocity",
            ));
        }
        cc.friction_velocity = v;
    }
    Ok(JointContact::Compliance(cc))
}
