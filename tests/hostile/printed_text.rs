//! Text a person reads: numbers printed with 40 to 325 digits (`--mu 'normal(1e308,1)'` echoed
//! mu with 309 digits), control characters from file names and paths written raw to the
//! terminal, and a usage error that dropped the flag it was about.

use super::cli_util::{longest_digit_run, stderr, stdout};
use super::run;

/// Commands at the ends of the float range, on every text writer: the range answer, the
/// distribution's, the robust V-block, the point V-block, `design` and the error messages. No
/// run of digits is longer than an f64's 17 significant digits.
#[test]
fn numbers_at_the_ends_of_the_float_range_print_short() {
    let dir = tempfile::tempdir().unwrap();
    let mut cases: Vec<Vec<String>> = Vec::new();
    for v in [
        "1e308",
        "1e-308",
        "5e-324",
        "1.7976931348623157e308",
        "1e-300",
    ] {
        for flag in ["--mu", "--mass", "--force"] {
            for value in [format!("1:{v}"), format!("normal({v},1)"), format!("{v}:1")] {
                cases.push(vec!["solve".into(), flag.into(), value]);
            }
        }
        for flag in ["--load", "--load-angle", "--load-at-rim", "--mass", "--mu"] {
            cases.push(vec!["vlocator".into(), flag.into(), v.into()]);
            cases.push(vec!["vlocator".into(), flag.into(), format!("1:{v}")]);
        }
        cases.push(vec!["solve".into(), "--palm-length".into(), v.into()]);
        cases.push(vec![
            "design".into(),
            "--x-target".into(),
            "40".into(),
            "--mu".into(),
            v.into(),
        ]);
    }
    cases.push(
        ["solve", "--model", "dynamics", "--omega", "1e-300"]
            .map(String::from)
            .to_vec(),
    );
    cases.push(
        ["solve", "--mu", "normal(0.3,0.01)", "--before", "1e300"]
            .map(String::from)
            .to_vec(),
    );
    for args in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = run(dir.path(), &args);
        let text = format!("{}{}", stdout(&o), stderr(&o));
        assert!(matches!(o.status.code(), Some(0 | 2)), "{args:?}: {text}");
        assert!(longest_digit_run(&text) <= 17, "{args:?}:\n{text}");
    }
}

/// A scene file whose name holds `ESC [ 31 m` and an output folder whose name holds the OSC
/// sequence `ESC ] 0 ;` reached the terminal raw in the list of files written, and a settings
/// file's name in the error message.
#[test]
fn control_characters_in_names_never_reach_the_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let scene = "a\u{1b}[31mred.toml";
    let text = std::fs::read_to_string(super::cli_util::repo().join("charts/fig6.toml")).unwrap();
    std::fs::write(d.join(scene), text).unwrap();
    for args in [
        &[
            "render",
            scene,
            "--out",
            "o\u{1b}]0;x\u{7}",
            "--format",
            "svg",
        ][..],
        &["solve", "--config", "\u{1b}[2Jnone.toml"][..],
        &["render", "--scenes-dir", "\u{9b}31m"][..],
    ] {
        let o = run(d, args);
        let text = format!("{}{}", stdout(&o), stderr(&o));
        assert!(
            !text.contains(['\u{1b}', '\u{7}', '\u{9b}']),
            "{args:?}: {text:?}"
        );
        assert!(
            text.contains("\\u{1b}") || text.contains("\\u{9b}"),
            "{args:?}: {text}"
        );
    }
}

/// `jamchart design` without `--x-target` said "the following required arguments were not
/// provided:;" and dropped the flag's name.
#[test]
fn a_missing_required_flag_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(dir.path(), &["design"]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(e.contains("--x-target"), "{e}");
    assert!(!e.contains(":;"), "{e}");
}

/// Three messages quoted a number with its 309 digits: a chart axis' end (`render
/// jam-probability --set chart.x_min_mm=-1e308`), a whole number given as a float (`render
/// fig7b --set size.width_px=1e308`, in the parser's words) and the warning that names a
/// `--set` the chart does not show (`render fig7b --set force_n=1e308`).
#[test]
fn messages_about_a_set_print_its_numbers_short() {
    let dir = tempfile::tempdir().unwrap();
    for (args, says) in [
        (
            &[
                "render",
                "jam-probability",
                "--set",
                "chart.x_min_mm=-1e308",
            ][..],
            "-1e308",
        ),
        (
            &["render", "fig7b", "--set", "size.width_px=1e308"][..],
            "1e308",
        ),
        (
            &[
                "render",
                "fig7b",
                "--set",
                "force_n=1e308",
                "--format",
                "svg",
            ][..],
            "--set force_n=1e308 does not show",
        ),
    ] {
        let mut all = args.to_vec();
        all.extend(["--out", "o"]);
        let o = run(dir.path(), &all);
        let text = format!("{}{}", stdout(&o), stderr(&o));
        assert!(matches!(o.status.code(), Some(0 | 2)), "{args:?}: {text}");
        assert!(stderr(&o).contains(says), "{args:?}: {text}");
        assert!(longest_digit_run(&text) <= 17, "{args:?}:\n{text}");
    }
}

