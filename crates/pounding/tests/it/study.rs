//! The parametric study: scenario parsing and errors, row order, spec §15 reference rows in
//! `bounds.csv`, μ behaviour of the bounds, LCP cross-check, summaries, sharding and determinism.

use pounding::analytic::ImpactLaw;
use pounding::contact::Delassus;
use pounding::geometry::ContactCase;
use pounding::study::cell::{lcp_agrees, lcp_mode, test_ratios};
use pounding::study::csv::BOUNDS_HEADER;
use pounding::study::run::compute_rows;
use pounding::study::shard::{ShardFiles, manifest_json, merge, shard_rows_csv};
use pounding::study::summary::shares;
use pounding::study::{
    DEFAULT_SCENARIO_TOML, Layout, Row, Scenario, ScenarioError, Shard, Study, Verdict,
};

fn none(_: usize) {}

fn scenario(text: &str) -> Scenario {
    Scenario::from_toml(text, "test.toml").expect("valid scenario")
}

fn study(text: &str) -> Study {
    Study::compute(text.to_string(), scenario(text), &none).expect("computes")
}

const SMALL: &str = r#"
[decks]
beta1_deg = [60.0]
beta2_deg = [90.0]
r1_m = [200.0, 100.0]
r2_m = [100.0]
[impact]
mu = [0.5, 0.0, 1.0, 0.25]
[grid]
theta1_deg = { start = -6.0, stop = 6.0, step = 2.0 }
theta2_deg = { start = -6.0, stop = 6.0, step = 3.0 }
[output]
figures = false
"#;

#[test]
fn default_text_parses_to_the_default_and_has_254016_rows() {
    let s = Scenario::from_toml(DEFAULT_SCENARIO_TOML, "default").unwrap();
    assert_eq!(s, Scenario::default());
    assert_eq!(s.row_count(), 254_016);
    assert_eq!(s.configuration_count(), 144);
    // The empty file is the default too (every key optional).
    assert_eq!(
        Scenario::from_toml("", "empty").unwrap(),
        Scenario::default()
    );
    assert_eq!(s.theta1.values().len(), 21);
    assert_eq!(s.theta1.value(20), 10.0);
}

/// (file text, expected key fragment, expected line)
fn assert_error(text: &str, key: &str, line: usize) {
    let err = Scenario::from_toml(text, "bad.toml").expect_err("must be rejected");
    let msg = err.to_string();
    assert!(msg.contains(key), "error {msg:?} should name {key:?}");
    assert!(msg.contains("bad.toml"), "{msg}");
    let got = match &err {
        ScenarioError::Syntax { line, .. } | ScenarioError::Invalid { line, .. } => *line,
    };
    assert_eq!(got, line, "wrong line in {msg:?}");
    assert!(msg.contains(&format!("line {line}")), "{msg}");
}

#[test]
fn bad_scenarios_name_key_and_line() {
    // syntax error (unterminated array) on line 3
    assert_error("[impact]\neps = [0.5]\nmu = [0.1, 0.2\n", "mu", 3);
    // unknown key on line 4
    assert_error("[decks]\nwidth_m = 10.0\n\nradius = [100.0]\n", "radius", 4);
    // unknown table
    assert_error("\n[decks]\n[solver]\nx = 1\n", "solver", 3);
    // R <= W/2 (W = 10 -> R = 5 is invalid)
    assert_error(
        "[decks]\nr1_m = [100.0]\nr2_m = [100.0, 5.0]\n",
        "decks.r2_m[1]",
        3,
    );
    // R <= W/2 through a larger width with explicit radii
    assert_error(
        "[decks]\nwidth_m = 300.0\nr1_m = [100.0]\n",
        "decks.r1_m[0]",
        3,
    );
    // ... and with default radii the width is blamed
    assert_error("[decks]\n\nwidth_m = 300.0\n", "decks.width_m", 3);
    // empty lists
    assert_error("[impact]\n\nmu = []\n", "impact.mu", 3);
    assert_error("[grid]\ncases = []\n", "grid.cases", 2);
    // step <= 0
    assert_error(
        "[grid]\ntheta1_deg = { start = -1.0, stop = 1.0, step = 0.5 }\ntheta2_deg = { start = -1.0, stop = 1.0, step = 0.0 }\n",
        "grid.theta2_deg.step",
        3,
    );
    assert_error(
        "[grid]\ntheta1_deg = { start = -1.0, stop = 1.0, step = -1.0 }\n",
        "grid.theta1_deg.step",
        2,
    );
    // other invalid values
    assert_error("[impact]\nmu = [0.1, -0.2]\n", "impact.mu[1]", 2);
    assert_error("[impact]\neps = [1.5]\n", "impact.eps[0]", 2);
    assert_error(
        "[impact]\nsigma_mode = \"middle\"\n",
        "impact.sigma_mode",
        2,
    );
    assert_error(
        "[grid]\nratio_min = 3.0\nratio_max = 2.0\n",
        "grid.ratio_max",
        3,
    );
    assert_error("[grid]\ncases = [\"deck3-inner\"]\n", "grid.cases[0]", 2);
    assert_error("[impact]\nmu = [0.5, 0.5]\n", "impact.mu[1]", 2);
    assert_error("[decks]\nbeta1_deg = [0.0]\n", "decks.beta1_deg[0]", 2);
    // wrong type
    assert_error("[decks]\nwidth_m = \"ten\"\n", "width_m", 2);
}

