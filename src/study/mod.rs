//! The reports on the models themselves: error against run time ([`accuracy`]), the cost of a
//! design map ([`map_cost`]) and numerical stability on stiff and extreme cases ([`stability`]).
//!
//! # Every answer against the physics, through the port
//!
//! A report runs many ways of answering "where does it jam" ([`Source`]: the closed form, the
//! min-norm program by its exact path or by clarabel at a tolerance, the simulation by an
//! integrator at a tolerance and a contact stiffness) through the one model port
//! ([`crate::models::solve`]), and compares each answer with the **physical reference** of the
//! scene as that source poses it ([`reference()`]):
//!
//! * a palm pushing with the scene's force F, quasi-statically (the statics, the min-norm
//!   program): the closed form of the corrected Eq. 1 at F;
//! * a palm driven by prescribed motion (the simulation with the `motion` drive): the rigid
//!   answer, the closed form at F -> infinity, theta = atan mu_g + atan mu_p and
//!   x = r cot(theta/2) (r / mu for equal frictions), with the closed form's statuses (beyond
//!   reach, jammed at start, never jams); the rigid dynamics locks up there;
//! * a force-limited palm (the simulation with the `force` drive): the converged rigid
//!   dynamics, where the rigid disc comes to rest ([`rigid_dynamics_reference`], used by the
//!   accuracy report, its map and the stability matrix).
//!
//! The closed forms are the paper's theory with the palm's face on the hinge line
//! (`palm_offset_mm` = 0); inertia is not in them, which is why a dynamic drive has the rigid
//! dynamics as its reference. The difference between a source and its reference is everything
//! that source adds: solver tolerance, the contact's compliance, regularised friction, the
//! integrator's error. The integration error alone is measured separately, against the same
//! regularised model solved at a tight tolerance ([`accuracy`]).
//!
//! A source that gives no answer is a row with its typed [`Why`], never a gap.

pub mod accuracy;
pub mod map_cost;
pub mod stability;

use serde::Serialize;

use crate::config::Config;
use crate::dynamics::{CrossCheck, Drive, DynamicsParams, DynamicsSolution, Failure, Method};
use crate::error::{Error, Result};
use crate::minnorm::palm::MinNormSettings;
use crate::minnorm::qp::QpSettings;
use crate::models::{Detail, ModelKind, ModelSpec, OutsideModel, Solution};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// A way of answering "where does it jam": a model with the settings a report varies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Source {
    /// The closed form (exact: it is the reference of every finite push).
    Statics,
    /// The min-norm program by its exact path (active sets, dense KKT solves).
    MinNormExact,
    /// The min-norm program by clarabel alone at `tol` = tol_feas = tol_gap = tol_infeas.
    MinNormClarabel {
        /// clarabel's tolerance, in (0, 1).
        tol: f64,
    },
    /// The regularised simulation by one integrator.
    Simulation {
        /// The integrator.
        method: Method,
        /// rtol = atol, in (0, 1).
        rtol: f64,
        /// The contact stiffness as the penetration in um at the scene's push F (None: the
        /// stiffness of the `[dynamics]` settings).
        penetration_um: Option<f64>,
        /// Run the verification at a tenth of the tolerance (what `solve` does by default).
        verify: bool,
    },
    /// The nonsmooth simulation (rigid contacts, exact Coulomb friction) at one step size.
    Nonsmooth {
        /// Palm turn per time step in deg, in (0, 1].
        step_deg: f64,
        /// Run the verification at twice the step (what `solve` does by default).
        verify: bool,
    },
}

impl Source {
    /// The model that answers.
    pub fn model(&self) -> ModelKind {
        match self {
            Source::Statics => ModelKind::Statics,
            Source::MinNormExact | Source::MinNormClarabel { .. } => ModelKind::MinNorm,
            Source::Simulation { .. } | Source::Nonsmooth { .. } => ModelKind::Dynamics,
        }
    }

