//! Chart kind `jam_map` (Fig. 3): where the disc jams over a parameter and the palm angle,
//! drawn from [`JamMapData`].
//!
//! The jam region is the margin grid's sign, traced by the `contour` crate (y: the palm angle
//! theta on a log scale, so that 1 % of theta is the same height everywhere); the boundary is
//! the model's theta_jam at every column, the right-hand scale is the disc position
//! x = r cot(theta/2), and the paper's read-off construction (lines 1, 2, 3) is drawn for the
//! scene's own value.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, Chart, DrawResult, Margins, PlotAxis, PlotFrame};
use super::legend::{self, LegendEntry, Swatch};
use super::picture::Picture;
use super::readoff::{Axis, Disc, JamMapColumns, Named, Panel, ReadOffData};
use super::style::{self, INK, JAM_FILL, LineKind, SLIDE_FILL};
use super::{axis_label, grid_lines, param_symbol, scene_subtitle};
use crate::figures::At;
use crate::figures::jam_map::{
    BEYOND_REACH as BEYOND, JAM, JamMapCells, JamMapData, JamMapLayer, JamMapSettings, SLIDE,
};
use crate::grid::AxisScale;
use crate::scene::{disc_position_mm, palm_angle_at};

/// The uncertain region of a jam map with a band: Okabe-Ito yellow (#F0E442) at 55 % on white,
/// apart from the jam tint, white slide and grey beyond-reach in colour and between white and
/// the jam tint in print (luma about 232).
pub const UNCERTAIN_FILL: RGBColor = RGBColor(247, 240, 152);

/// Shading of the cells beyond the palm's reach: grey, apart from both jam and slide.
const BEYOND_FILL: RGBColor = RGBColor(200, 200, 200);

/// A jam map ready to draw: its data, and the regions traced once in plot space (ln for log
/// axes) so that drawing, once per format, only fills them.
#[derive(Debug, Clone)]
pub struct JamMap {
    data: JamMapData,
    title: String,
    /// The jam region (margin >= 0; with a band, at both corners).
    jam_rings: Vec<Vec<(f64, f64)>>,
    /// The region beyond the palm's reach.
    beyond_rings: Vec<Vec<(f64, f64)>>,
    /// With a band: where the disc jams at some corner (drawn under the jam rings).
    uncertain_rings: Vec<Vec<(f64, f64)>>,
    /// With a band: the jam boundary (margin = 0) at its earliest-jam and latest-jam corners,
    /// as polylines.
    end_lines: [Vec<Vec<(f64, f64)>>; 2],
}

impl Picture for JamMap {
    type Settings = JamMapSettings;

    /// Traces `data`'s regions for drawing under `title`.
    fn new(data: JamMapData, title: &str) -> Self {
        let s = &data.settings;
        let (mut jam_rings, mut uncertain_rings, mut beyond_rings) = Default::default();
        let mut end_lines: [Vec<Vec<(f64, f64)>>; 2] = Default::default();
        if let Some(c) = &data.cells {
            match &c.corner_margins_n {
                Some([e, l]) => {
                    let lo: Vec<f64> = e.iter().zip(l).map(|(a, b)| a.min(*b)).collect();
                    let hi: Vec<f64> = e.iter().zip(l).map(|(a, b)| a.max(*b)).collect();
                    jam_rings = jam_rings_of(&lo, s);
                    uncertain_rings = jam_rings_of(&hi, s);
                    end_lines = [e, l].map(|m| boundary_lines(c, m, s));
                }
                None => jam_rings = jam_rings_of(&c.margin_n, s),
            }
            // Most maps have no cell beyond the palm's reach: nothing to trace then.
            if c.region.contains(&BEYOND) {
                let beyond: Vec<bool> = c.region.iter().map(|&r| r == BEYOND).collect();
                beyond_rings = crate::figures::contours::mask_rings(&beyond, &s.x_axis, &s.y_axis);
            }
        }
        JamMap {
            title: title.to_string(),
            data,
            jam_rings,
            beyond_rings,
            uncertain_rings,
            end_lines,
        }
    }

    fn data(&self) -> &JamMapData {
        &self.data
    }

