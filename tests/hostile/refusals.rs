//! The binary under hostile input, one regression test per class of defect:
//! sweeps that bypassed the model port, lost output reported as success, values accepted that
//! should be refused, and the rest as listed in each test's doc comment.

use std::path::Path;
use std::process::{Command, Output, Stdio};

use crate::common::cli as cli_util;
use cli_util::{jamchart, repo, stderr, stdout};

/// The rows of `dir/out/NAME.csv` whose first field is `layer`.
fn layer_rows(dir: &Path, name: &str, layer: &str) -> Vec<String> {
    let text = std::fs::read_to_string(dir.join("out").join(format!("{name}.csv"))).unwrap();
    text.lines()
        .filter(|l| l.starts_with(&format!("{layer},")))
        .map(str::to_string)
        .collect()
}

/// Regression ("sweeps bypass the model port"): `sweep mu=0.1:0.5:3
/// --start-angle 120` printed `statics,0.1,97.59493,11.70071` with exit 0 where `solve` says
/// `outside_model` (the palm lifts the disc above 90 deg), and `render fig7b --set
/// start_angle_deg=120` likewise: the statics and F -> infinity layers called the closed form
/// directly. They now go through the port: a sweep outside the model at every point is
/// refused with the reason, and a sweep across 90 deg leaves the rows above it empty.
#[test]
fn sweeps_go_through_the_model_ports_outside_rule() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = jamchart(
        d,
        &[
            "sweep",
            "mu=0.1:0.5:3",
            "--start-angle",
            "120",
            "--format",
            "svg",
        ],
    );
    assert_ne!(o.status.code(), Some(0), "stdout: {}", stdout(&o));
    assert!(stderr(&o).contains("above 90 deg"), "{}", stderr(&o));
    assert!(!d.join("out/sweep_mu.csv").exists());
    let fig7b = repo().join("charts");
    let o = jamchart(
        d,
        &[
            "render",
            "fig7b",
            "--scenes-dir",
            fig7b.to_str().unwrap(),
            "--set",
            "start_angle_deg=120",
            "--format",
            "svg",
        ],
    );
    assert_ne!(o.status.code(), Some(0), "stdout: {}", stdout(&o));
    assert!(stderr(&o).contains("above 90 deg"), "{}", stderr(&o));

    let o = jamchart(d, &["sweep", "start_angle_deg=60:120:4", "--format", "svg"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for layer in ["statics", "rigid"] {
        let rows = layer_rows(d, "sweep_start_angle_deg", layer);
        assert_eq!(rows.len(), 4, "{rows:?}");
        assert!(!rows[1].ends_with(",,"), "80 deg is answered: {rows:?}");
        assert_eq!(rows[2], format!("{layer},100,outside_model,,,"), "{rows:?}");
        assert_eq!(rows[3], format!("{layer},120,outside_model,,,"), "{rows:?}");
    }
}

/// Runs `jamchart ARGS` in `dir` through `sh -c` with `redirect` (e.g. `>&-`) on its stdout.
fn jamchart_redirected(dir: &Path, redirect: &str, args: &[&str]) -> Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("exec \"$0\" \"$@\" {redirect}"))
        .arg(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .env_remove("RAYON_NUM_THREADS")
        .output()
        .unwrap()
}

/// Regression ("lost output reported as success"): `table --format csv >
/// /dev/full` exited 0 with nothing written (an empty file on a full disk): the write's error
/// was dropped. A failed write is now an error with exit 2 and a message; a closed pipe (`|
/// head`) still is not. (A closed stdout, `>&-`, is reopened on /dev/null read-write by Rust's
/// runtime: it cannot be told from the /dev/null a script hands over, and both are answered.)
#[test]
fn a_failed_write_to_stdout_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (redirect, args, says) in [
        ("> /dev/full", &["table", "--format", "csv"][..], "space"),
        ("> /dev/full", &["solve"][..], "space"),
    ] {
        let o = jamchart_redirected(d, redirect, args);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?} {redirect}: {e}");
        assert!(e.starts_with("jamchart: ") && e.contains(says), "{e}");
        assert!(e.contains("standard output"), "{e}");
    }
    let o = jamchart_redirected(d, "| head -c 1 >/dev/null", &["table", "--format", "csv"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "");
}

/// A small valid `[chart]` for hand-made scene files.
const SWEEP_CHART: &str = "[chart]\nkind = \"sweep\"\nx_axis = { param = \"mu\", min = 0.1, \
                           max = 0.5, count = 3 }\npanels = [\"x_jam_mm\"]\nlayers = [\"statics\"]\n";

