//! One RADAU5 run of the regularised simulation against scipy's `solve_ivp(method="Radau")`
//! on the same model (goal: at least 300x scipy's CPU time).
//!
//! `cargo bench --bench scipy`. The baseline, benches/baseline/radau.py, integrates the same
//! ODE (the defaults, motion drive; the right-hand side on Python floats, the analytic
//! Jacobian) and reads the jam by scipy's events as jamchart reads it. It first checks that it
//! reaches jamchart's x_jam on two stiff cases (`radau.py check`, printed); without Python or
//! PyPI, or when the check fails, the bench prints `no baseline: <why>` and no ratio.
//!
//! Timed: `jamchart::solve` of the defaults without the verification run, in this process, and
//! scipy's integration inside one warm Python process (its start and imports are no part of a
//! run; each run is checked against jamchart's x_jam), interleaved round by round so that the
//! machine's load falls on both alike: the medians of the rounds and of the rounds' ratios, in
//! wall and CPU time. scipy runs at jamchart's rtol = atol = 1e-6 and at 1e-5, the error test
//! RADAU5 applies at 1e-6 (it maps rtol to 0.1 rtol^(2/3), scipy uses rtol as given). The call
//! with its verification run (`solve`'s default: a second run at a tenth of the tolerances and
//! the rigid contact) is timed beside them. Where valgrind is installed it also prints the
//! instructions of one run of each (callgrind, the same on a loaded machine as on a quiet one):
//! this binary run as `scipy runs-only K` solves K times, and the difference between K = 11
//! and K = 1 is ten runs; the script's `runs K` likewise, 2 less 1.

mod baseline;
mod common;

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdout, Command, Stdio};
use std::time::Instant;

use jamchart::dynamics::{DynamicsParams, Verification};
use jamchart::{Detail, ModelSpec, SceneParams};

/// jamchart's rtol = atol (its default).
const RTOL: f64 = 1e-6;
const ROUNDS: usize = 15;
/// jamchart's runs are timed in batches: one lasts a fraction of a millisecond.
const BATCH: usize = 20;

/// The error test RADAU5 applies at `rtol`: 0.1 rtol^(2/3) (radau.py's `error_test_rtol`).
fn error_test_rtol(rtol: f64) -> f64 {
    0.1 * rtol.powf(2.0 / 3.0)
}

/// `solve` of the default scene by the dynamics (RADAU5 at rtol 1e-6), with or without the
/// verification run: x_jam in mm and the accepted steps.
fn solve(verify: bool) -> (Option<f64>, u64) {
    let spec = ModelSpec::Dynamics {
        params: DynamicsParams {
            verification: Verification {
                verify,
                ..Default::default()
            },
            ..Default::default()
        },
        series_dt_s: None,
    };
    let s = jamchart::solve(&spec, &SceneParams::default()).expect("the defaults are valid");
    let steps = match &s.detail {
        Detail::Dynamics(d) => d.steps,
        _ => 0,
    };
    (s.x_jam_mm, steps)
}

/// The command running benches/baseline/radau.py with `args`, on one core as jamchart's run:
/// no BLAS thread pool idles into its CPU time.
fn radau_py(python: &Path, args: &[&str]) -> Command {
    let mut cmd = Command::new(python);
    cmd.arg(baseline::dir().join("radau.py"))
        .args(args)
        .env("OPENBLAS_NUM_THREADS", "1")
        .env("OMP_NUM_THREADS", "1");
    cmd
}

/// One scipy integration as radau.py prints it.
struct ScipyRun {
    wall_s: f64,
    cpu_s: f64,
    x_jam_mm: f64,
}

/// radau.py serving runs: one line in (the rtol), one timed integration out.
struct Scipy {
    child: Child,
    out: BufReader<ChildStdout>,
}

