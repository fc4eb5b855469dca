//! `jamchart render --read-off KEY=VALUE`: the user's own point on every built-in
//! map and sweep, checked against `solve` for the same part.

use crate::common::cli as cli_util;
use cli_util::{jamchart, json, stderr};

use serde_json::Value;

/// The example part of the universal chart: mu 0.27, r 12 mm, F 150 N (m 1 kg).
const PART: [&str; 6] = [
    "--read-off",
    "mu=0.27",
    "--read-off",
    "radius_mm=12",
    "--read-off",
    "force_n=150",
];

fn file(dir: &std::path::Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Regression: `render SCENE --read-off mu=0.27` was refused (only `sweep --read-off` and a
/// scene's own chart.read_off existed), so a user could not read a built-in map or sweep at
/// their point. Now every map and sweep draws it, prints the values on the chart and writes
/// them in its data, and the numbers are `solve`'s for the same part; a chart with no
/// read-off says so.
#[test]
fn render_read_off_draws_the_users_point_on_every_map_and_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let solved = json(&jamchart(
        dir.path(),
        &[
            "solve", "--mu", "0.27", "--radius", "12", "--force", "150", "--format", "json",
        ],
    ));
    let statics = &solved["results"][0];
    let (theta, x) = (
        statics["theta_jam_deg"].as_f64().unwrap(),
        statics["x_jam_mm"].as_f64().unwrap(),
    );
    let mut args = vec![
        "render",
        "fig3",
        "fig7a",
        "fig7c",
        "universal",
        "fig4",
        "--format",
        "svg",
    ];
    args.extend(PART);
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("scene fig4 (convergence) draws no read-off"),
        "{err}"
    );
    assert!(!err.contains("fig3") && !err.contains("fig7c"), "{err}");
    // The read-off in each map's data: the closed form at the user's part, to 1e-5 relative.
    let close = |r: &Value, what: &str| {
        let (t, xj) = (
            r["theta_jam_deg"].as_f64().unwrap(),
            r["x_jam_mm"].as_f64().unwrap(),
        );
        assert!(
            ((t - theta) / theta).abs() < 1e-5 && ((xj - x) / x).abs() < 1e-5,
            "{what}: {t} deg, {xj} mm; solve says {theta} deg, {x} mm"
        );
    };
    let out = dir.path().join("out");
    for map in ["fig3", "fig7c", "universal"] {
        let doc: Value = serde_json::from_str(&file(&out, &format!("{map}.json"))).unwrap();
        close(&doc["read_off"], map);
    }
    let fig7c: Value = serde_json::from_str(&file(&out, "fig7c.json")).unwrap();
    assert_eq!(fig7c["read_off"]["force_n"].as_f64(), Some(150.0));
    assert_eq!(fig7c["read_off"]["radius_mm"].as_f64(), Some(12.0));
    // The sweep's CSV row of the read-off, at r = 12 mm.
    let csv = file(&out, "fig7a.csv");
    let row = csv
        .lines()
        .find(|l| l.starts_with("read_off,"))
        .expect("fig7a.csv has a read_off row");
    let cells: Vec<&str> = row.split(',').collect();
    assert_eq!(cells[1], "12", "{row}");
    let (xj, t): (f64, f64) = (cells[3].parse().unwrap(), cells[4].parse().unwrap());
    assert!((xj - x).abs() < 1e-4 && (t - theta).abs() < 1e-4, "{row}");
    // The values and lines are on the pictures, named in their legends.
    let svg = file(&out, "fig7c.svg");
    assert!(svg.contains("3: x_jam = 43.0 mm, θ_jam = 31.2°"), "fig7c");
    assert!(
        svg.contains("read-off 1-2-3 at F = 150 N, r = 12 mm"),
        "fig7c"
    );
    let svg = file(&out, "fig3.svg");
    assert!(svg.contains("θ_jam = 31.196°") && svg.contains("x_jam = 42.986 mm"));
    assert!(svg.contains("read-off lines 1-2-3 at μ = 0.27"), "fig3");
    assert!(file(&out, "fig7a.svg").contains("read-off lines 1-2-3 at r = 12 mm (closed form)"));
    // The gallery's command reproduces the read-off.
    assert!(file(&out, "index.html").contains("--read-off mu=0.27"));
}

/// A read-off whose point lies off a map draws nothing and names nothing in the legend (a custom
/// map's legend named read-off lines at mu = 0.40 that were not drawn), and warns.
#[test]
fn a_read_off_off_the_map_is_not_in_the_legend() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &[
            "render",
            "fig7c",
            "--read-off",
            "force_n=20",
            "--format",
            "svg",
        ],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // ... and says so: 20 N is left of fig7c's force axis.
    assert!(
        stderr(&o)
            .contains("--read-off force_n=20 is off scene fig7c's chart.x_axis (force_n from"),
        "{}",
        stderr(&o)
    );
    let svg = file(&dir.path().join("out"), "fig7c.svg");
    assert!(!svg.contains("read-off") && !svg.contains("3: "), "drawn");
    let doc: Value = serde_json::from_str(&file(&dir.path().join("out"), "fig7c.json")).unwrap();
    assert_eq!(doc["read_off"]["force_n"].as_f64(), Some(20.0));
}

/// `render fig3 --read-off mu=0.8` drew nothing and said nothing: 0.8 is off fig3's mu axis
/// (0.1 to 0.5). It warns on stderr naming the read-off as typed and the axis' range, and
/// still renders (exit 0); a value on the axis, or a key no axis varies, warns nothing.
#[test]
fn a_read_off_off_the_axis_warns_naming_the_axis_range() {
    let dir = tempfile::tempdir().unwrap();
    let render = |args: &[&str]| {
        let mut a = vec!["render", "fig3", "--format", "svg"];
        a.extend(args);
        let o = jamchart(dir.path(), &a);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        stderr(&o)
    };
    let err = render(&["--read-off", "mu=0.8"]);
    assert!(
        err.contains(
            "jamchart: warning: --read-off mu=0.8 is off scene fig3's chart.x_axis (mu from 0.1 to 0.5)"
        ),
        "{err}"
    );
    for ok in [["--read-off", "mu=0.3"], ["--read-off", "radius_mm=12"]] {
        let err = render(&ok);
        assert!(!err.contains("warning"), "{ok:?}: {err}");
    }
}

/// `--read-off` takes a scene parameter and a value it accepts; anything else exits 2 naming
/// the flag and the value as typed.
#[test]
fn read_off_refuses_what_is_not_a_scene_parameter_value() {
    let dir = tempfile::tempdir().unwrap();
    for (typed, says) in [
        ("theta_deg=30", "theta_deg is not one of mu, mu_ground"),
        ("mu", "is not KEY=VALUE"),
        ("mu=abc", "abc is not a number"),
        ("mu=-1", "mu = -1 must be"),
        ("radius_mm=1e400", "1e400"),
    ] {
        let o = jamchart(dir.path(), &["render", "fig3", "--read-off", typed]);
        assert_eq!(o.status.code(), Some(2), "{typed}");
        let err = stderr(&o);
        assert!(
            err.starts_with("jamchart: ") && err.contains("--read-off") && err.contains(says),
            "{typed}: {err}"
        );
    }
    assert!(!dir.path().join("out").exists());
}