/// Asserts `o` was refused with exit 2 and a message naming `setting`, without a panic.
fn refused(o: &Output, setting: &str) {
    let e = stderr(o);
    assert_eq!(
        o.status.code(),
        Some(2),
        "stdout: {} stderr: {e}",
        stdout(o)
    );
    assert!(e.starts_with("jamchart: "), "{e}");
    assert!(e.contains(setting), "message should name {setting}: {e}");
    assert!(!e.contains("panicked"), "{e}");
}

/// Regression ("accepted when it should be refused"): `sweep mu=1e-400:0.5`
/// became 0 silently (the README says such numbers are refused), `mu=0.1:0.5:5:7` and
/// `:log:log` were accepted with the last one winning, and `--set title=`,
/// `dynamics.series.after_jam_s=1e300` and `chart.cases=[]` (which drew every case) rendered.
/// Each is now refused with exit 2, naming what was written, before anything is written.
#[test]
fn values_that_mean_nothing_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let charts = repo().join("charts");
    let charts = charts.to_str().unwrap();
    for (args, names) in [
        (&["sweep", "mu=1e-400:0.5"][..], "1e-400"),
        (&["sweep", "mu=0.1:0.5:5:7"][..], "count twice"),
        (&["sweep", "mu=0.1:0.5:log:log"][..], "scale twice"),
        (&["vlocator", "--load", "1e-400"][..], "1e-400"),
        (&["render", "fig7b", "--set", "title="][..], "title"),
        (&["render", "fig7b", "--set", "title=  "][..], "title"),
        (
            &[
                "render",
                "fig5",
                "--set",
                "dynamics.series.after_jam_s=1e300",
            ][..],
            "dynamics.series.after_jam_s",
        ),
        (
            &["render", "stability-matrix", "--set", "chart.cases=[]"][..],
            "chart.cases",
        ),
    ] {
        let mut args = args.to_vec();
        if args[0] == "render" {
            args.extend(["--scenes-dir", charts]);
        }
        if args[0] != "vlocator" {
            args.extend(["--out", "o", "--format", "svg"]);
        }
        refused(&jamchart(d, &args), names);
        assert!(!d.join("o").exists(), "{args:?} wrote output");
    }
}

