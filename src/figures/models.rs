//! The model calls a chart can make (any model through the port, min-norm traces, studies),
//! behind one trait.
//!
//! Charts compute through [`Models`], never by calling the models directly, so a test can hand
//! them a counting implementation and check the scene principle: a scene computes only what it
//! draws (fig3 builds no program and no simulation; fig4 runs no simulation). [`Live`] calls the
//! models. The closed-form statics' margin and F -> infinity limit are cheap closed forms and
//! are called directly, as are its jam points over a grid (in batches, [`evaluate`]).

use crate::dynamics::DynamicsParams;
use crate::dynamics::accuracy::{Study, StudySettings, run_study};
use crate::dynamics::system::System;
use crate::error::Result;
use crate::grid::{self, GridRequest, GridResult, JamPoint, ParamSet};
use crate::minnorm::tolerance::{ToleranceRow, tolerance_study};
use crate::minnorm::{ContactSolution, MinNormSettings, palm};
use crate::models::{self, ModelSpec, Solution};
use crate::scene::Param;
use crate::scene::SceneParams;

/// The model calls of charts; implementations must be callable from several threads.
pub trait Models: Sync {
    /// One model's answer through the port ([`models::solve`]).
    fn solve(&self, spec: &ModelSpec, p: &SceneParams) -> Result<Solution>;
    /// clarabel's trace at one palm angle (`palm::trace_at`).
    fn min_norm_trace(
        &self,
        p: &SceneParams,
        theta_deg: f64,
        s: &MinNormSettings,
    ) -> Result<ContactSolution>;
    /// The min-norm tolerance study (`minnorm::tolerance_study`).
    fn min_norm_tolerances(
        &self,
        p: &SceneParams,
        s: &MinNormSettings,
        tolerances: &[f64],
    ) -> Result<Vec<ToleranceRow>>;
    /// The integrators' work-precision study (`accuracy::run_study`).
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

    /// A rigid disc touching the palm of scene `p`, turning at `d`'s omega, at each palm angle
    /// of `theta_deg` (deg): its speed and position (`System::geometric_speed`,
    /// `System::touching_x`). A closed form of the scene's geometry, not a model run.
    fn touching_disc(
        &self,
        p: &SceneParams,
        d: &DynamicsParams,
        theta_deg: &[f64],
    ) -> Vec<TouchingDisc> {
        let sys = System::new(p, d);
        theta_deg
            .iter()
            .map(|t| {
                let theta = t.to_radians();
                TouchingDisc {
                    speed_mm_s: sys.geometric_speed(theta),
                    x_mm: sys.touching_x(theta),
                }
            })
            .collect()
    }

    /// The jam points of the min-norm model `spec` along a column of a map, in order
    /// ([`models::solve_column`]: each search starts from its neighbours' answers).
    fn min_norm_column(&self, spec: &ModelSpec, scenes: &[SceneParams]) -> Result<Vec<JamPoint>> {
        let answers = models::solve_column(spec, scenes)?;
        Ok(answers.iter().map(JamPoint::from).collect())
    }
}

/// A rigid disc touching the turning palm ([`Models::touching_disc`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TouchingDisc {
    /// Its speed in mm/s: omega (r + (r + h) cos theta) / sin^2 theta, which is
    /// r omega / (2 sin^2(theta/2)) for h = 0.
    pub speed_mm_s: f64,
    /// Its position in mm: (r (1 + cos theta) + h) / sin theta, r cot(theta/2) for h = 0.
    pub x_mm: f64,
}

/// The jam points of `spec` at `base` with `param` set to each of `values`, in order: the
/// min-norm model as one line of scenes ([`Models::min_norm_column`]), every other model at
/// each value in parallel ([`grid::at_values`]).
pub(crate) fn along(
    models: &dyn Models,
    spec: &ModelSpec,
    base: &SceneParams,
    param: Param,
    values: &[f64],
) -> Result<Vec<JamPoint>> {
    match spec {
        ModelSpec::MinNorm(_) => {
            let scenes: Vec<SceneParams> = values.iter().map(|&v| base.with(param, v)).collect();
            models.min_norm_column(spec, &scenes)
        }
        _ => grid::at_values(base, param, values, |p| models.jam_point(spec, p)),
    }
}

/// The grid of `req` with the jam points of `spec`: the min-norm model a column at a time
/// (each search starts from its neighbours' answers, about three programs a cell against 31
/// for a bisection from the reach), the closed form in batches of cells
/// ([`grid::evaluate_closed_form`], each cell's answer as its own), every other model cell by
/// cell.
pub(crate) fn evaluate(
    models: &dyn Models,
    spec: &ModelSpec,
    req: &GridRequest,
) -> Result<GridResult> {
    match spec {
        ModelSpec::MinNorm(_) => grid::evaluate_columns(req, |c| models.min_norm_column(spec, c)),
        ModelSpec::Statics => grid::evaluate_closed_form(req),
        _ => grid::evaluate(req, |p| models.jam_point(spec, p)),
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
