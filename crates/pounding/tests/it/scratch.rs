//! Scratch directories for tests that write files: each is removed with its contents when its
//! guard is dropped, so that no run (passing or failing) leaves anything in the user's temporary
//! directory. Shared by the library's integration tests (`pounding/tests/it`) and the CLI's
//! (`pounding-cli/tests/cli`, through `#[path]`).
#![allow(dead_code)]

/// A fresh, empty scratch directory `pounding-{prefix}-{name}-XXXXXX` under the system's temporary
/// directory (shared by the test modules), removed with its contents when the returned guard is
/// dropped, also when the test fails. Hold the guard for as long as the directory is used.
pub fn scratch_dir(prefix: &str, name: &str) -> Scratch {
    Scratch::new(&format!("pounding-{prefix}-{name}-"))
}

/// A scratch directory that is removed, with everything in it, when dropped: at the end of the test
/// or while a failing test unwinds. With `POUNDING_KEEP_SCRATCH` set it is kept instead and its
/// path printed on stderr, for inspection. Dereferences to its [`Path`](std::path::Path).
pub struct Scratch(tempfile::TempDir);

impl Scratch {
    fn new(prefix: &str) -> Scratch {
        let keep = std::env::var_os("POUNDING_KEEP_SCRATCH").is_some();
        let d = tempfile::Builder::new()
            .prefix(prefix)
            .disable_cleanup(keep)
            .tempdir()
            .unwrap();
        if keep {
            eprintln!("scratch directory kept: {}", d.path().display());
        }
        Scratch(d)
    }
}

impl std::ops::Deref for Scratch {
    type Target = std::path::Path;
    fn deref(&self) -> &std::path::Path {
        self.0.path()
    }
}

impl AsRef<std::path::Path> for Scratch {
    fn as_ref(&self) -> &std::path::Path {
        self.0.path()
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.0.path().as_os_str()
    }
}

impl Scratch {
    /// The path `rel` inside this directory, holding the directory (the guard) for as long as the
    /// path is held: for helpers that return a path inside a scratch directory.
    pub fn into_join(self, rel: impl AsRef<std::path::Path>) -> InScratch {
        InScratch {
            path: self.join(rel),
            _dir: self,
        }
    }
}

/// A path inside a [`Scratch`] directory that keeps the directory until dropped. Dereferences to
/// its [`Path`](std::path::Path).
pub struct InScratch {
    path: std::path::PathBuf,
    _dir: Scratch,
}

impl std::ops::Deref for InScratch {
    type Target = std::path::Path;
    fn deref(&self) -> &std::path::Path {
        &self.path
    }
}

impl AsRef<std::path::Path> for InScratch {
    fn as_ref(&self) -> &std::path::Path {
        &self.path
    }
}

impl AsRef<std::ffi::OsStr> for InScratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.path.as_os_str()
    }
}

#[test]
fn a_scratch_directory_is_removed_when_its_test_fails() {
    if std::env::var_os("POUNDING_KEEP_SCRATCH").is_some() {
        return; // kept on purpose
    }
    let mut path = None;
    let failed = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let d = scratch_dir("scratch", "unwind");
        std::fs::create_dir_all(d.join("out")).unwrap();
        std::fs::write(d.join("out/f.txt"), "x").unwrap();
        path = Some(d.to_path_buf());
        panic!("a failing test (expected)");
    }));
    assert!(failed.is_err());
    let p = path.unwrap();
    assert!(!p.exists(), "{} left behind", p.display());
    // and a helper's path inside one keeps it alive until dropped
    let inside = scratch_dir("scratch", "into").into_join("out");
    std::fs::write(&*inside, "x").unwrap();
    let parent = inside.parent().unwrap().to_path_buf();
    assert!(parent.is_dir());
    drop(inside);
    assert!(!parent.exists(), "{} left behind", parent.display());
}
