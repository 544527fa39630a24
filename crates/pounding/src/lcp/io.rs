//! LCP file formats.
//!
//! * **Siconos `.dat`** ([`parse_siconos`], [`read_siconos`]): whitespace-separated
//!   `n, storageType, size0, size1, <matrix body>, q₀ … q_{n−1}`, anything after `q` ignored.
//!   Dense body (`storageType = 0`): a line `size0 size1`, then `size0·size1` numbers in
//!   **column-major** order (each printed line is a column of `M`). Sparse-block body
//!   (`storageType = 1`): `nbblocks, blocknumber0, blocknumber1`, the cumulative block-row and
//!   block-column sizes, `filled1 (= blocknumber0 + 1), filled2 (= nbblocks)`, the CSR row pointers
//!   over blocks, the block-column index of each block, then per block its number and its entries
//!   column-major inside the block.
//! * **`LCPSET 1`** ([`parse_lcpset`], [`read_lcpset`]): many LCPs in one file (`COUNT`, then per
//!   problem `PROBLEM id class n`, `PARAMS k p…`, `M` row-major, `q`); `#` comments and empty
//!   lines anywhere.
//! * **`LCPSOL 1`** ([`write_lcpsol`], [`parse_lcpsol`]): `SOL id solver status z…`, status 0 =
//!   solved, 1 = failed (then every `z` is `nan`).
//!
//! Every parse error names the file, the line and what was expected.

use super::{LcpError, LcpProblem};
use crate::output::float_token;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Largest problem size accepted from a file (`M` is stored densely: 4096² doubles = 128 MiB).
pub const MAX_FILE_DIM: usize = 4096;

/// A file could not be read or is malformed.
#[derive(Debug, Error)]
pub enum LcpIoError {
    /// The file could not be read (missing, a directory, not UTF-8, ...).
    #[error("cannot read {}: {cause}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause (part of the message, hence not a `source`).
        cause: std::io::Error,
    },
    /// The file's contents do not follow the format.
    #[error("{file}:{line}: expected {expected}, found {found}")]
    Parse {
        /// File name (as given).
        file: String,
        /// 1-based line number (the last line + 1 at end of file).
        line: usize,
        /// What the format requires at this point.
        expected: String,
        /// What the file contains there.
        found: String,
    },
    /// A problem read from the file is invalid (e.g. size mismatch).
    #[error("{file}:{line}: {cause}")]
    Invalid {
        /// File name (as given).
        file: String,
        /// 1-based line number of the problem.
        line: usize,
        /// The cause (part of the message, hence not a `source`).
        cause: LcpError,
    },
}

/// One problem of a set, with its id, class and parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct LcpEntry {
    /// Problem id (`0..N−1` in an `LCPSET` file; `0` for a single Siconos problem).
    pub id: usize,
    /// Class name (`impact3`, `p6`, `p12`; `siconos` for a `.dat` file).
    pub class: String,
    /// The `PARAMS` values (for `impact3`: `mu eps gN gT Gnn Gnt Gtt`; empty otherwise).
    pub params: Vec<f64>,
    /// The LCP.
    pub problem: LcpProblem,
}

/// One `SOL` line of an `LCPSOL 1` file.
#[derive(Debug, Clone, PartialEq)]
pub struct SolRecord {
    /// Problem id.
    pub id: usize,
    /// Solver name (e.g. `pounding-lemke`).
    pub solver: String,
    /// `true` for status 0 (solved), `false` for status 1 (then `z` is all `NaN`).
    pub solved: bool,
    /// The solution.
    pub z: Vec<f64>,
}

fn read_text(path: &Path) -> Result<String, LcpIoError> {
    let io = |cause| LcpIoError::Io {
        path: path.to_path_buf(),
        cause,
    };
    crate::input::read_text(path, "LCP file", crate::input::LCP_LIMIT).map_err(io)
}

/// Reads a file that is either an `LCPSET 1` set (first non-empty line `LCPSET 1`) or a single
/// Siconos `.dat` LCP (returned as one entry, id 0, class `siconos`).
pub fn read_any(path: &Path) -> Result<Vec<LcpEntry>, LcpIoError> {
    let text = read_text(path)?;
    let name = path.display().to_string();
    let first = text.lines().map(str::trim).find(|l| !l.is_empty());
    match first {
        Some(l) if l.starts_with("LCPSET") => parse_lcpset(&text, &name),
        _ => Ok(vec![LcpEntry {
            id: 0,
            class: "siconos".into(),
            params: Vec::new(),
            problem: parse_siconos(&text, &name)?,
        }]),
    }
}

