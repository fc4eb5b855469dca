//! Uncertain inputs: a range answer of the closed form against a point answer, a
//! 100,000-sample Monte Carlo of the statics, and Monte Carlo of the nonsmooth motion-drive
//! simulation in samples per second on 1 thread and on all.
//!
//! `cargo bench --bench uncertain`; prints medians. Goals: the range answer within 2x of a
//! point answer; 1e5 statics samples well under 1 s; about 10,000 simulation samples per
//! second on 2 cores; at 1e7 statics samples at least 1.8 cores busy (CPU time over wall time
//! of the library call, and its speed-up over one thread, interleaved) and the memory per
//! sample of `jamchart solve --samples`, from the peak RSS of whole processes at 1e6 and
//! 1e7 samples. The range answer is timed twice: in the library (its two corners,
//! and with the status changes it solves for) and as a user gets it, `jamchart solve` with
//! `--mu 0.12:0.3` against `--mu 0.21` as whole processes, interleaved.

mod common;
#[path = "../src/uncertain/shaft.rs"]
mod shaft;

use common::{median, median_cpu_s, median_s, time_process};
use jamchart::ModelSpec;
use jamchart::bench_support::range_corners;
use jamchart::dynamics::{DynamicsParams, IntegratorSettings, Method, Verification};
use jamchart::uncertain::dist::{self, DistQuestion};
use jamchart::uncertain::range;
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};

fn mu(value: Uncertain) -> UncertainSet {
    UncertainSet {
        inputs: vec![UncertainInput {
            name: "mu",
            keys: vec!["mu_ground", "mu_palm"],
            value,
        }],
    }
}

