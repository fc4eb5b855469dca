//! The documented maxima of every count and size a user can ask for.
//!
//! A request beyond them is refused before anything is computed, with the estimate and the
//! limit in the message: running out of memory is never how a limit is found. The memory
//! limit is set so that a 24 GiB machine always honours it, with room for the rest of the
//! system, and so that a run stays well inside a 4 GiB address space.

use crate::error::{Error, Result};
use crate::numbers::human_seconds;

/// Timed runs per point of the accuracy study (`accuracy --runs`): a median of more than
/// 1000 runs of a millisecond computation says nothing more.
pub const MAX_RUNS: usize = 1000;

/// Tolerances in one study (`accuracy --tolerances`, `--min-norm-tolerances`, a
/// work-precision scene's lists): 64 points are 64 decades more than f64 resolves.
pub const MAX_TOLERANCES: usize = 64;

/// Optimum included angles one V-block optimum chart may compute (mus x (directions + loads)):
/// each is a search over the included angle (a bisection of exact equilibrium tests per
/// step), and nothing else bounds it: no memory limit stops a chart that runs for minutes.
/// `render vlocator-optimum --set chart.direction_axis.count=2000 --set
/// chart.load_axis.count=2000` (20,000 angles) times one fifth of the limit on your machine.
pub const MAX_OPTIMUM_POINTS: usize = 100_000;

/// Probabilities or positions one distribution answer reads (`--quantiles`, `--before`): each
/// is a line of the answer, and each is checked against the others (10^6 of them never
/// answered); the jam-probability chart draws the whole curve.
pub const MAX_PROBES: usize = 1000;

/// The tightest tolerance an integrator, a converged reference or clarabel takes (rtol,
/// atol, `accuracy --tolerances`): a tenth of it, the verification run's, is still 450 units
/// of round-off (scipy's `solve_ivp` floors rtol at 100). Tighter cannot be met in double
/// precision: RADAU5 at rtol 1e-320 cut its step to 0 s at t = 0, and was advised a softer
/// contact.
pub const MIN_TOLERANCE: f64 = 1e-13;

/// The finest step of the nonsmooth method in deg of palm turn, [`MIN_TOLERANCE`] of a half
/// turn: a step of 1e-320 deg turns the palm by no more than round-off, and its run took every
/// step it was allowed to stay at the start angle.
pub const MIN_NONSMOOTH_STEP_DEG: f64 = MIN_TOLERANCE * 180.0;

/// Estimated peak memory of one computation in bytes (1 GiB).
pub const MAX_MEMORY_BYTES: u64 = 1 << 30;

/// Estimated size of the files one scene writes, in bytes (1 GiB): a guard of the disk, not
/// of memory, since a map's cells CSV, the bulk of its files, is streamed to its file and never
/// held whole (`charts::Cells`); the same as [`MAX_MEMORY_BYTES`], so that a map the memory
/// allows (a 3200 x 3200 jam map writes about 340 MB) is not refused for its files.
pub const MAX_OUTPUT_BYTES: u64 = 1 << 30;

/// Levels of one contour map's x_jam or theta_jam iso-lines: each is a pass over the grid, and
/// more than 64 lines cannot be told apart on a chart.
pub const MAX_LEVELS: usize = 64;

/// Longest chart title in characters: a title is one line across the chart (about 120
/// characters at the widest picture); a 10 MB title once took 3 GiB to lay out and aborted.
pub const MAX_TITLE_CHARS: usize = 200;

/// Most dotted parts of a `--set` key: the deepest key of any scene has 3
/// (`dynamics.contact.stiffness_n_per_mm_e`); a key of 10,000 parts once overflowed the stack
/// while its table was built.
pub const MAX_KEY_PARTS: usize = 8;

/// Most worker threads (`RAYON_NUM_THREADS`): more than the hardware threads of the largest
/// machines (2 x 192 cores, 768 threads) only adds stacks. Without a limit,
/// `RAYON_NUM_THREADS=100000000` started rayon's own maximum of 65,535 threads and `render fig3`
/// had not begun after 60 s.
pub const MAX_THREADS: usize = 1024;

/// What one item (grid cell, sweep point, time-series row) costs, for the estimates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerItem {
    /// The item in words, plural ("cells of the jam map").
    pub what: &'static str,
    /// Peak memory per item in bytes.
    pub memory_bytes: u64,
    /// Bytes per item in the files written (data file and pictures).
    pub output_bytes: u64,
}

