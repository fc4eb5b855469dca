//! The Python package's speed (`cargo bench --bench python`), in the environment the package's
//! test builds (`cargo test --release --test integration python_package` first):
//!
//! - 10^6 closed-form answers from a numpy array against numpy's vectorised closed form (the
//!   best form we could write among them), the memory bandwidth that reaches, and one scalar
//!   call's time against the closed form in pure Python (`benches/baseline/python_package.py`,
//!   in one process, interleaved), with jamchart's default threads and then on one thread;
//! - a 100 x 100 nonsmooth-simulation map from Python against the CLI's (`jamchart render` of
//!   a contour map of the same cells, SVG only, its whole process): the `solve` call timed in
//!   Python (what a user who has imported numpy waits for), and Python's whole process;
//!   interleaved, medians of 5.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use common::{median, time_process};

/// Cells per axis of the map.
const CELLS: usize = 100;

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"));
    let python = target.join("python-venv/bin/python");
    let installed = Command::new(&python)
        .args(["-c", "import jamchart"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !installed {
        println!(
            "no Python package in {}: run cargo test --release --test integration python_package first",
            python.display()
        );
        return;
    }
    let script = root.join("benches/baseline/python_package.py");
    // glibc would map and unmap numpy's 8 MB temporaries at each operation: page faults, not
    // numpy's arithmetic (the V-locator bench keeps numpy's heap the same way).
    // Twice: jamchart with its default threads, then on one (numpy runs on one either way).
    for threads in [None, Some("1")] {
        let mut cmd = Command::new(&python);
        cmd.arg(&script)
            .env("MALLOC_TOP_PAD_", "67108864")
            .env("MALLOC_MMAP_THRESHOLD_", "33554432")
            .env_remove("RAYON_NUM_THREADS");
        if let Some(n) = threads {
            cmd.env("RAYON_NUM_THREADS", n);
        }
        let status = cmd.status().expect("the bench script starts");
        assert!(status.success(), "{} failed", script.display());
    }

    let dir = tempfile::tempdir().expect("a temporary folder");
    let scene = dir.path().join("map.toml");
    std::fs::write(
        &scene,
        format!(
            "title = \"nonsmooth map\"\n[chart]\nkind = \"contour_map\"\nmodel = \"dynamics\"\n\
             x_axis = {{ param = \"force_n\", min = 50.0, max = 1000.0, count = {CELLS}, scale = \"log\" }}\n\
             y_axis = {{ param = \"radius_mm\", min = 10.0, max = 30.0, count = {CELLS} }}\n\
             x_jam_levels_mm = [25.0, 30.0]\n\n[dynamics.integrator]\nmethod = \"nonsmooth\"\n"
        ),
    )
    .expect("write the scene");
    // The map's call is timed inside Python too: what a user with numpy imported waits for.
    let call_file = dir.path().join("call_s");
    let map = format!(
        "import time, numpy as np, jamchart as jc\n\
         f = np.geomspace(50.0, 1000.0, {CELLS}); r = np.linspace(10.0, 30.0, {CELLS})\n\
         t = time.perf_counter()\n\
         jc.solve(model='dynamics', method='nonsmooth', force_n=f[None, :], radius_mm=r[:, None])\n\
         open({:?}, 'w').write(repr(time.perf_counter() - t))\n",
        call_file.display().to_string()
    );
    let out = dir.path().join("out");
    let (mut cli, mut py, mut call) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..5 {
        cli.push(
            time_process(
                Command::new(env!("CARGO_BIN_EXE_jamchart"))
                    .arg("render")
                    .arg(&scene)
                    .args(["--format", "svg", "--quiet", "--out"])
                    .arg(&out),
            )
            .0,
        );
        py.push(time_process(Command::new(&python).args(["-c", &map])).0);
        let text = std::fs::read_to_string(&call_file).expect("the map script's time");
        call.push(text.trim().parse::<f64>().expect("a time in s"));
    }
    let (c, p, s) = (median(cli), median(py), median(call));
    println!(
        "nonsmooth map {CELLS} x {CELLS}: CLI {c:.2} s (whole `render` process, SVG); Python \
         {s:.2} s (the solve call; goal within 10 % of the CLI), {p:.2} s (whole process, with \
         Python's start and numpy's import); call / CLI = {:.2}, whole process / CLI = {:.2} \
         (medians of 5 interleaved runs)",
        s / c,
        p / c
    );
}
