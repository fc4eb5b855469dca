//! Chart kind `convergence` (Fig. 4): the min-norm program's interior-point iterations at the
//! jam, objective phi^2 (N^2) and the relative primal and dual residuals, on log axes, drawn
//! from [`ConvergenceData`].

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff::{Axis, PointsPanel, ReadOffData, Rows};
use super::scene_subtitle_with;
use super::style::{LineKind, Marker};
use super::ticks::power_of_ten;
use super::xy::{Curve, CurveStyle, Figure, Panel, decade_axis};
use crate::csv_out::Dec;
use crate::figures::convergence::{
    ConvergenceData, ConvergenceSettings, TraceAt, TraceRow, held_words,
};
use crate::grid::AxisScale;

/// A trace ready to draw: its data and its two panels.
#[derive(Debug, Clone)]
pub struct Convergence {
    data: ConvergenceData,
    figure: Figure,
}

impl Picture for Convergence {
    type Settings = ConvergenceSettings;

    /// Lays out the two panels.
    fn new(data: ConvergenceData, title: &str) -> Self {
        let trace = &data.rows;
        let s = &data.min_norm;
        let last = trace.last().map_or(1, |p| p.iteration).max(1) as f64;
        let x = PlotAxis::new(
            -0.4,
            last + 0.4,
            AxisScale::Linear,
            "interior-point iteration (-)",
        );
        let tol = s.qp.tol_feas;
        let along = |v: fn(&TraceRow) -> f64| -> Vec<(f64, f64)> {
            trace.iter().map(|p| (p.iteration as f64, v(p))).collect()
        };
        let objective = Panel {
            x: x.clone(),
            y: decade_axis(
                trace.iter().map(|p| p.objective_n2.0),
                "objective φ² = Σ|f|² (N²)",
            ),
            curves: vec![Curve {
                label: "objective φ² (Eq. 4), N²".into(),
                style: CurveStyle::LinePoints(LineKind::Solid, Marker::Circle),
                points: along(|p| p.objective_n2.0),
            }],
            marks: Vec::new(),
            tags: Vec::new(),
        };
        let residuals = Panel {
            x: x.clone(),
            y: decade_axis(
                trace
                    .iter()
                    .flat_map(|p| [p.res_primal.0, p.res_dual.0])
                    .chain([tol]),
                "relative residual (-)",
            ),
            curves: vec![
                Curve {
                    label: "primal residual (equilibrium, cones)".into(),
                    style: CurveStyle::LinePoints(LineKind::Solid, Marker::Dot),
                    points: along(|p| p.res_primal.0),
                },
                Curve {
                    label: "dual residual".into(),
                    style: CurveStyle::LinePoints(LineKind::Dashed, Marker::Triangle),
                    points: along(|p| p.res_dual.0),
                },
                Curve {
                    label: "clarabel's feasibility tolerance tol_feas".into(),
                    style: CurveStyle::Line(LineKind::Dotted),
                    points: vec![(x.min, tol), (x.max, tol)],
                },
            ],
            marks: Vec::new(),
            tags: Vec::new(),
        };
        let objective_note = match (trace.first(), trace.last()) {
            (Some(a), Some(b)) => format!(
                "φ² goes from {:.3} to {:.3} N²: at the jam the minimum is the ground force of \
                 Eq. 1 with its sign corrected (see the crate docs' corrections to the paper); \
                 the iterates reach it from inside the cones.",
                a.objective_n2.0, b.objective_n2.0
            ),
            _ => "clarabel returned no iterations.".into(),
        };
        let at_what = match data.at {
            TraceAt::Given => "the scene's angle".to_string(),
            TraceAt::ThetaJam => "θ_jam".to_string(),
            TraceAt::Start(status) => format!("the start ({status})"),
        };
        let figure = Figure {
            title: title.to_string(),
            subtitle: scene_subtitle_with(
                &format!(
                    "min-norm program by clarabel at θ = {:.3}° ({at_what}, {})",
                    data.theta_deg,
                    held_words(data.status)
                ),
                &data.params,
                &[],
            ),
            panels: vec![objective, residuals],
            notes: std::iter::once(objective_note)
                .chain(trace.last().map(|end| {
                    format!(
                        "Converged after {} iterations, primal residual {}, dual {}: both below \
                         tol_feas = {} ({} formulation).",
                        end.iteration,
                        sci(end.res_primal.0),
                        sci(end.res_dual.0),
                        sci(tol),
                        s.formulation.as_str()
                    )
                }))
                .collect(),
        };
        Convergence { data, figure }
    }

    fn data(&self) -> &ConvergenceData {
        &self.data
    }

    /// The gallery's read-off ([`ReadOffData::Points`]): the iteration nearest the pointer
    /// on either panel, with its row of the data file.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let [objective, residuals] = self.figure.panels.as_slice() else {
            return None;
        };
        let [f0, f1] = *frames else { return None };
        let trace = &self.data.rows;
        let at = |i: usize, p: &TraceRow, v: Dec| (p.iteration as f64, v.0, i);
        let objective_points: Vec<_> = (trace.iter().enumerate())
            .map(|(i, p)| at(i, p, p.objective_n2))
            .collect();
        let residual_points: Vec<_> = (trace.iter().enumerate())
            .flat_map(|(i, p)| [at(i, p, p.res_primal), at(i, p, p.res_dual)])
            .collect();
        let x = Axis::of("iteration", &objective.x);
        let panel = |f, y, points: &[_]| PointsPanel::new(f, x.clone(), y, points);
        Some(ReadOffData::Points {
            crosshair: true,
            cell: None,
            panels: vec![
                panel(
                    f0,
                    Axis::of("objective_n2", &objective.y),
                    &objective_points,
                ),
                panel(f1, Axis::of("residual", &residuals.y), &residual_points),
            ],
            rows: Rows::Trace(trace.clone()),
        })
    }

    /// Draws the two panels.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

/// `v` as m·10ⁿ with two significant digits, e.g. 3.4·10⁻¹⁰.
pub fn sci(v: f64) -> String {
    if !(v.is_finite() && v > 0.0) {
        return format!("{v}");
    }
    let k = v.log10().floor() as i32;
    let m = v / 10f64.powi(k);
    if (m - 1.0).abs() < 0.005 {
        power_of_ten(k)
    } else {
        format!("{m:.1}·{}", power_of_ten(k))
    }
}
