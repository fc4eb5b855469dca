//! Chart kind `vlocator_robust`: the window of included angles of a V-block that holds every
//! load of a range without self-locking at any friction of a range, against the width of the
//! friction range, with the most robust angle and the standard 60/90/120 deg V-blocks marked;
//! drawn from [`VlocatorRobustData`].

use plotters::coord::Shift;
use plotters::prelude::*;
use serde_json::json;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff;
use super::style::LineKind;
use super::vlocator_capacity::locator_subtitle;
use super::xy::{Curve, CurveStyle, Figure, Panel, Tag};
use crate::figures::vlocator_capacity::STANDARD_V_DEG;
use crate::figures::vlocator_robust::{VlocatorRobustData, VlocatorRobustSettings};
use crate::grid::AxisScale;
use crate::locator::{RobustBox, RobustDesign};

/// A robust-design chart ready to draw.
#[derive(Debug, Clone)]
pub struct VlocatorRobust {
    data: VlocatorRobustData,
    title: String,
}

impl Picture for VlocatorRobust {
    type Settings = VlocatorRobustSettings;

    fn new(data: VlocatorRobustData, title: &str) -> Self {
        VlocatorRobust {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &VlocatorRobustData {
        &self.data
    }

    /// What the gallery's read-off needs (see [`super::readoff`], kind `panels`): the frame,
    /// and per width the friction range and the design as the CSV names them (the first
    /// window; `null` where no V works), the box's loads as fixed inputs.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let fig = self.figure();
        let (p, frame) = (fig.panels.first()?, frames.first()?);
        // The pointer's y is read against the most robust angle (the crosshair lands on it).
        let y = readoff::axis("included_angle_deg", &p.y);
        let x = readoff::axis("mu_width", &p.x);
        let panel = readoff::sweep_panel(frame, x, y, "robust_deg", 0);
        let d = &self.data.designs;
        let col = |v: &dyn Fn(&RobustDesign) -> Option<f64>| readoff::column(d.iter().map(v));
        let boxes: Vec<RobustBox> = self
            .data
            .widths
            .iter()
            .map(|&w| self.data.settings.box_of(w))
            .collect();
        let series = json!({
            "label": "robust design",
            "mu_lo": readoff::column(boxes.iter().map(|b| b.mu_left.0)),
            "mu_hi": readoff::column(boxes.iter().map(|b| b.mu_left.1)),
            "lock_bound_deg": col(&|d| Some(d.lock_bound_deg)),
            "window_lo_deg": col(&|d| d.windows.first().map(|w| w.0)),
            "window_hi_deg": col(&|d| d.windows.first().map(|w| w.1)),
            "robust_deg": col(&|d| d.robust.map(|r| r.included_angle_deg)),
            "safety_factor": col(&|d| d.robust.map(|r| r.safety_factor).filter(|r| r.is_finite())),
        });
        let s = &self.data.settings;
        Some(json!({
            "kind": "panels",
            "model": "vlocator",
            "panels": [panel],
            "sweeps": [{
                "param": "mu_width",
                "at": self.data.widths,
                "fixed": { "mu_center": s.mu_center, "load_n": s.load_n, "load_angle_deg": s.load_angle_deg },
                "series": [series],
            }],
        }))
    }

    /// Draws the panel.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure().draw(root)
    }
}