/// Reads a Siconos `.dat` LCP file.
pub fn read_siconos(path: &Path) -> Result<LcpProblem, LcpIoError> {
    let text = read_text(path)?;
    parse_siconos(&text, &path.display().to_string())
}

/// Reads an `LCPSET 1` file.
pub fn read_lcpset(path: &Path) -> Result<Vec<LcpEntry>, LcpIoError> {
    let text = read_text(path)?;
    parse_lcpset(&text, &path.display().to_string())
}

/// Whitespace tokens with their 1-based line numbers.
struct Tokens<'a> {
    file: &'a str,
    toks: Vec<(usize, &'a str)>,
    pos: usize,
    last_line: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str, file: &'a str) -> Self {
        let mut toks = Vec::new();
        let mut last_line = 1;
        for (i, line) in text.lines().enumerate() {
            last_line = i + 1;
            for t in line.split_whitespace() {
                toks.push((i + 1, t));
            }
        }
        Self {
            file,
            toks,
            pos: 0,
            last_line: last_line + 1,
        }
    }
    fn err(&self, line: usize, expected: &str, found: &str) -> LcpIoError {
        LcpIoError::Parse {
            file: self.file.to_string(),
            line,
            expected: expected.to_string(),
            found: found.to_string(),
        }
    }
    fn next(&mut self, expected: &str) -> Result<(usize, &'a str), LcpIoError> {
        match self.toks.get(self.pos) {
            Some(&t) => {
                self.pos += 1;
                Ok(t)
            }
            None => Err(self.err(self.last_line, expected, "end of file")),
        }
    }
    fn usize(&mut self, what: &str) -> Result<usize, LcpIoError> {
        let (line, t) = self.next(what)?;
        t.parse::<usize>()
            .map_err(|_| self.err(line, what, &format!("`{t}`")))
    }
    fn f64(&mut self, what: &str) -> Result<f64, LcpIoError> {
        let (line, t) = self.next(what)?;
        match t.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(self.err(
                line,
                &format!("{what} (a finite number)"),
                &format!("`{t}`"),
            )),
        }
    }
    fn line(&self) -> usize {
        self.toks.get(self.pos).map_or(self.last_line, |t| t.0)
    }
}

/// Parses the text of a Siconos `.dat` LCP file (`file` is used in error messages).
pub fn parse_siconos(text: &str, file: &str) -> Result<LcpProblem, LcpIoError> {
    let mut t = Tokens::new(text, file);
    let nl = t.line();
    let n = t.usize("the problem size n (a nonnegative integer)")?;
    if n == 0 || n > MAX_FILE_DIM {
        return Err(t.err(
            nl,
            &format!("a problem size 1 <= n <= {MAX_FILE_DIM} (M is stored densely)"),
            &n.to_string(),
        ));
    }
    let l = t.line();
    let storage = t.usize("the storage type (0 = dense, 1 = sparse-block)")?;
    let s0l = t.line();
    let size0 = t.usize("size0 (rows of M)")?;
    let size1 = t.usize("size1 (columns of M)")?;
    if size0 != n || size1 != n {
        return Err(t.err(
            s0l,
            &format!("a square {n} x {n} matrix (size0 = size1 = n)"),
            &format!("{size0} x {size1}"),
        ));
    }
    let mut m = vec![0.0; n * n]; // row-major
    match storage {
        0 => {
            let l2 = t.line();
            let a = t.usize("the dense header `size0 size1`")?;
            let b = t.usize("the dense header `size0 size1`")?;
            if a != n || b != n {
                return Err(t.err(
                    l2,
                    &format!("dense header `{n} {n}`"),
                    &format!("`{a} {b}`"),
                ));
            }
            for j in 0..n {
                for i in 0..n {
                    m[i * n + j] = t.f64(&format!("M entry ({i}, {j}) (column-major)"))?;
                }
            }
        }
        1 => parse_sbm(&mut t, n, &mut m)?,
        _ => {
            return Err(t.err(
                l,
                "storage type 0 (dense) or 1 (sparse-block)",
                &storage.to_string(),
            ));
        }
    }
    let ql = t.line();
    let mut q = vec![0.0; n];
    for (i, qi) in q.iter_mut().enumerate() {
        *qi = t.f64(&format!("q[{i}] of {n}"))?;
    }
    LcpProblem::new(m, q).map_err(|cause| LcpIoError::Invalid {
        file: file.to_string(),
        line: ql,
        cause,
    })
}