    /// How it answers: `closed_form`, `exact`, `clarabel`, or the integrator's name.
    pub fn method(&self) -> &'static str {
        match self {
            Source::Statics => "closed_form",
            Source::MinNormExact => "exact",
            Source::MinNormClarabel { .. } => "clarabel",
            Source::Simulation { method, .. } => method.as_str(),
            Source::Nonsmooth { .. } => Method::Nonsmooth.as_str(),
        }
    }

    /// The tolerance it was given (clarabel's tol or the integrator's rtol), if any.
    pub fn tolerance(&self) -> Option<f64> {
        match *self {
            Source::MinNormClarabel { tol } => Some(tol),
            Source::Simulation { rtol, .. } => Some(rtol),
            _ => None,
        }
    }

    /// The nonsmooth method's step in deg of palm turn, if this is it.
    pub fn step_deg(&self) -> Option<f64> {
        match *self {
            Source::Nonsmooth { step_deg, .. } => Some(step_deg),
            _ => None,
        }
    }

    /// The contact stiffness it was given as a penetration in um at F, if any.
    pub fn penetration_um(&self) -> Option<f64> {
        match *self {
            Source::Simulation { penetration_um, .. } => penetration_um,
            _ => None,
        }
    }

    /// A short label, e.g. `dynamics radau5 rtol 1e-6 10 um`.
    pub fn label(&self) -> String {
        let mut s = format!("{} {}", self.model(), self.method());
        if let Some(t) = self.tolerance() {
            s.push_str(&format!(" tol {t:.0e}"));
        }
        if let Some(p) = self.penetration_um() {
            s.push_str(&format!(" {p} um"));
        }
        if let Some(h) = self.step_deg() {
            s.push_str(&format!(" step {h} deg"));
        }
        s
    }

    /// The port's model spec for this source, from the settings in `base`.
    pub fn spec(&self, base: &Config) -> ModelSpec {
        match *self {
            Source::Statics => ModelSpec::Statics,
            Source::MinNormExact => ModelSpec::MinNorm(MinNormSettings {
                qp: QpSettings {
                    fast_path: true,
                    ..base.min_norm.qp
                },
                ..base.min_norm
            }),
            Source::MinNormClarabel { tol } => ModelSpec::MinNorm(MinNormSettings {
                qp: QpSettings {
                    fast_path: false,
                    tol_feas: tol,
                    tol_gap: tol,
                    tol_infeas: tol,
                    ..base.min_norm.qp
                },
                ..base.min_norm
            }),
            Source::Simulation {
                method,
                rtol,
                penetration_um,
                verify,
            } => {
                let d = &base.dynamics;
                let stiffness = penetration_um.map_or(d.contact.stiffness_n_per_mm_e, |um| {
                    stiffness_for_penetration(base.scene.force_n, um * 1e-3, d.contact.exponent)
                });
                ModelSpec::Dynamics {
                    params: DynamicsParams {
                        contact: crate::dynamics::ContactLaw {
                            stiffness_n_per_mm_e: stiffness,
                            ..d.contact
                        },
                        integrator: crate::dynamics::IntegratorSettings {
                            method,
                            rtol,
                            atol: Some(rtol),
                            ..d.integrator
                        },
                        verification: crate::dynamics::Verification {
                            verify,
                            ..d.verification
                        },
                        ..*d
                    },
                    series_dt_s: None,
                }
            }
            Source::Nonsmooth { step_deg, verify } => ModelSpec::Dynamics {
                params: DynamicsParams {
                    integrator: crate::dynamics::IntegratorSettings {
                        method: Method::Nonsmooth,
                        nonsmooth_step_deg: Some(step_deg),
                        ..base.dynamics.integrator
                    },
                    verification: crate::dynamics::Verification {
                        verify,
                        ..base.dynamics.verification
                    },
                    ..base.dynamics
                },
                series_dt_s: None,
            },
        }
    }

    /// The drive this source poses the scene with: the simulation's, none for a finite push.
    pub fn drive(&self, base: &Config) -> Option<Drive> {
        match self {
            Source::Simulation { .. } | Source::Nonsmooth { .. } => Some(base.dynamics.drive.mode),
            _ => None,
        }
    }
}

