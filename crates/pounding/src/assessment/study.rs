//! One fragility study from its scenario to its data files, as `pounding fragility` and the
//! Python package's `pounding.fragility` run it (one code path, the same bytes): [`Study::read`]
//! reads and checks everything before any run, [`Study::plan`] computes the IMs and scale
//! factors, [`Study::run`] runs them, [`Study::fit`] fits every limit state, and
//! [`Study::data_files`] gives the texts of `runs.csv`, `fragility.csv` and `fragility.json`
//! ([`write_data_files`] writes them). The figure, the report and `timing.json` are the CLI's.

use super::im::{ImSpec, PeriodInfo, fundamental_period};
use super::limit::{BoundLimit, bind};
use super::run::{Plan, RunRow, fit_limit_state, run_all, runs_csv};
use super::{AssessmentError, FragilitySettings, ImKind, PeriodChoice};
use crate::fragility::{
    BootstrapSettings, FragilityError, FragilityRow, StudyColumns, fragility_csv_study,
    fragility_json_study,
};
use crate::ground_motion::set::{RecordSet, SetError};
use crate::math::Real;
use crate::sim::scenario::{BridgeSetup, Scenario};
use serde_json::json;
use std::path::{Path, PathBuf};

/// Every file `pounding fragility` writes (removed from the output directory before writing).
pub const OUTPUTS: &[&str] = &[
    "runs.csv",
    "fragility.csv",
    "fragility.json",
    "fragility.png",
    "report.html",
    "timing.json",
    "svgm_ratio.csv",
    "runs_uniform.csv",
    "fragility_uniform.csv",
    "maf.csv",
    "hazard.csv",
    "hazard.png",
];

/// Everything read and checked before any run.
pub struct Study {
    /// The scenario's name in messages.
    pub origin: String,
    /// The bridge, its ground motion and the simulation settings.
    pub setup: BridgeSetup,
    /// The `[fragility]` table and the `[[limit_state]]`s.
    pub settings: FragilitySettings,
    /// The record set.
    pub set: RecordSet,
    /// Where the record set was read from.
    pub set_path: PathBuf,
    /// The limit states bound to the model.
    pub limits: Vec<BoundLimit>,
    /// The intensity measure.
    pub spec: ImSpec,
    /// The model's fundamental period, when the IM is `Sa` at `period_s = "model"`.
    pub period: Option<PeriodInfo>,
    /// The code check of a scenario with a `[code_check]` table (its input read and checked
    /// against the bridge before any run; `Err`: the check could not be evaluated, with the
    /// reason).
    pub code_check: Option<Result<super::CheckReport, String>>,
    /// The `[code_check]` input the check was made with (a campaign variant's bridge is checked
    /// with it again).
    pub code_check_input: Option<super::CodeCheckInput>,
    /// The site hazard curve (`[hazard]`, or [`Study::with_hazard`]): the MAF of every limit
    /// state is computed when present.
    pub hazard: Option<super::hazard_input::HazardInput>,
}

/// The fits of every limit state and the IMs of the bootstrap band.
pub struct Fits {
    /// One fit per limit state, in the scenario's order.
    pub rows: Vec<FragilityRow>,
    /// The IMs \[g\] the band is evaluated at.
    pub band_im: Vec<Real>,
}

impl Study {
    /// Reads the study of `scenario` (a bridge with `[fragility]` and `[[limit_state]]`s): its
    /// record set is `set` when given (`--set`), else `[fragility] records` relative to
    /// `scenario_dir` (the scenario file's directory; `None`: the current directory). Text
    /// records of entries without `units` are read in the scenario's `csv_units`.
    pub fn read(
        scenario: Scenario,
        scenario_dir: Option<&Path>,
        set: Option<&Path>,
    ) -> Result<Self, AssessmentError> {
        Self::read_at(scenario, scenario_dir, set, None)
    }

