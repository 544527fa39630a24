//! Applying a [`Variant`] to a scenario's text: the edits, the merged text and its line map.

use super::locate::{Found, header_end, locate};
use super::{Step, Variant, VariantError, render_path};
use crate::toml_schema::line_col;
use std::fmt::Display;
use toml::de::DeTable;

/// Where a line of the merged text comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Source {
    /// 1-based line of the base scenario.
    Base(usize),
    /// 1-based line of the variants file.
    Variant(usize),
}

/// A scenario's text with a variant's overrides applied.
#[derive(Debug, Clone, PartialEq)]
pub struct Applied {
    /// The merged TOML text (the base's lines, with overridden values replaced in place and added
    /// keys on new lines after their table's header).
    pub text: String,
    /// Per 1-based line of `text` (index `line − 1`): its source.
    lines: Vec<Source>,
}

impl Applied {
    /// Rewrites every `{base_origin}:{line}` of `message` (a message about the merged text read
    /// under the name `base_origin`) to the line's true source: the base's line, or
    /// `{variants_origin}:{line}` for a line holding a variant's value.
    pub fn relabel(&self, message: &str, base_origin: &str, variants_origin: &str) -> String {
        let pat = format!("{base_origin}:");
        let mut out = String::new();
        let mut rest = message;
        while let Some(i) = rest.find(&pat) {
            out.push_str(&rest[..i]);
            let after = &rest[i + pat.len()..];
            let digits = after.chars().take_while(char::is_ascii_digit).count();
            let src = after[..digits]
                .parse::<usize>()
                .ok()
                .and_then(|l| self.lines.get(l.wrapping_sub(1)));
            match src {
                Some(Source::Base(l)) => out.push_str(&format!("{base_origin}:{l}")),
                Some(Source::Variant(l)) => out.push_str(&format!("{variants_origin}:{l}")),
                None => out.push_str(&rest[i..i + pat.len() + digits]),
            }
            rest = &after[digits..];
        }
        out.push_str(rest);
        self.relabel_toml(&out, variants_origin)
    }

    /// The TOML reader's own line references of the merged text: `at line N, column C` and the
    /// `N | text` lines of its excerpt, relabelled to their sources.
    fn relabel_toml(&self, message: &str, variants_origin: &str) -> String {
        let src = |n: &str| {
            n.parse::<usize>()
                .ok()
                .and_then(|l| self.lines.get(l.wrapping_sub(1)))
                .copied()
        };
        let mut out = Vec::new();
        for line in message.split('\n') {
            let mut l = line.to_string();
            if let Some(i) = l.find("at line ") {
                let after = &l[i + 8..];
                let digits: String = after.chars().take_while(char::is_ascii_digit).collect();
                let new = match src(&digits) {
                    Some(Source::Base(b)) => Some(format!("at line {b}")),
                    Some(Source::Variant(v)) => Some(format!("at {variants_origin}:{v}")),
                    None => None,
                };
                if let Some(new) = new {
                    l = format!("{}{new}{}", &l[..i], &after[digits.len()..]);
                }
            }
            let trimmed = l.trim_start();
            let digits: String = trimmed.chars().take_while(char::is_ascii_digit).collect();
            if !digits.is_empty() && trimmed[digits.len()..].starts_with(" |") {
                let pad = l.len() - trimmed.len();
                let n = match src(&digits) {
                    Some(Source::Base(b)) => b.to_string(),
                    Some(Source::Variant(v)) => format!("{variants_origin}:{v}"),
                    None => digits.clone(),
                };
                l = format!("{}{n}{}", &l[..pad], &trimmed[digits.len()..]);
            }
            out.push(l);
        }
        out.join("\n")
    }
}

enum Edit {
    /// Replace `start..end` of the base by `text` (the line of the override: `line`).
    Replace {
        start: usize,
        end: usize,
        text: String,
        line: usize,
    },
    /// Insert the line `key = value` at `at` (a line start).
    Insert {
        at: usize,
        key: String,
        value: toml::Value,
        line: usize,
    },
}

impl Edit {
    fn at(&self) -> usize {
        match self {
            Edit::Replace { start, .. } => *start,
            Edit::Insert { at, .. } => *at,
        }
    }
}

impl Variant {
    /// Applies every override to the scenario text `base` (`variants_origin` names the variants
    /// file in errors). Errors are those of the paths (module documentation); the result is not
    /// checked as a scenario ([`Variant::apply_checked`] does).
    pub fn apply(&self, base: &str, variants_origin: &str) -> Result<Applied, VariantError> {
        self.apply_first(base, variants_origin, self.overrides.len())
    }

    /// Applies the overrides and checks the result with `check` (the caller's reading of a
    /// scenario, e.g. parse, build and validate; it reads the merged text under the base's name
    /// `base_origin`). When `check` fails, the overrides are applied one more at a time to find
    /// the first after which it fails: the error names that override (variants file, variant,
    /// key, its line) and carries `check`'s message with the merged text's lines relabelled to
    /// their sources ([`Applied::relabel`]). A failure already with no override applied (the
    /// base itself) is named as the variant's.
    pub fn apply_checked<E: Display>(
        &self,
        base: &str,
        base_origin: &str,
        variants_origin: &str,
        check: impl Fn(&str) -> Result<(), E>,
    ) -> Result<Applied, VariantError> {
        let all = self.apply(base, variants_origin)?;
        let Err(e) = check(&all.text) else {
            return Ok(all);
        };
        for n in 1..=self.overrides.len() {
            let part = self.apply_first(base, variants_origin, n)?;
            if let Err(e) = check(&part.text) {
                let o = &self.overrides[n - 1];
                return Err(VariantError::Key {
                    origin: variants_origin.into(),
                    line: o.line,
                    variant: self.name.clone(),
                    key: o.key.clone(),
                    message: format!(
                        "{} = {}: {}",
                        o.key,
                        o.value,
                        part.relabel(&e.to_string(), base_origin, variants_origin)
                    ),
                });
            }
        }
        Err(VariantError::Key {
            origin: variants_origin.into(),
            line: self.line,
            variant: self.name.clone(),
            key: "name".into(),
            message: all.relabel(&e.to_string(), base_origin, variants_origin),
        })
    }

