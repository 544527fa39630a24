//! `pounding motion svgm`: the files (one CSV per realisation with a `t,<ids>` header, samples
//! equal to the library's generator, `SVGM.txt`, `manifest.toml` in the agreed form), the same
//! bytes for the same seed, a smaller set removes the CSVs of a larger one, and bad flags exit 2
//! naming the flag with nothing written.

use crate::{run_capture, scratch_dir};
use pounding::ground_motion::svgm::{Coherency, Generator, SvgmParams};
use pounding::ground_motion::synth::SynthParams;
use std::path::{Path, PathBuf};

/// Runs `pounding motion svgm --out D/NAME ARGS...`: (exit code, stderr, the output directory).
fn svgm(d: &Path, name: &str, args: &[&str]) -> (Option<i32>, String, PathBuf) {
    let out = d.join(name);
    let mut a = vec!["motion", "svgm", "--out", out.to_str().unwrap()];
    a.extend_from_slice(args);
    let (code, _, err) = run_capture(&a);
    (code, err, out)
}

const BASE: &[&str] = &[
    "--supports",
    "0,30,60,90",
    "--v-app",
    "250",
    "--duration",
    "4",
    "--count",
    "3",
    "--seed",
    "7",
];

#[test]
fn svgm_writes_csvs_and_the_manifest_with_the_generators_samples() {
    let d = scratch_dir("motion_svgm", "files");
    let (code, err, out) = svgm(&d, "set", BASE);
    assert_eq!(code, Some(0), "{err}");
    let manifest = std::fs::read_to_string(out.join("manifest.toml")).unwrap();
    let source = "pounding motion svgm --supports 0,30,60,90 --ids start,joint1,joint2,end \
                  --coherency harichandran-vanmarcke --hv-a 0.736 --hv-alpha 0.147 --hv-k 5210 \
                  --hv-omega0 6.85 --hv-b 2.78 --v-app 250 --psd clough-penzien --wg 15.6 \
                  --zg 0.6 --wf 1.5 --zf 0.6 --s0 0.01 --duration 4 --dt 0.01 --count 3 --seed 7";
    let mut want = format!("[set]\nname = \"svgm\"\nsource = \"{source}\"\n");
    for id in ["real_0001", "real_0002", "real_0003"] {
        want.push_str(&format!(
            "\n[[record]]\nid = \"{id}\"\nsupports = \"{id}.csv\"\n\n[record.meta]\nseed = 7\n"
        ));
    }
    // the manifest without the motions' statistics (checked below from the samples)
    let bare: String = manifest
        .lines()
        .filter(|l| !l.starts_with("pgd_m = ") && !l.starts_with("differential_m = "))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(bare, want);
    let stat = |name: &str| -> Vec<f64> {
        manifest
            .lines()
            .filter_map(|l| l.strip_prefix(name))
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let (pgd, diff) = (stat("pgd_m = "), stat("differential_m = "));
    assert_eq!((pgd.len(), diff.len()), (3, 3));
    let readme = std::fs::read_to_string(out.join("SVGM.txt")).unwrap();
    assert!(readme.contains("Harichandran-Vanmarcke") && readme.contains("250 m/s"));
    // the samples are the library generator's, read back exactly
    let p = SvgmParams {
        positions: vec![0.0, 30.0, 60.0, 90.0],
        ids: ["start", "joint1", "joint2", "end"]
            .map(String::from)
            .to_vec(),
        coherency: Coherency::HV_SMART1,
        v_app: 250.0,
        psd: SynthParams {
            duration: 4.0,
            ..SynthParams::default()
        },
        stationary: false,
    };
    let g = Generator::new(&p).unwrap();
    for r in 0..3 {
        let text = std::fs::read_to_string(out.join(format!("real_000{}.csv", r + 1))).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,start,joint1,joint2,end"));
        let want = g.realisation(7, r);
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), 401);
        // the manifest's statistics: trapezoid velocity, exact piecewise-linear displacement
        let (mut v, mut u) = ([0.0f64; 4], [0.0f64; 4]);
        let (mut pk, mut df) = (0.0f64, 0.0f64);
        for w in rows.windows(2) {
            for j in 0..4 {
                let (a0, a1) = (w[0][j + 1], w[1][j + 1]);
                u[j] += v[j] * 0.01 + (2.0 * a0 + a1) * 1e-4 / 6.0;
                v[j] += (a0 + a1) * 0.005;
                pk = pk.max(u[j].abs());
            }
            let hi = u.iter().copied().fold(f64::MIN, f64::max);
            let lo = u.iter().copied().fold(f64::MAX, f64::min);
            df = df.max(hi - lo);
        }
        assert!(
            (pk - pgd[r]).abs() <= 1e-9 * pk && pk > 0.0,
            "pgd {pk} vs {}",
            pgd[r]
        );
        assert!(
            (df - diff[r]).abs() <= 1e-9 * df && df > 0.0,
            "diff {df} vs {}",
            diff[r]
        );
        for (k, row) in rows.iter().enumerate() {
            assert!((row[0] - k as f64 * 0.01).abs() < 1e-12, "t at row {k}");
            for j in 0..4 {
                assert_eq!(
                    row[j + 1],
                    want[j][k],
                    "realisation {r}, support {j}, row {k}"
                );
            }
        }
    }
    // the same flags elsewhere: the same bytes; another seed: other samples
    let (code, _, again) = svgm(&d, "again", BASE);
    assert_eq!(code, Some(0));
    for f in ["real_0002.csv", "manifest.toml", "SVGM.txt"] {
        assert_eq!(
            std::fs::read(out.join(f)).unwrap(),
            std::fs::read(again.join(f)).unwrap(),
            "{f}"
        );
    }
    let mut other: Vec<&str> = BASE.to_vec();
    other[9] = "8";
    let (code, _, other) = svgm(&d, "other", &other);
    assert_eq!(code, Some(0));
    assert_ne!(
        std::fs::read(out.join("real_0001.csv")).unwrap(),
        std::fs::read(other.join("real_0001.csv")).unwrap()
    );
}

