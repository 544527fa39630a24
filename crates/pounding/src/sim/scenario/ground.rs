//! `[ground_motion]`: the records (files read in the format [`crate::ground_motion::format`]
//! finds, with `csv_units` and `record_dt`), the `--record` override, scales and incidence.

use super::build::sim_error;
use super::error::{ParamKey, ScenarioError, Section};
use super::{Scenario, Src};
use crate::ground_motion::{
    AccelUnits, EL_CENTRO_180_AT2, EL_CENTRO_270_AT2, GroundMotion, ReadOptions, Record,
};
use crate::math::Real;
use crate::output::float_token;
use crate::sim::SimError;

const fn ground(key: &'static str) -> ParamKey {
    ParamKey::new(Section::GroundMotion, key)
}

/// A record named by `[ground_motion] key`: `none`, `builtin:…` or a path relative to the
/// scenario file, read with `opts`.
fn load_record(
    src: &Src,
    spec: &str,
    key: &'static str,
    opts: &ReadOptions,
) -> Result<Option<Record>, ScenarioError> {
    let spec_t = spec.trim();
    if spec_t.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    let at = || src.at(ground(key));
    if spec_t.is_empty() {
        return Err(src.key_error(
            format!(
                "{key} is empty at {}: give a record file (relative to the scenario), \
                 builtin:ELC180 / builtin:ELC270, or \"none\"",
                at()
            ),
            &[ground(key)],
        ));
    }
    let wrap = |error| ScenarioError::Record {
        at: at(),
        error: Box::new(error),
    };
    if let Some(b) = spec_t.strip_prefix("builtin:") {
        let (text, name) = match b {
            "ELC180" => (EL_CENTRO_180_AT2, "RSN6_IMPVALL.I_I-ELC180-hor1.AT2"),
            "ELC270" => (EL_CENTRO_270_AT2, "RSN6_IMPVALL.I_I-ELC270-hor2.AT2"),
            other => {
                return Err(src.key_error(
                    format!(
                        "unknown built-in record {other:?} in {} (use builtin:ELC180 or \
                         builtin:ELC270)",
                        at()
                    ),
                    &[ground(key)],
                ));
            }
        };
        if opts.dt.is_some() {
            return Err(src.key_error(
                format!(
                    "{} applies to one-column record files, but {} names the built-in record \
                     {spec_t}, which has its own DT: remove record_dt",
                    src.at(ground("record_dt")),
                    at()
                ),
                &[ground("record_dt"), ground(key)],
            ));
        }
        return Record::from_at2_str(text, name).map(Some).map_err(wrap);
    }
    Record::from_path_with(&src.dir.join(spec_t), opts)
        .map(Some)
        .map_err(wrap)
}

/// `csv_units` of the scenario, with its label (`csv_units` when the file sets it, else
/// `csv_units default`).
fn csv_units(sc: &Scenario) -> Result<(AccelUnits, &'static str), ScenarioError> {
    let src = &sc.src;
    let g = &sc.raw.ground_motion;
    let units = AccelUnits::from_name(&g.csv_units).ok_or_else(|| {
        src.key_error(
            format!(
                "invalid csv_units {:?} at {}: use \"g\" or \"m/s2\"",
                g.csv_units,
                src.at(ground("csv_units"))
            ),
            &[ground("csv_units")],
        )
    })?;
    // the built-in default writes its defaults out
    let from = match src.is_set(ground("csv_units")) && !src.builtin {
        true => "csv_units",
        false => "csv_units default",
    };
    Ok((units, from))
}

/// A sample interval must be finite and > 0.
fn check_dt(dt: Option<Real>, what: &str) -> Result<(), String> {
    match dt {
        Some(v) if !(v.is_finite() && v > 0.0) => Err(format!(
            "invalid {what} = {}: the sample interval must be finite and > 0 s",
            float_token(v)
        )),
        _ => Ok(()),
    }
}

impl Scenario {
    /// The sample interval \[s\] of one-column files given on the command line (`--record-dt`)
    /// for the `--record` file or the files of a batch (the scenario's `record_dt` applies to
    /// its own `record_y` / `record_x` only).
    pub fn with_record_dt(mut self, dt: Option<Real>) -> Self {
        self.record_dt = dt;
        self
    }

