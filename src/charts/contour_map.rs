//! Chart kind `contour_map` (Fig. 7c): iso-lines of x_jam and theta_jam over two parameters.
//!
//! The grid evaluator computes x_jam (and theta_jam, and the F -> infinity limit r/mu when the
//! "settle" line is drawn) on every cell; the `contour` crate turns them into filled bands and
//! iso-lines. The settle line is where x_jam comes within `settle_pct` % of its limit: beyond
//! it the push force no longer matters.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde::{Deserialize, Serialize};
use serde_json::json;

use super::axes::{self, DrawResult, PlotAxis};
use super::collide::PxBox;
use super::colorbar::ColorBar;
use super::data::CellsTable;
use super::labels;
use super::legend::{self, LegendEntry, Swatch};
use super::readoff;
use super::spec::Scene;
use super::style::{self, LineKind};
use super::typeset;
use super::{
    DataFile, axis_label, cells_csv, cells_json, grid_lines, grid_polygons, param_symbol,
    param_unit, scene_subtitle,
};
use crate::csv_out::{Column, Num, nums};
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::grid::{AxisScale, GridAxis, GridParam, GridRequest, GridResult, JamPoint, Quantity};
use crate::models::ModelKind;
use crate::scene::JamStatus;
use crate::scene::SceneParams;

/// `[chart]` keys of `kind = "contour_map"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContourMapSpec {
    /// Horizontal axis (a scene parameter).
    pub x_axis: GridAxis,
    /// Vertical axis (a scene parameter).
    pub y_axis: GridAxis,
    /// x_jam iso-line levels in mm, increasing; the bands between them are shaded (default:
    /// about eight round levels over the map's range).
    #[serde(default)]
    pub x_jam_levels_mm: Vec<f64>,
    /// theta_jam iso-line levels in deg (default: none).
    #[serde(default)]
    pub theta_jam_levels_deg: Vec<f64>,
    /// Draw where x_jam comes within this many percent of its F -> infinity limit
    /// (default: none; the paper's Fig. 7b discussion suggests 1).
    #[serde(default)]
    pub settle_pct: Option<f64>,
    /// The model whose x_jam and theta_jam are contoured (default: statics; the settle line's
    /// limit r/mu is always the statics').
    #[serde(default)]
    pub model: ModelKind,
    /// Draw the read-off at the scene's own values of both axes' parameters: line 1 up from
    /// the x axis, line 2 across from the y axis, and 3, the model's x_jam and theta_jam
    /// there, printed (default: false; `render fig7c --read-off force_n=150 --read-off
    /// radius_mm=12`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub read_off: bool,
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

impl super::kinds::Kind for ContourMapSpec {
    const CELLS: bool = true;
    type Chart = ContourMap;

    /// Checks the axes and levels.
    fn validate(&self, scene: &Scene) -> Result<()> {
        let base = &scene.params;
        if [self.x_axis.param, self.y_axis.param].contains(&GridParam::ThetaDeg) {
            return Err(Error::invalid(
                "chart.x_axis/y_axis",
                "theta_deg",
                "a contour map varies scene parameters",
            ));
        }
        let increasing =
            |v: &[f64]| v.windows(2).all(|w| w[0] < w[1]) && v.iter().all(|x| x.is_finite());
        if !increasing(&self.x_jam_levels_mm) {
            return Err(Error::invalid(
                "chart.x_jam_levels_mm",
                format!("{:?}", self.x_jam_levels_mm),
                "give finite, increasing levels",
            ));
        }
        if !increasing(&self.theta_jam_levels_deg) {
            return Err(Error::invalid(
                "chart.theta_jam_levels_deg",
                format!("{:?}", self.theta_jam_levels_deg),
                "levels must increase",
            ));
        }
        if let Some(s) = self.settle_pct
            && !(s.is_finite() && s > 0.0 && s < 100.0)
        {
            return Err(Error::invalid(
                "chart.settle_pct",
                s,
                "must lie in (0, 100) %",
            ));
        }
        // The settle line's label and legend read "F ≈ ...", "to the right": true only when the
        // push force runs along x (x_jam falls towards r/mu as F grows).
        if self.settle_pct.is_some() && self.x_axis.param != GridParam::ForceN {
            return Err(Error::invalid(
                "chart.settle_pct",
                format!("x_axis.param = {}", self.x_axis.param.as_str()),
                "the settle line needs force_n on the x axis; drop settle_pct or put force_n on x",
            ));
        }
        self.request(base).validate()
    }

