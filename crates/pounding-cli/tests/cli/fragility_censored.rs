//! `pounding fragility` on truncated IDA (`scales`): records that never exceed the limit state
//! within the scales (right-censored) or exceed already at the first scale (left-censored) give
//! a finite fit by the censored MLE (`mle_censored_ida`), exit 0; a limit state without censoring
//! keeps the method of moments. The fit is recomputed from `runs.csv` with the documented
//! interpolation and bounds.

use crate::{run_capture, scratch_dir};
use pounding::fragility::{CensoredIdaData, IdaRecord, Method, fit_ida_censored};

/// The study on the bridge of `cli::fragility` (two segments, 2 s runs): six synthetic records at
/// PGA 0.3 g scaled by 0.25…2; `impulse` (6e5 N s) is never reached by two records, `low`
/// (1e5 N s) is exceeded by one at the first scale, `mid` (2e5 N s) is crossed between scales by
/// every record.
const STUDY: &str = r#"[fragility]
records = "set.toml"
im = "pga"
scales = [0.25, 0.5, 1.0, 2.0]
bootstrap = 50
seed = 3

[[limit_state]]
name = "impulse"
kind = "joint_force"
capacity_ns = 6.0e5

[[limit_state]]
name = "low"
kind = "joint_force"
capacity_ns = 1.0e5

[[limit_state]]
name = "mid"
kind = "joint_force"
capacity_ns = 2.0e5
"#;

const SET: &str = "[synth]\ncount = 6\nseed = 1\ndt = 0.01\nduration = 2.0\npga_g = 0.3\n";

/// The IDA records of limit state `ls` from `runs.csv` (rows by record, scales increasing):
/// the crossing interpolated linearly in IM where the ratio reaches 1, or the bound.
fn records_from_runs(runs: &str, ls: &str) -> Vec<IdaRecord> {
    let mut lines = runs.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let (rec, im, ex, ra) = (
        col("record"),
        col("im_g"),
        col(&format!("{ls}_exceeded")),
        col(&format!("{ls}_ratio")),
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let mut out = Vec::new();
    for chunk in rows.chunk_by(|a, b| a[rec] == b[rec]) {
        let mut prev: Option<(f64, f64)> = None;
        let mut r = None;
        for row in chunk {
            let (x, ratio): (f64, f64) = (row[im].parse().unwrap(), row[ra].parse().unwrap());
            if row[ex] == "true" {
                r = Some(match prev {
                    None => IdaRecord::ExceededAtFirst(x),
                    Some((x0, r0)) => IdaRecord::Exceeded(
                        (x0 + (1.0 - r0) / (ratio - r0) * (x - x0)).clamp(x0, x),
                    ),
                });
                break;
            }
            prev = Some((x, ratio));
        }
        out.push(r.unwrap_or_else(|| IdaRecord::NotExceeded(prev.unwrap().0)));
    }
    out
}

#[test]
fn truncated_ida_with_records_that_never_exceed_gets_a_censored_fit() {
    let d = scratch_dir("fragcens", "ida");
    let bridge =
        &crate::fragility::SCENARIO[..crate::fragility::SCENARIO.find("[fragility]").unwrap()];
    std::fs::write(d.join("bridge.toml"), format!("{bridge}{STUDY}")).unwrap();
    std::fs::write(d.join("set.toml"), SET).unwrap();
    let out = d.join("out");
    let (code, stdout, err) = run_capture(&[
        "fragility",
        d.join("bridge.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "2",
    ]);
    assert_eq!(code, Some(0), "{stdout}\n{err}");
    let runs = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let csv = std::fs::read_to_string(out.join("fragility.csv")).unwrap();
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("fragility.json")).unwrap())
            .unwrap();
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let expected = [
        ("impulse", Method::MleCensoredIda { right: 2, left: 0 }),
        ("low", Method::MleCensoredIda { right: 0, left: 1 }),
        ("mid", Method::MomentsIda),
    ];
    for (k, (line, (ls, method))) in lines.zip(expected).enumerate() {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f[col("limit_state")], ls);
        let data = CensoredIdaData {
            records: records_from_runs(&runs, ls),
        };
        let (m, fit) = fit_ida_censored(&data).unwrap();
        assert_eq!(m, method, "{ls}: {:?}", data.records);
        assert_eq!(f[col("method")], method.as_str(), "{line}");
        assert_eq!(f[col("status")], "ok", "{line}");
        let (theta, beta) = fit.params().unwrap();
        let num = |c: &str| f[col(c)].parse::<f64>().unwrap();
        assert_eq!((num("theta"), num("beta")), (theta, beta), "{line}");
        assert!(num("theta_lo") < theta && theta < num("theta_hi"), "{line}");
        assert!(num("beta_lo") < beta && beta < num("beta_hi"), "{line}");
        let j = &json["fits"][k];
        assert_eq!(j["method"], method.as_str());
        match method {
            Method::MleCensoredIda { right, left } => {
                assert_eq!(
                    (j["censored"].as_u64(), j["exceeded_at_first"].as_u64()),
                    (Some(right as u64), Some(left as u64))
                );
            }
            _ => assert!(j["censored"].is_null() && j["exceeded_at_first"].is_null()),
        }
    }
    // A record never reaching `impulse` is censored at its largest IM, 2 × 0.3 g.
    let impulse = records_from_runs(&runs, "impulse");
    assert!(
        impulse.contains(&IdaRecord::NotExceeded(0.6)),
        "{impulse:?}"
    );
}
