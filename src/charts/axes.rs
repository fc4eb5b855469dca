//! Axes drawn the same way on every chart: frame, ticks, grid lines, labels with units, title.
//!
//! Where the ticks go is [`super::ticks`]' job; this module only draws. Ticks and labels are
//! drawn here rather than by plotters' mesh so that log axes get their readable ticks and one
//! drawing path serves linear and log axes (plot space, see [`super::ticks`]).

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::collide::PxBox;
use super::style::{self, GRID_MAJOR, GRID_MINOR, INK, PAPER};
pub use super::ticks::{PlotAxis, Ticks};

/// A chart in plot space (ln for log axes).
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Result of a drawing step on backend `DB`.
pub type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// Space around a chart's plotting area, in px.
#[derive(Debug, Clone, Copy)]
pub struct Margins {
    /// Above the plotting area (title, subtitle).
    pub top: u32,
    /// Below it (x tick labels, axis title, legend).
    pub bottom: u32,
    /// Left of it (y tick labels, axis title).
    pub left: u32,
    /// Right of it (a second scale, labels).
    pub right: u32,
}

/// Above the first of stacked panels, in px: the title and the subtitle.
const STACK_TOP_PX: i32 = 72;
/// Between stacked panels, in px: the upper one's tick labels and x-axis title.
const STACK_GAP_PX: i32 = 78;
/// Below the last of stacked panels, in px, above the notes or the legend: its tick labels and
/// x-axis title.
const STACK_BELOW_PX: i32 = 64;
/// Left of stacked panels, in px: the y tick labels and axis title (a decade axis's `1e-10`
/// included).
const STACK_LEFT_PX: u32 = 105;
/// Right of stacked panels, in px.
const STACK_RIGHT_PX: u32 = 40;

/// The margins of `n` panels of equal height stacked top to bottom on an area `height_px`
/// high, above `end_px` (where the notes or the legend begin): every chart of panels over one
/// another (the sweep's, the x-y figures') lays them out alike.
pub fn stacked(height_px: i32, end_px: i32, n: usize) -> impl Iterator<Item = Margins> {
    let n = n.max(1) as i32;
    let panel_h = (end_px - STACK_BELOW_PX - STACK_TOP_PX - STACK_GAP_PX * (n - 1)) / n;
    (0..n).map(move |i| {
        let top = STACK_TOP_PX + i * (panel_h + STACK_GAP_PX);
        Margins {
            top: top as u32,
            bottom: (height_px - top - panel_h) as u32,
            left: STACK_LEFT_PX,
            right: STACK_RIGHT_PX,
        }
    })
}

/// A chart on `area` with the given plot-space axes and margins (no plotters mesh).
///
/// Inside [`record_frames`] it also notes where its plotting area lies (the gallery's
/// read-off maps the pointer through it); drawing is the same either way.
pub fn build_chart<'a, 'b, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    x: &PlotAxis,
    y: &PlotAxis,
    m: Margins,
) -> Result<Chart<'b, DB>, DrawingAreaErrorKind<DB::ErrorType>>
where
    'a: 'b,
{
    let chart = ChartBuilder::on(area)
        .margin_top(m.top)
        .margin_bottom(m.bottom)
        .margin_left(m.left)
        .margin_right(m.right)
        .build_cartesian_2d(x.plot_range(), y.plot_range())?;
    FRAMES.with_borrow_mut(|frames| {
        if let Some(frames) = frames {
            let (px, py) = chart.plotting_area().get_pixel_range();
            let (w, h) = area.dim_in_pixel();
            // plotters maps the minimum to the first pixel and the maximum to the last
            // (`end - 1`); a value sits at its pixel's centre, half a pixel in.
            let (w, h) = (f64::from(w), f64::from(h));
            frames.push(PlotFrame {
                left: (f64::from(px.start) + 0.5) / w,
                right: (f64::from(px.end) - 0.5) / w,
                top: (f64::from(py.start) + 0.5) / h,
                bottom: (f64::from(py.end) - 0.5) / h,
            });
        }
    });
    Ok(chart)
}

