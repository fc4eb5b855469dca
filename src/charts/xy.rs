//! A figure of stacked x-y panels, the drawing shared by the trace, time-series and
//! work-precision charts: each panel has its own axes (linear or log), curves, point sets and
//! labelled points; one legend strip and optional note lines sit below the panels.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis};
use super::legend::{self, LegendEntry, Swatch};
use super::style::{self, LineKind, Marker};
use crate::grid::AxisScale;

/// How a curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CurveStyle {
    /// A line through the points.
    Line(LineKind),
    /// A marker at each point.
    Points(Marker),
    /// A line with a marker at each point.
    LinePoints(LineKind, Marker),
    /// A region filled with a colour, under the curves drawn after it: the points are its
    /// outline, closed from the last to the first.
    Band(RGBColor),
}

/// One curve or point set of a panel, in value space (the panel's axes map it).
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend text (entries with the same text are listed once).
    pub label: String,
    /// Line, markers or both.
    pub style: CurveStyle,
    /// The points (x, y).
    pub points: Vec<(f64, f64)>,
}

/// A labelled point with dotted guides to the panel's left and bottom axes.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// The point (x, y) in value space.
    pub at: (f64, f64),
    /// The label, on a white box.
    pub text: String,
    /// Where the label sits, 14 px off the point.
    pub side: LabelSide,
    /// Dotted guides from the point to the left and bottom axes (a read-off).
    pub guides: bool,
}

/// Where a mark's label sits relative to its point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LabelSide {
    /// At the left end of the horizontal guide, just above it (true) or below it (false): the
    /// guide leads the eye from the label to the point.
    GuideStart {
        /// Above the guide (true) or below it (false).
        above: bool,
    },
    /// Beside the point, level with it, and no dot: a label of the line the point lies on
    /// (e.g. a vertical line's verdict near its top).
    OnLine {
        /// Right of the point (true) or left of it (false).
        right: bool,
    },
}

impl LabelSide {
    /// Offset in px and the text anchor at the offset point.
    fn place(self) -> ((i32, i32), Pos) {
        match self {
            LabelSide::GuideStart { above: true } => ((8, -4), Pos::new(HPos::Left, VPos::Bottom)),
            LabelSide::GuideStart { above: false } => ((8, 5), Pos::new(HPos::Left, VPos::Top)),
            LabelSide::OnLine { right: true } => ((12, 0), Pos::new(HPos::Left, VPos::Center)),
            LabelSide::OnLine { right: false } => ((-12, 0), Pos::new(HPos::Right, VPos::Center)),
        }
    }
}

/// One panel: axes, curves and marks.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Horizontal axis.
    pub x: PlotAxis,
    /// Vertical axis.
    pub y: PlotAxis,
    /// Curves, drawn in order.
    pub curves: Vec<Curve>,
    /// Labelled points, drawn last.
    pub marks: Vec<Mark>,
    /// Short texts beside points (e.g. the tolerance of a run).
    pub tags: Vec<Tag>,
}

/// A short text beside a point, without a box or marker.
#[derive(Debug, Clone, PartialEq)]
pub struct Tag {
    /// The point (x, y) in value space.
    pub at: (f64, f64),
    /// The text.
    pub text: String,
    /// Left of the point (true) or right of it.
    pub left: bool,
}

/// A whole figure: title, subtitle, panels top to bottom, note lines and the legend.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The chart title.
    pub title: String,
    /// One line under the title naming the parameters.
    pub subtitle: String,
    /// Panels, top to bottom.
    pub panels: Vec<Panel>,
    /// Lines of small text between the panels and the legend.
    pub notes: Vec<String>,
}

