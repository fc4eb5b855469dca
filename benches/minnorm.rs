//! Min-norm speed: programs solved per second on 1 and 2 threads, Table 1 by min-norm, and the
//! exact path's agreement with clarabel on random planar problems.
//!
//! Run: `cargo bench --bench minnorm`. Prints medians of 7 runs. Goals: >= 20,000
//! solves/s across both cores; Table 1 in a few ms.

mod common;

use jamchart::bench_support::{ContactProblem, palm_problem, solve_program as solve};
use jamchart::minnorm::{Formulation, HoldStatus, MinNormSettings, QpSettings};
use jamchart::{ModelSpec, SceneParams};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::TestRunner;
use rayon::prelude::*;

#[path = "../src/minnorm/random_planar.rs"]
mod random_planar;

const RUNS: usize = 7;

/// The frictions of the paper's Table 1, top to bottom (tests/golden/table1.csv).
const TABLE1_MU: [f64; 7] = [0.45, 0.40, 0.35, 0.30, 0.25, 0.20, 0.15];

/// Median seconds of `f` over RUNS runs.
fn time(f: impl FnMut()) -> f64 {
    common::median_s(RUNS, f)
}

/// Palm problems at angles across 5..90 deg for mu in 0.15..0.45: what a grid of cells asks.
fn palm_batch(n: usize, formulation: Formulation) -> Vec<ContactProblem> {
    (0..n)
        .map(|i| {
            let u = i as f64 / n as f64;
            let p = SceneParams::default().with_mu(0.15 + 0.3 * u);
            let theta = (5.0 + 85.0 * ((i * 7919) % n) as f64 / n as f64).to_radians();
            palm_problem(&p, theta, formulation)
        })
        .collect()
}

fn solves_per_second(batch: &[ContactProblem], qp: &QpSettings, threads: usize) -> f64 {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    let secs = time(|| {
        let held = pool.install(|| {
            batch
                .par_iter()
                .filter(|p| solve(p, qp).expect("valid").status == HoldStatus::Held)
                .count()
        });
        std::hint::black_box(held);
    });
    batch.len() as f64 / secs
}

fn main() {
    let exact = QpSettings::default();
    let clarabel = QpSettings {
        fast_path: false,
        ..Default::default()
    };
    println!("min-norm benchmark: medians of {RUNS} runs");
    for formulation in [Formulation::Translational, Formulation::Rolling] {
        for (name, qp, n) in [
            ("exact path", &exact, 200_000),
            ("clarabel", &clarabel, 20_000),
        ] {
            let batch = palm_batch(n, formulation);
            let one = solves_per_second(&batch, qp, 1);
            let two = solves_per_second(&batch, qp, 2);
            println!(
                "  {:<13} {:<10}: {:>10.0} solves/s on 1 thread, {:>10.0} on 2 threads ({:.2}x)",
                formulation.as_str(),
                name,
                one,
                two,
                two / one
            );
        }
    }

    for (name, qp) in [("exact path", exact), ("clarabel", clarabel)] {
        let spec = ModelSpec::MinNorm(MinNormSettings {
            qp,
            ..Default::default()
        });
        let mut solves = 0;
        let secs = time(|| {
            solves = TABLE1_MU
                .iter()
                .map(|&mu| {
                    let s = jamchart::solve(&spec, &SceneParams::default().with_mu(mu));
                    s.expect("valid").work().0
                })
                .sum::<u64>();
        });
        println!(
            "  Table 1 (7 rows) by min-norm, {name:<10}: {:.3} ms, {solves} solves",
            secs * 1e3
        );
    }

    // Agreement of the exact path with clarabel, on the tests' random problems (fixed seed).
    let n = 20_000;
    let mut runner = TestRunner::deterministic();
    let strategy = random_planar::planar_problem();
    let (mut robust, mut mismatch, mut undetermined, mut held) = (0, 0, 0, 0);
    let (mut worst_force, mut worst_excess) = (0.0_f64, f64::NEG_INFINITY);
    for _ in 0..n {
        let p = strategy.new_tree(&mut runner).expect("strategy").current();
        let c = random_planar::compare(&p);
        if c.clarabel.status == HoldStatus::Undetermined {
            undetermined += 1;
        }
        if let Some(v) = c.robust {
            robust += 1;
            if c.exact.status != v
                || (c.clarabel.status != v && c.clarabel.status != HoldStatus::Undetermined)
            {
                mismatch += 1;
            }
        }
        if c.exact.status == HoldStatus::Held && c.clarabel.status == HoldStatus::Held {
            held += 1;
            worst_force = worst_force.max(c.force_diff_rel);
            worst_excess = worst_excess.max(c.objective_excess_rel);
        }
    }
    println!(
        "  exact vs clarabel on {n} random planar problems: {robust} robust verdicts, {mismatch} \
         disagree, clarabel undetermined {undetermined}; both held {held}: worst force difference \
         {worst_force:.1e} of max(load, phi), worst (phi2_exact - phi2_clarabel) / phi2 {worst_excess:.1e}"
    );
}
