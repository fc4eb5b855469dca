//! Chart kind `vlocator_capacity`: the holding capacity P_max / W of a V over its included
//! angle and the load direction, with the self-locking (wedged) band, the region where every
//! load is held, iso-lines of capacity and the standard 60 / 90 / 120 deg V-blocks, drawn from
//! [`VlocatorCapacityData`].

use contour::ContourBuilder;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis};
use super::colorbar::{self, ColorBar};
use super::legend::{self, LegendEntry, Swatch};
use super::picture::Picture;
use super::readoff::{Axis, Grid, Panel, ReadOffData};
use super::style::{self, INK, LineKind, PAPER};
use super::{grid_lines, grid_polygons};
use crate::figures::contours::lines_at;
use crate::figures::vlocator_capacity::{
    STANDARD_V_DEG, UNBOUNDED_OVER_W, VlocatorCapacityData, VlocatorCapacitySettings,
};
use crate::locator::{LocatorParams, Rotation};
use crate::numbers::Num;

/// Tint of the self-locking band (under its hatch).
const WEDGED_FILL: RGBColor = RGBColor(236, 214, 214);

/// A capacity map ready to draw: its data, and the bands and iso-lines traced once in plot
/// space.
#[derive(Debug, Clone)]
pub struct VlocatorCapacity {
    data: VlocatorCapacityData,
    title: String,
    /// Shaded bands, lowest first (the last is the unbounded region).
    bands: Vec<Paths>,
    /// Capacity iso-lines (level in W, paths).
    lines: Vec<(f64, Paths)>,
    /// The edge of the unbounded region.
    unbounded_edge: Paths,
}

/// Polylines or rings in plot space.
type Paths = Vec<Vec<(f64, f64)>>;

impl Picture for VlocatorCapacity {
    type Settings = VlocatorCapacitySettings;

    /// Traces the bands and iso-lines of the capacity the lines follow (the V just unlocked
    /// under the locking band), unbounded cells above every level.
    fn new(data: VlocatorCapacityData, title: &str) -> Self {
        let c = &data.cells;
        let field: Vec<f64> = c
            .unlocked_over_w
            .iter()
            .map(|v| v.map_or(UNBOUNDED_OVER_W, |v| v.min(UNBOUNDED_OVER_W)))
            .collect();
        let s = &data.settings;
        let (xa, ya) = (&s.x_axis, &s.y_axis);
        let b = ContourBuilder::new(c.included_angle_deg.len(), c.load_angle_deg.len(), true);
        let mut edges = vec![f64::MIN];
        edges.extend(&s.levels_over_w);
        edges.push(0.5 * UNBOUNDED_OVER_W);
        edges.push(f64::MAX);
        // Finite values and levels cannot fail; nothing is drawn if they ever did.
        let bands = b
            .isobands(&field, &edges)
            .unwrap_or_default()
            .iter()
            .map(|band| grid_polygons(band.geometry(), xa, ya))
            .collect();
        let mut levels = s.levels_over_w.clone();
        levels.push(0.5 * UNBOUNDED_OVER_W);
        let mut lines: Vec<(f64, Paths)> = lines_at(&b, &field, &levels)
            .into_iter()
            .map(|l| (l.threshold(), grid_lines(&l.into_inner().0, xa, ya)))
            .collect();
        let unbounded_edge = lines.pop().map(|(_, p)| p).unwrap_or_default();
        VlocatorCapacity {
            title: title.to_string(),
            data,
            bands,
            lines,
            unbounded_edge,
        }
    }

    fn data(&self) -> &VlocatorCapacityData {
        &self.data
    }

