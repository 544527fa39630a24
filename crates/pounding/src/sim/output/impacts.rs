//! `impacts.csv` (a [`TypedTable`]: numbers, counts and names in columns of their own types)
//! and the run warnings of a run, in the layout of its scenario ([`Layout`]): a bridge names
//! each contact by its site (`joint<k>`, `abutment-start`/`-end`) and its corner in two
//! columns; the two-deck model by its own contact names (`deck1-inner`, …, `abutment1-c0`, …)
//! in one.

use super::{ESTIMATE_COLUMNS, Layout, PULSE_COLUMNS, RunWarning, energy_warnings, rigid_estimate};
use crate::math::Real;
use crate::sim::bridge::{ABUTMENT_SIDES, BridgeModel, BridgeSolution};
use crate::sim::table::{Column, ColumnData, TypedTable};
use crate::sim::{ImpactRecord, JointContact, SimContact};

/// Where a contact is: `joint<k>` (1-based) or `abutment-start` / `abutment-end`.
fn site_name(c: &SimContact, site: usize) -> String {
    match c {
        SimContact::Joint(_) => format!("joint{}", site + 1),
        SimContact::Abutment { .. } => format!("abutment-{}", ABUTMENT_SIDES[site]),
    }
}

/// The contact's corner within its site: the joint candidate (`deck1-inner` … with segment `k`
/// as deck 1) or the abutment corner `c0` / `c1` of the segment's outer face.
fn corner_name(c: &SimContact) -> &'static str {
    match c {
        SimContact::Joint(case) => case.name(),
        SimContact::Abutment { corner: 0, .. } => "c0",
        SimContact::Abutment { .. } => "c1",
    }
}

/// The restitution coefficient `ε_N` of the site of an impact record.
pub(super) fn site_restitution(m: &BridgeModel, r: &ImpactRecord) -> Real {
    match r.contact {
        SimContact::Joint(_) => m.joints.get(r.site).map_or(Real::NAN, |j| j.restitution),
        SimContact::Abutment { .. } => m.abutments[r.site].map_or(Real::NAN, |a| a.restitution),
    }
}

/// Whether some contact site of the bridge is rigid, and whether some has a compliance law
/// (a bridge without any site counts as rigid).
pub(super) fn site_kinds(m: &BridgeModel) -> (bool, bool) {
    let contacts = m
        .joints
        .iter()
        .map(|j| j.contact)
        .chain(m.abutments.iter().flatten().map(|a| a.contact));
    let (mut rigid, mut compliant) = (false, false);
    for c in contacts {
        match c {
            JointContact::Rigid => rigid = true,
            JointContact::Compliance(_) => compliant = true,
        }
    }
    (rigid || !compliant, compliant)
}

/// How a warning names the contact of a record: as `impacts.csv` does (the bridge's
/// `site/contact`).
fn contact_name(layout: Layout, r: &ImpactRecord) -> String {
    match layout {
        Layout::TwoDecks => r.contact.name().to_string(),
        Layout::Bridge => format!(
            "{}/{}",
            site_name(&r.contact, r.site),
            corner_name(&r.contact)
        ),
    }
}

/// The run's warnings ([`energy_warnings`]), contacts named as in `impacts.csv`.
pub fn run_warnings(layout: Layout, sol: &BridgeSolution) -> Vec<RunWarning> {
    let rigid = sol.time_step_advice.is_none() && sol.impacts.iter().all(|r| r.pulse.is_none());
    energy_warnings(&sol.impacts, rigid, |r| contact_name(layout, r))
}

/// What a numeric column of `impacts.csv` reads from a record.
type RecordValue = fn(&ImpactRecord) -> Real;

