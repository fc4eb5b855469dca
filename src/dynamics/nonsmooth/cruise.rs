//! Cruising: one long step in place of many steps while the palm pushes the disc steadily along
//! the ground.
//!
//! While both contacts are closed, the ground contact slides, the disc only slides (its rotation
//! locked) and the drive runs, the step's answer does not depend on the disc's velocity before
//! it: the two gap conditions U_N + g / dt = 0 fix x_dot and y_dot, and the palm turns at omega.
//! The disc is slaved to the palm, so a longer step there changes nothing that the next step
//! does not give back: the disc lags its touching position by the second order of the step
//! (2e-4 mm for a 1 deg step at mu = 0.2). The disc is moved along the ground out of that lag
//! at the cruise's end ([`Stepper::touch_palm`]); the next step then starts touching, as the
//! run's own steps do to their own second order, and ends where the run without the cruise
//! ends on the same palm angle. Where something happens (the disc sticks, lifts, leaves the
//! palm, the push grows towards the drive's limit or towards the lock-up, or the contact nears
//! the palm's end) the run takes its own step: a cruise is kept only when its answer has the
//! same contact modes, the push changed by less than [`PUSH_CHANGE`] since the cruise before, a
//! force-limited push stays [`LIMIT_CRUISES`] cruises of its growth below its limit and the
//! run's step after the cruise keeps the modes (below), the palm stays [`WEDGE_CRUISES`]
//! cruises short of the self-locking wedge (the sum of the friction angles, static or dynamic,
//! whichever is larger) and the contact stays on the palm a cruise longer.
//!
//! The shortest cruise is ten steps; each longer one is three times the next, up to
//! [`LONGEST_CRUISE_DEG`] of palm turn, the longest tried first: the motion drive (0.1 deg
//! steps) cruises 1 deg at a time, the force drive (0.01 deg) 0.9, 0.3 and 0.1 deg at a time. A
//! cruise spans a whole number of steps, so the steps after it lie on the same grid of palm
//! angles as without it. A length refused waits its own span before it is tried again, twice
//! that after two refusals in a row, and so on up to [`LONGEST_WAIT`] spans: a refused try costs
//! a step problem and changes nothing, and where cruising fails (near the drive's limit, or at
//! 900 deg/s, where the catch-up below stalls the palm after most cruises) it keeps failing.
//!
//! Left in the lag, the step after a cruise closed it with a velocity (Stewart-Trinkle's
//! g / dt), which then carried the disc ahead of the palm: at mu = 0.1-0.2 runs cruising
//! reported 1-12 steps off the palm at 30 deg/s and hundreds at 900 deg/s, where the run without
//! cruising has none. With the force drive the step after a cruise also catches up with the
//! disc's acceleration over the cruise, its push larger than the steady one by about the ratio
//! of the lengths: at 900 deg/s, where that acceleration is most of the push, letting it stall
//! the palm moved the rest by up to 0.7 %.
//!
//! That step is only taken where cruising ends: a cruise followed by another hands its state to
//! a cruise, whose own push is checked. So a cruise is kept on trial, and the run's own step
//! after it is the check: when that step leaves the cruise's modes, the run goes back to where
//! the cruise began and cruising goes on as if its length had been refused (then, in turn, the
//! cruise before it is on trial). From the first cruise taken back on, each cruise is checked
//! by solving its next step before it is kept, as a run that keeps taking cruises back (at low
//! friction and push the catch-up stalls the palm after every long cruise) would otherwise walk
//! back and forth. With each cruise's next step solved first, a cell of the design map took
//! 562 step problems with the force drive; with cruises on trial, 391 (and a margin of one
//! cruise to the drive's limit, [`LIMIT_CRUISES`]), with the same answers to round-off; with
//! the longer waits after refusals too, 382 (`cargo bench --bench maps -- goals`).
//!
//! Measured by `cruising_keeps_the_answers` (tests of the nonsmooth module): over mu 0.1-0.8,
//! F 20-2000 N, both drives, palm speeds of 30 and 900 deg/s and a palm the disc leaves, every
//! run ends as without cruising, with the same steps off the palm, x_jam within the figure the
//! test prints (round-off), and the steps on the design map's cases fall 17 times with the
//! force drive and 5 times with the motion drive. At 30 deg/s no run solves more step problems
//! than without cruising; at 900 deg/s, where the catch-up stalls the palm after most cruises,
//! the cruises refused cost up to 3 % more (11 % when each refused length waited only its own
//! span; the figures the test prints).

