//! Retrofit comparison (`pounding design`): variants of one bridge run on the same records and
//! stripes (common random numbers), each fitted as a fragility study, compared with the as-built
//! bridge by paired bootstrap differences.
//!
//! ```toml
//! [design]
//! scenario = "viaduct.toml"   # the as-built bridge with [fragility], [[limit_state]], [hazard]
//! baseline = "as-built"       # the as-built bridge's name in outputs (default "as-built")
//!
//! [[variant]]                 # the variants: overrides of the scenario's keys
//! name = "stiff-restrainers"
//! [variant.set]
//! "bridge.restrainer_k" = 1.0e8
//! ```
//!
//! Every variant is the scenario with its overrides ([`super::variant`]) read as a fragility
//! study ([`Study::read`]; every check of the scenario applies, errors name the design file, the
//! variant, the key and its line). A variant may change the bridge only: overrides of
//! `[fragility]`, `[[limit_state]]`, `[hazard]`, `[ground_motion]` or `[time]` are refused (they
//! would change the study, not the bridge). All variants share the as-built study's intensity
//! measure (its period too, when `period_s = "model"`: a stiffer bridge is compared at the
//! same IM), records, stripes, scale factors, bootstrap seed and hazard: the runs of a record at
//! a stripe differ between variants only by the bridge.
//!
//! **Paired differences.** The bootstrap of each variant's fit resamples the records with the
//! replicate's own random stream ([`crate::fragility::bootstrap`]): replicate `b` of every variant
//! draws the same record indices. The difference of a statistic (the MAF with a hazard, else the
//! median θ) between a variant and the as-built bridge is taken replicate by replicate (paired);
//! its interval is the bias-corrected percentile interval of those differences. The unpaired
//! interval, for contrast, pairs replicate `b` of the variant with replicate `(b + B/2) mod B` of
//! the as-built bridge (independent resamples of the records), the same way.

use super::AssessmentError;
pub use super::design_file::DesignError;
use super::hazard_input::HazardInput;
use super::run::{Plan, RunRow};
use super::study::{Fits, Study};
use super::variant::{Step, Variant, VariantError, Variants};
use crate::sim::scenario::Scenario;
use std::cell::RefCell;
use std::path::{Path, PathBuf};

/// Top-level tables a variant may not override.
pub const STUDY_TABLES: [&str; 6] = [
    "fragility",
    "limit_state",
    "hazard",
    "ground_motion",
    "time",
    "code_check",
];

/// One member of a design: the as-built bridge or a variant.
pub struct Member {
    /// Its name (`baseline` for the as-built bridge).
    pub name: String,
    /// Its description (empty for the as-built bridge unless given).
    pub description: String,
    /// Its overrides as `key = value` (empty for the as-built bridge).
    pub overrides: Vec<String>,
    /// Its study (the scenario with the overrides).
    pub study: Study,
}

/// A design read and checked before any run.
pub struct Design {
    /// The design file's name.
    pub origin: String,
    /// The scenario file.
    pub scenario_path: PathBuf,
    /// The as-built bridge first, then the variants in the file's order.
    pub members: Vec<Member>,
    /// How the studies were read (to read more: [`Design::study_with`]).
    reader: Reader,
    /// The `[search]` table, when given.
    pub search: Option<super::design_file::SearchSpec>,
}

/// What reading a member's study needs.
struct Reader {
    base_text: String,
    base_origin: String,
    sdir: PathBuf,
    origin: String,
    set: Option<PathBuf>,
    hazard: Option<PathBuf>,
    period: Option<super::PeriodChoice>,
}

impl Reader {
    fn study(&self, text: &str) -> Result<Study, AssessmentError> {
        let scn = Scenario::from_toml(text, &self.base_origin)?.with_base_dir(self.sdir.clone());
        let st = Study::read_at(scn, Some(&self.sdir), self.set.as_deref(), self.period)?;
        match &self.hazard {
            Some(h) => st.with_hazard(h),
            None => Ok(st),
        }
    }

    /// The study of variant `v` at the as-built study `base`'s IM and hazard.
    fn variant_study(&self, v: &Variant, base: &Study) -> Result<Study, DesignError> {
        check_bridge_only(v, &self.origin)?;
        let kept: RefCell<Option<Study>> = RefCell::new(None);
        v.apply_checked(&self.base_text, &self.base_origin, &self.origin, |t| {
            self.study(t).map(|st| *kept.borrow_mut() = Some(st))
        })?;
        let mut st = kept.into_inner().ok_or_else(|| {
            DesignError::Study(AssessmentError::Invalid(format!(
                "variant {}: not read",
                v.name
            )))
        })?;
        st.spec = base.spec;
        st.period = base.period.clone();
        st.hazard = base.hazard.clone();
        Ok(st)
    }
}

#[derive(serde::Deserialize)]
struct File {
    design: Option<toml::Spanned<crate::toml_schema::Table<DesignSec>>>,
    #[serde(default, rename = "variant")]
    _variant: serde::de::IgnoredAny,
    #[serde(default, rename = "search")]
    _search: serde::de::IgnoredAny,
}

#[derive(serde::Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct DesignSec {
    scenario: Option<toml::Spanned<String>>,
    baseline: Option<toml::Spanned<String>>,
    hazard: Option<toml::Spanned<String>>,
}

