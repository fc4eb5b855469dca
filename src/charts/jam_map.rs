//! Chart kind `jam_map` (Fig. 3): where the disc jams over a parameter and the palm angle.
//!
//! The statics margin mu_g R_n - R_t is evaluated on the grid (x: the scene parameter, y: the
//! palm angle theta on a log scale, so that 1 % of theta is the same height everywhere); the
//! `contour` crate turns its sign into the jam region. The boundary is the closed-form
//! theta_jam at every column, the right-hand scale is the disc position x = r cot(theta/2), and
//! the paper's read-off construction (lines 1, 2, 3) is drawn for the scene's own value.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use serde::{Deserialize, Serialize};
use serde_json::json;

use super::axes::{self, Chart, DrawResult, Margins, PlotAxis, PlotFrame};
use super::data::CellsTable;
use super::legend::{self, LegendEntry, Swatch};
use super::models::Models;
use super::readoff;
use super::spec::Scene;
use super::style::{self, INK, JAM_FILL, LineKind, SLIDE_FILL};
use super::{
    DataFile, axis_label, cells_csv, cells_json, grid_lines, grid_polygons, param_symbol,
    scene_subtitle,
};
use crate::csv_out::{Column, Num};
use crate::error::{Error, Result};
use crate::grid::{AxisScale, GridAxis, GridParam, GridRequest, GridResult, JamPoint, Quantity};
use crate::models::ModelKind;
use crate::scene::{SceneParams, disc_position_mm, palm_angle_at};

/// What a jam map draws (`layers`, default all).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JamMapLayer {
    /// The jam and slide regions from the sign of the margin grid.
    Regions,
    /// The closed-form boundary theta_jam(parameter).
    Boundary,
    /// The disc position x = r cot(theta/2) as a right-hand scale.
    PositionScale,
    /// The read-off construction, lines 1-3, at the scene's value of the x parameter.
    ReadOff,
}

/// `[chart]` keys of `kind = "jam_map"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JamMapSpec {
    /// The horizontal axis: any scene parameter but the radius (the position scale needs one r).
    pub x_axis: GridAxis,
    /// The vertical axis: `param = "theta_deg"`, the palm angle in deg.
    pub y_axis: GridAxis,
    /// The layers to draw (default: all).
    #[serde(default = "all_layers")]
    pub layers: Vec<JamMapLayer>,
    /// The model whose jam points are drawn (default: statics; the margin of a jam map's
    /// regions is always the statics').
    #[serde(default)]
    pub model: ModelKind,
    /// The band of an uncertain input not on the axes (`--set force_n=30:50`, or a range in
    /// the scene's `[scene]`): the regions at the box's earliest-jam and latest-jam corners,
    /// cells whose verdict differs between them shaded as their own class `uncertain`
    /// ([`UNCERTAIN_FILL`], CSV `region = uncertain`), and the jam region's boundary at both
    /// corners (default: none; the built-in scenes have none).
    ///
    /// Exact by monotonicity: at a cell (parameter, theta) the disc is held iff theta lies on
    /// the jam side of theta_jam, and theta_jam is monotone in every uncertain input (the
    /// proof is in [`crate::statics`]), so a cell's verdict at every value of the box lies
    /// between its verdicts at the two corners.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub band: Option<super::sweep::SweepBand>,
}

/// A cell's region as the cells CSV writes it; a cell holds its index here.
const REGIONS: &[&str] = &["jam", "slide", "uncertain", "beyond_reach"];
/// The indices in [`REGIONS`].
const JAM: u8 = 0;
const SLIDE: u8 = 1;
const UNCERTAIN: u8 = 2;
const BEYOND_REACH: u8 = 3;

/// The uncertain region of a jam map with a band: Okabe-Ito yellow (#F0E442) at 55 % on white,
/// apart from the jam tint, white slide and grey beyond-reach in colour and between white and
/// the jam tint in print (luma about 232).
pub const UNCERTAIN_FILL: RGBColor = RGBColor(247, 240, 152);

