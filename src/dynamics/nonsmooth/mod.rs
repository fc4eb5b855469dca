//! The nonsmooth method: rigid unilateral contacts with exact Coulomb friction, time-stepped at
//! the velocity-impulse level (Moreau-Jean; Stewart-Trinkle's form of the gap condition).
//!
//! # Formulation
//!
//! The disc's configuration is q = (x, y, phi) (centre in mm, rotation in rad, counter-clockwise)
//! with generalised velocity v = (x_dot, y_dot, phi_dot) and mass matrix M = diag(m, m, I),
//! I = m r^2 / 2 (a solid disc). [`crate::dynamics::DiscMotion::Slides`] is the paper's translational joint:
//! phi is locked (I^-1 = 0), so the ground's friction, not a rotation, takes the palm's moment;
//! [`crate::dynamics::DiscMotion::Rolls`] lets the disc turn. With the palm's normal n = (sin theta, -cos theta)
//! and direction t = (cos theta, sin theta), the gaps and relative velocities (disc minus
//! support, mm and mm/s) are
//!
//! ```text
//! ground A:  g_A = y - r                       U_NA = y_dot     U_TA = x_dot + r phi_dot
//! palm B:    g_B = x sin t - y cos t - r - h   U_NB = v_c . n + s_B theta_dot
//!                                              U_TB = v_c . t - r phi_dot - h theta_dot
//! ```
//!
//! with s_B = x cos theta + y sin theta the contact's distance from the hinge and h the palm's
//! offset. In matrix form U = J v + c theta_dot. One step of length dt from (q, v, theta):
//!
//! ```text
//! M (v+ - v) = dt f_ext + J^T P               f_ext = (0, -m g, 0), P the contact impulses
//! 0 <= P_N  _|_  U_N+ + g / dt >= 0           Signorini at the velocity level, per contact
//! P_T in -mu P_N sign(U_T+)                   exact Coulomb (|P_T| <= mu_s P_N when U_T+ = 0)
//! q+ = q + dt v+,  theta+ = theta + dt theta_dot
//! ```
//!
//! The gap term g/dt makes the contact close exactly at the end of the step (Stewart-Trinkle)
//! instead of letting a drift in the gap accumulate. theta_dot is -omega for the motion drive; the
//! force drive adds the law of a self-locking drive with a limit N_max = F cos(atan mu_palm) on
//! its normal push: theta_dot = -omega below the limit, in [-omega, 0] at it, 0 above it (the
//! drive holds); when none of these is consistent (a rolling disc coming to rest in the wedge
//! would, at the limit, turn the palm back) the drive stops below its limit rather than back
//! off (`step::DriveMode::Stalls`). Each step's problem is small (five unknowns) and solved exactly by enumerating
//! the contact modes (`step`): no relaxation of the friction cone, so a sliding contact does
//! not separate (the artefact of Anitescu's convex relaxation, which makes a contact sliding at
//! speed u_T open at mu u_T, is absent). The test `the_step_is_a_fixed_point_of_clarabels_tresca_problem`
//! checks each step against clarabel: with the friction bounds fixed at mu times the normal
//! impulses found, the step's velocities minimise the kinetic energy under the contact
//! constraints (the Tresca problem, a convex QP), and clarabel finds the same velocities.
//!
//! # Restitution
//!
//! Newton's coefficient is 0: an impact is plastic, the contact closes and stays closed while it
//! pushes. A disc in a palm's grip is in sustained contact, where any e > 0 would only add
//! chatter; a real gripper's impacts at 30 deg/s are slow and well damped. A regularised model
//! with a stiff, lightly damped contact bounces instead, so the two methods disagree where a fast
//! palm knocks the disc ahead (see the module docs of [`crate::dynamics`]).
//!
//! # The jam
//!
//! Exact Coulomb friction has true stiction: a held disc does not move, to round-off. With the
//! motion drive the palm must turn whatever the load; past the self-locking wedge no impulse can
//! both keep the palm out of the disc and obey the friction laws, so the step problem has no
//! solution: a lock-up, the rigid model's jam (the push needed grows without bound). Whether a
//! step from a given state has a solution depends on the palm angle at its start (the push's
//! forward component net of the ground's friction changes sign at the wedge), so the lock-up is
//! located inside the step where it happens: the state moves along the last step that turned,
//! and a bisection on the fraction of that step (16 halvings, 1.5e-5 of a step) finds where the
//! next step stops having a solution. It is reported as the jam at the disc's position there,
//! with the push of the last full step ([`LockUp::push_n`]), which grows as the step shrinks (it
//! is about mu_g m g / D with D the wedge's margin at the last step). With the force drive the
//! palm stalls at its limit and holds; the jam is the first step in which the disc and the palm
//! are both at rest, and it lasts: it is read at that step's start, within the disc's travel in
//! the step before (reported as `jam_resolution_mm`, part of the error estimate).
//!
//! # Step and accuracy
//!
//! The default step is 0.1 deg of palm turn with the motion drive and 0.01 deg with the force
//! drive ([`crate::dynamics::params::MOTION_STEP_DEG`], `FORCE_STEP_DEG`). Motion drive, 30 deg/s,
//! (x_jam - r/mu) / (r/mu) (the lock-up located inside its step; before, read at a step end, it lay up to a
//! step's travel past r/mu, +9e-5 ... +2.7e-4 at 0.01 deg):
//!
//! ```text
//! step      mu = 0.15   0.3        0.45       steps (mu 0.15)
//! 0.3 deg   -2.7e-4     -6.4e-5    -3.0e-5      244
//! 0.1 deg   -2.6e-5     -9.0e-6    -3.4e-6      730
//! 0.01 deg  -3.0e-7     -8.0e-8    -3.2e-8     7294
//! ```
//!
//! (printed by the test `the_step_table_of_the_module_docs`; run times are measured by
//! `jamchart accuracy`, not quoted here)
//!
//! The steps in the table are the plain run's: without a time series a run cruises
//! (`cruise`: 10 steps in one while the push is steady, up to 1 deg of palm turn in one far
//! from the wedge and the drive's limit), which on the design map's cases (mu 0.1-0.8, F 20-2000
//! N) takes 17 times fewer steps with the force drive (up to 37 times a run) and 4.9 times fewer
//! with the motion drive (2.0-5.8 times a run), and moves no jam by more than round-off (3e-13
//! of itself; `cruising_keeps_the_answers`, which prints the figures).
//!
//! The error is of second order in the step: each step closes the palm's gap with the geometry
//! of its start, so at its end the palm has turned into the disc by the second order of the
//! step, and the disc lags its touching position by that much. Verification runs at twice the
//! step; the difference (about three times the error) bounds it. The force drive's rest is not
//! located inside its step: at 30 deg/s 0.1 deg is within 7.8e-5 of 0.01 deg, but a slow push
//! (0.5 deg/s) lands up to 0.26 % off at 0.1 deg, hence its finer default (mu 0.2-0.4, F 50
//! and 200 N; `the_step_figures_of_the_nonsmooth_docs` prints them).
//!
//! # The disc free to roll
//!
//! With [`crate::dynamics::DiscMotion::Rolls`] the palm's friction turns the disc, and a rolling disc's moment
//! balance makes the ground's and the palm's friction forces equal in size. The ground, pressed
//! by the weight and the push, holds first; the palm contact reaches its cone where
//! tan(theta/2) = mu_p; and the disc locks up where tan(theta/2) = min(mu_p, mu_g (1 + m g / N))
//! (the min-norm rolling formulation), i.e. at r / min(mu_g, mu_p) with the motion drive's
//! unbounded push. Measured at the defaults (motion drive, 30 deg/s, step 0.1 deg; printed by
//! `the_rolling_table_of_the_nonsmooth_docs` in `tests/dynamics_nonsmooth.rs`):
//!
//! ```text
//! mu_g / mu_p   slides (translational)     rolls
//! 0.15 / 0.15   66.665 mm                  66.665 mm, rolls (ground sticks) all the way
//! 0.25 ... 0.45 r/mu within 1.1e-5         the same, rolls all the way
//! 0.2 / 0.6     25.866 mm = r cot((a_g + a_p)/2)   49.999 mm: rolls while 0.6 N_B <= 0.2 N_A,
//!                                                  then slips on the ground, spinning
//! 0.6 / 0.2     25.866 mm                  49.999 mm, rolls all the way
//! ```
//!
//! So with equal frictions rolling changes nothing (the disc rolls instead of sliding, which is
//! what a real gripper sees, and jams at the same r/mu), while with unequal frictions the
//! translational joint, which takes the palm's moment, makes the disc jam at half the distance:
//! the sum of the friction angles counts for a disc that cannot turn, the smaller one for a disc
//! that can. With the force drive at 0.5 deg/s and F = 200 N the rolling disc jams within 0.072 %
//! of the min-norm rolling answer (25.006 / 47.326 / 50.036 mm against 25.000 / 47.296 /
//! 50.000 mm for 0.4/0.4, 0.2/0.6, 0.6/0.2).
//!
//! # Against the regularised model in the stiff limit
//!
//! With the motion drive both methods lock up at r/mu (`nonsmooth_and_stiff_regularised_agree`).
//! With the force drive both report where the disc comes to rest (the
//! regularised model used to read the jam at the speed collapse, while the disc, let go by the
//! stalled palm, still coasted, 1.5-1.7 % short at mu = 0.15 and 30 deg/s). The nonsmooth rest
//! lies within 4.8e-6 of an independent rigid model over mu 0.15-0.45, F 50-1000 N, 10-90 deg/s
//! (`nonsmooth_force_drive_rests_where_the_rigid_ode_does`). With a 1 um contact at rtol 1e-8
//! RADAU5's rest agrees with the nonsmooth one within 0.020-0.031 % at mu 0.15 (10, 30,
//! 90 deg/s), mu 0.3 (90 deg/s) and mu 0.45 (30 deg/s), where its half-speed reading lies up to
//! 3.9 % short (`force_drive_agrees_with_the_stiff_regularised_disc_where_it_stops` prints
//! them). At the default contact (59 um at 200 N) RADAU5 rests 0.25-1.04 % short of the rigid
//! rest: the contact's give (`regularised_force_drive_rest_against_the_rigid_ode`).
//!
//! # Known artefacts
//!
//! * The geometry (n, t, s_B, the gaps) is taken at the start of each step: the palm ends each
//!   step inside the disc by the second order of the step (2e-6 mm at 0.1 deg and mu = 0.2), and
//!   the next step gives that back. A palm at its force limit may therefore turn back by the
//!   speed that closes that penetration over a step (with only round-off allowed, a disc coasting
//!   into the wedge at 30 deg/s and 0.05-0.5 deg steps had no consistent mode: the run failed).
//! * Contact is decided per step: a disc knocked ahead flies for whole steps; the palm catches
//!   it at a step end.
//! * Coulomb's law with a rigid body can have several consistent answers (Painleve); the first
//!   consistent mode wins, the previous step's tried first, so the choice is deterministic.

