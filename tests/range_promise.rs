//! A range answer is a promise: every point of the box answers inside the printed interval of
//! theta_jam and x_jam, and the interval claims no value that no point reaches (a disc held at
//! the start answers the start angle; one beyond the palm, too weak or never jamming answers
//! none). Checked over seeded random boxes of one and two inputs (every input that takes a
//! range; corners too weak, held at the start, at mu = 0 and beyond the palm) against the
//! point answers of the model port on a dense grid of the box, refined at each status change.

use crate::common::boxes;
use crate::common::cli as cli_util;

use boxes::{Broken, Draw, INPUTS, answers_in_box, check, random_box};
use jamchart::uncertain::{Uncertain, UncertainInput, UncertainSet, range};
use jamchart::{JamStatus, SceneParams};

/// Boxes tried; the seed fixes them.
const BOXES: usize = 300;

/// Values per input on the grid (each grid line refined where the status changes).
const GRID: usize = 41;

/// The closed form's range answer keeps its promise on every random box: the count of boxes
/// that break it is printed (`cargo test --release --test integration range_promise -- --nocapture`).
#[test]
fn every_point_of_a_random_box_answers_inside_its_interval_and_each_end_is_reached() {
    let mut d = Draw::new(2024);
    let (mut broken, mut misses, mut claims) = (Vec::new(), 0, 0);
    // How often each status is met in a box: the boxes must meet every one.
    let mut met = [0usize; JamStatus::ALL.len()];
    for k in 0..BOXES {
        let (p, set) = random_box(&mut d);
        let a = range::closed_form(&p, &set).unwrap();
        for s in &a.statuses {
            met[JamStatus::ALL.iter().position(|x| x == s).unwrap()] += 1;
        }
        let found = answers_in_box(&p, &set, GRID);
        let thetas: Vec<f64> = found.iter().map(|f| f.0).collect();
        let xs: Vec<f64> = found.iter().map(|f| f.1).collect();
        let mut why = check("theta_jam_deg", a.theta_jam_deg, &thetas, 1e-9, 1e-6);
        why.extend(check("x_jam_mm", a.x_jam_mm, &xs, 1e-9, 1e-6));
        if why.is_empty() {
            continue;
        }
        let missed = why
            .iter()
            .any(|w| matches!(w, Broken::Misses { .. } | Broken::Empty { .. }));
        misses += usize::from(missed);
        claims += usize::from(why.iter().any(|w| matches!(w, Broken::Claims { .. })));
        broken.push(format!(
            "box {k}: {} over {:?}: interval {:?} deg, {:?} mm: {why:?}",
            set.describe(),
            p,
            a.theta_jam_deg,
            a.x_jam_mm
        ));
    }
    let met: Vec<String> = JamStatus::ALL
        .iter()
        .zip(met)
        .map(|(s, n)| format!("{s} {n}"))
        .collect();
    println!("boxes meeting each status: {}", met.join(", "));
    println!(
        "{BOXES} random boxes: {} break the promise ({misses} with a point outside, {claims} \
         claiming a value no point reaches)",
        broken.len()
    );
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

/// The flags that give scene `p` exactly, leaving out the settings `set` takes a range for,
/// then the ranges.
fn flags(p: &SceneParams, set: &UncertainSet) -> Vec<String> {
    let taken = |k: &str| set.inputs.iter().any(|i| i.keys.contains(&k));
    let mut out: Vec<String> = [
        ("--mu-ground", "mu_ground", p.mu_ground),
        ("--mu-palm", "mu_palm", p.mu_palm),
        ("--radius", "radius_mm", p.radius_mm),
        ("--mass", "mass_kg", p.mass_kg),
        ("--force", "force_n", p.force_n),
        ("--start-angle", "start_angle_deg", p.start_angle_deg),
        ("--palm-length", "palm_length_mm", p.palm_length_mm),
        ("--palm-offset", "palm_offset_mm", p.palm_offset_mm),
    ]
    .into_iter()
    .filter(|(_, key, _)| !taken(key))
    .flat_map(|(flag, _, v)| [flag.to_string(), v.to_string()])
    .collect();
    for i in &set.inputs {
        let flag = INPUTS.iter().find(|x| x.0 == i.name).unwrap().2;
        out.extend([flag.to_string(), i.value.to_string()]);
    }
    out
}

/// Runs `jamchart ARGS` in `dir` and checks it succeeded.
fn run(dir: &std::path::Path, args: &[String]) {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = cli_util::jamchart(dir, &args);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{args:?}: {}",
        cli_util::stderr(&o)
    );
}

/// The rows of a CSV file with a header, each as a map from column to text.
fn csv_rows(path: &std::path::Path) -> Vec<std::collections::HashMap<String, String>> {
    let mut r = csv::Reader::from_path(path).expect("the CSV reads");
    let header = r.headers().unwrap().clone();
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            header
                .iter()
                .map(str::to_string)
                .zip(rec.iter().map(str::to_string))
                .collect()
        })
        .collect()
}