fn parse_sbm(t: &mut Tokens<'_>, n: usize, m: &mut [f64]) -> Result<(), LcpIoError> {
    let nb = t.usize("nbblocks")?;
    let l = t.line();
    let bn0 = t.usize("blocknumber0 (number of block rows)")?;
    let bn1 = t.usize("blocknumber1 (number of block columns)")?;
    if bn0 == 0 || bn1 == 0 || bn0 > n || bn1 > n {
        return Err(t.err(
            l,
            &format!("block counts in 1..={n}"),
            &format!("{bn0} x {bn1}"),
        ));
    }
    if nb == 0 || nb > bn0 * bn1 {
        return Err(t.err(
            l,
            &format!(
                "nbblocks in 1..={} (blocknumber0 x blocknumber1)",
                bn0 * bn1
            ),
            &nb.to_string(),
        ));
    }
    let mut cum = |cnt: usize, what: &str| -> Result<Vec<usize>, LcpIoError> {
        let mut v = vec![0usize];
        for k in 0..cnt {
            let l = t.line();
            let c = t.usize(&format!("cumulative {what} size {k}"))?;
            if c <= *v.last().unwrap() || c > n {
                return Err(t.err(
                    l,
                    &format!("increasing cumulative {what} sizes ending at {n}"),
                    &c.to_string(),
                ));
            }
            v.push(c);
        }
        if *v.last().unwrap() != n {
            return Err(t.err(
                t.line(),
                &format!("cumulative {what} sizes ending at n = {n}"),
                &v.last().unwrap().to_string(),
            ));
        }
        Ok(v)
    };
    let rows = cum(bn0, "block-row")?;
    let cols = cum(bn1, "block-column")?;
    let l = t.line();
    let f1 = t.usize("filled1 (= blocknumber0 + 1)")?;
    if f1 != bn0 + 1 {
        return Err(t.err(l, &format!("filled1 = {}", bn0 + 1), &f1.to_string()));
    }
    let l = t.line();
    let f2 = t.usize("filled2 (= nbblocks)")?;
    if f2 != nb {
        return Err(t.err(l, &format!("filled2 = nbblocks = {nb}"), &f2.to_string()));
    }
    let mut ptr = Vec::with_capacity(f1);
    for k in 0..f1 {
        let l = t.line();
        let p = t.usize(&format!("block row pointer {k}"))?;
        if p > nb || ptr.last().is_some_and(|&q| p < q) || (k == 0 && p != 0) {
            return Err(t.err(
                l,
                &format!("nondecreasing block row pointers from 0 to {nb}"),
                &p.to_string(),
            ));
        }
        ptr.push(p);
    }
    if ptr[bn0] != nb {
        return Err(t.err(
            t.line(),
            &format!("last block row pointer = nbblocks = {nb}"),
            &ptr[bn0].to_string(),
        ));
    }
    let mut bcol = Vec::with_capacity(nb);
    for k in 0..nb {
        let l = t.line();
        let c = t.usize(&format!("block column index {k}"))?;
        if c >= bn1 {
            return Err(t.err(l, &format!("a block column index < {bn1}"), &c.to_string()));
        }
        // Within one block row each block column appears once (a repeat would overwrite a block).
        let row_start = ptr
            .iter()
            .take(bn0)
            .rposition(|&p| p <= k)
            .map_or(0, |r| ptr[r]);
        if bcol[row_start..].contains(&c) {
            return Err(t.err(
                l,
                "a block column index not already used in this block row",
                &c.to_string(),
            ));
        }
        bcol.push(c);
    }
    for br in 0..bn0 {
        for (k, &bc) in bcol.iter().enumerate().take(ptr[br + 1]).skip(ptr[br]) {
            let l = t.line();
            let num = t.usize(&format!("block number {k}"))?;
            if num != k {
                return Err(t.err(l, &format!("block number {k}"), &num.to_string()));
            }
            let (r0, r1) = (rows[br], rows[br + 1]);
            let (c0, c1) = (cols[bc], cols[bc + 1]);
            for j in c0..c1 {
                for i in r0..r1 {
                    m[i * n + j] = t.f64(&format!("entry ({i}, {j}) of block {k}"))?;
                }
            }
        }
    }
    Ok(())
}

