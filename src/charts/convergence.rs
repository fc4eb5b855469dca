//! Chart kind `convergence` (Fig. 4): the min-norm program's interior-point iterations at the
//! jam, objective phi^2 (N^2) and the relative primal and dual residuals, on log axes.
//!
//! The jam angle comes from the scene's min-norm settings (the exact path answers it without
//! iterations); the trace is clarabel's at that angle ([`crate::minnorm::palm::trace_at`]).

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::{Deserialize, Serialize};

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::spec::Scene;
use super::style::{LineKind, Marker};
use super::ticks::power_of_ten;
use super::xy::{Curve, CurveStyle, Figure, Panel, decade_axis};
use super::{DataFile, readoff, scene_subtitle_with};
use crate::csv_out::{Dec, to_csv};
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::grid::AxisScale;
use crate::minnorm::HoldStatus;
use crate::minnorm::qp::TracePoint;
use crate::models::ModelSpec;

/// `[chart]` keys of `kind = "convergence"`.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ConvergenceSpec {
    /// Palm angle of the trace in deg, in (0, 180) (default: the min-norm theta_jam, or the
    /// start angle when the disc does not jam).
    pub theta_deg: Option<f64>,
}

impl super::kinds::Kind for ConvergenceSpec {
    type Chart = Convergence;

    /// Checks the angle.
    fn validate(&self, _scene: &Scene) -> Result<()> {
        if let Some(t) = self.theta_deg
            && !(t.is_finite() && t > 0.0 && t < 180.0)
        {
            return Err(Error::invalid(
                "chart.theta_deg",
                t,
                "the palm angle lies in (0, 180) deg",
            ));
        }
        Ok(())
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        Ok(())
    }

    fn compute(
        &self,
        scene: &Scene,
        models: &dyn crate::figures::models::Models,
    ) -> Result<Convergence> {
        Convergence::compute(scene, self, models)
    }
}

/// The computed trace.
#[derive(Debug, Clone)]
pub struct Convergence {
    figure: Figure,
    trace: Vec<TracePoint>,
    theta_deg: f64,
}

