//! Files written by the dynamics commands: the time series CSV, written atomically.

use std::fmt::Write as _;
use std::path::Path;

use crate::dynamics::jam::SeriesRow;
use crate::error::{Error, Result};

/// Writes `text` to `path` through a temporary file in the same directory and a rename, so a
/// reader never sees half a file.
pub fn write_atomic(path: &Path, text: &str) -> Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    let tmp = dir.join(format!(
        ".{}.{}.tmp",
        name.unwrap_or_else(|| "out".into()),
        std::process::id()
    ));
    std::fs::write(&tmp, text).map_err(|e| Error::io("write", &tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        Error::io("rename a temporary file to", path, e)
    })
}

/// The time series as CSV, one row per sample, units in the header.
pub fn series_csv(rows: &[SeriesRow]) -> String {
    let mut s = String::from(
        "t_s,theta_deg,x_mm,x_dot_mm_s,penetration_mm,normal_n,palm_friction_n,\
         ground_normal_n,ground_friction_n\n",
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{:.7},{:.6},{:.7},{:.6},{:.7},{:.5},{:.5},{:.5},{:.5}",
            r.t_s,
            r.theta_deg,
            r.x_mm,
            r.x_dot_mm_s,
            r.penetration_mm,
            r.normal_n,
            r.palm_friction_n,
            r.ground_normal_n,
            r.ground_friction_n
        );
    }
    s
}