mod cruise;
pub(crate) mod step;

use serde::Serialize;

use self::cruise::{Cruise, Pace};
use self::step::{ContactMode, DriveMode, LIFT_MM, Modes, Stepper};
use super::jam::SeriesRow;
use super::{Drive, DynamicsParams};
use crate::scene::SceneParams;

/// Speed (mm/s, and rad/s for the rotation) below which the disc is at rest: the speeds that
/// close gaps of round-off size (1e-11 mm) over a step are around 1e-7 mm/s.
const REST_MM_S: f64 = 1e-6;

/// A lock-up: the motion-driven palm cannot turn any further without entering the disc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LockUp {
    /// Time in s.
    pub t_s: f64,
    /// Palm angle in deg.
    pub theta_deg: f64,
    /// Disc centre abscissa in mm.
    pub x_mm: f64,
    /// The palm's normal push in the last step before it, in N (grows as the step shrinks).
    pub push_n: f64,
}

/// How the disc moved while the palm touched it, counted in steps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct MotionTally {
    /// Steps with the disc sliding on the ground.
    pub slipping_steps: u64,
    /// Steps with the disc rolling on the ground (no slip at A) while it moves.
    pub rolling_steps: u64,
    /// Steps with the disc off the palm.
    pub free_steps: u64,
    /// Steps with the disc lifted off the ground.
    pub lifted_steps: u64,
}