    /// [`Study::read`] with the period of `Sa` given (`Some`: instead of `[fragility]
    /// period_s`; a design's variants use the as-built bridge's, so that every variant is
    /// compared at the same IM).
    pub fn read_at(
        scenario: Scenario,
        scenario_dir: Option<&Path>,
        set: Option<&Path>,
        period: Option<PeriodChoice>,
    ) -> Result<Self, AssessmentError> {
        let scenario = scenario.for_batch();
        if !scenario.is_bridge() {
            return Err(AssessmentError::Invalid(format!(
                "{}: fragility runs bridge scenarios of [[segment]]s; this is a two-deck \
                 scenario ([decks]): describe it as a two-segment bridge",
                scenario.origin()
            )));
        }
        let setup = scenario.build_bridge()?;
        let mut settings = FragilitySettings::from_scenario(scenario.text(), scenario.origin())?;
        if let Some(p) = period {
            settings.period = p;
        }
        let set_path = match (set, &settings.records) {
            (Some(p), _) => p.to_path_buf(),
            (None, Some(rel)) => scenario_dir.map_or_else(|| rel.clone(), |d| d.join(rel)),
            (None, None) => {
                return Err(AssessmentError::Invalid(format!(
                    "{}: no record set: give [fragility] records = \"MANIFEST.toml\" (or .csv) \
                     or --set MANIFEST",
                    scenario.origin()
                )));
            }
        };
        let reading = scenario.override_reading(None)?;
        let records = RecordSet::load_with_units(&set_path, reading.units, &reading.units_from)
            .map_err(|e| match (set, e) {
                // a manifest that cannot be read or has no known extension: name the key
                (None, e @ (SetError::Read { .. } | SetError::Extension { .. })) => {
                    AssessmentError::Key {
                        message: e.to_string(),
                        key: "fragility.records".into(),
                        origin: scenario.origin().to_string(),
                        line: settings.records_line,
                    }
                }
                (_, e) => e.into(),
            })?;
        // a `[code_check]` table is read (and refused, naming its key) before any run
        let (code_check, code_check_input) = if super::CodeCheckInput::is_present(scenario.text()) {
            let input = super::CodeCheckInput::from_scenario(scenario.text(), scenario.origin())?;
            input.check_segments(setup.problem.model.segments.len())?;
            let report = super::check_bridge(&setup.problem.model, &input, scenario.origin())
                .map_err(|e| e.to_string());
            (Some(report), Some(input))
        } else {
            (None, None)
        };
        let limits = bind(
            &settings.limit_states,
            &setup.problem.model,
            scenario.origin(),
        )?;
        let (period, info) = match settings.period {
            PeriodChoice::Given(t) => (t, None),
            PeriodChoice::Model => {
                let p = fundamental_period(&setup.problem.model)?;
                (p.period, Some(p))
            }
        };
        // support-motion entries: refused before any run if no run could take them
        let entries = crate::sim::batch::BatchRecord::of_set(&records);
        crate::sim::batch::check_support_entries(&setup.problem, &entries).map_err(|e| {
            AssessmentError::Invalid(format!(
                "record set {}: its support-motion entries cannot run on {}: {e}",
                set_path.display(),
                scenario.origin()
            ))
        })?;
        let spec = ImSpec {
            kind: settings.im,
            period,
            damping: settings.damping,
            pair: settings.pair_im,
        };
        let hazard = super::hazard_input::HazardInput::from_toml(
            scenario.text(),
            scenario.origin(),
            scenario_dir.unwrap_or(Path::new(".")),
        )?;
        if let Some(h) = &hazard {
            h.check_against(&spec)?;
        }
        Ok(Study {
            origin: scenario.origin().to_string(),
            setup,
            period: (settings.im == ImKind::Sa).then_some(info).flatten(),
            settings,
            set: records,
            set_path,
            limits,
            spec,
            code_check,
            code_check_input,
            hazard,
        })
    }

    /// Replaces the hazard curve by the one of `path` (`--hazard`: a `.csv` table or a `.toml`
    /// file with a `[hazard]` table), checked against the study's IM.
    pub fn with_hazard(mut self, path: &Path) -> Result<Self, AssessmentError> {
        let h = super::hazard_input::HazardInput::from_path(path)?;
        h.check_against(&self.spec)?;
        self.hazard = Some(h);
        Ok(self)
    }

    /// With a hazard: the MAF of every limit state ([`super::hazard_study::maf_rows`]).
    pub fn maf(&self, fits: &Fits) -> Option<Vec<super::hazard_study::MafRow>> {
        let h = self.hazard.as_ref()?;
        Some(super::hazard_study::maf_rows(&h.curve, &fits.rows))
    }