#[test]
fn grid_values_are_start_plus_i_step() {
    let s = scenario("[grid]\ntheta1_deg = { start = -1.0, stop = 1.0, step = 0.1 }\n");
    let v = s.theta1.values();
    assert_eq!(v.len(), 21);
    for (i, x) in v.iter().enumerate() {
        assert_eq!(x.to_bits(), (-1.0 + i as f64 * 0.1).to_bits());
    }
}

#[test]
fn rows_are_ordered_with_theta2_innermost() {
    let st = study(SMALL);
    let s = &st.scenario;
    let layout = Layout::of(s);
    assert_eq!(st.rows.len(), layout.total());
    assert_eq!(layout.total(), 2 * 4 * 4 * 7 * 5);
    for (i, r) in st.rows.iter().enumerate() {
        assert_eq!(r.index, i);
        assert_eq!(layout.key(i), r.key);
        assert_eq!(layout.index(&r.key), i);
    }
    let csv = st.bounds_csv();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some(BOUNDS_HEADER));
    let first: Vec<Vec<String>> = lines
        .take(6)
        .map(|l| l.split(',').take(9).map(str::to_string).collect())
        .collect();
    // scenario order of r1 (200 first) and mu (0.5 first), then deck1-inner, θ1 = -6, θ2 = -6, -3, 0, 3, 6
    assert_eq!(
        first[0],
        [
            "60",
            "90",
            "200",
            "100",
            "0.5",
            "0.5",
            "deck1-inner",
            "-6",
            "-6"
        ]
    );
    assert_eq!(first[1][8], "-3");
    assert_eq!(first[4][8], "6");
    assert_eq!(first[5][7..9], ["-4", "-6"]);
    // cases in canonical order within each configuration
    let cases: Vec<ContactCase> = (0..4).map(|c| s.cases[c]).collect();
    assert_eq!(cases, ContactCase::ALL);
}

#[test]
fn degenerate_diagonals_are_flagged_nan_and_agree() {
    let st = study(SMALL);
    let csv = st.bounds_csv();
    let mut n = 0;
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let (t1, t2): (f64, f64) = (f[7].parse().unwrap(), f[8].parse().unwrap());
        if t1 == t2 || t1 == -t2 {
            n += 1;
            assert_eq!(&f[9..11], ["false", "false"], "{line}");
            assert!(f[11..19].iter().all(|t| *t == "nan"), "{line}");
            assert_eq!(f[19], "true");
        } else {
            assert!(f[11..19].iter().all(|t| *t != "nan"), "{line}");
        }
    }
    // θ1 ∈ {-6,-4,...,6}, θ2 ∈ {-6,-3,0,3,6}: diagonal points (-6,-6),(-6,6),(0,0),(6,-6),(6,6) per block
    assert_eq!(n, 5 * 32);
}

