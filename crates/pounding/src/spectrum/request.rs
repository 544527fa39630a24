//! The spectra of `pounding spectrum` from its arguments, as the CLI and the Python package's
//! `pounding.spectrum` compute them (one code path, the same numbers): [`SpectrumRequest::read`]
//! checks the arguments and reads every record (nothing is computed before all are read), and
//! [`SpectrumInputs::curves`] gives the curves of `spectrum.csv` ([`super::spectrum_csv`]).
//! Messages name the CLI's flags (`--damping`, `--record-dt`, ...); another front end renames
//! them with [`crate::input::rename_flags`].

use super::{Curve, SpectrumError, check, default_periods, rotd, spectrum};
use crate::ground_motion::{AccelUnits, BUILTIN_RECORDS, ReadOptions, Record, builtin_record};
use crate::math::Real;
use crate::output::float_token;
use std::path::Path;

/// Bad arguments of a spectrum request (the message names the flag or the record).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct RequestError(pub String);

/// The arguments of `pounding spectrum`.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumRequest {
    /// Records (file names or `builtin:ELC180` / `builtin:ELC270`): component `x` each.
    pub records: Vec<String>,
    /// Horizontal pairs `(X, Y)`: components `x`, `y`, `rotd50`, `rotd100` each.
    pub pairs: Vec<(String, String)>,
    /// Damping ratio (a fraction of critical).
    pub damping: Real,
    /// Periods \[s\]; empty: [`default_periods`].
    pub periods: Vec<Real>,
    /// Units of text records: `g` or `m/s2`.
    pub csv_units: String,
    /// Sample interval \[s\] of one-column records.
    pub record_dt: Option<Real>,
}

/// A checked request with its records read.
#[derive(Debug, Clone)]
pub struct SpectrumInputs {
    /// The single records by name.
    pub singles: Vec<(String, Record)>,
    /// The pairs: `X+Y` and the two records.
    pub pairs: Vec<(String, Record, Record)>,
    /// Damping ratio.
    pub damping: Real,
    /// Periods \[s\].
    pub periods: Vec<Real>,
}

impl SpectrumRequest {
    /// Checks the arguments and reads every record (errors name the flag or record; nothing is
    /// computed).
    pub fn read(&self) -> Result<SpectrumInputs, RequestError> {
        let bad = |m: String| RequestError(m);
        if self.records.is_empty() && self.pairs.is_empty() {
            return Err(bad(
                "give at least one record or --pair X Y (e.g. pounding spectrum \
                 builtin:ELC180)"
                    .into(),
            ));
        }
        let periods = if self.periods.is_empty() {
            default_periods()
        } else {
            self.periods.clone()
        };
        check(self.damping, &[]).map_err(|e| bad(format!("{e} (--damping)")))?;
        check(self.damping, &periods).map_err(|e| bad(format!("{e} (--periods)")))?;
        let mut sorted = periods.clone();
        sorted.sort_by(Real::total_cmp);
        if let Some(w) = sorted.windows(2).find(|w| w[0] == w[1]) {
            return Err(bad(format!(
                "invalid --periods: {} s is given twice",
                float_token(w[0])
            )));
        }
        let units = AccelUnits::from_name(&self.csv_units).ok_or_else(|| {
            bad(format!(
                "invalid --csv-units {:?}: use g or m/s2",
                self.csv_units
            ))
        })?;
        if let Some(dt) = self.record_dt
            && !(dt.is_finite() && dt > 0.0)
        {
            return Err(bad(format!(
                "invalid --record-dt {}: must be finite and > 0",
                float_token(dt)
            )));
        }
        let opts = ReadOptions {
            units,
            units_from: "--csv-units".into(),
            dt: self.record_dt,
            dt_from: "--record-dt".into(),
            dt_default: false,
        };
        let singles = self
            .records
            .iter()
            .map(|n| Ok((n.clone(), load(n, &opts)?)))
            .collect::<Result<_, RequestError>>()?;
        let pairs = self
            .pairs
            .iter()
            .map(|(x, y)| Ok((format!("{x}+{y}"), load(x, &opts)?, load(y, &opts)?)))
            .collect::<Result<_, RequestError>>()?;
        Ok(SpectrumInputs {
            singles,
            pairs,
            damping: self.damping,
            periods,
        })
    }
}

impl SpectrumInputs {
    /// The curves of `spectrum.csv`: each single record's `x`, then each pair's `x`, `y`,
    /// `rotd50` and `rotd100`.
    pub fn curves(&self) -> Result<Vec<Curve>, SpectrumError> {
        let (d, periods) = (self.damping, &self.periods[..]);
        let mut curves = Vec::new();
        let curve = |record: &str, component: &str, ordinates| Curve {
            record: record.to_string(),
            component: component.into(),
            ordinates,
        };
        for (name, r) in &self.singles {
            curves.push(curve(name, "x", spectrum(r, d, periods)?));
        }
        for (name, x, y) in &self.pairs {
            let rd = rotd(x, y, d, periods)?;
            curves.push(curve(name, "x", spectrum(x, d, periods)?));
            curves.push(curve(name, "y", spectrum(y, d, periods)?));
            curves.push(curve(name, "rotd50", rd.rotd50));
            curves.push(curve(name, "rotd100", rd.rotd100));
        }
        Ok(curves)
    }
}

/// A record by file name or `builtin:NAME`, refused if it has fewer than two samples (a
/// spectrum of one sample would be all zeros: the load is zero after the last sample).
fn load(name: &str, opts: &ReadOptions) -> Result<Record, RequestError> {
    let r = load_any(name, opts)?;
    if r.times().len() < 2 {
        return Err(RequestError(format!(
            "record {name}: {} sample: a spectrum needs at least two (the record is linear \
             between its samples and zero after the last)",
            r.times().len()
        )));
    }
    Ok(r)
}

fn load_any(name: &str, opts: &ReadOptions) -> Result<Record, RequestError> {
    if let Some(b) = name.strip_prefix("builtin:") {
        if opts.dt.is_some() {
            return Err(RequestError(format!(
                "--record-dt does not apply to the built-in record {name} (it carries its own \
                 times)"
            )));
        }
        return builtin_record(b).ok_or_else(|| {
            RequestError(format!(
                "unknown built-in record {name:?}: use {BUILTIN_RECORDS}"
            ))
        });
    }
    Record::from_path_with(Path::new(name), opts).map_err(|e| RequestError(e.to_string()))
}