    fn param_axes(&self) -> Vec<(&'static str, crate::grid::GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// With the read-off, the chart marks the scene's values of both axes' parameters.
    fn marks_scene_value(&self) -> bool {
        self.read_off
    }

    fn enable_read_off(&mut self) -> bool {
        self.read_off = true;
        true
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        let levels = [
            ("chart.x_jam_levels_mm", self.x_jam_levels_mm.len()),
            (
                "chart.theta_jam_levels_deg",
                self.theta_jam_levels_deg.len(),
            ),
        ];
        for (key, n) in levels {
            crate::limits::check_at_most(key, n, crate::limits::MAX_LEVELS, "levels")?;
        }
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::CONTOUR_MAP_CELL)
    }

    fn compute(
        &self,
        scene: &Scene,
        models: &dyn crate::figures::models::Models,
    ) -> Result<ContourMap> {
        ContourMap::compute(scene, self, models)
    }

    fn cells(chart: &ContourMap) -> Option<CellsTable<'_>> {
        Some(chart.cells())
    }
}

impl ContourMapSpec {
    fn request(&self, base: &SceneParams) -> GridRequest {
        let mut quantities = vec![Quantity::XJamMm];
        if !self.theta_jam_levels_deg.is_empty() {
            quantities.push(Quantity::ThetaJamDeg);
        }
        if self.settle_pct.is_some() {
            quantities.push(Quantity::XRigidMm);
        }
        GridRequest {
            base: *base,
            x: self.x_axis,
            y: self.y_axis,
            quantities,
        }
    }
}

/// About eight round levels (steps of 1, 2 or 5 times a power of ten) strictly inside the range
/// of the jammed cells of `values`; one level in the middle when the range is flat.
fn round_levels(values: &[f64]) -> Vec<f64> {
    let jammed = values.iter().copied().filter(|v| *v != NO_JAM);
    let (lo, hi) = jammed.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    if lo >= hi {
        return vec![if lo < f64::MAX { lo } else { 1.0 }];
    }
    let raw = (hi - lo) / 8.0;
    let decade = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * decade)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * decade);
    let first = (lo / step).floor() as i64 + 1;
    (first..)
        .map(|k| k as f64 * step)
        .take_while(|v| *v < hi)
        .collect()
}

/// The computed contour map.
#[derive(Debug, Clone)]
pub struct ContourMap {
    spec: ContourMapSpec,
    params: SceneParams,
    title: String,
    grid: GridResult,
    /// Percent gap (x_rigid - x_jam) / x_rigid per cell, when the settle line is drawn.
    gap_pct: Option<Vec<f64>>,
    /// The shaded x_jam bands in plot space, lowest first: the rings of each band.
    bands: Vec<Paths>,
    /// The x_jam iso-lines in plot space, (level in mm, paths).
    x_jam_lines: Vec<(f64, Paths)>,
    /// The theta_jam iso-lines in plot space, (level in deg, paths).
    theta_lines: Vec<(f64, Paths)>,
    /// The settle line in plot space.
    settle_lines: Vec<Paths>,
    /// The read-off at the scene's own (x, y) values, when asked for: (x, y, the model's point).
    read_off: Option<(f64, f64, JamPoint)>,
}

