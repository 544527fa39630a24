//! Record-set manifests of 20,000 entries (one small one-column file, read once):
//!
//! * `toml_20000` — a TOML manifest of 20,000 `[[record]]` tables;
//! * `csv_20000` — the equivalent CSV manifest.
//!
//! Both are linear in the number of entries (naming each entry's line once scanned the text
//! from the start, which made the TOML manifest quadratic: 40 s for 20,000 entries).

use pounding::ground_motion::set::RecordSet;
use std::hint::black_box;
use std::path::Path;

const N: usize = 20_000;

fn main() {
    divan::main();
}

fn dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/benches"))
}

#[divan::bench(sample_count = 5)]
fn toml_20000(b: divan::Bencher) {
    let text: String = (0..N)
        .map(|i| format!("[[record]]\nid = \"R{i}\"\nx = \"manifest-record.txt\"\ndt = 0.01\n\n"))
        .collect();
    b.bench(|| {
        let s = RecordSet::from_toml(black_box(&text), "bench.toml", dir()).unwrap();
        assert_eq!(s.records.len(), N);
    });
}

#[divan::bench(sample_count = 5)]
fn csv_20000(b: divan::Bencher) {
    let rows: String = (0..N)
        .map(|i| format!("R{i},manifest-record.txt,0.01\n"))
        .collect();
    let text = format!("id,x,dt\n{rows}");
    b.bench(|| {
        let s = RecordSet::from_csv(black_box(&text), "bench.csv", dir()).unwrap();
        assert_eq!(s.records.len(), N);
    });
}
