//! Maps by every model: wall time of a mu x F map (the `accuracy --map` design map: mu 0.1 ...
//! 0.8 linear, F 20 ... 2000 N log) by the min-norm program, the nonsmooth simulation (motion
//! and force drive) and the regularised simulation (RADAU5, both drives), on all threads and on
//! one.
//!
//! `cargo bench --bench maps`. Each model answers a coarser map over the same ranges (sampled
//! cells per axis in the line) and the full map's time is extrapolated from the time per cell,
//! as `accuracy --map` does; the line says so. Median of 3 runs. Goals (issue 21): min-norm
//! 400 x 400 and the nonsmooth 100 x 100 (either drive) under 2 s on 2 cores; the regularised
//! simulation's cost printed beside them.

mod common;

use common::median_s;
use jamchart::dynamics::{Drive, DynamicsParams, Method};
use jamchart::grid::{Grid, GridAxis, GridParam};
use jamchart::minnorm::MinNormSettings;
use jamchart::{ModelSpec, SceneParams};

/// The design map sampled at `k` x `k` cells.
fn map(k: usize) -> Grid<SceneParams> {
    Grid {
        base: SceneParams::default(),
        x: GridAxis::linear(GridParam::Mu, 0.1, 0.8, k),
        y: Some(GridAxis::log(GridParam::ForceN, 20.0, 2000.0, k)),
    }
}

/// The simulation by `method` under `drive`, default settings otherwise.
fn dynamics(method: Method, drive: Drive) -> ModelSpec {
    let mut params = DynamicsParams::default();
    params.drive.mode = drive;
    params.integrator.method = method;
    ModelSpec::Dynamics {
        params,
        series_dt_s: None,
    }
}

fn main() {
    let threads = rayon::current_num_threads();
    let one = common::one_thread_pool();
    // (label, model, cells per axis sampled, cells per axis of the full map)
    let mut rows = vec![(
        "min-norm (exact path)".to_string(),
        ModelSpec::MinNorm(MinNormSettings::default()),
        40,
        400,
    )];
    for (method, k) in [(Method::Nonsmooth, 25), (Method::Radau5, 10)] {
        for drive in [Drive::Motion, Drive::Force] {
            let label = format!("{method}, {drive} drive");
            rows.push((label, dynamics(method, drive), k, 100));
        }
    }
    println!("maps by every model (mu 0.1-0.8 x F 20-2000 N), median of 3 runs:");
    for (label, spec, k, n) in rows {
        let grid = map(k);
        let run = || {
            let cells = grid
                .map(|p| jamchart::solve(&spec, p))
                .expect("every cell answers");
            std::hint::black_box(cells);
        };
        let all = median_s(3, run);
        let single = one.install(|| median_s(3, run));
        let scale = (n * n) as f64 / (k * k) as f64;
        println!(
            "  {label}: {n} x {n} about {:.2} s on {threads} threads, {:.2} s on 1 thread \
             (extrapolated from {k} x {k}: {:.3} s / {:.3} s, {:.0} us per cell on 1 thread)",
            all * scale,
            single * scale,
            all,
            single,
            single / (k * k) as f64 * 1e6,
        );
    }
}
