//! The conventions of a command-line tool (issue 22): `--version` that traces a chart's bytes,
//! help texts that match the tool, completions and a man page.

#[path = "common/cli.rs"]
mod cli_util;
use cli_util::{jamchart, repo, stderr, stdout};

/// `--version` printed only `0.1.0`, so a changed chart hash could not be traced to a build:
/// it names the commit (as `git rev-parse HEAD` says, "unknown" without git) and the chart
/// format, for `jamchart` and every subcommand.
#[test]
fn version_names_crate_version_commit_and_chart_format() {
    let commit = std::process::Command::new("git")
        .args(["rev-parse", "HEAD"])
        .current_dir(repo())
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or("unknown".to_string(), |o| {
            String::from_utf8_lossy(&o.stdout).trim().to_string()
        });
    let want = format!(
        "{} (commit {commit}, chart format {})",
        env!("CARGO_PKG_VERSION"),
        jamchart::charts::CHART_FORMAT
    );
    for args in [&["--version"][..], &["-V"], &["render", "--version"]] {
        let out = jamchart(repo(), args);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", stderr(&out));
        let text = stdout(&out);
        assert!(text.trim_end().ends_with(&want), "{args:?}: {text}");
    }
}
