//! The expensive model calls a chart can make (min-norm programs, simulations, studies), behind
//! one trait.
//!
//! Charts compute through [`Models`], never by calling the models directly, so a test can hand
//! them a counting implementation and check the scene principle: a scene computes only what it
//! draws (fig3 builds no program and no simulation; fig4 runs no simulation). [`Live`] calls the
//! models. The closed-form statics are cheap and are called directly.

use crate::dynamics::accuracy::{Study, StudySettings, run_study};
use crate::dynamics::{DynamicsParams, DynamicsSolution, simulate};
use crate::error::Result;
use crate::minnorm::tolerance::{ToleranceRow, tolerance_study};
use crate::minnorm::{ContactSolution, MinNormSettings, PalmSolution, palm};
use crate::model::SceneParams;

/// The model calls of charts; implementations must be callable from several threads.
pub trait Models: Sync {
    /// The min-norm jam point ([`palm::solve`]).
    fn min_norm(&self, p: &SceneParams, s: &MinNormSettings) -> Result<PalmSolution>;
    /// clarabel's trace at one palm angle ([`palm::trace_at`]).
    fn min_norm_trace(
        &self,
        p: &SceneParams,
        theta_deg: f64,
        s: &MinNormSettings,
    ) -> Result<ContactSolution>;
    /// The min-norm tolerance study ([`tolerance_study`]).
    fn min_norm_tolerances(
        &self,
        p: &SceneParams,
        s: &MinNormSettings,
        tolerances: &[f64],
    ) -> Result<Vec<ToleranceRow>>;
    /// One simulation ([`simulate`]).
    fn simulate(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        series_dt_s: Option<f64>,
    ) -> Result<DynamicsSolution>;
    /// The integrators' work-precision study ([`run_study`]).
    fn accuracy_study(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        s: &StudySettings,
    ) -> Result<Study>;
}

/// The models themselves.
#[derive(Debug, Clone, Copy, Default)]
pub struct Live;

impl Models for Live {
    fn min_norm(&self, p: &SceneParams, s: &MinNormSettings) -> Result<PalmSolution> {
        palm::solve(p, s)
    }

    fn min_norm_trace(
        &self,
        p: &SceneParams,
        theta_deg: f64,
        s: &MinNormSettings,
    ) -> Result<ContactSolution> {
        palm::trace_at(p, theta_deg, s)
    }

    fn min_norm_tolerances(
        &self,
        p: &SceneParams,
        s: &MinNormSettings,
        tolerances: &[f64],
    ) -> Result<Vec<ToleranceRow>> {
        tolerance_study(p, s, tolerances)
    }

    fn simulate(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        series_dt_s: Option<f64>,
    ) -> Result<DynamicsSolution> {
        simulate(p, d, series_dt_s)
    }

    fn accuracy_study(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        s: &StudySettings,
    ) -> Result<Study> {
        run_study(p, d, s, &mut |_, _| {})
    }
}
