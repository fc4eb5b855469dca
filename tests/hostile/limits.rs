//! The binary under hostile input, one regression test per class of defect: resource
//! limits, repeated flags, validation before computation, empty scene folders, charts whose
//! model failed, and a series that ends before the time asked for.

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::common::cli as cli_util;
use cli_util::{jam_map, jamchart, jamchart_capped, jamchart_under, json, render, scene, stderr};

/// Regression ("scene limits that pass validation exhaust memory"): a jam map at
/// 8192 x 8192 (the old 2^26-cell limit) took 10 GB and a sweep of 16777216 points 3.7 GB;
/// under a 4 GiB address-space cap both died by SIGABRT. Every grid, sweep and series is now
/// refused by its estimate, with the estimate and the limit in the message, before anything
/// is allocated, and a large scene within the limits runs under the same cap.
#[test]
fn scene_limits_are_found_by_estimate_not_by_allocation_failure() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    scene(d, "map", &jam_map(8192));
    scene(
        d,
        "contour",
        "[chart]\nkind = \"contour_map\"\nx_axis = { param = \"force_n\", min = 50.0, max = \
         1e4, count = 16777216 }\ny_axis = { param = \"radius_mm\", min = 10.0, max = 30.0, \
         count = 4 }\nx_jam_levels_mm = [25.0, 30.0]\n",
    );
    scene(
        d,
        "sweep",
        "[chart]\nkind = \"sweep\"\nx_axis = { param = \"force_n\", min = 50.0, max = 1e4, \
         count = 16777216 }\npanels = [\"x_jam_mm\"]\nlayers = [\"statics\"]\n",
    );
    scene(
        d,
        "series",
        "[dynamics.drive]\nomega_deg_s = 1e-6\n[chart]\nkind = \"time_series\"\nseries_dt_s = 1e-5\n",
    );
    for (name, key) in [
        ("map", "chart.x_axis.count * chart.y_axis.count"),
        ("contour", "chart.x_axis.count * chart.y_axis.count"),
        ("sweep", "chart.x_axis.count"),
        ("series", "series_dt_s"),
    ] {
        let out = render(d, name);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains("would take about")
                && err.contains("over the limit of")
                && err.contains(key),
            "{name}: {err}"
        );
        assert!(!d.join("o").exists(), "{name}: nothing is written");
    }
    let out = jamchart_capped(
        d,
        &[
            "solve", "--model", "dynamics", "--omega", "1e-6", "--series", "s.csv",
        ],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("rows of the time series would take about"),
        "{}",
        stderr(&out)
    );
    // Within the limits, under the same cap: 1500 x 1500 cells, about 27 MB at 12 B/cell.
    scene(d, "within", &jam_map(1500));
    let out = render(d, "within");
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
}

/// Regression ("aborts at sizes the tool accepts"): under a 512 MiB
/// address-space cap `sweep mu=0.1:0.5:1600000` (2.2 GB peak, estimated at 640 MB from 400 B a
/// point) and a 1958 x 1958 map died by SIGABRT. The estimates are now measured (1200 B a sweep
/// point, `crate::limits`) and the memory limit is half the address-space cap when that is
/// below 1 GiB, so both are refused with exit 2, naming the estimate, the limit, where the
/// limit comes from and the count as the user wrote it; nothing is written. The largest sweep
/// the cap allows still runs under it.
#[test]
fn memory_check_follows_the_address_space_cap() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cap_kib = 512 << 10;
    for args in [
        &["sweep", "mu=0.1:0.5:1600000", "--out", "o"][..],
        &[
            "sweep",
            "mu=0.1:0.5:1958",
            "force_n=10:1000:1958",
            "--out",
            "o",
        ],
    ] {
        let out = jamchart_under(d, cap_kib, args);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.starts_with("jamchart: the memory of")
                && err.contains("over the limit of 256 MiB (half the address-space limit")
                && err.contains("COUNT of mu=MIN:MAX:COUNT"),
            "{args:?}: {err}"
        );
        assert!(!d.join("o").exists(), "{args:?}: nothing is written");
    }
    // 150000 points: 214.6 MiB estimated, about 180 MB measured.
    let out = jamchart_under(d, cap_kib, &["sweep", "mu=0.1:0.5:150000", "--out", "o"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(d.join("o/sweep_mu.csv").is_file());
}

/// Regression ("every count has a sane documented maximum"): `accuracy --runs
/// 18446744073709551615` panicked (capacity overflow), `--runs 1000000000` reserved 8 GB.
#[test]
fn every_count_has_a_maximum() {
    let dir = tempfile::tempdir().unwrap();
    let many = vec!["1e-3"; 65].join(",");
    let cases: [(&[&str], &str); 5] = [
        (&["accuracy", "--runs", "18446744073709551615"], "1 to 1000"),
        (&["accuracy", "--runs", "1000000000"], "1 to 1000"),
        (&["accuracy", "--runs", "0"], "1 to 1000"),
        (&["accuracy", "--tolerances", &many], "at most 64"),
        (&["accuracy", "--min-norm-tolerances", &many], "at most 64"),
    ];
    for (args, says) in cases {
        let out = jamchart_capped(dir.path(), args);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.starts_with("jamchart: ") && err.contains(says),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
    let levels: Vec<String> = (0..65)
        .map(|i| format!("{:.1}", 25.0 + 0.5 * i as f64))
        .collect();
    let levels = levels.join(", ");
    scene(
        dir.path(),
        "levels",
        &format!(
            "[chart]\nkind = \"contour_map\"\nx_axis = {{ param = \"force_n\", min = 50.0, \
             max = 1e4, count = 4 }}\ny_axis = {{ param = \"radius_mm\", min = 10.0, max = \
             30.0, count = 4 }}\nx_jam_levels_mm = [{levels}]\n"
        ),
    );
    let out = render(dir.path(), "levels");
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("at most 64 levels"),
        "{}",
        stderr(&out)
    );
}

/// Regression: `accuracy --tolerances 1e-3 --tolerances 1e-4` was accepted while
/// every other repeated flag is refused.
#[test]
fn repeated_list_flags_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    for flag in ["--tolerances", "--min-norm-tolerances"] {
        let out = jamchart(dir.path(), &["accuracy", flag, "1e-3", flag, "1e-4"]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{flag}: {err}");
        assert!(
            err.contains("cannot be used multiple times"),
            "{flag}: {err}"
        );
    }
}

/// Regression: `accuracy --min-norm-tolerances abc` was refused only after the
/// whole study had run. With a study of minutes (1000 runs per point), the refusal must come
/// at once: a run still going after 60 s has computed before validating.
#[test]
fn everything_is_validated_before_computing() {
    let dir = tempfile::tempdir().unwrap();
    for bad in [
        ["--min-norm-tolerances", "abc"],
        ["--min-norm-tolerances", "2"],
        ["--out-dir", "/dev/full"],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_jamchart"))
            .args(["accuracy", "--runs", "1000", bad[0], bad[1]])
            .current_dir(dir.path())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let t0 = Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break s;
            }
            if t0.elapsed() > Duration::from_secs(60) {
                child.kill().unwrap();
                child.wait().unwrap();
                panic!("{bad:?}: still computing after 60 s instead of refusing the flag");
            }
            std::thread::sleep(Duration::from_millis(50));
        };
        let out = child.wait_with_output().unwrap();
        assert_eq!(status.code(), Some(2), "{bad:?}: {}", stderr(&out));
    }
}

