//! Hardening, second round (issue 15): hangs, memory, silently ignored settings and unreadable
//! messages found by a hostile tester on a release build.

use crate::pounding;
use std::path::Path;
use std::time::{Duration, Instant};

fn tmp(name: &str) -> crate::Scratch {
    crate::scratch_dir("hr2", name)
}

/// Runs `pounding ARGS` in `dir`, killing it after `limit`; returns (exit code, stderr), or
/// panics when the limit was reached (a hang).
fn run_limited(dir: &Path, args: &[&str], limit: Duration) -> (Option<i32>, String) {
    let mut child = pounding()
        .current_dir(dir)
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let mut err = String::new();
            use std::io::Read;
            child
                .stderr
                .take()
                .unwrap()
                .read_to_string(&mut err)
                .unwrap();
            return (status.code(), err);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("pounding {args:?} did not finish within {limit:?} (hang)");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Runs `pounding ARGS` in `dir` (60 s limit); returns (exit code, stderr).
fn run_in(dir: &Path, args: &[&str]) -> (Option<i32>, String) {
    run_limited(dir, args, Duration::from_secs(60))
}

/// Writes `text` as `dir/name` and runs `pounding simulate name --out o`.
fn simulate(dir: &Path, name: &str, text: &str) -> (Option<i32>, String) {
    std::fs::write(dir.join(name), text).unwrap();
    run_in(dir, &["simulate", name, "--out", "o"])
}

/// An infinite contact impulse (χ = 1e300 overflows the Hunt–Crossley force) used to make the
/// impulse plot's axis infinite, and plotters then looped forever: the run must finish, write all
/// its outputs, release the lock and report Diverged (exit 1).
#[test]
fn infinite_impulse_diverges_without_hanging_the_plots() {
    let d = tmp("chi");
    let (code, err) = simulate(
        &d,
        "chi.toml",
        "[time]\nduration = 3.0\n[contact]\nlaw = \"hertz-damp\"\nchi = 1e300\n",
    );
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("Diverged"), "{err}");
    let o = d.join("o");
    for f in [
        "history.csv",
        "impacts.csv",
        "summary.json",
        "timing.json",
        "impulses.png",
        "displacements.png",
        "energy.png",
    ] {
        assert!(o.join(f).is_file(), "{f} missing: {err}");
    }
    assert!(!o.join(".pounding.lock").exists(), "lock left behind");
    // the impulse really is non-finite (else this test would not exercise the fix)
    let impacts = std::fs::read_to_string(o.join("impacts.csv")).unwrap();
    assert!(
        impacts
            .lines()
            .skip(1)
            .any(|l| l.contains("inf") || l.contains("nan")),
        "{impacts}"
    );
}

