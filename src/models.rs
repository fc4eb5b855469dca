//! The model port: one way to ask any model where a push jams.
//!
//! A model is chosen by data, a [`ModelSpec`] carrying its settings, and answers with one
//! [`Solution`]: the status, theta_jam and x_jam every consumer reads (`solve`'s text and JSON,
//! grids, sweeps, charts, the reports), the counted work, and the model's own [`Detail`].
//! [`solve`] is the only dispatch on the model: grids ([`crate::grid`]) and charts call it per
//! cell or per point.
//!
//! # Adding a model
//!
//! Write its module (a function from `&SceneParams` and its settings to its own solution
//! struct), then register it here, the one registration point: a [`ModelKind`] variant (its
//! name in scene files and output), a [`ModelSpec`] variant (its settings), a [`Detail`] variant
//! (its own solution), the arm of [`solve`] that calls it and its line in [`ModelKind::ALL`],
//! [`ModelKind::summary`] and [`Solution::work`]. Every grid, sweep layer, chart scene
//! (`model = "<name>"`), report and `solve --model` (its choices follow `ModelKind::ALL`) then
//! reaches it. The one place outside this file is presentation: `solve`'s text and JSON print
//! each model's own detail (`src/cli/solve.rs`), and the compiler points there. A new method of
//! an existing model (an integrator of the dynamics) is a setting of that model's spec, not a
//! new model.
//!
//! # When a model cannot run a scene
//!
//! A model that does not represent a scene the others can answer says so in its own result,
//! never by refusing the whole command: [`JamStatus::OutsideModel`] with a typed
//! [`OutsideModel`] reason (the dynamics need a mass: a weightless disc has no equations of
//! motion, while the statics and the min-norm model are defined for it). A push starting above
//! 90 deg is outside every model ([`OutsideModel::PalmLiftsDisc`]): the palm's push points
//! upwards there and can lift the disc, and every model keeps it on the ground. `Err` is left
//! for misuse: parameters that no model accepts.

use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::dynamics::{self, DynamicsParams, DynamicsSolution};
use crate::error::Result;
use crate::minnorm::{MinNormSettings, PalmSolution, palm};
use crate::scene::{JamStatus, SceneParams};
use crate::statics::{self, StaticsSolution};

/// Which model answers: its name in scene files (`model = "min_norm"`), flags and output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ModelKind {
    /// The closed-form statics of the corrected Eq. 1-2 ([`crate::statics`]).
    #[default]
    Statics,
    /// The minimum-norm contact forces, a convex program ([`crate::minnorm`]).
    #[serde(alias = "min-norm")]
    MinNorm,
    /// The dynamic simulation of the paper's Adams model ([`crate::dynamics`]).
    Dynamics,
}

impl ModelKind {
    /// Every model, in the order `solve --model all` prints them.
    pub const ALL: [ModelKind; 3] = [ModelKind::Statics, ModelKind::MinNorm, ModelKind::Dynamics];

    /// One line saying what the model is, for `--help` and listings.
    pub fn summary(self) -> &'static str {
        match self {
            ModelKind::Statics => "closed-form statics (corrected Eq. 1-2)",
            ModelKind::MinNorm => "minimum-norm contact forces (convex program)",
            ModelKind::Dynamics => "dynamic simulation (regularised or nonsmooth contact)",
        }
    }

    /// The name in `solve`'s output: `statics`, `min-norm` or `dynamics`.
    pub fn as_str(self) -> &'static str {
        match self {
            ModelKind::Statics => "statics",
            ModelKind::MinNorm => "min-norm",
            ModelKind::Dynamics => "dynamics",
        }
    }

    /// This model with the given settings of each model (only its own are used).
    pub fn with(self, min_norm: &MinNormSettings, dynamics: &DynamicsParams) -> ModelSpec {
        match self {
            ModelKind::Statics => ModelSpec::Statics,
            ModelKind::MinNorm => ModelSpec::MinNorm(*min_norm),
            ModelKind::Dynamics => ModelSpec::Dynamics {
                params: *dynamics,
                series_dt_s: None,
            },
        }
    }
}

impl std::fmt::Display for ModelKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A model with its settings: what [`solve`] is asked to run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ModelSpec {
    /// The closed form; it has no settings.
    Statics,
    /// The minimum-norm model with its formulation, search and solver settings.
    MinNorm(MinNormSettings),
    /// The simulation with its drive, contact, friction and integrator settings.
    Dynamics {
        /// The `[dynamics]` settings.
        params: DynamicsParams,
        /// Record the time series at this interval in s (None: no series).
        series_dt_s: Option<f64>,
    },
}

impl ModelSpec {
    /// Which model this is.
    pub fn kind(&self) -> ModelKind {
        match self {
            ModelSpec::Statics => ModelKind::Statics,
            ModelSpec::MinNorm(_) => ModelKind::MinNorm,
            ModelSpec::Dynamics { .. } => ModelKind::Dynamics,
        }
    }

