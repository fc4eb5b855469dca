//! The binary under hostile input: a signal in the middle of a write
//! into folders the render created, the one-thread fallback on an address-space-starved
//! system, and a battery over every class of hostile input and every surface of the tool, each
//! run checked for a clean answer or a clean refusal.

use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use crate::common::cli as cli_util;
use cli_util::{kill_and_wait, longest_digit_run, stderr, stdout};

/// The test hook of `atomic::write_all`: a pause between staging a set and committing it.
const PAUSE_VAR: &str = "JAMCHART_TEST_PAUSE_AFTER_STAGING_MS";

/// The files under `dir`, at any depth, as paths relative to it.
fn files_under(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let p = e.path();
            if p.is_dir() {
                todo.push(p.clone());
            }
            out.push(p.strip_prefix(dir).unwrap().display().to_string());
        }
    }
    out.sort();
    out
}

/// A signal arriving while a render writes into folders it
/// created must leave neither the folders nor a `.tmp` file. The test hook holds the render
/// after its temporaries are written in `new/sub` (it otherwise passes that point in about a
/// millisecond); SIGTERM, SIGINT and SIGHUP then each leave the working folder as it was.
#[test]
fn a_signal_during_a_write_into_created_folders_leaves_nothing() {
    for signal in ["TERM", "INT", "HUP"] {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args(["render", "fig3", "--format", "svg", "--out", "new/sub"])
            .env(PAUSE_VAR, "30000")
            .current_dir(d)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        while !files_under(d).iter().any(|f| f.ends_with(".tmp")) {
            assert!(
                t0.elapsed() < Duration::from_secs(60),
                "no temporaries appeared: {:?}",
                files_under(d)
            );
            std::thread::sleep(Duration::from_millis(10));
        }
        kill_and_wait(&mut child, signal);
        assert_eq!(files_under(d), Vec::<String>::new(), "SIG{signal}");
    }
}

/// When the threads could not all be started, those that did
/// start were told to stop but not waited for, so their stacks (8 MiB each) still held the
/// address space the one-thread run needed: under `ulimit -v 409600` with 250 threads asked,
/// `render fig3` aborted with "memory allocation of 2572816 bytes failed" in 3 runs of 5
/// (without the MALLOC_ARENA_MAX=1 of the earlier test). They are now joined first; five runs
/// in a row succeed.
#[test]
fn the_one_thread_fallback_waits_for_the_threads_that_started() {
    let dir = tempfile::tempdir().unwrap();
    for run in 0..5 {
        let out = format!("o{run}");
        let o = Command::new("sh")
            .arg("-c")
            .arg("ulimit -v 409600 && exec \"$0\" \"$@\"")
            .arg(env!("CARGO_BIN_EXE_jamchart"))
            .args(["render", "fig3", "--format", "svg", "--out", &out])
            .env("RAYON_NUM_THREADS", "250")
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "run {run}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("running on one thread"),
            "{}",
            stderr(&o)
        );
    }
}

