//! Ranges and distributions on the command line and in files: which settings take
//! them, how bad ones are refused, and the answers over a range.

use crate::common::cli as cli_util;

use cli_util::{jamchart, stderr};

/// Runs the binary in a fresh temp dir and returns (exit code, stderr).
fn refused(args: &[&str]) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(dir.path(), args);
    (o.status.code(), stderr(&o))
}

/// Bad ranges and distributions: each exits 2 with one `jamchart:` line naming the flag as written.
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

/// The 25 mm shaft over a friction range is one command: the jam interval, the worst ends and the
/// status change over the friction range, in text and JSON.
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
        "theta_jam from 17.761 to 35.013 deg, x_jam from 39.629 to 80.000 mm, over the points \
         that jam on the palm or are held at the start",
        "furthest out: pushed past the palm's end (x = 80.000 mm, theta = 17.761 deg) at the \
         corner mu = 0.12, beyond_reach; on a long enough palm it would jam at theta_jam = \
         14.355 deg, x_jam = 99.261 mm (a palm of at least 99.261 mm)",
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
    // The latest corner's would-be jam on a long palm, as `solve --mu 0.12` gives it.
    let past = r["latest"]["past_palm"]["x_jam_mm"].as_f64().unwrap();
    assert!((past - 99.261).abs() < 5e-4, "{r}");
}

