//! Reading a store through the spec that made it: the study of one variant as `pounding
//! fragility --from-store --campaign SPEC` fits it ([`Campaign::into_variant_study`]: the
//! campaign's record set and stripes, the variant's own bridge and limit states), and the code
//! check's seats against the stored demands (`pounding check --from-store`, [`seat_exceedance`]).
//!
//! **Seat demand against a code's seat.** A run stores, per seated end, the ratio `r` of the
//! end's peak seat displacement `d` to its provided seat length `N`: `d = r N`. For a seat length
//! `S` — the provided one, or the length a code requires at that end — the run *exceeds* `S` when
//! `d > S`: an end on a seat of length `S` would have lost its support. Per stripe, the fraction
//! of trusted runs that exceed `S` estimates `P(d > S | stripe)`; its interval is Wilson's score
//! interval at 95 % (`z = 1.959964`), which stays inside `[0, 1]` and is not empty at 0 or `n`
//! exceedances. `S = N` gives the unseating fraction of the run itself; `S` = a code's seat tells
//! how often the code's minimum would not have kept the deck on its seat under these motions.

use super::{Campaign, CampaignError, store::Meta};
use crate::assessment::check::Code;
use crate::assessment::run::{Plan, RunRow};
use crate::assessment::study::Study;
use crate::assessment::{CheckReport, check_bridge};
use crate::math::Real;
use crate::output::float_token;
use std::path::Path;

impl Campaign {
    /// The study of variant `variant` (`None`: the only one) of this campaign, as its runs were
    /// made: the campaign's record set, stripes and IM plan with the variant's bridge, limit
    /// states and code check. `store` must be this campaign's store (the fingerprints of
    /// `campaign.json` and of this spec agree), else it is refused.
    pub fn into_variant_study(
        mut self,
        store: &Path,
        variant: Option<&str>,
    ) -> Result<(Study, Plan, String), CampaignError> {
        if !store.exists() {
            return Err(CampaignError::Store(format!(
                "no campaign store at {} (give the --out directory of `pounding campaign run`, \
                 or its runs.parquet)",
                store.display()
            )));
        }
        let dir = if store.is_dir() {
            store.to_path_buf()
        } else {
            match store.parent() {
                Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
                _ => Path::new(".").to_path_buf(),
            }
        };
        let meta = Meta::read(&dir)?;
        if meta.fingerprint != format!("{:016x}", self.fingerprint) {
            return Err(CampaignError::Store(format!(
                "{}: the store holds another campaign (fingerprint {}) than {} ({:016x}): give \
                 the spec that made it, unchanged (its scenario, records, stripes and variants)",
                store.display(),
                meta.fingerprint,
                self.path.display(),
                self.fingerprint
            )));
        }
        let v = match variant {
            None if self.variants.len() == 1 => 0,
            None => {
                return Err(CampaignError::Store(format!(
                    "the campaign has {} variants: name one with --variant ({})",
                    self.variants.len(),
                    shortened(&self.variants)
                )));
            }
            Some(name) => self
                .variants
                .iter()
                .position(|x| x == name)
                .ok_or_else(|| {
                    CampaignError::Store(format!(
                        "no variant {name:?} in {} (it has {})",
                        self.path.display(),
                        shortened(&self.variants)
                    ))
                })?,
        };
        let run = self.variant_runs.swap_remove(v);
        let mut study = self.study;
        if let Some(input) = &study.code_check_input {
            study.code_check = Some(
                check_bridge(&run.setup.problem.model, input, &study.origin)
                    .map_err(|e| e.to_string()),
            );
        }
        study.setup = run.setup;
        study.limits = run.limits;
        Ok((study, self.plan, run.name))
    }
}

/// At most 5 names, then how many more.
pub(super) fn shortened(names: &[String]) -> String {
    let mut s = names.iter().take(5).cloned().collect::<Vec<_>>().join(", ");
    if names.len() > 5 {
        s.push_str(&format!(", … {} more", names.len() - 5));
    }
    s
}

/// Which seat length a row of [`seat_exceedance`] is about.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SeatBasis {
    /// The seat the model provides.
    Provided,
    /// The largest seat the evaluated codes require.
    Governing(Code),
    /// One code's required seat.
    Code(Code),
}

impl SeatBasis {
    /// `provided`, `governing` or the code's key (`ec8`, `aashto-lrfd`, …).
    pub fn label(&self) -> String {
        match self {
            SeatBasis::Provided => "provided".into(),
            SeatBasis::Governing(_) => "governing".into(),
            SeatBasis::Code(c) => c.name().into(),
        }
    }
}

