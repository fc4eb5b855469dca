//! Whole-process render time: `jamchart render fig3` beside the paper's Fig. 3 in numpy +
//! matplotlib (benches/baseline/fig3.py: same grid, closed form, PNG and cells CSV), and
//! `jamchart render` (all scenes).
//!
//! `cargo bench --bench render`; runs jamchart and the Python script 11 times each,
//! interleaved (one of each in turn, so the machine's load falls on both alike), each in its
//! own temporary folder, and prints the median wall time and the median CPU time (user + sys
//! of the child) of each, and the ratio of the medians. Without the Python baseline (no
//! python3, no PyPI) it prints `no baseline: <why>` and no ratio. Goals: `render fig3` at
//! least 60x faster than the script; all scenes under 0.8 s on 2 cores. Where valgrind is
//! installed it also prints the instructions of one `render fig3` (callgrind: the same on a
//! loaded machine as on a quiet one).

mod baseline;
mod common;

use common::{median, time_process};

use std::path::Path;
use std::process::Command;

fn render(scenes: &[&str], out: &Path) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_jamchart"));
    cmd.arg("render")
        .args(scenes)
        .arg("--out")
        .arg(out)
        .arg("--scenes-dir")
        .arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("charts"))
        .arg("-q");
    cmd
}

/// Medians of (wall, cpu) over the runs.
fn medians(runs: &[(f64, f64)]) -> (f64, f64) {
    (
        median(runs.iter().map(|r| r.0).collect()),
        median(runs.iter().map(|r| r.1).collect()),
    )
}

fn main() {
    const RUNS: usize = 11;
    let python = baseline::python();
    let (ours, theirs) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    let mut rust = Vec::new();
    let mut py = Vec::new();
    for _ in 0..RUNS {
        rust.push(time_process(&mut render(&["fig3"], ours.path())));
        if let Ok(python) = &python {
            let mut cmd = Command::new(python);
            cmd.arg(baseline::dir().join("fig3.py")).arg(theirs.path());
            py.push(time_process(&mut cmd));
        }
    }
    let all: Vec<(f64, f64)> = (0..RUNS)
        .map(|_| time_process(&mut render(&[], ours.path())))
        .collect();
    let (rust, all) = (medians(&rust), medians(&all));
    println!("whole processes, medians of {RUNS} interleaved runs (wall, cpu = user + sys):");
    println!(
        "  jamchart render fig3: {:.1} ms wall, {:.1} ms cpu",
        rust.0 * 1e3,
        rust.1 * 1e3
    );
    match &python {
        Ok(_) => {
            let py = medians(&py);
            println!(
                "  numpy + matplotlib fig3 (benches/baseline/fig3.py): {:.1} ms wall, {:.1} ms cpu",
                py.0 * 1e3,
                py.1 * 1e3
            );
            println!(
                "  ratio: {:.1}x wall, {:.1}x cpu (goal at least 60x)",
                py.0 / rust.0,
                py.1 / rust.1
            );
        }
        Err(why) => println!("  no baseline: {why}"),
    }
    match common::instructions(&mut render(&["fig3"], ours.path())) {
        Some(n) => println!(
            "  jamchart render fig3: {:.1} M instructions (callgrind)",
            n / 1e6
        ),
        None => println!("  instructions: no valgrind"),
    }
    println!(
        "  jamchart render (all scenes): {:.1} ms wall, {:.1} ms cpu (goal under 0.8 s wall on \
         2 cores)",
        all.0 * 1e3,
        all.1 * 1e3
    );
}
