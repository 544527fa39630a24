//! Strict shapes for scenario files read with `serde` and `toml`, and the one locator of keys and
//! lines that every scenario, study, fragility, design and campaign file uses in its error
//! messages: a value read with its span is placed by [`line_col`]; a key known by its name by
//! [`key_span`] (and [`line_of_key`] over it), from the parsed document, never by scanning
//! lines; a parser's error position is named by [`key_on_line`].
//!
//! `serde`'s derived `Deserialize` for a struct accepts a *sequence* as well as a map: the values
//! are taken as the fields in declaration order. In a scenario file that turns a slip of the pen
//! into a silently different model — `theta1_deg = [-1, 0, 1]` (meant as three angles) was read as
//! `{ start = -1, stop = 0, step = 1 }`, and `joint = [0.1, 0.4, 0.5, 0.5]` would set four keys by
//! position. Likewise serde's fixed-size arrays ignore extra elements in some formats, so a bearing
//! point `[0, 1, 2]` lost its third coordinate. The wrappers here refuse both: a table must be
//! written as a table, a fixed-size array must have exactly its length. The error carries the
//! value's span, so the caller's usual `file: line N` message names the key.

use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use std::fmt;
use std::marker::PhantomData;
use std::ops::Range;
use toml::Spanned;
use toml::de::{DeString, DeTable, DeValue};

/// A `T` that may only be written as a TOML table (inline `{ ... }` or a `[section]`), never as
/// an array.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Table<T>(pub T);

impl<T> Table<T> {
    /// The wrapped value.
    pub fn into_inner(self) -> T {
        self.0
    }
}

impl<T> std::ops::Deref for Table<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.0
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Table<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for V<T> {
            type Value = Table<T>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a table (`{ key = value, ... }` or a `[section]`)")
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
                T::deserialize(de::value::MapAccessDeserializer::new(map)).map(Table)
            }
        }
        d.deserialize_map(V(PhantomData))
    }
}

/// `[f64; N]` written as an array of exactly `N` numbers (for `#[serde(deserialize_with)]`-free
/// use as a field type).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exact<const N: usize>(pub [f64; N]);

impl<const N: usize> std::ops::Deref for Exact<N> {
    type Target = [f64; N];
    fn deref(&self) -> &[f64; N] {
        &self.0
    }
}

impl<'de, const N: usize> Deserialize<'de> for Exact<N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<const N: usize>;
        impl<'de, const N: usize> Visitor<'de> for V<N> {
            type Value = Exact<N>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                write!(f, "an array of exactly {N} numbers")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
                let mut out = [0.0; N];
                let mut n = 0;
                while let Some(x) = seq.next_element::<f64>()? {
                    if n < N {
                        out[n] = x;
                    }
                    n += 1;
                }
                if n != N {
                    return Err(de::Error::invalid_length(n, &self));
                }
                Ok(Exact(out))
            }
        }
        d.deserialize_seq(V::<N>)
    }
}

