//! The fuzz targets' bodies and oracles, as plain functions of the input bytes.
//!
//! `fuzz_targets/*.rs` wrap each in `fuzz_target!`; the normal test suite includes this file
//! (`crates/pounding/tests/it/fuzz.rs`) and replays every committed regression input and seed
//! through the same functions, so a crash found once stays fixed without libFuzzer.
#![allow(clippy::needless_range_loop)]

use pounding::lcp::{LcpProblem, LcpStatus};

/// Reads structured values from the fuzzer's bytes (zeros once the bytes run out).
pub struct Bytes<'a> {
    data: &'a [u8],
}

impl<'a> Bytes<'a> {
    /// Wraps the input.
    pub fn new(data: &'a [u8]) -> Self {
        Self { data }
    }
    /// Next byte (0 when exhausted).
    pub fn u8(&mut self) -> u8 {
        match self.data.split_first() {
            Some((b, rest)) => {
                self.data = rest;
                *b
            }
            None => 0,
        }
    }
    /// A float drawn to reach every scale: small integers, simple fractions, powers of ten from
    /// 1e-300 to 1e300, zero, tiny denormals, and raw bit patterns (which may be non-finite).
    pub fn f64(&mut self) -> f64 {
        let tag = self.u8();
        let a = self.u8();
        match tag % 8 {
            0 => 0.0,
            1 => a as f64 - 128.0,
            2 => (a as f64 - 128.0) / 16.0,
            3 => {
                let e = (self.u8() as i32 % 61 - 30) * 10;
                let s = if a & 1 == 1 { -1.0 } else { 1.0 };
                s * (1.0 + (a >> 1) as f64 / 16.0) * 10f64.powi(e)
            }
            4 => (a as f64) * 1e-3,
            5 => {
                let mut b = [0u8; 8];
                b[0] = a;
                for x in b.iter_mut().skip(1) {
                    *x = self.u8();
                }
                f64::from_le_bytes(b)
            }
            6 => 1.0 + (a as f64 - 128.0) * 1e-12,
            _ => [
                f64::MIN_POSITIVE,
                5e-324,
                1e-18,
                1e18,
                f64::MAX,
                -1.0,
                1.0,
                0.5,
            ][a as usize % 8],
        }
    }
    /// A finite float within `[lo, hi]` (`lo < hi`, both finite), log-spread when `lo > 0`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let u = (self.u8() as f64 * 256.0 + self.u8() as f64) / 65535.0;
        if lo > 0.0 {
            (lo.ln() + u * (hi.ln() - lo.ln())).exp().clamp(lo, hi)
        } else {
            (lo + u * (hi - lo)).clamp(lo, hi)
        }
    }
    /// The rest of the input.
    pub fn rest(&self) -> &'a [u8] {
        self.data
    }
}

/// Independent check of a solution the solver calls [`LcpStatus::Solved`]: `z` finite and
/// `z ≥ 0`, `w = M z + q` recomputed here with `wᵢ ≥ −tol·sᵢ` and complementarity
/// (`|wᵢ| ≤ tol·sᵢ` wherever `zᵢ > tol·‖z‖∞`), judged in each row's own units by its backward-error
/// scale `sᵢ = |qᵢ| + Σⱼ |Mᵢⱼ| ‖z‖∞` (what `wᵢ` may move when every entry of `z` moves by its
/// rounding, relative to the largest). `tol = 1e-6`, a thousand times looser than the solver's own
/// `1e-9`, so that only a real defect trips it. Panics (a crash for libFuzzer) on failure.
pub fn check_lcp(p: &LcpProblem, status: LcpStatus, z: &[f64]) {
    if status != LcpStatus::Solved {
        return;
    }
    let n = p.dim();
    assert_eq!(z.len(), n, "z has the wrong length");
    let tol = 1e-6;
    let zmax = z.iter().fold(0.0f64, |a, &x| a.max(x.abs()));
    assert!(zmax.is_finite(), "Solved with non-finite z = {z:?}");
    for i in 0..n {
        assert!(z[i] >= 0.0, "Solved with z[{i}] = {} < 0", z[i]);
        let mut w = p.q()[i];
        let (mut row, mut terms) = (0.0, p.q()[i].abs());
        for j in 0..n {
            w += p.m(i, j) * z[j];
            row += p.m(i, j).abs();
            terms += (p.m(i, j) * z[j]).abs();
        }
        // (`Σ|Mᵢⱼ| ‖z‖∞` may overflow where the products do not: then the products' scale)
        let s = match p.q()[i].abs() + row * zmax {
            s if s.is_finite() => s,
            _ => terms,
        };
        // M z overflows: the solver must not have called this solved.
        assert!(
            s.is_finite() && w.is_finite(),
            "Solved but row {i} of M z + q overflows"
        );
        assert!(
            w >= -tol * s,
            "Solved with w[{i}] = {w} < 0 (scale {s}), z = {z:?}"
        );
        if z[i] > tol * zmax {
            assert!(
                w.abs() <= tol * s,
                "Solved with z[{i}] = {} > 0 and w[{i}] = {w} != 0 (scale {s}): z = {z:?}, {p:?}",
                z[i]
            );
        }
    }
}