#[test]
fn svgm_ids_coherency_flags_and_a_smaller_set_over_a_larger_one() {
    let d = scratch_dir("motion_svgm", "ids");
    let args = |count: &'static str| {
        vec![
            "--supports",
            "-10,40",
            "--ids",
            "west_abut,P-1",
            "--coherency",
            "luco-wong",
            "--lw-alpha-vs",
            "3e-4",
            "--v-app",
            "inf",
            "--stationary",
            "--pga",
            "0.2",
            "--duration",
            "2",
            "--count",
            count,
            "--seed",
            "1",
        ]
    };
    let (code, err, out) = svgm(&d, "set", &args("4"));
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(out.join("real_0004.csv")).unwrap();
    assert!(text.starts_with("t,west_abut,P-1\n"));
    let manifest = std::fs::read_to_string(out.join("manifest.toml")).unwrap();
    assert!(
        manifest.contains(
            "--coherency luco-wong --lw-alpha-vs 0.0003 --v-app inf --psd clough-penzien"
        )
    );
    assert!(manifest.contains("--pga 0.2 --stationary --duration 2"));
    std::fs::write(out.join("mine.csv"), "t,a\n0,1\n").unwrap();
    let (code, err, _) = svgm(&d, "set", &args("2"));
    assert_eq!(code, Some(0), "{err}");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "SVGM.txt",
            "manifest.toml",
            "mine.csv",
            "real_0001.csv",
            "real_0002.csv"
        ]
    );
}