/// One seated end, one seat length, one stripe: how many trusted runs exceeded it.
#[derive(Debug, Clone, PartialEq)]
pub struct SeatExceedance {
    /// The end (`segment2-start`).
    pub end: String,
    /// What it sits on (`joint1`, `abutment-start`, …).
    pub support: String,
    /// Which seat length.
    pub basis: SeatBasis,
    /// The seat length \[m\].
    pub seat_m: Real,
    /// The stripe's index.
    pub stripe: usize,
    /// The stripe's value (`level_g` or `scale`).
    pub stripe_value: Real,
    /// Trusted runs at the stripe (runs not `Completed` are excluded).
    pub runs: usize,
    /// Runs whose peak seat displacement exceeded the seat.
    pub exceeded: usize,
}

/// Wilson's score interval of a binomial proportion `k / n` at 95 % (`(0, 1)` for `n = 0`).
pub fn wilson_95(k: usize, n: usize) -> (Real, Real) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let z: Real = 1.959_963_984_540_054;
    let (all, n, p) = (k == n, n as Real, k as Real / n as Real);
    let z2n = z * z / n;
    let centre = p + z2n / 2.0;
    let half = z * (p * (1.0 - p) / n + z2n / (4.0 * n)).sqrt();
    let d = 1.0 + z2n;
    // exactly 0 at k = 0 and 1 at k = n (the formula's value; rounding would miss it)
    let lo = if k == 0 {
        0.0
    } else {
        ((centre - half) / d).clamp(0.0, p)
    };
    let hi = if all {
        1.0
    } else {
        ((centre + half) / d).clamp(p, 1.0)
    };
    (lo, hi)
}

impl SeatExceedance {
    /// `exceeded / runs` (NaN without runs).
    pub fn fraction(&self) -> Real {
        self.exceeded as Real / self.runs as Real
    }
}

/// The stored demands of `rows` (one variant's runs, in the order of `ends`, the model's
/// [`crate::sim::bridge::BridgeModel::seat_end_names`]) against the seats of `report` (that
/// variant's code check): per seated end, per seat length (provided, governing, each evaluated
/// code), per stripe of `stripes`. Runs that are not trusted are left out of every count.
pub fn seat_exceedance(
    report: &CheckReport,
    ends: &[String],
    rows: &[RunRow],
    stripes: &[Real],
) -> Result<Vec<SeatExceedance>, CampaignError> {
    let mut out = Vec::new();
    for e in &report.ends {
        let Some(k) = ends.iter().position(|n| *n == e.at.end) else {
            return Err(CampaignError::Store(format!(
                "the bridge has no seated end {} (another bridge than the store's?)",
                e.at.end
            )));
        };
        let mut bases = vec![(SeatBasis::Provided, e.at.seat_length)];
        if let Some((code, s)) = e.governing() {
            bases.push((SeatBasis::Governing(code), s));
        }
        bases.extend(
            e.codes
                .iter()
                .filter_map(|(c, r)| r.value().map(|s| (SeatBasis::Code(*c), s))),
        );
        for (basis, seat_m) in bases {
            for (b, &value) in stripes.iter().enumerate() {
                let (mut runs, mut exceeded) = (0, 0);
                for r in rows.iter().filter(|r| r.stripe == b && r.trusted()) {
                    let Some(ratio) = r.seats.get(k) else {
                        return Err(CampaignError::Store(
                            "the store has no seat ratios (its campaign was run with [outputs] \
                             seats = false): there is no seat demand to count"
                                .into(),
                        ));
                    };
                    runs += 1;
                    exceeded += usize::from(ratio * e.at.seat_length > seat_m);
                }
                out.push(SeatExceedance {
                    end: e.at.end.clone(),
                    support: e.at.support.clone(),
                    basis,
                    seat_m,
                    stripe: b,
                    stripe_value: value,
                    runs,
                    exceeded,
                });
            }
        }
    }
    Ok(out)
}

/// `check_store.csv`: one row per seated end, seat length and stripe.
pub fn seat_exceedance_csv(rows: &[SeatExceedance], stripe_column: &str) -> String {
    let mut s = format!(
        "end,support,seat,code,seat_m,stripe,{stripe_column},runs,exceeded,fraction,\
         fraction_lo_95,fraction_hi_95\n"
    );
    for r in rows {
        let code = match r.basis {
            SeatBasis::Provided => String::new(),
            SeatBasis::Governing(c) | SeatBasis::Code(c) => c.name().into(),
        };
        let (lo, hi) = wilson_95(r.exceeded, r.runs);
        let frac = if r.runs == 0 {
            String::new()
        } else {
            float_token(r.fraction())
        };
        s.push_str(&format!(
            "{},{},{},{},{},{},{},{},{},{},{},{}\n",
            r.end,
            r.support,
            r.basis.label(),
            code,
            float_token(r.seat_m),
            r.stripe,
            float_token(r.stripe_value),
            r.runs,
            r.exceeded,
            frac,
            float_token(lo),
            float_token(hi)
        ));
    }
    s
}

