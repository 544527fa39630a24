//! Study scenarios: the TOML file format, its validation and the built-in default (the paper's study).
//!
//! A scenario lists the deck shape (`[decks] shape`: curved, straight or skew, see [`StudyShape`]),
//! deck geometries (`β1, β2, R1, R2` for curved decks; `L1, L2` and for skewed decks the common skew
//! angle; shared width, thickness, density), impact laws
//! (`μ`, `ε_N`), the `θ1 × θ2` grid, the ratio range of the region maps, the candidate cases, the σ mode
//! and output options. Every key is optional; a missing key takes the built-in default
//! ([`Scenario::default`], the paper's study extended to all combinations). Unknown keys are errors.
//! Every error names the key and the line of the file ([`ScenarioError`]).

use crate::geometry::{ContactCase, SigmaMode};
use crate::math::Real;
use crate::toml_schema::{Table, key_on_line, line_col};
use keys::DeckKeys;
use serde::Deserialize;
use std::ops::Range;
use thiserror::Error;
use toml::Spanned;

mod keys;
pub use keys::{DECK_RENAMES, DeprecatedKey};

/// A scenario file that cannot be used. The message names the key and the line.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum ScenarioError {
    /// The file is not valid TOML or does not match the schema (unknown key, wrong type).
    #[error("{origin}: line {line}, column {column}{key}: {message}")]
    Syntax {
        /// Where the text came from (file name).
        origin: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// `" (key `name`)"` when a key could be identified, else empty.
        key: String,
        /// The parser's message.
        message: String,
    },
    /// A value is out of its valid range.
    #[error("{origin}: line {line}: invalid {key} = {value}: {reason}")]
    Invalid {
        /// Where the text came from (file name).
        origin: String,
        /// 1-based line of the key (`0` for a built-in default value).
        line: usize,
        /// Dotted key, e.g. `grid.theta1_deg.step`.
        key: String,
        /// The offending value as text.
        value: String,
        /// What was expected.
        reason: String,
    },
}

/// An inclusive angle range `start, start + step, …` up to `stop` (degrees).
///
/// Values are `θ_i = start + i·step` (never accumulated), `i = 0..n` with the largest `n` such that
/// `θ_{n−1} ≤ stop + 1e-9·step`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleRange {
    /// First value \[deg\].
    pub start: Real,
    /// Last admissible value \[deg\], `≥ start`.
    pub stop: Real,
    /// Increment \[deg\], `> 0`.
    pub step: Real,
}

impl AngleRange {
    /// Number of grid values.
    ///
    /// Saturates at `usize::MAX` instead of wrapping for a range too fine to count (a scenario
    /// refuses any range of more than [`MAX_GRID_VALUES`] values).
    pub fn len(&self) -> usize {
        (((self.stop - self.start) / self.step + 1e-9).floor() as usize).saturating_add(1)
    }
    /// Always false for a validated range (there is at least `start`).
    pub fn is_empty(&self) -> bool {
        false
    }
    /// The `i`-th value `start + i·step` \[deg\].
    pub fn value(&self, i: usize) -> Real {
        self.start + i as Real * self.step
    }
    /// All values \[deg\].
    pub fn values(&self) -> Vec<Real> {
        (0..self.len()).map(|i| self.value(i)).collect()
    }
}

/// Output options of a study run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutputOptions {
    /// Draw the figures (and show them in the report).
    pub figures: bool,
    /// Also write every figure as SVG.
    pub svg: bool,
    /// Number of `θ_a` samples across the striking deck's range in the region maps (`≥ 2`).
    pub region_map_samples: usize,
}

/// The deck shape of a study (`[decks] shape`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum StudyShape {
    /// Two annular sectors in the S arrangement (spec §4): geometry axes `β1, β2, R1, R2`.
    #[default]
    Curved,
    /// Two rectangles: geometry axes `L1, L2`.
    Straight,
    /// Two parallelograms with a common skew angle: geometry axes `L1, L2, θ_s`.
    Skew,
}

impl StudyShape {
    /// The scenario/CSV name: `curved`, `straight` or `skew`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Curved => "curved",
            Self::Straight => "straight",
            Self::Skew => "skew",
        }
    }
}

/// A validated study scenario (every list non-empty, duplicate-free, every value in range).
///
/// The four *geometry axes* of the row order are `(β1, β2, R1, R2)` for curved decks and
/// `(L1, L2, θ_s, –)` for straight and skewed decks (the last axis has one entry; a straight study
/// has the single skew `0`). The lists of the other shape are empty.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// Deck shape.
    pub shape: StudyShape,
    /// Lengths of deck 1, `L1` \[m\] (straight/skew; empty for curved).
    pub l1_m: Vec<Real>,
    /// Lengths of deck 2, `L2` \[m\] (straight/skew; empty for curved).
    pub l2_m: Vec<Real>,
    /// Common skew angles `θ_s` of both decks \[deg\], in `[0, 90)` (skew; `[0]` for straight;
    /// empty for curved).
    pub skew_deg: Vec<Real>,
    /// Common deck width `W` \[m\].
    pub width: Real,
    /// Common deck thickness `t` \[m\].
    pub thickness: Real,
    /// Common density `ρ` \[kg/m³\].
    pub density: Real,
    /// Subtended angles of deck 1, `β1` \[deg\], in output order.
    pub beta1_deg: Vec<Real>,
    /// Subtended angles of deck 2, `β2` \[deg\].
    pub beta2_deg: Vec<Real>,
    /// Centre-line radii of deck 1, `R1` \[m\] (`> W/2`).
    pub r1_m: Vec<Real>,
    /// Centre-line radii of deck 2, `R2` \[m\] (`> W/2`).
    pub r2_m: Vec<Real>,
    /// Friction coefficients `μ ≥ 0`.
    pub mu: Vec<Real>,
    /// Newton restitution coefficients `ε_N ∈ [0, 1]`.
    pub eps: Vec<Real>,
    /// Deck 1 rotations `θ1` \[deg\].
    pub theta1: AngleRange,
    /// Deck 2 rotations `θ2` \[deg\].
    pub theta2: AngleRange,
    /// Lower end of the pre-impact ratio range `r = γ_T⁻/γ_N⁻` used by summaries and region maps.
    pub ratio_min: Real,
    /// Upper end of the ratio range (`> ratio_min`, with a finite width `ratio_max − ratio_min`).
    pub ratio_max: Real,
    /// Candidate cases, always in the canonical order of [`ContactCase::ALL`].
    pub cases: Vec<ContactCase>,
    /// Where the contact point lies on the struck face.
    pub sigma_mode: SigmaMode,
    /// Output options.
    pub output: OutputOptions,
}

