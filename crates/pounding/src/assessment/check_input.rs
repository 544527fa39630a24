//! The `[code_check]` table of a scenario: the inputs of the code formulas
//! ([`super::code_check`]) that the model cannot give (site, hazard, code categories, design
//! displacements, column heights), read and validated. Unknown keys are refused; a bad value is
//! an [`AssessmentError::Key`] naming `code_check.KEY`, the file and the line.
//!
//! Every key is optional; [`DEFAULTS`] lists the default of each (the guide prints the same
//! table). Per-segment keys take one number (every segment) or an array with one number per
//! segment, from the start.

use super::AssessmentError;
use super::check_values::Cx;
pub use super::check_values::PerSegment;
use super::code_check::{AashtoZone, GroundType, JraGround, Sdc, SpectrumType};
use crate::math::Real;
use crate::toml_schema::Table;
use serde::Deserialize;

mod parts;
use toml::Spanned;

type Sp<T> = Option<Spanned<T>>;

/// Each key of `[code_check]` and its default, in the order of the guide's table.
pub const DEFAULTS: &[(&str, &str)] = &[
    (
        "ground",
        "none: EN 1998-2 is not evaluated without it (A–E)",
    ),
    (
        "a_gr_ms2",
        "none: EN 1998-2 is not evaluated without it (m/s²)",
    ),
    ("spectrum_type", "1"),
    ("importance_class", "2 (γ_I = 1.0)"),
    ("near_fault_factor", "1"),
    ("l_m_m", "0.40 (the least §6.6.4 allows)"),
    (
        "l_eff_m",
        "each deck section's length L (at a joint, each of the two segments')",
    ),
    (
        "displacement_m",
        "none: the codes that need a design displacement are not evaluated",
    ),
    ("period_s", "\"model\" (each segment's own first period)"),
    ("damping", "the bridge's damping_ratio"),
    ("pier_height_m", "0"),
    (
        "in_span_hinges",
        "none: every joint sits over a pier (AASHTO's L is each segment's own length)",
    ),
    ("aashto_zone", "4 (150 %, the most demanding)"),
    ("a_s", "none: taken as ≥ 0.05 (100 % in zone 1 / SDC A)"),
    ("sdc", "\"C\" (150 %)"),
    ("delta_ps_m", "0"),
    ("delta_crsh_m", "0"),
    ("delta_temp_m", "0"),
    ("jra_ground", "\"III\" (the largest ε_G)"),
    (
        "codes",
        "every code: [\"ec8\", \"aashto_lrfd\", \"aashto_guide\", \"caltrans\", \"jra\"]",
    ),
];

/// The periods of the frames for the double-difference gap.
#[derive(Debug, Clone, PartialEq)]
pub enum PeriodInput {
    /// Each segment's own first natural period on its bearings,
    /// `T = 2π / ω₁` of [`crate::sim::bridge::BridgeModel::segment_frequencies`].
    Model,
    /// Given \[s\].
    Given(PerSegment),
}

/// The inputs of a code check, validated, with their defaults applied.
#[derive(Debug, Clone, PartialEq)]
pub struct CodeCheckInput {
    /// EN 1998-1 ground type (`None`: EN 1998-2 not evaluated).
    pub ground: Option<GroundType>,
    /// Reference peak ground acceleration `a_gR` \[m/s²\] (`None`: EN 1998-2 not evaluated).
    pub a_gr: Option<Real>,
    /// EN 1998-1 spectrum type.
    pub spectrum: SpectrumType,
    /// EN 1998-2 importance class 1–3.
    pub importance_class: u8,
    /// Factor on `d_eg` near an active fault.
    pub near_fault_factor: Real,
    /// `l_m` \[m\].
    pub l_m: Real,
    /// `L_eff` \[m\] of every end (`None`: the end's deck length).
    pub l_eff: Option<Real>,
    /// Design displacement of each segment (frame) \[m\].
    pub displacement: Option<PerSegment>,
    /// Periods of the frames.
    pub period: PeriodInput,
    /// Damping ratio of the double-difference rule (`None`: the bridge's).
    pub damping: Option<Real>,
    /// Average column height `H` under each segment \[m\].
    pub pier_height: PerSegment,
    /// The joints (0-based) that are hinges within a span (written 1-based, as `joint<k>`):
    /// there AASHTO takes `L` as the sum of the two segments' lengths and `H` as the mean of
    /// their column heights.
    pub in_span_hinges: Vec<usize>,
    /// AASHTO LRFD seismic zone.
    pub aashto_zone: AashtoZone,
    /// `A_s` (`None`: taken as ≥ 0.05).
    pub a_s: Option<Real>,
    /// AASHTO Guide Specification seismic design category.
    pub sdc: Sdc,
    /// Caltrans `Δ_p/s`, `Δ_cr+sh`, `Δ_temp` \[m\].
    pub caltrans: [Real; 3],
    /// JRA ground type.
    pub jra_ground: JraGround,
    /// The codes that apply (the others are not evaluated and do not govern): every code by
    /// default.
    pub codes: Vec<super::code_check::Code>,
    /// The keys the file sets (the others are at their [`DEFAULTS`]).
    pub given: Vec<&'static str>,
    /// Where the per-segment keys are written, for [`CodeCheckInput::check_segments`].
    lines: Vec<(&'static str, Option<usize>, usize)>,
    /// The line of `in_span_hinges`, for [`CodeCheckInput::check_segments`].
    hinges_line: Option<usize>,
    origin: String,
}

#[derive(Deserialize)]
struct File {
    code_check: Option<Table<Sec>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, default)]