impl Scipy {
    fn start(python: &Path) -> Result<Scipy, String> {
        let mut child = radau_py(python, &["serve"])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| format!("radau.py did not start: {e}"))?;
        let out = BufReader::new(child.stdout.take().expect("piped"));
        Ok(Scipy { child, out })
    }

    fn run(&mut self, rtol: f64) -> Result<ScipyRun, String> {
        let stdin = self.child.stdin.as_mut().expect("piped");
        writeln!(stdin, "{rtol:e}").map_err(|e| format!("radau.py stopped: {e}"))?;
        let mut line = String::new();
        self.out
            .read_line(&mut line)
            .map_err(|e| format!("radau.py stopped: {e}"))?;
        let field = |i: usize| line.split_whitespace().nth(i).and_then(|v| v.parse().ok());
        match (field(1), field(3), field(5)) {
            (Some(wall_s), Some(cpu_s), Some(x_jam_mm)) => Ok(ScipyRun {
                wall_s,
                cpu_s,
                x_jam_mm,
            }),
            _ => Err(format!("radau.py printed {line:?}")),
        }
    }
}

impl Drop for Scipy {
    fn drop(&mut self) {
        // Closing its stdin ends the script's loop.
        drop(self.child.stdin.take());
        let _ = self.child.wait();
    }
}

/// Wall and CPU time in s of one `solve(verify)`: the mean of a batch.
fn time_batch(verify: bool) -> (f64, f64) {
    let (w0, c0) = (Instant::now(), common::process_cpu_s());
    for _ in 0..BATCH {
        std::hint::black_box(solve(verify));
    }
    let per_run = |s: f64| s / BATCH as f64;
    (
        per_run(w0.elapsed().as_secs_f64()),
        per_run(common::process_cpu_s() - c0),
    )
}

/// The timed series of one contender: wall and CPU time in s, one entry per round.
#[derive(Default)]
struct Series {
    wall: Vec<f64>,
    cpu: Vec<f64>,
}

impl Series {
    fn push(&mut self, (wall, cpu): (f64, f64)) {
        self.wall.push(wall);
        self.cpu.push(cpu);
    }

    /// Medians in ms of (wall, cpu).
    fn ms(&self) -> (f64, f64) {
        (
            common::median(self.wall.clone()) * 1e3,
            common::median(self.cpu.clone()) * 1e3,
        )
    }

    /// Medians of the rounds' ratios self / other, (wall, cpu).
    fn over(&self, other: &Series) -> (f64, f64) {
        let ratio =
            |a: &[f64], b: &[f64]| common::median(a.iter().zip(b).map(|(a, b)| a / b).collect());
        (ratio(&self.wall, &other.wall), ratio(&self.cpu, &other.cpu))
    }
}

