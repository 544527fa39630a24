//! `bounds.csv`: header, row text and the exact inverse (for merging shards).
//!
//! Tokens: `true`/`false`; floats via [`float_token`] (shortest round-trip, `inf`, `-inf`, `nan`),
//! so parsing a row gives back the same bits.

use super::StudyError;
use super::cell::Cell;
use super::run::{Layout, Row};
use super::scenario::{Scenario, StudyShape};
use crate::geometry::ContactCase;
use crate::output::float_token;
use rayon::prelude::*;

/// The header line of `bounds.csv` (without newline).
pub const BOUNDS_HEADER: &str = "beta1_deg,beta2_deg,r1_m,r2_m,mu,eps,case,theta1_deg,theta2_deg,first_contact,end_closes,sigma_m,g_nn,g_nt,g_tt,kappa,varrho,lower,upper,lcp_agrees";

/// The extra columns appended to [`BOUNDS_HEADER`] in straight and skew studies (only there, so a
/// curved study's `bounds.csv` is unchanged): the shape name and `L1`, `L2`, the skew angle.
pub const SHAPE_COLUMNS: &str = "shape,l1_m,l2_m,skew_deg";

/// The header of `scenario`'s `bounds.csv`: [`BOUNDS_HEADER`] for curved decks, followed by
/// `,`[`SHAPE_COLUMNS`] for straight and skewed decks (whose `beta*`/`r*` columns hold `nan`).
pub fn bounds_header(scenario: &Scenario) -> String {
    if scenario.shape == StudyShape::Curved {
        BOUNDS_HEADER.to_string()
    } else {
        format!("{BOUNDS_HEADER},{SHAPE_COLUMNS}")
    }
}

/// Number of fields of a `bounds.csv` line of `scenario`.
pub fn bounds_field_count(scenario: &Scenario) -> usize {
    if scenario.shape == StudyShape::Curved {
        20
    } else {
        24
    }
}

/// Appends `float_token(x)` and a comma without allocating (same bytes as [`float_token`]).
fn push_f(s: &mut String, x: f64) {
    push_token(s, x);
    s.push(',');
}

/// Appends exactly the text of [`float_token`]`(x)`.
pub fn push_token(s: &mut String, x: f64) {
    crate::output::push_float_token(s, x);
}

/// Reusable text pieces of `bounds.csv` rows: the θ tokens of the grid and the parameter prefix of the
/// current block (one configuration and case), so that each row formats only its own numbers.
pub struct RowWriter<'a> {
    scenario: &'a Scenario,
    block_len: usize,
    theta1: Vec<String>,
    theta2: Vec<String>,
    block: usize,
    prefix: String,
    suffix: String,
}

impl<'a> RowWriter<'a> {
    /// A writer for rows of `scenario`.
    pub fn new(scenario: &'a Scenario) -> Self {
        let tokens = |v: Vec<f64>| v.into_iter().map(float_token).collect();
        Self {
            scenario,
            block_len: Layout::of(scenario).block_len(),
            theta1: tokens(scenario.theta1.values()),
            theta2: tokens(scenario.theta2.values()),
            block: usize::MAX,
            prefix: String::new(),
            suffix: String::new(),
        }
    }

    /// Appends `row` as a CSV line (with trailing newline) to `s`.
    pub fn push(&mut self, s: &mut String, row: &Row) {
        let block = row.index / self.block_len;
        if block != self.block {
            let p = self.scenario.params(&row.key);
            self.prefix.clear();
            for x in [p.beta1_deg, p.beta2_deg, p.r1_m, p.r2_m, p.mu, p.eps] {
                push_f(&mut self.prefix, x);
            }
            self.prefix.push_str(p.case.name());
            self.prefix.push(',');
            self.suffix.clear();
            if self.scenario.shape != StudyShape::Curved {
                self.suffix.push(',');
                self.suffix.push_str(self.scenario.shape.name());
                for x in [p.l1_m, p.l2_m, p.skew_deg] {
                    self.suffix.push(',');
                    push_token(&mut self.suffix, x);
                }
            }
            self.block = block;
        }
        let c = &row.cell;
        s.push_str(&self.prefix);
        s.push_str(&self.theta1[row.key.i]);
        s.push(',');
        s.push_str(&self.theta2[row.key.j]);
        s.push(',');
        s.push_str(if c.first_contact { "true," } else { "false," });
        s.push_str(if c.end_closes { "true," } else { "false," });
        for x in [
            c.sigma_m, c.g_nn, c.g_nt, c.g_tt, c.kappa, c.varrho, c.lower, c.upper,
        ] {
            push_f(s, x);
        }
        s.push_str(if c.lcp_agrees { "true" } else { "false" });
        s.push_str(&self.suffix);
        s.push('\n');
    }
}

/// One row as a CSV line (with trailing newline).
pub fn bounds_line(scenario: &Scenario, row: &Row) -> String {
    let mut s = String::with_capacity(256);
    RowWriter::new(scenario).push(&mut s, row);
    s
}

