//! The summary quantities whose discretisation error is estimated: the bridge's governing peaks
//! (the largest over its sites, which decide a verdict) and each site's own.

use crate::math::Real;
use crate::sim::bridge::BridgeSolution;

/// What a quantity measures: its unit and the scale below which relative errors are taken
/// against the scale instead of the value ([`Kind::floor`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A displacement, closing, opening or slip \[m\].
    Length,
    /// A ratio (a seat displacement over its seat length) \[-\].
    Ratio,
    /// A rotation \[deg\].
    Angle,
    /// A force \[N\].
    Force,
    /// An impulse \[N s\].
    Impulse,
    /// A count (impacts).
    Count,
}

impl Kind {
    /// The unit in the files.
    pub fn unit(self) -> &'static str {
        match self {
            Kind::Length => "m",
            Kind::Ratio => "-",
            Kind::Angle => "deg",
            Kind::Force => "N",
            Kind::Impulse => "N s",
            Kind::Count => "count",
        }
    }

    /// The smallest value a relative error is taken against: 1 mm, a ratio of 0.001, 0.001°,
    /// 1 kN, 1 N s, one impact. A peak opening of 1 µm whose estimate is 0.5 µm is not a 50 %
    /// error of anything an engineer reads: it is 0.05 % of a millimetre.
    pub fn floor(self) -> Real {
        match self {
            Kind::Length => 1e-3,
            Kind::Ratio => 1e-3,
            Kind::Angle => 1e-3,
            Kind::Force => 1e3,
            Kind::Impulse => 1.0,
            Kind::Count => 1.0,
        }
    }
}

/// A named summary quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Quantity {
    /// `peak_seat_ratio`, `max_joint_closing_m`, `joint2.peak_opening_m`, `segment1-end.seat_ratio`, …
    pub name: String,
    /// Its unit ([`Kind::unit`]).
    pub unit: &'static str,
    /// What it measures.
    pub kind: Kind,
    /// A governing quantity: the largest over the bridge's sites of a peak that decides a
    /// verdict (seat ratio, joint closing and opening, abutment closing, bearing deformation,
    /// rotation, contact force, pier drift). A tolerance applies to these.
    pub governing: bool,
}

/// The quantities of a run and their values, governing first, then per site in bridge order.
pub fn quantities(sol: &BridgeSolution) -> Vec<(Quantity, Real)> {
    let s = &sol.summary;
    let mut out = Vec::new();
    let mut push = |name: String, kind: Kind, governing: bool, v: Real| {
        out.push((
            Quantity {
                name,
                unit: kind.unit(),
                kind,
                governing,
            },
            v,
        ))
    };
    let max = |it: &mut dyn Iterator<Item = Real>| it.fold(0.0, Real::max);
    let g = |n: &str| n.to_string();
    push(g("peak_seat_ratio"), Kind::Ratio, true, s.peak_seat_ratio);
    push(
        g("peak_seat_displacement_m"),
        Kind::Length,
        false,
        s.peak_seat_displacement,
    );
    if !s.joints.is_empty() {
        let closing = max(&mut s.joints.iter().map(|j| j.peak_closing));
        let opening = max(&mut s.joints.iter().map(|j| j.peak_opening));
        push(g("max_joint_closing_m"), Kind::Length, true, closing);
        push(g("max_joint_opening_m"), Kind::Length, true, opening);
    }
    if s.abutments.iter().any(Option::is_some) {
        let closing = max(&mut s.abutments.iter().flatten().map(|a| a.peak_closing));
        push(g("max_abutment_closing_m"), Kind::Length, true, closing);
    }
    let bearing = max(&mut s.segments.iter().map(|x| x.peak_bearing_deformation));
    push(g("max_bearing_deformation_m"), Kind::Length, true, bearing);
    let rotation = max(&mut s.segments.iter().map(|x| x.peak_rotation.to_degrees()));
    push(g("max_rotation_deg"), Kind::Angle, true, rotation);
    let forces: Vec<Real> = s
        .joints
        .iter()
        .filter_map(|j| j.peak_contact_force)
        .chain(
            s.abutments
                .iter()
                .flatten()
                .filter_map(|a| a.peak_contact_force),
        )
        .collect();
    if !forces.is_empty() {
        let f = max(&mut forces.into_iter());
        push(g("max_contact_force_n"), Kind::Force, true, f);
    }
    if !s.piers.is_empty() {
        let drift = max(&mut s.piers.iter().map(|p| p.peak_drift_magnitude));
        push(g("max_pier_drift_m"), Kind::Length, true, drift);
    }
    push(g("impacts"), Kind::Count, false, s.impacts as Real);
    for (k, j) in s.joints.iter().enumerate() {
        let n = |q: &str| format!("joint{}.{q}", k + 1);
        push(n("peak_closing_m"), Kind::Length, false, j.peak_closing);
        push(n("peak_opening_m"), Kind::Length, false, j.peak_opening);
        push(n("peak_slip_m"), Kind::Length, false, j.peak_slip);
        push(n("peak_impulse_ns"), Kind::Impulse, false, j.peak_impulse);
        if let Some(f) = j.peak_contact_force {
            push(n("peak_contact_force_n"), Kind::Force, false, f);
        }
        if let Some(f) = j.restrainer_peak_force {
            push(n("restrainer_peak_force_n"), Kind::Force, false, f);
        }
        push(n("impacts"), Kind::Count, false, j.impacts as Real);
    }
    for (a, side) in s.abutments.iter().zip(["start", "end"]) {
        let Some(a) = a else { continue };
        let n = |q: &str| format!("abutment-{side}.{q}");
        push(n("peak_closing_m"), Kind::Length, false, a.peak_closing);
        push(n("peak_impulse_ns"), Kind::Impulse, false, a.peak_impulse);
        if let Some(f) = a.peak_contact_force {
            push(n("peak_contact_force_n"), Kind::Force, false, f);
        }
        push(n("impacts"), Kind::Count, false, a.impacts as Real);
    }
    for (i, x) in s.segments.iter().enumerate() {
        let n = |q: &str| format!("segment{}.{q}", i + 1);
        push(
            n("peak_displacement_m"),
            Kind::Length,
            false,
            x.peak_displacement,
        );
        push(
            n("peak_rotation_deg"),
            Kind::Angle,
            false,
            x.peak_rotation.to_degrees(),
        );
        push(
            n("peak_bearing_deformation_m"),
            Kind::Length,
            false,
            x.peak_bearing_deformation,
        );
    }
    for seat in &s.seats {
        push(
            format!("{}.seat_ratio", seat.end),
            Kind::Ratio,
            false,
            seat.ratio,
        );
    }
    for p in &s.piers {
        let n = |q: &str| format!("pier{}.{q}", p.joint);
        push(
            n("peak_drift_m"),
            Kind::Length,
            false,
            p.peak_drift_magnitude,
        );
        push(
            n("peak_column_force_n"),
            Kind::Force,
            false,
            p.peak_column_force,
        );
    }
    for k in &s.shear_keys {
        let n = |q: &str| format!("shear-keys-{}.{q}", k.side);
        push(n("peak_force_n"), Kind::Force, false, k.peak_force);
        push(
            n("peak_deformation_m"),
            Kind::Length,
            false,
            k.peak_deformation,
        );
    }
    out
}
