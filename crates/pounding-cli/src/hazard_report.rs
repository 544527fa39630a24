//! The hazard section of `report.html` (`pounding fragility` with a hazard curve): the curve, per
//! limit state the mean annual frequency with its interval and the return period, what the
//! table's range leaves out, and the deaggregation figure.

use crate::report::esc;
use pounding::assessment::hazard_input::HazardInput;
use pounding::assessment::hazard_study::MafRow;
use pounding::fragility::hazard::HazardCurve;
use pounding::math::Real;
use std::fmt::Write;

/// `x` in scientific notation to 3 digits, `-` when not finite.
pub(crate) fn sci(x: Real) -> String {
    if x.is_finite() {
        format!("{x:.3e}")
    } else {
        "-".into()
    }
}

/// A return period in years, rounded, `-` when not finite.
pub(crate) fn years(x: Real) -> String {
    if x.is_finite() {
        format!("{:.0}", x)
    } else {
        "-".into()
    }
}

/// The curve in words.
pub(crate) fn describe(h: &HazardInput) -> String {
    match &h.curve {
        HazardCurve::PowerLaw { k0, k } => format!(
            "power law λ(IM) = {} · IM^−{} per year (IM in g), from {}; the MAF is the closed \
             form k0 θ^−k exp(k²β²/2)",
            sci(*k0),
            k,
            h.source
        ),
        HazardCurve::Table { im, .. } => format!(
            "table of {} points from {} g to {} g, from {}; log-log interpolation between \
             points, integrated over the table's range only",
            im.len(),
            im[0],
            im[im.len() - 1],
            h.source
        ),
    }
}

/// The section.
pub(crate) fn section(h: &mut String, hz: &HazardInput, rows: &[MafRow], warnings: &[String]) {
    let _ = write!(
        h,
        "<h2 id=\"hazard\">Mean annual frequency</h2>\n<p>Site hazard: {}. The mean annual \
         frequency (MAF) of a limit state is λ_LS = ∫ P(LS | IM = x) |dλ(x)|; its interval comes \
         from the same bootstrap replicates (θ_b, β_b) as the fragility's. Data: <a \
         href=\"maf.csv\">maf.csv</a>, <a href=\"hazard.csv\">hazard.csv</a> (the \
         deaggregation).</p>\n<table>\n<tr><th>limit state</th><th>status</th><th>MAF \
         [1/yr]</th><th>interval</th><th>return period [yr]</th><th>interval [yr]</th><th>left \
         out above the table [1/yr]</th></tr>\n",
        esc(&describe(hz))
    );
    for r in rows {
        let m = r.maf;
        let rate = m.map_or(Real::NAN, |m| m.rate);
        let (lo, hi) = r.interval.unwrap_or((Real::NAN, Real::NAN));
        let tail = m
            .and_then(|m| m.upper_tail)
            .map_or("-".into(), |(a, b)| format!("{}–{}", sci(a), sci(b)));
        let _ = writeln!(
            h,
            "<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}–{}</td><td>{}</td><td>{}–{}</td><td>{}</td></tr>",
            esc(&r.limit_state),
            esc(&r.status),
            sci(rate),
            sci(lo),
            sci(hi),
            years(1.0 / rate),
            years(1.0 / hi),
            years(1.0 / lo),
            tail
        );
    }
    h.push_str("</table>\n");
    for w in warnings {
        let _ = writeln!(h, "<p class=\"warn\">{}</p>", esc(w));
    }
    h.push_str("<p><img src=\"hazard.png\" alt=\"deaggregation of the MAF by IM\" width=\"1100\"></p>\n<p>Each curve is the share of the limit state's MAF per unit ln IM: where on the hazard curve the frequency of exceedance comes from.</p>\n");
}
