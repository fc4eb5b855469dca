//! Model 3: dynamic simulation of the paper's Adams model (Section 4).
//!
//! # The model
//!
//! The disc (radius r, mass m) slides on a translational joint along X: its centre is (x, r), it
//! neither rotates nor leaves the ground, and the joint's vertical reaction R_n is the ground's
//! normal force. The palm, hinged at the origin, closes from the start angle at omega. Between
//! the palm's face (offset h from the hinge line; 0 in the paper's theory) and the disc acts
//! Adams' IMPACT force; at the palm and at the joint acts Adams' regularised Coulomb friction
//! (`contact`). The state is (theta, x, v) and the equations of motion are derived in
//! `system`: in the limit of a rigid contact at constant speed they reduce to the corrected
//! Eq. 1-2, so the closed form ([`crate::statics`]) is their quasi-static limit.
//!
//! # Drives
//!
//! * `motion` (the paper's): theta = theta_0 - omega t whatever the load. It pushes as hard as
//!   needed, so the jam tends to the F -> infinity limit x = r/mu, a little short of it because
//!   of the contact's compliance (the disc lags the palm by the penetration: 24.75 mm at the
//!   defaults, 24.94 mm with 10 um of penetration at 200 N, 25.00 mm with 1 um).
//! * `force`: a speed drive with a force limit. The palm turns at omega until its elastic push
//!   reaches N_max = F cos(atan mu_palm) (a total push F while the palm slides), then stalls and
//!   holds. The jam is where the disc comes to rest, as the paper defines jamming
//!   (immobilisation), for every method: the nonsmooth method's disc and palm at rest, and for
//!   RADAU5 and DOPRI5 the first instant after the speed collapse at which the disc moves slower
//!   than 2 V_d (`jam::rest_speed_mm_s`: Adams' friction has no true stiction, so a held disc
//!   creeps, at 0.124 mm/s at the defaults, `the_force_drive_creep_figure_of_the_docs`). The collapse itself, where the disc's speed falls to
//!   half the geometric speed, is where the palm stalled and let the disc coast on; it is kept
//!   as `x_half_speed_mm` and is not the jam. Against an independent rigid model (the disc tied
//!   to the palm until the push needed reaches N_max, then pushed with N_max until it stops,
//!   `tests/force_drive_rest.rs`) over mu 0.15-0.45, F 50-1000 N and 10-90 deg/s: the nonsmooth
//!   rest lies within 4.8e-6 of it; RADAU5's at the default contact 0.25-1.04 % short of it (the
//!   contact's give), and the half-speed reading 0.04-9.55 % short of the rest (most at
//!   mu 0.15, F 50 N, 90 deg/s). A slow push rests near the closed form at finite F (Fig. 7b's
//!   force dependence); a fast one coasts past it, most at low mu and low F. A palm that
//!   stalls against a disc at rest before the disc ever reached its speed ends the run there
//!   when the rigid statics say the disc can never move again (`held`: its push at the limit
//!   is below the push that slides it at its angle, and the palm only closes): the answer is
//!   known without integrating to the end of the push, for every method.

//! # Integration and its trust
//!
//! Two integrators (`integrators`): RADAU5 (implicit, analytic Jacobian) and DOPRI5
//! (explicit). The problem is stiff: the friction slope at zero slip, 1.5 mu_s/V_s, gives
//! time constants of about a microsecond under a 200 N load. The jam is read by
//! `jam::JamDetector` from the dense output. Step error control does not bound the error of
//! x_jam, so every result is checked against the quasi-static limit and an error estimate:
//!
//! * no push can slide a disc past the self-locking wedge (theta = atan mu_g + atan mu_p); only
//!   its inertia can carry it a little further, so a jam more than 5 % beyond the wedge's
//!   position is `inaccurate`;
//! * a disc that stands still at the end of the confirmation window while the palm pushes with
//!   more than twice the force that slides it at that angle (the corrected Eq. 1 with static
//!   frictions) is `inaccurate`: the regularised friction cannot hold it;
//! * for the force drive, a disc that stops while the drive's push stays below its limit is
//!   `inaccurate`;
//! * with `verify` (the default) the simulation runs a second time at a tenth of rtol and atol;
//!   the difference of the two x_jam is reported as the error estimate `x_jam_error_mm`, and an
//!   estimate above `max_jam_error` (relative, default 1e-3) or a different status makes the
//!   answer `inaccurate`;
//! * rtol looser than 1e-2 is always `inaccurate`. With this cap lifted, rtol 0.05-0.5 (both
//!   methods and drives, contacts of 59 and 1 um) gave x_jam from 58 % short to 574 % long
//!   (10-14 mm and 33-169 mm against 24.5-25.0 mm), and some wrong answers passed every other
//!   check: DOPRI5's 10-14 mm jams without the verification run, and DOPRI5's `beyond_reach` at
//!   the 1 um contact (the disc jams at 25 mm) with it.
//!
//! The estimate from one tenth of the tolerance can understate the error
//! a few times over at loose tolerances. RADAU5 also tightens the tolerance it is given
//! (rtol' = 0.1 rtol^(2/3)), as Hairer's code does. A method that gives up reports
//! `integrator_failed` with the time and the reason.

