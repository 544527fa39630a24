//! A contact law per joint and per abutment of a bridge scenario (issue 11): `[joint.contact]`,
//! `[abutment.end.contact]` override the file's `[contact]` key by key; a site that changes the
//! law inherits only the keys its law reads; bad site keys name `joint[k].contact.KEY` and line.

use pounding::sim::JointContact;
use pounding::sim::scenario::{BridgeSetup, Scenario};

/// Three equal straight segments between two abutments, 2 s of El Centro (strong enough to
/// pound at every site); `contact` is the file's `[contact]` and the site tables.
fn bridge(contact: &str) -> String {
    let seg = "[[segment]]\nshape = \"straight\"\nL = 30.0\nmass = 1.0e6\nperiod_s = 1.0\n";
    format!(
        "[bridge]\ngap = 0.01\nmu = 0.0\ndamping = \"dashpots\"\n{seg}{seg}{seg}\
         [abutment.start]\ngap = 0.01\n[abutment.end]\ngap = 0.01\n{contact}\n\
         [ground_motion]\nrecord_y = \"builtin:ELC180\"\nrecord_x = \"none\"\nscale_y = -1.0\n\
         [time]\ndt = 1e-4\nduration = 2.0\nhistory_every = 50\n"
    )
}

/// `[[joint]]` tables (each with its optional `contact` table text) after the abutments.
fn joints(j1: &str, j2: &str) -> String {
    format!("[[joint]]\n{j1}\n[[joint]]\n{j2}\n")
}

fn build(text: &str) -> Result<BridgeSetup, String> {
    Scenario::from_toml(text, "b.toml")
        .and_then(|s| s.build_bridge())
        .map_err(|e| e.to_string())
}

/// The contact of joint 1 of a bridge whose only contact is the `[contact]` section `c`
/// (the law as the library builds it for the two segments' masses).
fn file_law(c: &str) -> JointContact {
    build(&bridge(c)).unwrap().problem.model.joints[0].contact
}

/// Three different compliance laws at joint 1, joint 2 and the end abutment (the start
/// abutment keeps the file's): the scenario builds exactly the laws the library builds from a
/// `[contact]` section of each, and the run equals the library bridge with those laws put in
/// directly. Joint 1, made 20 times stiffer than joint 2's identical Kelvin law in an otherwise
/// identical bridge, closes less and pushes harder.
#[test]
fn a_bridge_with_a_law_per_site_runs_each_sites_law() {
    let file = "[contact]\nlaw = \"kelvin\"\nk = 1.0e9\n";
    let text = bridge(&format!(
        "{}[abutment.end.contact]\nlaw = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3\n{file}",
        joints(
            "[joint.contact]\nk = 2.0e10",
            "contact = { law = \"hertz\", k_h = 5.0e10 }"
        )
    ));
    let setup = build(&text).unwrap();
    let m = &setup.problem.model;
    let kelvin_stiff = file_law("[contact]\nlaw = \"kelvin\"\nk = 2.0e10\n");
    let hertz = file_law("[contact]\nlaw = \"hertz\"\nk_h = 5.0e10\n");
    let kelvin = file_law(file);
    assert_eq!(m.joints[0].contact, kelvin_stiff);
    assert_eq!(m.joints[1].contact, hertz);
    assert_ne!(kelvin_stiff, kelvin);
    // the abutment's law: calibrated for the segment's mass, as the file-wide law is
    let plain = build(&bridge(
        "[contact]\nlaw = \"bilinear\"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3\n",
    ))
    .unwrap();
    let bilinear_end = plain.problem.model.abutments[1].as_ref().unwrap().contact;
    assert_eq!(m.abutments[1].as_ref().unwrap().contact, bilinear_end);
    let uniform = build(&bridge(file)).unwrap();
    let kelvin_start = uniform.problem.model.abutments[0].as_ref().unwrap().contact;
    assert_eq!(m.abutments[0].as_ref().unwrap().contact, kelvin_start);

    // the same bridge built in the library: the uniform Kelvin bridge with the laws put in
    let mut lib = uniform.clone();
    lib.problem.model.joints[0].contact = kelvin_stiff;
    lib.problem.model.joints[1].contact = hertz;
    lib.problem.model.abutments[1].as_mut().unwrap().contact = bilinear_end;
    let ours = setup.run().unwrap();
    let theirs = lib.run().unwrap();
    assert_eq!(ours.summary, theirs.summary);
    assert_eq!(ours.end_gaps, theirs.end_gaps);
    assert_eq!(ours.status, pounding::sim::SimStatus::Completed);

    // joint 1 stiffer than in the otherwise identical uniform bridge
    let base = uniform.run().unwrap();
    let (stiff, soft) = (&ours.summary.joints[0], &base.summary.joints[0]);
    assert!(soft.impacts > 0 && stiff.impacts > 0, "{soft:?} {stiff:?}");
    assert!(
        stiff.peak_closing < soft.peak_closing,
        "stiffer joint closes less: {} vs {}",
        stiff.peak_closing,
        soft.peak_closing
    );
    assert!(
        stiff.peak_contact_force.unwrap() > soft.peak_contact_force.unwrap(),
        "{stiff:?} {soft:?}"
    );
    for a in &ours.summary.abutments {
        assert!(a.as_ref().unwrap().peak_contact_force.is_some());
    }
}

