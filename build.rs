//! Compiles the scene files `charts/*.toml` into the binary (see `src/charts/builtin.rs`): a
//! scene is added by adding its file, with no list to keep in step. Also records the git commit
//! for `--version` (`JAMCHART_GIT_COMMIT`, "unknown" without git or outside a checkout).

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    // Read when the script runs, not when it is compiled: a build script compiled in another
    // checkout (a target/ copied or shared between worktrees) must still read this one's scenes.
    let manifest_dir = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let charts = Path::new(&manifest_dir).join("charts");
    println!("cargo::rerun-if-changed={}", charts.display());
    let mut scenes: Vec<(String, String)> = std::fs::read_dir(&charts)
        .expect("charts/ is readable")
        .map(|e| e.expect("charts/ is readable").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let name = p.file_stem().expect("a file name").to_string_lossy().into();
            println!("cargo::rerun-if-changed={}", p.display());
            (name, p.display().to_string())
        })
        .collect();
    scenes.sort();
    let mut out = String::from("&[\n");
    for (name, path) in &scenes {
        writeln!(out, "    ({name:?}, include_str!({path:?})),").expect("writes to a String");
    }
    out.push(']');
    let dest = Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("scenes.rs");
    std::fs::write(dest, out).expect("OUT_DIR is writable");
    git_commit(Path::new(&manifest_dir));
}

/// Sets `JAMCHART_GIT_COMMIT` to the checkout's commit, or "unknown": a build from a source
/// tarball, or on a machine without git, must not fail for want of it.
fn git_commit(dir: &Path) {
    let git = |args: &[&str]| -> Option<String> {
        let out = std::process::Command::new("git")
            .args(args)
            .current_dir(dir)
            .output()
            .ok()?;
        let text = String::from_utf8(out.stdout).ok()?;
        (out.status.success() && !text.trim().is_empty()).then(|| text.trim().to_string())
    };
    let commit = git(&["rev-parse", "HEAD"]);
    println!(
        "cargo::rustc-env=JAMCHART_GIT_COMMIT={}",
        commit.as_deref().unwrap_or("unknown")
    );
    if commit.is_none() {
        return;
    }
    // Run again when HEAD moves: a commit on the branch, or a checkout of another one. Only
    // files that exist (cargo reruns every build for a missing one); a worktree's HEAD and the
    // shared refs both come from `--git-path`.
    let mut watched = vec!["HEAD".to_string(), "packed-refs".to_string()];
    watched.extend(git(&["symbolic-ref", "-q", "HEAD"]));
    for name in watched {
        if let Some(p) = git(&["rev-parse", "--git-path", &name]) {
            let p = dir.join(p);
            if p.exists() {
                println!("cargo::rerun-if-changed={}", p.display());
            }
        }
    }
}
