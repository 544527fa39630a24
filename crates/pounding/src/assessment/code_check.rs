//! Code checks of seat width and joint gap: the minimum seat (overlap) length of a seated end
//! and the joint gap required to avoid pounding, by the formulas of the design codes.
//!
//! All inputs and outputs are SI (metres, m/s², degrees at the interface only for skew and
//! subtended angles). Formulas written in US customary units (AASHTO, Caltrans) are evaluated
//! in inches and feet exactly as printed and converted back (1 in = 0.0254 m, 1 ft = 0.3048 m).
//!
//! | Code | Clause | Formula |
//! |---|---|---|
//! | Eurocode 8-2 | EN 1998-2 §6.6.4 | `l_ov = l_m + d_eg + d_es`, `d_eg = ε_s L_eff ≤ 2 d_g`, `ε_s = 2 d_g / L_g`; at an intermediate separation joint (§6.6.4(4)) `√(l_ov,1² + l_ov,2²)` of the two deck sections |
//! | AASHTO LRFD | 4.7.4.4 | `N = (8 + 0.02 L + 0.08 H)(1 + 0.000125 S²)` in, times the zone percentage |
//! | AASHTO Guide Spec | 4.12.2 (SDC A–C), 4.12.3 (SDC D) | as LRFD with SDC percentage; `N = (4 + 1.65 Δ_eq)(1 + 0.00025 S²) ≥ 24` in |
//! | Caltrans SDC 1.7 | 7.2.5.4 (hinge), 7.8.3 (abutment) | `N = Δ_p/s + Δ_cr+sh + Δ_temp + Δ_eq + 4` in, `≥ 24` in (hinge), `≥ 30` in (abutment) |
//! | JRA V (2002) | 16.2 | `S_E = u_R + u_G ≥ S_EM = 0.7 + 0.005 l` m, `u_G = ε_G L`; skew `S_Eθ = (L_θ/2)(sin θ − sin(θ − α_E))` |
//!
//! The required gap between two adjacent frames with peak displacements `u₁`, `u₂` is
//! `g_SRSS = √(u₁² + u₂²)` or, by the double-difference (CQC) rule,
//! `g_DDC = √(u₁² + u₂² − 2 ρ₁₂ u₁ u₂)` with the CQC correlation of two equally damped modes
//! `ρ₁₂ = 8 ξ² (1 + r) r^{3/2} / ((1 − r²)² + 4 ξ² r (1 + r)²)`, `r = T₂/T₁` (Der Kiureghian 1981).
//! See the guide page `docs/guide/check.md` for every input and clause.

use thiserror::Error;

mod codes;
mod gap;
pub use codes::{CODES, Code};
pub use gap::{cqc_rho, gap_ddc, gap_srss};

const INCH: f64 = 0.0254;
const FOOT: f64 = 0.3048;

/// A code-check input outside its range (the caller adds file, key and line).
#[derive(Debug, Error, PartialEq)]
pub enum CodeCheckError {
    /// A quantity that must be finite and non-negative (or positive) is not.
    #[error("`{key}` must be {what}, got {value}")]
    OutOfRange {
        /// The input's key in the `[code_check]` table.
        key: &'static str,
        /// What the value must be.
        what: &'static str,
        /// The value given.
        value: f64,
    },
}

/// `value` if it is finite and `ok`, else an error naming `key` and `what` it must be.
fn within(
    key: &'static str,
    value: f64,
    ok: bool,
    what: &'static str,
) -> Result<f64, CodeCheckError> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(CodeCheckError::OutOfRange { key, what, value })
    }
}

fn non_negative(key: &'static str, value: f64) -> Result<f64, CodeCheckError> {
    within(key, value, value >= 0.0, "a finite number ≥ 0")
}

fn positive(key: &'static str, value: f64) -> Result<f64, CodeCheckError> {
    within(key, value, value > 0.0, "a finite number > 0")
}

fn angle(key: &'static str, deg: f64) -> Result<f64, CodeCheckError> {
    let ok = (0.0..90.0).contains(&deg.abs());
    within(key, deg, ok, "an angle in degrees with |value| < 90").map(f64::abs)
}

/// Ground type of EN 1998-1 §3.1.2 (Table 3.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroundType {
    /// Rock.
    A,
    /// Very dense sand, gravel or very stiff clay.
    B,
    /// Dense or medium-dense sand, gravel or stiff clay.
    C,
    /// Loose-to-medium cohesionless soil or soft-to-firm cohesive soil.
    D,
    /// Surface alluvium over stiffer material.
    E,
}

