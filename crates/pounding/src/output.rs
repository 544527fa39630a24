//! Deterministic output tokens and atomic file writes, shared by every writer.
//!
//! Tokens (project convention): booleans `true`/`false`; finite floats in the shortest form that
//! round-trips (`str::parse::<f64>` gives back the same bits); non-finite floats `inf`, `-inf`, `nan`
//! in CSV and `null` in JSON.

use std::io::Write;
use std::path::Path;

/// Shortest round-trip text of a float for CSV and plain-text outputs.
///
/// Finite values use Rust's shortest round-trip digits, in positional notation for
/// `1e-5 ≤ |x| < 1e16` (and zero), in exponent notation (`1.5e-7`, `2e20`) otherwise, so that
/// tiny or huge values stay short. Non-finite values are `inf`, `-inf` and `nan`.
pub fn float_token(x: f64) -> String {
    if x.is_nan() {
        "nan".to_string()
    } else if x.is_infinite() {
        if x > 0.0 {
            "inf".to_string()
        } else {
            "-inf".to_string()
        }
    } else {
        let a = x.abs();
        if a == 0.0 || (1e-5..1e16).contains(&a) {
            format!("{x}")
        } else {
            format!("{x:e}")
        }
    }
}

/// A float as a JSON value: finite numbers as numbers (shortest round-trip), non-finite as `null`.
pub fn json_float(x: f64) -> serde_json::Value {
    serde_json::Number::from_f64(x)
        .map(serde_json::Value::Number)
        .unwrap_or(serde_json::Value::Null)
}

/// Writes `bytes` to `path` atomically: the data go to a temporary file in the same directory,
/// which is flushed, synced and then renamed over `path`. An interrupted run therefore leaves
/// either the old file or no file, never a half-written one under the final name.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    let name = path.file_name().ok_or_else(|| {
        std::io::Error::new(std::io::ErrorKind::InvalidInput, "path has no file name")
    })?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".{}.tmp", std::process::id()));
    let tmp = dir.join(tmp_name);
    let result = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Whether `path` is `dir` or lies inside it, after resolving symbolic links and `..` (`dir` must
/// exist; `path` need not: its longest existing ancestor is resolved and the rest appended).
pub fn path_is_within(path: &Path, dir: &Path) -> std::io::Result<bool> {
    let dir = std::fs::canonicalize(dir)?;
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir()?.join(path)
    };
    // resolve the longest existing ancestor, then append the remaining components
    let mut rest = Vec::new();
    let mut cur = abs.as_path();
    let resolved = loop {
        match std::fs::canonicalize(cur) {
            Ok(p) => break p,
            Err(_) => match (cur.parent(), cur.file_name()) {
                (Some(parent), Some(name)) => {
                    rest.push(name.to_os_string());
                    cur = parent;
                }
                // `..` or the root: resolve lexically from here
                _ => break cur.to_path_buf(),
            },
        }
    };
    let mut full = resolved;
    for c in rest.iter().rev() {
        full.push(c);
    }
    Ok(full.starts_with(&dir))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_round_trip() {
        for &x in &[
            0.0,
            -0.0,
            1.0,
            0.1,
            -2.5,
            1e-7,
            123456.789,
            1e300,
            5e-324,
            f64::MAX,
            0.3 - 0.1,
        ] {
            let t = float_token(x);
            assert_eq!(t.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{t}");
        }
        assert_eq!(float_token(f64::INFINITY), "inf");
        assert_eq!(float_token(f64::NEG_INFINITY), "-inf");
        assert_eq!(float_token(f64::NAN), "nan");
        assert_eq!(float_token(0.5), "0.5");
        assert_eq!(float_token(1e-7), "1e-7");
        assert_eq!(json_float(f64::NAN), serde_json::Value::Null);
    }
}