fn all_layers() -> Vec<JamMapLayer> {
    use JamMapLayer::*;
    vec![Regions, Boundary, PositionScale, ReadOff]
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

impl super::kinds::Kind for JamMapSpec {
    const CELLS: bool = true;
    type Chart = JamMap;

    fn param_axes(&self) -> Vec<(&'static str, crate::grid::GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// The read-off lines mark the scene's value of the x parameter.
    fn marks_scene_value(&self) -> bool {
        self.has(JamMapLayer::ReadOff)
    }

    /// Adds the read-off layer when the scene's layers leave it out.
    fn enable_read_off(&mut self) -> bool {
        if !self.has(JamMapLayer::ReadOff) {
            self.layers.push(JamMapLayer::ReadOff);
        }
        true
    }

    /// Checks the axes against the scene.
    fn validate(&self, scene: &Scene) -> Result<()> {
        let base = &scene.params;
        if self.y_axis.param != GridParam::ThetaDeg {
            return Err(Error::invalid(
                "chart.y_axis.param",
                self.y_axis.param.as_str(),
                "a jam map's y axis is theta_deg",
            ));
        }
        if matches!(self.x_axis.param, GridParam::ThetaDeg | GridParam::RadiusMm) {
            return Err(Error::invalid(
                "chart.x_axis.param",
                self.x_axis.param.as_str(),
                "a jam map's x axis is a scene parameter other than radius_mm",
            ));
        }
        self.request(base).validate()
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::JAM_MAP_CELL)
    }

    fn compute(&self, scene: &Scene, models: &dyn super::models::Models) -> Result<JamMap> {
        JamMap::compute(scene, self, models)
    }

    fn cells(chart: &JamMap) -> Option<CellsTable<'_>> {
        chart.cells()
    }
}

impl JamMapSpec {
    fn request(&self, base: &SceneParams) -> GridRequest {
        GridRequest {
            base: *base,
            x: self.x_axis,
            y: self.y_axis,
            quantities: vec![Quantity::MarginN],
        }
    }

    fn has(&self, l: JamMapLayer) -> bool {
        self.layers.contains(&l)
    }
}

/// The computed jam map.
#[derive(Debug, Clone)]
pub struct JamMap {
    spec: JamMapSpec,
    params: SceneParams,
    title: String,
    /// The margin grid (present only with the regions layer).
    grid: Option<GridResult>,
    /// The jam region (margin >= 0) as rings in plot space (ln for log axes), traced once here
    /// so that drawing, once per format, only fills them.
    jam_rings: Vec<Vec<(f64, f64)>>,
    /// Per cell, with the regions: the palm cannot reach the disc there (its contact would lie
    /// past the palm's end), whatever the margin.
    beyond: Vec<bool>,
    /// The region beyond the palm's reach as rings in plot space.
    beyond_rings: Vec<Vec<(f64, f64)>>,
    /// Each cell's region, as its index in [`REGIONS`] (the CSV's words): jam, slide,
    /// uncertain (a band's corners disagree) or beyond_reach.
    region: Vec<u8>,
    /// With a band: the region where the disc jams at some corner (drawn under the jam
    /// rings, which are then those where it jams at both), as rings in plot space.
    uncertain_rings: Vec<Vec<(f64, f64)>>,
    /// With a band: the jam boundary (margin = 0) at its earliest-jam and latest-jam corners,
    /// as polylines in plot space.
    end_lines: [Vec<Vec<(f64, f64)>>; 2],
    /// The closed-form jam point at each x sample, (value, point).
    boundary: Vec<(f64, JamPoint)>,
    /// The read-off at the scene's own x value.
    read_off: Option<(f64, JamPoint)>,
}

