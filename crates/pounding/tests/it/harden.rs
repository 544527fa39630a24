//! Hardening: derived mass properties that overflow or underflow, absurd AT2 NPTS.

use pounding::geometry::GeometryError;
use pounding::ground_motion::Record;
use pounding::shape::Deck;
use pounding::shape::{SkewedDeck, StraightDeck};

fn name_of(e: GeometryError) -> String {
    let GeometryError::InvalidParameter { name, .. } = e;
    name
}

#[test]
fn curved_deck_mass_properties_must_be_normal_and_name_the_cause() {
    // valid inputs whose derived area/mass/inertia overflow or underflow
    let cases = [
        ((1e300, 1.0, 10.0, 1.0, 2500.0), "R"), // A = βRW ok, I ~ m R² → inf/NaN
        ((100.0, 1.0, 10.0, 1e-320, 2500.0), "thickness"), // subnormal mass
        ((100.0, 1.0, 10.0, 1.0, 1e-320), "density"),
        ((100.0, 1e-320, 10.0, 1.0, 1.0), "beta"), // subnormal area
    ];
    for ((r, b, w, t, d), want) in cases {
        let e = Deck::new(r, b, w, t, d).expect_err(want);
        let msg = e.to_string();
        assert_eq!(name_of(e), want, "{msg}");
        assert!(msg.len() < 300, "number printed in full: {msg}");
    }
    // an ordinary deck still passes and its properties are normal
    let p = Deck::new(100.0, 1.0, 10.0, 1.0, 2500.0)
        .unwrap()
        .mass_properties();
    assert!(p.mass.is_normal() && p.inertia.is_normal() && p.area.is_normal());
}

#[test]
fn straight_and_skewed_mass_properties_must_be_normal() {
    let e = StraightDeck::new(30.0, 10.0, 1e-320, 2500.0).unwrap_err();
    assert_eq!(name_of(e), "thickness");
    let e = StraightDeck::new(1e200, 1e200, 1.0, 1.0).unwrap_err();
    assert!(["length", "width"].contains(&name_of(e).as_str()));
    let e = SkewedDeck::new(30.0, 10.0, 0.3, 1.0, 1e-318).unwrap_err();
    assert_eq!(name_of(e), "density");
    let e = SkewedDeck::new(1e160, 10.0, 0.3, 1.0, 1.0).unwrap_err();
    assert_eq!(name_of(e), "length");
    assert!(SkewedDeck::new(30.0, 10.0, 0.3, 1.0, 2500.0).is_ok());
}

#[test]
fn absurd_at2_npts_is_refused_before_allocating() {
    let text = "h\nh\nh\nNPTS= 99999999999, DT= 0.01 SEC\n0.1 0.2\n";
    let e = Record::from_at2_str(text, "big.AT2")
        .unwrap_err()
        .to_string();
    assert!(e.contains("big.AT2:4") && e.contains("NPTS"), "{e}");
    // an honest short count is still accepted
    let ok = "h\nh\nh\nNPTS= 2, DT= 0.01 SEC\n0.1 0.2\n";
    assert_eq!(
        Record::from_at2_str(ok, "ok.AT2").unwrap().values().len(),
        2
    );
}