/// A newline in an `--out` path split the list of files written over two lines of the answer
/// (`fig6: a` and `b/fig6.svg`), as if it listed a file `b/fig6.svg`: a path is one line, its
/// newline escaped, in the answer and in a message.
#[test]
fn a_newline_in_a_path_stays_on_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        dir.path(),
        &["render", "fig6", "--format", "svg", "--out", "a\nb"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(
        stdout(&o),
        "fig6: a\\u{a}b/fig6.csv a\\u{a}b/fig6.svg\ngallery: a\\u{a}b/index.html\n"
    );
    assert!(dir.path().join("a\nb/fig6.svg").is_file());
    let o = run(
        dir.path(),
        &["sweep", "mu=0.1:0.5:5", "--format", "svg", "--out", "c\nd"],
    );
    assert_eq!(stdout(&o).lines().count(), 2, "{}", stdout(&o));
    let o = run(dir.path(), &["solve", "--config", "x\ny.toml"]);
    assert_eq!(
        stderr(&o),
        "jamchart: cannot read x\\u{a}y.toml: No such file or directory (os error 2)\n"
    );
}

/// Answers at the ends of the float range printed `inf` or every digit: a start angle of
/// 5e-324 deg said the palm "would touch it inf mm from the hinge", `--model all --force
/// 1e300` wrote the push with 301 digits in its design line, and a nonsmooth palm at
/// `--omega 1e308` "pushed with inf N". Each now answers with a short number or says the
/// value is beyond the float range. The same start angle in `design` said the disc "starts at
/// x = inf mm" and `--model all` wrote the largest double with its 17 digits; the stability
/// tables wrote x with 309 digits at `--palm-offset 1e308` and a friction cone used "1 to inf"
/// at mu = 5e-324. Every number now has at most the 12 digits a number is shown with.
#[test]
fn answers_at_the_float_range_print_no_inf_and_no_long_number() {
    let dir = tempfile::tempdir().unwrap();
    for args in [
        &["solve", "--start-angle", "5e-324"][..],
        &["design", "--x-target", "40", "--start-angle", "5e-324"],
        &[
            "solve",
            "--model",
            "all",
            "--no-verify",
            "--start-angle",
            "5e-324",
        ],
        &[
            "stability",
            "--cases",
            "barely_moves",
            "--palm-offset",
            "1e308",
            "-q",
        ],
        &[
            "stability",
            "--cases",
            "barely_moves",
            "--mu",
            "5e-324",
            "-q",
        ],
        &[
            "solve", "--model", "all", "--force", "1e300", "--mass", "1e-300",
        ],
        &[
            "solve",
            "--model",
            "dynamics",
            "--method",
            "nonsmooth",
            "--omega",
            "1e308",
        ],
    ] {
        let o = run(dir.path(), args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let out = stdout(&o).replace("-> inf", "");
        assert!(longest_digit_run(&out) <= 12, "{args:?}: {out}");
        let shows_inf = out
            .split(|c: char| !c.is_ascii_alphanumeric())
            .any(|w| w == "inf" || w == "NaN");
        assert!(!shows_inf, "{args:?}: {out}");
    }
}

/// The series file's name was printed as given: `--series "$(printf 'a\nb')"` split the
/// answer's series line in two. It is escaped, on one line.
#[test]
fn a_series_path_with_a_newline_is_printed_on_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "solve",
        "--model",
        "dynamics",
        "--method",
        "nonsmooth",
        "--series",
        "a\nb.csv",
    ];
    let o = run(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let line = out.lines().find(|l| l.contains("series:")).unwrap();
    assert!(line.contains(r#"a\u{a}b.csv"#), "{out}");
    assert!(dir.path().join("a\nb.csv").is_file());
}

/// `--help > /dev/full` exited 0 with the help lost, as the answers once did.
#[test]
fn help_lost_to_a_full_disk_is_an_error() {
    let full = std::fs::File::options()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .arg("--help")
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).starts_with("jamchart: writing"),
        "{}",
        stderr(&o)
    );
}