    /// Checks the model's own settings (not the scene); the error names the key and value.
    pub fn validate(&self) -> Result<()> {
        match self {
            ModelSpec::Statics => Ok(()),
            ModelSpec::MinNorm(s) => s.validate(),
            ModelSpec::Dynamics { params, .. } => params.validate(),
        }
    }
}

/// Why a model does not represent a scene the other models can answer.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
pub enum OutsideModel {
    /// The simulation needs a disc with mass: a weightless disc has no equations of motion.
    NeedsMass {
        /// The scene's mass in kg.
        mass_kg: f64,
    },
    /// The push starts above 90 deg, where the palm's face leans over the disc and its normal
    /// push n = (sin theta, -cos theta) points upwards: it can lift the disc off the ground.
    /// Every model keeps the disc on the ground (the closed form's R_n = m g + F cos(theta -
    /// alpha_p) and the min-norm program's ground contact assume it; the simulation lifts the
    /// disc at once at 120 deg with mu = 1), so none answers: statics and min-norm used to jam
    /// at 91.99 deg for `--mu 1 --start-angle 120`, a disc the palm had already lifted.
    PalmLiftsDisc {
        /// The scene's start angle in deg.
        start_angle_deg: f64,
    },
}

/// Largest start angle any model represents, in deg: above it the palm's push points upwards.
pub(crate) const MAX_START_ANGLE_DEG: f64 = 90.0;

impl std::fmt::Display for OutsideModel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            OutsideModel::NeedsMass { mass_kg } => write!(
                f,
                "the simulation needs a disc with mass (m = {mass_kg} kg): a weightless disc has \
                 no equations of motion"
            ),
            OutsideModel::PalmLiftsDisc { start_angle_deg } => write!(
                f,
                "the push starts at {start_angle_deg} deg, above 90 deg: the palm's face leans \
                 over the disc and its push points upwards, so it can lift the disc off the \
                 ground, and every model here keeps the disc on the ground"
            ),
        }
    }
}

/// A model's own answer, beyond the fields every model shares.
#[derive(Debug, Clone, PartialEq)]
pub enum Detail {
    /// The closed form: the F -> infinity limit and the lift-off angle.
    Statics(StaticsSolution),
    /// The min-norm search: solves, iterations, backend and the contact forces at the jam.
    MinNorm(PalmSolution),
    /// The simulation: jam time, trust checks, integrator work and the time series.
    Dynamics(Box<DynamicsSolution>),
    /// The model did not run: the scene lies outside what it represents.
    Outside(OutsideModel),
}

/// One model's answer to one push: the port's single solution type.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The model that answered.
    pub model: ModelKind,
    /// Outcome of the push.
    pub status: JamStatus,
    /// Palm angle at the jam in deg (None where the model gives none).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm (None where the model gives none).
    pub x_jam_mm: Option<f64>,
    /// Wall time of the answer in s.
    pub elapsed_s: f64,
    /// The model's own answer.
    pub detail: Detail,
}

impl Solution {
    /// The work a solution counted: (steps, evaluations). Steps are the integrator's accepted
    /// steps or the min-norm programs solved; evaluations are right-hand-side evaluations or
    /// clarabel iterations (0 on the exact path).
    pub fn work(&self) -> (u64, u64) {
        match &self.detail {
            Detail::Dynamics(d) => (d.steps, d.rhs_evals),
            Detail::MinNorm(m) => (u64::from(m.solves), u64::from(m.iterations)),
            Detail::Statics(_) | Detail::Outside(_) => (0, 0),
        }
    }
}

/// Why model `kind` does not represent `scene`, if it does not: a push starting above
/// [`MAX_START_ANGLE_DEG`] lifts the disc (every model), and the dynamics need a mass. The one
/// rule [`solve`] and the reports' references apply.
pub(crate) fn outside(kind: ModelKind, scene: &SceneParams) -> Option<OutsideModel> {
    if scene.start_angle_deg > MAX_START_ANGLE_DEG {
        Some(OutsideModel::PalmLiftsDisc {
            start_angle_deg: scene.start_angle_deg,
        })
    } else if kind == ModelKind::Dynamics && scene.mass_kg <= 0.0 {
        Some(OutsideModel::NeedsMass {
            mass_kg: scene.mass_kg,
        })
    } else {
        None
    }
}

/// Solves `scene` with the model of `spec`.
///
/// Validates the scene and the model's settings first; `Err` only for invalid input. A model
/// that does not represent the scene answers [`JamStatus::OutsideModel`].
pub fn solve(spec: &ModelSpec, scene: &SceneParams) -> Result<Solution> {
    scene.validate()?;
    spec.validate()?;
    let t0 = Instant::now();
    let (status, theta_jam_deg, x_jam_mm, detail) = match spec {
        _ if let Some(why) = outside(spec.kind(), scene) => {
            (JamStatus::OutsideModel, None, None, Detail::Outside(why))
        }
        ModelSpec::Statics => {
            let s = statics::solve(scene);
            (s.status, s.theta_jam_deg, s.x_jam_mm, Detail::Statics(s))
        }
        ModelSpec::MinNorm(settings) => {
            let s = palm::solve(scene, settings)?;
            (s.status, s.theta_jam_deg, s.x_jam_mm, Detail::MinNorm(s))
        }
        ModelSpec::Dynamics {
            params,
            series_dt_s,
        } => {
            let s = dynamics::simulate(scene, params, *series_dt_s)?;
            let (st, t, x) = (s.status, s.theta_jam_deg, s.x_jam_mm);
            (st, t, x, Detail::Dynamics(Box::new(s)))
        }
    };
    Ok(Solution {
        model: spec.kind(),
        status,
        theta_jam_deg,
        x_jam_mm,
        elapsed_s: t0.elapsed().as_secs_f64(),
        detail,
    })
}