/// Spec §15: (R1, R2, β1, β2, θ1, θ2, case, first, σ, G·ρt (3), L, U at μ = 0.5, L, U at μ = 1).
type RefRow = (
    f64,
    f64,
    f64,
    f64,
    f64,
    f64,
    &'static str,
    bool,
    f64,
    [f64; 3],
    [f64; 4],
);
const SPEC_15: [RefRow; 10] = [
    (
        100.,
        100.,
        60.,
        60.,
        -5.,
        2.,
        "deck1-inner",
        true,
        4.984009614,
        [2.784789492e-03, 2.022511840e-03, 6.619671336e-03],
        [-1.088778793, 2.107066801, -9.046230363, 2.696580445],
    ),
    (
        100.,
        100.,
        60.,
        60.,
        5.,
        -2.,
        "deck1-outer",
        true,
        -4.984009614,
        [2.353427721e-03, 1.500269571e-03, 7.052214505e-03],
        [-1.895322093, 2.429326047, -9.761282130, 3.328939753],
    ),
    (
        100.,
        100.,
        60.,
        60.,
        2.,
        -5.,
        "deck2-inner",
        true,
        4.984009614,
        [2.784789492e-03, 2.022511840e-03, 6.619671336e-03],
        [-1.088778793, 2.107066801, -9.046230363, 2.696580445],
    ),
    (
        100.,
        100.,
        60.,
        60.,
        -2.,
        5.,
        "deck2-outer",
        true,
        -4.984009614,
        [2.353427721e-03, 1.500269571e-03, 7.052214505e-03],
        [-1.895322093, 2.429326047, -9.761282130, 3.328939753],
    ),
    (
        200.,
        100.,
        120.,
        90.,
        -8.,
        3.,
        "deck1-inner",
        true,
        4.958135296,
        [1.800466485e-03, 1.187112898e-03, 2.499500086e-03],
        [-0.077848153, 1.526841852, -3.209536591, 1.850969888],
    ),
    (
        200.,
        100.,
        120.,
        90.,
        3.,
        -8.,
        "deck2-inner",
        true,
        4.958135296,
        [1.771056088e-03, 1.140473087e-03, 2.331698922e-03],
        [-0.031698818, 1.477595656, -2.833629751, 1.788839369],
    ),
    (
        100.,
        200.,
        90.,
        60.,
        6.,
        -1.,
        "deck1-outer",
        true,
        -4.973366945,
        [1.600872729e-03, 1.139298725e-03, 3.903539079e-03],
        [-1.181806252, 2.136169180, -8.983089380, 2.760504893],
    ),
    (
        100.,
        200.,
        90.,
        60.,
        1.,
        7.,
        "deck2-outer",
        true,
        -4.963486721,
        [1.558301656e-03, 1.059904371e-03, 3.797643886e-03],
        [-1.223685522, 2.125263406, -8.239630105, 2.782944623],
    ),
    (
        100.,
        100.,
        60.,
        60.,
        0.,
        5.,
        "deck1-inner",
        false,
        5.019099188,
        [2.727089941e-03, 1.955319894e-03, 6.679043363e-03],
        [-1.186845252, 2.143805278, -9.180953875, 2.765999847],
    ),
    (
        100.,
        100.,
        60.,
        60.,
        5.,
        0.,
        "deck1-inner",
        false,
        4.980973490,
        [2.507682464e-03, 1.556180477e-03, 6.896633777e-03],
        [-1.640967492, 2.284621222, -8.418983945, 3.119992373],
    ),
];

fn close(got: f64, want: f64, rel: f64) -> bool {
    (got - want).abs() <= rel * want.abs().max(1e-300) + 1e-12
}