/// Siconos `.dat`, `LCPSET 1` and `LCPSOL 1` readers; every problem read is solved with Lemke and
/// checked by the oracle of `check_lcp`; `LCPSOL` round-trips through its writer.
pub fn lcp_io(data: &[u8]) {
    lcp_io_impl::run(data)
}

mod lcp_io_impl {
    #[allow(unused_imports)]
    use super::{Bytes, check_lcp};
    use pounding::lcp::{Lemke, LemkeSettings, io};

    pub fn run(data: &[u8]) {
        let Some((&sel, rest)) = data.split_first() else {
            return;
        };
        let Ok(text) = std::str::from_utf8(rest) else {
            return;
        };
        let mut problems = Vec::new();
        match sel % 3 {
            0 => {
                if let Ok(p) = io::parse_siconos(text, "fuzz.dat") {
                    problems.push(p);
                }
            }
            1 => {
                if let Ok(set) = io::parse_lcpset(text, "fuzz.lcpset") {
                    problems.extend(set.into_iter().take(8).map(|e| e.problem));
                }
            }
            _ => {
                if let Ok(sols) = io::parse_lcpsol(text, "fuzz.lcpsol") {
                    let again = io::parse_lcpsol(&io::write_lcpsol(&sols), "again")
                        .expect("the writer's own output must parse");
                    assert_eq!(sols.len(), again.len());
                    for (a, b) in sols.iter().zip(&again) {
                        assert_eq!((a.id, &a.solver, a.solved), (b.id, &b.solver, b.solved));
                        // negative zero is written `0` (float_token): it reads back as +0, the
                        // same value
                        let bits = |v: &[f64]| {
                            v.iter()
                                .map(|x| if *x == 0.0 { 0 } else { x.to_bits() })
                                .collect::<Vec<_>>()
                        };
                        assert_eq!(bits(&a.z), bits(&b.z), "LCPSOL z does not round-trip");
                    }
                }
            }
        }
        let mut lemke = Lemke::new(LemkeSettings::default());
        for p in problems.iter().filter(|p| p.dim() <= 24) {
            let s = lemke.solve(p);
            check_lcp(p, s.status, &s.z);
        }
    }
}

/// Lemke (dynamic and fixed-size kernels) and enumeration on structured random LCPs of every scale;
/// the oracle of `check_lcp` on every `Solved`.
pub fn lcp_solve(data: &[u8]) {
    lcp_solve_impl::run(data)
}

mod lcp_solve_impl {
    #[allow(unused_imports)]
    use super::{Bytes, check_lcp};
    use pounding::lcp::{self, LcpProblem, Lemke, LemkeSettings};

    fn fixed<const N: usize>(p: &LcpProblem, settings: &LemkeSettings) {
        let mut m = [[0.0; N]; N];
        let mut q = [0.0; N];
        for i in 0..N {
            q[i] = p.q()[i];
            for j in 0..N {
                m[i][j] = p.m(i, j);
            }
        }
        let s = lcp::solve_fixed::<N>(&m, &q, settings);
        check_lcp(p, s.status, &s.z);
    }

