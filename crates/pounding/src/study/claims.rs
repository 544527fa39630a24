//! The paper's results and conclusions, restated next to the metric this run measured for each.
//!
//! Each [`ClaimCheck`] quotes (or paraphrases) a statement of the paper, states the metric computed
//! from this run's rows and summaries, and gives a [`Verdict`]. The metrics are deliberately simple
//! and documented on [`check_claims`], so that a reader can recompute them from `bounds.csv`.

use super::run::{Layout, Row};
use super::scenario::{Scenario, StudyShape};
use super::summary::SummaryRow;
use crate::geometry::ContactCase;
use crate::math::Real;
use nalgebra::{Matrix3, Vector3};

/// How this run's numbers relate to a claim.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Verdict {
    /// The numbers support the claim.
    Reproduced,
    /// The numbers support the claim only in part (the metric says where).
    Partly,
    /// The numbers contradict the claim.
    Contradicted,
    /// The scenario does not contain the data needed (e.g. a single μ).
    NotTested,
}

impl Verdict {
    /// Short label: `reproduced`, `partly`, `contradicted`, `not tested`.
    pub fn label(self) -> &'static str {
        match self {
            Self::Reproduced => "reproduced",
            Self::Partly => "partly reproduced",
            Self::Contradicted => "contradicted",
            Self::NotTested => "not tested by this scenario",
        }
    }
}

/// One claim of the paper with this run's metric.
#[derive(Debug, Clone, PartialEq)]
pub struct ClaimCheck {
    /// Short identifier (`stick-widens-with-mu`, …).
    pub id: &'static str,
    /// The paper's statement (quoted or closely paraphrased) and where it is made.
    pub claim: &'static str,
    /// What was measured, with numbers.
    pub metric: String,
    /// The verdict.
    pub verdict: Verdict,
}

fn pct(x: Real) -> String {
    if x.is_nan() {
        "n/a".into()
    } else {
        format!("{:.1} %", 100.0 * x)
    }
}

/// Cell-weighted mean of `f` over the summaries accepted by `keep`.
fn weighted(
    s: &[SummaryRow],
    keep: impl Fn(&SummaryRow) -> bool,
    f: impl Fn(&SummaryRow) -> Real,
) -> Real {
    let (mut num, mut den) = (0.0, 0.0);
    for r in s.iter().filter(|r| keep(r) && r.first_contact_cells > 0) {
        num += f(r) * r.first_contact_cells as Real;
        den += r.first_contact_cells as Real;
    }
    if den > 0.0 { num / den } else { Real::NAN }
}

/// Fraction of the variance of `z` over `(x, y)` not explained by a least-squares plane
/// `z = a + b x + c y` (`1 − R²`; 0 for a plane, `None` for fewer than 4 points).
pub fn plane_misfit(pts: &[(Real, Real, Real)]) -> Option<Real> {
    if pts.len() < 4 {
        return None;
    }
    let mut a = Matrix3::zeros();
    let mut b = Vector3::zeros();
    for &(x, y, z) in pts {
        let v = Vector3::new(1.0, x, y);
        a += v * v.transpose();
        b += v * z;
    }
    let c = a.lu().solve(&b)?;
    let mean = pts.iter().map(|p| p.2).sum::<Real>() / pts.len() as Real;
    let (mut res, mut tot) = (0.0, 0.0);
    for &(x, y, z) in pts {
        let e = z - (c[0] + c[1] * x + c[2] * y);
        res += e * e;
        tot += (z - mean) * (z - mean);
    }
    Some(if tot <= 1e-300 { 0.0 } else { res / tot })
}

