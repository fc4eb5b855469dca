//! Numbers printed in the paper, kept verbatim so that outputs can stand beside them.
//!
//! H. Parvaz, AUT J. Mech. Eng. 4(4) (2020) 553-564. What is wrong in them is listed in the
//! crate docs, "Corrections to the paper".

/// One row of the paper's Table 1 (m = 1 kg, r = 10 mm, F = 200 N, equal frictions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Table1Row {
    /// Friction coefficient at both contacts.
    pub mu: f64,
    /// First model (force analysis): x_jam in mm, as printed.
    pub statics_x_jam_mm: f64,
    /// First model: theta_jam in degrees, as printed: the closed form truncated to 0.1 deg,
    /// not rounded (23.171 deg at mu = 0.20 is printed 23.1;
    /// `statics_tests::paper_table1_is_our_theta_truncated_and_x_of_that_theta`).
    pub statics_theta_jam_deg: f64,
    /// Second model (minimum norm): x_jam in mm, as printed.
    pub min_norm_x_jam_mm: f64,
    /// Second model: theta_jam in degrees, as printed.
    pub min_norm_theta_jam_deg: f64,
    /// Known erratum in this row, if any.
    pub erratum: Option<&'static str>,
}

/// Table 1 of the paper, top to bottom.
pub const TABLE1: [Table1Row; 7] = [
    row(0.45, 21.64, 49.6, 21.53, 49.8, None),
    row(0.40, 24.38, 44.6, 24.26, 44.8, None),
    row(0.35, 27.85, 39.5, 27.78, 39.6, None),
    row(
        0.30,
        35.50,
        34.2,
        35.50,
        34.2,
        Some("x = 35.50 mm does not match theta = 34.2 deg: r cot(34.2/2) = 32.51 mm"),
    ),
    row(0.25, 39.09, 28.7, 39.23, 28.6, None),
    row(0.20, 48.93, 23.1, 48.93, 23.1, None),
    row(0.15, 65.35, 17.4, 65.73, 17.3, None),
];

const fn row(
    mu: f64,
    statics_x_jam_mm: f64,
    statics_theta_jam_deg: f64,
    min_norm_x_jam_mm: f64,
    min_norm_theta_jam_deg: f64,
    erratum: Option<&'static str>,
) -> Table1Row {
    Table1Row {
        mu,
        statics_x_jam_mm,
        statics_theta_jam_deg,
        min_norm_x_jam_mm,
        min_norm_theta_jam_deg,
        erratum,
    }
}

/// The paper's Adams result for mu = 0.4 (Section 5): x_jam = 25.58 mm.
pub const ADAMS_X_JAM_MM_MU_0_4: f64 = 25.58;