    /// With a hazard: the texts of `maf.csv` and `hazard.csv` (empty without one).
    pub fn hazard_files(&self, fits: &Fits) -> Vec<(&'static str, String)> {
        let (Some(h), Some(rows)) = (&self.hazard, self.maf(fits)) else {
            return Vec::new();
        };
        vec![
            ("maf.csv", super::hazard_study::maf_csv(h, &rows)),
            (
                "hazard.csv",
                super::hazard_study::hazard_csv(h, &fits.rows, &rows),
            ),
        ]
    }

    /// The scenario's name.
    pub fn scenario_origin(&self) -> &str {
        &self.origin
    }

    /// The implausible-PGA warnings of the set's records (units probably wrong), one per
    /// component, naming the entry.
    pub fn record_warnings(&self) -> Vec<String> {
        use crate::ground_motion::ComponentInfo;
        self.set
            .records
            .iter()
            .flat_map(|r| {
                [("x", Some(&r.x)), ("y", r.y.as_ref())]
                    .into_iter()
                    .filter_map(move |(c, rec)| {
                        let w = ComponentInfo::of(c, rec?).units_warning()?;
                        Some(format!("record set entry {:?}: {w}", r.id))
                    })
            })
            .collect()
    }

    /// The IM of every entry and the scale factor of every run ([`Plan::new`], on the current
    /// rayon pool).
    pub fn plan(&self) -> Result<Plan, AssessmentError> {
        Plan::new(
            &self.set,
            &self.spec,
            &self.settings.stripes,
            &self.setup.problem.ground,
        )
    }

    /// Runs every entry at every stripe on the current rayon pool ([`run_all`]).
    pub fn run(&self, plan: &Plan, progress: &(dyn Fn() + Sync)) -> Vec<RunRow> {
        run_all(
            &self.setup.problem,
            &self.setup.settings,
            &self.set,
            plan,
            &self.limits,
            progress,
        )
    }

    /// Fits every limit state ([`fit_limit_state`], on the current rayon pool); the band spans
    /// the IMs run, 60 points evenly spaced in log IM.
    pub fn fit(&self, plan: &Plan, rows: &[RunRow]) -> Result<Fits, FragilityError> {
        let (lo, hi) = rows
            .iter()
            .fold((Real::INFINITY, 0.0 as Real), |(a, b), r| {
                (a.min(r.im_g), b.max(r.im_g))
            });
        let band_im: Vec<Real> = (0..60)
            .map(|k| (lo.ln() + (hi / lo).ln() * k as Real / 59.0).exp())
            .filter(|x| x.is_finite() && *x > 0.0)
            .collect();
        let b = BootstrapSettings {
            samples: self.settings.bootstrap,
            seed: self.settings.seed,
            level: self.settings.level,
        };
        let fits = self
            .limits
            .iter()
            .enumerate()
            .map(|(l, lim)| fit_limit_state(&lim.state.name, plan, rows, l, &b, &band_im))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Fits {
            rows: fits,
            band_im,
        })
    }

    /// The texts of `runs.csv`, `fragility.csv` and `fragility.json`, in that order.
    pub fn data_files(
        &self,
        plan: &Plan,
        rows: &[RunRow],
        fits: &Fits,
    ) -> [(&'static str, String); 3] {
        let label = self.spec.label();
        let cols = StudyColumns {
            im: &label,
            im_unit: "g",
            level: self.settings.level,
        };
        [
            (
                "runs.csv",
                runs_csv(
                    &self.set,
                    plan,
                    &self.limits,
                    &self.setup.problem.model.seat_end_names(),
                    rows,
                ),
            ),
            ("fragility.csv", fragility_csv_study(&fits.rows, &cols)),
            (
                "fragility.json",
                self.fragility_json(plan, rows, fits, &cols),
            ),
        ]
    }

    /// `fragility.json`: the fits ([`fragility_json_study`]) with the IM, the period, the
    /// counts of records, runs and excluded runs, and the empirical points of every limit state.
    fn fragility_json(
        &self,
        plan: &Plan,
        rows: &[RunRow],
        fits: &Fits,
        cols: &StudyColumns,
    ) -> String {
        let mut j = fragility_json_study(&fits.rows, cols);
        if let Some(o) = j.as_object_mut() {
            o.insert("im".into(), json!(self.spec.label()));
            o.insert(
                "period".into(),
                json!(self.period.as_ref().map(PeriodInfo::describe)),
            );
            o.insert("records".into(), json!(self.set.records.len()));
            o.insert("runs".into(), json!(rows.len()));
            o.insert(
                "runs_excluded".into(),
                json!(rows.iter().filter(|r| !r.trusted()).count()),
            );
            let emp: serde_json::Map<String, serde_json::Value> = self
                .limits
                .iter()
                .enumerate()
                .map(|(l, lim)| {
                    let pts: Vec<serde_json::Value> = empirical(plan, rows, l)
                        .into_iter()
                        .map(|(im, p, n)| json!({"im_g": im, "runs": n, "fraction": p}))
                        .collect();
                    (lim.state.name.clone(), json!(pts))
                })
                .collect();
            o.insert("empirical".into(), serde_json::Value::Object(emp));
            if let (Some(h), Some(m)) = (&self.hazard, self.maf(fits)) {
                o.insert("hazard".into(), super::hazard_study::hazard_json(h, &m));
            }
        }
        crate::output::json_without_negative_zero(&mut j);
        // a serde_json::Value of strings, numbers and maps always serialises
        serde_json::to_string_pretty(&j).unwrap_or_default() + "\n"
    }
}