    /// What the gallery's read-off needs ([`ReadOffData::Grid`]): the plotting area, the axes
    /// and per cell P_max / W, P_max in N (null where every load is held) and whether the
    /// capacity is unbounded, as `jamchart vlocator` names them (model `vlocator`: the exact
    /// path of [`crate::locator::capacity`]).
    fn read_off(&self, frames: &[axes::PlotFrame]) -> Option<ReadOffData> {
        let (x, y) = self.plot_axes();
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        let w = self.data.weight_n;
        let c = &self.data.cells;
        let over_w = &c.p_max_over_w;
        let grid = Grid::over(&c.included_angle_deg, &c.load_angle_deg)
            .numbers("p_max_over_w", |i| over_w[i])
            .numbers("p_max_n", |i| over_w[i].map(|v| v * w))
            .flags("unbounded", |i| over_w[i].is_none());
        Some(ReadOffData::Grid {
            model: "vlocator",
            x: Axis::of(xa.param.as_str(), &x),
            panels: vec![Panel {
                frame: *frames.first()?,
                y: Axis::of(ya.param.as_str(), &y),
            }],
            grid,
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let (x, y) = self.plot_axes();
        let entries = self.legend();
        // Darker = holds more; the unbounded region stays white.
        let levels = &self.data.settings.levels_over_w;
        let mut colors = style::band_colors(levels.len() + 1);
        let bar = ColorBar {
            colors: colors.clone(),
            levels: levels.iter().map(|v| level_text(*v)).collect(),
            title: "holding capacity P_max (multiples of W)".into(),
        };
        colors.push(PAPER);
        let chart = colorbar::band_map(root, &x, &y, &entries, &self.bands, &colors, &bar)?;
        let area = chart.plotting_area();
        for p in &self.unbounded_edge {
            style::draw_line(area, p, LineKind::Dashed, INK)?;
        }
        for (_, paths) in &self.lines {
            for p in paths {
                style::draw_line(area, p, LineKind::Solid, INK)?;
            }
        }
        self.draw_wedged_band(root, &chart, &x, &y)?;
        self.draw_standard_vs(root, &chart, &x, &y)?;
        for (level, paths) in &self.lines {
            // Labelled off the sideways line (the standard V-blocks are read there), right
            // of the locking band.
            let clear = x.to_plot(self.data.self_locking_below_included_angle_deg) + 3.0;
            let pt = [-25.0, -50.0, 25.0, 50.0].into_iter().find_map(|h| {
                nearest_to_height(paths, y.to_plot(h))
                    .filter(|p| p.0 > clear && (p.1 - y.to_plot(h)).abs() < 2.0)
            });
            if let Some(&(u, v)) = pt {
                let at = chart.backend_coord(&(u, v));
                let s = format!("{} W", level_text(*level));
                axes::boxed_text(
                    root,
                    &s,
                    at,
                    Pos::new(HPos::Center, VPos::Center),
                    style::TICK_PX,
                )?;
            }
        }
        axes::draw_frame(root, &chart, &x, &y)?;
        axes::draw_header(
            root,
            &self.title,
            &locator_subtitle(&self.data.settings.locator, "load at any angle", true),
        )?;
        let (_, py) = area.get_pixel_range();
        legend::draw_legend(root, &entries, py.end + 62)
    }
}

impl VlocatorCapacity {
    /// The drawn axes: included angle on x, load direction on y.
    fn plot_axes(&self) -> (PlotAxis, PlotAxis) {
        let (xa, ya) = (&self.data.settings.x_axis, &self.data.settings.y_axis);
        let x = PlotAxis::new(xa.min, xa.max, xa.scale, "included angle γ of the V (deg)");
        let y = PlotAxis::new(
            ya.min,
            ya.max,
            ya.scale,
            "load direction φ (deg from +x; −90 pushes into the V, 0 sideways, 90 lifts)",
        );
        (x, y)
    }

    /// The self-locking band, hatched, labelled with its bound.
    fn draw_wedged_band<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let (xr, yr) = (x.plot_range(), y.plot_range());
        let right = x
            .to_plot(self.data.self_locking_below_included_angle_deg)
            .min(xr.end);
        if right <= xr.start {
            return Ok(());
        }
        chart.plotting_area().draw(&Rectangle::new(
            [(xr.start, yr.start), (right, yr.end)],
            WEDGED_FILL.filled(),
        ))?;
        // Hatch at 45 deg, every 12 px, in the root's pixels (the root sits at the origin).
        let (l, t) = chart.backend_coord(&(xr.start, yr.end));
        let (r, b) = chart.backend_coord(&(right, yr.start));
        let mut k = l - (b - t);
        while k < r {
            let x0 = k.max(l);
            let x1 = (k + (b - t)).min(r);
            if x1 > x0 {
                root.draw(&PathElement::new(
                    vec![(x0, b - (x0 - k)), (x1, b - (x1 - k))],
                    INK.mix(0.35).stroke_width(1),
                ))?;
            }
            k += 12;
        }
        let label = format!(
            "wedged: self-locks below γ = {:.1}°",
            self.data.self_locking_below_included_angle_deg
        );
        let font = style::text(style::TICK_PX)
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Center));
        let (text_w, _) = root.estimate_text_size(&label, &style::text(style::TICK_PX))?;
        if (text_w as i32) < b - t && r - l > 24 {
            root.draw(&Rectangle::new(
                [
                    ((l + r) / 2 - 11, (t + b) / 2 - text_w as i32 / 2 - 4),
                    ((l + r) / 2 + 11, (t + b) / 2 + text_w as i32 / 2 + 4),
                ],
                PAPER.filled(),
            ))?;
            root.draw(&Text::new(label, ((l + r) / 2, (t + b) / 2), font))?;
        }
        Ok(())
    }

    /// Dotted verticals at the standard V-blocks, labelled at the top.
    fn draw_standard_vs<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        x: &PlotAxis,
        y: &PlotAxis,
    ) -> DrawResult<DB> {
        let yr = y.plot_range();
        for g in STANDARD_V_DEG
            .into_iter()
            .filter(|g| (x.min..=x.max).contains(g))
        {
            let u = x.to_plot(g);
            style::draw_line(
                chart.plotting_area(),
                &[(u, yr.start), (u, yr.end)],
                LineKind::Dashed,
                INK,
            )?;
            let at = chart.backend_coord(&(u, yr.end));
            let s = format!("{g:.0}° V-block");
            axes::boxed_text(
                root,
                &s,
                (at.0, at.1 + 14),
                Pos::new(HPos::Center, VPos::Center),
                style::TICK_PX,
            )?;
            // The read-off a designer wants first: what it holds sideways.
            let blocks = &self.data.standard_v_blocks;
            if let Some(v) = blocks.iter().find(|v| v.included_angle_deg == g) {
                let s = match v.sideways.p_max_over_w {
                    Some(c) => format!("sideways: {} W", style::fmt_num(c, 2)),
                    None => "sideways: unbounded".to_string(),
                };
                let p = chart.backend_coord(&(u, y.to_plot(0.0)));
                style::draw_marker(root, style::Marker::Dot, p)?;
                axes::boxed_text(
                    root,
                    &s,
                    (p.0 + 8, p.1 - 6),
                    Pos::new(HPos::Left, VPos::Bottom),
                    style::TICK_PX,
                )?;
            }
        }
        Ok(())
    }

    fn legend(&self) -> Vec<LegendEntry> {
        // The self-locking band is drawn (and listed) only where it reaches into the axis.
        let wedged_in_view = self.data.self_locking_below_included_angle_deg
            > self
                .data
                .settings
                .x_axis
                .min
                .min(self.data.settings.x_axis.max);
        let mut entries = vec![
            LegendEntry::new(
                Swatch::Line(LineKind::Solid),
                "P_max iso-lines (multiples of W)",
            ),
            LegendEntry::new(
                Swatch::Patch(PAPER),
                "white beyond the dashed line: every load held (it pushes into the V)",
            ),
            LegendEntry::new(
                Swatch::Patch(WEDGED_FILL),
                "hatched: the V self-locks, the part can jam",
            ),
            LegendEntry::new(
                Swatch::Stroke(LineKind::Dashed, INK, LineKind::Dashed.width()),
                "standard V-blocks, with P_max / W for a sideways load (φ = 0)",
            ),
        ];
        if !wedged_in_view {
            entries.remove(2);
        }
        entries
    }
}