#[test]
fn spec_15_rows_appear_in_bounds_csv() {
    // The default grid and law, restricted to the geometries of the table (all four (β1,β2,R1,R2)
    // combinations of each row's pair are in the default study).
    let mut found = 0;
    for (r1, r2, b1, b2, t1, t2, case, first, sigma, g, lu) in SPEC_15 {
        let text = format!(
            "[decks]\nbeta1_deg = [{b1:?}]\nbeta2_deg = [{b2:?}]\nr1_m = [{r1:?}]\nr2_m = [{r2:?}]\n[impact]\nmu = [0.5, 1.0]\n[output]\nfigures = false\n"
        );
        let st = study(&text);
        assert_eq!(st.scenario.theta1, Scenario::default().theta1);
        let rho_t = st.scenario.rho_t();
        assert_eq!(rho_t, 1250.0);
        let csv = st.bounds_csv();
        for (m, mu) in [(0usize, "0.5"), (1, "1")] {
            let prefix = format!("{b1},{b2},{r1},{r2},{mu},0.5,{case},{t1},{t2},");
            let line = csv
                .lines()
                .find(|l| l.starts_with(&prefix))
                .unwrap_or_else(|| panic!("no row {prefix}"));
            let f: Vec<&str> = line.split(',').collect();
            let num = |k: usize| f[k].parse::<f64>().unwrap();
            assert_eq!(f[9], if first { "true" } else { "false" }, "{line}");
            assert!((num(11) - sigma).abs() <= 1e-9, "sigma {line}");
            for (k, gk) in g.iter().enumerate() {
                assert!(close(num(12 + k) * rho_t, *gk, 2e-9), "G[{k}] {line}");
            }
            assert!(close(num(15), g[1] / g[0], 1e-8), "kappa {line}");
            assert!(close(num(16), g[2] / g[0], 1e-8), "varrho {line}");
            // the table prints 9 decimals
            assert!(
                (num(17) - lu[2 * m]).abs() <= 1e-9,
                "L {line} vs {}",
                lu[2 * m]
            );
            assert!(
                (num(18) - lu[2 * m + 1]).abs() <= 1e-9,
                "U {line} vs {}",
                lu[2 * m + 1]
            );
            assert_eq!(f[19], "true");
            found += 1;
        }
    }
    assert_eq!(found, 20);
}

fn by_mu(st: &Study) -> Vec<Vec<&Row>> {
    // groups of rows that differ only in μ, μ ascending
    let s = &st.scenario;
    let layout = Layout::of(s);
    let mut order: Vec<usize> = (0..s.mu.len()).collect();
    order.sort_by(|&a, &b| s.mu[a].total_cmp(&s.mu[b]));
    st.rows
        .iter()
        .filter(|r| r.key.mu == 0)
        .map(|r| {
            order
                .iter()
                .map(|&m| {
                    let mut k = r.key;
                    k.mu = m;
                    &st.rows[layout.index(&k)]
                })
                .collect()
        })
        .collect()
}

#[test]
fn mu_zero_gives_one_surface_and_the_band_widens_with_mu() {
    let st = study(SMALL);
    let groups = by_mu(&st);
    assert!(!groups.is_empty());
    let mut checked = 0;
    for g in groups {
        let mus: Vec<f64> = g.iter().map(|r| st.scenario.params(&r.key).mu).collect();
        assert_eq!(mus, [0.0, 0.25, 0.5, 1.0]);
        let c0 = g[0].cell;
        if c0.lower.is_nan() {
            assert!(g.iter().all(|r| r.cell.lower.is_nan()));
            continue;
        }
        // μ = 0: a single dividing surface L = U = (1 + ε) κ
        assert_eq!(c0.lower, c0.upper);
        assert!(close(c0.lower, 1.5 * c0.kappa, 1e-12));
        for w in g.windows(2) {
            let (a, b) = (w[0].cell, w[1].cell);
            assert!(b.lower < a.lower, "L must fall with μ: {a:?} -> {b:?}");
            assert!(b.upper > a.upper, "U must rise with μ: {a:?} -> {b:?}");
            assert!(b.upper - b.lower > a.upper - a.lower);
        }
        checked += 1;
    }
    assert!(checked > 50);
}

#[test]
fn lcp_agrees_everywhere_and_can_disagree() {
    let st = study(SMALL);
    assert_eq!(st.lcp_disagreements(), 0);
    assert!(st.rows.iter().all(|r| r.cell.lcp_agrees));
    // The check has teeth: moved bounds are caught.
    let r = st
        .rows
        .iter()
        .find(|r| st.scenario.params(&r.key).mu == 0.5 && !r.cell.lower.is_nan())
        .unwrap();
    let c = r.cell;
    let g = Delassus {
        nn: c.g_nn,
        nt: c.g_nt,
        tt: c.g_tt,
    };
    let law = ImpactLaw::new(0.5, 0.5).unwrap();
    assert!(lcp_agrees(&g, &law, c.lower, c.upper));
    assert!(!lcp_agrees(&g, &law, c.lower + 0.01, c.upper));
    assert!(!lcp_agrees(&g, &law, c.lower, c.upper - 0.01));
    // Infinite bounds skip their test; "mid" is the finite bound moved by 1.
    assert_eq!(test_ratios(f64::NEG_INFINITY, 2.0), vec![1.0, 2.0 + 2e-6]);
    assert_eq!(test_ratios(-3.0, f64::INFINITY), vec![-3.0 - 3e-6, -2.0]);
    assert_eq!(test_ratios(-1.0, 3.0).len(), 3);
    // Lemke mode far outside the band
    use pounding::analytic::SlipMode;
    assert_eq!(
        lcp_mode(&g, &law, c.lower - 5.0),
        Some(SlipMode::SlipOutward)
    );
    assert_eq!(
        lcp_mode(&g, &law, c.upper + 5.0),
        Some(SlipMode::SlipInward)
    );
}

