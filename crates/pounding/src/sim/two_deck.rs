//! The two-deck model of the original study: two decks (annular sectors in the S arrangement,
//! or straight / skewed decks of [`crate::shape`]) meeting at one joint, their bearings, damping,
//! contact law, optional rigid abutments beyond their far ends, and the problem of a run
//! ([`SimProblem`]). It runs as the bridge of two segments ([`super::bridge::BridgeModel::from_pair`]).

use super::model::{self, SegmentBody};
use super::options::{DampingModel, JointContact};
use super::param::{ParamPath, TwoDeckParam};
use super::{Bearing, SimError};
use crate::geometry::ContactCase;
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector};
use crate::pair::SArrangement;
use crate::shape::DeckShape;

/// The structural model: decks, joint, bearings, damping, contact law, seats.
#[derive(Debug, Clone, PartialEq)]
pub struct SimModel {
    /// The two decks (spec §4); both must have the same width.
    pub arrangement: SArrangement,
    /// Joint opening `g ≥ 0` in the reference pose (`M_1 = (0, g)`) \[m\].
    pub gap: Real,
    /// Bearings of deck 1 (points relative to `M_1`, reference pose).
    pub bearings1: Vec<Bearing>,
    /// Bearings of deck 2 (points relative to `M_2`, reference pose).
    pub bearings2: Vec<Bearing>,
    /// Rayleigh damping ratio `ζ ∈ [0, 1)` at each deck's two lowest distinct frequencies.
    pub damping_ratio: Real,
    /// Coulomb friction coefficient `μ ≥ 0` at the joint.
    pub friction: Real,
    /// Newton restitution coefficient `ε_N ∈ [0, 1]`.
    pub restitution: Real,
    /// Seat length `> 0` \[m\]: an end whose seat displacement exceeds it is unseated.
    pub seat_length: Real,
    /// Normal contact law of the joint (default: rigid, the LCP impact law).
    pub contact: JointContact,
    /// Damping model (default: Rayleigh with [`SimModel::damping_ratio`]).
    pub damping_model: DampingModel,
    /// Deck shapes `[deck 1, deck 2]` in the frames of [`crate::shape`] (deck 1 = body frame
    /// moved by `(0, g)`, deck 2 = body frame turned by π); `None` = the curved decks of
    /// `arrangement` (which is then the only geometry used). When set, `arrangement` is ignored;
    /// both joint faces must have the same length so that the decks meet face to face.
    pub shapes: Option<[DeckShape; 2]>,
    /// Optional rigid abutment beyond the far end of deck 1 / deck 2.
    pub abutments: [Option<SimAbutment>; 2],
}

/// A rigid abutment (the ground) beyond the far end face of a deck.
///
/// Its face is the line parallel to the deck's far end face in the reference pose, at distance
/// `gap` along that face's outward normal `n_out`. Each corner `c_k` of the far face is a contact
/// (body a = the deck, body b = the ground) with normal `n = −n_out` (into the deck), tangent
/// `t = perp(n) = (−n_y, n_x)` and signed gap `g_k = (P_k − A)·n`, `A` = far-face midpoint `+ gap
/// n_out` (reference pose), `P_k` the corner in the current pose; the same impact law
/// (ε_N, μ) as the joint. The abutment face is taken long enough for both corners.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimAbutment {
    /// Gap `≥ 0` between the far end face and the abutment face \[m\].
    pub gap: Real,
    /// Seat length `> 0` of that deck end on the abutment \[m\] (replaces
    /// [`SimModel::seat_length`] for the far end of this deck).
    pub seat_length: Real,
}

/// A contact of the simulation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SimContact {
    /// Corner of one deck's joint face against the other deck's joint face (spec §5.3).
    Joint(ContactCase),
    /// Far-face corner `corner ∈ {0, 1}` (the shape's `c0`, `c1`) of deck `deck ∈ {1, 2}` against
    /// its abutment.
    Abutment {
        /// 1 or 2.
        deck: usize,
        /// 0 or 1.
        corner: usize,
    },
}

impl SimContact {
    /// Output name: `deck1-inner`, … (joint, [`ContactCase::name`]) or `abutment1-c0`, ….
    pub fn name(&self) -> &'static str {
        match self {
            Self::Joint(c) => c.name(),
            Self::Abutment { deck, corner } => match (deck, corner) {
                (1, 0) => "abutment1-c0",
                (1, _) => "abutment1-c1",
                (_, 0) => "abutment2-c0",
                _ => "abutment2-c1",
            },
        }
    }
}

