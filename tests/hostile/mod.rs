//! The binary under hostile but fair input, one module per subject: special files where a
//! file is read, the folder `render --check` writes, the manifest as `sha256sum -c` reads it,
//! numbers and names printed to a terminal, scripted callers' descriptors, usage errors, the
//! V-block at the edges of the float range, and values in files that are not valid scenes.

use crate::common::cli as cli_util;

mod battery;
mod check_folder;
mod file_values;
mod limits;
mod manifest_forms;
mod printed_text;
mod refusals;
mod sampled_work;
mod scripted_callers;
mod special_files;
mod vlocator_edges;

use std::io::Read;
use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// Runs `jamchart ARGS` in `dir` with `env` set, killing it after `limit`: a hang is a failure
/// that names the command, never a test that does not end.
pub fn run_within(dir: &Path, args: &[&str], env: &[(&str, &Path)], limit: Duration) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_jamchart"));
    cmd.args(args)
        .current_dir(dir)
        .env_remove("RUST_BACKTRACE")
        .env_remove("RAYON_NUM_THREADS")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for (k, v) in env {
        cmd.env(k, v);
    }
    let mut child = cmd.spawn().expect("the binary runs");
    // Read both pipes while waiting: a child that fills one would otherwise never end.
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut bytes);
            }
            bytes
        })
    };
    let out = drain(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let err = drain(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("jamchart {args:?} did not end within {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Output {
        status,
        stdout: out.join().expect("stdout read"),
        stderr: err.join().expect("stderr read"),
    }
}

/// [`run_within`] with no environment and 60 s.
pub fn run(dir: &Path, args: &[&str]) -> Output {
    run_within(dir, args, &[], Duration::from_secs(60))
}
