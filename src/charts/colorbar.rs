//! The colour bar of a filled map: its band colours stacked beside the plot, lowest band at
//! the bottom, the levels between them as tick labels and the quantity with its unit as title.
//!
//! The bands are discrete (one colour between two iso-lines), so the bar is a stack of equal
//! boxes, one per band, and a tick sits on each boundary: the reader matches a band's colour
//! to the two levels around it, as on the map, whatever the spacing of the levels.
//!
//! [`band_map`] lays out a filled map with its bar beside it and its legend below.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, Chart, DrawResult, Margins, PlotAxis, build_chart, draw_grid};
use super::legend::{self, LegendEntry};
use super::style::{self, INK};

/// Space between the plot's right edge and the bar, in px.
const GAP_PX: i32 = 16;
/// Width of the bar, in px.
const BAR_PX: i32 = 20;
/// Tick length plus the space before its label, in px.
const TICK_PX: i32 = 8;
/// Space between the widest label and the title, and after the title, in px.
const TITLE_GAP_PX: i32 = 12;

/// A colour bar: the colours of a map's bands and the levels between them.
#[derive(Debug, Clone, PartialEq)]
pub struct ColorBar {
    /// The band colours, lowest band first (the band below the first level, ..., the band
    /// above the last).
    pub colors: Vec<RGBColor>,
    /// The levels between consecutive bands as printed (one fewer than the colours).
    pub levels: Vec<String>,
    /// The quantity and its unit, e.g. `x_jam (mm)`, written up the bar's side.
    pub title: String,
}

impl ColorBar {
    /// The width in px the bar with its labels and title takes right of the plot.
    pub fn width_px<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> Result<i32, DrawingAreaErrorKind<DB::ErrorType>> {
        let font = style::text(style::TICK_PX);
        let mut widest = 0;
        for s in &self.levels {
            widest = widest.max(root.estimate_text_size(s, &font)?.0 as i32);
        }
        let title_h = style::LABEL_PX.ceil() as i32;
        Ok(GAP_PX + BAR_PX + TICK_PX + widest + 2 * TITLE_GAP_PX + title_h)
    }

    /// Draws the bar right of the plot whose right edge is at x = `plot_right`, spanning the
    /// plot's height from `top` to `bottom` (backend pixels of `root`).
    pub fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        plot_right: i32,
        top: i32,
        bottom: i32,
    ) -> DrawResult<DB> {
        let n = self.colors.len() as i32;
        if n == 0 {
            return Ok(());
        }
        let (l, r) = (plot_right + GAP_PX, plot_right + GAP_PX + BAR_PX);
        // Boundary k (0 = bottom, n = top), rounded the same way for every box.
        let edge = |k: i32| bottom - ((bottom - top) as i64 * k as i64 / n as i64) as i32;
        for (k, c) in (0..n).zip(&self.colors) {
            root.draw(&Rectangle::new(
                [(l, edge(k + 1)), (r, edge(k))],
                c.filled(),
            ))?;
        }
        root.draw(&Rectangle::new(
            [(l, top), (r, bottom)],
            INK.stroke_width(1),
        ))?;
        let font = style::text(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
        let mut widest = 0;
        for (k, s) in (1..n).zip(&self.levels) {
            let y = edge(k);
            root.draw(&PathElement::new(vec![(l, y), (r + 4, y)], INK))?;
            root.draw(&Text::new(s.clone(), (r + TICK_PX, y), font.clone()))?;
            widest = widest.max(root.estimate_text_size(s, &style::text(style::TICK_PX))?.0);
        }
        let title_x = r + TICK_PX + widest as i32 + TITLE_GAP_PX + style::LABEL_PX as i32 / 2;
        axes::draw_vertical_label(root, &self.title, title_x, (top + bottom) / 2)
    }
}

/// A filled map's chart: the standard margins with room below for `entries`' legend and right
/// for `bar`, each band's rings filled in its colour (`bands[i]` in `colors[i]`; extra bands
/// stay unfilled), the grid over them and the colour bar beside them. The contour map and the
/// V-locator capacity map share it.
pub fn band_map<'a, 'b, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    x: &PlotAxis,
    y: &PlotAxis,
    entries: &[LegendEntry],
    bands: &[Vec<Vec<(f64, f64)>>],
    colors: &[RGBColor],
    bar: &ColorBar,
) -> Result<Chart<'b, DB>, DrawingAreaErrorKind<DB::ErrorType>>
where
    'a: 'b,
{
    let rows = legend::rows_needed(root, entries)?;
    let m = Margins {
        top: 70,
        bottom: 75 + (rows * legend::ROW_PX) as u32,
        left: 95,
        right: bar.width_px(root)? as u32,
    };
    let chart = build_chart(root, x, y, m)?;
    let area = chart.plotting_area();
    let (px, py) = area.get_pixel_range();
    bar.draw(root, px.end - 1, py.start, py.end - 1)?;
    for (rings, color) in bands.iter().zip(colors) {
        for ring in rings {
            area.draw(&Polygon::new(ring.clone(), color.filled()))?;
        }
    }
    draw_grid(&chart, x, y)?;
    Ok(chart)
}
