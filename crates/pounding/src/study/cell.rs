//! One cell of the study: a candidate case at `(θ1, θ2)` for one geometry and impact law.
//!
//! For a non-degenerate cell the cell carries the impact configuration's flags and σ (spec §5.3–§5.4),
//! the Delassus matrix `G` (spec §7), `κ = G_NT/G_NN`, `ϱ = G_TT/G_NN`, the stick interval `[L, U]`
//! (spec §9) and whether Lemke's method on the impact LCP (spec §8) reproduces the analytic mode on
//! both sides of and inside `[L, U]` ([`lcp_agrees`]).

use crate::analytic::{self, ImpactLaw, SlipMode};
use crate::contact::Delassus;
use crate::geometry::{ContactCase, Degeneracy, SigmaMode};
use crate::law_check;
use crate::lcp::{self, LcpStatus, LemkeSettings};
use crate::math::Real;
use crate::pair::{DeckPair, SArrangement};

/// The deck geometry of a study configuration. Both kinds are computed by the one pair path
/// ([`DeckPair::configuration`], [`DeckPair::delassus`]); the curved S arrangement is its preset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Geometry {
    /// Two curved decks in the S arrangement (the study's `shape = "curved"`).
    Curved(SArrangement),
    /// Two decks of any shape.
    Pair(DeckPair),
}

impl Geometry {
    /// The general pair of decks (for [`Geometry::Curved`], [`SArrangement::pair`]).
    pub fn pair(&self) -> DeckPair {
        match self {
            Self::Curved(arrangement) => arrangement.pair(),
            Self::Pair(pair) => *pair,
        }
    }
}

/// The computed values of one cell. For a degenerate cell (`degeneracy` is `Some`) both flags are
/// false, every number is NaN and `lcp_agrees` is true (spec §5.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// `θ1 = ±θ2`: the single-impact model does not apply.
    pub degeneracy: Option<Degeneracy>,
    /// The candidate is the real first contact (spec §5.4).
    pub first_contact: bool,
    /// The candidate's end of the joint closes (spec §5.4).
    pub end_closes: bool,
    /// `σ_b` on the struck face \[m\] (+ toward the struck deck's outer corner).
    pub sigma_m: Real,
    /// `G_NN` \[1/kg\] (for the scenario's `ρ t`).
    pub g_nn: Real,
    /// `G_NT` \[1/kg\].
    pub g_nt: Real,
    /// `G_TT` \[1/kg\].
    pub g_tt: Real,
    /// `κ = G_NT/G_NN`.
    pub kappa: Real,
    /// `ϱ = G_TT/G_NN`.
    pub varrho: Real,
    /// Lower stick bound `L` of the pre-impact ratio `r = γ_T⁻/γ_N⁻` (outward slip below).
    pub lower: Real,
    /// Upper stick bound `U` (inward slip above).
    pub upper: Real,
    /// Lemke on the impact LCP gives the analytic mode at the three test ratios.
    pub lcp_agrees: bool,
}

impl Cell {
    /// The degenerate cell: flags false, numbers NaN, `lcp_agrees` true.
    pub fn degenerate(kind: Degeneracy) -> Self {
        let nan = Real::NAN;
        Self {
            degeneracy: Some(kind),
            first_contact: false,
            end_closes: false,
            sigma_m: nan,
            g_nn: nan,
            g_nt: nan,
            g_tt: nan,
            kappa: nan,
            varrho: nan,
            lower: nan,
            upper: nan,
            lcp_agrees: true,
        }
    }
}

/// The degeneracy of the grid point `(θ1, θ2)` in degrees, judged with the tolerance `tol_deg`
/// (the grids are `start + i·step`, so ±θ may differ from an exact mirror by rounding):
/// `|θ1 − θ2| ≤ tol` → parallel faces, `|θ1 + θ2| ≤ tol` → corner meets corner.
pub fn grid_degeneracy(theta1_deg: Real, theta2_deg: Real, tol_deg: Real) -> Option<Degeneracy> {
    crate::geometry::degeneracy_within(theta1_deg, theta2_deg, tol_deg)
}

/// Computes one cell (angles in degrees). Degenerate grid points are detected with
/// [`grid_degeneracy`] (tolerance `tol_deg`) before the geometry is asked.
pub fn compute_cell(
    arrangement: &SArrangement,
    law: &ImpactLaw,
    case: ContactCase,
    theta1_deg: Real,
    theta2_deg: Real,
    sigma_mode: SigmaMode,
    tol_deg: Real,
) -> Cell {
    compute_cell_in(
        &Geometry::Curved(*arrangement),
        law,
        case,
        theta1_deg,
        theta2_deg,
        sigma_mode,
        tol_deg,
    )
}