use super::step::{ContactMode, DriveMode, LIFT_MM, Modes, Stepper};

/// The longest cruise in deg of palm turn: the motion drive's cruise at its default 0.1 deg
/// step, where the lag above was measured.
const LONGEST_CRUISE_DEG: f64 = 1.0;

/// Steps in the shortest cruise.
const SHORTEST_STEPS: u32 = 10;

/// Each cruise length is this many times the next shorter one.
const LENGTH_RATIO: u32 = 3;

/// Cruise lengths at most: 10 x 3^5 steps reach 1 deg at steps of 4e-4 deg.
const LEVELS: usize = 6;

/// Largest relative change of the palm's push from one cruise to the next of the same length:
/// the push grows as 1 / D towards the self-locking wedge (D the wedge's margin), so cruising
/// ends about ten cruises before it.
const PUSH_CHANGE: f64 = 0.1;

/// Cruises that must fit between a cruise's end and the self-locking wedge: the push read at a
/// cruise's start carries the disc's acceleration over the cruise, not over a step, so near
/// the wedge it is no guide to the lock-up ahead, and the steps towards it are the run's own.
const WEDGE_CRUISES: f64 = 3.0;

/// Cruises of the push's growth that must fit between the push at a cruise's end and the
/// force drive's limit, where the palm stalls and the disc comes to rest: the steps towards the
/// limit are the run's own (a long cruise ends a length of itself before it, a short one goes
/// on closer), and the run's step after the last cruise checks that the palm still runs. A
/// margin of three cruises took 424 step problems a cell of the design map against 391, with
/// the same answers.
const LIMIT_CRUISES: f64 = 1.0;

/// The longest wait after refusals in a row, in spans of the length refused (a power of 2).
const LONGEST_WAIT: u32 = 16;

/// Steady steps needed before a cruise.
const SETTLE_STEPS: u32 = 2;

/// One length of cruise.
#[derive(Debug, Clone, Copy)]
struct Level {
    /// The stepper with the cruise's step.
    stepper: Stepper,
    /// The run's steps the cruise spans.
    steps: u32,
}

/// What cruising remembers of the run's last steps: small, so that a cruise can be taken back.
#[derive(Debug, Clone, Copy)]
pub(super) struct Pace {
    /// For each length, the run's steps to wait before it is tried again.
    waits: [u32; LEVELS],
    /// For each length, its refusals in a row.
    refusals: [u32; LEVELS],
    /// Steady steps still needed before a cruise.
    settle: u32,
    /// The length in s of the last step taken (a step or a cruise).
    last_dt: f64,
    /// Steps of that length taken in a row up to the last.
    in_row: u32,
    /// Whether a cruise's next step is checked before the cruise is kept (with a limit on the
    /// drive, once a cruise was taken back).
    probes: bool,
}

impl Pace {
    /// Refuses the `j`-th length, of `steps` run steps: it waits that long, twice as long after
    /// each refusal in a row, up to [`LONGEST_WAIT`] times.
    fn refuse(&mut self, j: usize, steps: u32) {
        self.waits[j] = steps << self.refusals[j].min(LONGEST_WAIT.ilog2());
        self.refusals[j] += 1;
    }
}

/// A cruise kept: where the run goes on from, and what it reports of it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cruised {
    /// The run's steps it spans.
    pub steps: u32,
    /// Its length in s.
    pub dt: f64,
    /// The palm's push in N.
    pub push_n: f64,
    /// The palm's speed in rad/s.
    pub theta_dot: f64,
    /// Cruising as it was before this cruise, with its length refused: what
    /// [`Cruise::take_back`] restores when the run's step after it leaves its modes.
    pub refused: Pace,
    /// Whether it is on trial: with a limit on the drive, kept without its next step solved.
    pub on_trial: bool,
    /// The state at its end, the disc touching the palm: configuration, velocity, palm angle.
    pub q: [f64; 3],
    pub v: [f64; 3],
    pub theta: f64,
}