/// Inside [`record_frames`], notes the rectangle from `top_left` to `bottom_right` (px of
/// `area`, edges) as a plotting area: a chart drawn without [`build_chart`] (the stability
/// matrix's cells) gives the read-off its frame this way. Nothing is drawn.
pub fn record_area<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    top_left: (i32, i32),
    bottom_right: (i32, i32),
) {
    FRAMES.with_borrow_mut(|frames| {
        if let Some(frames) = frames {
            let (w, h) = area.dim_in_pixel();
            let (w, h) = (f64::from(w), f64::from(h));
            frames.push(PlotFrame {
                left: f64::from(top_left.0) / w,
                right: f64::from(bottom_right.0) / w,
                top: f64::from(top_left.1) / h,
                bottom: f64::from(bottom_right.1) / h,
            });
        }
    });
}

/// Where a plotting area lies in the picture, as fractions of its width and height from the
/// top left, so that it holds at any scale and any displayed size: the centre of the pixel of
/// the axis minimum is at `left` (x) and `bottom` (y), that of the maximum at `right` and `top`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PlotFrame {
    /// Left edge.
    pub left: f64,
    /// Top edge.
    pub top: f64,
    /// Right edge.
    pub right: f64,
    /// Bottom edge.
    pub bottom: f64,
}

thread_local! {
    /// The frames [`build_chart`] built on this thread, while [`record_frames`] runs.
    static FRAMES: std::cell::RefCell<Option<Vec<PlotFrame>>> = const { std::cell::RefCell::new(None) };
}

/// Runs `draw` and returns, beside its result, the plotting areas it built, in order (one per
/// panel). A drawing runs on one thread, so a thread-local list sees exactly its own charts;
/// the list is not shared between drawings (a nested call records its own).
pub fn record_frames<R>(draw: impl FnOnce() -> R) -> (R, Vec<PlotFrame>) {
    let outer = FRAMES.with_borrow_mut(|f| f.replace(Vec::new()));
    let r = draw();
    let frames = FRAMES.with_borrow_mut(|f| std::mem::replace(f, outer));
    (r, frames.unwrap_or_default())
}

/// The backend pixel of value point (xv, yv).
pub fn pixel<DB: DrawingBackend>(
    c: &Chart<DB>,
    x: &PlotAxis,
    y: &PlotAxis,
    xv: f64,
    yv: f64,
) -> (i32, i32) {
    c.backend_coord(&(x.to_plot(xv), y.to_plot(yv)))
}

/// Minor and major grid lines of both axes, to draw before the data.
pub fn draw_grid<DB: DrawingBackend>(c: &Chart<DB>, x: &PlotAxis, y: &PlotAxis) -> DrawResult<DB> {
    let area = c.plotting_area();
    let (xr, yr) = (x.plot_range(), y.plot_range());
    let (pxr, pyr) = area.get_pixel_range();
    let (xt, yt) = (
        x.ticks(pxr.len() as f64, false),
        y.ticks(pyr.len() as f64, true),
    );
    let majors = |t: &Ticks| t.major.iter().map(|(v, _)| *v).collect::<Vec<_>>();
    for (vals, color) in [(&xt.minor, GRID_MINOR), (&majors(&xt), GRID_MAJOR)] {
        for &v in vals {
            let u = x.to_plot(v);
            area.draw(&PathElement::new(vec![(u, yr.start), (u, yr.end)], color))?;
        }
    }
    for (vals, color) in [(&yt.minor, GRID_MINOR), (&majors(&yt), GRID_MAJOR)] {
        for &v in vals {
            let u = y.to_plot(v);
            area.draw(&PathElement::new(vec![(xr.start, u), (xr.end, u)], color))?;
        }
    }
    Ok(())
}

