//! Time integration of a bridge: an [`Integrator`] owns the loop over time of a whole run.
//!
//! The model (bodies, links, supports, contact sites with their laws) is the integrator's input
//! ([`RunInput`]); the integrator decides how time advances. Today there is one:
//! [`MoreauJean`], the θ-method time stepping of `driver.rs` (module doc of [`crate::sim`]),
//! whose per-step contact treatment is a stepper chosen from the sites' kinds — every joint and
//! abutment is a contact site with its own law, rigid (an impact law, solved by the impact LCP of
//! [`super::rigid`]) or compliance (a force law, solved by Newton's method in
//! [`super::compliance`]): the rigid stepper when every site is rigid, the compliance stepper when
//! every site has a compliance law, and otherwise both, each restricted to its own sites and
//! coupled per step ([`super::mixed`]).
//!
//! Another integrator (an event-driven one: smooth flow between events, root finding on the
//! gaps, an impact LCP at each event) is another implementation of [`Integrator`] with its own
//! loop, returning the same [`driver::RunResult`] from the same input, selected in
//! [`integrate`]; the Moreau–Jean loop is not touched. The two-deck model runs here too, as its
//! bridge of two segments.

use super::bridge::{BridgeModel, abut_key, check, joint_key};
use super::contact::State;
use super::driver::{self};
use super::excitation::{SupportExcitation, SupportMotion};
use super::param::{BridgeKey, BridgeTable};
use super::scheme::BodySystem;
use super::view::Bridge;
use super::{JointContact, SimError, SimSettings, compliance, rigid};
use crate::analytic::ImpactLaw;
use crate::ground_motion::GroundMotion;
use crate::math::Real;

/// What an integrator integrates: a validated model, the driver's view of it, the segments'
/// linear systems, the kinds of its contact sites, the ground motion, the initial state and the
/// settings.
pub(crate) struct RunInput<'a> {
    /// The bridge.
    pub model: &'a BridgeModel,
    /// Its lists (segments, joints, abutments, seats, elements, supports).
    pub bridge: &'a Bridge,
    /// Each segment's `M`, `K`, `C`.
    pub systems: &'a [BodySystem],
    /// Which sites are rigid and which compliant.
    pub kinds: &'a SiteKinds,
    /// The ground acceleration (the reference motion when the supports move apart).
    pub ground: &'a GroundMotion,
    /// The supports' own motions (`None`: every support moves with `ground`).
    pub motion: Option<&'a SupportMotion>,
    /// `(q(0), u(0))`.
    pub initial: (&'a [Real], &'a [Real]),
    /// Step, duration, θ, history stride, monitors.
    pub settings: &'a SimSettings,
}

