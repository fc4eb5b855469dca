//! What every benchmark shares: the median of noisy timings, whole-process times and
//! instruction counts.

use std::process::Command;
use std::time::Instant;

/// The median of `v` (the upper middle for an even count).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// The median wall time of `runs` calls of `f`, in s.
#[allow(dead_code)] // not every benchmark times a closure
pub fn median_s(runs: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..runs)
            .map(|_| {
                let t0 = Instant::now();
                f();
                t0.elapsed().as_secs_f64()
            })
            .collect(),
    )
}

/// CPU time (user + sys) of this process so far, in s: unlike wall time, it does not grow
/// when other processes share the cores.
#[allow(dead_code)] // not every benchmark counts CPU time
pub fn process_cpu_s() -> f64 {
    // SAFETY: getrusage writes one rusage through a valid pointer.
    let mut u: libc::rusage = unsafe { std::mem::zeroed() };
    unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut u) };
    let s = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    s(u.ru_utime) + s(u.ru_stime)
}

/// The median CPU time ([`process_cpu_s`]) of `runs` calls of `f`, in s.
#[allow(dead_code)] // not every benchmark counts CPU time
pub fn median_cpu_s(runs: usize, mut f: impl FnMut()) -> f64 {
    median(
        (0..runs)
            .map(|_| {
                let c0 = process_cpu_s();
                f();
                process_cpu_s() - c0
            })
            .collect(),
    )
}

/// A rayon pool of one thread, to time a parallel computation on one core.
#[allow(dead_code)] // not every benchmark compares thread counts
pub fn one_thread_pool() -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool")
}

/// Wall and CPU (user + sys) time of one run of `cmd` in s; panics when it fails.
#[allow(dead_code)] // not every benchmark times processes
pub fn time_process(cmd: &mut Command) -> (f64, f64) {
    let cpu = || {
        // SAFETY: getrusage writes one rusage through a valid pointer.
        let mut u: libc::rusage = unsafe { std::mem::zeroed() };
        unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) };
        let s = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
        s(u.ru_utime) + s(u.ru_stime)
    };
    let (c0, t0) = (cpu(), Instant::now());
    let out = cmd.output().expect("the process starts");
    let wall = t0.elapsed().as_secs_f64();
    assert!(
        out.status.success(),
        "{cmd:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    (wall, cpu() - c0)
}

/// The instructions `cmd` executes on all its threads, by callgrind (the same on a loaded
/// machine as on a quiet one); None without valgrind.
#[allow(dead_code)] // not every benchmark counts instructions
pub fn instructions(cmd: &mut Command) -> Option<f64> {
    let mut grind = Command::new("valgrind");
    grind
        .args(["--tool=callgrind", "--callgrind-out-file=/dev/null"])
        .arg(cmd.get_program())
        .args(cmd.get_args());
    for (key, value) in cmd.get_envs() {
        match value {
            Some(v) => grind.env(key, v),
            None => grind.env_remove(key),
        };
    }
    let out = grind.output().ok()?;
    let err = String::from_utf8_lossy(&out.stderr);
    let line = err.lines().find(|l| l.contains("Collected :"))?;
    line.rsplit(':').next()?.trim().parse().ok()
}

/// Wall time in s of one `jamchart render SCENES...` (all built-in scenes when `scenes` is
/// empty) as a whole process drawing into `out`: `render fig3` is the unit the speed goals are
/// ratios of.
#[allow(dead_code)] // not every benchmark compares with it
pub fn render_s(scenes: &[&str], out: &std::path::Path) -> f64 {
    time_process(&mut render_command(scenes, out)).0
}

/// The command `jamchart render SCENES... -q --out OUT` on the built-in scenes.
#[allow(dead_code)] // not every benchmark compares with it
pub fn render_command(scenes: &[&str], out: &std::path::Path) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_jamchart"));
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("charts");
    cmd.arg("render")
        .args(scenes)
        .args(["-q", "--out"])
        .arg(out)
        .arg("--scenes-dir")
        .arg(dir);
    cmd
}