impl PerItem {
    /// `what`, with its peak memory and file bytes per item.
    const fn new(what: &'static str, memory_bytes: u64, output_bytes: u64) -> Self {
        PerItem {
            what,
            memory_bytes,
            output_bytes,
        }
    }
}

// Measured with `/usr/bin/time -v` (peak RSS) and the files' sizes, per item as the difference
// between two sizes of a built-in scene (`render SCENE --set chart.x_axis.count=N --set
// chart.y_axis.count=N`, N = 400 and 800; fig3 800 and 1600; `sweep mu=0.1:0.5:N`, N = 1e5 and
// 2e5), then 25 % added (estimates within 2x of what is measured):
//
// | item                       | memory B | files B |
// |----------------------------|----------|---------|
// | jam map cell (fig3)        |        9 |      33 |
// | contour map cell (fig7c)   |      168 |      46 |
// | universal chart cell       |       82 |      44 |
// | V-locator capacity cell    |      105 |      25 |
// | sweep point (`sweep`)      |     1200 |      96 |
//
// A jam map cell was 59 B while its CSV was built in memory; streamed to its file, 33 B; with
// each cell's region a byte (it was a 16-byte reference to its word), 17 B (800 -> 1600 cells a
// side: 26.4 -> 57.8 MB peak RSS; 500 -> 1000, as tests/hostile/limits.rs measures: 20-22 B;
// 3200: see the guide's Limits); with the regions classed row by row as the grid is computed,
// 9 B (`/usr/bin/time -v`, fig3 at 500, 1000 and 1600 a side: 18.1, 24.8 and 38.6 MB, 9.1 and
// 9.0 B a cell). The universal chart's status went the same way: 97 -> 82 B (400 -> 800).
// The other maps' peaks come before their CSV is written (contour maps: 129.0 MB at 800^2
// either way), so streaming left them as they were.
//
// Where a sweep point's 1200 B go is not measured item by item: the points, the CSV, the SVG
// path and the gallery's read-off (JSON values) are all held at once; a whole model solution
// kept per point until the series was built was 220 B of the 1420 B measured before. A series
// row is 9 f64 (72 B) held as a row, a drawn sample and a CSV line of about 90 B.

/// A cell of a jam map (statics; the other models cost time, not memory).
pub const JAM_MAP_CELL: PerItem = PerItem::new("cells of the jam map", 12, 41);

/// A cell of a contour map.
pub const CONTOUR_MAP_CELL: PerItem = PerItem::new("cells of the contour map", 210, 58);

/// A cell of the universal chart.
pub const UNIVERSAL_CELL: PerItem = PerItem::new("cells of the universal chart", 102, 55);

/// A cell of a V-locator capacity map.
pub const VLOCATOR_CAPACITY_CELL: PerItem = PerItem::new("cells of the capacity map", 130, 32);

/// A push of a binding's arrays: its answers (a status byte, theta_jam and x_jam as f64).
#[cfg(feature = "python")]
pub const PUSH: PerItem = PerItem::new("pushes", 17, 0);

/// A point of a sweep.
pub const SWEEP_POINT: PerItem = PerItem::new("points of the sweep", 1500, 120);

/// A row of a simulated time series.
pub const SERIES_ROW: PerItem = PerItem::new("rows of the time series", 300, 100);

/// What one Monte Carlo sample of a model costs on one core at the default settings, for the
/// estimate that bounds `solve --samples` by time, as [`PerItem`] bounds the maps by memory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PerSample {
    /// The model in words ("min-norm").
    pub what: &'static str,
    /// CPU time per sample in s.
    pub cpu_s: f64,
}

// Measured by `cargo bench --bench uncertain` (its "per sample" lines: the default scene,
// mu normal(0.3, 0.01), one thread, CPU time, so that other processes on the cores do not
// count; medians of 3):
//
// | model               | s of CPU per sample |
// |---------------------|---------------------|
// | closed form         |              2.1e-7 |
// | min-norm            |              2.6e-4 |
// | dynamics, RADAU5    |              6.3e-4 |
// | dynamics, DOPRI5    |              9.3e-3 |
// | dynamics, nonsmooth |              8.7e-5 |
//
// A scene's cost moves with its settings (a stiffer contact, a tighter tolerance, a slower
// palm, min-norm without its fast path: 2.9e-3 s, eleven times the table's): `uncertain::dist`
// times one sample at the nominal values and takes the larger of the two
// ([`PerSample::at_least`]).

/// A sample of the closed form.
pub const STATICS_SAMPLE: PerSample = PerSample::new("the closed form", 2.1e-7);