/// `sweep` with a range draws the band's two edges and shades the band between them, each
/// edge in its own colour, and writes one CSV row of layer `band` per swept value with each
/// corner's status, x_jam and theta_jam and the shaded interval: checked against `solve` with
/// the same range at every sampled push (its earliest and latest corners), the shade running to
/// the palm's end (x = L = 80 mm) where the latest jam lies past it. A map of two axes refuses
/// a range for now.
#[test]
fn a_sweep_with_a_range_writes_the_bands_edges() {
    let dir = tempfile::tempdir().unwrap();
    let base = ["--radius", "12.5", "--mass", "0.4", "--palm-length", "80"];
    let mut args = vec!["sweep", "force_n=10:100:7", "--out", "o", "--format", "svg"];
    args.extend(base);
    args.extend(["--mu", "0.15:0.3"]);
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // The two edges are told apart by colour (and dash): once both were the construction
    // lines' thin blue dash. Bluish green for the earliest jam, orange for the latest, the
    // shade a light sky blue.
    let svg = std::fs::read_to_string(dir.path().join("o/sweep_force_n.svg")).unwrap();
    for colour in ["#009E73", "#E69F00", "#CCE8F8"] {
        assert!(svg.contains(colour), "no {colour} in the band");
    }
    let csv = std::fs::read_to_string(dir.path().join("o/sweep_force_n.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .filter(|l| l.starts_with("band,"))
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 7, "one band row per push\n{csv}");
    let col = |row: &[&str], name: &str| -> String {
        let i = header.iter().position(|h| *h == name).unwrap();
        row[i].to_string()
    };
    let num = |s: String| -> Option<f64> { (!s.is_empty()).then(|| s.parse().unwrap()) };
    let close = |a: f64, b: f64| (a - b).abs() < 1e-4;
    let mut capped = 0;
    for row in &rows {
        let f = col(row, "force_n");
        let mut solve = vec![
            "solve", "--force", &f, "--mu", "0.15:0.3", "--format", "json",
        ];
        solve.extend(base);
        let v = cli_util::json(&jamchart(dir.path(), &solve));
        let r = &v["results"][0];
        for end in ["earliest", "latest"] {
            let want = &r[end];
            assert_eq!(
                col(row, &format!("{end}_status")),
                want["status"],
                "F = {f}"
            );
            if want["status"] == "jams" {
                let x = num(col(row, &format!("{end}_x_jam_mm"))).unwrap();
                let t = num(col(row, &format!("{end}_theta_jam_deg"))).unwrap();
                let (wx, wt) = (want["x_jam_mm"].as_f64(), want["theta_jam_deg"].as_f64());
                assert!(
                    close(x, wx.unwrap()) && close(t, wt.unwrap()),
                    "{end} at F = {f}"
                );
            }
        }
        let lo = num(col(row, "band_x_jam_lo_mm")).unwrap();
        let hi = num(col(row, "band_x_jam_hi_mm")).unwrap();
        assert!(
            close(lo, r["earliest"]["x_jam_mm"].as_f64().unwrap()),
            "F = {f}"
        );
        match r["latest"]["status"].as_str() {
            Some("jams") => assert!(close(hi, r["latest"]["x_jam_mm"].as_f64().unwrap())),
            Some("beyond_reach") => {
                capped += 1;
                assert!(
                    close(hi, 80.0),
                    "shaded to {hi} mm at F = {f}, not the palm's end"
                );
            }
            other => panic!("latest {other:?} at F = {f}"),
        }
    }
    assert!(
        capped > 0 && capped < rows.len(),
        "both kinds of row: {capped} of {} capped",
        rows.len()
    );
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

/// A range given to a scene (`render fig7b --set mu=0.12:0.3`, or `mu = "0.12:0.3"` in a scene
/// file's `[scene]`) was refused as "invalid type: string, expected f64". A sweep scene now
/// draws it as its band (the same rows as `jamchart sweep --mu 0.12:0.3`, checked against
/// `solve` at the range's ends); any other kind refuses it naming the setting as written and
/// the sweep that draws it, and a range on the swept parameter itself is refused.
#[test]
fn a_range_given_to_a_scene_was_refused_as_an_invalid_type() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["render", "fig7b", "--set", "mu=0.12:0.3", "--out", "o"];
    let o = jamchart(dir.path(), &[&args[..], &["--format", "svg"]].concat());
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let file = "title = \"t\"\n[scene]\nmu = \"0.12:0.3\"\n[chart]\nkind = \"sweep\"\n\
                x_axis = { param = \"force_n\", min = 50.0, max = 10000.0, count = 301, scale = \"log\" }\n";
    std::fs::write(dir.path().join("s.toml"), file).unwrap();
    let o = jamchart(
        dir.path(),
        &["render", "s.toml", "--out", "o", "--format", "svg"],
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    for csv in ["o/fig7b.csv", "o/s.csv"] {
        let csv = std::fs::read_to_string(dir.path().join(csv)).unwrap();
        let band: Vec<&str> = csv.lines().filter(|l| l.starts_with("band,")).collect();
        assert_eq!(band.len(), 301, "{csv}");
        // At F = 50 N: earliest at mu = 0.3, latest at mu = 0.12 (the paper's other values).
        let row: Vec<&str> = band[0].split(',').collect();
        for (mu, x) in [("0.3", row[7]), ("0.12", row[10])] {
            let solve = ["solve", "--force", "50", "--mu", mu, "--format", "json"];
            let v = cli_util::json(&jamchart(dir.path(), &solve));
            let want = v["results"][0]["x_jam_mm"].as_f64().unwrap();
            let x: f64 = x.parse().unwrap();
            assert!((x - want).abs() < 1e-4, "mu {mu}: {x} vs solve {want}");
        }
    }
    let o = jamchart(
        dir.path(),
        &["render", "fig7c", "--set", "mu=0.12:0.3", "--out", "o"],
    );
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    for part in ["jamchart: ", "--set mu", "contour_map", "kind = \"sweep\""] {
        assert!(err.contains(part), "{part} in {err}");
    }
    let o = jamchart(dir.path(), &["render", "fig7b", "--set", "force_n=30:50"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("swept parameter"), "{}", stderr(&o));
}

/// A jam map with a range on an input not on its axes (fig3 over (mu, theta) with the mass
/// 1 to 8 kg) shades the cells whose verdict depends on the mass as `uncertain`: checked cell by
/// cell against the point maps at the range's ends (jam where both jam, slide where both
/// slide, uncertain where they differ) and against point maps inside the range (3 and 5.5 kg),
/// which agree with every cell the band calls jam or slide (the statics is monotone in the
/// mass). A range on the map's own axis (mu) is refused.
#[test]
fn a_jam_map_with_a_range_shades_the_uncertain_region() {
    let dir = tempfile::tempdir().unwrap();
    let regions = |mass: &str| -> Vec<String> {
        let set = format!("mass_kg={mass}");
        let out = format!("m{}", mass.replace(':', "_"));
        let args = [
            "render",
            "fig3",
            "--set",
            &set,
            "--set",
            "chart.x_axis.count=61",
            "--set",
            "chart.y_axis.count=61",
            "--out",
            &out,
            "--format",
            "svg",
        ];
        let o = jamchart(dir.path(), &args);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        let csv = std::fs::read_to_string(dir.path().join(&out).join("fig3.csv")).unwrap();
        let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        let i = header.iter().position(|h| *h == "region").unwrap();
        csv.lines()
            .skip(1)
            .map(|l| l.split(',').nth(i).unwrap().to_string())
            .collect()
    };
    let band = regions("1:8");
    let (lo, hi) = (regions("1"), regions("8"));
    let inside = [regions("3"), regions("5.5")];
    assert_eq!(band.len(), 61 * 61);
    let mut uncertain = 0;
    for (k, r) in band.iter().enumerate() {
        let want = match (lo[k].as_str(), hi[k].as_str()) {
            (a, b) if a == b => a,
            ("jam", "slide") | ("slide", "jam") => "uncertain",
            other => panic!("cell {k}: ends {other:?}"),
        };
        assert_eq!(r, want, "cell {k}");
        if r == "uncertain" {
            uncertain += 1;
        } else {
            for m in &inside {
                assert_eq!(&m[k], r, "cell {k} inside the range");
            }
        }
    }
    assert!(uncertain > 0, "no uncertain cell");
    let svg = std::fs::read_to_string(dir.path().join("m1_8/fig3.svg")).unwrap();
    assert!(svg.contains("#F7F098"), "no uncertain fill");
    let o = jamchart(dir.path(), &["render", "fig3", "--set", "mu=0.12:0.3"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("swept parameter mu"), "{}", stderr(&o));
}

/// Runs `jamchart ARGS` in a fresh temp dir, killing it after `secs` seconds: (exit code,
/// stdout), None for the code when it had to be killed.
fn run_within(args: &[&str], secs: u64) -> (Option<i32>, String) {
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_jamchart"))
        .args(args)
        .current_dir(dir.path())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(secs);
    while std::time::Instant::now() < deadline {
        if child.try_wait().unwrap().is_some() {
            let o = child.wait_with_output().unwrap();
            return (
                o.status.code(),
                String::from_utf8_lossy(&o.stdout).into_owned(),
            );
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    (None, String::new())
}

/// Regression: a range narrower than the bisection's tolerance hung. The status change along it
/// was bisected to 1e-9 of the range's width with no cap on the halvings: 1e-17 for `--force
/// 3.64185697:3.64185698`, below the spacing of floats at 3.6 (4.4e-16), so the bracket never
/// shrank to it; likewise a mass range 1e-7 wide at 55 kg and a lognormal friction of median
/// 5e-324 (every value subnormal), and P(x_jam < x) of a friction normal(0.4,1e-15) at an x
/// inside its support (bisected to 1e-12 of a support 6e-15 wide). Each now answers within
/// seconds.
#[test]
fn a_range_narrower_than_the_float_spacing_answers() {
    for range in [
        &["--force", "3.64185697:3.64185698"][..],
        &["--mass", "54.9170386:54.9170387"],
        &["--mu", "lognormal(5e-324,1)"],
        &[
            "--mu",
            "normal(0.4,1e-15)",
            "--before",
            "24.354551362801473",
        ],
    ] {
        let mut args = vec!["solve"];
        args.extend(range);
        let (code, out) = run_within(&args, 30);
        assert_eq!(code, Some(0), "{range:?} did not answer in 30 s");
        assert!(out.contains("statuses in the box"), "{range:?}: {out}");
        assert!(
            !out.contains(" inf") && !out.contains("NaN"),
            "{range:?}: {out}"
        );
    }
    // Every friction of the subnormal lognormal jams beyond what a double holds: its
    // quantiles say so.
    let (_, out) = run_within(&["solve", "--mu", "lognormal(5e-324,1)"], 30);
    assert!(
        out.contains("50 % quantile of x_jam: beyond 1.8e308 mm, past every position"),
        "{out}"
    );
}

/// Regression: at subnormal frictions every point's jam lies past the palm (x_jam overflows to
/// infinity), and `solve --mu 1e-320:1e-310` printed "x_jam from inf to inf mm". No point
/// answers a jam there: the output says so, with no infinite number in it.
#[test]
fn a_box_of_subnormal_frictions_prints_no_infinite_jam() {
    let (code, out) = run_within(&["solve", "--mu", "1e-320:1e-310"], 30);
    assert_eq!(code, Some(0));
    assert!(!out.contains("inf"), "{out}");
    assert!(
        out.contains("no point of the box jams on the palm or is held at the start"),
        "{out}"
    );
    assert!(out.contains("statuses in the box: beyond_reach"), "{out}");
}

/// Regression: a sweep's band was empty wherever its earliest-jam corner could not move the
/// disc. `sweep mu=0.2:0.5 --force 3:10 --start-angle 80` shaded nothing for mu >= 0.3215
/// (120 of 201 values), where pushes a little above the least that moves the disc hold it at
/// the start (80 deg, 11.918 mm) and 10 N jams it. Every row now shades from the start angle.
#[test]
fn a_sweep_band_with_a_too_weak_corner_is_shaded() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "sweep",
        "mu=0.2:0.5",
        "--force",
        "3:10",
        "--start-angle",
        "80",
        "--out",
        "o",
        "--format",
        "svg",
    ];
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let mut r = csv::Reader::from_path(dir.path().join("o/sweep_mu.csv")).unwrap();
    let header = r.headers().unwrap().clone();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (mut too_weak, mut rows) = (0, 0);
    for rec in r.records() {
        let rec = rec.unwrap();
        if &rec[0] != "band" {
            continue;
        }
        rows += 1;
        let hi: f64 = rec[col("band_theta_jam_hi_deg")]
            .parse()
            .expect("a shaded row");
        let x_lo: f64 = rec[col("band_x_jam_lo_mm")].parse().unwrap();
        if &rec[col("earliest_status")] == "too_weak" {
            too_weak += 1;
            assert!(
                (hi - 80.0).abs() < 1e-9 && (x_lo - 11.91754).abs() < 1e-5,
                "{rec:?}"
            );
        }
    }
    assert_eq!(rows, 201);
    assert_eq!(
        too_weak, 120,
        "the rows whose earliest corner cannot move the disc"
    );
}

/// Regression (docs): `solve --help` said the statics with one distributed input are exact, and
/// `solve --mu normal(0.2,0.03) --force 30:50` (one distribution beside a range) is answered by
/// Monte Carlo. The help now says when it is exact, and the answers say which they are.
#[test]
fn the_help_says_when_a_distribution_is_answered_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let help = cli_util::stdout(&jamchart(dir.path(), &["solve", "--help"]));
    let flat = help.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        flat.contains("where one distribution is the only uncertain input (no range beside it)"),
        "{help}"
    );
    for (args, how) in [
        (
            &["--mu", "normal(0.2,0.03)"][..],
            "(exact, by the monotone map",
        ),
        (
            &["--mu", "normal(0.2,0.03)", "--force", "30:50"],
            "(Monte Carlo, 100000 samples",
        ),
    ] {
        let mut all = vec!["solve"];
        all.extend(args);
        let out = cli_util::stdout(&jamchart(dir.path(), &all));
        assert!(out.contains(how), "{args:?}: {out}");
    }
}

/// `solve` printed "over the box" of a normal input without saying what the box is (its ends
/// were mean +- 3.09 sd, unexplained): it says the box is the central 99.8 %, from the 0.1 %
/// to the 99.9 % quantile, with the ends the corners then name.
#[test]
fn solve_says_what_the_box_of_a_distribution_is() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["solve"];
    args.extend(cli_util::SHAFT);
    args.extend(["--mu", "normal(0.2,0.03)", "--before", "50"]);
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = cli_util::stdout(&o);
    let line = "the box takes mu = normal(0.2,0.03) as its central 99.8 %: 0.1073 to 0.2927 \
                (its 0.1 % and 99.9 % quantiles)";
    assert!(out.contains(line), "{out}");
    // The same ends as the box's corners: 0.2 -+ 3.090 * 0.03.
    assert!(out.contains("at the corner mu = 0.2927"), "{out}");
}

/// The probability chart's read-off is `solve --before`'s answer to the digits of its data
/// file (P(jam before 50 mm) = 0.1028 for the shaft with mu normal(0.2,0.03)), and it refuses
/// a range, which has no probability, naming it as given.
#[test]
fn the_probability_chart_reads_off_solves_answer() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["render", "jam-probability", "--out", "o", "--format", "svg"];
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let data = std::fs::read_to_string(dir.path().join("o/jam-probability.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&data).unwrap();
    let chart = v["read_off"]["probability"]["value"].as_f64().unwrap();
    let mut solve = vec!["solve"];
    solve.extend(cli_util::SHAFT);
    solve.extend([
        "--mu",
        "normal(0.2,0.03)",
        "--before",
        "50",
        "--format",
        "json",
    ]);
    let s = cli_util::json(&jamchart(dir.path(), &solve));
    let want = s["results"][0]["distribution"]["before"][0]["probability"]["value"]
        .as_f64()
        .unwrap();
    assert!(
        (chart - want).abs() < 1e-6 && (want - 0.1028).abs() < 5e-5,
        "{chart} vs {want}"
    );
    assert_eq!(v["method"]["method"], "exact");
    let o = jamchart(
        dir.path(),
        &[&args[..], &["--set", "force_n=30:50"]].concat(),
    );
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    for part in ["--set force_n", "no probability", "uniform(30,50)"] {
        assert!(err.contains(part), "{part} in {err}");
    }
}

/// The universal chart refused `mu=0.12:0.3`; it draws the range's box and reads off its two
/// ends, each the closed form at the box's corner as `solve` gives it: the earliest jam at
/// mu = 0.3 (x_jam = 39.629 mm) and the latest at mu = 0.12, past the 80 mm palm's end (x/r =
/// cot(theta/2) on a long palm, above L/r = 6.4). A range of a friction that is not its x axis
/// is refused, naming it.
#[test]
fn the_universal_chart_reads_off_a_ranges_ends() {
    let dir = tempfile::tempdir().unwrap();
    let mut args = vec!["render", "universal", "--out", "o", "--format", "svg"];
    for s in [
        "mu=0.12:0.3",
        "radius_mm=12.5",
        "mass_kg=0.4",
        "force_n=40",
        "palm_length_mm=80",
    ] {
        args.extend(["--set", s]);
    }
    let o = jamchart(dir.path(), &args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let data = std::fs::read_to_string(dir.path().join("o/universal.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&data).unwrap();
    let r = &v["range"];
    assert_eq!(r["given"], "mu = 0.12:0.3");
    assert_eq!(r["earliest"]["mu"], 0.3);
    assert_eq!(r["earliest"]["status"], "jams");
    let x = r["earliest"]["x_jam_mm"].as_f64().unwrap();
    assert!((x - 39.629).abs() < 1e-3, "{x}");
    assert_eq!(r["latest"]["mu"], 0.12);
    assert_eq!(r["latest"]["status"], "beyond_reach");
    let t = r["latest"]["theta_jam_on_a_long_palm_deg"]
        .as_f64()
        .unwrap();
    let x_over_r = 1.0 / (0.5 * t.to_radians()).tan();
    assert!(x_over_r > 80.0 / 12.5, "{x_over_r}");
    let bad = [&args[..], &["--set", "mu_ground=0.1:0.2"]].concat();
    let o = jamchart(dir.path(), &bad);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("along its axes"), "{}", stderr(&o));
}

/// `solve --mu 0:0.3` said `never_jams for mu < 2.794e-10`, while only mu = 0 never jams
/// (`--mu 1e-10` is beyond_reach): the statuses along the range name that one point.
#[test]
fn a_friction_range_from_zero_never_jams_at_zero_alone() {
    let dir = tempfile::tempdir().unwrap();
    let o = jamchart(dir.path(), &["solve", "--mu", "0:0.3"]);
    let text = cli_util::stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        text.contains("mu in [0, 0.3]: never_jams at mu = 0, beyond_reach from 0 to 0.06507, "),
        "{text}"
    );
    let o = jamchart(dir.path(), &["solve", "--mu", "1e-10"]);
    assert!(cli_util::stdout(&o).contains("statics: beyond_reach"));
}
