//! Reading the jam off the motion.
//!
//! The paper reads the jam as "an instability of the velocity" (Fig. 5a). We read it as the
//! instant the disc's speed v collapses below a fraction beta (`jam_speed_ratio`, default 0.5) of
//! the geometric speed the turning palm would impose on a rigid disc,
//!
//! ```text
//! v_geo(theta) = omega (r + (r + h) cos theta) / sin^2 theta  =  r omega / (2 sin^2(theta/2))  (h = 0),
//! ```
//!
//! after the disc has once reached `arm_speed_ratio` (0.9) of it (so the start from rest does not
//! count). A candidate is confirmed when, for a window of 0.25 deg of palm turn (or 1.5 times the
//! longest flight of a bounce, 2 v_geo / (mu_g g), if longer) during which the palm touches the
//! disc throughout, the disc has not recovered to the arming ratio. A disc standing free ahead of
//! the palm is waiting for it, not jammed; a disc that recovers was only slowed (it bounced off
//! a stiff, lightly damped contact and friction stopped it before the palm caught up, or a
//! transient was poorly resolved), and the search goes on. The simulation stops at the
//! confirmation, or `after_jam_s` after the jam if that is later.
//!
//! A second reading is reported beside it when the run lasts long enough: the first instant
//! after the jam at which the ground slip falls below the stiction transition velocity V_s, i.e.
//! the ground contact enters Adams' stiction band. Both readings measure the same collapse. The
//! stiction reading comes later (the disc must slow from about v_geo, ~19 mm/s at the default jam,
//! to V_s = 0.1 mm/s) and lies further out by the distance the disc creeps meanwhile: at the
//! defaults (motion drive) the disc creeps at 0.130 mm/s falling to V_s over the 64 ms after the
//! collapse, and the stiction reading lies 0.030 mm further out (so it needs `after_jam_s` >=
//! 0.07; `the_motion_drive_creep_figures_of_the_jam_docs` in `tests/dynamics_physics.rs`). We pick
//! the speed ratio because it needs no creep threshold: Adams' friction has no true stiction, so
//! a held disc creeps at a speed set by V_s and the load, and the stiction reading drifts with
//! V_s; the ratio is dimensionless, and its value barely matters because the collapse is steep.
//!
//! Both drives use the commanded omega in v_geo. With the motion drive the collapse is the
//! lock-up, and it is the jam. With the force drive it is where the palm stalled at its limit
//! and let the disc go on alone, braked by the ground: the disc still moves (9.2 mm/s at the
//! defaults) and comes to rest up to 9.55 % further out (`tests/force_drive_rest.rs`). There the
//! jam is read where the disc's speed first falls below the rest speed 2 V_d
//! ([`rest_speed_mm_s`]) after the collapse, and the run goes on until it does; the collapse is
//! kept as the half-speed reading.
//!
//! A force-driven disc that never arms may be held for good by the stalled palm: the rigid
//! statics say so ([`super::held`]), and the detector then stops the run after the same
//! confirmation window instead of letting the regularised disc creep to the end of the push.

use super::held::{self, CONFIRM_DEG};
use super::integrators::{Control, DenseStep, Observer};
use super::system::System;

/// Safety factor on the flight time of a bounce in the confirmation window.
const BOUNCE_FACTOR: f64 = 1.5;

/// One instant of the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Instant {
    /// Time in s.
    pub t: f64,
    /// Palm angle in rad.
    pub theta: f64,
    /// Disc position in mm.
    pub x: f64,
}

/// One row of the time series (the data of the paper's Fig. 5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesRow {
    /// Time from the start of the push in s.
    pub t_s: f64,
    /// Palm angle in deg.
    pub theta_deg: f64,
    /// Disc position (hinge to ground contact) in mm.
    pub x_mm: f64,
    /// Disc speed in mm/s.
    pub x_dot_mm_s: f64,
    /// Penetration of the palm into the disc in mm (0 for a rigid contact).
    pub penetration_mm: f64,
    /// Palm's normal force on the disc in N.
    pub normal_n: f64,
    /// Palm's friction force on the disc in N.
    pub palm_friction_n: f64,
    /// Ground's normal force in N.
    pub ground_normal_n: f64,
    /// Ground's friction force in N.
    pub ground_friction_n: f64,
}

