//! Chart kind `vlocator_optimum`: the balanced optimum included angle gamma* of a V and its
//! safety factor rho* against the load direction (at a given P / W) and against P / W (at a
//! given direction), one curve per friction coefficient; the standard V-blocks marked; drawn
//! from [`VlocatorOptimumData`].

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff::{Axis, Fixed, Named, PanelSeries, ParamKey, ReadOffData, Sweep, SweepPanel};
use super::style::{LineKind, Marker};
use super::vlocator_capacity::locator_subtitle;
use super::xy::{Curve, CurveStyle, Figure, Panel, Tag, decade_axis};
use crate::figures::vlocator_capacity::STANDARD_V_DEG;
use crate::figures::vlocator_optimum::{
    MAX_MUS, MuCurves, VlocatorOptimumData, VlocatorOptimumSettings,
};
use crate::grid::{AxisScale, LocatorParam};
use crate::locator::Optimum;

/// Markers of the friction curves, in order.
const MARKERS: [Marker; MAX_MUS] = [
    Marker::Circle,
    Marker::Dot,
    Marker::Triangle,
    Marker::Square,
    Marker::Diamond,
];

/// An optimum chart ready to draw.
#[derive(Debug, Clone)]
pub struct VlocatorOptimum {
    data: VlocatorOptimumData,
    title: String,
}

impl Picture for VlocatorOptimum {
    type Settings = VlocatorOptimumSettings;

    fn new(data: VlocatorOptimumData, title: &str) -> Self {
        VlocatorOptimum {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &VlocatorOptimumData {
        &self.data
    }

    /// What the gallery's read-off needs ([`ReadOffData::Panels`]): the four
    /// frames, each with its x axis (direction above, P / W below), and per friction gamma*
    /// and rho* at every sample as `jamchart vlocator` names them (`null` where the optimum
    /// lies at the search bound, a gap in the chart).
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let fig = self.figure();
        if frames.len() != fig.panels.len() {
            return None;
        }
        let (gamma, rho) = ("included_angle_deg", "safety_factor");
        let params = [LocatorParam::LoadAngleDeg, LocatorParam::LoadOverW];
        let panels = (fig.panels.iter().zip(frames).zip([gamma, rho, gamma, rho]))
            .enumerate()
            .map(|(i, ((p, frame), q))| SweepPanel {
                frame: *frame,
                y: Axis::of(q, &p.y),
                quantity: q,
                x: Axis::of(params[i / 2].as_str(), &p.x),
                sweep: i / 2,
            })
            .collect();
        let s = &self.data.settings;
        let sweep = |i: usize, at: &[f64], fixed, pick: fn(&MuCurves) -> &Vec<Optimum>| {
            let series = (self.data.curves.iter())
                .map(|c| {
                    let drawn = |v: fn(&Optimum) -> f64| {
                        (pick(c).iter().map(|o| (!o.at_bound).then(|| v(o)))).collect()
                    };
                    PanelSeries {
                        label: format!("μ = {}", c.mu),
                        mu: Some(c.mu),
                        columns: Named(vec![
                            (gamma, drawn(|o| o.included_angle_deg)),
                            (rho, drawn(|o| o.safety_factor)),
                        ]),
                    }
                })
                .collect();
            Sweep {
                param: params[i].as_str(),
                at: at.to_vec(),
                fixed: Named(vec![fixed]),
                series,
                param_key: ParamKey::Last,
            }
        };
        let by_load = ("load_over_w", Fixed::Number(Some(s.p_over_w)));
        let by_direction = (
            "load_angle_deg",
            Fixed::Number(Some(s.locator.load_angle_deg)),
        );
        Some(ReadOffData::Panels {
            model: "vlocator",
            panels,
            sweeps: vec![
                sweep(0, &self.data.load_angle_deg, by_load, |c| &c.by_direction),
                sweep(1, &self.data.load_over_w, by_direction, |c| &c.by_load),
            ],
        })
    }

    /// Draws the four panels.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure().draw(root)
    }
}

