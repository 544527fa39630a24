//! Time integration of a bridge: the stepper of its contact sites in the one driver loop.
//!
//! Every joint and abutment is a contact site with its own law, rigid (an impact law, solved by
//! the impact LCP of [`super::rigid`]) or compliance (a force law, solved by Newton's method in
//! [`super::compliance`]). [`integrate`] takes the rigid stepper when every site is rigid, the
//! compliance stepper when every site has a compliance law, and otherwise both, each restricted
//! to its own sites and coupled per step ([`super::mixed`]). The two-deck model runs here too,
//! as its bridge of two segments.

use super::bridge::{BridgeModel, abut_key, check, joint_key};
use super::contact::State;
use super::driver::{self, Bridge};
use super::{JointContact, SimError, SimSettings, compliance, rigid};
use crate::analytic::ImpactLaw;
use crate::ground_motion::GroundMotion;
use crate::math::Real;

/// Integrates a validated `model` from the initial state of `problem` over the driver's view
/// `bridge` of it ([`BridgeModel::bridge`], whose seat order a preset may change): the stepper of
/// its contact sites in the one driver loop — the rigid one when every site is rigid, the
/// compliance one when every site has a compliance law, else both coupled
/// ([`super::mixed`]). Returns the run, its scheme and the kinds of the sites. The time step
/// and the contact laws are checked here.
pub(crate) fn integrate(
    model: &BridgeModel,
    bridge: &Bridge,
    ground: &GroundMotion,
    (q0, u0): (&[Real], &[Real]),
    settings: &SimSettings,
) -> Result<(driver::RunResult, driver::Scheme, SiteKinds), SimError> {
    let kinds = model.contact_kinds()?;
    // relative coordinates: every support moves with the one ground motion (support.rs)
    super::support::check_uniform(&bridge.supports)?;
    model.check_time_step(settings.dt)?;
    let systems = model.body_systems()?;
    let scheme = driver::Scheme::new(ground, settings, systems)?;
    let q0 = State::from_column_slice(q0);
    let u0 = State::from_column_slice(u0);
    let observers = super::observer::standard(bridge);
    let (any_rigid, any_compliant) = (kinds.any(false), kinds.any(true));
    let rigid = || model.rigid_stepper(&kinds, settings);
    let compliance = || model.compliance_stepper(&kinds, bridge, &scheme, (&q0, &u0));
    let result = match (any_rigid, any_compliant) {
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
    };
    Ok((result, scheme, kinds))
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
                    name.replace(".law", ".friction_velocity"),
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
        let law = |name: String, mu: Real, eps: Real| {
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
        scheme: &driver::Scheme,
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
        let mut law_of = |name: String, c: &JointContact, mu: Real| -> Result<_, SimError> {
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