/// Width of the theta_jam iso-lines in px: as wide as the settle line they may run on
/// ([`LineKind::Dashed`]), so that drawn over it they stay visible.
const THETA_LINE_PX: u32 = 2;

/// Places along the x axis an x_jam label may take, beyond the three preferred ones: every
/// 1/20 of the plot's width (a label is about 1/15 of it wide).
const LABEL_PLACES: usize = 20;

/// Polylines or rings in plot space (ln for log axes).
pub(super) type Paths = Vec<Vec<(f64, f64)>>;

/// A value for cells where a model gives no jam: below every level, so they stay unshaded.
const NO_JAM: f64 = -1.0;

fn dense(v: &[Option<f64>]) -> Vec<f64> {
    v.iter().map(|x| x.unwrap_or(NO_JAM)).collect()
}

impl ContourMap {
    /// Evaluates the grid quantities the layers need.
    pub fn compute(scene: &Scene, spec: &ContourMapSpec, models: &dyn Models) -> Result<Self> {
        let model = spec.model.with(&scene.min_norm, &scene.dynamics);
        let grid = crate::figures::models::evaluate(models, &model, &spec.request(&scene.params))?;
        let gap_pct: Option<Vec<f64>> = match (&grid.x_jam_mm, &grid.x_rigid_mm) {
            (Some(x), Some(r)) => Some(
                x.iter()
                    .zip(r)
                    .map(|(x, r)| match (x, r) {
                        (Some(x), Some(r)) => 100.0 * (r - x) / r,
                        // No jam or no limit: far from settled.
                        _ => 100.0,
                    })
                    .collect(),
            ),
            _ => None,
        };
        // The marching squares run once here; `draw` only strokes (it runs once per format).
        let (xa, ya) = (&spec.x_axis, &spec.y_axis);
        let b = ContourBuilder::new(grid.nx(), grid.ny(), true);
        // Finite values and levels cannot fail; nothing is drawn if they ever did.
        let lines = |values: &[f64], levels: &[f64]| -> Vec<(f64, Paths)> {
            b.lines(values, levels)
                .unwrap_or_default()
                .into_iter()
                .map(|l| {
                    let t = l.threshold();
                    (t, grid_lines(&l.into_inner().0, xa, ya))
                })
                .collect()
        };
        let xj = dense(grid.x_jam_mm.as_deref().unwrap_or_default());
        let mut spec = spec.clone();
        if spec.x_jam_levels_mm.is_empty() {
            spec.x_jam_levels_mm = round_levels(&xj);
        }
        let levels = &spec.x_jam_levels_mm;
        // Bands: below the first level, between levels, above the last.
        let mut edges = vec![f64::MIN];
        edges.extend(levels);
        edges.push(f64::MAX);
        let bands = b
            .isobands(&xj, &edges)
            .unwrap_or_default()
            .iter()
            .map(|band| grid_polygons(band.geometry(), xa, ya))
            .collect();
        let x_jam_lines = lines(&xj, levels);
        let theta_lines = grid
            .theta_jam_deg
            .as_deref()
            .map(|tj| lines(&dense(tj), &spec.theta_jam_levels_deg))
            .unwrap_or_default();
        let settle_lines = match (&gap_pct, spec.settle_pct) {
            (Some(gap), Some(pct)) => lines(gap, &[pct]).into_iter().map(|(_, p)| p).collect(),
            _ => Vec::new(),
        };
        let read_off = match (
            spec.read_off,
            xa.param.get(&scene.params),
            ya.param.get(&scene.params),
        ) {
            (true, Some(u), Some(v)) => Some((u, v, models.jam_point(&model, &scene.params)?)),
            _ => None,
        };
        Ok(ContourMap {
            read_off,
            spec,
            params: scene.params,
            title: scene.title.clone(),
            grid,
            gap_pct,
            bands,
            x_jam_lines,
            theta_lines,
            settle_lines,
        })
    }

