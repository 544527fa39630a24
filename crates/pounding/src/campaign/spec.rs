//! The campaign spec (`[campaign]`, `[outputs]`), read and checked with key and line, and its
//! expansion into runs ([`Campaign::run_spec`]).

use super::{CampaignError, Fnv};
use crate::assessment::Stripes;
use crate::assessment::run::Plan;
use crate::assessment::study::Study;
use crate::math::Real;
use crate::output::float_token;
use crate::sim::scenario::Scenario;
use crate::toml_schema::{Table, line_col};
use serde::Deserialize;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Default runs per part.
pub const DEFAULT_RUNS_PER_PART: usize = 64;
/// Largest runs per part (a part is held in memory while it is computed and written).
pub const MAX_RUNS_PER_PART: usize = 100_000;
/// Largest number of runs of one campaign.
pub const MAX_RUNS: usize = 100_000_000;
pub use super::variants::BASE_VARIANT;

type Sp<T> = Option<Spanned<T>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    campaign: Option<Spanned<Table<CampaignSec>>>,
    outputs: Option<Spanned<Table<OutputsSec>>>,
    /// `[[variant]]` tables, read by [`super::variants`].
    #[allow(dead_code)]
    variant: Option<toml::Value>,
    /// `[grid]`, read by [`super::variants`].
    #[allow(dead_code)]
    grid: Option<toml::Value>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct CampaignSec {
    name: Sp<String>,
    scenario: Sp<String>,
    records: Sp<String>,
    levels_g: Sp<Vec<Real>>,
    scales: Sp<Vec<Real>>,
    runs_per_part: Sp<i64>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct OutputsSec {
    seats: Sp<bool>,
    histories: Sp<bool>,
}

/// One run of a campaign.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSpec {
    /// The global run index `(v R + a) S + b`.
    pub index: usize,
    /// The stable id `VARIANT/RECORD/level_g=L` (or `scale=s`).
    pub id: String,
    /// The variant's index.
    pub variant: usize,
    /// The record-set entry's index.
    pub entry: usize,
    /// The stripe's index.
    pub stripe: usize,
    /// The run's IM \[g\].
    pub im_g: Real,
    /// The factor both components are multiplied by.
    pub scale_factor: Real,
}

/// A campaign read and planned: everything checked before any run.
pub struct Campaign {
    /// The spec's path.
    pub path: PathBuf,
    /// `[campaign] name` (the spec's file stem when not given).
    pub name: String,
    /// The study every variant runs (scenario, record set, IM, limit states).
    pub study: Study,
    /// The IM of every entry and the stripes.
    pub plan: Plan,
    /// Variant names (one, [`BASE_VARIANT`], without `[[variant]]` or `[grid]`).
    pub variants: Vec<String>,
    /// Each variant's bridge and limit states, in the order of `variants`.
    pub variant_runs: Vec<super::variants::VariantRun>,
    /// Runs per part.
    pub runs_per_part: usize,
    /// Whether the per-end seat ratios are stored.
    pub seats: bool,
    /// The hash of everything the stored results depend on.
    pub fingerprint: u64,
    /// The hash of the scenario's text (checked by `fragility --from-store`).
    pub scenario_fingerprint: u64,
}

/// Error context: the spec's name and text.
struct Cx<'a> {
    origin: &'a str,
    text: &'a str,
}

impl Cx<'_> {
    fn err<T>(&self, key: &str, s: &Spanned<T>, msg: String) -> CampaignError {
        CampaignError::Key {
            message: msg,
            key: key.to_string(),
            origin: self.origin.to_string(),
            line: Some(line_col(self.text, s.span().start).0),
        }
    }
}

/// Stripes from the spec: not empty, every value finite and > 0, strictly increasing.
fn stripes(cx: &Cx, key: &str, v: &Spanned<Vec<Real>>) -> Result<Vec<Real>, CampaignError> {
    let x = v.get_ref();
    if x.is_empty() {
        return Err(cx.err(key, v, "give at least one value".into()));
    }
    if let Some(bad) = x.iter().find(|x| !(x.is_finite() && **x > 0.0)) {
        let what = if bad.is_finite() {
            "not > 0"
        } else {
            "not a finite number"
        };
        return Err(cx.err(key, v, format!("{bad} is {what}: give finite values > 0")));
    }
    if x.windows(2).any(|w| w[1] <= w[0]) {
        return Err(cx.err(key, v, "the values must increase strictly".into()));
    }
    Ok(x.clone())
}

