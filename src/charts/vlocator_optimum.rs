//! Chart kind `vlocator_optimum`: the balanced optimum included angle gamma* of a V and its
//! safety factor rho*, against the load direction (at a given P / W) and against P / W (at a
//! given direction), one curve per friction coefficient; the standard V-blocks marked.

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::{Deserialize, Serialize};
use serde_json::json;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::spec::Scene;
use super::style::{LineKind, Marker};
use super::vlocator_capacity::{STANDARD_V_DEG, locator_subtitle};
use super::xy::{Curve, CurveStyle, Figure, Panel, Tag, decade_axis};
use super::{DataFile, readoff};
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::grid::{AxisScale, Grid, GridAxis, LocatorParam};
use crate::locator::{self, LocatorParams, Optimum};

/// `[chart]` keys of `kind = "vlocator_optimum"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VlocatorOptimumSpec {
    /// The V's tilt, rotation, load point and weight (default: [`LocatorParams::default`]);
    /// the included angle is the unknown, the axes and `mus` set the rest.
    #[serde(default)]
    pub locator: LocatorParams,
    /// One curve per friction coefficient (both flanks), increasing.
    pub mus: Vec<f64>,
    /// Upper panels: the load direction axis (`load_angle_deg`).
    pub direction_axis: GridAxis<LocatorParam>,
    /// P / W of the upper panels.
    pub p_over_w: f64,
    /// Lower panels: the load axis (`load_over_w`), at the locator's load direction.
    pub load_axis: GridAxis<LocatorParam>,
}

impl super::kinds::Kind for VlocatorOptimumSpec {
    /// The V-block's parameters are `[chart.locator]`'s, not the palm scene's.
    fn takes_scene(&self) -> bool {
        false
    }

    type Chart = VlocatorOptimum;

    /// Checks the axes, the frictions and the load.
    fn validate(&self, _scene: &Scene) -> Result<()> {
        if self.direction_axis.param != LocatorParam::LoadAngleDeg {
            return Err(Error::invalid(
                "chart.direction_axis.param",
                self.direction_axis.param.as_str(),
                "use load_angle_deg",
            ));
        }
        if self.load_axis.param != LocatorParam::LoadOverW {
            return Err(Error::invalid(
                "chart.load_axis.param",
                self.load_axis.param.as_str(),
                "use load_over_w",
            ));
        }
        let m = &self.mus;
        if m.is_empty()
            || m.len() > MARKERS.len()
            || !m.windows(2).all(|w| w[0] < w[1])
            || !m.iter().all(|v| v.is_finite() && *v > 0.0)
        {
            return Err(Error::invalid(
                "chart.mus",
                format!("{m:?}"),
                format!("give 1 to {} increasing frictions > 0", MARKERS.len()),
            ));
        }
        if !(self.p_over_w.is_finite() && self.p_over_w > 0.0) {
            return Err(Error::invalid(
                "chart.p_over_w",
                self.p_over_w,
                "the load of the direction panels is a finite P / W > 0",
            ));
        }
        for mu in m {
            for g in self.grids(*mu) {
                g.validate()?;
            }
        }
        Ok(())
    }

    /// The optimum at every sample of both sweeps, through the grid.
    fn compute(&self, scene: &Scene, _models: &dyn Models) -> Result<VlocatorOptimum> {
        let spec = self;
        let mut curves = Vec::with_capacity(spec.mus.len());
        let (mut directions, mut loads) = (Vec::new(), Vec::new());
        for &mu in &spec.mus {
            let [by_dir, by_load] = spec.grids(mu);
            let d = by_dir.map(|p| Ok(locator::optimum(p)))?;
            let l = by_load.map(|p| Ok(locator::optimum(p)))?;
            directions = d.x_values;
            loads = l.x_values;
            curves.push(MuCurves {
                mu,
                by_direction: d.values,
                by_load: l.values,
            });
        }
        Ok(VlocatorOptimum {
            spec: spec.clone(),
            title: scene.title.clone(),
            directions,
            loads,
            curves,
        })
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        // At most five curves (one per marker) of two sweeps.
        let n = (self.direction_axis.count + self.load_axis.count) as f64 * self.mus.len() as f64;
        // Work, not only memory: each point is a search over the included angle.
        let max = crate::limits::MAX_OPTIMUM_POINTS;
        if n > max as f64 {
            return Err(Error::invalid(
                "chart.direction_axis.count + chart.load_axis.count",
                format!("{n} optima ({} mus)", self.mus.len()),
                format!(
                    "a V-block optimum chart computes at most {max} optima (about 25 s on 2 \
                     cores); lower the counts or the number of mus"
                ),
            ));
        }
        crate::limits::check_items(
            "chart.direction_axis.count + chart.load_axis.count",
            n,
            crate::limits::SWEEP_POINT,
        )
    }
}

impl VlocatorOptimumSpec {
    /// The two sweeps at friction `mu`: over the direction, over the load.
    fn grids(&self, mu: f64) -> [Grid<LocatorParams>; 2] {
        let base = self.locator.with_mu(mu);
        let at_load = LocatorParams {
            load_n: self.p_over_w * base.weight_n(),
            ..base
        };
        [
            Grid {
                base: at_load,
                x: self.direction_axis,
                y: None,
            },
            Grid {
                base,
                x: self.load_axis,
                y: None,
            },
        ]
    }
}