/// [`compute_cell`] for any [`Geometry`]. The grid test [`grid_degeneracy`] is exact for pairs
/// with equal joint-face half-lengths (every pair a study builds); otherwise the pair's own
/// degeneracy ([`crate::pair::pair_degeneracy`]) also applies.
pub fn compute_cell_in(
    geometry: &Geometry,
    law: &ImpactLaw,
    case: ContactCase,
    theta1_deg: Real,
    theta2_deg: Real,
    sigma_mode: SigmaMode,
    tol_deg: Real,
) -> Cell {
    if let Some(d) = grid_degeneracy(theta1_deg, theta2_deg, tol_deg) {
        return Cell::degenerate(d);
    }
    let (t1, t2) = (theta1_deg.to_radians(), theta2_deg.to_radians());
    let pair = geometry.pair();
    let (config, g) = match pair.configuration_and_delassus(case, t1, t2, sigma_mode) {
        Ok(cg) => cg,
        Err(d) => return Cell::degenerate(d),
    };
    let interval = analytic::stick_interval(&g, law);
    Cell {
        degeneracy: None,
        first_contact: config.first_contact,
        end_closes: config.end_closes,
        sigma_m: config.sigma,
        g_nn: g.nn,
        g_nt: g.nt,
        g_tt: g.tt,
        kappa: g.kappa(),
        varrho: g.varrho(),
        lower: interval.lower,
        upper: interval.upper,
        lcp_agrees: lcp_agrees(&g, law, interval.lower, interval.upper),
    }
}

/// The pre-impact ratios at which [`lcp_agrees`] tests the LCP: `L − 1e-6·max(1,|L|)`, the
/// mid-interval and `U + 1e-6·max(1,|U|)`; an infinite bound's test is skipped, and with one bound
/// infinite "mid" is the finite bound moved 1 into the interval (`U − 1` or `L + 1`).
pub fn test_ratios(lower: Real, upper: Real) -> Vec<Real> {
    let margin = |x: Real| 1e-6 * x.abs().max(1.0);
    let mut out = Vec::with_capacity(3);
    if lower.is_finite() {
        out.push(lower - margin(lower));
    }
    let mid = match (lower.is_finite(), upper.is_finite()) {
        (true, true) => 0.5 * (lower + upper),
        (true, false) => lower + 1.0,
        (false, true) => upper - 1.0,
        (false, false) => 0.0,
    };
    out.push(mid);
    if upper.is_finite() {
        out.push(upper + margin(upper));
    }
    out
}

/// The mode of the Lemke solution of the single-contact impact LCP (spec §8, n = 1) at
/// `γ_N⁻ = −1`, `γ_T⁻ = −r`, or `None` when Lemke does not return a verified solution or the
/// recovered `Λ_T = Λ_TR − μΛ_N`, `γ⁺ = γ⁻ + GΛ` fail the post-solve checks
/// ([`crate::law_check::check_laws`]).
///
/// `M = [[G_NN − μG_NT, G_NT, 0], [G_NT − μG_TT, G_TT, 1], [2μ, −1, 0]]`,
/// `q = ((1+ε_N)γ_N⁻, γ_T⁻, 0)`, unknowns `z = (Λ_N, Λ_TR, γ_TL)`, `w = (ξ_N, γ_TR, Λ_TL)`,
/// `γ_T⁺ = γ_T⁻ + G_TN Λ_N + G_TT Λ_T` recovered from `Λ_T = Λ_TR − μΛ_N` (equal to
/// `γ_TR − γ_TL` up to rounding for a well-conditioned `G`); stick iff `|γ_T⁺| ≤ 1e-9·n` with `n = −γ_N⁻ = 1` (spec §10), outward slip
/// iff `γ_T⁺ > 0`, inward slip iff `γ_T⁺ < 0`.
///
/// The LCP is solved with `G/G_NN` (entries `1, κ, ϱ`): scaling `G` by `c` maps a solution
/// `(Λ_N, Λ_TR, γ_TL)` to `(Λ_N/c, Λ_TR/c, γ_TL)` with the same `w` up to the factor `c` on `Λ_TL`,
/// so the complementarity structure and `γ_T⁺` are unchanged, while the tableau is well scaled
/// (`G` itself is of order 1e-6 1/kg for bridge decks).
pub fn lcp_mode(g: &Delassus, law: &ImpactLaw, ratio: Real) -> Option<SlipMode> {
    let (nn, nt, tt) = (1.0, g.nt / g.nn, g.tt / g.nn);
    let mu = law.mu();
    let gamma_n = -1.0;
    let gamma_t = -ratio;
    let m = [
        [nn - mu * nt, nt, 0.0],
        [nt - mu * tt, tt, 1.0],
        [2.0 * mu, -1.0, 0.0],
    ];
    let q = [(1.0 + law.eps()) * gamma_n, gamma_t, 0.0];
    let sol = lcp::solve_fixed::<3>(&m, &q, &LemkeSettings::default());
    if sol.status != LcpStatus::Solved {
        return None;
    }
    // post-solve check on the recovered velocities γ⁺ = γ⁻ + GΛ (crate::law_check)
    let (ln, lt) = (sol.z[0], sol.z[1] - mu * sol.z[0]);
    let post = [gamma_n + nn * ln + nt * lt, gamma_t + nt * ln + tt * lt];
    let scale = [
        gamma_n.abs() + (nn * ln).abs() + (nt * lt).abs(),
        gamma_t.abs() + (nt * ln).abs() + (tt * lt).abs(),
    ];
    law_check::check_laws(
        std::slice::from_ref(law),
        &[gamma_n, gamma_t],
        &[ln, lt],
        &post,
        &scale,
        &[nn, tt],
    )
    .ok()?;
    // classify on the recovered velocity (what the check verified), not on the LCP's own
    // γ_TR − γ_TL, which can disagree with it for an ill-conditioned G
    let gamma_t_post = post[1];
    let n = -gamma_n;
    Some(if gamma_t_post.abs() <= 1e-9 * n {
        SlipMode::Stick
    } else if gamma_t_post > 0.0 {
        SlipMode::SlipOutward
    } else {
        SlipMode::SlipInward
    })
}