    /// The data behind the chart as JSON: the scene, the levels and the iso-lines drawn, as
    /// polylines of (x, y) axis values; the grids are in the long CSV beside it
    /// ([`ContourMap::cells`]), described under `cells`.
    pub fn data_file(&self, scene: &Scene) -> DataFile {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let lines = |levelled: &mut dyn Iterator<Item = (f64, &Paths)>| {
            levelled
                .map(|(level, paths)| {
                    let paths: Vec<Vec<[Num; 2]>> = paths
                        .iter()
                        .map(|p| {
                            p.iter()
                                .map(|&(u, v)| {
                                    [Num(plot_to_value(u, xa)), Num(plot_to_value(v, ya))]
                                })
                                .collect()
                        })
                        .collect();
                    json!({ "level": Num(level), "paths": paths })
                })
                .collect::<Vec<_>>()
        };
        let settle = self.spec.settle_pct.unwrap_or_default();
        let (x, y) = (xa.param, ya.param);
        DataFile::json(&json!({
            "scene": scene.name, "title": self.title, "params": self.params,
            "x_axis": self.spec.x_axis, "y_axis": self.spec.y_axis,
            "x_jam_levels_mm": nums(self.spec.x_jam_levels_mm.iter().copied()),
            "theta_jam_levels_deg": nums(self.spec.theta_jam_levels_deg.iter().copied()),
            "settle_pct": self.spec.settle_pct,
            "iso_lines": {
                "point": [x.as_str(), y.as_str()],
                "x_jam_mm": lines(&mut self.x_jam_lines.iter().map(|(l, p)| (*l, p))),
                "theta_jam_deg": lines(&mut self.theta_lines.iter().map(|(l, p)| (*l, p))),
                "gap_to_x_rigid_pct": lines(&mut self.settle_lines.iter().map(|p| (settle, p))),
            },
            "read_off": self.read_off.map(|(u, v, p)| json!({
                x.as_str(): Num(u), y.as_str(): Num(v), "status": p.status,
                "theta_jam_deg": p.theta_jam_deg.map(Num), "x_jam_mm": p.x_jam_mm.map(Num),
            })),
            "cells_file": format!("{}.csv", scene.name),
            "cells": cells_json(&scene.name, &self.grid, x, y, &self.columns()),
        }))
    }