/// Frame, tick marks, tick labels and axis labels of the bottom and left axes, drawn on `root`
/// (the whole drawing, so pixel coordinates are backend coordinates).
pub fn draw_frame<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    c: &Chart<DB>,
    x: &PlotAxis,
    y: &PlotAxis,
) -> DrawResult<DB> {
    let (px, py) = c.plotting_area().get_pixel_range();
    root.draw(&Rectangle::new(
        [(px.start, py.start), (px.end - 1, py.end - 1)],
        INK.stroke_width(1),
    ))?;
    let tick = style::text(style::TICK_PX);
    let mut widest_y_tick = 0;
    for (v, s) in x.ticks(px.len() as f64, false).major {
        let (u, _) = pixel(c, x, y, v, y.min);
        root.draw(&PathElement::new(
            vec![(u, py.end - 1), (u, py.end + 5)],
            INK,
        ))?;
        let pos = Pos::new(HPos::Center, VPos::Top);
        root.draw(&Text::new(s, (u, py.end + 8), tick.pos(pos)))?;
    }
    for (v, s) in y.ticks(py.len() as f64, true).major {
        let (_, w) = pixel(c, x, y, x.min, v);
        root.draw(&PathElement::new(
            vec![(px.start - 5, w), (px.start, w)],
            INK,
        ))?;
        widest_y_tick = widest_y_tick.max(root.estimate_text_size(&s, &tick)?.0 as i32);
        let pos = Pos::new(HPos::Right, VPos::Center);
        root.draw(&Text::new(s, (px.start - 8, w), tick.pos(pos)))?;
    }
    let label = style::text(style::LABEL_PX);
    let mid_x = (px.start + px.end) / 2;
    let pos = Pos::new(HPos::Center, VPos::Top);
    root.draw(&Text::new(
        x.label.clone(),
        (mid_x, py.end + 30),
        label.pos(pos),
    ))?;
    let span = py.len() as i32;
    // 62 px left of the frame, or further when a tick label is wide enough to reach it (10^-10
    // on a log axis): the label's own height plus a gap left of the widest tick label.
    let clear = 8 + widest_y_tick + 4 + style::LABEL_PX as i32;
    let cx = px.start - clear.max(62);
    draw_vertical_label_within(root, &y.label, cx, (py.start + py.end) / 2, span)
}

/// A label rotated to read bottom-up, centred on (cx, cy).
pub fn draw_vertical_label<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    cx: i32,
    cy: i32,
) -> DrawResult<DB> {
    draw_vertical_label_within(root, s, cx, cy, i32::MAX)
}

/// [`draw_vertical_label`] within `span` px of height (a short panel of a stacked chart): a
/// label longer than that is broken into two lines at the space nearest its middle, and set
/// smaller if a line is still too long, so that it never runs into its neighbours' labels.
pub fn draw_vertical_label_within<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    cx: i32,
    cy: i32,
    span: i32,
) -> DrawResult<DB> {
    let set = |size: f64, text: &str, x: i32| {
        let style = style::text(size)
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Center));
        root.draw(&Text::new(text.to_string(), (x, cy), style))
    };
    let width = |text: &str, size: f64| -> Result<i32, DrawingAreaErrorKind<DB::ErrorType>> {
        Ok(root.estimate_text_size(text, &style::text(size))?.0 as i32)
    };
    if width(s, style::LABEL_PX)? <= span {
        return set(style::LABEL_PX, s, cx);
    }
    let middle = s.len() / 2;
    let cut = s
        .char_indices()
        .filter(|(_, c)| *c == ' ')
        .map(|(i, _)| i)
        .min_by_key(|i| i.abs_diff(middle));
    let lines: Vec<&str> = match cut {
        Some(i) => vec![&s[..i], &s[i + 1..]],
        None => vec![s],
    };
    let mut widest = 0;
    for l in &lines {
        widest = widest.max(width(l, style::LABEL_PX)?);
    }
    // Smaller until the longest line fits, but never below a legible 9 px.
    let size = (style::LABEL_PX * span as f64 / widest.max(1) as f64).clamp(9.0, style::LABEL_PX);
    let step = (size * 1.15).round() as i32;
    let first = cx - step * (lines.len() as i32 - 1) / 2;
    for (k, l) in lines.iter().enumerate() {
        set(size, l, first + step * k as i32)?;
    }
    Ok(())
}

/// A short label (a step number, a level) on a white box centred at `at`, tick-label size.
pub fn tag<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    at: (i32, i32),
) -> DrawResult<DB> {
    boxed_text(
        root,
        s,
        at,
        Pos::new(HPos::Center, VPos::Center),
        style::TICK_PX,
    )
}

/// The white margin in px around a [`boxed_text`]'s text.
pub const BOX_PAD: i32 = 3;

/// Text on a white box (for labels over data); `pos` anchors the box like a text anchor.
pub fn boxed_text<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    at: (i32, i32),
    pos: Pos,
    size_px: f64,
) -> DrawResult<DB> {
    boxed_text_placed(root, s, at, pos, size_px).map(|_| ())
}

