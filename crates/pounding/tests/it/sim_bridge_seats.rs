//! Every seated end's margin in the bridge summary: what each end sits on, its own seat, peak,
//! ratio, time of the peak and residual, and the governing end (the largest ratio) — a joint end
//! where it governs, not only the largest displacement over all ends.

use pounding::sim::scenario::Scenario;

#[test]
fn every_seated_end_reports_its_margin_and_the_governing_end_is_the_largest_ratio() {
    // three segments, an abutment at the start only, a short outer seat at the end
    let text = "[bridge]\ngap = 0.02\nseat_length = 0.4\nouter_seat_length = 0.1\n\
                [[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.2\n\
                [[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 0.5\n\
                [[segment]]\nshape = \"straight\"\nL = 30.0\nperiod_s = 1.5\n\
                [[joint]]\n[[joint]]\nseat_length = 0.3\n\
                [abutment.start]\ngap = 0.04\nseat_length = 0.5\n\
                [ground_motion]\nscale_y = -1.0\n[time]\ndt = 1e-3\nduration = 12.0\n";
    let sol = Scenario::from_toml(text, "seats.toml")
        .unwrap()
        .build_bridge()
        .unwrap()
        .run()
        .unwrap();
    let s = &sol.summary;
    let supports: Vec<&str> = s.seats.iter().map(|e| e.support.as_str()).collect();
    assert_eq!(
        supports,
        [
            "abutment-start",
            "joint1",
            "joint1",
            "joint2",
            "joint2",
            "outer-end"
        ]
    );
    let lengths: Vec<f64> = s.seats.iter().map(|e| e.seat_length).collect();
    assert_eq!(lengths, [0.5, 0.4, 0.4, 0.3, 0.3, 0.1]);
    for e in &s.seats {
        assert_eq!(e.ratio, e.peak_displacement / e.seat_length, "{}", e.end);
        assert_eq!(e.unseated, e.peak_displacement > e.seat_length, "{}", e.end);
        assert!(e.residual_displacement <= e.peak_displacement, "{}", e.end);
        assert!((0.0..=12.0).contains(&e.peak_time), "{}", e.end);
    }
    let g = &s.seats[s.governing_seat];
    assert!(s.seats.iter().all(|e| e.ratio <= g.ratio));
    assert_eq!(g.ratio, s.peak_seat_ratio);
    // the short outer seat governs, though the end at joint 2 moves more
    assert_eq!(g.support, "outer-end", "{g:?}");
    let largest = s
        .seats
        .iter()
        .map(|e| e.peak_displacement)
        .fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(largest, s.peak_seat_displacement);
    assert!(
        g.peak_displacement < largest,
        "another end moves more: {:?}",
        s.seats
    );
    assert_eq!(
        s.unseated,
        s.seats.iter().any(|e| e.unseated),
        "the flags agree"
    );
}