    pub fn run(data: &[u8]) {
        let mut b = Bytes::new(data);
        let n = 1 + b.u8() as usize % 7;
        let sym = b.u8();
        let mut m = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                m[i * n + j] = if sym & 1 == 1 && j < i {
                    m[j * n + i]
                } else {
                    b.f64()
                };
            }
        }
        let q: Vec<f64> = (0..n).map(|_| b.f64()).collect();
        let Ok(p) = LcpProblem::new(m, q) else {
            return;
        };
        let settings = LemkeSettings::default().with_max_pivots(2000).unwrap();
        let s = Lemke::new(settings.clone()).solve(&p);
        check_lcp(&p, s.status, &s.z);
        match n {
            3 => fixed::<3>(&p, &settings),
            6 => fixed::<6>(&p, &settings),
            _ => {}
        }
        if sym & 2 == 2
            && let Ok(sols) = lcp::enumerate(&p)
        {
            for z in &sols {
                check_lcp(&p, lcp::LcpStatus::Solved, z);
            }
        }
    }
}

/// Ground-motion record readers: PEER `.AT2` and two-column CSV (`g` or `m/s2`). A record read
/// must hold only finite samples at strictly increasing times, and interpolating or resampling it
/// must give finite numbers.
pub fn record(data: &[u8]) {
    record_impl::run(data)
}

mod record_impl {
    #[allow(unused_imports)]
    use super::{Bytes, check_lcp};
    use pounding::ground_motion::{AccelUnits, GroundMotion, Record};

    pub fn run(data: &[u8]) {
        let Some((&sel, rest)) = data.split_first() else {
            return;
        };
        let Ok(text) = std::str::from_utf8(rest) else {
            return;
        };
        let r = match sel % 3 {
            0 => Record::from_at2_str(text, "fuzz.AT2"),
            1 => Record::from_csv_str(text, "fuzz.csv", AccelUnits::G),
            _ => Record::from_csv_str(text, "fuzz.csv", AccelUnits::MetresPerSecondSquared),
        };
        let Ok(r) = r else {
            return;
        };
        let (t, a) = (r.times(), r.values());
        assert!(!t.is_empty() && t.len() == a.len());
        assert!(t.iter().all(|x| x.is_finite()) && a.iter().all(|x| x.is_finite()));
        assert!(t.windows(2).all(|w| w[0] < w[1]), "times must increase");
        assert!(r.pga().is_finite());
        let end = r.end_time();
        assert!(end.is_finite());
        for s in [-1.0, 0.0, 0.25, 0.5, 1.0, 2.0] {
            let v = r.accel(end * s);
            assert!(v.is_finite(), "accel({}) = {v}", end * s);
        }
        if end > 0.0 {
            let n = 64;
            let h = end / n as f64;
            if h > 0.0 {
                let v = r.sample_uniform(h, n);
                assert!(
                    v.iter().all(|x| x.is_finite()),
                    "resampled value not finite"
                );
            }
        }
        let g = GroundMotion {
            along_y: Some(r.clone()),
            scale_y: 1.0,
            along_x: Some(r),
            scale_x: -0.5,
            incidence: 0.3,
        };
        if g.validate().is_ok() {
            let v = g.accel(end * 0.5);
            assert!(v.x.is_finite() && v.y.is_finite());
        }
    }
}

/// The study scenario TOML (`Scenario::from_toml`). A scenario read with at most 256 rows is
/// run, and every claimed-valid number checked: a non-degenerate cell has finite geometry and
/// Delassus entries (`G_NN > 0`) and a stick interval `L ≤ U` (bounds may be infinite in the
/// Painlevé regime, never NaN); a block with first-contact cells has finite shares in `[0, 1]`
/// summing to 1. The CSV/JSON writers and the claim checks must not panic.
pub fn study_toml(data: &[u8]) {
    study_toml_impl::run(data)
}

mod study_toml_impl {
    #[allow(unused_imports)]
    use super::{Bytes, check_lcp};
    use pounding::study::{Scenario, Study};

    pub fn run(data: &[u8]) {
        let Ok(text) = std::str::from_utf8(data) else {
            return;
        };
        let Ok(sc) = Scenario::from_toml(text, "fuzz.toml") else {
            return;
        };
        if sc.row_count() > 256 {
            return;
        }
        let Ok(study) = Study::compute(text.to_string(), sc, &|_| {}) else {
            return;
        };
        super::check_study(&study);
    }
}