/// An interval from two CSV cells, None where both are empty.
fn interval(
    row: &std::collections::HashMap<String, String>,
    lo: &str,
    hi: &str,
) -> Option<[f64; 2]> {
    let num = |k: &str| row[k].parse::<f64>().ok();
    Some([num(lo)?, num(hi)?])
}

/// A sweep's band keeps the range answer's promise at every swept value: the shaded interval
/// of its CSV (seven significant digits) holds every point answer of the box there, and each
/// end is reached. Random scenes, boxes of one and two inputs and a swept parameter that is
/// not one of them, through the real binary.
#[test]
fn every_point_of_a_random_box_answers_inside_the_sweep_band() {
    let dir = tempfile::tempdir().unwrap();
    let mut d = Draw::new(77);
    let mut broken = Vec::new();
    let sweeps = 30;
    for k in 0..sweeps {
        let (mut p, set) = random_box(&mut d);
        let taken = |k: &str| set.inputs.iter().any(|i| i.keys.contains(&k));
        // Each swept parameter with its range and what it sets in a scene (`mu` both frictions).
        type Sets = fn(SceneParams, f64) -> SceneParams;
        let all: [(&str, f64, f64, Sets); 5] = [
            ("mu", 0.01, 0.8, |p, v| p.with_mu(v)),
            ("radius_mm", 2.0, 20.0, |p, v| SceneParams {
                radius_mm: v,
                ..p
            }),
            ("palm_length_mm", 15.0, 200.0, |p, v| SceneParams {
                palm_length_mm: v,
                ..p
            }),
            ("mass_kg", 0.05, 5.0, |p, v| SceneParams { mass_kg: v, ..p }),
            ("force_n", 1.0, 200.0, |p, v| SceneParams {
                force_n: v,
                ..p
            }),
        ];
        let choices: Vec<(&str, f64, f64, Sets)> = all
            .into_iter()
            .filter(|&(key, ..)| {
                !(taken(key) || (key == "mu" && (taken("mu_ground") || taken("mu_palm"))))
            })
            .collect();
        let (param, min, max, apply) = d.pick(&choices);
        if param == "mu" {
            // A mu axis sets both frictions: the scene has one.
            p.mu_palm = p.mu_ground;
        }
        let values = spaced(min, max, 31, false);
        let name = format!("band{k}");
        let mut args = vec![
            "sweep".to_string(),
            format!("{param}={min}:{max}:31"),
            "--out".into(),
            dir.path().display().to_string(),
            "--name".into(),
            name.clone(),
            "--format".into(),
            "svg".into(),
        ];
        args.extend(flags(&p, &set));
        run(dir.path(), &args);
        let rows = csv_rows(&dir.path().join(format!("{name}.csv")));
        let band: Vec<_> = rows.iter().filter(|r| r["layer"] == "band").collect();
        assert_eq!(band.len(), values.len(), "{args:?}");
        for (row, &v) in band.iter().zip(&values) {
            let q = apply(p, v);
            let found = answers_in_box(&q, &set, 21);
            let thetas: Vec<f64> = found.iter().map(|f| f.0).collect();
            let xs: Vec<f64> = found.iter().map(|f| f.1).collect();
            let t = interval(row, "band_theta_jam_lo_deg", "band_theta_jam_hi_deg");
            let x = interval(row, "band_x_jam_lo_mm", "band_x_jam_hi_mm");
            let mut why = check("theta_jam_deg", t, &thetas, 1e-6, 1e-5);
            why.extend(check("x_jam_mm", x, &xs, 1e-6, 1e-5));
            if !why.is_empty() {
                broken.push(format!("{args:?} at {param} = {v}: {why:?}"));
            }
        }
    }
    println!(
        "{sweeps} random sweeps of 31 values: {} band rows break the promise",
        broken.len()
    );
    assert!(broken.is_empty(), "{}", broken.join("\n"));
}