/// Inputs that were accepted and then cost minutes or answered nothing:
/// `accuracy --max-steps 2147483648` ran for hours (DOPRI5 takes every step at a stiff
/// contact); a tolerance of 1e-320 (`accuracy --tolerances`, `solve --rtol`) cut the step to
/// 0 s and advised a softer contact, and a nonsmooth step of 1e-320 deg ran out its steps at
/// the start angle; `stability --cases barely_moves,barely_moves` gave the
/// same answers twice; a `sweep --name` with a newline or an escape wrote it into every list
/// of files. Each is refused at once, naming the setting.
#[test]
fn settings_that_cost_hours_or_mean_nothing_are_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (args, names) in [
        (
            &["accuracy", "--max-steps", "2147483648", "-q"][..],
            "--max-steps",
        ),
        (
            &["accuracy", "--tolerances", "1e-320", "-q"][..],
            "--tolerances",
        ),
        (
            &["accuracy", "--converged-rtol", "1e-14", "-q"][..],
            "--converged-rtol",
        ),
        (
            &["accuracy", "--min-norm-tolerances", "1e-20", "-q"][..],
            "--min-norm-tolerances",
        ),
        (
            &["solve", "--model", "dynamics", "--rtol", "1e-320"][..],
            "--rtol",
        ),
        (
            &["accuracy", "--nonsmooth-steps", "1e-320", "-q"][..],
            "--nonsmooth-steps",
        ),
        (
            &["accuracy", "--converged-step", "1e-320", "-q"][..],
            "--converged-step",
        ),
        (
            &["solve", "--model", "dynamics", "--nonsmooth-step", "1e-12"][..],
            "--nonsmooth-step",
        ),
        (
            &["stability", "--cases", "barely_moves,barely_moves", "-q"][..],
            "named twice",
        ),
        (
            &["sweep", "mu=0.1:0.5:5", "--name", "a\nb", "--out", "o"][..],
            "--name",
        ),
        (
            &["sweep", "mu=0.1:0.5:5", "--name", "a\u{1b}b", "--out", "o"][..],
            "--name",
        ),
    ] {
        let started = std::time::Instant::now();
        let o = jamchart(d, args);
        refused(&o, names);
        // A tolerance of 1e-20 was quoted as 0.00000000000000000001.
        assert!(!stderr(&o).contains("0.0000000"), "{}", stderr(&o));
        assert!(
            started.elapsed().as_secs() < 20,
            "{args:?} was not refused at once"
        );
        assert!(!d.join("o").exists(), "{args:?} wrote output");
    }
    // The tightest tolerance taken still answers.
    let o = jamchart(
        d,
        &[
            "solve",
            "--model",
            "dynamics",
            "--rtol",
            "1e-13",
            "--no-verify",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

/// Regression ("axis samples that overflow"): only an axis's ends were
/// checked, so `sweep mu=1e-320:1:5:log` wrote rows with a blank mu, `sweep
/// force_n=1e-300:1e300:41:log` 39 rows with no force, and a capacity scene with
/// load_angle_deg from -1e308 to 1e308 rows `30,,`: the span max/min or max - min overflowed.
/// Every sample is now finite or the axis is refused, naming it as written.
#[test]
fn every_axis_sample_is_a_number_or_the_axis_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for axis in [
        "mu=1e-320:1:5:log",
        "force_n=1e-300:1e300:41:log",
        "palm_offset_mm=-1e308:1e308:5",
    ] {
        let o = jamchart(d, &["sweep", axis, "--out", "o", "--format", "svg"]);
        refused(&o, axis);
        assert!(stderr(&o).contains("overflows"), "{}", stderr(&o));
        assert!(!d.join("o").exists());
    }
    let charts = repo().join("charts");
    let o = jamchart(
        d,
        &[
            "render",
            "vlocator-capacity",
            "--scenes-dir",
            charts.to_str().unwrap(),
            "--set",
            "chart.y_axis={param=\"load_angle_deg\",min=-1e308,max=1e308,count=5}",
            "--out",
            "o",
            "--format",
            "svg",
        ],
    );
    refused(&o, "chart.y_axis");
    assert!(stderr(&o).contains("-1e308..1e308"), "{}", stderr(&o));
    // A wide range that fits is still drawn, each row with its number.
    let o = jamchart(
        d,
        &["sweep", "force_n=1e-150:1e150:41:log", "--format", "svg"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let rows = layer_rows(d, "sweep_force_n", "statics");
    assert_eq!(rows.len(), 41);
    assert!(rows.iter().all(|r| !r.starts_with("statics,,")), "{rows:?}");
}

/// Regression ("messages that name the wrong flag or garble the value"):
/// `sweep radius_mm=0:10` named the flag --radius, which the user had not given, and `solve
/// --rtol 1e300` quoted the value as 301 digits cut to 60. The axis is now refused as written
/// and long numbers read in exponent form.
#[test]
fn messages_name_the_setting_as_written_and_numbers_readably() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = jamchart(d, &["sweep", "radius_mm=0:10", "--out", "o"]);
    refused(&o, "radius_mm=0:10");
    assert!(!stderr(&o).contains("--radius"), "{}", stderr(&o));
    let o = jamchart(d, &["solve", "--rtol", "1e300"]);
    refused(&o, "--rtol");
    assert!(stderr(&o).contains("= 1e300 "), "{}", stderr(&o));
    assert!(!stderr(&o).contains("000000"), "{}", stderr(&o));
}

/// Regression: `vlocator --mass 1e-300 --gravity 1e-300` printed
/// `P_max = 0.000 N = NaN W` with exit 0 (the weight m g underflowed to 0 and capacities are per
/// weight), and a load and weight that overflow together were refused by the solver naming its
/// internal key `load.force_n`. Both are refused up front, naming the flags given.
#[test]
fn a_weight_out_of_range_is_refused_never_printed_as_nan() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for args in [
        &["vlocator", "--mass", "1e-300", "--gravity", "1e-300"][..],
        &[
            "vlocator",
            "--mass",
            "1e300",
            "--gravity",
            "1e300",
            "--format",
            "json",
        ][..],
    ] {
        let o = jamchart(d, args);
        refused(&o, "--mass and --gravity");
        assert!(!stdout(&o).contains("NaN"), "{}", stdout(&o));
    }
    let o = jamchart(
        d,
        &[
            "vlocator",
            "--mass",
            "1.5e307",
            "--gravity",
            "10",
            "--load",
            "1.7e308",
            "--load-angle",
            "-90",
        ],
    );
    refused(&o, "--load, --mass and --gravity");
    assert!(!stderr(&o).contains("load.force_n"), "{}", stderr(&o));
}

/// Runs `jamchart ARGS` in `dir`, killed after 20 s (a hang would otherwise hang the suite;
/// the time is a guard, not a measurement).
fn jamchart_guarded(dir: &Path, args: &[&str]) -> Output {
    jamchart_guarded_env(dir, &[], args)
}

/// [`jamchart_guarded`] with the environment variables `env` set.
fn jamchart_guarded_env(dir: &Path, env: &[(&str, &str)], args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .envs(env.iter().copied())
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed().as_secs() > 20 {
            child.kill().unwrap();
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// Regression ("hangs"): a scene file that is a FIFO with no writer blocked
/// forever, and a scene whose `base` is /dev/zero was read until memory ran out. Settings and
/// scene files are now opened without blocking, refused unless regular, and read no further
/// than 4 MiB.
#[test]
fn scene_files_must_be_regular_and_small() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let sc = d.join("scenes");
    std::fs::create_dir_all(&sc).unwrap();
    let made = Command::new("mkfifo")
        .arg(sc.join("fifo.toml"))
        .status()
        .unwrap();
    assert!(made.success());
    let chart = SWEEP_CHART;
    std::fs::write(
        sc.join("zero.toml"),
        format!("title = \"t\"\nbase = \"/dev/zero\"\n{chart}"),
    )
    .unwrap();
    let big = format!("title = \"t\"\n{chart}# {}\n", "x".repeat(5 << 20));
    std::fs::write(sc.join("big.toml"), big).unwrap();
    for (name, says) in [
        ("fifo", "not a regular file"),
        ("zero", "not a regular file"),
        ("big", "larger than 4 MiB"),
    ] {
        let o = jamchart_guarded(
            d,
            &["render", name, "--scenes-dir", "scenes", "--format", "svg"],
        );
        refused(&o, says);
    }
    let o = jamchart_guarded(d, &["solve", "--config", "scenes/fifo.toml"]);
    refused(&o, "scenes/fifo.toml");
}

/// Regression ("leftovers"): under a file-size limit (`ulimit -f`) SIGXFSZ
/// killed `render fig3` and left `.fig3.csv.<pid>.<n>.tmp` files in the output folder. The
/// signal is now ignored, the write fails with EFBIG like a full disk, and the run exits 2
/// with the message, its temporaries and the folder it created removed.
#[test]
fn a_file_size_limit_fails_cleanly_without_leftovers() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let o = jamchart_redirected(d, "", &["render", "fig3", "--out", "o", "--format", "svg"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = Command::new("sh")
        .arg("-c")
        .arg("ulimit -f 100 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_jamchart"))
        .args(["render", "fig3", "--out", "capped", "--format", "svg"])
        .current_dir(d)
        .output()
        .unwrap();
    refused(&o, "File too large");
    let left: Vec<String> = std::fs::read_dir(d.join("capped"))
        .map(|r| {
            r.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    assert!(left.is_empty(), "left behind: {left:?}");
}

/// Regression ("aborts"): a 10 MB scene title took 3 GiB to lay out and
/// aborted under a 4 GiB limit, and `--set chart.x_axis.x.x.x...` (10,000 levels) overflowed
/// the stack. A title has at most 200 characters and a `--set` key at most 8 parts; both are
/// refused with exit 2 before anything is computed.
#[test]
fn huge_titles_and_deep_keys_are_refused_not_aborted() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let sc = d.join("scenes");
    std::fs::create_dir_all(&sc).unwrap();
    let chart = SWEEP_CHART;
    let title = "x".repeat(1 << 20);
    std::fs::write(
        sc.join("long.toml"),
        format!("title = \"{title}\"\n{chart}"),
    )
    .unwrap();
    let o = jamchart_guarded(
        d,
        &["render", "long", "--scenes-dir", "scenes", "--out", "o"],
    );
    refused(&o, "title");
    assert!(stderr(&o).len() < 400, "{}", stderr(&o).len());
    let key = format!("chart.x_axis.{}x=1", "x.".repeat(10_000));
    let o = jamchart_guarded(
        d,
        &["render", "long", "--scenes-dir", "scenes", "--set", &key],
    );
    refused(&o, "at most 8 dotted parts");
    assert!(!d.join("o").exists());
}

/// Regression ("paths checked first"): `stability --out-dir` on a dangling
/// symbolic link computed the whole matrix, then failed creating the folder (and a read-only
/// folder likewise, for a user other than root). The output paths are now refused before
/// anything is computed: the run says nothing about the matrix.
#[test]
fn output_folders_are_checked_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::os::unix::fs::symlink(d.join("nowhere/x"), d.join("dangling")).unwrap();
    let o = jamchart(
        d,
        &[
            "stability",
            "--cases",
            "barely_moves",
            "--out-dir",
            "dangling",
        ],
    );
    refused(&o, "dangling symbolic link");
    assert!(
        !stderr(&o).contains("stability matrix of"),
        "{}",
        stderr(&o)
    );
    assert!(!d.join("nowhere").exists());
}

/// Regression: `stability --cases barely_moves --mu 0` was refused naming
/// the flag --force, which the user never gave: the case derives F = 1.05 m g sin(atan mu_g)
/// from the scene, 0 for mu = 0. The refusal now names the case and its rule.
#[test]
fn a_derived_case_value_names_the_case_not_a_flag() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &["stability", "--cases", "barely_moves", "--mu", "0"],
    );
    refused(&o, "case barely_moves");
    assert!(!stderr(&o).contains("--force"), "{}", stderr(&o));
}

