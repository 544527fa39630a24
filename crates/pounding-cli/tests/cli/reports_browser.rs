//! Headless-browser check of the reports (issue 12 acceptance): `report.html` of `pounding study`
//! (a small scenario with figures, so an index page and two geometry pages), of `pounding
//! simulate` and of `pounding compare` (two decks, and the three-segment viaduct each) are
//! opened in headless Chromium.
//!
//! * Rust crawls every page reachable from `report.html`: each `src=`/`href=` target is relative
//!   and exists; PNG targets decode in full.
//! * Chromium loads each page inside a probe page (a test-only page with a script; the reports
//!   themselves have none but for a bridge run's plan animation) that lists every image whose `naturalWidth` is 0 (missing, or not an
//!   image): none may be. Any console message of a report page (`INFO:CONSOLE` in Chromium's
//!   log: errors, uncaught exceptions) fails the test.
//! * Each page is screenshot at 1400 × 2000 px: the PNG must decode at that size and not be blank.
//!
//! Chromium is Debian's `chromium` (`/usr/bin/chromium`; `$POUNDING_CHROMIUM` overrides); `.ci/run`
//! installs it when it runs as root. Without it the test is skipped with the reason printed and
//! logged to `$POUNDING_SKIP_LOG`.

use crate::{pounding, scratch_dir, skipped};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The Chromium binary, if one runs (`--version` succeeds).
pub(crate) fn chromium() -> Option<PathBuf> {
    let candidates: Vec<PathBuf> = match std::env::var_os("POUNDING_CHROMIUM") {
        Some(p) => vec![p.into()],
        None => ["chromium", "chromium-browser", "/usr/bin/chromium"]
            .map(PathBuf::from)
            .to_vec(),
    };
    candidates.into_iter().find(|c| {
        Command::new(c)
            .arg("--version")
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    })
}

/// Runs headless Chromium on `url` with `extra` arguments: (stdout, stderr). Fails after 60 s.
pub(crate) fn headless(
    chrome: &Path,
    profile: &Path,
    extra: &[String],
    url: &str,
) -> (String, String) {
    let dir = profile.parent().unwrap();
    let (out_p, err_p) = (dir.join("chrome.out"), dir.join("chrome.err"));
    let mut child = Command::new(chrome)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--allow-file-access-from-files",
            "--virtual-time-budget=10000",
            "--enable-logging=stderr",
            "--v=0",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(url)
        .stdout(std::fs::File::create(&out_p).unwrap())
        .stderr(std::fs::File::create(&err_p).unwrap())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let err = std::fs::read_to_string(&err_p).unwrap_or_default();
            assert!(
                status.success(),
                "chromium on {url} exited with {status}:\n{err}"
            );
            return (std::fs::read_to_string(&out_p).unwrap_or_default(), err);
        }
        if t0.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("chromium on {url} did not finish within 60 s");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// `file://` URL of an absolute path (percent-encoding what a temporary path may hold).
pub(crate) fn file_url(p: &Path) -> String {
    let mut u = String::from("file://");
    for b in p.to_str().unwrap().bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'/' | b'-' | b'_' | b'.' | b'~' => {
                u.push(b as char)
            }
            _ => u.push_str(&format!("%{b:02X}")),
        }
    }
    u
}

/// Every HTML page reachable from `out/report.html` (itself included), after checking that each
/// `src=`/`href=` target of each page is relative and exists (PNGs with the PNG signature).
fn crawl(out: &Path) -> Vec<PathBuf> {
    let mut seen = BTreeSet::new();
    let mut todo = vec![out.join("report.html")];
    while let Some(page) = todo.pop() {
        let page = page.canonicalize().unwrap();
        if !seen.insert(page.clone()) {
            continue;
        }
        let html = std::fs::read_to_string(&page).unwrap();
        // Scripts only in the plan animation of a bridge run, inline (no `src`).
        assert!(
            !html.contains("<script") || html.contains("id=\"an-plan\""),
            "{} has a script",
            page.display()
        );
        assert!(
            !html.contains("<script src"),
            "{} loads a script",
            page.display()
        );
        for attr in ["src=\"", "href=\""] {
            for part in html.split(attr).skip(1) {
                let target = &part[..part.find('"').unwrap()];
                let file = target.split('#').next().unwrap();
                if file.is_empty() {
                    continue;
                }
                assert!(
                    !target.contains("://") && !target.starts_with('/'),
                    "{}: non-relative link {target}",
                    page.display()
                );
                let p = page.parent().unwrap().join(file);
                assert!(p.is_file(), "{} links to missing {target}", page.display());
                if file.ends_with(".png") {
                    // Decoded in full (Chromium shows a truncated PNG's header size).
                    if let Err(err) = image::open(&p) {
                        panic!("{}: {target} does not decode: {err}", page.display());
                    }
                }
                if file.ends_with(".html") {
                    todo.push(p);
                }
            }
        }
    }
    seen.into_iter().collect()
}