#[test]
fn summaries_match_a_recomputation_from_rows() {
    let st = study(SMALL);
    let s = &st.scenario;
    let bl = Layout::of(s).block_len();
    assert_eq!(st.summaries.len(), st.rows.len() / bl);
    for (sum, block) in st.summaries.iter().zip(st.rows.chunks(bl)) {
        let fc: Vec<&Row> = block.iter().filter(|r| r.cell.first_contact).collect();
        assert_eq!(sum.first_contact_cells, fc.len());
        assert_eq!(sum.case, s.params(&block[0].key).case);
        if fc.is_empty() {
            assert!(sum.stick_fraction.is_nan());
            continue;
        }
        let n = fc.len() as f64;
        let mean_stick: f64 = fc
            .iter()
            .map(|r| (r.cell.upper.clamp(-12.0, 12.0) - r.cell.lower.clamp(-12.0, 12.0)) / 24.0)
            .sum::<f64>()
            / n;
        assert!(close(sum.stick_fraction, mean_stick, 1e-12));
        assert!(
            (sum.stick_fraction + sum.outward_fraction + sum.inward_fraction - 1.0).abs() < 1e-12
        );
        let lmin = fc
            .iter()
            .map(|r| r.cell.lower)
            .fold(f64::INFINITY, f64::min);
        assert_eq!(sum.lower_min, lmin);
        let umax = fc
            .iter()
            .map(|r| r.cell.upper)
            .fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(sum.upper_max, umax);
    }
    assert_eq!(shares(-20.0, 20.0, -12.0, 12.0), (0.0, 1.0, 0.0));
    assert_eq!(shares(0.0, 6.0, -12.0, 12.0), (0.5, 0.25, 0.25));
    let json: serde_json::Value = serde_json::from_str(&st.summary_json()).unwrap();
    assert_eq!(
        json["summaries"].as_array().unwrap().len(),
        st.summaries.len()
    );
    assert_eq!(json["lcp_disagreements"], 0);
    assert_eq!(st.summary_csv().lines().count(), st.summaries.len() + 1);
}

#[test]
fn sharded_and_merged_equals_unsharded() {
    let whole = study(SMALL);
    let s = &whole.scenario;
    let n = 3;
    let mut parts = Vec::new();
    for k in (1..=n).rev() {
        let shard = Shard::new(k, n).unwrap();
        let rows = compute_rows(s, shard, &none).unwrap();
        assert!(rows.iter().all(|r| r.index % n == k - 1));
        let csv = shard_rows_csv(s, &rows);
        parts.push(ShardFiles {
            origin: format!("shard{k}"),
            manifest: manifest_json(shard, SMALL, s.row_count(), rows.len(), &csv),
            rows: csv,
        });
    }
    let merged = merge(&parts).unwrap();
    let m = Study::from_rows(merged.scenario_text, merged.scenario, merged.rows);
    assert_eq!(m.bounds_csv(), whole.bounds_csv());
    assert_eq!(m.summary_csv(), whole.summary_csv());
    assert_eq!(m.summary_json(), whole.summary_json());
    // Missing or duplicated shards are errors, not silent gaps.
    let err = merge(&parts[..2]).unwrap_err().to_string();
    assert!(err.contains("missing"), "{err}");
    let dup = vec![parts[0].clone(), parts[0].clone(), parts[1].clone()];
    assert!(merge(&dup).is_err());
    let mut truncated = parts.clone();
    let t = &mut truncated[1].rows;
    let cut = t.trim_end().rfind('\n').unwrap();
    t.truncate(cut + 1);
    // (a truncated rows file is reported by its row count, before its checksum)
    let err = merge(&truncated).unwrap_err().to_string();
    assert!(
        err.contains("shard2/rows.csv") && err.contains("rows but"),
        "{err}"
    );
    assert!(Shard::parse("0/3").is_err());
    assert!(Shard::parse("4/3").is_err());
    assert_eq!(Shard::parse("2/3").unwrap(), Shard::new(2, 3).unwrap());
}