/// Settings of the reading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JamRule {
    pub jam_ratio: f64,
    pub arm_ratio: f64,
    /// V_s in mm/s (stiction reading).
    pub v_stiction: f64,
    /// Palm length in mm: beyond it the disc is lost.
    pub palm_length: f64,
    /// Simulated time after the confirmed jam, in s.
    pub after_jam: f64,
    /// Friction deceleration of a free disc, mu_g g, in mm/s^2.
    pub ground_decel: f64,
    /// Time step of the recorded series in s (None: no series).
    pub series_dt: Option<f64>,
    /// Speed in mm/s below which the disc is at rest after the jam (the force drive's rest
    /// reading, [`rest_speed_mm_s`]); None: the jam is the speed collapse itself (the motion
    /// drive's lock-up).
    pub rest_speed: Option<f64>,
}

/// The speed (mm/s) below which a regularised disc counts as at rest: twice the friction
/// transition velocity V_d. Adams' friction has no true stiction, so a disc held by friction
/// creeps at a speed set by V_s, V_d and the load (0.124 mm/s at the defaults' force drive,
/// between V_s = 0.1 and V_d = 0.2 mm/s, printed by `the_force_drive_creep_figure_of_the_docs`);
/// below 2 V_d a disc braked by the ground alone (mu_g g) stops within (2 V_d)^2 / (2 mu_g g),
/// 2e-5 mm at the defaults.
pub fn rest_speed_mm_s(friction_velocity_mm_s: f64) -> f64 {
    2.0 * friction_velocity_mm_s
}

/// The observer that reads the jam during the integration.
#[derive(Debug, Clone)]
pub struct JamDetector<'a> {
    sys: &'a System,
    rule: JamRule,
    /// The disc has reached the arming speed once.
    pub armed: bool,
    /// Candidate (or confirmed) jam.
    pub jam: Option<Instant>,
    pub confirmed: bool,
    /// First instant after the jam with ground slip below V_s.
    pub stiction: Option<Instant>,
    /// First instant after the jam with the disc's speed below the rule's rest speed.
    pub rest: Option<Instant>,
    /// The contact left the palm's end at this instant.
    pub beyond_reach: Option<Instant>,
    /// Candidates the disc recovered from.
    pub discarded: u32,
    /// The palm lost the disc (no penetration at a step end) after it first pushed it to speed.
    pub separated: bool,
    /// Largest palm push (N, the whole contact force, which the force drive's limit senses)
    /// from the candidate jam to its confirmation; it stops updating once the jam is confirmed
    /// (the run-on after it does not count).
    pub push_after_jam: f64,
    /// Palm angle (rad) and elastic push (N) when the jam was confirmed.
    pub at_confirmation: Option<(f64, f64)>,
    /// Since when (s) the palm has touched the disc without a break, seen at step ends.
    touching_since: Option<f64>,
    /// The palm lost the disc at the candidate or at a step end since: it may have bounced ahead.
    bounced: bool,
    /// Period in s of the disc oscillating on the palm contact's stiffness at the candidate.
    contact_period: f64,
    /// Force drive, never armed: watches for the disc held for good by the stalled palm.
    held: held::HeldWatch,
    pub series: Vec<SeriesRow>,
    next_sample: f64,
    y: Vec<f64>,
}

impl<'a> JamDetector<'a> {
    pub fn new(sys: &'a System, rule: JamRule, t0: f64) -> Self {
        JamDetector {
            sys,
            rule,
            armed: false,
            jam: None,
            confirmed: false,
            stiction: None,
            rest: None,
            beyond_reach: None,
            discarded: 0,
            separated: false,
            push_after_jam: 0.0,
            at_confirmation: None,
            touching_since: None,
            bounced: false,
            contact_period: 0.0,
            held: held::HeldWatch::default(),
            series: Vec::new(),
            next_sample: t0,
            y: vec![0.0; 3],
        }
    }

