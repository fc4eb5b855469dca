//! Uncertain inputs (issue 19): a range answer of the closed form against a point answer, a
//! 100,000-sample Monte Carlo of the statics, and Monte Carlo of the nonsmooth motion-drive
//! simulation in samples per second on 1 thread and on all.
//!
//! `cargo bench --bench uncertain`; prints medians. Goals (issue 19): the range answer within
//! 2x of a point answer; 1e5 statics samples well under 1 s; about 10,000 simulation samples
//! per second on 2 cores. The range answer is timed twice: in the library (its two corners,
//! and with the status changes it solves for) and as a user gets it, `jamchart solve` with
//! `--mu 0.12:0.3` against `--mu 0.21` as whole processes, interleaved.

mod common;

use common::{median, median_s, time_process};
use jamchart::dynamics::{DynamicsParams, IntegratorSettings, Method, Verification};
use jamchart::uncertain::dist::{self, DistQuestion};
use jamchart::uncertain::range;
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet};
use jamchart::{ModelSpec, statics};

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
    let p = jamchart::uncertain::shaft_25mm();
    let box_mu = mu(Uncertain::Range { lo: 0.12, hi: 0.3 });
    let reps = 10_000;
    let point = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(statics::solve(std::hint::black_box(&p)));
        }
    }) / reps as f64;
    let whole = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(range::closed_form(std::hint::black_box(&p), &box_mu).unwrap());
        }
    }) / reps as f64;
    let corners = median_s(15, || {
        for _ in 0..reps {
            std::hint::black_box(range::ends(std::hint::black_box(&p), &box_mu).unwrap());
        }
    }) / reps as f64;
    // A point answer's cost depends on its status: past the palm `solve` also finds the friction
    // and the palm length that would bring the jam onto it. So each end is timed on its own, and
    // the range answer is set against the dearer of the two point answers it needs at least.
    let point_at = |m: f64| {
        let q = p.with_mu(m);
        median_s(15, || {
            for _ in 0..reps {
                std::hint::black_box(statics::solve(std::hint::black_box(&q)));
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
}
