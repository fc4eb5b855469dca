//! Chart kind `work_precision` (scene `accuracy`): the dynamics' integrators as integration
//! error of x_jam (against the other integrator at `reference_rtol`: the same regularised model)
//! against cost, and the min-norm program's tolerance against its error in theta_jam.
//!
//! `jamchart accuracy` measures something else for the simulation: its error against the
//! physical reference (the closed form or the rigid limit), which has a floor no tolerance gets
//! under. The chart says which one it draws and notes that floor from the reference runs.
//!
//! The picture must be the same bytes on every machine, so the cost is counted, not timed:
//! right-hand-side evaluations (or accepted steps) of one run without the verification run
//! (`crate::dynamics::accuracy::run_study`). Wall times are left to `jamchart accuracy`, which
//! reports their medians; neither the chart nor its data file carries one.

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::{Deserialize, Serialize};

use super::axes::{DrawResult, PlotFrame};
use super::convergence::sci;
use super::spec::Scene;
use super::style::{LineKind, Marker};
use super::xy::{Curve, CurveStyle, Figure, Panel, Tag, decade_axis};
use super::{DataFile, readoff, scene_subtitle_with};
use crate::csv_out::{Dec, dec, to_csv};
use crate::dynamics::Method;
use crate::dynamics::accuracy::{Study, StudyRow, StudySettings};
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::minnorm::tolerance::ToleranceRow;
use crate::scene::JamStatus;

/// The deterministic cost on the horizontal axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Cost {
    /// Right-hand-side evaluations.
    #[default]
    RhsEvals,
    /// Accepted steps.
    Steps,
}

impl Cost {
    /// The cost of run `r`.
    fn of(self, r: &StudyRow) -> f64 {
        match self {
            Cost::RhsEvals => r.rhs_evals as f64,
            Cost::Steps => r.steps as f64,
        }
    }

    /// Its column in the data file.
    fn key(self) -> &'static str {
        match self {
            Cost::RhsEvals => "rhs_evals",
            Cost::Steps => "steps",
        }
    }
}

/// `[chart]` keys of `kind = "work_precision"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WorkPrecisionSpec {
    /// Integrator tolerances rtol = atol, each in (0, 1) (default: 1e-2, 1e-3, ..., 1e-9).
    pub tolerances: Vec<f64>,
    /// Tolerance of the two reference runs (default: 1e-11).
    pub reference_rtol: f64,
    /// The cost axis: "rhs_evals" or "steps" (default: rhs_evals).
    pub cost: Cost,
    /// clarabel tolerances of the min-norm panel, each in (0, 1); empty: no panel
    /// (default: 1e-2, 1e-3, ..., 1e-10).
    pub min_norm_tolerances: Vec<f64>,
}

impl Default for WorkPrecisionSpec {
    fn default() -> Self {
        WorkPrecisionSpec {
            tolerances: StudySettings::default().tolerances,
            reference_rtol: StudySettings::default().reference_rtol,
            cost: Cost::RhsEvals,
            min_norm_tolerances: (2..=10).map(|k| 10f64.powi(-k)).collect(),
        }
    }
}

impl super::kinds::Kind for WorkPrecisionSpec {
    type Chart = WorkPrecision;

    /// Checks every tolerance.
    fn validate(&self, _scene: &Scene) -> Result<()> {
        let lists = [
            ("chart.tolerances", &self.tolerances),
            ("chart.min_norm_tolerances", &self.min_norm_tolerances),
        ];
        for (key, list) in lists {
            for &t in list {
                if !(t.is_finite() && t > 0.0 && t < 1.0) {
                    return Err(Error::invalid(key, t, "tolerances lie strictly in (0, 1)"));
                }
            }
        }
        if self.tolerances.is_empty() {
            return Err(Error::invalid(
                "chart.tolerances",
                "[]",
                "at least one integrator tolerance",
            ));
        }
        let r = self.reference_rtol;
        if !(r.is_finite() && r > 0.0 && r < 1.0) {
            return Err(Error::invalid(
                "chart.reference_rtol",
                r,
                "a tolerance lies strictly in (0, 1)",
            ));
        }
        Ok(())
    }