pub mod accuracy;
pub(crate) mod contact;
mod held;
pub(crate) mod integrators;
pub(crate) mod jam;
pub(crate) mod nonsmooth;
pub(crate) mod params;
mod run;
pub(crate) mod system;
#[cfg(test)]
mod tests;
mod verdict;

use serde::Serialize;

/// mm per m: the simulations work in mm, s, kg and N, so a force per mass in N/kg (= m/s^2)
/// is `MM_PER_M` times that many mm/s^2, and a stiffness in N/mm is `MM_PER_M` times as many N/m.
pub(crate) const MM_PER_M: f64 = 1000.0;

pub use integrators::Failure;
pub use jam::SeriesRow;
pub use nonsmooth::{LockUp, MotionTally};
pub use params::{
    ContactLaw, DiscMotion, Drive, DriveSettings, DynamicsParams, FrictionLaw, IntegratorSettings,
    JamReading, Method, SeriesSettings, Verification,
};
pub use verdict::CrossCheck;
pub use verdict::Refinement;

use crate::error::Result;
use crate::scene::{JamStatus, SceneParams};

/// How far past the self-locking wedge, beyond the disc's coasting distance, a jam may lie before
/// it is called inaccurate: the contact's give (the motion drive's jam lies 0.23-2.69 % from the
/// rigid contact's over mu 0.1-0.6 at 10-90 deg/s, `model_spread_of_the_default_contact`).
pub(crate) const WEDGE_MARGIN: f64 = 0.05;

/// Largest step: 1 deg of commanded palm turn, so that arming and a jam never share a step.
pub(crate) const MAX_STEP_DEG: f64 = 1.0;

/// Largest relative distance between the compliant contact's jam and the rigid contact's before
/// the answer is called contact-model dependent. The default contact (59 um at 200 N) lies
/// 0.23-2.69 % from the rigid answer with the motion drive over mu 0.1-0.6 at 10-90 deg/s (2.69 %
/// at mu = 0.15 and 90 deg/s; 3.68 % at mu = 0.1 and 90 deg/s, flagged), and 0.36-0.56 % with
/// the force drive, whose jam is where the disc comes to rest (`tests/force_drive_rest.rs`,
/// `model_spread_of_the_default_contact` prints them). The
/// extreme cases (a palm at 3600 deg/s on soft contacts, a 1e4 kg disc, a 1 N/mm contact,
/// no ground friction on a stiff contact) lie further off; no test prints their spread, so no
/// figure is quoted.
pub(crate) const MAX_MODEL_SPREAD: f64 = 0.035;

/// With a palm that lost the disc before the jam, a smaller distance to the rigid answer already
/// says the disc was knocked ahead: at 3600 deg/s the jam moves with the contact's stiffness
/// (by how much, no test prints yet, so no figure is quoted).
pub(crate) const KNOCKED_SPREAD: f64 = 0.01;

/// Tolerances looser than this are never trusted: at rtol = 0.05-0.5 the answers were 58 % short
/// to 574 % long, and some wrong ones passed every other check (see the module docs).
pub(crate) const LOOSEST_RTOL: f64 = 1e-2;

