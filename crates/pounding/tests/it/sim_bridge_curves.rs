//! `curve` left out: the curves alternate along the bridge, left first, spans that are not
//! curved not counting (it used to follow the parity of the segment's index, so the first curved
//! span after a straight one curved right, against the documented default).

use pounding::sim::scenario::Scenario;

fn model_of(segments: &[&str]) -> String {
    let mut t = String::from("[bridge]\ngap = 0.05\n");
    for s in segments {
        t.push_str("\n[[segment]]\n");
        t.push_str(s);
        t.push_str("\nmass = 1.0e6\nperiod_s = 1.0\n");
    }
    t.push_str("\n[time]\nduration = 0.01\n");
    let setup = Scenario::from_toml(&t, "curves.toml")
        .unwrap()
        .build_bridge()
        .unwrap();
    format!("{:?}", setup.problem.model)
}

const STRAIGHT: &str = "shape = \"straight\"\nL = 30.0";

fn curved(curve: Option<&str>) -> String {
    let c = curve.map_or(String::new(), |c| format!("\ncurve = \"{c}\""));
    format!("shape = \"curved\"\nR = 100.0\nbeta_deg = 20.0{c}")
}

#[test]
fn left_out_curves_alternate_left_first_over_curved_spans_only() {
    let (d, l, r) = (curved(None), curved(Some("left")), curved(Some("right")));
    // after a straight span, the first curve is left, the next right
    assert_eq!(model_of(&[STRAIGHT, &d, &d]), model_of(&[STRAIGHT, &l, &r]));
    // a straight span between two curves does not break the alternation
    assert_eq!(
        model_of(&[&d, STRAIGHT, &d, &d]),
        model_of(&[&l, STRAIGHT, &r, &l])
    );
    // a given curve sets the direction the next left-out one turns from
    assert_eq!(
        model_of(&[&r, &d, STRAIGHT, &d]),
        model_of(&[&r, &l, STRAIGHT, &r])
    );
    // and the defaults do change the model (the test can fail)
    assert_ne!(model_of(&[STRAIGHT, &d, &d]), model_of(&[STRAIGHT, &r, &l]));
}