    /// How the files given on the command line (`--record`, `--records`) are read: text formats
    /// in `units` (`--csv-units`) if given, else the scenario's `csv_units`; one-column files with
    /// the interval of [`Scenario::with_record_dt`] if given, else the scenario's `record_dt`
    /// (a default: files with their own times are read without it,
    /// [`ReadOptions::dt_default`]). Errors: an invalid `csv_units` (key and line), `record_dt`
    /// or `--record-dt`.
    pub fn override_reading(
        &self,
        units: Option<AccelUnits>,
    ) -> Result<ReadOptions, ScenarioError> {
        let (own, from) = csv_units(self)?;
        check_dt(self.record_dt, "--record-dt").map_err(|message| ScenarioError::Key {
            message,
            at: Vec::new(),
        })?;
        let scenario = self.scenario_reading()?;
        let (dt, dt_from, dt_default) = match (self.record_dt, scenario.dt) {
            (Some(dt), _) => (Some(dt), "--record-dt".to_string(), false),
            (None, Some(dt)) => (Some(dt), scenario.dt_from, true),
            (None, None) => (None, "--record-dt".to_string(), false),
        };
        Ok(ReadOptions {
            units: units.unwrap_or(own),
            units_from: match units {
                Some(_) => "--csv-units".into(),
                None => from.into(),
            },
            dt,
            dt_from,
            dt_default,
        })
    }

    /// How the scenario's own record files are read (`csv_units`, `record_dt`).
    fn scenario_reading(&self) -> Result<ReadOptions, ScenarioError> {
        let src = &self.src;
        let (units, from) = csv_units(self)?;
        let dt = self.raw.ground_motion.record_dt;
        check_dt(dt, "record_dt").map_err(|m| src.invalid(m, ground("record_dt")))?;
        Ok(ReadOptions {
            units,
            units_from: from.into(),
            dt,
            dt_from: format!("record_dt ({})", src.at(ground("record_dt"))),
            dt_default: false,
        })
    }
}

/// The ground motion of `[ground_motion]` and the overrides, with the record names and units.
pub(in crate::sim::scenario) fn build_ground(
    sc: &Scenario,
) -> Result<(GroundMotion, [String; 2], AccelUnits), ScenarioError> {
    let src = &sc.src;
    let g = &sc.raw.ground_motion;
    let own = sc.scenario_reading()?;
    let units = own.units;
    let files = super::supports::check_support_files(sc)?;
    let (along_y, along_x, records) = match &sc.record {
        // the records are the support-motion files' (build_supports)
        _ if files => (None, None, super::supports::support_files(sc)),
        None if sc.batch => (None, None, ["batch".into(), "none".into()]),
        Some((p, u)) => {
            let reading = sc.override_reading(*u)?;
            let fail = |error| ScenarioError::RecordOverride {
                path: p.display().to_string(),
                error: Box::new(error),
            };
            let r = Record::open_with(p, &reading).map_err(fail)?;
            (Some(r), None, [p.display().to_string(), "none".into()])
        }
        None => {
            let files = [&g.record_y, &g.record_x]
                .iter()
                .any(|r| !r.trim().eq_ignore_ascii_case("none"));
            if own.dt.is_some() && !files {
                return Err(src.key_error(
                    format!(
                        "{} is given but record_y and record_x are \"none\": remove record_dt",
                        src.at(ground("record_dt"))
                    ),
                    &[ground("record_dt")],
                ));
            }
            (
                load_record(src, &g.record_y, "record_y", &own)?,
                load_record(src, &g.record_x, "record_x", &own)?,
                [g.record_y.clone(), g.record_x.clone()],
            )
        }
    };
    let mult = match sc.scale {
        Some(s) if s.is_finite() => s,
        Some(s) => return Err(ScenarioError::Scale(s)),
        None => 1.0,
    };
    let ground = GroundMotion {
        along_y,
        scale_y: g.scale_y * mult,
        along_x,
        scale_x: g.scale_x * mult,
        incidence: g.incidence_deg.to_radians(),
    };
    ground
        .validate()
        .map_err(|e| sim_error(src, SimError::from(e)))?;
    Ok((ground, records, units))
}
