//! The Python baseline the benches time beside jamchart: a ratio is printed
//! only against a baseline measured in the same run.
//!
//! The scripts beside this file (`fig3.py`: the paper's Fig. 3 in numpy + matplotlib;
//! `vlocator.py`: the V-locator's closed-form capacity map in numpy; `radau.py`: one simulation
//! to the jam by scipy's Radau) run in a virtual environment under the target folder, made on
//! first use by `python3 -m venv` and `pip install -r requirements.txt` (pinned versions from
//! PyPI) and remade when the requirements change. Where that cannot be done, [`python`] says
//! why and the bench prints `no baseline: <why>` and no ratio.

use std::path::{Path, PathBuf};
use std::process::Command;

/// This folder: the scripts and requirements.txt.
pub fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/baseline")
}

/// The interpreter of the baseline's virtual environment, made (or remade, when
/// requirements.txt changed) first; Err says why there is none.
pub fn python() -> Result<PathBuf, String> {
    venv("baseline-venv", &dir().join("requirements.txt"))
}

/// The target folder: `CARGO_TARGET_DIR`, or `target/` beside Cargo.toml.
pub fn target() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
}

/// The interpreter of the virtual environment `name` under the target folder with the
/// packages of `requirements` (pinned, from PyPI), made first, or remade when the file
/// changed; Err says why there is none. The Python package's test shares it
/// (`tests/python_package.rs`).
pub fn venv(name: &str, requirements: &Path) -> Result<PathBuf, String> {
    let venv = target().join(name);
    let python = venv.join("bin/python");
    let wanted = std::fs::read_to_string(requirements)
        .map_err(|e| format!("cannot read {}: {e}", requirements.display()))?;
    // The requirements the environment was made from: a copy written after pip succeeded.
    let stamp = venv.join("jamchart-requirements.txt");
    if python.is_file() && std::fs::read_to_string(&stamp).ok().as_deref() == Some(&wanted) {
        return Ok(python);
    }
    eprintln!(
        "installing {} into {} ...",
        requirements.display(),
        venv.display()
    );
    run(Command::new("python3")
        .args(["-m", "venv", "--clear"])
        .arg(&venv))?;
    run(pip_install(&python).arg("-r").arg(requirements))?;
    std::fs::write(&stamp, &wanted)
        .map_err(|e| format!("cannot write {}: {e}", stamp.display()))?;
    Ok(python)
}

/// `python -m pip install`, quiet: add what to install.
pub fn pip_install(python: &Path) -> Command {
    let mut cmd = Command::new(python);
    cmd.args([
        "-m",
        "pip",
        "install",
        "--quiet",
        "--disable-pip-version-check",
    ]);
    cmd
}

/// Runs `cmd`; Err names the command and what it printed when it fails or cannot start.
pub fn run(cmd: &mut Command) -> Result<(), String> {
    let shown = format!("{cmd:?}");
    let out = cmd
        .output()
        .map_err(|e| format!("{shown} did not start: {e}"))?;
    if out.status.success() {
        return Ok(());
    }
    let err = String::from_utf8_lossy(&out.stderr);
    let last = err
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("");
    Err(format!("{shown} failed ({}): {last}", out.status))
}