/// Markers of the friction curves, in order.
const MARKERS: [Marker; 5] = [
    Marker::Circle,
    Marker::Dot,
    Marker::Triangle,
    Marker::Square,
    Marker::Diamond,
];

/// One friction's two sweeps.
#[derive(Debug, Clone, Serialize)]
struct MuCurves {
    mu: f64,
    /// Optimum per load direction (the direction axis' values).
    by_direction: Vec<Optimum>,
    /// Optimum per P / W (the load axis' values).
    by_load: Vec<Optimum>,
}

/// The computed optimum chart.
#[derive(Debug, Clone)]
pub struct VlocatorOptimum {
    spec: VlocatorOptimumSpec,
    title: String,
    directions: Vec<f64>,
    loads: Vec<f64>,
    curves: Vec<MuCurves>,
}

impl VlocatorOptimum {
    /// The data behind the chart as JSON.
    pub fn data_file(&self, scene: &Scene) -> DataFile {
        DataFile::json(&json!({
            "scene": scene.name, "title": self.title, "locator": self.spec.locator,
            "p_over_w_of_direction_sweep": self.spec.p_over_w,
            "load_angle_deg": self.directions, "load_over_w": self.loads,
            "curves": self.curves,
        }))
    }

    /// What the gallery's read-off needs (see [`super::readoff`], kind `panels`): the four
    /// frames, each with its x axis (direction above, P / W below), and per friction gamma*
    /// and rho* at every sample as `jamchart vlocator` names them (`null` where the optimum
    /// lies at the search bound, a gap in the chart).
    pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let fig = self.figure();
        if frames.len() != fig.panels.len() {
            return None;
        }
        let (gamma, rho) = ("included_angle_deg", "safety_factor");
        let params = [LocatorParam::LoadAngleDeg, LocatorParam::LoadOverW];
        let panels: Vec<_> = fig
            .panels
            .iter()
            .zip(frames)
            .zip([gamma, rho, gamma, rho])
            .enumerate()
            .map(|(i, ((p, frame), q))| {
                let x = readoff::axis(params[i / 2].as_str(), &p.x);
                readoff::sweep_panel(frame, x, readoff::axis(q, &p.y), q, i / 2)
            })
            .collect();
        let sweep = |at: &[f64], pick: fn(&MuCurves) -> &Vec<Optimum>| {
            let series: Vec<_> = self
                .curves
                .iter()
                .map(|c| {
                    let drawn = |v: fn(&Optimum) -> f64| {
                        readoff::column(pick(c).iter().map(|o| (!o.at_bound).then(|| v(o))))
                    };
                    json!({
                        "label": format!("μ = {}", c.mu),
                        "mu": c.mu,
                        gamma: drawn(|o| o.included_angle_deg),
                        rho: drawn(|o| o.safety_factor),
                    })
                })
                .collect();
            json!({ "at": at, "series": series })
        };
        let mut sweeps = [
            sweep(&self.directions, |c| &c.by_direction),
            sweep(&self.loads, |c| &c.by_load),
        ];
        sweeps[0]["fixed"] = json!({ "load_over_w": self.spec.p_over_w });
        sweeps[1]["fixed"] = json!({ "load_angle_deg": self.spec.locator.load_angle_deg });
        for (s, p) in sweeps.iter_mut().zip(params) {
            s["param"] = p.as_str().into();
        }
        Some(json!({
            "kind": "panels",
            "model": "vlocator",
            "panels": panels,
            "sweeps": sweeps,
        }))
    }

    /// Draws the four panels.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure().draw(root)
    }

    fn figure(&self) -> Figure {
        let dir_label = "load direction φ (deg from +x; 0 sideways, 90 lifts, −90 pushes in)";
        // The load in N too: P = (P / W) W, with this chart's weight.
        let load_label = format!(
            "load P / W at φ = {}° (-; P in N = value × W = {} N)",
            self.spec.locator.load_angle_deg,
            super::style::fmt_num(self.spec.locator.weight_n(), 3)
        );
        let (da, la) = (&self.spec.direction_axis, &self.spec.load_axis);
        let gamma_axis = |label: &str| PlotAxis::new(0.0, 180.0, AxisScale::Linear, label);
        let x_dir = PlotAxis::new(da.min, da.max, da.scale, dir_label);
        let x_load = PlotAxis::new(la.min, la.max, la.scale, load_label);
        let rhos = self
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
            self.spec.p_over_w
        );
        let mut panels = vec![
            self.panel(
                x_dir.clone(),
                gamma_axis(&gamma_label),
                &self.directions,
                |c| &c.by_direction,
                |o| o.included_angle_deg,
            ),
            self.panel(
                x_dir,
                rho_axis.clone(),
                &self.directions,
                |c| &c.by_direction,
                |o| o.safety_factor,
            ),
            self.panel(
                x_load.clone(),
                gamma_axis("optimum included angle γ* (deg)"),
                &self.loads,
                |c| &c.by_load,
                |o| o.included_angle_deg,
            ),
            self.panel(
                x_load,
                rho_axis,
                &self.loads,
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
            subtitle: locator_subtitle(&self.spec.locator, "load", false),
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
        for (n, (c, marker)) in self.curves.iter().zip(MARKERS).enumerate() {
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
