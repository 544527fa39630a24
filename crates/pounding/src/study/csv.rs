//! `bounds.csv`: header, row text and the exact inverse (for merging shards).
//!
//! Tokens: `true`/`false`; floats via [`float_token`] (shortest round-trip, `inf`, `-inf`, `nan`),
//! so parsing a row gives back the same bits.

use super::StudyError;
use super::cell::Cell;
use super::run::{Layout, Row};
use super::scenario::Scenario;
use crate::geometry::ContactCase;
use crate::output::float_token;
use rayon::prelude::*;
use std::fmt::Write;

/// The header line of `bounds.csv` (without newline).
pub const BOUNDS_HEADER: &str = "beta1_deg,beta2_deg,r1_m,r2_m,mu,eps,case,theta1_deg,theta2_deg,first_contact,end_closes,sigma_m,g_nn,g_nt,g_tt,kappa,varrho,lower,upper,lcp_agrees";

fn push_f(s: &mut String, x: f64) {
    s.push_str(&float_token(x));
    s.push(',');
}

/// One row as a CSV line (with trailing newline).
pub fn bounds_line(scenario: &Scenario, row: &Row) -> String {
    let p = scenario.params(&row.key);
    let c = &row.cell;
    let mut s = String::with_capacity(256);
    for x in [p.beta1_deg, p.beta2_deg, p.r1_m, p.r2_m, p.mu, p.eps] {
        push_f(&mut s, x);
    }
    s.push_str(p.case.name());
    s.push(',');
    push_f(&mut s, p.theta1_deg);
    push_f(&mut s, p.theta2_deg);
    let _ = write!(s, "{},{},", c.first_contact, c.end_closes);
    for x in [
        c.sigma_m, c.g_nn, c.g_nt, c.g_tt, c.kappa, c.varrho, c.lower, c.upper,
    ] {
        push_f(&mut s, x);
    }
    let _ = writeln!(s, "{}", c.lcp_agrees);
    s
}

/// The whole `bounds.csv` text (header + rows in the given order), formatted in parallel on the
/// current rayon pool; the bytes do not depend on the thread count.
pub fn bounds_csv(scenario: &Scenario, rows: &[Row]) -> String {
    let chunks: Vec<String> = rows
        .par_chunks(4096)
        .map(|ch| ch.iter().map(|r| bounds_line(scenario, r)).collect())
        .collect();
    let mut out = String::with_capacity(chunks.iter().map(String::len).sum::<usize>() + 256);
    out.push_str(BOUNDS_HEADER);
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
    if f.len() != 20 {
        return Err(StudyError::Parse(format!(
            "{what}: {} fields, expected 20",
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
    let got = [f[0], f[1], f[2], f[3], f[4], f[5], f[7], f[8]];
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