/// Spectrum type of EN 1998-1 §3.2.2.2 (type 1: M_s > 5.5; type 2: M_s ≤ 5.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpectrumType {
    /// Type 1 (Table 3.2).
    Type1,
    /// Type 2 (Table 3.3).
    Type2,
}

impl GroundType {
    /// `(S, T_C, T_D)` of EN 1998-1 Tables 3.2 (type 1) and 3.3 (type 2), recommended values.
    pub fn spectrum_params(self, spectrum: SpectrumType) -> (f64, f64, f64) {
        use GroundType::*;
        match (spectrum, self) {
            (SpectrumType::Type1, A) => (1.0, 0.4, 2.0),
            (SpectrumType::Type1, B) => (1.2, 0.5, 2.0),
            (SpectrumType::Type1, C) => (1.15, 0.6, 2.0),
            (SpectrumType::Type1, D) => (1.35, 0.8, 2.0),
            (SpectrumType::Type1, E) => (1.4, 0.5, 2.0),
            (SpectrumType::Type2, A) => (1.0, 0.25, 1.2),
            (SpectrumType::Type2, B) => (1.35, 0.25, 1.2),
            (SpectrumType::Type2, C) => (1.5, 0.25, 1.2),
            (SpectrumType::Type2, D) => (1.8, 0.3, 1.2),
            (SpectrumType::Type2, E) => (1.6, 0.25, 1.2),
        }
    }

    /// Distance `L_g` (m) beyond which ground motions are uncorrelated, EN 1998-2 §3.3(6)
    /// Table 3.1N: A 600, B 500, C 400, D 300, E 500.
    pub fn l_g(self) -> f64 {
        match self {
            GroundType::A => 600.0,
            GroundType::B => 500.0,
            GroundType::C => 400.0,
            GroundType::D => 300.0,
            GroundType::E => 500.0,
        }
    }
}

/// Importance factor `γ_I` of a bridge, EN 1998-2 §2.1(6) recommended values: class I 0.85,
/// class II 1.0, class III 1.3. `class` outside 1–3 is an error.
pub fn ec8_importance_factor(class: u8) -> Result<f64, CodeCheckError> {
    match class {
        1 => Ok(0.85),
        2 => Ok(1.0),
        3 => Ok(1.3),
        _ => Err(CodeCheckError::OutOfRange {
            key: "importance_class",
            what: "1, 2 or 3",
            value: f64::from(class),
        }),
    }
}

/// Inputs of the EN 1998-2 §6.6.4 minimum overlap length.
#[derive(Debug, Clone, PartialEq)]
pub struct Ec8Seat {
    /// Ground type.
    pub ground: GroundType,
    /// Spectrum type.
    pub spectrum: SpectrumType,
    /// Reference peak ground acceleration on type A ground `a_gR` (m/s²).
    pub a_gr: f64,
    /// Importance class (1–3).
    pub importance_class: u8,
    /// Effective length `L_eff` (m): distance from the deck joint to the nearest full connection
    /// of deck to substructure (§6.6.4(3)).
    pub l_eff: f64,
    /// Design seismic displacement `d_Ed` of the deck at the support (m), `d_es` of §6.6.4(3)
    /// for a monolithic or bearing-supported deck (the user's analysis, or the simulated peak).
    pub d_ed: f64,
    /// Minimum support length securing the transmission of the vertical reaction `l_m`
    /// (m), not less than 0.40 m (§6.6.4(3)).
    pub l_m: f64,
    /// Factor on `d_eg` for a site near a seismically active fault (1 elsewhere): the user's
    /// site-specific value, stated in the report.
    pub near_fault_factor: f64,
}

/// Terms of the EN 1998-2 §6.6.4 overlap length (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8SeatResult {
    /// Design ground displacement `d_g = 0.025 a_g S T_C T_D` (EN 1998-1 §3.2.2.4(1)).
    pub d_g: f64,
    /// Relative ground displacement `d_eg = ε_s L_eff ≤ 2 d_g`, times the near-fault factor.
    pub d_eg: f64,
    /// Deck displacement term `d_es`.
    pub d_es: f64,
    /// Support length `l_m` (≥ 0.40 m).
    pub l_m: f64,
    /// Overlap length `l_ov = l_m + d_eg + d_es`.
    pub l_ov: f64,
}

