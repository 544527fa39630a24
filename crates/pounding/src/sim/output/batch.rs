//! `batch.csv` of `pounding simulate --records` (one row per `(record, scale)` run), for bridges
//! ([`bridge_batch_header`]: one writer, [`bridge_cells`]) and for the two-deck model (its columns,
//! [`BATCH_HEADER`], a translation of the bridge row: [`PAIR_BATCH_COLUMNS`]); of a record-set
//! manifest (`--set`), with the columns of its entries after `record` ([`batch_set_csv`]).

use super::DEG;
use crate::ground_motion::G0;
use crate::ground_motion::set::RecordSet;
use crate::math::Real;
use crate::output::float_token;
use crate::sim::batch::{BatchOutcome, BatchRow};
use crate::sim::bridge::{ABUTMENT_SIDES, BridgeSummary};

mod pair;
use pair::two_deck_batch_csv;
pub use pair::{PAIR_BATCH_COLUMNS, PairBatchCell};

/// CSV field: quoted when it contains a comma, a quote or a line break.
pub(super) fn field(s: &str) -> String {
    crate::output::csv_field(s)
}

/// Header of `batch.csv` (the [`BATCH_TAIL`] columns were appended before `error`, which stays
/// last).
pub const BATCH_HEADER: &str = "index,record,scale,pga_g,pga_mps2,status,impacts,impacting_contacts,\
peak_joint_closing_m,peak_joint_opening_m,peak_rotation1_deg,peak_rotation2_deg,peak_slip_m,\
peak_seat_displacement_m,unseated,unseating_time_s,unseated_end,max_penetration_m,\
energy_balance_error,input_energy_J,viscous_dissipation_J,contact_dissipation_J,duration_s,steps,\
lcp_solves,lcp_failures,peak_contact_force_n,steps_per_contact,newton_failures,warnings,error";

/// Columns appended (before `error`, which stays last) to both `batch.csv` files (two-deck and bridge; empty for the
/// rigid law and for a run that failed): the peak total contact force of a joint or abutment
/// (`summary.json`'s `peak_contact_force_n`; for a bridge the largest over its joints and
/// abutments), the time-step adequacy figure `time_step.steps_per_contact` of `summary.json`
/// (`T_c / Δt`, adequate when ≥ 20) and the steps whose Newton iteration did not converge;
/// then, for every law, `warnings`: the number of warnings of the run (the length of the same
/// single run's `summary.json` `warnings` list: an implausible record PGA, a coarse time step,
/// energy created at a contact).
pub const BATCH_TAIL: &str = "peak_contact_force_n,steps_per_contact,newton_failures,warnings";

/// The [`BATCH_TAIL`] cells of a run: empty for rigid contact (`compliance = false`).
fn tail_cells(
    compliance: bool,
    peak: Option<Real>,
    advice: Option<crate::contact_law::timestep::TimeStepAdvice>,
    newton_failures: usize,
    warnings: usize,
) -> Vec<String> {
    let mut c = if compliance {
        vec![
            opt(peak),
            opt(advice.map(|a| a.steps_per_contact)),
            newton_failures.to_string(),
        ]
    } else {
        vec![String::new(); 3]
    };
    c.push(warnings.to_string());
    c
}

/// A `batch.csv` as cells: the header's names and each row's CSV fields.
struct Grid {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
}

impl Grid {
    /// The index of the column `name` (present: the translations name columns of the layout).
    fn col(&self, name: &str) -> usize {
        let i = self.header.iter().position(|h| h == name);
        i.unwrap_or_else(|| panic!("batch.csv has no column {name}"))
    }

    /// The CSV text: the header, then one line per row.
    fn csv(&self) -> String {
        let mut s = self.header.join(",");
        s.push('\n');
        for r in &self.rows {
            debug_assert_eq!(r.len(), self.header.len());
            s.push_str(&r.join(","));
            s.push('\n');
        }
        s
    }
}

/// The columns of `header` with, for a record `set`, its columns after `record`
/// (`record_y`, `record_x`, `meta_<name>`), and the set's metadata names.
fn with_set(header: &str, set: Option<&RecordSet>) -> (Vec<String>, Vec<String>) {
    let mut h: Vec<String> = header.split(',').map(String::from).collect();
    let Some(set) = set else {
        return (h, Vec::new());
    };
    let meta = set.meta_keys();
    let cols = ["record_y".to_string(), "record_x".to_string()];
    let cols = cols
        .into_iter()
        .chain(meta.iter().map(|k| format!("meta_{k}")));
    h.splice(2..2, cols);
    (h, meta)
}

