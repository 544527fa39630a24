//! The two-deck files are translations of the bridge files of the same run (issue 22): every
//! cell of a two-deck `batch.csv` row and every value of its `history.csv` equals the bridge
//! cell or column it names ([`PAIR_BATCH_COLUMNS`], [`PAIR_HISTORY_COLUMNS`]), so the two cannot
//! drift; the bridge files' joint slip columns peak at `summary.json`'s `peak_slip_m`.

use pounding::ground_motion::Record;
use pounding::output::float_token;
use pounding::sim::batch::{BatchRecord, BatchRow, BatchShard, run_batch};
use pounding::sim::bridge::BridgeSolution;
use pounding::sim::output::{
    BATCH_HEADER, History, Layout, PAIR_BATCH_COLUMNS, PAIR_HISTORY_COLUMNS, PairBatchCell,
    PairHistoryColumn, batch_csv,
};
use pounding::sim::scenario::Scenario;
use pounding::sim::table::Table;

/// Default (curved) decks, short seats (some runs unseat), oblique incidence (the decks rotate
/// and slide along the joint).
const PAIR: &str = r#"
[joint]
gap = 0.01
seat_length = 0.06
[ground_motion]
incidence_deg = 30.0
[time]
dt = 2e-3
duration = 2.5
"#;

/// Three synthetic records (m/s²: decaying sines) and one that cannot be read.
fn records() -> Vec<BatchRecord> {
    let rec = |f: f64, a: f64| {
        let v = (0..=250).map(|k| {
            let t = k as f64 * 0.01;
            a * (2.0 * std::f64::consts::PI * f * t).sin() * (-0.3 * t).exp()
        });
        Record::uniform("r", 0.01, v.collect()).unwrap()
    };
    let mut r: Vec<BatchRecord> = [(1.0, 3.0), (1.7, 2.5), (0.8, 4.0)]
        .iter()
        .enumerate()
        .map(|(i, &(f, a))| BatchRecord {
            name: format!("r{i}"),
            record: Ok(rec(f, a)),
            along_x: None,
            supports: Vec::new(),
        })
        .collect();
    r.insert(
        1,
        BatchRecord {
            name: "broken".into(),
            record: Err("cannot read broken".into()),
            along_x: None,
            supports: Vec::new(),
        },
    );
    r
}

fn batch(text: &str) -> Vec<BatchRow> {
    let setup = Scenario::from_toml(text, "pair.toml")
        .unwrap()
        .for_batch()
        .build()
        .unwrap();
    let recs = records();
    run_batch(
        &setup.problem,
        &setup.settings,
        &recs,
        &[0.5, 2.0, 4.0],
        BatchShard::ALL,
        &|_| {},
    )
    .unwrap()
}

/// The header and rows of a CSV without quoted fields.
fn cells(csv: &str) -> (Vec<&str>, Vec<Vec<&str>>) {
    let mut lines = csv.lines();
    let head = lines.next().unwrap().split(',').collect();
    (head, lines.map(|l| l.split(',').collect()).collect())
}

/// The two-deck name of a seated end of the two-deck bridge (segment `j` is deck `j`; its end on
/// the joint is `deck<j>-joint`, the other `deck<j>-far`).
fn pair_end(bridge_end: &str) -> &'static str {
    match bridge_end {
        "segment1-start" => "deck1-far",
        "segment1-end" => "deck1-joint",
        "segment2-start" => "deck2-joint",
        "segment2-end" => "deck2-far",
        e => panic!("no seated end {e} on two segments"),
    }
}

#[test]
fn two_deck_batch_rows_are_their_bridge_rows_translated_cell_by_cell() {
    let names: Vec<&str> = PAIR_BATCH_COLUMNS.iter().map(|c| c.0).collect();
    assert_eq!(names.join(","), BATCH_HEADER);
    // rigid with an abutment beyond deck 1; hertz (two-deck abutments are rigid-only)
    for law in ["[abutments]\ngap1 = 0.02\n", "[contact]\nlaw = \"hertz\"\n"] {
        let rows = batch(&format!("{PAIR}{law}"));
        let rigid = law.starts_with("[abutments]");
        let pair = batch_csv(Layout::TwoDecks, 2, &rows);
        let bridge = batch_csv(Layout::Bridge, 2, &rows);
        let (ph, prows) = cells(&pair);
        let (bh, brows) = cells(&bridge);
        assert_eq!(ph.join(","), BATCH_HEADER);
        let bcol = |n: &str| bh.iter().position(|h| *h == n).unwrap();
        let (mut unseated, mut slid) = (false, false);
        for ((r, p), b) in rows.iter().zip(&prows).zip(&brows) {
            assert_eq!((p.len(), b.len()), (ph.len(), bh.len()));
            for (i, (name, cell)) in PAIR_BATCH_COLUMNS.iter().enumerate() {
                assert_eq!(ph[i], *name);
                let want = match cell {
                    PairBatchCell::Bridge(c) => b[bcol(c)].to_string(),
                    PairBatchCell::UnseatedEnd => match b[bcol("unseated_end")] {
                        "" => String::new(),
                        e => pair_end(e).to_string(),
                    },
                };
                assert_eq!(p[i], want, "{name} of row {}", r.index);
            }
            let Ok(o) = &r.outcome else {
                assert_eq!(p[5], "error");
                assert!(p.last().unwrap().contains("cannot read broken"));
                continue;
            };
            // the slip columns are the summary's peak slip
            let s = &o.summary;
            let slip = float_token(s.joints[0].peak_slip);
            assert_eq!(b[bcol("joint1_peak_slip_m")], slip);
            assert_eq!(
                p[ph.iter().position(|h| *h == "peak_slip_m").unwrap()],
                slip
            );
            slid |= s.joints[0].peak_slip > 0.0;
            unseated |= s.unseated_end.is_some();
            // the joint's force, not the largest over joint and abutment
            let force = b[bcol("joint1_peak_contact_force_n")];
            assert_eq!(force.is_empty(), rigid);
        }
        assert!(slid, "the decks slide along the joint");
        assert!(unseated, "some run unseats: the end's name is translated");
        assert!(rows.iter().any(|r| r.outcome.is_err()));
    }
}

