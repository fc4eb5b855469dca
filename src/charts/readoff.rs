//! What the gallery's read-off needs of a chart, embedded in `index.html` as JSON: where each
//! plotting area lies in the picture, its axes (range and scale) and the chart's own data.
//!
//! A page opened from disk cannot fetch its CSV, so the page carries this instead; it stays
//! small: a jam map gives its boundary per column and the rule that turns it into a status
//! (not its 160k cells), a sweep its curves. The frames come from the drawing itself
//! ([`super::axes::record_frames`]), so pointer and picture cannot disagree.
//!
//! Shape (`kind` decides the data keys):
//! ```text
//! { "kind": "jam_map" | "sweep" | "grid" | "panels" | "points", "x": AXIS,
//!   "panels": [{ "frame": { "left", "top", "right", "bottom" }, "y": AXIS, "quantity"?,
//!                "x"?: AXIS, "sweep"?: INDEX }],
//!   jam_map: "model", "columns": { PARAM, "theta_jam_deg", "x_jam_mm", "status", "reach_deg" },
//!            "disc": { "radius_mm", "palm_offset_mm", "palm_length_mm" }
//!   sweep:   "series": [{ "label", "layer", "line", "at", "x_jam_mm", "theta_jam_deg" }]
//!   grid:    "model", "grid": { "x": [..], "y": [..], "cells": { QUANTITY: [..] } }
//!   panels:  "model", "sweeps": [{ "param", "at": [..], "fixed": { KEY: VALUE },
//!                                  "series": [{ "label", KEY: VALUE, QUANTITY: [..] }] }] }
//!   points:  "rows": [ROW], "crosshair": bool, "cell"?: [W, H];
//!            each panel "x": AXIS, "points": [[x, y, ROW INDEX]]
//! AXIS = { "param", "label", "min", "max", "log" }   (an empty "param": no quantity, not printed)
//! ```
//! `panels` is a figure of stacked panels whose x axes differ (the V-locator's optimum and
//! robust charts, no top-level `x`): each panel has its own x axis and reads the sweep
//! `sweep` names; the page reads the panel under the pointer, every quantity of every series
//! at the pointer's x (straight between samples, as the curves are drawn), and lists the
//! sweep's fixed inputs beside them.
//! `points` is a chart of discrete points whose data is a table (the convergence trace, the
//! work-precision chart, the stability matrix): the page reads the point of the panel nearest
//! the pointer (distance in fractions of the plotting area) and shows its whole row, the row
//! of the chart's data file (CSV cells as their text, so the page and the file agree to the
//! digit); `crosshair` false where lines to the axes mean nothing (the matrix's cells), and
//! `cell` the size of a cell around each point in axis units, outlined when read.
//! A grid (the universal chart, contour maps) carries its cells, every k-th row and column so
//! that at most [`GRID_SAMPLES`] per axis, row by row (x fastest); the page interpolates
//! numbers bilinearly in plot space and gives a text (a status) of the nearest cell.
//!
//! A jam map's status at (v, theta): `beyond_reach` when theta < reach_deg(v) (the contact lies
//! past the palm's end), else `jam` when theta <= theta_jam_deg(v) (margin >= 0), else `slide`.

use serde::Serialize;
use serde_json::{Value, json};

use super::axes::{PlotAxis, PlotFrame};
use crate::grid::AxisScale;

/// An axis as the read-off sees it: its parameter key, label, range and scale.
pub fn axis(param: &str, a: &PlotAxis) -> Value {
    json!({
        "param": param,
        "label": a.label,
        "min": a.min,
        "max": a.max,
        "log": a.scale == AxisScale::Log,
    })
}

/// One panel: its frame in the picture and its y axis (and the quantity it shows, if any).
pub fn panel(frame: &PlotFrame, y: Value, quantity: Option<&str>) -> Value {
    let mut p = json!({ "frame": frame, "y": y });
    if let Some(q) = quantity {
        p["quantity"] = q.into();
    }
    p
}

/// A panel of a `panels` read-off: [`panel`] with its own x axis and the index of the sweep
/// it reads.
pub fn sweep_panel(frame: &PlotFrame, x: Value, y: Value, quantity: &str, sweep: usize) -> Value {
    let mut p = panel(frame, y, Some(quantity));
    p["x"] = x;
    p["sweep"] = sweep.into();
    p
}