/// 1-based `(line, column)` of byte offset `pos` in `text` (column in characters).
pub fn line_col(text: &str, pos: usize) -> (usize, usize) {
    let pos = floor_char_boundary(text, pos.min(text.len()));
    let before = &text[..pos];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

fn floor_char_boundary(text: &str, mut pos: usize) -> usize {
    while !text.is_char_boundary(pos) {
        pos -= 1;
    }
    pos
}

/// The key written on the line containing byte offset `pos` (the text before `=`), prefixed by
/// its enclosing `[table]` as `table.key`; `None` on a comment, a header or a line without `=`.
pub fn key_on_line(text: &str, pos: usize) -> Option<String> {
    let pos = floor_char_boundary(text, pos.min(text.len()));
    let start = text[..pos].rfind('\n').map_or(0, |i| i + 1);
    let end = text[pos..].find('\n').map_or(text.len(), |i| pos + i);
    let line = &text[start..end];
    let (k, _) = line.split_once('=')?;
    let k = k.trim();
    if k.is_empty() || k.starts_with('#') || k.starts_with('[') {
        return None;
    }
    // Prefix the enclosing `[table]`, if any.
    let table = text[..start].lines().rev().find_map(|l| {
        let l = l.trim();
        l.strip_prefix('[')
            .and_then(|r| r.split(']').next())
            .map(|t| t.trim().to_string())
    });
    Some(match table {
        Some(t) if !t.is_empty() => format!("{t}.{k}"),
        _ => k.to_string(),
    })
}

/// The span of the key at `path` in the TOML `text` (the names of the tables it lies in, then
/// the key itself, each as written, unquoted: `["grid", "bridge.gap"]`), however the file
/// writes it (under a `[table]` header, as a dotted key, in an inline table); `None` when the
/// text does not set it or is not TOML. The one locator of a key by name: every
/// "file:line" of a key that was not read with its own span comes from here.
pub fn key_span(text: &str, path: &[&str]) -> Option<Range<usize>> {
    let doc = DeTable::parse(text).ok()?;
    let mut table = doc.get_ref();
    for (i, name) in path.iter().enumerate() {
        let (key, value) = entry(table, name)?;
        if i + 1 == path.len() {
            return Some(key.span());
        }
        match value.get_ref() {
            DeValue::Table(t) => table = t,
            _ => return None,
        }
    }
    None
}

/// The entry `key` of a parsed table (`toml::de::DeTable`): its key and its value, each with
/// its span.
pub fn entry<'a, 'i>(
    table: &'a DeTable<'i>,
    key: &str,
) -> Option<(&'a Spanned<DeString<'i>>, &'a Spanned<DeValue<'i>>)> {
    table.iter().find(|(k, _)| k.get_ref().as_ref() == key)
}

/// 1-based line on which `key` is written in `[section]` of `text` (`""`: the root table), or
/// `None` when the file does not set it (commented-out keys do not count); [`key_span`].
pub fn line_of_key(text: &str, section: &str, key: &str) -> Option<usize> {
    let path: &[&str] = if section.is_empty() {
        &[key]
    } else {
        &[section, key]
    };
    key_span(text, path).map(|s| line_col(text, s.start).0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Deserialize, Debug, PartialEq)]
    #[serde(deny_unknown_fields)]
    struct R {
        start: f64,
        stop: f64,
    }

    #[derive(Deserialize, Debug)]
    #[serde(deny_unknown_fields)]
    struct Doc {
        r: Option<Table<R>>,
        p: Option<Vec<Exact<2>>>,
    }

    #[test]
    fn table_accepts_tables_only() {
        let d: Doc = toml::from_str("r = { start = 1, stop = 2 }").unwrap();
        assert_eq!(
            d.r.unwrap().0,
            R {
                start: 1.0,
                stop: 2.0
            }
        );
        let d: Doc = toml::from_str("[r]\nstart = 1.0\nstop = 2.0\n").unwrap();
        assert_eq!(
            d.r.unwrap().0,
            R {
                start: 1.0,
                stop: 2.0
            }
        );
        let e = toml::from_str::<Doc>("r = [1.0, 2.0]").unwrap_err();
        assert!(e.message().contains("table"), "{e}");
        assert!(e.span().is_some());
        // Unknown fields are still refused inside the table.
        assert!(toml::from_str::<Doc>("r = { start = 1, stop = 2, step = 3 }").is_err());
    }

    #[test]
    fn locator_finds_keys_and_lines() {
        let t = "a = 1\n[decks]\n# R1 = 3\nR1 = 100.0\n\"R2\" = 5\n[time]\ndt = 1e-3\n";
        assert_eq!(line_of_key(t, "decks", "R1"), Some(4));
        assert_eq!(line_of_key(t, "decks", "R2"), Some(5));
        assert_eq!(line_of_key(t, "decks", "dt"), None);
        assert_eq!(line_of_key(t, "time", "dt"), Some(7));
        assert_eq!(line_of_key(t, "", "a"), Some(1));
        // dotted keys and inline tables are found as well; a key in a string is not a key
        let t2 = "s = \"[decks]\\nR1 = 1\"\ndecks.R1 = 3\ntime = { dt = 1e-3 }\n";
        assert_eq!(line_of_key(t2, "decks", "R1"), Some(2));
        assert_eq!(line_of_key(t2, "time", "dt"), Some(3));
        assert_eq!(
            key_span("[grid]\n\"bridge.gap\" = [1]\n", &["grid", "bridge.gap"]),
            Some(7..19)
        );
        assert_eq!(line_of_key("not toml [", "decks", "R1"), None);
        let pos = t.find("100.0").unwrap();
        assert_eq!(line_col(t, pos), (4, 6));
        assert_eq!(key_on_line(t, pos).as_deref(), Some("decks.R1"));
        assert_eq!(key_on_line(t, 0).as_deref(), Some("a"));
        assert_eq!(key_on_line(t, t.find("# R1").unwrap()), None);
        // offsets past the end or inside a multi-byte character do not panic
        assert_eq!(line_col("é", 1), (1, 1));
        assert_eq!(line_col(t, 10_000).0, 8);
    }

    #[test]
    fn exact_length_arrays() {
        let d: Doc = toml::from_str("p = [[0, 1], [2.5, 3]]").unwrap();
        assert_eq!(d.p.unwrap()[1].0, [2.5, 3.0]);
        for bad in ["p = [[0, 1, 2]]", "p = [[0]]", "p = [[]]"] {
            let e = toml::from_str::<Doc>(bad).unwrap_err();
            assert!(e.message().contains("exactly 2"), "{bad}: {e}");
        }
    }
}