/// Minimum overlap length by EN 1998-2 §6.6.4:
/// `l_ov = l_m + d_eg + d_es`, `d_eg = ε_s L_eff ≤ 2 d_g`, `ε_s = 2 d_g / L_g`,
/// `d_g = 0.025 a_g S T_C T_D` (EN 1998-1 §3.2.2.4), `a_g = γ_I a_gR`.
pub fn ec8_seat(input: &Ec8Seat) -> Result<Ec8SeatResult, CodeCheckError> {
    let a_gr = non_negative("a_gR", input.a_gr)?;
    let l_eff = non_negative("l_eff_m", input.l_eff)?;
    let d_es = non_negative("d_ed_m", input.d_ed)?;
    let l_m = non_negative("l_m_m", input.l_m)?.max(0.40);
    let factor = positive("near_fault_factor", input.near_fault_factor)?;
    let a_g = ec8_importance_factor(input.importance_class)? * a_gr;
    let (s, t_c, t_d) = input.ground.spectrum_params(input.spectrum);
    let d_g = 0.025 * a_g * s * t_c * t_d;
    let eps_s = 2.0 * d_g / input.ground.l_g();
    let d_eg = (eps_s * l_eff).min(2.0 * d_g) * factor;
    Ok(Ec8SeatResult {
        d_g,
        d_eg,
        d_es,
        l_m,
        l_ov: l_m + d_eg + d_es,
    })
}

/// Terms of the EN 1998-2 §6.6.4(4) overlap length at an intermediate separation joint (m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8JointSeatResult {
    /// Expression (6.11) of each deck section alone, in the order given.
    pub sections: [Ec8SeatResult; 2],
    /// `l_ov = √(l_ov,1² + l_ov,2²)`.
    pub l_ov: f64,
}

/// Minimum overlap length at an intermediate separation joint between two deck sections by
/// EN 1998-2 §6.6.4(4): the square root of the sum of squares of expression (6.11)
/// (`l_ov = l_m + d_eg + d_es`, [`ec8_seat`]) evaluated for each section separately, each with
/// its own `L_eff` (the distance from the joint to the furthest end of that section) and its own
/// `d_es`: `l_ov = √(l_ov,1² + l_ov,2²)`.
pub fn ec8_joint_seat(sections: [&Ec8Seat; 2]) -> Result<Ec8JointSeatResult, CodeCheckError> {
    let [a, b] = [ec8_seat(sections[0])?, ec8_seat(sections[1])?];
    Ok(Ec8JointSeatResult {
        sections: [a, b],
        l_ov: a.l_ov.hypot(b.l_ov),
    })
}

/// Base empirical seat width of AASHTO LRFD 4.7.4.4 (eq. 4.7.4.4-1), in metres:
/// `N = (8 + 0.02 L + 0.08 H)(1 + 0.000125 S²)` inches, with `L` the length of the deck to the
/// adjacent expansion joint or end (ft), `H` the average column height (ft), `S` the skew (deg).
pub fn aashto_base_seat(l: f64, h: f64, skew_deg: f64) -> Result<f64, CodeCheckError> {
    let l_ft = non_negative("l_deck_m", l)? / FOOT;
    let h_ft = non_negative("pier_height_m", h)? / FOOT;
    let s = angle("skew_deg", skew_deg)?;
    Ok((8.0 + 0.02 * l_ft + 0.08 * h_ft) * (1.0 + 0.000125 * s * s) * INCH)
}

/// Seismic zone of AASHTO LRFD 3.10.6.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AashtoZone {
    /// Zone 1 (`S_D1 ≤ 0.15`).
    Z1,
    /// Zone 2.
    Z2,
    /// Zone 3.
    Z3,
    /// Zone 4.
    Z4,
}

/// Percentage of `N` of AASHTO LRFD Table 4.7.4.4-1: zone 1 with `A_s < 0.05`: 75 %; zone 1
/// with `A_s ≥ 0.05`: 100 %; zones 2–4: 150 %.
pub fn aashto_lrfd_percentage(zone: AashtoZone, a_s: f64) -> f64 {
    match zone {
        AashtoZone::Z1 if a_s < 0.05 => 0.75,
        AashtoZone::Z1 => 1.0,
        _ => 1.5,
    }
}

/// Minimum seat width of AASHTO LRFD 4.7.4.4 (m): the base `N` times the zone percentage.
pub fn aashto_lrfd_seat(
    l: f64,
    h: f64,
    skew_deg: f64,
    zone: AashtoZone,
    a_s: f64,
) -> Result<f64, CodeCheckError> {
    let a_s = non_negative("a_s", a_s)?;
    Ok(aashto_base_seat(l, h, skew_deg)? * aashto_lrfd_percentage(zone, a_s))
}

/// Seismic design category of the AASHTO Guide Specifications for LRFD Seismic Bridge Design
/// (§3.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sdc {
    /// SDC A.
    A,
    /// SDC B.
    B,
    /// SDC C.
    C,
    /// SDC D.
    D,
}

