//! A block of stored runs as named columns, and its Parquet bytes: one row group per block,
//! plain encodings, no compression, no dictionary (the bytes depend only on the values).
//!
//! Every column is `OPTIONAL` (a missing value is a null) except `run`, the global run index.

use super::CampaignError;
use parquet::basic::{ConvertedType, Repetition, Type as PhysicalType};
use parquet::column::reader::{ColumnReader, get_typed_column_reader};
use parquet::data_type::{BoolType, ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::{WriterProperties, WriterVersion};
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::{Type, TypePtr};
use std::sync::Arc;

/// The values of one column (`None`: null).
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// 64-bit integers.
    Int(Vec<Option<i64>>),
    /// Doubles (NaN is a value, not a null).
    Float(Vec<Option<f64>>),
    /// UTF-8 text.
    Text(Vec<Option<String>>),
    /// Booleans.
    Bool(Vec<Option<bool>>),
}

impl Values {
    /// An empty column of the same type.
    pub fn empty_like(&self) -> Values {
        match self {
            Values::Int(_) => Values::Int(Vec::new()),
            Values::Float(_) => Values::Float(Vec::new()),
            Values::Text(_) => Values::Text(Vec::new()),
            Values::Bool(_) => Values::Bool(Vec::new()),
        }
    }

    /// The number of values.
    pub fn len(&self) -> usize {
        match self {
            Values::Int(v) => v.len(),
            Values::Float(v) => v.len(),
            Values::Text(v) => v.len(),
            Values::Bool(v) => v.len(),
        }
    }

    /// Whether the column has no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Appends `other`'s values (same type; a different type is an error).
    pub fn extend(&mut self, other: Values) -> Result<(), CampaignError> {
        match (self, other) {
            (Values::Int(a), Values::Int(b)) => a.extend(b),
            (Values::Float(a), Values::Float(b)) => a.extend(b),
            (Values::Text(a), Values::Text(b)) => a.extend(b),
            (Values::Bool(a), Values::Bool(b)) => a.extend(b),
            _ => {
                return Err(CampaignError::Store(
                    "column types differ between parts".into(),
                ));
            }
        }
        Ok(())
    }

    fn physical(&self) -> (PhysicalType, ConvertedType) {
        match self {
            Values::Int(_) => (PhysicalType::INT64, ConvertedType::NONE),
            Values::Float(_) => (PhysicalType::DOUBLE, ConvertedType::NONE),
            Values::Text(_) => (PhysicalType::BYTE_ARRAY, ConvertedType::UTF8),
            Values::Bool(_) => (PhysicalType::BOOLEAN, ConvertedType::NONE),
        }
    }
}

/// Named columns of equal length.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Columns {
    /// `(name, values)` in schema order.
    pub cols: Vec<(String, Values)>,
}

fn store_err(e: impl std::fmt::Display) -> CampaignError {
    CampaignError::Store(e.to_string())
}

impl Columns {
    /// The number of rows (of the first column).
    pub fn rows(&self) -> usize {
        self.cols.first().map_or(0, |(_, v)| v.len())
    }