    /// The cells as long-format CSV: the axis values, x_jam_mm and, where computed,
    /// theta_jam_deg and gap_to_x_rigid_pct.
    pub fn cells(&self) -> CellsTable<'_> {
        let (x, y) = (self.spec.x_axis.param, self.spec.y_axis.param);
        cells_csv(&self.grid, x, y, &self.columns())
    }

    /// The quantity columns of the cells, named as in JSON.
    fn columns(&self) -> Vec<(&'static str, Column<'_>)> {
        let g = &self.grid;
        let mut columns = Vec::new();
        columns.extend(
            g.x_jam_mm
                .as_deref()
                .map(|v| ("x_jam_mm", Column::Sparse(v))),
        );
        columns.extend(
            g.theta_jam_deg
                .as_deref()
                .map(|v| ("theta_jam_deg", Column::Sparse(v))),
        );
        columns.extend(
            self.gap_pct
                .as_deref()
                .map(|v| ("gap_to_x_rigid_pct", Column::Dense(v))),
        );
        columns
    }

    /// What the gallery's read-off needs (see [`super::readoff`]): the plotting area, the axes
    /// and the cells' x_jam and, where computed, theta_jam.
    pub fn read_off(&self, frames: &[axes::PlotFrame]) -> Option<serde_json::Value> {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let g = &self.grid;
        let column = |v: &[Option<f64>], i: usize| json!(v[i]);
        let mut quantities: Vec<(&str, &dyn Fn(usize) -> serde_json::Value)> = Vec::new();
        let (xj, tj) = (g.x_jam_mm.as_deref(), g.theta_jam_deg.as_deref());
        let xj_at = |i| column(xj.unwrap_or_default(), i);
        let tj_at = |i| column(tj.unwrap_or_default(), i);
        if xj.is_some() {
            quantities.push(("x_jam_mm", &xj_at));
        }
        if tj.is_some() {
            quantities.push(("theta_jam_deg", &tj_at));
        }
        Some(json!({
            "kind": "grid",
            "model": self.spec.model,
            "x": readoff::axis(xa.param.as_str(), &x),
            "panels": [readoff::panel(frames.first()?, readoff::axis(ya.param.as_str(), &y), None)],
            "grid": readoff::grid(g, &quantities),
        }))
    }

    /// Draws the map on `root`.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let entries = self.legend();
        // One band below the first level, one between each pair, one above the last.
        let colors = style::band_colors(self.spec.x_jam_levels_mm.len() + 1);
        let bar = ColorBar {
            colors: colors.clone(),
            levels: self
                .spec
                .x_jam_levels_mm
                .iter()
                .map(|v| level_text(*v))
                .collect(),
            title: "jam position x_jam (mm)".into(),
        };
        let chart = axes::band_map(root, &x, &y, &entries, &self.bands, &colors, &bar)?;
        let area = chart.plotting_area();
        let (px, py) = area.get_pixel_range();
        let xr = x.plot_range();
        // Right of the plot where lines are flat; further left for lines that leave the plot
        // there (near an edge); then anywhere along the line, right to left.
        let places: Vec<f64> = [0.86, 0.5, 0.1]
            .into_iter()
            .chain(
                (1..LABEL_PLACES)
                    .rev()
                    .map(|k| k as f64 / LABEL_PLACES as f64),
            )
            .map(|f| xr.start + f * (xr.end - xr.start))
            .collect();
        let crossing = self.crossing_lines(&chart);
        for (level, paths) in &self.x_jam_lines {
            for p in paths {
                style::draw_line(area, p, LineKind::Solid, LineKind::Solid.color())?;
            }
            let s = format!("{} mm", level_text(*level));
            let size = typeset::text_size(&s, style::TICK_PX);
            // Never on a theta_jam or settle line (fig7c's "25 mm" sat on the 46 deg line);
            // the first place found when every place is crossed.
            let found: Vec<(i32, i32)> = places
                .iter()
                .filter_map(|u| nearest_x(paths, *u, &chart, (&px, &py)))
                .collect();
            let clear = found.iter().find(|at| {
                let b = PxBox::centred(**at, size, axes::BOX_PAD);
                !crossing.iter().any(|l| b.meets_polyline(l))
            });
            if let Some(at) = clear.or(found.first()).copied() {
                axes::boxed_text(
                    root,
                    &s,
                    at,
                    Pos::new(HPos::Center, VPos::Center),
                    style::TICK_PX,
                )?;
            }
        }
        // The theta_jam lines over the settle line and as wide: near the F -> infinity limit
        // they run on it (fig7c: 44 deg on the 1 % line) and their dots show on its dashes.
        self.draw_settle_line(root, &chart, &y)?;
        self.draw_theta_lines(root, &chart, &y)?;
        self.draw_read_off(root, &chart, (&x, &y))?;
        axes::draw_frame(root, &chart, &x, &y)?;
        let sub = scene_subtitle(&self.params, &[xa.param, ya.param]);
        axes::draw_header(root, &self.title, &sub)?;
        legend::draw_legend(root, &entries, py.end + 62)
    }

    /// Whether the read-off is drawn: the scene's point lies on the map (a legend never names
    /// a line that is not drawn).
    fn read_off_drawn(&self) -> bool {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        self.read_off.is_some_and(|(u, v, _)| {
            (xa.min..=xa.max).contains(&u) && (ya.min..=ya.max).contains(&v)
        })
    }

    /// The read-off at the scene's point: lines 1 and 2 from the axes, and 3, the values
    /// there (or the model's verdict where it gives no jam).
    fn draw_read_off<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        axes: (&PlotAxis, &PlotAxis),
    ) -> DrawResult<DB> {
        let Some((u, v, p)) = self.read_off.filter(|_| self.read_off_drawn()) else {
            return Ok(());
        };
        let answer = match (p.x_jam_mm, p.theta_jam_deg) {
            (Some(x), Some(t)) if p.status == JamStatus::Jams => format!(
                "3: x_jam = {} mm, θ_jam = {}°",
                style::fmt_num(x, 1),
                style::fmt_num(t, 1)
            ),
            _ => format!("3: {}", p.status),
        };
        let place = super::point_read_off::AnswerAt::TowardsMiddle;
        super::point_read_off::draw(root, chart, axes, (u, v), &answer, place)
    }

    /// The theta_jam and settle lines in backend pixels: what an x_jam label must not sit on.
    fn crossing_lines<DB: DrawingBackend>(&self, chart: &axes::Chart<DB>) -> Vec<Vec<(i32, i32)>> {
        let theta = self.theta_lines.iter().flat_map(|(_, p)| p);
        theta
            .chain(self.settle_lines.iter().flatten())
            .map(|p| p.iter().map(|q| chart.backend_coord(q)).collect())
            .collect()
    }

    /// Dotted theta_jam iso-lines, labelled near the top, staggered so close lines stay legible.
    fn draw_theta_lines<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let levels = &self.spec.theta_jam_levels_deg;
        for (i, (level, paths)) in self.theta_lines.iter().enumerate() {
            for p in paths {
                style::draw_line_px(
                    chart.plotting_area(),
                    p,
                    LineKind::Dotted,
                    LineKind::Dotted.color(),
                    THETA_LINE_PX,
                )?;
            }
            let frac = 0.95 - 0.06 * (levels.len() - 1 - i) as f64;
            if let Some((_, at)) = at_height(paths, chart, y, frac) {
                let s = format!("θ_jam = {}°", level_text(*level));
                let pos = Pos::new(HPos::Left, VPos::Center);
                axes::boxed_text(root, &s, (at.0 + 5, at.1), pos, style::TICK_PX)?;
            }
        }
        Ok(())
    }

    /// The dashed line where x_jam comes within `settle_pct` % of r/mu, labelled with its value
    /// of the x-axis parameter (read off the contour near the bottom of the plot).
    fn draw_settle_line<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let Some(pct) = self.spec.settle_pct else {
            return Ok(());
        };
        let xa = &self.spec.x_axis;
        for paths in &self.settle_lines {
            for p in paths {
                style::draw_line(
                    chart.plotting_area(),
                    p,
                    LineKind::Dashed,
                    LineKind::Dashed.color(),
                )?;
            }
            let Some(((u, _), at)) = at_height(paths, chart, y, 0.06) else {
                continue;
            };
            let value = plot_to_value(u, xa);
            let s = format!(
                "{} ≈ {} {}: x_jam within {pct} % of {} →",
                param_symbol(xa.param),
                style::fmt_num(value, 0),
                param_unit(xa.param),
                self.rigid_limit_name()
            );
            axes::boxed_text(
                root,
                &s,
                (at.0 + 6, at.1),
                Pos::new(HPos::Left, VPos::Center),
                style::TICK_PX,
            )?;
        }
        Ok(())
    }

    /// The F -> infinity limit of x_jam: r/μ where the two frictions are equal everywhere on the
    /// map, r cot((α_g + α_p)/2) otherwise.
    fn rigid_limit_name(&self) -> &'static str {
        let axes = [self.spec.x_axis.param, self.spec.y_axis.param];
        let one_mu = self.params.mu_ground == self.params.mu_palm
            && !axes.contains(&GridParam::MuGround)
            && !axes.contains(&GridParam::MuPalm);
        if one_mu {
            "r/μ"
        } else {
            "r·cot((α_g + α_p)/2)"
        }
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let mut e = vec![LegendEntry::new(
            Swatch::Line(LineKind::Solid),
            "x_jam iso-lines (mm), bands as in the colour bar",
        )];
        // Only where a line is drawn: at mu = 0.27 fig7c's 44-47 deg levels lie off the map.
        if self.theta_lines.iter().any(|(_, p)| !p.is_empty()) {
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Dotted, LineKind::Dotted.color(), THETA_LINE_PX),
                "θ_jam iso-lines (deg)",
            ));
        }
        if let Some(p) = self.spec.settle_pct {
            let s = format!(
                "x_jam within {p} % of its F → ∞ limit {} to the right: F no longer matters",
                self.rigid_limit_name()
            );
            e.push(LegendEntry::new(Swatch::Line(LineKind::Dashed), s));
        }
        if let Some((u, v, _)) = self.read_off.filter(|_| self.read_off_drawn()) {
            let (x, y) = (self.spec.x_axis.param, self.spec.y_axis.param);
            let s = format!(
                "read-off 1-2-3 at {}, {}",
                labels::param_value(x, u),
                labels::param_value(y, v)
            );
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Dotted, style::INK, 2),
                s,
            ));
        }
        e
    }
}

