//! The model port: one way to ask any model where a push jams.
//!
//! A model is chosen by data, a [`ModelSpec`] carrying its settings, and answers with one
//! [`Solution`]: the status, theta_jam and x_jam every consumer reads (`solve`'s text and JSON,
//! grids, sweeps, charts, the reports), the counted work, and the model's own [`Detail`].
//! [`solve`] is the only dispatch on the model: grids (`crate::grid`) and charts call it per
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

// The array entry: N pushes in, the answers written into buffers the caller owns (the Python
// package calls it; so can any front end that holds its own arrays).
pub mod columns;
mod record;

use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::dynamics::{self, DynamicsParams, DynamicsSolution};
use crate::error::Result;
use crate::minnorm::{MinNormSettings, PalmSolution, palm};
use crate::scene::{JamStatus, SceneParams};
use crate::statics::{self, StaticsSolution};

/// Which model answers: its name in scene files (`model = "min-norm"`), flags and output.
///
/// One spelling is printed everywhere, [`ModelKind::as_str`]'s (`min-norm`); `min_norm` is read
/// too, in scene files, settings and flags.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ModelKind {
    /// The closed-form statics of the corrected Eq. 1-2 ([`crate::statics`]).
    #[default]
    Statics,
    /// The minimum-norm contact forces, a convex program ([`crate::minnorm`]).
    #[serde(alias = "min_norm")]
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

/// A model and its settings as data (a dict from Python, a section of a file): the model's
/// name under `model` beside its own keys, those of its `[min_norm]` or `[dynamics]` section,
/// each at its default when left out: `{"model": "statics"}`,
/// `{"model": "min-norm", "formulation": "paper"}`,
/// `{"model": "dynamics", "integrator": {"method": "nonsmooth"}}`. Unknown keys are refused.
/// Check it with [`ModelSpec::validate`] ([`solve`] does).
impl<'de> Deserialize<'de> for ModelSpec {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        /// The statics take no settings.
        #[derive(Deserialize)]
        #[serde(deny_unknown_fields)]
        struct NoSettings {}

        #[derive(Deserialize)]
        #[serde(tag = "model", rename_all = "kebab-case")]
        enum Written {
            Statics(NoSettings),
            #[serde(alias = "min_norm")]
            MinNorm(MinNormSettings),
            Dynamics(DynamicsParams),
        }
        Ok(match Written::deserialize(d)? {
            Written::Statics(NoSettings {}) => ModelSpec::Statics,
            Written::MinNorm(s) => ModelSpec::MinNorm(s),
            Written::Dynamics(params) => ModelSpec::Dynamics {
                params,
                series_dt_s: None,
            },
        })
    }
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

pub(crate) use crate::scene::MAX_START_ANGLE_DEG;

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

/// What one push comes to, in the fields every model shares: a [`Solution`] without its
/// detail or its time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// The model that answered.
    pub model: ModelKind,
    /// Outcome of the push.
    pub status: JamStatus,
    /// Palm angle at the jam in deg (None where the model gives none).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm (None where the model gives none).
    pub x_jam_mm: Option<f64>,
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
    /// The solution's outcome: the model, the status, theta_jam and x_jam.
    pub fn outcome(&self) -> Outcome {
        Outcome {
            model: self.model,
            status: self.status,
            theta_jam_deg: self.theta_jam_deg,
            x_jam_mm: self.x_jam_mm,
        }
    }

    /// Where a jam past the palm's end would be on a long enough palm: the closed form's
    /// [`crate::statics::PastPalm`] of a `beyond_reach` push; None for every other status and
    /// model.
    pub fn past_palm(&self) -> Option<crate::statics::PastPalm> {
        match &self.detail {
            Detail::Statics(d) if self.status == JamStatus::BeyondReach => d.past_palm,
            _ => None,
        }
    }

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

