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

/// Estimated peak memory of one computation in bytes (1 GiB).
pub const MAX_MEMORY_BYTES: u64 = 1 << 30;

/// Estimated size of the files one scene writes, in bytes (256 MiB).
pub const MAX_OUTPUT_BYTES: u64 = 256 << 20;

/// Refuses a request whose estimate exceeds its limit; `what` says what was estimated
/// ("memory of the 8192 x 8192 grid"), `key` names the setting to lower.
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

/// Bytes in a human unit: `1.26 GiB`, `640 MiB`, `12 kiB`.
pub fn human_bytes(b: u64) -> String {
    let units = ["B", "kiB", "MiB", "GiB", "TiB", "PiB", "EiB"];
    let mut v = b as f64;
    let mut i = 0;
    while v >= 1024.0 && i + 1 < units.len() {
        v /= 1024.0;
        i += 1;
    }
    if i == 0 {
        format!("{b} B")
    } else {
        format!("{v:.3} {}", units[i]).replace(".000 ", " ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn human_bytes_reads_well() {
        assert_eq!(human_bytes(512), "512 B");
        assert_eq!(human_bytes(1 << 30), "1 GiB");
        assert_eq!(human_bytes(3 * (1 << 29)), "1.500 GiB");
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