/// The state of cruising in one run.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cruise {
    /// The cruises' lengths, longest first (`count` of them).
    levels: [Level; LEVELS],
    count: usize,
    /// The run's own stepper.
    step: Stepper,
    /// The palm's length in mm: a cruise stays on the palm.
    palm_length_mm: f64,
    pace: Pace,
    /// The self-locking wedge's angle in rad with the larger of each contact's frictions.
    wedge_rad: f64,
    /// The wedge's angle in rad with the dynamic frictions, alpha_g + alpha_p.
    wedge_dynamic_rad: f64,
    /// The drive's limit on the palm's push in N (infinite: motion drive).
    push_limit_n: f64,
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
        if st.inv_mass[2] != 0.0 {
            return None;
        }
        let step_deg = (st.omega * st.dt).to_degrees();
        let level = |steps: u32| {
            let k = f64::from(steps);
            Level {
                stepper: Stepper {
                    dt: k * st.dt,
                    push_limit: k * st.push_limit,
                    ..*st
                },
                steps,
            }
        };
        let mut levels = [level(SHORTEST_STEPS); LEVELS];
        let mut count = 1;
        // Longer while within the longest, to round-off.
        while count < LEVELS
            && f64::from(LENGTH_RATIO * levels[0].steps) * step_deg
                <= LONGEST_CRUISE_DEG * (1.0 + 1e-9)
        {
            levels.copy_within(0..count, 1);
            levels[0] = level(LENGTH_RATIO * levels[1].steps);
            count += 1;
        }
        Some(Cruise {
            levels,
            count,
            step: *st,
            palm_length_mm,
            pace: Pace {
                waits: [0; LEVELS],
                refusals: [0; LEVELS],
                settle: SETTLE_STEPS,
                last_dt: st.dt,
                in_row: 0,
                probes: false,
            },
            wedge_rad: (0..2).map(|k| st.mu[k].max(st.mu_static[k]).atan()).sum(),
            wedge_dynamic_rad: st.mu.iter().map(|mu| mu.atan()).sum(),
            // kg mm/s per step -> N.
            push_limit_n: st.push_limit * 1e-3 / st.dt,
        })
    }

    /// Counts `steps` of the run's steps taken, as one step of `dt` (s): a step, or a cruise.
    fn pass(&mut self, steps: u32, dt: f64) {
        let pace = &mut self.pace;
        pace.in_row = if dt == pace.last_dt {
            pace.in_row + 1
        } else {
            1
        };
        pace.last_dt = dt;
        for wait in &mut pace.waits[..self.count] {
            *wait = wait.saturating_sub(steps);
        }
    }

    /// Counts a step taken by the run: a steady step brings the next cruise closer.
    pub fn after_step(&mut self, modes: Modes, lifts: bool) {
        self.pass(1, self.step.dt);
        if steady(modes) && !lifts {
            self.pace.settle = self.pace.settle.saturating_sub(1);
        } else {
            self.pace.settle = SETTLE_STEPS;
        }
    }

    /// Tries a cruise from (q, v, theta) in the modes of the last step, whose push was
    /// `push_n` (N), the longest length first. Returns the cruise when one is kept; a length
    /// refused waits before it is tried again, longer after each refusal in a row. `tries`
    /// counts the step problems solved.
    pub fn try_step(
        &mut self,
        q: &[f64; 3],
        v: &[f64; 3],
        theta: f64,
        modes: Modes,
        push_n: f64,
        tries: &mut u64,
    ) -> Option<Cruised> {
        if self.pace.settle > 0 || !steady(modes) || push_n <= 0.0 {
            return None;
        }
        for j in 0..self.count {
            let level = self.levels[j];
            if self.pace.waits[j] > 0 {
                continue;
            }
            if let Some(mut kept) = self.accept(&level, (q, v, theta), modes, push_n, tries) {
                kept.refused.refuse(j, level.steps);
                self.pace.refusals[j] = 0;
                self.pass(level.steps, level.stepper.dt);
                return Some(kept);
            }
            self.pace.refuse(j, level.steps);
        }
        None
    }

    /// Takes back a cruise whose next step of the run left its modes: cruising goes on as if
    /// its length had been refused.
    pub fn take_back(&mut self, refused: Pace) {
        self.pace = Pace {
            probes: true,
            ..refused
        };
    }

    /// The cruise of `level` from (q, v, theta) in `modes`, when it is kept. `push_n` (N) is
    /// the last step's push; `tries` counts the problems solved.
    ///
    /// Pushes are compared only between cruises of one length that follow one as long. Each
    /// step's velocity closes the gap with the geometry at its start, so its push carries the
    /// disc's acceleration times the ratio of the step before it to its own: at mu = 0.1 and
    /// 22 deg, where the acceleration is a sixth of the push, the steps read 6.07 N, a cruise
    /// after them 5.16 N. The first two cruises of a length are judged by the rest alone.
    fn accept(
        &self,
        level: &Level,
        (q, v, theta): (&[f64; 3], &[f64; 3], f64),
        modes: Modes,
        push_n: f64,
        tries: &mut u64,
    ) -> Option<Cruised> {
        let st = &level.stepper;
        let built = st.build(q, v, theta);
        *tries += 1;
        let sol = built.problem.try_modes(modes)?;
        let push = sol.impulse[2] * 1e-3 / st.dt;
        let (mut q_end, v_end) = (*q, st.velocities(&built, &sol.impulse));
        for k in 0..3 {
            q_end[k] += st.dt * v_end[k];
        }
        let theta_end = theta + st.dt * sol.theta_dot;
        let turn = theta - theta_end;
        let (s, c) = theta_end.sin_cos();
        let reach = q_end[0] * c + q_end[1] * s;
        // The contact's distance from the hinge a cruise further on, at the cruise's rate: the
        // palm's end is met by the run's own steps.
        let reach_next = 2.0 * reach - built.contact_distance;
        let steady = st.dt != self.pace.last_dt
            || self.pace.in_row < 2
            || (push - push_n).abs() <= PUSH_CHANGE * push_n;
        let ahead = theta_end - LIMIT_CRUISES * turn;
        let ok = built.gaps[0] + st.dt * v_end[1] <= LIFT_MM
            && steady
            && self.below_limit(push.max(push_n), theta, ahead)
            && theta_end - self.wedge_rad >= WEDGE_CRUISES * turn
            && reach_next <= self.palm_length_mm;
        if !ok {
            return None;
        }
        st.touch_palm(&mut q_end, theta_end);
        if self.pace.probes {
            *tries += 1;
            let after = self.step.build(&q_end, &v_end, theta_end);
            after.problem.try_modes(modes)?;
        }
        Some(Cruised {
            steps: level.steps,
            dt: st.dt,
            push_n: push,
            theta_dot: sol.theta_dot,
            // Its own length refused by the caller.
            refused: self.pace,
            on_trial: self.push_limit_n.is_finite() && !self.pace.probes,
            q: q_end,
            v: v_end,
            theta: theta_end,
        })
    }

    /// Whether the force drive's push, `push` (N) at palm angle `theta`, stays below its limit
    /// up to the palm angle `theta_ahead` (rad). A sliding disc's push grows as 1 / sin(theta -
    /// alpha_g - alpha_p) with the dynamic friction angles (N_B (sin theta - mu_p cos theta) =
    /// mu_g N_A + m x'' with N_A = m g + N_B (cos theta + mu_p sin theta)), its inertial part
    /// too, so the push ahead is read off that law.
    fn below_limit(&self, push: f64, theta: f64, theta_ahead: f64) -> bool {
        if self.push_limit_n.is_infinite() {
            return true;
        }
        let margin = (theta_ahead - self.wedge_dynamic_rad).sin();
        margin > 0.0 && push * (theta - self.wedge_dynamic_rad).sin() <= margin * self.push_limit_n
    }
}