impl Campaign {
    /// Reads the spec at `path`, its scenario, record set and limit states, and computes the IM
    /// plan (on the current rayon pool).
    pub fn load(path: &Path) -> Result<Self, CampaignError> {
        Self::load_with_progress(path, &|_, _| {})
    }

    /// [`Campaign::load`], calling `progress(built, variants)` as the variants' scenarios are
    /// read and built (in parallel on the current rayon pool; each takes about as long as
    /// reading the scenario: tens of milliseconds).
    pub fn load_with_progress(
        path: &Path,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Result<Self, CampaignError> {
        let text = crate::input::read_text(path, "campaign spec", crate::input::SCENARIO_LIMIT)
            .map_err(|cause| CampaignError::Io {
                what: "cannot read the campaign spec",
                path: path.to_path_buf(),
                cause,
            })?;
        Self::read(
            &text,
            &path.display().to_string(),
            path.parent(),
            path,
            progress,
        )
    }

    /// Reads a spec from its `text` named `origin`; paths in it are relative to `dir`.
    pub fn from_toml(
        text: &str,
        origin: &str,
        dir: Option<&Path>,
        path: &Path,
    ) -> Result<Self, CampaignError> {
        Self::read(text, origin, dir, path, &|_, _| {})
    }

    fn read(
        text: &str,
        origin: &str,
        dir: Option<&Path>,
        path: &Path,
        progress: &(dyn Fn(usize, usize) + Sync),
    ) -> Result<Self, CampaignError> {
        let cx = Cx { origin, text };
        let f: File = toml::from_str(text).map_err(|e| CampaignError::Syntax {
            origin: origin.to_string(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let Some(sec) = f.campaign else {
            return Err(CampaignError::Key {
                message: "the spec has no [campaign] table (scenario = \"BRIDGE.toml\", …)".into(),
                key: "campaign".into(),
                origin: origin.to_string(),
                line: None,
            });
        };
        let c = &sec.get_ref().0;
        let rel = |p: &str| dir.map_or_else(|| PathBuf::from(p), |d| d.join(p));
        let Some(sc) = &c.scenario else {
            return Err(CampaignError::Key {
                message: "give the bridge scenario: scenario = \"BRIDGE.toml\"".into(),
                key: "campaign.scenario".into(),
                origin: origin.to_string(),
                line: Some(line_col(text, sec.span().start).0),
            });
        };
        let sc_path = rel(sc.get_ref());
        let scenario = Scenario::load(&sc_path).map_err(|e| {
            cx.err(
                "campaign.scenario",
                sc,
                format!("cannot read the scenario {}: {e}", sc_path.display()),
            )
        })?;
        let scenario_fingerprint = super::scenario_fingerprint(scenario.text());
        let set = c.records.as_ref().map(|r| rel(r.get_ref()));
        let base_scenario = scenario.clone();
        let mut study = Study::read(scenario, sc_path.parent(), set.as_deref()).map_err(|e| {
            match (e, &c.records) {
                // the spec's record set cannot be read: name the spec's key
                (
                    crate::assessment::AssessmentError::Set(
                        e @ (crate::ground_motion::set::SetError::Read { .. }
                        | crate::ground_motion::set::SetError::Extension { .. }),
                    ),
                    Some(r),
                ) => cx.err("campaign.records", r, e.to_string()),
                (e, _) => e.into(),
            }
        })?;
        match (&c.levels_g, &c.scales) {
            (Some(_), Some(s)) => {
                return Err(cx.err(
                    "campaign.scales",
                    s,
                    "give levels_g or scales, not both".into(),
                ));
            }
            (Some(l), None) => {
                study.settings.stripes = Stripes::Levels(stripes(&cx, "campaign.levels_g", l)?)
            }
            (None, Some(s)) => {
                study.settings.stripes = Stripes::Scales(stripes(&cx, "campaign.scales", s)?)
            }
            (None, None) => {}
        }
        let runs_per_part = match &c.runs_per_part {
            None => DEFAULT_RUNS_PER_PART,
            Some(v) => match usize::try_from(*v.get_ref()) {
                Ok(n) if (1..=MAX_RUNS_PER_PART).contains(&n) => n,
                _ => {
                    return Err(cx.err(
                        "campaign.runs_per_part",
                        v,
                        format!("need 1 ..= {MAX_RUNS_PER_PART}"),
                    ));
                }
            },
        };
        let (mut seats, mut histories) = (true, None);
        if let Some(o) = &f.outputs {
            let o = &o.get_ref().0;
            seats = o.seats.as_ref().is_none_or(|s| *s.get_ref());
            histories = o.histories.clone();
        }
        if let Some(h) = histories.filter(|h| *h.get_ref()) {
            return Err(cx.err(
                "outputs.histories",
                &h,
                "a campaign stores each run's summary quantities, not its time histories: \
                 run single records with `pounding simulate` for histories"
                    .into(),
            ));
        }
        let plan = study.plan()?;
        let variant_runs =
            super::variants::variants(text, origin, &sc_path, &base_scenario, &study, progress)?;
        let name = match &c.name {
            Some(n) if n.get_ref().trim().is_empty() => {
                return Err(cx.err("campaign.name", n, "the name is empty".into()));
            }
            Some(n) => n.get_ref().clone(),
            None => path
                .file_stem()
                .map_or("campaign".into(), |s| s.to_string_lossy().into_owned()),
        };
        let mut out = Campaign {
            path: path.to_path_buf(),
            name,
            study,
            plan,
            variants: variant_runs.iter().map(|v| v.name.clone()).collect(),
            variant_runs,
            runs_per_part,
            seats,
            fingerprint: 0,
            scenario_fingerprint,
        };
        let runs = out.runs();
        if runs == 0 || runs > MAX_RUNS {
            return Err(CampaignError::Key {
                message: format!("{runs} runs: need 1 ..= {MAX_RUNS}"),
                key: "campaign".into(),
                origin: origin.to_string(),
                line: Some(line_col(text, sec.span().start).0),
            });
        }
        out.fingerprint = out.compute_fingerprint();
        Ok(out)
    }

    /// The hash of what the stored results depend on: the scenario's text, every record's
    /// samples, the stripes, the IMs, the variants, the part size and the columns.
    fn compute_fingerprint(&self) -> u64 {
        let mut h = Fnv::default();
        h.text("pounding campaign 1");
        h.bytes(&self.scenario_fingerprint.to_le_bytes());
        for e in &self.study.set.records {
            h.text(&e.id);
            for r in std::iter::once(&e.x)
                .chain(e.y.as_ref())
                .chain(e.supports.iter().map(|(_, r)| r))
            {
                h.floats(r.times());
                h.floats(r.values());
            }
        }
        h.text(self.stripe_column());
        h.floats(self.plan.values());
        h.floats(&self.plan.entry_im);
        for v in &self.variant_runs {
            h.text(&v.name);
            h.bytes(&v.fingerprint.to_le_bytes());
        }
        h.bytes(&(self.runs_per_part as u64).to_le_bytes());
        for c in self.column_names() {
            h.text(&c);
        }
        h.0
    }

    /// `level_g` (stripes) or `scale` (IDA): the name of the stripe column.
    pub fn stripe_column(&self) -> &'static str {
        match self.plan.stripes {
            Stripes::Levels(_) => "level_g",
            Stripes::Scales(_) => "scale",
        }
    }

    /// The number of runs `V R S`.
    pub fn runs(&self) -> usize {
        self.variants.len() * self.study.set.records.len() * self.plan.values().len()
    }

    /// The number of parts.
    pub fn parts(&self) -> usize {
        self.runs().div_ceil(self.runs_per_part)
    }

    /// The runs of part `p`.
    pub fn part_range(&self, p: usize) -> Range<usize> {
        let b = self.runs_per_part;
        (p * b).min(self.runs())..((p + 1) * b).min(self.runs())
    }

    /// Run `i` (`i < runs()`).
    pub fn run_spec(&self, i: usize) -> RunSpec {
        let (r, s) = (self.study.set.records.len(), self.plan.values().len());
        let (v, a, b) = (i / (r * s), (i / s) % r, i % s);
        let (im_g, scale_factor) = self.plan.point(a, b);
        RunSpec {
            index: i,
            id: format!(
                "{}/{}/{}={}",
                self.variants[v],
                self.study.set.records[a].id,
                self.stripe_column(),
                float_token(self.plan.values()[b])
            ),
            variant: v,
            entry: a,
            stripe: b,
            im_g,
            scale_factor,
        }
    }

    /// Every run, in index order.
    pub fn expand(&self) -> Vec<RunSpec> {
        (0..self.runs()).map(|i| self.run_spec(i)).collect()
    }
}
