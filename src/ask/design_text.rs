//! The text of a design answer: the target, the corners, the least push and the largest
//! friction with their simulated checks, the palm lengths.

use std::fmt::Write;

use super::Words;
use super::design::{COAST_TOLERANCE, DesignReport, SimCheck};
use crate::design::{AvoidJams, Carry, LeastPush};
use crate::numbers::{Num, fixed, fixed_or_past};
use crate::scene::{JamStatus, SceneParams};

/// A corner's friction, mass or push as the other answers print an input's value: 4
/// significant digits (a distribution's 0.1 % quantile printed as 0.302706969185).
fn short(v: f64) -> String {
    crate::numbers::sig(v, 4)
}

/// The least push's line of the text answer.
fn push_line(e: &SceneParams, least_push: LeastPush) -> String {
    match least_push {
        LeastPush::Push { force_n } => format!(
            "least push that carries it there without jamming at any friction: F = {force_n:.3} N \
             (closed form m g sin(alpha_g) / sin(theta_t - alpha_g - alpha_p))",
            force_n = Num(force_n)
        ),
        LeastPush::AnyPushThatMoves { least_moving_n } => format!(
            "least push: any push above {least_moving_n:.3} N (the least that moves the disc) \
             carries it there",
            least_moving_n = Num(least_moving_n)
        ),
        LeastPush::BelowNormal { least_normal_n } => format!(
            "least push: below {least_normal_n:.3e} N, too small for a double to hold to its \
             digits (at a subnormal ground friction); every push of at least that carries it \
             there without jamming at any friction (not simulated: no simulation moves a disc \
             by such a push)"
        ),
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg,
            x_rigid_mm,
        } => format!(
            "least push: none: at mu_ground {} / mu_palm {} the friction wedge locks at {:.3} deg \
             (x = {x_rigid_mm:.3} mm) before the target whatever the push; lower the friction \
             or move the target nearer",
            short(e.mu_ground),
            short(e.mu_palm),
            Num(theta_rigid_deg),
            x_rigid_mm = Num(x_rigid_mm)
        ),
    }
}

fn sim_line(c: &SimCheck) -> String {
    let mm = |v: Option<f64>| v.map_or("no jam".into(), |x| format!("{x:.3} mm", x = Num(x)));
    format!(
        "  check (F = {:.3} N, mu {} / {}): closed form x_jam = {}, nonsmooth simulation (force \
         drive) x_jam = {}",
        Num(c.force_n),
        short(c.mu.0),
        short(c.mu.1),
        mm(c.x_jam_closed_form_mm),
        mm(c.x_jam_nonsmooth_mm)
    )
}