/// The simulate model through the library API: `SimModel` (curved, straight or skewed decks,
/// bearings, damping model, abutments), `GroundMotion`, `SimSettings`, validation, the linear
/// system and a short rigid-contact run (≤ 120 steps).
///
/// The simulate scenario TOML itself is parsed in the CLI binary (`cmd_simulate.rs`, with the
/// plotting modules); until it moves into the library (issue 10) this target fuzzes the library
/// pieces the scenario feeds. Each parameter is either drawn within its valid range or, when the
/// input says so, as an arbitrary float (validation must then refuse it or run without panic).
/// Oracle: when every parameter was drawn from its valid range, a run that ends `Completed` or
/// `CompletedWithLcpFailures` has only finite histories, impacts and summary numbers.
pub fn sim_model(data: &[u8]) {
    sim_model_impl::run(data)
}

mod sim_model_impl {
    #[allow(unused_imports)]
    use super::{Bytes, check_lcp};
    use pounding::ground_motion::{GroundMotion, Record};
    use pounding::math::Vector;
    use pounding::pair::SArrangement;
    use pounding::shape::Deck;
    use pounding::shape::{DeckShape, SkewedDeck, StraightDeck};
    use pounding::sim::{
        Bearing, DampingModel, SimAbutment, SimModel, SimProblem, SimSettings, SimStatus, simulate,
    };

    struct Draw<'a> {
        b: Bytes<'a>,
        raw_mask: u64,
        k: u32,
        valid: bool,
    }

    impl Draw<'_> {
        /// A parameter within `[lo, hi]`, or an arbitrary float when the mask bit says so.
        fn p(&mut self, lo: f64, hi: f64) -> f64 {
            let raw = self.k < 64 && (self.raw_mask >> self.k) & 1 == 1;
            self.k += 1;
            if raw {
                self.valid = false;
                self.b.f64()
            } else {
                self.b.range(lo, hi)
            }
        }
    }

    pub fn run(data: &[u8]) {
        let mut b = Bytes::new(data);
        let mode = b.u8();
        // raw floats only when bit 0 of the mode is set (then one parameter in 8 on average)
        let mut raw_mask = 0u64;
        for i in 0..8 {
            let m = b.u8() as u64;
            if mode & 1 == 1 {
                raw_mask |= (m & (m >> 1) & (m >> 2) & 0x11) << (8 * i);
            }
        }
        let mut d = Draw {
            b,
            raw_mask,
            k: 0,
            valid: true,
        };
        let (width, thickness, density) = (d.p(2.0, 20.0), d.p(0.2, 3.0), d.p(500.0, 5000.0));
        let (gap, k1, k2) = (d.p(0.0, 0.2), d.p(1e5, 1e9), d.p(1e5, 1e9));
        let (zeta, mu, eps, seat) = (d.p(0.0, 0.3), d.p(0.0, 1.5), d.p(0.0, 1.0), d.p(0.05, 2.0));
        let mut model = match (mode >> 1) % 3 {
            0 => {
                let deck = |d: &mut Draw| Deck {
                    radius: d.p(20.0, 2000.0),
                    angle: d.p(5.0, 120.0).to_radians(),
                    width,
                    thickness,
                    density,
                };
                let arr = SArrangement {
                    deck1: deck(&mut d),
                    deck2: deck(&mut d),
                };
                SimModel::with_corner_bearings(arr, gap, k1, k2, zeta, mu, eps, seat)
            }
            s => {
                let skew = if s == 2 {
                    d.p(0.0, 60.0).to_radians()
                } else {
                    0.0
                };
                let mk = |d: &mut Draw| {
                    let length = d.p(5.0, 100.0);
                    if s == 1 {
                        DeckShape::Straight(StraightDeck {
                            length,
                            width,
                            thickness,
                            density,
                        })
                    } else {
                        DeckShape::Skewed(SkewedDeck {
                            length,
                            width,
                            skew,
                            thickness,
                            density,
                        })
                    }
                };
                let shapes = [mk(&mut d), mk(&mut d)];
                SimModel::with_shapes(shapes, gap, k1, k2, zeta, mu, eps, seat)
            }
        };
        if (mode >> 3) & 1 == 1 {
            model.damping_model = DampingModel::TranslationalDashpots;
        }
        for k in 0..2 {
            if (mode >> (4 + k)) & 1 == 1 {
                model.abutments[k] = Some(SimAbutment {
                    gap: d.p(0.0, 0.1),
                    seat_length: d.p(0.05, 2.0),
                });
            }
        }
        if (mode >> 6) & 1 == 1 {
            // a custom bearing layout on deck 1: 1 to 4 bearings
            let n = 1 + d.b.u8() as usize % 4;
            model.bearings1 = (0..n)
                .map(|_| Bearing {
                    point: Vector::new(d.p(-10.0, 10.0), d.p(-60.0, 0.0)),
                    stiffness: k1,
                })
                .collect();
        }
        if model.validate().is_err() || model.check().is_err() {
            return;
        }
        let dt_rec = d.p(0.005, 0.05);
        let n_rec = 2 + d.b.u8() as usize % 16;
        let values: Vec<f64> = (0..n_rec).map(|_| d.p(-1.0, 1.0) * 9.80665).collect();
        let Ok(rec) = Record::uniform("fuzz", dt_rec, values) else {
            return;
        };
        let ground = GroundMotion {
            along_y: Some(rec.clone()),
            scale_y: d.p(-3.0, 3.0),
            along_x: ((mode >> 7) & 1 == 1).then_some(rec),
            scale_x: d.p(-3.0, 3.0),
            incidence: d.p(-180.0, 180.0).to_radians(),
        };
        if ground.validate().is_err() {
            return;
        }
        let dt = d.p(2e-4, 5e-3);
        let duration = (d.p(1e-3, 0.1)).min(120.0 * dt.max(0.0));
        let settings = SimSettings {
            dt,
            duration: Some(duration),
            history_stride: 1 + d.b.u8() as usize % 4,
            ..SimSettings::default()
        };
        if settings.validate().is_err() || settings.dt > duration || duration / settings.dt > 200.0
        {
            return;
        }
        let Ok(sol) = simulate(&SimProblem::at_rest(model, ground), &settings) else {
            return;
        };
        if !d.valid
            || !matches!(
                sol.status,
                SimStatus::Completed | SimStatus::CompletedWithLcpFailures
            )
        {
            return;
        }
        super::check_sim(&sol);
    }
}

