//! Variants of a scenario: a name and a set of overrides of the scenario's TOML keys, applied to
//! the scenario's **text** before it is parsed, so that every validation of the scenario runs on
//! the result (used by `pounding design`; generic: any TOML scenario, any caller's check).
//!
//! ```toml
//! [[variant]]
//! name = "stiff-restrainers"          # unique; letters, digits, '-', '_', '.'
//! description = "restrainers twice as stiff"   # optional
//! [variant.set]                       # the overrides: dotted key paths into the scenario
//! "bridge.restrainer_k" = 1.0e8
//! "joint[1].gap" = 0.05               # array-of-tables elements by 0-based index
//! "joint[0].contact" = { law = "hertz", k_h = 5e9 }   # a table the base does not have
//! ```
//!
//! Keys of `set` are paths: bare keys joined by `.`, an element of an array of tables as
//! `name[i]` (0-based, as the scenario's own error keys). Unquoted dotted keys (`bridge.gap = …`)
//! and nested tables are the same paths. A path to a key the base sets replaces its value in
//! place (the base's other lines keep their numbers); a path to a key the base does not set is
//! added to its table, which must exist in the base and be written under a `[header]` (or be the
//! root); missing tables on the way are added as one inline table. Refused, naming the variants
//! file, the variant, the key and its line: a malformed path, an index beyond the base's array, a
//! path through a value that is not a table, an override of a whole table or array of tables, a
//! key set twice. What the scenario itself refuses ([`Variant::apply_checked`]: an unknown key, a
//! value out of range) is reported the same way, with the first override that makes it fail, so
//! that an override is never a silent no-op: a key the scenario does not know is refused by the
//! scenario's own strict reading.

use crate::toml_schema::line_col;
use std::fmt::Write as _;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// One step of a key path.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// A table key.
    Key(String),
    /// An element of an array (of tables), 0-based.
    Index(usize),
}

/// One override: a key path and its new value.
#[derive(Debug, Clone, PartialEq)]
pub struct Override {
    /// The path as written (normalised: `joint[1].gap`).
    pub key: String,
    /// The parsed path.
    pub path: Vec<Step>,
    /// The new value.
    pub value: toml::Value,
    /// 1-based line of the override in the variants file.
    pub line: usize,
}

/// A named set of overrides.
#[derive(Debug, Clone, PartialEq)]
pub struct Variant {
    /// The variant's name (unique in its file).
    pub name: String,
    /// Free text (empty when not given).
    pub description: String,
    /// 1-based line of its `name`.
    pub line: usize,
    /// The overrides, in the file's order.
    pub overrides: Vec<Override>,
}

/// The `[[variant]]` tables of a file.
#[derive(Debug, Clone, PartialEq)]
pub struct Variants {
    /// The file's name in messages.
    pub origin: String,
    /// The variants, in the file's order.
    pub list: Vec<Variant>,
}

/// A bad variants file or override. Every message names the variants file and a line.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VariantError {
    /// TOML syntax of the variants file.
    #[error("invalid variants file {origin}: {message}")]
    Syntax {
        /// The variants file.
        origin: String,
        /// The TOML reader's message.
        message: String,
    },
    /// A bad entry of the variants file (a key of a `[[variant]]` table or an override).
    #[error(
        "{origin}:{line}: {}`{key}`: {message}",
        if variant.is_empty() { String::new() } else { format!("variant {variant:?}: ") }
    )]
    Key {
        /// The variants file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// The variant (empty before its name is known).
        variant: String,
        /// The key (e.g. `bridge.restrainer_k`, or `variant[2].name`).
        key: String,
        /// What is wrong.
        message: String,
    },
}