/// The result of one simulation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DynamicsSolution {
    /// Outcome: jams, jammed_at_start, never_jams, beyond_reach, inaccurate or integrator_failed.
    pub status: JamStatus,
    /// Palm angle at the jam in deg: where the disc comes to rest (force drive) or the palm locks
    /// up (motion drive).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm: where the disc comes to rest (force drive, every method)
    /// or where the motion-driven palm locks up against it.
    pub x_jam_mm: Option<f64>,
    /// Time of the jam in s (for the force drive, when the disc came to rest).
    pub t_jam_s: Option<f64>,
    /// The stiction reading: disc position (mm) when the ground slip first falls below V_s.
    pub x_stiction_mm: Option<f64>,
    /// Time of the stiction reading in s.
    pub t_stiction_s: Option<f64>,
    /// The force drive's half-speed reading (RADAU5, DOPRI5): disc position (mm) when its speed
    /// fell below `jam_speed_ratio` of the geometric speed, i.e. where the palm stalled and let
    /// the disc coast on. Not the jam: the disc comes to rest further out (`x_jam_mm`).
    pub x_half_speed_mm: Option<f64>,
    /// Time of the half-speed reading in s.
    pub t_half_speed_s: Option<f64>,
    /// The self-locking limit in mm: the touching position at theta = atan mu_g + atan mu_p
    /// (the statics' `x_rigid_mm`, the jam as F -> infinity).
    pub x_rigid_mm: Option<f64>,
    /// The integration method that answered.
    pub method: Method,
    /// How the palm was driven.
    pub drive: Drive,
    /// Accepted steps (of both runs when verified).
    pub steps: u64,
    /// Rejected steps (both runs).
    pub rejected_steps: u64,
    /// Right-hand-side evaluations (both runs).
    pub rhs_evals: u64,
    /// Jacobian evaluations (both runs).
    pub jacobian_evals: u64,
    /// Estimated error of x_jam in mm: the difference to a second run at a tenth of the
    /// tolerances (None unless `verify`).
    pub x_jam_error_mm: Option<f64>,
    /// Jam candidates the disc recovered from.
    pub discarded_candidates: u32,
    /// Why the result is `inaccurate`, if it is.
    pub cross_check: Option<CrossCheck>,
    /// Set when the integrator gave up (also after a confirmed jam, during the run-on).
    pub failure: Option<Failure>,
    /// Simulated time in s.
    pub simulated_s: f64,
    /// The nonsmooth method's lock-up: where the motion-driven palm could turn no further and
    /// the push it needed (None for the other methods and drives).
    pub lock_up: Option<nonsmooth::LockUp>,
    /// How the disc moved, in steps of the nonsmooth method (None for the other methods).
    pub disc_motion: Option<nonsmooth::MotionTally>,
    /// The palm lost the disc after first pushing it to speed, before the jam (it bounced off a
    /// stiff contact or was knocked ahead).
    pub palm_lost_disc: bool,
    /// The rigid contact's answer for the same scene and drive (the nonsmooth method, disc
    /// sliding), in mm: computed beside RADAU5 and DOPRI5 with `verify`.
    pub x_jam_rigid_mm: Option<f64>,
    /// The model's own uncertainty in mm: |x_jam - x_jam_rigid_mm|, how far the unknown contact
    /// compliance moves the jam. Not the integrator's error (that is `x_jam_error_mm`).
    pub model_uncertainty_mm: Option<f64>,
    /// The series is physical up to this time in s: with the motion drive the jam is a lock-up,
    /// and after it a real palm stops while the simulated one grinds on into the disc
    /// (millimetres of penetration, kN of force). None: physical throughout.
    pub physical_until_s: Option<f64>,
    /// How finely the nonsmooth method located the jam in mm: the lock-up's bisection bracket,
    /// or the disc's travel in its last moving step before it came to rest (None for the other
    /// methods and without a jam). Part of `x_jam_error_mm`.
    pub jam_resolution_mm: Option<f64>,
    /// The time series (empty unless asked for).
    #[serde(skip)]
    pub series: Vec<SeriesRow>,
}