impl Default for Scenario {
    /// The paper's study, extended to all combinations: β1, β2 ∈ {60, 90, 120}°, R1, R2 ∈ {100, 200} m,
    /// W = 10 m, t = 0.5 m, ρ = 2500 kg/m³, μ ∈ {0, 0.25, 0.5, 1}, ε_N = 0.5, θ1, θ2 ∈ [−10°, 10°] step 1°,
    /// all four cases, exact σ, ratio range [−12, 12].
    fn default() -> Self {
        let theta = AngleRange {
            start: -10.0,
            stop: 10.0,
            step: 1.0,
        };
        Self {
            shape: StudyShape::Curved,
            l1_m: Vec::new(),
            l2_m: Vec::new(),
            skew_deg: Vec::new(),
            width: 10.0,
            thickness: 0.5,
            density: 2500.0,
            beta1_deg: vec![60.0, 90.0, 120.0],
            beta2_deg: vec![60.0, 90.0, 120.0],
            r1_m: vec![100.0, 200.0],
            r2_m: vec![100.0, 200.0],
            mu: vec![0.0, 0.25, 0.5, 1.0],
            eps: vec![0.5],
            theta1: theta,
            theta2: theta,
            ratio_min: -12.0,
            ratio_max: 12.0,
            cases: ContactCase::ALL.to_vec(),
            sigma_mode: SigmaMode::Exact,
            output: OutputOptions {
                figures: true,
                svg: false,
                region_map_samples: 201,
            },
        }
    }
}

/// The built-in default as a commented scenario file (`pounding study --print-default`).
/// Parsing it gives exactly [`Scenario::default`].
pub const DEFAULT_SCENARIO_TOML: &str = r#"# pounding study scenario — the built-in default (the paper's parametric study, all combinations).
#
# Every key is optional: a missing key takes the value shown here. Unknown keys are errors.
# Rows of bounds.csv are ordered by beta1, beta2, r1, r2, mu, eps (each in the order listed here),
# then case, then theta1, then theta2.

[decks]
# Deck shape: "curved" (this default: beta/R lists below), "straight" (lists L1, L2 [m]) or
# "skew" (L1, L2 and skew_deg, the common skew angle in [0, 90) deg). Keys of another shape are
# errors. Defaults for straight/skew: L1 = L2 = [30.0, 60.0], skew_deg = [0.0, 15.0, 30.0].
# The keys are those of `pounding simulate`; the older names width_m, thickness_m, density_kg_m3,
# r1_m, r2_m, l1_m, l2_m still work (with a deprecation note).
shape = "curved"
# Common width W [m], thickness t [m] and density rho [kg/m^3] of both decks (S arrangement).
width = 10.0
thickness = 0.5
density = 2500.0
# Subtended (curve) angles of deck 1 and deck 2 [deg], each in (0, 360).
beta1_deg = [60.0, 90.0, 120.0]
beta2_deg = [60.0, 90.0, 120.0]
# Centre-line radii of deck 1 and deck 2 [m]; each must exceed width / 2.
R1 = [100.0, 200.0]
R2 = [100.0, 200.0]

[impact]
# Coulomb friction coefficients (>= 0) and Newton restitution coefficients (in [0, 1]).
mu = [0.0, 0.25, 0.5, 1.0]
eps = [0.5]
# Contact point on the struck face: "exact" (the striking corner) or "end" (the paper's face end).
sigma_mode = "exact"

[grid]
# Deck rotations [deg]: theta = start + i * step for i = 0, 1, ... while theta <= stop.
theta1_deg = { start = -10.0, stop = 10.0, step = 1.0 }
theta2_deg = { start = -10.0, stop = 10.0, step = 1.0 }
# Range of the pre-impact ratio r = gamma_T^- / gamma_N^- for summaries and region maps.
ratio_min = -12.0
ratio_max = 12.0
# Candidate contacts (any non-empty subset; output order is always the order below).
cases = ["deck1-inner", "deck1-outer", "deck2-inner", "deck2-outer"]

[output]
# Draw figures (PNG; also SVG when svg = true or with --svg).
figures = true
svg = false
# Samples of the striking deck's rotation across its range in the region maps.
region_map_samples = 201
"#;

/// Default deck lengths `L1`, `L2` \[m\] of a straight or skew study.
pub const DEFAULT_LENGTHS_M: [Real; 2] = [30.0, 60.0];
/// Largest number of values of one `θ` range (`grid.theta1_deg`, `grid.theta2_deg`).
pub const MAX_GRID_VALUES: usize = 100_000;

