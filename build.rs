//! Compiles the scene files `charts/*.toml` into the binary (see `src/charts/builtin.rs`): a
//! scene is added by adding its file, with no list to keep in step.

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
}