/// True when, at every ratio of [`test_ratios`]`(lower, upper)`, the Lemke mode ([`lcp_mode`])
/// equals the analytic mode ([`analytic::single_impact`]) and the analytic mode is the one the
/// interval predicts (outward slip below `L`, stick inside, inward slip above `U`).
pub fn lcp_agrees(g: &Delassus, law: &ImpactLaw, lower: Real, upper: Real) -> bool {
    test_ratios(lower, upper).into_iter().all(|r| {
        let expected = if r < lower {
            SlipMode::SlipOutward
        } else if r > upper {
            SlipMode::SlipInward
        } else {
            SlipMode::Stick
        };
        let analytic = analytic::single_impact(g, law, -1.0, -r).mode;
        analytic == expected && lcp_mode(g, law, r) == Some(expected)
    })
}

/// One sample of a region map (the paper's Figures 7–8): the striking deck rotates by `θ_a`, the
/// struck deck stays at `θ_b = 0`, so the striking deck's inner corner strikes for `θ_a < 0` and its
/// outer corner for `θ_a > 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionSample {
    /// Rotation of the striking deck \[deg\].
    pub theta_a_deg: Real,
    /// The case at this sample.
    pub case: ContactCase,
    /// The cell (degenerate at `θ_a = 0`).
    pub cell: Cell,
}

/// Region-map samples for the striking deck `deck1_strikes` (else deck 2): `samples` values of `θ_a`
/// spread evenly over `[start, stop]` of that deck's grid range (`θ_a,k = start + k·(stop − start)/(samples − 1)`).
#[allow(clippy::too_many_arguments)]
pub fn region_samples(
    arrangement: &SArrangement,
    law: &ImpactLaw,
    deck1_strikes: bool,
    start_deg: Real,
    stop_deg: Real,
    samples: usize,
    sigma_mode: SigmaMode,
    tol_deg: Real,
) -> Vec<RegionSample> {
    region_samples_in(
        &Geometry::Curved(*arrangement),
        law,
        deck1_strikes,
        start_deg,
        stop_deg,
        samples,
        sigma_mode,
        tol_deg,
    )
}

/// [`region_samples`] for any [`Geometry`].
#[allow(clippy::too_many_arguments)]
pub fn region_samples_in(
    geometry: &Geometry,
    law: &ImpactLaw,
    deck1_strikes: bool,
    start_deg: Real,
    stop_deg: Real,
    samples: usize,
    sigma_mode: SigmaMode,
    tol_deg: Real,
) -> Vec<RegionSample> {
    let n = samples.max(2);
    (0..n)
        .map(|k| {
            let ta = start_deg + k as Real * (stop_deg - start_deg) / (n - 1) as Real;
            let (case, t1, t2) = match (deck1_strikes, ta < 0.0) {
                (true, true) => (ContactCase::Deck1Inner, ta, 0.0),
                (true, false) => (ContactCase::Deck1Outer, ta, 0.0),
                (false, true) => (ContactCase::Deck2Inner, 0.0, ta),
                (false, false) => (ContactCase::Deck2Outer, 0.0, ta),
            };
            RegionSample {
                theta_a_deg: ta,
                case,
                cell: compute_cell_in(geometry, law, case, t1, t2, sigma_mode, tol_deg),
            }
        })
        .collect()
}