/// The IMPACT stiffness k in N/mm^e at which a push of `force_n` penetrates `depth_mm`:
/// k = F / delta^e (the IMPACT law F = k delta^e without damping).
pub fn stiffness_for_penetration(force_n: f64, depth_mm: f64, exponent: f64) -> f64 {
    force_n / depth_mm.powf(exponent)
}

/// The penetration in mm of a push of `force_n` at stiffness k: (F / k)^(1/e).
pub fn penetration_mm(force_n: f64, stiffness: f64, exponent: f64) -> f64 {
    (force_n / stiffness).powf(1.0 / exponent)
}

/// Which physical reference a row is compared with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ReferenceKind {
    /// The closed form at the scene's push F (corrected Eq. 1).
    ClosedForm,
    /// The closed form at F -> infinity, the rigid limit x_rigid (`x_rigid_mm` in the statics'
    /// JSON): the self-locking wedge, r / mu for equal frictions.
    Rigid,
    /// The converged rigid dynamics of a force-limited palm: the nonsmooth method (rigid
    /// contacts, exact Coulomb friction) at a fine step, where the disc comes to rest, inertia
    /// included ([`rigid_dynamics_reference`]).
    RigidDynamics,
}

impl ReferenceKind {
    /// The snake_case name.
    pub fn as_str(self) -> &'static str {
        match self {
            ReferenceKind::ClosedForm => "closed_form",
            ReferenceKind::Rigid => "rigid",
            ReferenceKind::RigidDynamics => "rigid_dynamics",
        }
    }
}

/// The physical answer a source is judged by.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Reference {
    /// Which one.
    pub kind: ReferenceKind,
    /// Its status (the closed form's statuses).
    pub status: JamStatus,
    /// theta_jam in deg, where it jams (or jams at the start).
    pub theta_jam_deg: Option<f64>,
    /// x_jam in mm, where it jams (or jams at the start).
    pub x_jam_mm: Option<f64>,
}

/// The reference of `scene` for a source with `drive` (None: a push of the scene's force).
pub fn reference(scene: &SceneParams, drive: Option<Drive>) -> Reference {
    let (kind, posed) = match drive {
        Some(Drive::Motion) => (
            ReferenceKind::Rigid,
            // The largest finite push: m g sin(alpha_g) / F underflows to 0, so theta_jam is
            // the wedge, and the closed form decides reach and start as for any push.
            SceneParams {
                force_n: f64::MAX,
                ..*scene
            },
        ),
        Some(Drive::Force) | None => (ReferenceKind::ClosedForm, *scene),
    };
    // Where the scene is outside the closed form (a push above 90 deg lifts the disc), the
    // reference is outside too.
    if crate::models::outside(ModelKind::Statics, scene).is_some() {
        return Reference {
            kind,
            status: JamStatus::OutsideModel,
            theta_jam_deg: None,
            x_jam_mm: None,
        };
    }
    let s = statics::solve(&posed);
    Reference {
        kind,
        status: s.status,
        theta_jam_deg: s.theta_jam_deg,
        x_jam_mm: s.x_jam_mm,
    }
}

/// The physical reference of a simulation of `params`' force drive on `scene`: the converged
/// rigid dynamics, the nonsmooth method at `step_deg` of palm turn (the disc sliding or rolling
/// as `disc` says), without its verification run. A force-limited palm lets the disc coast past
/// the closed form at F (by 0.95 % at the defaults, printed by
/// `accuracy_force_drive_reference_is_the_rigid_dynamics`), so the quasi-static closed form is
/// no reference for it; with the motion drive the rigid dynamics
/// locks up at the rigid limit ([`ReferenceKind::Rigid`]), within 3e-5 at the default step.
/// The nonsmooth force drive's rest lies within 4.8e-6 of an independent rigid model
/// (`tests/force_drive_rest.rs`). `Err` only for invalid input.
pub fn rigid_dynamics_reference(
    params: &DynamicsParams,
    scene: &SceneParams,
    step_deg: f64,
    disc: crate::dynamics::DiscMotion,
) -> Result<Reference> {
    let spec = ModelSpec::Dynamics {
        params: DynamicsParams {
            drive: crate::dynamics::DriveSettings {
                mode: Drive::Force,
                ..params.drive
            },
            integrator: crate::dynamics::IntegratorSettings {
                method: Method::Nonsmooth,
                nonsmooth_step_deg: Some(step_deg),
                disc,
                ..params.integrator
            },
            verification: crate::dynamics::Verification {
                verify: false,
                ..params.verification
            },
            ..*params
        },
        series_dt_s: None,
    };
    let s = crate::models::solve(&spec, scene)?;
    let answered = why(&s).is_none_or(|w| matches!(w, Why::NoJam { .. }));
    Ok(Reference {
        kind: ReferenceKind::RigidDynamics,
        status: s.status,
        theta_jam_deg: s.theta_jam_deg.filter(|_| answered),
        x_jam_mm: s.x_jam_mm.filter(|_| answered),
    })
}