/// The warnings after the fits: each fit's interval warnings, then how many runs have
/// warnings of their own (`total` runs).
pub fn fit_warnings(rows: &[RunRow], fits: &Fits) -> Vec<String> {
    let mut out: Vec<String> = fits
        .rows
        .iter()
        .flat_map(FragilityRow::interval_warnings)
        .collect();
    let warned = rows.iter().filter(|r| r.warnings > 0).count();
    if warned > 0 {
        out.push(format!(
            "{warned} of {} runs have warnings (a time step coarser than the record's samples, \
             energy created at a contact, ...): the warnings column of runs.csv counts them; \
             reproduce a run to read them (a single record: `pounding simulate --record R \
             --scale S`; a pair: `pounding simulate --set` with a manifest of that pair and \
             `--scales S`, or the fragility guide's recipe)",
            rows.len()
        ));
    }
    out
}

/// The message for runs that failed or are not trustworthy (excluded from the fit), or `None`
/// when every run is `Completed` (the CLI then exits 0, otherwise 1 after writing).
pub fn excluded_message(rows: &[RunRow]) -> Option<String> {
    let excluded = rows.iter().filter(|r| !r.trusted()).count();
    (excluded > 0).then(|| {
        format!(
            "{excluded} of {} runs failed or are not trustworthy (status in runs.csv): excluded \
             from the fit",
            rows.len()
        )
    })
}

/// Empirical points of limit state `l`: per stripe, `(IM, fraction exceeded, runs counted)`;
/// the IM of a stripe is its level (stripes) or the median IM of its runs (IDA).
pub fn empirical(plan: &Plan, rows: &[RunRow], l: usize) -> Vec<(Real, Real, usize)> {
    let ns = plan.values().len();
    (0..ns)
        .filter_map(|b| {
            let runs: Vec<&RunRow> = rows.iter().filter(|r| r.stripe == b).collect();
            let mut ims: Vec<Real> = runs.iter().map(|r| r.im_g).collect();
            ims.sort_by(Real::total_cmp);
            let im = match ims.len() {
                0 => return None,
                n if n % 2 == 1 => ims[n / 2],
                n => 0.5 * (ims[n / 2 - 1] + ims[n / 2]),
            };
            let counted: Vec<bool> = runs.iter().filter_map(|r| r.limits[l].0).collect();
            let n = counted.len();
            (n > 0).then(|| {
                (
                    im,
                    counted.iter().filter(|&&x| x).count() as Real / n as Real,
                    n,
                )
            })
        })
        .collect()
}

/// Writes the data `files` ([`Study::data_files`]) into `out` (created if needed): locks it,
/// removes the previous outputs of a study ([`OUTPUTS`], so no figure or report of another
/// study stays beside the new data), then writes each file atomically.
pub fn write_data_files(
    out: &Path,
    files: &[(&str, String)],
) -> Result<(), crate::output::OutputError> {
    let lock = crate::output::lock_output_dir(out)?;
    crate::output::remove_previous_outputs(&lock, OUTPUTS)?;
    for (name, text) in files {
        let path = out.join(name);
        crate::output::write_atomic(&path, text.as_bytes()).map_err(|cause| {
            crate::output::OutputError::Io {
                what: "cannot write",
                path: path.clone(),
                cause,
            }
        })?;
    }
    Ok(())
}