/// The numeric columns of every `impacts.csv` after `mode` (name, unit, value of a record):
/// relative velocities before and after, impulses, dissipated energy.
const IMPACT_NUMBERS: [(&str, &str, RecordValue); 7] = [
    ("gamma_n_pre", "mps", |r| r.gamma_n_pre),
    ("gamma_t_pre", "mps", |r| r.gamma_t_pre),
    ("gamma_n_post", "mps", |r| r.gamma_n_post),
    ("gamma_t_post", "mps", |r| r.gamma_t_post),
    ("impulse_n", "Ns", |r| r.impulse_n),
    ("impulse_t", "Ns", |r| r.impulse_t),
    ("energy_dissipated", "J", |r| r.energy_dissipated),
];

/// `impacts.csv` as a [`TypedTable`]: one row per impacting contact; `impact` (int), `t_s`,
/// where (text: the two-deck model's `contact`; a bridge's `site` and `contact`), `mode` (text),
/// relative velocities before and after, impulses, dissipated energy, then [`PULSE_COLUMNS`]
/// (compliance laws) or [`ESTIMATE_COLUMNS`] (rigid law, with each site's `ε_N`), both for a
/// bridge mixing the two (NaN where a record has none). `model` is the bridge that ran (the
/// two-deck model's [`BridgeModel::from_pair`]).
pub fn impacts_table(layout: Layout, model: &BridgeModel, sol: &BridgeSolution) -> TypedTable {
    let (rigid, compliant) = site_kinds(model);
    let imp = &sol.impacts;
    let real = |f: &dyn Fn(&ImpactRecord) -> Real| ColumnData::Real(imp.iter().map(f).collect());
    let text = |f: &dyn Fn(&ImpactRecord) -> String| ColumnData::Text(imp.iter().map(f).collect());
    let mut t = TypedTable::new("impacts");
    // an impact number is a step count: far below 2^63
    let numbers = imp
        .iter()
        .map(|r| i64::try_from(r.impact).unwrap_or(i64::MAX));
    t.push(
        Column::new("impact", ""),
        ColumnData::Int(numbers.collect()),
    );
    t.push(Column::new("t", "s"), real(&|r| r.time));
    if layout == Layout::Bridge {
        t.push(
            Column::new("site", ""),
            text(&|r| site_name(&r.contact, r.site)),
        );
        t.push(
            Column::new("contact", ""),
            text(&|r| corner_name(&r.contact).into()),
        );
    } else {
        t.push(
            Column::new("contact", ""),
            text(&|r| r.contact.name().into()),
        );
    }
    t.push(Column::new("mode", ""), text(&|r| r.mode.name().into()));
    for (name, unit, f) in IMPACT_NUMBERS {
        t.push(Column::new(name, unit), real(&f));
    }
    if compliant {
        let pulse = |r: &ImpactRecord| {
            r.pulse.map_or([Real::NAN; 3], |p| {
                [p.peak_force, p.duration, p.max_penetration]
            })
        };
        for (i, (name, unit)) in PULSE_COLUMNS.iter().enumerate() {
            t.push(Column::new(*name, unit), real(&|r| pulse(r)[i]));
        }
    }
    if rigid {
        // a mixed bridge: the estimate of a rigid record only (a compliance one has its pulse)
        let estimate = |r: &ImpactRecord| match r.pulse {
            Some(_) if compliant => [Real::NAN; 2],
            _ => {
                let e = rigid_estimate(r, site_restitution(model, r));
                [e.peak_force, e.contact_time]
            }
        };
        let values: Vec<[Real; 2]> = imp.iter().map(estimate).collect();
        for (i, (name, unit)) in ESTIMATE_COLUMNS.iter().enumerate() {
            let column = ColumnData::Real(values.iter().map(|v| v[i]).collect());
            t.push(Column::new(*name, unit), column);
        }
    }
    t
}

/// The text of `impacts.csv` ([`impacts_table`], by the one CSV writer).
pub fn impacts_csv(layout: Layout, model: &BridgeModel, sol: &BridgeSolution) -> String {
    impacts_table(layout, model, sol).csv()
}