/// [`boxed_text`], returning the white box it drew: what a label placed later must keep
/// clear of.
pub fn boxed_text_placed<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    at: (i32, i32),
    pos: Pos,
    size_px: f64,
) -> Result<PxBox, DrawingAreaErrorKind<DB::ErrorType>> {
    let style = style::text(size_px);
    let (w, h) = root.estimate_text_size(s, &style)?;
    let (w, h) = (w as i32, h as i32);
    let x0 = match pos.h_pos {
        HPos::Left => at.0,
        HPos::Center => at.0 - w / 2,
        HPos::Right => at.0 - w,
    };
    let y0 = match pos.v_pos {
        VPos::Top => at.1,
        VPos::Center => at.1 - h / 2,
        VPos::Bottom => at.1 - h,
    };
    let pad = BOX_PAD;
    root.draw(&Rectangle::new(
        [(x0 - pad, y0 - pad), (x0 + w + pad, y0 + h + pad)],
        PAPER.filled(),
    ))?;
    root.draw(&Text::new(
        s.to_string(),
        (x0, y0),
        style.pos(Pos::new(HPos::Left, VPos::Top)),
    ))?;
    Ok(PxBox {
        x0: x0 - pad,
        y0: y0 - pad,
        x1: x0 + w + pad,
        y1: y0 + h + pad,
    })
}

/// Space between two lines of a [`boxed_lines`] block, px.
const LINE_GAP_PX: i32 = 2;

/// The size in px of `lines` set as one [`boxed_lines`] block (without its box's margin).
pub fn lines_size<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    lines: &[String],
    size_px: f64,
) -> Result<(u32, u32), DrawingAreaErrorKind<DB::ErrorType>> {
    let style = style::text(size_px);
    let (mut w, mut h) = (0, 0);
    for (k, l) in lines.iter().enumerate() {
        let (lw, lh) = root.estimate_text_size(l, &style)?;
        w = w.max(lw);
        h += lh + if k > 0 { LINE_GAP_PX as u32 } else { 0 };
    }
    Ok((w, h))
}

/// Lines of text, left-aligned, on one white box whose text starts at `at` (top left): a
/// label too long for one line beside a point.
pub fn boxed_lines<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    lines: &[String],
    at: (i32, i32),
    size_px: f64,
) -> DrawResult<DB> {
    let (w, h) = lines_size(root, lines, size_px)?;
    let pad = BOX_PAD;
    root.draw(&Rectangle::new(
        [
            (at.0 - pad, at.1 - pad),
            (at.0 + w as i32 + pad, at.1 + h as i32 + pad),
        ],
        PAPER.filled(),
    ))?;
    let font = style::text(size_px).pos(Pos::new(HPos::Left, VPos::Top));
    let mut y = at.1;
    for l in lines {
        root.draw(&Text::new(l.clone(), (at.0, y), font.clone()))?;
        y += root.estimate_text_size(l, &font)?.1 as i32 + LINE_GAP_PX;
    }
    Ok(())
}

/// The chart title centred at the top of `root`, and the subtitle line (the scene, the source) under it.
pub fn draw_header<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    subtitle: &str,
) -> DrawResult<DB> {
    let (w, _) = root.dim_in_pixel();
    let mid = w as i32 / 2;
    // A title or subtitle wider than the picture less 20 px a side is set smaller until it
    // fits (a 200-character title ran 450 px past both edges of a 1000 px picture).
    let room = w as f64 - 40.0;
    let fitted = |text: &str, size_px: f64| -> Result<f64, DrawingAreaErrorKind<DB::ErrorType>> {
        let wide = root.estimate_text_size(text, &style::text(size_px))?.0 as f64;
        Ok(if wide > room {
            (size_px * room / wide).max(9.0)
        } else {
            size_px
        })
    };
    let title_px = fitted(title, style::TITLE_PX)?;
    let title_font = style::text(title_px).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new(title.to_string(), (mid, 12), title_font))?;
    let size = fitted(subtitle, style::TICK_PX)?;
    let sub_font = style::text(size).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new(subtitle.to_string(), (mid, 40), sub_font))
}
