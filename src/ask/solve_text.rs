//! The text of one push's answer: the scene, each model's status and jam with its own lines,
//! and which to design to when several answered.

use std::fmt::Write;

use super::Words;
use super::solve::{PushAnswer, PushRecord};
use crate::config::Config;
use crate::design::LeastPush;
use crate::dynamics::Drive;
use crate::models::{Detail, ModelKind, OutsideModel, Solution};
use crate::numbers::{Num, fixed, fixed_or_past};
use crate::scene::{JamStatus, SceneParams};
use crate::statics::{self, StaticsSolution};

pub(super) use super::model_text::{dynamics_advice, series_end};

/// Models whose x_jam differ by more than this are flagged: 2 % of x_jam is about the spread of
/// the paper's own two models and Adams run (0.6 % and 2.3 %).
pub(crate) const DISAGREEMENT_PCT: f64 = 2.0;

/// What to do when the palm lifts the disc (a start above 90 deg, in every model).
pub(super) fn lifts_disc_advice(words: Words) -> String {
    format!(
        "start the push at 90 deg or below ({}): above it the palm's push points upwards and \
         lifts the disc, which no model here represents",
        words.name("start_angle_deg")
    )
}

impl PushAnswer {
    /// The command line's report, in `words`: the scene, then each model's answer with units.
    pub fn text(&self, words: Words) -> String {
        let p = &self.config.scene;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "scene: mu_ground = {}, mu_palm = {}, r = {} mm, m = {} kg, F = {} N, g = {} m/s^2, \
             start at {} deg, palm {} mm{}",
            Num(p.mu_ground),
            Num(p.mu_palm),
            Num(p.radius_mm),
            Num(p.mass_kg),
            Num(p.force_n),
            Num(p.gravity_m_s2),
            Num(p.start_angle_deg),
            Num(p.palm_length_mm),
            if p.palm_offset_mm > 0.0 {
                format!(
                    ", palm face {} mm off the hinge line",
                    Num(p.palm_offset_mm)
                )
            } else {
                String::new()
            }
        );
        for x in &self.results {
            self.record_text(&mut s, x, words);
        }
        if let Some(g) = self.guidance() {
            s.push('\n');
            s.push_str(&g);
        }
        s
    }

    /// Where several models answered: which answer to design to and why, and where they
    /// disagree (the paragraph that ends the report).
    pub fn guidance(&self) -> Option<String> {
        (self.results.len() > 1).then(|| {
            guidance(&self.config, self.results.iter().map(|x| &x.solution))
                .trim_start_matches('\n')
                .to_string()
        })
    }

    /// One model's lines: its status, the jam, its own details and the time it took.
    fn record_text(&self, s: &mut String, x: &PushRecord, words: Words) {
        let p = &self.config.scene;
        let r = &x.solution;
        let _ = writeln!(s, "\n{}: {}", r.model, r.status);
        match (r.status, r.theta_jam_deg, r.x_jam_mm) {
            (JamStatus::Jams, Some(t), Some(x)) => {
                let _ = writeln!(
                    s,
                    "  theta_jam = {} deg   palm angle at which the disc stops sliding and jams",
                    fixed(t, 3)
                );
                let _ = writeln!(
                    s,
                    "  x_jam     = {} mm    disc position at the jam (hinge to ground contact)",
                    fixed(x, 3)
                );
            }
            (JamStatus::JammedAtStart, Some(t), x) => {
                let at = x.map_or(String::new(), |x| format!(" (x = {x:.3} mm)", x = Num(x)));
                let _ = writeln!(
                    s,
                    "  the disc does not move: it is held already at the start angle {t:.3} deg{at}",
                    t = Num(t)
                );
            }
            (JamStatus::TooWeak, ..) => {
                let _ = writeln!(s, "  {}", too_weak_advice(p, words));
            }
            (JamStatus::NeverJams, ..) => {
                let _ = writeln!(
                    s,
                    "  the disc never jams: without friction it slides for as long as the palm pushes"
                );
            }
            (JamStatus::BeyondReach, ..) if has_past_palm(&r.detail) => {
                let _ = writeln!(
                    s,
                    "  the jam lies past the palm's end ({} mm): the palm loses the disc first",
                    Num(p.palm_length_mm)
                );
            }
            (JamStatus::BeyondReach, ..) => {
                let start = p.start_angle_deg.to_radians();
                let touch_mm = p.contact_distance_mm(start);
                let _ = match touch_mm > p.palm_length_mm {
                    true => writeln!(
                        s,
                        "  the disc starts past the palm's end: the palm would touch it {} mm \
                         from the hinge at the start angle {} deg, and the palm is {} mm long \
                         ({})",
                        // A start angle near 0 puts the touch beyond the float range.
                        fixed_or_past(touch_mm, 3),
                        Num(p.start_angle_deg),
                        Num(p.palm_length_mm),
                        words.name("palm_length_mm")
                    ),
                    false => writeln!(
                        s,
                        "  the jam point lies beyond the palm's end ({} mm): the palm loses the \
                         disc first",
                        Num(p.palm_length_mm)
                    ),
                };
            }
            _ => {}
        }
        match &r.detail {
            Detail::Statics(d) => statics_lines(s, d, p, words),
            Detail::MinNorm(d) => super::model_text::min_norm_lines(s, d, x.trace.as_ref(), words),
            Detail::Dynamics(d) => {
                super::model_text::dynamics_lines(s, d, &self.config, self.series.as_deref(), words)
            }
            Detail::Outside(why) => {
                let _ = writeln!(s, "  not run: {why}");
                if let OutsideModel::PalmLiftsDisc { .. } = why {
                    let _ = writeln!(s, "  advice: {}", lifts_disc_advice(words));
                }
            }
        }
        // A model that did not run took no time worth a line.
        if !matches!(r.detail, Detail::Outside(_)) {
            let (t, unit) = match r.elapsed_s {
                t if t < 1e-3 => (t * 1e6, "us"),
                t => (t * 1e3, "ms"),
            };
            let _ = writeln!(s, "  took {t:.1} {unit}");
        }
    }
}

