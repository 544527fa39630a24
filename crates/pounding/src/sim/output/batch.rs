//! `batch.csv` of `pounding simulate --records` (one row per `(record, scale)` run).

use super::DEG;
use crate::ground_motion::G0;
use crate::math::Real;
use crate::output::float_token;
use crate::sim::SEAT_ENDS;
use crate::sim::batch::BatchRow;

/// CSV field: quoted when it contains a comma, a quote or a line break.
fn field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Header of `batch.csv`.
pub const BATCH_HEADER: &str = "index,record,scale,pga_g,pga_mps2,status,impacts,impacting_contacts,\
peak_joint_closing_m,peak_joint_opening_m,peak_rotation1_deg,peak_rotation2_deg,peak_slip_m,\
peak_seat_displacement_m,unseated,unseating_time_s,unseated_end,max_penetration_m,\
energy_balance_error,input_energy_J,viscous_dissipation_J,contact_dissipation_J,duration_s,steps,\
lcp_solves,lcp_failures,error";

/// `batch.csv`: [`BATCH_HEADER`], then one row per run (a run that failed has `status = error`
/// and its message in `error`).
pub fn batch_csv(rows: &[BatchRow]) -> String {
    let mut s = String::from(BATCH_HEADER);
    s.push('\n');
    let ncols = BATCH_HEADER.split(',').count();
    for r in rows {
        let mut c: Vec<String> = vec![r.index.to_string(), field(&r.record), float_token(r.scale)];
        match &r.outcome {
            Err(msg) => {
                c.extend(["".into(), "".into(), "error".into()]);
                c.resize(ncols - 1, String::new());
                c.push(field(msg));
            }
            Ok(o) => {
                let m = &o.summary;
                c.push(float_token(r.pga / G0));
                c.push(float_token(r.pga));
                c.push(format!("{:?}", o.status));
                c.push(m.impacts.to_string());
                c.push(m.impacting_contacts.to_string());
                for v in [
                    m.peak_joint_closing,
                    m.peak_joint_opening,
                    m.peak_rotation[0] * DEG,
                    m.peak_rotation[1] * DEG,
                    m.peak_slip,
                    m.peak_seat_displacement,
                ] {
                    c.push(float_token(v));
                }
                c.push(m.unseated.to_string());
                c.push(m.unseating_time.map_or(String::new(), float_token));
                c.push(m.unseated_end.map_or("", |i| SEAT_ENDS[i]).to_string());
                let e = &m.final_energy;
                for v in [
                    m.max_penetration,
                    m.energy_balance_error,
                    e.input,
                    e.viscous,
                    e.contact,
                    o.steps as Real * o.dt,
                ] {
                    c.push(float_token(v));
                }
                c.push(o.steps.to_string());
                c.push(o.lcp_solves.to_string());
                c.push(o.lcp_failures.to_string());
                c.push(String::new());
            }
        }
        debug_assert_eq!(c.len(), ncols);
        s.push_str(&c.join(","));
        s.push('\n');
    }
    s
}