/// A 5 M-step run keeping every step needed more than 1 GB (the 200 M-step limit ~40 GB): it is
/// refused as bad input before anything runs, naming the three keys with their lines and the
/// `history_every` that fits (the library test `harden_round2` checks that this value fits).
#[test]
fn simulate_refuses_a_history_too_large_for_memory() {
    let d = tmp("mem");
    let (code, err) = simulate(
        &d,
        "mem.toml",
        "[ground_motion]\nrecord_x = \"none\"\n[time]\nduration = 5000.0\nhistory_every = 1\n",
    );
    assert_eq!(code, Some(2), "{err}");
    for want in [
        "GiB",
        "`[time] history_every` (mem.toml:5)",
        "`[time] duration` (mem.toml:4)",
        "`[time] dt`",
        "history_every >= 4",
    ] {
        assert!(err.contains(want), "{want}: {err}");
    }
    assert!(!d.join("o").exists(), "nothing may be written");
    // compare keeps every law's history (coarsened to fit): refused as a whole when even the
    // ground samples of the six laws exceed the limit
    std::fs::write(
        d.join("c.toml"),
        "[ground_motion]\nrecord_x = \"none\"\n[time]\nduration = 30000.0\nhistory_every = 100000\n",
    )
    .unwrap();
    let (code, err) = run_in(&d, &["compare", "c.toml", "--out", "oc"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("GiB") && err.contains("duration"), "{err}");
    assert!(!d.join("oc").exists());
}

/// `[contact]` keys the chosen law does not read used to be accepted and ignored (exit 0): each
/// is now refused by `simulate`, naming the key and its line.
#[test]
fn simulate_refuses_contact_keys_the_law_does_not_use() {
    let d = tmp("keys");
    for (text, want) in [
        (
            "[contact]\nlaw = \"rigid\"\nk = 1e10\n",
            "k applies to compliance laws",
        ),
        (
            "[contact]\n# the default law is rigid\nrestitution = 0.5\n",
            "restitution applies to compliance laws",
        ),
        (
            "[contact]\nlaw = \"hertz\"\nk = 1e10\n",
            "k is not used by law = \"hertz\"",
        ),
        (
            "[contact]\nlaw = \"hertz-damp\"\nchi = 0.3\nzeta = 0.1\n",
            "chi is not used by law = \"hertz-damp\" with zeta given",
        ),
        (
            "[contact]\nlaw = \"kelvin\"\nrestitution = 0.5\nc = 1e6\n",
            "restitution is not used by law = \"kelvin\" with c given",
        ),
        (
            "[contact]\nlaw = \"jankowski\"\nk_h = 1e9\nbeta = 2e9\n",
            "k_h is not used by law = \"jankowski\"",
        ),
    ] {
        let (code, err) = simulate(&d, "s.toml", text);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(
            err.contains(want) && err.contains("(s.toml:3)"),
            "{text}: {err}"
        );
        assert!(!d.join("o").exists(), "{text}: nothing may be written");
    }
    // a key the law does read is still accepted (short run)
    let (code, err) = simulate(
        &d,
        "ok.toml",
        "[time]\nduration = 0.05\n[contact]\nlaw = \"hertz\"\nk_h = 1e9\nfriction_velocity = 0.01\n",
    );
    assert_eq!(code, Some(0), "{err}");
}

/// `compare` applies simulate's rule to the list of compared laws: a `[contact]` key that no law
/// of `--laws` reads (with the other keys given) is refused, naming the key, its line, the
/// compared laws and the laws that would read it; nothing is written. `[contact] law` itself is
/// replaced by each compared law and is no error.
#[test]
fn compare_refuses_contact_keys_no_compared_law_uses() {
    let d = tmp("cmpunused");
    for (text, laws, want) in [
        (
            "[contact]\nlaw = \"linear\"\nzeta = 0.1\n",
            "rigid,kelvin,linear",
            "zeta is not used by any of the compared laws (rigid, kelvin, linear)",
        ),
        // chi is not read by hertz-damp when zeta is given, nor by any other law
        (
            "[contact]\nzeta = 0.1\nchi = 0.3\n",
            "hertz-damp,kelvin",
            "no law reads it together with the other keys given",
        ),
        (
            "[contact]\nk_h = 1e9\nrestitution = 0.6\n",
            "rigid,hertz",
            "it is read by kelvin without c; hertz-damp",
        ),
        (
            "[contact]\nlaw = \"kelvin\"\nfriction_velocity = 0.01\n",
            "rigid",
            "friction_velocity is not used by any of the compared laws (rigid)",
        ),
    ] {
        std::fs::write(d.join("c.toml"), text).unwrap();
        let (code, err) = run_in(&d, &["compare", "c.toml", "--laws", laws, "--out", "oc"]);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(
            err.contains(want) && err.contains("(c.toml:3)"),
            "{text}: {err}"
        );
        assert!(!d.join("oc").exists(), "{text}: nothing may be written");
    }
    // the default list reads every key of the section (zeta: hertz-damp), and `law` is no error
    std::fs::write(
        d.join("c.toml"),
        "[time]\nduration = 0.02\n[contact]\nlaw = \"linear\"\nzeta = 0.1\n",
    )
    .unwrap();
    let (code, err) = run_in(&d, &["compare", "c.toml", "--out", "oc"]);
    assert_eq!(code, Some(0), "{err}");
}

/// `compare` builds every law from the one `[contact]` section: a key of one compared law is no
/// error for the others (documented), while a bad value of a key still is.
#[test]
fn compare_accepts_contact_keys_of_any_compared_law() {
    let d = tmp("cmpkeys");
    std::fs::write(
        d.join("c.toml"),
        "[time]\nduration = 0.05\n[contact]\nk = 2e10\nk_h = 1e9\nzeta = 0.2\n",
    )
    .unwrap();
    let (code, err) = run_in(
        &d,
        &[
            "compare",
            "c.toml",
            "--laws",
            "rigid,kelvin,hertz-damp",
            "--out",
            "oc",
        ],
    );
    assert_eq!(code, Some(0), "{err}");
}

/// `shape = "skew"` without `skew_deg` used to run as a 0° skew; now an error naming the shape's
/// line.
#[test]
fn skew_shape_needs_its_angle() {
    let d = tmp("skew");
    let (code, err) = simulate(
        &d,
        "s.toml",
        "[time]\nduration = 0.05\n[decks]\nshape = \"skew\"\nL1 = 30.0\nL2 = 30.0\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("shape = \"skew\" needs skew_deg") && err.contains("s.toml:4"),
        "{err}"
    );
    assert!(!d.join("o").exists());
}

