//! Deterministic output tokens and atomic file writes, shared by every writer.
//!
//! Tokens (project convention): booleans `true`/`false`; finite floats in the shortest form that
//! round-trips (`str::parse::<f64>` gives back the same bits; negative zero is written `0`, equal
//! to it); non-finite floats `inf`, `-inf`, `nan`
//! in CSV and `null` in JSON.

use std::io::Write;

/// `x` with `decimals` decimals for readable tables and messages (`{x:.4}`), never `-0.0000`: a
/// value that rounds to zero is written without a sign.
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => s,
    }
}

/// [`fixed`] for `|x| < 1e6`, exponent form (`1.2346e190`) beyond, and `inf`/`-inf`/`nan` when
/// not finite: a bounded width for the summary line of a diverged run (a closing of 1e300 m
/// printed as 301 digits).
pub fn bounded(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        float_token(x)
    } else if x.abs() < 1e6 {
        fixed(x, decimals)
    } else {
        format!("{x:.4e}")
    }
}

/// The text of a JSON file the tool writes: pretty-printed, negative zeros as `0`, a final line
/// break (`summary.json`, `check.json`, …).
pub fn json_text(mut v: serde_json::Value) -> String {
    json_without_negative_zero(&mut v);
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
    s.push('\n');
    s
}

/// Replaces every negative zero in a JSON tree by `0.0` (a `-0.0` in a report only puzzles a
/// reader; it equals `0`).
pub fn json_without_negative_zero(v: &mut serde_json::Value) {
    use serde_json::Value;
    match v {
        Value::Number(n)
            if n.as_f64() == Some(0.0) && n.as_f64().is_some_and(f64::is_sign_negative) =>
        {
            *v = Value::from(0.0);
        }
        Value::Array(xs) => xs.iter_mut().for_each(json_without_negative_zero),
        Value::Object(m) => m.values_mut().for_each(json_without_negative_zero),
        _ => {}
    }
}
use std::path::{Path, PathBuf};

/// A CSV field: quoted (`"` doubled) when it contains a comma, a quote or a line break.
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Shortest round-trip text of a float for CSV and plain-text outputs.
///
/// Finite values use Rust's shortest round-trip digits, in positional notation for
/// `1e-5 ≤ |x| < 1e16` (and zero), in exponent notation (`1.5e-7`, `2e20`) otherwise, so that
/// tiny or huge values stay short. Non-finite values are `inf`, `-inf` and `nan`. Negative zero
/// is written `0` (it equals `0`; a `-0` only puzzles a reader).
pub fn float_token(x: f64) -> String {
    let mut s = String::new();
    push_float_token(&mut s, x);
    s
}

/// [`float_token`] appended to `out` (no allocation of its own: the writers of large tables).
pub fn push_float_token(out: &mut String, x: f64) {
    use std::fmt::Write;
    if x == 0.0 {
        out.push('0');
    } else if x.is_nan() {
        out.push_str("nan");
    } else if x.is_infinite() {
        out.push_str(if x > 0.0 { "inf" } else { "-inf" });
    } else if (1e-5..1e16).contains(&x.abs()) {
        let _ = write!(out, "{x}");
    } else {
        let _ = write!(out, "{x:e}");
    }
}

/// A float as a JSON value: finite numbers as numbers (shortest round-trip; negative zero as
/// `0.0`), non-finite as `null`.
pub fn json_float(x: f64) -> serde_json::Value {
    serde_json::Number::from_f64(x + 0.0)
        .map(serde_json::Value::Number)
        .unwrap_or(serde_json::Value::Null)
}

/// What an output path names, as far as writing it is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A new path or an existing regular file (or a link to one): replaced atomically.
    Replace,
    /// An existing character device or FIFO (`/dev/null`, `/dev/stdout`, `/dev/full`, a pipe):
    /// written through, never replaced.
    WriteThrough,
}

