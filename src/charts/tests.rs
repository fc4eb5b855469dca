use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use super::*;
use crate::dynamics::DynamicsParams;
use crate::dynamics::accuracy::{Study, StudySettings};
use crate::figures::jam_map::JamMapLayer;
use crate::figures::models::{Live, Models};
use crate::figures::sweep_layers::{self, SweepLayer};
use crate::minnorm::tolerance::ToleranceRow;
use crate::minnorm::{ContactSolution, MinNormSettings};
use crate::models::{ModelKind, ModelSpec, Solution};
use crate::scene::SceneParams;
use picture::Picture;

fn charts_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("charts")
}

fn fig3() -> Scene {
    load_scene(&charts_dir(), "fig3").expect("fig3 loads")
}

/// The read-off fig3 labels is the corrected Eq. 1 (crate docs): 44.646 deg, 24.355 mm (+-5e-4).
#[test]
fn fig3_reads_off_the_errata_values() {
    let scene = fig3();
    let Chart::JamMap(map) = Chart::of_scene(&scene).unwrap() else {
        panic!("fig3 is a jam map")
    };
    let doc: serde_json::Value =
        serde_json::from_slice(&map.data_file(&scene.name, &scene.title).bytes).unwrap();
    let r = &doc["read_off"];
    let (t, x) = (
        r["theta_jam_deg"].as_f64().unwrap(),
        r["x_jam_mm"].as_f64().unwrap(),
    );
    assert!(
        (t - 44.646).abs() < 5e-4 && (x - 24.355).abs() < 5e-4,
        "{t} deg, {x} mm"
    );
    assert_eq!(r["mu"].as_f64(), Some(0.4));
    // >= 400 x 400 cells, fine enough to read the boundary off.
    let m = &doc["cells"];
    assert!(m["nx"].as_u64().unwrap() >= 400 && m["ny"].as_u64().unwrap() >= 400);
    assert_eq!(doc["cells_file"], "fig3.csv");
}

/// The margin grid's jam cells lie exactly below the closed-form boundary of their column.
#[test]
fn fig3_regions_agree_with_the_boundary() {
    let scene = fig3();
    let ChartSpec::JamMap(spec) = &scene.chart else {
        panic!("jam map")
    };
    let g = crate::grid::evaluate(
        &crate::grid::GridRequest {
            base: scene.params,
            x: spec.x_axis,
            y: spec.y_axis,
            quantities: vec![crate::grid::Quantity::MarginN],
        },
        crate::grid::statics_point,
    )
    .unwrap();
    let m = g.margin_n.as_ref().unwrap();
    let mut wrong = 0;
    for (ix, &mu) in g.x_values.iter().enumerate() {
        let tj = crate::statics::solve(&scene.params.with_mu(mu))
            .theta_jam_deg
            .unwrap();
        for (iy, &t) in g.y_values.iter().enumerate() {
            // Cells within 1e-9 deg of the boundary may round either way.
            if (t - tj).abs() > 1e-9 && (m[g.index(ix, iy)] > 0.0) != (t < tj) {
                wrong += 1;
            }
        }
    }
    assert_eq!(wrong, 0, "cells on the wrong side of theta_jam");
}

/// A scene computes only what it draws: without the regions layer no grid is evaluated.
#[test]
fn jam_map_without_regions_evaluates_no_grid() {
    let mut scene = fig3();
    let ChartSpec::JamMap(spec) = &mut scene.chart else {
        panic!("jam map")
    };
    spec.layers = vec![JamMapLayer::Boundary];
    let Chart::JamMap(map) = Chart::of_scene(&scene).unwrap() else {
        panic!("jam map")
    };
    let doc: serde_json::Value =
        serde_json::from_slice(&map.data_file(&scene.name, &scene.title).bytes).unwrap();
    assert!(doc["cells"].is_null() && doc["read_off"].is_null());
    assert_eq!(doc["boundary"].as_array().unwrap().len(), 401);
}

#[test]
fn every_committed_scene_loads() {
    let names = scene_names(&charts_dir()).unwrap();
    for want in [
        "fig3",
        "fig4",
        "fig5",
        "fig6",
        "fig7a",
        "fig7b",
        "fig7c",
        "integration-error",
        "stability-matrix",
    ] {
        assert!(
            names.iter().any(|n| n == want),
            "{want} missing from {names:?}"
        );
    }
    for n in names {
        load_scene(&charts_dir(), &n).unwrap_or_else(|e| panic!("{n}: {e}"));
    }
}

