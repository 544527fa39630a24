//! `impacts.csv` and the run warnings of a run, in the layout of its scenario ([`Layout`]): a
//! bridge names each contact by its site (`joint<k>`, `abutment-start`/`-end`) and its corner
//! in two columns; the two-deck model by its own contact names (`deck1-inner`, …,
//! `abutment1-c0`, …) in one.

use super::{
    ESTIMATE_COLUMNS, Layout, PULSE_COLUMNS, RunWarning, energy_warnings, impact_numbers,
    pulse_cells,
};
use crate::math::Real;
use crate::output::float_token;
use crate::sim::bridge::{ABUTMENT_SIDES, BridgeModel, BridgeSolution};
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

/// `impacts.csv`: one row per impacting contact (time, where, mode, relative velocities before
/// and after, impulses, dissipated energy), then [`PULSE_COLUMNS`] (compliance laws) or
/// [`ESTIMATE_COLUMNS`] (rigid law, with each site's `ε_N`), both for a bridge mixing the two
/// (`nan` where a record has none). `model` is the bridge that ran (the two-deck model's
/// [`BridgeModel::from_pair`]).
pub fn impacts_csv(layout: Layout, model: &BridgeModel, sol: &BridgeSolution) -> String {
    let (rigid, compliant) = site_kinds(model);
    let columns = match (rigid, compliant) {
        (true, false) => ESTIMATE_COLUMNS.to_string(),
        (false, true) => PULSE_COLUMNS.to_string(),
        _ => format!("{PULSE_COLUMNS},{ESTIMATE_COLUMNS}"),
    };
    let place = match layout {
        Layout::TwoDecks => "contact",
        Layout::Bridge => "site,contact",
    };
    let mut s = format!(
        "impact,t_s,{place},mode,gamma_n_pre_mps,gamma_t_pre_mps,gamma_n_post_mps,\
         gamma_t_post_mps,impulse_n_Ns,impulse_t_Ns,energy_dissipated_J,{columns}\n"
    );
    for r in &sol.impacts {
        let f = impact_numbers(r);
        let eps = site_restitution(model, r);
        let p = match (rigid, compliant) {
            (true, false) => pulse_cells(r, true, eps),
            (false, true) => pulse_cells(r, false, eps),
            // a mixed bridge: the pulse of a compliance record, the estimate of a rigid one
            _ if r.pulse.is_some() => format!("{},nan,nan", pulse_cells(r, false, eps)),
            _ => format!("nan,nan,nan,{}", pulse_cells(r, true, eps)),
        };
        let place = match layout {
            Layout::TwoDecks => r.contact.name().to_string(),
            Layout::Bridge => format!(
                "{},{}",
                site_name(&r.contact, r.site),
                corner_name(&r.contact)
            ),
        };
        s.push_str(&format!(
            "{},{},{place},{},{f},{p}\n",
            r.impact,
            float_token(r.time),
            r.mode.name(),
        ));
    }
    s
}