/// How a nonsmooth run ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum End {
    /// Lock-up (motion drive).
    LockUp(LockUp),
    /// Disc and palm at rest (force drive): (t, theta, x).
    AtRest { t: f64, theta: f64, x: f64 },
    /// The contact passed the palm's end: (t, theta, x).
    BeyondReach { t: f64, theta: f64, x: f64 },
    /// The palm closed to theta = 0 without a jam.
    PalmClosed,
    /// The step problem had no solution although the drive could give way (should not happen).
    NoSolution { t: f64 },
    /// The step limit `max_steps` was reached at time t.
    StepLimit { t: f64 },
}

/// The result of one nonsmooth run.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Run {
    pub end: End,
    /// Time steps taken.
    pub steps: u64,
    /// Choices of contact modes tried (linear solves).
    pub mode_solves: u64,
    pub tally: MotionTally,
    /// Whether the disc moved at all before the end.
    pub moved: bool,
    /// Whether the palm lost the disc after first pushing it (knocked ahead).
    pub knocked_ahead: bool,
    /// Palm angle in deg where the disc first left the ground while the palm touched it.
    pub lift_off_deg: Option<f64>,
    /// The time series (empty unless asked for).
    pub series: Vec<SeriesRow>,
    /// Simulated time in s.
    pub simulated_s: f64,
    /// How finely the jam is located in mm: the lock-up's last bisection bracket, or the disc's
    /// travel in its last moving step before it came to rest (0 without a jam).
    pub jam_resolution_mm: f64,
}

