//! The read-off at a point of a two-parameter map (universal, contour): line 1 up from the x
//! axis, line 2 across from the y axis, a dot where they meet and step 3, the answer, printed
//! beside it.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis};
use super::style::{self, INK, LineKind};

/// Where step 3's answer goes, above or below the point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AnswerAt {
    /// Below the point (the universal chart: its labels run along the top).
    Below,
    /// Towards the middle of the plot: above a point in the lower half, below one in the upper
    /// half (a contour map labels its settle line near the bottom, its theta_jam lines near
    /// the top).
    TowardsMiddle,
}

/// Draws the read-off at value point `(u, v)` of `c` with `answer` (starting "3: ") beside it:
/// right of the point, or left of it in the right half of the plot; above or below as `place`
/// says.
pub fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    c: &axes::Chart<DB>,
    (x, y): (&PlotAxis, &PlotAxis),
    (u, v): (f64, f64),
    answer: &str,
    place: AnswerAt,
) -> DrawResult<DB> {
    let at = |a: f64, b: f64| axes::pixel(c, x, y, a, b);
    let (corner, bottom, left) = (at(u, v), at(u, y.min), at(x.min, v));
    for line in [[bottom, corner], [left, corner]] {
        style::draw_line_px(root, &line, LineKind::Dotted, INK, 2)?;
    }
    root.draw(&Circle::new(corner, 5, INK.filled()))?;
    let num = |s: &str, p: (i32, i32)| axes::tag(root, s, p);
    num("1", (bottom.0 + 12, (bottom.1 + corner.1) / 2))?;
    num("2", ((left.0 + corner.0) / 2, corner.1 - 14))?;
    let (px, py) = c.plotting_area().get_pixel_range();
    let lower_half = corner.1 > (py.start + py.end) / 2;
    let (dy, v_pos) = match place {
        AnswerAt::TowardsMiddle if lower_half => (-18, VPos::Bottom),
        _ => (18, VPos::Top),
    };
    let right_half = corner.0 > (px.start + px.end) / 2;
    let (dx, h) = if right_half {
        (-12, HPos::Right)
    } else {
        (12, HPos::Left)
    };
    axes::boxed_text(
        root,
        answer,
        (corner.0 + dx, corner.1 + dy),
        Pos::new(h, v_pos),
        style::NOTE_PX,
    )
}