/// Classifies `path` for writing: a new path or a regular file is [`Target::Replace`]; a
/// character device or a FIFO is [`Target::WriteThrough`]; a directory, a block device or a
/// socket is refused (an error saying what it is), since replacing it would destroy it and writing
/// into it is never what was meant. Symbolic links are followed.
pub fn target_kind(path: &Path) -> std::io::Result<Target> {
    use std::io::{Error, ErrorKind};
    let meta = match std::fs::metadata(path) {
        Ok(m) => m,
        Err(e) if e.kind() == ErrorKind::NotFound => return Ok(Target::Replace),
        Err(e) => return Err(e),
    };
    let ft = meta.file_type();
    if ft.is_file() {
        return Ok(Target::Replace);
    }
    let what = if ft.is_dir() {
        "a directory"
    } else {
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if ft.is_char_device() || ft.is_fifo() {
                return Ok(Target::WriteThrough);
            }
            if ft.is_block_device() {
                "a block device"
            } else if ft.is_socket() {
                "a socket"
            } else {
                "not a regular file"
            }
        }
        #[cfg(not(unix))]
        {
            "not a regular file"
        }
    };
    Err(Error::new(
        ErrorKind::InvalidInput,
        format!("is {what}: refusing to write over it (give a new path or a regular file)"),
    ))
}

/// A temporary file beside `target` (`.NAME.PID.tmp`, in the same directory) that is removed
/// when dropped unless [`TempFile::commit`] renamed it over the target: every error path (and a
/// panic) cleans up after itself.
#[derive(Debug)]
pub struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    done: bool,
}

impl TempFile {
    /// The temporary for `target`: `DIR/.NAME.PID.tmp` (nothing is created yet).
    pub fn new(target: &Path) -> std::io::Result<Self> {
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let name = target.file_name().ok_or_else(|| {
            std::io::Error::new(std::io::ErrorKind::InvalidInput, "path has no file name")
        })?;
        let mut tmp_name = std::ffi::OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".{}.tmp", std::process::id()));
        Ok(Self {
            tmp: dir.join(tmp_name),
            target: target.to_path_buf(),
            done: false,
        })
    }

    /// Path of the temporary file.
    pub fn path(&self) -> &Path {
        &self.tmp
    }

    /// Renames the temporary over the target.
    pub fn commit(mut self) -> std::io::Result<()> {
        std::fs::rename(&self.tmp, &self.target)?;
        self.done = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}

/// Writes `bytes` to `path`.
///
/// A new path or a regular file is written atomically: the data go to a temporary file in the
/// same directory ([`TempFile`]), which is flushed, synced and then renamed over `path`. An
/// interrupted run therefore leaves either the old file or no file, never a half-written one
/// under the final name, and a failed write removes its temporary. A character device or a FIFO
/// (`/dev/null`, `/dev/stdout`, `/dev/full`, a pipe) is written through and never replaced; its
/// write error (e.g. `ENOSPC` from `/dev/full`) is returned. A directory, block device or socket
/// is refused ([`target_kind`]). Errors do not contain the path: callers add it.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if target_kind(path)? == Target::WriteThrough {
        let mut f = std::fs::OpenOptions::new().write(true).open(path)?;
        f.write_all(bytes)?;
        return f.flush();
    }
    let tmp = TempFile::new(path)?;
    let mut f = std::fs::File::create(tmp.path())?;
    f.write_all(bytes)?;
    f.sync_all()?;
    drop(f);
    tmp.commit()
}

/// Name of the advisory lock file that a run holds in its output directory while it writes.
pub const LOCK_FILE: &str = ".pounding.lock";

/// Errors of preparing an output directory.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Another run holds the directory's lock.
    #[error(
        "output directory {dir} is in use by another pounding run (it holds the lock {lock}); \
         wait for that run to end or choose another output directory"
    )]
    Locked {
        /// The output directory.
        dir: PathBuf,
        /// Its lock file.
        lock: PathBuf,
    },
    /// An I/O error on `path`. The cause is part of the message and deliberately not a
    /// `source()` as well: an error chain (`{:#}`) printed it twice ("File exists (os error 17):
    /// File exists (os error 17)").
    #[error("{what} {path}: {cause}")]
    Io {
        /// What was being done ("cannot create output directory").
        what: &'static str,
        /// The file or directory.
        path: PathBuf,
        /// The cause.
        cause: std::io::Error,
    },
}

