//! Headless-browser check of the plan animation in `report.html` of `pounding simulate` on a
//! bridge: the page is opened offline in Chromium inside a probe page that moves the time slider
//! to three frames (a quarter of the run, the first impact, the end) and reads the player's
//! state. At each, the drawn displacements `x_i, y_i, θ_i` equal `history.csv`'s row at that
//! time and each drawn centroid is `G⁰ + o_i + f d` for the shown magnification `f`, with the
//! gap offsets `o_{k+1} − o_k = (f − 1)(S_{k+1} − E_k)` (the joints' gaps magnified as the
//! displacements); at the first
//! impact a marker is drawn at that impact's joint (nearest joint of the plan) with its time.
//! The bridge has restrainers: at each of the three frames every drawn restrainer tension equals
//! `restrainers.csv`'s row, and every seated end's drawn seat displacement equals the one
//! computed here from `history.csv`'s row and the end's corners (and stays within the run's
//! peak for that end).
//! No console message may appear. Skipped (reason printed) without Chromium, as
//! [`crate::reports_browser`].

use crate::reports_browser::{chromium, file_url, headless};
use crate::{pounding, scratch_dir, skipped};
use serde_json::Value;
use std::path::Path;

/// `history.csv` as (header, rows).
fn csv(p: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(p).unwrap();
    let mut lines = text.lines();
    let head = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    (head, rows)
}