impl JamMap {
    /// Computes what the layers of `spec` need, and nothing else.
    pub fn compute(scene: &Scene, spec: &JamMapSpec, models: &dyn Models) -> Result<Self> {
        let p = scene.params;
        let model = spec.model.with(&scene.min_norm, &scene.dynamics);
        let jam_point = |q: &SceneParams| models.jam_point(&model, q);
        let evaluate = |q: &SceneParams| super::models::evaluate(models, &model, &spec.request(q));
        let grid = match spec.has(JamMapLayer::Regions) {
            true => Some(evaluate(&p)?),
            false => None,
        };
        // With a band, the margins at its two corners: the disc is held at every value of the
        // box where the smaller is >= 0, at some where the larger is.
        let corners = match (&spec.band, &grid) {
            (Some(b), Some(_)) => Some((evaluate(&b.earliest)?, evaluate(&b.latest)?)),
            _ => None,
        };
        let end_lines = match &corners {
            Some((e, l)) => {
                [e, l].map(|c| boundary_lines(c, c.margin_n.as_deref().unwrap_or_default(), spec))
            }
            None => Default::default(),
        };
        let corner_margins = corners.as_ref().and_then(|(e, l)| {
            let (e, l) = (e.margin_n.as_deref()?, l.margin_n.as_deref()?);
            let lo: Vec<f64> = e.iter().zip(l).map(|(a, b)| a.min(*b)).collect();
            let hi: Vec<f64> = e.iter().zip(l).map(|(a, b)| a.max(*b)).collect();
            Some((lo, hi))
        });
        let (jam_rings, uncertain_rings) = match (&grid, &corner_margins) {
            (Some(g), Some((lo, hi))) => (jam_rings(g, lo, spec), jam_rings(g, hi, spec)),
            (Some(g), None) => (
                jam_rings(g, g.margin_n.as_deref().unwrap_or_default(), spec),
                Vec::new(),
            ),
            _ => (Vec::new(), Vec::new()),
        };
        let beyond = grid
            .as_ref()
            .map(|g| beyond_reach(g, &p, spec.x_axis.param))
            .unwrap_or_default();
        let beyond_rings = super::contours::mask_rings(&beyond, &spec.x_axis, &spec.y_axis);
        let margins = grid.as_ref().and_then(|g| g.margin_n.as_deref());
        let margins = margins.unwrap_or_default();
        let (lo, hi) = match &corner_margins {
            Some((lo, hi)) => (&lo[..], &hi[..]),
            None => (margins, margins),
        };
        let region = (0..beyond.len())
            .map(|i| match (beyond[i], lo[i] >= 0.0, hi[i] >= 0.0) {
                (true, _, _) => BEYOND_REACH,
                (false, true, _) => JAM,
                (false, false, true) => UNCERTAIN,
                (false, false, false) => SLIDE,
            })
            .collect();
        let param = spec.x_axis.param;
        let boundary = match spec.has(JamMapLayer::Boundary) {
            true => {
                let xs = spec.x_axis.values();
                let points = super::models::along(models, &model, &p, param, &xs)?;
                xs.into_iter().zip(points).collect()
            }
            false => Vec::new(),
        };
        let read_off = match (spec.has(JamMapLayer::ReadOff), param.get(&p)) {
            (true, Some(v)) => Some((v, jam_point(&p)?)),
            _ => None,
        };
        Ok(JamMap {
            spec: spec.clone(),
            params: p,
            title: scene.title.clone(),
            grid,
            jam_rings,
            beyond,
            beyond_rings,
            region,
            uncertain_rings,
            end_lines,
            boundary,
            read_off,
        })
    }

    /// The data behind the chart as JSON: the scene, the boundary and the read-off; the margin
    /// grid is in the long CSV beside it ([`JamMap::cells`]), described under `cells`.
    pub fn data(&self, scene: &Scene) -> DataFile {
        let point = |(v, p): &(f64, JamPoint)| {
            json!({ self.spec.x_axis.param.as_str(): Num(*v), "status": p.status,
                    "theta_jam_deg": p.theta_jam_deg.map(Num), "x_jam_mm": p.x_jam_mm.map(Num) })
        };
        let doc = json!({
            "scene": scene.name,
            "title": self.title,
            "params": self.params,
            "x_axis": self.spec.x_axis,
            "y_axis": self.spec.y_axis,
            "read_off": self.read_off.as_ref().map(point),
            "boundary": self.boundary.iter().map(point).collect::<Vec<_>>(),
            "cells": self.columns().map(|(g, c)| cells_json(&scene.name, g, self.spec.x_axis.param, self.spec.y_axis.param, &c)),
        });
        DataFile::json(&doc)
    }

