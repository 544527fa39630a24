//! # pounding — nonsmooth rigid-impact analysis of pounding between bridge deck segments
//!
//! The library follows the binding physics specification (`spec/physics.md` of the project's
//! shared data, cited below as "spec §N"). It is organised like a paper:
//!
//! * [`assessment`] — fragility studies: record sets at IM stripes, limit states per run.
//! * [`math`] — type aliases over `nalgebra` and small planar helpers (scalar cross product, rotations).
//! * [`lcp`] — the linear complementarity problem `w = M z + q, z ≥ 0, w ≥ 0, zᵀw = 0`, a
//!   lexicographic Lemke solver (with fixed-size kernels for the tiny impact LCPs) and exhaustive
//!   enumeration of complementary bases; readers/writers for the Siconos `.dat`, `LCPSET 1` and
//!   `LCPSOL 1` formats.
//! * [`geometry`] — annular-sector decks, their mass properties (spec §3), the S arrangement (§4) and the
//!   impact configuration of a corner against the other deck's end face (§5).
//! * [`contact`] — generalised force directions `w_N`, `w_T` (§6) and the Delassus matrix (§7).
//! * [`contact_law`] — compliance contact laws (Kelvin, Hertz, Hertz-damp, bilinear, Jankowski), their
//!   calibrations, a two-mass collision integrator and joint sharing (used by `sim` for compliance runs).
//! * [`element`] — bearings (linear; bilinear with kinematic hardening, 2-D `Steel01`) and cable
//!   restrainers (tension-only with slack, optional yield; `ElasticPPGap`) as constitutive laws.
//! * [`analytic`] — the closed-form single-impact solution: stick interval `[L, U]`, modes, impulses (§9–§11).
//! * [`impact`] — the generic multi-contact frictional impact of planar rigid bodies, solved as an LCP (§8).
//! * [`law_check`] — post-solve physics checks: the impact laws and the energy bound verified on the
//!   recovered post-impact velocities.
//! * [`shape`] — straight and skewed decks beside the curved one (mass properties, end faces, corners in
//!   one body frame) and corner impacts against a rigid abutment.
//! * [`pair`] — the joint-anchored impact configuration and Delassus matrix of two decks of any shape.
//! * [`study`] — the parametric stick/slip study of the paper (scenarios, bounds, summaries).
//! * [`ground_motion`] — recorded ground motions (PEER `.AT2`, CSV), interpolation, two components,
//!   the embedded El Centro 1940 record.
//! * [`sim`] — seismic time histories of two decks with pounding: bearings, Rayleigh damping,
//!   Moreau–Jean time stepping with the impact LCP at every step, abutments, batch runs.
//! * [`shard`] — `--shard K/N`: which rows of a study or runs of a batch one process computes.
//! * [`toml_schema`] — strict table and fixed-length array shapes for scenario files.
//! * [`fragility`] — lognormal fragility functions fitted to stripe counts (maximum likelihood) and
//!   IDA data (method of moments), record bootstrap, `fragility.csv`/`.json` writers (issue 13).
//! * [`output`] — deterministic number formatting and atomic file output shared by every writer.
//! * [`input`] — input files read within documented size limits, strict JSON, the thread limit.
//!
//! Errors (bad input) are [`thiserror`] enums per module; numerical outcomes (ray termination,
//! pivot limit, no impact) are *statuses* inside results, never errors and never panics.
#![warn(missing_docs)]

pub mod analytic;
pub mod assessment;
pub mod campaign;
pub mod contact;
pub mod contact_law;
pub mod element;
pub mod fragility;
pub mod geometry;
pub mod ground_motion;
pub mod impact;
pub mod impact_report;
pub mod input;
pub mod law_check;
pub mod lcp;
pub mod math;
pub mod output;
pub mod pair;
pub mod shape;
pub mod shard;
pub mod sim;
pub mod spectrum;
pub mod study;
pub mod toml_schema;