    /// The confirmation window after a candidate at palm angle `theta`: 0.25 deg of palm turn, and
    /// two periods of the disc oscillating on the contact (a soft contact slows the disc below
    /// the threshold while it compresses, then throws it ahead); if the palm lost the disc since
    /// the candidate (`bounced`), also longer than the flight of a bounce: a disc knocked ahead of
    /// the palm at up to twice the palm's speed is caught again after 2 v_geo / (mu_g g) at most
    /// (friction decelerates it). Without a bounce that flight term would keep the palm grinding
    /// on a stuck disc for up to a second at mu = 0.1.
    fn confirm_time(&self, theta: f64) -> f64 {
        let turn = (CONFIRM_DEG.to_radians() / self.sys.omega).max(2.0 * self.contact_period);
        let decel = self.rule.ground_decel;
        let flight = if self.bounced && decel > 0.0 {
            2.0 * self.sys.geometric_speed(theta) / decel
        } else {
            0.0
        };
        turn.max(BOUNCE_FACTOR * flight)
    }

    fn record(&mut self, step: &dyn DenseStep, upto: f64) {
        let Some(dt) = self.rule.series_dt else {
            return;
        };
        while self.next_sample <= upto {
            step.eval(self.next_sample, &mut self.y);
            let f = self.sys.evaluate(&self.y, None);
            self.series.push(SeriesRow {
                t_s: self.next_sample,
                theta_deg: self.y[0].to_degrees(),
                x_mm: self.y[1],
                x_dot_mm_s: self.y[2],
                penetration_mm: f.penetration,
                normal_n: f.normal,
                palm_friction_n: f.palm_friction,
                ground_normal_n: f.ground_normal,
                ground_friction_n: f.ground_friction,
            });
            self.next_sample += dt;
        }
    }
}

/// The first root of g in [a, b] given g(a) >= 0 > g(b), by Illinois false position.
fn first_root(step: &dyn DenseStep, a: f64, b: f64, g: impl Fn(&[f64]) -> f64) -> f64 {
    let mut y = [0.0; 3];
    let mut at = |t: f64| {
        step.eval(t, &mut y);
        g(&y)
    };
    let (mut a, mut b) = (a, b);
    let (mut ga, mut gb) = (at(a), at(b));
    let mut side = 0;
    for _ in 0..100 {
        if (b - a) <= 1e-13 * b.abs().max(1.0) {
            break;
        }
        let mut t = (a * gb - b * ga) / (gb - ga);
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
        }
        let gt = at(t);
        if gt >= 0.0 {
            a = t;
            ga = gt;
            if side == 1 {
                gb *= 0.5;
            }
            side = 1;
        } else {
            b = t;
            gb = gt;
            if side == -1 {
                ga *= 0.5;
            }
            side = -1;
        }
    }
    b
}