/// The start of the last step solved, with the velocities it gave: a lock-up is located inside
/// it.
#[derive(Debug, Clone, Copy, PartialEq)]
struct LastStep {
    q: [f64; 3],
    v: [f64; 3],
    theta: f64,
    theta_dot: f64,
    t: f64,
}

/// The run before a cruise, kept while the cruise is on trial: with a limit on the drive, the
/// run's step after a cruise must keep the cruise's modes (its push catches up with the disc's
/// acceleration over the cruise, times the cruise's length over its own, and must not stall
/// the palm). A cruise followed by another needs no such step; one followed by the run's step
/// that leaves the modes is taken back, and with it, in turn, each cruise before it that the
/// run's step then leaves in the same way.
#[derive(Debug, Clone, Copy)]
struct OnTrial {
    q: [f64; 3],
    v: [f64; 3],
    theta: f64,
    t: f64,
    last: Option<LastStep>,
    travel: f64,
    last_push: f64,
    slipping_steps: u64,
    steps: u64,
    moved: bool,
    /// Cruising with the cruise's length refused.
    refused: Pace,
}

/// Halvings of the step in which the palm locks up: the lock-up is located to 2^-16 of a step
/// (7e-6 mm at mu = 0.15 and the default 0.1 deg), far below the method's own error.
const LOCATE_HALVINGS: u32 = 16;

/// Runs the push from the start angle with the disc at rest touching the palm and the ground,
/// and on for `after_jam_s` after a force-driven jam (a lock-up ends the run: the rigid palm can
/// turn no further). Parameters must be valid. Cruises (`cruise`) unless a series is asked for,
/// whose samples are taken at step starts.
pub(crate) fn run(scene: &SceneParams, params: &DynamicsParams, series_dt_s: Option<f64>) -> Run {
    let cruises = series_dt_s.is_none_or(|d| !(d > 0.0 && d.is_finite()));
    run_with(scene, params, series_dt_s, cruises)
}