/// The printed summary of [`seat_exceedance`]: per seated end, the runs that exceeded the
/// provided seat and the governing code's seat, over every stripe and at the highest.
pub fn seat_exceedance_text(rows: &[SeatExceedance], variant: &str, stripe_column: &str) -> String {
    let mut s = format!(
        "Seat demands of the stored runs (variant {variant}): runs whose peak seat displacement \
         exceeded the provided seat and the governing code's (every code in check_store.csv)\n\
         {:<16} {:<15} {:<10} {:>8}  {:>17}  {:>17}\n",
        "end",
        "support",
        "seat",
        "length",
        "all stripes",
        format!("top {stripe_column}")
    );
    let cell = |k: usize, n: usize| match n {
        0 => "-".to_string(),
        _ => format!("{k}/{n} {:5.1} %", 100.0 * k as Real / n as Real),
    };
    let mut i = 0;
    while i < rows.len() {
        let r = &rows[i];
        let group = rows[i..]
            .iter()
            .take_while(|x| x.end == r.end && x.basis == r.basis)
            .count();
        let g = &rows[i..i + group];
        let show = matches!(r.basis, SeatBasis::Provided | SeatBasis::Governing(_));
        if show {
            let (k, n) = g
                .iter()
                .fold((0, 0), |(k, n), x| (k + x.exceeded, n + x.runs));
            let top = g.last().map_or((0, 0), |x| (x.exceeded, x.runs));
            let label = match r.basis {
                SeatBasis::Governing(c) => c.name().to_string(),
                _ => r.basis.label(),
            };
            s.push_str(&format!(
                "{:<16} {:<15} {:<10} {:>8.3}  {:>17}  {:>17}\n",
                r.end,
                r.support,
                label,
                r.seat_m,
                cell(k, n),
                cell(top.0, top.1)
            ));
        }
        i += group;
    }
    s
}

/// The study whose runs a store holds, as `fragility --from-store` and `check --from-store`
/// read it ([`store_study`]).
pub struct StoreStudy {
    /// The study (with `--campaign`, the variant's bridge, limit states and code check).
    pub study: Study,
    /// Its IM plan, when already computed (with `--campaign`).
    pub plan: Option<Plan>,
    /// The variant to read (resolved to its name with `--campaign`).
    pub variant: Option<String>,
    /// The hash of the base scenario's text, which the store must hold.
    pub scenario_fingerprint: u64,
}

/// The study of `scenario` (read from `scenario_path`) whose runs the store `store` holds: with
/// `campaign` (the spec that made the store), the campaign's record set, stripes and the
/// variant's bridge ([`Campaign::into_variant_study`]; `scenario` must be the spec's scenario);
/// without, the scenario's own study (its record set `set`, else `[fragility] records`).
pub fn store_study(
    scenario: crate::sim::scenario::Scenario,
    scenario_path: &Path,
    set: Option<&Path>,
    store: &Path,
    campaign: Option<&Path>,
    variant: Option<&str>,
) -> Result<StoreStudy, CampaignError> {
    let scenario_fingerprint = super::scenario_fingerprint(scenario.text());
    let Some(spec) = campaign else {
        let study = Study::read(scenario, scenario_path.parent(), set)?;
        return Ok(StoreStudy {
            study,
            plan: None,
            variant: variant.map(str::to_string),
            scenario_fingerprint,
        });
    };
    let c = Campaign::load(spec)?;
    if c.scenario_fingerprint != scenario_fingerprint {
        return Err(CampaignError::Store(format!(
            "{} is not the scenario of the campaign {} (its text differs from the one the \
             campaign names)",
            scenario_path.display(),
            spec.display()
        )));
    }
    let (study, plan, name) = c.into_variant_study(store, variant)?;
    Ok(StoreStudy {
        study,
        plan: Some(plan),
        variant: Some(name),
        scenario_fingerprint,
    })
}

#[cfg(test)]
mod tests {
    use super::wilson_95;

    /// Wilson's interval against values computed by hand from its formula (n = 10, z = 1.96):
    /// k = 3 → (0.107791, 0.603222); and its exact ends at k = 0 and k = n.
    #[test]
    fn wilson_interval() {
        let (lo, hi) = wilson_95(3, 10);
        assert!(
            (lo - 0.107_791).abs() < 1e-5 && (hi - 0.603_222).abs() < 1e-5,
            "{lo} {hi}"
        );
        assert_eq!(wilson_95(0, 10).0, 0.0);
        assert_eq!(wilson_95(10, 10).1, 1.0);
        assert!(wilson_95(10, 10).0 > 0.6 && wilson_95(0, 10).1 < 0.4);
        assert_eq!(wilson_95(0, 0), (0.0, 1.0));
    }
}
