//! Chart kind `stability` (scene `stability-matrix`): the stability matrix at a glance, one row per
//! case and one column per model and method, each cell coloured by its class
//! ([`crate::study::stability::Class`]) and labelled with x_jam or the status; drawn from
//! [`StabilityData`].

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis, PlotFrame, draw_header};
use super::picture::Picture;
use super::readoff::{Axis, PointsPanel, ReadOffData, Rows};
use super::style;
use crate::figures::stability::{StabilityData, StabilitySettings};
use crate::grid::AxisScale;
use crate::scene::JamStatus;
use crate::study::stability::Class;

/// The matrix ready to draw.
#[derive(Debug, Clone)]
pub struct Stability {
    data: StabilityData,
    title: String,
}

/// Each class's tint; their greys (luma about 230, 198, 172, 126) differ too, so the classes
/// stay apart in the print style (`style = "print"`), lightest for correct.
const FILL: [(Class, RGBColor); 4] = [
    (Class::Correct, RGBColor(215, 240, 215)),
    (Class::InaccurateFlagged, RGBColor(230, 165, 60)),
    (Class::FailedNamed, RGBColor(185, 198, 228)),
    (Class::WrongUnflagged, RGBColor(235, 80, 80)),
];

fn fill(c: Class) -> RGBColor {
    FILL.iter().find(|f| f.0 == c).map_or(style::PAPER, |f| f.1)
}

impl Picture for Stability {
    type Settings = StabilitySettings;

    fn new(data: StabilityData, title: &str) -> Self {
        Stability {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &StabilityData {
        &self.data
    }

    /// The gallery's read-off ([`ReadOffData::Points`], no crosshair): the cell under the
    /// pointer, with its row of the data file (case, method, status, x_jam, the reference, the
    /// error and its allowance, the class). The cells are points at (method index, -case
    /// index) over the matrix's frame, so the nearest point is the cell under the pointer.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let [frame] = *frames else { return None };
        let (n_m, n_c) = (self.data.methods.len(), self.data.cases.len());
        let x = PlotAxis::new(-0.5, n_m as f64 - 0.5, AxisScale::Linear, "method");
        let y = PlotAxis::new(0.5 - n_c as f64, 0.5, AxisScale::Linear, "case");
        let cells: Vec<_> = (0..self.data.rows.len().min(n_m * n_c))
            .map(|k| ((k % n_m) as f64, -((k / n_m) as f64), k))
            .collect();
        Some(ReadOffData::Points {
            crosshair: false,
            cell: Some([1.0, 1.0]),
            panels: vec![PointsPanel::new(
                frame,
                Axis::of("", &x),
                Axis::of("", &y),
                &cells,
            )],
            rows: Rows::Stability(self.data.rows.clone()),
        })
    }

    /// Draws the matrix.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (w, h) = root.dim_in_pixel();
        let (w, h) = (w as i32, h as i32);
        let r = &self.data;
        let n_cases = r.cases.len().max(1) as i32;
        let n_methods = r.methods.len().max(1) as i32;
        draw_header(
            root,
            &self.title,
            "class of each answer against the case's physical reference (closed form at F; \
             rigid limit for the motion drive; rigid dynamics for the force drive)",
        )?;
        let (left, top, bottom_room) = (440, 110, 90);
        let cell_w = (w - left - 20) / n_methods;
        let cell_h = ((h - top - bottom_room) / n_cases).max(12);
        axes::record_area(
            root,
            (left, top),
            (left + n_methods * cell_w, top + n_cases * cell_h),
        );
        let head = style::text(14.0).pos(Pos::new(HPos::Center, VPos::Bottom));
        for (j, m) in r.methods.iter().enumerate() {
            let x = left + j as i32 * cell_w + cell_w / 2;
            // Two lines: model and the rest.
            let (a, b) = m.split_once(' ').unwrap_or((m.as_str(), ""));
            root.draw(&Text::new(a.to_string(), (x, top - 22), head.clone()))?;
            root.draw(&Text::new(b.to_string(), (x, top - 6), head.clone()))?;
        }
        let case_font = style::text(13.0).pos(Pos::new(HPos::Right, VPos::Center));
        let cell_font = style::text(12.0).pos(Pos::new(HPos::Center, VPos::Center));
        for (i, c) in r.cases.iter().enumerate() {
            let y = top + i as i32 * cell_h;
            root.draw(&Text::new(
                format!("{}: {}", c.name, c.what),
                (left - 8, y + cell_h / 2),
                case_font.clone(),
            ))?;
            for j in 0..r.methods.len() {
                let Some(row) = r.rows.get(i * r.methods.len() + j) else {
                    continue;
                };
                let x = left + j as i32 * cell_w;
                root.draw(&Rectangle::new(
                    [(x, y), (x + cell_w, y + cell_h)],
                    fill(row.class).filled(),
                ))?;
                root.draw(&Rectangle::new(
                    [(x, y), (x + cell_w, y + cell_h)],
                    style::PAPER.stroke_width(1),
                ))?;
                let label = match (row.status, row.x_jam_mm) {
                    (JamStatus::Jams, Some(x)) => format!("{} mm", style::fmt_num(x, 4)),
                    (s, _) => s.as_str().replace('_', " "),
                };
                root.draw(&Text::new(
                    label,
                    (x + cell_w / 2, y + cell_h / 2),
                    cell_font.clone(),
                ))?;
            }
        }
        // Legend: each class with its count (wrong_unflagged must read 0).
        let legend_y = top + n_cases * cell_h + 30;
        let lf = style::text(14.0).pos(Pos::new(HPos::Left, VPos::Center));
        let mut x = left;
        for (class, colour) in FILL {
            let count = r.of_class(class).count();
            root.draw(&Rectangle::new(
                [(x, legend_y - 8), (x + 18, legend_y + 8)],
                colour.filled(),
            ))?;
            let text = format!("{} ({count})", class.as_str().replace('_', " "));
            root.draw(&Text::new(text, (x + 24, legend_y), lf.clone()))?;
            x += 200;
        }
        let note = style::text(13.0).pos(Pos::new(HPos::Left, VPos::Center));
        root.draw(&Text::new(
            "cell: x_jam where the method says it jams, else its status; wall times and \
             reasons: jamchart stability"
                .to_string(),
            (left, legend_y + 26),
            note,
        ))?;
        Ok(())
    }
}