/// Why a row has no trusted answer, with what the model said.
///
/// JSON: the snake_case variant name under `reason`, beside its fields; the simulation's own
/// typed reason under `failure` or `check`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
pub enum Why {
    /// The model says the disc does not jam inside the palm's travel: `status` is one of
    /// never_jams, too_weak, beyond_reach (not a failure when the reference agrees).
    NoJam {
        /// The model's status.
        status: JamStatus,
    },
    /// The model does not represent the scene (a weightless disc in the simulation).
    Outside {
        /// The model's reason.
        outside: OutsideModel,
    },
    /// The integrator gave up (step limit, step size too small).
    IntegratorGaveUp {
        /// The integrator's reason, with the simulated time.
        failure: Failure,
    },
    /// The simulation's answer failed a cross-check or its error estimate.
    CrossCheck {
        /// The check and its numbers.
        check: CrossCheck,
    },
    /// The min-norm answer failed its check (forces outside a friction cone).
    MinNormCheck {
        /// The check and its numbers.
        check: crate::minnorm::MinNormCheck,
    },
}

impl Why {
    /// The snake_case tag, e.g. `integrator_gave_up`.
    pub fn tag(&self) -> &'static str {
        match self {
            Why::NoJam { .. } => "no_jam",
            Why::Outside { .. } => "outside",
            Why::IntegratorGaveUp { .. } => "integrator_gave_up",
            Why::CrossCheck { .. } => "cross_check",
            Why::MinNormCheck { .. } => "min_norm_check",
        }
    }
}

impl std::fmt::Display for Why {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Why::NoJam { status } => write!(f, "the model says {status}"),
            Why::Outside { outside } => write!(f, "{outside}"),
            Why::IntegratorGaveUp { failure } => write!(f, "the integrator gave up: {failure}"),
            Why::CrossCheck { check } => write!(f, "{check}"),
            Why::MinNormCheck { check } => write!(f, "{check}"),
        }
    }
}

/// The reason of a solution without a trusted jam; None for a trusted `jams` or
/// `jammed_at_start`.
pub fn why(s: &Solution) -> Option<Why> {
    match &s.detail {
        Detail::Outside(o) => return Some(Why::Outside { outside: *o }),
        Detail::Dynamics(d) => {
            if let Some(w) = dynamics_why(d) {
                return Some(w);
            }
        }
        Detail::MinNorm(m) => {
            if let Some(check) = m.cross_check {
                return Some(Why::MinNormCheck { check });
            }
        }
        _ => {}
    }
    match s.status {
        JamStatus::Jams | JamStatus::JammedAtStart => None,
        status => Some(Why::NoJam { status }),
    }
}

fn dynamics_why(d: &DynamicsSolution) -> Option<Why> {
    // A failure during the run-on after a confirmed jam leaves the jam standing.
    if d.status == JamStatus::IntegratorFailed
        && let Some(failure) = d.failure
    {
        return Some(Why::IntegratorGaveUp { failure });
    }
    d.cross_check.map(|check| Why::CrossCheck { check })
}

/// The port's signature: [`crate::models::solve`], or a wrapper that counts the calls (charts).
pub type SolveFn<'a> = &'a (dyn Fn(&ModelSpec, &SceneParams) -> Result<Solution> + Sync);

