//! One integration of the scene to the jam, and its reading and quasi-static cross-checks.

use super::held;
use super::integrators::Failure;
use super::integrators::{Dopri5, Outcome, Radau5, Stats, Tolerances};
use super::jam::{JamDetector, JamRule, rest_speed_mm_s};
use super::nonsmooth::{self, End};
use super::system::System;
use super::{
    CrossCheck, Drive, DynamicsParams, DynamicsSolution, MAX_STEP_DEG, Method, WEDGE_MARGIN,
};
use crate::dynamics::MM_PER_M;
use crate::scene::{JamStatus, SceneParams};

/// One run at the given tolerances, without the verification run. Parameters must be valid.
pub(super) fn run_once(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> DynamicsSolution {
    if params.integrator.method == Method::Nonsmooth {
        return run_nonsmooth(scene, params, series_dt_s);
    }
    let sys = System::new(scene, params);
    let theta0 = scene.start_angle_deg.to_radians();
    let mut y = [theta0, sys.touching_x(theta0), 0.0];
    let t_end = theta0 / sys.omega;
    let tol = Tolerances {
        rtol: params.integrator.rtol,
        atol: params.atol(),
        max_step: MAX_STEP_DEG.to_radians() / sys.omega,
        max_steps: params.integrator.max_steps,
    };
    let rule = JamRule {
        jam_ratio: params.jam_reading.jam_speed_ratio,
        arm_ratio: params.jam_reading.arm_speed_ratio,
        v_stiction: params.friction.stiction_velocity_mm_s,
        palm_length: scene.palm_length_mm,
        after_jam: params.series.after_jam_s,
        ground_decel: scene.mu_ground * scene.gravity_m_s2 * MM_PER_M,
        series_dt: series_dt_s.filter(|dt| *dt > 0.0 && dt.is_finite()),
        rest_speed: (params.drive.mode == Drive::Force)
            .then(|| rest_speed_mm_s(params.friction.friction_velocity_mm_s)),
    };
    let mut det = JamDetector::new(&sys, rule, 0.0);
    let (outcome, stats) = match params.integrator.method {
        Method::Radau5 => Radau5.integrate(&sys, 0.0, &mut y, t_end, &tol, &mut det),
        Method::Dopri5 => Dopri5.integrate(&sys, 0.0, &mut y, t_end, &tol, &mut det),
        Method::Nonsmooth => unreachable!("dispatched above"),
    };
    conclude(scene, params, &sys, det, outcome, stats)
}

fn conclude(
    scene: &SceneParams,
    params: &DynamicsParams,
    sys: &System,
    det: JamDetector,
    outcome: Outcome,
    stats: Stats,
) -> DynamicsSolution {
    let wedge = scene.alpha_ground() + scene.alpha_palm();
    let x_rigid = (wedge > 0.0)
        .then(|| sys.touching_x(wedge))
        .filter(|x| x.is_finite());
    let (failure, simulated) = match &outcome {
        Outcome::Failed(f) => (Some(*f), f.t_s()),
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
        x_half_speed_mm: None,
        t_half_speed_s: None,
        x_rigid_mm: x_rigid,
        method: params.integrator.method,
        drive: params.drive.mode,
        steps: stats.steps,
        rejected_steps: stats.rejected,
        rhs_evals: stats.rhs_evals,
        jacobian_evals: stats.jacobian_evals,
        discarded_candidates: det.discarded,
        cross_check: None,
        x_jam_error_mm: None,
        failure,
        simulated_s: simulated,
        lock_up: None,
        disc_motion: None,
        palm_lost_disc: det.separated,
        x_jam_rigid_mm: None,
        model_uncertainty_mm: None,
        physical_until_s: None,
        jam_resolution_mm: None,
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
            // The disc never reached the palm's speed: the push could not get it going (a
            // force-driven run stops as soon as the stalled palm holds it for good, `held`).
            out.theta_jam_deg = Some(scene.start_angle_deg);
            out.x_jam_mm = Some(sys.touching_x(scene.start_angle_deg.to_radians()));
            out.t_jam_s = Some(0.0);
            JamStatus::JammedAtStart
        } else {
            JamStatus::NeverJams
        };
        return out;
    };
    // The force drive's jam is where the disc comes to rest; the speed collapse read before it
    // is where the stalled palm let the disc coast (kept as the half-speed reading).
    let rest = match params.drive.mode {
        Drive::Force => {
            out.x_half_speed_mm = Some(jam.x);
            out.t_half_speed_s = Some(jam.t);
            det.rest
        }
        Drive::Motion => Some(jam),
    };
    let at = rest.unwrap_or(jam);
    out.theta_jam_deg = Some(at.theta.to_degrees());
    out.x_jam_mm = Some(at.x);
    out.t_jam_s = Some(at.t);
    // A motion-driven palm against a jammed disc is a lock-up: a real palm stops there.
    if params.drive.mode == Drive::Motion {
        out.physical_until_s = Some(jam.t);
    }
    // A disc reaching the wedge at the palm's speed v_geo coasts on, braked by the ground, for
    // up to v_geo^2 / (2 mu_g g): 0.05 mm at mu = 0.4, 36 mm at mu = 0.1 (omega = 30 deg/s).
    let decel = scene.mu_ground * scene.gravity_m_s2 * MM_PER_M;
    let coast = if decel > 0.0 {
        sys.geometric_speed(wedge).powi(2) / (2.0 * decel)
    } else {
        f64::INFINITY
    };
    if rest.is_none() {
        out.cross_check = Some(CrossCheck::NotAtRest {
            x_half_speed_mm: jam.x,
            simulated_s: simulated,
            rest_speed_mm_s: rest_speed_mm_s(params.friction.friction_velocity_mm_s),
        });
    }
    if let Some(xw) = x_rigid
        && at.x > xw * (1.0 + WEDGE_MARGIN) + coast
    {
        out.cross_check = Some(CrossCheck::PastWedge {
            x_jam_mm: at.x,
            x_rigid_mm: xw,
            coast_mm: coast,
            geometric_speed_mm_s: sys.geometric_speed(wedge),
            stiction_velocity_mm_s: params.friction.stiction_velocity_mm_s,
        });
    }
    let stalled = det.push_after_jam >= (1.0 - 2.0 * params.drive.force_band) * sys.normal_limit;
    if params.drive.mode == Drive::Force && jam.theta > wedge + 0.1_f64.to_radians() && !stalled {
        out.cross_check = Some(CrossCheck::StoppedBelowForceLimit {
            theta_deg: jam.theta.to_degrees(),
            push_n: det.push_after_jam,
            limit_n: sys.normal_limit,
        });
    }
    if let Some((theta, push)) = det.at_confirmation {
        // Against the static frictions: the disc stands still.
        let (g, p) = (sys.ground_friction.mu_static, sys.palm_friction.mu_static);
        let needed = held::sliding_push_n(sys.weight, g, p, theta);
        if push > 2.0 * needed {
            out.cross_check = Some(CrossCheck::HeldBelowSlidingPush {
                x_jam_mm: at.x,
                theta_deg: theta.to_degrees(),
                push_n: push,
                needed_n: needed,
                geometric_speed_mm_s: sys.geometric_speed(jam.theta),
                stiction_velocity_mm_s: params.friction.stiction_velocity_mm_s,
            });
        }
    }
    if let Some(c) = &out.cross_check {
        out.status = c.status();
    }
    out
}