/// `header`, then one row per run: `index, record, scale`, then for a run that failed
/// `, , error`, empty cells and the message in the last column (`error`); else the PGA in g and
/// m/s², the cells of `cells` and an empty `error`. With a record `set` (the rows' records are
/// its entries, in its order), its columns ([`set_columns`]) follow `record`.
fn grid(
    header: &str,
    rows: &[BatchRow],
    set: Option<&RecordSet>,
    cells: impl Fn(&BatchOutcome, &mut Vec<String>),
) -> Grid {
    let (header, meta) = with_set(header, set);
    let ncols = header.len();
    let rows = rows.iter().map(|r| {
        let mut c: Vec<String> = vec![r.index.to_string(), field(&r.record)];
        if let Some(set) = set {
            c.extend(set_columns(set, &meta, r.record_index));
        }
        c.push(float_token(r.scale));
        match &r.outcome {
            Err(msg) => {
                c.extend(["".into(), "".into(), "error".into()]);
                c.resize(ncols - 1, String::new());
                c.push(field(msg));
            }
            Ok(o) => {
                c.push(float_token(r.pga / G0));
                c.push(float_token(r.pga));
                cells(o, &mut c);
                c.push(String::new());
            }
        }
        c
    });
    Grid {
        rows: rows.collect(),
        header,
    }
}

/// The cells of entry `a` of `set` after `record`: `record_y` (the entry's `x` record, which
/// acts along `Rot(α) ŷ`), `record_x` (a pair's `y` record, along `Rot(α) x̂`; empty for a
/// single record), both as read (the reader's name: the path, or the built-in record's file
/// name), then its metadata under the names `meta` (sorted; empty where it has none).
fn set_columns(set: &RecordSet, meta: &[String], a: usize) -> Vec<String> {
    let e = &set.records[a];
    let mut c = vec![
        field(&e.x.name),
        e.y.as_ref().map_or(String::new(), |y| field(&y.name)),
    ];
    c.extend(meta.iter().map(|k| {
        e.meta
            .iter()
            .find(|(n, _)| n == k)
            .map_or(String::new(), |(_, v)| v.csv_cell())
    }));
    c
}

/// The leading columns of a bridge's `batch.csv`: those of [`BATCH_HEADER`] that keep their
/// meaning for a bridge (joint closing and opening: the largest over the joints; seat
/// displacement: over all seated ends; the governing seated end, the one of the largest ratio of
/// its seat displacement to its own seat length, and that ratio after it), with the dissipation of yielding bearings and the work
/// on restrainers added after the contact dissipation.
const BRIDGE_BATCH_LEAD: &str = "index,record,scale,pga_g,pga_mps2,status,impacts,\
impacting_contacts,peak_joint_closing_m,peak_joint_opening_m,peak_seat_displacement_m,\
governing_seat_end,governing_seat_ratio,unseated,unseating_time_s,unseated_end,max_penetration_m,energy_balance_error,input_energy_J,\
viscous_dissipation_J,contact_dissipation_J,hysteretic_dissipation_J,restrainer_work_J,\
duration_s,steps,lcp_solves,lcp_failures";

/// Per-joint columns of a bridge's `batch.csv` (after `joint<k>_`, `k` 1-based).
const BRIDGE_JOINT_COLS: [&str; 9] = [
    "impacts",
    "peak_closing_m",
    "peak_opening_m",
    "peak_contact_force_n",
    "peak_impulse_ns",
    "restrainer_engagements",
    "restrainer_peak_force_n",
    "unseated",
    "peak_slip_m",
];
/// Per-abutment columns (after `abutment_start_` / `abutment_end_`).
const BRIDGE_ABUTMENT_COLS: [&str; 4] = [
    "impacts",
    "peak_closing_m",
    "peak_contact_force_n",
    "peak_impulse_ns",
];
/// Per-segment columns (after `segment<i>_`, `i` 1-based); the seat ratios are each end's
/// peak seat displacement over its own seat length (`summary.json` `seats[].ratio`).
const BRIDGE_SEGMENT_COLS: [&str; 7] = [
    "peak_displacement_m",
    "final_displacement_m",
    "peak_rotation_deg",
    "peak_bearing_deformation_m",
    "hysteretic_energy_j",
    "start_seat_ratio",
    "end_seat_ratio",
];