/// Oracle of a generic impact: the solution has one entry per contact and body; a solved impact
/// (`Solved`, `SolvedByFallback`) carries finite velocities and impulses within the Coulomb cone
/// `Λ_N ≥ 0`, `|Λ_T| ≤ μ Λ_N` (tolerance 1e-6 of the largest impulse of the problem); `NoImpact`
/// carries zero impulses. Panics on failure.
pub fn check_impact(p: &pounding::impact::ImpactProblem, s: &pounding::impact::ImpactSolution) {
    use pounding::impact::ImpactStatus;
    assert_eq!(s.contacts.len(), p.contacts().len());
    assert_eq!(s.bodies.len(), p.bodies().len());
    match s.status {
        ImpactStatus::Solved | ImpactStatus::SolvedByFallback => {
            for (k, b) in s.bodies.iter().enumerate() {
                assert!(
                    b.velocity.x.is_finite() && b.velocity.y.is_finite() && b.omega.is_finite(),
                    "{:?}: body {k} post velocity not finite: {b:?}",
                    s.status
                );
            }
            // impulse scale of the whole problem: rounding noise is judged against it
            let scale = s.contacts.iter().fold(0.0f64, |a, c| {
                a.max(c.normal_impulse.abs())
                    .max(c.tangential_impulse.abs())
            });
            for (c, spec) in s.contacts.iter().zip(p.contacts()) {
                let (n, t) = (c.normal_impulse, c.tangential_impulse);
                assert!(
                    n.is_finite() && t.is_finite(),
                    "{:?}: impulse {c:?}",
                    s.status
                );
                assert!(n >= -1e-9 * scale, "{:?}: Λ_N = {n} < 0", s.status);
                assert!(
                    t.abs() <= spec.law.mu() * n + 1e-6 * scale,
                    "{:?}: |Λ_T| = {} > μ Λ_N = {}",
                    s.status,
                    t.abs(),
                    spec.law.mu() * n
                );
            }
        }
        ImpactStatus::NoImpact => {
            for c in &s.contacts {
                assert_eq!((c.normal_impulse, c.tangential_impulse), (0.0, 0.0));
            }
        }
        // Not trustworthy, and reported so: nothing to check.
        ImpactStatus::Failed | ImpactStatus::IllConditioned => {}
    }
}