impl PartialEq<ContactCase> for SimContact {
    fn eq(&self, other: &ContactCase) -> bool {
        *self == SimContact::Joint(*other)
    }
}

/// The four corners of a deck's two end faces, relative to its face midpoint `M_j`, reference
/// pose (spec §4): joint face `(±W/2, 0)`, far face at the angle `β`.
pub fn end_corner_points(arrangement: &SArrangement, deck: usize) -> [Vector; 4] {
    let d = if deck == 1 {
        &arrangement.deck1
    } else {
        &arrangement.deck2
    };
    deck_corners(&SegmentBody::of_curved_deck(d, deck, 0.0), deck)
}

/// The four end-face corners of a deck of any shape relative to its joint-face midpoint `M_j`,
/// reference pose, global orientation (deck 2 turned by π): `[joint c0, joint c1, far c0, far c1]`.
pub fn shape_corner_points(shape: &DeckShape, deck: usize) -> [Vector; 4] {
    deck_corners(&SegmentBody::of_deck_shape(shape, deck, 0.0), deck)
}

/// `[joint c0, joint c1, far c0, far c1]` of deck `j` relative to its joint-face midpoint.
fn deck_corners(body: &SegmentBody, j: usize) -> [Vector; 4] {
    let (joint, far) = (body.joint_face(j), body.far_face(j));
    [
        joint.corners[0] - joint.mid,
        joint.corners[1] - joint.mid,
        far.corners[0] - joint.mid,
        far.corners[1] - joint.mid,
    ]
}

impl SimModel {
    /// A model with the default bearing layout: one bearing of stiffness `k1` (deck 1) / `k2`
    /// (deck 2) at each of the four end-face corners of each deck.
    #[allow(clippy::too_many_arguments)]
    pub fn with_corner_bearings(
        arrangement: SArrangement,
        gap: Real,
        k1: Real,
        k2: Real,
        damping_ratio: Real,
        friction: Real,
        restitution: Real,
        seat_length: Real,
    ) -> Self {
        let b = |deck: usize, k: Real| {
            end_corner_points(&arrangement, deck)
                .into_iter()
                .map(|point| Bearing {
                    point,
                    stiffness: k,
                })
                .collect()
        };
        SimModel {
            arrangement,
            gap,
            bearings1: b(1, k1),
            bearings2: b(2, k2),
            damping_ratio,
            friction,
            restitution,
            seat_length,
            contact: JointContact::Rigid,
            damping_model: DampingModel::Rayleigh,
            shapes: None,
            abutments: [None, None],
        }
    }

    /// A model of two decks of any shape ([`SimModel::shapes`]) with one bearing of stiffness
    /// `k1` / `k2` at each of the four end-face corners of each deck and no abutments
    /// (`arrangement` is set to the default curved decks and ignored).
    #[allow(clippy::too_many_arguments)]
    pub fn with_shapes(
        shapes: [DeckShape; 2],
        gap: Real,
        k1: Real,
        k2: Real,
        damping_ratio: Real,
        friction: Real,
        restitution: Real,
        seat_length: Real,
    ) -> Self {
        let b = |deck: usize, k: Real| {
            shape_corner_points(&shapes[deck - 1], deck)
                .into_iter()
                .map(|point| Bearing {
                    point,
                    stiffness: k,
                })
                .collect()
        };
        SimModel {
            bearings1: b(1, k1),
            bearings2: b(2, k2),
            gap,
            damping_ratio,
            friction,
            restitution,
            seat_length,
            shapes: Some(shapes),
            ..Self::default_bridge()
        }
    }

    /// Deck masses `[m1, m2]` \[kg\].
    pub fn masses(&self) -> [Real; 2] {
        let b = self.bodies();
        [b[0].mass.mass, b[1].mass.mass]
    }

    /// The decks' reference-pose bodies (global frame of spec §4): deck `j` is segment `j` of
    /// its bridge ([`SegmentBody::joint_face`], [`SegmentBody::far_face`]).
    pub fn deck_bodies(&self) -> [SegmentBody; 2] {
        self.bodies()
    }

