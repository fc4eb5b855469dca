//! `jamchart sweep` run as a process in a temporary directory: a chart of one's own parameters
//! without a scene file.

use crate::common::cli as cli_util;
use cli_util::{SHAFT, jamchart, stderr, stdout};

/// The statics row at mu = 0.4 of a one-line sweep is the paper's closed form, 24.355 mm.
#[test]
fn one_axis_sweep_writes_data_and_pictures_with_the_closed_form() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(dir.path(), &["sweep", "mu=0.2:0.6:5"]);
    assert!(out.status.success(), "{}", stderr(&out));
    for ext in ["csv", "svg", "png"] {
        assert!(
            dir.path().join(format!("out/sweep_mu.{ext}")).exists(),
            "{ext}"
        );
    }
    let csv = std::fs::read_to_string(dir.path().join("out/sweep_mu.csv")).unwrap();
    let row = csv
        .lines()
        .find(|l| l.starts_with("statics,0.4,"))
        .unwrap_or_else(|| panic!("{csv}"));
    // layer, mu, status, x_jam_mm, theta_jam_deg
    assert_eq!(row.split(',').nth(2), Some("jams"), "{row}");
    let x: f64 = row.split(',').nth(3).unwrap().parse().unwrap();
    assert!((x - 24.355).abs() < 5e-4, "{row}");
}

#[test]
fn two_axis_sweep_draws_a_map_with_flags_for_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "sweep",
        "force_n=50:1000:9:log",
        "radius_mm=10:30:7",
        "--mass",
        "2.5",
        "--name",
        "shaft",
        "--out",
        "o",
    ];
    let out = jamchart(dir.path(), &args);
    assert!(out.status.success(), "{}", stderr(&out));
    let png = std::fs::read(dir.path().join("o/shaft.png")).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    assert!(dir.path().join("o/shaft.svg").exists());
}

#[test]
fn bad_axis_exits_2_and_names_the_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let out = jamchart(dir.path(), &["sweep", "radious_mm=10:30"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("radius_mm"), "{}", stderr(&out));
    let out = jamchart(dir.path(), &["sweep", "mu=0.5:0.1"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        !dir.path().join("out").exists(),
        "nothing written for a bad request"
    );
}

/// Regression: a sweep's curve stopped at mu = 0.150 with no explanation and its CSV
/// had no status column (empty cells): the 25 mm shaft on an 80 mm palm. Every row now
/// says the model's verdict, and the cells with no jam say why. A `beyond_reach` row's
/// `x_jam_mm` stays empty (no jam on this palm) and `past_palm_x_jam_mm` says where it would
/// jam on a long enough palm (99.261 mm at mu = 0.12, as `solve --mu 0.12` says).
#[test]
fn sweep_rows_carry_the_status_and_the_curve_says_where_it_ends() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(
        dir.path(),
        &["sweep", "mu=0.1:0.3:21"]
            .into_iter()
            .chain(SHAFT)
            .collect::<Vec<_>>(),
    );
    assert_eq!(o.status.code(), Some(0));
    let csv = std::fs::read_to_string(dir.path().join("out/sweep_mu.csv")).unwrap();
    let mut rows = csv.lines();
    assert_eq!(
        rows.next(),
        Some("layer,mu,status,x_jam_mm,theta_jam_deg,past_palm_x_jam_mm")
    );
    let statics: Vec<Vec<&str>> = rows
        .map(|r| r.split(',').collect::<Vec<_>>())
        .filter(|f| f[0] == "statics")
        .collect();
    assert_eq!(statics.len(), 21);
    for f in &statics {
        let mu: f64 = f[1].parse().unwrap();
        // The jam reaches the 80 mm palm from mu = 0.1489 (solve's friction needed).
        let want = if mu < 0.1489 { "beyond_reach" } else { "jams" };
        assert_eq!(f[2], want, "{f:?}");
        assert_eq!(f[3].is_empty(), want != "jams", "{f:?}");
        assert_eq!(f[5].is_empty(), want == "jams", "{f:?}");
        if want != "jams" {
            // Past this palm's end, and further out the less friction there is.
            let past: f64 = f[5].parse().unwrap();
            assert!(past > 80.0, "{f:?}");
        }
    }
    let at_0_12 = (statics.iter())
        .find(|f| (f[1].parse::<f64>().unwrap() - 0.12).abs() < 1e-12)
        .unwrap();
    let past: f64 = at_0_12[5].parse().unwrap();
    // The data files round to 7 significant digits.
    assert!((past - 99.2613605241956).abs() < 1e-4, "{at_0_12:?}");
}

