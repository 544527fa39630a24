//! Typed tables of a run: named columns with units, one row per kept step, and the one CSV
//! writer for them.
//!
//! An observer (`sim/observer.rs`) fills a [`Table`] while the driver runs; the run returns its
//! tables in order, and every front end writes or hands them on without knowing their content:
//! the CLI writes `<name>.csv`, Python gets numpy columns. A header cell is `<column>_<unit>`
//! (`t_s`, `segment1_bearing2_fx_N`), the convention of every CSV the library writes.

use crate::math::Real;
use crate::output::push_float_token;

pub use super::observer::{BearingRecipe, BearingsTable, TableSource};

/// One column: its name and its unit (`m`, `N`, `s`, `deg`, …; empty: dimensionless).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Column {
    /// Name without the unit (`segment1_bearing2_fx`).
    pub name: String,
    /// Unit symbol.
    pub unit: &'static str,
}

impl Column {
    /// A column `name` in `unit`.
    pub fn new(name: impl Into<String>, unit: &'static str) -> Self {
        Column {
            name: name.into(),
            unit,
        }
    }

    /// The CSV header cell `<name>_<unit>` (the name alone when dimensionless).
    pub fn header(&self) -> String {
        if self.unit.is_empty() {
            self.name.clone()
        } else {
            format!("{}_{}", self.name, self.unit)
        }
    }
}

/// A table of a run: `columns` and their values row by row (`values.len()` is a multiple of
/// `columns.len()`; the first column is the time `t` in s).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// File stem of the table (`bearings` → `bearings.csv`).
    pub name: &'static str,
    /// The columns.
    pub columns: Vec<Column>,
    /// Row-major values.
    pub values: Vec<Real>,
}

impl Table {
    /// An empty table with the time column first and then `columns`.
    pub fn with_time(name: &'static str, columns: Vec<Column>) -> Self {
        let mut all = vec![Column::new("t", "s")];
        all.extend(columns);
        Table {
            name,
            columns: all,
            values: Vec::new(),
        }
    }

    /// Room for `rows` more rows.
    pub fn reserve_rows(&mut self, rows: usize) {
        self.values.reserve(rows.saturating_mul(self.columns.len()));
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.values.len() / self.columns.len().max(1)
    }

    /// Row `r`.
    pub fn row(&self, r: usize) -> &[Real] {
        let n = self.columns.len();
        &self.values[n * r..n * (r + 1)]
    }

    /// The values of the column whose header ([`Column::header`]) is `header`, if any.
    pub fn column(&self, header: &str) -> Option<Vec<Real>> {
        let i = self.columns.iter().position(|c| c.header() == header)?;
        Some((0..self.rows()).map(|r| self.row(r)[i]).collect())
    }

    /// The file name `<name>.csv`.
    pub fn file_name(&self) -> String {
        format!("{}.csv", self.name)
    }

    /// The CSV text: the header, then one line per row of shortest round-trip floats.
    pub fn csv(&self) -> String {
        csv_rows(&self.columns, self.rows(), |r, out| {
            out.extend_from_slice(self.row(r))
        })
    }
}

/// The one CSV writer of the tables of a run: the header cells of `columns`, then `rows` lines,
/// line `r` the values `row(r, out)` appends to `out` (one per column), as shortest round-trip
/// floats ([`crate::output::float_token`]). A writer that derives its rows (`history.csv`)
/// streams them here without holding them all.
pub fn csv_rows(
    columns: &[Column],
    rows: usize,
    mut row: impl FnMut(usize, &mut Vec<Real>),
) -> String {
    let head: Vec<String> = columns.iter().map(Column::header).collect();
    let mut s = String::with_capacity(rows * columns.len() * 20 + 64);
    s.push_str(&head.join(","));
    s.push('\n');
    let mut line = Vec::with_capacity(columns.len());
    for r in 0..rows {
        line.clear();
        row(r, &mut line);
        debug_assert_eq!(line.len(), columns.len());
        for (i, v) in line.iter().enumerate() {
            if i > 0 {
                s.push(',');
            }
            push_float_token(&mut s, *v);
        }
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_has_unit_headers_and_one_line_per_row() {
        let mut t = Table::with_time("x", vec![Column::new("a", "N"), Column::new("n", "")]);
        t.values.extend([0.0, 1.5, 2.0, 0.001, -0.0, 3.0]);
        assert_eq!(t.rows(), 2);
        assert_eq!(t.csv(), "t_s,a_N,n\n0,1.5,2\n0.001,0,3\n");
        assert_eq!(t.column("a_N"), Some(vec![1.5, -0.0]));
        assert_eq!(t.column("a"), None);
        assert_eq!(t.file_name(), "x.csv");
    }
}
