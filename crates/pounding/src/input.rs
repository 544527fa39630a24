//! Reading input files within documented size limits, strict JSON, and the thread-count limit.
//!
//! Every file the tool reads goes through [`read_text`] with the limit of its kind, so that an
//! oversized or endless input (`/dev/zero`, a FIFO that never ends) is refused as bad input after
//! at most `limit + 1` bytes, within seconds and with memory bounded by the limit:
//!
//! | input | limit |
//! |---|---|
//! | scenario file (study, simulate, compare, fragility) | [`SCENARIO_LIMIT`] = 16 MiB |
//! | record set (`fragility --set`: a `.toml` or `.csv` manifest) | [`SCENARIO_LIMIT`] = 16 MiB |
//! | ground-motion record (`.AT2`, `.csv`) | [`RECORD_LIMIT`] = 256 MiB |
//! | LCP file (Siconos `.dat`, `LCPSET 1`) | [`LCP_LIMIT`] = 256 MiB |
//! | impact problem (`impact --problem`, JSON) | [`PROBLEM_LIMIT`] = 16 MiB |
//! | shard manifest (`shard.json`) | [`SHARD_MANIFEST_LIMIT`] = 64 MiB |
//! | shard rows (`rows.csv`) | [`shard_rows_limit`]: 4 KiB per row the manifest declares |
//!
//! JSON inputs are checked for duplicate object keys ([`check_json_duplicate_keys`]): `serde_json`
//! would silently keep the last value, which reads a file differently from what its author meant.

use std::io::Read;
use std::path::Path;

const MIB: u64 = 1 << 20;

/// Largest scenario file (TOML) read: 16 MiB.
pub const SCENARIO_LIMIT: u64 = 16 * MIB;
/// Largest ground-motion record file read: 256 MiB.
pub const RECORD_LIMIT: u64 = 256 * MIB;
/// Largest LCP file (Siconos `.dat` or `LCPSET 1`) read: 256 MiB.
pub const LCP_LIMIT: u64 = 256 * MIB;
/// Largest impact problem (JSON) read: 16 MiB.
pub const PROBLEM_LIMIT: u64 = 16 * MIB;
/// Largest shard manifest (`shard.json`, which embeds the scenario text) read: 64 MiB.
pub const SHARD_MANIFEST_LIMIT: u64 = 64 * MIB;
/// Bytes allowed per row of a shard's `rows.csv` (a row is about 260 bytes).
pub const SHARD_ROW_BYTES: u64 = 4096;

/// Largest worker-thread count accepted by `--threads` (every subcommand that takes it).
pub const MAX_THREADS: usize = 1024;

/// Limit of a shard's `rows.csv` that declares `rows` rows: [`SHARD_ROW_BYTES`] per row plus one
/// (the header).
pub fn shard_rows_limit(rows: u64) -> u64 {
    rows.saturating_add(1).saturating_mul(SHARD_ROW_BYTES)
}

/// A limit in words: `16 MiB`, `4096 bytes`.
pub fn limit_text(limit: u64) -> String {
    if limit >= MIB && limit.is_multiple_of(MIB) {
        format!("{} MiB", limit / MIB)
    } else {
        format!("{limit} bytes")
    }
}

