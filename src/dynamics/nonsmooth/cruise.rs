//! Cruising: one long step in place of [`CRUISE_STEPS`] steps while the palm pushes the disc
//! steadily along the ground.
//!
//! While both contacts are closed, the ground contact slides, the disc only slides (its rotation
//! locked) and the drive runs, the step's answer does not depend on the disc's velocity before
//! it: the two gap conditions U_N + g / dt = 0 fix x_dot and y_dot, and the palm turns at omega.
//! The disc is slaved to the palm, so a longer step there changes nothing that the next step
//! does not give back: the disc lags its touching position by the second order of the step
//! (2e-4 mm for a 1 deg step at mu = 0.2), and the next short step closes that lag with its own
//! geometry; what is left is of the order of the short step times that lag. Where something
//! happens (the disc sticks, lifts, leaves the palm, the push nears the drive's limit, grows
//! towards the lock-up, or the contact nears the palm's end) the run takes its own step: a
//! cruise is kept only when its answer has the same contact modes, the push changed by less
//! than [`PUSH_CHANGE`] over it, a force-limited push stays below [`LIMIT_SHARE`] of its limit,
//! the palm stays [`WEDGE_CRUISES`] cruises short of the self-locking wedge (the sum of the
//! friction angles, static or dynamic, whichever is larger) and the contact stays on the palm a
//! cruise longer. A cruise spans a whole number of steps, so the steps after
//! it lie on the same grid of palm angles as without it.
//!
//! Measured by `cruising_keeps_the_answers` (tests of the nonsmooth module): over mu 0.1-0.8,
//! F 20-2000 N and both drives the status is the same and x_jam moves by at most the figure the
//! test prints, while the steps fall 3-8 fold.

use super::step::{Built, ContactMode, DriveMode, LIFT_MM, Modes, StepSolution, Stepper};

/// Steps per cruise: 1 deg of palm turn at the motion drive's 0.1 deg step, 0.1 deg at the
/// force drive's 0.01 deg.
pub(super) const CRUISE_STEPS: u32 = 10;

/// Largest relative change of the palm's push over a cruise, at the rate it changed over the
/// last step: the push grows as 1 / D towards the self-locking wedge (D the wedge's margin),
/// so cruising ends about ten cruises before it.
const PUSH_CHANGE: f64 = 0.1;

/// Cruises that must fit between a cruise's end and the self-locking wedge. The push read at
/// a cruise's start carries the disc's acceleration over the cruise, not over a step, so near
/// the wedge it is no guide: a cruise 1.7 deg before the wedge (mu = 0.2, 1 deg cruises) read
/// a push 1 % below the step's before it and sent the disc ahead of the palm for 7 steps.
const WEDGE_CRUISES: f64 = 10.0;

/// Largest share of the drive's limit the push may reach at a cruise's end: the force drive
/// stalls at its limit, and the steps towards it are its own.
const LIMIT_SHARE: f64 = 0.5;

/// Steady steps needed before a cruise, and steps waited after a cruise is refused.
const SETTLE_STEPS: u32 = 2;

/// The state of cruising in one run.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cruise {
    /// The stepper with the cruise's step.
    pub stepper: Stepper,
    /// The palm's length in mm: a cruise stays on the palm.
    palm_length_mm: f64,
    /// Steps to wait before the next try.
    wait: u32,
    /// The length in s of the last step taken (a step or a cruise).
    last_dt: f64,
    /// The self-locking wedge's angle in rad with the larger of each contact's frictions.
    wedge_rad: f64,
}

/// Whether the modes are a steady push: the ground slides, the palm touches, the drive runs.
fn steady(modes: Modes) -> bool {
    let (ground, palm, drive) = modes;
    matches!(
        ground,
        ContactMode::SlidePositive | ContactMode::SlideNegative
    ) && palm != ContactMode::Open
        && drive == DriveMode::Runs
}

impl Cruise {
    /// Cruising for the run by `st`, when the disc only slides (a rolling disc's spin is not
    /// slaved to the palm while the ground slides).
    pub fn new(st: &Stepper, palm_length_mm: f64) -> Option<Cruise> {
        (st.inv_mass[2] == 0.0).then(|| {
            let k = f64::from(CRUISE_STEPS);
            Cruise {
                stepper: Stepper {
                    dt: k * st.dt,
                    push_limit: k * st.push_limit,
                    ..*st
                },
                palm_length_mm,
                wait: SETTLE_STEPS,
                last_dt: st.dt,
                wedge_rad: (0..2).map(|k| st.mu[k].max(st.mu_static[k]).atan()).sum(),
            }
        })
    }

    /// Counts a step taken by the run: a steady step brings the next cruise closer.
    pub fn after_step(&mut self, modes: Modes, lifts: bool) {
        self.last_dt = self.stepper.dt / f64::from(CRUISE_STEPS);
        if steady(modes) && !lifts {
            self.wait = self.wait.saturating_sub(1);
        } else {
            self.wait = SETTLE_STEPS;
        }
    }

    /// Tries a cruise from (q, v, theta) in the modes of the last step, whose push was
    /// `push_n` (N). Returns its problem and answer when it is kept, None (and waits a cruise's
    /// length before the next try) otherwise. `tries` counts the step problems solved.
    pub fn try_step(
        &mut self,
        q: &[f64; 3],
        v: &[f64; 3],
        theta: f64,
        modes: Modes,
        push_n: f64,
        tries: &mut u64,
    ) -> Option<(Built, StepSolution)> {
        if self.wait > 0 || !steady(modes) || push_n <= 0.0 {
            return None;
        }
        let st = &self.stepper;
        let built = st.build(q, v, theta);
        *tries += 1;
        let kept = built.problem.try_modes(modes).filter(|sol| {
            let v_end = st.velocities(&built, &sol.impulse);
            let push = sol.impulse[2] * 1e-3 / st.dt;
            let theta_end = theta + st.dt * sol.theta_dot;
            let (s, c) = theta_end.sin_cos();
            let reach = (q[0] + st.dt * v_end[0]) * c + (q[1] + st.dt * v_end[1]) * s;
            // A cruise's end lags by its own second order: the palm's end is met a cruise
            // later, after the steps that give that back.
            let reach_next = 2.0 * reach - built.contact_distance;
            // Both pushes are read with the geometry at their steps' starts: the change
            // since the last step, at its rate, over the cruise's length.
            let change = (push - push_n).abs() * st.dt / self.last_dt;
            built.gaps[0] + st.dt * v_end[1] <= LIFT_MM
                && change <= PUSH_CHANGE * push_n
                && sol.impulse[2] <= LIMIT_SHARE * st.push_limit
                && theta_end - self.wedge_rad >= WEDGE_CRUISES * (theta - theta_end)
                && reach_next <= self.palm_length_mm
        });
        if kept.is_none() {
            self.wait = CRUISE_STEPS;
        } else {
            self.last_dt = st.dt;
        }
        kept.map(|sol| (built, sol))
    }
}