/// A panel of a `points` read-off: its frame, axes and points (x, y, index of the row).
pub fn points_panel(frame: &PlotFrame, x: Value, y: Value, points: &[(f64, f64, usize)]) -> Value {
    let mut p = panel(frame, y, None);
    p["x"] = x;
    p["points"] = points
        .iter()
        .filter(|(x, y, _)| x.is_finite() && y.is_finite())
        .map(|(x, y, i)| json!([x, y, i]))
        .collect();
    p
}

/// Most samples per axis of a grid read-off: 101 x 101 cells of three quantities at 7 digits
/// are about 300 kB of page, and the iso-lines they are read between are smooth (the browser
/// test measures the error against `solve`).
pub const GRID_SAMPLES: usize = 101;

/// A map's cells as the read-off carries them, every k-th row and column so that at most
/// [`GRID_SAMPLES`] per axis (cell (ix, iy) at flat index `iy * xs.len() + ix`): each
/// quantity's value per kept cell, row by row.
pub fn cells(xs: &[f64], ys: &[f64], quantities: &[(&str, &dyn Fn(usize) -> Value)]) -> Value {
    let picks = |n: usize| {
        let mut v: Vec<usize> = (0..n).step_by(n.div_ceil(GRID_SAMPLES).max(1)).collect();
        if v.last() != Some(&(n - 1)) {
            v.push(n - 1);
        }
        v
    };
    let (ixs, iys) = (picks(xs.len()), picks(ys.len()));
    let mut cells = serde_json::Map::new();
    for (name, at) in quantities {
        let values = iys
            .iter()
            .flat_map(|iy| ixs.iter().map(move |ix| (*ix, *iy)))
            .map(|(ix, iy)| at(iy * xs.len() + ix));
        cells.insert(name.to_string(), Value::Array(values.collect()));
    }
    json!({
        "x": ixs.iter().map(|i| xs[*i]).collect::<Vec<_>>(),
        "y": iys.iter().map(|i| ys[*i]).collect::<Vec<_>>(),
        "cells": cells,
    })
}

/// A column of optional numbers as JSON (`null` where there is none).
pub fn column<T: Serialize>(values: impl Iterator<Item = T>) -> Value {
    Value::Array(values.map(|v| json!(v)).collect())
}