/// Largest number of rows of a study (`bounds.csv` rows over all shards): the product of the list
/// lengths, the cases and the two `θ` ranges. Sizes are computed with checked arithmetic and a
/// larger study is refused as bad input.
pub const MAX_ROWS: usize = 1_000_000_000_000;

/// Largest width `ratio_max − ratio_min` of the ratio range. The ratio `r = γ_T⁻/γ_N⁻` of a real
/// impact is a slope of order one (the default range is `[−12, 12]`); the limit keeps every share,
/// sample position and axis tick finite and well resolved.
pub const MAX_RATIO_WIDTH: Real = 1e12;

/// Default skew angles \[deg\] of a skew study.
pub const DEFAULT_SKEW_DEG: [Real; 3] = [0.0, 15.0, 30.0];

type S<T> = Option<Spanned<T>>;

/// A list key of a study (`R1`, `mu`, …): a list of numbers, or one number meaning a list of one,
/// as the same key of a `simulate` scenario is written (`R1 = 100.0`).
fn list<'de, D: serde::Deserializer<'de>>(d: D) -> Result<S<Vec<Real>>, D::Error> {
    struct OneOrMany(Vec<Real>);
    impl<'de> Deserialize<'de> for OneOrMany {
        fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            struct V;
            impl<'de> serde::de::Visitor<'de> for V {
                type Value = OneOrMany;
                fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                    f.write_str("a number or a list of numbers")
                }
                fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<OneOrMany, E> {
                    Ok(OneOrMany(vec![v]))
                }
                fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<OneOrMany, E> {
                    Ok(OneOrMany(vec![v as Real]))
                }
                fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<OneOrMany, E> {
                    Ok(OneOrMany(vec![v as Real]))
                }
                fn visit_seq<A: serde::de::SeqAccess<'de>>(
                    self,
                    a: A,
                ) -> Result<OneOrMany, A::Error> {
                    Vec::<Real>::deserialize(serde::de::value::SeqAccessDeserializer::new(a))
                        .map(OneOrMany)
                }
            }
            d.deserialize_any(V)
        }
    }
    let s: Option<Spanned<OneOrMany>> = Option::deserialize(d)?;
    Ok(s.map(|s| {
        let span = s.span();
        Spanned::new(span, s.into_inner().0)
    }))
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawScenario {
    decks: Option<Table<RawDecks>>,
    impact: Option<Table<RawImpact>>,
    grid: Option<Table<RawGrid>>,
    output: Option<Table<RawOutput>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawDecks {
    shape: S<String>,
    #[serde(rename = "L1")]
    #[serde(default, deserialize_with = "list")]
    l1: S<Vec<Real>>,
    #[serde(rename = "L2")]
    #[serde(default, deserialize_with = "list")]
    l2: S<Vec<Real>>,
    #[serde(default, deserialize_with = "list")]
    skew_deg: S<Vec<Real>>,
    width: S<Real>,
    thickness: S<Real>,
    density: S<Real>,
    #[serde(default, deserialize_with = "list")]
    beta1_deg: S<Vec<Real>>,
    #[serde(default, deserialize_with = "list")]
    beta2_deg: S<Vec<Real>>,
    #[serde(rename = "R1")]
    #[serde(default, deserialize_with = "list")]
    r1: S<Vec<Real>>,
    #[serde(rename = "R2")]
    #[serde(default, deserialize_with = "list")]
    r2: S<Vec<Real>>,
    // Deprecated names (folded into the ones above by `keys::fold_deprecated`).
    #[serde(default, deserialize_with = "list")]
    l1_m: S<Vec<Real>>,
    #[serde(default, deserialize_with = "list")]
    l2_m: S<Vec<Real>>,
    width_m: S<Real>,
    thickness_m: S<Real>,
    density_kg_m3: S<Real>,
    #[serde(default, deserialize_with = "list")]
    r1_m: S<Vec<Real>>,
    #[serde(default, deserialize_with = "list")]
    r2_m: S<Vec<Real>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawImpact {
    #[serde(default, deserialize_with = "list")]
    mu: S<Vec<Real>>,
    #[serde(default, deserialize_with = "list")]
    eps: S<Vec<Real>>,
    sigma_mode: S<String>,
}

#[derive(Deserialize, Clone)]
#[serde(deny_unknown_fields)]
struct RawRange {
    start: Spanned<Real>,
    stop: Spanned<Real>,
    step: Spanned<Real>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawGrid {
    theta1_deg: Option<Table<RawRange>>,
    theta2_deg: Option<Table<RawRange>>,
    ratio_min: S<Real>,
    ratio_max: S<Real>,
    cases: S<Vec<String>>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct RawOutput {
    figures: S<bool>,
    svg: S<bool>,
    region_map_samples: S<i64>,
}

struct Ctx<'a> {
    text: &'a str,
    origin: &'a str,
}

impl Ctx<'_> {
    fn invalid(&self, span: Range<usize>, key: &str, value: String, reason: &str) -> ScenarioError {
        let line = if span.start == span.end && span.start == 0 {
            0
        } else {
            line_col(self.text, span.start).0
        };
        ScenarioError::Invalid {
            origin: self.origin.to_string(),
            line,
            key: key.to_string(),
            value,
            reason: reason.to_string(),
        }
    }

    fn scalar(
        &self,
        v: &S<Real>,
        default: Real,
        key: &str,
        ok: impl Fn(Real) -> bool,
        reason: &str,
    ) -> Result<(Real, Range<usize>), ScenarioError> {
        let (x, span) = match v {
            Some(s) => (*s.get_ref(), s.span()),
            None => (default, 0..0),
        };
        if !x.is_finite() || !ok(x) {
            return Err(self.invalid(span, key, fmt_num(x), reason));
        }
        Ok((x, span))
    }

    fn list(
        &self,
        v: &S<Vec<Real>>,
        default: &[Real],
        key: &str,
        ok: impl Fn(Real) -> bool,
        reason: &str,
    ) -> Result<(Vec<Real>, Range<usize>), ScenarioError> {
        let (xs, span) = match v {
            Some(s) => (s.get_ref().clone(), s.span()),
            None => (default.to_vec(), 0..0),
        };
        if xs.is_empty() {
            return Err(self.invalid(span, key, "[]".into(), "the list must not be empty"));
        }
        for (i, &x) in xs.iter().enumerate() {
            if !x.is_finite() || !ok(x) {
                return Err(self.invalid(span, &format!("{key}[{i}]"), fmt_num(x), reason));
            }
            if xs[..i].contains(&x) {
                return Err(self.invalid(
                    span,
                    &format!("{key}[{i}]"),
                    fmt_num(x),
                    "duplicate value (each value may appear once)",
                ));
            }
        }
        Ok((xs, span))
    }

    fn range(
        &self,
        v: &Option<Table<RawRange>>,
        default: AngleRange,
        key: &str,
    ) -> Result<AngleRange, ScenarioError> {
        let Some(r) = v else { return Ok(default) };
        let (start, stop, step) = (*r.start.get_ref(), *r.stop.get_ref(), *r.step.get_ref());
        for (name, x, span) in [
            ("start", start, r.start.span()),
            ("stop", stop, r.stop.span()),
            ("step", step, r.step.span()),
        ] {
            if !x.is_finite() || x.abs() >= 90.0 && name != "step" {
                return Err(self.invalid(
                    span,
                    &format!("{key}.{name}"),
                    fmt_num(x),
                    "must be finite with |theta| < 90 deg",
                ));
            }
        }
        if step <= 0.0 {
            return Err(self.invalid(
                r.step.span(),
                &format!("{key}.step"),
                fmt_num(step),
                "must be > 0",
            ));
        }
        if stop < start {
            return Err(self.invalid(
                r.stop.span(),
                &format!("{key}.stop"),
                fmt_num(stop),
                &format!("must be >= start = {}", fmt_num(start)),
            ));
        }
        // Count in floating point first: a tiny step gives a count beyond `usize` (1e-20 deg over
        // 20 deg is 2e21 values), which must be refused, not wrapped.
        let count = ((stop - start) / step + 1e-9).floor() + 1.0;
        let out = AngleRange { start, stop, step };
        if count.is_nan() || count > MAX_GRID_VALUES as Real {
            return Err(self.invalid(
                r.step.span(),
                &format!("{key}.step"),
                fmt_num(step),
                &format!(
                    "gives {} grid values, more than the limit {MAX_GRID_VALUES}",
                    fmt_num(count)
                ),
            ));
        }
        Ok(out)
    }
}

/// The TOML `text` read into the raw sections; a syntax error, unknown key or wrong type names
/// the line, the column and the key written there.
fn parse_raw(text: &str, origin: &str) -> Result<RawScenario, ScenarioError> {
    toml::from_str(text).map_err(|e| {
        let pos = e.span().map_or(0, |s| s.start);
        let (line, column) = line_col(text, pos);
        let key = key_on_line(text, pos)
            .map(|k| format!(" (key `{k}`)"))
            .unwrap_or_default();
        ScenarioError::Syntax {
            origin: origin.to_string(),
            line,
            column,
            key,
            message: crate::input::shorten_lines(e.message().trim(), 200),
        }
    })
}

/// A too-large scenario ([`Scenario::check_size`]) pointed at the finer θ range the user wrote,
/// if any (the usual culprit).
fn locate_size_error(e: ScenarioError, grid: &RawGrid, text: &str) -> ScenarioError {
    match e {
        ScenarioError::Invalid {
            origin,
            key,
            value,
            reason,
            ..
        } => {
            let span = [&grid.theta2_deg, &grid.theta1_deg]
                .into_iter()
                .flatten()
                .map(|r| r.step.span())
                .next();
            ScenarioError::Invalid {
                origin,
                line: span.map_or(0, |s| line_col(text, s.start).0),
                key,
                value,
                reason,
            }
        }
        e => e,
    }
}

/// The geometry axes of a study: `β1, β2, R1, R2` for curved decks (the others empty), `L1, L2,
/// θ_s` for straight and skewed decks (the curved ones empty).
#[derive(Default)]
struct DeckAxes {
    beta1_deg: Vec<Real>,
    beta2_deg: Vec<Real>,
    r1_m: Vec<Real>,
    r2_m: Vec<Real>,
    l1_m: Vec<Real>,
    l2_m: Vec<Real>,
    skew_deg: Vec<Real>,
}

impl Ctx<'_> {
    /// `decks.shape`: `curved` (default), `straight` or `skew`.
    fn shape(&self, decks: &RawDecks) -> Result<StudyShape, ScenarioError> {
        let Some(v) = &decks.shape else {
            return Ok(StudyShape::Curved);
        };
        match v.get_ref().as_str() {
            "curved" => Ok(StudyShape::Curved),
            "straight" => Ok(StudyShape::Straight),
            "skew" => Ok(StudyShape::Skew),
            other => Err(self.invalid(
                v.span(),
                "decks.shape",
                format!("{other:?}"),
                "expected \"curved\", \"straight\" or \"skew\"",
            )),
        }
    }

    /// Keys of another shape are errors (they would be silently ignored otherwise).
    fn refuse_foreign_keys(
        &self,
        decks: &RawDecks,
        keys: &DeckKeys,
        shape: StudyShape,
    ) -> Result<(), ScenarioError> {
        let span = |v: &S<Vec<Real>>| v.as_ref().map(|v| v.span());
        let mut foreign = if shape == StudyShape::Curved {
            vec![
                (keys.l1.as_str(), span(&decks.l1)),
                (keys.l2.as_str(), span(&decks.l2)),
                ("decks.skew_deg", span(&decks.skew_deg)),
            ]
        } else {
            vec![
                ("decks.beta1_deg", span(&decks.beta1_deg)),
                ("decks.beta2_deg", span(&decks.beta2_deg)),
                (keys.r1.as_str(), span(&decks.r1)),
                (keys.r2.as_str(), span(&decks.r2)),
            ]
        };
        if shape == StudyShape::Straight {
            foreign.push(("decks.skew_deg", span(&decks.skew_deg)));
        }
        for (key, span) in foreign {
            if let Some(span) = span {
                return Err(self.invalid(
                    span,
                    key,
                    "(set)".into(),
                    &format!(
                        "this key does not apply to decks.shape = \"{}\"",
                        shape.name()
                    ),
                ));
            }
        }
        Ok(())
    }

    /// `decks.beta1_deg`, `beta2_deg` in `(0, 360)` and `decks.R1`, `R2` above `width/2`
    /// (default radii made invalid by a user-set width blame the width).
    fn curved_axes(
        &self,
        decks: &RawDecks,
        keys: &DeckKeys,
        d: &Scenario,
        width: Real,
        width_span: Range<usize>,
    ) -> Result<DeckAxes, ScenarioError> {
        let beta_ok = |x: Real| x > 0.0 && x < 360.0;
        let beta = "must lie in (0, 360) deg";
        let (beta1_deg, _) = self.list(
            &decks.beta1_deg,
            &d.beta1_deg,
            "decks.beta1_deg",
            beta_ok,
            beta,
        )?;
        let (beta2_deg, _) = self.list(
            &decks.beta2_deg,
            &d.beta2_deg,
            "decks.beta2_deg",
            beta_ok,
            beta,
        )?;
        let half = width / 2.0;
        let r_reason = format!("R must exceed width/2 = {} m", fmt_num(half));
        let mut radii = Vec::new();
        for (key, v, dv) in [
            (keys.r1.as_str(), &decks.r1, &d.r1_m),
            (keys.r2.as_str(), &decks.r2, &d.r2_m),
        ] {
            let rs = match self.list(v, dv, key, |x| x > half, &r_reason) {
                Ok((rs, _)) => rs,
                Err(_) if v.is_none() => {
                    return Err(self.invalid(
                        width_span,
                        &keys.width,
                        fmt_num(width),
                        &format!("width/2 must be below every radius of {key} (built-in default)"),
                    ));
                }
                Err(e) => return Err(e),
            };
            radii.push(rs);
        }
        let r2_m = radii.pop().unwrap_or_default();
        let r1_m = radii.pop().unwrap_or_default();
        Ok(DeckAxes {
            beta1_deg,
            beta2_deg,
            r1_m,
            r2_m,
            ..DeckAxes::default()
        })
    }

    /// `decks.L1`, `L2` (> 0) and, for skewed decks, `decks.skew_deg` in `[0, 90)`
    /// (straight decks: one skew angle, 0).
    fn straight_axes(
        &self,
        decks: &RawDecks,
        keys: &DeckKeys,
        shape: StudyShape,
    ) -> Result<DeckAxes, ScenarioError> {
        let l_ok = |x: Real| x > 0.0;
        let l = "the deck length must be finite and > 0";
        let (l1_m, _) = self.list(&decks.l1, &DEFAULT_LENGTHS_M, &keys.l1, l_ok, l)?;
        let (l2_m, _) = self.list(&decks.l2, &DEFAULT_LENGTHS_M, &keys.l2, l_ok, l)?;
        let skew_deg = if shape == StudyShape::Skew {
            self.list(
                &decks.skew_deg,
                &DEFAULT_SKEW_DEG,
                "decks.skew_deg",
                |x| (0.0..90.0).contains(&x),
                "the skew angle must lie in [0, 90) deg",
            )?
            .0
        } else {
            vec![0.0]
        };
        Ok(DeckAxes {
            l1_m,
            l2_m,
            skew_deg,
            ..DeckAxes::default()
        })
    }

    /// `impact.sigma_mode`: `exact` or `end`.
    fn sigma_mode(
        &self,
        impact: &RawImpact,
        default: SigmaMode,
    ) -> Result<SigmaMode, ScenarioError> {
        let Some(s) = &impact.sigma_mode else {
            return Ok(default);
        };
        match s.get_ref().as_str() {
            "exact" => Ok(SigmaMode::Exact),
            "end" => Ok(SigmaMode::End),
            other => Err(self.invalid(
                s.span(),
                "impact.sigma_mode",
                format!("{other:?}"),
                "expected \"exact\" or \"end\"",
            )),
        }
    }

    /// `grid.ratio_min` (finite) and `grid.ratio_max` (above it, by at most
    /// [`MAX_RATIO_WIDTH`]).
    fn ratio_bounds(&self, grid: &RawGrid, d: &Scenario) -> Result<(Real, Real), ScenarioError> {
        let (ratio_min, _) = self.scalar(
            &grid.ratio_min,
            d.ratio_min,
            "grid.ratio_min",
            |_| true,
            "must be finite",
        )?;
        let (ratio_max, _) = self.scalar(
            &grid.ratio_max,
            d.ratio_max,
            "grid.ratio_max",
            |x| x > ratio_min && (x - ratio_min).is_finite() && (x - ratio_min) <= MAX_RATIO_WIDTH,
            &format!(
                "must be finite and > ratio_min = {}, with ratio_max - ratio_min <= {}",
                fmt_num(ratio_min),
                fmt_num(MAX_RATIO_WIDTH)
            ),
        )?;
        Ok((ratio_min, ratio_max))
    }

    /// `grid.cases`: a non-empty list of distinct case names, returned in [`ContactCase::ALL`]
    /// order.
    fn cases(
        &self,
        grid: &RawGrid,
        default: &[ContactCase],
    ) -> Result<Vec<ContactCase>, ScenarioError> {
        let Some(s) = &grid.cases else {
            return Ok(default.to_vec());
        };
        let names = s.get_ref();
        if names.is_empty() {
            return Err(self.invalid(
                s.span(),
                "grid.cases",
                "[]".into(),
                "the list must not be empty",
            ));
        }
        let mut set = Vec::new();
        for (i, n) in names.iter().enumerate() {
            let Some(c) = ContactCase::from_name(n) else {
                return Err(self.invalid(
                    s.span(),
                    &format!("grid.cases[{i}]"),
                    format!("{n:?}"),
                    "expected one of \"deck1-inner\", \"deck1-outer\", \"deck2-inner\", \"deck2-outer\"",
                ));
            };
            if set.contains(&c) {
                return Err(self.invalid(
                    s.span(),
                    &format!("grid.cases[{i}]"),
                    format!("{n:?}"),
                    "duplicate case",
                ));
            }
            set.push(c);
        }
        Ok(ContactCase::ALL
            .into_iter()
            .filter(|c| set.contains(c))
            .collect())
    }

    /// `[output]`: `figures`, `svg` (needs figures) and `region_map_samples` in `[2, 100000]`.
    fn output(
        &self,
        output: &RawOutput,
        d: &OutputOptions,
    ) -> Result<OutputOptions, ScenarioError> {
        let figures = output.figures.as_ref().map_or(d.figures, |s| *s.get_ref());
        let svg = output.svg.as_ref().map_or(d.svg, |s| *s.get_ref());
        if let Some(s) = &output.svg
            && svg
            && !figures
        {
            return Err(self.invalid(
                s.span(),
                "output.svg",
                "true".into(),
                "SVG copies of the figures need figures = true (output.figures is false)",
            ));
        }
        let region_map_samples = match &output.region_map_samples {
            None => d.region_map_samples,
            Some(s) => {
                let n = *s.get_ref();
                if !(2..=100_000).contains(&n) {
                    return Err(self.invalid(
                        s.span(),
                        "output.region_map_samples",
                        n.to_string(),
                        "must lie in [2, 100000]",
                    ));
                }
                n as usize
            }
        };
        Ok(OutputOptions {
            figures,
            svg,
            region_map_samples,
        })
    }
}

/// Checks the derived mass properties (area, mass, polar inertia) of every deck at load time, so
/// that an overflow or underflow (e.g. `density = 1e300` on large decks) names the scenario
/// key and its line instead of failing during the run. Mass and inertia grow with every
/// dimension, so the extremes of each list suffice; the run validates every configuration again.
fn check_deck_mass_properties(
    s: &Scenario,
    cx: &Ctx,
    decks: &RawDecks,
    keys: &DeckKeys,
) -> Result<(), ScenarioError> {
    use crate::geometry::GeometryError;
    use crate::shape::Deck;
    use crate::shape::{SkewedDeck, StraightDeck};
    let span = |v: Option<Range<usize>>| v.unwrap_or(0..0);
    let scalar = |v: &S<Real>| span(v.as_ref().map(|v| v.span()));
    let list = |v: &S<Vec<Real>>| span(v.as_ref().map(|v| v.span()));
    // (scenario key, span) of a deck's parameter named by the geometry error
    let key_of = |name: &str, j: usize| -> (&str, Range<usize>) {
        match (name, j) {
            ("density", _) => (&keys.density, scalar(&decks.density)),
            ("thickness", _) => (&keys.thickness, scalar(&decks.thickness)),
            ("width", _) => (&keys.width, scalar(&decks.width)),
            ("skew", _) => ("decks.skew_deg", list(&decks.skew_deg)),
            ("R", 1) => (&keys.r1, list(&decks.r1)),
            ("R", _) => (&keys.r2, list(&decks.r2)),
            ("beta", 1) => ("decks.beta1_deg", list(&decks.beta1_deg)),
            ("beta", _) => ("decks.beta2_deg", list(&decks.beta2_deg)),
            (_, 1) => (&keys.l1, list(&decks.l1)),
            _ => (&keys.l2, list(&decks.l2)),
        }
    };
    let (w, t, rho) = (s.width, s.thickness, s.density);
    for j in [1usize, 2] {
        let mut results: Vec<Result<(), GeometryError>> = Vec::new();
        match s.shape {
            StudyShape::Curved => {
                let (rs, bs) = if j == 1 {
                    (&s.r1_m, &s.beta1_deg)
                } else {
                    (&s.r2_m, &s.beta2_deg)
                };
                for r in extremes(rs) {
                    for b in extremes(bs) {
                        results.push(Deck::new(r, b.to_radians(), w, t, rho).map(|_| ()));
                    }
                }
            }
            shape => {
                let ls = if j == 1 { &s.l1_m } else { &s.l2_m };
                for l in extremes(ls) {
                    if shape == StudyShape::Straight {
                        results.push(StraightDeck::new(l, w, t, rho).map(|_| ()));
                    } else {
                        for sk in extremes(&s.skew_deg) {
                            results
                                .push(SkewedDeck::new(l, w, sk.to_radians(), t, rho).map(|_| ()));
                        }
                    }
                }
            }
        }
        if let Some(Err(GeometryError::InvalidParameter {
            name,
            value,
            reason,
            ..
        })) = results.into_iter().find(Result::is_err)
        {
            let (key, span) = key_of(&name, j);
            return Err(cx.invalid(span, key, fmt_num(value), &format!("deck {j}: {reason}")));
        }
    }
    Ok(())
}

/// The smallest and the largest value of a list (the list itself when it has one value).
fn extremes(xs: &[Real]) -> Vec<Real> {
    let lo = xs.iter().copied().fold(Real::INFINITY, Real::min);
    let hi = xs.iter().copied().fold(Real::NEG_INFINITY, Real::max);
    if lo == hi { vec![lo] } else { vec![lo, hi] }
}

fn fmt_num(x: Real) -> String {
    crate::output::float_token(x)
}

impl Scenario {
    /// Parses and validates a scenario from TOML text. `origin` (e.g. the file name) prefixes errors.
    ///
    /// Errors name the key and the line: syntax errors, unknown keys and wrong types
    /// ([`ScenarioError::Syntax`]); an unknown `decks.shape`, keys of another shape, `L ≤ 0`,
    /// skew `∉ [0, 90)`, empty or duplicate lists, `R ≤ W/2`, `step ≤ 0`, `μ < 0`,
    /// `ε ∉ [0, 1]`, `β ∉ (0, 360)`, non-positive width/thickness/density, `ratio_max ≤ ratio_min`
    /// or an infinite `ratio_max − ratio_min`
    /// ([`ScenarioError::Invalid`]).
    ///
    /// The deprecated `[decks]` names ([`DECK_RENAMES`]) are accepted; use
    /// [`Scenario::from_toml_with_notes`] to learn which ones a file used.
    pub fn from_toml(text: &str, origin: &str) -> Result<Self, ScenarioError> {
        Self::from_toml_with_notes(text, origin).map(|(s, _)| s)
    }

    /// [`Scenario::from_toml`], also returning a note for each deprecated key the file used
    /// (`width_m` for `width`, …, see [`DECK_RENAMES`]). A quantity given under both its
    /// current and its deprecated name is an error naming both keys and their lines.
    pub fn from_toml_with_notes(
        text: &str,
        origin: &str,
    ) -> Result<(Self, Vec<DeprecatedKey>), ScenarioError> {
        let raw = parse_raw(text, origin)?;
        let cx = Ctx { text, origin };
        let d = Scenario::default();
        let mut decks = raw.decks.map(Table::into_inner).unwrap_or_default();
        let mut notes = Vec::new();
        let keys = keys::fold_deprecated(&cx, &mut decks, &mut notes)?;
        let impact = raw.impact.map(Table::into_inner).unwrap_or_default();
        let grid = raw.grid.map(Table::into_inner).unwrap_or_default();
        let output = raw.output.map(Table::into_inner).unwrap_or_default();
        // The order of the checks is the order of the keys in the file's documentation: the
        // first bad value found is the one reported.
        let pos = |x: Real| x > 0.0;
        let (width, width_span) =
            cx.scalar(&decks.width, d.width, &keys.width, pos, "must be > 0")?;
        let (thickness, _) = cx.scalar(
            &decks.thickness,
            d.thickness,
            &keys.thickness,
            pos,
            "must be > 0",
        )?;
        let (density, _) =
            cx.scalar(&decks.density, d.density, &keys.density, pos, "must be > 0")?;
        let shape = cx.shape(&decks)?;
        cx.refuse_foreign_keys(&decks, &keys, shape)?;
        let axes = if shape == StudyShape::Curved {
            cx.curved_axes(&decks, &keys, &d, width, width_span)?
        } else {
            cx.straight_axes(&decks, &keys, shape)?
        };
        let (mu, _) = cx.list(
            &impact.mu,
            &d.mu,
            "impact.mu",
            |x| x >= 0.0,
            "must be finite and >= 0",
        )?;
        let (eps, _) = cx.list(
            &impact.eps,
            &d.eps,
            "impact.eps",
            |x| (0.0..=1.0).contains(&x),
            "must lie in [0, 1]",
        )?;
        let sigma_mode = cx.sigma_mode(&impact, d.sigma_mode)?;
        let theta1 = cx.range(&grid.theta1_deg, d.theta1, "grid.theta1_deg")?;
        let theta2 = cx.range(&grid.theta2_deg, d.theta2, "grid.theta2_deg")?;
        let (ratio_min, ratio_max) = cx.ratio_bounds(&grid, &d)?;
        let cases = cx.cases(&grid, &d.cases)?;
        let output = cx.output(&output, &d.output)?;
        let scenario = Self {
            shape,
            l1_m: axes.l1_m,
            l2_m: axes.l2_m,
            skew_deg: axes.skew_deg,
            width,
            thickness,
            density,
            beta1_deg: axes.beta1_deg,
            beta2_deg: axes.beta2_deg,
            r1_m: axes.r1_m,
            r2_m: axes.r2_m,
            mu,
            eps,
            theta1,
            theta2,
            ratio_min,
            ratio_max,
            cases,
            sigma_mode,
            output,
        };
        check_deck_mass_properties(&scenario, &cx, &decks, &keys)?;
        scenario
            .check_size(origin)
            .map_err(|e| locate_size_error(e, &grid, text))?;
        Ok((scenario, notes))
    }

    /// `ρ t` \[kg/m²\], the factor by which the Delassus entries of the spec's §15 table (per unit ρt)
    /// are divided.
    pub fn rho_t(&self) -> Real {
        self.density * self.thickness
    }

    /// Sizes of the four geometry axes: `(β1, β2, R1, R2)` for curved decks, `(L1, L2, θ_s, 1)`
    /// for straight and skewed decks.
    pub fn geometry_dims(&self) -> [usize; 4] {
        match self.shape {
            StudyShape::Curved => [
                self.beta1_deg.len(),
                self.beta2_deg.len(),
                self.r1_m.len(),
                self.r2_m.len(),
            ],
            _ => [self.l1_m.len(), self.l2_m.len(), self.skew_deg.len(), 1],
        }
    }

    /// The geometry axes of this shape at the indices `g`: `(name in labels, unit, name in file
    /// names, value)`.
    fn geometry_axes(
        &self,
        g: [usize; 4],
    ) -> Vec<(&'static str, &'static str, &'static str, Real)> {
        match self.shape {
            StudyShape::Curved => vec![
                ("β1", "°", "b1", self.beta1_deg[g[0]]),
                ("β2", "°", "b2", self.beta2_deg[g[1]]),
                ("R1", " m", "r1", self.r1_m[g[2]]),
                ("R2", " m", "r2", self.r2_m[g[3]]),
            ],
            StudyShape::Straight => vec![
                ("L1", " m", "l1", self.l1_m[g[0]]),
                ("L2", " m", "l2", self.l2_m[g[1]]),
            ],
            StudyShape::Skew => vec![
                ("L1", " m", "l1", self.l1_m[g[0]]),
                ("L2", " m", "l2", self.l2_m[g[1]]),
                ("skew", "°", "skew", self.skew_deg[g[2]]),
            ],
        }
    }

    /// Human-readable geometry of the axis indices `g` (figure titles), e.g.
    /// `β1 = 60°, β2 = 90°, R1 = 100 m, R2 = 200 m` or `straight decks, L1 = 30 m, L2 = 60 m`.
    pub fn geometry_label(&self, g: [usize; 4]) -> String {
        let prefix = match self.shape {
            StudyShape::Curved => "",
            StudyShape::Straight => "straight decks, ",
            StudyShape::Skew => "skewed decks, ",
        };
        let axes: Vec<String> = self
            .geometry_axes(g)
            .into_iter()
            .map(|(name, unit, _, v)| format!("{name} = {}{unit}", fmt_num(v)))
            .collect();
        format!("{prefix}{}", axes.join(", "))
    }

    /// File-name fragment of the geometry `g`: `b1-60_b2-90_r1-100_r2-200` (curved, as before),
    /// `straight_l1-30_l2-60` or `skew_l1-30_l2-60_skew-15`.
    pub fn geometry_id(&self, g: [usize; 4]) -> String {
        let prefix = match self.shape {
            StudyShape::Curved => "",
            StudyShape::Straight => "straight_",
            StudyShape::Skew => "skew_",
        };
        let axes: Vec<String> = self
            .geometry_axes(g)
            .into_iter()
            .map(|(_, _, id, v)| format!("{id}-{}", fmt_num(v)))
            .collect();
        format!("{prefix}{}", axes.join("_"))
    }

    /// Number of deck geometries (product of [`geometry_dims`](Self::geometry_dims)).
    pub fn geometry_count(&self) -> usize {
        self.geometry_dims().iter().product()
    }

    /// Number of configurations `(β1, β2, R1, R2, μ, ε)`.
    pub fn configuration_count(&self) -> usize {
        self.geometry_count() * self.mu.len() * self.eps.len()
    }

    /// Number of `θ1 × θ2` cells.
    pub fn cell_count(&self) -> usize {
        self.theta1.len() * self.theta2.len()
    }

    /// Total number of rows of `bounds.csv`.
    ///
    /// Saturates at `usize::MAX` for a scenario built by hand beyond every limit; a scenario read by
    /// [`from_toml`](Self::from_toml) has at most [`MAX_ROWS`] rows.
    pub fn row_count(&self) -> usize {
        self.checked_row_count().unwrap_or(usize::MAX)
    }

    /// Total number of rows of `bounds.csv`, or `None` if the product overflows `usize`.
    pub fn checked_row_count(&self) -> Option<usize> {
        let mut n = self.mu.len().checked_mul(self.eps.len())?;
        for d in self.geometry_dims() {
            n = n.checked_mul(d)?;
        }
        n.checked_mul(self.cases.len())?
            .checked_mul(self.theta1.len())?
            .checked_mul(self.theta2.len())
    }

    /// Refuses a scenario of more than [`MAX_ROWS`] rows (or none), as bad input naming the grid.
    pub fn check_size(&self, origin: &str) -> Result<(), ScenarioError> {
        match self.checked_row_count() {
            Some(n) if (1..=MAX_ROWS).contains(&n) => Ok(()),
            n => Err(ScenarioError::Invalid {
                origin: origin.to_string(),
                line: 0,
                key: "grid".into(),
                value: n.map_or_else(|| "more than 2^64".into(), |n| n.to_string()),
                reason: format!(
                    "the study has this many rows (geometries {:?} x mu {} x eps {} x cases {} x theta1 {} x theta2 {}); the limit is {MAX_ROWS}",
                    self.geometry_dims(),
                    self.mu.len(),
                    self.eps.len(),
                    self.cases.len(),
                    self.theta1.len(),
                    self.theta2.len()
                ),
            }),
        }
    }
}