    /// The plotting area drawn in `frames`, the axes, and per column the boundary, its status
    /// and the palm's reach.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let frame = *frames.first()?;
        let (x, y) = self.axes();
        let param = self.data.settings.x_axis.param;
        let b = &self.data.boundary;
        let reach_deg = b.iter().map(|a| {
            param
                .apply(self.data.params, a.at[0])
                .reach_angle()
                .to_degrees()
        });
        let p = &self.data.params;
        Some(ReadOffData::JamMap {
            model: self.data.settings.model.as_str(),
            x: Axis::of(param.as_str(), &x),
            panels: vec![Panel {
                frame,
                y: Axis::of(self.data.settings.y_axis.param.as_str(), &y),
            }],
            columns: JamMapColumns {
                at: Named(vec![(param.as_str(), b.iter().map(|a| a.at[0]).collect())]),
                theta_jam_deg: b.iter().map(|a| a.point.theta_jam_deg).collect(),
                x_jam_mm: b.iter().map(|a| a.point.x_jam_mm).collect(),
                status: b.iter().map(|a| a.point.status).collect(),
                reach_deg: reach_deg.collect(),
            },
            disc: Disc {
                radius_mm: p.radius_mm,
                palm_offset_mm: p.palm_offset_mm,
                palm_length_mm: p.palm_length_mm,
            },
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (x, y) = self.axes();
        let entries = self.legend();
        let rows = legend::rows_needed(root, &entries)?;
        let right = if self.data.settings.has(JamMapLayer::PositionScale) {
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
            .data
            .boundary
            .iter()
            .filter_map(|a| {
                a.point
                    .theta_jam_deg
                    .map(|t| (x.to_plot(a.at[0]), y.to_plot(t)))
            })
            .collect();
        style::draw_line(area, &curve, LineKind::Solid, LineKind::Solid.color())?;
        self.draw_region_labels(root, &chart)?;
        axes::draw_frame(root, &chart, &x, &y)?;
        if self.data.settings.has(JamMapLayer::PositionScale) {
            self.draw_position_scale(root, &chart, &x, &y)?;
        }
        self.draw_read_off(root, &chart, &x, &y)?;
        let sub = scene_subtitle(&self.data.params, &[self.data.settings.x_axis.param]);
        axes::draw_header(root, &self.title, &sub)?;
        let (_, py) = chart.plotting_area().get_pixel_range();
        legend::draw_legend(root, &entries, py.end + 62)
    }
}

impl JamMap {
    fn axes(&self) -> (PlotAxis, PlotAxis) {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        (
            PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param)),
            PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param)),
        )
    }

    fn legend(&self) -> Vec<LegendEntry> {
        let mut e = Vec::new();
        let band = self.data.settings.band.as_ref().map(|b| b.label.as_str());
        if self.data.settings.has(JamMapLayer::Regions) {
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
            if self
                .data
                .cells
                .as_ref()
                .is_some_and(|c| c.region.contains(&BEYOND))
            {
                let s = format!(
                    "beyond the palm's end (L = {} mm): the palm cannot reach the disc there",
                    self.data.params.palm_length_mm
                );
                e.push(LegendEntry::new(Swatch::Patch(BEYOND_FILL), s));
            }
        }
        if self.data.settings.has(JamMapLayer::Boundary) {
            e.push(LegendEntry::new(
                Swatch::Line(LineKind::Solid),
                "boundary θ_jam (closed form)",
            ));
        }
        if let Some(v) = self.drawn_read_off().map(|a| a.at[0]) {
            let s = format!(
                "read-off lines 1-2-3 at {} = {}",
                param_symbol(self.data.settings.x_axis.param),
                style::fmt_num(v, 2)
            );
            e.push(LegendEntry::new(Swatch::Line(LineKind::Dashed), s));
        }
        e
    }

    /// The read-off, where its lines are drawn: the scene's value lies on the x axis and its
    /// jam on the theta axis (a legend never names a line that is not drawn).
    fn drawn_read_off(&self) -> Option<&At<1>> {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        self.data.read_off.as_ref().filter(|a| {
            (xa.min..=xa.max).contains(&a.at[0])
                && a.point.x_jam_mm.is_some()
                && a.point
                    .theta_jam_deg
                    .is_some_and(|t| (ya.min..=ya.max).contains(&t))
        })
    }

    /// "SLIDE" top left and "JAM" bottom right: where each region lies for every map whose
    /// theta_jam grows with the x parameter (all friction maps).
    fn draw_region_labels<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &Chart<DB>,
    ) -> DrawResult<DB> {
        if !self.data.settings.has(JamMapLayer::Regions) {
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
        let g = self.data.cells.as_ref()?;
        let (nx, ny) = (g.nx(), g.ny());
        let ix = (fx * (nx - 1) as f64).round() as usize;
        let row = |fy: f64| ((1.0 - fy) * (ny - 1) as f64).round() as usize;
        let is = |iy: usize| g.region.get(g.index(ix, iy)) == Some(&region);
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
        let (r, h) = (self.data.params.radius_mm, self.data.params.palm_offset_mm);
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
        let Some(&At {
            at: [v], point: p, ..
        }) = self.drawn_read_off()
        else {
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
        let name = param_symbol(self.data.settings.x_axis.param);
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

/// The polylines where `margin` (a grid of `c`'s shape) is 0, in plot space.
fn boundary_lines(c: &JamMapCells, margin: &[f64], s: &JamMapSettings) -> Vec<Vec<(f64, f64)>> {
    if margin.is_empty() {
        return Vec::new();
    }
    let builder = ContourBuilder::new(c.nx(), c.ny(), true);
    // A single threshold on a finite grid cannot fail; no line is drawn if it ever did.
    let lines = builder.lines(margin, &[0.0]).unwrap_or_default();
    lines
        .into_iter()
        .flat_map(|l| grid_lines(&l.into_inner().0, &s.x_axis, &s.y_axis))
        .collect()
}

/// The rings of the region where `margin` (a grid over the axes of `s`) is >= 0, in plot space.
fn jam_rings_of(margin: &[f64], s: &JamMapSettings) -> Vec<Vec<(f64, f64)>> {
    if margin.is_empty() {
        return Vec::new();
    }
    crate::figures::contours::region_rings(margin, 0.0, &s.x_axis, &s.y_axis)
}
