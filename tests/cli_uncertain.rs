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
            "solve --mu normal(0.2,0.03) --samples 20000000",
            "invalid samples = 20000000 (flag --samples): the Monte Carlo sample count must be in [1, 10000000]",
        ),
        // Once "invalid digit found in string", the standard library's words.
        (
            "solve --mu 0.1:0.3 --samples 1e9",
            "1e9 is not a whole number >= 0 (write it out",
        ),
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

/// The shaft job is one command: the jam interval, the worst ends and the status
/// change over the friction range, in text and JSON.
#[test]
fn the_shaft_job_is_one_command() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["solve"];
    args.extend(cli_util::SHAFT);
    args.extend(["--mu", "0.12:0.3"]);
    let o = jamchart(dir.path(), &args);
    let out = cli_util::stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for line in [
        "theta_jam from 14.355 to 35.013 deg, x_jam from 39.629 to 99.261 mm",
        "beyond_reach for mu < 0.1489, jams from 0.1489 to 0.3",
        "the jam comes earliest at the high end",
    ] {
        assert!(out.contains(line), "{line}\n{out}");
    }
    args.extend(["--format", "json"]);
    let v = cli_util::json(&jamchart(dir.path(), &args));
    let r = &v["results"][0];
    assert_eq!(r["method"], "corners");
    assert_eq!(r["inputs"][0]["segments"][1]["status"], "jams");
    assert_eq!(v["uncertain"][0]["kind"], "range");
}

/// `sweep` with a range draws the band's two edges and writes them as layers `band_earliest`
/// and `band_latest` of the CSV, each in its own colour: the closed form at the range's ends
/// (here mu = 0.3 and 0.16, checked against `solve` at those points); a map of two axes refuses
/// a range for now.
#[test]
fn a_sweep_with_a_range_writes_the_bands_edges() {
    let dir = tempfile::tempdir().unwrap();
    let base = ["--radius", "12.5", "--mass", "0.4", "--palm-length", "80"];
    let mut args = vec!["sweep", "force_n=20:100:5", "--out", "o", "--format", "svg"];
    args.extend(base);
    args.extend(["--mu", "0.16:0.3"]);
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // The two edges are told apart by colour (and dash): once both were the construction
    // lines' thin blue dash. Bluish green for the earliest jam, orange for the latest.
    let svg = std::fs::read_to_string(dir.path().join("o/sweep_force_n.svg")).unwrap();
    for colour in ["#009E73", "#E69F00"] {
        assert!(svg.contains(colour), "no band edge in {colour}");
    }
    let csv = std::fs::read_to_string(dir.path().join("o/sweep_force_n.csv")).unwrap();
    for (layer, mu) in [("band_earliest", "0.3"), ("band_latest", "0.16")] {
        let row = csv
            .lines()
            .find(|l| l.starts_with(&format!("{layer},60,")))
            .unwrap_or_else(|| panic!("{layer} at F = 60 in\n{csv}"));
        let x: f64 = row.split(',').nth(3).unwrap().parse().unwrap();
        let mut solve = vec!["solve", "--force", "60", "--mu", mu, "--format", "json"];
        solve.extend(base);
        let v = cli_util::json(&jamchart(dir.path(), &solve));
        let want = v["results"][0]["x_jam_mm"].as_f64().unwrap();
        assert!((x - want).abs() < 1e-4, "{layer}: {x} vs solve {want}");
    }
    let o = jamchart(
        dir.path(),
        &[
            "sweep",
            "force_n=20:100",
            "mass_kg=0.1:1",
            "--mu",
            "0.1:0.3",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
}