impl DesignReport {
    /// The command line's report: the target, the corners, the least push and largest
    /// friction with their checks, the palm lengths. It names no setting, so it reads the
    /// same in every face's words.
    pub fn text(&self, _words: Words) -> String {
        let (d, u) = (&self.design, &self.uncertain);
        let (push, late) = (
            self.check_least_push.as_ref(),
            self.check_latest_jam.as_ref(),
        );
        let latest = &self.latest_corner;
        let mut out = String::new();
        let over = if u.is_empty() {
            "the given point".to_string()
        } else {
            format!("every value of {}", u.describe())
        };
        let e = &self.earliest_corner;
        let _ = writeln!(
            out,
            "design over {over}: target x = {} mm (palm angle {} deg)",
            Num(d.x_target_mm),
            fixed(d.theta_target_deg, 3)
        );
        let _ = writeln!(
            out,
            "jams earliest at mu_ground {} / mu_palm {}, m = {} kg, F = {} N; latest at mu_ground {} / \
         mu_palm {}, m = {} kg, F = {} N",
            short(e.mu_ground),
            short(e.mu_palm),
            short(e.mass_kg),
            short(e.force_n),
            short(latest.mu_ground),
            short(latest.mu_palm),
            short(latest.mass_kg),
            short(latest.force_n)
        );
        if d.target_past_palm {
            let _ = writeln!(
                out,
                "the target lies past the palm's end ({} mm): no push carries the disc there on this \
             palm",
                Num(e.palm_length_mm)
            );
        }
        match d.carry {
            Carry::StartsPast { x_start_mm } => {
                let _ = writeln!(
                    out,
                    "the disc starts at x = {} mm, at or past the target: it is there before the \
                 palm moves, whatever the push and the friction (and held there if it jams at \
                 once); no least push or largest friction applies",
                    fixed_or_past(x_start_mm, 3)
                );
            }
            Carry::Ahead {
                least_push,
                mu_ground_max,
                mu_max,
            } => {
                let _ = writeln!(out, "{}", push_line(e, least_push));
                if let Some(c) = push {
                    let _ = writeln!(out, "{}", sim_line(c));
                    let held = c.nonsmooth_status == JamStatus::JammedAtStart;
                    if held
                        && c.x_jam_closed_form_mm
                            .is_some_and(|x| x > e.disc_position_mm(e.start_angle_deg.to_radians()))
                    {
                        // Not "push harder than the least push": the closed form moves this
                        // disc, the simulation resolves no motion from so small a margin.
                        let _ = writeln!(
                            out,
                            "  the simulated disc does not move from its start: the push is {:.3e} N \
                             above the least that moves it (m g sin(alpha_g) = {:.3e} N), less \
                             than the simulation resolves; a real push needs a margin",
                            c.force_n - crate::statics::least_push_n(e),
                            crate::statics::least_push_n(e)
                        );
                    } else if let (Some(x_cf), Some(x_sim)) =
                        (c.x_jam_closed_form_mm, c.x_jam_nonsmooth_mm)
                        && x_sim < x_cf * (1.0 - COAST_TOLERANCE)
                    {
                        let _ = writeln!(
                            out,
                            "  the simulated disc stops short of the target ({x_sim:.3} mm): push \
                         harder than the closed form's least push",
                            x_sim = Num(x_sim)
                        );
                    }
                }
                let mu =
                    |v: Option<f64>| v.map_or("none".into(), |m| format!("{m:.4}", m = Num(m)));
                let _ = writeln!(
                    out,
                    "largest friction for the push F = {} N: mu_ground up to {} (mu_palm {}; closed \
                 form), or mu up to {} on both",
                    Num(e.force_n),
                    mu(mu_ground_max),
                    short(e.mu_palm),
                    mu(mu_max)
                );
            }
        }
        match (d.palm_length_keeping_jams_on_mm, d.x_jam_latest_mm) {
            (Some(l), Some(x)) => {
                let _ = writeln!(
                    out,
                    "palm length that keeps every jam on the palm: at least {l:.3} mm (the latest \
                 jam, x = {x:.3} mm)",
                    l = Num(l),
                    x = Num(x)
                );
            }
            _ => {
                let _ = writeln!(
                    out,
                    "palm length that keeps every jam on the palm: none: at the latest corner no \
                 jam lies at a finite distance (without friction the disc never jams; a start \
                 angle that rounds to 0 rad puts it past every length)"
                );
            }
        }
        let _ = writeln!(
            out,
            "palm length that ends before every jam: {}",
            match d.palm_length_avoiding_jams {
                AvoidJams::ShorterThan {
                    below_mm,
                    x_jam_earliest_mm,
                    touches_mm,
                } => format!(
                    "under {below_mm:.3} mm (the earliest jam, x = {x:.3} mm), and at least \
                 {touches_mm:.3} mm to touch the disc at the start",
                    below_mm = Num(below_mm),
                    x = Num(x_jam_earliest_mm),
                    touches_mm = Num(touches_mm)
                ),
                AvoidJams::AnyPalm => "any: no point of the box jams (no friction)".into(),
                AvoidJams::None => "none: at the earliest corner the disc is held where the palm \
                                first touches it, or the push cannot move it"
                    .into(),
            }
        );
        if let Some(c) = late {
            let _ = writeln!(out, "{}", sim_line(c));
            if let Some(x_sim) = c.coasts_to_mm {
                let _ = writeln!(
                    out,
                    "  the simulated disc coasts past the quasi-static jam to {x_sim:.3} mm at the \
                 drive's speed: the palm must reach past that (the closed-form length holds for a \
                 slow push)",
                    x_sim = Num(x_sim)
                );
            }
        }
        out
    }
}

impl super::DesignAnswer {
    /// The verdict in one line: what carries the disc to the target over the box, or why
    /// nothing does.
    pub fn headline(&self) -> String {
        match self {
            super::DesignAnswer::Outside { why, .. } => format!("design: outside_model: {why}"),
            super::DesignAnswer::Design(r) => r.headline(),
        }
    }
}