    /// The column `name`.
    pub fn get(&self, name: &str) -> Option<&Values> {
        self.cols.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    /// Appends the rows of `other` (same column names and types).
    pub fn append(&mut self, other: Columns) -> Result<(), CampaignError> {
        if self.cols.is_empty() {
            *self = other;
            return Ok(());
        }
        let same = self.cols.len() == other.cols.len()
            && self.cols.iter().zip(&other.cols).all(|(a, b)| a.0 == b.0);
        if !same {
            return Err(CampaignError::Store(
                "the parts have different columns".into(),
            ));
        }
        for ((_, a), (_, b)) in self.cols.iter_mut().zip(other.cols) {
            a.extend(b)?;
        }
        Ok(())
    }

    /// The Parquet schema of these columns.
    pub fn schema(&self) -> Result<TypePtr, CampaignError> {
        let fields = self
            .cols
            .iter()
            .map(|(name, v)| {
                let (p, c) = v.physical();
                let rep = if name == "run" {
                    Repetition::REQUIRED
                } else {
                    Repetition::OPTIONAL
                };
                Type::primitive_type_builder(name, p)
                    .with_repetition(rep)
                    .with_converted_type(c)
                    .build()
                    .map(Arc::new)
                    .map_err(store_err)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Type::group_type_builder("pounding_campaign")
            .with_fields(fields)
            .build()
            .map(Arc::new)
            .map_err(store_err)
    }
}

/// Writer properties: the same bytes for the same values, whatever the machine.
pub fn properties() -> Arc<WriterProperties> {
    Arc::new(
        WriterProperties::builder()
            .set_writer_version(WriterVersion::PARQUET_1_0)
            .set_dictionary_enabled(false)
            .set_created_by(format!("pounding {}", env!("CARGO_PKG_VERSION")))
            .build(),
    )
}

/// Streams row groups into one Parquet file.
pub struct Writer<W: std::io::Write + Send> {
    inner: SerializedFileWriter<W>,
}

impl<W: std::io::Write + Send> Writer<W> {
    /// A writer of `schema` into `sink`.
    pub fn new(sink: W, schema: TypePtr) -> Result<Self, CampaignError> {
        Ok(Self {
            inner: SerializedFileWriter::new(sink, schema, properties()).map_err(store_err)?,
        })
    }

    /// Writes `cols` as one row group.
    pub fn write(&mut self, cols: &Columns) -> Result<(), CampaignError> {
        let mut rg = self.inner.next_row_group().map_err(store_err)?;
        let mut it = cols.cols.iter();
        while let Some(mut w) = rg.next_column().map_err(store_err)? {
            let Some((name, v)) = it.next() else {
                return Err(CampaignError::Store("schema and columns differ".into()));
            };
            let def = |o: &mut dyn Iterator<Item = bool>| -> Vec<i16> {
                o.map(|present| present as i16).collect()
            };
            let required = name == "run";
            let r = match v {
                Values::Int(x) => {
                    let d = def(&mut x.iter().map(Option::is_some));
                    let vals: Vec<i64> = x.iter().flatten().copied().collect();
                    let d = (!required).then_some(&d[..]);
                    w.typed::<Int64Type>().write_batch(&vals, d, None)
                }
                Values::Float(x) => {
                    let d = def(&mut x.iter().map(Option::is_some));
                    let vals: Vec<f64> = x.iter().flatten().copied().collect();
                    w.typed::<DoubleType>().write_batch(&vals, Some(&d), None)
                }
                Values::Text(x) => {
                    let d = def(&mut x.iter().map(Option::is_some));
                    let vals: Vec<ByteArray> = x
                        .iter()
                        .flatten()
                        .map(|s| ByteArray::from(s.as_str()))
                        .collect();
                    w.typed::<ByteArrayType>()
                        .write_batch(&vals, Some(&d), None)
                }
                Values::Bool(x) => {
                    let d = def(&mut x.iter().map(Option::is_some));
                    let vals: Vec<bool> = x.iter().flatten().copied().collect();
                    w.typed::<BoolType>().write_batch(&vals, Some(&d), None)
                }
            };
            r.map_err(store_err)?;
            w.close().map_err(store_err)?;
        }
        rg.close().map_err(store_err)?;
        Ok(())
    }

    /// Writes the footer and returns the sink.
    pub fn finish(self) -> Result<W, CampaignError> {
        self.inner.into_inner().map_err(store_err)
    }
}

/// The Parquet bytes of `cols` (one row group).
pub fn to_bytes(cols: &Columns) -> Result<Vec<u8>, CampaignError> {
    let mut w = Writer::new(Vec::new(), cols.schema()?)?;
    w.write(cols)?;
    w.finish()
}

/// A Parquet file read one row group at a time.
pub struct Reader {
    file: SerializedFileReader<std::fs::File>,
}

impl Reader {
    /// Opens `path` (reads its footer).
    pub fn open(path: &std::path::Path) -> Result<Self, CampaignError> {
        let f = std::fs::File::open(path).map_err(|e| CampaignError::Io {
            what: "cannot open",
            path: path.to_path_buf(),
            cause: e,
        })?;
        let file = SerializedFileReader::new(f)
            .map_err(|e| CampaignError::Store(format!("{}: {e}", path.display())))?;
        Ok(Self { file })
    }

    /// The number of row groups.
    pub fn row_groups(&self) -> usize {
        self.file.metadata().num_row_groups()
    }

    /// The total number of rows.
    pub fn rows(&self) -> usize {
        self.file.metadata().file_metadata().num_rows().max(0) as usize
    }

    /// The column names.
    pub fn names(&self) -> Vec<String> {
        let schema = self.file.metadata().file_metadata().schema_descr_ptr();
        schema
            .columns()
            .iter()
            .map(|c| c.name().to_string())
            .collect()
    }

    /// Row group `i` as columns; `only`: read only the columns of these names.
    pub fn row_group(&self, i: usize, only: Option<&[&str]>) -> Result<Columns, CampaignError> {
        let rg = self.file.get_row_group(i).map_err(store_err)?;
        let n = rg.metadata().num_rows().max(0) as usize;
        let mut out = Columns::default();
        for (j, name) in self.names().into_iter().enumerate() {
            if only.is_some_and(|o| !o.contains(&name.as_str())) {
                continue;
            }
            let cr = rg.get_column_reader(j).map_err(store_err)?;
            let mut def: Vec<i16> = Vec::with_capacity(n);
            let values = match cr {
                ColumnReader::Int64ColumnReader(_) => {
                    let mut v: Vec<i64> = Vec::with_capacity(n);
                    get_typed_column_reader::<Int64Type>(cr)
                        .read_records(n, Some(&mut def), None, &mut v)
                        .map_err(store_err)?;
                    Values::Int(spread(v, &def, n))
                }
                ColumnReader::DoubleColumnReader(_) => {
                    let mut v: Vec<f64> = Vec::with_capacity(n);
                    get_typed_column_reader::<DoubleType>(cr)
                        .read_records(n, Some(&mut def), None, &mut v)
                        .map_err(store_err)?;
                    Values::Float(spread(v, &def, n))
                }
                ColumnReader::ByteArrayColumnReader(_) => {
                    let mut v: Vec<ByteArray> = Vec::with_capacity(n);
                    get_typed_column_reader::<ByteArrayType>(cr)
                        .read_records(n, Some(&mut def), None, &mut v)
                        .map_err(store_err)?;
                    let v = v
                        .into_iter()
                        .map(|b| String::from_utf8(b.data().to_vec()).map_err(store_err))
                        .collect::<Result<Vec<_>, _>>()?;
                    Values::Text(spread(v, &def, n))
                }
                ColumnReader::BoolColumnReader(_) => {
                    let mut v: Vec<bool> = Vec::with_capacity(n);
                    get_typed_column_reader::<BoolType>(cr)
                        .read_records(n, Some(&mut def), None, &mut v)
                        .map_err(store_err)?;
                    Values::Bool(spread(v, &def, n))
                }
                _ => {
                    return Err(CampaignError::Store(format!(
                        "column {name}: a type the campaign store does not write"
                    )));
                }
            };
            if values.len() != n {
                return Err(CampaignError::Store(format!(
                    "column {name}: {} values for {n} rows",
                    values.len()
                )));
            }
            out.cols.push((name, values));
        }
        Ok(out)
    }
}

/// Values with nulls where the definition level is 0 (`def` empty: a required column).
fn spread<T>(v: Vec<T>, def: &[i16], n: usize) -> Vec<Option<T>> {
    if def.is_empty() {
        return v.into_iter().map(Some).collect();
    }
    let mut it = v.into_iter();
    def.iter()
        .take(n)
        .map(|&d| if d > 0 { it.next() } else { None })
        .collect()
}