#[test]
fn bytes_do_not_depend_on_the_thread_count() {
    let s = scenario(SMALL);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let st = Study::compute(SMALL.to_string(), s.clone(), &none).unwrap();
            (st.bounds_csv(), st.summary_csv(), st.summary_json())
        })
    };
    assert_eq!(run(1), run(3));
}

#[test]
fn claims_restate_the_paper_with_this_runs_numbers() {
    let st = study(SMALL);
    let claims = st.claims();
    let get = |id: &str| claims.iter().find(|c| c.id == id).unwrap();
    assert_eq!(get("stick-widens-with-mu").verdict, Verdict::Reproduced);
    assert_eq!(get("mu-zero-single-surface").verdict, Verdict::Reproduced);
    // Spec erratum 13: inward slip is not negligible for μ > 0.25.
    assert_eq!(
        get("inward-negligible-mu-gt-0.25").verdict,
        Verdict::Contradicted
    );
    assert_eq!(claims.len(), 7);
    for id in ["deck1-r200-r100-inner-more-stick", "deck2-inner-more-stick"] {
        let c = get(id);
        assert_ne!(c.verdict, Verdict::NotTested, "{c:?}");
        assert!(c.metric.contains("inner") && c.metric.contains("outer"));
    }
    // Without μ = 0 the single-surface claim is not tested.
    let st2 = study(&SMALL.replace("mu = [0.5, 0.0, 1.0, 0.25]", "mu = [0.5]"));
    let c2 = st2.claims();
    assert!(
        c2.iter()
            .all(|c| c.id != "mu-zero-single-surface" || c.verdict == Verdict::NotTested)
    );
    assert!(
        c2.iter()
            .all(|c| c.id != "stick-widens-with-mu" || c.verdict == Verdict::NotTested)
    );
}

mod prop {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

        /// Any shard count, shards given in any rotation: merged rows equal the unsharded rows.
        #[test]
        fn shards_partition_the_rows(n in 1usize..6, rot in 0usize..6, n1 in 1usize..5, n2 in 1usize..5) {
            let text = format!(
                "[decks]\nbeta1_deg = [60.0, 120.0]\nbeta2_deg = [90.0]\nr1_m = [100.0]\nr2_m = [200.0]\n[impact]\nmu = [0.3]\n[grid]\ntheta1_deg = {{ start = -3.0, stop = {}, step = 1.5 }}\ntheta2_deg = {{ start = -2.0, stop = {}, step = 2.0 }}\n",
                -3.0 + 1.5 * (n1 - 1) as f64,
                -2.0 + 2.0 * (n2 - 1) as f64,
            );
            let s = scenario(&text);
            let layout = Layout::of(&s);
            prop_assert_eq!(layout.total(), 2 * 4 * n1 * n2);
            for i in 0..layout.total() {
                prop_assert_eq!(layout.index(&layout.key(i)), i);
            }
            let whole = compute_rows(&s, Shard::ALL, &none).unwrap();
            let mut parts = Vec::new();
            for k in 1..=n {
                let shard = Shard::new(k, n).unwrap();
                let rows = compute_rows(&s, shard, &none).unwrap();
                let csv = shard_rows_csv(&s, &rows);
                parts.push(ShardFiles {
                    origin: format!("s{k}"),
                    manifest: manifest_json(shard, &text, s.row_count(), rows.len(), &csv),
                    rows: csv,
                });
            }
            parts.rotate_left(rot % n);
            let merged = merge(&parts).unwrap();
            prop_assert_eq!(merged.rows.len(), whole.len());
            for (a, b) in merged.rows.iter().zip(&whole) {
                prop_assert_eq!(a.index, b.index);
                prop_assert_eq!(format!("{:?}", a.cell), format!("{:?}", b.cell));
            }
        }
    }
}
