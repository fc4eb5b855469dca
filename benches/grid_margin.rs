//! Grid points per second of the statics margin over (mu, theta), the fig3 case.
//!
//! `cargo bench --bench grid_margin`; prints the median of 9 runs for the default rayon pool
//! (all cores) and for one thread. Goal (issue 5): >= 100 million points/s on 2 cores.

use std::time::Instant;

use jamchart::SceneParams;
use jamchart::grid::{self, GridAxis, GridParam, GridRequest, Quantity, Statics};

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn measure(req: &GridRequest, runs: usize) -> f64 {
    let cells = (req.x.count * req.y.count) as f64;
    let rates = (0..runs)
        .map(|_| {
            let t0 = Instant::now();
            let g = grid::evaluate(req, &Statics).expect("valid grid");
            let dt = t0.elapsed().as_secs_f64();
            std::hint::black_box(g);
            cells / dt
        })
        .collect();
    median(rates)
}

fn main() {
    let n = 4001;
    let req = GridRequest {
        base: SceneParams::default(),
        x: GridAxis::linear(GridParam::Mu, 0.1, 0.5, n),
        y: GridAxis::log(GridParam::ThetaDeg, 10.0, 70.0, n),
        quantities: vec![Quantity::MarginN],
    };
    // One warm-up run to fault in the pages and start the pool.
    let _ = grid::evaluate(&req, &Statics);
    let threads = rayon::current_num_threads();
    let all = measure(&req, 9);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let one = pool.install(|| measure(&req, 9));
    println!("statics margin grid {n} x {n} (mu x theta), median of 9 runs:");
    println!("  {threads} threads: {:.1} million points/s", all / 1e6);
    println!("  1 thread:  {:.1} million points/s", one / 1e6);
    println!("  goal: >= 100 million points/s on 2 cores");
}