fn main() {
    let p = shaft::shaft_25mm();
    let box_mu = mu(Uncertain::Range { lo: 0.12, hi: 0.3 });
    let reps = 10_000;
    let point = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(
                jamchart::solve(&ModelSpec::Statics, std::hint::black_box(&p)).unwrap(),
            );
        }
    }) / reps as f64;
    let whole = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(range::closed_form(std::hint::black_box(&p), &box_mu).unwrap());
        }
    }) / reps as f64;
    let corners = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(range_corners(std::hint::black_box(&p), &box_mu).unwrap());
        }
    }) / reps as f64;
    // A point answer's cost depends on its status: past the palm `solve` also finds the friction
    // and the palm length that would bring the jam onto it. So each end is timed on its own, and
    // the range answer is set against the dearer of the two point answers it needs at least.
    let point_at = |m: f64| {
        let q = p.with_mu(m);
        median_s(15, || {
            for _ in 0..reps {
                std::hint::black_box(
                    jamchart::solve(&ModelSpec::Statics, std::hint::black_box(&q)).unwrap(),
                );
            }
        }) / reps as f64
    };
    let (lo, hi) = (point_at(0.12), point_at(0.3));
    println!(
        "shaft, mu 0.12:0.3: point answer (`solve`) at the nominal mu 0.21 {:.0} ns, at mu 0.12 \
         (beyond_reach) {:.0} ns, at mu 0.3 (jams) {:.0} ns",
        point * 1e9,
        lo * 1e9,
        hi * 1e9,
    );
    println!(
        "  range answer: the interval from its two corners (range::ends) {:.0} ns, {:.1}x the \
         nominal point answer; with the status change along mu (range::closed_form) {:.0} ns, \
         {:.1}x the nominal point, {:.1}x the dearer end's point answer",
        corners * 1e9,
        corners / point,
        whole * 1e9,
        whole / point,
        whole / lo.max(hi)
    );

    // As a user gets them: the command with a range against the command with a point.
    let solve = |mu: &str| {
        let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"));
        cmd.args([
            "solve", "--radius", "12.5", "--mass", "0.4", "--force", "40",
        ])
        .args(["--palm-length", "80", "--mu", mu]);
        cmd
    };
    let (mut at_point, mut over_range) = (Vec::new(), Vec::new());
    for _ in 0..41 {
        at_point.push(time_process(&mut solve("0.21")).0);
        over_range.push(time_process(&mut solve("0.12:0.3")).0);
    }
    let (at_point, over_range) = (median(at_point), median(over_range));
    println!(
        "  as commands (whole processes, medians of 41 interleaved runs): `jamchart solve \
         --mu 0.12:0.3` {:.2} ms, `--mu 0.21` {:.2} ms: {:.2}x",
        over_range * 1e3,
        at_point * 1e3,
        over_range / at_point
    );

    let threads = rayon::current_num_threads();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    let mut two_inputs = mu(Uncertain::Normal {
        mean: 0.2,
        sd: 0.03,
    });
    two_inputs.inputs.push(UncertainInput {
        name: "force_n",
        keys: vec!["force_n"],
        value: Uncertain::Uniform { lo: 30.0, hi: 50.0 },
    });
    let ask = |samples| DistQuestion {
        before_mm: vec![50.0],
        quantiles: vec![0.05, 0.5, 0.95],
        samples,
        seed: 1,
    };
    let mc = |set: &UncertainSet, spec: &ModelSpec, n: u64| {
        std::hint::black_box(dist::monte_carlo(spec, &p, set, &ask(n)).expect("valid"));
    };
    let all = median_s(9, || mc(&two_inputs, &ModelSpec::Statics, 100_000));
    let single = one.install(|| median_s(9, || mc(&two_inputs, &ModelSpec::Statics, 100_000)));
    println!(
        "statics Monte Carlo, mu normal(0.2,0.03) x force uniform(30,50), 100000 samples: \
         {:.1} ms on {threads} threads, {:.1} ms on 1 thread",
        all * 1e3,
        single * 1e3
    );

    let rss_of = |samples: &str| {
        let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"));
        cmd.args([
            "solve",
            "--radius",
            "12.5",
            "--mass",
            "0.4",
            "--palm-length",
            "80",
        ])
        .args(["--force", "uniform(30,50)", "--mu", "normal(0.2,0.03)"])
        .args(["--samples", samples]);
        time_process(&mut cmd);
        // The largest child so far, in KiB: each run here is larger than every one before.
        // Measured before this process grows (the 1e7 runs below): a spawned child's peak
        // counts the parent's resident pages until it execs.
        // SAFETY: getrusage writes one rusage through a valid pointer.
        let mut u: libc::rusage = unsafe { std::mem::zeroed() };
        unsafe { libc::getrusage(libc::RUSAGE_CHILDREN, &mut u) };
        u.ru_maxrss as f64 * 1024.0
    };
    let (small, large) = (rss_of("1000000"), rss_of("10000000"));
    println!(
        "  jamchart solve --samples 1e7 (mu and force distributed): peak RSS {:.1} MiB, {:.1} \
         bytes per sample (peaks at 1e7 and 1e6 samples, differenced)",
        large / 1048576.0,
        (large - small) / 9e6
    );

    // 1e7 samples: how many cores the whole answer keeps busy.
    let big = 10_000_000;
    let cpu_self = || {
        // SAFETY: getrusage writes one rusage through a valid pointer.
        let mut u: libc::rusage = unsafe { std::mem::zeroed() };
        unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut u) };
        let s = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
        s(u.ru_utime) + s(u.ru_stime)
    };
    let (mut walls, mut cores, mut singles) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..3 {
        let (c0, t0) = (cpu_self(), std::time::Instant::now());
        mc(&two_inputs, &ModelSpec::Statics, big);
        let wall = t0.elapsed().as_secs_f64();
        walls.push(wall);
        cores.push((cpu_self() - c0) / wall);
        singles.push(one.install(|| median_s(1, || mc(&two_inputs, &ModelSpec::Statics, big))));
    }
    let (wall, single) = (median(walls), median(singles));
    println!(
        "statics Monte Carlo, 1e7 samples, medians of 3 interleaved runs: {:.2} s on {threads} \
         threads, {:.2} cores busy (CPU / wall; goal at least 1.8 of 2), {:.2} s on 1 thread: \
         {:.2}x",
        wall,
        median(cores),
        single,
        single / wall
    );
    let nonsmooth = ModelSpec::Dynamics {
        params: DynamicsParams {
            integrator: IntegratorSettings {
                method: Method::Nonsmooth,
                ..Default::default()
            },
            verification: Verification {
                verify: false,
                ..Default::default()
            },
            ..Default::default()
        },
        series_dt_s: None,
    };
    let n = 2_000;
    let all = median_s(3, || mc(&two_inputs, &nonsmooth, n));
    let single = one.install(|| median_s(3, || mc(&two_inputs, &nonsmooth, n)));
    println!(
        "nonsmooth motion-drive Monte Carlo (no verify run), {n} samples: {:.0} samples/s on \
         {threads} threads, {:.0} samples/s on 1 thread",
        n as f64 / all,
        n as f64 / single
    );

    // What one sample costs each model as `solve` runs it (the default scene and settings,
    // verification included), on one thread: the table behind limits::PerSample, which bounds
    // --samples.
    let with = |method: Method| ModelSpec::Dynamics {
        params: DynamicsParams {
            integrator: IntegratorSettings {
                method,
                ..Default::default()
            },
            ..Default::default()
        },
        series_dt_s: None,
    };
    let per_model: [(&str, ModelSpec, u64); 5] = [
        ("the closed form", ModelSpec::Statics, 100_000),
        ("min-norm", ModelSpec::MinNorm(Default::default()), 1_000),
        ("dynamics, RADAU5", with(Method::Radau5), 300),
        ("dynamics, DOPRI5", with(Method::Dopri5), 60),
        ("dynamics, nonsmooth", with(Method::Nonsmooth), 2_000),
    ];
    let one_mu = mu(Uncertain::Normal {
        mean: 0.3,
        sd: 0.01,
    });
    let scene = jamchart::SceneParams::default();
    for (what, spec, n) in per_model {
        let run = || {
            std::hint::black_box(
                dist::monte_carlo(&spec, &scene, &one_mu, &ask(n)).expect("valid"),
            );
        };
        let wall = one.install(|| median_s(3, run));
        let cpu = one.install(|| median_cpu_s(3, run));
        println!(
            "per sample, default scene, mu normal(0.3,0.01), 1 thread, {what}: {:.2e} s of CPU \
             ({:.2e} s wall; {n} samples, medians of 3)",
            cpu / n as f64,
            wall / n as f64
        );
    }
}