/// A statics answer that knows where the jam past the palm's end would be.
fn has_past_palm(d: &Detail) -> bool {
    matches!(d, Detail::Statics(d) if d.past_palm.is_some())
}

/// The statics' own lines: the F -> inf limit, the jam past the palm's end, a lift-off warning.
fn statics_lines(s: &mut String, d: &StaticsSolution, p: &SceneParams, words: Words) {
    if let Some(x) = d.x_rigid_mm {
        let _ = writeln!(
            s,
            "  x_rigid   = {} mm, theta_rigid = {} deg: the rigid limit, the jam as F -> inf \
             (a motion-driven palm)",
            fixed(x, 3),
            fixed(d.theta_rigid_deg, 3)
        );
    }
    if let Some(past) = &d.past_palm {
        let _ = writeln!(
            s,
            "  on a long enough palm it would jam at theta = {} deg, x = {} mm: that needs \
             a palm of at least {} mm ({})",
            fixed(past.theta_jam_deg, 3),
            fixed(past.x_jam_mm, 3),
            fixed(past.palm_length_needed_mm, 3),
            words.name("palm_length_mm")
        );
        let more = match past.friction_factor_needed {
            Some(k) if p.mu_ground == p.mu_palm => {
                format!("mu >= {:.4} ({})", Num(k * p.mu_ground), words.name("mu"))
            }
            Some(k) => format!(
                "mu_ground >= {:.4} and mu_palm >= {:.4} (both scaled by {k:.4})",
                Num(k * p.mu_ground),
                Num(k * p.mu_palm),
                k = Num(k)
            ),
            None => "no friction within a factor 1e6 does".into(),
        };
        let _ = writeln!(
            s,
            "  or more friction brings the jam onto this palm: {more}"
        );
    }
    if d.lifts_off
        && let Some(above) = d.lift_off_above_deg
    {
        let _ = writeln!(
            s,
            "  warning: above {above:.3} deg the palm lifts the disc off the ground (R_n < 0); \
             the statics do not hold there",
            above = Num(above)
        );
    }
}

/// What it takes to slide a disc the push cannot move: the least push that slides it from the
/// start angle ([`crate::design::least_push`] at the start), which is more than the least push
/// that moves it at all where the wedge would hold it at the start, and none where the wedge
/// alone, atan mu_ground + atan mu_palm, reaches the start angle: more push then only holds it
/// there (at 1000 N as at 20 N for mu 0.9 and a start at 80 deg).
fn too_weak_advice(p: &SceneParams, words: Words) -> String {
    let moves = statics::least_push_n(p);
    let head = "the push cannot move the disc at any palm angle";
    if !moves.is_finite() {
        // A weight past the float range (a mass of 1e308 kg) made the least push inf N.
        return format!(
            "{head}: the weight m g is beyond the range of a 64-bit float, and no finite push \
             moves it"
        );
    }
    let force = words.name("force_n");
    match crate::design::least_push(p, p.start_angle_deg.to_radians()) {
        LeastPush::AnyPushThatMoves { .. } | LeastPush::BelowNormal { .. } => format!(
            "{head}: it takes more than m g sin(atan mu_ground) = {:.4} N ({force}), or less \
             ground friction",
            Num(moves)
        ),
        LeastPush::Push { force_n } => format!(
            "{head}: above m g sin(atan mu_ground) = {:.4} N it moves but is held at the start \
             angle; it slides from there above {:.4} N ({force}), or with less friction",
            Num(moves),
            Num(force_n)
        ),
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg, ..
        } => format!(
            "{head}, and no push slides it: above m g sin(atan mu_ground) = {:.4} N it moves, \
             but the friction wedge atan mu_ground + atan mu_palm = {:.2} deg holds it at the \
             start angle {} deg; lower the frictions ({}, {}) until the wedge is below the \
             start angle{}",
            Num(moves),
            theta_rigid_deg,
            Num(p.start_angle_deg),
            words.name("mu_ground"),
            words.name("mu_palm"),
            if theta_rigid_deg < 90.0 {
                format!(
                    " or start the palm above the wedge ({}, at most 90 deg)",
                    words.name("start_angle_deg")
                )
            } else {
                String::new()
            }
        ),
    }
}

