//! The documentation stays navigable: README.md is at most 200 lines, and every relative link in
//! README.md and docs/**/*.md points to a file that exists (and, for `file.md#anchor`, to a heading
//! of that file whose GitHub-style anchor is `anchor`).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn markdown_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let p = entry.unwrap().path();
        if p.is_dir() {
            markdown_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "md") {
            out.push(p);
        }
    }
}

/// Text outside fenced code blocks and inline code spans.
fn prose(text: &str) -> String {
    let mut out = String::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        let mut in_code = false;
        for c in line.chars() {
            if c == '`' {
                in_code = !in_code;
            } else if !in_code {
                out.push(c);
            }
        }
        out.push('\n');
    }
    out
}

/// Targets of inline links `[text](target)`.
fn link_targets(text: &str) -> Vec<String> {
    let p = prose(text);
    let mut out = Vec::new();
    let mut rest = p.as_str();
    while let Some(i) = rest.find("](") {
        rest = &rest[i + 2..];
        if let Some(j) = rest.find(')') {
            let t = rest[..j]
                .split_whitespace()
                .next()
                .unwrap_or("")
                .to_string();
            out.push(t);
            rest = &rest[j..];
        }
    }
    out
}

/// GitHub-style anchors of a file's headings (lower case, punctuation dropped, spaces to `-`).
fn anchors(text: &str) -> BTreeSet<String> {
    let mut set = BTreeSet::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        }
        if fenced || !line.starts_with('#') {
            continue;
        }
        let title = line.trim_start_matches('#').trim();
        let mut a = String::new();
        for c in title.chars().flat_map(char::to_lowercase) {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                a.push(c);
            } else if c == ' ' {
                a.push('-');
            }
        }
        let mut candidate = a.clone();
        let mut n = 1;
        while set.contains(&candidate) {
            candidate = format!("{a}-{n}");
            n += 1;
        }
        set.insert(candidate);
    }
    set
}

#[test]
fn readme_is_at_most_200_lines() {
    let text = std::fs::read_to_string(repo_root().join("README.md")).unwrap();
    let n = text.lines().count();
    assert!(
        n <= 200,
        "README.md has {n} lines; the limit is 200 (details belong in docs/)"
    );
}

#[test]
fn every_relative_link_in_the_docs_resolves() {
    let root = repo_root();
    let mut files = vec![root.join("README.md")];
    markdown_files(&root.join("docs"), &mut files);
    let mut broken = Vec::new();
    let mut checked = 0;
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for target in link_targets(&text) {
            if target.is_empty() || target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (path, anchor) = match target.split_once('#') {
                Some((p, a)) => (p, Some(a)),
                None => (target.as_str(), None),
            };
            let dest = if path.is_empty() {
                file.clone()
            } else {
                file.parent().unwrap().join(path)
            };
            checked += 1;
            if !dest.exists() {
                broken.push(format!("{}: {target} (no such file)", file.display()));
                continue;
            }
            let is_md = dest.extension().is_some_and(|e| e == "md");
            if let (Some(a), true) = (anchor, is_md) {
                let dtext = std::fs::read_to_string(&dest).unwrap();
                if !anchors(&dtext).contains(a) {
                    broken.push(format!(
                        "{}: {target} (no heading with that anchor)",
                        file.display()
                    ));
                }
            }
        }
    }
    assert!(
        checked > 10,
        "only {checked} relative links found: is the link parser broken?"
    );
    assert!(
        broken.is_empty(),
        "broken relative links:\n{}",
        broken.join("\n")
    );
}
