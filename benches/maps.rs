//! Maps by every model: wall time of a mu x F map (the `accuracy --map` design map: mu 0.1 ...
//! 0.8 linear, F 20 ... 2000 N log) by the min-norm program, the nonsmooth simulation (motion
//! and force drive) and the regularised simulation (RADAU5, both drives), on all threads and on
//! one.
//!
//! `cargo bench --bench maps`. Each model answers a coarser map over the same ranges (sampled
//! cells per axis in the line) and the full map's time is extrapolated from the time per cell,
//! as `accuracy --map` does; the line says so. The min-norm map by columns is timed whole
//! (400 x 400), cell by cell at 40 x 40 for comparison. Each line also counts the cells that
//! jam and those without a trusted answer. Median of 3 runs. Goals: min-norm
//! 400 x 400 and the nonsmooth 100 x 100 (either drive) under 2 s on 2 cores; the regularised
//! simulation's cost printed beside them.
//!
//! `cargo bench --bench maps -- min-norm` measures only the rows whose label contains the word.
//!
//! Two goals are ratios measured in the same run, interleaved round by round so that the
//! machine's load falls on both sides alike (medians of the rounds' ratios): the min-norm
//! 400 x 400 map by columns against a whole `jamchart render fig3` (goal: at most 20x), and the
//! nonsmooth method's force drive against its motion drive per cell (goal: at most 1.5x),
//! beside the step problems each solves per cell, a count the load does not disturb. The
//! min-norm ratio is printed in wall time (the goal's) and in CPU time, and, where valgrind is
//! installed, in instructions: callgrind counts a sample of the map (whole columns of 400 cells,
//! so each search starts from its neighbours as in the full map) and one `render fig3`.
//! `cargo bench --bench maps -- goals` runs only these. The sample is this binary run with
//! `column-sample [COLUMNS]` (20 columns by default, 400 the whole map): a process to count or
//! to time from outside against `jamchart render fig3`.

mod common;

use common::median_s;
use jamchart::Param;
use jamchart::dynamics::{Drive, DynamicsParams, Method};
use jamchart::grid::{Grid, GridAxis};
use jamchart::minnorm::MinNormSettings;
use jamchart::models::Detail;
use jamchart::{JamStatus, ModelSpec, SceneParams};