/// Checks the paper's claims against a complete, ordered set of rows and its summaries.
///
/// Metrics:
/// 1. *Stick band widens with μ*: over every non-degenerate cell, for consecutive μ values
///    (ascending), count the pairs where `L` rises or `U` falls (tolerance `1e-12·max(1,|x|)`);
///    also the cell-weighted mean stick share per μ over first-contact cells.
/// 2. *μ = 0 gives one dividing surface*: `max |U − L| / max(1, |L|)` over the μ = 0 cells.
/// 3. *Equal radii vary smoothly (comparatively linear)*: per block (configuration and case) the plane
///    misfit `1 − R²` of `L` and of `U` over the first-contact cells, averaged over blocks with
///    `R1 = R2` and with `R1 ≠ R2`.
/// 4. *Outward slip dominates when deck 1 strikes*: cell-weighted mean outward vs inward share over
///    first-contact cells of the deck-1 cases, per μ > 0.
/// 5. *Inward slip negligible for μ > 0.25* (spec erratum 13): mean and minimum inward share over the
///    first-contact cells with μ > 0.25 ("negligible" taken as below 5 % of the ratio range).
/// 6. *R1 = 200 m, R2 = 100 m, deck 1 strikes: more stick at the inner than at the outer corner*:
///    cell-weighted mean stick share of `deck1-inner` vs `deck1-outer`, per μ > 0.
/// 7. *More stick when deck 2's inner corner is in contact*: `deck2-inner` vs `deck2-outer`, per μ > 0.
///
/// For straight and skew studies every verdict is [`Verdict::NotTested`] (the paper's statements
/// concern curved decks); the metrics are still computed and labelled with the shape.
pub fn check_claims(
    scenario: &Scenario,
    rows: &[Row],
    summaries: &[SummaryRow],
) -> Vec<ClaimCheck> {
    let mut mus: Vec<(usize, Real)> = scenario.mu.iter().copied().enumerate().collect();
    mus.sort_by(|a, b| a.1.total_cmp(&b.1));
    let run = Run {
        scenario,
        rows,
        summaries,
        layout: Layout::of(scenario),
        mus,
    };
    CLAIMS
        .iter()
        .map(|c| {
            let (metric, verdict) = (c.measure)(&run);
            if scenario.shape == StudyShape::Curved {
                ClaimCheck {
                    id: c.id,
                    claim: c.claim,
                    metric,
                    verdict,
                }
            } else {
                // The paper's statements concern two curved decks; the metrics are still shown.
                ClaimCheck {
                    id: c.id,
                    claim: c.claim,
                    metric: format!(
                        "{} decks (the paper studies curved decks; metric for reference only): {metric}",
                        scenario.shape.name()
                    ),
                    verdict: Verdict::NotTested,
                }
            }
        })
        .collect()
}

/// What a claim's metric reads: the run's scenario, rows and summaries, with the μ values
/// sorted ascending (`(index in scenario.mu, value)`).
struct Run<'a> {
    scenario: &'a Scenario,
    rows: &'a [Row],
    summaries: &'a [SummaryRow],
    layout: Layout,
    mus: Vec<(usize, Real)>,
}

impl Run<'_> {
    /// The μ values above zero, ascending.
    fn positive_mus(&self) -> impl Iterator<Item = Real> + '_ {
        self.mus.iter().map(|&(_, m)| m).filter(|&m| m > 0.0)
    }
}

/// One entry of the claims table: the paper's statement and the function measuring it on a run
/// (returning the metric text and the verdict its rule gives).
struct Claim {
    id: &'static str,
    claim: &'static str,
    measure: fn(&Run) -> (String, Verdict),
}

