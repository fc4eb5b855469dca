//! Chart kind `universal`: one jam chart for every part, theta_jam and x_jam / r over the
//! friction and the push over the weight.
//!
//! The closed form depends on the part only through two numbers (Eq. 1 corrected):
//!
//! ```text
//! theta_jam = alpha_g + alpha_p + asin(sin(alpha_g) / (F / (m g))),   x_jam / r = cot(theta_jam / 2)
//! ```
//!
//! so theta_jam over (mu, F / (m g)) holds for any radius, mass, push and gravity, and
//! x_jam / r is a function of theta_jam alone: one family of iso-lines carries both, labelled
//! with theta_jam at the top and x_jam / r at the bottom. A palm face h off the hinge line adds
//! h / sin(theta_jam) to x_jam (the chart says so). The part's own palm reach, L / r, is the
//! iso-line theta_jam = theta_reach (jams beyond it lie past the palm's end); the scene's own
//! part is read off in three steps, drawn as lines 1-2-3.
//!
//! The cells are the closed-form statics through the model port, on a palm long enough to
//! reach every jam (the reach is the scene's, drawn as its line), so that a cell's theta_jam
//! does not depend on the part; a cell held at the start carries the start angle, which keeps
//! the field continuous across that boundary.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::json;

use super::axes::{self, DrawResult, PlotAxis};
use super::collide::PxBox;
use super::colorbar::ColorBar;
use super::contour_map::{Paths, at_height, level_text, plot_to_value};
use super::data::CellsTable;
use super::legend::{self, LegendEntry, Swatch};
use super::readoff;
use super::spec::Scene;
use super::style::{self, GRID_MAJOR, INK, LineKind};
use super::typeset;
use super::{DataFile, axis_label, cells_csv, cells_json, grid_lines, grid_polygons, param_symbol};
use crate::csv_out::{Column, Num, nums};
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::grid::{self, GridAxis, GridParam, GridRequest, GridResult, Quantity};
use crate::models::ModelKind;
use crate::scene::{JamStatus, SceneParams};

/// `[chart]` keys of `kind = "universal"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UniversalSpec {
    /// Horizontal axis: a friction, `mu` (both contacts), `mu_ground` or `mu_palm` (the other
    /// stays the scene's).
    pub x_axis: GridAxis,
    /// Vertical axis: `push_ratio`, the push over the weight F / (m g) (log recommended).
    pub y_axis: GridAxis,
    /// Spacing of the thin theta_jam iso-lines in deg (default: 1).
    #[serde(default = "default_step")]
    pub theta_step_deg: f64,
    /// Spacing of the labelled iso-lines in deg; the bands between them are shaded (default:
    /// 5).
    #[serde(default = "default_label_step")]
    pub label_step_deg: f64,
}

fn default_step() -> f64 {
    1.0
}

fn default_label_step() -> f64 {
    5.0
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

/// The frictions a universal chart's x axis may vary.
const FRICTIONS: [GridParam; 3] = [GridParam::Mu, GridParam::MuGround, GridParam::MuPalm];

impl super::kinds::Kind for UniversalSpec {
    const CELLS: bool = true;
    type Chart = Universal;

    fn param_axes(&self) -> Vec<(&'static str, crate::grid::GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// The read-off lines mark the scene's friction and F / (m g).
    fn marks_scene_value(&self) -> bool {
        true
    }

    /// The read-off is always drawn where the scene's point lies on the chart.
    fn enable_read_off(&mut self) -> bool {
        true
    }

    fn validate(&self, scene: &Scene) -> Result<()> {
        if !FRICTIONS.contains(&self.x_axis.param) {
            return Err(Error::invalid(
                "chart.x_axis.param",
                self.x_axis.param.as_str(),
                "a universal chart's x axis is a friction: mu, mu_ground or mu_palm",
            ));
        }
        if self.y_axis.param != GridParam::PushRatio {
            return Err(Error::invalid(
                "chart.y_axis.param",
                self.y_axis.param.as_str(),
                "a universal chart's y axis is push_ratio, the push over the weight F / (m g)",
            ));
        }
        if scene.params.weight_n() <= 0.0 {
            return Err(Error::invalid(
                "mass_kg",
                scene.params.mass_kg,
                "the push over the weight F / (m g) needs a weight: set mass_kg and \
                 gravity_m_s2 above 0",
            ));
        }
        for (key, v) in [
            ("chart.theta_step_deg", self.theta_step_deg),
            ("chart.label_step_deg", self.label_step_deg),
        ] {
            if !(v.is_finite() && (0.1..=90.0).contains(&v)) {
                return Err(Error::invalid(key, v, "give a step in [0.1, 90] deg"));
            }
        }
        self.request(&scene.params).validate()
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::UNIVERSAL_CELL)
    }

    fn compute(&self, scene: &Scene, models: &dyn Models) -> Result<Universal> {
        Universal::compute(scene, self, models)
    }

    fn cells(chart: &Universal) -> Option<CellsTable<'_>> {
        Some(chart.cells())
    }
}

