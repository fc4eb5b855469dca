//! The Python package: builds it with `pip install .` (maturin, the `python` feature) into a
//! virtual environment under the target folder, with the pinned test tools of
//! `tests/python/requirements.txt` from PyPI, and runs its pytest suite (`tests/python/`)
//! against this build's binary.
//!
//! Without a `python3` the test is skipped, saying so on stderr ("skipped: no python3"); under
//! `CI=true` it fails instead, so a machine without Python never passes CI silently.
//!
//! The package is built into the target folder of `cargo test`, so that its build compiles
//! jamchart and pyo3 and reuses every other crate; a second test checks that the two builds
//! resolve those crates alike.

#[path = "../benches/baseline/mod.rs"]
#[allow(dead_code)] // the benches' scripts folder is not used here
mod baseline;

use std::collections::{BTreeMap, BTreeSet};
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

/// The Python package's build (maturin runs cargo with `--no-default-features --features
/// python`) reuses a crate that `cargo test` compiled only when both builds resolve it with the
/// same features; one that differs is compiled again with every crate above it (syn's features
/// took serde's, clap's and thiserror's derives along, and clap and the charts' crates after
/// them). Cargo.toml names what either build turns on for the other; this fails when a
/// dependency change turns on something it does not name, and says in which crate.
#[test]
fn the_python_build_shares_every_crate_with_the_test_build() {
    let test_build = features(&["--edges", "normal,build,dev"]);
    let python_build = features(&[
        "--edges",
        "normal,build",
        "--no-default-features",
        "--features",
        "python",
    ]);
    let differ: Vec<String> = python_build
        .iter()
        .filter(|(package, _)| !package.starts_with("jamchart "))
        .filter_map(|(package, python)| {
            let test = test_build.get(package)?;
            (test != python).then(|| format!("{package}: tests {test:?}, Python {python:?}"))
        })
        .collect();
    assert!(
        python_build.keys().any(|p| p.starts_with("pyo3 ")) && test_build.len() > 100,
        "cargo tree listed too little to compare: {} and {} packages",
        test_build.len(),
        python_build.len()
    );
    assert!(
        differ.is_empty(),
        "the Python package's build would compile these again: name the features in \
         Cargo.toml (beside `smallvec`)\n{}",
        differ.join("\n")
    );
}

/// Each package of the build that `args` selects (`cargo tree`), with the feature lists it is
/// compiled with (two when it is both a build-time and a run-time dependency). Not offline:
/// on a fresh machine the test build has not downloaded the crates only the Python build uses
/// (ndarray), and `cargo tree` reads their manifests.
fn features(args: &[&str]) -> BTreeMap<String, BTreeSet<String>> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .args(["tree", "--locked", "--prefix", "none", "--no-dedupe"])
        .args(["--format", "{p}|{f}", "--manifest-path"])
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml"))
        .args(args)
        .output()
        .expect("cargo starts");
    assert!(
        out.status.success(),
        "cargo tree {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut packages: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        // "name vX.Y.Z (path)|feature,feature": the path only for a local package.
        let Some((package, features)) = line.split_once('|') else {
            continue;
        };
        let id = package.split(" (").next().unwrap_or(package).trim();
        packages
            .entry(id.to_string())
            .or_default()
            .insert(features.trim().to_string());
    }
    packages
}