/// One nonsmooth run read as a solution: a lock-up (motion drive) or the disc and palm at rest
/// (force drive) is the jam.
fn run_nonsmooth(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
) -> DynamicsSolution {
    let sys = System::new(scene, params);
    let wedge = scene.alpha_ground() + scene.alpha_palm();
    let x_rigid = (wedge > 0.0)
        .then(|| sys.touching_x(wedge))
        .filter(|x| x.is_finite());
    let run = nonsmooth::run(scene, params, series_dt_s);
    let mut out = DynamicsSolution {
        status: JamStatus::Jams,
        theta_jam_deg: None,
        x_jam_mm: None,
        t_jam_s: None,
        x_stiction_mm: None,
        t_stiction_s: None,
        x_half_speed_mm: None,
        t_half_speed_s: None,
        x_rigid_mm: x_rigid,
        method: params.integrator.method,
        drive: params.drive.mode,
        steps: run.steps,
        rejected_steps: 0,
        rhs_evals: run.mode_solves,
        jacobian_evals: 0,
        x_jam_error_mm: None,
        discarded_candidates: 0,
        cross_check: None,
        failure: None,
        simulated_s: run.simulated_s,
        lock_up: None,
        disc_motion: Some(run.tally),
        palm_lost_disc: run.knocked_ahead,
        x_jam_rigid_mm: None,
        model_uncertainty_mm: None,
        physical_until_s: None,
        jam_resolution_mm: None,
        series: run.series,
    };
    let (t, theta, x) = match run.end {
        End::LockUp(l) => {
            out.lock_up = Some(l);
            (l.t_s, l.theta_deg.to_radians(), l.x_mm)
        }
        End::AtRest { t, theta, x } => (t, theta, x),
        End::BeyondReach { .. } => {
            out.status = JamStatus::BeyondReach;
            return out;
        }
        End::PalmClosed => {
            out.status = JamStatus::NeverJams;
            return out;
        }
        End::NoSolution { t } | End::StepLimit { t } => {
            out.failure = Some(match run.end {
                End::StepLimit { .. } => Failure::StepLimit {
                    t_s: t,
                    steps: params.integrator.max_steps,
                },
                _ => Failure::NoConsistentContact { t_s: t },
            });
            out.status = JamStatus::IntegratorFailed;
            return out;
        }
    };
    out.theta_jam_deg = Some(theta.to_degrees());
    out.x_jam_mm = Some(x);
    out.t_jam_s = Some(t);
    out.jam_resolution_mm = Some(run.jam_resolution_mm);
    if let Some(theta_deg) = run.lift_off_deg
        && params.integrator.disc == crate::dynamics::DiscMotion::Slides
    {
        let c = CrossCheck::LiftsOff { theta_deg };
        out.cross_check = Some(c);
        out.status = c.status();
        return out;
    }
    // Held where it started: the jam is at the start (as the regularised model's "never armed").
    // A disc that moved by round-off, or (motion drive) by no more than the lock-up is located
    // to, did not move (`jams` at 10.0000 mm where nothing moved). A force
    // drive's first step or two of travel is kept: it halves with the step.
    let x_start = sys.touching_x(scene.start_angle_deg.to_radians());
    let moved_mm = (x - x_start).abs();
    let still = moved_mm <= 1e-12 * x_start.abs().max(1.0)
        || (out.lock_up.is_some() && moved_mm <= run.jam_resolution_mm);
    if !run.moved || still {
        out.status = JamStatus::JammedAtStart;
    }
    out
}

fn sys_end(scene: &SceneParams, sys: &System) -> f64 {
    scene.start_angle_deg.to_radians() / sys.omega
}
