//! The two scenario forms are not mixed: a bridge file (`[[segment]]` tables) refuses the
//! two-deck form's tables (`[decks]`, `[bearings]`, `[abutments]`, a single `[joint]` table), and
//! a two-deck file refuses a bridge's (`[bridge]`, `[[joint]]`, `[abutment.start]` /
//! `[abutment.end]`). Each refusal names the table and the line of its header.

use super::ScenarioError;

/// The two-deck form's tables that a bridge file refuses.
const TWO_DECK_ONLY: [&str; 3] = ["decks", "bearings", "abutments"];

/// Refuses a table of the other form (see the module docs); `table` is the parsed `text`.
pub(super) fn refuse_mixed(
    text: &str,
    table: &toml::Table,
    origin: &str,
) -> Result<(), ScenarioError> {
    let err = |message: String| ScenarioError::Syntax {
        origin: origin.to_string(),
        message,
    };
    let is_bridge = table.contains_key("segment");
    if is_bridge {
        if let Some(k) = TWO_DECK_ONLY.iter().find(|k| table.contains_key(**k)) {
            return Err(err(format!(
                "[{k}]{} is the two-deck form's table, refused next to [[segment]]: a bridge file \
                 sets each segment's shape, mass and bearings in its [[segment]] table, the joints \
                 in [[joint]] and the abutments in [abutment.start] / [abutment.end] (see \
                 docs/guide/scenarios.md)",
                at_line(text, k)
            )));
        }
        if table.get("joint").is_some_and(toml::Value::is_table) {
            return Err(err(format!(
                "`[joint]`{} is the two-deck form's; a bridge file uses `[[joint]]` (one table \
                 per joint, from the start) or the joints' defaults in [bridge]",
                at_line(text, "joint")
            )));
        }
        return Ok(());
    }
    if table.contains_key("bridge") {
        return Err(err(format!(
            "a [bridge] table{} needs the bridge's [[segment]] tables (one per segment, from the \
             start); without them this is a two-deck file, which has no [bridge]",
            at_line(text, "bridge")
        )));
    }
    // an array of tables (`[[joint]]`), not a list of numbers (a type error later)
    let joints = matches!(table.get("joint"), Some(toml::Value::Array(a))
        if !a.is_empty() && a.iter().all(toml::Value::is_table));
    let abutment_sides = table
        .get("abutment")
        .and_then(toml::Value::as_table)
        .is_some_and(|t| t.contains_key("start") || t.contains_key("end"));
    let (form, key) = match (joints, abutment_sides) {
        (true, _) => ("[[joint]]", "joint"),
        (false, true) => ("[abutment.start] / [abutment.end]", "abutment"),
        _ => return Ok(()),
    };
    Err(err(format!(
        "{form} tables belong to a bridge file{}: add the bridge's [[segment]] tables (one per \
         segment, from the start); a two-deck file has one [joint] table and an [abutments] table",
        at_line(text, key)
    )))
}

/// ` (line N)` of the first line of `text` that opens table `key` (`[key]`, `[key.…]`,
/// `[[key]]`) or sets it at the top level (`key = …`, `key.sub = …` before any header); empty
/// when none is found (a quoted key, say).
fn at_line(text: &str, key: &str) -> String {
    let mut top = true;
    for (n, line) in text.lines().enumerate() {
        let l: String = line
            .split('#')
            .next()
            .unwrap_or_default()
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect();
        let header = l.trim_start_matches('[');
        if l.starts_with('[') {
            let name = header.split([']', '.']).next().unwrap_or_default();
            if name == key {
                return format!(" (line {})", n + 1);
            }
            top = false;
        } else if top
            && l.strip_prefix(key)
                .is_some_and(|r| r.starts_with('=') || r.starts_with('.'))
        {
            return format!(" (line {})", n + 1);
        }
    }
    String::new()
}

#[cfg(test)]
mod tests {
    use super::at_line;

    #[test]
    fn header_lines_are_found() {
        let text = "# [bridge] in a comment\n[time]\nduration = 1\n[ bridge ]\ngap = 1\n";
        assert_eq!(at_line(text, "bridge"), " (line 4)");
        assert_eq!(at_line("[[joint]]\n", "joint"), " (line 1)");
        assert_eq!(
            at_line("x = 1\n[abutment.start]\n", "abutment"),
            " (line 2)"
        );
        assert_eq!(at_line("bridge.gap = 1\n", "bridge"), " (line 1)");
        assert_eq!(at_line("[time]\nbridge = 1\n", "bridge"), "");
        assert_eq!(at_line("[bridges]\n", "bridge"), "");
    }
}