/// [`solve`]'s outcome, to the bit, where the model gives it without its whole answer: the
/// closed form without its extras (the lift-off angle, the rigid limit, the jam past the
/// palm's end) or the clock, and any model on a scene it does not represent. None for the
/// min-norm search and the simulation, whose outcome is all their work. Validates as
/// [`solve`] does.
pub fn outcome(spec: &ModelSpec, scene: &SceneParams) -> Result<Option<Outcome>> {
    scene.validate()?;
    spec.validate()?;
    let (status, theta_jam_deg, x_jam_mm) = match spec {
        _ if outside(spec.kind(), scene).is_some() => (JamStatus::OutsideModel, None, None),
        ModelSpec::Statics => statics::outcome(scene),
        ModelSpec::MinNorm(_) | ModelSpec::Dynamics { .. } => return Ok(None),
    };
    Ok(Some(Outcome {
        model: spec.kind(),
        status,
        theta_jam_deg,
        x_jam_mm,
    }))
}

/// Solves `scenes` in order with the model of `spec`: a line of a map (one parameter fixed).
///
/// The min-norm model starts each cell's search from its neighbours' answers
/// (`crate::minnorm::solve_column`: Newton on the friction utilisation, about three programs a
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

    /// A model's settings read from data take its name in either spelling, default every key
    /// left out, and refuse a key the model does not have.
    #[test]
    fn a_model_spec_is_read_from_its_name_and_keys() {
        let read = |text: &str| serde_json::from_str::<ModelSpec>(text);
        assert_eq!(read(r#"{"model": "statics"}"#).unwrap(), ModelSpec::Statics);
        let paper = MinNormSettings::default();
        for name in ["min-norm", "min_norm"] {
            let spec = read(&format!(r#"{{"model": "{name}"}}"#)).unwrap();
            assert_eq!(spec, ModelSpec::MinNorm(paper), "{name}");
        }
        let nonsmooth = read(r#"{"model": "dynamics", "integrator": {"method": "nonsmooth"}}"#);
        let ModelSpec::Dynamics { params, .. } = nonsmooth.unwrap() else {
            panic!("dynamics")
        };
        assert_eq!(params.integrator.method, dynamics::Method::Nonsmooth);
        assert_eq!(params.drive, DynamicsParams::default().drive);
        for wrong in [
            r#"{"model": "statics", "formulation": "paper"}"#,
            r#"{"model": "min-norm", "rtol": 1e-6}"#,
            r#"{"model": "adams"}"#,
            r#"{"formulation": "paper"}"#,
        ] {
            assert!(read(wrong).is_err(), "{wrong} was read");
        }
    }

    /// The array entry answers every push as `solve` does alone, in order, for every model,
    /// with a column that varies and one that stays; NaN where `solve` has no number.
    #[test]
    fn columns_answer_each_push_as_solve_does() {
        use crate::scene::Param;
        // Out of order, with a weak push, a held start and a jam past the palm among them.
        let mu = [0.3, 0.05, 0.9, 0.12, 0.4, 0.2, 1e-9, 0.6];
        let force = [40.0, 2.0, 40.0, 40.0, 200.0, 40.0, 40.0, 5.0];
        let base = SceneParams {
            palm_length_mm: 80.0,
            start_angle_deg: 80.0,
            ..SceneParams::default()
        };
        let pushes = columns::Pushes {
            base,
            columns: vec![
                (Param::named("mu").unwrap(), &mu[..]),
                (Param::named("force_n").unwrap(), &force[..]),
                (Param::named("radius_mm").unwrap(), &[12.5][..]),
            ],
        };
        let fast = DynamicsParams {
            integrator: crate::dynamics::IntegratorSettings {
                method: crate::dynamics::Method::Nonsmooth,
                ..DynamicsParams::default().integrator
            },
            ..DynamicsParams::default()
        };
        for spec in [
            ModelSpec::Statics,
            ModelSpec::MinNorm(MinNormSettings::default()),
            ModelKind::Dynamics.with(&MinNormSettings::default(), &fast),
        ] {
            let n = mu.len();
            let (mut st, mut th, mut x) = (vec![0; n], vec![0.0; n], vec![0.0; n]);
            let out = columns::Answers {
                status: &mut st,
                theta_jam_deg: &mut th,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: None,
            };
            columns::solve_into(&spec, &pushes, out).unwrap();
            let mut seen = std::collections::HashSet::new();
            for i in 0..n {
                let p = SceneParams {
                    radius_mm: 12.5,
                    force_n: force[i],
                    ..base.with_mu(mu[i])
                };
                let one = solve(&spec, &p).unwrap();
                seen.insert(one.status);
                assert_eq!(JamStatus::ALL[st[i] as usize], one.status, "{spec:?} {i}");
                for (got, want) in [(th[i], one.theta_jam_deg), (x[i], one.x_jam_mm)] {
                    match want {
                        // The min-norm column search lands within its bisection's tolerance.
                        Some(w) => assert!((got - w).abs() <= 1e-6 * w.abs(), "{i}: {got} {w}"),
                        None => assert!(got.is_nan(), "{i}: {got}"),
                    }
                }
            }
            if spec == ModelSpec::Statics {
                assert!(seen.len() >= 4, "{seen:?}");
            }
        }
    }

    /// A column of another length than the rest, a palm-angle column, an answer buffer of the
    /// wrong length and an invalid value are refused before anything is solved, naming them.
    #[test]
    fn columns_refuse_what_solve_would() {
        use crate::scene::Param;
        let mu = Param::named("mu").unwrap();
        let run = |columns: Vec<(Param, &[f64])>, n: usize| {
            let pushes = columns::Pushes {
                base: SceneParams::default(),
                columns,
            };
            let (mut st, mut th, mut x) = (vec![0; n], vec![0.0; n], vec![0.0; n]);
            let out = columns::Answers {
                status: &mut st,
                theta_jam_deg: &mut th,
                x_jam_mm: &mut x,
                past_palm_x_jam_mm: None,
            };
            columns::solve_into(&ModelSpec::Statics, &pushes, out)
                .unwrap_err()
                .to_string()
        };
        let force = Param::named("force_n").unwrap();
        let msg = run(vec![(mu, &[0.1, 0.2]), (force, &[1.0, 2.0, 3.0])], 3);
        assert!(msg.contains("mu") && msg.contains("2 values"), "{msg}");
        let msg = run(vec![(Param::ThetaDeg, &[10.0])], 1);
        assert!(msg.contains("theta_deg"), "{msg}");
        let msg = run(vec![(mu, &[0.1, 0.2])], 3);
        assert!(msg.contains("answers"), "{msg}");
        let msg = run(vec![(mu, &[0.1, -0.2])], 2);
        assert!(msg.contains("mu") && msg.contains("-0.2"), "{msg}");
    }

    /// A solution's serde form is the port's one record: the shared keys, then the model's own
    /// (each model's status once), then the wall time.
    #[test]
    fn a_solution_serialises_with_its_models_own_keys() {
        let scene = SceneParams::default();
        for kind in ModelKind::ALL {
            let spec = kind.with(&MinNormSettings::default(), &DynamicsParams::default());
            let s = solve(&spec, &scene).unwrap();
            let doc = serde_json::to_value(&s).unwrap();
            let keys: Vec<&str> = doc
                .as_object()
                .unwrap()
                .keys()
                .map(|k| k.as_str())
                .collect();
            assert_eq!(
                keys[..4],
                ["model", "status", "theta_jam_deg", "x_jam_mm"],
                "{kind}"
            );
            assert_eq!(keys.last(), Some(&"elapsed_s"), "{kind}");
            assert_eq!(doc["model"], kind.as_str());
            assert_eq!(doc["status"], "jams");
            assert_eq!(doc["x_jam_mm"].as_f64(), s.x_jam_mm);
            let own = match kind {
                ModelKind::Statics => "x_rigid_mm",
                ModelKind::MinNorm => "contacts_at_jam",
                ModelKind::Dynamics => "steps",
            };
            assert!(doc.get(own).is_some(), "{kind} lacks {own}: {doc}");
        }
        let lifted = SceneParams {
            start_angle_deg: 120.0,
            ..scene
        };
        let s = solve(&ModelSpec::Statics, &lifted).unwrap();
        let doc = serde_json::to_value(&s).unwrap();
        assert_eq!(doc["status"], "outside_model");
        assert_eq!(doc["outside_model"]["reason"], "palm_lifts_disc");
    }

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
