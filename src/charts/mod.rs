//! Design charts: scenes (`charts/<name>.toml`) computed from the grid and models, drawn with
//! plotters to byte-identical SVG and PNG, with the data behind each chart.
//!
//! A scene is loaded ([`spec::load_scene`]), its chart computes only what its layers draw
//! ([`Chart::compute`]), then one backend-generic `draw` produces both the SVG and the PNG.
//! Bytes depend only on the scene: the font is embedded ([`style::init_fonts`]), the PNG has no
//! metadata ([`output::encode_png`]), nothing is random and every number that feeds a pixel is
//! computed the same way for any thread count.
//!
//! Chart kinds, one module each: [`jam_map`] (Fig. 3), [`sweep`] (Figs. 6, 7a, 7b),
//! [`contour_map`] (Fig. 7c), [`convergence`] (Fig. 4), [`time_series`] (Fig. 5),
//! [`work_precision`] (the accuracy study), [`stability`] (the stability matrix),
//! [`vlocator_capacity`] and [`vlocator_optimum`] (V-type locators, [`crate::locator`]);
//! [`error_time`] draws `jamchart accuracy`'s wall-time chart, which is not a scene. The last
//! three x-y kinds draw through [`xy`], stacked x-y
//! panels. Min-norm programs and simulations are called through `models::Models`, so a test
//! can count them: a scene computes only what it draws.
//!
//! ## Where the other models plug in
//!
//! - Points of a model on a sweep (Fig. 6: min-norm points, simulation points with motion and
//!   force drive): one [`sweep_layers::SweepLayer`] variant and its arm in
//!   [`sweep_layers::series`], returning [`sweep::Series`] of markers; legend, panels, data file
//!   and hashes follow.
//! - A model over a map (jam map boundary and read-off, contour map): nothing to do here. Maps
//!   name any model of the port ([`crate::models::ModelKind`]: `model = "min_norm"`) and call
//!   it per cell through `models::Models::solve`.
//! - A new chart kind: a module with a spec struct, `compute`, `data` and a backend-generic
//!   `draw` (x-y panels through [`xy::Figure`], as [`convergence`] and [`time_series`] do), a
//!   [`ChartSpec`] variant, a [`Chart`] variant and a scene `charts/<name>.toml`.

pub mod axes;
pub mod builtin;
pub mod contour_map;
pub mod convergence;
pub mod error_time;
pub mod gallery;
pub mod jam_map;
pub mod legend;
pub(crate) mod models;
pub mod output;
pub mod overrides;
pub mod spec;
pub mod stability;
pub mod style;
pub mod sweep;
pub mod sweep_layers;
pub mod time_series;
pub mod vlocator_capacity;
pub mod vlocator_optimum;
pub mod work_precision;
pub mod xy;

use geo_types::{MultiLineString, MultiPolygon};
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::csv_out::{Column, cells_summary, grid_cells};
use crate::error::{Error, Result};
use crate::grid::{GridAxis, GridParam};
use crate::model::SceneParams;
use axes::DrawResult;
pub use spec::{ChartSpec, Scene, SceneSource, load_scene, scene_files, scene_names};

/// Which pictures to produce.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formats {
    /// SVG only.
    Svg,
    /// PNG only.
    Png,
    /// SVG and PNG.
    Both,
}

impl Formats {
    /// Whether an SVG is wanted.
    pub fn svg(self) -> bool {
        self != Formats::Png
    }
    /// Whether a PNG is wanted.
    pub fn png(self) -> bool {
        self != Formats::Svg
    }
}

/// The data behind a chart: file extension and bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct DataFile {
    /// `csv` or `json`.
    pub extension: &'static str,
    /// The file content.
    pub bytes: Vec<u8>,
}

impl DataFile {
    /// Compact JSON of `doc` with a trailing newline.
    pub fn json(doc: &serde_json::Value) -> Self {
        let mut bytes = serde_json::to_vec(doc).expect("JSON values serialise");
        bytes.push(b'\n');
        DataFile {
            extension: "json",
            bytes,
        }
    }

    /// CSV bytes (see [`crate::csv_out`]).
    pub fn csv(bytes: Vec<u8>) -> Self {
        DataFile {
            extension: "csv",
            bytes,
        }
    }
}