/// `source` on `scene` `runs` times through `solve` (the port): the last solution, the median
/// wall time in s and the runs timed. A failed simulation is not timed again (a failure is
/// deterministic).
pub fn solve_timed(
    solve: SolveFn,
    source: &Source,
    base: &Config,
    scene: &SceneParams,
    runs: usize,
) -> Result<(Solution, f64, usize)> {
    let spec = source.spec(base);
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs.max(1) {
        let s = solve(&spec, scene)?;
        times.push(s.elapsed_s);
        let failed = s.status == JamStatus::IntegratorFailed;
        last = Some(s);
        if failed {
            break;
        }
    }
    times.sort_by(f64::total_cmp);
    let n = times.len();
    let median = if n % 2 == 1 {
        times[n / 2]
    } else {
        0.5 * (times[n / 2 - 1] + times[n / 2])
    };
    Ok((last.expect("at least one run"), median, n))
}

/// Refuses a count outside `min..=max`, naming the key.
pub(crate) fn check_count(key: &str, n: usize, min: usize, max: usize) -> Result<()> {
    if (min..=max).contains(&n) {
        Ok(())
    } else {
        Err(Error::invalid(key, n, format!("must be {min} to {max}")))
    }
}

/// Refuses a list of tolerances as [`check_list`] does, and any tolerance below
/// [`crate::limits::MIN_TOLERANCE`], which double precision cannot meet.
pub(crate) fn check_tolerances(key: &str, list: &[f64], max: usize) -> Result<()> {
    check_list_from(
        key,
        list,
        max,
        crate::limits::MIN_TOLERANCE,
        "double precision meets no tighter tolerance",
    )
}

/// Refuses a list as [`check_list`] does in (0, 1), and any value below `floor`, for `why`.
pub(crate) fn check_list_from(
    key: &str,
    list: &[f64],
    max: usize,
    floor: f64,
    why: &str,
) -> Result<()> {
    check_list(key, list, max, 0.0, 1.0)?;
    match list.iter().find(|&&v| v < floor) {
        Some(&v) => Err(Error::invalid(
            key,
            crate::numbers::Num(v),
            format!("each value must be at least {floor:e}: {why}"),
        )),
        None => Ok(()),
    }
}

/// Refuses a list longer than `max` or a value outside the open interval (lo, hi).
pub(crate) fn check_list(key: &str, list: &[f64], max: usize, lo: f64, hi: f64) -> Result<()> {
    if list.len() > max {
        return Err(Error::invalid(
            key,
            list.len(),
            format!("at most {max} values"),
        ));
    }
    for &v in list {
        if !(v.is_finite() && v > lo && v < hi) {
            return Err(Error::invalid(
                key,
                crate::numbers::Num(v),
                format!("each value must lie strictly between {lo} and {hi}"),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_references_of_the_paper_case() {
        let p = SceneParams::default();
        let cf = reference(&p, None);
        assert_eq!(cf.kind, ReferenceKind::ClosedForm);
        assert!((cf.x_jam_mm.unwrap() - 24.355).abs() < 1e-3);
        let rigid = reference(&p, Some(Drive::Motion));
        assert_eq!(rigid.status, JamStatus::Jams);
        // r / mu = 25 mm for equal frictions (the crate docs' corrections to the paper).
        assert!((rigid.x_jam_mm.unwrap() - 25.0).abs() < 1e-9);
        let force = reference(&p, Some(Drive::Force));
        assert_eq!(force.x_jam_mm, cf.x_jam_mm);
    }

    #[test]
    fn a_penetration_gives_back_its_stiffness() {
        let k = stiffness_for_penetration(200.0, 0.06, 2.2);
        assert!((penetration_mm(200.0, k, 2.2) - 0.06).abs() < 1e-12);
        // Adams' default 1e5 N/mm^2.2 gives about 60 um at 200 N (crate docs).
        assert!((penetration_mm(200.0, 1e5, 2.2) - 0.0591).abs() < 1e-3);
    }
}
