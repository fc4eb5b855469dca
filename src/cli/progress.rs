//! Progress on stderr for the long commands (`render`, `accuracy`, a long Monte Carlo of
//! `solve`) and `--quiet`, which silences it and the other notes they write there
//! (`stability`'s timing line).

use std::io::IsTerminal;

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};

/// `--quiet` of a long command.
#[derive(Debug, Clone, Copy, Default, Args)]
pub struct Quiet {
    /// Print no progress bar or notes on stderr, nor the list of files written (errors and
    /// warnings are still printed).
    #[arg(long, short = 'q')]
    pub quiet: bool,
}

/// Whether to draw a bar: only for a person watching, so not with --quiet, not into a pipe or
/// file, not in CI logs (`CI` set).
fn shown(quiet: bool, terminal: bool, ci: bool) -> bool {
    !quiet && terminal && !ci
}

/// A bar of `len` steps (0: its length is set later) with `template` (indicatif's syntax), or a
/// hidden one when nobody watches ([`shown`]).
pub fn bar(quiet: Quiet, len: u64, template: &str) -> ProgressBar {
    let terminal = std::io::stderr().is_terminal();
    if !shown(quiet.quiet, terminal, std::env::var_os("CI").is_some()) {
        return ProgressBar::hidden();
    }
    let b = ProgressBar::new(len);
    if let Ok(style) = ProgressStyle::with_template(template) {
        b.set_style(style);
    }
    b
}

/// Estimated CPU time above which sampled work shows a bar, s: below it the bar would only
/// flash.
const LONG_WORK_CPU_S: f64 = 2.0;

/// A bar over `count` Monte Carlo samples for a person watching, when their estimated CPU time
/// `estimated_cpu_s` is long enough to want one; hidden otherwise.
pub fn long_work(count: u64, estimated_cpu_s: f64) -> ProgressBar {
    if estimated_cpu_s < LONG_WORK_CPU_S {
        return ProgressBar::hidden();
    }
    bar(
        Quiet::default(),
        count,
        "Monte Carlo {bar:30} {pos}/{len} samples, {eta} left",
    )
}

#[cfg(test)]
mod tests {
    use super::shown;

    #[test]
    fn a_bar_only_for_a_person_watching_and_never_with_quiet() {
        assert!(shown(false, true, false));
        assert!(!shown(true, true, false));
        assert!(!shown(false, false, false));
        assert!(!shown(false, true, true));
    }
}