impl Convergence {
    /// Finds theta_jam by the min-norm model (unless the scene gives the angle), then traces
    /// clarabel there.
    pub fn compute(scene: &Scene, spec: &ConvergenceSpec, models: &dyn Models) -> Result<Self> {
        let (p, s) = (&scene.params, &scene.min_norm);
        let (theta_deg, at_what) = match spec.theta_deg {
            Some(t) => (t, "the scene's angle".to_string()),
            None => {
                let sol = models.solve(&ModelSpec::MinNorm(*s), p)?;
                match sol.theta_jam_deg {
                    Some(t) => (t, "θ_jam".to_string()),
                    None => (p.start_angle_deg, format!("the start ({})", sol.status)),
                }
            }
        };
        let t = models.min_norm_trace(p, theta_deg, s)?;
        let held = match t.status {
            HoldStatus::Held => "held",
            HoldStatus::NotHeld => "not held",
            HoldStatus::Undetermined => "undetermined",
        };
        let trace = t.trace;
        // No iteration to draw: the render fails instead of drawing empty panels.
        if trace.is_empty() {
            return Err(Error::ModelFailed {
                scene: scene.name.clone(),
                model: "min-norm program",
                reason: format!("clarabel recorded no iteration at {theta_deg} deg ({held})"),
            });
        }
        let last = trace.last().map_or(1, |p| p.iteration).max(1) as f64;
        let x = PlotAxis::new(
            -0.4,
            last + 0.4,
            AxisScale::Linear,
            "interior-point iteration (-)",
        );
        let tol = s.qp.tol_feas;
        let objective = Panel {
            x: x.clone(),
            y: decade_axis(
                trace.iter().map(|p| p.objective_n2),
                "objective φ² = Σ|f|² (N²)",
            ),
            curves: vec![Curve {
                label: "objective φ² (Eq. 4), N²".into(),
                style: CurveStyle::LinePoints(LineKind::Solid, Marker::Circle),
                points: trace
                    .iter()
                    .map(|p| (p.iteration as f64, p.objective_n2))
                    .collect(),
            }],
            marks: Vec::new(),
            tags: Vec::new(),
        };
        let residuals = Panel {
            x: x.clone(),
            y: decade_axis(
                trace
                    .iter()
                    .flat_map(|p| [p.res_primal, p.res_dual])
                    .chain([tol]),
                "relative residual (-)",
            ),
            curves: vec![
                Curve {
                    label: "primal residual (equilibrium, cones)".into(),
                    style: CurveStyle::LinePoints(LineKind::Solid, Marker::Dot),
                    points: trace
                        .iter()
                        .map(|p| (p.iteration as f64, p.res_primal))
                        .collect(),
                },
                Curve {
                    label: "dual residual".into(),
                    style: CurveStyle::LinePoints(LineKind::Dashed, Marker::Triangle),
                    points: trace
                        .iter()
                        .map(|p| (p.iteration as f64, p.res_dual))
                        .collect(),
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
                "φ² goes from {:.3} to {:.3} N²: at the jam the minimum is the corrected Eq. 1 \
                 force at the ground (ERRATA); the iterates reach it from inside the cones.",
                a.objective_n2, b.objective_n2
            ),
            _ => "clarabel returned no iterations.".into(),
        };
        let figure = Figure {
            title: scene.title.clone(),
            subtitle: scene_subtitle_with(
                &format!("min-norm program by clarabel at θ = {theta_deg:.3}° ({at_what}, {held})"),
                p,
                &[],
            ),
            panels: vec![objective, residuals],
            notes: std::iter::once(objective_note)
                .chain(trace.last().map(|end| {
                    format!(
                        "Converged after {} iterations, primal residual {}, dual {}: both below \
                         tol_feas = {} ({} formulation).",
                        end.iteration,
                        sci(end.res_primal),
                        sci(end.res_dual),
                        sci(tol),
                        s.formulation.as_str()
                    )
                }))
                .collect(),
        };
        Ok(Convergence {
            figure,
            trace,
            theta_deg,
        })
    }

    /// The trace's rows, one per interior-point iteration: the data file's and the read-off's.
    fn rows(&self) -> Vec<TraceRow> {
        self.trace
            .iter()
            .map(|p| TraceRow {
                theta_deg: Dec(self.theta_deg),
                iteration: p.iteration as usize,
                objective_n2: Dec(p.objective_n2),
                res_primal: Dec(p.res_primal),
                res_dual: Dec(p.res_dual),
            })
            .collect()
    }

    /// The trace as CSV: the palm angle (deg), iteration, objective (N^2), residuals.
    pub fn data_file(&self, _scene: &Scene) -> DataFile {
        DataFile::csv(to_csv(self.rows()))
    }

    /// The gallery's read-off ([`readoff`], kind `points`): the iteration nearest the pointer
    /// on either panel, with its row of the data file.
    pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let [objective, residuals] = self.figure.panels.as_slice() else {
            return None;
        };
        let [f0, f1] = frames else { return None };
        let at = |i: usize, p: &TracePoint, v: f64| (p.iteration as f64, v, i);
        let objective_points: Vec<_> = (self.trace.iter().enumerate())
            .map(|(i, p)| at(i, p, p.objective_n2))
            .collect();
        let residual_points: Vec<_> = (self.trace.iter().enumerate())
            .flat_map(|(i, p)| [at(i, p, p.res_primal), at(i, p, p.res_dual)])
            .collect();
        let x = readoff::axis("iteration", &objective.x);
        Some(serde_json::json!({
            "kind": "points",
            "crosshair": true,
            "panels": [
                readoff::points_panel(f0, x.clone(), readoff::axis("objective_n2", &objective.y), &objective_points),
                readoff::points_panel(f1, x, readoff::axis("residual", &residuals.y), &residual_points),
            ],
            "rows": serde_json::to_value(self.rows()).ok()?,
        }))
    }

    /// Draws the two panels.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

/// One interior-point iteration at theta_jam: a row of the data file.
#[derive(Serialize)]
struct TraceRow {
    theta_deg: Dec,
    iteration: usize,
    objective_n2: Dec,
    res_primal: Dec,
    res_dual: Dec,
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
