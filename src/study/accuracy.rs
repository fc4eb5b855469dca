//! Error against run time, against the truth: every source's x_jam and theta_jam against the
//! scene's physical reference, beside its median wall time and its integration error.
//!
//! Two errors side by side, because they answer different questions:
//!
//! * **error** (`x_error_mm`, `theta_error_deg`): the answer against the physical reference of
//!   the scene as the source poses it ([`super::reference`]). For the simulation it is the sum
//!   of everything the regularised model adds to the rigid theory (the contact's compliance,
//!   inertia, regularised friction) and of the integration error; where it stops falling as the
//!   tolerance tightens is the model's floor, and no tolerance gets under it.
//! * **integration error** (`integration_error_mm`): the answer against the same regularised
//!   model (same contact, same friction law) solved at `converged_rtol` by the same integrator,
//!   or by the other if that one does not finish (the row names which, `converged_by`).
//!
//! The nonsmooth method (rigid contacts, exact Coulomb friction) is its own model: its rows
//! vary the step, and its integration error is against itself at `converged_step_deg`.
//!
//! The simulation runs without its verification run (the raw method is measured) and with the
//! step limit `max_steps`. Wall time is the median of `runs` answers through the port.

use serde::Serialize;

use super::{
    Reference, ReferenceKind, Source, Why, check_count, check_list, check_list_from,
    check_tolerances, reference, rigid_dynamics_reference, why,
};
use crate::config::Config;
use crate::dynamics::{DiscMotion, Drive, Method};
use crate::error::{Error, Result};
use crate::limits::MIN_NONSMOOTH_STEP_DEG;
use crate::models::ModelKind;
use crate::scene::JamStatus;

/// Most values in one list of tolerances or steps (the crate's limit).
pub const MAX_TOLERANCES: usize = crate::limits::MAX_TOLERANCES;
/// Most contact stiffnesses.
pub const MAX_PENETRATIONS: usize = 8;
/// Most timed runs per row (the crate's limit).
pub const MAX_RUNS: usize = crate::limits::MAX_RUNS;

/// What the accuracy study measures.
#[derive(Debug, Clone, PartialEq)]
pub struct AccuracySettings {
    /// clarabel tolerances of the min-norm rows, each in (0, 1), at most 64 (default: 1e-2,
    /// 1e-4, 1e-6, 1e-8, 1e-10); the exact path is always a row.
    pub min_norm_tolerances: Vec<f64>,
    /// Integrators of the simulation rows (default: radau5, dopri5).
    pub methods: Vec<Method>,
    /// rtol = atol of the simulation rows, each in (0, 1), at most 64 (default: 1e-2 ... 1e-8).
    pub tolerances: Vec<f64>,
    /// Contact stiffnesses beside the `[dynamics]` one, as the penetration in um at the
    /// scene's push F, each in (0, 1e4), at most 8 (default: 10, 1).
    pub penetrations_um: Vec<f64>,
    /// Steps of the nonsmooth rows in deg of palm turn, each in (0, 1), at most 64 (default:
    /// 0.3, 0.1, 0.03, 0.01).
    pub nonsmooth_steps_deg: Vec<f64>,
    /// Timed runs per row, 1 to 1000; the median is reported (default: 3).
    pub runs: usize,
    /// rtol of the integrators' converged answers, in (0, 1) (default: 1e-10).
    pub converged_rtol: f64,
    /// Step of the nonsmooth method's converged answer in deg, in (0, 1) (default: 0.002; the
    /// method is of first order, so its error there is about a fifth of the 0.01 deg row's).
    pub converged_step_deg: f64,
    /// Step limit of every simulation, >= 1 (default: 500000: RADAU5 at rtol 1e-10 and 1 um
    /// needs about 1e5 steps, and DOPRI5, which cannot pass the stiff contacts, fails in a
    /// second instead of four).
    pub max_steps: u64,
}

