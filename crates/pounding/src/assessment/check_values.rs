//! Reading the values of `[code_check]` ([`super::check_input`]): each kind of value checked,
//! errors naming `code_check.KEY`, the file and the line.

use super::AssessmentError;
use crate::math::Real;
use crate::output::float_token;
use crate::toml_schema::line_col;
use toml::Spanned;

/// A value given once for every segment or once per segment.
#[derive(Debug, Clone, PartialEq)]
pub enum PerSegment {
    /// The same value at every segment.
    All(Real),
    /// One value per segment, from the start.
    Each(Vec<Real>),
}

impl PerSegment {
    /// The value of segment `i` (0-based); `None` past the list's end (refused by
    /// [`CodeCheckInput::check_segments`]).
    pub fn of(&self, i: usize) -> Option<Real> {
        match self {
            PerSegment::All(x) => Some(*x),
            PerSegment::Each(v) => v.get(i).copied(),
        }
    }
}

type Sp<T> = Option<Spanned<T>>;

/// Error context: the scenario's name and text.
pub(super) struct Cx<'a> {
    pub(super) origin: &'a str,
    pub(super) text: &'a str,
}

impl Cx<'_> {
    pub(super) fn line<T>(&self, s: &Spanned<T>) -> usize {
        line_col(self.text, s.span().start).0
    }
    pub(super) fn err<T>(&self, key: &str, s: &Spanned<T>, message: String) -> AssessmentError {
        AssessmentError::Key {
            message,
            key: format!("code_check.{key}"),
            origin: self.origin.to_string(),
            line: Some(self.line(s)),
        }
    }
    /// A number `x` with `ok(x)`, else an error saying it must be `what`.
    pub(super) fn num(
        &self,
        key: &str,
        v: &Spanned<Real>,
        ok: impl Fn(Real) -> bool,
        what: &str,
    ) -> Result<Real, AssessmentError> {
        let x = *v.get_ref();
        if x.is_finite() && ok(x) {
            Ok(x)
        } else {
            Err(self.err(
                key,
                v,
                format!("invalid {key} = {}: {what}", float_token(x)),
            ))
        }
    }
    /// An optional number, checked as [`Cx::num`] when given.
    pub(super) fn opt_num(
        &self,
        key: &str,
        v: &Sp<Real>,
        ok: impl Fn(Real) -> bool,
        what: &str,
    ) -> Result<Option<Real>, AssessmentError> {
        v.as_ref().map(|v| self.num(key, v, &ok, what)).transpose()
    }
    /// A length in metres in `[0, 1e4]` (a code's displacement or height is never beyond).
    pub(super) fn length(&self, key: &str, v: &Sp<Real>) -> Result<Option<Real>, AssessmentError> {
        v.as_ref()
            .map(|v| {
                self.num(
                    key,
                    v,
                    |x| (0.0..=1e4).contains(&x),
                    "must lie in [0, 1e4] m",
                )
            })
            .transpose()
    }
    /// One of `names` (case as written), its index.
    pub(super) fn choice(
        &self,
        key: &str,
        v: &Spanned<String>,
        names: &[&str],
    ) -> Result<usize, AssessmentError> {
        names
            .iter()
            .position(|n| *n == v.get_ref().trim())
            .ok_or_else(|| {
                self.err(
                    key,
                    v,
                    format!("unknown {key} {:?}: use {}", v.get_ref(), names.join(", ")),
                )
            })
    }
    /// An integer in `lo..=hi`.
    pub(super) fn int(
        &self,
        key: &str,
        v: &Spanned<i64>,
        lo: i64,
        hi: i64,
    ) -> Result<u8, AssessmentError> {
        let x = *v.get_ref();
        if (lo..=hi).contains(&x) {
            Ok(x as u8)
        } else {
            Err(self.err(key, v, format!("invalid {key} = {x}: must be {lo} to {hi}")))
        }
    }
    /// A number or an array of numbers, each in `[0, max]` (and `> 0` when `positive`).
    pub(super) fn per_segment(
        &self,
        key: &str,
        v: &Spanned<toml::Value>,
        max: Real,
        positive: bool,
    ) -> Result<PerSegment, AssessmentError> {
        let bound = if positive { "(0, " } else { "[0, " };
        let check = |x: Option<Real>, item: String| -> Result<Real, AssessmentError> {
            match x {
                Some(x) if x.is_finite() && x <= max && (x > 0.0 || !positive && x == 0.0) => Ok(x),
                Some(x) => Err(self.err(
                    key,
                    v,
                    format!(
                        "invalid {key}{item} = {}: must lie in {bound}{}]",
                        float_token(x),
                        float_token(max)
                    ),
                )),
                None => Err(self.err(key, v, format!("{key}{item} must be a number"))),
            }
        };
        let number = |x: &toml::Value| x.as_float().or(x.as_integer().map(|i| i as Real));
        match v.get_ref() {
            toml::Value::Array(items) if items.is_empty() => Err(self.err(
                key,
                v,
                format!("{key} lists no value: give one number or one per segment"),
            )),
            toml::Value::Array(items) => items
                .iter()
                .enumerate()
                .map(|(i, x)| check(number(x), format!("[{i}]")))
                .collect::<Result<Vec<_>, _>>()
                .map(PerSegment::Each),
            x => check(number(x), String::new()).map(PerSegment::All),
        }
    }
}