    /// The built-in default of `pounding simulate`: R = 100 m, β = 60°, W = 10 m, t = 0.5 m,
    /// ρ = 2500 kg/m³ (1309 t per deck) for both decks; 4 corner bearings of 2.02e7 N/m (deck 1)
    /// and 8.97e6 N/m (deck 2); ζ = 5 %; g = 0.05 m; seat 0.4 m; μ = 0.5; ε_N = 0.5.
    pub fn default_bridge() -> Self {
        use super::defaults as d;
        let deck = crate::shape::Deck {
            radius: d::RADIUS,
            angle: d::ANGLE_DEG.to_radians(),
            width: d::WIDTH,
            thickness: d::THICKNESS,
            density: d::DENSITY,
        };
        let arr = SArrangement {
            deck1: deck,
            deck2: deck,
        };
        let [k1, k2] = d::BEARING_STIFFNESS;
        Self::with_corner_bearings(
            arr,
            d::GAP,
            k1,
            k2,
            d::DAMPING_RATIO,
            d::MU,
            d::EPS_N,
            d::SEAT_LENGTH,
        )
    }

    /// Validates every parameter (errors name it).
    pub fn validate(&self) -> Result<(), SimError> {
        self.validate_options()?;
        match &self.shapes {
            None => {
                model::validate_deck(&self.arrangement.deck1, 1)?;
                model::validate_deck(&self.arrangement.deck2, 2)?;
                let (w1, w2) = (self.arrangement.deck1.width, self.arrangement.deck2.width);
                if w1 != w2 {
                    return Err(SimError::invalid(
                        ParamPath::deck(TwoDeckParam::Width, 2),
                        w2,
                        &format!("both decks must have the same width (deck 1: {w1})"),
                    ));
                }
            }
            Some(shapes) => {
                for (j, sh) in shapes.iter().enumerate() {
                    validate_shape(sh, j + 1)?;
                }
                let b = self.bodies();
                let (h1, h2) = (b[0].joint_face(1).half, b[1].joint_face(2).half);
                if (h1 - h2).abs() > 1e-9 * h1.max(h2) {
                    return Err(SimError::invalid(
                        ParamPath::deck(TwoDeckParam::JointFace, 2),
                        2.0 * h2,
                        &format!(
                            "the joint faces must have the same length to meet face to face \
                             (deck 1: {})",
                            2.0 * h1
                        ),
                    ));
                }
            }
        }
        for (j, a) in self.abutments.iter().enumerate() {
            if let Some(a) = a {
                if !(a.gap.is_finite() && a.gap >= 0.0) {
                    return Err(SimError::invalid(
                        ParamPath::deck(TwoDeckParam::AbutmentGap, j as u8 + 1),
                        a.gap,
                        "must be finite and >= 0",
                    ));
                }
                if !(a.seat_length.is_finite() && a.seat_length > 0.0) {
                    return Err(SimError::invalid(
                        ParamPath::deck(TwoDeckParam::AbutmentSeat, j as u8 + 1),
                        a.seat_length,
                        "must be finite and > 0",
                    ));
                }
            }
        }
        let chk = |name: ParamPath, v: Real, ok: bool, reason: &str| {
            if ok && v.is_finite() {
                Ok(())
            } else if v.is_finite() {
                Err(SimError::invalid(name, v, reason))
            } else {
                Err(SimError::invalid(name, v, &super::finite_reason(reason)))
            }
        };
        chk(
            ParamPath::pair(TwoDeckParam::Gap),
            self.gap,
            self.gap >= 0.0,
            "must be >= 0",
        )?;
        chk(
            ParamPath::pair(TwoDeckParam::DampingRatio),
            self.damping_ratio,
            (0.0..1.0).contains(&self.damping_ratio),
            "must lie in [0, 1)",
        )?;
        chk(
            ParamPath::pair(TwoDeckParam::Mu),
            self.friction,
            self.friction >= 0.0,
            "must be >= 0",
        )?;
        chk(
            ParamPath::pair(TwoDeckParam::EpsN),
            self.restitution,
            (0.0..=1.0).contains(&self.restitution),
            "must lie in [0, 1]",
        )?;
        chk(
            ParamPath::pair(TwoDeckParam::SeatLength),
            self.seat_length,
            self.seat_length > 0.0,
            "must be > 0",
        )?;
        for (j, bs) in [(1, &self.bearings1), (2, &self.bearings2)] {
            for (i, b) in bs.iter().enumerate() {
                chk(
                    ParamPath::TwoDeck {
                        param: TwoDeckParam::BearingStiffness,
                        deck: Some(j),
                        bearing: Some(i + 1),
                    },
                    b.stiffness,
                    b.stiffness >= 0.0,
                    "must be >= 0",
                )?;
                let path = ParamPath::TwoDeck {
                    param: TwoDeckParam::BearingPoint,
                    deck: Some(j),
                    bearing: Some(i + 1),
                };
                // each coordinate first, so that the bad one is the value reported
                for v in [b.point.x, b.point.y] {
                    chk(
                        path.clone(),
                        v,
                        v * v < 1e100,
                        "must be finite, with |coordinate| < 1e50 m",
                    )?;
                }
                // the rotational stiffness k r² must stay finite (1e300 m would overflow it)
                let kr2 = b.stiffness * (b.point.x * b.point.x + b.point.y * b.point.y);
                let far = if b.point.x.abs() >= b.point.y.abs() {
                    b.point.x
                } else {
                    b.point.y
                };
                chk(
                    path,
                    far,
                    kr2.is_finite(),
                    "too far from the deck: the rotational stiffness k r² overflows",
                )?;
            }
        }
        Ok(())
    }