impl Default for AccuracySettings {
    fn default() -> Self {
        AccuracySettings {
            min_norm_tolerances: vec![1e-2, 1e-4, 1e-6, 1e-8, 1e-10],
            methods: vec![Method::Radau5, Method::Dopri5],
            tolerances: (2..=8).map(|k| 10f64.powi(-k)).collect(),
            penetrations_um: vec![10.0, 1.0],
            nonsmooth_steps_deg: vec![0.3, 0.1, 0.03, 0.01],
            runs: 3,
            converged_rtol: 1e-10,
            converged_step_deg: 0.002,
            max_steps: 500_000,
        }
    }
}

impl AccuracySettings {
    /// Checks every list and count; the error names the key.
    pub fn validate(&self) -> Result<()> {
        check_tolerances(
            "min_norm_tolerances",
            &self.min_norm_tolerances,
            MAX_TOLERANCES,
        )?;
        check_tolerances("tolerances", &self.tolerances, MAX_TOLERANCES)?;
        check_list(
            "penetrations_um",
            &self.penetrations_um,
            MAX_PENETRATIONS,
            0.0,
            1e4,
        )?;
        let turns_nothing = "a finer step turns the palm by no more than round-off";
        check_list_from(
            "nonsmooth_steps_deg",
            &self.nonsmooth_steps_deg,
            MAX_TOLERANCES,
            MIN_NONSMOOTH_STEP_DEG,
            turns_nothing,
        )?;
        check_count("runs", self.runs, 1, MAX_RUNS)?;
        check_tolerances("converged_rtol", &[self.converged_rtol], 1)?;
        check_list_from(
            "converged_step_deg",
            &[self.converged_step_deg],
            1,
            MIN_NONSMOOTH_STEP_DEG,
            turns_nothing,
        )?;
        if self.methods.len() > 4 {
            return Err(Error::invalid(
                "methods",
                self.methods.len(),
                "at most four integrators",
            ));
        }
        if self.methods.contains(&Method::Nonsmooth) {
            return Err(Error::invalid(
                "methods",
                "nonsmooth",
                "the integrators of the regularised model are radau5 and dopri5; the nonsmooth \
                 method's rows are set by its steps",
            ));
        }
        if self.max_steps == 0 {
            return Err(Error::invalid("max_steps", 0, "at least one step"));
        }
        crate::limits::check_steps("max_steps", self.max_steps, &self.simulation_runs())
    }

    /// The method of every simulation the study runs, its rows' and their converged answers',
    /// each once: a run that takes its whole step limit fails and is not timed again.
    fn simulation_runs(&self) -> Vec<Method> {
        let rows = self.sources().into_iter().filter_map(|s| match s {
            Source::Simulation { method, .. } => Some(method),
            Source::Nonsmooth { .. } => Some(Method::Nonsmooth),
            _ => None,
        });
        let converged = (self.stiffnesses().into_iter())
            .flat_map(|_| self.methods.iter().copied())
            .chain((!self.nonsmooth_steps_deg.is_empty()).then_some(Method::Nonsmooth));
        rows.chain(converged).collect()
    }

    /// Every source of the study, in the order of its rows.
    pub fn sources(&self) -> Vec<Source> {
        let mut out = vec![Source::Statics, Source::MinNormExact];
        out.extend((self.min_norm_tolerances.iter()).map(|&tol| Source::MinNormClarabel { tol }));
        for pen in self.stiffnesses() {
            for &method in &self.methods {
                for &rtol in &self.tolerances {
                    out.push(Source::Simulation {
                        method,
                        rtol,
                        penetration_um: pen,
                        verify: false,
                    });
                }
            }
        }
        out.extend(
            (self.nonsmooth_steps_deg.iter()).map(|&step_deg| Source::Nonsmooth {
                step_deg,
                verify: false,
            }),
        );
        out
    }

    fn stiffnesses(&self) -> Vec<Option<f64>> {
        std::iter::once(None)
            .chain(self.penetrations_um.iter().map(|&p| Some(p)))
            .collect()
    }
}