/// Per-pier columns (after `pier<k>_`, `k` the joint it carries).
const PIER_COLS: [&str; 4] = [
    "peak_drift_m",
    "residual_drift_m",
    "peak_column_force_n",
    "yielded",
];
/// Per-backwall columns (after `abutment_start_` / `abutment_end_`).
const BACKWALL_COLS: [&str; 3] = ["backwall_peak_m", "backfill_peak_n", "piles_peak_n"];
/// Per-abutment shear-key columns.
const KEY_COLS: [&str; 3] = [
    "shear_key_peak_force_n",
    "shear_key_peak_m",
    "shear_key_yielded",
];

/// Header of a bridge's `batch.csv` for a bridge of `n_segments` segments: the leading columns
/// (as [`BATCH_HEADER`] where the meaning is the same), then per joint `joint<k>_…`, per
/// abutment `abutment_start_…` and `abutment_end_…` (both always, empty where absent), per
/// segment `segment<i>_…` in bridge order (the keys of `summary.json`), in a batch of a bridge
/// with them per pier `pier<k>_…`, per backwall and per shear-key pair `abutment_<side>_…`, the
/// appended
/// [`BATCH_TAIL`] columns, and `error` last.
pub fn bridge_batch_header(n_segments: usize) -> String {
    bridge_header(n_segments, None)
}

/// [`bridge_batch_header`] with, after the segments, the columns of the piers, backwalls and
/// shear keys of `shape` (a run's summary: every run of a batch has the same members).
fn bridge_header(n_segments: usize, shape: Option<&BridgeSummary>) -> String {
    let mut h: Vec<String> = BRIDGE_BATCH_LEAD.split(',').map(String::from).collect();
    for k in 1..n_segments {
        h.extend(BRIDGE_JOINT_COLS.iter().map(|c| format!("joint{k}_{c}")));
    }
    for side in ABUTMENT_SIDES {
        h.extend(
            BRIDGE_ABUTMENT_COLS
                .iter()
                .map(|c| format!("abutment_{side}_{c}")),
        );
    }
    for i in 1..=n_segments {
        h.extend(
            BRIDGE_SEGMENT_COLS
                .iter()
                .map(|c| format!("segment{i}_{c}")),
        );
    }
    if let Some(m) = shape {
        for p in &m.piers {
            h.extend(PIER_COLS.iter().map(|c| format!("pier{}_{c}", p.joint)));
        }
        for (side, a) in ABUTMENT_SIDES.iter().zip(&m.abutments) {
            if a.as_ref().is_some_and(|a| a.backwall.is_some()) {
                h.extend(BACKWALL_COLS.iter().map(|c| format!("abutment_{side}_{c}")));
            }
        }
        for k in &m.shear_keys {
            h.extend(KEY_COLS.iter().map(|c| format!("abutment_{}_{c}", k.side)));
        }
    }
    h.extend(BATCH_TAIL.split(',').map(String::from));
    h.push("error".into());
    h.join(",")
}

/// `Some(x)` as its token, `None` (not applicable: a rigid law's contact force, no restrainer,
/// no unseating) as an empty field.
fn opt(x: Option<Real>) -> String {
    x.map_or(String::new(), float_token)
}