/// Solves `scenes` in order with the model of `spec`: a line of a map (one parameter fixed).
///
/// The min-norm model starts each cell's search from its neighbours' answers
/// ([`crate::minnorm::solve_column`]: Newton on the friction utilisation, about three programs a
/// cell; each jam within the bisection's tolerance of [`solve`]'s, every status the same);
/// the other models solve cell by cell. A min-norm cell's [`Solution::elapsed_s`] is the
/// column's time over its cells.
pub fn solve_column(spec: &ModelSpec, scenes: &[SceneParams]) -> Result<Vec<Solution>> {
    let ModelSpec::MinNorm(settings) = spec else {
        return scenes.iter().map(|p| solve(spec, p)).collect();
    };
    spec.validate()?;
    if scenes.iter().any(|p| outside(spec.kind(), p).is_some()) {
        return scenes.iter().map(|p| solve(spec, p)).collect();
    }
    let t0 = Instant::now();
    let answers = crate::minnorm::solve_column(scenes, settings)?;
    let elapsed_s = t0.elapsed().as_secs_f64() / scenes.len().max(1) as f64;
    Ok(answers
        .into_iter()
        .map(|s| Solution {
            model: ModelKind::MinNorm,
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
            elapsed_s,
            detail: Detail::MinNorm(s),
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_answers_the_paper_case_through_the_port() {
        let scene = SceneParams::default();
        for kind in ModelKind::ALL {
            let spec = kind.with(&MinNormSettings::default(), &DynamicsParams::default());
            let s = solve(&spec, &scene).unwrap();
            assert_eq!(s.model, kind);
            assert_eq!(s.status, JamStatus::Jams, "{kind}");
            let x = s.x_jam_mm.unwrap();
            // Statics and min-norm: 24.355 mm; the motion-driven simulation: near r/mu = 25.
            assert!((24.3..25.1).contains(&x), "{kind}: {x}");
        }
    }

    /// Regression: above 90 deg only the dynamics answered `outside_model` (the palm lifts the
    /// disc); the statics and the min-norm model still jammed, e.g. at 91.99 deg for mu = 1 and
    /// a start at 120 deg, a disc the palm had already lifted. Every model now answers
    /// `outside_model` with the one reason, and 90 deg itself is still answered.
    #[test]
    fn start_angle_above_90_is_outside_every_model() {
        for start_angle_deg in [90.001, 120.0, 179.999] {
            let scene = SceneParams {
                start_angle_deg,
                ..SceneParams::default().with_mu(1.0)
            };
            for kind in ModelKind::ALL {
                let spec = kind.with(&MinNormSettings::default(), &DynamicsParams::default());
                let s = solve(&spec, &scene).unwrap();
                assert_eq!(
                    s.status,
                    JamStatus::OutsideModel,
                    "{kind} {start_angle_deg}"
                );
                assert_eq!(
                    s.detail,
                    Detail::Outside(OutsideModel::PalmLiftsDisc { start_angle_deg }),
                    "{kind}"
                );
                assert_eq!((s.theta_jam_deg, s.x_jam_mm), (None, None), "{kind}");
            }
        }
        let at_90 = SceneParams::default();
        for kind in ModelKind::ALL {
            let spec = kind.with(&MinNormSettings::default(), &DynamicsParams::default());
            let s = solve(&spec, &at_90).unwrap();
            assert_eq!(s.status, JamStatus::Jams, "{kind} at 90 deg");
        }
    }

    /// Regression: `solve --model all --mass 0` refused the whole command because the dynamics
    /// need a mass, although the statics and the min-norm model are defined for a weightless
    /// disc. The dynamics now say so in their own result and the others answer.
    #[test]
    fn a_weightless_disc_is_outside_the_dynamics_only() {
        let scene = SceneParams {
            mass_kg: 0.0,
            ..Default::default()
        };
        for kind in ModelKind::ALL {
            let spec = kind.with(&MinNormSettings::default(), &DynamicsParams::default());
            let s = solve(&spec, &scene).unwrap();
            if kind == ModelKind::Dynamics {
                assert_eq!(s.status, JamStatus::OutsideModel);
                assert!(matches!(
                    s.detail,
                    Detail::Outside(OutsideModel::NeedsMass { .. })
                ));
                assert_eq!(s.x_jam_mm, None);
            } else {
                assert_eq!(s.status, JamStatus::Jams, "{kind}");
            }
        }
    }
}
