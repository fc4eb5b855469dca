//! Axes drawn the same way on every chart: ticks, grid lines, labels with units.
//!
//! Charts plot in "plot space": a log axis is plotted as ln(value), so every chart is a plain
//! Cartesian f64 chart and one drawing path serves linear and log axes. Ticks and labels are
//! drawn here rather than by plotters' mesh so that log axes get readable 1-2-5 (or 1..9) ticks
//! and dense minor grids that an engineer can read to 1 %.

use std::ops::Range;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::legend::{self, LegendEntry};
use super::style::{self, GRID_MAJOR, GRID_MINOR, INK, PAPER};
use crate::grid::AxisScale;

/// A chart in plot space (ln for log axes).
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Result of a drawing step on backend `DB`.
pub type DrawResult<DB> = Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

/// One plotted axis: value range, spacing and its label (quantity and unit).
#[derive(Debug, Clone, PartialEq)]
pub struct PlotAxis {
    /// Smallest value shown, in the quantity's unit.
    pub min: f64,
    /// Largest value shown.
    pub max: f64,
    /// Linear or logarithmic.
    pub scale: AxisScale,
    /// Quantity and unit, e.g. "friction coefficient mu (-)".
    pub label: String,
}

/// Tick positions (values, not plot space) and major labels.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Ticks {
    /// Major ticks with their labels.
    pub major: Vec<(f64, String)>,
    /// Minor ticks (grid only).
    pub minor: Vec<f64>,
}

impl PlotAxis {
    /// A new axis.
    pub fn new(min: f64, max: f64, scale: AxisScale, label: impl Into<String>) -> Self {
        PlotAxis {
            min,
            max,
            scale,
            label: label.into(),
        }
    }

    /// The plot-space coordinate of value `v`.
    pub fn to_plot(&self, v: f64) -> f64 {
        match self.scale {
            AxisScale::Linear => v,
            AxisScale::Log => v.ln(),
        }
    }

    /// The plot-space range.
    pub fn plot_range(&self) -> Range<f64> {
        self.to_plot(self.min)..self.to_plot(self.max)
    }

    /// Readable ticks for this axis drawn `len_px` long. A vertical log axis gets ticks as
    /// dense as its local scale allows ([`adaptive_ticks`]); the others get 1-2-5 steps.
    pub fn ticks(&self, len_px: f64, vertical: bool) -> Ticks {
        match self.scale {
            AxisScale::Linear => linear_ticks(self.min, self.max),
            // Beyond three decades plain numbers get long: powers of ten instead.
            AxisScale::Log if self.max / self.min > 1e3 => decade_ticks(self.min, self.max, len_px),
            AxisScale::Log if vertical => {
                let per_ln = len_px / (self.max / self.min).ln();
                adaptive_ticks(self.min, self.max, |v| per_ln / v, 6.0, 26.0)
            }
            AxisScale::Log => log_ticks(self.min, self.max),
        }
    }
}

fn inside(v: f64, lo: f64, hi: f64) -> bool {
    let eps = 1e-9 * (hi - lo).abs();
    v >= lo - eps && v <= hi + eps
}

/// About 5-10 majors at 1, 2 or 5 times a power of ten, with 4-5 minors between.
fn linear_ticks(lo: f64, hi: f64) -> Ticks {
    let raw = (hi - lo) / 8.0;
    let mag = 10f64.powf(raw.log10().floor());
    let (step, minor_div) = [(1.0, 5.0), (2.0, 4.0), (5.0, 5.0), (10.0, 5.0)]
        .into_iter()
        .map(|(m, d)| (m * mag, d))
        .find(|(s, _)| *s >= raw)
        .unwrap_or((10.0 * mag, 5.0));
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    let minor_step = step / minor_div;
    let first = (lo / minor_step).ceil() as i64;
    let last = (hi / minor_step).floor() as i64;
    let mut t = Ticks::default();
    for k in first..=last {
        let v = k as f64 * minor_step;
        // Integer arithmetic on the minor index decides majors: no float modulo.
        if k.rem_euclid(minor_div as i64) == 0 {
            t.major.push((v, style::fmt_num(v, decimals)));
        } else {
            t.minor.push(v);
        }
    }
    t
}

/// The smallest of 1, 2, 5 times a power of ten that is >= `x` (> 0).
fn nice_at_least(x: f64) -> f64 {
    let mag = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * mag)
        .find(|s| *s >= x * (1.0 - 1e-12))
        .unwrap_or(10.0 * mag)
}