/// One source's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AccuracyRow {
    /// The model that answered.
    pub model: ModelKind,
    /// How: closed_form, exact, clarabel, radau5, dopri5.
    pub method: &'static str,
    /// clarabel's tol or the integrator's rtol.
    pub tolerance: Option<f64>,
    /// Contact penetration in um at the scene's push F (regularised simulation rows).
    pub penetration_um: Option<f64>,
    /// Step in deg of palm turn (nonsmooth rows).
    pub step_deg: Option<f64>,
    /// The model's status.
    pub status: JamStatus,
    /// theta_jam in deg.
    pub theta_jam_deg: Option<f64>,
    /// x_jam in mm.
    pub x_jam_mm: Option<f64>,
    /// Which physical reference the errors are against.
    pub reference: ReferenceKind,
    /// The reference's status.
    pub reference_status: JamStatus,
    /// The reference's theta_jam in deg.
    pub theta_ref_deg: Option<f64>,
    /// The reference's x_jam in mm.
    pub x_ref_mm: Option<f64>,
    /// |x_jam - x_ref| in mm (both jam).
    pub x_error_mm: Option<f64>,
    /// |x_jam - x_ref| / x_ref.
    pub x_rel_error: Option<f64>,
    /// |theta_jam - theta_ref| in deg.
    pub theta_error_deg: Option<f64>,
    /// The integrator whose answer at converged_rtol this row's integration error is against.
    pub converged_by: Option<Method>,
    /// That converged x_jam in mm.
    pub x_converged_mm: Option<f64>,
    /// |x_jam - x_converged| in mm.
    pub integration_error_mm: Option<f64>,
    /// Median wall time of one answer in s.
    pub median_time_s: f64,
    /// Timed runs.
    pub runs: usize,
    /// Accepted steps, or min-norm programs solved.
    pub steps: u64,
    /// Right-hand-side evaluations, or clarabel iterations.
    pub evaluations: u64,
    /// Why the row has no trusted answer, if it has none.
    pub reason: Option<Why>,
}

/// A converged answer of the regularised model at one stiffness.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Converged {
    /// The method.
    pub method: Method,
    /// Penetration in um at F (None: the `[dynamics]` stiffness, or the nonsmooth method).
    pub penetration_um: Option<f64>,
    /// Its rtol (integrators).
    pub rtol: Option<f64>,
    /// Its step in deg (the nonsmooth method).
    pub step_deg: Option<f64>,
    /// Its status.
    pub status: JamStatus,
    /// Its x_jam in mm, if it jams.
    pub x_jam_mm: Option<f64>,
    /// Why it has none.
    pub reason: Option<Why>,
}

/// The whole study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AccuracyReport {
    /// The references: the closed form at F (the statics and min-norm rows), and the rigid
    /// limit (motion drive) or the converged rigid dynamics (force drive) of the simulation rows.
    pub references: Vec<Reference>,
    /// The converged answers.
    pub converged: Vec<Converged>,
    /// One row per source.
    pub rows: Vec<AccuracyRow>,
}

fn jam_x(status: JamStatus, x: Option<f64>) -> Option<f64> {
    matches!(status, JamStatus::Jams | JamStatus::JammedAtStart)
        .then_some(x)
        .flatten()
}

