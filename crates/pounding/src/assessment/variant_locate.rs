//! Where a key path lies in a scenario's text: its value's span, or the table and header line a
//! missing key is added under ([`super::Variant::apply`]).

use super::{Step, get, render_path};
use toml::de::{DeTable, DeValue};

pub(super) enum Found {
    /// The value's span.
    Value(usize, usize),
    /// `path[at]` is missing from the table at `path[..table]`.
    Missing { table: usize, at: usize },
}

/// Finds `path` in the base document.
pub(super) fn locate(doc: &DeTable, path: &[Step]) -> Result<Found, String> {
    let mut t = doc;
    let mut j = 0;
    let mut table = 0;
    while j < path.len() {
        let Step::Key(k) = &path[j] else {
            return Err(format!(
                "`{}` is a table, not an array",
                render_path(&path[..j])
            ));
        };
        let Some(v) = get(t, k) else {
            return Ok(Found::Missing { table, at: j });
        };
        let mut v = v;
        j += 1;
        if let (DeValue::Array(a), Some(Step::Index(i))) = (v.get_ref(), path.get(j)) {
            v = a.get(*i).ok_or_else(|| {
                format!(
                    "the base scenario's `{}` has {} entries: index {i} is beyond them (0-based)",
                    render_path(&path[..j]),
                    a.len()
                )
            })?;
            j += 1;
        }
        if j == path.len() {
            return match v.get_ref() {
                DeValue::Table(_) => Err(format!(
                    "`{}` is a table in the base scenario: override its keys one by one",
                    render_path(path)
                )),
                DeValue::Array(a) if !a.is_empty() && a.iter().all(|x| x.get_ref().is_table()) => {
                    Err(format!(
                        "`{}` is an array of tables in the base scenario: override the keys of \
                         its elements (`{}[0].KEY`)",
                        render_path(path),
                        render_path(path)
                    ))
                }
                _ => Ok(Found::Value(v.span().start, v.span().end)),
            };
        }
        match v.get_ref() {
            DeValue::Table(x) => {
                t = x;
                table = j;
            }
            other => {
                return Err(format!(
                    "`{}` is a {} in the base scenario, not a table",
                    render_path(&path[..j]),
                    other.type_str()
                ));
            }
        }
    }
    Ok(Found::Missing {
        table,
        at: path.len(),
    })
}

/// A header line's table path, normalised (`[[ joint ]]` → `(true, "joint")`), or `None`.
fn header(line: &str) -> Option<(bool, String)> {
    let l = line.trim();
    let l = l.split('#').next().unwrap_or("").trim();
    let arr = l.starts_with("[[");
    let inner = l.strip_prefix('[')?.strip_suffix(']')?;
    let inner = if arr {
        inner.strip_prefix('[')?.strip_suffix(']')?
    } else {
        inner
    };
    let name: String = inner
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '"' && *c != '\'')
        .collect();
    Some((arr, name))
}

/// Byte offset just after the header line of the table at `path` (the root: 0), or `None` when
/// the table has no header of its own (defined by dotted keys or inline, or a path this does not
/// handle: at most one array index, on the first key).
pub(super) fn header_end(text: &str, path: &[Step]) -> Option<usize> {
    if path.is_empty() {
        return Some(0);
    }
    let (arr_name, arr_index, rest): (Option<String>, usize, &[Step]) = match path {
        [Step::Key(a), Step::Index(i), rest @ ..] => (Some(a.clone()), *i, rest),
        _ => (None, 0, path),
    };
    let keys: Option<Vec<&str>> = rest
        .iter()
        .map(|s| match s {
            Step::Key(k) => Some(k.as_str()),
            Step::Index(_) => None,
        })
        .collect();
    let keys = keys?;
    let mut offset = 0;
    let mut count = 0usize;
    let mut inside = arr_name.is_none();
    for l in text.split_inclusive('\n') {
        let end = offset + l.len();
        if let Some((is_arr, name)) = header(l) {
            match &arr_name {
                Some(a) if is_arr && &name == a => {
                    inside = count == arr_index;
                    count += 1;
                    if inside && keys.is_empty() {
                        return Some(end);
                    }
                }
                Some(a) => {
                    let want = format!("{a}.{}", keys.join("."));
                    if inside && !is_arr && name == want {
                        return Some(end);
                    }
                    if is_arr && !name.starts_with(&format!("{a}.")) {
                        inside = false;
                    }
                }
                None => {
                    if !is_arr && name == keys.join(".") {
                        return Some(end);
                    }
                }
            }
        }
        offset = end;
    }
    let _ = inside;
    None
}
