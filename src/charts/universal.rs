//! Chart kind `universal`: one jam chart for every part, drawn from [`UniversalData`]
//! (the physics is in [`crate::figures::universal`]).
//!
//! One family of theta_jam iso-lines carries both answers, labelled with theta_jam at the top
//! and x_jam / r at the bottom; the bands between the labelled lines are shaded, the cells
//! held at the start greyed, the part's palm reach dashed, and the scene's own part read off
//! in three steps, drawn as lines 1-2-3.

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis};
use super::collide::PxBox;
use super::colorbar::{self, ColorBar};
use super::contour_map::{at_height, level_text};
use super::legend::{self, LegendEntry, Swatch};
use super::picture::Picture;
use super::point_read_off;
use super::readoff::{Axis, Grid, Panel, ReadOffData};
use super::style::{self, GRID_MAJOR, INK, LineKind};
use super::typeset;
use super::{axis_label, grid_polygons, param_symbol};
use crate::figures::contours::{Paths, mask_rings};
use crate::figures::universal::{
    RangeEnd, UniversalData, UniversalReadOff, UniversalSettings, cot_half, theta_field,
};
use crate::models::ModelKind;
use crate::scene::JamStatus;
use crate::scene::Param;

/// Shading of the cells held at the start: a light grey under the bands' colours.
const HELD_FILL: RGBColor = RGBColor(200, 200, 200);

/// The range's box and its ends: Okabe-Ito vermillion, apart from the black iso-lines and the
/// viridis bands (the palm's end is dashed in the same hue, thinner).
const RANGE_INK: RGBColor = style::OKABE_ITO[6];

/// A universal chart ready to draw: its data, and its bands and held region traced once.
#[derive(Debug, Clone)]
pub struct Universal {
    data: UniversalData,
    title: String,
    /// Bands between the labelled levels, lowest first.
    bands: Vec<Paths>,
    /// The region held at the start (or never moved).
    held: Paths,
}

impl Picture for Universal {
    type Settings = UniversalSettings;

    fn new(data: UniversalData, title: &str) -> Self {
        let (xa, ya) = (&data.settings.x_axis, &data.settings.y_axis);
        let c = &data.cells;
        let b = ContourBuilder::new(c.x.len(), c.push_ratio.len(), true);
        let mut edges = vec![-1e2];
        edges.extend(&data.labelled_theta_jam_deg);
        edges.push(f64::MAX);
        // Finite values and levels cannot fail; nothing is drawn if they ever did.
        let bands = b
            .isobands(&theta_field(&c.theta_field), &edges)
            .unwrap_or_default()
            .iter()
            .map(|band| grid_polygons(band.geometry(), xa, ya))
            .collect();
        Universal {
            held: mask_rings(&c.held, xa, ya),
            bands,
            title: title.to_string(),
            data,
        }
    }

    fn data(&self) -> &UniversalData {
        &self.data
    }

