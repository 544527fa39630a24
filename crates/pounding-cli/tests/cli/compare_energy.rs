//! `compare`'s energy warning says the contacts that created energy are listed in report.html:
//! the page lists each of them under its law, the same entries as `simulate`'s `summary.json`
//! `"warnings"` for that law (found by a fresh-clone trial: the page showed only the summary
//! sentence).

use crate::{run_capture, scratch_dir};

/// `(contact, kind, impact, t, amount)` of one entry.
type Entry = (String, String, u64, f64, f64);

#[test]
fn compare_report_lists_every_contact_that_created_energy_as_simulate_does() {
    let d = scratch_dir("compare_energy", "bilinear");
    let (cmp, sim) = (d.join("cmp"), d.join("sim"));
    // the two-deck default: bilinear creates energy at a contact (a discretisation error)
    let (code, _, err) = run_capture(&[
        "compare",
        "--laws",
        "bilinear",
        "--out",
        cmp.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("every one is listed"), "{err}");
    let (code, _, err) = run_capture(&[
        "simulate",
        "--law",
        "bilinear",
        "--out",
        sim.to_str().unwrap(),
    ]);
    assert_eq!(code, Some(0), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(sim.join("summary.json")).unwrap()).unwrap();
    let want: Vec<Entry> = summary["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|w| {
            w["kind"]
                .as_str()
                .unwrap()
                .starts_with("contact_energy_created")
        })
        .map(|w| {
            (
                w["contact"].as_str().unwrap().to_string(),
                w["kind"].as_str().unwrap().to_string(),
                w["impact"].as_u64().unwrap(),
                w["t_s"].as_f64().unwrap(),
                w["amount_j"].as_f64().unwrap(),
            )
        })
        .collect();
    assert!(!want.is_empty(), "simulate warns of no created energy");

    let html = std::fs::read_to_string(cmp.join("report.html")).unwrap();
    let section = crate::report_warnings(&html)
        .split("<h3>bilinear: energy created, contact by contact</h3>")
        .nth(1)
        .unwrap_or_else(|| panic!("no contact list in {}", crate::report_warnings(&html)));
    let table = section.split("</table>").next().unwrap();
    let got: Vec<Entry> = table
        .lines()
        .filter(|l| l.starts_with("<tr><td"))
        .map(|l| {
            let cells: Vec<&str> = l
                .split("<td")
                .skip(1)
                .map(|c| {
                    let c = &c[c.find('>').unwrap() + 1..];
                    &c[..c.find("</td>").unwrap()]
                })
                .collect();
            (
                cells[0].to_string(),
                cells[1].to_string(),
                cells[2].parse().unwrap(),
                cells[3].parse().unwrap(),
                cells[4].parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(got, want);
}
