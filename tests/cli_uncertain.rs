//! Ranges and distributions on the command line and in files (issue 19): which settings take
//! them, how bad ones are refused, and the answers over a range.

#[path = "common/cli.rs"]
mod cli_util;

use cli_util::{jamchart, stderr};

/// Runs the binary in a fresh temp dir and returns (exit code, stderr).
fn refused(args: &[&str]) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(dir.path(), args);
    (o.status.code(), stderr(&o))
}

/// The bad input: each exits 2 with one `jamchart:` line naming the flag as written.
#[test]
fn bad_ranges_exit_2_naming_the_flag() {
    for (line, says) in [
        (
            "solve --mu 0.3:0.12",
            "invalid mu = 0.3:0.12 (flag --mu): the range is reversed",
        ),
        (
            "solve --force 40:40",
            "invalid force_n = 40:40 (flag --force): the range is empty",
        ),
        (
            "solve --mu-palm -0.1:0.3",
            "(flag --mu-palm or --mu): its low end -0.1 must be",
        ),
        (
            "solve --mass normal(0.4,0)",
            "standard deviation must be > 0",
        ),
        ("solve --mu 0.1:inf", "inf is not a finite number"),
        ("solve --mu gauss(0.2,0.1)", "'gauss' is not a distribution"),
        (
            "solve --radius 10:12",
            "--radius takes a single number; a range or a distribution is taken by --mu",
        ),
        ("accuracy --mu 0.1:0.3", "accuracy takes a single value"),
        (
            "vlocator --load-angle normal(-90,5)",
            "give a range LOW:HIGH",
        ),
    ] {
        let args: Vec<&str> = line.split(' ').collect();
        let (code, err) = refused(&args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.starts_with("jamchart: ") && err.contains(says),
            "{args:?}: {err}"
        );
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
    }
}

/// A parameter file's `[scene]` takes a range as a string, and a bad one names the file, line
/// and key; a point setting given a range there is refused with the settings that take one.
#[test]
fn a_files_bad_range_names_file_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "[scene]\nradius_mm = 10\nmu = \"0.3:0.1\"\n",
            "c.toml:3:6: invalid mu = 0.3:0.1: the range is reversed",
        ),
        (
            "[scene]\nradius_mm = \"10:12\"\n",
            "c.toml:2:13: invalid radius_mm = 10:12: radius_mm takes a single number",
        ),
    ];
    for (text, says) in cases {
        std::fs::write(dir.path().join("c.toml"), text).unwrap();
        let err = stderr(&jamchart(dir.path(), &["solve", "--config", "c.toml"]));
        assert!(err.contains(says), "{text}: {err}");
    }
}
