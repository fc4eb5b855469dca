//! The documented maxima of every count and size a user can ask for.
//!
//! A request beyond them is refused before anything is computed, with the estimate and the
//! limit in the message: running out of memory is never how a limit is found. The memory
//! limit is set so that a 24 GiB machine always honours it, with room for the rest of the
//! system, and so that a run stays well inside a 4 GiB address space.

use crate::error::{Error, Result};

/// Timed runs per point of the accuracy study (`accuracy --runs`): a median of more than
/// 1000 runs of a millisecond computation says nothing more.
pub const MAX_RUNS: usize = 1000;

/// Tolerances in one study (`accuracy --tolerances`, `--min-norm-tolerances`, a
/// work-precision scene's lists): 64 points are 64 decades more than f64 resolves.
pub const MAX_TOLERANCES: usize = 64;

/// Optimum included angles one V-block optimum chart may compute (mus x (directions + loads)):
/// each is a search over the included angle, measured at 0.23 ms wall on 2 cores (20,000 in
/// 4.6 s: `render vlocator-optimum --set chart.direction_axis.count=2000 --set
/// chart.load_axis.count=2000`), so 100,000 is about 25 s. More would run for minutes with no
/// memory limit to stop it.
pub const MAX_OPTIMUM_POINTS: usize = 100_000;

/// Estimated peak memory of one computation in bytes (1 GiB).
pub const MAX_MEMORY_BYTES: u64 = 1 << 30;

/// Estimated size of the files one scene writes, in bytes (256 MiB).
pub const MAX_OUTPUT_BYTES: u64 = 256 << 20;

/// Levels of one contour map's x_jam or theta_jam iso-lines: each is a pass over the grid, and
/// more than 64 lines cannot be told apart on a chart.
pub const MAX_LEVELS: usize = 64;

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

// Measured on the binary of this commit with /usr/bin/time (peak RSS) and the files' sizes,
// as the difference between 1024 x 1024 and 512 x 512 grids (1e6 and 2.5e5 sweep points), with
// about 25 % margin: jam map 153 B/cell, JSON 19 B/cell; contour map 221 B/cell, JSON
// 36 B/cell; sweep 325 B/point, CSV 114 B/point and SVG 16 B/point. A series row is 9 f64
// (72 B) held as a row, a drawn sample and a CSV line of about 90 B.

/// A cell of a jam map (statics; the other models cost time, not memory).
pub const JAM_MAP_CELL: PerItem = PerItem {
    what: "cells of the jam map",
    memory_bytes: 200,
    // The long-format CSV 24 B per cell (fig3: 3,865,995 B for 160,801 cells); the JSON beside
    // it no longer repeats the grid (30 kB for fig3); with 25 % margin.
    output_bytes: 31,
};

/// A cell of a contour map.
pub const CONTOUR_MAP_CELL: PerItem = PerItem {
    what: "cells of the contour map",
    memory_bytes: 280,
    // The long-format CSV 45 B per cell (fig7c: 5,404,959 B for 120,000 cells); the JSON
    // beside it holds the iso-lines, not the grid (115 kB for fig7c); with 25 % margin.
    output_bytes: 58,
};

/// A point of a sweep.
pub const SWEEP_POINT: PerItem = PerItem {
    what: "points of the sweep",
    memory_bytes: 400,
    output_bytes: 160,
};

/// A row of a simulated time series.
pub const SERIES_ROW: PerItem = PerItem {
    what: "rows of the time series",
    memory_bytes: 300,
    output_bytes: 100,
};

/// Refuses `count` items whose estimated memory or output exceeds [`MAX_MEMORY_BYTES`] or
/// [`MAX_OUTPUT_BYTES`]; `key` names the setting to lower.
pub fn check_items(key: &str, count: f64, per: PerItem) -> Result<()> {
    // f64: a count from a hostile scene may overflow u64 once multiplied.
    let bytes = |per_item: u64| (count * per_item as f64).min(u64::MAX as f64) as u64;
    let shown = if count < 1e15 {
        format!("{count:.0}")
    } else {
        format!("{count:.3e}")
    };
    check(
        key,
        &format!("the memory of {shown} {}", per.what),
        bytes(per.memory_bytes),
        MAX_MEMORY_BYTES,
    )?;
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
    })
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

/// Bytes in a human unit: `1.26 GiB`, `640 MiB`, `12 kiB`.
pub fn human_bytes(b: u64) -> String {
    let units = ["B", "kiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
    let mut v = b as f64;
    let mut i = 0;
    while v >= 1024.0 && i + 1 < units.len() {
        v /= 1024.0;
        i += 1;
    }
    match i {
        0 => format!("{b} B"),
        _ if v.fract() == 0.0 => format!("{v:.0} {}", units[i]),
        _ => format!("{v:.1} {}", units[i]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn human_bytes_reads_well() {
        assert_eq!(human_bytes(512), "512 B");
        assert_eq!(human_bytes(1 << 30), "1 GiB");
        assert_eq!(human_bytes(3 * (1 << 29)), "1.5 GiB");
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