/// The paper's claims, in report order (metrics 1–7 of [`check_claims`]).
const CLAIMS: &[Claim] = &[
    Claim {
        id: "stick-widens-with-mu",
        claim: "\"The increase in stick region is obvious with the increase in the coefficient of friction\" (results, Figures 3–6).",
        measure: stick_widens_with_mu,
    },
    Claim {
        id: "mu-zero-single-surface",
        claim: "Without friction (μ = 0) the lower and upper stick surfaces coincide: one dividing surface separates outward from inward slip (Figures 3–6, μ = 0 panels).",
        measure: mu_zero_single_surface,
    },
    Claim {
        id: "equal-radii-smooth",
        claim: "\"A comparatively linear variation, between the outward and inward slip, for both inner and outer point impacts is observed for all the cases, when the radii of both the decks are equal.\" (results)",
        measure: equal_radii_smooth,
    },
    Claim {
        id: "outward-dominates-deck1",
        claim: "When deck 1 strikes deck 2, outward slip (the lower part of the γ_T⁻/γ_N⁻ axis) dominates the post-impact behaviour (Figure 7 and its discussion).",
        measure: outward_dominates_deck1,
    },
    Claim {
        id: "inward-negligible-mu-gt-0.25",
        claim: "\"The validity of inward slip is negligible when the coefficient of friction is greater than 0.25.\" (conclusions; see docs/guide/model.md, where this differs from the paper)",
        measure: inward_negligible,
    },
    Claim {
        id: "deck1-r200-r100-inner-more-stick",
        claim: "\"A unique feature is observed at the instance of deck-1 hitting deck-2, when the radius of deck-1 is 200m and that of deck-2 is 100m, where the amount stick region is more when the inner point of deck-1 is in contact and gradually decreases when the outer point is in impact.\" (results)",
        measure: deck1_r200_r100_inner_more_stick,
    },
    Claim {
        id: "deck2-inner-more-stick",
        claim: "\"Variations in the stick regions can be observed with the amount of stick region being more when the inner point of deck-2 is in contact with the contour of deck-1.\" (results, Figures 5–6)",
        measure: deck2_inner_more_stick,
    },
];

/// The verdict rule of the per-μ comparisons (claims 4, 6, 7): reproduced when the comparison
/// holds for every tested μ, contradicted when for none, partly otherwise.
fn per_mu_verdict(yes: usize, tested: usize) -> Verdict {
    if tested == 0 {
        Verdict::NotTested
    } else if yes == tested {
        Verdict::Reproduced
    } else if yes == 0 {
        Verdict::Contradicted
    } else {
        Verdict::Partly
    }
}

/// Metric 1: `L` falls and `U` rises with μ in every cell.
fn stick_widens_with_mu(run: &Run) -> (String, Verdict) {
    let (scenario, rows, mus) = (run.scenario, run.rows, &run.mus);
    let (mut pairs, mut bad) = (0usize, 0usize);
    if mus.len() >= 2 {
        for r in rows.iter().filter(|r| r.key.mu == mus[0].0) {
            let mut prev = r.cell;
            for &(m, _) in &mus[1..] {
                let mut k = r.key;
                k.mu = m;
                let c = rows[run.layout.index(&k)].cell;
                if !(c.lower.is_nan() || prev.lower.is_nan()) {
                    pairs += 1;
                    let tl = 1e-12 * prev.lower.abs().max(1.0);
                    let tu = 1e-12 * prev.upper.abs().max(1.0);
                    if c.lower > prev.lower + tl || c.upper < prev.upper - tu {
                        bad += 1;
                    }
                }
                prev = c;
            }
        }
    }
    let per_mu: Vec<String> = mus
        .iter()
        .map(|&(_, m)| {
            format!(
                "μ = {m}: {}",
                pct(weighted(run.summaries, |s| s.mu == m, |s| s.stick_fraction))
            )
        })
        .collect();
    let verdict = if mus.len() < 2 || pairs == 0 {
        Verdict::NotTested
    } else if bad == 0 {
        Verdict::Reproduced
    } else {
        Verdict::Contradicted
    };
    let metric = format!(
        "L falls and U rises with μ in every cell: {bad} violations in {pairs} consecutive-μ comparisons. Mean stick share of the ratio range [{}, {}] over first-contact cells: {}.",
        scenario.ratio_min,
        scenario.ratio_max,
        per_mu.join("; ")
    );
    (metric, verdict)
}

/// Metric 2: `max |U − L| / max(1, |L|)` over the μ = 0 cells.
fn mu_zero_single_surface(run: &Run) -> (String, Verdict) {
    let zero = run.scenario.mu.iter().position(|&m| m == 0.0);
    let (mut n, mut worst) = (0usize, 0.0 as Real);
    if let Some(z) = zero {
        for r in run
            .rows
            .iter()
            .filter(|r| r.key.mu == z && !r.cell.lower.is_nan())
        {
            n += 1;
            let d = (r.cell.upper - r.cell.lower).abs() / r.cell.lower.abs().max(1.0);
            worst = worst.max(d);
        }
    }
    if n == 0 {
        return ("μ = 0 is not in this scenario.".into(), Verdict::NotTested);
    }
    let verdict = if worst <= 1e-12 {
        Verdict::Reproduced
    } else {
        Verdict::Contradicted
    };
    (
        format!(
            "max |U − L| / max(1, |L|) over {n} non-degenerate μ = 0 cells: {worst:.3e} (the surface is r₀ = (1+ε_N) G_NT/G_NN)."
        ),
        verdict,
    )
}

