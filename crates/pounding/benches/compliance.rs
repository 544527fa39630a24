//! Benchmarks of `pounding::sim::simulate` with compliance contact laws: the curved default
//! bridge (El Centro 1940, dt = 1e-3) with the Kelvin and bilinear laws, and the OpenSees 1-D
//! benchmark (straight decks, bilinear law, dt = 1e-4, 537 100 steps). Library call only, every
//! 10th step kept.

use pounding::contact_law::calibration::KelvinCalibration;
use pounding::contact_law::{BilinearImpact, ContactLaw, KelvinVoigt, units};
use pounding::ground_motion::el_centro_1940;
use pounding::shape::{DeckShape, StraightDeck};
use pounding::sim::{
    ComplianceContact, DampingModel, JointContact, SimModel, SimProblem, SimSettings, simulate,
};

fn main() {
    divan::main();
}

fn bilinear() -> ContactLaw {
    BilinearImpact::from_hertz(units::kip_per_in_1_5(25_000.0), 0.5, units::INCH, 0.1)
        .unwrap()
        .law
        .into()
}

fn run(p: &SimProblem, s: &SimSettings) -> usize {
    simulate(divan::black_box(p), s).unwrap().summary.impacts
}

fn curved(law: ContactLaw) -> SimProblem {
    let mut m = SimModel::default_bridge();
    m.contact = JointContact::Compliance(ComplianceContact::new(law));
    SimProblem::at_rest(m, el_centro_1940())
}

/// The default bridge with the rigid law (reference for the two below).
#[divan::bench]
fn default_rigid(bencher: divan::Bencher) {
    let p = SimProblem::at_rest(SimModel::default_bridge(), el_centro_1940());
    let s = SimSettings {
        history_stride: 10,
        ..SimSettings::default()
    };
    bencher.bench(|| run(&p, &s));
}

/// The default bridge with Kelvin (k = 1e10, e = 0.5).
#[divan::bench]
fn default_kelvin(bencher: divan::Bencher) {
    let m = 1309.0e3;
    let law = KelvinVoigt::from_restitution(1e10, 0.5, m, m, KelvinCalibration::Numerical).unwrap();
    let p = curved(law.into());
    let s = SimSettings {
        history_stride: 10,
        ..SimSettings::default()
    };
    bencher.bench(|| run(&p, &s));
}

/// The default bridge with the bilinear law derived from k_h = 25 000 kip/in^1.5, e = 0.5.
#[divan::bench]
fn default_bilinear(bencher: divan::Bencher) {
    let p = curved(bilinear());
    let s = SimSettings {
        history_stride: 10,
        ..SimSettings::default()
    };
    bencher.bench(|| run(&p, &s));
}

/// The OpenSees 1-D benchmark (`examples/opensees-1d.toml`), dt = 1e-4.
#[divan::bench(sample_count = 5)]
fn opensees_1d(bencher: divan::Bencher) {
    let (l, w, t, mass) = (30.0, 10.0, 0.5, 1.0e6);
    let deck = DeckShape::Straight(StraightDeck {
        length: l,
        width: w,
        thickness: t,
        density: mass / (l * w * t),
    });
    let k = |p: f64| mass * (2.0 * std::f64::consts::PI / p).powi(2) / 4.0;
    let mut m = SimModel::with_shapes([deck, deck], 0.05, k(1.0), k(0.5), 0.05, 0.0, 0.5, 0.4);
    m.damping_model = DampingModel::TranslationalDashpots;
    let law = BilinearImpact::new(1.5586e10, 3.1328e9, 2.54e-3).unwrap();
    m.contact = JointContact::Compliance(ComplianceContact::new(law.into()));
    let mut g = el_centro_1940();
    g.along_x = None;
    let p = SimProblem::at_rest(m, g);
    let s = SimSettings {
        dt: 1e-4,
        history_stride: 100,
        ..SimSettings::default()
    };
    bencher.bench(|| {
        let n = run(&p, &s);
        assert_eq!(n, 6);
        n
    });
}