/// Regression: `accuracy --penetrations 1e-300` named `--stiffness`, a flag
/// never given: the penetration's stiffness F / delta^e overflowed. It names the penetration.
#[test]
fn a_penetration_whose_stiffness_overflows_names_the_penetration() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &["accuracy", "--penetrations", "1e-300", "--map-cells", "0"],
    );
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.contains("--penetrations") && err.contains("1e-300"),
        "{err}"
    );
    assert!(!err.contains("--stiffness"), "{err}");
}

/// Regression: the `vlocator_optimum` chart had no work limit: 100,000
/// directions ran past 60 s (each point is a search over the included angle). It is refused at
/// once, naming the counts.
#[test]
fn a_v_block_optimum_chart_with_too_much_work_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &[
            "render",
            "vlocator-optimum",
            "--set",
            "chart.direction_axis.count=100000",
        ],
    );
    refused(&o, "chart.direction_axis.count");
    assert!(
        stderr(&o).contains("at most 100000 optima"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.path().join("out").exists());
}

/// Regression ("aborts"): `--set` with a key of 10,000 dotted parts was
/// refused, but clap quoted the whole 20,001-byte value in the message, twice. The value is
/// now cut to 60 characters and its length, like every other quoted value.
#[test]
fn a_huge_invalid_flag_value_is_quoted_cut() {
    let dir = tempfile::tempdir().unwrap();
    let key = format!("{}a=1", "a.".repeat(10_000));
    let o = jamchart_guarded(dir.path(), &["render", "fig3", "--set", &key]);
    refused(&o, "at most 8 dotted parts");
    assert!(stderr(&o).contains("bytes in all"), "{}", stderr(&o));
    assert!(stderr(&o).len() < 400, "{} bytes", stderr(&o).len());
}