/// One rendered scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Rendered {
    /// Scene name.
    pub name: String,
    /// SVG bytes, if requested.
    pub svg: Option<Vec<u8>>,
    /// PNG bytes, if requested.
    pub png: Option<Vec<u8>>,
    /// The data behind the chart.
    pub data: DataFile,
    /// A map's cells as long-format CSV (one row per cell), beside its JSON.
    pub cells: Option<DataFile>,
}

/// A computed chart of any kind.
#[allow(missing_docs)] // one variant per chart kind, documented on its module
pub enum Chart {
    JamMap(jam_map::JamMap),
    Sweep(sweep::Sweep),
    ContourMap(contour_map::ContourMap),
    Convergence(convergence::Convergence),
    TimeSeries(time_series::TimeSeries),
    WorkPrecision(work_precision::WorkPrecision),
    VlocatorCapacity(vlocator_capacity::VlocatorCapacity),
    VlocatorOptimum(vlocator_optimum::VlocatorOptimum),
    Stability(stability::Stability),
}

impl Chart {
    /// Computes what `scene`'s chart draws, with the model the scene names.
    pub fn compute(scene: &Scene) -> Result<Chart> {
        Self::compute_with(scene, &models::Live)
    }

    /// [`Chart::compute`] with the min-norm and dynamics calls going through `models`.
    pub(crate) fn compute_with(scene: &Scene, models: &dyn models::Models) -> Result<Chart> {
        Ok(match &scene.chart {
            ChartSpec::JamMap(s) => Chart::JamMap(jam_map::JamMap::compute(scene, s, models)?),
            ChartSpec::Sweep(s) => Chart::Sweep(sweep::Sweep::compute(scene, s, models)?),
            ChartSpec::ContourMap(s) => {
                Chart::ContourMap(contour_map::ContourMap::compute(scene, s, models)?)
            }
            ChartSpec::Convergence(s) => {
                Chart::Convergence(convergence::Convergence::compute(scene, s, models)?)
            }
            ChartSpec::TimeSeries(s) => {
                Chart::TimeSeries(time_series::TimeSeries::compute(scene, s, models)?)
            }
            ChartSpec::WorkPrecision(s) => {
                Chart::WorkPrecision(work_precision::WorkPrecision::compute(scene, s, models)?)
            }
            ChartSpec::VlocatorCapacity(s) => {
                Chart::VlocatorCapacity(vlocator_capacity::VlocatorCapacity::compute(scene, s)?)
            }
            ChartSpec::VlocatorOptimum(s) => {
                Chart::VlocatorOptimum(vlocator_optimum::VlocatorOptimum::compute(scene, s)?)
            }
            ChartSpec::Stability(s) => {
                Chart::Stability(stability::Stability::compute(scene, s, models)?)
            }
        })
    }

    /// Draws on any plotters backend.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        root.fill(&WHITE)?;
        match self {
            Chart::JamMap(c) => c.draw(root),
            Chart::Sweep(c) => c.draw(root),
            Chart::ContourMap(c) => c.draw(root),
            Chart::Convergence(c) => c.draw(root),
            Chart::TimeSeries(c) => c.draw(root),
            Chart::WorkPrecision(c) => c.draw(root),
            Chart::VlocatorCapacity(c) => c.draw(root),
            Chart::VlocatorOptimum(c) => c.draw(root),
            Chart::Stability(c) => c.draw(root),
        }
    }

    /// A map's cells as long-format CSV: the two parameters and each quantity per cell, units in
    /// the header; None for charts whose data is CSV already.
    pub fn cells(&self) -> Option<DataFile> {
        match self {
            Chart::JamMap(c) => c.cells(),
            Chart::ContourMap(c) => Some(c.cells()),
            _ => None,
        }
    }

    /// The data behind the chart.
    pub fn data(&self, scene: &Scene) -> DataFile {
        match self {
            Chart::JamMap(c) => c.data(scene),
            Chart::Sweep(c) => c.data(scene),
            Chart::ContourMap(c) => c.data(scene),
            Chart::Convergence(c) => c.data(scene),
            Chart::TimeSeries(c) => c.data(scene),
            Chart::WorkPrecision(c) => c.data(scene),
            Chart::VlocatorCapacity(c) => c.data(scene),
            Chart::VlocatorOptimum(c) => c.data(scene),
            Chart::Stability(c) => c.data(scene),
        }
    }
}