struct Sec {
    ground: Sp<String>,
    a_gr_ms2: Sp<Real>,
    spectrum_type: Sp<i64>,
    importance_class: Sp<i64>,
    near_fault_factor: Sp<Real>,
    l_m_m: Sp<Real>,
    l_eff_m: Sp<Real>,
    displacement_m: Sp<toml::Value>,
    period_s: Sp<toml::Value>,
    damping: Sp<Real>,
    pier_height_m: Sp<toml::Value>,
    in_span_hinges: Sp<Vec<i64>>,
    aashto_zone: Sp<i64>,
    a_s: Sp<Real>,
    sdc: Sp<String>,
    delta_ps_m: Sp<Real>,
    delta_crsh_m: Sp<Real>,
    delta_temp_m: Sp<Real>,
    jra_ground: Sp<String>,
    codes: Option<Spanned<Vec<Spanned<String>>>>,
}

impl Sec {
    /// The keys written (in [`DEFAULTS`] order).
    fn given(&self) -> Vec<&'static str> {
        let set = [
            self.ground.is_some(),
            self.a_gr_ms2.is_some(),
            self.spectrum_type.is_some(),
            self.importance_class.is_some(),
            self.near_fault_factor.is_some(),
            self.l_m_m.is_some(),
            self.l_eff_m.is_some(),
            self.displacement_m.is_some(),
            self.period_s.is_some(),
            self.damping.is_some(),
            self.pier_height_m.is_some(),
            self.in_span_hinges.is_some(),
            self.aashto_zone.is_some(),
            self.a_s.is_some(),
            self.sdc.is_some(),
            self.delta_ps_m.is_some(),
            self.delta_crsh_m.is_some(),
            self.delta_temp_m.is_some(),
            self.jra_ground.is_some(),
            self.codes.is_some(),
        ];
        DEFAULTS
            .iter()
            .zip(set)
            .filter_map(|((k, _), s)| s.then_some(*k))
            .collect()
    }
}