impl Figure {
    fn legend(&self) -> Vec<LegendEntry> {
        let mut out: Vec<LegendEntry> = Vec::new();
        for c in self.panels.iter().flat_map(|p| &p.curves) {
            if out.iter().any(|e| e.label == c.label) {
                continue;
            }
            let sw = match c.style {
                CurveStyle::Line(k) => Swatch::Line(k),
                CurveStyle::LinePoints(k, m) => Swatch::LineMarker(k, m),
                CurveStyle::Points(m) => Swatch::Marker(m),
                CurveStyle::Band(c) => Swatch::Patch(c),
            };
            out.push(LegendEntry::new(sw, c.label.clone()));
        }
        out
    }

    /// Draws the figure on `root`.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let h = root.dim_in_pixel().1 as i32;
        let entries = self.legend();
        let legend_top = h - 12 - legend::rows_needed(root, &entries)? * legend::ROW_PX;
        let note_px = style::NOTE_PX as i32 + 6;
        let notes = wrap(root, &self.notes, legend::wrap_width(root))?;
        let notes_top = legend_top - 6 - notes.len() as i32 * note_px;
        let stack = axes::stacked(h, notes_top, self.panels.len());
        for (panel, m) in self.panels.iter().zip(stack) {
            let chart = axes::build_chart(root, &panel.x, &panel.y, m)?;
            axes::draw_grid(&chart, &panel.x, &panel.y)?;
            let area = chart.plotting_area();
            for c in &panel.curves {
                if let CurveStyle::Band(color) = c.style {
                    // Held inside the panel's ranges: an outline point beyond them would fill
                    // over the frame.
                    let (xr, yr) = (panel.x.plot_range(), panel.y.plot_range());
                    let within = |v: f64, r: &std::ops::Range<f64>| {
                        v.max(r.start.min(r.end)).min(r.start.max(r.end))
                    };
                    let ring: Vec<(f64, f64)> = (c.points.iter())
                        .map(|&(x, y)| {
                            let (px, py) = (panel.x.to_plot(x), panel.y.to_plot(y));
                            (within(px, &xr), within(py, &yr))
                        })
                        .collect();
                    area.draw(&Polygon::new(ring, color.filled()))?;
                    continue;
                }
                let pts: Vec<(f64, f64)> = c
                    .points
                    .iter()
                    .filter(|(x, y)| visible(&panel.x, *x) && visible(&panel.y, *y))
                    .map(|&(x, y)| (panel.x.to_plot(x), panel.y.to_plot(y)))
                    .collect();
                let (line, marker) = match c.style {
                    CurveStyle::Line(k) => (Some(k), None),
                    CurveStyle::Points(m) => (None, Some(m)),
                    CurveStyle::LinePoints(k, m) => (Some(k), Some(m)),
                    CurveStyle::Band(_) => (None, None),
                };
                if let Some(k) = line {
                    let color = marker.map_or(k.color(), style::marked_line_color);
                    // Runs inside the vertical range only: a curve leaving the panel ends at
                    // its frame instead of being drawn along it.
                    let (lo, hi) = (panel.y.plot_range().start, panel.y.plot_range().end);
                    for run in pts.split(|p| p.1 < lo || p.1 > hi) {
                        if run.len() > 1 {
                            style::draw_line(area, run, k, color)?;
                        }
                    }
                }
                if let Some(m) = marker {
                    for p in &pts {
                        style::draw_marker(area, m, *p)?;
                    }
                }
            }
            for mk in &panel.marks {
                let (x, y) = (&panel.x, &panel.y);
                let guide = [
                    vec![
                        (x.to_plot(mk.at.0), y.to_plot(mk.at.1)),
                        (x.to_plot(mk.at.0), y.to_plot(y.min)),
                    ],
                    vec![
                        (x.to_plot(mk.at.0), y.to_plot(mk.at.1)),
                        (x.to_plot(x.min), y.to_plot(mk.at.1)),
                    ],
                ];
                for g in guide.into_iter().filter(|_| mk.guides) {
                    style::draw_line(area, &g, LineKind::Dotted, LineKind::Dotted.color())?;
                }
                let px = axes::pixel(&chart, x, y, mk.at.0, mk.at.1);
                if !matches!(mk.side, LabelSide::OnLine { .. }) {
                    style::draw_marker(root, Marker::Dot, px)?;
                }
                let (off, anchor) = mk.side.place();
                // The label sits at the start of the horizontal guide, or beside the point.
                let from = match mk.side {
                    LabelSide::GuideStart { .. } => axes::pixel(&chart, x, y, x.min, mk.at.1),
                    LabelSide::OnLine { .. } => px,
                };
                let at = (from.0 + off.0, from.1 + off.1);
                axes::boxed_text(root, &mk.text, at, anchor, style::NOTE_PX)?;
            }
            for tag in &panel.tags {
                let px = axes::pixel(&chart, &panel.x, &panel.y, tag.at.0, tag.at.1);
                let (dx, h) = if tag.left {
                    (-12, HPos::Right)
                } else {
                    (12, HPos::Left)
                };
                let font = style::text(style::TICK_PX).pos(Pos::new(h, VPos::Center));
                root.draw(&Text::new(tag.text.clone(), (px.0 + dx, px.1), font))?;
            }
            axes::draw_frame(root, &chart, &panel.x, &panel.y)?;
        }
        axes::draw_header(root, &self.title, &self.subtitle)?;
        let note = style::text(style::NOTE_PX).pos(Pos::new(HPos::Left, VPos::Top));
        for (i, line) in notes.iter().enumerate() {
            let y = notes_top + i as i32 * note_px;
            root.draw(&Text::new(line.clone(), (60, y), note.clone()))?;
        }
        legend::draw_legend(root, &entries, legend_top)
    }
}