    fn check_size(&self, _scene: &Scene) -> Result<()> {
        let lists = [
            ("chart.tolerances", self.tolerances.len()),
            ("chart.min_norm_tolerances", self.min_norm_tolerances.len()),
        ];
        for (key, n) in lists {
            crate::limits::check_at_most(key, n, crate::limits::MAX_TOLERANCES, "tolerances")?;
        }
        Ok(())
    }

    fn compute(
        &self,
        scene: &Scene,
        models: &dyn crate::figures::models::Models,
    ) -> Result<WorkPrecision> {
        WorkPrecision::compute(scene, self, models)
    }
}

/// One row of the chart's data: an integrator at a tolerance (error in mm) or the min-norm
/// program at a tolerance (error in deg); each unit has its own column.
#[derive(Debug, Serialize)]
struct AccuracyCsvRow {
    study: &'static str,
    method: &'static str,
    /// The integrator's rtol or clarabel's tolerance.
    tol: Dec,
    status: JamStatus,
    x_jam_mm: Option<Dec>,
    theta_jam_deg: Option<Dec>,
    error_mm: Option<Dec>,
    error_deg: Option<Dec>,
    rel_error: Option<Dec>,
    steps: Option<u64>,
    rhs_evals: Option<u64>,
    jacobian_evals: Option<u64>,
    solves: Option<u32>,
    qp_iterations: Option<u32>,
    reason: Option<String>,
}

impl AccuracyCsvRow {
    /// A row with every optional cell empty.
    fn new(study: &'static str, method: &'static str, tol: f64, status: JamStatus) -> Self {
        AccuracyCsvRow {
            study,
            method,
            tol: Dec(tol),
            status,
            x_jam_mm: None,
            theta_jam_deg: None,
            error_mm: None,
            error_deg: None,
            rel_error: None,
            steps: None,
            rhs_evals: None,
            jacobian_evals: None,
            solves: None,
            qp_iterations: None,
            reason: None,
        }
    }
}

/// The computed study.
#[derive(Debug, Clone)]
pub struct WorkPrecision {
    figure: Figure,
    cost: Cost,
    study: Study,
    min_norm: Vec<ToleranceRow>,
}