impl CodeCheckInput {
    /// Whether the scenario `text` has a `[code_check]` table (`false` for text that is not
    /// TOML: the scenario reader reports that).
    pub fn is_present(text: &str) -> bool {
        toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("code_check"))
    }

    /// Checks the `[code_check]` table of a scenario that has one (so that `simulate` does not
    /// leave a typo in it unnoticed); `Ok` when there is none.
    pub fn check_if_present(text: &str, origin: &str) -> Result<(), AssessmentError> {
        if Self::is_present(text) {
            Self::from_scenario(text, origin)?;
        }
        Ok(())
    }

    /// Checks the `[code_check]` table of a scenario that has one against its bridge of
    /// `segments` segments (per-segment arrays of the right length, in-span hinges that are
    /// joints), so that a run refuses what its report's code check would not evaluate; `Ok`
    /// when there is none.
    pub fn check_against(text: &str, origin: &str, segments: usize) -> Result<(), AssessmentError> {
        if Self::is_present(text) {
            Self::from_scenario(text, origin)?.check_segments(segments)?;
        }
        Ok(())
    }

    /// Reads `[code_check]` of the scenario `text` named `origin`; every default
    /// ([`DEFAULTS`]) when the table is absent.
    pub fn from_scenario(text: &str, origin: &str) -> Result<Self, AssessmentError> {
        let f: File = toml::from_str(text).map_err(|e| AssessmentError::Syntax {
            origin: origin.to_string(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let s = f.code_check.map(Table::into_inner).unwrap_or_default();
        Self::read(&Cx { origin, text }, &s)
    }

    fn read(cx: &Cx, s: &Sec) -> Result<Self, AssessmentError> {
        use GroundType as G;
        let grounds = ["A", "B", "C", "D", "E"];
        let ground = s
            .ground
            .as_ref()
            .map(|v| cx.choice("ground", v, &grounds))
            .transpose()?;
        let ground = ground.map(|i| [G::A, G::B, G::C, G::D, G::E][i]);
        let a_gr = s
            .a_gr_ms2
            .as_ref()
            .map(|v| {
                cx.num(
                    "a_gr_ms2",
                    v,
                    |x| (0.0..=30.0).contains(&x),
                    "must lie in [0, 30] m/s²",
                )
            })
            .transpose()?;
        let spectrum = match &s.spectrum_type {
            None => SpectrumType::Type1,
            Some(v) if cx.int("spectrum_type", v, 1, 2)? == 1 => SpectrumType::Type1,
            Some(_) => SpectrumType::Type2,
        };
        let importance_class = match &s.importance_class {
            None => 2,
            Some(v) => cx.int("importance_class", v, 1, 3)?,
        };
        let near_fault_factor = match &s.near_fault_factor {
            None => 1.0,
            Some(v) => cx.num(
                "near_fault_factor",
                v,
                |x| (1.0..=10.0).contains(&x),
                "must lie in [1, 10]",
            )?,
        };
        let l_m = match &s.l_m_m {
            None => 0.40,
            Some(v) => cx.num(
                "l_m_m",
                v,
                |x| (0.40..=10.0).contains(&x),
                "must lie in [0.4, 10] m (EN 1998-2 §6.6.4(3): at least 0.40 m)",
            )?,
        };
        let l_eff = match &s.l_eff_m {
            None => None,
            Some(v) => Some(cx.num(
                "l_eff_m",
                v,
                |x| (0.0..=1e5).contains(&x),
                "must lie in [0, 1e5] m",
            )?),
        };
        let mut lines = Vec::new();
        let mut per = |key: &'static str, v: &Sp<toml::Value>, max: Real, positive: bool| {
            v.as_ref()
                .map(|v| {
                    let p = cx.per_segment(key, v, max, positive)?;
                    if let PerSegment::Each(xs) = &p {
                        lines.push((key, Some(cx.line(v)), xs.len()));
                    }
                    Ok::<_, AssessmentError>(p)
                })
                .transpose()
        };
        let displacement = per("displacement_m", &s.displacement_m, 100.0, false)?;
        let pier_height =
            per("pier_height_m", &s.pier_height_m, 1e3, false)?.unwrap_or(PerSegment::All(0.0));
        let period = match &s.period_s {
            None => PeriodInput::Model,
            Some(v) if v.get_ref().as_str() == Some("model") => PeriodInput::Model,
            Some(v) if v.get_ref().is_str() => {
                return Err(cx.err(
                    "period_s",
                    v,
                    "must be \"model\", a period in seconds or one period per segment".into(),
                ));
            }
            Some(_) => PeriodInput::Given(
                per("period_s", &s.period_s, 20.0, true)?.unwrap_or(PerSegment::All(1.0)),
            ),
        };
        let damping = cx.opt_num(
            "damping",
            &s.damping,
            |x| (0.0..1.0).contains(&x),
            "must be in [0, 1) (a fraction of critical)",
        )?;
        let (aashto_zone, a_s, sdc, caltrans, jra_ground) = parts::us_jra(cx, s)?;
        let (in_span_hinges, hinges_line) = parts::hinges(cx, s)?;
        let codes = parts::codes(cx, s)?;
        let given = s.given();
        Ok(Self {
            ground,
            a_gr,
            spectrum,
            importance_class,
            near_fault_factor,
            l_m,
            l_eff,
            displacement,
            period,
            damping,
            pier_height,
            in_span_hinges,
            aashto_zone,
            a_s,
            sdc,
            caltrans,
            jra_ground,
            codes,
            given,
            lines,
            hinges_line,
            origin: cx.origin.to_string(),
        })
    }

    /// Refuses a per-segment array whose length is not the bridge's number of segments `n`, and
    /// an in-span hinge that is not one of its `n − 1` joints.
    pub fn check_segments(&self, n: usize) -> Result<(), AssessmentError> {
        if let Some(&k) = self.in_span_hinges.iter().find(|&&k| k + 1 >= n) {
            return Err(AssessmentError::Key {
                message: format!(
                    "joint {} is not a joint of this bridge of {n} segment(s) (joints 1 to {})",
                    k + 1,
                    n.saturating_sub(1)
                ),
                key: "code_check.in_span_hinges".into(),
                origin: self.origin.clone(),
                line: self.hinges_line,
            });
        }
        match self.lines.iter().find(|(_, _, len)| *len != n) {
            None => Ok(()),
            Some((key, line, len)) => Err(AssessmentError::Key {
                message: format!(
                    "lists {len} values for a bridge of {n} segments: give one number or one per segment"
                ),
                key: format!("code_check.{key}"),
                origin: self.origin.clone(),
                line: *line,
            }),
        }
    }
}