/// Metric 3: plane misfit of `L` and `U` per block, equal vs unequal radii.
fn equal_radii_smooth(run: &Run) -> (String, Verdict) {
    let scenario = run.scenario;
    let bl = run.layout.block_len();
    let (mut eq, mut ne) = ([0.0 as Real; 2], [0.0 as Real; 2]);
    let (mut neq, mut nne) = (0usize, 0usize);
    for block in run.rows.chunks(bl) {
        let p = scenario.params(&block[0].key);
        let pts = |f: fn(&Row) -> Real| -> Vec<(Real, Real, Real)> {
            block
                .iter()
                .filter(|r| r.cell.first_contact && f(r).is_finite())
                .map(|r| {
                    let q = scenario.params(&r.key);
                    (q.theta1_deg, q.theta2_deg, f(r))
                })
                .collect()
        };
        let (Some(ml), Some(mu)) = (
            plane_misfit(&pts(|r| r.cell.lower)),
            plane_misfit(&pts(|r| r.cell.upper)),
        ) else {
            continue;
        };
        if p.r1_m == p.r2_m {
            eq[0] += ml;
            eq[1] += mu;
            neq += 1;
        } else {
            ne[0] += ml;
            ne[1] += mu;
            nne += 1;
        }
    }
    if neq == 0 || nne == 0 {
        let metric = format!(
            "needs blocks with equal and with unequal radii (have {neq} and {nne} with at least 4 first-contact cells)."
        );
        return (metric, Verdict::NotTested);
    }
    let e = [eq[0] / neq as Real, eq[1] / neq as Real];
    let u = [ne[0] / nne as Real, ne[1] / nne as Real];
    // "Comparatively linear" for equal radii needs a clear difference: at least 20 % less misfit.
    let better = (e[0] < 0.8 * u[0]) as u8 + (e[1] < 0.8 * u[1]) as u8;
    let verdict = match better {
        2 => Verdict::Reproduced,
        1 => Verdict::Partly,
        _ => Verdict::Contradicted,
    };
    let metric = format!(
        "Plane misfit 1 − R² of the surfaces over first-contact cells (0 = exactly planar), mean over blocks: R1 = R2 ({neq} blocks): L {:.4}, U {:.4}; R1 ≠ R2 ({nne} blocks): L {:.4}, U {:.4}. The claim needs equal radii to be clearly (≥ 20 %) more linear; {}.",
        e[0],
        e[1],
        u[0],
        u[1],
        match better {
            2 => "they are, for both surfaces",
            1 => "that holds for one surface only",
            _ =>
                "equal and unequal radii are about equally (non)linear, so the distinction the paper draws is not borne out",
        }
    );
    (metric, verdict)
}

/// Metric 4: outward vs inward share over deck-1 first-contact cells, per μ > 0.
fn outward_dominates_deck1(run: &Run) -> (String, Verdict) {
    let deck1 =
        |s: &SummaryRow| matches!(s.case, ContactCase::Deck1Inner | ContactCase::Deck1Outer);
    let mut parts = Vec::new();
    let (mut yes, mut tested) = (0, 0);
    for m in run.positive_mus() {
        let o = weighted(
            run.summaries,
            |s| deck1(s) && s.mu == m,
            |s| s.outward_fraction,
        );
        let i = weighted(
            run.summaries,
            |s| deck1(s) && s.mu == m,
            |s| s.inward_fraction,
        );
        if o.is_nan() {
            continue;
        }
        tested += 1;
        if o > i {
            yes += 1;
        }
        parts.push(format!("μ = {m}: outward {} vs inward {}", pct(o), pct(i)));
    }
    let metric = if parts.is_empty() {
        "no μ > 0 with deck-1 first-contact cells in this scenario.".into()
    } else {
        format!(
            "Mean share of the ratio range [{}, {}] over deck-1 first-contact cells: {}.",
            run.scenario.ratio_min,
            run.scenario.ratio_max,
            parts.join("; ")
        )
    };
    (metric, per_mu_verdict(yes, tested))
}