/// Parses the text of an `LCPSET 1` file (`file` is used in error messages).
pub fn parse_lcpset(text: &str, file: &str) -> Result<Vec<LcpEntry>, LcpIoError> {
    let mut r = LcpSetReader::new(text, file);
    let (ln, h) = r.next("the header `LCPSET 1`")?;
    if h != ["LCPSET", "1"] {
        return Err(r.err(ln, "the header `LCPSET 1`", &format!("`{}`", h.join(" "))));
    }
    let (ln, c) = r.next("`COUNT <N>`")?;
    let count = match c.as_slice() {
        ["COUNT", k] => k
            .parse::<usize>()
            .map_err(|_| r.err(ln, "`COUNT <N>` with an integer N", &format!("`{k}`")))?,
        _ => return Err(r.err(ln, "`COUNT <N>`", &format!("`{}`", c.join(" ")))),
    };
    let mut out = Vec::with_capacity(count.min(1 << 16));
    for id in 0..count {
        out.push(r.entry(id, count)?);
    }
    if let Some(&(ln, l)) = r.lines.get(r.pos) {
        return Err(r.err(
            ln,
            &format!("end of file after COUNT = {count} problems"),
            &format!("`{l}`"),
        ));
    }
    Ok(out)
}

/// The reader of an `LCPSET 1` text: its non-blank, non-comment lines (1-based line number,
/// trimmed text) and the position of the next one.
struct LcpSetReader<'a> {
    file: &'a str,
    lines: Vec<(usize, &'a str)>,
    pos: usize,
    /// The line number reported for a missing line (one past the last).
    end: usize,
}

impl<'a> LcpSetReader<'a> {
    fn new(text: &'a str, file: &'a str) -> Self {
        let lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
            .collect();
        LcpSetReader {
            file,
            lines,
            pos: 0,
            end: text.lines().count() + 1,
        }
    }

    /// A parse error at `line`: what was expected there and what was found.
    fn err(&self, line: usize, expected: &str, found: &str) -> LcpIoError {
        LcpIoError::Parse {
            file: self.file.to_string(),
            line,
            expected: expected.to_string(),
            found: found.to_string(),
        }
    }

    /// The next line as whitespace-separated tokens, or an error expecting `what` at the end.
    fn next(&mut self, what: &str) -> Result<(usize, Vec<&'a str>), LcpIoError> {
        match self.lines.get(self.pos) {
            Some(&(ln, l)) => {
                self.pos += 1;
                Ok((ln, l.split_whitespace().collect()))
            }
            None => Err(self.err(self.end, what, "end of file")),
        }
    }

    /// The tokens `toks` of line `ln` as finite numbers (`what` names them in errors).
    fn nums(&self, ln: usize, toks: &[&str], what: &str) -> Result<Vec<f64>, LcpIoError> {
        toks.iter()
            .enumerate()
            .map(|(k, s)| match s.parse::<f64>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(self.err(
                    ln,
                    &format!("{what} value {k} (a finite number)"),
                    &format!("`{s}`"),
                )),
            })
            .collect()
    }

    /// Problem `id`: `PROBLEM id class n`, `PARAMS k p1..pk`, `M <n*n numbers>`, `q <n numbers>`.
    fn entry(&mut self, id: usize, count: usize) -> Result<LcpEntry, LcpIoError> {
        let (pl, class, n) = self.problem_line(id, count)?;
        let params = self.params()?;
        let m = self.tagged("M", "`M <n*n numbers>`", n * n, || {
            format!("n*n = {} entries of M (n = {n})", n * n)
        })?;
        let q = self.tagged("q", "`q <n numbers>`", n, || {
            format!("n = {n} entries of q")
        })?;
        let problem = LcpProblem::new(m, q).map_err(|cause| LcpIoError::Invalid {
            file: self.file.to_string(),
            line: pl,
            cause,
        })?;
        Ok(LcpEntry {
            id,
            class,
            params,
            problem,
        })
    }

    /// `PROBLEM id class n` with the expected `id` and `1 <= n <= MAX_FILE_DIM`: its line, class
    /// and size.
    fn problem_line(
        &mut self,
        id: usize,
        count: usize,
    ) -> Result<(usize, String, usize), LcpIoError> {
        let exp = format!("`PROBLEM {id} <class> <n>` (COUNT = {count})");
        let (pl, p) = self.next(&exp)?;
        let ["PROBLEM", i, class, n] = p.as_slice() else {
            return Err(self.err(pl, &exp, &format!("`{}`", p.join(" "))));
        };
        if i.parse::<usize>().ok() != Some(id) {
            return Err(self.err(pl, &format!("problem id {id}"), &format!("`{i}`")));
        }
        let n = n
            .parse::<usize>()
            .ok()
            .filter(|&n| n > 0 && n <= MAX_FILE_DIM)
            .ok_or_else(|| {
                self.err(
                    pl,
                    &format!("a problem size 1 <= n <= {MAX_FILE_DIM}"),
                    &format!("`{n}`"),
                )
            })?;
        Ok((pl, class.to_string(), n))
    }

    /// `PARAMS k p1 .. pk`: exactly `k` finite numbers.
    fn params(&mut self) -> Result<Vec<f64>, LcpIoError> {
        let (ln, pr) = self.next("`PARAMS <k> <p1> ... <pk>`")?;
        let Some((&"PARAMS", rest)) = pr.split_first().filter(|(_, rest)| !rest.is_empty()) else {
            return Err(self.err(
                ln,
                "`PARAMS <k> <p1> ... <pk>`",
                &format!("`{}`", pr.join(" ")),
            ));
        };
        let k = rest[0].parse::<usize>().map_err(|_| {
            self.err(
                ln,
                "`PARAMS <k> ...` with an integer k",
                &format!("`{}`", rest[0]),
            )
        })?;
        if rest.len() - 1 != k {
            return Err(self.err(
                ln,
                &format!("{k} PARAMS values"),
                &format!("{}", rest.len() - 1),
            ));
        }
        self.nums(ln, &rest[1..], "PARAMS")
    }

    /// `TAG v1 ... vN`: the next line, tagged `tag` (`form` when it is not), with exactly `want`
    /// finite numbers (`count_what` when the count differs).
    fn tagged(
        &mut self,
        tag: &str,
        form: &str,
        want: usize,
        count_what: impl FnOnce() -> String,
    ) -> Result<Vec<f64>, LcpIoError> {
        let (ln, t) = self.next(form)?;
        match t.split_first() {
            Some((&x, rest)) if x == tag => {
                if rest.len() != want {
                    // the message is built only on error (every problem of a set passes here)
                    return Err(self.err(ln, &count_what(), &format!("{}", rest.len())));
                }
                self.nums(ln, rest, tag)
            }
            _ => Err(self.err(ln, form, &format!("`{}`", t.join(" ")))),
        }
    }
}

