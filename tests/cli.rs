//! The real binary: exit codes, messages, JSON keys, config files.

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

fn jamchart(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir)
        .env_remove("RUST_BACKTRACE")
        .output()
        .expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn repo() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn json(o: &Output) -> Value {
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(o));
    serde_json::from_slice(&o.stdout).expect("stdout is JSON")
}

#[test]
fn solve_reads_off_the_papers_example() {
    let o = jamchart(repo(), &["solve", "--mu", "0.4"]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    assert!(out.contains("theta_jam = 44.646 deg"), "{out}");
    assert!(out.contains("x_jam     = 24.355 mm"), "{out}");
    assert!(
        out.contains("x = 25.000 mm"),
        "the F -> inf limit r/mu: {out}"
    );
}

#[test]
fn solve_json_has_the_agreed_keys() {
    let v = json(&jamchart(
        repo(),
        &["solve", "--mu", "0.4", "--format", "json"],
    ));
    let inputs = v["inputs"].as_object().unwrap();
    for key in [
        "mu_ground",
        "mu_palm",
        "radius_mm",
        "mass_kg",
        "force_n",
        "gravity_m_s2",
        "start_angle_deg",
        "palm_length_mm",
    ] {
        assert!(inputs[key].is_number(), "inputs.{key}");
    }
    let r = &v["results"][0];
    assert_eq!(r["model"], "statics");
    assert_eq!(r["status"], "jams");
    assert!((r["theta_jam_deg"].as_f64().unwrap() - 44.646).abs() < 1e-3);
    assert!((r["x_jam_mm"].as_f64().unwrap() - 24.355).abs() < 1e-3);
    assert!(r["elapsed_s"].as_f64().unwrap() >= 0.0);
}

#[test]
fn jam_outside_reach_gives_null_numbers() {
    let v = json(&jamchart(
        repo(),
        &["solve", "--mu", "0.01", "--format", "json"],
    ));
    assert_eq!(v["results"][0]["status"], "beyond_reach");
    assert!(v["results"][0]["theta_jam_deg"].is_null());
    assert!(v["results"][0]["x_jam_mm"].is_null());
}

#[test]
fn flags_override_the_config_file_and_mu_sides_override_mu() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("p.toml"),
        "[scene]\nradius_mm = 20.0\nforce_n = 50.0\n",
    )
    .unwrap();
    let v = json(&jamchart(
        dir.path(),
        &[
            "solve",
            "--config",
            "p.toml",
            "--force",
            "300",
            "--mu",
            "0.3",
            "--mu-palm",
            "0.5",
            "--format",
            "json",
        ],
    ));
    let i = &v["inputs"];
    assert_eq!(i["radius_mm"].as_f64(), Some(20.0));
    assert_eq!(i["force_n"].as_f64(), Some(300.0));
    assert_eq!(i["mu_ground"].as_f64(), Some(0.3));
    assert_eq!(i["mu_palm"].as_f64(), Some(0.5));
}

#[test]
fn paper_toml_equals_the_defaults() {
    let strip = |mut v: Value| {
        v["results"][0]["elapsed_s"] = Value::Null;
        v
    };
    let defaults = strip(json(&jamchart(repo(), &["solve", "--format", "json"])));
    let paper = strip(json(&jamchart(
        repo(),
        &["solve", "--config", "config/paper.toml", "--format", "json"],
    )));
    assert_eq!(defaults, paper);
}

/// Every bad input: exit 2, one line `jamchart: ...` naming the flag or key and the value,
/// no panic, nothing on stdout.
#[test]
fn bad_input_is_refused_with_one_line_naming_it() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("typo.toml"),
        "[scene]\nmu_ground = 0.3\nradus_mm = 4\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("bad.toml"), "[scene]\nforce_n = -3.0\n").unwrap();
    let cases: &[(&[&str], &[&str])] = &[
        (&["--radius", "-1"], &["radius_mm", "-1", "--radius"]),
        (&["--radius", "0"], &["radius_mm", "0", "--radius"]),
        (&["--mass", "-2"], &["mass_kg", "-2", "--mass"]),
        (&["--mu", "-0.1"], &["mu_ground", "-0.1"]),
        (&["--mu-palm", "-3"], &["mu_palm", "-3", "--mu-palm"]),
        (&["--radius", "nan"], &["radius_mm", "NaN"]),
        (&["--force", "inf"], &["force_n", "inf", "--force"]),
        (&["--force", "0"], &["force_n", "0"]),
        (
            &["--gravity", "-9.8"],
            &["gravity_m_s2", "-9.8", "--gravity"],
        ),
        (
            &["--start-angle", "0"],
            &["start_angle_deg", "0", "--start-angle"],
        ),
        (&["--start-angle", "180"], &["start_angle_deg", "180"]),
        (&["--start-angle", "-30"], &["start_angle_deg", "-30"]),
        (
            &["--palm-length", "0"],
            &["palm_length_mm", "0", "--palm-length"],
        ),
        (&["--radius", "ten"], &["--radius", "ten"]),
        (&["--frobnicate"], &["--frobnicate"]),
        (&["--config", "typo.toml"], &["typo.toml:3:1", "radus_mm"]),
        (&["--config", "bad.toml"], &["force_n", "-3"]),
        (&["--config", "missing.toml"], &["missing.toml"]),
    ];
    for (args, needles) in cases {
        let mut all = vec!["solve"];
        all.extend_from_slice(args);
        let o = jamchart(dir.path(), &all);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(o.stdout.is_empty(), "{args:?} printed to stdout");
        assert!(err.starts_with("jamchart: "), "{args:?}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        for n in *needles {
            assert!(err.contains(n), "{args:?}: {err:?} lacks {n:?}");
        }
    }
    // Nothing was written.
    let mut names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names, ["bad.toml", "typo.toml"]);
}

#[test]
fn table_formats_agree() {
    let csv = stdout(&jamchart(repo(), &["table", "--format", "csv"]));
    assert!(csv.starts_with("mu,theta_jam_deg,x_jam_mm,"), "{csv}");
    assert_eq!(csv.lines().count(), 8);
    let rows = json(&jamchart(repo(), &["table", "--format", "json"]));
    let rows = rows.as_array().unwrap();
    assert_eq!(rows.len(), 7);
    let r030 = rows
        .iter()
        .find(|r| (r["mu"].as_f64().unwrap() - 0.3).abs() < 1e-12)
        .unwrap();
    assert!((r030["x_jam_mm"].as_f64().unwrap() - 32.4997).abs() < 1e-3);
    assert!(r030["erratum"].is_string());
    let md = stdout(&jamchart(repo(), &["table"]));
    assert!(
        md.contains("| 0.40 | 44.646 | 44.6 | 24.355 | 24.38 |"),
        "{md}"
    );
    assert!(md.contains("(*) mu = 0.30: erratum"), "{md}");
}

#[test]
fn help_answers_with_units_and_defaults() {
    let o = jamchart(repo(), &["solve", "--help"]);
    assert_eq!(o.status.code(), Some(0));
    let h = stdout(&o);
    for needle in [
        "--radius <MM>",
        "[default: 10]",
        "--force <N>",
        "--model",
        "min-norm",
    ] {
        assert!(h.contains(needle), "--help lacks {needle}: {h}");
    }
}