#[test]
fn bad_svgm_flags_exit_2_naming_the_flag_and_write_nothing() {
    let d = scratch_dir("motion_svgm", "bad");
    let with = |flag: &'static str, value: &'static str| -> Vec<&'static str> {
        let mut a = BASE.to_vec();
        match a.iter().position(|x| *x == flag) {
            Some(i) => a[i + 1] = value,
            None => a.extend([flag, value]),
        }
        a
    };
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (with("--supports", "0,30,30,90"), "--supports"),
        (with("--supports", "0,60,30,90"), "--supports"),
        (with("--supports", "0,30,nan,90"), "--supports"),
        (with("--supports", "0,30,inf,90"), "--supports"),
        (with("--supports", "0,x"), "--supports"),
        (with("--ids", "a,b,c"), "--ids"),
        (with("--ids", "a,b,c,a"), "--ids"),
        (with("--ids", "a,,c,d"), "--ids"),
        (with("--ids", "a,b c,c,d"), "--ids"),
        (with("--ids", "a,b,c,t"), "--ids"),
        (with("--v-app", "0"), "--v-app"),
        (with("--v-app", "-250"), "--v-app"),
        (with("--v-app", "nan"), "--v-app"),
        (with("--v-app", "20"), "--v-app"),
        (with("--supports", "0,30,60,1e308"), "--v-app"),
        (with("--hv-a", "0"), "--hv-a"),
        (with("--hv-a", "1.2"), "--hv-a"),
        (with("--hv-alpha", "0"), "--hv-alpha"),
        (with("--hv-k", "-5210"), "--hv-k"),
        (with("--hv-omega0", "0"), "--hv-omega0"),
        (with("--hv-b", "nan"), "--hv-b"),
        (with("--lw-alpha-vs", "2e-4"), "--lw-alpha-vs"),
        (with("--wg", "0"), "--wg"),
        (with("--zg", "1"), "--zg"),
        (with("--wf", "-1"), "--wf"),
        (with("--zf", "0"), "--zf"),
        (with("--s0", "0"), "--s0"),
        (with("--pga", "0"), "--pga"),
        (with("--pga", "11"), "--pga"),
        (with("--dt", "0"), "--dt"),
        (with("--dt", "0.03"), "--duration"),
        (with("--duration", "0.5"), "--duration"),
        (with("--count", "0"), "--count"),
        (with("--count", "10001"), "--count"),
        (with("--psd", "kanai-tajimi"), "--psd"),
        (with("--coherency", "vanmarcke"), "--coherency"),
        (with("--condition", "no-such-record.AT2"), "--condition"),
        (with("--window", "4"), "--window"),
        (with("--at", "start"), "--at"),
        (with("--duration", "30000"), "--duration"),
    ];
    let mut s0_and_pga = with("--s0", "0.02");
    s0_and_pga.extend(["--pga", "0.3"]);
    let mut lw_params = with("--coherency", "luco-wong");
    lw_params.extend(["--hv-k", "100"]);
    let cond = |extra: &[&'static str]| {
        let mut a = vec![
            "--supports",
            "0,30,60,90",
            "--v-app",
            "250",
            "--count",
            "1",
            "--seed",
            "1",
            "--condition",
            "builtin:ELC180",
        ];
        a.extend_from_slice(extra);
        a
    };
    let conditioned = [
        (cond(&[]), "--at"),
        (cond(&["--at", "middle"]), "--at"),
        (cond(&["--at", "start", "--window", "0.1"]), "--window"),
        (cond(&["--at", "start", "--window", "100"]), "--window"),
        (cond(&["--at", "start", "--pga", "0.3"]), "--pga"),
        (cond(&["--at", "start", "--wg", "10"]), "--wg"),
        (cond(&["--at", "start", "--stationary"]), "--stationary"),
        (cond(&["--at", "start", "--duration", "20"]), "--duration"),
    ];
    let mut lw_bad = with("--coherency", "luco-wong");
    lw_bad.extend(["--lw-alpha-vs", "0"]);
    for (i, (args, flag)) in cases
        .into_iter()
        .chain([
            (s0_and_pga, "--s0"),
            (lw_params, "--hv-k"),
            (lw_bad, "--lw-alpha-vs"),
        ])
        .chain(conditioned)
        .enumerate()
    {
        let (code, err, out) = svgm(&d, &format!("out{i}"), &args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains(flag), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(!out.exists(), "{args:?} wrote outputs");
    }
}

#[test]
fn svgm_conditioned_on_a_record_keeps_the_record_at_its_support() {
    use pounding::ground_motion::builtin_record;
    let d = scratch_dir("motion_svgm", "condition");
    let (code, err, out) = svgm(
        &d,
        "set",
        &[
            "--supports",
            "0,30,60,90",
            "--v-app",
            "250",
            "--condition",
            "builtin:ELC180",
            "--at",
            "joint1",
            "--count",
            "2",
            "--seed",
            "3",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    let manifest = std::fs::read_to_string(out.join("manifest.toml")).unwrap();
    assert!(manifest.contains(
        "--v-app 250 --condition builtin:ELC180 --at joint1 --window 4 --count 2 --seed 3"
    ));
    let rec = builtin_record("ELC180").unwrap();
    let peak = rec.pga();
    for f in ["real_0001.csv", "real_0002.csv"] {
        let text = std::fs::read_to_string(out.join(f)).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("t,start,joint1,joint2,end"));
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert_eq!(rows.len(), rec.values().len());
        for (k, (row, a)) in rows.iter().zip(rec.values()).enumerate() {
            assert!((row[0] - rec.times()[k]).abs() < 1e-9);
            assert!((row[2] - a).abs() < 1e-12 * peak, "{f} row {k}");
            assert!(row[1] != row[2] && row[3] != row[2]);
        }
    }
    assert!(
        std::fs::read_to_string(out.join("SVGM.txt"))
            .unwrap()
            .contains("CONDITIONED")
    );
}