#[test]
fn plan_animation_draws_history_positions_and_impacts() {
    let Some(chrome) = chromium() else {
        skipped("no runnable chromium (install Debian's `chromium` package)");
        return;
    };
    let work = scratch_dir("browser", "anim");
    let out = work.join("viaduct");
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-rigid-1d.toml");
    // the example with restrainers at both joints
    let text = std::fs::read_to_string(&source).unwrap();
    assert!(text.contains("\nseat_length = 0.4\n"));
    let example = work.join("viaduct-restrained.toml");
    std::fs::write(
        &example,
        text.replacen(
            "\nseat_length = 0.4\n",
            "\nseat_length = 0.4\nrestrainer_k = 5.0e7\nrestrainer_slack = 0.01\n",
            1,
        ),
    )
    .unwrap();
    let o = pounding()
        .args([
            "simulate",
            example.to_str().unwrap(),
            "--duration",
            "3",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The first impact (impacts.csv: impact,t_s,site,...; site `jointK`, 1-based).
    let impacts = std::fs::read_to_string(out.join("impacts.csv")).unwrap();
    let first: Vec<&str> = impacts
        .lines()
        .nth(1)
        .expect("an impact")
        .split(',')
        .collect();
    let t_imp: f64 = first[1].parse().unwrap();
    // its total normal impulse over its contacts (the rows of the same impact and site)
    let head: Vec<&str> = impacts.lines().next().unwrap().split(',').collect();
    let col = head.iter().position(|h| *h == "impulse_n_Ns").unwrap();
    let impulse: f64 = impacts
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|r| r[0] == first[0] && r[2] == first[2])
        .map(|r| r[col].parse::<f64>().unwrap())
        .sum();
    let joint: usize = first[2]
        .strip_prefix("joint")
        .unwrap()
        .parse::<usize>()
        .unwrap()
        - 1;
    let probe = work.join("probe.html");
    std::fs::write(
        &probe,
        format!(
            "<!DOCTYPE html><html><body><div id=\"r\">PROBE pending</div>\
             <iframe id=\"f\" src=\"{}\" width=\"1400\" height=\"1200\"></iframe><script>\
             document.getElementById('f').onload = function () {{\
             var r = document.getElementById('r');\
             try {{ var A = this.contentWindow.poundingAnim, N = A.data.frames.length, res = [];\
             [Math.floor(N / 4), A.frameAt({t_imp}), N - 1].forEach(function (k) {{\
             var s = this.contentDocument.getElementById('an-t'); s.value = k;\
             s.dispatchEvent(new Event('input'));\
             res.push({{frame: A.state.frame, t: A.data.frames[A.state.frame].t, mag: A.state.mag,\
             drawn: A.state.drawn, markers: A.state.markers, seats: A.state.seats,\
             restrainers: A.state.restrainers, offsets: A.state.offsets}}); }}, this);\
             var seen = 0; for (var k = 0; k < N; k++) {{ A.setFrame(k);\
             A.state.markers.forEach(function (m) {{ seen += m.impacts; }}); }}\
             var w = this.contentWindow, q = [], now = 0; w.requestAnimationFrame = function (cb) {{ q.push(cb); }};\
             A.setFrame(0); var t0 = A.state.playT; this.contentDocument.getElementById('an-play').click();\
             for (var i = 0; i < 60 && q.length; i++) {{ now += 1000 / 60; q.shift()(now); }}\
             res.push({{seen: seen, impacts: A.data.impacts.length, played: A.state.playT - t0,\
             shown: A.data.frames[A.state.frame].t - t0}});\
             r.textContent = 'PROBE ' + JSON.stringify(res) + ' END';\
             }} catch (e) {{ r.textContent = 'PROBE error ' + e + ' END'; }} }};</script></body></html>",
            file_url(&out.join("report.html"))
        ),
    )
    .unwrap();
    let (dom, log) = headless(
        &chrome,
        &work.join("profile"),
        &["--dump-dom".into()],
        &file_url(&probe),
    );
    let console = crate::reports_browser::console_messages(&log);
    assert!(
        console.is_empty(),
        "console messages:\n{}",
        console.join("\n")
    );
    let result = dom
        .split("PROBE ")
        .nth(1)
        .and_then(|r| r.split(" END").next())
        .unwrap_or("no probe result");
    let states: Value = serde_json::from_str(result)
        .unwrap_or_else(|e| panic!("probe result {result}: {e}\n{log}"));
    let traj: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("trajectories.json")).unwrap())
            .unwrap();
    let (head, rows) = csv(&out.join("history.csv"));
    let n = traj["segments"].as_u64().unwrap() as usize;
    assert_eq!(head[3], "x1_m");
    let mut states = states.as_array().unwrap().clone();
    // every impact entry flashes in exactly one frame (its nearest); playing at 1× for one
    // second of page time (60 animation frames) advances the shown time by one second
    let play = states.pop().unwrap();
    assert_eq!(
        play["seen"], play["impacts"],
        "impacts flashed over all frames"
    );
    let played = play["played"].as_f64().unwrap();
    assert!((played - 59.0 / 60.0).abs() < 1e-9, "played {played} s");
    let shown = play["shown"].as_f64().unwrap();
    let spacing =
        traj["frames"][1]["t"].as_f64().unwrap() - traj["frames"][0]["t"].as_f64().unwrap();
    assert!(
        shown <= played + 1e-12 && shown > played - spacing - 1e-12,
        "shown {shown} s"
    );
    assert_eq!(states.len(), 3);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()));
    for st in &states {
        let t = st["t"].as_f64().unwrap();
        let row = rows
            .iter()
            .find(|r| close(r[0], t))
            .unwrap_or_else(|| panic!("no history row at t = {t}"));
        let drawn = st["drawn"].as_array().unwrap();
        assert_eq!(drawn.len(), n);
        let mag = st["mag"].as_f64().unwrap();
        let off = |i: usize, c: usize| st["offsets"][i][c].as_f64().unwrap();
        let corner = |s: usize, j: usize, a: usize| traj["corners"][s][j][a].as_f64().unwrap();
        for k in 0..n - 1 {
            for c in 0..2 {
                let s_next = (corner(k + 1, 0, c) + corner(k + 1, 1, c)) / 2.0;
                let e = (corner(k, 2, c) + corner(k, 3, c)) / 2.0;
                let want = (mag - 1.0) * (s_next - e);
                let got = off(k + 1, c) - off(k, c);
                assert!(
                    (got - want).abs() <= 1e-9 * (1.0 + want.abs()),
                    "gap offset of joint {}: {got} vs {want}",
                    k + 1
                );
            }
        }
        for (i, d) in drawn.iter().enumerate() {
            let want = [row[3 + 3 * i], row[4 + 3 * i], row[5 + 3 * i]];
            let got = ["x", "y", "theta_deg"].map(|k| d[k].as_f64().unwrap());
            for c in 0..3 {
                assert!(
                    close(got[c], want[c]),
                    "t {t} segment {}: {got:?} vs {want:?}",
                    i + 1
                );
            }
            let g0 = &traj["centroids"][i];
            for c in 0..2 {
                let g = g0[c].as_f64().unwrap() + off(i, c) + mag * want[c];
                let shown = d["centroid"][c].as_f64().unwrap();
                assert!(
                    close(shown, g),
                    "t {t} segment {} centroid {shown} vs {g}",
                    i + 1
                );
            }
        }
    }
    // Restrainer tensions and seat displacements at the three frames.
    let (rhead, rrows) = csv(&out.join("restrainers.csv"));
    let force_cols: Vec<usize> = (0..rhead.len())
        .filter(|&c| rhead[c].ends_with("_force_N"))
        .collect();
    assert_eq!(force_cols.len(), 2, "{rhead:?}");
    let mut engaged = false;
    for st in &states {
        let t = st["t"].as_f64().unwrap();
        let row = rows.iter().find(|r| close(r[0], t)).unwrap();
        let rrow = rrows.iter().find(|r| close(r[0], t)).unwrap();
        let drawn = st["restrainers"].as_array().unwrap();
        assert_eq!(drawn.len(), force_cols.len());
        for (d, &c) in drawn.iter().zip(&force_cols) {
            let f = d["force"].as_f64().unwrap();
            assert!(
                close(f, rrow[c]),
                "t {t}: restrainer force {f} vs {}",
                rrow[c]
            );
            engaged |= f > 0.0;
        }
        let seats = st["seats"].as_array().unwrap();
        let spec = traj["seats"].as_array().unwrap();
        assert_eq!(seats.len(), 2 * n);
        for (e, d) in spec.iter().zip(seats) {
            let i = e["segment"].as_u64().unwrap() as usize;
            let g = &traj["centroids"][i];
            let (gx, gy) = (g[0].as_f64().unwrap(), g[1].as_f64().unwrap());
            let (x, y, th) = (row[3 + 3 * i], row[4 + 3 * i], row[5 + 3 * i].to_radians());
            let nin = [0, 1].map(|a| e["inward"][a].as_f64().unwrap());
            let want = e["corners"]
                .as_array()
                .unwrap()
                .iter()
                .map(|p| {
                    let (px, py) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
                    let (rx, ry) = (px - gx, py - gy);
                    let dx = x + th.cos() * rx - th.sin() * ry - rx;
                    let dy = y + th.sin() * rx + th.cos() * ry - ry;
                    dx * nin[0] + dy * nin[1]
                })
                .fold(f64::NEG_INFINITY, f64::max);
            let got = d["displacement"].as_f64().unwrap();
            assert!(
                (got - want).abs() <= 1e-9,
                "t {t} {}: seat displacement {got} vs {want}",
                e["end"]
            );
            let length = e["length"].as_f64().unwrap();
            let peak = e["peak_ratio"].as_f64().unwrap() * length;
            assert!(
                got <= peak + 1e-12,
                "{}: {got} above the run's peak {peak}",
                e["end"]
            );
            assert!(close(d["remaining"].as_f64().unwrap(), length - got));
        }
    }
    assert!(engaged, "no restrainer in tension at the probed frames");
    // The first impact: a marker with its time at its joint.
    let st = &states[1];
    let marks = st["markers"].as_array().unwrap();
    let m = marks
        .iter()
        .find(|m| m["site_kind"] == "joint" && close(m["t"].as_f64().unwrap(), t_imp))
        .unwrap_or_else(|| panic!("no marker of the impact at {t_imp}: {marks:?}"));
    assert_eq!(m["site"].as_u64(), Some(joint as u64));
    let shown = m["impulse_n"].as_f64().unwrap();
    assert!(
        (shown - impulse).abs() <= 1e-9 * impulse,
        "marker impulse {shown} vs the impact's total {impulse}"
    );
    // Nearest joint (midpoint of segment k's end face and k+1's start face, at rest) to the marker.
    let (mx, my) = (m["x"].as_f64().unwrap(), m["y"].as_f64().unwrap());
    let c = &traj["corners"];
    let mid = |k: usize| -> (f64, f64) {
        let p = |s: usize, j: usize, a: usize| c[s][j][a].as_f64().unwrap();
        let x = (p(k, 2, 0) + p(k, 3, 0) + p(k + 1, 0, 0) + p(k + 1, 1, 0)) / 4.0;
        let y = (p(k, 2, 1) + p(k, 3, 1) + p(k + 1, 0, 1) + p(k + 1, 1, 1)) / 4.0;
        (x, y)
    };
    let nearest = (0..n - 1)
        .min_by(|&a, &b| {
            let d = |k| {
                let (x, y) = mid(k);
                (x - mx).hypot(y - my)
            };
            d(a).total_cmp(&d(b))
        })
        .unwrap();
    assert_eq!(
        nearest,
        joint,
        "marker at ({mx}, {my}) is not at joint {}",
        joint + 1
    );
    let _ = std::fs::remove_dir_all(work.join("profile"));
}