/// The backend pixel of the path point whose plot-x is nearest `u`, if inside the plot.
fn nearest_x<DB: DrawingBackend>(
    paths: &[Vec<(f64, f64)>],
    u: f64,
    chart: &axes::Chart<DB>,
    (px, py): (&std::ops::Range<i32>, &std::ops::Range<i32>),
) -> Option<(i32, i32)> {
    let p = nearest_point(paths, u)?;
    let at = chart.backend_coord(p);
    (px.contains(&at.0) && py.start + 8 < at.1 && at.1 < py.end - 8).then_some(at)
}

/// The plot-space point and backend pixel of the path point nearest the height `frac` (0 bottom, 1 top) of the plot.
pub(super) fn at_height<DB: DrawingBackend>(
    paths: &[Vec<(f64, f64)>],
    chart: &axes::Chart<DB>,
    y: &PlotAxis,
    frac: f64,
) -> Option<((f64, f64), (i32, i32))> {
    let yr = y.plot_range();
    let v = yr.start + frac * (yr.end - yr.start);
    let p = paths
        .iter()
        .flatten()
        .min_by(|a, b| (a.1 - v).abs().total_cmp(&(b.1 - v).abs()))?;
    Some((*p, chart.backend_coord(p)))
}

/// The point of `paths` whose first coordinate is nearest `u` (first found wins ties).
fn nearest_point(paths: &[Vec<(f64, f64)>], u: f64) -> Option<&(f64, f64)> {
    paths
        .iter()
        .flatten()
        .min_by(|a, b| (a.0 - u).abs().total_cmp(&(b.0 - u).abs()))
}

/// The axis value of plot coordinate `u` (plot space is ln of the value on a log axis).
pub(super) fn plot_to_value(u: f64, a: &GridAxis) -> f64 {
    match a.scale {
        AxisScale::Log => u.exp(),
        AxisScale::Linear => u,
    }
}

/// A level as a label: whole numbers without decimals.
pub(super) fn level_text(v: f64) -> String {
    style::fmt_num(v, if v.fract() == 0.0 { 0 } else { 1 })
}

#[cfg(test)]
mod round_levels_tests {
    use super::*;

    #[test]
    fn levels_are_round_inside_the_range_and_skip_unjammed_cells() {
        let l = round_levels(&[NO_JAM, 24.3, 31.0, 61.7]);
        assert_eq!(l, [25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 55.0, 60.0]);
        assert_eq!(round_levels(&[3.0, 3.0]), [3.0]);
        assert_eq!(round_levels(&[NO_JAM]), [1.0]);
    }
}