#[test]
fn paper_points_on_a_non_mu_sweep_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("base.toml"), "").unwrap();
    let text = "title = \"t\"\nbase = \"base.toml\"\n[chart]\nkind = \"sweep\"\n\
                x_axis = { param = \"force_n\", min = 50.0, max = 100.0, count = 3 }\n\
                layers = [\"paper_table1\"]\n";
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let msg = load_scene(dir.path(), "s").unwrap_err().to_string();
    assert!(msg.contains("chart.layers") && msg.contains("mu"), "{msg}");
}

/// A contour map with x = mu and y = force_n drew "mu ≈ 0 : x_jam within 1 % of r/μ →" and a
/// legend saying "to the right": the settle line assumed force_n on x. Other x axes are refused.
#[test]
fn settle_line_without_force_on_x_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("base.toml"), "").unwrap();
    let scene = |x: &str, y: &str| {
        format!(
            "title = \"t\"\nbase = \"base.toml\"\n[chart]\nkind = \"contour_map\"\n\
             x_axis = {{ {x}, count = 3 }}\ny_axis = {{ {y}, count = 3 }}\n\
             x_jam_levels_mm = [30.0]\nsettle_pct = 1.0\n"
        )
    };
    let (mu, force) = (
        "param = \"mu\", min = 0.2, max = 0.6",
        "param = \"force_n\", min = 50.0, max = 500.0",
    );
    std::fs::write(dir.path().join("bad.toml"), scene(mu, force)).unwrap();
    let msg = load_scene(dir.path(), "bad").unwrap_err().to_string();
    assert!(
        msg.contains("chart.settle_pct") && msg.contains("x_axis.param = mu"),
        "{msg}"
    );
    std::fs::write(dir.path().join("good.toml"), scene(force, mu)).unwrap();
    load_scene(dir.path(), "good").unwrap();
}

/// Counts the model calls of a chart, delegating to the models themselves; with
/// `fail_dynamics_below_mu`, every simulation below that mu answers that it cannot run the
/// scene instead.
#[derive(Default)]
struct Counting {
    min_norm: AtomicUsize,
    traces: AtomicUsize,
    tolerance_studies: AtomicUsize,
    simulations: AtomicUsize,
    accuracy_studies: AtomicUsize,
    fail_dynamics_below_mu: Option<f64>,
}

impl Counting {
    fn counts(&self) -> [usize; 5] {
        [
            &self.min_norm,
            &self.traces,
            &self.tolerance_studies,
            &self.simulations,
            &self.accuracy_studies,
        ]
        .map(|c| c.load(Ordering::Relaxed))
    }
}

fn bump(c: &AtomicUsize) {
    c.fetch_add(1, Ordering::Relaxed);
}

impl Models for Counting {
    fn solve(&self, spec: &ModelSpec, p: &SceneParams) -> Result<Solution> {
        match spec.kind() {
            ModelKind::MinNorm => bump(&self.min_norm),
            ModelKind::Dynamics => {
                bump(&self.simulations);
                if self
                    .fail_dynamics_below_mu
                    .is_some_and(|mu| p.mu_ground < mu)
                {
                    return Ok(Solution {
                        model: ModelKind::Dynamics,
                        status: crate::scene::JamStatus::OutsideModel,
                        theta_jam_deg: None,
                        x_jam_mm: None,
                        elapsed_s: 0.0,
                        detail: crate::models::Detail::Outside(
                            crate::models::OutsideModel::NeedsMass { mass_kg: 0.0 },
                        ),
                    });
                }
            }
            // The closed form is cheap; it is not what the scene principle guards.
            ModelKind::Statics => {}
        }
        Live.solve(spec, p)
    }
    fn min_norm_column(
        &self,
        spec: &ModelSpec,
        scenes: &[SceneParams],
    ) -> Result<Vec<crate::grid::JamPoint>> {
        self.min_norm.fetch_add(scenes.len(), Ordering::Relaxed);
        Live.min_norm_column(spec, scenes)
    }
    fn min_norm_trace(
        &self,
        p: &SceneParams,
        theta_deg: f64,
        s: &MinNormSettings,
    ) -> Result<ContactSolution> {
        bump(&self.traces);
        Live.min_norm_trace(p, theta_deg, s)
    }
    fn min_norm_tolerances(
        &self,
        p: &SceneParams,
        s: &MinNormSettings,
        tolerances: &[f64],
    ) -> Result<Vec<ToleranceRow>> {
        bump(&self.tolerance_studies);
        Live.min_norm_tolerances(p, s, tolerances)
    }
    fn accuracy_study(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        s: &StudySettings,
    ) -> Result<Study> {
        bump(&self.accuracy_studies);
        Live.accuracy_study(p, d, s)
    }
}