/// The paragraph after several models' answers: which to design to, and where they disagree.
fn guidance<'a>(config: &Config, results: impl Iterator<Item = &'a Solution> + Clone) -> String {
    let x_of = |kind: ModelKind| {
        results
            .clone()
            .find(|r| r.model == kind)
            .and_then(|r| r.x_jam_mm)
    };
    let mut s = String::from("\nwhich to design to:\n");
    if let Some(x) = x_of(ModelKind::Statics) {
        let _ = writeln!(
            s,
            "  a slow push limited to F = {} N: statics, x_jam = {x:.3} mm",
            Num(config.scene.force_n),
            x = Num(x)
        );
    }
    let rigid = results.clone().find_map(|r| match &r.detail {
        Detail::Statics(d) => d.x_rigid_mm,
        _ => None,
    });
    if let Some(x) = rigid {
        let offset = if config.scene.palm_offset_mm > 0.0 {
            " + h / sin(alpha_g + alpha_p)"
        } else {
            ""
        };
        let _ = writeln!(
            s,
            "  a palm driven by motion (it pushes as hard as needed): the limit x_rigid = \
             r cot((alpha_g + alpha_p)/2){offset} = {x:.3} mm",
            x = Num(x)
        );
    }
    let drive = match config.dynamics.drive.mode {
        Drive::Motion => "motion drive: it tends to the driven-palm limit",
        Drive::Force => "force drive: it tends to the statics at F",
    };
    let dynamics = results.clone().find(|r| r.model == ModelKind::Dynamics);
    if let Some((x, status)) = dynamics.and_then(|r| r.x_jam_mm.map(|x| (x, r.status))) {
        // An answer its model does not stand behind is not a figure to design to.
        let trust = match status {
            JamStatus::Jams | JamStatus::JammedAtStart => String::new(),
            other => format!(", untrusted ({other}: see its reason above)"),
        };
        let _ = writeln!(
            s,
            "  a fast push where inertia and contact stiffness matter: dynamics ({drive}), \
             x_jam = {x:.3} mm{trust}",
            x = Num(x)
        );
    }
    let answered: Vec<(ModelKind, f64)> = results
        .clone()
        .filter_map(|r| r.x_jam_mm.map(|x| (r.model, x)))
        .collect();
    if results.clone().all(|r| r.status == JamStatus::OutsideModel) {
        s.push_str("  none: the scene lies outside every model (each one's reason is above)\n");
    }
    // Against the first answer (the closed form, the oracle, when every model answers).
    if let Some(((a, xa), rest)) = answered.split_first() {
        for (b, xb) in rest {
            let pct = 100.0 * (xb - xa) / xa;
            if pct.abs() > DISAGREEMENT_PCT {
                let _ = writeln!(
                    s,
                    "  note: {b} differs from {a} by {pct:+.1} % in x_jam (more than \
                     {DISAGREEMENT_PCT} %): they answer different questions, see above"
                );
            }
        }
    }
    s
}

impl PushAnswer {
    /// The verdict in one line: each model's status, and its jam where it has one.
    pub fn headline(&self) -> String {
        let each: Vec<String> = self
            .results
            .iter()
            .map(|r| {
                let s = &r.solution;
                match (s.theta_jam_deg, s.x_jam_mm) {
                    (Some(t), Some(x)) => format!(
                        "{}: {} at theta_jam = {} deg, x_jam = {} mm",
                        s.model,
                        s.status,
                        fixed(t, 3),
                        fixed(x, 3)
                    ),
                    _ => format!("{}: {}", s.model, s.status),
                }
            })
            .collect();
        each.join("; ")
    }
}