impl UniversalSpec {
    fn request(&self, base: &SceneParams) -> GridRequest {
        GridRequest {
            // A palm long enough for every jam: the field must not depend on the part; the
            // scene's own reach is drawn as a line.
            base: SceneParams {
                palm_length_mm: f64::MAX,
                ..*base
            },
            x: self.x_axis,
            y: self.y_axis,
            quantities: vec![Quantity::Status, Quantity::ThetaJamDeg],
        }
    }
}

/// The scene's own part read off the chart: where it sits and what the closed form says.
#[derive(Debug, Clone, Copy)]
struct ReadOff {
    /// The friction on the x axis.
    mu: f64,
    /// F / (m g).
    push_ratio: f64,
    /// The closed-form answer for the scene (its own palm).
    point: grid::JamPoint,
    /// theta_jam in deg on a long enough palm (the field's value), if it jams there.
    theta_deg: Option<f64>,
}

/// The computed universal chart.
#[derive(Debug, Clone)]
pub struct Universal {
    spec: UniversalSpec,
    params: SceneParams,
    title: String,
    grid: GridResult,
    /// The status per cell, as its index in [`JamStatus::ALL`] (its word in
    /// [`JamStatus::NAMES`]).
    status: Vec<u8>,
    /// x_jam / r per cell, cot(theta_jam / 2) where it jams.
    x_over_r: Vec<Option<f64>>,
    /// The labelled levels in deg (band edges).
    major: Vec<f64>,
    /// Bands between the labelled levels, lowest first.
    bands: Vec<Paths>,
    /// Every iso-line in plot space, (level deg, paths).
    lines: Vec<(f64, Paths)>,
    /// The region held at the start (or never moved), in plot space.
    held: Paths,
    /// The scene palm's reach: theta at which the contact reaches the palm's end, and its line.
    reach: (f64, Paths),
    read_off: Option<ReadOff>,
}

/// Shading of the cells held at the start: a light grey under the bands' colours.
const HELD_FILL: RGBColor = RGBColor(200, 200, 200);

impl Universal {
    fn compute(scene: &Scene, spec: &UniversalSpec, models: &dyn Models) -> Result<Self> {
        let p = scene.params;
        let model = ModelKind::Statics.with(&scene.min_norm, &scene.dynamics);
        let grid = grid::evaluate(&spec.request(&p), |q| models.jam_point(&model, q))?;
        let statuses = grid.status.as_deref().unwrap_or_default();
        let thetas = grid.theta_jam_deg.as_deref().unwrap_or_default();
        // theta_jam per cell in deg: the start angle where held at the start, 0 where it
        // never jams (no friction), NaN outside the model.
        let theta: Vec<f64> = statuses
            .iter()
            .zip(thetas)
            .map(|(s, t)| match s {
                JamStatus::Jams | JamStatus::JammedAtStart => t.unwrap_or(f64::NAN),
                JamStatus::TooWeak => p.start_angle_deg,
                JamStatus::NeverJams => 0.0,
                _ => f64::NAN,
            })
            .collect();
        let status = statuses.iter().map(|s| s.index()).collect();
        let x_over_r = statuses
            .iter()
            .zip(&theta)
            .map(|(s, t)| (*s == JamStatus::Jams).then(|| cot_half(*t)))
            .collect();
        let (xa, ya) = (&spec.x_axis, &spec.y_axis);
        let b = ContourBuilder::new(grid.nx(), grid.ny(), true);
        // Contours need finite values: a cell outside the model is put far below every level.
        let field: Vec<f64> = theta
            .iter()
            .map(|t| if t.is_finite() { *t } else { -1e3 })
            .collect();
        let (lo, hi) = theta
            .iter()
            .filter(|t| t.is_finite())
            .fold((f64::MAX, f64::MIN), |(a, b), t| (a.min(*t), b.max(*t)));
        let levels = |step: f64| -> Vec<f64> {
            if lo > hi {
                return Vec::new();
            }
            let first = (lo / step).floor() as i64 + 1;
            (first..)
                .map(|k| k as f64 * step)
                .take_while(|v| *v < hi)
                .collect()
        };
        let all = levels(spec.theta_step_deg);
        let major = levels(spec.label_step_deg);
        // Finite values and levels cannot fail; nothing is drawn if they ever did.
        let lines = b
            .lines(&field, &all)
            .unwrap_or_default()
            .into_iter()
            .map(|l| (l.threshold(), grid_lines(&l.into_inner().0, xa, ya)))
            .collect();
        let mut edges = vec![-1e2];
        edges.extend(&major);
        edges.push(f64::MAX);
        let bands = b
            .isobands(&field, &edges)
            .unwrap_or_default()
            .iter()
            .map(|band| grid_polygons(band.geometry(), xa, ya))
            .collect();
        let held_mask: Vec<bool> = statuses
            .iter()
            .map(|s| matches!(s, JamStatus::JammedAtStart | JamStatus::TooWeak))
            .collect();
        let held = super::contours::mask_rings(&held_mask, xa, ya);
        let reach_deg = p.reach_angle().to_degrees();
        let reach_line = b
            .lines(&field, &[reach_deg])
            .unwrap_or_default()
            .into_iter()
            .flat_map(|l| grid_lines(&l.into_inner().0, xa, ya))
            .collect();
        let read_off = match (xa.param.get(&p), GridParam::PushRatio.get(&p)) {
            (Some(mu), Some(push_ratio)) => {
                let long = spec.request(&p).base;
                let on_long = models.jam_point(&model, &long)?;
                Some(ReadOff {
                    mu,
                    push_ratio,
                    point: models.jam_point(&model, &p)?,
                    theta_deg: on_long
                        .theta_jam_deg
                        .filter(|_| on_long.status == JamStatus::Jams),
                })
            }
            _ => None,
        };
        Ok(Universal {
            spec: spec.clone(),
            params: p,
            title: scene.title.clone(),
            grid,
            status,
            x_over_r,
            major,
            bands,
            lines,
            held,
            reach: (reach_deg, reach_line),
            read_off,
        })
    }