/// The cells of one completed bridge run after `pga_mps2`.
fn bridge_cells(o: &BatchOutcome, c: &mut Vec<String>) {
    let m = &o.summary;
    let e = &m.final_energy;
    let hyst: Real = m.segments.iter().map(|g| g.hysteretic_energy).sum();
    let max_of = |v: Vec<Real>| v.into_iter().reduce(Real::max);
    c.push(format!("{:?}", o.status));
    c.push(m.impacts.to_string());
    c.push(o.impacting_contacts.to_string());
    c.push(opt(max_of(
        m.joints.iter().map(|j| j.peak_closing).collect(),
    )));
    c.push(opt(max_of(
        m.joints.iter().map(|j| j.peak_opening).collect(),
    )));
    c.push(float_token(m.peak_seat_displacement));
    match m.seats.get(m.governing_seat) {
        Some(g) => c.extend([g.end.clone(), float_token(g.ratio)]),
        None => c.extend([String::new(), String::new()]),
    }
    c.push(m.unseated.to_string());
    c.push(opt(m.unseating_time));
    c.push(m.unseated_end.clone().unwrap_or_default());
    for v in [
        m.peak_penetration,
        m.energy_balance_error,
        e.input,
        e.viscous,
        e.contact,
        hyst,
        m.restrainer_work,
        crate::sim::step_time(o.steps, o.dt),
    ] {
        c.push(float_token(v));
    }
    c.push(o.steps.to_string());
    c.push(o.lcp_solves.to_string());
    c.push(o.lcp_failures.to_string());
    for j in &m.joints {
        c.push(j.impacts.to_string());
        c.push(float_token(j.peak_closing));
        c.push(float_token(j.peak_opening));
        c.push(opt(j.peak_contact_force));
        c.push(float_token(j.peak_impulse));
        c.push(j.restrainer_engagements.to_string());
        c.push(opt(j.restrainer_peak_force));
        c.push(j.unseated.to_string());
        c.push(float_token(j.peak_slip));
    }
    for a in &m.abutments {
        match a {
            Some(a) => {
                c.push(a.impacts.to_string());
                c.push(float_token(a.peak_closing));
                c.push(opt(a.peak_contact_force));
                c.push(float_token(a.peak_impulse));
            }
            None => c.extend(BRIDGE_ABUTMENT_COLS.iter().map(|_| String::new())),
        }
    }
    for (i, g) in m.segments.iter().enumerate() {
        for v in [
            g.peak_displacement,
            g.final_displacement,
            g.peak_rotation * DEG,
            g.peak_bearing_deformation,
            g.hysteretic_energy,
        ] {
            c.push(float_token(v));
        }
        for face in ["start", "end"] {
            let name = format!("segment{}-{face}", i + 1);
            let seat = m.seats.iter().find(|s| s.end == name);
            c.push(seat.map_or(String::new(), |s| float_token(s.ratio)));
        }
    }
    for p in &m.piers {
        c.push(float_token(p.peak_drift_magnitude));
        c.push(float_token(p.residual_drift[0].hypot(p.residual_drift[1])));
        c.push(float_token(p.peak_column_force));
        c.push(p.yielded.to_string());
    }
    for w in m
        .abutments
        .iter()
        .flatten()
        .filter_map(|a| a.backwall.as_ref())
    {
        c.push(float_token(w.peak_displacement));
        c.push(opt(w.peak_backfill_force));
        c.push(opt(w.peak_pile_force));
    }
    for k in &m.shear_keys {
        c.push(float_token(k.peak_force));
        c.push(float_token(k.peak_deformation));
        c.push(k.yielded.to_string());
    }
    let peaks: Vec<Option<Real>> = (m.joints.iter().map(|j| j.peak_contact_force))
        .chain(m.abutments.iter().flatten().map(|a| a.peak_contact_force))
        .collect();
    let compliance = peaks.iter().any(Option::is_some);
    let peak = peaks.into_iter().flatten().reduce(Real::max);
    c.extend(tail_cells(
        compliance,
        peak,
        o.time_step_advice,
        o.newton_failures,
        o.warnings,
    ));
}

/// A bridge's `batch.csv` as cells ([`bridge_batch_header`], then one row per run; a run that failed has
/// `status = error`, empty cells and its message in `error`). Absent or not-applicable items
/// (an abutment the bridge does not have, the contact force of the rigid law, a joint without a
/// restrainer, no unseating, no joint at all for one segment) are empty fields; a value that is
/// not a number is `nan` (the project's CSV tokens, [`float_token`]).
fn bridge_grid(n_segments: usize, rows: &[BatchRow], set: Option<&RecordSet>) -> Grid {
    let shape = rows
        .iter()
        .find_map(|r| r.outcome.as_ref().ok().map(|o| &o.summary));
    grid(&bridge_header(n_segments, shape), rows, set, bridge_cells)
}

/// `batch.csv` of a batch in `layout`: the two-deck model's columns ([`BATCH_HEADER`]) or a
/// bridge's of `n_segments` segments ([`bridge_batch_header`]); one row per run (a run that
/// failed has `status = error` and its message in `error`).
pub fn batch_csv(layout: super::Layout, n_segments: usize, rows: &[BatchRow]) -> String {
    match layout {
        super::Layout::TwoDecks => two_deck_batch_csv(rows, None),
        super::Layout::Bridge => bridge_grid(n_segments, rows, None).csv(),
    }
}

/// `batch.csv` of a batch over the entries of the record set `set`
/// ([`crate::sim::batch::BatchRecord::of_set`], in its order): the columns of [`batch_csv`] with,
/// after `record` (the entry's id), `record_y` and `record_x` (the records as read: the entry's
/// `x` acting along y, a pair's `y` along x; empty for a single record) and its metadata as
/// `meta_<name>` (sorted names; empty where an entry has none).
pub fn batch_set_csv(
    layout: super::Layout,
    n_segments: usize,
    rows: &[BatchRow],
    set: &RecordSet,
) -> String {
    match layout {
        super::Layout::TwoDecks => two_deck_batch_csv(rows, Some(set)),
        super::Layout::Bridge => bridge_grid(n_segments, rows, Some(set)).csv(),
    }
}