/// Read-off at the user's point on a sweep. `sweep ... --mu 0.27 --read-off` draws the
/// closed form's x_jam and theta_jam at mu 0.27 and writes them as a `read_off` row, the same
/// numbers as `solve` for the same flags.
#[test]
fn a_sweep_reads_off_the_users_own_value() {
    let dir = tempfile::tempdir().unwrap();
    let args: Vec<&str> = ["sweep", "mu=0.1:0.3:21", "--mu", "0.27", "--read-off"]
        .into_iter()
        .chain(SHAFT)
        .collect();
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let csv = std::fs::read_to_string(dir.path().join("out/sweep_mu.csv")).unwrap();
    let row = csv
        .lines()
        .find(|l| l.starts_with("read_off,"))
        .unwrap_or_else(|| panic!("{csv}"));
    let solve: Vec<&str> = ["solve", "--mu", "0.27", "--format", "json"]
        .into_iter()
        .chain(SHAFT)
        .collect();
    let v: serde_json::Value =
        serde_json::from_str(&stdout(&jamchart(dir.path(), &solve))).unwrap();
    let f: Vec<&str> = row.split(',').collect();
    assert_eq!(&f[..3], ["read_off", "0.27", "jams"], "{row}");
    for (i, key) in [(3, "x_jam_mm"), (4, "theta_jam_deg")] {
        let want = v["results"][0][key].as_f64().unwrap();
        let got: f64 = f[i].parse().unwrap();
        assert!((got - want).abs() <= 1e-6 * want, "{key}: {got} vs {want}");
    }
}

/// A sweep with a range read off at an unexplained midpoint (mu = 0.21, 56.678 mm) and wrote
/// no gallery. `sweep force_n=20:100 --mu 0.12:0.3 --force 40 --read-off` on the 25 mm shaft
/// reads off the band's ends at F = 40 N, `solve --mu 0.12:0.3`'s interval (the earliest jam
/// 39.629 mm at mu 0.3, the palm's end 80 mm past which mu 0.12 jams), names the range in
/// the subtitle, and joins the folder's gallery with its read-off and the command.
#[test]
fn a_sweep_with_a_range_reads_off_the_bands_ends_and_joins_the_gallery() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec![
        "sweep",
        "force_n=20:100:17",
        "--mu",
        "0.12:0.3",
        "--read-off",
    ];
    args.extend(SHAFT);
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = dir.path().join("out");
    let csv = std::fs::read_to_string(out.join("sweep_force_n.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().filter(|l| l.starts_with("read_off,")).collect();
    let [row] = rows[..] else {
        panic!("one read-off row:\n{csv}")
    };
    let mut solve = vec!["solve", "--mu", "0.12:0.3", "--format", "json"];
    solve.extend(SHAFT);
    let v: serde_json::Value =
        serde_json::from_str(&stdout(&jamchart(dir.path(), &solve))).unwrap();
    let r = &v["results"][0];
    let f: Vec<&str> = row.split(',').collect();
    // layer, force_n, (status, x, theta, past_palm_x empty), earliest_*, latest_*, the shaded
    // interval.
    assert_eq!(&f[..6], ["read_off", "40", "", "", "", ""], "{row}");
    assert_eq!((f[6], f[9]), ("jams", "beyond_reach"), "{row}");
    let num = |i: usize| f[i].parse::<f64>().unwrap();
    let want = |k: &str, i: usize| r[k][i].as_f64().unwrap();
    for (got, want) in [
        (num(7), r["earliest"]["x_jam_mm"].as_f64().unwrap()),
        (num(12), want("x_jam_mm", 0)),
        (num(13), want("x_jam_mm", 1)),
        (num(14), want("theta_jam_deg", 0)),
        (num(15), want("theta_jam_deg", 1)),
    ] {
        assert!((got - want).abs() <= 1e-6 * want, "{got} vs {want}: {row}");
    }
    // The subtitle and the read-off in the picture, the section with its read-off and command
    // in the gallery.
    for (file, want) in [
        ("sweep_force_n.svg", "μ = 0.12 to 0.3 (curves at 0.21)"),
        (
            "sweep_force_n.svg",
            "3: x_jam 39.629 mm (earliest, μ = 0.3) to 80.000 mm (the palm's end: μ = 0.12 \
             jams past it)",
        ),
        (
            "index.html",
            "<figure class=\"readoff\" data-chart=\"sweep_force_n\">",
        ),
        (
            "index.html",
            "Reproduce: <code>jamchart sweep force_n=20:100:17",
        ),
    ] {
        let text = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(text.contains(want), "{file} lacks {want}");
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(!html.contains("not recorded here"), "{html}");
}
