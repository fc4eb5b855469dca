//! Model 3: dynamic simulation of the paper's Adams model (Section 4).
//!
//! # The model
//!
//! The disc (radius r, mass m) slides on a translational joint along X: its centre is (x, r), it
//! neither rotates nor leaves the ground, and the joint's vertical reaction R_n is the ground's
//! normal force. The palm, hinged at the origin, closes from the start angle at omega. Between
//! the palm's face (offset h from the hinge line; 0 in the paper's theory) and the disc acts
//! Adams' IMPACT force; at the palm and at the joint acts Adams' regularised Coulomb friction
//! ([`contact`]). The state is (theta, x, v) and the equations of motion are derived in
//! [`scene`]: in the limit of a rigid contact at constant speed they reduce to the corrected
//! Eq. 1-2, so the closed form ([`crate::statics`]) is their quasi-static limit.
//!
//! # Drives
//!
//! * `motion` (the paper's): theta = theta_0 - omega t whatever the load. It pushes as hard as
//!   needed, so the jam tends to the F -> infinity limit x = r/mu, delayed slightly by the
//!   contact's compliance (the disc lags the palm by the penetration).
//! * `force`: a speed drive with a force limit. The palm turns at omega until its elastic push
//!   reaches N_max = F cos(atan mu_palm) (a total push F while the palm slides), then stalls and
//!   holds. The disc jams where the closed form at finite F says, and Fig. 7b's force
//!   dependence can be simulated.
//!
//! # Integration and its trust
//!
//! Two integrators ([`integrators`]): RADAU5 (implicit, analytic Jacobian) and DOPRI5
//! (explicit). The problem is stiff: the friction slope at zero slip, 1.5 mu_s/V_s, gives
//! time constants of about a microsecond under a 200 N load. The jam is read by
//! [`jam::JamDetector`] from the dense output. Step error control does not bound the error of
//! x_jam, so every result is cross-checked against the quasi-static limit:
//!
//! * no push can slide a disc past the self-locking wedge (theta = atan mu_g + atan mu_p); only
//!   its inertia can carry it a little further, so a jam more than 5 % beyond the wedge's
//!   position is `inaccurate`;
//! * a disc that stands still at the end of the confirmation window while the palm pushes with
//!   more than twice the force that slides it at that angle (the corrected Eq. 1 with static
//!   frictions) is `inaccurate`: the regularised friction cannot hold it;
//! * for the force drive, a disc that stops while the drive's push stays below its limit is
//!   `inaccurate`.
//!
//! RADAU5 also tightens the tolerance it is given (rtol' = 0.1 rtol^(2/3)), as Hairer's code does. A method
//! that gives up reports `integrator_failed` with the time and the reason.

pub mod accuracy;
pub mod contact;
pub mod integrators;
pub mod jam;
pub mod params;
pub mod scene;

use serde::Serialize;

pub use params::{Drive, DynamicsParams, Method};

use crate::error::Result;
use crate::model::{JamStatus, SceneParams};
use integrators::{Dopri5, Outcome, Radau5, Stats, Tolerances};
use jam::{JamDetector, JamRule, SeriesRow};
use scene::Scene;

/// How far past the self-locking wedge a jam may lie before it is called inaccurate: a fast disc
/// coasts past the wedge on its inertia (0.7 % at mu = 0.15 with the defaults).
const WEDGE_MARGIN: f64 = 0.05;

/// Largest step: 1 deg of commanded palm turn, so that arming and a jam never share a step.
const MAX_STEP_DEG: f64 = 1.0;

/// An integration that gave up.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Failure {
    /// Simulated time in s where it stopped.
    pub t_s: f64,
    /// Why, e.g. "step limit of 2000000 reached".
    pub reason: String,
}

/// The result of one simulation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DynamicsSolution {
    /// Outcome: jams, jammed_at_start, never_jams, beyond_reach, inaccurate or integrator_failed.
    pub status: JamStatus,
    /// Palm angle at the jam (speed-ratio reading) in deg.
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm.
    pub x_jam_mm: Option<f64>,
    /// Time of the jam in s.
    pub t_jam_s: Option<f64>,
    /// The stiction reading: disc position (mm) when the ground slip first falls below V_s.
    pub x_stiction_mm: Option<f64>,
    /// Time of the stiction reading in s.
    pub t_stiction_s: Option<f64>,
    /// The self-locking limit in mm: the touching position at theta = atan mu_g + atan mu_p.
    pub x_wedge_mm: Option<f64>,
    pub method: Method,
    pub drive: Drive,
    pub steps: u64,
    pub rejected_steps: u64,
    pub rhs_evals: u64,
    pub jacobian_evals: u64,
    /// Jam candidates the disc recovered from.
    pub discarded_candidates: u32,
    /// Why the result is `inaccurate`, if it is.
    pub cross_check: Option<String>,
    /// Set when the integrator gave up (also after a confirmed jam, during the run-on).
    pub failure: Option<Failure>,
    /// Simulated time in s.
    pub simulated_s: f64,
    /// The time series (empty unless asked for).
    #[serde(skip)]
    pub series: Vec<SeriesRow>,
}