impl VlocatorRobust {
    fn figure(&self) -> Figure {
        let s = &self.data.settings;
        let x = PlotAxis::new(
            0.0,
            s.width_max,
            AxisScale::Linear,
            format!(
                "width w of the friction range (-): μ from {} − w/2 to {} + w/2, both flanks",
                s.mu_center, s.mu_center
            ),
        );
        let y = PlotAxis::new(0.0, 180.0, AxisScale::Linear, "included angle γ (deg)");
        let mut curves = Vec::new();
        // The window as vertical bars, one per width: a band without a fill style.
        for (&w, d) in self.data.widths.iter().zip(&self.data.designs) {
            for &(lo, hi) in &d.windows {
                curves.push(Curve {
                    label: "window: holds every load, never locks".into(),
                    style: CurveStyle::Line(LineKind::Solid),
                    points: vec![(w, lo), (w, hi)],
                });
            }
        }
        let lock: Vec<(f64, f64)> = self
            .data
            .widths
            .iter()
            .zip(&self.data.designs)
            .map(|(&w, d)| (w, d.lock_bound_deg))
            .collect();
        curves.push(Curve {
            label: "2 atan μ_hi: narrower locks at the top friction".into(),
            style: CurveStyle::Line(LineKind::Dashed),
            points: lock,
        });
        let robust: Vec<(f64, f64)> = self
            .data
            .widths
            .iter()
            .zip(&self.data.designs)
            .filter_map(|(&w, d)| d.robust.map(|r| (w, r.included_angle_deg)))
            .collect();
        if !robust.is_empty() {
            curves.push(Curve {
                label: "most robust γ (largest common factor ρ* on loads and friction)".into(),
                // Purple dots: apart from the black bars it runs through.
                style: CurveStyle::Line(LineKind::Level),
                points: robust,
            });
        }
        let mut tags = Vec::new();
        for g in STANDARD_V_DEG {
            curves.push(Curve {
                label: "standard V-blocks 60°, 90°, 120°".into(),
                style: CurveStyle::Line(LineKind::Dotted),
                points: vec![(0.0, g), (s.width_max, g)],
            });
            tags.push(Tag {
                at: (s.width_max, g + 4.0),
                text: format!("{g:.0}° V"),
                left: true,
            });
        }
        let closes = self
            .data
            .widths
            .iter()
            .zip(&self.data.designs)
            .find(|(_, d)| d.windows.is_empty())
            .map(|(&w, _)| w);
        let mut notes = vec![format!(
            "Loads {} to {} N at {}° to {}°; a V works when it holds every load at the lowest \
             friction and does not lock at the highest (both ends decide: see the locator docs).",
            s.load_n[0], s.load_n[1], s.load_angle_deg[0], s.load_angle_deg[1]
        )];
        if let Some(w) = closes {
            notes.push(format!(
                "No single V works from a range width of {} on (no bar): narrow the friction \
                 range or lighten the load.",
                super::style::fmt_num(w, 3)
            ));
        }
        Figure {
            title: self.title.clone(),
            // The frictions are the x axis' ranges, not curves "as marked".
            subtitle: locator_subtitle(&s.locator, "loads as noted", false)
                .replace("μ on both flanks as marked", "μ ranges on the x axis"),
            panels: vec![Panel {
                x,
                y,
                curves,
                marks: Vec::new(),
                tags,
            }],
            notes,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charts::builtin::scene_text;
    use crate::locator::robust_design;

    fn built_in() -> VlocatorRobustSettings {
        let table: toml::Table = toml::from_str(scene_text("vlocator-robust").unwrap()).unwrap();
        let mut chart = table["chart"].as_table().unwrap().clone();
        chart.remove("kind");
        toml::Value::Table(chart).try_into().unwrap()
    }

    /// The built-in scene's window against the closed form of a free symmetric V under centre
    /// loads within 10 deg of sideways (`robust` docs): it opens at 2 atan mu_hi, its top is
    /// the heaviest load at the most lifting direction, x <= (W / P - sin 10) / cos 10 with
    /// x = tan(gamma/2), and it closes where the two meet.
    #[test]
    fn robust_chart_window_matches_the_closed_form() {
        let s = built_in();
        let w = s.locator.weight_n();
        let (sn, cs) = 10.0_f64.to_radians().sin_cos();
        let x_top = (w / s.load_n[1] - sn) / cs;
        let top = 2.0 * x_top.atan().to_degrees();
        let mut worst: f64 = 0.0;
        for k in 0..s.count {
            let width = s.width_max * k as f64 / (s.count - 1) as f64;
            let b = s.box_of(width);
            let d = robust_design(&s.locator, &b);
            let lock = 2.0 * b.mu_left.1.atan().to_degrees();
            if b.mu_left.1 < x_top * (1.0 - 1e-9) {
                let (lo, hi) = d.windows[0];
                worst = worst.max((lo - lock).abs()).max((hi - top).abs());
            } else if b.mu_left.1 > x_top * (1.0 + 1e-9) {
                assert!(d.windows.is_empty(), "{width}: {d:?}");
            }
        }
        // The arc cover overstates the load by at most 1e-5: the top moves by less than 1e-3 deg.
        assert!(worst < 1e-3, "worst {worst:e} deg");
    }
}
