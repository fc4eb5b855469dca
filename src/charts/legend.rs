//! Legends, always drawn in a strip outside the plotting area so they never cover data.

use std::cell::RefCell;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult};
use super::style::{self, INK, LineKind, Marker};
use super::tape::{self, Tape};

/// What a legend entry shows beside its text.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// A line sample.
    Line(LineKind),
    /// A marker.
    Marker(Marker),
    /// A line sample with a marker on it.
    LineMarker(LineKind, Marker),
    /// A filled patch of a region colour.
    Patch(RGBColor),
    /// A line sample with a line kind's dashes in another colour and width (px) than its own
    /// (e.g. black on a filled map).
    Stroke(LineKind, RGBColor, u32),
    /// A step's number in a box, for instructions ("how to read").
    Step(u8),
}

/// One legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct LegendEntry {
    /// What the entry's sample looks like.
    pub swatch: Swatch,
    /// Its text.
    pub label: String,
}

impl LegendEntry {
    /// A new entry.
    pub fn new(swatch: Swatch, label: impl Into<String>) -> Self {
        LegendEntry {
            swatch,
            label: label.into(),
        }
    }
}

thread_local! {
    /// The samples legends drew on this thread, while [`record_swatches`] runs.
    static SWATCHES: Tape<Swatch> = const { RefCell::new(None) };
}

/// Runs `draw` and returns, beside its result, every legend sample it drew, in drawing order
/// (the test that no two series look alike).
#[cfg(test)]
pub fn record_swatches<R>(draw: impl FnOnce() -> R) -> (R, Vec<Swatch>) {
    tape::record(&SWATCHES, draw)
}

/// Height in px of one legend row.
pub const ROW_PX: i32 = 24;

/// Legends (and notes) sit under the plot, inset this far from each side of the picture, in px.
pub const INSET_PX: i32 = 60;

/// The width a legend under the plot wraps in: the picture's width less the two insets.
pub fn wrap_width<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>) -> i32 {
    root.dim_in_pixel().0 as i32 - 2 * INSET_PX
}

/// Number of rows `entries` take under the plot (for reserving space).
pub fn rows_needed<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry],
) -> Result<i32, DrawingAreaErrorKind<DB::ErrorType>> {
    Ok(layout(root, entries, 0, wrap_width(root))?
        .last()
        .map_or(0, |p| p.1 + 1))
}

/// Entry positions (x, row) wrapped within [left, left + width).
fn layout<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry],
    left: i32,
    width: i32,
) -> Result<Vec<(i32, i32)>, DrawingAreaErrorKind<DB::ErrorType>> {
    let font = style::text(style::TICK_PX);
    let (mut x, mut row) = (left, 0);
    let mut out = Vec::with_capacity(entries.len());
    for e in entries {
        let w = 40 + root.estimate_text_size(&e.label, &font)?.0 as i32 + 24;
        if x > left && x + w > left + width {
            x = left;
            row += 1;
        }
        out.push((x, row));
        x += w;
    }
    Ok(out)
}

/// Draws `entries` under the plot from `top` (px), inset [`INSET_PX`] on each side, wrapped in rows.
pub fn draw_legend<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry],
    top: i32,
) -> DrawResult<DB> {
    draw_at(root, entries, INSET_PX, top, wrap_width(root))
}