/// Oracle of a computed study: a non-degenerate cell has finite `σ`, `G_NN > 0`, `G_NT`, `G_TT`,
/// `κ`, `ϱ` and a stick interval `L ≤ U` (bounds may be infinite in the Painlevé regime, never
/// NaN); a block with first-contact cells has finite shares in `[0, 1]` summing to 1; the CSV/JSON
/// writers and the claim checks do not panic. Panics on failure.
pub fn check_study(study: &pounding::study::Study) {
    for r in &study.rows {
        let c = &r.cell;
        if c.degeneracy.is_some() {
            continue;
        }
        for (name, v) in [
            ("sigma", c.sigma_m),
            ("g_nn", c.g_nn),
            ("g_nt", c.g_nt),
            ("g_tt", c.g_tt),
            ("kappa", c.kappa),
            ("varrho", c.varrho),
        ] {
            assert!(v.is_finite(), "row {}: {name} = {v} (not finite)", r.index);
        }
        assert!(c.g_nn > 0.0, "row {}: G_NN = {} <= 0", r.index, c.g_nn);
        assert!(
            !c.lower.is_nan() && !c.upper.is_nan() && c.lower <= c.upper,
            "row {}: stick interval [{}, {}]",
            r.index,
            c.lower,
            c.upper
        );
    }
    for s in &study.summaries {
        if s.first_contact_cells == 0 {
            continue;
        }
        let f = [s.outward_fraction, s.stick_fraction, s.inward_fraction];
        for x in f {
            assert!(
                x.is_finite() && (-1e-9..=1.0 + 1e-9).contains(&x),
                "share {x}: {s:?}"
            );
        }
        let sum: f64 = f.iter().sum();
        assert!((sum - 1.0).abs() < 1e-6, "shares sum to {sum}: {s:?}");
    }
    let _ = study.bounds_csv();
    let _ = study.summary_csv();
    let _ = study.summary_json();
    let _ = study.claims();
}

/// Oracle of a finished rigid or compliance run that ended `Completed` or
/// `CompletedWithLcpFailures` (callers filter): every history sample, impact record and summary
/// number is finite and every normal impulse `≥ 0`. Panics on failure.
pub fn check_sim(sol: &pounding::sim::bridge::BridgeSolution) {
    let fin = |x: f64| x.is_finite();
    assert!(sol.t.iter().copied().all(fin), "time not finite");
    assert!(
        sol.q.iter().copied().all(fin),
        "{:?} with non-finite q",
        sol.status
    );
    assert!(
        sol.u.iter().copied().all(fin),
        "{:?} with non-finite u",
        sol.status
    );
    assert!(sol.slip.iter().copied().all(fin), "non-finite slip");
    for e in &sol.energy {
        for x in [e.input, e.kinetic, e.potential, e.viscous, e.contact] {
            assert!(
                x.is_finite(),
                "{:?} with non-finite energy {e:?}",
                sol.status
            );
        }
    }
    for i in &sol.impacts {
        // A compliance impact has no instantaneous post-impact velocity: its γ⁺ are NaN by
        // definition (README, compliance outputs); every other field must be finite.
        for x in [
            i.gamma_n_pre,
            i.gamma_t_pre,
            i.impulse_n,
            i.impulse_t,
            i.energy_dissipated,
        ] {
            assert!(
                x.is_finite(),
                "{:?} with non-finite impact {i:?}",
                sol.status
            );
        }
        assert!(i.impulse_n >= 0.0, "negative normal impulse {i:?}");
    }
    let s = &sol.summary;
    let mut v = vec![
        s.peak_seat_displacement,
        s.energy_balance_error,
        s.max_input_energy,
        s.peak_penetration,
    ];
    for j in &s.joints {
        v.extend([j.peak_closing, j.peak_opening, j.peak_slip]);
    }
    v.extend(s.segments.iter().map(|g| g.peak_rotation));
    v.extend(s.seats.iter().map(|e| e.peak_displacement));
    for (k, x) in v.iter().enumerate() {
        assert!(
            x.is_finite(),
            "{:?} with non-finite summary value #{k} = {x}: {s:?}",
            sol.status
        );
    }
}