/// Runs the study on `base` (scene and settings); `progress(done, total)` before the first
/// answer and after each row. `Err` only for invalid input, checked before anything runs.
pub fn run(
    base: &Config,
    settings: &AccuracySettings,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<AccuracyReport> {
    base.validate()?;
    settings.validate()?;
    let base = &Config {
        dynamics: crate::dynamics::DynamicsParams {
            integrator: crate::dynamics::IntegratorSettings {
                max_steps: settings.max_steps,
                ..base.dynamics.integrator
            },
            ..base.dynamics
        },
        ..base.clone()
    };
    let sources = settings.sources();
    let stiff = settings.stiffnesses();
    let mut converged_sources: Vec<Source> = stiff
        .iter()
        .flat_map(|&pen| {
            settings
                .methods
                .iter()
                .map(move |&method| Source::Simulation {
                    method,
                    rtol: settings.converged_rtol,
                    penetration_um: pen,
                    verify: false,
                })
        })
        .collect();
    if !settings.nonsmooth_steps_deg.is_empty() {
        converged_sources.push(Source::Nonsmooth {
            step_deg: settings.converged_step_deg,
            verify: false,
        });
    }
    for s in sources.iter().chain(&converged_sources) {
        s.spec(base).validate()?;
    }
    let scene = &base.scene;
    let total = sources.len() + converged_sources.len();
    let mut done = 0;
    progress(done, total);
    let mut converged = Vec::new();
    for src in &converged_sources {
        let (s, _, _) = super::solve_timed(&crate::models::solve, src, base, scene, 1)?;
        let (method, penetration_um) = match *src {
            Source::Simulation {
                method,
                penetration_um,
                ..
            } => (method, penetration_um),
            _ => (Method::Nonsmooth, None),
        };
        converged.push(Converged {
            method,
            penetration_um,
            rtol: src.tolerance(),
            step_deg: src.step_deg(),
            status: s.status,
            x_jam_mm: jam_x(s.status, s.x_jam_mm).filter(|_| why(&s).is_none()),
            reason: why(&s),
        });
        done += 1;
        progress(done, total);
    }
    let converged_x = |m: Method, pen: Option<f64>| {
        let find = |m: Method| {
            converged
                .iter()
                .find(|c| c.method == m && c.penetration_um == pen)
                .and_then(|c| c.x_jam_mm.map(|x| (m, x)))
        };
        // The nonsmooth method is its own model: no other method's answer stands in for it.
        find(m).or_else(|| {
            (settings.methods.iter())
                .filter(|&&o| o != m && m != Method::Nonsmooth)
                .find_map(|&o| find(o))
        })
    };
    // A force-limited palm's physical answer is the converged rigid dynamics (the disc coasts
    // past the closed form at F): the regularised model's disc slides, the nonsmooth rows' disc
    // moves as the settings say.
    let force = base.dynamics.drive.mode == Drive::Force;
    let rigid_dynamics = |disc: DiscMotion| {
        force
            .then(|| {
                rigid_dynamics_reference(&base.dynamics, scene, settings.converged_step_deg, disc)
            })
            .transpose()
    };
    let rigid_sliding = rigid_dynamics(DiscMotion::Slides)?;
    let rigid_own = rigid_dynamics(base.dynamics.integrator.disc)?;
    let mut rows = Vec::with_capacity(sources.len());
    for src in &sources {
        let (s, median, runs) =
            super::solve_timed(&crate::models::solve, src, base, scene, settings.runs)?;
        let r = match src {
            Source::Simulation { .. } => rigid_sliding,
            Source::Nonsmooth { .. } => rigid_own,
            _ => None,
        }
        .unwrap_or_else(|| reference(scene, src.drive(base)));
        let reason = why(&s);
        let trusted = reason.is_none();
        let x = jam_x(s.status, s.x_jam_mm).filter(|_| trusted);
        let theta = (s.status == JamStatus::Jams || s.status == JamStatus::JammedAtStart)
            .then_some(s.theta_jam_deg)
            .flatten()
            .filter(|_| trusted);
        let x_err = x.zip(r.x_jam_mm).map(|(a, b)| (a - b).abs());
        let conv = match src {
            Source::Simulation {
                method,
                penetration_um,
                ..
            } => converged_x(*method, *penetration_um),
            Source::Nonsmooth { .. } => converged_x(Method::Nonsmooth, None),
            _ => None,
        };
        let (steps, evaluations) = s.work();
        let penetration_um = match src {
            Source::Simulation { .. } => {
                let crate::models::ModelSpec::Dynamics { params, .. } = src.spec(base) else {
                    unreachable!("a simulation source is a dynamics spec")
                };
                Some(
                    super::penetration_mm(
                        scene.force_n,
                        params.contact.stiffness_n_per_mm_e,
                        params.contact.exponent,
                    ) * 1e3,
                )
            }
            _ => None,
        };
        rows.push(AccuracyRow {
            model: src.model(),
            method: src.method(),
            tolerance: src.tolerance(),
            penetration_um,
            step_deg: src.step_deg(),
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
            reference: r.kind,
            reference_status: r.status,
            theta_ref_deg: r.theta_jam_deg,
            x_ref_mm: r.x_jam_mm,
            x_error_mm: x_err,
            x_rel_error: x_err.zip(r.x_jam_mm).map(|(e, b)| e / b.abs()),
            theta_error_deg: theta.zip(r.theta_jam_deg).map(|(a, b)| (a - b).abs()),
            converged_by: conv.map(|c| c.0),
            x_converged_mm: conv.map(|c| c.1),
            integration_error_mm: x.zip(conv).map(|(a, (_, b))| (a - b).abs()),
            median_time_s: median,
            runs,
            steps,
            evaluations,
            reason,
        });
        done += 1;
        progress(done, total);
    }
    let mut references = vec![reference(scene, None)];
    references.extend(if force {
        rigid_sliding
            .into_iter()
            .chain(rigid_own.filter(|r| Some(*r) != rigid_sliding))
            .collect()
    } else {
        vec![reference(scene, Some(Drive::Motion))]
    });
    Ok(AccuracyReport {
        references,
        converged,
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small() -> AccuracySettings {
        AccuracySettings {
            min_norm_tolerances: vec![1e-3, 1e-8],
            methods: vec![Method::Radau5],
            tolerances: vec![1e-3, 1e-6],
            penetrations_um: vec![1.0],
            nonsmooth_steps_deg: vec![0.1, 0.01],
            runs: 1,
            converged_rtol: 1e-9,
            converged_step_deg: 0.002,
            max_steps: 500_000,
        }
    }

    /// The statics is its own reference; the exact min-norm path meets it to the bisection's
    /// resolution; the motion-driven simulation's error against r / mu falls with the
    /// penetration (the compliance floor) while its integration error stays small.
    #[test]
    fn errors_against_the_physics_and_against_the_converged_answer() {
        let report = run(&Config::default(), &small(), &mut |_, _| {}).unwrap();
        let rows = &report.rows;
        assert_eq!(rows[0].method, "closed_form");
        assert_eq!(rows[0].x_error_mm, Some(0.0));
        let exact = &rows[1];
        assert_eq!(exact.method, "exact");
        assert!(exact.x_rel_error.unwrap() < 1e-6, "{exact:?}");
        let sim: Vec<&AccuracyRow> = rows.iter().filter(|r| r.method == "radau5").collect();
        assert_eq!(sim.len(), 4);
        let at = |pen_small: bool| {
            sim.iter()
                .find(|r| {
                    r.tolerance == Some(1e-6) && (r.penetration_um.unwrap() < 2.0) == pen_small
                })
                .unwrap()
        };
        let (soft, stiff) = (at(false), at(true));
        assert_eq!(soft.reference, ReferenceKind::Rigid);
        assert_eq!(soft.x_ref_mm, Some(25.0));
        // Adams' default contact: the disc lags the palm, about 1 % short of r/mu.
        let e_soft = soft.x_rel_error.unwrap();
        let e_stiff = stiff.x_rel_error.unwrap();
        assert!((0.002..0.03).contains(&e_soft), "{e_soft}");
        assert!(e_stiff < e_soft / 5.0, "{e_stiff} vs {e_soft}");
        // The integration error at rtol 1e-6 is far below the model's floor.
        let ie = soft.integration_error_mm.unwrap();
        assert!(ie < 0.1 * soft.x_error_mm.unwrap(), "{ie}");
        assert_eq!(soft.converged_by, Some(Method::Radau5));
        // The nonsmooth method has no contact give: at 0.1 and 0.01 deg it meets r / mu to
        // 1e-4 (measured 7e-5: both lock up on the same step of palm angle, 43.600 deg; RADAU5
        // at 1 um comes to 4e-5), and within 2 um of its own answer at 0.002 deg.
        let ns: Vec<&AccuracyRow> = rows.iter().filter(|r| r.method == "nonsmooth").collect();
        assert_eq!(ns.len(), 2);
        for r in &ns {
            assert!(r.x_rel_error.unwrap() < 1e-4, "{r:?}");
            assert_eq!(r.converged_by, Some(Method::Nonsmooth));
            assert!(r.integration_error_mm.unwrap() < 2e-3, "{r:?}");
        }
        assert!(rows.iter().all(|r| r.median_time_s > 0.0 && r.runs == 1));
    }

    /// With the force drive the report judged every simulation against the
    /// quasi-static closed form at F, which a disc at 30 deg/s coasts past: the nonsmooth answer
    /// (24.5853 mm, the rigid disc's rest) showed as the worst error (0.95 %). The reference of
    /// a dynamic drive is now the converged rigid dynamics: the nonsmooth rows' error is their
    /// integration error, the regularised rows' the contact's give; the statics and min-norm
    /// rows keep the closed form.
    #[test]
    fn accuracy_force_drive_reference_is_the_rigid_dynamics() {
        let mut base = Config::default();
        base.dynamics.drive.mode = Drive::Force;
        let report = run(&base, &small(), &mut |_, _| {}).unwrap();
        let closed = report.references[0];
        let rigid = report.references[1];
        assert_eq!(report.references.len(), 2, "{:?}", report.references);
        assert_eq!(closed.kind, ReferenceKind::ClosedForm);
        assert_eq!(rigid.kind, ReferenceKind::RigidDynamics);
        let (xc, xr) = (closed.x_jam_mm.unwrap(), rigid.x_jam_mm.unwrap());
        eprintln!(
            "closed form {xc:.4} mm, rigid dynamics {xr:.4} mm: the disc coasts {:.2} % past",
            100.0 * (xr - xc) / xc
        );
        assert!((xr - 24.5853).abs() < 1e-3, "{xr}");
        for r in &report.rows {
            let want = match r.model {
                ModelKind::Dynamics => ReferenceKind::RigidDynamics,
                _ => ReferenceKind::ClosedForm,
            };
            assert_eq!(r.reference, want, "{r:?}");
        }
        for r in report.rows.iter().filter(|r| r.method == "nonsmooth") {
            let (e, ie) = (r.x_error_mm.unwrap(), r.integration_error_mm.unwrap());
            assert!(
                (e - ie).abs() < 1e-12 && r.x_rel_error.unwrap() < 1e-4,
                "{r:?}"
            );
        }
        let tight = |r: &&AccuracyRow| r.method == "radau5" && r.tolerance == Some(1e-6);
        for r in report.rows.iter().filter(tight) {
            // The contact's give: under 1 % at 59 um, under 0.1 % at 1 um.
            let limit = if r.penetration_um.unwrap() < 2.0 {
                1e-3
            } else {
                1e-2
            };
            assert!(r.x_rel_error.unwrap() < limit, "{r:?}");
        }
    }

    #[test]
    fn every_list_and_count_is_bounded() {
        let cases: Vec<(&str, AccuracySettings)> = vec![
            (
                "tolerances",
                AccuracySettings {
                    tolerances: vec![1e-3; MAX_TOLERANCES + 1],
                    ..small()
                },
            ),
            (
                "runs",
                AccuracySettings {
                    runs: MAX_RUNS + 1,
                    ..small()
                },
            ),
            ("runs", AccuracySettings { runs: 0, ..small() }),
            (
                "penetrations_um",
                AccuracySettings {
                    penetrations_um: vec![-1.0],
                    ..small()
                },
            ),
            (
                "min_norm_tolerances",
                AccuracySettings {
                    min_norm_tolerances: vec![1.0],
                    ..small()
                },
            ),
        ];
        for (key, s) in cases {
            let err = s.validate().unwrap_err().to_string();
            assert!(err.contains(key), "{key}: {err}");
        }
    }
}