/// Ticks whose steps follow the local scale: `px_per_unit(v)` is the axis' pixel density at
/// value v; minor ticks are at least `minor_px` apart and labelled majors at least `major_px`,
/// both at 1-2-5 steps with majors a whole multiple of minors. On a non-uniform scale (log, or
/// the disc position x = r cot(theta/2) beside theta) this labels densely where there is room.
pub fn adaptive_ticks(
    lo: f64,
    hi: f64,
    px_per_unit: impl Fn(f64) -> f64,
    minor_px: f64,
    major_px: f64,
) -> Ticks {
    let mut t = Ticks::default();
    let eps = 1e-9 * (hi - lo).abs();
    let mut v = lo;
    // A cap far above any axis' needs keeps a pathological density function finite.
    for _ in 0..10_000 {
        let d = px_per_unit(v).abs();
        if !(d.is_finite() && d > 0.0) {
            break;
        }
        let minor = nice_at_least(minor_px / d);
        let mut major = nice_at_least((major_px / d).max(minor));
        // Majors must fall on minors: 0.5 over 0.2 does not, so step up to 1.
        while ((major / minor).round() * minor - major).abs() > 1e-9 * major {
            major = nice_at_least(major * 1.01);
        }
        let tick = (((v - eps) / minor).ceil() * minor / minor).round() * minor;
        if tick > hi + eps {
            break;
        }
        if ((tick / major).round() * major - tick).abs() <= 1e-6 * minor {
            let decimals = (-(major.log10() + 1e-9).floor()).max(0.0) as usize;
            t.major.push((tick, style::fmt_num(tick, decimals)));
        } else {
            t.minor.push(tick);
        }
        v = tick + 0.5 * minor;
    }
    t
}

/// Log ticks: within about a decade and a half every mantissa 1..9 is a major and tenths are
/// minors; over wider ranges 1, 2, 5 are majors and 1..9 minors.
fn log_ticks(lo: f64, hi: f64) -> Ticks {
    let narrow = hi / lo <= 30.0;
    let mut t = Ticks::default();
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    for k in k0..=k1 {
        let p = 10f64.powi(k);
        // Mantissas in tenths: 10 = 1.0, ..., 99 = 9.9.
        for m10 in 10..100 {
            let v = m10 as f64 / 10.0 * p;
            if !inside(v, lo, hi) {
                continue;
            }
            let whole = m10 % 10 == 0;
            let major = if narrow {
                whole
            } else {
                matches!(m10, 10 | 20 | 50)
            };
            let minor = if narrow { true } else { whole };
            let decimals = if v >= 1.0 {
                0
            } else {
                (-v.log10()).ceil() as usize
            };
            if major {
                t.major.push((v, style::fmt_num(v, decimals)));
            } else if minor {
                t.minor.push(v);
            }
        }
    }
    t
}

/// Log ticks over many decades: powers of ten labelled 10ⁿ (every k-th decade when they would
/// be closer than 40 px), minors at 2..9 times each power when a decade is at least 60 px.
fn decade_ticks(lo: f64, hi: f64, len_px: f64) -> Ticks {
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let per_decade = len_px / (hi / lo).log10();
    let every = (40.0 / per_decade).ceil().max(1.0) as i32;
    let mut t = Ticks::default();
    for k in k0..=k1 {
        let p = 10f64.powi(k);
        if inside(p, lo, hi) {
            if k.rem_euclid(every) == 0 {
                t.major.push((p, power_of_ten(k)));
            } else {
                t.minor.push(p);
            }
        }
        if per_decade >= 60.0 {
            t.minor
                .extend((2..10).map(|m| m as f64 * p).filter(|v| inside(*v, lo, hi)));
        }
    }
    t
}

/// "10" with `k` as a superscript, e.g. 10⁻⁸.
pub fn power_of_ten(k: i32) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for d in k.unsigned_abs().to_string().bytes() {
        s.push(SUP[(d - b'0') as usize]);
    }
    s
}

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

/// A chart on `area` with the given plot-space axes and margins (no plotters mesh).
pub fn build_chart<'a, 'b, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    x: &PlotAxis,
    y: &PlotAxis,
    m: Margins,
) -> Result<Chart<'b, DB>, DrawingAreaErrorKind<DB::ErrorType>>
where
    'a: 'b,
{
    ChartBuilder::on(area)
        .margin_top(m.top)
        .margin_bottom(m.bottom)
        .margin_left(m.left)
        .margin_right(m.right)
        .build_cartesian_2d(x.plot_range(), y.plot_range())
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
    draw_vertical_label(root, &y.label, px.start - 62, (py.start + py.end) / 2)
}

/// A label rotated to read bottom-up, centred on (cx, cy).
pub fn draw_vertical_label<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    cx: i32,
    cy: i32,
) -> DrawResult<DB> {
    let style = style::text(style::LABEL_PX)
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Center));
    root.draw(&Text::new(s.to_string(), (cx, cy), style))
}