/// `notes` broken at spaces into lines at most `width` px wide in the note font.
fn wrap<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    notes: &[String],
    width: i32,
) -> Result<Vec<String>, DrawingAreaErrorKind<DB::ErrorType>> {
    let font = style::text(style::NOTE_PX);
    let mut out = Vec::new();
    for note in notes {
        let mut line = String::new();
        for word in note.split(' ') {
            let candidate = if line.is_empty() {
                word.to_string()
            } else {
                format!("{line} {word}")
            };
            if !line.is_empty() && root.estimate_text_size(&candidate, &font)?.0 as i32 > width {
                out.push(std::mem::take(&mut line));
                line = word.to_string();
            } else {
                line = candidate;
            }
        }
        out.push(line);
    }
    Ok(out)
}

/// Whether `v` can be drawn on axis `a` (finite, and positive on a log axis).
fn visible(a: &PlotAxis, v: f64) -> bool {
    v.is_finite() && (a.scale == AxisScale::Linear || v > 0.0)
}

/// A log axis over whole decades around the positive finite `values` (1..10 when none).
pub fn decade_axis(values: impl IntoIterator<Item = f64>, label: impl Into<String>) -> PlotAxis {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite() && *v > 0.0) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    let (lo, hi) = if lo.is_finite() {
        (lo, hi)
    } else {
        (1.0, 10.0)
    };
    let (mut k0, mut k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    if k1 <= k0 {
        k1 = k0 + 1;
    }
    // A value within a third of a decade line would touch the frame (its marker and label
    // cross it): one more decade of room.
    if lo / 10f64.powi(k0) < 1.35 {
        k0 -= 1;
    }
    if 10f64.powi(k1) / hi < 1.35 {
        k1 += 1;
    }
    PlotAxis::new(10f64.powi(k0), 10f64.powi(k1), AxisScale::Log, label)
}

/// A linear axis over the finite `values` with 6 % headroom (0..1 when none).
pub fn padded_axis(values: impl IntoIterator<Item = f64>, label: impl Into<String>) -> PlotAxis {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.into_iter().filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    let (lo, hi) = if lo.is_finite() { (lo, hi) } else { (0.0, 1.0) };
    let pad = (0.06 * (hi - lo)).max(1e-9 * hi.abs().max(1.0));
    PlotAxis::new(lo - pad, hi + pad, AxisScale::Linear, label)
}