/// Metric 5: mean and minimum inward share over the first-contact cells with μ > 0.25.
fn inward_negligible(run: &Run) -> (String, Verdict) {
    let scenario = run.scenario;
    let mean = weighted(run.summaries, |s| s.mu > 0.25, |s| s.inward_fraction);
    let (mut min_cell, mut max_u) = (Real::INFINITY, Real::NEG_INFINITY);
    for r in run.rows {
        let p = scenario.params(&r.key);
        if p.mu > 0.25 && r.cell.first_contact {
            let (_, _, i) = super::summary::shares(
                r.cell.lower,
                r.cell.upper,
                scenario.ratio_min,
                scenario.ratio_max,
            );
            min_cell = min_cell.min(i);
            max_u = max_u.max(r.cell.upper);
        }
    }
    if mean.is_nan() {
        return (
            "no μ > 0.25 with first-contact cells in this scenario.".into(),
            Verdict::NotTested,
        );
    }
    let verdict = if min_cell >= 0.05 {
        Verdict::Contradicted
    } else if mean < 0.05 {
        Verdict::Reproduced
    } else {
        Verdict::Partly
    };
    let metric = format!(
        "Over first-contact cells with μ > 0.25: inward slip (r > U) takes on average {} of the ratio range [{}, {}], at least {} in every cell; the largest U is {:.3}. \"Negligible\" would mean below 5 %.",
        pct(mean),
        scenario.ratio_min,
        scenario.ratio_max,
        pct(min_cell),
        max_u
    );
    (metric, verdict)
}

/// Metric 6: deck 1 strikes, R1 = 200 m, R2 = 100 m: inner vs outer corner stick share.
fn deck1_r200_r100_inner_more_stick(run: &Run) -> (String, Verdict) {
    corner_stick(
        run,
        ContactCase::Deck1Inner,
        ContactCase::Deck1Outer,
        Some((200.0, 100.0)),
    )
}

/// Metric 7: deck 2 strikes: inner vs outer corner stick share.
fn deck2_inner_more_stick(run: &Run) -> (String, Verdict) {
    corner_stick(run, ContactCase::Deck2Inner, ContactCase::Deck2Outer, None)
}

/// Cell-weighted mean stick share of the `inner` vs the `outer` case per μ > 0 (restricted to
/// the radii `(R1, R2)` when given).
fn corner_stick(
    run: &Run,
    inner: ContactCase,
    outer: ContactCase,
    radii: Option<(Real, Real)>,
) -> (String, Verdict) {
    let geom_ok = |r: &SummaryRow| radii.is_none_or(|(a, b)| r.r1_m == a && r.r2_m == b);
    let mut parts = Vec::new();
    let (mut yes, mut tested) = (0, 0);
    for m in run.positive_mus() {
        let share = |case| {
            weighted(
                run.summaries,
                |r| geom_ok(r) && r.mu == m && r.case == case,
                |r| r.stick_fraction,
            )
        };
        let (si, so) = (share(inner), share(outer));
        if si.is_nan() || so.is_nan() {
            continue;
        }
        tested += 1;
        if si > so {
            yes += 1;
        }
        parts.push(format!("μ = {m}: inner {} vs outer {}", pct(si), pct(so)));
    }
    let metric = if parts.is_empty() {
        "the scenario has no such cells with μ > 0.".into()
    } else {
        format!(
            "Mean stick share of the ratio range over first-contact cells{}: {}.",
            if radii.is_some() {
                " with R1 = 200 m, R2 = 100 m"
            } else {
                ""
            },
            parts.join("; ")
        )
    };
    (metric, per_mu_verdict(yes, tested))
}