    /// The data behind the chart as JSON: the scene, the iso-lines (each with its theta_jam
    /// and x_jam / r), the reach line and the read-off; the cells are in the CSV beside it.
    pub fn data_file(&self, scene: &Scene) -> DataFile {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let paths = |paths: &Paths| -> Vec<Vec<[Num; 2]>> {
            paths
                .iter()
                .map(|p| {
                    p.iter()
                        .map(|&(u, v)| [Num(plot_to_value(u, xa)), Num(plot_to_value(v, ya))])
                        .collect()
                })
                .collect()
        };
        let lines: Vec<_> = self
            .lines
            .iter()
            .map(|(level, p)| {
                json!({ "theta_jam_deg": Num(*level), "x_jam_over_r": Num(cot_half(*level)),
                        "paths": paths(p) })
            })
            .collect();
        let read_off = self.read_off.map(|r| {
            json!({
                xa.param.as_str(): Num(r.mu), "push_ratio": Num(r.push_ratio),
                "status": r.point.status, "theta_jam_deg": r.point.theta_jam_deg.map(Num),
                "x_jam_mm": r.point.x_jam_mm.map(Num),
                "theta_jam_on_a_long_palm_deg": r.theta_deg.map(Num),
            })
        });
        let (x, y) = (xa.param, ya.param);
        DataFile::json(&json!({
            "scene": scene.name, "title": self.title, "params": self.params,
            "x_axis": self.spec.x_axis, "y_axis": self.spec.y_axis,
            "how_to_read": self.steps(),
            "iso_lines": { "point": [x.as_str(), y.as_str()], "lines": lines },
            "labelled_theta_jam_deg": nums(self.major.iter().copied()),
            "palm_reach": {
                "l_over_r": Num(self.params.palm_length_mm / self.params.radius_mm),
                "theta_reach_deg": Num(self.reach.0),
                "paths": paths(&self.reach.1),
            },
            "read_off": read_off,
            "cells_file": format!("{}.csv", scene.name),
            "cells": cells_json(&scene.name, &self.grid, x, y, &self.columns()),
        }))
    }