/// Regression: `render --scenes-dir EMPTY` exited 0 and did nothing.
#[test]
fn render_of_an_empty_scenes_dir_fails_saying_so() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("empty")).unwrap();
    std::fs::write(dir.path().join("empty/notes.txt"), "not a scene").unwrap();
    let out = jamchart(
        dir.path(),
        &["render", "--scenes-dir", "empty", "--out", "o"],
    );
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("no scene files") && err.contains("empty"),
        "{err}"
    );
    assert!(!dir.path().join("o").exists());
}

/// Regression: a fig5 scene whose simulation fails (`[dynamics]
/// stiffness_n_per_mm_e = 1e300`) exited 0 with empty plots. The render now fails naming the
/// scene and the reason, and writes nothing (not even the other scenes' files).
#[test]
fn a_chart_whose_model_failed_fails_the_render_naming_scene_and_reason() {
    let broken = format!("{STIFF}[chart]\nkind = \"time_series\"\n");
    let fine = "[chart]\nkind = \"sweep\"\nx_axis = { param = \"force_n\", min = 50.0, max = 1e4, \
                count = 5 }\npanels = [\"x_jam_mm\"]\nlayers = [\"statics\"]\n";
    render_fails_saying(
        &[("broken", &broken), ("fine", fine)],
        &["scene broken", "integrator gave up"],
    );
}

/// A contact so stiff that every simulation gives up at t = 0.
const STIFF: &str = "[dynamics.contact]\nstiffness_n_per_mm_e = 1e300\n";

/// Regression ("a chart whose model failed", in a sweep): a fig6-like sweep whose
/// simulation layer failed at every point (`[dynamics] stiffness_n_per_mm_e = 1e300`: the
/// integrator gives up at t = 0) exited 0 and drew the layer as nothing. The render now fails
/// naming the scene, the model and the reason, and writes nothing.
#[test]
fn a_sweep_layer_whose_model_failed_at_every_point_fails_the_render() {
    let broken = format!(
        "{STIFF}[chart]\nkind = \"sweep\"\nx_axis = {{ param = \"mu\", min = 0.15, max = 0.45, \
         count = 31 }}\npanels = [\"x_jam_mm\"]\nlayers = [\"statics\", \"simulation_motion\"]\n"
    );
    let said = [
        "scene broken",
        "simulation (motion drive) failed",
        "integrator gave up",
    ];
    render_fails_saying(&[("broken", &broken)], &said);
}

/// Renders `scenes` (name, body) into a new folder: exit 2, every one of `said` in the
/// message, nothing written.
fn render_fails_saying(scenes: &[(&str, &str)], said: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, body) in scenes {
        scene(d, name, body);
    }
    let out = jamchart(d, &["render", "--scenes-dir", "scenes", "--out", "o"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(said.iter().all(|s| err.contains(s)), "{err}");
    assert!(!d.join("o").exists(), "nothing written: {err}");
}

/// Regression: `--after-jam 100 --series` stopped silently when the palm closed.
/// The text and the JSON say where the series ends and why.
#[test]
fn a_series_says_where_and_why_it_stopped() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "solve",
        "--model",
        "dynamics",
        "--no-verify",
        "--after-jam",
        "100",
        "--series",
        "s.csv",
    ];
    let out = jamchart(dir.path(), &args);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("the palm closed (theta = 0)") && text.contains("instead of the 100 s"),
        "{text}"
    );
    let mut args = args.to_vec();
    args.extend(["--format", "json"]);
    let v = json(&jamchart(dir.path(), &args));
    let r = &v["results"][0];
    let rows = std::fs::read_to_string(dir.path().join("s.csv"))
        .unwrap()
        .lines()
        .count()
        - 1;
    assert_eq!(r["series_rows"].as_u64(), Some(rows as u64));
    assert!(
        r["series_end"].as_str().unwrap().contains("palm closed"),
        "{r}"
    );
}