/// The scene principle: a scene computes only what it draws. Each committed scene's model calls
/// are counted: [min-norm solves, clarabel traces, min-norm tolerance studies, simulations,
/// integrator studies]. fig3 and fig7 build no program and no simulation; fig4 runs no
/// simulation; fig5 runs one and no program; fig6 one per drawn point.
#[test]
fn every_scene_makes_only_the_model_calls_it_draws() {
    let sim_points = 2 * sweep_layers::SIMULATION_MU.len();
    let expected = |name: &str| -> [usize; 5] {
        match name {
            "fig3" | "fig7a" | "fig7b" | "fig7c" | "universal" => [0; 5],
            // The exact answer of the closed form, no model call.
            "jam-probability" | "universal-range" => [0; 5],
            // The V-locator scenes use the locator's exact path, no palm-scene model.
            "vlocator-capacity"
            | "vlocator-optimum"
            | "vlocator-robust"
            | "vlocator-robust-range" => [0; 5],
            "fig4" => [1, 1, 0, 0, 0],
            "fig5" => [0, 0, 0, 1, 0],
            "fig6" => [crate::paper::TABLE1.len(), 0, 0, sim_points, 0],
            "integration-error" => [0, 0, 1, 0, 1],
            // Every case through the two min-norm paths, the two integrators and the nonsmooth
            // method.
            "stability-matrix" => {
                let n = crate::study::stability::cases(&crate::config::Config::default()).len();
                [2 * n, 0, 0, 3 * n, 0]
            }
            other => panic!("add scene {other} to this test with the calls it should make"),
        }
    };
    for name in scene_names(&charts_dir()).unwrap() {
        let scene = load_scene(&charts_dir(), &name).unwrap();
        let counting = Counting::default();
        Chart::of_scene_with(&scene, &counting).unwrap();
        assert_eq!(
            counting.counts(),
            expected(&name),
            "scene {name}: [min-norm, traces, tolerance studies, simulations, accuracy studies]"
        );
    }
}

/// fig4's trace converges at the closed form's theta_jam, fig5's jam lies within 1.5 % of
/// r/mu = 25 mm (the accuracy asked of the dynamics at the defaults), as their labels say.
#[test]
fn fig4_and_fig5_draw_the_jam_of_the_paper_case() {
    let fig4 = load_scene(&charts_dir(), "fig4").unwrap();
    let Chart::Convergence(c) = Chart::of_scene(&fig4).unwrap() else {
        panic!("fig4 is a convergence chart")
    };
    let rows = &c.data().rows;
    assert!(rows.len() >= 3, "{rows:?}");
    let theta = rows[0].theta_deg.0;
    assert!((theta - 44.646).abs() < 5e-4, "trace at {theta} deg");
    let last = rows[rows.len() - 1];
    assert!(
        last.res_primal.0 < 1e-8 && last.res_dual.0 < 1e-8,
        "not converged: {last:?}"
    );

    let fig5 = load_scene(&charts_dir(), "fig5").unwrap();
    let Chart::TimeSeries(t) = Chart::of_scene(&fig5).unwrap() else {
        panic!("fig5 is a time series")
    };
    let (tj, xj) = t.data().jam.expect("fig5 jams");
    assert!((xj - 25.0).abs() < 0.015 * 25.0, "x_jam {xj} mm");
    let t_last = t.data().samples.last().unwrap().t_s.0;
    assert!(
        t_last > tj + 0.1,
        "the series ends at {t_last} s, the jam is at {tj} s"
    );
}