    /// The cells of the margin grid as long-format CSV (None when the regions are not drawn).
    pub fn cells(&self) -> Option<CellsTable<'_>> {
        let (g, columns) = self.columns()?;
        let (x, y) = (self.spec.x_axis.param, self.spec.y_axis.param);
        Some(cells_csv(g, x, y, &columns))
    }

    /// The grid and its quantity columns, named as in JSON.
    fn columns(&self) -> Option<(&GridResult, Vec<(&'static str, Column<'_>)>)> {
        let g = self.grid.as_ref()?;
        Some((
            g,
            vec![
                (
                    "region",
                    Column::Words {
                        words: REGIONS,
                        of: &self.region,
                    },
                ),
                ("margin_n", Column::Dense(g.margin_n.as_ref()?)),
            ],
        ))
    }

    /// What the gallery's read-off needs (see [`super::readoff`]): the plotting area drawn in
    /// `frames`, the axes, and per column the boundary, its status and the palm's reach.
    pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let frame = frames.first()?;
        let (x, y) = self.axes();
        let param = self.spec.x_axis.param;
        let b = &self.boundary;
        let reach_deg = b
            .iter()
            .map(|(v, _)| param.apply(self.params, *v).reach_angle().to_degrees());
        let p = &self.params;
        Some(json!({
            "kind": "jam_map",
            "model": self.spec.model,
            "x": readoff::axis(param.as_str(), &x),
            "panels": [readoff::panel(frame, readoff::axis(self.spec.y_axis.param.as_str(), &y), None)],
            "columns": {
                param.as_str(): readoff::column(b.iter().map(|(v, _)| *v)),
                "theta_jam_deg": readoff::column(b.iter().map(|(_, q)| q.theta_jam_deg)),
                "x_jam_mm": readoff::column(b.iter().map(|(_, q)| q.x_jam_mm)),
                "status": readoff::column(b.iter().map(|(_, q)| q.status)),
                "reach_deg": readoff::column(reach_deg),
            },
            "disc": {
                "radius_mm": p.radius_mm,
                "palm_offset_mm": p.palm_offset_mm,
                "palm_length_mm": p.palm_length_mm,
            },
        }))
    }

    fn axes(&self) -> (PlotAxis, PlotAxis) {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        (
            PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param)),
            PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param)),
        )
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let mut e = Vec::new();
        let band = self.spec.band.as_ref().map(|b| b.label.as_str());
        if self.spec.has(JamMapLayer::Regions) {
            e.push(LegendEntry::new(
                Swatch::Patch(JAM_FILL),
                match band {
                    Some(_) => "jam at every value: ground holds the disc (μR_n ≥ R_t)",
                    None => "jam: ground holds the disc (μR_n ≥ R_t)",
                },
            ));
            if let Some(label) = band.filter(|_| !self.uncertain_rings.is_empty()) {
                e.push(LegendEntry::new(
                    Swatch::Patch(UNCERTAIN_FILL),
                    format!("uncertain ({label}): jams at one end, slides at the other"),
                ));
                for (i, (kind, end)) in [
                    (LineKind::BandEarliest, "earliest-jam"),
                    (LineKind::BandLatest, "latest-jam"),
                ]
                .into_iter()
                .enumerate()
                {
                    if !self.end_lines[i].is_empty() {
                        e.push(LegendEntry::new(
                            Swatch::Line(kind),
                            format!("jam boundary at the {end} end"),
                        ));
                    }
                }
            }
            e.push(LegendEntry::new(
                Swatch::Patch(SLIDE_FILL),
                "slide: the palm moves the disc",
            ));
            if self.beyond.contains(&true) {
                let s = format!(
                    "beyond the palm's end (L = {} mm): the palm cannot reach the disc there",
                    self.params.palm_length_mm
                );
                e.push(LegendEntry::new(Swatch::Patch(BEYOND_FILL), s));
            }
        }
        if self.spec.has(JamMapLayer::Boundary) {
            e.push(LegendEntry::new(
                Swatch::Line(LineKind::Solid),
                "boundary θ_jam (closed form)",
            ));
        }
        if let Some((v, _)) = self.read_off.filter(|_| self.read_off_drawn()) {
            let s = format!(
                "read-off lines 1-2-3 at {} = {}",
                param_symbol(self.spec.x_axis.param),
                style::fmt_num(v, 2)
            );
            e.push(LegendEntry::new(Swatch::Line(LineKind::Dashed), s));
        }
        e
    }

    /// Whether the read-off lines are drawn: the scene's value lies on the x axis and its jam
    /// on the theta axis (a legend never names a line that is not drawn).
    fn read_off_drawn(&self) -> bool {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        self.read_off.is_some_and(|(v, p)| {
            (xa.min..=xa.max).contains(&v)
                && p.x_jam_mm.is_some()
                && p.theta_jam_deg
                    .is_some_and(|t| (ya.min..=ya.max).contains(&t))
        })
    }

    /// Draws the map on `root`.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (x, y) = self.axes();
        let entries = self.legend();
        let rows = legend::rows_needed(root, &entries)?;
        let right = if self.spec.has(JamMapLayer::PositionScale) {
            110
        } else {
            30
        };
        let margins = Margins {
            top: 70,
            bottom: 75 + rows as u32 * legend::ROW_PX as u32,
            left: 95,
            right,
        };
        let chart = axes::build_chart(root, &x, &y, margins)?;
        let area = chart.plotting_area();
        for ring in &self.uncertain_rings {
            area.draw(&Polygon::new(ring.clone(), UNCERTAIN_FILL.filled()))?;
        }
        for ring in &self.jam_rings {
            area.draw(&Polygon::new(ring.clone(), JAM_FILL.filled()))?;
        }
        for ring in &self.beyond_rings {
            area.draw(&Polygon::new(ring.clone(), BEYOND_FILL.filled()))?;
        }
        axes::draw_grid(&chart, &x, &y)?;
        // The jam boundary at the band's two ends: the outlines of the two regions.
        let [earliest, latest] = &self.end_lines;
        for (lines, kind) in [
            (earliest, LineKind::BandEarliest),
            (latest, LineKind::BandLatest),
        ] {
            for line in lines {
                style::draw_line(area, line, kind, kind.color())?;
            }
        }
        let curve: Vec<(f64, f64)> = self
            .boundary
            .iter()
            .filter_map(|(v, p)| p.theta_jam_deg.map(|t| (x.to_plot(*v), y.to_plot(t))))
            .collect();
        style::draw_line(area, &curve, LineKind::Solid, LineKind::Solid.color())?;
        self.draw_region_labels(root, &chart)?;
        axes::draw_frame(root, &chart, &x, &y)?;
        if self.spec.has(JamMapLayer::PositionScale) {
            self.draw_position_scale(root, &chart, &x, &y)?;
        }
        self.draw_read_off(root, &chart, &x, &y)?;
        let sub = scene_subtitle(&self.params, &[self.spec.x_axis.param]);
        axes::draw_header(root, &self.title, &sub)?;
        let (_, py) = chart.plotting_area().get_pixel_range();
        legend::draw_legend(root, &entries, py.end + 62)
    }

    /// "SLIDE" top left and "JAM" bottom right: where each region lies for every map whose
    /// theta_jam grows with the x parameter (all friction maps).
    fn draw_region_labels<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &Chart<DB>,
    ) -> DrawResult<DB> {
        if !self.spec.has(JamMapLayer::Regions) {
            return Ok(());
        }
        let (px, py) = c.plotting_area().get_pixel_range();
        let at = |fx: f64, fy: f64| {
            let u = px.start as f64 + fx * (px.end - px.start) as f64;
            let v = py.start as f64 + fy * (py.end - py.start) as f64;
            (u as i32, v as i32)
        };
        let pos = Pos::new(HPos::Center, VPos::Center);
        for (label, region, fx, fy) in [("SLIDE", SLIDE, 0.2, 0.12), ("JAM", JAM, 0.8, 0.88)] {
            if let Some(fy) = self.label_height(region, fx, fy) {
                axes::boxed_text(root, label, at(fx, fy), pos, style::LABEL_PX)?;
            }
        }
        Ok(())
    }

    /// Where a region's label goes in the column at `fx` (fractions of the plot, `fy` from the
    /// top): at `fy` if that cell lies in the region, else in the middle of the region's cells
    /// of that column (the palm's reach may cover the default place); None if the column has
    /// none.
    fn label_height(&self, region: u8, fx: f64, fy: f64) -> Option<f64> {
        let g = self.grid.as_ref()?;
        let (nx, ny) = (g.nx(), g.ny());
        let ix = (fx * (nx - 1) as f64).round() as usize;
        let row = |fy: f64| ((1.0 - fy) * (ny - 1) as f64).round() as usize;
        let is = |iy: usize| self.region.get(g.index(ix, iy)) == Some(&region);
        if is(row(fy)) {
            return Some(fy);
        }
        let rows: Vec<usize> = (0..ny).filter(|iy| is(*iy)).collect();
        let mid = *rows.get(rows.len() / 2)?;
        Some(1.0 - mid as f64 / (ny - 1) as f64)
    }

    fn draw_position_scale<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let (r, h) = (self.params.radius_mm, self.params.palm_offset_mm);
        let (lo, hi) = (
            disc_position_mm(r, h, y.max.to_radians()),
            disc_position_mm(r, h, y.min.to_radians()),
        );
        let (px, py) = c.plotting_area().get_pixel_range();
        // Pixels per mm of x at position x, from |d theta/dx| (rad/mm): 2r/(x^2 + r^2) with
        // theta = 2 atan(r/x) for h = 0, else 1 / |dx/dtheta| with
        // dx/dtheta = -r / (2 sin^2(theta/2)) - h cos(theta) / sin^2(theta); and the theta axis'
        // pixels per rad (log: per ln unit / theta).
        let len = py.len() as f64;
        let density = |xmm: f64| {
            let theta = palm_angle_at(r, h, xmm);
            let dtheta = if h == 0.0 {
                2.0 * r / (xmm * xmm + r * r)
            } else {
                let (s, half) = (theta.sin(), (0.5 * theta).sin());
                1.0 / (r / (2.0 * half * half) + h * theta.cos() / (s * s))
            };
            match y.scale {
                AxisScale::Log => len / (y.max / y.min).ln() * dtheta / theta,
                AxisScale::Linear => len / (y.max - y.min) * dtheta.to_degrees(),
            }
        };
        let ticks = super::ticks::adaptive_ticks(lo, hi, density, 5.0, 24.0);
        let right = px.end - 1;
        let row = |xmm: f64| axes::pixel(c, x, y, x.min, palm_angle_at(r, h, xmm).to_degrees()).1;
        for v in ticks.minor {
            root.draw(&PathElement::new(
                vec![(right, row(v)), (right + 4, row(v))],
                INK,
            ))?;
        }
        let font = style::text(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
        for (v, s) in ticks.major {
            let w = row(v);
            root.draw(&PathElement::new(vec![(right, w), (right + 8, w)], INK))?;
            root.draw(&Text::new(s, (right + 11, w), font.clone()))?;
        }
        let label = if h == 0.0 {
            format!(
                "disc position x = r·cot(θ/2) (mm), r = {} mm",
                style::fmt_num(r, 1)
            )
        } else {
            format!(
                "disc position x = r·cot(θ/2) + h/sin θ (mm), r = {} mm, h = {} mm",
                style::fmt_num(r, 1),
                style::fmt_num(h, 2)
            )
        };
        axes::draw_vertical_label(root, &label, px.end + 62, (py.start + py.end) / 2)
    }

    fn draw_read_off<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let Some((v, p)) = self.read_off.filter(|_| self.read_off_drawn()) else {
            return Ok(());
        };
        let (Some(t), Some(xj)) = (p.theta_jam_deg, p.x_jam_mm) else {
            return Ok(());
        };
        let at = |a: f64, b: f64| axes::pixel(c, x, y, a, b);
        let (corner, bottom, left, right) = (at(v, t), at(v, y.min), at(x.min, t), at(x.max, t));
        for line in [[bottom, corner], [corner, left], [corner, right]] {
            style::draw_line(root, &line, LineKind::Dashed, LineKind::Dashed.color())?;
        }
        root.draw(&Circle::new(corner, 5, INK.filled()))?;
        let num = |s: &str, p: (i32, i32)| axes::tag(root, s, p);
        num(
            "1",
            ((bottom.0 + corner.0) / 2 + 12, (bottom.1 + corner.1) / 2),
        )?;
        num("2", ((left.0 + corner.0) / 2, corner.1 - 14))?;
        num("3", ((right.0 + corner.0) / 2, corner.1 - 14))?;
        let name = param_symbol(self.spec.x_axis.param);
        let big = style::NOTE_PX;
        axes::boxed_text(
            root,
            &format!("{name} = {}", style::fmt_num(v, 2)),
            (bottom.0 + 8, bottom.1 - 22),
            Pos::new(HPos::Left, VPos::Bottom),
            big,
        )?;
        axes::boxed_text(
            root,
            &format!("θ_jam = {}°", style::fmt_num(t, 3)),
            (left.0 + 8, left.1 + 10),
            Pos::new(HPos::Left, VPos::Top),
            big,
        )?;
        axes::boxed_text(
            root,
            &format!("x_jam = {} mm", style::fmt_num(xj, 3)),
            (right.0 - 8, right.1 + 10),
            Pos::new(HPos::Right, VPos::Top),
            big,
        )
    }
}