/// Runs `jamchart ARGS` in a fresh temp folder, stdin empty, killed after 20 s (a guard
/// against a hang, not a measurement).
fn run(args: &[&str]) -> Output {
    let dir = tempfile::tempdir().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .env_remove("RUST_BACKTRACE")
        .env("RAYON_NUM_THREADS", "1")
        .current_dir(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    while child.try_wait().unwrap().is_none() && t0.elapsed() < Duration::from_secs(20) {
        std::thread::sleep(Duration::from_millis(5));
    }
    let _ = child.kill();
    let o = child.wait_with_output().unwrap();
    let left: Vec<String> = files_under(dir.path())
        .into_iter()
        .filter(|f| f.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "{args:?} left {left:?}");
    o
}

/// What is wrong with a refusal of `args` that should name `flag`, if anything.
fn refusal_defect(args: &[&str], flag: &str) -> Option<String> {
    let o = run(args);
    let err = stderr(&o);
    let clean = o.status.code() == Some(2)
        && err.starts_with("jamchart: ")
        && err.contains(flag)
        && !err.contains("panicked")
        && err.len() < 600;
    (!clean).then(|| format!("{args:?}: exit {:?}, {err}", o.status.code()))
}

/// Whether `text` shows a NaN or an infinity as a number (the words "infinity" or "F -> inf",
/// which name the limit, are not numbers).
fn shows_nan_or_inf(text: &str) -> bool {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-'))
        .any(|w| matches!(w.to_ascii_lowercase().as_str(), "nan" | "inf" | "-inf"))
        && !text.contains("-> inf")
}

/// Wrong answers with exit 0 on the distributions:
/// `solve --mu lognormal(0.2,1e300)` reached mu = inf and printed theta_jam = 182.810 deg at
/// x_jam = -0.245 mm, `jammed_at_start`, with exit 0; `normal(1e308,1e308)` printed inf. A
/// distribution whose reach (the quantiles a draw can land on) leaves the setting's valid
/// values is refused naming the flag. A normal truncated at 0 stays accepted for a push.
#[test]
fn a_distribution_that_reaches_infinity_is_refused() {
    for (value, says) in [
        (
            "lognormal(0.2,1e300)",
            "highest value a sample can take is inf",
        ),
        (
            "normal(1e308,1e308)",
            "highest value a sample can take is inf",
        ),
    ] {
        let o = run(&["solve", "--mu", value]);
        assert_eq!(o.status.code(), Some(2), "{value}: {}", stdout(&o));
        assert!(
            stderr(&o).contains("--mu") && stderr(&o).contains(says),
            "{}",
            stderr(&o)
        );
    }
    let o = run(&["solve", "--force", "normal(200,100)"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// Garbled values: a distribution echoed its numbers in full,
/// `lognormal(0.2,1000...000)` with 301 digits, in the answer and in the refusal. They are
/// written as short as they read back.
#[test]
fn a_huge_number_in_a_distribution_is_echoed_short() {
    let o = run(&["solve", "--mu", "lognormal(0.2,1e300)"]);
    assert!(
        stderr(&o).contains("lognormal(0.2,1e300)"),
        "{}",
        stderr(&o)
    );
    let o = run(&["solve", "--mu", "1e-300:0.3"]);
    assert!(stdout(&o).contains("mu = 1e-300:0.3"), "{}", stdout(&o));
}

/// The wrong flag named: `solve --samples -1`, `--seed -1` and
/// `--quantiles -0.5` were refused as "unexpected argument '-1' found", naming no flag: clap
/// read the negative value as a flag. Each is now refused naming its own flag; so is a negative
/// number written with an exponent (`--rtol -1e-3` was read as the flags -1 and -e), a list
/// starting with one, and a number flag of every command that takes one.
#[test]
fn a_negative_count_or_probability_names_its_flag() {
    for (flag, value) in [
        ("--samples", "-1"),
        ("--seed", "-1"),
        ("--seed", "-1e3"),
        ("--quantiles", "-0.5"),
        ("--quantiles", "-1e-300"),
        ("--quantiles", "-0.5,0.5"),
        ("--rtol", "-1e-3"),
        ("--palm-offset", "-1e-3"),
        ("--gravity", "-1e-300"),
    ] {
        let args = ["solve", "--mu", "normal(0.2,0.03)", flag, value];
        assert_eq!(refusal_defect(&args, flag), None);
    }
    for args in [
        ["design", "--x-target", "-1e-3"],
        ["vlocator", "--included-angle", "-1e-3"],
        ["accuracy", "--tolerances", "-1e-3"],
        ["accuracy", "--converged-rtol", "-1e-3"],
        ["accuracy", "--penetrations", "-1e-3"],
        ["accuracy", "--nonsmooth-steps", "-1e-3"],
        ["accuracy", "--runs", "-1"],
        ["accuracy", "--map-cells", "-1"],
    ] {
        assert_eq!(refusal_defect(&args, args[1]), None);
    }
    // A count says what a count is, not the standard library's "invalid digit".
    let o = run(&["accuracy", "--runs", "-1"]);
    assert!(
        stderr(&o).contains("-1 is not a whole number >= 0"),
        "{}",
        stderr(&o)
    );
    // A negative position is a question with an answer (no jam lies before it).
    let o = run(&["solve", "--mu", "normal(0.2,0.03)", "--before", "-1e-3"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// The hostile battery over every class of bad input and every surface (ranges and
/// distributions, --samples, --seed, --before, design, vlocator --mu A:B, render --read-off,
/// --bless/--check, sweep axes, --set): each bad input is refused with exit 2, `jamchart: `
/// and the flag or key as written, in a short message, leaving no `.tmp`. Prints the count.
#[test]
fn the_hostile_battery_is_refused_cleanly() {
    let mut cases: Vec<(Vec<String>, String)> = Vec::new();
    let mut add = |args: &[&str], flag: &str| {
        cases.push((args.iter().map(|a| a.to_string()).collect(), flag.into()));
    };
    for flag in [
        "--mu",
        "--mu-ground",
        "--mu-palm",
        "--radius",
        "--mass",
        "--force",
        "--gravity",
        "--start-angle",
        "--palm-length",
        "--palm-offset",
    ] {
        for v in [
            "nan", "inf", "-inf", "1e-400", "1e400", "abc", "0x10", "1,5",
        ] {
            add(&["solve", &format!("{flag}={v}")], flag);
        }
    }
    for v in [
        "0.3:0.1",
        "0.1:0.3:0.5",
        "0.1:",
        ":0.3",
        "0.1:nan",
        "0.1:inf",
        "-0.1:0.3",
        "1e-400:0.3",
        "normal(0.2)",
        "normal(0.2,-1)",
        "normal(0.2,nan)",
        "lognormal(0,0.25)",
        "lognormal(0.2,1e300)",
    ] {
        add(&["solve", "--mu", v], "--mu");
        add(&["design", "--x-target", "50", "--mu", v], "--mu");
    }
    for v in ["0", "1e9", "abc", "1.5", "-1"] {
        add(
            &["solve", "--mu", "normal(0.2,0.03)", "--samples", v],
            "--samples",
        );
    }
    for v in ["nan", "inf", "abc"] {
        add(&["solve", "--mu", "0.1:0.3", "--before", v], "--before");
    }
    for v in ["0", "1", "nan", "-0.5"] {
        add(
            &["solve", "--mu", "normal(0.2,0.03)", "--quantiles", v],
            "--quantiles",
        );
    }
    for v in ["nan", "-1", "0", "1e400", "inf"] {
        add(&["design", "--x-target", v], "--x-target");
    }
    for v in ["0.3:0.1", "nan:0.3", "0.1:inf", "-1:0.3", "1e-400:0.3"] {
        add(&["vlocator", "--mu", v], "--mu");
    }
    for flag in [
        "--included-angle",
        "--mass",
        "--gravity",
        "--load",
        "--load-angle",
    ] {
        for v in ["nan", "inf", "1e-400", "abc"] {
            add(&["vlocator", &format!("{flag}={v}")], flag);
        }
    }
    for v in ["mu=nan", "mu=abc", "nonsense=1", "mu", "mu=1e400"] {
        add(
            &["render", "fig3", "--format", "svg", "--read-off", v],
            "--read-off",
        );
    }
    add(&["render", "fig3", "--bless", "--check"], "--bless");
    for (axis, key) in [
        ("mu=1e-320:1:5:log", "mu"),
        ("force_n=1e-300:1e300:41:log", "force_n"),
        ("mu=0.1:0.5:5:7", "mu"),
        ("mu=0.1:0.5:5:log:log", "mu"),
        ("radius_mm=0:10", "radius_mm"),
        ("mu=nan:0.5", "mu"),
    ] {
        add(&["sweep", axis, "--format", "svg"], key);
    }
    for (set, key) in [
        ("title=", "title"),
        ("dynamics.after_jam_s=1e300", "dynamics.after_jam_s"),
        ("scene.mu=1e400", "scene.mu"),
    ] {
        add(&["render", "fig3", "--format", "svg", "--set", set], key);
    }
    add(&["stability", "--cases", "nope"], "--cases");
    add(
        &["stability", "--cases", "barely_moves", "--mu", "0"],
        "barely_moves",
    );
    let defects: Vec<String> = cases
        .iter()
        .filter_map(|(args, flag)| {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            refusal_defect(&args, flag)
        })
        .collect();
    println!(
        "hostile battery: {} bad inputs, {} refused cleanly",
        cases.len(),
        cases.len() - defects.len()
    );
    assert!(defects.is_empty(), "{}", defects.join("\n"));
}

/// The battery's good inputs at the edges: each answers with exit 0 and no NaN or infinity
/// printed as a number (`vlocator --mass 1e-300 --gravity 1e-300` once printed `NaN W`).
#[test]
fn the_hostile_battery_answers_at_the_edges_without_nan() {
    let cases: &[&[&str]] = &[
        &["solve", "--mu", "0.1:0.3"],
        &["solve", "--mu", "normal(0.2,0.03)", "--format", "json"],
        &["solve", "--mu", "lognormal(0.2,0.25)", "--before", "40"],
        &["solve", "--force", "1e-300:1e300"],
        &["solve", "--mu", "1e-300:1e300"],
        &["solve", "--mass", "0:1e300"],
        &["solve", "--force", "1e-300"],
        &["solve", "--force", "1e300"],
        &[
            "solve",
            "--mu",
            "1e-9",
            "--palm-length",
            "1e12",
            "--model",
            "all",
        ],
        &["design", "--x-target", "50", "--mu", "0:1e300"],
        &["design", "--x-target", "50", "--mu", "normal(0.2,0.03)"],
        &["vlocator", "--mu", "0.1:0.3"],
        &[
            "vlocator",
            "--mu",
            "0.3",
            "--load",
            "9.806",
            "--load-angle",
            "90",
        ],
        &["render", "fig3", "--format", "svg", "--read-off", "mu=0.3"],
    ];
    for args in cases {
        let o = run(args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        assert!(!shows_nan_or_inf(&stdout(&o)), "{args:?}: {}", stdout(&o));
    }
}

/// Lost output: an answer written to /dev/full exits non-zero
/// with the message, for ranges, distributions, design and the V-block.
#[test]
fn lost_output_on_the_new_surfaces_is_an_error() {
    let cases: &[&[&str]] = &[
        &["solve", "--mu", "0.1:0.3"],
        &["solve", "--mu", "normal(0.2,0.03)", "--format", "json"],
        &["design", "--x-target", "50"],
        &["vlocator", "--mu", "0.1:0.3"],
    ];
    for args in cases {
        let full = std::fs::File::options()
            .write(true)
            .open("/dev/full")
            .unwrap();
        let o = Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args(*args)
            .stdout(full)
            .output()
            .unwrap();
        assert_ne!(o.status.code(), Some(0), "{args:?}");
        assert!(stderr(&o).starts_with("jamchart: "), "{}", stderr(&o));
    }
}

/// Runs the binary in an empty folder.
fn run_in_empty(args: &[&str]) -> Output {
    let dir = tempfile::tempdir().unwrap();
    cli_util::jamchart(dir.path(), args)
}

/// Regression: `solve --mu 1e-300` printed its `x_rigid` line (and the echoed mu) with
/// 300-digit numbers, the `--radius 1e-300` warning 300 zeros, `design --x-target 1e300` 301
/// digits, and `solve --mu 0.16:0.3` the nominal mu as 0.22999999999999998. Every number shown
/// now goes through one formatter: 12 significant digits at most, exponent at the extremes.
#[test]
fn numbers_shown_to_a_user_are_short() {
    for args in [
        &["solve", "--mu", "1e-300"][..],
        &["solve", "--radius", "1e-300"],
        &["design", "--x-target", "1e300"],
        &["solve", "--mu", "0.16:0.3"],
    ] {
        let o = run_in_empty(args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        let all = stdout(&o) + &stderr(&o);
        assert!(
            longest_digit_run(&all) <= 15,
            "{args:?} prints a {}-digit number:\n{all}",
            longest_digit_run(&all)
        );
    }
    let o = run_in_empty(&["solve", "--mu", "1e-300"]);
    assert!(
        stdout(&o).contains("x_rigid   = 1e301 mm"),
        "{}",
        stdout(&o)
    );
    let o = run_in_empty(&["solve", "--radius", "1e-300"]);
    assert!(
        stderr(&o).contains("= 1e-300 mm is under 0.5 mm"),
        "{}",
        stderr(&o)
    );
    let o = run_in_empty(&["design", "--x-target", "1e300"]);
    assert!(stdout(&o).contains("target x = 1e300 mm"), "{}", stdout(&o));
    let o = run_in_empty(&["solve", "--mu", "0.16:0.3"]);
    assert!(
        stdout(&o).contains("nominal mu_ground = 0.23,"),
        "{}",
        stdout(&o)
    );
}

/// Regression: `--before nan` / `--before inf` were accepted silently when no input is
/// distributed (the flag was ignored). They are refused naming `--before` with or without a
/// distribution, and a `--before` with no distributed input is said to have no effect.
#[test]
fn before_nan_is_refused_without_a_distribution() {
    for args in [
        &["solve", "--before", "nan"][..],
        &["solve", "--before", "inf"],
        &["solve", "--before=-inf", "--mu", "0.2:0.3"],
    ] {
        let o = run_in_empty(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
        assert!(stderr(&o).contains("--before"), "{args:?}: {}", stderr(&o));
        assert!(stdout(&o).is_empty(), "{args:?}: {}", stdout(&o));
    }
    let o = run_in_empty(&["solve", "--before", "40", "--quantiles", "0.5"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("warning: --before, --quantiles have no effect without a distributed input"),
        "{e}"
    );
    let o = run_in_empty(&["solve", "--mu", "normal(0.2,0.03)", "--before", "40"]);
    assert!(!stderr(&o).contains("no effect"), "{}", stderr(&o));
}

/// Regression: `--quantiles 0.5,0.5` was accepted and the quantile printed twice, and so was
/// `--before 40,40`; a probability or a position given twice is refused naming its flag.
#[test]
fn duplicate_quantiles_and_before_positions_are_refused() {
    for (flag, list) in [("--quantiles", "0.5,0.1,0.5"), ("--before", "40,50,40")] {
        let o = run_in_empty(&["solve", "--mu", "normal(0.2,0.03)", flag, list]);
        assert_eq!(o.status.code(), Some(2), "{flag}: {}", stdout(&o));
        let e = stderr(&o);
        assert!(
            e.starts_with("jamchart: ") && e.contains(flag) && e.contains("twice"),
            "{e}"
        );
    }
}

/// Regression: `render -q` still printed its per-scene file lines and the gallery line
/// (quiet means only errors and warnings), and `--bless` of one picture said "1 pictures
/// blessed". Quiet prints nothing on success and one picture is one picture.
#[test]
fn render_quiet_is_quiet_and_one_picture_is_singular() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = ["render", "fig3", "--format", "svg", "--out", "q", "--bless"];
    let o = cli_util::jamchart(d, &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("(1 picture blessed)"), "{}", stdout(&o));
    let o = cli_util::jamchart(d, &[&args[..], &["-q"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), "");
    assert!(d.join("q/fig3.svg").is_file());
    let check = ["render", "fig3", "--format", "svg", "--out", "q", "--check"];
    let o = cli_util::jamchart(d, &check);
    assert_eq!(stdout(&o).trim_end(), "1 picture matches q/SHA256SUMS");
    let o = cli_util::jamchart(d, &[&check[..], &["-q"]].concat());
    assert_eq!((o.status.code(), stdout(&o)), (Some(0), String::new()));
}