/// `doc` with every number rounded to 7 significant digits: finer than any chart's resolution
/// (a pixel is 1e-3 of an axis), and `0.10200000000000001` becomes `0.102`, which keeps the
/// page small.
pub fn rounded(doc: Value) -> Value {
    match doc {
        Value::Number(n) => match n.as_f64() {
            Some(v) if n.is_f64() && v.is_finite() => json!(crate::csv_out::significant(v)),
            _ => Value::Number(n),
        },
        Value::Array(a) => Value::Array(a.into_iter().map(rounded).collect()),
        Value::Object(o) => Value::Object(o.into_iter().map(|(k, v)| (k, rounded(v))).collect()),
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charts::{Formats, SceneSource, render};

    /// The pixel of (x, y) in a `w` x `h` picture, through the read-off's first panel as the
    /// page maps it (frames are at pixel centres).
    fn pixel_of(doc: &Value, x: f64, y: f64, (w, h): (u32, u32)) -> (usize, usize) {
        let f = &doc["panels"][0]["frame"];
        let frac = |a: &Value, v: f64| {
            let (lo, hi) = (a["min"].as_f64().unwrap(), a["max"].as_f64().unwrap());
            match a["log"].as_bool().unwrap() {
                true => (v / lo).ln() / (hi / lo).ln(),
                false => (v - lo) / (hi - lo),
            }
        };
        let e = |k: &str| f[k].as_f64().unwrap();
        let u = e("left") + frac(&doc["x"], x) * (e("right") - e("left"));
        let v = e("bottom") - frac(&doc["panels"][0]["y"], y) * (e("bottom") - e("top"));
        (
            (u * f64::from(w) - 0.5).round() as usize,
            (v * f64::from(h) - 0.5).round() as usize,
        )
    }

    /// RGB of pixel (i, j) of a PNG.
    fn rgb_at(png_bytes: &[u8], (i, j): (usize, usize)) -> [u8; 3] {
        let mut r = png::Decoder::new(std::io::Cursor::new(png_bytes))
            .read_info()
            .unwrap();
        let palette = r.info().palette.clone().map(|p| p.into_owned());
        let width = r.info().width as usize;
        let mut buf = vec![0; r.output_buffer_size()];
        r.next_frame(&mut buf).unwrap();
        match palette {
            Some(p) => {
                let k = 3 * buf[j * width + i] as usize;
                [p[k], p[k + 1], p[k + 2]]
            }
            None => {
                let k = 3 * (j * width + i);
                [buf[k], buf[k + 1], buf[k + 2]]
            }
        }
    }

    /// The gallery had no read-off: its frames must put a value where the chart drew it.
    /// fig3 draws its own read-off (mu 0.4, theta_jam 44.6 deg) as a black dot of radius 5;
    /// mapped through the exported frame and axes, that point lands on the dot, at scale 1 and
    /// at scale 2 (a frame in logical px would be off by half the picture at scale 2).
    #[test]
    fn the_read_off_frame_puts_fig3s_jam_point_on_its_dot() {
        for (scale, w, h) in [(1.0, 1000, 950), (2.0, 2000, 1900)] {
            let mut scene = SceneSource::BuiltIn("fig3".into()).load(&[]).unwrap();
            scene.size.scale = scale;
            (scene.size.width_px, scene.size.height_px) = (w, h);
            let r = render(&scene, Formats::Png).unwrap();
            let doc: Value = serde_json::from_str(r.read_off.as_deref().unwrap()).unwrap();
            let data: Value = serde_json::from_slice(&r.data.bytes).unwrap();
            let (mu, theta) = (
                data["read_off"]["mu"].as_f64().unwrap(),
                data["read_off"]["theta_jam_deg"].as_f64().unwrap(),
            );
            let at = pixel_of(&doc, mu, theta, (w, h));
            let [r_, g, b] = rgb_at(r.png.as_deref().unwrap(), at);
            assert!(
                u32::from(r_) + u32::from(g) + u32::from(b) < 120,
                "scale {scale}: pixel {at:?} is {:?}, not the dot's ink",
                [r_, g, b]
            );
            // The frame's corner is the axis corner: (0.1, 10 deg) is on the frame's ink too.
            let corner = pixel_of(&doc, 0.1, 10.0, (w, h));
            let [r_, g, b] = rgb_at(r.png.as_deref().unwrap(), corner);
            assert!(
                u32::from(r_) + u32::from(g) + u32::from(b) < 200,
                "{corner:?}"
            );
        }
    }

    /// The time series, the min-norm trace, the work-precision chart and the stability matrix
    /// had no read-off: every built-in scene has one now, with a frame per panel inside the
    /// picture, and a `points` chart's points name rows it carries (the matrix, drawn without
    /// axes, records its frame itself: without it the read-off would be missing).
    #[test]
    fn every_built_in_scene_has_a_read_off_with_frames_and_rows() {
        for name in crate::charts::builtin::scene_names() {
            let scene = SceneSource::BuiltIn(name.clone()).load(&[]).unwrap();
            let r = render(&scene, Formats::Svg).unwrap();
            let doc: Value = serde_json::from_str(
                r.read_off
                    .as_deref()
                    .unwrap_or_else(|| panic!("{name} has no read-off")),
            )
            .unwrap();
            let panels = doc["panels"].as_array().unwrap();
            assert!(!panels.is_empty(), "{name}");
            for p in panels {
                let f = |k: &str| p["frame"][k].as_f64().unwrap();
                assert!(
                    0.0 <= f("left") && f("left") < f("right") && f("right") <= 1.0,
                    "{name}: {p}"
                );
                assert!(
                    0.0 <= f("top") && f("top") < f("bottom") && f("bottom") <= 1.0,
                    "{name}: {p}"
                );
                if doc["kind"] == "points" {
                    let rows = doc["rows"].as_array().unwrap().len();
                    let points = p["points"].as_array().unwrap();
                    assert!(!points.is_empty(), "{name}: a panel without points");
                    for pt in points {
                        assert!((pt[2].as_u64().unwrap() as usize) < rows, "{name}: {pt}");
                    }
                }
            }
        }
    }

    #[test]
    fn rounding_keeps_seven_significant_digits() {
        let doc = json!({ "a": [0.10200000000000001, 30.951435839204933, null, 3], "b": "x" });
        assert_eq!(
            rounded(doc).to_string(),
            r#"{"a":[0.102,30.95144,null,3],"b":"x"}"#
        );
    }
}
