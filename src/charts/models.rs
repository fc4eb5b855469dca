//! The model calls a chart can make (any model through the port, min-norm traces, studies),
//! behind one trait.
//!
//! Charts compute through [`Models`], never by calling the models directly, so a test can hand
//! them a counting implementation and check the scene principle: a scene computes only what it
//! draws (fig3 builds no program and no simulation; fig4 runs no simulation). [`Live`] calls the
//! models. The closed-form statics' margin and F -> infinity limit are cheap closed forms and
//! are called directly.

use crate::dynamics::DynamicsParams;
use crate::dynamics::accuracy::{Study, StudySettings, run_study};
use crate::error::Result;
use crate::grid::JamPoint;
use crate::minnorm::tolerance::{ToleranceRow, tolerance_study};
use crate::minnorm::{ContactSolution, MinNormSettings, palm};
use crate::models::{self, ModelSpec, Solution};
use crate::scene::SceneParams;

/// The model calls of charts; implementations must be callable from several threads.
pub trait Models: Sync {
    /// One model's answer through the port ([`models::solve`]).
    fn solve(&self, spec: &ModelSpec, p: &SceneParams) -> Result<Solution>;
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
    /// The integrators' work-precision study ([`run_study`]).
    fn accuracy_study(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        s: &StudySettings,
    ) -> Result<Study>;

    /// The jam point of `spec` for `p`: the part of [`Models::solve`] a grid needs.
    fn jam_point(&self, spec: &ModelSpec, p: &SceneParams) -> Result<JamPoint> {
        self.solve(spec, p).map(|s| JamPoint::from(&s))
    }
}

/// The models themselves.
#[derive(Debug, Clone, Copy, Default)]
pub struct Live;

impl Models for Live {
    fn solve(&self, spec: &ModelSpec, p: &SceneParams) -> Result<Solution> {
        models::solve(spec, p)
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

    fn accuracy_study(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        s: &StudySettings,
    ) -> Result<Study> {
        run_study(p, d, s, &mut |_, _| {})
    }
}
