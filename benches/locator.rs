//! The V-locator capacity map: a 200 x 200 map of P_max over (included angle, load direction)
//! by the exact path, beside the clarabel LP per cell.
//!
//! `cargo bench --bench locator`; prints medians of 15 runs of the whole map (all cores and one
//! thread) by the exact path per cell, by `grid::capacity_map` (for the free V its closed form,
//! trigonometry once per axis sample) and the median clarabel time per cell over a 400-cell
//! sample, extrapolated to the map. Goals: the exact map in <= 10 ms on 2 cores (issue 9); the
//! closed-form map at least as fast as numpy's closed form (issue 21).
//!
//! numpy's closed form for the symmetric V (benches/baseline/vlocator.py, the same 200 x 200
//! map) is timed in the same run, interleaved with `capacity_map` under free rotation: five
//! rounds of the script (its median of 101 maps) then the Rust map (median of 15); the
//! medians of the rounds and their ratio are printed. Without the Python baseline it prints
//! `no baseline: <why>` and no ratio.

mod baseline;
mod common;

use common::{median, median_s};
use jamchart::grid::{Grid, GridAxis, LocatorParam, capacity_map};
use jamchart::locator::{self, LocatorParams};

fn map(rotation: locator::Rotation) -> Grid<LocatorParams> {
    Grid {
        base: LocatorParams {
            rotation,
            ..LocatorParams::default()
        },
        x: GridAxis::linear(LocatorParam::IncludedAngleDeg, 10.0, 170.0, 200),
        y: Some(GridAxis::linear(
            LocatorParam::LoadAngleDeg,
            -90.0,
            90.0,
            200,
        )),
    }
}

/// The median ms of one numpy map, as benches/baseline/vlocator.py prints it.
fn numpy_ms(python: &std::path::Path) -> Result<f64, String> {
    let out = std::process::Command::new(python)
        .arg(baseline::dir().join("vlocator.py"))
        .arg("101")
        .output()
        .map_err(|e| format!("vlocator.py did not start: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    text.split_whitespace()
        .nth(1)
        .and_then(|v| v.parse().ok())
        .filter(|_| out.status.success())
        .ok_or_else(|| {
            let err = String::from_utf8_lossy(&out.stderr);
            format!("vlocator.py printed {text:?} ({})", err.trim())
        })
}

/// numpy's map beside `capacity_map` on all threads, interleaved: (numpy, Rust) medians in s.
fn against_numpy(g: &Grid<LocatorParams>) -> Result<(f64, f64), String> {
    let python = baseline::python()?;
    let mut numpy = Vec::new();
    let mut rust = Vec::new();
    for _ in 0..5 {
        numpy.push(numpy_ms(&python)? * 1e-3);
        rust.push(median_s(15, || {
            std::hint::black_box(capacity_map(g).expect("valid grid"));
        }));
    }
    Ok((median(numpy), median(rust)))
}

fn main() {
    match against_numpy(&map(locator::Rotation::Free)) {
        Ok((numpy, rust)) => println!(
            "symmetric V, free rotation, 200 x 200 closed-form map, medians of 5 interleaved \
             rounds: numpy (benches/baseline/vlocator.py) {:.3} ms, capacity_map {:.3} ms on {} \
             threads: {:.1}x numpy's speed (goal at least 1x, issue 21)",
            numpy * 1e3,
            rust * 1e3,
            rayon::current_num_threads(),
            numpy / rust
        ),
        Err(why) => println!("symmetric V closed-form map: no baseline: {why}"),
    }
    let threads = rayon::current_num_threads();
    let one = common::one_thread_pool();
    for rotation in [locator::Rotation::Free, locator::Rotation::Blocked] {
        let g = map(rotation);
        let exact = || {
            let cells = g.map(|p| Ok(locator::capacity(p))).expect("valid grid");
            std::hint::black_box(cells);
        };
        let all = median_s(15, exact);
        let single = one.install(|| median_s(15, exact));
        let fast = || {
            std::hint::black_box(capacity_map(&g).expect("valid grid"));
        };
        let fast_all = median_s(15, fast);
        let fast_single = one.install(|| median_s(15, fast));
        // Every 100th cell: 400 LPs, each timed alone.
        let cells = g.map(|p| Ok(*p)).expect("valid grid").values;
        let per_cell = median(
            cells
                .iter()
                .step_by(100)
                .map(|p| {
                    median_s(3, || {
                        std::hint::black_box(locator::capacity_clarabel(p));
                    })
                })
                .collect(),
        );
        println!(
            "{:>7} rotation, 200 x 200 capacity map: exact {:.2} ms on {threads} threads, \
             {:.2} ms on 1 thread ({:.0} ns/cell); clarabel LP {:.1} us/cell, {:.2} s for the map \
             on 1 thread ({:.0}x the exact path)",
            rotation.as_str(),
            all * 1e3,
            single * 1e3,
            single / 4e4 * 1e9,
            per_cell * 1e6,
            per_cell * 4e4,
            per_cell * 4e4 / single,
        );
        let path = match locator::symmetric::applies(&g.base) {
            true => "closed form",
            false => "exact path (closed form does not apply)",
        };
        println!(
            "{:>7} rotation, 200 x 200 capacity_map ({path}): {:.3} ms on {threads} threads, \
             {:.3} ms on 1 thread ({:.1} ns/cell)",
            rotation.as_str(),
            fast_all * 1e3,
            fast_single * 1e3,
            fast_single / 4e4 * 1e9,
        );
    }
}
