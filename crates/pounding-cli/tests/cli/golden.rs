//! Golden tests: the output bytes of the real binary, pinned (see `tests/golden/README.md`).
//!
//! Every case runs one command line of `pounding` (from the workspace root, so that relative paths
//! in the outputs are those a user in a clone would see), collects its output files (except
//! `timing.json`, the one documented non-deterministic file; the wall times of `compare`'s
//! `report.html` between `<!--wall-->` markers are masked) and, where the case says so, its
//! stdout/stderr, and compares them with `crates/pounding-cli/tests/golden/<case>/`:
//! small text files (< 20 kB) are stored in full and compared byte by byte; larger or binary
//! files are stored as size + FNV-1a 64-bit hash, text files also with one hash per block of
//! lines so that a mismatch names the first differing block. A case with several variants (e.g.
//! `--threads 1` and the default thread count) must give the same bytes for each.
//!
//! `POUNDING_BLESS=1 cargo test -p pounding-cli --test cli golden` rewrites the golden data from
//! the current binary (the first variant; the others are still checked against it).

use crate::pounding;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Valid UTF-8 text files smaller than this are stored in full.
const FULL_LIMIT: usize = 20_000;
/// Lines per block hash of a large text file.
const BLOCK_LINES: usize = 100;
/// Placeholder for the case's output directory in an argument list.
const OUT: &str = "{out}";

/// One pinned command line.
struct Case {
    /// Directory under `tests/golden/` (also the case's name in messages).
    name: &'static str,
    /// Arguments of `pounding`, separated by whitespace (none contains a space); [`OUT`] stands
    /// for a fresh temporary output directory. Paths are relative to the workspace root.
    args: &'static str,
    /// Extra arguments appended for each variant; every variant must give the same bytes.
    variants: &'static [&'static str],
    /// Pin stdout (as the pseudo-file `stdout`).
    stdout: bool,
    /// Pin stderr (as the pseudo-file `stderr`); only where it has no timings.
    stderr: bool,
}

const NO_VARIANTS: &[&str] = &[""];
/// The default thread count (all cores), one thread and three (more than this machine's cores).
const THREADS: &[&str] = &["", "--threads 1", "--threads 3"];

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn golden_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden")
}

fn blessing() -> bool {
    std::env::var_os("POUNDING_BLESS").is_some_and(|v| !v.is_empty() && v != "0")
}

/// FNV-1a, 64 bits (no extra dependency; a change detector, not a cryptographic hash).
fn fnv1a64(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

fn is_text(bytes: &[u8]) -> bool {
    !bytes.contains(&0) && std::str::from_utf8(bytes).is_ok()
}

/// Lines including their terminators, so that the blocks cover every byte.
fn lines_of(bytes: &[u8]) -> Vec<&[u8]> {
    bytes.split_inclusive(|&b| b == b'\n').collect()
}

fn block_hashes(bytes: &[u8]) -> Vec<(usize, usize, u64)> {
    let lines = lines_of(bytes);
    lines
        .chunks(BLOCK_LINES)
        .enumerate()
        .map(|(k, chunk)| {
            let first = k * BLOCK_LINES + 1;
            (first, first + chunk.len() - 1, fnv1a64(&chunk.concat()))
        })
        .collect()
}

/// The command line as recorded in the manifest and in messages.
fn command_line(case: &Case, variant: &str) -> String {
    let mut s = String::from("pounding");
    for a in case
        .args
        .split_whitespace()
        .chain(variant.split_whitespace())
    {
        s.push(' ');
        s.push_str(&a.replace(OUT, "OUT"));
    }
    s
}

/// Runs one variant; returns the exit code and the pinned files (path relative to the output
/// directory, `/`-separated).
fn run(case: &Case, variant: &str) -> (i32, BTreeMap<String, Vec<u8>>) {
    let tag = variant.replace(['-', ' '], "");
    let scratch = crate::scratch_dir("golden", &format!("{}-{tag}", case.name));
    let out = scratch.join("out");
    let args: Vec<String> = case
        .args
        .split_whitespace()
        .chain(variant.split_whitespace())
        .map(|a| a.replace(OUT, out.to_str().unwrap()))
        .collect();
    // A file inside the output directory (`lcp solve --out`): the directory must exist.
    if case.args.contains("{out}/") {
        std::fs::create_dir_all(&out).unwrap();
    }
    let o = pounding()
        .current_dir(workspace_root())
        .args(&args)
        .output()
        .unwrap();
    let code = o.status.code().unwrap_or(-1);
    let mut files = BTreeMap::new();
    if case.stdout {
        files.insert("stdout".to_owned(), o.stdout);
    }
    if case.stderr {
        files.insert("stderr".to_owned(), o.stderr.clone());
    }
    if out.is_dir() {
        collect(&out, &out, &mut files);
    }
    if code != 0 && code != 1 {
        panic!(
            "golden case {}: `{}` exited with {code}:\n{}",
            case.name,
            command_line(case, variant),
            String::from_utf8_lossy(&o.stderr)
        );
    }
    (code, files)
}

fn collect(root: &Path, dir: &Path, files: &mut BTreeMap<String, Vec<u8>>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            collect(root, &p, files);
            continue;
        }
        let rel = p.strip_prefix(root).unwrap();
        let rel: Vec<_> = rel
            .iter()
            .map(|c| c.to_string_lossy().into_owned())
            .collect();
        let rel = rel.join("/");
        // The only documented non-deterministic output (wall times).
        if rel == "timing.json" {
            continue;
        }
        let bytes = std::fs::read(&p).unwrap();
        let bytes = if rel.ends_with(".html") {
            mask_wall_times(bytes)
        } else {
            bytes
        };
        files.insert(rel, bytes);
    }
}

