//! Chart kind `contour_map` (Fig. 7c): iso-lines of x_jam and theta_jam over two parameters,
//! drawn from [`ContourMapData`] (computed in [`crate::figures::contour_map`]): the x_jam bands
//! shaded as in the colour bar, the lines labelled where nothing crosses them, the settle line
//! dashed and the read-off at the scene's point.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis};
use super::collide::PxBox;
use super::colorbar::{self, ColorBar};
use super::labels;
use super::legend::{self, LegendEntry, Swatch};
use super::picture::Picture;
use super::readoff::{Axis, Grid, Panel, ReadOffData};
use super::style::{self, LineKind};
use super::typeset;
use super::{axis_label, grid_polygons, param_symbol, param_unit, scene_subtitle};
use crate::figures::At;
use crate::figures::contour_map::{ContourMapData, ContourMapSettings, LOWEST_BAND_EDGE, NO_JAM};
use crate::figures::contours::{Paths, axis_value, filled_from_neighbours, mask_rings};
use crate::scene::JamStatus;
use crate::scene::Param;

/// Width of the theta_jam iso-lines in px: as wide as the settle line they may run on
/// ([`LineKind::Dashed`]), so that drawn over it they stay visible.
const THETA_LINE_PX: u32 = 2;

/// Places along the x axis an x_jam label may take, beyond the three preferred ones: every
/// 1/20 of the plot's width (a label is about 1/15 of it wide).
const LABEL_PLACES: usize = 20;

/// A contour map ready to draw: its data and its x_jam bands, traced once.
#[derive(Debug, Clone)]
pub struct ContourMap {
    data: ContourMapData,
    title: String,
    /// The shaded x_jam bands, lowest first: the rings of each band; then the blank, the
    /// cells without a jam, painted over them.
    bands: Vec<Paths>,
}

impl Picture for ContourMap {
    type Settings = ContourMapSettings;

    fn new(data: ContourMapData, title: &str) -> Self {
        let (xa, ya) = (&data.settings.x_axis, &data.settings.y_axis);
        let c = &data.cells;
        let b = ContourBuilder::new(c.x.len(), c.y.len(), true);
        let x_jam = c.x_jam_mm.as_deref().unwrap_or_default();
        // Each cell without a jam takes a neighbour's x_jam, so that no band is interpolated
        // across the blank's edge (every band from the stand-in to the neighbour's value was
        // a fringe along it); the blank is then painted over them.
        let xj = filled_from_neighbours(x_jam, c.x.len(), NO_JAM);
        // Bands: below the first level (from just below 0, so that a map without any jam is in
        // none), between levels, above the last.
        let mut edges = vec![LOWEST_BAND_EDGE];
        edges.extend(&data.settings.x_jam_levels_mm);
        edges.push(f64::MAX);
        // Finite values and levels cannot fail; nothing is drawn if they ever did.
        let mut bands: Vec<Paths> = b
            .isobands(&xj, &edges)
            .unwrap_or_default()
            .iter()
            .map(|band| grid_polygons(band.geometry(), xa, ya))
            .collect();
        let blank: Vec<bool> = x_jam.iter().map(Option::is_none).collect();
        bands.push(mask_rings(&blank, xa, ya));
        ContourMap {
            bands,
            title: title.to_string(),
            data,
        }
    }

    fn data(&self) -> &ContourMapData {
        &self.data
    }