/// Minimum support length of the AASHTO Guide Specifications (m).
/// SDC A–C (§4.12.2, Table 4.12.2-1): the base `N` of eq. 4.12.2-1 (the LRFD form) times 75 %
/// (SDC A, `A_s < 0.05`), 100 % (SDC A, `A_s ≥ 0.05`) or 150 % (SDC B, C).
/// SDC D (§4.12.3, eq. 4.12.3-1): `N = (4 + 1.65 Δ_eq)(1 + 0.00025 S²) ≥ 24` in, with
/// `Δ_eq` the seismic displacement demand of the long-period frame at the joint (in).
pub fn aashto_guide_seat(
    sdc: Sdc,
    l: f64,
    h: f64,
    skew_deg: f64,
    a_s: f64,
    delta_eq: f64,
) -> Result<f64, CodeCheckError> {
    let a_s = non_negative("a_s", a_s)?;
    match sdc {
        Sdc::A => Ok(aashto_base_seat(l, h, skew_deg)? * if a_s < 0.05 { 0.75 } else { 1.0 }),
        Sdc::B | Sdc::C => Ok(aashto_base_seat(l, h, skew_deg)? * 1.5),
        Sdc::D => {
            let d_in = non_negative("delta_eq_m", delta_eq)? / INCH;
            let s = angle("skew_deg", skew_deg)?;
            Ok(((4.0 + 1.65 * d_in) * (1.0 + 0.00025 * s * s)).max(24.0) * INCH)
        }
    }
}

/// Kind of seat in Caltrans SDC.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeatKind {
    /// Abutment seat (SDC 1.7 §7.8.3: `N_A ≥ 30` in).
    Abutment,
    /// In-span hinge seat (SDC 1.7 §7.2.5.4: `N ≥ 24` in).
    Hinge,
}

/// Minimum seat width of Caltrans Seismic Design Criteria 1.7 (m):
/// `N = Δ_p/s + Δ_cr+sh + Δ_temp + Δ_eq + 4 in`, not less than 24 in at a hinge (§7.2.5.4) or
/// 30 in at an abutment (§7.8.3). Inputs in metres: prestress shortening, creep and shrinkage,
/// thermal movement and the relative earthquake displacement.
pub fn caltrans_seat(
    kind: SeatKind,
    d_ps: f64,
    d_crsh: f64,
    d_temp: f64,
    d_eq: f64,
) -> Result<f64, CodeCheckError> {
    let sum = non_negative("delta_ps_m", d_ps)?
        + non_negative("delta_crsh_m", d_crsh)?
        + non_negative("delta_temp_m", d_temp)?
        + non_negative("delta_eq_m", d_eq)?
        + 4.0 * INCH;
    let min = match kind {
        SeatKind::Abutment => 30.0,
        SeatKind::Hinge => 24.0,
    } * INCH;
    Ok(sum.max(min))
}

/// Ground type of JRA Specifications for Highway Bridges Part V §4.3 (I firm, II medium, III soft).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JraGround {
    /// Type I.
    I,
    /// Type II.
    II,
    /// Type III.
    III,
}

/// Seat length of JRA Part V (2002) §16.2 (m): `S_E = max(u_R + u_G, S_EM)`, with
/// `u_G = ε_G L` (`ε_G` = 0.0025, 0.00375, 0.005 for ground type I, II, III; `L` the distance
/// between the two substructures that decide the seat, m), `S_EM = 0.7 + 0.005 l` (`l` the span, m),
/// and for a skew bridge not less than `S_Eθ = (L_θ/2)(sin θ − sin(θ − α_E))`, `α_E = 2.5°`
/// (`L_θ` the continuous deck length, m; `θ` the skew angle).
pub fn jra_seat(
    ground: JraGround,
    u_r: f64,
    l_between: f64,
    span: f64,
    skew_deg: f64,
    l_theta: f64,
) -> Result<f64, CodeCheckError> {
    let eps = match ground {
        JraGround::I => 0.0025,
        JraGround::II => 0.00375,
        JraGround::III => 0.005,
    };
    let u_g = eps * non_negative("l_between_m", l_between)?;
    let s_em = 0.7 + 0.005 * non_negative("span_m", span)?;
    let th = angle("skew_deg", skew_deg)?.to_radians();
    let alpha = 2.5f64.to_radians();
    let s_theta = if th > 0.0 {
        non_negative("l_theta_m", l_theta)? / 2.0 * (th.sin() - (th - alpha).sin())
    } else {
        0.0
    };
    Ok((non_negative("u_r_m", u_r)? + u_g).max(s_em).max(s_theta))
}