impl Design {
    /// Reads the design file `path`: the as-built study (its record set `set` when given,
    /// `hazard` replacing the scenario's `[hazard]` when given), then every variant's.
    pub fn read(
        path: &Path,
        set: Option<&Path>,
        hazard: Option<&Path>,
    ) -> Result<Self, DesignError> {
        let origin = path.display().to_string();
        let text = crate::input::read_text(path, "design file", crate::input::SCENARIO_LIMIT)
            .map_err(|e| {
                DesignError::Study(AssessmentError::Invalid(format!(
                    "cannot read design file {origin}: {e}"
                )))
            })?;
        let dir = path.parent().unwrap_or(Path::new("")).to_path_buf();
        let key_err = |pos: Option<usize>, key: &str, message: String| DesignError::Key {
            origin: origin.clone(),
            line: pos.map_or(1, |p| crate::toml_schema::line_col(&text, p).0),
            key: key.into(),
            message,
        };
        let f: File = toml::from_str(&text).map_err(|e| VariantError::Syntax {
            origin: origin.clone(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let Some(sec) = f.design else {
            return Err(key_err(
                None,
                "design",
                "missing [design] table (scenario = \"BRIDGE.toml\")".into(),
            ));
        };
        let s = &sec.get_ref().0;
        let Some(sc) = &s.scenario else {
            return Err(key_err(
                Some(sec.span().start),
                "design.scenario",
                "missing: the as-built bridge's scenario file".into(),
            ));
        };
        let scenario_path = dir.join(sc.get_ref());
        let baseline = s
            .baseline
            .as_ref()
            .map_or("as-built".to_string(), |b| b.get_ref().clone());
        let variants = Variants::parse(&text, &origin)?;
        if let Some(v) = variants.list.iter().find(|v| v.name == baseline) {
            return Err(DesignError::Variant(VariantError::Key {
                origin: origin.clone(),
                line: v.line,
                variant: v.name.clone(),
                key: "name".into(),
                message: format!(
                    "the as-built bridge is named {baseline:?} (design.baseline): name the variant otherwise"
                ),
            }));
        }
        let hazard_path = match (hazard, &s.hazard) {
            (Some(h), _) => Some(h.to_path_buf()),
            (None, Some(h)) => Some(dir.join(h.get_ref())),
            (None, None) => None,
        };
        let base_text = crate::input::read_text(
            &scenario_path,
            "scenario file",
            crate::input::SCENARIO_LIMIT,
        )
        .map_err(|e| {
            key_err(
                Some(sc.span().start),
                "design.scenario",
                format!("cannot read {}: {e}", scenario_path.display()),
            )
        })?;
        let reader = Reader {
            base_origin: scenario_path.display().to_string(),
            sdir: scenario_path
                .parent()
                .map(Path::to_path_buf)
                .unwrap_or_default(),
            base_text,
            origin: origin.clone(),
            set: set.map(Path::to_path_buf),
            hazard: hazard_path,
            period: None,
        };
        let base = reader.study(&reader.base_text)?;
        // every variant at the as-built bridge's IM, its period too
        let reader = Reader {
            period: (base.spec.kind == super::ImKind::Sa)
                .then_some(super::PeriodChoice::Given(base.spec.period)),
            ..reader
        };
        let mut members = vec![Member {
            name: baseline,
            description: String::new(),
            overrides: Vec::new(),
            study: base,
        }];
        for v in &variants.list {
            let st = reader.variant_study(v, &members[0].study)?;
            members.push(Member {
                name: v.name.clone(),
                description: v.description.clone(),
                overrides: v
                    .overrides
                    .iter()
                    .map(|o| format!("{} = {}", o.key, o.value))
                    .collect(),
                study: st,
            });
        }
        let search = super::design_file::SearchSpec::from_design(&text, &origin)?;
        Ok(Design {
            origin,
            scenario_path,
            members,
            reader,
            search,
        })
    }

    /// The plan of the as-built study (the same for every member).
    pub fn plan(&self) -> Result<Plan, AssessmentError> {
        self.members[0].study.plan()
    }

    /// Runs every member on the plan (on the current rayon pool), members in order.
    pub fn run(&self, plan: &Plan, progress: &(dyn Fn() + Sync)) -> Vec<Vec<RunRow>> {
        self.members
            .iter()
            .map(|m| m.study.run(plan, progress))
            .collect()
    }

    /// Fits every member's limit states.
    pub fn fit(
        &self,
        plan: &Plan,
        rows: &[Vec<RunRow>],
    ) -> Result<Vec<Fits>, crate::fragility::FragilityError> {
        self.members
            .iter()
            .zip(rows)
            .map(|(m, r)| m.study.fit(plan, r))
            .collect()
    }

    /// The study of the as-built bridge with `variant`'s overrides (a variant built in memory,
    /// e.g. by a search), read as the design's variants are.
    pub fn study_with(&self, variant: &Variant) -> Result<Study, DesignError> {
        self.reader.variant_study(variant, &self.members[0].study)
    }

    /// The hazard shared by every member, if any.
    pub fn hazard(&self) -> Option<&HazardInput> {
        self.members[0].study.hazard.as_ref()
    }
}

/// Refuses an override of a table that defines the study rather than the bridge.
fn check_bridge_only(v: &Variant, origin: &str) -> Result<(), VariantError> {
    for o in &v.overrides {
        if let Some(Step::Key(k)) = o.path.first()
            && STUDY_TABLES.contains(&k.as_str())
        {
            return Err(VariantError::Key {
                origin: origin.into(),
                line: o.line,
                variant: v.name.clone(),
                key: o.key.clone(),
                message: format!(
                    "a design variant changes the bridge, not the study: [{k}] is shared by \
                     every variant (the same records, stripes, limit states and hazard for all)"
                ),
            });
        }
    }
    Ok(())
}