impl VlocatorOptimum {
    fn figure(&self) -> Figure {
        let dir_label = "load direction φ (deg from +x; 0 sideways, 90 lifts, −90 pushes in)";
        // The load in N too: P = (P / W) W, with this chart's weight.
        let load_label = format!(
            "load P / W at φ = {}° (-; P in N = value × W = {} N)",
            self.data.settings.locator.load_angle_deg,
            super::style::fmt_num(self.data.settings.locator.weight_n(), 3)
        );
        let (da, la) = (
            &self.data.settings.direction_axis,
            &self.data.settings.load_axis,
        );
        let gamma_axis = |label: &str| PlotAxis::new(0.0, 180.0, AxisScale::Linear, label);
        let x_dir = PlotAxis::new(da.min, da.max, da.scale, dir_label);
        let x_load = PlotAxis::new(la.min, la.max, la.scale, load_label);
        let rhos = self
            .data
            .curves
            .iter()
            .flat_map(|c| c.by_direction.iter().chain(&c.by_load))
            .filter(|o| !o.at_bound)
            .map(|o| o.safety_factor);
        let rho_axis = decade_axis(
            rhos.chain([1.0]),
            "safety factor ρ* (factor on load and friction)",
        );
        let gamma_label = format!(
            "optimum included angle γ* (deg), P / W = {}",
            self.data.settings.p_over_w
        );
        let mut panels = vec![
            self.panel(
                x_dir.clone(),
                gamma_axis(&gamma_label),
                &self.data.load_angle_deg,
                |c| &c.by_direction,
                |o| o.included_angle_deg,
            ),
            self.panel(
                x_dir,
                rho_axis.clone(),
                &self.data.load_angle_deg,
                |c| &c.by_direction,
                |o| o.safety_factor,
            ),
            self.panel(
                x_load.clone(),
                gamma_axis("optimum included angle γ* (deg)"),
                &self.data.load_over_w,
                |c| &c.by_load,
                |o| o.included_angle_deg,
            ),
            self.panel(
                x_load,
                rho_axis,
                &self.data.load_over_w,
                |c| &c.by_load,
                |o| o.safety_factor,
            ),
        ];
        // Tagged where the curves leave room: at the left against direction (the curves are
        // high there), at the right against load (they are low there).
        standard_lines(&mut panels[0], false);
        standard_lines(&mut panels[2], true);
        for i in [1, 3] {
            let p = &mut panels[i];
            let (lo, hi) = (p.x.min, p.x.max);
            p.curves.push(Curve {
                label: "ρ* = 1: below it no V that does not lock holds the load".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: vec![(lo, 1.0), (hi, 1.0)],
            });
        }
        Figure {
            title: self.title.clone(),
            subtitle: locator_subtitle(&self.data.settings.locator, "load", false),
            panels,
            notes: vec![
                "γ* balances two failures: the V drops the part when the load grows by ρ and \
                 friction falls by ρ, and it locks (self-locking wedge) when friction grows by ρ; \
                 γ* maximises the smaller ρ. Gaps: the optimum lies at the end of the 1-179° \
                 range (a load pushing into the V is held by any V, so the widest is best)."
                    .into(),
            ],
        }
    }

    /// A panel of one quantity of the optimum against `xs`, one curve per friction; samples at
    /// the search bound leave gaps.
    fn panel(
        &self,
        x: PlotAxis,
        y: PlotAxis,
        xs: &[f64],
        sweep: impl Fn(&MuCurves) -> &Vec<Optimum>,
        value: impl Fn(&Optimum) -> f64,
    ) -> Panel {
        let mut curves = Vec::new();
        for (n, (c, marker)) in self.data.curves.iter().zip(MARKERS).enumerate() {
            let label = format!("μ = {}", c.mu);
            let points: Vec<Option<(f64, f64)>> = xs
                .iter()
                .zip(sweep(c))
                .map(|(&x, o)| (!o.at_bound).then(|| (x, value(o))))
                .collect();
            for run in points.split(Option::is_none) {
                let pts: Vec<(f64, f64)> = run.iter().flatten().copied().collect();
                if !pts.is_empty() {
                    curves.push(Curve {
                        label: label.clone(),
                        // A dash of its own per friction: in print the markers' colours
                        // are near-equal greys.
                        style: CurveStyle::LinePoints(LineKind::Family(n as u8), marker),
                        points: pts,
                    });
                }
            }
        }
        Panel {
            x,
            y,
            curves,
            marks: Vec::new(),
            tags: Vec::new(),
        }
    }
}

/// Dotted horizontals at the standard V-blocks, tagged at the right end (`right`) or the left.
fn standard_lines(p: &mut Panel, right: bool) {
    let (lo, hi) = (p.x.min, p.x.max);
    for g in STANDARD_V_DEG {
        p.curves.push(Curve {
            label: "standard V-blocks 60°, 90°, 120°".into(),
            style: CurveStyle::Line(LineKind::Dotted),
            points: vec![(lo, g), (hi, g)],
        });
        p.tags.push(Tag {
            at: (if right { hi } else { lo }, g + 4.0),
            text: format!("{g:.0}° V"),
            left: right,
        });
    }
}
