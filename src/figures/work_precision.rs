//! The accuracy study as a figure (scene `accuracy`): the dynamics' integrators as integration
//! error of x_jam (against the other integrator at `reference_rtol`: the same regularised
//! model) against cost, and the min-norm program's tolerance against its error in theta_jam.
//!
//! `jamchart accuracy` measures something else for the simulation: its error against the
//! physical reference (the closed form or the rigid limit), which has a floor no tolerance gets
//! under; the figure carries that reference so the chart can note the floor.
//!
//! The figure must be the same on every machine, so the cost is counted, not timed:
//! right-hand-side evaluations (or accepted steps) of one run without the verification run
//! ([`Models::accuracy_study`]). Wall times are left to `jamchart accuracy`, which reports
//! their medians; neither the figure nor its data file carries one.

use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::csv_out::{Dec, dec, to_csv};
use crate::dynamics::accuracy::StudySettings;
use crate::dynamics::{DynamicsParams, Method};
use crate::error::{Error, Result};
use crate::minnorm::MinNormSettings;
use crate::scene::{JamStatus, SceneParams};
use crate::study::Reference;

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
    /// The cost of an integrator's row (None for the min-norm program's).
    pub fn of(self, r: &PrecisionRow) -> Option<f64> {
        match self {
            Cost::RhsEvals => r.rhs_evals,
            Cost::Steps => r.steps,
        }
        .map(|n| n as f64)
    }

    /// Its column in the data file.
    pub fn key(self) -> &'static str {
        match self {
            Cost::RhsEvals => "rhs_evals",
            Cost::Steps => "steps",
        }
    }
}

/// `[chart]` keys of `kind = "work_precision"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct WorkPrecisionSettings {
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

impl Default for WorkPrecisionSettings {
    fn default() -> Self {
        WorkPrecisionSettings {
            tolerances: StudySettings::default().tolerances,
            reference_rtol: StudySettings::default().reference_rtol,
            cost: Cost::RhsEvals,
            min_norm_tolerances: (2..=10).map(|k| 10f64.powi(-k)).collect(),
        }
    }
}

impl Figure for WorkPrecisionSettings {
    type Data = WorkPrecisionData;

    /// Checks every tolerance.
    fn validate(&self, _input: &Input) -> Result<()> {
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
        if !(crate::limits::MIN_TOLERANCE..1.0).contains(&r) {
            return Err(Error::invalid(
                "chart.reference_rtol",
                r,
                format!(
                    "a tolerance lies in [{:e}, 1)",
                    crate::limits::MIN_TOLERANCE
                ),
            ));
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        let lists = [
            ("chart.tolerances", self.tolerances.len()),
            ("chart.min_norm_tolerances", self.min_norm_tolerances.len()),
        ];
        for (key, n) in lists {
            crate::limits::check_at_most(key, n, crate::limits::MAX_TOLERANCES, "tolerances")?;
        }
        Ok(())
    }

    /// Runs the integrators' study (one run per point) and, if asked, the min-norm one.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<WorkPrecisionData> {
        let (p, d) = (&input.params, &input.dynamics);
        let settings = StudySettings {
            tolerances: self.tolerances.clone(),
            runs: 1,
            reference_rtol: self.reference_rtol,
        };
        let study = models.accuracy_study(p, d, &settings)?;
        let min_norm = if self.min_norm_tolerances.is_empty() {
            Vec::new()
        } else {
            models.min_norm_tolerances(p, &input.min_norm, &self.min_norm_tolerances)?
        };
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
        let integrators = study.rows.iter().map(|r| PrecisionRow {
            x_jam_mm: dec(r.x_jam_mm),
            error_mm: dec(r.error_mm),
            rel_error: dec(r.rel_error),
            steps: Some(r.steps),
            rhs_evals: Some(r.rhs_evals),
            jacobian_evals: Some(r.jacobian_evals),
            reason: r.reason.clone(),
            ..PrecisionRow::new(Study::Integrator, r.method.as_str(), r.rtol, r.status)
        });
        let programs = min_norm.iter().map(|r| PrecisionRow {
            theta_jam_deg: dec(r.theta_jam_deg),
            error_deg: dec(r.error_deg),
            solves: Some(r.solves),
            qp_iterations: Some(r.iterations),
            ..PrecisionRow::new(Study::MinNorm, "clarabel", r.tol, r.status)
        });
        Ok(WorkPrecisionData {
            params: *p,
            dynamics: *d,
            min_norm: input.min_norm,
            settings: self.clone(),
            rows: integrators.chain(programs).collect(),
            references: study
                .references
                .iter()
                .map(|r| ReferenceRun {
                    method: r.method,
                    rtol: r.rtol,
                    status: r.status,
                    x_jam_mm: r.x_jam_mm,
                })
                .collect(),
            physical,
        })
    }
}

