//! `jamchart design` run as a user would: the 25 mm shaft's inverse questions in one command,
//! checked against the closed form, and bad input.

use crate::common::cli as cli_util;
use cli_util::{SHAFT, jamchart, json, stderr};

/// `design --mu 0.12:0.3 --x-target X --format json` on the 25 mm shaft.
fn shaft_design(x_target: &'static str) -> Vec<&'static str> {
    let mut args = vec![
        "design",
        "--mu",
        "0.12:0.3",
        "--x-target",
        x_target,
        "--format",
        "json",
    ];
    args.extend(SHAFT);
    args
}

/// The least push over mu 0.12 to 0.3 puts the jam exactly on the 35 mm target at the top
/// friction: F = m g sin(alpha) / sin(theta_t - 2 alpha), alpha = atan 0.3,
/// theta_t = 2 atan(r / x_t); the simulation's check is printed beside it.
#[test]
fn design_least_push_is_the_closed_form_at_the_top_friction() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(&jamchart(dir.path(), &shaft_design("35")));
    let a = 0.3_f64.atan();
    let theta_t = 2.0 * (12.5_f64 / 35.0).atan();
    let want = 0.4 * 9.806 * a.sin() / (theta_t - 2.0 * a).sin();
    let got = v["design"]["least_push"]["force_n"].as_f64().unwrap();
    assert!((got - want).abs() < 1e-9 * want, "{got} vs {want}");
    let c = &v["check_least_push"];
    assert!((c["x_jam_closed_form_mm"].as_f64().unwrap() - 35.0).abs() < 1e-9);
    assert!(c["x_jam_nonsmooth_mm"].as_f64().is_some(), "{c}");
    // The latest jam (mu 0.12) lies past the 80 mm palm: the length needed says how far.
    let l = v["design"]["palm_length_keeping_jams_on_mm"]
        .as_f64()
        .unwrap();
    assert!(l > 80.0, "{l}");
    assert!(
        v["check_latest_jam"]["x_jam_nonsmooth_mm"]
            .as_f64()
            .is_some()
    );
}

/// The palm length from the closed form (99.261 mm at mu 0.12) is where a slowly pushed disc
/// jams; at the drive's speed the simulated disc coasts on to 112.6 mm, so a palm sized by the
/// closed form would lose it. `design` once printed both numbers without a word; it now says the
/// palm must reach past the coast, in the text and in the JSON (`coasts_to_mm`).
#[test]
fn design_says_when_the_disc_coasts_past_the_palm_length_it_gives() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(&jamchart(dir.path(), &shaft_design("35")));
    let l = v["design"]["palm_length_keeping_jams_on_mm"]
        .as_f64()
        .unwrap();
    let coast = v["check_latest_jam"]["coasts_to_mm"].as_f64().unwrap();
    assert!(coast > l * 1.05, "{coast} vs {l}");
    let mut args = shaft_design("35");
    args.truncate(args.len() - SHAFT.len() - 2);
    args.extend(SHAFT);
    let out = cli_util::stdout(&jamchart(dir.path(), &args));
    assert!(
        out.contains("coasts past the quasi-static jam to 112.6"),
        "{out}"
    );
}

/// A target past the rigid limit r / mu_hi = 41.7 mm is an answer (no push reaches it), not an
/// error; a target inside the disc's start, a negative or a reversed range exits 2 naming the flag.
#[test]
fn design_refuses_bad_input_and_answers_impossible_targets() {
    let dir = tempfile::tempdir().unwrap();
    let v = json(&jamchart(dir.path(), &shaft_design("60")));
    assert_eq!(v["design"]["least_push"]["status"], "wedge_locks_first");
    for (bad, flag) in [
        (vec!["--x-target", "5"], "--x-target"),
        (vec!["--x-target", "-3"], "--x-target"),
        (vec!["--x-target", "nan"], "--x-target"),
        (vec!["--x-target", "40", "--mu", "0.3:0.1"], "--mu"),
    ] {
        let mut all = vec!["design"];
        all.extend(SHAFT);
        all.extend(bad.iter().copied());
        let out = jamchart(dir.path(), &all);
        assert_eq!(out.status.code(), Some(2), "{all:?}");
        let err = stderr(&out);
        assert!(
            err.starts_with("jamchart: ") && err.contains(flag),
            "{all:?}: {err}"
        );
    }
}

