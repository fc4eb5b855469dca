//! Grid points per second of the statics margin over (mu, theta), the fig3 case.
//!
//! `cargo bench --bench grid_margin`; prints the median of 9 runs for the default rayon pool
//! (all cores) and for one thread. Goal: >= 100 million points/s on 2 cores.

mod common;

use std::time::Instant;

use common::median;
use jamchart::Param;
use jamchart::SceneParams;
use jamchart::grid::{GridAxis, GridRequest, Quantity, evaluate, statics_point};

fn measure(req: &GridRequest, runs: usize) -> f64 {
    let cells = (req.x.count * req.y.count) as f64;
    let rates = (0..runs)
        .map(|_| {
            let t0 = Instant::now();
            let g = evaluate(req, statics_point).expect("valid grid");
            let dt = t0.elapsed().as_secs_f64();
            std::hint::black_box(g);
            cells / dt
        })
        .collect();
    median(rates)
}

fn request(n: usize) -> GridRequest {
    GridRequest {
        base: SceneParams::default(),
        x: GridAxis::linear(Param::Mu, 0.1, 0.5, n),
        y: GridAxis::log(Param::ThetaDeg, 10.0, 70.0, n),
        quantities: vec![Quantity::MarginN],
    }
}

fn main() {
    let threads = rayon::current_num_threads();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    println!("statics margin grid (mu x theta), median of 9 runs:");
    // 4001^2 cells (128 MB of output, page faults dominate) and 1001^2 (8 MB, the allocator
    // reuses its pages, so the kernel's own speed shows).
    for n in [4001, 1001] {
        let req = request(n);
        // One warm-up run to start the pool and settle the allocator.
        let _ = evaluate(&req, statics_point);
        let all = measure(&req, 9);
        let one = pool.install(|| measure(&req, 9));
        println!(
            "  {n} x {n}: {threads} threads {:.1} million points/s, 1 thread {:.1} million points/s",
            all / 1e6,
            one / 1e6
        );
    }
    println!("  goal: >= 100 million points/s on 2 cores");
}
