//! Files written by the dynamics commands: the time series CSV, written atomically.

use std::fmt::Write as _;

use crate::dynamics::jam::SeriesRow;

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