/// Fig. 4's note called the minimum the corrected Eq. 1 force "(ERRATA)", naming a file that
/// is not in the repository; the corrections are listed in the crate docs, and the note points
/// there.
#[test]
fn fig4_points_at_the_corrections_in_the_crate_docs() {
    let fig4 = load_scene(&charts_dir(), "fig4").unwrap();
    let svg = String::from_utf8(render(&fig4, Formats::Svg).unwrap().svg.unwrap()).unwrap();
    assert!(!svg.contains("ERRATA"), "{svg}");
    assert!(svg.contains("corrections to the paper"), "{svg}");
}

/// The rolling layer's points lie on the F -> infinity line for equal frictions (minnorm docs:
/// theta_jam = 2 atan mu, x_jam = r/mu), to the bisection's 1e-9 rad (about 3e-8 mm here).
#[test]
fn rolling_points_lie_on_the_rigid_limit() {
    let scene = load_scene(&charts_dir(), "fig6").unwrap();
    let ChartSpec::Sweep(spec) = &scene.chart else {
        panic!("fig6 is a sweep")
    };
    let series = sweep_layers::series(
        SweepLayer::MinNormRolling,
        &spec.x_axis,
        &scene.input(),
        &Live,
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    for p in &series[0].points {
        let s = crate::statics::solve(&scene.params.with_mu(p.at));
        let (x, xr) = (p.x_jam_mm.unwrap(), s.x_rigid_mm.unwrap());
        let (t, tr) = (p.theta_jam_deg.unwrap(), s.theta_rigid_deg);
        worst = worst.max((x - xr).abs()).max((t - tr).abs());
    }
    assert_eq!(series[0].points.len(), crate::paper::TABLE1.len());
    assert!(worst < 1e-6, "worst difference {worst:e} (mm or deg)");
}

/// `style = "print"` draws in greys only: every pixel of the PNG has r = g = b, and the SVG
/// names no colour but greys (the capacity map has bands, hatching, dashed and dotted lines).
#[test]
fn print_style_draws_greys_only() {
    let settings = ["style=print".parse().unwrap()];
    for name in ["fig7b", "vlocator-capacity"] {
        let scene = SceneSource::BuiltIn(name.into()).load(&settings).unwrap();
        assert_eq!(scene.style, print::Ink::Print);
        let r = render(&scene, Formats::Both).unwrap();
        let png = r.png.unwrap();
        let px = &rgb_pixels(&png);
        assert!(
            px.chunks_exact(3).all(|p| p[0] == p[1] && p[1] == p[2]),
            "{name}: a pixel is not grey"
        );
        let svg = String::from_utf8(r.svg.unwrap()).unwrap();
        for rgb in svg.split("#").skip(1).filter_map(|s| s.get(..6)) {
            if rgb.chars().all(|c| c.is_ascii_hexdigit()) {
                assert!(
                    rgb[..2] == rgb[2..4] && rgb[2..4] == rgb[4..],
                    "{name}: colour #{rgb}"
                );
            }
        }
    }
}

/// Regression: a sweep layer whose model failed at some of its points drew a gap that read as
/// "no jam there". The chart now names those points beside the layer.
#[test]
fn a_sweep_layer_that_failed_at_some_points_names_them() {
    let scene = load_scene(&charts_dir(), "fig6").unwrap();
    let ChartSpec::Sweep(spec) = &scene.chart else {
        panic!("fig6 is a sweep")
    };
    use SweepLayer::{SimulationForce, SimulationMotion};
    let failing = Counting {
        fail_dynamics_below_mu: Some(0.2),
        ..Counting::default()
    };
    for layer in [SimulationMotion, SimulationForce] {
        let s = &sweep_layers::series(layer, &spec.x_axis, &scene.input(), &failing).unwrap()[0];
        let note = s.callout.as_deref().unwrap_or_default();
        assert!(
            note.contains("no answer at μ = 0.175 ("),
            "{}: {note}",
            s.curve.name()
        );
        assert!(
            s.points.iter().any(|p| p.x_jam_mm.is_some()),
            "{}",
            s.curve.name()
        );
    }
    // Where the model answers everywhere there is no note.
    let s =
        &sweep_layers::series(SimulationMotion, &spec.x_axis, &scene.input(), &Live).unwrap()[0];
    assert_eq!(s.callout, None);
}

/// Where the polyline `path` (points (mu, F/(m g))) crosses the height `ratio`: its mu there,
/// interpolated in ln(ratio) as the chart's log axis draws it.
fn mu_at(path: &[serde_json::Value], ratio: f64) -> Option<f64> {
    let pt = |v: &serde_json::Value| (v[0].as_f64().unwrap(), v[1].as_f64().unwrap().ln());
    let y = ratio.ln();
    path.windows(2).find_map(|w| {
        let ((x0, y0), (x1, y1)) = (pt(&w[0]), pt(&w[1]));
        ((y0 - y) * (y1 - y) <= 0.0 && y0 != y1).then(|| x0 + (x1 - x0) * (y - y0) / (y1 - y0))
    })
}

/// The universal chart read as a designer reads it, from its iso-lines alone: the
/// example part (mu 0.27, r 12 mm, F 150 N, m 1 kg) lies between two 1-degree lines;
/// interpolating between them gives theta_jam within 0.1 deg of the closed form (31.2 deg) and
/// x_jam = r cot(theta_jam / 2) within 1 % (43.0 mm). The same chart serves another part with
/// the same mu and F / (m g): the lines do not move.
#[test]
fn the_universal_chart_reads_back_the_closed_form_for_any_part() {
    let set = |pairs: &[(&str, f64)]| -> Vec<overrides::Setting> {
        pairs
            .iter()
            .map(|(k, v)| format!("{k}={v}").parse().unwrap())
            .collect()
    };
    let read = |pairs: &[(&str, f64)]| {
        let scene = SceneSource::BuiltIn("universal".into())
            .load(&set(pairs))
            .unwrap();
        let Chart::Universal(u) = Chart::of_scene(&scene).unwrap() else {
            panic!("a universal chart")
        };
        let doc: serde_json::Value =
            serde_json::from_slice(&u.data_file(&scene.name, &scene.title).bytes).unwrap();
        (scene.params, doc)
    };
    let shaft = [
        ("mu", 0.27),
        ("radius_mm", 12.0),
        ("force_n", 150.0),
        ("mass_kg", 1.0),
    ];
    let (p, doc) = read(&shaft);
    let ratio = p.force_n / p.weight_n();
    // Each 1-degree line's mu at the shaft's F / (m g).
    let crossings: Vec<(f64, f64)> = doc["iso_lines"]["lines"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|l| {
            let t = l["theta_jam_deg"].as_f64().unwrap();
            let mu = l["paths"]
                .as_array()
                .unwrap()
                .iter()
                .find_map(|path| mu_at(path.as_array().unwrap(), ratio))?;
            Some((t, mu))
        })
        .collect();
    let below = crossings
        .iter()
        .filter(|(_, mu)| *mu <= 0.27)
        .max_by(|a, b| a.1.total_cmp(&b.1));
    let above = crossings
        .iter()
        .filter(|(_, mu)| *mu > 0.27)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let (&(t0, m0), &(t1, m1)) = (below.unwrap(), above.unwrap());
    assert_eq!(
        (t0, t1),
        (31.0, 32.0),
        "the shaft lies between the 31 and 32 deg lines"
    );
    let theta = t0 + (t1 - t0) * (0.27 - m0) / (m1 - m0);
    let x = p.radius_mm / (0.5 * theta.to_radians()).tan();
    let exact = crate::statics::solve(&p);
    let (te, xe) = (exact.theta_jam_deg.unwrap(), exact.x_jam_mm.unwrap());
    assert!(
        (te - 31.2).abs() < 0.05 && (xe - 43.0).abs() < 0.05,
        "{te} deg, {xe} mm"
    );
    assert!(
        (theta - te).abs() < 0.1,
        "read {theta} deg, closed form {te} deg"
    );
    assert!(
        ((x - xe) / xe).abs() < 0.01,
        "read {x} mm, closed form {xe} mm"
    );
    // Another part with the same mu and F / (m g): twice the mass and push, another radius.
    let other = [
        ("mu", 0.27),
        ("radius_mm", 30.0),
        ("force_n", 300.0),
        ("mass_kg", 2.0),
    ];
    let (_, doc2) = read(&other);
    assert_eq!(doc["iso_lines"], doc2["iso_lines"]);
    assert_eq!(
        doc2["read_off"]["push_ratio"],
        doc["read_off"]["push_ratio"]
    );
}

/// Regression: a jam map shaded the cells the palm cannot reach as JAM. On a 40 mm
/// palm (r = 10 mm) every palm angle below 2 atan(r / L) = 28.07 deg puts the contact past the
/// palm's end: those cells are `beyond_reach` in the CSV, the others jam or slide by the
/// margin's sign.
#[test]
fn jam_map_cells_beyond_the_palms_reach_are_their_own_class() {
    let set = settings(&[
        "palm_length_mm=40",
        "chart.x_axis.count=21",
        "chart.y_axis.count=31",
    ]);
    let scene = SceneSource::BuiltIn("fig3".into()).load(&set).unwrap();
    let chart = Chart::of_scene(&scene).unwrap();
    let csv = String::from_utf8(chart.cells().unwrap().to_bytes()).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("mu,theta_deg,region,margin_n"));
    let reach = 2.0 * (10.0_f64 / 40.0).atan().to_degrees();
    let mut seen = std::collections::BTreeSet::new();
    for row in lines {
        let f: Vec<&str> = row.split(',').collect();
        let (theta, margin): (f64, f64) = (f[1].parse().unwrap(), f[3].parse().unwrap());
        let want = if theta < reach {
            "beyond_reach"
        } else if margin >= 0.0 {
            "jam"
        } else {
            "slide"
        };
        assert_eq!(f[2], want, "{row}");
        seen.insert(f[2].to_string());
    }
    assert_eq!(seen.len(), 3, "all three classes on this map: {seen:?}");
}