impl WorkPrecision {
    /// Runs the integrators' study (one run per point) and, if asked, the min-norm one.
    pub fn compute(scene: &Scene, spec: &WorkPrecisionSpec, models: &dyn Models) -> Result<Self> {
        let (p, d) = (&scene.params, &scene.dynamics);
        let settings = StudySettings {
            tolerances: spec.tolerances.clone(),
            runs: 1,
            reference_rtol: spec.reference_rtol,
        };
        let study = models.accuracy_study(p, d, &settings)?;
        let min_norm = if spec.min_norm_tolerances.is_empty() {
            Vec::new()
        } else {
            models.min_norm_tolerances(p, &scene.min_norm, &spec.min_norm_tolerances)?
        };
        let cost = |r: &StudyRow| spec.cost.of(r);
        let cost_label = match spec.cost {
            Cost::RhsEvals => "cost: right-hand-side evaluations of one run (-)",
            Cost::Steps => "cost: accepted steps of one run (-)",
        };
        let method_curve = |m: Method, line: LineKind, marker: Marker| Curve {
            label: format!(
                "{} (rtol = atol = {} … {})",
                m.as_str(),
                sci_first(&spec.tolerances),
                sci_last(&spec.tolerances)
            ),
            style: CurveStyle::LinePoints(line, marker),
            points: study
                .rows
                .iter()
                .filter(|r| r.method == m)
                .filter_map(|r| r.rel_error.map(|e| (cost(r), e)))
                .collect(),
        };
        let curves = vec![
            method_curve(Method::Radau5, LineKind::Family(0), Marker::Dot),
            method_curve(Method::Dopri5, LineKind::Family(1), Marker::Square),
        ];
        // The loosest and tightest run of each method named by its tolerance.
        let mut tags = Vec::new();
        for m in [Method::Radau5, Method::Dopri5] {
            let drawn: Vec<&StudyRow> = study
                .rows
                .iter()
                .filter(|r| r.method == m && r.rel_error.is_some_and(|e| e > 0.0))
                .collect();
            let ends = [drawn.first(), drawn.last()];
            for (i, r) in ends.into_iter().flatten().enumerate() {
                tags.push(Tag {
                    at: (cost(r), r.rel_error.unwrap_or(1.0)),
                    text: format!("rtol {}", sci(r.rtol)),
                    left: m == Method::Radau5 && i == 0,
                });
            }
        }
        let integrators = Panel {
            x: decade_axis(study.rows.iter().map(cost), cost_label),
            y: decade_axis(
                curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)),
                "integration error of x_jam, relative (-)",
            ),
            curves,
            marks: Vec::new(),
            tags,
        };
        let mut panels = vec![integrators];
        if !min_norm.is_empty() {
            let floor_deg = scene.min_norm.bisection_tol_rad.to_degrees();
            let pts: Vec<(f64, f64)> = min_norm
                .iter()
                .filter_map(|r| r.error_deg.map(|e| (r.tol, e)))
                .collect();
            let tol_axis = decade_axis(
                min_norm.iter().map(|r| r.tol),
                "clarabel tolerance tol_feas = tol_gap = tol_infeas (-)",
            );
            let floor = Curve {
                label: format!(
                    "bisection width {} rad = {} deg (the search's resolution)",
                    sci(scene.min_norm.bisection_tol_rad),
                    sci(floor_deg)
                ),
                style: CurveStyle::Line(LineKind::Dotted),
                points: vec![(tol_axis.min, floor_deg), (tol_axis.max, floor_deg)],
            };
            panels.push(Panel {
                y: decade_axis(
                    pts.iter().map(|p| p.1).chain([floor_deg]),
                    "error of min-norm θ_jam (deg)",
                ),
                x: tol_axis,
                curves: vec![
                    Curve {
                        label: "min-norm by clarabel vs closed form (translational)".into(),
                        // Its own dots, not radau5's black solid line (issue 18).
                        style: CurveStyle::LinePoints(LineKind::Family(2), Marker::Triangle),
                        points: pts,
                    },
                    floor,
                ],
                marks: Vec::new(),
                tags: Vec::new(),
            });
        }
        let mut notes = vec![
            "Cost is counted, not timed, so the picture is the same on every machine; \
             jamchart accuracy reports median wall times."
                .to_string(),
        ];
        // The physics the report judges by: the rigid limit (motion drive) or the converged
        // rigid dynamics (force drive; the accuracy report's converged step).
        let physical = match d.drive.mode {
            crate::dynamics::Drive::Motion => crate::study::reference(p, Some(d.drive.mode)),
            crate::dynamics::Drive::Force => crate::study::rigid_dynamics_reference(
                d,
                p,
                crate::study::accuracy::AccuracySettings::default().converged_step_deg,
                crate::dynamics::DiscMotion::Slides,
            )?,
        };
        for r in &study.references {
            let off = match (r.x_jam_mm, physical.x_jam_mm) {
                (Some(x), Some(xp)) => format!(
                    ", {:.2} % from the physics ({} x_jam = {xp:.3} mm): the model's floor, \
                     which no tolerance gets under",
                    100.0 * (x - xp).abs() / xp,
                    physical.kind.as_str()
                ),
                _ => String::new(),
            };
            notes.push(format!(
                "reference {} at rtol {}: {} x_jam = {} mm{off}",
                r.method.as_str(),
                sci(r.rtol),
                r.status,
                r.x_jam_mm.map_or("-".into(), |x| format!("{x:.6}"))
            ));
        }
        for r in study.rows.iter().filter(|r| r.rel_error.is_none()) {
            notes.push(format!(
                "not drawn: {} at rtol {}: {}",
                r.method.as_str(),
                sci(r.rtol),
                r.reason.as_deref().unwrap_or("no error")
            ));
        }
        for r in min_norm.iter().filter(|r| r.error_deg.is_none()) {
            notes.push(format!(
                "not drawn: min-norm at tol {}: {}",
                sci(r.tol),
                r.status
            ));
        }
        let figure = Figure {
            title: scene.title.clone(),
            subtitle: scene_subtitle_with(
                &format!(
                    "simulation, {} drive, against the other integrator at rtol {}",
                    d.drive.mode.as_str(),
                    sci(spec.reference_rtol)
                ),
                p,
                &[],
            ),
            panels,
            notes,
        };
        Ok(WorkPrecision {
            figure,
            cost: spec.cost,
            study,
            min_norm,
        })
    }

    /// Both studies' rows, integrators first: the data file's and the read-off's.
    fn rows(&self) -> Vec<AccuracyCsvRow> {
        let integrators = self.study.rows.iter().map(|r| AccuracyCsvRow {
            x_jam_mm: dec(r.x_jam_mm),
            error_mm: dec(r.error_mm),
            rel_error: dec(r.rel_error),
            steps: Some(r.steps),
            rhs_evals: Some(r.rhs_evals),
            jacobian_evals: Some(r.jacobian_evals),
            reason: r.reason.clone(),
            ..AccuracyCsvRow::new("integrator", r.method.as_str(), r.rtol, r.status)
        });
        let min_norm = self.min_norm.iter().map(|r| AccuracyCsvRow {
            theta_jam_deg: dec(r.theta_jam_deg),
            error_deg: dec(r.error_deg),
            solves: Some(r.solves),
            qp_iterations: Some(r.iterations),
            ..AccuracyCsvRow::new("min_norm", "clarabel", r.tol, r.status)
        });
        integrators.chain(min_norm).collect()
    }

    /// Both studies as one CSV: a row per point, `study` telling them apart.
    pub fn data_file(&self, _scene: &Scene) -> DataFile {
        DataFile::csv(to_csv(self.rows()))
    }

    /// The gallery's read-off ([`readoff`], kind `points`): the run nearest the pointer, an
    /// integrator's (cost, error) or the min-norm program's (tolerance, error), with its row of
    /// the data file. Runs that are not drawn (no error) are not read.
    pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let panels = &self.figure.panels;
        if frames.len() != panels.len() || panels.is_empty() {
            return None;
        }
        let n = self.study.rows.len();
        let runs: Vec<_> = (self.study.rows.iter().enumerate())
            .filter_map(|(i, r)| r.rel_error.map(|e| (self.cost.of(r), e, i)))
            .collect();
        let tolerances: Vec<_> = (self.min_norm.iter().enumerate())
            .filter_map(|(i, r)| r.error_deg.map(|e| (r.tol, e, n + i)))
            .collect();
        let keys = [
            (self.cost.key(), "rel_error", runs),
            ("tol", "error_deg", tolerances),
        ];
        let json_panels: Vec<_> = (panels.iter().zip(frames).zip(keys))
            .map(|((p, f), (x, y, points))| {
                readoff::points_panel(f, readoff::axis(x, &p.x), readoff::axis(y, &p.y), &points)
            })
            .collect();
        Some(serde_json::json!({
            "kind": "points",
            "crosshair": true,
            "panels": json_panels,
            "rows": serde_json::to_value(self.rows()).ok()?,
        }))
    }

    /// Draws the panels.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

fn sci_first(v: &[f64]) -> String {
    v.iter().copied().reduce(f64::max).map_or("-".into(), sci)
}

fn sci_last(v: &[f64]) -> String {
    v.iter().copied().reduce(f64::min).map_or("-".into(), sci)
}
