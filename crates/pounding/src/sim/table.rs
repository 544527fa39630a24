//! Typed tables of a run: named columns with units, and the one CSV writer for them.
//!
//! Two shapes, one writer ([`csv_lines`]):
//! - [`Table`]: numbers only, row-major, one row per kept step. An observer
//!   (`sim/observer/`) fills one while the driver runs; the run returns its tables in order.
//! - [`TypedTable`]: one row per event (`impacts.csv`: one per impacting contact), column-major,
//!   each column of one type ([`ColumnData`]: floats, integers or names), as a data-frame
//!   library holds a table whose columns are of different kinds.
//!
//! Every front end writes or hands them on without knowing their content: the CLI writes
//! `<name>.csv`, Python gets numpy columns (float64, int64, or str objects) without text in
//! between. A header cell is `<column>_<unit>` (`t_s`, `segment1_bearing2_fx_N`), the
//! convention of every CSV the library writes.

use crate::math::Real;
use crate::output::{csv_field, push_float_token};
use std::fmt::Write;

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

/// The CSV text of the numeric rows of a run's table: the header cells of `columns`, then
/// `rows` lines, line `r` the values `row(r, out)` appends to `out` (one per column), as shortest
/// round-trip floats ([`crate::output::float_token`]) through [`csv_lines`]. A writer that
/// derives its rows (`history.csv`) streams them here without holding them all.
pub fn csv_rows(
    columns: &[Column],
    rows: usize,
    mut row: impl FnMut(usize, &mut Vec<Real>),
) -> String {
    let mut line = Vec::with_capacity(columns.len());
    csv_lines(columns, rows, 20, |r, s| {
        line.clear();
        row(r, &mut line);
        debug_assert_eq!(line.len(), columns.len());
        for (i, v) in line.iter().enumerate() {
            if i > 0 {
                s.push(',');
            }
            push_float_token(s, *v);
        }
    })
}

/// The one CSV writer of the tables of a run: the header line of `columns`
/// ([`Column::header`], comma-separated), then `rows` lines, line `r` the cells `line(r, s)`
/// appends to `s` (comma-separated, without the line break). `cell_width` is the expected
/// width of a cell (the capacity reserved).
pub fn csv_lines(
    columns: &[Column],
    rows: usize,
    cell_width: usize,
    mut line: impl FnMut(usize, &mut String),
) -> String {
    let head: Vec<String> = columns.iter().map(Column::header).collect();
    let mut s = String::with_capacity(rows * columns.len() * cell_width + 64);
    s.push_str(&head.join(","));
    s.push('\n');
    for r in 0..rows {
        line(r, &mut s);
        s.push('\n');
    }
    s
}

/// The values of one column of a [`TypedTable`].
#[derive(Debug, Clone, PartialEq)]
pub enum ColumnData {
    /// Numbers (a value that does not apply is NaN, written `nan`).
    Real(Vec<Real>),
    /// Counts and indices.
    Int(Vec<i64>),
    /// Names (a contact, a mode): written as CSV fields, quoted only when they must be.
    Text(Vec<String>),
}

impl ColumnData {
    /// The number of values.
    pub fn len(&self) -> usize {
        match self {
            ColumnData::Real(v) => v.len(),
            ColumnData::Int(v) => v.len(),
            ColumnData::Text(v) => v.len(),
        }
    }

    /// Whether the column has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Appends value `r` to `s` as its CSV cell: a float's shortest round-trip token, an
    /// integer's digits, a name as a CSV field ([`csv_field`]).
    fn push_cell(&self, r: usize, s: &mut String) {
        match self {
            ColumnData::Real(v) => push_float_token(s, v[r]),
            ColumnData::Int(v) => {
                let _ = write!(s, "{}", v[r]);
            }
            ColumnData::Text(v) => s.push_str(&csv_field(&v[r])),
        }
    }
}

/// A table whose columns have their own types ([`ColumnData`]), one row per event, column-major
/// (`impacts.csv`): `columns[i]` holds `data[i]`, every column of the same length.
#[derive(Debug, Clone, PartialEq)]
pub struct TypedTable {
    /// File stem of the table (`impacts` → `impacts.csv`).
    pub name: &'static str,
    /// The columns.
    pub columns: Vec<Column>,
    /// The values, one entry per column.
    pub data: Vec<ColumnData>,
}

impl TypedTable {
    /// A table without columns.
    pub fn new(name: &'static str) -> Self {
        TypedTable {
            name,
            columns: Vec::new(),
            data: Vec::new(),
        }
    }

    /// Appends the column `column` holding `data` (as many values as the other columns).
    pub fn push(&mut self, column: Column, data: ColumnData) {
        debug_assert!(self.data.first().is_none_or(|d| d.len() == data.len()));
        self.columns.push(column);
        self.data.push(data);
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.data.first().map_or(0, ColumnData::len)
    }

    /// The values of the column whose header ([`Column::header`]) is `header`, if any.
    pub fn column(&self, header: &str) -> Option<&ColumnData> {
        let i = self.columns.iter().position(|c| c.header() == header)?;
        Some(&self.data[i])
    }

    /// The file name `<name>.csv`.
    pub fn file_name(&self) -> String {
        format!("{}.csv", self.name)
    }

    /// The CSV text: the header, then one line per row ([`csv_lines`]).
    pub fn csv(&self) -> String {
        csv_lines(&self.columns, self.rows(), 14, |r, s| {
            for (i, d) in self.data.iter().enumerate() {
                if i > 0 {
                    s.push(',');
                }
                d.push_cell(r, s);
            }
        })
    }
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

    #[test]
    fn typed_table_writes_each_type_by_the_same_writer() {
        let mut t = TypedTable::new("events");
        t.push(Column::new("n", ""), ColumnData::Int(vec![1, -2]));
        t.push(
            Column::new("t", "s"),
            ColumnData::Real(vec![0.25, f64::NAN]),
        );
        t.push(
            Column::new("who", ""),
            ColumnData::Text(vec!["a-b".into(), "c,d".into()]),
        );
        assert_eq!(t.rows(), 2);
        assert_eq!(t.csv(), "n,t_s,who\n1,0.25,a-b\n-2,nan,\"c,d\"\n");
        assert!(
            matches!(t.column("t_s"), Some(ColumnData::Real(v)) if v[0] == 0.25 && v[1].is_nan())
        );
        assert!(matches!(t.column("n"), Some(ColumnData::Int(v)) if v == &[1, -2]));
        assert_eq!(t.column("t"), None);
        // a float column writes as the numeric tables do
        let mut f = Table::with_time("x", vec![]);
        f.values.extend([0.25, f64::NAN]);
        let mut g = TypedTable::new("x");
        g.push(
            Column::new("t", "s"),
            ColumnData::Real(vec![0.25, f64::NAN]),
        );
        assert_eq!(f.csv(), g.csv());
        assert_eq!(TypedTable::new("e").csv(), "\n");
    }
}