/// A contour map over cells without a jam (a start past 90 deg is outside the model, a push
/// below about 3.6 N too weak) leaves them out of every band, says so in its legend, writes
/// no gap to the rigid limit for them (it wrote 100 %), and traces no iso-line along their
/// edge: each point of a theta_jam iso-line lies between cells
/// that all jam and whose theta_jam straddle its level. Those cells carried a stand-in below
/// every level, so each level under its neighbours' values ran along that edge, labelled, and
/// the cells were shaded as the lowest band. The lines' labels, which then sat at the lines'
/// top ends, are clear of one another.
#[test]
fn contour_lines_end_where_the_cells_stop_jamming() {
    let set = settings(&[
        "chart.y_axis.param=start_angle_deg",
        "chart.y_axis.min=60",
        "chart.y_axis.max=150",
        "chart.y_axis.count=30",
        "chart.x_axis.min=2",
        "chart.x_axis.count=40",
    ]);
    let scene = SceneSource::BuiltIn("fig7c".into()).load(&set).unwrap();
    let chart = Chart::of_scene(&scene).unwrap();
    let doc: serde_json::Value =
        serde_json::from_slice(&chart.data_file(&scene.name, &scene.title).bytes).unwrap();
    let csv = String::from_utf8(chart.cells().unwrap().to_bytes()).unwrap();
    // force_n, start_angle_deg, status, x_jam_mm, theta_jam_deg, gap per cell, x fastest.
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let (nx, ny) = (40, 30);
    assert_eq!(rows.len(), nx * ny);
    let theta: Vec<Option<f64>> = rows.iter().map(|r| r[4].parse().ok()).collect();
    let xs: Vec<f64> = rows[..nx].iter().map(|r| r[0].parse().unwrap()).collect();
    let ys: Vec<f64> = rows
        .iter()
        .step_by(nx)
        .map(|r| r[1].parse().unwrap())
        .collect();
    assert!(theta.iter().any(Option::is_none) && theta.iter().any(Option::is_some));
    // No gap to the rigid limit is claimed where there is no jam.
    for r in &rows {
        assert_eq!(r[3].is_empty(), r[5].is_empty(), "{r:?}");
    }
    // The samples on either side of `v` along an axis (one where `v` is a sample).
    let around = |axis: &[f64], v: f64| -> Vec<usize> {
        let tol = 1e-6 * (axis[axis.len() - 1] - axis[0]);
        match axis.iter().position(|a| (a - v).abs() <= tol) {
            Some(i) => vec![i],
            None => {
                let i = axis.iter().rposition(|a| *a < v).unwrap();
                vec![i, i + 1]
            }
        }
    };
    let mut points = 0;
    for line in doc["iso_lines"]["theta_jam_deg"].as_array().unwrap() {
        let level = line["level"].as_f64().unwrap();
        for path in line["paths"].as_array().unwrap() {
            for pt in path.as_array().unwrap() {
                let (x, y) = (pt[0].as_f64().unwrap(), pt[1].as_f64().unwrap());
                let cells: Vec<Option<f64>> = around(&ys, y)
                    .into_iter()
                    .flat_map(|j| around(&xs, x).into_iter().map(move |i| (i, j)))
                    .map(|(i, j)| theta[j * nx + i])
                    .collect();
                let ok = cells.iter().all(Option::is_some) && {
                    let v = cells.iter().flatten();
                    v.clone().any(|t| *t <= level) && v.clone().any(|t| *t >= level)
                };
                assert!(ok, "{level} deg line at ({x}, {y}): cells {cells:?}");
                points += 1;
            }
        }
    }
    assert!(points > 20, "{points} points");
    let svg = String::from_utf8(render(&scene, Formats::Svg).unwrap().svg.unwrap()).unwrap();
    assert!(
        svg.contains(
            "blank, no jam on the palm: the push is too weak to move the disc; \
                      outside the model"
        ),
        "the legend names the blank cells and why"
    );
    // The labels' boxes (white, 22 px high, in the plot) are clear of one another: the
    // theta_jam lines stop at 90 deg, short of their labels' staggered heights, and their
    // labels at the lines' top ends overlapped.
    let attr = |tag: &str, name: &str| -> f64 {
        let at = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        tag[at..].split('"').next().unwrap().parse().unwrap()
    };
    let boxes: Vec<[f64; 4]> = svg
        .split("<rect")
        .skip(1)
        .filter(|t| t.contains("fill=\"#FFFFFF\"") && attr(t, "height") == 22.0)
        .map(|t| {
            let (x, y) = (attr(t, "x"), attr(t, "y"));
            [x, y, x + attr(t, "width"), y + 22.0]
        })
        .collect();
    assert!(boxes.len() >= 5, "{boxes:?}");
    for (k, a) in boxes.iter().enumerate() {
        for b in &boxes[k + 1..] {
            let overlap = a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
            assert!(!overlap, "labels overlap: {a:?} {b:?}");
        }
    }
    // Pixels of the lowest band (every jam here is below the first level, 25 mm): with the
    // blank cells, under half of those of the same map up to 89 deg and from 5 N, where all
    // jam (the jams fill under a third of the wider map).
    let lowest = |set: &[overrides::Setting]| {
        let scene = SceneSource::BuiltIn("fig7c".into()).load(set).unwrap();
        let png = render(&scene, Formats::Png).unwrap().png.unwrap();
        let RGBColor(r, g, b) = style::band_colors(scene_levels(&scene) + 1)[0];
        let px = rgb_pixels(&png);
        px.chunks_exact(3).filter(|p| *p == [r, g, b]).count()
    };
    let all_jam = [
        set.clone(),
        settings(&["chart.y_axis.max=89", "chart.x_axis.min=5"]),
    ]
    .concat();
    let (some, all) = (lowest(&set), lowest(&all_jam));
    assert!(all > 10_000 && 2 * some < all, "{some} of {all} pixels");
}

/// `key=value` overrides, as `--set` takes them.
fn settings(pairs: &[&str]) -> Vec<overrides::Setting> {
    pairs.iter().map(|s| s.parse().unwrap()).collect()
}

/// The RGB bytes of a rendered PNG (an indexed PNG, `output::encode_png`'s smaller form, is
/// expanded).
pub(super) fn rgb_pixels(png: &[u8]) -> Vec<u8> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(png));
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    buf
}

/// The x_jam levels of a contour map scene.
fn scene_levels(scene: &Scene) -> usize {
    match Chart::of_scene(scene).unwrap() {
        Chart::ContourMap(c) => c.data().settings.x_jam_levels_mm.len(),
        _ => panic!("a contour map"),
    }
}