/// A sample of the minimum-norm model.
pub const MIN_NORM_SAMPLE: PerSample = PerSample::new("min-norm", 2.6e-4);

/// A sample of the simulation by RADAU5.
pub const RADAU5_SAMPLE: PerSample = PerSample::new("the simulation by RADAU5", 6.3e-4);

/// A sample of the simulation by DOPRI5.
pub const DOPRI5_SAMPLE: PerSample = PerSample::new("the simulation by DOPRI5", 9.3e-3);

/// A sample of the simulation by the nonsmooth method.
pub const NONSMOOTH_SAMPLE: PerSample =
    PerSample::new("the simulation by the nonsmooth method", 8.7e-5);

impl PerSample {
    /// `what`, at `cpu_s` seconds of one core a sample.
    const fn new(what: &'static str, cpu_s: f64) -> Self {
        PerSample { what, cpu_s }
    }

    /// This cost, or `cpu_s` where a sample was timed dearer.
    pub fn at_least(self, cpu_s: f64) -> PerSample {
        PerSample {
            cpu_s: self.cpu_s.max(cpu_s),
            ..self
        }
    }
}

/// CPU time of the calling thread so far, in s (`CLOCK_THREAD_CPUTIME_ID`): what one sample
/// costs, whatever else runs on the cores.
pub fn thread_cpu_s() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: clock_gettime writes one timespec through a valid pointer.
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut t) };
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// The cost of one sample of the model `spec`.
pub fn per_sample(spec: &crate::models::ModelSpec) -> PerSample {
    use crate::dynamics::Method;
    use crate::models::ModelSpec;
    match spec {
        ModelSpec::Statics => STATICS_SAMPLE,
        ModelSpec::MinNorm(_) => MIN_NORM_SAMPLE,
        ModelSpec::Dynamics { params, .. } => match params.integrator.method {
            Method::Radau5 => RADAU5_SAMPLE,
            Method::Dopri5 => DOPRI5_SAMPLE,
            Method::Nonsmooth => NONSMOOTH_SAMPLE,
        },
    }
}

/// CPU time one sampled answer may be estimated to take (10 min of one core, 5 min of a
/// 2-core machine's wall time), with a progress bar on a terminal while it runs: hours of work
/// were accepted (`solve --model min-norm --samples 10000000`).
pub const MAX_SAMPLED_CPU_S: f64 = 600.0;

/// A tighter bound on one computation than the crate's own limits, for a caller that shares
/// its machine: a server answering many clients gives each request a [`Budget`] so that no
/// one question may take the minutes and the gigabyte a command-line user may ask for.
///
/// Set for the calling thread by `limits::within`; the checks that run before any work is
/// done (of a sampled answer's time, of a chart's memory) run on the thread that asked, so the bound holds for
/// the parallel work that follows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    /// CPU time a sampled answer may be estimated to take, s.
    pub cpu_s: f64,
    /// Memory one computation may be estimated to take, bytes.
    pub memory_bytes: u64,
    /// Who sets it, as a phrase after the figure: `" (the server's limit per request)"`.
    pub source: &'static str,
}

thread_local! {
    static BUDGET: std::cell::Cell<Option<Budget>> = const { std::cell::Cell::new(None) };
}

/// Runs `f` with `budget` bounding what the checks of this module accept on this thread (the
/// lower of the budget and the crate's limits), then restores the bound before.
#[cfg(feature = "serve")]
pub fn within<T>(budget: Budget, f: impl FnOnce() -> T) -> T {
    struct Restore(Option<Budget>);
    impl Drop for Restore {
        fn drop(&mut self) {
            BUDGET.set(self.0);
        }
    }
    let _restore = Restore(BUDGET.replace(Some(budget)));
    f()
}

/// Refuses `count` pushes of `spec` answered at once (a binding's arrays, `key` naming them)
/// whose estimated CPU time exceeds [`MAX_SAMPLED_CPU_S`] as a Monte Carlo's would, or whose
/// answers and copies, `bytes_per_push` each, exceed the memory limit: a broadcast of 2^40
/// pushes once ran on for hours.
#[cfg(feature = "python")]
pub fn check_pushes(
    key: &str,
    count: f64,
    bytes_per_push: u64,
    spec: &crate::models::ModelSpec,
) -> Result<()> {
    check_items(key, count, PerItem::new(PUSH.what, bytes_per_push, 0))?;
    let per = per_sample(spec);
    check_cpu(key, count * per.cpu_s, || {
        let shown = match count < 1e15 {
            true => format!("{count:.0}"),
            false => format!("{count:.3e}"),
        };
        format!(
            "{shown} pushes of {}, about {} each,",
            per.what,
            human_seconds(per.cpu_s)
        )
    })
}