/// Reads the UTF-8 text of `path`, refusing more than `limit` bytes.
///
/// `what` names the kind of file in the error, singular ("scenario file": "the limit for scenario files"). At most `limit + 1` bytes are
/// read ([`Read::take`]), so an endless input (a character device, a FIFO) is refused quickly; a
/// regular file larger than the limit is refused before reading. Directories are refused. The
/// error (an [`std::io::Error`]) does not contain the path: callers add it. A leading
/// byte-order mark (U+FEFF) is removed.
pub fn read_text(path: &Path, what: &str, limit: u64) -> std::io::Result<String> {
    use std::io::{Error, ErrorKind};
    let too_large = || {
        Error::new(
            ErrorKind::InvalidData,
            format!(
                "larger than {}, the limit for {what}s (docs/guide/robustness.md lists the limits)",
                limit_text(limit)
            ),
        )
    };
    let meta = std::fs::metadata(path)?;
    if meta.is_dir() {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            "is a directory, expected a file",
        ));
    }
    if meta.is_file() && meta.len() > limit {
        return Err(too_large());
    }
    let f = std::fs::File::open(path)?;
    let mut buf = Vec::with_capacity(if meta.is_file() {
        meta.len() as usize
    } else {
        0
    });
    f.take(limit.saturating_add(1)).read_to_end(&mut buf)?;
    if buf.len() as u64 > limit {
        return Err(too_large());
    }
    if looks_utf16(&buf) {
        return Err(Error::new(
            ErrorKind::InvalidData,
            "is not UTF-8 text: it looks like UTF-16 (a UTF-16 byte-order mark, or a NUL byte \
             between characters): save it as UTF-8 (e.g. \"CSV UTF-8\" in a spreadsheet)",
        ));
    }
    let mut text = String::from_utf8(buf).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        Error::new(
            ErrorKind::InvalidData,
            format!(
                "is not valid UTF-8 text (invalid byte 0x{:02X} on line {line}, at offset {at}; \
                 Latin-1 or Windows-1252 text? save it as UTF-8)",
                bytes[at]
            ),
        )
    })?;
    // a leading byte-order mark (some editors write one) is not part of the text
    if text.starts_with('\u{feff}') {
        text.drain(..'\u{feff}'.len_utf8());
    }
    Ok(text)
}

/// UTF-16 text: a UTF-16 byte-order mark (`FF FE`, `FE FF`), or NUL bytes in a quarter to three
/// quarters of the first 4 KiB (UTF-16 writes a NUL beside every ASCII character; UTF-8 text
/// has none; a file of only NULs is not text at all and is left to the reader's messages).
fn looks_utf16(buf: &[u8]) -> bool {
    if buf.starts_with(&[0xFF, 0xFE]) || buf.starts_with(&[0xFE, 0xFF]) {
        return true;
    }
    let head = &buf[..buf.len().min(4096)];
    let nul = head.iter().filter(|&&b| b == 0).count();
    nul > 0 && 4 * nul >= head.len() && 4 * nul <= 3 * head.len()
}

/// Checks a `--threads` value against `1 ..= MAX_THREADS` (`None`: all cores, accepted).
pub fn check_threads(threads: Option<usize>) -> Result<(), String> {
    match threads {
        Some(n) if !(1..=MAX_THREADS).contains(&n) => Err(format!(
            "invalid --threads {n}: must lie in [1, {MAX_THREADS}]"
        )),
        _ => Ok(()),
    }
}

/// `message` with the command-line flags `names` (`(flag, name)`, e.g. `("--record-dt",
/// "record_dt")`) replaced by the names another front end gives the same arguments (the Python
/// package's keyword arguments): a flag is replaced only as a whole word (not followed by a
/// letter, digit or `-`), so `--pair` does not touch `--pairs`.
pub fn rename_flags(message: &str, names: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    'scan: while let Some(i) = rest.find("--") {
        out.push_str(&rest[..i]);
        let tail = &rest[i..];
        for (flag, name) in names {
            if let Some(after) = tail.strip_prefix(flag)
                && !after.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '-')
            {
                out.push_str(name);
                rest = after;
                continue 'scan;
            }
        }
        out.push_str("--");
        rest = &tail[2..];
    }
    out.push_str(rest);
    out
}

