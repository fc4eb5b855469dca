//! The conventions of a command-line tool: `--version` that traces a chart's bytes,
//! help texts that match the tool, completions and a man page.

use crate::common::cli as cli_util;
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

/// The subcommands every completion script and the man page must know.
const SUBCOMMANDS: [&str; 11] = [
    "solve",
    "table",
    "render",
    "sweep",
    "scenes",
    "settings",
    "accuracy",
    "stability",
    "vlocator",
    "completions",
    "man",
];

/// There were no shell completions: `jamchart completions SHELL` prints a script made from the
/// clap definitions, naming every subcommand, for bash, zsh and fish.
#[test]
fn completions_name_every_subcommand_for_bash_zsh_and_fish() {
    for (shell, marker) in [
        ("bash", "complete -F"),
        ("zsh", "#compdef jamchart"),
        ("fish", "complete -c jamchart"),
    ] {
        let out = jamchart(repo(), &["completions", shell]);
        assert_eq!(out.status.code(), Some(0), "{shell}: {}", stderr(&out));
        let script = stdout(&out);
        assert!(script.contains(marker), "{shell}: {script:.300}");
        for sub in SUBCOMMANDS {
            assert!(script.contains(sub), "{shell} script lacks {sub}");
        }
        // A flag of a subcommand, not only the names.
        assert!(
            script.contains("bless"),
            "{shell} script lacks render --bless"
        );
    }
    let bad = jamchart(repo(), &["completions", "tcsh"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(
        stderr(&bad).starts_with("jamchart: invalid value 'tcsh'"),
        "{}",
        stderr(&bad)
    );
}

/// There was no man page: `jamchart man` prints jamchart.1 in roff with every subcommand;
/// `--out-dir` writes a page per subcommand beside it.
#[test]
fn man_page_lists_every_subcommand_and_out_dir_writes_one_per_subcommand() {
    let out = jamchart(repo(), &["man"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let page = stdout(&out);
    assert!(
        page.starts_with(".ie") || page.contains(".TH jamchart 1"),
        "{page:.300}"
    );
    for sub in SUBCOMMANDS {
        assert!(page.contains(sub), "man page lacks {sub}");
    }
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(dir.path(), &["man", "--out-dir", "man1"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let render = std::fs::read_to_string(dir.path().join("man1/jamchart-render.1")).unwrap();
    assert!(
        render.contains("bless") && render.contains("check"),
        "{render:.300}"
    );
    for sub in SUBCOMMANDS {
        assert!(
            dir.path().join(format!("man1/jamchart-{sub}.1")).exists(),
            "no page for {sub}"
        );
    }
}

/// `stability` wrote its timing line on stderr with no way to silence it: `--quiet` does.
#[test]
fn quiet_silences_the_stability_timing_line() {
    let loud = jamchart(repo(), &["stability", "--cases", "paper"]);
    assert_eq!(loud.status.code(), Some(0), "{}", stderr(&loud));
    assert!(stderr(&loud).contains("took"), "{}", stderr(&loud));
    let quiet = jamchart(repo(), &["stability", "--cases", "paper", "--quiet"]);
    assert_eq!(quiet.status.code(), Some(0), "{}", stderr(&quiet));
    assert!(stderr(&quiet).is_empty(), "{}", stderr(&quiet));
    // The report itself is on stdout either way (the timings in it may differ).
    assert!(stdout(&quiet).contains("paper"), "{}", stdout(&quiet));
}

/// Colour is printed in one place, clap's help (bold and underlined headings); it follows
/// `NO_COLOR` even when colour is forced (`CLICOLOR_FORCE`).
#[test]
fn no_color_turns_off_the_colour_of_help() {
    let run = |no_color: bool| {
        let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"));
        c.args(["solve", "--help"]).env("CLICOLOR_FORCE", "1");
        if no_color {
            c.env("NO_COLOR", "1");
        } else {
            c.env_remove("NO_COLOR");
        }
        c.output().unwrap()
    };
    assert!(
        run(false).stdout.contains(&0x1b),
        "forced colour shows escapes"
    );
    assert!(!run(true).stdout.contains(&0x1b), "NO_COLOR leaves none");
}
