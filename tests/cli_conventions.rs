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

/// The completions offered no scene after `render`: the bash script, run by bash as it
/// completes `jamchart render fi<TAB>` and `jamchart scenes vl<TAB>`, offers the built-in scenes
/// that start so (`jamchart scenes` lists them).
#[test]
fn bash_completes_the_built_in_scenes_after_render() {
    let dir = tempfile::tempdir().unwrap();
    let script = stdout(&jamchart(dir.path(), &["completions", "bash"]));
    std::fs::write(dir.path().join("jamchart.bash"), script).unwrap();
    let listed = stdout(&jamchart(dir.path(), &["scenes"]));
    let scenes: Vec<&str> = listed
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for (line, prefix) in [("jamchart render fi", "fi"), ("jamchart scenes vl", "vl")] {
        let words: Vec<&str> = line.split(' ').collect();
        let probe = format!(
            "source ./jamchart.bash; COMP_WORDS=({line}); COMP_CWORD={cword}; \
             COMP_LINE='{line}'; COMP_POINT=${{#COMP_LINE}}; _jamchart jamchart {cur} {prev}; \
             printf '%s\\n' \"${{COMPREPLY[@]}}\"",
            cword = words.len() - 1,
            cur = words[words.len() - 1],
            prev = words[words.len() - 2],
        );
        let o = std::process::Command::new("bash")
            .args(["--norc", "-c", &probe])
            .current_dir(dir.path())
            .output()
            .unwrap();
        let mut offered: Vec<String> = String::from_utf8_lossy(&o.stdout)
            .lines()
            .map(str::to_string)
            .collect();
        offered.sort();
        let mut wanted: Vec<&str> = scenes
            .iter()
            .copied()
            .filter(|s| s.starts_with(prefix))
            .collect();
        wanted.sort();
        assert!(!wanted.is_empty(), "{listed}");
        assert_eq!(
            offered,
            wanted,
            "{line}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
}

/// The man pages' SYNOPSIS listed the flags without their values (`[--model]`): each flag now
/// shows its value, the named values where it has them (`--model
/// <statics|min-norm|dynamics|all>`), else its value name (`--mu <MU>`).
#[test]
fn man_synopsis_shows_the_values_of_the_flags() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(dir.path(), &["man", "--out-dir", "man1"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let synopsis = |sub: &str| {
        let page = std::fs::read_to_string(dir.path().join(format!("man1/jamchart-{sub}.1")))
            .unwrap()
            .replace("\\-", "-");
        let start = page.find(".SH SYNOPSIS").unwrap();
        let end = start + page[start..].find(".SH DESCRIPTION").unwrap();
        page[start..end].to_string()
    };
    let solve = synopsis("solve");
    for shown in [
        "[--model <statics|min-norm|dynamics|all>]",
        "[--mu <MU>]",
        "[--method <radau5|dopri5|nonsmooth>]",
        "[--trace]",
    ] {
        assert!(solve.contains(shown), "{shown}: {solve}");
    }
    let render = synopsis("render");
    assert!(render.contains("[--format <svg|png|both|pdf>]"), "{render}");
    assert!(render.trim_end().ends_with("[SCENE]..."), "{render}");
    assert!(
        synopsis("design").contains(" --x-target <MM>"),
        "{}",
        synopsis("design")
    );
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

/// `sweep` had no `-q` while `render`, which writes into the same gallery, had: both take it,
/// and print nothing but errors and warnings with it, their files written all the same.
#[test]
fn quiet_silences_render_and_sweep_alike() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["render", "fig6", "--format", "svg", "--out", "o", "-q"][..],
        &[
            "sweep",
            "mu=0.1:0.5:5",
            "--format",
            "svg",
            "--out",
            "o",
            "-q",
        ][..],
    ] {
        let o = jamchart(dir.path(), args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert_eq!(
            (stdout(&o), stderr(&o)),
            (String::new(), String::new()),
            "{args:?}"
        );
    }
    for f in ["fig6.svg", "sweep_mu.svg", "index.html"] {
        assert!(dir.path().join("o").join(f).is_file(), "{f}");
    }
}

/// `render --help` and the guide said a failed `--check` writes the new renders to a
/// temporary folder named in the report; it writes nothing anywhere (`hostile::check_folder`
/// checks that) and says how to look at them instead. The help says so, and so does the guide.
#[test]
fn the_docs_say_a_failed_check_writes_nothing() {
    let help = stdout(&jamchart(repo(), &["render", "--help"]));
    let guide = std::fs::read_to_string(repo().join("src/guide.md")).unwrap();
    for (doc, text) in [
        ("render --help", help.as_str()),
        ("the guide", guide.as_str()),
    ] {
        let one_line = text.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(!one_line.contains("temporary folder"), "{doc}");
        assert!(!one_line.contains("$TMPDIR"), "{doc}");
        assert!(
            one_line.contains("another --out") || one_line.contains("another `--out`"),
            "{doc}"
        );
    }
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