/// A study with `svg = true` and `figures = false` used to write no SVG silently.
#[test]
fn study_refuses_svg_without_figures() {
    let d = tmp("svg");
    std::fs::write(d.join("st.toml"), "[output]\nfigures = false\nsvg = true\n").unwrap();
    let (code, err) = run_in(&d, &["study", "st.toml", "--out", "os"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("output.svg") && err.contains("st.toml") && err.contains("line 3"),
        "{err}"
    );
    assert!(!d.join("os").exists());
}

/// A duration that is not a whole number of steps is rounded up (kept), with a note on stderr.
#[test]
fn rounded_duration_is_noted() {
    let d = tmp("round");
    let (code, err) = simulate(&d, "s.toml", "[time]\nduration = 1.0\ndt = 0.3\n");
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains("note: duration = 1 s is not a multiple of dt = 0.3 s: the run takes 4 steps, to t = 1.2 s"),
        "{err}"
    );
    let (code, err) = simulate(&d, "t.toml", "[time]\nduration = 0.9\ndt = 0.3\n");
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("note:"), "{err}");
}

/// A study density whose derived deck mass overflows used to fail during the run with no file,
/// line or scenario key; it is now refused at load time naming `decks.density_kg_m3` and its
/// line (and a length whose inertia overflows names `decks.l1_m`).
#[test]
fn study_derived_mass_overflow_names_the_key_and_line() {
    let d = tmp("dens");
    for (text, want) in [
        (
            "[decks]\n# huge\ndensity_kg_m3 = 1e307\n",
            "line 3: invalid decks.density_kg_m3 = 1e307",
        ),
        (
            "[decks]\nshape = \"straight\"\nl1_m = [1e150]\n",
            "line 3: invalid decks.l1_m = 1e150",
        ),
    ] {
        std::fs::write(d.join("st.toml"), text).unwrap();
        let (code, err) = run_in(&d, &["study", "st.toml", "--out", "os"]);
        assert_eq!(code, Some(2), "{text}: {err}");
        assert!(
            err.contains("st.toml") && err.contains(want),
            "{text}: {err}"
        );
        assert!(err.contains("derived"), "{err}");
        assert!(!d.join("os").exists());
    }
}

/// Abutments with a compliance law: the error names `[contact] law` and the `[abutments]` keys
/// with their lines (it used to say `invalid contact_law = nan` with no location).
#[test]
fn abutments_with_a_compliance_law_name_both_keys() {
    let d = tmp("abut");
    let (code, err) = simulate(
        &d,
        "s.toml",
        "[time]\nduration = 0.1\n[contact]\nlaw = \"kelvin\"\n[abutments]\ngap1 = 0.05\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("`[contact] law` (s.toml:4)")
            && err.contains("`[abutments] gap1` (s.toml:6)")
            && !err.contains("nan"),
        "{err}"
    );
}

