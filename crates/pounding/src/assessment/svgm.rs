//! Fragility under spatially variable ground motion against the uniform case.
//!
//! A record set of support-motion entries (each realisation gives every support its own motion,
//! `pounding motion svgm`) has a **uniform counterpart**: the same entries with every support on
//! the entry's `start` motion (its `x`, which also gives its intensity measure). Both run over
//! the same stripes; per limit state and stripe, `svgm_ratio.csv` compares the fraction of runs
//! that exceed it and the fitted probabilities `P_svgm(IM)`, `P_uniform(IM)` and their ratio
//! (`> 1`: the spatial variation makes the limit state more likely at that intensity).

use super::run::RunRow;
use super::study::{Fits, Study};
use crate::math::Real;
use crate::output::float_token;

/// The name of the comparison's table.
pub const SVGM_RATIO: &str = "svgm_ratio.csv";

impl Study {
    /// The uniform counterpart of a study whose record set has support-motion entries (module
    /// doc); `None` when no entry gives the supports their own motions.
    pub fn uniform_counterpart(&self) -> Option<Study> {
        if self.set.records.iter().all(|r| r.supports.is_empty()) {
            return None;
        }
        let mut set = self.set.clone();
        for r in &mut set.records {
            r.supports.clear();
        }
        Some(Study {
            origin: self.origin.clone(),
            setup: self.setup.clone(),
            settings: self.settings.clone(),
            set,
            set_path: self.set_path.clone(),
            limits: self.limits.clone(),
            spec: self.spec,
            period: self.period.clone(),
            code_check: self.code_check.clone(),
            code_check_input: self.code_check_input.clone(),
            hazard: self.hazard.clone(),
        })
    }
}

/// Per stripe: its IM (the median of the runs'), and per limit state the runs that exceeded it
/// and the runs counted.
fn stripe_counts(rows: &[RunRow], limits: usize) -> Vec<(Real, Vec<(usize, usize)>)> {
    let stripes = rows.iter().map(|r| r.stripe + 1).max().unwrap_or(0);
    (0..stripes)
        .map(|b| {
            let mut ims: Vec<Real> = rows
                .iter()
                .filter(|r| r.stripe == b)
                .map(|r| r.im_g)
                .collect();
            ims.sort_by(|a, b| a.total_cmp(b));
            let im = ims.get(ims.len() / 2).copied().unwrap_or(Real::NAN);
            let counts = (0..limits)
                .map(|l| {
                    let got = rows
                        .iter()
                        .filter(|r| r.stripe == b && r.trusted())
                        .filter_map(|r| r.limits[l].0);
                    got.fold((0, 0), |(e, n), x| (e + usize::from(x), n + 1))
                })
                .collect();
            (im, counts)
        })
        .collect()
}

/// `svgm_ratio.csv`: per limit state and stripe, the counts, the fitted probabilities and their
/// ratio under the spatially variable motion (`svgm`) and its uniform counterpart (`uniform`),
/// run over the same stripes.
pub fn svgm_ratio_csv(svgm: (&[RunRow], &Fits), uniform: (&[RunRow], &Fits)) -> String {
    let mut out = String::from(
        "limit_state,stripe,im_g,exceeded_svgm,runs_svgm,fraction_svgm,exceeded_uniform,\
         runs_uniform,fraction_uniform,p_svgm,p_uniform,ratio,theta_svgm_g,beta_svgm,\
         theta_uniform_g,beta_uniform\n",
    );
    let n_lim = svgm.1.rows.len();
    let (cs, cu) = (
        stripe_counts(svgm.0, n_lim),
        stripe_counts(uniform.0, n_lim),
    );
    let cell = |x: Option<Real>| {
        x.filter(|v| v.is_finite())
            .map_or(String::new(), float_token)
    };
    for (l, (fs, fu)) in svgm.1.rows.iter().zip(&uniform.1.rows).enumerate() {
        for (b, ((im, ns), (_, nu))) in cs.iter().zip(&cu).enumerate() {
            let (ps, pu) = (fs.fit.probability(*im), fu.fit.probability(*im));
            let ratio = match (ps, pu) {
                (Some(a), Some(u)) if u > 0.0 => Some(a / u),
                _ => None,
            };
            let frac = |(e, n): (usize, usize)| (n > 0).then(|| e as Real / n as Real);
            let (ts, tu) = (fs.fit.params(), fu.fit.params());
            out += &format!(
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                crate::output::csv_field(&fs.limit_state),
                b + 1,
                float_token(*im),
                ns[l].0,
                ns[l].1,
                cell(frac(ns[l])),
                nu[l].0,
                nu[l].1,
                cell(frac(nu[l])),
                cell(ps),
                cell(pu),
                cell(ratio),
                cell(ts.map(|t| t.0)),
                cell(ts.map(|t| t.1)),
                cell(tu.map(|t| t.0)),
                cell(tu.map(|t| t.1))
            );
        }
    }
    out
}