/// A jam map's band keeps its promise cell by cell: a cell is `jam` where the disc is held at
/// that palm angle at every point of the box, `slide` where at none, `uncertain` where at some
/// and not at others (the statics' margin at the cell's angle, on a grid of the box that holds
/// its corners). Random scenes and boxes of the mass and the push over fig3's (mu, theta) map,
/// through the real binary.
#[test]
fn every_cell_of_a_random_jam_maps_band_is_what_the_box_makes_it() {
    let dir = tempfile::tempdir().unwrap();
    let mut d = Draw::new(31);
    let mut broken = Vec::new();
    let maps = 20;
    let (nx, ny) = (31, 31);
    for k in 0..maps {
        let p = boxes::scene(&mut d);
        let n_inputs = if d.chance(0.5) { 1 } else { 2 };
        let picked: Vec<usize> = if n_inputs == 1 {
            vec![d.pick(&[3, 4])]
        } else {
            vec![3, 4]
        };
        let set = UncertainSet {
            inputs: picked
                .iter()
                .map(|&i| {
                    let (name, keys, _) = INPUTS[i];
                    let (lo, hi) = boxes::range(&mut d, name);
                    UncertainInput {
                        name,
                        keys: keys.to_vec(),
                        value: Uncertain::Range { lo, hi },
                    }
                })
                .collect(),
        };
        let (y_min, y_max, log) = match d.chance(0.5) {
            true => (10.0, 70.0, true),
            false => (0.5, 179.5, false),
        };
        let (x_min, x_max) = (0.02, 1.2);
        let set_arg = |k: &str, v: String| ["--set".to_string(), format!("{k}={v}")];
        let mut args = vec!["render".to_string(), "fig3".into()];
        for (key, v) in [
            ("radius_mm", p.radius_mm),
            ("mass_kg", p.mass_kg),
            ("force_n", p.force_n),
            ("start_angle_deg", p.start_angle_deg),
            ("palm_length_mm", p.palm_length_mm),
            ("palm_offset_mm", p.palm_offset_mm),
        ] {
            if !set.inputs.iter().any(|i| i.name == key) {
                args.extend(set_arg(key, format!("{v:?}")));
            }
        }
        for i in &set.inputs {
            args.extend(set_arg(i.name, format!("\"{}\"", i.value)));
        }
        args.extend(set_arg(
            "chart.x_axis",
            format!("{{param = \"mu\", min = {x_min:?}, max = {x_max:?}, count = {nx}}}"),
        ));
        args.extend(set_arg("chart.y_axis", format!(
            "{{param = \"theta_deg\", min = {y_min:?}, max = {y_max:?}, count = {ny}, scale = \"{}\"}}",
            if log { "log" } else { "linear" }
        )));
        let out = dir.path().join(format!("map{k}"));
        args.extend([
            "--out".into(),
            out.display().to_string(),
            "--format".into(),
            "svg".into(),
        ]);
        run(dir.path(), &args);
        let rows = csv_rows(&out.join("fig3.csv"));
        assert_eq!(rows.len(), nx * ny, "{args:?}");
        let (xs, ys) = (
            spaced(x_min, x_max, nx, false),
            spaced(y_min, y_max, ny, log),
        );
        let n: usize = if set.inputs.len() == 1 { 21 } else { 11 };
        let ends: Vec<(f64, f64)> = set.inputs.iter().map(|i| i.value.ends()).collect();
        let grid: Vec<Vec<f64>> = (0..n.pow(set.inputs.len() as u32))
            .map(|flat| {
                ends.iter()
                    .enumerate()
                    .map(|(i, &(lo, hi))| {
                        let j = flat / n.pow(i as u32) % n;
                        lo + (hi - lo) * j as f64 / (n - 1) as f64
                    })
                    .collect()
            })
            .collect();
        for (c, row) in rows.iter().enumerate() {
            let (mu, theta) = (xs[c % nx], ys[c / nx]);
            let read = |k: &str| row[k].parse::<f64>().unwrap();
            assert!(
                (read("mu") - mu).abs() <= 1e-6 * mu
                    && (read("theta_deg") - theta).abs() <= 1e-6 * theta
            );
            let region = row["region"].as_str();
            if region == "beyond_reach" {
                continue;
            }
            let held: Vec<bool> = grid
                .iter()
                .map(|v| {
                    let q = set.apply(&p.with_mu(mu), v);
                    held_at(&q, theta.to_radians())
                })
                .collect();
            let (some, all) = (held.iter().any(|&h| h), held.iter().all(|&h| h));
            let want = match (some, all) {
                (_, true) => "jam",
                (false, _) => "slide",
                _ => "uncertain",
            };
            if region != want {
                broken.push(format!(
                    "{args:?}: cell mu = {mu}, theta = {theta}: {region}, the box says {want}"
                ));
            }
        }
    }
    println!(
        "{maps} random jam maps of {nx} x {ny} cells: {} cells break the promise",
        broken.len()
    );
    assert!(
        broken.is_empty(),
        "{}",
        broken[..broken.len().min(20)].join("\n")
    );
}

/// `n` values from `min` to `max` (both exactly), evenly spaced or, with `log`, in equal ratios:
/// a chart axis's samples.
fn spaced(min: f64, max: f64, n: usize, log: bool) -> Vec<f64> {
    (0..n)
        .map(|i| match i + 1 == n {
            true => max,
            false if log => min * (max / min).powf(i as f64 / (n - 1) as f64),
            false => min + (max - min) * (i as f64 / (n - 1) as f64),
        })
        .collect()
}

/// Whether the ground holds the disc at palm angle `theta` (rad) by the corrected Eq. 1: the
/// sliding palm pushes F along the edge of its friction cone, so the ground's reaction is
/// R_t = F sin(theta - alpha_p) and R_n = m g + F cos(theta - alpha_p), and it holds where
/// R_t <= mu_g R_n.
fn held_at(p: &SceneParams, theta: f64) -> bool {
    let push = theta - p.mu_palm.atan();
    let (r_t, r_n) = (
        p.force_n * push.sin(),
        p.mass_kg * p.gravity_m_s2 + p.force_n * push.cos(),
    );
    p.mu_ground * r_n - r_t >= 0.0
}
