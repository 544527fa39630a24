//! Intensity measures of records and pairs, and the bridge's fundamental period.
//!
//! * `PGA` = `max |a|` / g of the record as applied.
//! * `Sa(T, ζ)` = `ω² S_d / g`, `S_d` the peak relative displacement of the linear oscillator
//!   ([`crate::spectrum::peak_displacement`], exact for piecewise-linear records, peaks over
//!   continuous time and the free vibration after the record).
//! * Pairs: the geometric mean `√(IM_x IM_y)`, or RotD50: the median over the angles
//!   `α = 0°, 1°, …, 179°` of the peak of `a_x cos α + a_y sin α` (PGA, on the union of the
//!   two sample grids, where the piecewise-linear peak lies) or of the oscillator's response
//!   ([`crate::spectrum::rotd`] for `Sa`).
//!
//! Every IM is homogeneous of degree 1: scaling both components by `s > 0` scales the IM by
//! `s`. A stripe at level `L` therefore runs the record (pair) times `L / IM`, and its IM is `L`.

use super::AssessmentError;
use super::settings::{ImKind, PairIm};
use crate::ground_motion::set::SetRecord;
use crate::ground_motion::{G0, Record};
use crate::math::Real;
use crate::sim::bridge::BridgeModel;

/// How an IM is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImSpec {
    /// PGA or Sa.
    pub kind: ImKind,
    /// Period of Sa \[s\] (unused for PGA).
    pub period: Real,
    /// Damping ratio of Sa.
    pub damping: Real,
    /// The IM of pairs.
    pub pair: PairIm,
}

impl ImSpec {
    /// The column label, e.g. `Sa(0.5 s, 5 %)` or `PGA`.
    pub fn label(&self) -> String {
        match self.kind {
            ImKind::Pga => "PGA".into(),
            ImKind::Sa => format!(
                "Sa({} s, {} %)",
                sig4(self.period),
                sig4(self.damping * 100.0)
            ),
        }
    }
}

/// `x` rounded to 4 significant digits, shortest form (`4.218134191537946` → `4.218`; labels
/// only: the data keep full precision).
fn sig4(x: Real) -> String {
    crate::output::float_token(format!("{x:.3e}").parse::<Real>().unwrap_or(x))
}

/// `record` times `s`; `None` when a scaled acceleration is not finite (a factor of 1e308).
fn scaled(record: &Record, s: Real) -> Option<Record> {
    if s == 1.0 {
        return Some(record.clone());
    }
    let v: Vec<Real> = record.values().iter().map(|a| a * s).collect();
    Record::new(record.name.clone(), record.times().to_vec(), v).ok()
}

/// IM of one component \[g\].
fn single(spec: &ImSpec, r: &Record) -> Real {
    match spec.kind {
        ImKind::Pga => r.pga() / G0,
        ImKind::Sa => {
            let sd = crate::spectrum::peak_displacement(
                r.times(),
                r.values(),
                spec.period,
                spec.damping,
            );
            let w = 2.0 * std::f64::consts::PI / spec.period;
            w * w * sd / G0
        }
    }
}

/// RotD50 of the PGA of a pair \[g\]: the peak of the rotated motion lies at a sample of the
/// union grid (the motion is linear between samples).
fn pga_rotd50(x: &Record, y: &Record) -> Real {
    let mut t: Vec<Real> = x.times().iter().chain(y.times()).copied().collect();
    t.sort_by(Real::total_cmp);
    t.dedup();
    let (ax, ay): (Vec<Real>, Vec<Real>) = t.iter().map(|&s| (x.accel(s), y.accel(s))).unzip();
    let mut peaks: Vec<Real> = (0..180)
        .map(|d| {
            let (sn, c) = (d as Real).to_radians().sin_cos();
            ax.iter()
                .zip(&ay)
                .fold(0.0, |m: Real, (a, b)| m.max((c * a + sn * b).abs()))
        })
        .collect();
    peaks.sort_by(Real::total_cmp);
    0.5 * (peaks[89] + peaks[90]) / G0
}

