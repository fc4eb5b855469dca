//! The accuracy study against wall time (`jamchart accuracy`, not a scene): each answer's
//! error of x_jam against the physical reference and its integration error, beside the median
//! wall time of one answer; the rows are `accuracy.csv`.
//!
//! Wall time differs from machine to machine and run to run, so this figure comes from the
//! measured report ([`crate::study::accuracy::run`]), not from a computation of its own.

use serde::Serialize;

use crate::csv_out::{Dec, dec};
use crate::dynamics::Method;
use crate::models::ModelKind;
use crate::scene::{JamStatus, SceneParams};
use crate::study::accuracy::AccuracyReport;
use crate::study::{Reference, ReferenceKind};

/// One answer of the study: a row of `accuracy.csv`, with its reason as a tag and a sentence.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ErrorTimeRow {
    /// The model that answered.
    pub model: ModelKind,
    /// How: closed_form, exact, clarabel, radau5, dopri5, nonsmooth.
    pub method: &'static str,
    /// clarabel's tol or the integrator's rtol.
    pub tolerance: Option<Dec>,
    /// Contact penetration in um at the scene's push F (regularised simulation rows).
    pub penetration_um: Option<Dec>,
    /// Step in deg of palm turn (nonsmooth rows).
    pub step_deg: Option<Dec>,
    /// The model's status.
    pub status: JamStatus,
    /// theta_jam in deg.
    pub theta_jam_deg: Option<Dec>,
    /// x_jam in mm.
    pub x_jam_mm: Option<Dec>,
    /// Which physical reference the errors are against.
    pub reference: ReferenceKind,
    /// The reference's status.
    pub reference_status: JamStatus,
    /// The reference's theta_jam in deg.
    pub theta_ref_deg: Option<Dec>,
    /// The reference's x_jam in mm.
    pub x_ref_mm: Option<Dec>,
    /// |x_jam - x_ref| in mm (both jam).
    pub x_error_mm: Option<Dec>,
    /// |x_jam - x_ref| / x_ref.
    pub x_rel_error: Option<Dec>,
    /// |theta_jam - theta_ref| in deg.
    pub theta_error_deg: Option<Dec>,
    /// The integrator whose converged answer the integration error is against.
    pub converged_by: Option<Method>,
    /// That converged x_jam in mm.
    pub x_converged_mm: Option<Dec>,
    /// |x_jam - x_converged| in mm.
    pub integration_error_mm: Option<Dec>,
    /// Median wall time of one answer in s.
    pub median_time_s: Dec,
    /// Timed runs.
    pub runs: usize,
    /// Accepted steps, or min-norm programs solved.
    pub steps: u64,
    /// Right-hand-side evaluations, or clarabel iterations.
    pub evaluations: u64,
    /// Why the row has no trusted answer: the reason's tag.
    pub reason: Option<&'static str>,
    /// The same reason as a sentence.
    pub reason_detail: Option<String>,
}

/// The rows of `accuracy.csv`, one per row of `r`, in its order.
pub fn rows(r: &AccuracyReport) -> Vec<ErrorTimeRow> {
    (r.rows.iter())
        .map(|x| ErrorTimeRow {
            model: x.model,
            method: x.method,
            tolerance: dec(x.tolerance),
            penetration_um: dec(x.penetration_um),
            step_deg: dec(x.step_deg),
            status: x.status,
            theta_jam_deg: dec(x.theta_jam_deg),
            x_jam_mm: dec(x.x_jam_mm),
            reference: x.reference,
            reference_status: x.reference_status,
            theta_ref_deg: dec(x.theta_ref_deg),
            x_ref_mm: dec(x.x_ref_mm),
            x_error_mm: dec(x.x_error_mm),
            x_rel_error: dec(x.x_rel_error),
            theta_error_deg: dec(x.theta_error_deg),
            converged_by: x.converged_by,
            x_converged_mm: dec(x.x_converged_mm),
            integration_error_mm: dec(x.integration_error_mm),
            median_time_s: Dec(x.median_time_s),
            runs: x.runs,
            steps: x.steps,
            evaluations: x.evaluations,
            reason: x.reason.as_ref().map(|w| w.tag()),
            reason_detail: x.reason.as_ref().map(|w| w.to_string()),
        })
        .collect()
}

/// The study as a figure: the rows of `accuracy.csv` and the references they are judged by.
#[derive(Debug, Clone, Serialize)]
pub struct ErrorTimeData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The physical references of the rows.
    pub references: Vec<Reference>,
    /// One row per answer, in the report's order.
    pub rows: Vec<ErrorTimeRow>,
}

impl ErrorTimeData {
    /// The figure of `report`, measured on scene `params`.
    pub fn of(report: &AccuracyReport, params: &SceneParams) -> Self {
        ErrorTimeData {
            params: *params,
            references: report.references.clone(),
            rows: rows(report),
        }
    }
}
