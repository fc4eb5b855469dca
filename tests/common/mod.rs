//! What the integration tests share: running the binary, browsers and the gallery's page,
//! random boxes and contact problems, the 25 mm shaft.

pub mod boxes;
pub mod browser;
pub mod cli;
#[macro_use]
pub mod gallery;
pub mod random_planar;
pub mod shaft;

/// Says on the terminal that a test was skipped and why. Written to the process's stderr
/// directly, not through `eprintln!`, which the test harness captures and shows only for a
/// failing test: a skip must be seen, not read as `ok`.
pub fn say_skipped(why: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n*** skipped: {why} ***");
}