/// The exclusive lock of an output directory. Dropping it removes the lock file and releases the
/// lock (the operating system also releases it when the process ends, however it ends; a lock
/// file left by a killed run is then free and is taken over).
#[derive(Debug)]
pub struct OutputLock {
    file: Option<std::fs::File>,
    dir: PathBuf,
}

impl OutputLock {
    /// The locked directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}

impl Drop for OutputLock {
    fn drop(&mut self) {
        // Unlink while still holding the lock: a run that opened the old file and locks it after
        // this sees that the path no longer names it and gives up (`lock_output_dir`).
        let _ = std::fs::remove_file(lock_path(&self.dir));
        drop(self.file.take());
    }
}

fn lock_path(dir: &Path) -> PathBuf {
    dir.join(LOCK_FILE)
}

/// Whether the open file `f` is still the file at `path` (not unlinked or replaced).
fn still_linked(f: &std::fs::File, path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (f.metadata(), std::fs::metadata(path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = (f, path);
        true
    }
}

/// Fails with [`OutputError::Locked`] when another process holds the lock of `dir`, and with
/// [`OutputError::Io`] when `dir` or its nearest existing ancestor is not a directory; creates
/// nothing (for an early check, before a long computation, that writes nothing on bad input).
pub fn check_output_dir_free(dir: &Path) -> Result<(), OutputError> {
    // The directory (or the nearest of its ancestors that exists) must be a directory: a regular
    // file there would fail only when the outputs are written, after the whole computation.
    if let Some(file) = dir
        .ancestors()
        .filter(|a| !a.as_os_str().is_empty())
        .find(|a| std::fs::symlink_metadata(a).is_ok())
        .filter(|a| !a.is_dir())
    {
        return Err(OutputError::Io {
            what: "cannot create output directory",
            path: dir.to_path_buf(),
            cause: std::io::Error::other(format!(
                "{} exists and is not a directory",
                file.display()
            )),
        });
    }
    let lock = lock_path(dir);
    let Ok(f) = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .open(&lock)
    else {
        return Ok(()); // no lock file (or unreadable: lock_output_dir reports it)
    };
    match f.try_lock() {
        Err(std::fs::TryLockError::WouldBlock) => Err(OutputError::Locked {
            dir: dir.to_path_buf(),
            lock,
        }),
        _ => Ok(()),
    }
}

/// Creates `dir` (and its parents) if needed and takes the exclusive advisory lock
/// `dir/.pounding.lock` ([`LOCK_FILE`], `flock`), without waiting: a second writer into the same
/// directory gets [`OutputError::Locked`]. Hold the returned lock until every output (and the
/// completion marker) is written; dropping it removes the lock file.
pub fn lock_output_dir(dir: &Path) -> Result<OutputLock, OutputError> {
    let io = |what, path: &Path| {
        let path = path.to_path_buf();
        move |cause| OutputError::Io { what, path, cause }
    };
    std::fs::create_dir_all(dir).map_err(io("cannot create output directory", dir))?;
    let lock = lock_path(dir);
    let locked = || OutputError::Locked {
        dir: dir.to_path_buf(),
        lock: lock.clone(),
    };
    // A few tries: the file may be unlinked by a run that ends between our open and our lock.
    for _ in 0..3 {
        let f = std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create(true)
            .truncate(false)
            .open(&lock)
            .map_err(io("cannot open the lock file", &lock))?;
        match f.try_lock() {
            Ok(()) if still_linked(&f, &lock) => {
                return Ok(OutputLock {
                    file: Some(f),
                    dir: dir.to_path_buf(),
                });
            }
            Ok(()) => continue,
            Err(std::fs::TryLockError::WouldBlock) => return Err(locked()),
            Err(std::fs::TryLockError::Error(e)) => return Err(io("cannot lock", &lock)(e)),
        }
    }
    Err(locked())
}

/// Removes the earlier outputs `names` (files, relative to the locked directory) and the
/// temporaries an interrupted run may have left there (`.NAME.PID.tmp…`), so that a new run never
/// leaves a set of files that mixes two runs. Call it under the lock, before writing anything;
/// write the completion marker last.
pub fn remove_previous_outputs(lock: &OutputLock, names: &[&str]) -> Result<(), OutputError> {
    let remove = |p: &Path| match std::fs::remove_file(p) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(OutputError::Io {
            what: "cannot remove the earlier output",
            path: p.to_path_buf(),
            cause: e,
        }),
        _ => Ok(()),
    };
    for n in names {
        remove(&lock.dir.join(n))?;
    }
    if let Ok(entries) = std::fs::read_dir(&lock.dir) {
        for e in entries.flatten() {
            let name = e.file_name();
            let name = name.to_string_lossy();
            if is_temporary_name(&name) && e.file_type().is_ok_and(|t| t.is_file()) {
                remove(&e.path())?;
            }
        }
    }
    Ok(())
}

/// Whether `name` is a temporary of [`TempFile`]: `.NAME.PID.tmp` (optionally followed by an
/// extension).
pub fn is_temporary_name(name: &str) -> bool {
    let Some(rest) = name.strip_prefix('.') else {
        return false;
    };
    let Some(pos) = rest.rfind(".tmp") else {
        return false;
    };
    let before = &rest[..pos];
    let after = &rest[pos + 4..];
    let pid_ok = before.rsplit_once('.').is_some_and(|(n, pid)| {
        !n.is_empty() && !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit())
    });
    pid_ok && (after.is_empty() || (after.starts_with('.') && !after[1..].contains('.')))
}