/// Key by key: a site that sets a key keeps the file's law and its other keys; a site that
/// changes the law inherits the `[contact]` keys its law reads (and no other: `zeta` is not
/// Hertz's, so it is not refused); `friction_velocity` is inherited by every compliance law.
#[test]
fn site_tables_inherit_the_file_keys_their_law_reads() {
    let file =
        "[contact]\nlaw = \"hertz-damp\"\nk_h = 1.0e10\nzeta = 0.2\nfriction_velocity = 0.002\n";
    let text = bridge(&format!(
        "{}[abutment.start.contact]\nlaw = \"hertz\"\n{file}",
        joints(
            "[joint.contact]\nzeta = 0.3",
            "[joint.contact]\nlaw = \"kelvin\"\nk = 1.0e9"
        )
    ));
    let m = build(&text).unwrap().problem.model;
    let fv = "friction_velocity = 0.002\n";
    assert_eq!(
        m.joints[0].contact,
        file_law(&format!(
            "[contact]\nlaw = \"hertz-damp\"\nk_h = 1.0e10\nzeta = 0.3\n{fv}"
        ))
    );
    assert_eq!(
        m.joints[1].contact,
        file_law(&format!("[contact]\nlaw = \"kelvin\"\nk = 1.0e9\n{fv}"))
    );
    let hertz = build(&bridge(&format!(
        "[contact]\nlaw = \"hertz\"\nk_h = 1.0e10\n{fv}"
    )))
    .unwrap();
    assert_eq!(
        m.abutments[0].as_ref().unwrap().contact,
        hertz.problem.model.abutments[0].as_ref().unwrap().contact
    );
    // the end abutment has no table: the file's law
    let plain = build(&bridge(file)).unwrap();
    assert_eq!(
        m.abutments[1].as_ref().unwrap().contact,
        plain.problem.model.abutments[1].as_ref().unwrap().contact
    );
    // a law override replaces the law at every site; keys it reads still apply
    let text2 = bridge(&format!(
        "{}{file}",
        joints(
            "[joint.contact]\nzeta = 0.3",
            "[joint.contact]\nlaw = \"kelvin\""
        )
    ));
    let sc = Scenario::from_toml(&text2, "b.toml").unwrap();
    let all_hd = sc.clone().with_law("hertz-damp").build_bridge().unwrap();
    assert_eq!(all_hd.problem.model.joints[0].contact, m.joints[0].contact);
    assert_eq!(
        all_hd.problem.model.joints[1].contact,
        plain.problem.model.joints[1].contact
    );
    // ... and a site key the override law does not read is refused (zeta with hertz; the
    // file's zeta first)
    let e = sc.with_law("hertz").build_bridge().unwrap_err().to_string();
    assert!(e.contains("zeta is not used by law = \"hertz\""), "{e}");
    let text3 = bridge(&joints("[joint.contact]\nzeta = 0.3", ""));
    let sc = Scenario::from_toml(&text3, "b.toml").unwrap();
    let e = sc.with_law("hertz").build_bridge().unwrap_err().to_string();
    assert!(
        e.contains("joint[0].contact.zeta is not used by law = \"hertz\"")
            && e.contains("b.toml:26"),
        "{e}"
    );
}

/// Bad site tables: an error naming `site.contact.KEY` and its line.
#[test]
fn bad_site_contact_tables_name_the_key_and_line() {
    let file = "[contact]\nlaw = \"kelvin\"\nk = 1.0e9\n";
    let cases: &[(&str, &str, &[&str])] = &[
        // unknown key
        (
            "[joint.contact]\nstiffness = 3",
            "",
            &["joint[0].contact.stiffness", "b.toml:26", "unknown key"],
        ),
        // a key the site's law does not read
        (
            "",
            "[joint.contact]\nk_h = 1e10",
            &[
                "joint[1].contact.k_h",
                "b.toml:28",
                "not used by law = \"kelvin\"",
            ],
        ),
        // bad value
        (
            "[joint.contact]\nk = -1.0",
            "",
            &["joint[0].contact.k", "b.toml:26", "invalid"],
        ),
        // wrong type
        (
            "[joint.contact]\nk = \"big\"",
            "",
            &["joint[0].contact.k", "b.toml:26", "must be a number"],
        ),
        // unknown law
        (
            "contact = { law = \"hook\" }",
            "",
            &["joint[0].contact.law", "b.toml:25", "unknown contact law"],
        ),
    ];
    for (j1, j2, want) in cases {
        let text = bridge(&format!("{}{file}", joints(j1, j2)));
        let e = build(&text).unwrap_err();
        for w in *want {
            assert!(e.contains(w), "{j1:?} {j2:?}: {e} lacks {w}");
        }
    }
    // an abutment key
    let text = bridge(&format!("[abutment.end.contact]\nzeta = 0.1\n{file}"));
    let e = build(&text).unwrap_err();
    assert!(
        e.contains("abutment.end.contact.zeta") && e.contains("b.toml:25"),
        "{e}"
    );
}