/// `design ARGS --format json` in a fresh folder: its exit code and its JSON.
fn design_json(args: &[&str]) -> serde_json::Value {
    let dir = tempfile::tempdir().unwrap();
    let mut all = vec!["design", "--format", "json"];
    all.extend(args);
    json(&jamchart(dir.path(), &all))
}

/// Regression: a target behind the disc's start was answered with numbers that meant nothing:
/// `design --x-target 11 --start-angle 80 --mu 0.3:0.4` gave a least push of 5.557 N and
/// mu_ground up to 1.7535, but the disc starts at x(80 deg) = 11.918 mm, already past the
/// target. Now the answer says so, whatever the push and the friction.
#[test]
fn design_says_when_the_disc_starts_past_the_target() {
    let v = design_json(&["--x-target", "11", "--start-angle", "80", "--mu", "0.3:0.4"]);
    let d = &v["design"];
    assert_eq!(d["carry"], "starts_past", "{d}");
    assert!(
        (d["x_start_mm"].as_f64().unwrap() - 11.918).abs() < 5e-4,
        "{d}"
    );
    assert!(
        d.get("least_push").is_none() && d.get("mu_ground_max").is_none(),
        "{d}"
    );
    let dir = tempfile::tempdir().unwrap();
    let text = cli_util::stdout(&jamchart(
        dir.path(),
        &[
            "design",
            "--x-target",
            "11",
            "--start-angle",
            "80",
            "--mu",
            "0.3:0.4",
        ],
    ));
    assert!(
        text.contains("the disc starts at x = 11.918 mm, at or past the target"),
        "{text}"
    );
    assert!(!text.contains("least push that carries"), "{text}");
}

/// Regression: a least push of 0 N was refused as invalid input. Without weight or ground
/// friction (`--mu 0`, `--mass 0`, `--gravity 0`, `--mu-ground 0`) the jam angle does not
/// depend on the push, and `design --x-target 40` exited 2 with "invalid force_n = 0 (flag
/// --force)" from the simulation of that push. Any push reaches a target the wedge allows: an
/// answer, exit 0; where the wedge locks first (mu 0.4 on the palm) that is the answer.
#[test]
fn design_answers_a_least_push_of_zero() {
    for (args, status) in [
        (vec!["--mu", "0"], "any_push_that_moves"),
        (vec!["--mu-ground", "0"], "any_push_that_moves"),
        (vec!["--mu", "0.1", "--mass", "0"], "any_push_that_moves"),
        (vec!["--mu", "0.1", "--gravity", "0"], "any_push_that_moves"),
        (vec!["--mass", "0"], "wedge_locks_first"),
    ] {
        let mut all = vec!["--x-target", "40"];
        all.extend(args.iter().copied());
        let v = design_json(&all);
        let push = &v["design"]["least_push"];
        assert_eq!(push["status"], status, "{all:?}: {push}");
        if status == "any_push_that_moves" {
            assert_eq!(push["least_moving_n"].as_f64(), Some(0.0), "{all:?}");
        }
    }
}

/// Regression: `design` answered scenes `solve` calls outside_model: a push starting at 100 deg
/// got a least push and palm lengths from the closed form, which keeps the disc on the ground
/// the palm would lift it from. Now it answers outside_model with the port's reason, exit 0.
#[test]
fn design_answers_outside_the_model_as_solve_does() {
    let v = design_json(&["--x-target", "40", "--start-angle", "100"]);
    assert_eq!(v["status"], "outside_model", "{v}");
    assert_eq!(v["reason"], "palm_lifts_disc", "{v}");
}