/// Regression ("aborts"): when no thread could be started (`ulimit -u` as
/// a normal user, or stacks that do not fit an address-space limit) rayon's global pool
/// panicked or aborted on allocation: under `ulimit -v 409600` with `RAYON_NUM_THREADS=250`
/// (250 stacks of 2 MiB) `render fig3` died with "memory allocation of 41 bytes failed". It
/// now warns and runs on one thread, and its files are byte for byte those of a threaded run.
#[test]
fn a_system_that_will_not_start_threads_runs_on_one_thread() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let args = ["render", "fig3", "--format", "svg", "--out"];
    let o = jamchart_redirected(d, "", &[&args[..], &["threaded"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 409600 && exec \"$0\" \"$@\"")
        .arg(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .arg("one")
        .env("RAYON_NUM_THREADS", "250")
        // One malloc arena: the threads that did start would otherwise each reserve a 64 MiB
        // arena of the same 400 MiB, leaving the one-thread run a share that varies from run to
        // run (it once failed an allocation in a full suite).
        .env("MALLOC_ARENA_MAX", "1")
        .current_dir(d)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("could not start 250 threads")
            && stderr(&o).contains("running on one thread"),
        "{}",
        stderr(&o)
    );
    for file in ["fig3.svg", "fig3.csv", "fig3.json"] {
        let read = |folder: &str| std::fs::read(d.join(folder).join(file)).unwrap();
        assert!(read("one") == read("threaded"), "{file} differs");
    }
}

/// Regression: `RAYON_NUM_THREADS=100000000` started rayon's maximum of
/// 65,535 threads and `render fig3` had not begun after 60 s. A count above
/// `limits::MAX_THREADS` (1024) is refused at once naming the variable.
#[test]
fn a_thread_count_beyond_any_machine_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let env = [("RAYON_NUM_THREADS", "100000000")];
    let o = jamchart_guarded_env(dir.path(), &env, &["render", "fig3", "--format", "svg"]);
    refused(&o, "RAYON_NUM_THREADS = 100000000");
    assert!(!dir.path().join("out").exists());
}