/// Writes `LCPSOL 1` text: the header, one comment line, then `SOL id solver status z…` per record
/// (status 0 solved, 1 failed with every `z` written `nan`; floats as shortest round-trip tokens).
pub fn write_lcpsol(records: &[SolRecord]) -> String {
    let mut s =
        String::from("LCPSOL 1\n# SOL <problem id> <solver> <status 0=solved> <z_1..z_n>\n");
    for r in records {
        s.push_str(&format!(
            "SOL {} {} {}",
            r.id,
            r.solver,
            if r.solved { 0 } else { 1 }
        ));
        for &z in &r.z {
            s.push(' ');
            s.push_str(&float_token(if r.solved { z } else { f64::NAN }));
        }
        s.push('\n');
    }
    s
}

/// Parses `LCPSOL 1` text (`file` is used in error messages).
pub fn parse_lcpsol(text: &str, file: &str) -> Result<Vec<SolRecord>, LcpIoError> {
    let perr = |line: usize, expected: &str, found: &str| LcpIoError::Parse {
        file: file.to_string(),
        line,
        expected: expected.to_string(),
        found: found.to_string(),
    };
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    match lines.next() {
        Some((_, "LCPSOL 1")) => {}
        Some((ln, l)) => return Err(perr(ln, "the header `LCPSOL 1`", &format!("`{l}`"))),
        None => return Err(perr(1, "the header `LCPSOL 1`", "end of file")),
    }
    let mut out = Vec::new();
    for (ln, l) in lines {
        let t: Vec<&str> = l.split_whitespace().collect();
        let exp = "`SOL <id> <solver> <status 0|1> <z...>`";
        if t.len() < 4 || t[0] != "SOL" {
            return Err(perr(ln, exp, &format!("`{l}`")));
        }
        let id = t[1]
            .parse::<usize>()
            .map_err(|_| perr(ln, "an integer problem id", &format!("`{}`", t[1])))?;
        let solved = match t[3] {
            "0" => true,
            "1" => false,
            s => return Err(perr(ln, "status 0 or 1", &format!("`{s}`"))),
        };
        let mut z = t[4..]
            .iter()
            .map(|s| {
                s.parse::<f64>()
                    .map_err(|_| perr(ln, "a number (or nan)", &format!("`{s}`")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        if !solved {
            // A failed solve has no solution: whatever numbers follow status 1, `z` is all NaN
            // (as documented on [`SolRecord::solved`] and written by [`write_lcpsol`]).
            z.fill(f64::NAN);
        }
        out.push(SolRecord {
            id,
            solver: t[2].to_string(),
            solved,
            z,
        });
    }
    Ok(out)
}
