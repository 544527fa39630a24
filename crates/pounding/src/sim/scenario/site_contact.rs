//! The contact table of one bridge site: `[joint.contact]` after a `[[joint]]` table (or
//! `contact = { law = "hertz-damp", k_h = 1e9 }` in it), `[abutment.start.contact]`,
//! `[abutment.end.contact]`. Its keys are those of `[contact]`.
//!
//! Rules (see the module doc of `sim::scenario::bridge`):
//! - the site's table overrides the file's `[contact]` key by key: a site that only sets `k_h`
//!   keeps the file's law and its other keys;
//! - a site that sets another `law` inherits only the `[contact]` keys that its law reads;
//! - a key of the site's table that the site's law does not read (with the keys it has) is an
//!   error naming `joint[k].contact.KEY` (`abutment.end.contact.KEY`) and its line;
//! - a law override (`--law`, `pounding compare`) replaces the law at every site; the site's
//!   other keys apply when that law reads them (for a comparison: a site key is refused only
//!   when no compared law reads it).

use super::Src;
use super::contact::{ContactKeys, ContactSec, FileKeys, contact, given, keys_read, section_keys};
use super::error::{KeyRef, ScenarioError};
use crate::contact_law::registry::{self, CALIBRATION_KEY};
use crate::toml_schema::line_col;
use std::collections::BTreeMap;
use toml::Spanned;

/// A site's `contact` table as written (keys, values and their positions).
pub(super) type SiteTable = BTreeMap<String, Spanned<toml::Value>>;

/// The contact of one site resolved from its table and the file's `[contact]`.
pub(super) struct SiteContact<'a> {
    src: &'a Src,
    /// `joint[k]` or `abutment.start` / `abutment.end`.
    pub site: String,
    /// The site's own keys with their lines.
    own: BTreeMap<&'static str, usize>,
    /// The `[contact]` keys the site inherits.
    inherited: Vec<&'static str>,
    /// The law of the site (override, own `law`, `[contact] law`, `rigid`).
    pub law: String,
    /// The line of the site's own `law` key, if it sets one.
    pub law_line: Option<usize>,
    /// The keys of the site: the inherited ones overridden by its own.
    pub sec: ContactSec,
}

impl SiteContact<'_> {
    /// Whether the site has a `contact` table of its own (else it is built exactly as the
    /// file's `[contact]`).
    pub(super) fn own_keys(&self) -> bool {
        !self.own.is_empty()
    }
    fn key(&self, key: &str) -> String {
        format!("{}.contact.{key}", self.site)
    }
    fn error(&self, key: &str, line: Option<usize>, message: String) -> ScenarioError {
        ScenarioError::Invalid {
            message,
            at: vec![KeyRef::path(self.key(key), &self.src.origin, line)],
            note: String::new(),
        }
    }

    /// Refuses a key of the site's own table that none of `laws` reads with the site's keys
    /// (`laws`: the site's law, or the compared laws when `compared`).
    pub(super) fn check_keys(&self, laws: &[&str], compared: bool) -> Result<(), ScenarioError> {
        for (&key, &line) in &self.own {
            if key == "law" {
                continue;
            }
            let read = laws
                .iter()
                .any(|l| keys_read(&self.sec, l).is_some_and(|(keys, _)| keys.contains(&key)));
            if read {
                continue;
            }
            let message = match (laws, compared) {
                (&["rigid"], false) => format!(
                    "{} applies to compliance laws, not to law = \"rigid\" (rigid contact uses \
                     {}.eps_n and {}.mu)",
                    self.key(key),
                    self.site,
                    self.site
                ),
                (&[law], false) => {
                    let (keys, how) = keys_read(&self.sec, law).unwrap_or_default();
                    format!(
                        "{} is not used by law = \"{law}\"{how} (it reads {})",
                        self.key(key),
                        keys.join(", ")
                    )
                }
                _ => format!(
                    "{} is not used by any of the compared laws ({})",
                    self.key(key),
                    laws.join(", ")
                ),
            };
            return Err(self.error(key, Some(line), message));
        }
        Ok(())
    }
}