/// A record whose sample interval makes it shorter than the default step used to blame the
/// built-in default dt; the record is blamed (name and duration), and a user-set dt is named.
#[test]
fn too_short_record_is_blamed_not_the_default_dt() {
    let d = tmp("dt");
    std::fs::write(
        d.join("tiny.AT2"),
        "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   4, DT=   1e-300 SEC\n0.1 0.2 0.1 0.0\n",
    )
    .unwrap();
    let (code, err) = run_in(&d, &["simulate", "--record", "tiny.AT2", "--out", "o"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("lasts only 3e-300 s")
            && err.contains("tiny.AT2")
            && err.contains("built-in default dt")
            && !err.contains("built-in default:"),
        "{err}"
    );
    let (code, err) = simulate(
        &d,
        "s.toml",
        "[ground_motion]\nrecord_y = \"tiny.AT2\"\nrecord_x = \"none\"\n[time]\ndt = 0.01\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("`[time] dt` (s.toml:5)") && err.contains("tiny.AT2"),
        "{err}"
    );
}

/// A record value finite in the file but infinite in m/s² (1e308 g) is reported as overflowing
/// on conversion, with the record file and line (it used to say `a[0] = inf: must be finite`).
#[test]
fn record_value_overflowing_on_conversion_names_file_and_line() {
    let d = tmp("ovf");
    std::fs::write(d.join("big.csv"), "t,a\n0,0\n0.01,1e308\n0.02,0\n").unwrap();
    std::fs::write(
        d.join("big.AT2"),
        "PEER\nx\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   4, DT=   0.01 SEC\n0.1 1e308 0.1 0.0\n",
    )
    .unwrap();
    let (code, err) = simulate(
        &d,
        "s.toml",
        "[ground_motion]\nrecord_y = \"big.csv\"\nrecord_x = \"none\"\ncsv_units = \"g\"\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("big.csv:3") && err.contains("1e308 overflows when converted to m/s²"),
        "{err}"
    );
    let (code, err) = run_in(&d, &["simulate", "--record", "big.AT2", "--out", "o"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("big.AT2:5") && err.contains("overflows"),
        "{err}"
    );
}

/// Floats in messages are the user's value in shortest form: `--skew -30` is not reported as
/// `-29.999999999999996`, a restitution of 1e-300 is not a 300-digit decimal.
#[test]
fn messages_print_floats_in_shortest_form() {
    let d = tmp("fmt");
    let (code, err) = run_in(
        &d,
        &[
            "impact",
            "--shape",
            "skew",
            "--length",
            "30",
            "--skew=-30",
            "--mu",
            "0.3",
            "--eps",
            "0.5",
        ],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("--skew -30:") && !err.contains("29.99"),
        "{err}"
    );
    let (code, err) = simulate(
        &d,
        "s.toml",
        "[time]\nduration = 0.1\n[decks]\nshape = \"skew\"\nL1 = 30.0\nL2 = 30.0\nskew_deg = -30.0\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("skew_deg = -30:") && err.contains("s.toml:7"),
        "{err}"
    );
    let (code, err) = simulate(
        &d,
        "r.toml",
        "[time]\nduration = 0.1\n[contact]\nlaw = \"kelvin\"\nrestitution = 1e-300\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("restitution = 1e-300") && err.len() < 400,
        "{err}"
    );
}

/// A parse error quoting a 400 KB scenario line is cut to ~200 characters per line (simulate
/// and study).
#[test]
fn parse_errors_do_not_echo_huge_lines() {
    let d = tmp("long");
    let long = "a".repeat(400_000);
    let (code, err) = simulate(&d, "s.toml", &format!("[time]\nduration = \"{long}\"\n"));
    assert_eq!(code, Some(2));
    assert!(
        err.len() < 2000 && err.contains("s.toml") && err.contains("line 2"),
        "{}",
        &err[..err.len().min(3000)]
    );
    assert!(err.contains("more characters"), "{err}");
    std::fs::write(
        d.join("st.toml"),
        format!("[decks]\nwidth_m = \"{long}\"\n"),
    )
    .unwrap();
    let (code, err) = run_in(&d, &["study", "st.toml", "--out", "os"]);
    assert_eq!(code, Some(2));
    assert!(
        err.len() < 2000 && err.contains("line 2"),
        "{}",
        &err[..err.len().min(3000)]
    );
}