/// A time integrator of a whole run (module doc).
pub(crate) trait Integrator {
    /// Integrates the run from its initial state to its end (or to divergence).
    fn integrate(&self, run: &RunInput<'_>) -> Result<driver::RunResult, SimError>;
}

/// Moreau–Jean time stepping (θ-method + a velocity-level contact step), the loop of
/// `driver.rs`, with the stepper of the run's contact-site kinds.
pub(crate) struct MoreauJean {
    /// Use the dense operators of the whole system ([`super::coupled`]) even where no link
    /// couples bodies (otherwise only where one does): the same scheme, to compare the two.
    pub dense: bool,
}

impl Integrator for MoreauJean {
    fn integrate(&self, run: &RunInput<'_>) -> Result<driver::RunResult, SimError> {
        let (model, bridge, kinds, settings) = (run.model, run.bridge, run.kinds, run.settings);
        let apart = run.motion.is_some();
        let coupled = model
            .coupled_system(run.systems, self.dense || apart, apart)?
            .map(|c| (c, model.dofs()));
        // a run to the record's end lasts until its last arrival's end (wave passage)
        let extended;
        let settings = match run.motion.map(|m| m.longest_delay()) {
            Some(d) if d > 0.0 && settings.duration.is_none() => {
                extended = SimSettings {
                    duration: Some(run.ground.end_time() + d),
                    ..settings.clone()
                };
                &extended
            }
            _ => settings,
        };
        let mut scheme =
            super::scheme::Scheme::new(run.ground, settings, run.systems.to_vec(), coupled)?;
        scheme.motion = run.motion.cloned();
        let q0 = State::from_column_slice(run.initial.0);
        let u0 = State::from_column_slice(run.initial.1);
        let observers = super::observer::standard(bridge);
        let (any_rigid, any_compliant) = (kinds.any(false), kinds.any(true));
        let rigid = || model.rigid_stepper(kinds, settings);
        let compliance = || model.compliance_stepper(kinds, bridge, &scheme, (&q0, &u0));
        Ok(match (any_rigid, any_compliant) {
            (_, false) => {
                let mut stepper = rigid()?;
                driver::run(q0, u0, settings, &scheme, bridge, &mut stepper, observers)
            }
            (false, true) => {
                let mut stepper = compliance()?.0;
                driver::run(q0, u0, settings, &scheme, bridge, &mut stepper, observers)
            }
            (true, true) => {
                let (c, joint_site, abutment_site) = compliance()?;
                let mut stepper =
                    super::mixed::MixedStepper::new(rigid()?, c, joint_site, abutment_site);
                driver::run(q0, u0, settings, &scheme, bridge, &mut stepper, observers)
            }
        })
    }
}

/// Integrates a validated `model` from `initial` over the driver's view `bridge` of it
/// ([`BridgeModel::bridge`]) with the run's integrator ([`MoreauJean`]). Returns the run, the
/// segments' linear systems and the kinds of the sites. The contact laws, the supports' motion
/// (uniform: relative coordinates) and the time step are checked here.
pub(crate) fn integrate(
    model: &BridgeModel,
    bridge: &Bridge,
    (ground, excitation): (&GroundMotion, &SupportExcitation),
    initial: (&[Real], &[Real]),
    settings: &SimSettings,
) -> Result<(driver::RunResult, Vec<BodySystem>, SiteKinds), SimError> {
    let kinds = model.contact_kinds()?;
    // relative coordinates: every support moves with the one ground motion (support.rs), or
    // each its own motion relative to it (excitation.rs)
    super::support::check_uniform(&bridge.supports)?;
    let motion = SupportMotion::new(&model.support_lines(), ground, excitation)?;
    if motion.is_some() {
        check_apart(model)?;
    }
    model.check_time_step(settings.dt)?;
    let systems = model.body_systems()?;
    let run = RunInput {
        model,
        bridge,
        systems: &systems,
        kinds: &kinds,
        ground,
        motion: motion.as_ref(),
        initial,
        settings,
    };
    let result = MoreauJean { dense: false }.integrate(&run)?;
    Ok((result, systems, kinds))
}

/// Refuses what the supports' own motions do not reach: the segments' dashpots to "the ground"
/// (which ground, when each support moves its own way?).
pub(crate) fn check_apart(model: &BridgeModel) -> Result<(), SimError> {
    let refuse = |name: BridgeKey, what: &str| {
        SimError::argument(
            name,
            format!(
                "{what} is not supported when the supports move apart (wave passage or a motion \
                 per support); run it under a uniform ground motion"
            ),
        )
    };
    if model.damping_model == super::DampingModel::TranslationalDashpots
        && model.damping_ratio > 0.0
    {
        return Err(refuse(
            BridgeKey::new(BridgeTable::Bridge, "damping"),
            "`dashpots` damping (each segment's dashpots to one ground; use `rayleigh` or the \
             bearings' `bearing_damping`)",
        ));
    }
    Ok(())
}

/// Which contact sites have a compliance law (`true`) and which are rigid (`false`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct SiteKinds {
    /// Per joint.
    pub joints: Vec<bool>,
    /// Per abutment side (`None`: no abutment).
    pub abutments: [Option<bool>; 2],
}

impl SiteKinds {
    /// Some site is of kind `compliant`.
    pub fn any(&self, compliant: bool) -> bool {
        self.joints.contains(&compliant) || self.abutments.contains(&Some(compliant))
    }
}

impl BridgeModel {
    /// The kind of every contact site; a compliance law's `friction_velocity` must be `> 0`.
    pub(crate) fn contact_kinds(&self) -> Result<SiteKinds, SimError> {
        for (name, c) in self.contacts() {
            if let JointContact::Compliance(cc) = c {
                let v = cc.friction_velocity;
                check(
                    BridgeKey::new(name.table, "friction_velocity"),
                    v,
                    v > 0.0,
                    "must be finite and > 0",
                )?;
            }
        }
        let comp = |c: &JointContact| matches!(c, JointContact::Compliance(_));
        Ok(SiteKinds {
            joints: self.joints.iter().map(|j| comp(&j.contact)).collect(),
            abutments: self.abutments.map(|a| a.map(|a| comp(&a.contact))),
        })
    }

