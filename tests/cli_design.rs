//! `jamchart design` run as a user would: the issue-19 shaft's inverse questions in one command,
//! checked against the closed form, and bad input.

#[path = "common/cli.rs"]
mod cli_util;
use cli_util::{SHAFT, jamchart, json, stderr};

/// `design --mu 0.12:0.3 --x-target X --format json` on the shaft.
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
    let l = v["design"]["palm_length_needed_mm"].as_f64().unwrap();
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
    let l = v["design"]["palm_length_needed_mm"].as_f64().unwrap();
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