/// The IM \[g\] of an entry as applied at unit scale: its first component times `|sx|`, its
/// second times `|sy|` (the scenario's `[ground_motion]` scale factors of the directions they act
/// along). `None` when a scaled component's accelerations overflow.
pub fn intensity(spec: &ImSpec, rec: &SetRecord, sx: Real, sy: Real) -> Option<Real> {
    let x = scaled(&rec.x, sx.abs())?;
    Some(match &rec.y {
        None => single(spec, &x),
        Some(y) => {
            let y = scaled(y, sy.abs())?;
            match (spec.pair, spec.kind) {
                (PairIm::GeoMean, _) => (single(spec, &x) * single(spec, &y)).sqrt(),
                (PairIm::RotD50, ImKind::Pga) => pga_rotd50(&x, &y),
                (PairIm::RotD50, ImKind::Sa) => {
                    let r = crate::spectrum::rotd(&x, &y, spec.damping, &[spec.period])
                        .expect("period and damping are checked by the settings");
                    r.rotd50[0].psa_g
                }
            }
        }
    })
}

/// How the fundamental period was found.
#[derive(Debug, Clone, PartialEq)]
pub struct PeriodInfo {
    /// The period \[s\].
    pub period: Real,
    /// The segment (1-based) whose first mode it is.
    pub segment: usize,
    /// `ω_1` of that segment \[rad/s\].
    pub omega: Real,
    /// The period is the whole bridge's (piers or backwalls couple the segments; `segment` is
    /// then 0).
    pub whole_bridge: bool,
}

impl PeriodInfo {
    /// One line for stdout and the report.
    pub fn describe(&self) -> String {
        if self.whole_bridge {
            return format!(
                "T1 = {} s: the first-mode period of the whole bridge (segments, pier caps and \
                 backwalls on the bearings, columns and piles at their initial stiffness; omega1 = \
                 {} rad/s; joints open, no contact, no backfill)",
                crate::output::float_token(self.period),
                crate::output::float_token(self.omega)
            );
        }
        format!(
            "T1 = {} s: the longest first-mode period of the segments on their bearings \
             (segment {}, mode 1, omega1 = {} rad/s; joints open, no contact)",
            crate::output::float_token(self.period),
            self.segment,
            crate::output::float_token(self.omega)
        )
    }
}

/// The bridge's fundamental period. With piers or backwalls, the first-mode period of the whole
/// coupled system ([`BridgeModel::system_frequencies`]). Otherwise the segments are coupled only
/// by contact and restrainers,
/// so with the joints open each segment vibrates on its own bearings; the fundamental period is
/// the longest first-mode period `2π / ω_1` over the segments
/// ([`BridgeModel::segment_frequencies`], initial bearing stiffness). A segment free to slide or
/// spin (`ω_1 = 0`) has no period: an error.
pub fn fundamental_period(model: &BridgeModel) -> Result<PeriodInfo, AssessmentError> {
    let whole = model
        .system_frequencies()
        .map_err(|e| AssessmentError::Model(e.to_string()))?;
    if let Some(om) = whole {
        let w = om.iter().copied().find(|w| *w > 0.0 && w.is_finite());
        let w = w.filter(|_| om[0] > 0.0).ok_or_else(|| {
            AssessmentError::Model(
                "the bridge is free to slide or spin on its bearings and piers (a zero natural \
                 frequency): period_s = \"model\" cannot be used; give period_s in seconds"
                    .into(),
            )
        })?;
        return Ok(PeriodInfo {
            period: 2.0 * std::f64::consts::PI / w,
            segment: 0,
            omega: w,
            whole_bridge: true,
        });
    }
    let om = model
        .segment_frequencies()
        .map_err(|e| AssessmentError::Model(e.to_string()))?;
    let mut best: Option<(usize, Real)> = None;
    for (i, w) in om.iter().enumerate() {
        let w1 = w[0];
        if !(w1.is_finite() && w1 > 0.0) {
            return Err(AssessmentError::Model(format!(
                "segment[{i}] (segment {} from the start) has no first-mode frequency (free to \
                 slide or spin): period_s = \"model\" cannot be used; give period_s in seconds",
                i + 1
            )));
        }
        if best.is_none_or(|(_, b)| w1 < b) {
            best = Some((i, w1));
        }
    }
    let (i, w) = best.ok_or_else(|| AssessmentError::Model("the bridge has no segment".into()))?;
    Ok(PeriodInfo {
        period: 2.0 * std::f64::consts::PI / w,
        segment: i + 1,
        omega: w,
        whole_bridge: false,
    })
}