/// One line naming the locator's parameters for under the title; `with_mu` false when the
/// chart varies the friction itself. Numbers as the CLI echoes them ([`Num`]): a friction set
/// from a range's midpoint (0.30000000000000004) reads 0.3.
pub fn locator_subtitle(p: &LocatorParams, load: &str, with_mu: bool) -> String {
    let mu = if !with_mu {
        "μ on both flanks as marked".to_string()
    } else if p.mu_left == p.mu_right {
        format!("μ = {} on both flanks", Num(p.mu_left))
    } else {
        format!("μ = {} left, {} right", Num(p.mu_left), Num(p.mu_right))
    };
    let at = p
        .load_at_rim_deg
        .map_or("at the centre".to_string(), |psi| {
            format!("at the rim, ψ = {}°", Num(psi))
        });
    let rotation = match p.rotation {
        Rotation::Free => "free rotation (a real V-block)",
        Rotation::Blocked => "rotation blocked (the paper's translational model)",
    };
    format!(
        "exact support-cone model: {rotation}, {mu}, W = m g = {:.3} N, {load} {at}",
        p.weight_n()
    )
}

/// A level as a label: at most two decimals, no trailing zeros.
pub(super) fn level_text(v: f64) -> String {
    let s = style::fmt_num(v, 2);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// The path point whose plot-y is nearest `v`.
fn nearest_to_height(paths: &[Vec<(f64, f64)>], v: f64) -> Option<&(f64, f64)> {
    paths
        .iter()
        .flatten()
        .min_by(|a, b| (a.1 - v).abs().total_cmp(&(b.1 - v).abs()))
}

#[cfg(test)]
mod subtitle_tests {
    use super::*;

    /// The capacity chart's subtitle printed unequal frictions with Rust's bare `{}`: a
    /// friction from a range's midpoint read "μ = 0.30000000000000004 left, 0.25 right".
    #[test]
    fn unequal_frictions_in_the_subtitle_are_formatted_numbers() {
        let p = LocatorParams {
            mu_left: (0.2 + 0.4) / 2.0,
            mu_right: 0.25,
            load_at_rim_deg: Some(0.1 + 0.2),
            ..LocatorParams::default()
        };
        let s = locator_subtitle(&p, "load", true);
        assert!(s.contains("μ = 0.3 left, 0.25 right"), "{s}");
        assert!(s.contains("ψ = 0.3°"), "{s}");
        let equal = LocatorParams {
            mu_left: 0.1 + 0.2,
            mu_right: 0.1 + 0.2,
            ..LocatorParams::default()
        };
        let s = locator_subtitle(&equal, "load", true);
        assert!(s.contains("μ = 0.3 on both flanks"), "{s}");
    }
}