/// Shading of the cells beyond the palm's reach: grey, apart from both jam and slide.
const BEYOND_FILL: RGBColor = RGBColor(200, 200, 200);

/// Per cell of `g` (x: `param`, y: the palm angle in deg): whether the palm's contact there
/// would lie past its end, theta below the reach angle of the column's scene.
fn beyond_reach(g: &GridResult, base: &SceneParams, param: GridParam) -> Vec<bool> {
    let reach_deg: Vec<f64> = g
        .x_values
        .iter()
        .map(|v| param.apply(*base, *v).reach_angle().to_degrees())
        .collect();
    g.y_values
        .iter()
        .flat_map(|t| reach_deg.iter().map(move |r| t < r))
        .collect()
}

/// The polylines where `margin` (a grid of `g`'s shape) is 0, in plot space.
fn boundary_lines(g: &GridResult, margin: &[f64], spec: &JamMapSpec) -> Vec<Vec<(f64, f64)>> {
    if margin.is_empty() {
        return Vec::new();
    }
    let builder = ContourBuilder::new(g.nx(), g.ny(), true);
    // A single threshold on a finite grid cannot fail; no line is drawn if it ever did.
    let lines = builder.lines(margin, &[0.0]).unwrap_or_default();
    lines
        .into_iter()
        .flat_map(|l| grid_lines(&l.into_inner().0, &spec.x_axis, &spec.y_axis))
        .collect()
}

/// The rings of the region where `margin` (a grid of `g`'s shape) is >= 0, in plot space.
fn jam_rings(g: &GridResult, margin: &[f64], spec: &JamMapSpec) -> Vec<Vec<(f64, f64)>> {
    if margin.is_empty() {
        return Vec::new();
    }
    let builder = ContourBuilder::new(g.nx(), g.ny(), true);
    // A single threshold on a finite grid cannot fail; no polygon is drawn if it ever did.
    let jam = builder.contours(margin, &[0.0]).unwrap_or_default();
    jam.iter()
        .flat_map(|c| grid_polygons(c.geometry(), &spec.x_axis, &spec.y_axis))
        .collect()
}