impl Variants {
    /// Reads the `[[variant]]` tables of `text` (other top-level keys are the caller's and are
    /// not read here). `origin` names the file in messages. At least one variant is required.
    pub fn parse(text: &str, origin: &str) -> Result<Self, VariantError> {
        let doc = DeTable::parse(text).map_err(|e| VariantError::Syntax {
            origin: origin.into(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let cx = Cx { text, origin };
        let Some(arr) = get(doc.get_ref(), "variant") else {
            return Err(cx.err(
                0,
                "",
                "variant".into(),
                "no [[variant]] table: list the variants as [[variant]] tables with a name and \
                 a [variant.set] table of overrides"
                    .into(),
            ));
        };
        let items = match arr.get_ref() {
            DeValue::Array(a) if a.iter().all(|v| v.get_ref().is_table()) => a,
            _ => {
                return Err(cx.err(
                    arr.span().start,
                    "",
                    "variant".into(),
                    "must be [[variant]] tables".into(),
                ));
            }
        };
        let mut list: Vec<Variant> = Vec::new();
        for (i, item) in items.iter().enumerate() {
            let DeValue::Table(t) = item.get_ref() else {
                continue;
            };
            let v = cx.variant(t, i, item.span().start)?;
            if let Some(prev) = list.iter().find(|p| p.name == v.name) {
                return Err(VariantError::Key {
                    origin: origin.into(),
                    line: v.line,
                    variant: v.name.clone(),
                    key: format!("variant[{i}].name"),
                    message: format!("duplicate name (also line {})", prev.line),
                });
            }
            list.push(v);
        }
        Ok(Variants {
            origin: origin.into(),
            list,
        })
    }

    /// The variant named `name`.
    pub fn get(&self, name: &str) -> Option<&Variant> {
        self.list.iter().find(|v| v.name == name)
    }
}

/// The variants file being read.
struct Cx<'a> {
    text: &'a str,
    origin: &'a str,
}

impl Cx<'_> {
    fn line(&self, pos: usize) -> usize {
        line_col(self.text, pos).0
    }

    fn err(&self, pos: usize, variant: &str, key: String, message: String) -> VariantError {
        VariantError::Key {
            origin: self.origin.into(),
            line: self.line(pos),
            variant: variant.into(),
            key,
            message,
        }
    }

    /// One `[[variant]]` table (index `i`, starting at byte `at`).
    fn variant(&self, t: &DeTable, i: usize, at: usize) -> Result<Variant, VariantError> {
        if let Some((k, _)) = t
            .iter()
            .find(|(k, _)| !["name", "description", "set"].contains(&k.get_ref().as_ref()))
        {
            return Err(self.err(
                k.span().start,
                "",
                format!("variant[{i}].{}", k.get_ref()),
                "unknown key (a variant has name, description and set)".into(),
            ));
        }
        let (name, name_at) = match get(t, "name") {
            Some(v) => match v.get_ref() {
                DeValue::String(s) if valid_name(s) => (s.to_string(), v.span().start),
                _ => {
                    return Err(self.err(
                        v.span().start,
                        "",
                        format!("variant[{i}].name"),
                        "must be a non-empty string of at most 64 letters, digits, '-', '_' or \
                         '.' (it names files and columns)"
                            .into(),
                    ));
                }
            },
            None => {
                return Err(self.err(
                    at,
                    "",
                    format!("variant[{i}].name"),
                    "missing: every variant needs a name".into(),
                ));
            }
        };
        let description = match get(t, "description") {
            None => String::new(),
            Some(v) => match v.get_ref() {
                DeValue::String(s) => s.to_string(),
                _ => {
                    return Err(self.err(
                        v.span().start,
                        &name,
                        format!("variant[{i}].description"),
                        "must be a string".into(),
                    ));
                }
            },
        };
        let mut overrides = Vec::new();
        if let Some(s) = get(t, "set") {
            match s.get_ref() {
                DeValue::Table(set) => self.flatten(set, "", &name, &mut overrides)?,
                _ => {
                    return Err(self.err(
                        s.span().start,
                        &name,
                        format!("variant[{i}].set"),
                        "must be a table of key paths and values".into(),
                    ));
                }
            }
        }
        // the same path twice (e.g. `bridge.gap` and a nested `bridge = { gap }`)
        for (j, o) in overrides.iter().enumerate() {
            if let Some(p) = overrides[..j].iter().find(|p| p.path == o.path) {
                return Err(VariantError::Key {
                    origin: self.origin.into(),
                    line: o.line,
                    variant: name,
                    key: o.key.clone(),
                    message: format!("set twice (also line {})", p.line),
                });
            }
        }
        Ok(Variant {
            line: self.line(name_at),
            name,
            description,
            overrides,
        })
    }

    /// The overrides of a `set` table: nested tables are paths; every other value a leaf.
    fn flatten(
        &self,
        set: &DeTable,
        prefix: &str,
        variant: &str,
        out: &mut Vec<Override>,
    ) -> Result<(), VariantError> {
        for (k, v) in set.iter() {
            let key = if prefix.is_empty() {
                k.get_ref().to_string()
            } else {
                format!("{prefix}.{}", k.get_ref())
            };
            if let DeValue::Table(t) = v.get_ref() {
                self.flatten(t, &key, variant, out)?;
                continue;
            }
            let path = parse_path(&key)
                .map_err(|m| self.err(k.span().start, variant, key.clone(), m.to_string()))?;
            out.push(Override {
                key: render_path(&path),
                path,
                value: to_value(v.get_ref()),
                line: self.line(k.span().start),
            });
        }
        Ok(())
    }
}

fn valid_name(s: &str) -> bool {
    !s.is_empty()
        && s.len() <= 64
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
}

/// The value of the entry `key` of a table ([`crate::toml_schema::entry`]).
fn get<'a, 'i>(t: &'a DeTable<'i>, key: &str) -> Option<&'a Spanned<DeValue<'i>>> {
    crate::toml_schema::entry(t, key).map(|(_, v)| v)
}

/// Parses `a.b[2].c` into steps.
pub fn parse_path(key: &str) -> Result<Vec<Step>, &'static str> {
    const BAD: &str = "not a key path: bare keys (letters, digits, '_', '-') joined by '.', an \
                       array element as name[i] (0-based), e.g. bridge.gap or joint[1].gap";
    let mut steps = Vec::new();
    for part in key.split('.') {
        let (name, rest) = match part.find('[') {
            Some(i) => (&part[..i], &part[i..]),
            None => (part, ""),
        };
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        {
            return Err(BAD);
        }
        steps.push(Step::Key(name.to_string()));
        let mut rest = rest;
        while !rest.is_empty() {
            let close = rest.find(']').ok_or(BAD)?;
            let idx: usize = rest[1..close].parse().map_err(|_| BAD)?;
            if !rest.starts_with('[') {
                return Err(BAD);
            }
            steps.push(Step::Index(idx));
            rest = &rest[close + 1..];
        }
    }
    Ok(steps)
}

