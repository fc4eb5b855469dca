//! The Python package: builds it with `pip install .` (maturin, the `python` feature) into a
//! virtual environment under the target folder, with the pinned test tools of
//! `tests/python/requirements.txt` from PyPI, and runs its pytest suite (`tests/python/`)
//! against this build's binary.
//!
//! Without a `python3` the test is skipped, saying so on stderr ("skipped: no python3"); under
//! `CI=true` it fails instead, so a machine without Python never passes CI silently.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The target folder (`CARGO_TARGET_DIR` or `target/`).
fn target() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root().join("target"))
}

/// Runs `cmd`, panicking with what it printed when it fails.
fn run(cmd: &mut Command) {
    let shown = format!("{cmd:?}");
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("{shown} did not start: {e}"));
    assert!(
        out.status.success(),
        "{shown} failed ({}):\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The virtual environment with the test tools, made (or remade when the requirements change).
fn venv() -> PathBuf {
    let venv = target().join("python-venv");
    let python = venv.join("bin/python");
    let requirements = root().join("tests/python/requirements.txt");
    let wanted = std::fs::read_to_string(&requirements).expect("tests/python/requirements.txt");
    // The requirements the environment was made from, written after pip succeeded.
    let stamp = venv.join("jamchart-requirements.txt");
    if python.is_file() && std::fs::read_to_string(&stamp).ok().as_deref() == Some(&wanted) {
        return python;
    }
    eprintln!("making {} from {}", venv.display(), requirements.display());
    run(Command::new("python3").args(["-m", "venv", "--clear"]).arg(&venv));
    run(Command::new(&python)
        .args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-r"])
        .arg(&requirements));
    std::fs::write(&stamp, &wanted).expect("write the requirements stamp");
    python
}

#[test]
fn the_python_package_passes_its_tests() {
    if Command::new("python3").arg("--version").output().is_err() {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "python3 is missing, and CI=true needs the Python package tested: install \
             python3 with its venv module"
        );
        eprintln!("\n*** skipped: no python3 (the Python package is not tested) ***\n");
        return;
    }
    let python = venv();
    let bin = python.parent().expect("the venv's bin folder").to_path_buf();
    let path = std::env::join_paths(
        std::iter::once(bin).chain(std::env::split_paths(
            &std::env::var_os("PATH").unwrap_or_default(),
        )),
    )
    .expect("a PATH");
    // maturin builds in the shared target folder: the crates the CLI built are reused.
    run(Command::new(&python)
        .args([
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            "--no-build-isolation",
            "--no-deps",
            "--force-reinstall",
        ])
        .arg(root())
        .env("PATH", &path)
        .env("CARGO_TARGET_DIR", target()));
    let status = Command::new(&python)
        .args(["-m", "pytest", "-q", "-p", "no:cacheprovider"])
        .arg(root().join("tests/python"))
        .current_dir(root().join("tests/python"))
        .env("PATH", &path)
        .env("JAMCHART_BIN", env!("CARGO_BIN_EXE_jamchart"))
        .status()
        .expect("pytest starts");
    assert!(status.success(), "pytest failed ({status}): its report is above");
}