/// Whether `path` is `dir` or lies inside it, as the operating system will resolve `path` when
/// it is created: symbolic links are followed, and `..` after a component that does not exist yet
/// (it will be created as a real directory) cancels that component. `dir` must exist.
pub fn path_is_within(path: &Path, dir: &Path) -> std::io::Result<bool> {
    use std::path::Component;
    let dir = std::fs::canonicalize(dir)?;
    let abs = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir()?.join(path)
    };
    let mut resolved = PathBuf::new();
    for c in abs.components() {
        match c {
            Component::Prefix(_) | Component::RootDir => resolved.push(c.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                resolved.pop();
            }
            Component::Normal(name) => {
                resolved.push(name);
                // an existing component may be a link: resolve it (the prefix is canonical)
                if let Ok(p) = std::fs::canonicalize(&resolved) {
                    resolved = p;
                }
            }
        }
    }
    Ok(resolved.starts_with(&dir))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Negative zero is written as zero everywhere a reader sees it: `0` (CSV/text), `0.0`
    /// (JSON), `0.0000` (fixed decimals, also for values that round to zero).
    #[test]
    fn negative_zero_is_written_without_a_sign() {
        assert_eq!(float_token(-0.0), "0");
        assert_eq!(json_float(-0.0).to_string(), "0.0");
        let mut v = serde_json::json!({"a": [-0.0, 1.5, {"b": -0.0}], "c": -2.0});
        json_without_negative_zero(&mut v);
        assert_eq!(v.to_string(), r#"{"a":[0.0,1.5,{"b":0.0}],"c":-2.0}"#);
        assert_eq!(fixed(-0.0, 4), "0.0000");
        assert_eq!(fixed(-3e-7, 4), "0.0000");
        assert_eq!(fixed(-0.00005, 4), "-0.0001");
        assert_eq!(fixed(-2.5, 1), "-2.5");
        assert_eq!(fixed(-0.4, 0), "0");
        assert_eq!(fixed(f64::NAN, 2), "NaN");
    }

    #[test]
    fn tokens_round_trip() {
        assert_eq!("0".parse::<f64>().unwrap(), -0.0);
        for &x in &[
            0.0,
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