    /// The cells as long-format CSV: the friction, F / (m g), the status, theta_jam_deg and
    /// x_jam_over_r.
    pub fn cells(&self) -> CellsTable<'_> {
        let (x, y) = (self.spec.x_axis.param, self.spec.y_axis.param);
        cells_csv(&self.grid, x, y, &self.columns())
    }

    fn columns(&self) -> Vec<(&'static str, Column<'_>)> {
        vec![
            (
                "status",
                Column::Words {
                    words: JamStatus::NAMES,
                    of: &self.status,
                },
            ),
            (
                "theta_jam_deg",
                Column::Sparse(self.grid.theta_jam_deg.as_deref().unwrap_or_default()),
            ),
            ("x_jam_over_r", Column::Sparse(&self.x_over_r)),
        ]
    }

    /// The three steps of the read-off, with the scene's own numbers as the example.
    fn steps(&self) -> [String; 3] {
        let p = &self.params;
        let mu = param_symbol(self.spec.x_axis.param);
        [
            format!(
                "F/(m g): your push over your part's weight, here {} N / ({} kg · {} m/s²) = {}; \
                 find it on the left axis",
                p.force_n,
                p.mass_kg,
                p.gravity_m_s2,
                style::fmt_num(p.force_n / p.weight_n(), 1)
            ),
            format!(
                "go across to your {mu} below; the iso-lines there give θ_jam (labels at the top)"
            ),
            "x_jam = r · x_jam/r (labels at the bottom) + h/sin θ_jam for a palm face h off the \
             hinge line; on your palm if x_jam/r ≤ L/r"
                .to_string(),
        ]
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let p = &self.params;
        let mut e: Vec<LegendEntry> = self
            .steps()
            .into_iter()
            .enumerate()
            .map(|(i, s)| LegendEntry::new(Swatch::Step(i as u8 + 1), s))
            .collect();
        e.push(LegendEntry::new(
            Swatch::Stroke(LineKind::Solid, INK, 1),
            format!(
                "θ_jam iso-lines every {}°, labelled every {}°",
                level_text(self.spec.theta_step_deg),
                level_text(self.spec.label_step_deg)
            ),
        ));
        if !self.reach.1.is_empty() {
            e.push(LegendEntry::new(
                Swatch::Line(LineKind::Dashed),
                format!(
                    "palm's end for L = {} mm, r = {} mm (L/r = {}): jams left of it lie past \
                     the palm",
                    p.palm_length_mm,
                    p.radius_mm,
                    style::fmt_num(p.palm_length_mm / p.radius_mm, 2)
                ),
            ));
        }
        if !self.held.is_empty() {
            e.push(LegendEntry::new(
                Swatch::Patch(HELD_FILL),
                format!(
                    "held at the start: θ_jam ≥ θ_start = {}°, the disc does not move",
                    p.start_angle_deg
                ),
            ));
        }
        if self.read_off_drawn() {
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Dotted, INK, 2),
                "read-off lines 1-2-3 for this scene's part",
            ));
        }
        e
    }

    /// Whether the scene's own point lies on the chart (its lines are drawn).
    fn read_off_drawn(&self) -> bool {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        self.read_off.is_some_and(|r| {
            (xa.min..=xa.max).contains(&r.mu) && (ya.min..=ya.max).contains(&r.push_ratio)
        })
    }

    /// What the gallery's read-off needs (see [`super::readoff`]): the plotting area, the axes
    /// and the cells' theta_jam, x_jam / r and status.
    pub fn read_off(&self, frames: &[axes::PlotFrame]) -> Option<serde_json::Value> {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let theta = self.grid.theta_jam_deg.as_deref()?;
        let cells = readoff::grid(
            &self.grid,
            &[
                ("theta_jam_deg", &|i| serde_json::json!(theta[i])),
                ("x_over_r", &|i| serde_json::json!(self.x_over_r[i])),
                ("status", &|i| {
                    serde_json::json!(JamStatus::NAMES[usize::from(self.status[i])])
                }),
            ],
        );
        Some(serde_json::json!({
            "kind": "grid",
            "model": ModelKind::Statics,
            "x": readoff::axis(xa.param.as_str(), &x),
            "panels": [readoff::panel(frames.first()?, readoff::axis(ya.param.as_str(), &y), None)],
            "grid": cells,
        }))
    }

    /// Draws the chart on `root`.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (xa, ya) = (&self.spec.x_axis, &self.spec.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let entries = self.legend();
        let colors = style::band_colors(self.major.len() + 1);
        let bar = ColorBar {
            colors: colors.clone(),
            levels: self
                .major
                .iter()
                .map(|t| format!("{}° ({})", level_text(*t), style::fmt_num(cot_half(*t), 2)))
                .collect(),
            title: "θ_jam (deg), in brackets x_jam / r".into(),
        };
        let chart = axes::band_map(root, &x, &y, &entries, &self.bands, &colors, &bar)?;
        let area = chart.plotting_area();
        for ring in &self.held {
            area.draw(&Polygon::new(ring.clone(), HELD_FILL.filled()))?;
        }
        let is_major = |t: f64| self.major.iter().any(|m| (m - t).abs() < 1e-9);
        for (level, paths) in &self.lines {
            let (color, px) = if is_major(*level) {
                (INK, 2)
            } else {
                (GRID_MAJOR, 1)
            };
            for p in paths {
                style::draw_line_px(area, p, LineKind::Solid, color, px)?;
            }
        }
        for p in &self.reach.1 {
            style::draw_line_px(area, p, LineKind::Dashed, LineKind::Dashed.color(), 3)?;
        }
        self.draw_labels(root, &chart, &y)?;
        axes::draw_frame(root, &chart, &x, &y)?;
        self.draw_read_off(root, &chart, &x, &y)?;
        let sub = format!(
            "closed-form statics (corrected Eq. 1) for any r, m, F and g{}, start at {}°",
            match self.spec.x_axis.param {
                GridParam::MuGround => format!(", μ_palm = {}", self.params.mu_palm),
                GridParam::MuPalm => format!(", μ_ground = {}", self.params.mu_ground),
                _ => String::new(),
            },
            self.params.start_angle_deg
        );
        axes::draw_header(root, &self.title, &sub)?;
        let (_, py) = area.get_pixel_range();
        legend::draw_legend(root, &entries, py.end + 62)
    }

    /// theta_jam on each labelled line near the top of the plot, x_jam / r near the bottom.
    fn draw_labels<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let (px, py) = chart.plotting_area().get_pixel_range();
        let inside = |at: (i32, i32)| px.contains(&at.0) && py.contains(&at.1);
        // A label whose text would overlap one already set is left out: over many decades of
        // F / (m g) the lines crowd together near the bottom (issue 18's layout test).
        let mut placed: Vec<PxBox> = Vec::new();
        // A label on a line at the plot's left edge is moved right until it clears the edge,
        // where the y axis' tick labels lie (a line there over 12 decades met "10⁰").
        let mut tag = |s: &str, at: (i32, i32)| {
            let size = typeset::text_size(s, style::TICK_PX);
            let at = (at.0.max(px.start + size.0 as i32 / 2), at.1);
            let b = PxBox::centred(at, size, 0);
            if placed.iter().any(|p| p.overlaps(&b)) {
                return Ok(());
            }
            placed.push(b);
            axes::tag(root, s, at)
        };
        for (level, paths) in self.lines.iter().filter(|(l, _)| self.major.contains(l)) {
            let top = at_height(paths, chart, y, 0.96).map(|(_, at)| at);
            let bottom = at_height(paths, chart, y, 0.04).map(|(_, at)| at);
            if let Some(at) = top.filter(|a| inside(*a)) {
                tag(&format!("{}°", level_text(*level)), at)?;
            }
            if let Some(at) = bottom.filter(|a| inside(*a) && Some(*a) != top) {
                tag(&style::fmt_num(cot_half(*level), 2), at)?;
            }
        }
        Ok(())
    }

    /// Lines 1 (up from the friction) and 2 (across from F / (m g)) to the scene's point, and
    /// 3: the answer boxed beside it.
    fn draw_read_off<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &axes::Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let Some(r) = self.read_off.filter(|_| self.read_off_drawn()) else {
            return Ok(());
        };
        let p = &self.params;
        let answer = match (r.theta_deg, r.point.status) {
            (Some(t), JamStatus::Jams) => format!(
                "3: θ_jam = {}°, x_jam/r = {} → x_jam = {} mm at r = {} mm",
                style::fmt_num(t, 1),
                style::fmt_num(cot_half(t), 2),
                style::fmt_num(r.point.x_jam_mm.unwrap_or(f64::NAN), 1),
                p.radius_mm
            ),
            (Some(t), JamStatus::BeyondReach) => format!(
                "3: θ_jam = {}°, x_jam/r = {}: past this palm's end (L/r = {})",
                style::fmt_num(t, 1),
                style::fmt_num(cot_half(t), 2),
                style::fmt_num(p.palm_length_mm / p.radius_mm, 2)
            ),
            (_, status) => format!("3: {status}"),
        };
        let below = super::point_read_off::AnswerAt::Below;
        super::point_read_off::draw(root, c, (x, y), (r.mu, r.push_ratio), &answer, below)
    }
}

/// x_jam / r = cot(theta / 2) for theta in deg.
fn cot_half(theta_deg: f64) -> f64 {
    1.0 / (0.5 * theta_deg.to_radians()).tan()
}
