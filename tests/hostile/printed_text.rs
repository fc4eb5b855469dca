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