    /// The rigid stepper of the rigid sites (every site of an all-rigid bridge).
    fn rigid_stepper(
        &self,
        kinds: &SiteKinds,
        settings: &SimSettings,
    ) -> Result<rigid::RigidStepper, SimError> {
        let law = |name: BridgeKey, mu: Real, eps: Real| {
            ImpactLaw::new(mu, eps).map_err(|_| SimError::invalid(name, mu, "invalid impact law"))
        };
        let none = ImpactLaw::new(0.0, 0.0).expect("valid");
        let joint_laws = self
            .joints
            .iter()
            .enumerate()
            .map(|(k, j)| match kinds.joints[k] {
                false => law(joint_key(k, "law"), j.friction, j.restitution),
                true => Ok(none),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut abut = [none; 2];
        for (s, a) in self.abutments.iter().enumerate() {
            if let (Some(a), Some(false)) = (a, kinds.abutments[s]) {
                abut[s] = law(abut_key(s, "law"), a.friction, a.restitution)?;
            }
        }
        let on = kinds.joints.iter().map(|c| !c).collect();
        let abut_on = kinds.abutments.map(|k| k == Some(false));
        Ok(rigid::RigidStepper::with_laws(joint_laws, abut, settings).only(on, abut_on))
    }

    /// The compliance stepper of the compliance sites, with the compliance site index of every
    /// joint and of every present abutment (`None`: rigid).
    #[allow(clippy::type_complexity)]
    fn compliance_stepper(
        &self,
        kinds: &SiteKinds,
        bridge: &Bridge,
        scheme: &super::scheme::Scheme,
        (q0, u0): (&State, &State),
    ) -> Result<
        (
            compliance::ComplianceStepper,
            Vec<Option<usize>>,
            Vec<Option<usize>>,
        ),
        SimError,
    > {
        let mut sites = Vec::new();
        let mut vr = Real::INFINITY;
        let mut law_of = |name: BridgeKey, c: &JointContact, mu: Real| -> Result<_, SimError> {
            let JointContact::Compliance(cc) = c else {
                unreachable!("a compliance site")
            };
            vr = vr.min(cc.friction_velocity);
            let law = crate::contact_law::sharing::JointLaw::new(cc.law, 2)
                .map_err(|e| SimError::invalid(name, 2.0, &e.to_string()))?;
            Ok(compliance::SiteLaw { law, mu })
        };
        let (mut joints, mut joint_site) = (Vec::new(), Vec::new());
        for (k, j) in self.joints.iter().enumerate() {
            joint_site.push(kinds.joints[k].then_some(sites.len()));
            if kinds.joints[k] {
                sites.push(law_of(joint_key(k, "law"), &j.contact, j.friction)?);
                joints.push(bridge.joints[k]);
            }
        }
        let (mut abuts, mut abutment_site) = (Vec::new(), Vec::new());
        for face in &bridge.abutments {
            let a = self.abutments[face.side]
                .as_ref()
                .expect("a present abutment");
            let compliant = kinds.abutments[face.side] == Some(true);
            abutment_site.push(compliant.then_some(sites.len()));
            if compliant {
                sites.push(law_of(abut_key(face.side, "law"), &a.contact, a.friction)?);
                abuts.push(*face);
            }
        }
        let stepper =
            compliance::ComplianceStepper::new(q0, u0, sites, (joints, abuts), vr, scheme, bridge);
        Ok((stepper, joint_site, abutment_site))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::scenario::Scenario;

    /// A scenario of `examples/`, cut to `duration` seconds.
    fn example(name: &str, duration: Real) -> (BridgeModel, GroundMotion, SimSettings) {
        let path = format!("{}/../../examples/{name}", env!("CARGO_MANIFEST_DIR"));
        let sc = Scenario::load(std::path::Path::new(&path)).expect("example reads");
        let b = sc.build_bridge().expect("a bridge example builds");
        let mut settings = b.settings.clone();
        settings.duration = Some(duration);
        (b.problem.model, b.problem.ground, settings)
    }

    fn run(
        model: &BridgeModel,
        ground: &GroundMotion,
        s: &SimSettings,
        dense: bool,
    ) -> driver::RunResult {
        let bridge = model.bridge();
        let kinds = model.contact_kinds().expect("valid");
        let systems = model.body_systems().expect("valid");
        let z = vec![0.0; model.dofs().len()];
        let input = RunInput {
            model,
            bridge: &bridge,
            systems: &systems,
            kinds: &kinds,
            ground,
            motion: None,
            initial: (&z, &z),
            settings: s,
        };
        MoreauJean { dense }.integrate(&input).expect("runs")
    }

    /// The dense operators of the coupled scheme are the block scheme's without the blocks: on
    /// bridges whose links couple nothing (yielding bearings, restrainers, rigid, compliance and
    /// mixed sites) the two give the same histories to rounding, and the dense run's energy
    /// balance closes as tightly.
    #[test]
    fn dense_scheme_equals_the_block_scheme() {
        for (name, duration) in [
            ("viaduct-1d.toml", 8.0),
            ("viaduct-rigid-1d.toml", 8.0),
            ("viaduct-curved-5.toml", 6.0),
        ] {
            let (model, ground, settings) = example(name, duration);
            let a = run(&model, &ground, &settings, false);
            let b = run(&model, &ground, &settings, true);
            assert_eq!(a.status, b.status, "{name}");
            assert_eq!(a.trace.q.len(), b.trace.q.len(), "{name}");
            let scale = a.trace.q.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
            let diff = a
                .trace
                .q
                .iter()
                .zip(&b.trace.q)
                .fold(0.0, |m: Real, (x, y)| m.max((x - y).abs()));
            assert!(scale > 1e-3, "{name}: the run moves ({scale})");
            assert!(
                diff <= 1e-9 * scale,
                "{name}: max |Δq| {diff:e} of {scale:e}"
            );
            assert_eq!(a.log.impacts, b.log.impacts, "{name}");
            assert!(
                b.energy_balance_error < 1e-9,
                "{name}: {}",
                b.energy_balance_error
            );
        }
    }
}