/// Which study a row is of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Study {
    /// An integrator at a tolerance.
    Integrator,
    /// The min-norm program at a tolerance.
    MinNorm,
}

/// One point of the studies, a row of the data file: an integrator at a tolerance (error in
/// mm) or the min-norm program at a tolerance (error in deg); each unit has its own column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PrecisionRow {
    /// Which study.
    pub study: Study,
    /// The integrator (radau5, dopri5) or clarabel.
    pub method: &'static str,
    /// The integrator's rtol or clarabel's tolerance.
    pub tol: Dec,
    /// The outcome.
    pub status: JamStatus,
    /// An integrator's x_jam in mm.
    pub x_jam_mm: Option<Dec>,
    /// The min-norm program's theta_jam in deg.
    pub theta_jam_deg: Option<Dec>,
    /// An integrator's |x_jam - x_ref| in mm, against the other integrator's reference run.
    pub error_mm: Option<Dec>,
    /// The min-norm program's |theta_jam - theta_jam(closed form)| in deg.
    pub error_deg: Option<Dec>,
    /// An integrator's |x_jam - x_ref| / x_ref.
    pub rel_error: Option<Dec>,
    /// An integrator's accepted steps.
    pub steps: Option<u64>,
    /// An integrator's right-hand-side evaluations.
    pub rhs_evals: Option<u64>,
    /// An integrator's Jacobian evaluations.
    pub jacobian_evals: Option<u64>,
    /// Programs the min-norm bisection solved.
    pub solves: Option<u32>,
    /// clarabel iterations over all of them.
    pub qp_iterations: Option<u32>,
    /// Why an integrator's row has no trusted jam, if it has none.
    pub reason: Option<String>,
}

impl PrecisionRow {
    /// A row with every optional cell empty.
    fn new(study: Study, method: &'static str, tol: f64, status: JamStatus) -> Self {
        PrecisionRow {
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

/// A reference run of the integrators' study: the error of the other integrator's rows is
/// against it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReferenceRun {
    /// The integrator.
    pub method: Method,
    /// Its rtol.
    pub rtol: f64,
    /// Its status.
    pub status: JamStatus,
    /// Its x_jam in mm.
    pub x_jam_mm: Option<f64>,
}

/// The computed studies: the rows are the data file.
#[derive(Debug, Clone, Serialize)]
pub struct WorkPrecisionData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The simulation's settings (drive, integrator).
    pub dynamics: DynamicsParams,
    /// The min-norm settings (the bisection's width).
    pub min_norm: MinNormSettings,
    /// The settings it was computed with.
    pub settings: WorkPrecisionSettings,
    /// Both studies' rows, integrators first.
    pub rows: Vec<PrecisionRow>,
    /// The integrators' reference runs.
    pub references: Vec<ReferenceRun>,
    /// The physical reference `jamchart accuracy` judges by: the rigid limit (motion drive)
    /// or the converged rigid dynamics (force drive).
    pub physical: Reference,
}

impl FigureData for WorkPrecisionData {
    const FORMAT: DataFormat = DataFormat::Csv;

    /// Both studies as one CSV: a row per point, `study` telling them apart.
    fn csv(&self) -> Vec<u8> {
        to_csv(&self.rows)
    }
}