impl ContactKeys for SiteContact<'_> {
    fn at(&self, key: &'static str) -> String {
        match self.own.get(key) {
            Some(l) => format!("`{}` ({}:{l})", self.key(key), self.src.origin),
            None if self.inherited.contains(&key) => self.src.at(contact(key)).to_string(),
            None => format!(
                "`{}` (not set in {}; default)",
                self.key(key),
                self.src.origin
            ),
        }
    }
    fn invalid(&self, message: String, key: &'static str) -> ScenarioError {
        match self.own.get(key) {
            Some(&l) => self.error(key, Some(l), message),
            None if self.inherited.contains(&key) => {
                FileKeys(self.src).invalid(format!("{}: {message}", self.site), key)
            }
            None if key == "restitution" => self.error(
                key,
                None,
                format!("{message} (the default is {}.eps_n)", self.site),
            ),
            None => self.error(key, None, message),
        }
    }
    fn key_error(&self, message: String, _keys: &[&'static str]) -> ScenarioError {
        ScenarioError::Key {
            message,
            at: Vec::new(),
        }
    }
}

/// Resolves the contact of site `site` (`joint[k]`, `abutment.end`) from its own `table` and
/// the file's `[contact]` `file`; `law_override` replaces the law (`--law`, compare).
/// Errors: an unknown key, a value of the wrong type, an unknown law (named with its line).
pub(super) fn resolve<'a>(
    src: &'a Src,
    file: &ContactSec,
    law_override: Option<&str>,
    site: String,
    table: Option<&Spanned<SiteTable>>,
) -> Result<SiteContact<'a>, ScenarioError> {
    let mut sc = SiteContact {
        src,
        site,
        own: BTreeMap::new(),
        inherited: Vec::new(),
        law: String::new(),
        law_line: None,
        sec: ContactSec::default(),
    };
    let mut own = ContactSec::default();
    for (k, v) in table.map(|t| t.get_ref().iter()).into_iter().flatten() {
        let line = line_col(&src.text, v.span().start).0;
        let Some(&key) = section_keys().iter().find(|&&s| s == k) else {
            return Err(sc.error(
                k,
                Some(line),
                format!(
                    "unknown key {}: a contact table has the keys of [contact] ({})",
                    sc.key(k),
                    section_keys().join(", ")
                ),
            ));
        };
        sc.own.insert(key, line);
        let text = |what: &str| match v.get_ref() {
            toml::Value::String(s) => Ok(s.clone()),
            _ => Err(sc.error(key, Some(line), format!("{} must be {what}", sc.key(key)))),
        };
        match key {
            "law" => {
                let l = text("a law name (a string)")?;
                if !registry::law_names().contains(&l.as_str()) {
                    return Err(sc.error(
                        key,
                        Some(line),
                        format!(
                            "unknown contact law {l:?}: use one of {}",
                            registry::law_names().join(", ")
                        ),
                    ));
                }
                own.law = Some(l);
                sc.law_line = Some(line);
            }
            CALIBRATION_KEY => own.calibration = Some(text("a calibration name (a string)")?),
            _ => {
                let x = match v.get_ref() {
                    toml::Value::Float(x) => *x,
                    toml::Value::Integer(i) => *i as f64,
                    _ => {
                        return Err(sc.error(
                            key,
                            Some(line),
                            format!("{} must be a number", sc.key(key)),
                        ));
                    }
                };
                if key == "friction_velocity" {
                    own.friction_velocity = Some(x);
                } else {
                    own.values.insert(key, x);
                }
            }
        }
    }
    let run_law = law_override
        .map(str::to_string)
        .or_else(|| file.law.clone())
        .unwrap_or_else(|| "rigid".into());
    sc.law = match (law_override, &own.law) {
        (None, Some(l)) => l.clone(),
        _ => run_law.clone(),
    };
    // a site that changes the law inherits the keys its law reads (with its keys and the file's)
    let inherit: Vec<&'static str> = if sc.law == run_law {
        section_keys()[1..].to_vec()
    } else {
        let both = |k: &str| given(&own, k) || given(file, k);
        registry::entry(&sc.law).map_or_else(Vec::new, |e| {
            let mut keys = (e.reads)(&both).keys.to_vec();
            keys.push("friction_velocity");
            keys
        })
    };
    let mut sec = ContactSec {
        law: Some(sc.law.clone()),
        ..ContactSec::default()
    };
    for &k in &inherit {
        if !given(file, k) {
            continue;
        }
        sc.inherited.push(k);
        match k {
            CALIBRATION_KEY => sec.calibration = file.calibration.clone(),
            "friction_velocity" => sec.friction_velocity = file.friction_velocity,
            _ => {
                sec.values.insert(k, file.values[k]);
            }
        }
    }
    if own.calibration.is_some() {
        sec.calibration = own.calibration;
    }
    if own.friction_velocity.is_some() {
        sec.friction_velocity = own.friction_velocity;
    }
    sec.values.extend(own.values);
    sc.sec = sec;
    Ok(sc)
}