/// Simulates one push until the jam is read (plus `after_jam_s`). `series_dt_s` asks for the
/// time series at that interval. Errors only for invalid parameters.
pub fn simulate(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> Result<DynamicsSolution> {
    scene.validate()?;
    params.validate()?;
    params.validate_scene(scene)?;
    let sys = Scene::new(scene, params);
    let theta0 = scene.start_angle_deg.to_radians();
    let mut y = vec![theta0, sys.touching_x(theta0), 0.0];
    let t_end = theta0 / sys.omega;
    let tol = Tolerances {
        rtol: params.rtol,
        atol: params.atol(),
        max_step: MAX_STEP_DEG.to_radians() / sys.omega,
        max_steps: params.max_steps,
    };
    let rule = JamRule {
        jam_ratio: params.jam_speed_ratio,
        arm_ratio: params.arm_speed_ratio,
        v_stiction: params.stiction_velocity_mm_s,
        palm_length: scene.palm_length_mm,
        after_jam: params.after_jam_s,
        ground_decel: scene.mu_ground * scene.gravity_m_s2 * 1000.0,
        series_dt: series_dt_s.filter(|dt| *dt > 0.0 && dt.is_finite()),
    };
    let mut det = JamDetector::new(&sys, rule, 0.0);
    let (outcome, stats) = match params.method {
        Method::Radau5 => Radau5.integrate(&sys, 0.0, &mut y, t_end, &tol, &mut det),
        Method::Dopri5 => Dopri5.integrate(&sys, 0.0, &mut y, t_end, &tol, &mut det),
    };
    Ok(conclude(scene, params, &sys, det, outcome, stats))
}

fn conclude(
    scene: &SceneParams,
    params: &DynamicsParams,
    sys: &Scene,
    det: JamDetector,
    outcome: Outcome,
    stats: Stats,
) -> DynamicsSolution {
    let wedge = scene.alpha_ground() + scene.alpha_palm();
    let x_wedge = (wedge > 0.0).then(|| sys.touching_x(wedge)).filter(|x| x.is_finite());
    let (failure, simulated) = match &outcome {
        Outcome::Failed { t, reason } => (
            Some(Failure {
                t_s: *t,
                reason: reason.clone(),
            }),
            *t,
        ),
        Outcome::Stopped { t } => (None, *t),
        Outcome::Finished => (None, sys_end(scene, sys)),
    };
    let mut out = DynamicsSolution {
        status: JamStatus::Jams,
        theta_jam_deg: None,
        x_jam_mm: None,
        t_jam_s: None,
        x_stiction_mm: det.stiction.map(|s| s.x),
        t_stiction_s: det.stiction.map(|s| s.t),
        x_wedge_mm: x_wedge,
        method: params.method,
        drive: params.drive,
        steps: stats.steps,
        rejected_steps: stats.rejected,
        rhs_evals: stats.rhs_evals,
        jacobian_evals: stats.jacobian_evals,
        discarded_candidates: det.discarded,
        cross_check: None,
        failure,
        simulated_s: simulated,
        series: det.series,
    };
    if det.beyond_reach.is_some() {
        out.status = JamStatus::BeyondReach;
        return out;
    }
    // A candidate still waiting for confirmation when the run ends normally is taken as is.
    let jam = det.jam.filter(|_| det.confirmed || out.failure.is_none());
    let Some(jam) = jam else {
        out.status = if out.failure.is_some() {
            JamStatus::IntegratorFailed
        } else if !det.armed {
            // The disc never reached the palm's speed: the push could not get it going.
            out.theta_jam_deg = Some(scene.start_angle_deg);
            out.x_jam_mm = Some(sys.touching_x(scene.start_angle_deg.to_radians()));
            out.t_jam_s = Some(0.0);
            JamStatus::JammedAtStart
        } else {
            JamStatus::NeverJams
        };
        return out;
    };
    out.theta_jam_deg = Some(jam.theta.to_degrees());
    out.x_jam_mm = Some(jam.x);
    out.t_jam_s = Some(jam.t);
    if let Some(xw) = x_wedge
        && jam.x > xw * (1.0 + WEDGE_MARGIN)
    {
        out.cross_check = Some(format!(
            "x_jam = {:.4} mm lies beyond the self-locking limit {xw:.4} mm that no push can \
             pass: the integration is not accurate enough; tighten --rtol",
            jam.x
        ));
    }
    let stalled = det.push_after_jam >= (1.0 - 2.0 * params.force_band) * sys.normal_limit;
    if params.drive == Drive::Force && jam.theta > wedge + 0.1_f64.to_radians() && !stalled {
        out.cross_check = Some(format!(
            "the disc stopped at {:.3} deg while the drive's push stayed at {:.2} N, below its \
             limit {:.2} N: the integration is not accurate enough; tighten --rtol",
            jam.theta.to_degrees(),
            det.push_after_jam,
            sys.normal_limit
        ));
    }
    if let Some((theta, push)) = det.at_confirmation {
        let needed = sliding_push_n(scene, params, theta);
        if push > 2.0 * needed {
            out.cross_check = Some(format!(
                "the disc stood still at {:.4} mm while the palm pushed with {push:.2} N at \
                 {:.3} deg, more than twice the {needed:.2} N that slides it: the integration is \
                 not accurate enough; tighten --rtol",
                jam.x,
                theta.to_degrees()
            ));
        }
    }
    if out.cross_check.is_some() {
        out.status = JamStatus::Inaccurate;
    }
    out
}

/// The palm's normal push (N) that slides the disc at palm angle `theta` against the static
/// frictions at both contacts (the corrected Eq. 1 solved for the push), infinite at and below
/// the self-locking wedge.
fn sliding_push_n(scene: &SceneParams, params: &DynamicsParams, theta: f64) -> f64 {
    let mg = params.mu_static_ground.unwrap_or(scene.mu_ground);
    let mp = params.mu_static_palm.unwrap_or(scene.mu_palm);
    let (s, c) = theta.sin_cos();
    let denom = s * (1.0 - mg * mp) - c * (mg + mp);
    if denom > 0.0 {
        mg * scene.weight_n() / denom
    } else {
        f64::INFINITY
    }
}

fn sys_end(scene: &SceneParams, sys: &Scene) -> f64 {
    scene.start_angle_deg.to_radians() / sys.omega
}