/// Loads `page` in Chromium through a probe page and screenshots it; returns the number of
/// images the page shows.
fn check_page(chrome: &Path, work: &Path, page: &Path, tag: &str) -> usize {
    let probe = work.join(format!("probe-{tag}.html"));
    std::fs::write(
        &probe,
        format!(
            "<!DOCTYPE html><html><body><div id=\"r\">PROBE pending</div>\
             <iframe id=\"f\" src=\"{}\" width=\"1400\" height=\"2000\"></iframe><script>\
             document.getElementById('f').onload = function () {{\
             var r = document.getElementById('r');\
             try {{ var imgs = Array.from(this.contentDocument.images);\
             var bad = imgs.filter(function (i) {{ return !(i.complete && i.naturalWidth > 0); }})\
             .map(function (i) {{ return i.getAttribute('src'); }});\
             r.textContent = 'PROBE images=' + imgs.length + ' bad=' + JSON.stringify(bad) + ' END';\
             }} catch (e) {{ r.textContent = 'PROBE error ' + e + ' END'; }} }};</script></body></html>",
            file_url(page)
        ),
    )
    .unwrap();
    let profile = work.join("profile");
    let (dom, log) = headless(chrome, &profile, &["--dump-dom".into()], &file_url(&probe));
    let shown = page.display();
    let result = dom
        .split("PROBE ")
        .nth(1)
        .and_then(|r| r.split(" END").next())
        .unwrap_or("no probe result");
    let Some(rest) = result.strip_prefix("images=") else {
        panic!("{shown}: the probe did not run: {result}\n{log}");
    };
    let (n, bad) = rest.split_once(" bad=").unwrap();
    assert_eq!(bad, "[]", "{shown}: images that did not load: {bad}");
    // Console messages of the report page (the probe itself logs nothing).
    let console = console_messages(&log);
    assert!(
        console.is_empty(),
        "{shown}: console messages:\n{}",
        console.join("\n")
    );
    // Screenshot of the page itself: decodes at the window size and is not blank.
    let shot = work.join(format!("screenshot-{tag}.png"));
    let args = [
        format!("--screenshot={}", shot.display()),
        "--window-size=1400,2000".to_string(),
    ];
    headless(chrome, &profile, &args, &file_url(page));
    let img = image::open(&shot).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (1400, 2000), "{shown}");
    let colours: BTreeSet<[u8; 3]> = img.pixels().step_by(97).map(|p| p.0).collect();
    assert!(colours.len() > 20, "{shown}: the screenshot looks blank");
    n.parse().unwrap()
}

/// Runs `pounding ARGS` (must succeed) and checks every page of `out`'s report in Chromium:
/// (pages, images).
fn run_and_check(chrome: &Path, work: &Path, args: &[&str], out: &Path) -> (usize, usize) {
    let o = pounding().args(args).output().unwrap();
    assert!(
        o.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    let pages = crawl(out);
    let mut images = 0;
    for (k, p) in pages.iter().enumerate() {
        let tag = format!("{}-{k}", out.file_name().unwrap().to_string_lossy());
        images += check_page(chrome, work, p, &tag);
    }
    (pages.len(), images)
}

#[test]
fn both_reports_load_in_headless_chromium() {
    let Some(chrome) = chromium() else {
        skipped(
            "no runnable chromium (install Debian's `chromium` package; .ci/run does so when \
             it runs as root with apt-get)",
        );
        return;
    };
    let work = scratch_dir("browser", "reports");
    let sc = work.join("study.toml");
    // The small study of `study.rs` (2 geometries, 2 μ) with figures.
    let scenario = crate::study::SMALL.replace("figures = false", "region_map_samples = 21");
    std::fs::write(&sc, scenario).unwrap();
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let study = work.join("study");
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &["study", &s(&sc), "--out", &s(&study)],
        &study,
    );
    // Index (3 overview figures) + 2 geometry pages (2 surfaces + 1 region map each).
    assert_eq!((pages, images), (3, 3 + 2 * 3));
    let two = work.join("two-decks");
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &["simulate", "--duration", "3", "--out", &s(&two)],
        &two,
    );
    assert_eq!(pages, 1);
    assert!(images >= 3, "two-deck report shows {images} images");
    let viaduct = work.join("viaduct");
    let example =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/viaduct-rigid-1d.toml");
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &[
            "simulate",
            &s(&example),
            "--duration",
            "3",
            "--out",
            &s(&viaduct),
        ],
        &viaduct,
    );
    assert_eq!(pages, 1);
    assert!(images >= 3, "viaduct report shows {images} images");
    // the fragility report of the tiny study, with its code-check section
    let frag = work.join("fragility");
    std::fs::create_dir_all(&frag).unwrap();
    std::fs::write(
        frag.join("bridge.toml"),
        format!(
            "{}{}",
            crate::fragility::SCENARIO,
            crate::fragility_report::CODE_CHECK
        ),
    )
    .unwrap();
    std::fs::write(frag.join("set.toml"), crate::fragility_report::SET).unwrap();
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &[
            "fragility",
            &s(&frag.join("bridge.toml")),
            "--out",
            &s(&frag.join("out")),
        ],
        &frag.join("out"),
    );
    assert_eq!((pages, images), (1, 1));
    // `compare` of the two decks (two overlay figures) and of the viaduct (its gap panels)
    let cmp = work.join("compare-two-decks");
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &[
            "compare",
            "--duration",
            "3",
            "--laws",
            "rigid,kelvin",
            "--out",
            &s(&cmp),
        ],
        &cmp,
    );
    assert_eq!((pages, images), (1, 2));
    let cmp = work.join("compare-viaduct");
    let (pages, images) = run_and_check(
        &chrome,
        &work,
        &[
            "compare",
            &s(&example),
            "--duration",
            "3",
            "--laws",
            "rigid,bilinear",
            "--out",
            &s(&cmp),
        ],
        &cmp,
    );
    assert_eq!((pages, images), (1, 1));
    // The screenshots (screenshot-*.png) go with the scratch directory; POUNDING_KEEP_SCRATCH=1
    // keeps them to look at (docs/development.md). Chromium's profile goes in any case.
    let _ = std::fs::remove_dir_all(work.join("profile"));
}

/// The console messages and failed loads in a headless Chromium log.
pub(crate) fn console_messages(log: &str) -> Vec<&str> {
    log.lines()
        .filter(|l| l.contains(":CONSOLE") || l.contains("Failed to load resource"))
        .collect()
}
