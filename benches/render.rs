//! Whole-process render time: `jamchart render fig3` and `jamchart render` (all scenes).
//!
//! `cargo bench --bench render`; runs the release binary 11 times each in a temporary directory
//! and prints the medians. It prints no ratio to a Python baseline: a ratio needs the baseline
//! measured in the same run on the same machine, and the repository holds no numpy +
//! matplotlib script to run (the "2.7 s" it used to divide by was measured rounds ago). Goal
//! (issue 21): `render fig3` at least 25x faster than such a script, timed beside it.

mod common;

use common::median;

use std::path::Path;
use std::process::Command;
use std::time::Instant;

fn time_render(scenes: &[&str], runs: usize) -> f64 {
    let out = tempfile::tempdir().expect("temp dir");
    let charts = Path::new(env!("CARGO_MANIFEST_DIR")).join("charts");
    let times = (0..runs)
        .map(|_| {
            let t0 = Instant::now();
            let status = Command::new(env!("CARGO_BIN_EXE_jamchart"))
                .arg("render")
                .args(scenes)
                .arg("--out")
                .arg(out.path())
                .arg("--scenes-dir")
                .arg(&charts)
                .output()
                .expect("the binary runs")
                .status;
            assert!(status.success(), "render failed");
            t0.elapsed().as_secs_f64()
        })
        .collect();
    median(times)
}

fn main() {
    let fig3 = time_render(&["fig3"], 11);
    let all = time_render(&[], 11);
    println!("whole-process render, median of 11 runs:");
    println!("  render fig3: {:.1} ms", fig3 * 1e3);
    println!(
        "  render (all scenes): {:.1} ms (goal under 0.8 s on 2 cores, issue 21)",
        all * 1e3
    );
}