/// [`run`], with or without cruising.
fn run_with(
    scene: &SceneParams,
    params: &DynamicsParams,
    series_dt_s: Option<f64>,
    cruises: bool,
) -> Run {
    let st = Stepper::new(scene, params);
    let mut cruise = Cruise::new(&st, scene.palm_length_mm).filter(|_| cruises);
    let dt = st.dt;
    let r = st.radius;
    let mut theta = scene.start_angle_deg.to_radians();
    let (s0, c0) = theta.sin_cos();
    // Touching both: y = r, x sin - r cos = r + h.
    let mut q = [(r * (1.0 + c0) + st.offset) / s0, r, 0.0];
    let mut v = [0.0; 3];
    let mut modes: Modes = (ContactMode::Stick, ContactMode::Open, DriveMode::Runs);
    let mut out = Run {
        end: End::PalmClosed,
        steps: 0,
        mode_solves: 0,
        tally: MotionTally::default(),
        moved: false,
        knocked_ahead: false,
        lift_off_deg: None,
        series: Vec::new(),
        simulated_s: 0.0,
        jam_resolution_mm: 0.0,
    };
    let series_dt = series_dt_s.filter(|d| *d > 0.0 && d.is_finite());
    let mut next_sample = 0.0;
    let mut t = 0.0;
    let mut last_push = 0.0;
    let mut pushed = false;
    let mut rest: Option<End> = None;
    let mut last: Option<LastStep> = None;
    // The disc's travel in the previous step in mm.
    let mut travel = 0.0;
    // The cruises on trial since the run's last step, the latest last.
    let mut on_trial: Vec<OnTrial> = Vec::new();
    while theta > 0.0 {
        if let Some(End::AtRest { t: t_jam, .. }) = rest
            && t >= t_jam + params.series.after_jam_s
        {
            break;
        }
        if out.steps >= params.integrator.max_steps {
            out.end = End::StepLimit { t };
            break;
        }
        if rest.is_none()
            && let Some(c) = cruise.as_mut()
            && let Some(k) = c.try_step(&q, &v, theta, modes, last_push, &mut out.mode_solves)
        {
            if !k.on_trial {
                // Checked against its next step: the cruises before it are kept.
                on_trial.clear();
            } else {
                on_trial.push(OnTrial {
                    q,
                    v,
                    theta,
                    t,
                    last,
                    travel,
                    last_push,
                    slipping_steps: out.tally.slipping_steps,
                    steps: out.steps,
                    moved: out.moved,
                    refused: k.refused,
                });
            }
            last_push = k.push_n;
            // Counted as the steps it spans, all sliding; a lock-up right after it is located
            // in its last step's length.
            out.tally.slipping_steps += u64::from(k.steps);
            (q, v, theta) = (k.q, k.v, k.theta);
            out.moved |= v[0] != 0.0;
            t += k.dt;
            last = Some(LastStep {
                q: [q[0] - dt * v[0], q[1] - dt * v[1], q[2] - dt * v[2]],
                v,
                theta: theta - dt * k.theta_dot,
                theta_dot: k.theta_dot,
                t: t - dt,
            });
            travel = dt * v[0].abs();
            out.steps += 1;
            continue;
        }
        let built = st.build(&q, &v, theta);
        if rest.is_none() && built.contact_distance > scene.palm_length_mm {
            // The contact left the palm during the last step, unless the palm locked up inside
            // that step before it did: the reach is judged where the lock-up is, not at the
            // end of the step that ran into it (up to a step's travel, 0.24 mm at mu = 0.15).
            let locked = match (params.drive.mode, last) {
                (Drive::Motion, Some(last)) if built.problem.solve(modes).is_none() => {
                    out.mode_solves += 1;
                    let located = locate_lock_up(&st, &last, modes, last_push);
                    out.mode_solves += located.probes;
                    (located.contact_distance_mm <= scene.palm_length_mm).then_some(located)
                }
                _ => None,
            };
            out.end = match locked {
                Some(located) => {
                    out.jam_resolution_mm = located.resolution_mm;
                    End::LockUp(located.lock)
                }
                None => End::BeyondReach { t, theta, x: q[0] },
            };
            break;
        }
        let solved = built.problem.solve(modes);
        if let Some(before) = on_trial.pop() {
            if solved.is_some_and(|s| s.modes == modes) {
                on_trial.clear();
            } else {
                out.mode_solves += 1;
                (q, v, theta, t) = (before.q, before.v, before.theta, before.t);
                (last, travel, last_push) = (before.last, before.travel, before.last_push);
                (out.tally.slipping_steps, out.steps) = (before.slipping_steps, before.steps);
                out.moved = before.moved;
                if let Some(c) = cruise.as_mut() {
                    c.take_back(before.refused);
                }
                continue;
            }
        }
        let Some(sol) = solved else {
            out.end = match (params.drive.mode, last) {
                (Drive::Motion, Some(last)) => {
                    let located = locate_lock_up(&st, &last, modes, last_push);
                    out.mode_solves += located.probes;
                    out.jam_resolution_mm = located.resolution_mm;
                    End::LockUp(located.lock)
                }
                // Locked at the start: the disc is where it started.
                (Drive::Motion, None) => End::LockUp(LockUp {
                    t_s: t,
                    theta_deg: theta.to_degrees(),
                    x_mm: q[0],
                    push_n: last_push,
                }),
                (Drive::Force, _) => End::NoSolution { t },
            };
            break;
        };
        out.mode_solves += 1;
        modes = sol.modes;
        let p = sol.impulse;
        v = st.velocities(&built, &p);
        // kg mm/s per step -> N.
        let to_n = 1e-3 / dt;
        last_push = p[2] * to_n;
        let (ground, palm, drive) = modes;
        // Lifted: the disc leaves the ground by more than round-off over the step (an open
        // ground contact with the palm's friction carrying the weight exactly is not a lift).
        let lifts = built.gaps[0] + dt * v[1] > LIFT_MM;
        if let Some(c) = cruise.as_mut() {
            c.after_step(modes, lifts);
        }
        if palm != ContactMode::Open {
            pushed = true;
            if lifts {
                out.tally.lifted_steps += 1;
                out.lift_off_deg.get_or_insert(theta.to_degrees());
            } else if ground == ContactMode::Stick {
                // Moving faster than rest: a sliding disc held by the ground keeps a velocity of
                // round-off size, which is no roll.
                if v[0].abs() > REST_MM_S {
                    out.tally.rolling_steps += 1;
                }
            } else {
                out.tally.slipping_steps += 1;
            }
        } else if pushed {
            out.tally.free_steps += 1;
            out.knocked_ahead = true;
        }
        if let Some(sdt) = series_dt {
            while next_sample <= t + dt {
                out.series.push(SeriesRow {
                    t_s: next_sample,
                    theta_deg: theta.to_degrees(),
                    x_mm: q[0],
                    x_dot_mm_s: v[0],
                    penetration_mm: -built.gaps[1],
                    normal_n: p[2] * to_n,
                    palm_friction_n: -p[3] * to_n,
                    ground_normal_n: p[0] * to_n,
                    ground_friction_n: p[1] * to_n,
                });
                next_sample += sdt;
            }
        }
        // At rest to round-off: the velocities that close a gap of round-off size (1e-11 mm
        // over a step) are far below 1e-6 mm/s.
        let at_rest =
            v.iter().all(|x| x.abs() <= REST_MM_S) && sol.theta_dot.abs() <= 1e-6 * st.omega;
        if rest.is_none() && drive != DriveMode::Runs && at_rest {
            rest = Some(End::AtRest { t, theta, x: q[0] });
            // It came to rest during the previous step: somewhere within that step's travel.
            out.jam_resolution_mm = travel;
        }
        if v[0] != 0.0 {
            out.moved = true;
        }
        last = Some(LastStep {
            q,
            v,
            theta,
            theta_dot: sol.theta_dot,
            t,
        });
        travel = dt * v[0].abs();
        for k in 0..3 {
            q[k] += dt * v[k];
        }
        theta += dt * sol.theta_dot;
        t += dt;
        out.steps += 1;
    }
    if let Some(end) = rest {
        out.end = end;
    }
    out.simulated_s = t;
    out
}