    /// The plotting area, the axes and the cells' theta_jam, x_jam / r and status.
    fn read_off(&self, frames: &[axes::PlotFrame]) -> Option<ReadOffData> {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, axis_label(xa.param));
        let y = PlotAxis::new(ya.min, ya.max, ya.scale, axis_label(ya.param));
        let c = &self.data.cells;
        let grid = Grid::over(&c.x, &c.push_ratio)
            .numbers("theta_jam_deg", |i| c.theta_jam_deg[i])
            .numbers("x_over_r", |i| c.x_over_r[i])
            .numbers("x_jam_mm", |i| c.x_jam_mm[i])
            .statuses("status", |i| JamStatus::NAMES[usize::from(c.status[i])]);
        Some(ReadOffData::Grid {
            model: ModelKind::Statics.as_str(),
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
        let major = &self.data.labelled_theta_jam_deg;
        let colors = style::band_colors(major.len() + 1);
        let bar = ColorBar {
            colors: colors.clone(),
            levels: major
                .iter()
                .map(|t| format!("{}° ({})", level_text(*t), style::fmt_num(cot_half(*t), 2)))
                .collect(),
            title: "θ_jam (deg), in brackets x_jam / r".into(),
        };
        let chart = colorbar::band_map(root, &x, &y, &entries, &self.bands, &colors, &bar)?;
        let area = chart.plotting_area();
        for ring in &self.held {
            area.draw(&Polygon::new(ring.clone(), HELD_FILL.filled()))?;
        }
        let is_major = |t: f64| major.iter().any(|m| (m - t).abs() < 1e-9);
        for line in &self.data.iso_lines.lines {
            let (color, px) = if is_major(line.theta_jam_deg) {
                (INK, 2)
            } else {
                (GRID_MAJOR, 1)
            };
            for p in &line.paths.paths {
                style::draw_line_px(area, p, LineKind::Solid, color, px)?;
            }
        }
        for p in &self.data.palm_reach.paths.paths {
            style::draw_line_px(area, p, LineKind::Dashed, LineKind::Dashed.color(), 3)?;
        }
        // The read-off's and the range's lines under the labels: a label they would cut
        // moves off them, or where it cannot, is set over them.
        let over = self.lines_over_labels(&chart, (&x, &y));
        for l in &over.read_off {
            style::draw_line_px(root, l, LineKind::Dotted, INK, 2)?;
        }
        if !over.range.is_empty() {
            style::draw_line_px(root, &over.range, LineKind::Solid, RANGE_INK, 4)?;
        }
        self.draw_labels(root, &chart, &y, &over)?;
        axes::draw_frame(root, &chart, &x, &y)?;
        self.draw_read_off(root, &chart, &x, &y)?;
        self.draw_range(root, &chart, &x, &y, &over.range)?;
        let params = &self.data.params;
        let sub = format!(
            "closed-form statics (corrected Eq. 1) for any r, m, F and g{}, start at {}°",
            match xa.param {
                Param::MuGround => format!(", μ_palm = {}", params.mu_palm),
                Param::MuPalm => format!(", μ_ground = {}", params.mu_ground),
                _ => String::new(),
            },
            params.start_angle_deg
        );
        axes::draw_header(root, &self.title, &sub)?;
        let (_, py) = area.get_pixel_range();
        legend::draw_legend(root, &entries, py.end + 62)
    }
}

impl Universal {
    /// The three steps of the read-off, with the scene's own numbers as the example.
    fn steps(&self) -> [String; 3] {
        let p = &self.data.params;
        let mu = param_symbol(self.data.settings.x_axis.param);
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
        let p = &self.data.params;
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
                level_text(self.data.settings.theta_step_deg),
                level_text(self.data.settings.label_step_deg)
            ),
        ));
        if !self.data.palm_reach.paths.paths.is_empty() {
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
        if self.drawn_read_off().is_some() {
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Dotted, INK, 2),
                "read-off lines 1-2-3 for this scene's part",
            ));
        }
        if let Some(r) = &self.data.range {
            e.push(LegendEntry::new(
                Swatch::Stroke(LineKind::Solid, RANGE_INK, 4),
                format!(
                    "the range given, {}: every jam lies between its two ends (dots), read off \
                     beside them",
                    r.given
                ),
            ));
        }
        e
    }

    /// The scene's own point, where it lies on the chart (its lines are drawn); with ranges
    /// the range's ends are read off instead (a nominal point inside a range says nothing
    /// the ends do not).
    fn drawn_read_off(&self) -> Option<&UniversalReadOff> {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        let ranged = self.data.range.is_some();
        self.data.read_off.as_ref().filter(|r| {
            !ranged
                && (xa.min..=xa.max).contains(&r.at.at[0])
                && (ya.min..=ya.max).contains(&r.at.at[1])
        })
    }

    /// The lines drawn across the iso-lines' labels, in px: the read-off's lines 1 and 2 and
    /// the range's box.
    fn lines_over_labels<DB: DrawingBackend>(
        &self,
        c: &axes::Chart<DB>,
        (x, y): (&PlotAxis, &PlotAxis),
    ) -> OverLabels {
        let read_off = self
            .drawn_read_off()
            .map(|r| point_read_off::lines(c, (x, y), (r.at.at[0], r.at.at[1])));
        let at =
            |u: f64, v: f64| axes::pixel(c, x, y, u.clamp(x.min, x.max), v.clamp(y.min, y.max));
        let range = self.data.range.as_ref().map(|r| {
            let ([x0, x1], [y0, y1]) = (r.x, r.push_ratio);
            vec![at(x0, y0), at(x1, y0), at(x1, y1), at(x0, y1), at(x0, y0)]
        });
        OverLabels {
            read_off: read_off.map(Vec::from).unwrap_or_default(),
            range: range.unwrap_or_default(),
        }
    }

    /// theta_jam on each labelled line near the top of the plot, x_jam / r near the bottom.
    fn draw_labels<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        y: &PlotAxis,
        over: &OverLabels,
    ) -> DrawResult<DB> {
        let (px, py) = chart.plotting_area().get_pixel_range();
        let inside = |at: (i32, i32)| px.contains(&at.0) && py.contains(&at.1);
        let over = over.segments();
        // Each label where it belongs: theta_jam at the top, x_jam / r at the bottom; a label
        // on a line at the plot's left edge moved right until it clears the edge, where the y
        // axis' tick labels lie (a line there over 12 decades met "10⁰").
        let major = &self.data.labelled_theta_jam_deg;
        let mut labels: Vec<Label> = Vec::new();
        for (level, paths) in (self.data.iso_lines.lines.iter())
            .filter(|l| major.contains(&l.theta_jam_deg))
            .map(|l| (l.theta_jam_deg, &l.paths.paths))
        {
            let top = at_height(paths, chart, y, 0.96).map(|(_, at)| at);
            let bottom = at_height(paths, chart, y, 0.04).map(|(_, at)| at);
            let texts = [
                top.filter(|a| inside(*a))
                    .map(|a| (format!("{}°", level_text(level)), a)),
                bottom
                    .filter(|a| inside(*a) && Some(*a) != top)
                    .map(|a| (style::fmt_num(cot_half(level), 2), a)),
            ];
            for (s, at) in texts.into_iter().flatten() {
                let size = typeset::text_size(&s, style::TICK_PX);
                let at = (at.0.max(px.start + size.0 as i32 / 2), at.1);
                labels.push((s, at, size));
            }
        }
        move_off_lines(&mut labels, &over);
        // A label whose text would overlap one already set is left out: over many decades of
        // F / (m g) the lines crowd together near the bottom (the layout tests' awkward scenes).
        let mut placed: Vec<PxBox> = Vec::new();
        for (s, at, size) in &labels {
            let b = PxBox::centred(*at, *size, 0);
            if placed.iter().any(|p| p.overlaps(&b)) {
                continue;
            }
            placed.push(b);
            axes::tag(root, s, *at)?;
        }
        Ok(())
    }

    /// The box of the scene's ranges (a segment when one of its sides is a point), thick, with
    /// its earliest-jam and latest-jam corners dotted and read off: theta_jam, x_jam / r and
    /// x_jam in mm (r is the scene's), or where the jam lies past the palm.
    fn draw_range<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        c: &axes::Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
        ring: &[(i32, i32)],
    ) -> DrawResult<DB> {
        let Some(r) = &self.data.range else {
            return Ok(());
        };
        let clamp = |v: f64, a: &PlotAxis| v.clamp(a.min, a.max);
        let at = |u: f64, v: f64| axes::pixel(c, x, y, clamp(u, x), clamp(v, y));
        let p = &self.data.params;
        let lr = p.palm_length_mm / p.radius_mm;
        let text = |what: &str, e: &RangeEnd| -> String {
            let corner = format!(
                "{what} at {} = {}, F/(m g) = {}",
                param_symbol(e.at.params[0]),
                style::fmt_num(e.at.at[0], 3),
                style::fmt_num(e.at.at[1], 1)
            );
            match (e.theta_on_a_long_palm_deg, e.at.point.status) {
                (Some(t), JamStatus::Jams) => format!(
                    "{corner}: θ_jam = {}°, x_jam/r = {} → x_jam = {} mm",
                    style::fmt_num(t, 1),
                    style::fmt_num(cot_half(t), 2),
                    style::fmt_num(e.at.point.x_jam_mm.unwrap_or(f64::NAN), 1)
                ),
                (Some(t), JamStatus::BeyondReach) => format!(
                    "{corner}: x_jam/r = {} ({} mm) > L/r = {}: past the palm's end",
                    style::fmt_num(cot_half(t), 2),
                    style::fmt_num(p.disc_position_mm(t.to_radians()), 1),
                    style::fmt_num(lr, 2)
                ),
                (_, status) => format!("{corner}: {status}"),
            }
        };
        let ends = [("earliest jam", &r.earliest), ("latest jam", &r.latest)];
        let px: Vec<(i32, i32)> = ends
            .iter()
            .map(|(_, e)| at(e.at.at[0], e.at.at[1]))
            .collect();
        // The earliest jam's label above the box, the latest's below, each centred on its
        // dot and moved sideways to stay inside the plot: the two never meet.
        let (area_x, _) = c.plotting_area().get_pixel_range();
        for ((what, e), dot) in ends.iter().zip(&px) {
            root.draw(&Circle::new(*dot, 6, RANGE_INK.filled()))?;
            let s = text(what, e);
            let w = root.estimate_text_size(&s, &style::text(style::NOTE_PX))?.0 as i32;
            let left = (dot.0 - w / 2)
                .min(area_x.end - 6 - w)
                .max(area_x.start + 6);
            let (v, dy) = match *what == "earliest jam" {
                true => (VPos::Bottom, -14),
                false => (VPos::Top, 14),
            };
            let top = ring.iter().map(|p| p.1).min().unwrap_or(dot.1);
            let bottom = ring.iter().map(|p| p.1).max().unwrap_or(dot.1);
            let edge = if dy < 0 { top } else { bottom };
            let pos = Pos::new(HPos::Left, v);
            axes::boxed_text(root, &s, (left, edge + dy), pos, style::NOTE_PX)?;
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
        let Some(r) = self.drawn_read_off() else {
            return Ok(());
        };
        let p = &self.data.params;
        let answer = match (r.theta_on_a_long_palm_deg, r.at.point.status) {
            (Some(t), JamStatus::Jams) => format!(
                "3: θ_jam = {}°, x_jam/r = {} → x_jam = {} mm at r = {} mm",
                style::fmt_num(t, 1),
                style::fmt_num(cot_half(t), 2),
                style::fmt_num(r.at.point.x_jam_mm.unwrap_or(f64::NAN), 1),
                p.radius_mm
            ),
            (Some(t), JamStatus::BeyondReach) => format!(
                "3: θ_jam = {}°, x_jam/r = {} → {} mm: past this palm's end (L/r = {})",
                style::fmt_num(t, 1),
                style::fmt_num(cot_half(t), 2),
                style::fmt_num(p.disc_position_mm(t.to_radians()), 1),
                style::fmt_num(p.palm_length_mm / p.radius_mm, 2)
            ),
            (_, status) => format!("3: {status}"),
        };
        let below = point_read_off::AnswerAt::Below;
        point_read_off::draw_answer(root, c, (x, y), (r.at.at[0], r.at.at[1]), &answer, below)
    }
}