/// Refuses JSON text in which an object has the same key twice (at any depth).
///
/// The error (from `serde_json`) names the key, line and column, e.g. `duplicate key "mass" at
/// line 4 column 12`. Syntax errors are reported the same way as by `serde_json::from_str`.
pub fn check_json_duplicate_keys(text: &str) -> Result<(), serde_json::Error> {
    use serde::de::{Deserialize, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
    struct Any;
    impl<'de> Deserialize<'de> for Any {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            d.deserialize_any(AnyVisitor)
        }
    }
    struct AnyVisitor;
    impl<'de> Visitor<'de> for AnyVisitor {
        type Value = Any;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("any JSON value")
        }
        fn visit_bool<E>(self, _: bool) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_i64<E>(self, _: i64) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_u64<E>(self, _: u64) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_f64<E>(self, _: f64) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_str<E>(self, _: &str) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_unit<E>(self) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_none<E>(self) -> Result<Any, E> {
            Ok(Any)
        }
        fn visit_some<D: Deserializer<'de>>(self, d: D) -> Result<Any, D::Error> {
            Any::deserialize(d)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Any, A::Error> {
            while seq.next_element::<Any>()?.is_some() {}
            Ok(Any)
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Any, A::Error> {
            let mut keys = std::collections::HashSet::new();
            while let Some(k) = map.next_key::<String>()? {
                if !keys.insert(k.clone()) {
                    return Err(serde::de::Error::custom(format!("duplicate key {k:?}")));
                }
                map.next_value_seed(AnySeed)?;
            }
            Ok(Any)
        }
    }
    struct AnySeed;
    impl<'de> DeserializeSeed<'de> for AnySeed {
        type Value = Any;
        fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Any, D::Error> {
            Any::deserialize(d)
        }
    }
    let mut de = serde_json::Deserializer::from_str(text);
    Any::deserialize(&mut de)?;
    de.end()
}

/// FNV-1a 64-bit hash of `bytes`, as 16 lower-case hex digits (the checksum of a shard's rows).
///
/// `h ← 0xcbf29ce484222325; for each byte b: h ← (h ⊕ b) · 0x100000001b3 (mod 2⁶⁴)`. It detects
/// accidental edits and corruption (any single changed byte changes it); it is not a
/// cryptographic signature.
pub fn fnv1a64_hex(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// `text` with every line longer than `max_chars` characters cut to its first `max_chars`
/// followed by `… (N more characters)`: error messages that quote an input line (a parser's
/// excerpt of a 400 KB line) stay readable. The list of a schema's accepted names that ends a
/// parser's `unknown field `x`, expected one of `a`, `b`, …` line is kept whole (it comes from
/// the program, not the input): only the part before it is cut.
pub fn shorten_lines(text: &str, max_chars: usize) -> String {
    let mut out = String::with_capacity(text.len().min(64 * 1024));
    for (i, line) in text.split('\n').enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let (head, list) = match line.rfind("`, expected one of `") {
            Some(at) if line.starts_with("unknown ") => line.split_at(at + 1),
            _ => (line, ""),
        };
        let n = head.chars().count();
        if n > max_chars {
            out.extend(head.chars().take(max_chars));
            out.push_str(&format!("… ({} more characters)", n - max_chars));
        } else {
            out.push_str(head);
        }
        out.push_str(list);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_are_renamed_as_whole_words_only() {
        let names = [("--pair", "pair"), ("--record-dt", "record_dt")];
        assert_eq!(
            rename_flags("--pairs and --pair X; --record-dt=1, --record-dtx", &names),
            "--pairs and pair X; record_dt=1, --record-dtx"
        );
        assert_eq!(rename_flags("no flags -- here", &names), "no flags -- here");
        assert_eq!(rename_flags("ends with --pair", &names), "ends with pair");
    }

    #[test]
    fn fnv_matches_the_reference_vectors() {
        // Reference values of FNV-1a 64 (Fowler–Noll–Vo test suite).
        assert_eq!(fnv1a64_hex(b""), "cbf29ce484222325");
        assert_eq!(fnv1a64_hex(b"a"), "af63dc4c8601ec8c");
        assert_eq!(fnv1a64_hex(b"foobar"), "85944171f73967e8");
    }

    #[test]
    fn duplicate_keys_are_found_at_any_depth_with_their_line() {
        assert!(check_json_duplicate_keys(r#"{"a": 1, "b": [{"c": 1}, {"c": 2}]}"#).is_ok());
        let e =
            check_json_duplicate_keys("{\"a\": 1,\n \"b\": {\"x\": 1,\n \"x\": 2}}").unwrap_err();
        let m = e.to_string();
        assert!(
            m.contains("duplicate key \"x\"") && m.contains("line 3"),
            "{m}"
        );
        assert!(check_json_duplicate_keys("{\"a\": 1, \"a\": 1}").is_err());
        assert!(check_json_duplicate_keys("{\"a\": 1} x").is_err());
    }
}