/// Text on a white box (for labels over data); `pos` anchors the box like a text anchor.
pub fn boxed_text<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    s: &str,
    at: (i32, i32),
    pos: Pos,
    size_px: f64,
) -> DrawResult<DB> {
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
    let pad = 3;
    root.draw(&Rectangle::new(
        [(x0 - pad, y0 - pad), (x0 + w + pad, y0 + h + pad)],
        PAPER.filled(),
    ))?;
    root.draw(&Text::new(
        s.to_string(),
        (x0, y0),
        style.pos(Pos::new(HPos::Left, VPos::Top)),
    ))
}

/// The chart title centred at the top of `root`, and the subtitle line (the scene, the source) under it.
pub fn draw_header<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    subtitle: &str,
) -> DrawResult<DB> {
    let (w, _) = root.dim_in_pixel();
    let mid = w as i32 / 2;
    let title_font = style::text(style::TITLE_PX).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new(title.to_string(), (mid, 12), title_font))?;
    let sub_font = style::text(style::TICK_PX).pos(Pos::new(HPos::Center, VPos::Top));
    root.draw(&Text::new(subtitle.to_string(), (mid, 40), sub_font))
}

/// A filled map's chart: the standard margins with room below for `entries`' legend, each
/// band's rings filled in its colour (`bands[i]` in `colors[i]`; extra bands stay unfilled),
/// and the grid over them. The contour map and the V-locator capacity map share it.
pub fn band_map<'a, 'b, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    x: &PlotAxis,
    y: &PlotAxis,
    entries: &[LegendEntry],
    bands: &[Vec<Vec<(f64, f64)>>],
    colors: &[RGBColor],
) -> Result<Chart<'b, DB>, DrawingAreaErrorKind<DB::ErrorType>>
where
    'a: 'b,
{
    let (w, _) = root.dim_in_pixel();
    let rows = legend::rows_needed(root, entries, w as i32 - 120)?;
    let m = Margins {
        top: 70,
        bottom: 75 + (rows * legend::ROW_PX) as u32,
        left: 95,
        right: 40,
    };
    let chart = build_chart(root, x, y, m)?;
    let area = chart.plotting_area();
    for (rings, color) in bands.iter().zip(colors) {
        for ring in rings {
            area.draw(&Polygon::new(ring.clone(), color.filled()))?;
        }
    }
    draw_grid(&chart, x, y)?;
    Ok(chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round() {
        let t = linear_ticks(0.1, 0.5);
        let labels: Vec<&str> = t.major.iter().map(|(_, s)| s.as_str()).collect();
        assert_eq!(
            labels,
            [
                "0.10", "0.15", "0.20", "0.25", "0.30", "0.35", "0.40", "0.45", "0.50"
            ]
        );
        assert_eq!(t.minor.len(), 32);
    }

    #[test]
    fn adaptive_ticks_follow_the_scale() {
        // A log axis 10..70 deg drawn 755 px tall: 0.2 deg minors near 10, 1 deg near 45.
        let per_ln = 755.0 / 7f64.ln();
        let t = adaptive_ticks(10.0, 70.0, |v| per_ln / v, 6.0, 26.0);
        let near = |x: f64| t.minor.iter().any(|m| (m - x).abs() < 1e-9);
        assert!(
            near(10.2) && near(44.0) && !near(44.5),
            "{:?}",
            &t.minor[..8]
        );
        let labels: Vec<&str> = t.major.iter().map(|(_, s)| s.as_str()).collect();
        assert_eq!(&labels[..3], ["10", "11", "12"]);
        assert!(
            labels.contains(&"45") && labels.contains(&"70"),
            "{labels:?}"
        );
    }

    #[test]
    fn decade_ticks_label_powers_of_ten() {
        let t = decade_ticks(1e-10, 1.0, 300.0);
        let labels: Vec<&str> = t.major.iter().map(|(_, s)| s.as_str()).collect();
        assert_eq!(labels, ["10⁻¹⁰", "10⁻⁸", "10⁻⁶", "10⁻⁴", "10⁻²", "10⁰"]);
        assert_eq!(power_of_ten(5), "10⁵");
    }

    #[test]
    fn log_ticks_narrow_and_wide() {
        let t = log_ticks(10.0, 70.0);
        let labels: Vec<&str> = t.major.iter().map(|(_, s)| s.as_str()).collect();
        assert_eq!(labels, ["10", "20", "30", "40", "50", "60", "70"]);
        let t = log_ticks(50.0, 10_000.0);
        let labels: Vec<&str> = t.major.iter().map(|(_, s)| s.as_str()).collect();
        assert_eq!(
            labels,
            ["50", "100", "200", "500", "1000", "2000", "5000", "10000"]
        );
    }
}