/// The check, then the interleaved rounds: the lines to print.
fn against_scipy(python: &Path) -> Result<Vec<String>, String> {
    let check = radau_py(python, &["check", env!("CARGO_BIN_EXE_jamchart")])
        .output()
        .map_err(|e| format!("radau.py did not start: {e}"))?;
    let checked = String::from_utf8_lossy(&check.stdout);
    if !check.status.success() {
        let err = String::from_utf8_lossy(&check.stderr);
        return Err(format!(
            "radau.py does not reach jamchart's jam: {} {}",
            checked.trim(),
            err.trim()
        ));
    }
    let (x_jam, steps) = solve(false);
    let x_jam = x_jam.ok_or("jamchart found no jam")?;
    let rtols = [RTOL, error_test_rtol(RTOL)];
    let mut scipy = Scipy::start(python)?;
    // Warm-up: the first run of a process pays for scipy's lazy imports.
    for rtol in rtols {
        scipy.run(rtol)?;
    }
    let (mut once, mut verified) = (Series::default(), Series::default());
    let mut theirs: [Series; 2] = Default::default();
    for _ in 0..ROUNDS {
        once.push(time_batch(false));
        verified.push(time_batch(true));
        for (series, rtol) in theirs.iter_mut().zip(rtols) {
            let run = scipy.run(rtol)?;
            if (run.x_jam_mm - x_jam).abs() > RTOL * x_jam {
                return Err(format!(
                    "scipy's x_jam {} mm at rtol {rtol:e} is not jamchart's {x_jam} mm",
                    run.x_jam_mm
                ));
            }
            series.push((run.wall_s, run.cpu_s));
        }
    }
    let mut lines = vec![format!(
        "RADAU5 against scipy's Radau (benches/baseline/radau.py), defaults, motion drive, \
         jamchart at rtol = atol = {RTOL:e}; the script's check:"
    )];
    lines.extend(checked.lines().map(|l| format!("  {l}")));
    let (w, c) = once.ms();
    lines.push(format!(
        "  jamchart::solve, no verification run ({steps} steps): {w:.3} ms wall, {c:.3} ms cpu"
    ));
    for (series, (rtol, what)) in theirs.iter().zip([
        (rtols[0], "the same rtol"),
        (rtols[1], "the error test RADAU5 applies at 1e-6"),
    ]) {
        let ((w, c), (rw, rc)) = (series.ms(), series.over(&once));
        lines.push(format!(
            "  scipy at rtol = atol = {rtol:.0e} ({what}): {w:.1} ms wall, {c:.1} ms cpu: \
             {rw:.0}x wall, {rc:.0}x cpu (goal at least 300x cpu)"
        ));
    }
    let ((w, c), (rw, rc)) = (verified.ms(), theirs[0].over(&verified));
    lines.push(format!(
        "  jamchart::solve with its verification run (solve's default): {w:.3} ms wall, \
         {c:.3} ms cpu; scipy at the same rtol {rw:.0}x wall, {rc:.0}x cpu"
    ));
    lines.push(format!(
        "  medians of {ROUNDS} interleaved rounds (jamchart: the mean of {BATCH} calls a \
         round), load average {}",
        load_average()
    ));
    Ok(lines)
}

/// The 1-minute load average (/proc/loadavg), or "unknown".
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|l| l.split_whitespace().next().map(str::to_owned))
        .unwrap_or_else(|| "unknown".into())
}

/// Instructions of one run by callgrind: (jamchart's, scipy's at the same rtol); None without
/// valgrind.
fn instructions(python: Option<&Path>) -> (Option<f64>, Option<f64>) {
    let ours = |runs: u32| -> Option<f64> {
        let mut cmd = Command::new(std::env::current_exe().ok()?);
        cmd.args(["runs-only", &runs.to_string()]);
        common::instructions(&mut cmd)
    };
    let theirs = |runs: u32| -> Option<f64> {
        common::instructions(&mut radau_py(
            python?,
            &["runs", &runs.to_string(), &RTOL.to_string()],
        ))
    };
    (
        ours(11).zip(ours(1)).map(|(a, b)| (a - b) / 10.0),
        theirs(2).zip(theirs(1)).map(|(a, b)| a - b),
    )
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "runs-only") {
        let runs: u32 = args.get(i + 1).and_then(|k| k.parse().ok()).unwrap_or(1);
        for _ in 0..runs {
            std::hint::black_box(solve(false));
        }
        return;
    }
    let python = baseline::python();
    match python
        .as_deref()
        .map_err(Clone::clone)
        .and_then(against_scipy)
    {
        Ok(lines) => lines.iter().for_each(|l| println!("{l}")),
        Err(why) => println!("RADAU5 against scipy's Radau: no baseline: {why}"),
    }
    match instructions(python.as_deref().ok()) {
        (Some(ours), Some(theirs)) => println!(
            "  instructions of one run (callgrind): jamchart {:.2} M, scipy {:.0} M: {:.0}x",
            ours / 1e6,
            theirs / 1e6,
            theirs / ours
        ),
        (Some(ours), None) => println!(
            "  instructions of one jamchart run (callgrind): {:.2} M; scipy's: no baseline",
            ours / 1e6
        ),
        _ => println!("  instructions: no valgrind"),
    }
}