/// `a.b[2].c` of steps.
pub fn render_path(path: &[Step]) -> String {
    let mut s = String::new();
    for st in path {
        match st {
            Step::Key(k) => {
                if !s.is_empty() {
                    s.push('.');
                }
                s.push_str(k);
            }
            Step::Index(i) => {
                let _ = write!(s, "[{i}]");
            }
        }
    }
    s
}

/// A parsed value as a plain `toml::Value`.
fn to_value(v: &DeValue) -> toml::Value {
    match v {
        DeValue::String(s) => toml::Value::String(s.to_string()),
        DeValue::Integer(i) => i64::from_str_radix(i.as_str(), i.radix())
            .map(toml::Value::Integer)
            .unwrap_or(toml::Value::Float(f64::NAN)),
        DeValue::Float(f) => toml::Value::Float(parse_float(f.as_str())),
        DeValue::Boolean(b) => toml::Value::Boolean(*b),
        DeValue::Datetime(d) => toml::Value::Datetime(*d),
        DeValue::Array(a) => toml::Value::Array(a.iter().map(|x| to_value(x.get_ref())).collect()),
        DeValue::Table(t) => toml::Value::Table(
            t.iter()
                .map(|(k, x)| (k.get_ref().to_string(), to_value(x.get_ref())))
                .collect(),
        ),
    }
}

fn parse_float(s: &str) -> f64 {
    match s.replace('_', "").as_str() {
        "inf" | "+inf" => f64::INFINITY,
        "-inf" => f64::NEG_INFINITY,
        "nan" | "+nan" | "-nan" => f64::NAN,
        t => t.parse().unwrap_or(f64::NAN),
    }
}

#[path = "variant_apply.rs"]
mod apply;
#[path = "variant_locate.rs"]
mod locate;
pub use apply::Applied;