/// A lock-up located inside the last step solved.
struct Located {
    lock: LockUp,
    /// The bisection bracket's width in mm of the disc's travel.
    resolution_mm: f64,
    /// Step problems solved to locate it.
    probes: u64,
    /// The contact's distance from the hinge at the lock-up, s_B, in mm.
    contact_distance_mm: f64,
}

/// Locates a lock-up inside the last step solved by bisection: the state moves along that step
/// (q + s dt v, theta + s dt theta_dot) and the step problem from there either has a solution
/// (the palm can still turn) or not. The lock-up is the first state found locked.
fn locate_lock_up(st: &Stepper, last: &LastStep, modes: Modes, push_n: f64) -> Located {
    let at = |s: f64| {
        let h = s * st.dt;
        let q = [
            last.q[0] + h * last.v[0],
            last.q[1] + h * last.v[1],
            last.q[2] + h * last.v[2],
        ];
        (q, last.theta + h * last.theta_dot, last.t + h)
    };
    // s = 0 is the last step's start (it turned); s = 1 its end (it did not).
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..LOCATE_HALVINGS {
        let mid = 0.5 * (lo + hi);
        let (q, theta, _) = at(mid);
        if st.build(&q, &last.v, theta).problem.solve(modes).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let (q, theta, t) = at(hi);
    let (s, c) = theta.sin_cos();
    Located {
        lock: LockUp {
            t_s: t,
            theta_deg: theta.to_degrees(),
            x_mm: q[0],
            push_n,
        },
        resolution_mm: (hi - lo) * st.dt * last.v[0].abs(),
        probes: u64::from(LOCATE_HALVINGS),
        contact_distance_mm: q[0] * c + q[1] * s,
    }
}

#[cfg(test)]
mod tests;