/// The design map sampled at `k` x `k` cells.
fn map(k: usize) -> Grid<SceneParams> {
    Grid {
        base: SceneParams::default(),
        x: GridAxis::linear(Param::Mu, 0.1, 0.8, k),
        y: Some(GridAxis::log(Param::ForceN, 20.0, 2000.0, k)),
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

/// Rounds of each interleaved ratio.
const ROUNDS: usize = 7;

/// The word that makes this binary solve [`column_sample`] once and exit: the process whose
/// instructions callgrind counts. A number after it sets the columns (400: the whole map, a
/// process to time against `render fig3` from outside).
const COLUMN_SAMPLE: &str = "column-sample";

/// Columns of the 400 x 400 design map whose instructions callgrind counts (each a whole
/// column of 400 cells, so each search starts from its neighbours as in the full map).
const SAMPLE_COLUMNS: usize = 20;

/// The min-norm design map at `columns` values of mu, each a column of 400 cells: the programs
/// solved.
fn column_sample(columns: usize) -> u32 {
    let spec = ModelSpec::MinNorm(MinNormSettings::default());
    let mut grid = map(400);
    grid.x = GridAxis::linear(Param::Mu, 0.1, 0.8, columns);
    let cells = grid.map_columns(|column| jamchart::solve_column(&spec, column));
    programs(&cells.expect("every cell answers").values)
}

/// Min-norm programs solved over `cells`.
fn programs(cells: &[jamchart::Solution]) -> u32 {
    cells
        .iter()
        .map(|s| match &s.detail {
            Detail::MinNorm(m) => m.solves,
            _ => 0,
        })
        .sum()
}

/// The instructions per cell of [`column_sample`] and of one whole `render fig3`, by callgrind
/// (the same on a loaded machine as on a quiet one); None without valgrind.
fn instructions_per_cell(out: &std::path::Path) -> Option<(f64, f64)> {
    let mut sample = std::process::Command::new(std::env::current_exe().ok()?);
    sample.arg(COLUMN_SAMPLE);
    let cells = (SAMPLE_COLUMNS * 400) as f64;
    let per_cell = common::instructions(&mut sample)? / cells;
    let fig3 = common::instructions(&mut common::render_command(&["fig3"], out))?;
    Some((per_cell, fig3))
}

/// The min-norm 400 x 400 map by columns (all threads) against `render fig3`, and the nonsmooth
/// force drive against the motion drive per cell, each a median of `ROUNDS` interleaved ratios.
fn goals() {
    let out = tempfile::tempdir().expect("a temporary folder");
    let spec = ModelSpec::MinNorm(MinNormSettings::default());
    let grid = map(400);
    let min_norm_map = || {
        let cells = grid.map_columns(|column| jamchart::solve_column(&spec, column));
        cells.expect("every cell answers").values
    };
    let programs = programs(&min_norm_map());
    // Wall and CPU (user + sys) time of each side: the map in this process, fig3 as a child.
    let (mut map_s, mut fig3_s) = (Vec::new(), Vec::new());
    for _ in 0..ROUNDS {
        let (t0, c0) = (std::time::Instant::now(), common::process_cpu_s());
        std::hint::black_box(min_norm_map());
        map_s.push((t0.elapsed().as_secs_f64(), common::process_cpu_s() - c0));
        fig3_s.push(common::time_process(&mut common::render_command(
            &["fig3"],
            out.path(),
        )));
    }
    let ratio = |pick: fn(&(f64, f64)) -> f64| {
        common::median(
            map_s
                .iter()
                .zip(&fig3_s)
                .map(|(a, b)| pick(a) / pick(b))
                .collect(),
        )
    };
    println!(
        "min-norm 400 x 400 map by columns ({:.2} programs a cell): {:.3} s wall, {:.3} s cpu; \
         render fig3 {:.1} ms wall, {:.1} ms cpu; ratio {:.1}x wall (goal at most 20x), {:.1}x \
         cpu, medians of {ROUNDS} interleaved rounds",
        f64::from(programs) / (400.0 * 400.0),
        common::median(map_s.iter().map(|m| m.0).collect()),
        common::median(map_s.iter().map(|m| m.1).collect()),
        common::median(fig3_s.iter().map(|f| f.0).collect()) * 1e3,
        common::median(fig3_s.iter().map(|f| f.1).collect()) * 1e3,
        ratio(|t| t.0),
        ratio(|t| t.1),
    );
    match instructions_per_cell(out.path()) {
        Some((per_cell, fig3)) => println!(
            "  by callgrind: {:.0} instructions a cell ({SAMPLE_COLUMNS} columns of 400 cells), \
             render fig3 {:.1} M; a 400 x 400 map is {:.1}x render fig3 in instructions",
            per_cell,
            fig3 / 1e6,
            per_cell * 400.0 * 400.0 / fig3,
        ),
        None => println!("  instructions: no valgrind"),
    }

    // The nonsmooth method, force drive against motion drive, per cell of the design map.
    let k = 25;
    let grid = map(k);
    let per_cell = |drive: Drive| {
        let spec = dynamics(Method::Nonsmooth, drive);
        let mut solves = 0;
        let s = median_s(1, || {
            let cells = grid
                .map(|p| jamchart::solve(&spec, p))
                .expect("every cell answers");
            solves = cells
                .values
                .iter()
                .map(|s| match &s.detail {
                    Detail::Dynamics(d) => d.rhs_evals,
                    _ => 0,
                })
                .sum::<u64>();
        });
        (s / (k * k) as f64, solves as f64 / (k * k) as f64)
    };
    let (mut force, mut motion) = (Vec::new(), Vec::new());
    for _ in 0..ROUNDS {
        force.push(per_cell(Drive::Force));
        motion.push(per_cell(Drive::Motion));
    }
    let (force_solves, motion_solves) = (force[0].1, motion[0].1);
    let ratios = force.iter().zip(&motion).map(|(f, m)| f.0 / m.0).collect();
    println!(
        "nonsmooth per cell ({k} x {k} design map, all threads): force drive {:.1} us, motion \
         drive {:.1} us, ratio {:.2}x (goal at most 1.5x), medians of {ROUNDS} interleaved \
         rounds; step problems a cell: force {force_solves:.0}, motion {motion_solves:.0} \
         ({:.2}x)",
        common::median(force.iter().map(|f| f.0).collect()) * 1e6,
        common::median(motion.iter().map(|m| m.0).collect()) * 1e6,
        common::median(ratios),
        force_solves / motion_solves,
    );
}

fn main() {
    // A word after `--` keeps the rows whose label contains it (the simulations take minutes);
    // `goals` runs the interleaved ratios alone.
    let filter = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    if filter.as_deref() == Some(COLUMN_SAMPLE) {
        let columns = std::env::args()
            .skip_while(|a| a != COLUMN_SAMPLE)
            .nth(1)
            .and_then(|a| a.parse().ok());
        std::hint::black_box(column_sample(columns.unwrap_or(SAMPLE_COLUMNS)));
        return;
    }
    if filter.as_deref().is_none_or(|f| f == "goals") {
        goals();
    }
    if filter.as_deref() == Some("goals") {
        return;
    }
    let threads = rayon::current_num_threads();
    let one = common::one_thread_pool();
    // (label, model, cells per axis sampled, cells per axis of the full map, by columns)
    let min_norm = ModelSpec::MinNorm(MinNormSettings::default());
    let mut rows = vec![
        (
            "min-norm (exact path)".to_string(),
            min_norm,
            40,
            400,
            false,
        ),
        // Each cell's search started from the column's previous jams (`solve_column`: Newton
        // on the friction utilisation, about 3 programs a cell); the sampled map is the full
        // one, as a coarser column's neighbours are further apart.
        (
            "min-norm (exact path, by columns)".to_string(),
            min_norm,
            400,
            400,
            true,
        ),
    ];
    for (method, k) in [(Method::Nonsmooth, 25), (Method::Radau5, 25)] {
        for drive in [Drive::Motion, Drive::Force] {
            let label = format!("{method}, {drive} drive");
            rows.push((label, dynamics(method, drive), k, 100, false));
        }
    }
    println!("maps by every model (mu 0.1-0.8 x F 20-2000 N), median of 3 runs:");
    for (label, spec, k, n, by_columns) in rows {
        if filter.as_ref().is_some_and(|f| !label.contains(f.as_str())) {
            continue;
        }
        let grid = map(k);
        let run = || {
            let cells = if by_columns {
                grid.map_columns(|column| jamchart::solve_column(&spec, column))
            } else {
                grid.map(|p| jamchart::solve(&spec, p))
            };
            std::hint::black_box(cells.expect("every cell answers"));
        };
        // What the time buys: how many cells jam (or are held at the start), and how many
        // the model could not answer with a trusted jam point.
        let cells = if by_columns {
            grid.map_columns(|column| jamchart::solve_column(&spec, column))
        } else {
            grid.map(|p| jamchart::solve(&spec, p))
        }
        .expect("every cell answers")
        .values;
        let stops = cells
            .iter()
            .filter(|s| matches!(s.status, JamStatus::Jams | JamStatus::JammedAtStart))
            .count();
        let untrusted = cells
            .iter()
            .filter(|s| {
                matches!(
                    s.status,
                    JamStatus::Inaccurate | JamStatus::IntegratorFailed | JamStatus::OutsideModel
                )
            })
            .count();
        // The min-norm rows: programs solved per cell (the search's cost, which the load does
        // not disturb).
        let programs = match programs(&cells) {
            0 => String::new(),
            n => format!(", {:.2} programs a cell", n as f64 / cells.len() as f64),
        };
        let all = median_s(3, run);
        let single = one.install(|| median_s(3, run));
        let scale = (n * n) as f64 / (k * k) as f64;
        println!(
            "  {label}: {n} x {n} about {:.2} s on {threads} threads, {:.2} s on 1 thread \
             (extrapolated from {k} x {k}: {:.3} s / {:.3} s, {:.0} us per cell on 1 thread; \
             {stops} of {} cells jam or are held at the start, {untrusted} untrusted{programs})",
            all * scale,
            single * scale,
            all,
            single,
            single / (k * k) as f64 * 1e6,
            k * k,
        );
    }
}