    /// The plotting area, the axes and the cells' x_jam and, where computed, theta_jam.
    fn read_off(&self, frames: &[axes::PlotFrame]) -> Option<ReadOffData> {
        let s = &self.data.settings;
        let (xa, ya) = (&s.x_axis, &s.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let c = &self.data.cells;
        let mut grid = Grid::over(&c.x, &c.y);
        if let Some(xj) = &c.x_jam_mm {
            grid = grid.numbers("x_jam_mm", |i| xj[i]);
        }
        if let Some(tj) = &c.theta_jam_deg {
            grid = grid.numbers("theta_jam_deg", |i| tj[i]);
        }
        Some(ReadOffData::Grid {
            model: s.model.as_str(),
            x: Axis::of(xa.param.as_str(), &x),
            panels: vec![Panel {
                frame: *frames.first()?,
                y: Axis::of(ya.param.as_str(), &y),
            }],
            grid,
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let entries = self.legend();
        // One band below the first level, one between each pair, one above the last; the
        // blank over them.
        let colors = style::band_colors(self.data.settings.x_jam_levels_mm.len() + 1);
        let fills: Vec<RGBColor> = colors.iter().copied().chain([style::PAPER]).collect();
        let bar = ColorBar {
            colors: colors.clone(),
            levels: self
                .data
                .settings
                .x_jam_levels_mm
                .iter()
                .map(|v| level_text(*v))
                .collect(),
            title: "jam position x_jam (mm)".into(),
        };
        let chart = colorbar::band_map(root, &x, &y, &entries, &self.bands, &fills, &bar)?;
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
        let mut labels = Vec::new();
        for line in &self.data.iso_lines.x_jam_mm {
            let (level, paths) = (&line.level, &line.paths.paths);
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
                labels.push(PxBox::centred(at, size, axes::BOX_PAD));
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
        self.draw_theta_lines(root, &chart, &y, labels)?;
        self.draw_read_off(root, &chart, (&x, &y))?;
        axes::draw_frame(root, &chart, &x, &y)?;
        let sub = scene_subtitle(&self.data.params, &[xa.param, ya.param]);
        axes::draw_header(root, &self.title, &sub)?;
        legend::draw_legend(root, &entries, py.end + 62)
    }
}

impl ContourMap {
    /// The read-off, where it is drawn: the scene's point lies on the map (a legend never names
    /// a line that is not drawn).
    fn drawn_read_off(&self) -> Option<&At<2>> {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        self.data.read_off.as_ref().filter(|r| {
            (xa.min..=xa.max).contains(&r.at[0]) && (ya.min..=ya.max).contains(&r.at[1])
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
        let Some(&At {
            at: [u, v],
            point: p,
            ..
        }) = self.drawn_read_off()
        else {
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
        let lines = &self.data.iso_lines;
        let theta = lines.theta_jam_deg.iter().flat_map(|l| &l.paths.paths);
        theta
            .chain(lines.gap_to_x_rigid_pct.iter().flat_map(|l| &l.paths.paths))
            .map(|p| p.iter().map(|q| chart.backend_coord(q)).collect())
            .collect()
    }

    /// Dotted theta_jam iso-lines, labelled near the top, staggered so close lines stay
    /// legible, each label clear of the others and of the labels `placed` already.
    fn draw_theta_lines<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        y: &PlotAxis,
        mut placed: Vec<PxBox>,
    ) -> DrawResult<DB> {
        let levels = &self.data.settings.theta_jam_levels_deg;
        let lines = self.data.iso_lines.theta_jam_deg.iter();
        for (i, (level, paths)) in lines.map(|l| (&l.level, &l.paths.paths)).enumerate() {
            for p in paths {
                style::draw_line_px(
                    chart.plotting_area(),
                    p,
                    LineKind::Dotted,
                    LineKind::Dotted.color(),
                    THETA_LINE_PX,
                )?;
            }
            let s = format!("θ_jam = {}°", level_text(*level));
            let size = typeset::text_size(&s, style::TICK_PX);
            // Its box 5 px right of the line, or left of it where the plot ends sooner (a
            // line near the right edge put its label over the colour bar), as drawn below.
            let right_edge = chart.plotting_area().get_pixel_range().0.end;
            let w = size.0 as i32;
            let left_of = |at: (i32, i32)| at.0 + 5 + w + axes::BOX_PAD > right_edge;
            let label = |at: (i32, i32)| {
                let dx = if left_of(at) { -5 - w / 2 } else { 5 + w / 2 };
                PxBox::centred((at.0 + dx, at.1), size, axes::BOX_PAD)
            };
            // From its staggered height down the line, the first place clear of the labels
            // drawn already: lines that stop short of their height (at cells without a jam)
            // would put every label at their top ends, one over the other.
            let frac = 0.95 - 0.06 * (levels.len() - 1 - i) as f64;
            let found: Vec<(i32, i32)> = (0..)
                .map(|k| frac - 0.04 * k as f64)
                .take_while(|f| *f > 0.0)
                .filter_map(|f| at_height(paths, chart, y, f).map(|(_, at)| at))
                .collect();
            let clear = found
                .iter()
                .find(|at| !placed.iter().any(|b| b.overlaps(&label(**at))));
            if let Some(at) = clear.or(found.first()).copied() {
                placed.push(label(at));
                let (x, h) = match left_of(at) {
                    true => (at.0 - 5, HPos::Right),
                    false => (at.0 + 5, HPos::Left),
                };
                let pos = Pos::new(h, VPos::Center);
                axes::boxed_text(root, &s, (x, at.1), pos, style::TICK_PX)?;
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
        let Some(pct) = self.data.settings.settle_pct else {
            return Ok(());
        };
        let xa = &self.data.settings.x_axis;
        for paths in self
            .data
            .iso_lines
            .gap_to_x_rigid_pct
            .iter()
            .map(|l| &l.paths.paths)
        {
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
            let value = axis_value(u, xa.scale);
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
        let axes = [
            self.data.settings.x_axis.param,
            self.data.settings.y_axis.param,
        ];
        let one_mu = self.data.params.mu_ground == self.data.params.mu_palm
            && !axes.contains(&Param::MuGround)
            && !axes.contains(&Param::MuPalm);
        if one_mu {
            "r/μ"
        } else {
            "r·cot((α_g + α_p)/2)"
        }
    }

    /// Why the cells without x_jam have none, from their statuses in [`JamStatus::ALL`]'s
    /// order, or None when every cell jams.
    fn blank_reasons(&self) -> Option<String> {
        let c = &self.data.cells;
        let x_jam = c.x_jam_mm.as_deref().unwrap_or_default();
        let mut seen = vec![false; JamStatus::ALL.len()];
        for (x, s) in x_jam.iter().zip(&c.status) {
            if x.is_none() {
                seen[usize::from(*s)] = true;
            }
        }
        let l = self.data.params.palm_length_mm;
        let why: Vec<String> = (JamStatus::ALL.iter().zip(seen))
            .filter(|(_, seen)| *seen)
            .map(|(s, _)| match s {
                JamStatus::BeyondReach => format!(
                    "the disc is pushed past the palm's end (L = {} mm) before it jams",
                    style::fmt_num(l, 1)
                ),
                JamStatus::TooWeak => "the push is too weak to move the disc".into(),
                JamStatus::NeverJams => "no friction: it never jams".into(),
                JamStatus::OutsideModel => "outside the model".into(),
                other => other.as_str().replace('_', " "),
            })
            .collect();
        (!why.is_empty()).then(|| why.join("; "))
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let mut e = vec![LegendEntry::new(
            Swatch::Line(LineKind::Solid),
            "x_jam iso-lines (mm), bands as in the colour bar",
        )];
        if let Some(why) = self.blank_reasons() {
            e.push(LegendEntry::new(
                Swatch::Patch(style::PAPER),
                format!("blank, no jam on the palm: {why} (status in the CSV)"),
            ));
        }
        // Only where a line is drawn: at mu = 0.27 fig7c's 44-47 deg levels lie off the map.
        let theta_lines = &self.data.iso_lines.theta_jam_deg;
        if theta_lines.iter().any(|l| !l.paths.paths.is_empty()) {
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Dotted, LineKind::Dotted.color(), THETA_LINE_PX),
                "θ_jam iso-lines (deg)",
            ));
        }
        if let Some(p) = self.data.settings.settle_pct {
            let s = format!(
                "x_jam within {p} % of its F → ∞ limit {} to the right: F no longer matters",
                self.rigid_limit_name()
            );
            e.push(LegendEntry::new(Swatch::Line(LineKind::Dashed), s));
        }
        if let Some(&At { at: [u, v], .. }) = self.drawn_read_off() {
            let (x, y) = (
                self.data.settings.x_axis.param,
                self.data.settings.y_axis.param,
            );
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

/// A level as a label: whole numbers without decimals.
pub(super) fn level_text(v: f64) -> String {
    style::fmt_num(v, if v.fract() == 0.0 { 0 } else { 1 })
}