/// Draws `entries` wrapped in rows starting at (left, top), within `width` px.
fn draw_at<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[LegendEntry],
    left: i32,
    top: i32,
    width: i32,
) -> DrawResult<DB> {
    let font = style::text(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (e, (x, row)) in entries.iter().zip(layout(root, entries, left, width)?) {
        tape::note(&SWATCHES, || e.swatch);
        let y = top + row * ROW_PX + ROW_PX / 2;
        match e.swatch {
            Swatch::Line(kind) => {
                style::draw_line(root, &[(x, y), (x + 32, y)], kind, kind.color())?
            }
            Swatch::Stroke(kind, c, px) => {
                style::draw_line_px(root, &[(x, y), (x + 32, y)], kind, c, px)?
            }
            Swatch::Marker(m) => style::draw_marker(root, m, (x + 16, y))?,
            Swatch::LineMarker(kind, m) => {
                let color = style::marked_line_color(m);
                style::draw_line(root, &[(x, y), (x + 32, y)], kind, color)?;
                style::draw_marker(root, m, (x + 16, y))?;
            }
            Swatch::Step(n) => axes::tag(root, &n.to_string(), (x + 16, y))?,
            Swatch::Patch(c) => {
                root.draw(&Rectangle::new([(x, y - 8), (x + 32, y + 8)], c.filled()))?;
                root.draw(&Rectangle::new(
                    [(x, y - 8), (x + 32, y + 8)],
                    INK.stroke_width(1),
                ))?;
            }
        }
        root.draw(&Text::new(e.label.clone(), (x + 40, y), font.clone()))?;
    }
    Ok(())
}

/// Legend entries under a heading, e.g. the paper's numbers apart from the tool's models.
#[derive(Debug, Clone, PartialEq)]
pub struct LegendGroup {
    /// The heading, drawn above the entries and underlined.
    pub heading: String,
    /// The entries, one per row.
    pub entries: Vec<LegendEntry>,
}

/// Space between two columns of a grouped legend, in px.
const COLUMN_GAP_PX: i32 = 24;

/// Where each group goes: (x of its column, first row), side by side in columns one entry a
/// row when they fit in `width` px, one group under the other else.
fn group_layout<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    groups: &[LegendGroup],
    width: i32,
) -> Result<Vec<(i32, i32)>, DrawingAreaErrorKind<DB::ErrorType>> {
    let font = style::text(style::TICK_PX);
    let mut widths = Vec::with_capacity(groups.len());
    for g in groups {
        let mut w = root.estimate_text_size(&g.heading, &font)?.0 as i32;
        for e in &g.entries {
            w = w.max(40 + root.estimate_text_size(&e.label, &font)?.0 as i32);
        }
        widths.push(w);
    }
    let total = widths.iter().sum::<i32>() + COLUMN_GAP_PX * (groups.len() as i32 - 1);
    let mut out = Vec::with_capacity(groups.len());
    let (mut x, mut row) = (0, 0);
    for (g, w) in groups.iter().zip(widths) {
        if total <= width {
            out.push((x, 0));
            x += w + COLUMN_GAP_PX;
        } else {
            out.push((0, row));
            row += 1 + g.entries.len() as i32;
        }
    }
    Ok(out)
}

/// Number of rows `groups` take in `width` px (for reserving space).
pub fn grouped_rows_needed<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    groups: &[LegendGroup],
) -> Result<i32, DrawingAreaErrorKind<DB::ErrorType>> {
    let at = group_layout(root, groups, wrap_width(root))?;
    Ok(groups
        .iter()
        .zip(at)
        .map(|(g, (_, row))| row + 1 + g.entries.len() as i32)
        .max()
        .unwrap_or(0))
}

/// Draws `groups` from (left, top) within `width` px: each group's heading, underlined, then
/// its entries one a row.
pub fn draw_grouped_legend<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    groups: &[LegendGroup],
    top: i32,
) -> DrawResult<DB> {
    let (left, width) = (INSET_PX, wrap_width(root));
    let font = style::text(style::TICK_PX).pos(Pos::new(HPos::Left, VPos::Center));
    for (g, (x, row)) in groups.iter().zip(group_layout(root, groups, width)?) {
        let (x, y) = (left + x, top + row * ROW_PX);
        root.draw(&Text::new(
            g.heading.clone(),
            (x, y + ROW_PX / 2),
            font.clone(),
        ))?;
        let (w, _) = root.estimate_text_size(&g.heading, &style::text(style::TICK_PX))?;
        let rule = y + ROW_PX / 2 + style::TICK_PX as i32 / 2 + 2;
        root.draw(&PathElement::new(
            vec![(x, rule), (x + w as i32, rule)],
            INK,
        ))?;
        for (k, e) in g.entries.iter().enumerate() {
            // One entry a row: its own wrapped legend of one, as wide as anything.
            let entry_top = y + (k as i32 + 1) * ROW_PX;
            draw_at(root, std::slice::from_ref(e), x, entry_top, i32::MAX / 2)?;
        }
    }
    Ok(())
}