/// Computes and draws `scene` into the requested formats.
pub fn render(scene: &Scene, formats: Formats) -> Result<Rendered> {
    style::init_fonts();
    let chart = Chart::compute(scene)?;
    let (w, h) = (scene.size.width_px, scene.size.height_px);
    let draw_err = |m: String| Error::Draw {
        scene: scene.name.clone(),
        message: m,
    };
    let (svg, png) = rayon::join(
        || -> Result<Option<Vec<u8>>> {
            if !formats.svg() {
                return Ok(None);
            }
            let mut s = String::new();
            {
                let root = SVGBackend::with_string(&mut s, (w, h)).into_drawing_area();
                chart.draw(&root).map_err(|e| draw_err(e.to_string()))?;
                root.present().map_err(|e| draw_err(e.to_string()))?;
            }
            Ok(Some(s.into_bytes()))
        },
        || -> Result<Option<Vec<u8>>> {
            if !formats.png() {
                return Ok(None);
            }
            let mut rgb = vec![0u8; w as usize * h as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
                chart.draw(&root).map_err(|e| draw_err(e.to_string()))?;
                root.present().map_err(|e| draw_err(e.to_string()))?;
            }
            output::encode_png(&rgb, w, h).map(Some).map_err(draw_err)
        },
    );
    Ok(Rendered {
        name: scene.name.clone(),
        svg: svg?,
        png: png?,
        data: chart.data(scene),
        cells: chart.cells(),
    })
}

/// The symbol of a scene parameter in labels, e.g. `F` for force_n.
pub fn param_symbol(p: GridParam) -> &'static str {
    match p {
        GridParam::Mu => "μ",
        GridParam::MuGround => "μ_ground",
        GridParam::MuPalm => "μ_palm",
        GridParam::RadiusMm => "r",
        GridParam::MassKg => "m",
        GridParam::ForceN => "F",
        GridParam::GravityMS2 => "g",
        GridParam::StartAngleDeg => "θ_start",
        GridParam::PalmLengthMm => "L_palm",
        GridParam::ThetaDeg => "θ",
    }
}

/// The unit of a scene parameter in labels; `-` for the friction coefficients.
pub fn param_unit(p: GridParam) -> &'static str {
    match p {
        GridParam::Mu | GridParam::MuGround | GridParam::MuPalm => "-",
        GridParam::RadiusMm | GridParam::PalmLengthMm => "mm",
        GridParam::MassKg => "kg",
        GridParam::ForceN => "N",
        GridParam::GravityMS2 => "m/s²",
        GridParam::StartAngleDeg | GridParam::ThetaDeg => "deg",
    }
}

/// Axis label of a scene parameter: quantity, symbol and unit.
pub fn axis_label(p: GridParam) -> String {
    let quantity = match p {
        GridParam::Mu => "friction coefficient",
        GridParam::MuGround => "ground friction coefficient",
        GridParam::MuPalm => "palm friction coefficient",
        GridParam::RadiusMm => "disc radius",
        GridParam::MassKg => "disc mass",
        GridParam::ForceN => "palm push",
        GridParam::GravityMS2 => "gravity",
        GridParam::StartAngleDeg => "start angle of the palm",
        GridParam::PalmLengthMm => "palm length",
        GridParam::ThetaDeg => "palm angle",
    };
    // One mu stands for both contacts; the label says so.
    let symbol = match p {
        GridParam::Mu => "μ = μ_ground = μ_palm",
        _ => param_symbol(p),
    };
    format!("{quantity} {symbol} ({})", param_unit(p))
}

/// `symbol = value unit`, e.g. `F = 200 N`.
fn param_value(p: GridParam, v: f64) -> String {
    format!("{} = {v} {}", param_symbol(p), param_unit(p))
}

/// One line naming the scene's parameters for under the title, without the `swept` ones (they
/// are on an axis).
pub fn scene_subtitle(p: &SceneParams, swept: &[GridParam]) -> String {
    scene_subtitle_with("closed-form statics (corrected Eq. 1)", p, swept)
}