/// A report's wall times (`compare`'s `report.html`: each between `<!--wall-->` and
/// `<!--/wall-->`, the page's only non-deterministic bytes) replaced by `…`.
fn mask_wall_times(bytes: Vec<u8>) -> Vec<u8> {
    const OPEN: &str = "<!--wall-->";
    const CLOSE: &str = "<!--/wall-->";
    let Ok(text) = String::from_utf8(bytes.clone()) else {
        return bytes;
    };
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_str();
    while let Some(i) = rest.find(OPEN) {
        let after = &rest[i + OPEN.len()..];
        let Some(j) = after.find(CLOSE) else { break };
        out.push_str(&rest[..i + OPEN.len()]);
        out.push('…');
        out.push_str(CLOSE);
        rest = &after[j + CLOSE.len()..];
    }
    out.push_str(rest);
    out.into_bytes()
}

/// What the manifest records about one file.
#[derive(Debug, PartialEq)]
struct Entry {
    size: usize,
    hash: u64,
    /// Stored in full under `files/`.
    full: bool,
    /// Line count and block hashes (large text files only).
    lines: Option<usize>,
    blocks: Vec<(usize, usize, u64)>,
}

fn entry_of(bytes: &[u8]) -> Entry {
    let text = is_text(bytes);
    let full = text && bytes.len() < FULL_LIMIT;
    let big_text = text && !full;
    Entry {
        size: bytes.len(),
        hash: fnv1a64(bytes),
        full,
        lines: big_text.then(|| lines_of(bytes).len()),
        blocks: if big_text {
            block_hashes(bytes)
        } else {
            Vec::new()
        },
    }
}

