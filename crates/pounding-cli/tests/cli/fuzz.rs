//! Fuzzing regressions of the generic impact JSON reader (`impact --problem`): every input the
//! `impact_json` fuzzer crashed on (`fuzz/regressions/impact_json/`) and every seed, replayed
//! through the reader and the fuzz oracle in-process, and through the binary (never a panic).

use crate::pounding;
use pounding::impact::{self, ImpactSettings};
use std::path::PathBuf;

#[allow(dead_code)]
#[path = "../../../../fuzz/src/lib.rs"]
mod oracle;

fn inputs() -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let mut v = Vec::new();
    for kind in ["regressions", "corpus"] {
        if let Ok(d) = std::fs::read_dir(root.join(kind).join("impact_json")) {
            v.extend(d.map(|e| e.unwrap().path()));
        }
    }
    v.sort();
    assert!(!v.is_empty(), "no impact_json seeds");
    v
}

#[test]
fn fuzz_replay_impact_json() {
    for p in inputs() {
        let text = std::fs::read_to_string(&p).unwrap_or_default();
        if let Ok(problem) = pounding::impact_report::parse_problem(&text) {
            let s = impact::solve(&problem, &ImpactSettings::default());
            let r = std::panic::catch_unwind(|| oracle::check_impact(&problem, &s));
            assert!(r.is_ok(), "impact oracle fails on {}", p.display());
        }
        let o = pounding()
            .args(["impact", "--json", "--problem"])
            .arg(&p)
            .output()
            .unwrap();
        let code = o.status.code();
        assert!(
            matches!(code, Some(0..=2)),
            "{}: exit {code:?}: {}",
            p.display(),
            String::from_utf8_lossy(&o.stderr)
        );
    }
}