    /// The first `n` overrides applied.
    fn apply_first(
        &self,
        base: &str,
        variants_origin: &str,
        n: usize,
    ) -> Result<Applied, VariantError> {
        let doc = DeTable::parse(base).map_err(|e| VariantError::Syntax {
            origin: variants_origin.into(),
            message: format!("the base scenario does not read as TOML: {e}"),
        })?;
        let mut edits: Vec<Edit> = Vec::new();
        for o in &self.overrides[..n] {
            let err = |message: String| VariantError::Key {
                origin: variants_origin.into(),
                line: o.line,
                variant: self.name.clone(),
                key: o.key.clone(),
                message,
            };
            match locate(doc.get_ref(), &o.path).map_err(&err)? {
                Found::Value(start, end) => edits.push(Edit::Replace {
                    start,
                    end,
                    text: o.value.to_string(),
                    line: o.line,
                }),
                Found::Missing { table, at } => {
                    let rest = &o.path[at..];
                    let Some(keys) = rest
                        .iter()
                        .map(|s| match s {
                            Step::Key(k) => Some(k.clone()),
                            Step::Index(_) => None,
                        })
                        .collect::<Option<Vec<String>>>()
                    else {
                        return Err(err(format!(
                            "the base scenario has no `{}`: an array element cannot be added",
                            render_path(&o.path[..at + 1])
                        )));
                    };
                    let offset = header_end(base, &o.path[..table]).ok_or_else(|| {
                        err(format!(
                            "the base scenario has no `{}`, and its table `{}` is not written \
                             under a [header] line there; write the key in the base scenario \
                             (any value) and override it",
                            o.key,
                            render_path(&o.path[..table])
                        ))
                    })?;
                    let value = keys[1..].iter().rev().fold(o.value.clone(), |v, k| {
                        toml::Value::Table([(k.clone(), v)].into_iter().collect())
                    });
                    insert(&mut edits, offset, &keys[0], value, o.line).map_err(err)?;
                }
            }
        }
        Ok(merge(base, edits))
    }
}

/// Adds an insertion, merging it with an earlier one of the same key at the same place.
fn insert(
    edits: &mut Vec<Edit>,
    at: usize,
    key: &str,
    value: toml::Value,
    line: usize,
) -> Result<(), String> {
    for e in edits.iter_mut() {
        if let Edit::Insert {
            at: a,
            key: k,
            value: v,
            ..
        } = e
            && *a == at
            && k == key
        {
            return merge_value(v, value);
        }
    }
    edits.push(Edit::Insert {
        at,
        key: key.into(),
        value,
        line,
    });
    Ok(())
}

fn merge_value(into: &mut toml::Value, add: toml::Value) -> Result<(), String> {
    match (into, add) {
        (toml::Value::Table(a), toml::Value::Table(b)) => {
            for (k, v) in b {
                match a.get_mut(&k) {
                    Some(x) => merge_value(x, v)?,
                    None => {
                        a.insert(k, v);
                    }
                }
            }
            Ok(())
        }
        _ => Err("set twice".into()),
    }
}

/// The merged text of `base` with `edits` and its line map.
fn merge(base: &str, mut edits: Vec<Edit>) -> Applied {
    edits.sort_by_key(Edit::at);
    let mut text = String::with_capacity(base.len() + 64);
    let mut lines: Vec<Option<Source>> = vec![None];
    let push = |text: &mut String,
                lines: &mut Vec<Option<Source>>,
                s: &str,
                src: Source,
                mark_new: bool| {
        for (k, piece) in s.split('\n').enumerate() {
            if k > 0 {
                text.push('\n');
                lines.push(mark_new.then_some(src));
            }
            text.push_str(piece);
            let last = lines.last_mut().expect("one line at least");
            match src {
                Source::Variant(_) if !piece.is_empty() => *last = Some(src),
                Source::Base(l) if last.is_none() => *last = Some(Source::Base(l + k)),
                _ => {}
            }
        }
    };
    let mut pos = 0;
    for e in &edits {
        let start = e.at().max(pos);
        push(
            &mut text,
            &mut lines,
            &base[pos..start],
            Source::Base(line_col(base, pos).0),
            false,
        );
        match e {
            Edit::Replace {
                end, text: t, line, ..
            } => {
                // keep the base's line count: the old value's line breaks follow the new value
                let breaks = base[start..*end].matches('\n').count();
                push(&mut text, &mut lines, t, Source::Variant(*line), false);
                for _ in 0..breaks {
                    push(&mut text, &mut lines, "\n", Source::Variant(*line), true);
                }
                pos = *end;
            }
            Edit::Insert {
                key, value, line, ..
            } => {
                let k = if key
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
                {
                    key.clone()
                } else {
                    toml::Value::String(key.clone()).to_string()
                };
                push(
                    &mut text,
                    &mut lines,
                    &format!("{k} = {value}\n"),
                    Source::Variant(*line),
                    false,
                );
                pos = start;
            }
        }
    }
    push(
        &mut text,
        &mut lines,
        &base[pos..],
        Source::Base(line_col(base, pos).0),
        false,
    );
    let lines = lines
        .into_iter()
        .enumerate()
        .map(|(i, s)| s.unwrap_or(Source::Base(i + 1)))
        .collect();
    Applied { text, lines }
}
