use std::path::{Path, PathBuf};

use super::jam_map::JamMapLayer;
use super::*;
use crate::grid::Statics;

fn charts_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("charts")
}

fn fig3() -> Scene {
    load_scene(&charts_dir(), "fig3").expect("fig3 loads")
}

/// The read-off fig3 labels is the closed form of ERRATA.md: 44.646 deg, 24.355 mm (+-5e-4).
#[test]
fn fig3_reads_off_the_errata_values() {
    let scene = fig3();
    let Chart::JamMap(map) = Chart::compute(&scene).unwrap() else {
        panic!("fig3 is a jam map")
    };
    let doc: serde_json::Value = serde_json::from_slice(&map.data(&scene).bytes).unwrap();
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
    // >= 400 x 400 cells, as the issue asks.
    let m = &doc["margin_n"];
    assert!(m["nx"].as_u64().unwrap() >= 400 && m["ny"].as_u64().unwrap() >= 400);
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
        &Statics,
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
    let Chart::JamMap(map) = Chart::compute(&scene).unwrap() else {
        panic!("jam map")
    };
    let doc: serde_json::Value = serde_json::from_slice(&map.data(&scene).bytes).unwrap();
    assert!(doc["margin_n"].is_null() && doc["read_off"].is_null());
    assert_eq!(doc["boundary"].as_array().unwrap().len(), 401);
}

#[test]
fn every_committed_scene_loads() {
    let names = scene_names(&charts_dir()).unwrap();
    for want in ["fig3", "fig6", "fig7a", "fig7b", "fig7c"] {
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
                axis = { param = \"force_n\", min = 50.0, max = 100.0, count = 3 }\n\
                layers = [\"paper_table1\"]\n";
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let msg = load_scene(dir.path(), "s").unwrap_err().to_string();
    assert!(msg.contains("chart.layers") && msg.contains("mu"), "{msg}");
}