/// The estimated CPU time of `samples` samples of `per`, in s.
pub fn sampled_cpu_s(samples: u64, per: PerSample) -> f64 {
    samples as f64 * per.cpu_s
}

/// Refuses work estimated at `estimate_s` of CPU above [`MAX_SAMPLED_CPU_S`] (or the
/// [`Budget`] of the calling thread, when lower): `what` says what would take that long, and
/// `key` names the setting to lower.
fn check_cpu(key: &str, estimate_s: f64, what: impl FnOnce() -> String) -> Result<()> {
    let (limit_s, limit_source) = match BUDGET.get() {
        Some(b) if b.cpu_s < MAX_SAMPLED_CPU_S => (b.cpu_s, b.source),
        _ => (MAX_SAMPLED_CPU_S, ""),
    };
    if estimate_s <= limit_s {
        return Ok(());
    }
    Err(Error::TooLong {
        key: key.to_string(),
        what: what(),
        estimate_s,
        limit_s,
        limit_source,
    })
}

/// Refuses `samples` samples of `per` whose estimated CPU time exceeds [`MAX_SAMPLED_CPU_S`]
/// (or the [`Budget`] of the calling thread, when lower); `key` names the setting to lower.
pub fn check_samples(key: &str, samples: u64, per: PerSample) -> Result<()> {
    check_cpu(key, sampled_cpu_s(samples, per), || {
        format!(
            "{samples} samples of {}, about {} each,",
            per.what,
            human_seconds(per.cpu_s)
        )
    })
}

/// CPU time of one step of a simulation by `method`, rejected steps included, for the bound
/// on a step limit: a run that cannot pass a stiff contact (DOPRI5 at 1 um) takes every step
/// it is allowed.
// Measured by `solve --model dynamics --method M --stiffness 1e7 --no-verify --format json`,
// elapsed_s over steps and rejected steps: RADAU5 1.9 us (376 steps), DOPRI5 1.1 us (93,300),
// the nonsmooth method 1.0-1.5 us (95, its set-up included).
pub fn step_cpu_s(method: crate::dynamics::Method) -> f64 {
    use crate::dynamics::Method;
    match method {
        Method::Radau5 => 2.0e-6,
        Method::Dopri5 => 1.1e-6,
        Method::Nonsmooth => 1.5e-6,
    }
}

/// Refuses simulations whose step limit `max_steps` lets them run longer than
/// [`MAX_SAMPLED_CPU_S`] (or the [`Budget`] of the calling thread, when lower) if each takes
/// every step: one run by each method of `runs`. A run that uses its whole limit fails and is
/// not repeated, so a timed study counts each of its runs once. `accuracy --max-steps 2^31`
/// once ran for hours before a first row.
pub fn check_steps(key: &str, max_steps: u64, runs: &[crate::dynamics::Method]) -> Result<()> {
    let per_step_s: f64 = runs.iter().map(|&m| step_cpu_s(m)).sum();
    check_cpu(key, max_steps as f64 * per_step_s, || {
        format!(
            "{} of up to {max_steps} steps, about {} a step, should a stiff contact take them all,",
            match runs.len() {
                1 => "a simulation".to_string(),
                n => format!("{n} simulations"),
            },
            human_seconds(per_step_s / runs.len() as f64)
        )
    })
}

/// Refuses `count` items whose estimated memory or output exceeds [`memory_limit_bytes`] or
/// [`MAX_OUTPUT_BYTES`]; `key` names the setting to lower.
pub fn check_items(key: &str, count: f64, per: PerItem) -> Result<()> {
    // f64: a count from a hostile scene may overflow u64 once multiplied.
    let bytes = |per_item: u64| (count * per_item as f64).min(u64::MAX as f64) as u64;
    let shown = if count < 1e15 {
        format!("{count:.0}")
    } else {
        format!("{count:.3e}")
    };
    let memory = format!("the memory of {shown} {}", per.what);
    let estimate = bytes(per.memory_bytes);
    let (limit, source) = memory_limit_bytes();
    if estimate > limit {
        return Err(Error::TooLarge {
            key: key.to_string(),
            what: memory,
            estimate_bytes: estimate,
            limit_bytes: limit,
            limit_source: source,
        });
    }
    check(
        key,
        &format!("the files of {shown} {}", per.what),
        bytes(per.output_bytes),
        MAX_OUTPUT_BYTES,
    )
}

