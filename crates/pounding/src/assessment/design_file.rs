//! The design file's own tables as read: the error of reading a design file ([`DesignError`])
//! and its optional `[search]` table ([`SearchSpec`], run by [`super::design_search::search`]).

use super::AssessmentError;
use super::variant::{VariantError, parse_path};
use crate::math::Real;

/// Why a design cannot start.
#[derive(Debug, thiserror::Error)]
pub enum DesignError {
    /// The design file: syntax, keys, a variant's override.
    #[error(transparent)]
    Variant(#[from] VariantError),
    /// The as-built study.
    #[error(transparent)]
    Study(#[from] AssessmentError),
    /// A `[design]` key.
    #[error("{origin}:{line}: `{key}`: {message}")]
    Key {
        /// The design file.
        origin: String,
        /// 1-based line (1 when the key is missing).
        line: usize,
        /// The key.
        key: String,
        /// What is wrong.
        message: String,
    },
}

/// The `[search]` table.
#[derive(Debug, Clone, PartialEq)]
pub struct SearchSpec {
    /// The key path.
    pub key: String,
    /// The range, `lo < hi`, both > 0.
    pub range: (Real, Real),
    /// The limit state's name.
    pub limit_state: String,
    /// The target MAF \[1/yr\].
    pub target: Real,
    /// Relative width at which the bisection stops.
    pub tolerance: Real,
    /// 1-based line of `key` in the design file.
    pub line: usize,
}

#[derive(serde::Deserialize)]
struct File {
    search: Option<toml::Spanned<crate::toml_schema::Table<Sec>>>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Sec {
    key: toml::Spanned<String>,
    range: toml::Spanned<Vec<Real>>,
    limit_state: toml::Spanned<String>,
    target_maf: toml::Spanned<Real>,
    tolerance: Option<toml::Spanned<Real>>,
}

impl SearchSpec {
    /// The `[search]` table of the design file `text` (`None` without one).
    pub fn from_design(text: &str, origin: &str) -> Result<Option<Self>, DesignError> {
        let f: File = toml::from_str(text).map_err(|e| VariantError::Syntax {
            origin: origin.into(),
            message: crate::input::shorten_lines(&e.to_string(), 200),
        })?;
        let Some(s) = f.search else { return Ok(None) };
        let line = |p: usize| crate::toml_schema::line_col(text, p).0;
        let err = |p: usize, k: &str, m: &str| DesignError::Key {
            origin: origin.into(),
            line: line(p),
            key: format!("search.{k}"),
            message: m.into(),
        };
        let s = &s.get_ref().0;
        parse_path(s.key.get_ref()).map_err(|m| err(s.key.span().start, "key", m))?;
        let r = s.range.get_ref();
        if !(r.len() == 2 && r[0] > 0.0 && r[1] > r[0] && r[1].is_finite()) {
            return Err(err(s.range.span().start, "range", "two values 0 < lo < hi"));
        }
        let t = *s.target_maf.get_ref();
        if !(t > 0.0 && t.is_finite()) {
            return Err(err(
                s.target_maf.span().start,
                "target_maf",
                "must be > 0 (per year)",
            ));
        }
        let tol = s.tolerance.as_ref().map_or(Ok(0.05), |v| {
            let x = *v.get_ref();
            if x > 0.0 && x < 1.0 {
                Ok(x)
            } else {
                Err(err(v.span().start, "tolerance", "must lie in (0, 1)"))
            }
        })?;
        Ok(Some(SearchSpec {
            key: s.key.get_ref().clone(),
            range: (r[0], r[1]),
            limit_state: s.limit_state.get_ref().clone(),
            target: t,
            tolerance: tol,
            line: line(s.key.span().start),
        }))
    }
}
