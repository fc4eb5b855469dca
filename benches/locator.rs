//! The V-locator capacity map: a 200 x 200 map of P_max over (included angle, load direction)
//! by the exact path, beside the clarabel LP per cell.
//!
//! `cargo bench --bench locator`; prints medians of 15 runs of the whole map (all cores and one
//! thread) by the exact path per cell, by `grid::capacity_map` (for the free V its closed form,
//! trigonometry once per axis sample) and the median clarabel time per cell over a 400-cell
//! sample, extrapolated to the map. Goals: the exact map in <= 10 ms on 2 cores; the closed-form
//! map at least 3x as fast as numpy's closed form, both warm.
//!
//! numpy's closed form for the symmetric V (benches/baseline/vlocator.py, the same 200 x 200
//! map) is timed in the same run, interleaved with `capacity_map` under free rotation: seven
//! rounds of the script (its median of 101 maps) then the Rust map (median of 101 on all
//! threads and on one); the medians of the rounds and their ratios are printed (goal: at least
//! 3x numpy on all threads). numpy is timed warm, as a numpy user who makes maps in a loop
//! sees it: in one process after a warm-up map, with MALLOC_TOP_PAD_ set so that glibc keeps
//! the top of its heap instead of giving a map's freed temporaries back to the kernel and
//! faulting them in again for the next map (the script's docs; it prints its page faults per
//! map, 0 when warm). The Rust map is warm alike: its 360 kB of cells (P_max / W and the
//! failure mode, 9 bytes a cell; numpy's map holds P_max / W alone) come from a heap that
//! glibc keeps after the first map. A 200 x 200 map is below the size from which
//! `capacity_map` shares a map among the pool's threads (waking them costs more than the map),
//! so its figure on all threads is the calling thread's work, as a caller gets it. Without
//! the Python baseline it prints
//! `no baseline: <why>` and no ratio.
//!
//! Where valgrind is installed it also prints the instructions per cell of the closed-form
//! map on one thread (callgrind, independent of the machine's load): this binary run as
//! `locator map-only K` makes K maps, and the difference between K = 11 and K = 1 is ten maps.

mod baseline;
mod common;

use common::{median, median_s};
use jamchart::bench_support::{capacity_clarabel, closed_form_applies};
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

/// One warm numpy map's median ms and page faults per map, as benches/baseline/vlocator.py
/// prints them.
fn numpy_ms(python: &std::path::Path) -> Result<(f64, f64), String> {
    let out = std::process::Command::new(python)
        .arg(baseline::dir().join("vlocator.py"))
        .arg("101")
        // 16 MiB: far above a map's temporaries (about 2 MB), so no map gives its heap back.
        .env("MALLOC_TOP_PAD_", "16777216")
        .output()
        .map_err(|e| format!("vlocator.py did not start: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout);
    let field = |i: usize| text.split_whitespace().nth(i).and_then(|v| v.parse().ok());
    field(1)
        .zip(field(3))
        .filter(|_| out.status.success())
        .ok_or_else(|| {
            let err = String::from_utf8_lossy(&out.stderr);
            format!("vlocator.py printed {text:?} ({})", err.trim())
        })
}

/// numpy's map beside `capacity_map` on all threads and on one, interleaved: medians in s of
/// (numpy, Rust on all threads, Rust on one) and numpy's page faults per map.
fn against_numpy(g: &Grid<LocatorParams>) -> Result<([f64; 3], f64), String> {
    let python = baseline::python()?;
    let one = common::one_thread_pool();
    let map = || {
        std::hint::black_box(capacity_map(g).expect("valid grid"));
    };
    let mut rounds: [Vec<f64>; 4] = Default::default();
    for _ in 0..7 {
        let (ms, faults) = numpy_ms(&python)?;
        rounds[0].push(ms * 1e-3);
        rounds[1].push(median_s(101, map));
        rounds[2].push(one.install(|| median_s(101, map)));
        rounds[3].push(faults);
    }
    let [numpy, all, single, faults] = rounds.map(median);
    Ok(([numpy, all, single], faults))
}

/// Instructions per cell of the closed-form map on one thread, by callgrind: this binary's
/// `map-only` run with 11 maps less the one with 1; None without valgrind.
fn instructions_per_cell() -> Option<f64> {
    let run = |maps: u32| -> Option<f64> {
        let mut cmd = std::process::Command::new(std::env::current_exe().ok()?);
        cmd.args(["map-only", &maps.to_string()])
            .env("RAYON_NUM_THREADS", "1");
        common::instructions(&mut cmd)
    };
    Some((run(11)? - run(1)?) / 10.0 / 4e4)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(i) = args.iter().position(|a| a == "map-only") {
        let maps: u32 = args.get(i + 1).and_then(|k| k.parse().ok()).unwrap_or(1);
        let g = map(locator::Rotation::Free);
        for _ in 0..maps {
            std::hint::black_box(capacity_map(&g).expect("valid grid"));
        }
        return;
    }
    match against_numpy(&map(locator::Rotation::Free)) {
        Ok(([numpy, all, single], faults)) => println!(
            "symmetric V, free rotation, 200 x 200 closed-form map, medians of 7 interleaved \
             rounds: numpy (benches/baseline/vlocator.py, warm: {faults:.2} page faults a map) \
             {:.3} ms; capacity_map {:.3} ms on {} threads: {:.1}x numpy's speed (goal at least \
             3x), {:.3} ms on 1 thread: {:.1}x",
            numpy * 1e3,
            all * 1e3,
            rayon::current_num_threads(),
            numpy / all,
            single * 1e3,
            numpy / single,
        ),
        Err(why) => println!("symmetric V closed-form map: no baseline: {why}"),
    }
    match instructions_per_cell() {
        Some(per_cell) => println!(
            "  closed-form map on 1 thread: {per_cell:.1} instructions per cell (callgrind)"
        ),
        None => println!("  instructions per cell: no valgrind"),
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
                        std::hint::black_box(capacity_clarabel(p));
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
        let path = match closed_form_applies(&g.base) {
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
