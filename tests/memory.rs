//! The peak memory of a render against its estimate, in a test binary of its own: a child's
//! peak resident size counts its parent's resident pages (the spawn shares the parent's
//! address space until the child execs), so it is measured from a process that stays small,
//! not from the integration binary after hundreds of other tests.

#[allow(dead_code, unused_macros)] // the helpers of every subject; this binary uses a few
#[path = "common/mod.rs"]
mod common;

use std::path::Path;
use std::process::{Command, Stdio};

use common::cli::{jam_map, scene, stderr};

/// Peak resident memory in bytes of `jamchart ARGS` run in `dir`, read from the kernel's
/// accounting of that one child (wait4), so tests running beside it do not count.
#[allow(clippy::zombie_processes)] // reaped by wait4, which std's Child does not see
fn peak_rss_bytes(dir: &Path, args: &[&str]) -> u64 {
    let child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut status = 0;
    // SAFETY: wait4 reaps our own child and writes one rusage through a valid pointer; the
    // Child is not waited on again.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let pid = unsafe { libc::wait4(child.id() as i32, &mut status, 0, &mut usage) };
    assert_eq!(pid, child.id() as i32);
    assert!(libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0);
    // ru_maxrss is in KiB on Linux.
    usage.ru_maxrss as u64 * 1024
}

/// Memory estimates lie within 2x of what is measured: a jam map's estimate per cell,
/// as the refusal of a map too large states it, lies between the measured cost per cell and
/// twice it. Measured as the difference of the peaks at 500 x 500 and 1000 x 1000 cells (the
/// process's fixed part cancels); about 9 B a cell since each row's regions are classed as
/// the row is computed (33 B once the cells CSV was streamed to its file; 59 B while it was
/// built in memory, against an estimate of 75 B).
#[test]
fn jam_map_memory_estimate_is_within_2x_of_the_measured_peak() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let peak = |n: usize| {
        let name = format!("map{n}");
        scene(d, &name, &jam_map(n));
        let args = [
            "render",
            &name,
            "--scenes-dir",
            "scenes",
            "--out",
            "o",
            "-q",
        ];
        peak_rss_bytes(d, &args)
    };
    let (small, large) = (peak(500), peak(1000));
    let measured = (large as f64 - small as f64) / (1000.0 * 1000.0 - 500.0 * 500.0);
    // The estimate as the refusal states it: "the memory of 67108864 cells of the jam map
    // would take about 768 MiB". The largest grid (2^26 cells) is within the memory limit of
    // 1 GiB at 12 B a cell, so the limit is made half of a 1 GiB address-space cap, and the
    // memory is refused before the files are.
    scene(d, "huge", &jam_map(8192));
    let args = ["render", "huge", "--scenes-dir", "scenes", "--out", "o"];
    let out = common::cli::jamchart_under(d, 1 << 20, &args);
    assert!(stderr(&out).contains("the memory of"), "{}", stderr(&out));
    let err = stderr(&out);
    let bytes: f64 = err
        .split("would take about ")
        .nth(1)
        .and_then(|r| {
            let mut words = r.split(' ');
            let v: f64 = words.next()?.parse().ok()?;
            let unit = match words.next()?.trim_end_matches(',') {
                "MiB" => 1u64 << 20,
                "GiB" => 1 << 30,
                _ => return None,
            };
            Some(v * unit as f64)
        })
        .unwrap_or_else(|| panic!("no estimate in MiB or GiB: {err}"));
    let estimate = bytes / (8192.0 * 8192.0);
    assert!(
        measured <= estimate * 1.05 && estimate <= 2.0 * measured,
        "estimate {estimate:.1} B/cell, measured {measured:.1} B/cell ({small} -> {large} B)"
    );
}