/// The lines drawn across the iso-lines' labels, in px.
struct OverLabels {
    /// The read-off's lines 1 and 2 (none where it is not drawn).
    read_off: Vec<[(i32, i32); 2]>,
    /// The range's box as a closed ring (empty without a range).
    range: Vec<(i32, i32)>,
}

impl OverLabels {
    /// Every line as a segment.
    fn segments(&self) -> Vec<[(i32, i32); 2]> {
        let ring = self.range.windows(2).map(|w| [w[0], w[1]]);
        self.read_off.iter().copied().chain(ring).collect()
    }
}

/// A label: its text, centre and size in px.
type Label = (String, (i32, i32), (u32, u32));

/// Each label a read-off or range line would cut ("3.73" under line 1) moved just off that
/// line, still touching its own iso-line, where its box stays clear of the other labels'
/// boxes; where it cannot, it stays (and is set over the line, which is drawn first).
fn move_off_lines(labels: &mut [Label], over: &[[(i32, i32); 2]]) {
    for i in 0..labels.len() {
        let (at, size) = (labels[i].1, labels[i].2);
        let free = |a: (i32, i32)| {
            let b = PxBox::centred(a, size, axes::BOX_PAD + 1);
            let apart = PxBox::centred(a, size, 2 * axes::BOX_PAD + 2);
            !over.iter().any(|l| b.meets_segment(l[0], l[1]))
                && !(labels.iter().enumerate())
                    .any(|(j, o)| j != i && PxBox::centred(o.1, o.2, 0).overlaps(&apart))
        };
        if let Some(a) = off_lines(at, size, over).into_iter().find(|a| free(*a)) {
            labels[i].1 = a;
        }
    }
}