fn write_manifest(case: &Case, command: &str, code: i32, files: &BTreeMap<String, Vec<u8>>) {
    let dir = golden_root().join(case.name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut m = String::new();
    writeln!(
        m,
        "# Golden outputs of one `pounding` run (see ../README.md; never edit by hand)."
    )
    .unwrap();
    writeln!(m, "command: {command}").unwrap();
    writeln!(m, "exit: {code}").unwrap();
    for (path, bytes) in files {
        let e = entry_of(bytes);
        let kind = if e.full {
            "full"
        } else if e.lines.is_some() {
            "text"
        } else {
            "binary"
        };
        write!(m, "file {path} {} {:016x} {kind}", e.size, e.hash).unwrap();
        if let Some(n) = e.lines {
            write!(m, " {n}").unwrap();
        }
        m.push('\n');
        for (a, b, h) in &e.blocks {
            writeln!(m, "  {a}-{b} {h:016x}").unwrap();
        }
        if e.full {
            let p = dir.join("files").join(path);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(p, bytes).unwrap();
        }
    }
    std::fs::write(dir.join("MANIFEST"), m).unwrap();
}

/// The parsed manifest: command, exit code, entries.
type Manifest = (String, i32, BTreeMap<String, Entry>);

fn read_manifest(case: &Case) -> Result<Manifest, String> {
    let path = golden_root().join(case.name).join("MANIFEST");
    let text = std::fs::read_to_string(&path).map_err(|e| {
        format!(
            "no golden data for case {} ({}: {e}); create it with \
             POUNDING_BLESS=1 cargo test -p pounding-cli --test cli golden",
            case.name,
            path.display()
        )
    })?;
    let bad = |n: usize, l: &str| format!("{}:{}: malformed line {l:?}", path.display(), n + 1);
    let (mut command, mut code) = (String::new(), 0);
    let mut entries: BTreeMap<String, Entry> = BTreeMap::new();
    let mut last: Option<String> = None;
    for (n, l) in text.lines().enumerate() {
        if l.starts_with('#') || l.is_empty() {
            continue;
        }
        if let Some(c) = l.strip_prefix("command: ") {
            command = c.to_owned();
        } else if let Some(c) = l.strip_prefix("exit: ") {
            code = c.parse().map_err(|_| bad(n, l))?;
        } else if let Some(rest) = l.strip_prefix("file ") {
            let w: Vec<&str> = rest.split(' ').collect();
            if w.len() < 4 {
                return Err(bad(n, l));
            }
            let e = Entry {
                size: w[1].parse().map_err(|_| bad(n, l))?,
                hash: u64::from_str_radix(w[2], 16).map_err(|_| bad(n, l))?,
                full: w[3] == "full",
                lines: match w.get(4) {
                    Some(x) => Some(x.parse().map_err(|_| bad(n, l))?),
                    None => None,
                },
                blocks: Vec::new(),
            };
            entries.insert(w[0].to_owned(), e);
            last = Some(w[0].to_owned());
        } else if let Some(rest) = l.strip_prefix("  ") {
            let (range, h) = rest.split_once(' ').ok_or_else(|| bad(n, l))?;
            let (a, b) = range.split_once('-').ok_or_else(|| bad(n, l))?;
            let e = last
                .as_ref()
                .and_then(|k| entries.get_mut(k))
                .ok_or_else(|| bad(n, l))?;
            e.blocks.push((
                a.parse().map_err(|_| bad(n, l))?,
                b.parse().map_err(|_| bad(n, l))?,
                u64::from_str_radix(h, 16).map_err(|_| bad(n, l))?,
            ));
        } else {
            return Err(bad(n, l));
        }
    }
    Ok((command, code, entries))
}

fn shorten(s: &str) -> String {
    const MAX: usize = 400;
    if s.chars().count() <= MAX {
        s.to_owned()
    } else {
        let t: String = s.chars().take(MAX).collect();
        format!("{t}… ({} chars)", s.chars().count())
    }
}

/// The first differing line of two texts, with both versions (around the first differing
/// character when the line is long) and, for comma-separated lines, the column.
fn first_diff(old: &[u8], new: &[u8]) -> String {
    let (a, b) = (lines_of(old), lines_of(new));
    for k in 0..a.len().max(b.len()) {
        let (x, y) = (a.get(k), b.get(k));
        if x == y {
            continue;
        }
        let text = |l: Option<&&[u8]>| {
            l.map(|l| String::from_utf8_lossy(l).trim_end_matches('\n').to_owned())
        };
        let (x, y) = (text(x), text(y));
        // Character index of the first difference, and the field (column) it falls in.
        let (xs, ys) = (x.as_deref().unwrap_or(""), y.as_deref().unwrap_or(""));
        let at = xs
            .chars()
            .zip(ys.chars())
            .take_while(|(p, q)| p == q)
            .count();
        let column = ys.chars().take(at).filter(|&c| c == ',').count() + 1;
        let start = at.saturating_sub(60);
        let show = |l: &Option<String>| match l {
            None => "<end of file>".to_owned(),
            Some(l) if start > 0 => {
                format!("…{}", shorten(&l.chars().skip(start).collect::<String>()))
            }
            Some(l) => shorten(l),
        };
        let col = if ys.contains(',') || xs.contains(',') {
            format!(", column {column}")
        } else {
            String::new()
        };
        return format!(
            "first difference at line {}{col}, character {}:\n      golden: {}\n      now:    {}",
            k + 1,
            at + 1,
            show(&x),
            show(&y)
        );
    }
    "identical lines".to_owned()
}

/// Tokens of a text: runs separated by whitespace, `,`, `:`, brackets, braces and quotes.
fn tokens(text: &str) -> Vec<&str> {
    text.split(|c: char| c.is_whitespace() || ",:[]{}\"".contains(c))
        .filter(|t| !t.is_empty())
        .collect()
}

/// Compares two texts number by number: when they have the same tokens except for numbers, the
/// largest absolute and relative difference of those numbers (how far a change is from rounding);
/// otherwise the first token that differs in kind.
fn numeric_diff(old: &[u8], new: &[u8]) -> String {
    let (a, b) = (String::from_utf8_lossy(old), String::from_utf8_lossy(new));
    let (ta, tb) = (tokens(&a), tokens(&b));
    if ta.len() != tb.len() {
        return format!(
            "not a numbers-only change: {} tokens, golden {}",
            tb.len(),
            ta.len()
        );
    }
    let (mut n, mut changed, mut abs, mut rel) = (0usize, 0usize, 0.0f64, 0.0f64);
    for (x, y) in ta.iter().zip(&tb) {
        match (x.parse::<f64>(), y.parse::<f64>()) {
            (Ok(u), Ok(v)) => {
                n += 1;
                if u.to_bits() != v.to_bits() && !(u.is_nan() && v.is_nan()) {
                    changed += 1;
                    let d = (u - v).abs();
                    abs = abs.max(d);
                    rel = rel.max(d / u.abs().max(v.abs()).max(f64::MIN_POSITIVE));
                }
            }
            _ if x == y => {}
            _ => return format!("not a numbers-only change: token {y:?}, golden {x:?}"),
        }
    }
    format!(
        "numbers only: {changed} of {n} numbers differ, max |Δ| = {abs:e}, max relative Δ = {rel:e}"
    )
}

/// `POUNDING_GOLDEN_DUMP=DIR`: also write each case's outputs to `DIR/<case>/` (e.g. from the
/// commit before a refactor, to compare with `POUNDING_GOLDEN_REFERENCE`).
fn dump(case: &Case, files: &BTreeMap<String, Vec<u8>>) {
    let Some(dir) = std::env::var_os("POUNDING_GOLDEN_DUMP") else {
        return;
    };
    let dir = PathBuf::from(dir).join(case.name);
    let _ = std::fs::remove_dir_all(&dir);
    for (path, bytes) in files {
        let p = dir.join(path);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}

/// `POUNDING_GOLDEN_REFERENCE=DIR` (a `POUNDING_GOLDEN_DUMP` of an earlier build): the full copy
/// of a file the manifest stores only as hashes.
fn reference_copy(case: &Case, path: &str) -> Option<Vec<u8>> {
    let dir = std::env::var_os("POUNDING_GOLDEN_REFERENCE")?;
    std::fs::read(PathBuf::from(dir).join(case.name).join(path)).ok()
}

/// Compares one variant's files with the manifest; returns the problems found.
fn compare_files(
    case: &Case,
    (command, code, entries): &Manifest,
    got_code: i32,
    files: &BTreeMap<String, Vec<u8>>,
) -> Vec<String> {
    let mut errs = Vec::new();
    if *code != got_code {
        errs.push(format!("exit status {got_code}, golden {code}"));
    }
    for path in entries.keys().filter(|p| !files.contains_key(*p)) {
        errs.push(format!("{path}: not written any more (golden has it)"));
    }
    for (path, bytes) in files {
        let Some(g) = entries.get(path) else {
            errs.push(format!("{path}: new output file, not in the golden data"));
            continue;
        };
        let now = entry_of(bytes);
        if g.full {
            let stored = golden_root().join(case.name).join("files").join(path);
            let Ok(old) = std::fs::read(&stored) else {
                errs.push(format!(
                    "{path}: the golden copy {} is missing",
                    stored.display()
                ));
                continue;
            };
            if old != *bytes {
                let mut msg = format!(
                    "{path}: {} bytes, golden {} bytes; {}",
                    bytes.len(),
                    old.len(),
                    first_diff(&old, bytes)
                );
                if is_text(&old) {
                    write!(msg, "\n    {}", numeric_diff(&old, bytes)).unwrap();
                }
                errs.push(msg);
            }
        } else if g.size != now.size || g.hash != now.hash {
            let mut msg = format!(
                "{path}: {} bytes, hash {:016x}; golden {} bytes, hash {:016x}",
                now.size, now.hash, g.size, g.hash
            );
            if let (Some(gl), Some(nl)) = (g.lines, now.lines) {
                write!(msg, "; {nl} lines, golden {gl}").unwrap();
                let lines = lines_of(bytes);
                if let Some((a, b, _)) = now
                    .blocks
                    .iter()
                    .zip(&g.blocks)
                    .find(|(x, y)| x != y)
                    .map(|(x, _)| x)
                    .or_else(|| now.blocks.get(g.blocks.len()))
                {
                    write!(
                        msg,
                        "; first differing block: lines {a}-{b} (golden stores only hashes of this \
                         file); it now starts with: {}",
                        shorten(String::from_utf8_lossy(lines[a - 1]).trim_end_matches('\n'))
                    )
                    .unwrap();
                }
            } else if !is_text(bytes) {
                msg.push_str(" (binary file)");
            }
            match reference_copy(case, path) {
                Some(old) if is_text(bytes) => {
                    write!(
                        msg,
                        "\n    against POUNDING_GOLDEN_REFERENCE: {}\n    {}",
                        first_diff(&old, bytes),
                        numeric_diff(&old, bytes)
                    )
                    .unwrap();
                }
                _ if is_text(bytes) => msg.push_str(
                    "\n    (to see the lines and the size of the change: POUNDING_GOLDEN_DUMP=DIR \
                     with the old build, then POUNDING_GOLDEN_REFERENCE=DIR with the new one)",
                ),
                _ => {}
            }
            errs.push(msg);
        }
    }
    let _ = command;
    errs
}

/// Runs every variant of every case and checks (or, with `POUNDING_BLESS=1`, rewrites) the golden
/// data; panics with every mismatch found.
fn check(cases: &[Case]) {
    let mut failures = Vec::new();
    for case in cases {
        let variants = if case.variants.is_empty() {
            NO_VARIANTS
        } else {
            case.variants
        };
        let command = command_line(case, variants[0]);
        if blessing() {
            let (code, files) = run(case, variants[0]);
            write_manifest(case, &command, code, &files);
            eprintln!("blessed golden case {} ({command})", case.name);
        }
        let manifest = match read_manifest(case) {
            Ok(m) => m,
            Err(e) => {
                failures.push(e);
                continue;
            }
        };
        if manifest.0 != command {
            failures.push(format!(
                "golden case {}: the golden data was recorded for `{}`, the test runs `{command}`; \
                 bless it",
                case.name, manifest.0
            ));
            continue;
        }
        for (k, variant) in variants.iter().enumerate() {
            let (code, files) = run(case, variant);
            if k == 0 {
                dump(case, &files);
            }
            let errs = compare_files(case, &manifest, code, &files);
            if !errs.is_empty() {
                let mut msg = format!(
                    "golden case {}: `{}` differs from tests/golden/{}:",
                    case.name,
                    command_line(case, variant),
                    case.name
                );
                for e in errs {
                    write!(msg, "\n  - {e}").unwrap();
                }
                failures.push(msg);
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{}\n\nIf the change is intended, bless it: POUNDING_BLESS=1 cargo test -p pounding-cli \
         --test cli golden, and say in the commit message which bytes changed and why \
         (crates/pounding-cli/tests/golden/README.md).",
        failures.join("\n\n")
    );
}

macro_rules! input {
    ($f:literal) => {
        concat!("crates/pounding-cli/tests/golden/inputs/", $f)
    };
}

/// A case pinning the files of the output directory.
const fn case(name: &'static str, args: &'static str) -> Case {
    Case {
        name,
        args,
        variants: NO_VARIANTS,
        stdout: false,
        stderr: false,
    }
}

/// A case pinning stdout (and the output directory, if any).
const fn stdout_case(name: &'static str, args: &'static str) -> Case {
    Case {
        stdout: true,
        ..case(name, args)
    }
}

/// `study` on `examples/small.toml` (bounds, summaries, scenario, report, every figure) for the
/// default thread count, 1 and 3 threads; with `--svg`; the straight/skew example without
/// figures; the `--print-default` text.
fn study_cases() -> Vec<Case> {
    vec![
        Case {
            variants: THREADS,
            ..case("study-small", "study examples/small.toml --out {out}")
        },
        case(
            "study-small-svg",
            "study examples/small.toml --svg --threads 2 --out {out}",
        ),
        case(
            "study-straight-no-figures",
            "study examples/straight-study.toml --no-figures --out {out}",
        ),
        stdout_case("study-print-default", "study --print-default"),
    ]
}

/// `simulate` on the built-in default (rigid law), the two 1-D examples, skew decks with
/// abutments and one record with a scale: every output file (history, impacts, summary,
/// figures); the `--print-default` text.
fn simulate_cases() -> Vec<Case> {
    vec![
        case("simulate-default", "simulate --out {out}"),
        case(
            "simulate-straight-1d",
            "simulate examples/straight-1d.toml --out {out}",
        ),
        case(
            "simulate-opensees-1d",
            "simulate examples/opensees-1d.toml --out {out}",
        ),
        case(
            "simulate-skew-abutments",
            concat!("simulate ", input!("skew-abutments.toml"), " --out {out}"),
        ),
        case(
            "simulate-record-scale",
            "simulate --record data/records/RSN6_IMPVALL.I_I-ELC270-hor2.AT2 --scale 1.5 --out {out}",
        ),
        stdout_case("simulate-print-default", "simulate --print-default"),
    ]
}

/// `simulate` on the default bridge with each compliance law at its default parameters (the rigid
/// law is `simulate-default`).
fn simulate_laws_cases() -> Vec<Case> {
    vec![
        case(
            "law-kelvin",
            concat!("simulate ", input!("law-kelvin.toml"), " --out {out}"),
        ),
        case(
            "law-hertz",
            concat!("simulate ", input!("law-hertz.toml"), " --out {out}"),
        ),
        case(
            "law-hertz-damp",
            concat!("simulate ", input!("law-hertz-damp.toml"), " --out {out}"),
        ),
        case(
            "law-bilinear",
            concat!("simulate ", input!("law-bilinear.toml"), " --out {out}"),
        ),
        case(
            "law-jankowski",
            concat!("simulate ", input!("law-jankowski.toml"), " --out {out}"),
        ),
    ]
}

/// `compare` with its default six laws on the default bridge, and three laws with `--dt` on the
/// OpenSees example.
fn compare_cases() -> Vec<Case> {
    vec![
        case("compare-default", "compare --out {out}"),
        case(
            "compare-opensees-1d",
            "compare examples/opensees-1d.toml --laws rigid,bilinear,kelvin --dt 2e-4 --out {out}",
        ),
    ]
}

/// Batch mode: both repository records × two scales, default/1/3 threads.
fn batch_cases() -> Vec<Case> {
    vec![Case {
        variants: THREADS,
        ..case(
            "batch",
            "simulate --records data/records --scales 0.5,1 --out {out}",
        )
    }]
}

/// `impact --json` in every form, and the readable summary of three.
fn impact_cases() -> Vec<Case> {
    vec![
        // The README's example (spec §15 row 1, per unit ρt).
        stdout_case(
            "impact-bridge",
            "impact --r1 100 --r2 100 --beta1 60 --beta2 60 --theta1 -5 --theta2 2 \
             --case deck1-inner --mu 0.5 --eps 0.5 --thickness 1 --density 1 --ratio 0.5 --json",
        ),
        stdout_case(
            "impact-bridge-opening",
            "impact --r1 200 --r2 100 --beta1 90 --beta2 60 --theta1 3 --theta2 -4 \
             --case deck2-outer --mu 1 --eps 0.5 --sigma-mode end --opening 1 --ratio -2 --json",
        ),
        stdout_case(
            "impact-bridge-overlap",
            "impact --r1 200 --r2 100 --beta1 90 --beta2 60 --theta1 3 --theta2 -4 \
             --case deck2-outer --mu 1 --eps 0.5 --opening 0.05 --json",
        ),
        stdout_case(
            "impact-bridge-degenerate",
            "impact --r1 100 --r2 100 --beta1 60 --beta2 60 --theta1 3 --theta2 3 \
             --case deck1-inner --mu 0.5 --eps 0.5 --json",
        ),
        stdout_case(
            "impact-bridge-text",
            "impact --r1 100 --r2 100 --beta1 60 --beta2 60 --theta1 -5 --theta2 2 \
             --case deck1-inner --mu 0.5 --eps 0.5 --ratio 0.5 --opening 0.1",
        ),
        stdout_case(
            "impact-straight-joint",
            "impact --shape straight --length 30 --length2 50 --mu 0.3 --eps 0.5 --json",
        ),
        stdout_case(
            "impact-skew-joint",
            "impact --shape skew --length 30 --length2 50 --skew 30 --mu 0 --eps 0.5 --json",
        ),
        stdout_case(
            "impact-skew-abutment",
            "impact --shape skew --length 30 --width 10 --skew 30 --abutment --mu 0 --eps 0.5 \
             --speed 2 --gap 0.05 --json",
        ),
        stdout_case(
            "impact-skew-abutment-corner",
            "impact --shape skew --length 30 --skew 30 --abutment --corner acute --mu 0.5 \
             --eps 0.5 --ratio 0.2 --json",
        ),
        stdout_case(
            "impact-skew-abutment-text",
            "impact --shape skew --length 30 --width 10 --skew 30 --abutment --mu 0 --eps 0.5",
        ),
        stdout_case(
            "impact-straight-abutment",
            "impact --shape straight --length 30 --abutment --mu 0.3 --eps 0.5 --json",
        ),
        stdout_case(
            "impact-curved-abutment",
            "impact --r1 100 --beta1 90 --abutment --mu 0 --eps 0.5 --json",
        ),
        stdout_case(
            "impact-problem-disc",
            concat!("impact --problem ", input!("disc.json"), " --json"),
        ),
        stdout_case(
            "impact-problem-double",
            concat!("impact --problem ", input!("double.json"), " --json"),
        ),
        stdout_case(
            "impact-problem-disc-text",
            concat!("impact --problem ", input!("disc.json")),
        ),
    ]
}

/// `lcp solve` with both solvers on the LCPSET sample and three small Siconos `.dat` files
/// (dense, sparse-block, and a bimatrix game with three solutions on which Lemke ends on a ray),
/// stdout and the stderr count line; and `--out`.
fn lcp_cases() -> Vec<Case> {
    let c = |name: &'static str, args: &'static str| Case {
        stderr: true,
        ..stdout_case(name, args)
    };
    vec![
        c(
            "lcp-sample-lemke",
            "lcp solve crates/pounding/tests/data/lcp_problems_sample.txt",
        ),
        c(
            "lcp-sample-enum",
            "lcp solve crates/pounding/tests/data/lcp_problems_sample.txt --solver enum",
        ),
        c(
            "lcp-dense3-lemke",
            concat!("lcp solve ", input!("dense3.dat")),
        ),
        c(
            "lcp-dense3-enum",
            concat!("lcp solve ", input!("dense3.dat"), " --solver enum"),
        ),
        c(
            "lcp-block4-lemke",
            concat!("lcp solve ", input!("block4.dat")),
        ),
        c(
            "lcp-block4-enum",
            concat!("lcp solve ", input!("block4.dat"), " --solver enum"),
        ),
        c(
            "lcp-multi4-lemke",
            concat!("lcp solve ", input!("multi4.dat")),
        ),
        c(
            "lcp-multi4-enum",
            concat!("lcp solve ", input!("multi4.dat"), " --solver enum"),
        ),
        Case {
            stdout: false,
            ..c(
                "lcp-sample-out",
                "lcp solve crates/pounding/tests/data/lcp_problems_sample.txt --out {out}/sol.txt",
            )
        },
    ]
}

/// Every directory under `tests/golden/` belongs to a case of this module (no stale data after a
/// case is renamed or removed), and the inputs the cases use exist.
#[test]
fn no_stale_golden_data() {
    let known: Vec<&str> = [
        study_cases(),
        simulate_cases(),
        simulate_laws_cases(),
        compare_cases(),
        batch_cases(),
        impact_cases(),
        lcp_cases(),
    ]
    .iter()
    .flatten()
    .map(|c| c.name)
    .collect();
    let mut stale = Vec::new();
    for e in std::fs::read_dir(golden_root()).unwrap() {
        let e = e.unwrap();
        let name = e.file_name().to_string_lossy().into_owned();
        if e.path().is_dir() && name != "inputs" && !known.contains(&name.as_str()) {
            stale.push(name);
        }
    }
    assert!(
        stale.is_empty(),
        "golden directories of no case (remove them): {stale:?}"
    );
    assert!(workspace_root().join(input!("disc.json")).is_file());
}

#[test]
fn study() {
    check(&study_cases());
}

#[test]
fn simulate() {
    check(&simulate_cases());
}

#[test]
fn simulate_laws() {
    check(&simulate_laws_cases());
}

#[test]
fn compare() {
    check(&compare_cases());
}

#[test]
fn batch() {
    check(&batch_cases());
}

#[test]
fn impact() {
    check(&impact_cases());
}

#[test]
fn lcp() {
    check(&lcp_cases());
}