/// Rows of a time series sampled every `dt_s` while the palm closes from `start_angle_deg` at
/// `omega_deg_s` (the simulation ends when the palm is closed, if not before).
pub fn series_rows(start_angle_deg: f64, omega_deg_s: f64, dt_s: f64) -> f64 {
    start_angle_deg / omega_deg_s / dt_s + 1.0
}

/// Refuses a request whose estimate exceeds its limit; `what` says what was estimated
/// ("the memory of 67108864 cells of the jam map"), `key` names the setting that sets it.
pub fn check(key: &str, what: &str, estimate: u64, limit: u64) -> Result<()> {
    if estimate <= limit {
        return Ok(());
    }
    Err(Error::TooLarge {
        key: key.to_string(),
        what: what.to_string(),
        estimate_bytes: estimate,
        limit_bytes: limit,
        limit_source: "",
    })
}

/// The memory a request may take: [`MAX_MEMORY_BYTES`], or half the process's address-space
/// or data limit (`ulimit -v`, `ulimit -d`) when that is lower, with the phrase that says so.
///
/// Half, measured: a run needs about twice its peak resident memory in address space (a
/// growing buffer is copied into one twice its size, each thread reserves a stack). fig3 at
/// 1600 x 1600 (peak RSS 158 MB) aborts on allocation under `ulimit -v 262144` and runs under
/// 393216 (sizes the tool accepted aborted under a 512 MiB limit).
pub fn memory_limit_bytes() -> (u64, &'static str) {
    let soft = |resource| {
        let mut r = libc::rlimit {
            rlim_cur: 0,
            rlim_max: 0,
        };
        // SAFETY: getrlimit writes one rlimit through a valid pointer.
        let ok = unsafe { libc::getrlimit(resource, &mut r) } == 0;
        (ok && r.rlim_cur != libc::RLIM_INFINITY).then_some(r.rlim_cur / 2)
    };
    let limits = [
        (
            BUDGET.get().map(|b| b.memory_bytes),
            BUDGET.get().map_or("", |b| b.source),
        ),
        (
            soft(libc::RLIMIT_AS),
            " (half the address-space limit, ulimit -v)",
        ),
        (
            soft(libc::RLIMIT_DATA),
            " (half the data-size limit, ulimit -d)",
        ),
    ];
    limits
        .into_iter()
        .filter_map(|(l, why)| Some((l?, why)))
        .filter(|(l, _)| *l < MAX_MEMORY_BYTES)
        .min_by_key(|(l, _)| *l)
        .unwrap_or((MAX_MEMORY_BYTES, ""))
}

/// A count within `1..=max`, or an error naming `key`.
pub fn check_count(key: &str, count: usize, max: usize, what: &str) -> Result<()> {
    if (1..=max).contains(&count) {
        return Ok(());
    }
    Err(Error::invalid(key, count, format!("{what} is 1 to {max}")))
}

/// A list of at most `max` items (it may be empty), or an error naming `key`.
pub fn check_at_most(key: &str, count: usize, max: usize, what: &str) -> Result<()> {
    if count <= max {
        return Ok(());
    }
    Err(Error::invalid(
        key,
        format!("{count} {what}"),
        format!("at most {max} {what}"),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `solve --model min-norm --samples 10000000` was accepted (hours of work); the sampled
    /// models are bounded by their estimated time, the closed form by its count alone.
    #[test]
    fn sampled_work_is_bounded_by_its_estimated_time() {
        let msg = check_samples("--samples", 10_000_000, MIN_NORM_SAMPLE)
            .unwrap_err()
            .to_string();
        assert!(msg.contains("--samples") && msg.contains("43 min"), "{msg}");
        assert!(msg.contains("10 min"), "{msg}");
        check_samples("--samples", 2_000, DOPRI5_SAMPLE).unwrap();
        check_samples("--samples", 10_000_000, STATICS_SAMPLE).unwrap();
        assert!(check_samples("--samples", 100_000, DOPRI5_SAMPLE).is_err());
    }

    #[test]
    fn too_large_says_estimate_and_limit() {
        let msg = check(
            "chart.x_axis.count",
            "memory of the grid",
            10 << 30,
            MAX_MEMORY_BYTES,
        )
        .unwrap_err()
        .to_string();
        assert!(msg.contains("10 GiB") && msg.contains("1 GiB"), "{msg}");
        assert!(msg.contains("chart.x_axis.count"), "{msg}");
        check("k", "w", MAX_MEMORY_BYTES, MAX_MEMORY_BYTES).unwrap();
    }
}