/// [`scene_subtitle`] naming another source than the closed form, e.g. "simulation, ...".
pub fn scene_subtitle_with(source: &str, p: &SceneParams, swept: &[GridParam]) -> String {
    let mu = if p.mu_ground == p.mu_palm {
        format!("μ = {}", p.mu_ground)
    } else {
        format!("μ_ground = {}, μ_palm = {}", p.mu_ground, p.mu_palm)
    };
    let shown = [
        GridParam::MassKg,
        GridParam::RadiusMm,
        GridParam::ForceN,
        GridParam::GravityMS2,
    ];
    let parts = std::iter::once((GridParam::Mu, mu)).chain(
        shown
            .into_iter()
            .filter_map(|k| k.get(p).map(|v| (k, param_value(k, v)))),
    );
    let kept: Vec<String> = parts
        .filter(|(k, _)| !swept.contains(k))
        .map(|(_, s)| s)
        .collect();
    format!("{source}: {}", kept.join(", "))
}

/// The cells of `grid` as long-format CSV: one row per cell (x fastest), the two axis values then
/// each `(column, values)` (see [`crate::csv_out::grid_cells`]).
pub fn cells_csv(
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Column)],
) -> DataFile {
    let (header, values) = cells_columns(x, y, columns);
    DataFile::csv(grid_cells(&header, &grid.x_values, &grid.y_values, &values))
}

/// What a map's JSON says about the cells [`cells_csv`] writes to `<scene>.csv` (see
/// [`crate::csv_out::cells_summary`]): the same column names.
pub fn cells_json(
    scene: &str,
    grid: &crate::grid::GridResult,
    x: GridParam,
    y: GridParam,
    columns: &[(&str, Column)],
) -> serde_json::Value {
    let (header, values) = cells_columns(x, y, columns);
    let file = format!("{scene}.csv");
    cells_summary(&file, &header, (grid.nx(), grid.ny()), &values)
}

fn cells_columns<'a, 'b>(
    x: GridParam,
    y: GridParam,
    columns: &[(&'a str, Column<'b>)],
) -> (Vec<&'a str>, Vec<Column<'b>>) {
    let mut header = vec![x.as_str(), y.as_str()];
    header.extend(columns.iter().map(|(name, _)| *name));
    (header, columns.iter().map(|(_, c)| *c).collect())
}

/// The exterior rings of contour polygons, mapped from the contour crate's grid coordinates to
/// plot space (ln for log axes). The crate puts sample i at the centre of cell [i, i + 1].
pub fn grid_polygons<P>(
    mp: &MultiPolygon<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
) -> Vec<Vec<(f64, f64)>> {
    mp.0.iter()
        .map(|poly| {
            poly.exterior()
                .0
                .iter()
                .map(|c| (grid_to_plot(c.x, xa), grid_to_plot(c.y, ya)))
                .collect()
        })
        .collect()
}

/// Plot-space coordinate of contour-crate grid coordinate `g` on axis `a`.
pub fn grid_to_plot<P>(g: f64, a: &GridAxis<P>) -> f64 {
    let (lo, hi) = match a.scale {
        crate::grid::AxisScale::Linear => (a.min, a.max),
        crate::grid::AxisScale::Log => (a.min.ln(), a.max.ln()),
    };
    lo + (hi - lo) * (g - 0.5) / (a.count - 1) as f64
}

/// Contour-crate polylines mapped to plot space, split where they run along the grid's border.
///
/// The crate closes every ring around the edge of the grid; those pieces are not iso-lines and
/// would be drawn on the frame.
pub fn grid_lines<P>(
    ml: &MultiLineString<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
) -> Vec<Vec<(f64, f64)>> {
    let (nx, ny) = (xa.count as f64, ya.count as f64);
    let on_border =
        |c: &geo_types::Coord<f64>| c.x <= 0.5 || c.x >= nx - 0.5 || c.y <= 0.5 || c.y >= ny - 0.5;
    let mut out = Vec::new();
    for ls in &ml.0 {
        let mut cur: Vec<(f64, f64)> = Vec::new();
        for w in ls.0.windows(2) {
            if on_border(&w[0]) && on_border(&w[1]) {
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
                continue;
            }
            if cur.is_empty() {
                cur.push((grid_to_plot(w[0].x, xa), grid_to_plot(w[0].y, ya)));
            }
            cur.push((grid_to_plot(w[1].x, xa), grid_to_plot(w[1].y, ya)));
        }
        if cur.len() > 1 {
            out.push(cur);
        }
    }
    out
}

#[cfg(test)]
mod tests;
