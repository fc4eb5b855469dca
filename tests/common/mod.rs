//! What the integration tests share: running the binary, browsers and the gallery's page,
//! each model's answer through the port, random boxes of uncertain inputs, the paper's Adams
//! result.

pub mod boxes;
pub mod browser;
pub mod cli;
#[macro_use]
pub mod gallery;
pub mod http;
pub mod port;

/// Says on the terminal that a test was skipped and why. Written to the process's stderr
/// directly, not through `eprintln!`, which the test harness captures and shows only for a
/// failing test: a skip must be seen, not read as `ok`.
pub fn say_skipped(why: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n*** skipped: {why} ***");
}

/// The paper's Adams result for mu = 0.4 (Section 5): x_jam = 25.58 mm, as printed (the crate
/// keeps it too, to print beside its own answers).
pub const PAPER_ADAMS_X_JAM_MM_MU_0_4: f64 = 25.58;