/// Simulates one push until the jam is read (plus `after_jam_s`), and, with `verify`, once more
/// at a tenth of the tolerances to estimate the error of x_jam. `series_dt_s` asks for the time
/// series at that interval. Errors only for invalid parameters.
pub(crate) fn simulate(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> Result<DynamicsSolution> {
    scene.validate()?;
    params.validate()?;
    params.validate_scene(scene)?;
    if scene.start_angle_deg > crate::scene::MAX_START_ANGLE_DEG {
        return Ok(lifted_at_start(scene, params));
    }
    // A start angle that rounds to 0 rad (5e-324 deg) puts the contact at no finite distance
    // along the palm (r cot(theta/2) overflows): the disc is never touched, beyond reach before
    // any step, as the closed form says. The run integrated a disc at infinity and called its
    // x_jam = inf inaccurate.
    if !scene.start_contact_distance_mm().is_finite() {
        return Ok(before_any_step(params, JamStatus::BeyondReach, None));
    }
    let mut out = simulate_checked(scene, params, series_dt_s);
    // A force-limited palm whose push is below the least push that can slide the disc at any
    // angle, m g sin(atan mu_g) (the corrected Eq. 1 at 90 deg + alpha_g + alpha_p), cannot
    // move it: the disc only settles into the contact (10.09 mm for a 10 mm disc at 0.95 of
    // that push) and a jam read there is the push's weakness, not a jam.
    if params.drive.mode == Drive::Force
        && scene.force_n <= crate::statics::least_push_n(scene)
        && matches!(out.status, JamStatus::Jams | JamStatus::JammedAtStart)
    {
        out.status = JamStatus::TooWeak;
        out.theta_jam_deg = None;
        out.x_jam_mm = None;
    }
    Ok(out)
}

/// A push that starts above 90 deg: the palm's face leans over the disc and its normal push
/// points upwards, so it can lift the disc (the regularised contact lifts it at once at 120 deg
/// with mu = 1, and a 1e6 kg disc at 179.999 deg), which no model here represents. Said before
/// any step is taken: with rigid contacts lifting and sliding along the ground can both obey the
/// contact laws there (Painleve), and the nonsmooth method's choice depends on its step (at
/// 120 deg and mu = 1 it lifts the disc at 0.01 deg but slides it to a lock-up at 90 deg at
/// 0.1 deg).
fn lifted_at_start(scene: &SceneParams, params: &DynamicsParams) -> DynamicsSolution {
    let c = CrossCheck::LiftsOff {
        theta_deg: scene.start_angle_deg,
    };
    before_any_step(params, c.status(), Some(c))
}

/// The answer `status` said before any step is taken, with the cross-check that says why.
fn before_any_step(
    params: &DynamicsParams,
    status: JamStatus,
    cross_check: Option<CrossCheck>,
) -> DynamicsSolution {
    DynamicsSolution {
        status,
        theta_jam_deg: None,
        x_jam_mm: None,
        t_jam_s: None,
        x_stiction_mm: None,
        t_stiction_s: None,
        x_half_speed_mm: None,
        t_half_speed_s: None,
        x_rigid_mm: None,
        method: params.integrator.method,
        drive: params.drive.mode,
        steps: 0,
        rejected_steps: 0,
        rhs_evals: 0,
        jacobian_evals: 0,
        x_jam_error_mm: None,
        discarded_candidates: 0,
        cross_check,
        failure: None,
        simulated_s: 0.0,
        lock_up: None,
        disc_motion: None,
        palm_lost_disc: false,
        x_jam_rigid_mm: None,
        model_uncertainty_mm: None,
        physical_until_s: None,
        jam_resolution_mm: None,
        series: Vec::new(),
    }
}

/// [`simulate`] once validated: the run, then its cross-checks and verification.
fn simulate_checked(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> DynamicsSolution {
    let mut out = run::run_once(scene, params, series_dt_s);
    let nonsmooth = params.integrator.method == Method::Nonsmooth;
    if params.integrator.rtol > LOOSEST_RTOL && !nonsmooth {
        out.cross_check = Some(CrossCheck::LooseTolerance {
            rtol: params.integrator.rtol,
            loosest: LOOSEST_RTOL,
        });
        out.status = JamStatus::Inaccurate;
        return out;
    }
    // Nothing to verify when the run failed or already failed a cross-check.
    if !params.verification.verify
        || out.status == JamStatus::IntegratorFailed
        || out.cross_check.is_some()
    {
        return out;
    }
    // The time after the jam changes neither the status nor x_jam: the check stops at the jam.
    let fine = if nonsmooth {
        let mut fine = *params;
        // Twice the step: the method is of first order, so |x(h) - x(2h)| estimates the
        // error of x(h), at half the cost of a run at half the step.
        fine.integrator.nonsmooth_step_deg = Some((2.0 * params.nonsmooth_step_deg()).min(1.0));
        fine.series.after_jam_s = 0.0;
        fine
    } else {
        let mut fine = *params;
        fine.integrator.rtol = params.integrator.rtol / 10.0;
        fine.integrator.atol = Some(params.atol() / 10.0);
        fine.series.after_jam_s = 0.0;
        fine
    };
    let refinement = if nonsmooth {
        Refinement::Step {
            step_deg: fine.nonsmooth_step_deg(),
        }
    } else {
        Refinement::Tolerance {
            rtol: fine.integrator.rtol,
        }
    };
    let check = run::run_once(scene, &fine, None);
    out.steps += check.steps;
    out.rejected_steps += check.rejected_steps;
    out.rhs_evals += check.rhs_evals;
    out.jacobian_evals += check.jacobian_evals;
    let reason = match (out.x_jam_mm, check.x_jam_mm) {
        _ if check.status != out.status => Some(CrossCheck::VerificationDisagrees {
            check: refinement,
            status: out.status,
            check_status: check.status,
        }),
        (Some(a), Some(b)) => {
            // The nonsmooth jam is located inside a step: it can lie anywhere in the bracket it
            // was located to, whatever the second run says.
            let e = (a - b).abs().max(out.jam_resolution_mm.unwrap_or(0.0));
            out.x_jam_error_mm = Some(e);
            (e > params.verification.max_jam_error * b.abs()).then_some(CrossCheck::ErrorEstimate {
                error_mm: e,
                allowed_rel: params.verification.max_jam_error,
                check: refinement,
            })
        }
        _ => None,
    };
    if let Some(r) = reason {
        out.cross_check = Some(r);
        out.status = JamStatus::Inaccurate;
        return out;
    }
    if !nonsmooth {
        compare_with_rigid(scene, params, &mut out);
    }
    out
}

/// Runs the rigid contact (the nonsmooth method) on the same scene and drive, reports the
/// distance of the two jams as the model's uncertainty, and gives an honest verdict where the
/// compliant contact is not to be believed: the palm lifts the disc, knocks it ahead, or the
/// contact's compliance sets the answer.
fn compare_with_rigid(scene: &SceneParams, params: &DynamicsParams, out: &mut DynamicsSolution) {
    let rigid = run::run_once(
        scene,
        &DynamicsParams {
            integrator: crate::dynamics::IntegratorSettings {
                method: Method::Nonsmooth,
                disc: crate::dynamics::DiscMotion::Slides,
                ..params.integrator
            },
            series: crate::dynamics::SeriesSettings { after_jam_s: 0.0 },
            ..*params
        },
        None,
    );
    if let Some(c) = rigid
        .cross_check
        .filter(|c| matches!(c, CrossCheck::LiftsOff { .. }))
    {
        out.cross_check = Some(c);
        out.status = c.status();
        return;
    }
    // Where the two contacts answer differently (a status of their own, not a failure), the
    // compliant answer is flagged: skipping the check there let a disc read as never moving
    // stand against a rigid disc pushed on to the lock-up.
    let answers = |s: JamStatus| {
        matches!(
            s,
            JamStatus::Jams
                | JamStatus::JammedAtStart
                | JamStatus::NeverJams
                | JamStatus::BeyondReach
        )
    };
    let leaves = |s: JamStatus| matches!(s, JamStatus::NeverJams | JamStatus::BeyondReach);
    if answers(rigid.status)
        && answers(out.status)
        && rigid.status != out.status
        && !(leaves(rigid.status) && leaves(out.status))
    {
        let c = CrossCheck::RigidDisagrees {
            status: out.status,
            x_jam_mm: out.x_jam_mm,
            rigid_status: rigid.status,
            x_jam_rigid_mm: rigid.x_jam_mm,
        };
        out.x_jam_rigid_mm = rigid.x_jam_mm;
        out.cross_check = Some(c);
        out.status = c.status();
        return;
    }
    let (Some(x), Some(xr)) = (out.x_jam_mm, rigid.x_jam_mm) else {
        return;
    };
    if rigid.status != JamStatus::Jams || out.status != JamStatus::Jams {
        return;
    }
    out.x_jam_rigid_mm = Some(xr);
    out.model_uncertainty_mm = Some((x - xr).abs());
    if (x - xr).abs() <= MAX_MODEL_SPREAD * xr
        && !(out.palm_lost_disc && (x - xr).abs() > KNOCKED_SPREAD * xr)
    {
        return;
    }
    let c = if out.palm_lost_disc && (x - xr).abs() > KNOCKED_SPREAD * xr {
        CrossCheck::KnockedAhead {
            x_jam_mm: x,
            x_jam_rigid_mm: xr,
        }
    } else {
        CrossCheck::ContactModelDependent {
            x_jam_mm: x,
            x_jam_rigid_mm: xr,
            allowed_rel: MAX_MODEL_SPREAD,
        }
    };
    out.cross_check = Some(c);
    out.status = c.status();
}