impl DesignReport {
    /// The verdict in one line.
    pub fn headline(&self) -> String {
        let d = &self.design;
        let over = match self.uncertain.is_empty() {
            true => String::new(),
            false => format!(" over {}", self.uncertain.describe()),
        };
        let target = format!("x = {} mm", Num(d.x_target_mm));
        if d.target_past_palm {
            return format!(
                "no push carries the disc to {target}: it lies past the palm's end ({} mm)",
                Num(self.earliest_corner.palm_length_mm)
            );
        }
        match d.carry {
            Carry::StartsPast { x_start_mm } => format!(
                "the disc starts at x = {} mm, at or past the target {target}",
                fixed_or_past(x_start_mm, 3)
            ),
            Carry::Ahead { least_push, .. } => match least_push {
                LeastPush::Push { force_n } => format!(
                    "a push of at least {:.3} N carries the disc to {target}{over}",
                    Num(force_n)
                ),
                LeastPush::AnyPushThatMoves { least_moving_n } => format!(
                    "any push above {:.3} N carries the disc to {target}{over}",
                    Num(least_moving_n)
                ),
                LeastPush::BelowNormal { least_normal_n } => {
                    format!(
                        "any push of at least {least_normal_n:.3e} N carries the disc to {target}{over}"
                    )
                }
                LeastPush::WedgeLocksFirst { x_rigid_mm, .. } => format!(
                    "no push carries the disc to {target}{over}: the friction wedge locks it at \
                     x = {:.3} mm first",
                    Num(x_rigid_mm)
                ),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ask::DesignQuestion;

    /// `design` with a distributed friction printed its corners with 12 digits (`mu_ground
    /// 0.302706969185`) beside answers of 4: a corner reads as an input's value does.
    #[test]
    fn design_corners_read_with_the_digits_of_the_other_answers() {
        let q: DesignQuestion = serde_json::from_value(serde_json::json!({
            "x_target_mm": 40.0,
            "mu": "normal(0.21,0.03)",
        }))
        .unwrap();
        let text = q.answer().unwrap().text(Words::Flags);
        assert!(
            text.contains("jams earliest at mu_ground 0.3027 / mu_palm 0.3027"),
            "{text}"
        );
        assert!(!text.contains("0.302706969185"), "{text}");
    }

    /// The text of `design` for a JSON body of keywords.
    fn report(body: serde_json::Value) -> String {
        let q: DesignQuestion = serde_json::from_value(body).unwrap();
        q.answer().unwrap().text(Words::Flags)
    }

    /// At subnormal frictions (`--mu 5e-324:1e-323`, `--mu-ground`, a lognormal at 5e-324) the
    /// least push was printed as F = 2.124e-322 N, whose closed form jams at 40.533 mm against a
    /// 40 mm target, and its simulation "stops short (10.000 mm): push harder". The push is said
    /// as the bound a double holds, and nothing is simulated at it.
    #[test]
    fn a_subnormal_least_push_is_said_as_a_bound() {
        for body in [
            serde_json::json!({"x_target_mm": 40.0, "mu": "5e-324:1e-323"}),
            serde_json::json!({"x_target_mm": 40.0, "mu_ground": "5e-324:1e-323"}),
            serde_json::json!({"x_target_mm": 40.0, "mu": "lognormal(5e-324,1)"}),
        ] {
            let text = report(body.clone());
            assert!(
                text.contains("least push: below 2.225e-308 N, too small for a double"),
                "{body}: {text}"
            );
            assert!(!text.contains("stops short"), "{body}: {text}");
            assert!(!text.contains("40.533"), "{body}: {text}");
        }
    }

    /// A tiny but normal least push (mu 1e-12) is right, but the simulation holds the disc at
    /// its start: the text said "stops short of the target: push harder than the closed
    /// form's least push", advice against a right answer. It says the margin is too small to
    /// simulate.
    #[test]
    fn a_least_push_too_small_to_simulate_is_not_called_short() {
        let text = report(serde_json::json!({"x_target_mm": 40.0, "mu": "1e-12:2e-12"}));
        assert!(text.contains("closed form x_jam = 40.000 mm"), "{text}");
        assert!(!text.contains("push harder"), "{text}");
        assert!(
            text.contains("the simulated disc does not move from its start"),
            "{text}"
        );
    }
}