/// Where a label of `size` px centred at `at` may go so that none of `lines` cuts it: where it
/// is, if none does; else just beside each line that does, on the label's own side first
/// (sideways off an upright line, up or down off a level one), then the other side.
fn off_lines(at: (i32, i32), size: (u32, u32), lines: &[[(i32, i32); 2]]) -> Vec<(i32, i32)> {
    let half = (size.0 as i32 / 2, size.1 as i32 / 2);
    // The box's padding and one more pixel of white between the box and the line.
    let gap = axes::BOX_PAD + 2;
    let mut out = vec![at];
    let b = PxBox::centred(at, size, axes::BOX_PAD + 1);
    for [a, z] in lines.iter().filter(|l| b.meets_segment(l[0], l[1])) {
        let (near, far) = if a.0 == z.0 {
            let (l, r) = ((a.0 - gap - half.0, at.1), (a.0 + gap + half.0, at.1));
            if at.0 <= a.0 { (l, r) } else { (r, l) }
        } else {
            let (u, d) = ((at.0, a.1 - gap - half.1), (at.0, a.1 + gap + half.1));
            if at.1 <= a.1 { (u, d) } else { (d, u) }
        };
        out.extend([near, far]);
    }
    if out.len() > 1 {
        out.remove(0);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{Label, PxBox, move_off_lines};
    use crate::charts::{Formats, SceneSource, render};
    use crate::scene::Param;
    use serde_json::Value;

    /// The gallery's hover on the universal chart said `status = jams` at mu 0.12 for the 25 mm
    /// shaft, whose jam lies past its 80 mm palm (x/r 7.95 > L/r 6.40), and gave x/r without x
    /// in mm: the read-off's cells carry `solve`'s status, beyond_reach, and x_jam_mm, where
    /// the shaft would jam (`solve`'s past-palm x_jam), at the cells nearest that point.
    #[test]
    fn the_read_off_says_beyond_reach_and_x_in_mm_past_the_palm() {
        let scene = SceneSource::BuiltIn("universal-range".into())
            .load(&[])
            .unwrap();
        let doc: Value = serde_json::from_str(
            &render(&scene, Formats::Png)
                .unwrap()
                .read_off
                .expect("a read-off"),
        )
        .unwrap();
        let g = &doc["grid"];
        let nearest = |axis: &Value, v: f64| {
            let a: Vec<f64> = serde_json::from_value(axis.clone()).unwrap();
            let i = (0..a.len())
                .min_by(|&i, &j| (a[i] - v).abs().total_cmp(&(a[j] - v).abs()))
                .unwrap();
            (i, a[i], a.len())
        };
        let ratio = 40.0 / (0.4 * 9.806);
        let (ix, mu, nx) = nearest(&g["x"], 0.12);
        let (iy, at_ratio, _) = nearest(&g["y"], ratio);
        assert!((mu - 0.12).abs() < 0.01 && (at_ratio / ratio - 1.0).abs() < 0.05);
        let cell = |q: &str| g["cells"][q][iy * nx + ix].clone();
        let q = Param::PushRatio.apply(Param::Mu.apply(scene.params, mu), at_ratio);
        let s = crate::statics::solve(&q);
        assert_eq!(s.status, crate::scene::JamStatus::BeyondReach);
        assert_eq!(cell("status"), "beyond_reach");
        let want = s.past_palm.unwrap().x_jam_mm;
        let got = cell("x_jam_mm").as_f64().unwrap();
        assert!((got / want - 1.0).abs() < 1e-6, "{got} against {want}");
        let x_over_r = cell("x_over_r").as_f64().unwrap();
        assert!(x_over_r > scene.params.palm_length_mm / scene.params.radius_mm);
    }

    /// Line 1 of the read-off cut the label "3.73" of the iso-line it crossed: a label that a
    /// line crosses moves beside the line, on its own side, where the other labels leave room,
    /// and stays (to be set over the line) where they do not.
    #[test]
    fn a_label_a_line_crosses_moves_beside_it_where_there_is_room() {
        let size = (32, 14);
        let line = [[(100, 0), (100, 300)]];
        let mut labels: Vec<Label> = vec![
            ("3.73".into(), (95, 280), size),
            ("3.17".into(), (300, 280), size),
        ];
        move_off_lines(&mut labels, &line);
        let b = PxBox::centred(labels[0].1, size, crate::charts::axes::BOX_PAD);
        assert!(!b.meets_segment(line[0][0], line[0][1]), "{labels:?}");
        assert!(
            labels[0].1.0 < 100 && labels[0].1.0 > 95 - size.0 as i32,
            "{labels:?}"
        );
        assert_eq!(labels[1].1, (300, 280));
        // Neighbours on both sides, 40 px apart: no room, it stays.
        let mut crowded: Vec<Label> = vec![
            ("4.51".into(), (60, 280), size),
            ("3.73".into(), (100, 280), size),
            ("3.17".into(), (140, 280), size),
        ];
        move_off_lines(&mut crowded, &line);
        assert_eq!(crowded[1].1, (100, 280));
    }
}
