//! The Python package: builds it with `pip install .` (maturin, the `python` feature) into a
//! virtual environment under the target folder, with the pinned test tools of
//! `tests/python/requirements.txt` from PyPI, and runs its pytest suite (`tests/python/`)
//! against this build's binary.
//!
//! Without a `python3` the test is skipped, saying so on stderr ("skipped: no python3"); under
//! `CI=true` it fails instead, so a machine without Python never passes CI silently.

#[path = "../benches/baseline/mod.rs"]
#[allow(dead_code)] // the benches' scripts folder is not used here
mod baseline;

use std::path::Path;
use std::process::Command;

#[test]
fn the_python_package_passes_its_tests() {
    if Command::new("python3").arg("--version").output().is_err() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "python3 is missing, and CI=true needs the Python package tested: install \
             python3 with its venv module"
        );
        crate::common::say_skipped("no python3 (the Python package is not tested)");
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let python = baseline::venv("python-venv", &root.join("tests/python/requirements.txt"))
        .unwrap_or_else(|why| panic!("no environment for the Python package: {why}"));
    // maturin (the build backend, installed in the environment) is found on its PATH.
    let bin = python
        .parent()
        .expect("the venv's bin folder")
        .to_path_buf();
    let old = std::env::var_os("PATH").unwrap_or_default();
    let path = std::env::join_paths(std::iter::once(bin).chain(std::env::split_paths(&old)))
        .expect("a PATH");
    // Built in the shared target folder: the crates the CLI built are reused.
    baseline::run(
        Command::new(&python)
            .args([
                "-m",
                "pip",
                "install",
                "--quiet",
                "--disable-pip-version-check",
            ])
            .args(["--no-build-isolation", "--no-deps", "--force-reinstall"])
            .arg(root)
            .env("PATH", &path)
            .env("CARGO_TARGET_DIR", baseline::target()),
    )
    .unwrap_or_else(|why| panic!("the package does not build: {why}"));
    let status = Command::new(&python)
        .args(["-m", "pytest", "-q", "-p", "no:cacheprovider"])
        .arg(root.join("tests/python"))
        .current_dir(root.join("tests/python"))
        .env("PATH", &path)
        .env("JAMCHART_BIN", env!("CARGO_BIN_EXE_jamchart"))
        .status()
        .expect("pytest starts");
    assert!(
        status.success(),
        "pytest failed ({status}): its report is above"
    );
}