impl Observer for JamDetector<'_> {
    fn on_step(&mut self, step: &dyn DenseStep) -> Control {
        let (t0, t1) = (step.t_start(), step.t_end());
        self.record(step, t1);
        let mut y = [0.0; 3];
        step.eval(t1, &mut y);
        let instant = |t: f64| {
            let mut y = [0.0; 3];
            step.eval(t, &mut y);
            Instant {
                t,
                theta: y[0],
                x: y[1],
            }
        };
        let sys = self.sys;
        let rule = self.rule;
        if self.jam.is_none() {
            self.touching_since = None;
        }
        let jam_ratio = rule.jam_ratio;
        let geometry = sys.geometry(&y);
        // How far the disc's speed lies above `ratio` of the geometric speed, in mm/s.
        let margin = |ratio: f64| y[2] - ratio * geometry.geometric_speed;
        // The contact passes the palm's end before any jam: the disc is lost.
        if self.jam.is_none() && geometry.contact_distance > rule.palm_length {
            let t = first_root(step, t0, t1, |y| rule.palm_length - sys.contact_distance(y));
            self.beyond_reach = Some(instant(t));
            return Control::Stop(t);
        }
        if !self.armed {
            self.armed = margin(rule.arm_ratio) >= 0.0;
            // Held for good before it ever armed: the rigid statics end the run; its jam is at
            // the start, so `after_jam` counts from there.
            if let Some(v_rest) = rule.rest_speed
                && !self.armed
                && self.held.see(sys, &y, t1, v_rest)
                && t1 >= rule.after_jam
            {
                return Control::Stop(t1);
            }
            return Control::Continue;
        }
        if self.jam.is_none() && geometry.penetration <= 0.0 {
            self.separated = true;
        }
        if self.jam.is_none() {
            if margin(jam_ratio) < 0.0 {
                let t = first_root(step, t0, t1, |y| {
                    y[2] - jam_ratio * sys.geometric_speed(y[0])
                });
                self.jam = Some(instant(t));
                self.push_after_jam = 0.0;
                self.stiction = None;
                self.rest = None;
                let mut at = [0.0; 3];
                step.eval(t, &mut at);
                let delta = sys.geometry(&at).penetration;
                self.contact_period = sys.impact.period_s(sys.mass, delta);
                self.bounced = self.contact_period <= 0.0;
            } else {
                return Control::Continue;
            }
        }
        let jam = self.jam.expect("set above");
        let penetration = geometry.penetration;
        if !self.confirmed {
            if margin(rule.arm_ratio) >= 0.0 {
                // The disc recovered: it was slowed, not jammed.
                self.jam = None;
                self.stiction = None;
                self.rest = None;
                self.discarded += 1;
                return Control::Continue;
            }
            // The whole contact force, which the force drive's limit senses.
            self.push_after_jam = self.push_after_jam.max(sys.evaluate(&y, None).normal);
        }
        if self.stiction.is_none() && y[2] < rule.v_stiction {
            let a = t0.max(jam.t);
            let t = first_root(step, a, t1, |y| y[2] - rule.v_stiction);
            self.stiction = Some(instant(t));
        }
        if let Some(v_rest) = rule.rest_speed
            && self.rest.is_none()
            && y[2] < v_rest
        {
            let a = t0.max(jam.t);
            let mut ya = [0.0; 3];
            step.eval(a, &mut ya);
            let t = if ya[2] < v_rest {
                a
            } else {
                first_root(step, a, t1, |y| y[2] - v_rest)
            };
            self.rest = Some(instant(t));
        }
        if penetration <= 0.0 {
            self.touching_since = None;
            self.bounced = true;
        } else if self.touching_since.is_none() {
            self.touching_since = Some(t1);
        }
        if !self.confirmed
            && self
                .touching_since
                .is_some_and(|t| t1 >= t + self.confirm_time(jam.theta))
        {
            self.confirmed = true;
            let (elastic_push, _) = sys.impact.elastic(penetration);
            self.at_confirmation = Some((y[0], elastic_push));
        }
        let at_rest = rule.rest_speed.is_none() || self.rest.is_some();
        if self.confirmed && at_rest && t1 >= jam.t + rule.after_jam {
            Control::Stop(t1)
        } else {
            Control::Continue
        }
    }

    /// With a candidate jam and the palm touching the disc: the end of its confirmation
    /// window, or `after_jam_s` after it if later (where the run stops unless the disc
    /// recovers). Before arming, the end of a held disc's window (`held`), or `after_jam_s`.
    fn horizon(&self) -> Option<f64> {
        if !self.armed {
            return self.held.until().map(|t| t.max(self.rule.after_jam));
        }
        let jam = self.jam?;
        let confirmed_by = match self.at_confirmation {
            Some(_) => jam.t,
            None => self.touching_since? + self.confirm_time(jam.theta),
        };
        // A disc still coasting to rest stops within v / (mu_g g) of the jam.
        let coast = match (self.rule.rest_speed, self.rest) {
            (Some(_), None) if self.rule.ground_decel > 0.0 => {
                self.sys.geometric_speed(jam.theta) / self.rule.ground_decel
            }
            _ => 0.0,
        };
        Some(
            confirmed_by
                .max(jam.t + coast)
                .max(jam.t + self.rule.after_jam),
        )
    }
}
