//! Whole-process render time: `jamchart render fig3` beside the paper's Fig. 3 in numpy +
//! matplotlib (benches/baseline/fig3.py: same grid, closed form, PNG and cells CSV), and
//! `jamchart render` (all scenes) as a multiple of `render fig3`.
//!
//! `cargo bench --bench render`; runs `render fig3`, the Python script and `render` (all
//! scenes) 11 times each, interleaved (one of each in turn, so the machine's load falls on all
//! alike), each in its own temporary folder, and prints the median wall time and the median
//! CPU time (user + sys of the child) of each and the ratios of the medians. Without the
//! Python baseline (no python3, no PyPI) it prints `no baseline: <why>` and no ratio to it.
//! Goals: `render fig3` at least 60x faster than the script; all scenes within 12x `render
//! fig3`. Where valgrind is installed it also prints the instructions of one `render fig3` and
//! of one `render` (callgrind: the same on a loaded machine as on a quiet one) and their ratio,
//! the all-scenes goal measured without the load's noise. `render fig3` runs a second time with
//! `JAMCHART_SYNC=none` (its files renamed into place but not synced to the disk, as matplotlib
//! writes its own): the ratio at the script's durability beside the ratio at ours.

mod baseline;
mod common;

use common::{median, render_command, time_process};

use std::process::Command;

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
    // Each command replaces its own files only: `render fig3` in a folder that also held every
    // scene's charts read and rewrote their gallery page as well (14 % longer).
    let folder = || tempfile::tempdir().unwrap();
    let (ours, theirs, every, unsynced) = (folder(), folder(), folder(), folder());
    let mut rust = Vec::new();
    let mut rust_unsynced = Vec::new();
    let mut py = Vec::new();
    let mut all = Vec::new();
    for _ in 0..RUNS {
        rust.push(time_process(&mut render_command(&["fig3"], ours.path())));
        rust_unsynced.push(time_process(
            render_command(&["fig3"], unsynced.path()).env("JAMCHART_SYNC", "none"),
        ));
        if let Ok(python) = &python {
            let mut cmd = Command::new(python);
            cmd.arg(baseline::dir().join("fig3.py")).arg(theirs.path());
            py.push(time_process(&mut cmd));
        }
        all.push(time_process(&mut render_command(&[], every.path())));
    }
    let (rust, all, unsynced) = (medians(&rust), medians(&all), medians(&rust_unsynced));
    println!("whole processes, medians of {RUNS} interleaved runs (wall, cpu = user + sys):");
    println!(
        "  jamchart render fig3: {:.1} ms wall, {:.1} ms cpu",
        rust.0 * 1e3,
        rust.1 * 1e3
    );
    println!(
        "  jamchart render fig3, JAMCHART_SYNC=none: {:.1} ms wall, {:.1} ms cpu",
        unsynced.0 * 1e3,
        unsynced.1 * 1e3
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
                "  ratio: {:.1}x wall, {:.1}x cpu (goal at least 60x); with JAMCHART_SYNC=none \
                 (no sync, as the script): {:.1}x wall, {:.1}x cpu",
                py.0 / rust.0,
                py.1 / rust.1,
                py.0 / unsynced.0,
                py.1 / unsynced.1
            );
        }
        Err(why) => println!("  no baseline: {why}"),
    }
    println!(
        "  jamchart render (all scenes): {:.1} ms wall, {:.1} ms cpu: {:.1}x wall, {:.1}x cpu \
         of render fig3 (goal at most 12x)",
        all.0 * 1e3,
        all.1 * 1e3,
        all.0 / rust.0,
        all.1 / rust.1
    );
    let fig3 = common::instructions(&mut render_command(&["fig3"], ours.path()));
    let all_scenes = common::instructions(&mut render_command(&[], every.path()));
    match (fig3, all_scenes) {
        (Some(fig3), Some(every)) => println!(
            "  instructions (callgrind): render fig3 {:.1} M, render (all scenes) {:.1} M: \
             {:.1}x",
            fig3 / 1e6,
            every / 1e6,
            every / fig3
        ),
        _ => println!("  instructions: no valgrind"),
    }
}