    pub(crate) fn bodies(&self) -> [SegmentBody; 2] {
        match &self.shapes {
            None => [
                SegmentBody::of_curved_deck(&self.arrangement.deck1, 1, self.gap),
                SegmentBody::of_curved_deck(&self.arrangement.deck2, 2, self.gap),
            ],
            Some(sh) => [
                SegmentBody::of_deck_shape(&sh[0], 1, self.gap),
                SegmentBody::of_deck_shape(&sh[1], 2, self.gap),
            ],
        }
    }

    /// Validates every parameter and the bridge it expands into ([`BridgeModel::from_pair`]):
    /// each deck's natural frequencies `[deck 1, deck 2]` \[rad/s\] from the bridge's one
    /// assembly of `M`, `K`, `C` ([`BridgeModel::body_systems`]), with the bridge's errors
    /// under the two-deck names ([`super::pair_errors`]: a bearing point outside its deck names
    /// the deck and bearing; an overflowing stiffness over mass names `mass<j>`; a deck without
    /// bearing stiffness under Rayleigh damping names `damping_ratio`).
    ///
    /// [`BridgeModel::from_pair`]: super::bridge::BridgeModel::from_pair
    /// [`BridgeModel::body_systems`]: super::bridge::BridgeModel::body_systems
    pub fn check(&self) -> Result<[[Real; 3]; 2], SimError> {
        self.validate()?;
        let bridge = super::bridge::BridgeModel::from_pair(self);
        let point = |deck: usize, b: usize| {
            let pts = if deck == 0 {
                &self.bearings1
            } else {
                &self.bearings2
            };
            pts.get(b).map(|b| b.point)
        };
        let pair = |e| super::pair_errors::pair_error(self.damping_ratio, &point, &bridge, e);
        bridge.validate().map_err(pair)?;
        let systems = bridge.body_systems().map_err(pair)?;
        Ok([systems[0].frequencies, systems[1].frequencies])
    }
}

/// Re-validates one deck shape through its constructor; parameter names get the deck number
/// (`L1`, `skew2`, `R1`, …; `width`, `thickness`, `density` keep their name).
fn validate_shape(shape: &DeckShape, j: usize) -> Result<(), SimError> {
    shape
        .validate()
        .map_err(|e| SimError::Geometry(e.for_deck(j)))
}

/// Everything a run needs besides the settings: model, ground motion, initial state.
#[derive(Debug, Clone, PartialEq)]
pub struct SimProblem {
    /// The structure.
    pub model: SimModel,
    /// The ground acceleration.
    pub ground: GroundMotion,
    /// Initial displacements `q(0)` (spec §5.1 order) \[m, rad\].
    pub q0: [Real; 6],
    /// Initial velocities `u(0)` relative to the ground \[m/s, rad/s\].
    pub u0: [Real; 6],
}

impl SimProblem {
    /// At rest in the reference pose.
    pub fn at_rest(model: SimModel, ground: GroundMotion) -> Self {
        Self {
            model,
            ground,
            q0: [0.0; 6],
            u0: [0.0; 6],
        }
    }
}