/// The whole `bounds.csv` text (header + rows in the given order), formatted in parallel on the
/// current rayon pool; the bytes do not depend on the thread count.
pub fn bounds_csv(scenario: &Scenario, rows: &[Row]) -> String {
    let chunks: Vec<String> = rows
        .par_chunks(4096)
        .map(|ch| {
            let mut w = RowWriter::new(scenario);
            let mut s = String::with_capacity(ch.len() * 200);
            for r in ch {
                w.push(&mut s, r);
            }
            s
        })
        .collect();
    let mut out = String::with_capacity(chunks.iter().map(String::len).sum::<usize>() + 256);
    out.push_str(&bounds_header(scenario));
    out.push('\n');
    for c in chunks {
        out.push_str(&c);
    }
    out
}

fn parse_f(tok: &str, what: &str) -> Result<f64, StudyError> {
    tok.parse::<f64>()
        .map_err(|_| StudyError::Parse(format!("{what}: {tok:?} is not a number")))
}

fn parse_b(tok: &str, what: &str) -> Result<bool, StudyError> {
    match tok {
        "true" => Ok(true),
        "false" => Ok(false),
        _ => Err(StudyError::Parse(format!(
            "{what}: {tok:?} is not true/false"
        ))),
    }
}

/// Parses one `bounds.csv` line (no newline) known to be global row `index` of `scenario`, checking
/// that its parameter columns match the row's key exactly.
pub fn parse_bounds_line(scenario: &Scenario, index: usize, line: &str) -> Result<Row, StudyError> {
    let layout = Layout::of(scenario);
    if index >= layout.total() {
        return Err(StudyError::Parse(format!(
            "row {index} is beyond the study's {} rows",
            layout.total()
        )));
    }
    let f: Vec<&str> = line.split(',').collect();
    let what = format!("row {index}");
    let nf = bounds_field_count(scenario);
    if f.len() != nf {
        return Err(StudyError::Parse(format!(
            "{what}: {} fields, expected {nf}",
            f.len()
        )));
    }
    let key = layout.key(index);
    let p = scenario.params(&key);
    let expect = [
        p.beta1_deg,
        p.beta2_deg,
        p.r1_m,
        p.r2_m,
        p.mu,
        p.eps,
        p.theta1_deg,
        p.theta2_deg,
    ];
    let mut expect = expect.to_vec();
    let mut got = vec![f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[8]];
    if nf == 24 {
        if f[20] != scenario.shape.name() {
            return Err(StudyError::Parse(format!(
                "{what}: shape {:?} does not match the scenario ({})",
                f[20],
                scenario.shape.name()
            )));
        }
        expect.extend([p.l1_m, p.l2_m, p.skew_deg]);
        got.extend([f[21], f[22], f[23]]);
    }
    for (e, g) in expect.iter().zip(got) {
        if float_token(*e) != g {
            return Err(StudyError::Parse(format!(
                "{what}: parameter {g:?} does not match the scenario ({})",
                float_token(*e)
            )));
        }
    }
    if ContactCase::from_name(f[6]) != Some(p.case) {
        return Err(StudyError::Parse(format!(
            "{what}: case {:?} does not match the scenario ({})",
            f[6],
            p.case.name()
        )));
    }
    let first_contact = parse_b(f[9], &what)?;
    let end_closes = parse_b(f[10], &what)?;
    let n: Vec<f64> = f[11..19]
        .iter()
        .map(|t| parse_f(t, &what))
        .collect::<Result<_, _>>()?;
    let lcp_agrees = parse_b(f[19], &what)?;
    let degeneracy = super::cell::grid_degeneracy(
        p.theta1_deg,
        p.theta2_deg,
        scenario.degeneracy_tolerance_deg(),
    );
    Ok(Row {
        index,
        key,
        cell: Cell {
            degeneracy,
            first_contact,
            end_closes,
            sigma_m: n[0],
            g_nn: n[1],
            g_nt: n[2],
            g_tt: n[3],
            kappa: n[4],
            varrho: n[5],
            lower: n[6],
            upper: n[7],
            lcp_agrees,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn push_token_matches_float_token() {
        let mut xs = vec![
            0.0,
            -0.0,
            1.0,
            -2.5,
            1e-5,
            9.99e-6,
            1e16,
            9.9e15,
            5e-324,
            f64::MAX,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            1.8936102321543417e-6,
        ];
        let mut v = 0.123_456_789_f64;
        for _ in 0..2000 {
            v = (v * 7.3 + 0.1).fract() * 10f64.powi(((v * 1000.0) as i32 % 40) - 20);
            xs.push(v);
            xs.push(-v);
        }
        for x in xs {
            let mut s = String::new();
            push_token(&mut s, x);
            assert_eq!(s, float_token(x));
        }
    }
}