/// The two-deck history of `sol` and its bridge history, as tables.
fn histories(setup: &pounding::sim::scenario::SimSetup, sol: &BridgeSolution) -> [Table; 2] {
    let ab = setup
        .problem
        .model
        .abutments
        .each_ref()
        .map(Option::is_some);
    let g = &setup.problem.ground;
    [Layout::TwoDecks, Layout::Bridge].map(|l| History::new(l, sol, g, ab).table())
}

fn column<'t>(t: &'t Table, name: &str) -> Option<(usize, &'t pounding::sim::table::Column)> {
    t.columns.iter().enumerate().find(|(_, c)| c.name == name)
}

#[test]
fn two_deck_history_is_its_bridge_history_translated_column_by_column() {
    let cases = [
        "[time]\nduration = 1.0\nhistory_every = 3\n",
        "[time]\nduration = 1.0\nprojection = true\n[abutments]\ngap1 = 0.01\ngap2 = 0.02\n",
        "[contact]\nlaw = \"hertz\"\n[time]\nduration = 1.0\n[ground_motion]\nincidence_deg = 20.0\n",
    ];
    for text in cases {
        let setup = Scenario::from_toml(text, "h.toml")
            .unwrap()
            .build()
            .unwrap();
        let sol = setup.run().unwrap();
        let [pair, bridge] = histories(&setup, &sol);
        let (np, nb) = (pair.columns.len(), bridge.columns.len());
        assert_eq!(pair.rows(), bridge.rows());
        let mut names = Vec::new();
        for col in PAIR_HISTORY_COLUMNS {
            match col {
                PairHistoryColumn::Renamed(p, b) => {
                    // present exactly when the bridge writes it, with its unit and bits
                    let Some((j, bc)) = column(&bridge, b) else {
                        assert!(column(&pair, p).is_none(), "{p} without {b}");
                        continue;
                    };
                    let (i, pc) = column(&pair, p).unwrap();
                    assert_eq!(pc.unit, bc.unit);
                    for r in 0..pair.rows() {
                        let (x, y) = (pair.values[r * np + i], bridge.values[r * nb + j]);
                        assert_eq!(x.to_bits(), y.to_bits(), "{p} <- {b}, row {r}");
                    }
                    names.push(p.to_string());
                }
                PairHistoryColumn::CandidateGaps => {
                    names.extend(
                        ["deck1-inner", "deck1-outer", "deck2-inner", "deck2-outer"]
                            .map(|c| format!("gap_{c}")),
                    );
                }
                PairHistoryColumn::EndForces => {
                    let Some((j, _)) = column(&bridge, "joint1_force") else {
                        continue;
                    };
                    let (i, _) = column(&pair, "contact_force_xplus").unwrap();
                    for r in 0..pair.rows() {
                        let f = &pair.values[r * np + i..r * np + i + 2];
                        assert_eq!((f[0] + f[1]).to_bits(), bridge.values[r * nb + j].to_bits());
                    }
                    names.extend(["contact_force_xplus", "contact_force_xminus"].map(String::from));
                }
            }
        }
        // exactly these columns, in the map's order
        let got: Vec<&str> = pair.columns.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(got, names, "{text}");
        let slip = column(&bridge, "joint1_slip").unwrap().0;
        assert!((0..bridge.rows()).any(|r| bridge.values[r * nb + slip] != 0.0));
    }
}

#[test]
fn bridge_joint_slip_columns_peak_at_the_summary_peak_slip() {
    for every in [1, 4] {
        // straight, curved, straight; oblique incidence: both joints slide
        let bridge = crate::sim_bridge_batch::BRIDGE;
        let text = format!("{bridge}duration = 3.0\nhistory_every = {every}\n");
        let setup = Scenario::from_toml(&text, "b.toml")
            .unwrap()
            .build_bridge()
            .unwrap();
        let sol = setup.run().unwrap();
        let h = History::new(Layout::Bridge, &sol, &setup.problem.ground, [false; 2]).table();
        let observed = sol.tables().into_iter().find(|t| t.name == "joint_slip");
        let observed = observed.unwrap();
        for (k, j) in sol.summary.joints.iter().enumerate() {
            let name = format!("joint{}_slip_m", k + 1);
            let v = h.column(&name).unwrap();
            // the same series as joint_slip.csv
            assert_eq!(v, observed.column(&name).unwrap(), "{name}");
            let peak = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            assert!(peak > 1e-6, "{name} slides");
            // the summary's peak is over every step, the history's rows every `every` steps
            if every == 1 {
                assert_eq!(peak, j.peak_slip, "{name}");
            } else {
                assert!(peak <= j.peak_slip && peak > 0.5 * j.peak_slip, "{name}");
            }
        }
    }
}
