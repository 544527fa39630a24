//! A hazard CSV file (`im_g,rate`) and the checks of a hazard table's points
//! ([`super::hazard_input`]).

use super::AssessmentError;
use crate::fragility::hazard::HazardCurve;
use crate::math::Real;

/// Checks points `(IM, rate)`: `Err((column, index, message))`.
pub(crate) fn check_points(pts: &[(Real, Real)]) -> Result<(), (&'static str, usize, String)> {
    if pts.len() < 2 {
        return Err(("im", 0, "a hazard table needs at least two points".into()));
    }
    for (i, &(x, l)) in pts.iter().enumerate() {
        if !(x.is_finite() && x > 0.0) {
            return Err(("im", i, format!("IM {x} must be finite and > 0")));
        }
        if !(l.is_finite() && l > 0.0) {
            return Err((
                "rate",
                i,
                format!("rate {l} must be finite and > 0 (per year)"),
            ));
        }
        if i > 0 && x <= pts[i - 1].0 {
            return Err((
                "im",
                i,
                format!("IM {x} does not increase (previous {})", pts[i - 1].0),
            ));
        }
        if i > 0 && l >= pts[i - 1].1 {
            return Err((
                "rate",
                i,
                format!(
                    "rate {l} does not decrease (previous {}): the rate of exceedance falls as \
                     the IM rises",
                    pts[i - 1].1
                ),
            ));
        }
    }
    Ok(())
}

/// A hazard CSV: `#` comments and blank lines skipped; a header `im_<unit>,rate` (the unit must
/// be `g`); then one `IM,rate` point a line.
pub fn read_csv(text: &str, origin: &str) -> Result<HazardCurve, AssessmentError> {
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim().trim_start_matches('\u{feff}')))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((hl, header)) = rows.next() else {
        return Err(AssessmentError::key(
            origin,
            "header",
            None,
            "empty hazard file".into(),
        ));
    };
    let cols: Vec<&str> = header.split(',').map(str::trim).collect();
    let [im_col, rate_col] = cols[..] else {
        return Err(AssessmentError::key(
            origin,
            "header",
            Some(hl),
            format!("{header:?}: a hazard file has two columns, im_g,rate"),
        ));
    };
    match im_col.strip_prefix("im_") {
        Some("g") => {}
        Some(u) => {
            return Err(AssessmentError::key(
                origin,
                im_col,
                Some(hl),
                format!(
                    "the IMs are in {u:?} but the fragility's IM is in g: convert them to g \
                     (column im_g)"
                ),
            ));
        }
        None => {
            return Err(AssessmentError::key(
                origin,
                im_col,
                Some(hl),
                "the first column must name the IM's unit: im_g".into(),
            ));
        }
    }
    if rate_col != "rate" {
        return Err(AssessmentError::key(
            origin,
            rate_col,
            Some(hl),
            "the second column must be rate (annual rate of exceedance, per year)".into(),
        ));
    }
    let mut pts = Vec::new();
    let mut lines = Vec::new();
    for (ln, l) in rows {
        let cells: Vec<&str> = l.split(',').map(str::trim).collect();
        if cells.len() != 2 {
            return Err(AssessmentError::key(
                origin,
                "row",
                Some(ln),
                format!("{} cells, the header has 2", cells.len()),
            ));
        }
        let num = |c: &str, col: &str| {
            c.parse::<Real>().map_err(|_| {
                AssessmentError::key(origin, col, Some(ln), format!("not a number: {c:?}"))
            })
        };
        pts.push((num(cells[0], im_col)?, num(cells[1], rate_col)?));
        lines.push(ln);
    }
    check_points(&pts).map_err(|(col, i, m)| {
        let c = if col == "im" { im_col } else { rate_col };
        AssessmentError::key(origin, c, lines.get(i).copied().or(Some(hl)), m)
    })?;
    Ok(HazardCurve::Table {
        im: pts.iter().map(|p| p.0).collect(),
        rate: pts.iter().map(|p| p.1).collect(),
    })
}
