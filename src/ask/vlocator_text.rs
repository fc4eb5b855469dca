//! The text of a V-block answer: one V's verdict, forces, capacity and optimum; over a box,
//! the window of included angles, the most robust V and the standard V-blocks' verdicts.

use std::fmt::Write;

use super::Words;
use super::vlocator::PointReport;
use super::vlocator_robust::RobustReport;
use crate::locator::{
    BoxVerdict, DroppedLoad, LocatorParams, OPT_MAX_DEG, OPT_MIN_DEG, RobustBox, Verdict,
    lock_angle_deg,
};
use crate::numbers::Num;

impl PointReport {
    /// The command line's report, units on every number, in `words`.
    pub fn text(&self, words: Words) -> String {
        let (p, s) = (&self.inputs, &self.solution);
        let mut out = String::new();
        let w = p.weight_n();
        let at = load_point(p);
        let _ = writeln!(
            out,
            "{}",
            part_line((p.mass_kg, p.mass_kg), p, self.mass_default, words)
        );
        let _ = writeln!(
            out,
            "V of {:.3} deg (left flank {} deg, right flank {} deg), mu {} left / {} right, {} rotation",
            Num(p.included_angle_deg()),
            Num(p.flank_left_deg),
            Num(p.flank_right_deg),
            Num(p.mu_left),
            Num(p.mu_right),
            p.rotation.as_str()
        );
        let _ = writeln!(
            out,
            "load P = {} N at {} deg {at}",
            Num(p.load_n),
            Num(p.load_angle_deg),
        );
        let verdict = match s.verdict {
            Verdict::Wedged => {
                "wedged: the V self-locks; it holds any load, the part can jam and needs a pull to \
             come out"
                    .to_string()
            }
            Verdict::Slips { mode } => {
                format!("slips: no equilibrium, the part {}", mode.describe())
            }
            Verdict::LiftsOff { flank } => format!(
                "lifts off: held on the {} flank alone, the {} flank carries nothing",
                flank.other().as_str(),
                flank.as_str()
            ),
            Verdict::Unloaded => "unloaded: the load cancels the weight, so nothing presses the \
                              disc into the V; it rests on neither flank, and any further lift \
                              takes it out"
                .to_string(),
            Verdict::Held => "held on both flanks".to_string(),
        };
        let _ = writeln!(out, "verdict: {verdict}");
        let yes = |b: bool| if b { "yes" } else { "no" };
        let _ = writeln!(
            out,
            "  self-locking: {}; held only by friction: {}; held only because it locks: {}",
            yes(s.self_locking),
            yes(s.friction_held),
            yes(s.locking_needed)
        );
        match &s.forces {
            Some(forces) => {
                let lower = if s.self_locking {
                    " (a lower bound: the V can squeeze harder)"
                } else {
                    ""
                };
                let _ = writeln!(out, "minimum-norm flank forces{lower}:");
                let scale = w.max(p.load_n);
                for f in forces {
                    let _ = writeln!(
                        out,
                        "  {:<5} flank: normal {:.3} N, friction {:.3} N up the flank, \
                     (fx, fy) = ({:.3}, {:.3}) N, friction utilisation {:.1} %",
                        f.flank.as_str(),
                        Num(clean(f.normal_n, scale)),
                        Num(clean(f.tangential_up_n, scale)),
                        Num(clean(f.fx_n, scale)),
                        Num(clean(f.fy_n, scale)),
                        Num(100.0 * f.utilisation)
                    );
                }
            }
            None => {
                let _ = writeln!(out, "flank forces: none (no equilibrium)");
            }
        }
        let c = &s.capacity;
        let cap = match (c.unbounded, c.p_max_n, c.failure_mode) {
            (true, _, _) => "unbounded: every load in this direction is held".to_string(),
            (false, Some(pm), Some(m)) => format!(
                "P_max = {pm:.3} N = {:.3} W; beyond it the part {}",
                Num(pm / w),
                m.describe(),
                pm = Num(pm)
            ),
            (false, _, m) => format!(
                "none: not even the weight is held; the part {}",
                m.map_or("leaves", |m| m.describe())
            ),
        };
        let _ = writeln!(
            out,
            "holding capacity at {} deg {at}: {cap}",
            Num(p.load_angle_deg)
        );
        let o = &s.optimum;
        let bound = if o.at_bound {
            format!(
                " (at the end of the search range: {OPT_MIN_DEG} to {OPT_MAX_DEG} deg, or a flank \
             at 0 deg for a tilted V)"
            )
        } else {
            String::new()
        };
        let rho = if o.safety_factor.is_finite() {
            format!(
                "{:.3} (a factor on load and friction)",
                Num(o.safety_factor)
            )
        } else {
            "unbounded (no error in load or friction drops or locks the part)".to_string()
        };
        if o.no_v_holds {
            let _ = writeln!(
                out,
                "optimum included angle: none: no V that does not self-lock holds this load at this \
             friction (the least bad, {:.2} deg, self-locks at it and survives only rho* = {rho})",
                Num(o.included_angle_deg)
            );
        } else {
            let _ = writeln!(
                out,
                "optimum included angle (balanced: survives load x rho with friction / rho, and \
             friction x rho): {:.2} deg{bound}, safety factor rho* = {rho}",
                Num(o.included_angle_deg)
            );
        }
        if let Some(widest) = o.plateau_to_deg.filter(|_| !o.no_v_holds) {
            let _ = writeln!(
                out,
                "  not unique: every V from {:.2} to {widest:.2} deg survives the same rho* (the \
             holding does not depend on the angle for this load)",
                Num(o.included_angle_deg),
                widest = Num(widest)
            );
        }
        if o.at_bound && p.load_n == 0.0 {
            let _ = writeln!(
                out,
                "  with no load but the weight, every V that does not lock holds the part, so the \
             criterion only moves away from locking and the widest V wins: give the load the \
             V must hold ({}, {}) to size it",
                words.name("load_n"),
                words.name("load_angle_deg")
            );
        }
        out
    }
}

/// Roundoff shows as 0.000, not -0.000 or 3e-17: below the printed digits of a force of order
/// `scale` (the larger of weight and load, N), and below the solver's resolution of it.
fn clean(v: f64, scale: f64) -> f64 {
    if v.abs() < 5e-4_f64.min(1e-12 * scale) {
        0.0
    } else {
        v
    }
}

/// "holds every load", "locks at mu = 0.3", "drops 30 N at 0 deg: the part rolls out ...".
fn describe(v: &BoxVerdict, b: &RobustBox) -> String {
    match v {
        BoxVerdict::Works => "works: holds every load at every friction, never locks".into(),
        BoxVerdict::Locks { mu_left, mu_right } => {
            format!("self-locks at {}", frictions(*mu_left, *mu_right))
        }
        BoxVerdict::Drops { load } => dropped(load, b),
    }
}

/// "drops 30.000 N at 0.00 deg (at the lowest friction[, m = 0.4 kg]): the part ...".
fn dropped(load: &DroppedLoad, b: &RobustBox) -> String {
    let mass = match b.mass_kg.0 == b.mass_kg.1 {
        true => String::new(),
        false => format!(", m = {} kg", Num(load.mass_kg)),
    };
    format!(
        "drops {:.3} N at {:.2} deg (at the lowest friction{mass}): the part {}",
        Num(load.load_n),
        Num(load.load_angle_deg),
        load.mode.describe()
    )
}

/// `0.3`, `0.12 to 0.3`, with the unit after.
fn range((lo, hi): (f64, f64), unit: &str) -> String {
    if lo == hi {
        format!("{}{unit}", Num(lo))
    } else {
        format!("{} to {}{unit}", Num(lo), Num(hi))
    }
}

/// The frictions at one end of the box: `mu = 0.3`, or `mu = 0.1 left / 0.3 right`.
fn frictions(left: f64, right: f64) -> String {
    if left == right {
        format!("mu = {}", Num(left))
    } else {
        format!("mu = {} left / {} right", Num(left), Num(right))
    }
}

/// The answer for a person.
impl RobustReport {
    /// The command line's report: the box, the window and the most robust V (or what would
    /// open a window), then the verdicts of the user's V and the standard ones; a default
    /// mass names its setting in `words`.
    pub fn text(&self, words: Words) -> String {
        let (p, b, d) = (&self.inputs, &self.r#box, &self.design);
        let (given, standard) = (self.given_v.as_ref(), &self.standard_v_blocks);
        let mut out = String::new();
        let at = load_point(p);
        let flanks = match b.one_friction_range() {
            true => format!("mu {} (both flanks)", range(b.mu_left, "")),
            false => format!(
                "mu {} left, {} right",
                range(b.mu_left, ""),
                range(b.mu_right, "")
            ),
        };
        let _ = writeln!(out, "{}", part_line(b.mass_kg, p, self.mass_default, words));
        let _ = writeln!(
            out,
            "robust V-block over {flanks}, load {} at {} {at}, {} rotation",
            range(b.load_n, " N"),
            range(b.load_angle_deg, " deg"),
            p.rotation.as_str()
        );
        let (lows, highs) = (
            frictions(b.mu_left.0, b.mu_right.0),
            frictions(b.mu_left.1, b.mu_right.1),
        );
        let every_weight = match b.mass_kg.0 == b.mass_kg.1 {
            true => "",
            false => " and every weight",
        };
        let _ = writeln!(
            out,
            "a V works when it holds every load{every_weight} at the lowest friction, {lows}, and \
         does not self-lock at the highest, {highs} (narrower than {:.2} deg locks)",
            Num(d.lock_bound_deg)
        );
        match d.windows.as_slice() {
            [] => {
                let _ = writeln!(
                    out,
                    "no single V works over this range: every V that does not lock at {highs} drops \
                 a load"
                );
                if let Some(load) = &d.dropped_at_lock_bound {
                    let _ = writeln!(
                        out,
                        "  the narrowest V that does not lock, {:.2} deg, {}",
                        Num(d.lock_bound_deg),
                        dropped(load, b)
                    );
                }
                if let Some(o) = d.opening {
                    let _ = writeln!(out, "what would open a window:");
                    match o.mu_hi_max {
                        Some(m) => {
                            let cut = (b.mu_left.1.min(m), b.mu_right.1.min(m));
                            let narrower = match b.one_friction_range() {
                                true => {
                                    format!(
                                        "mu from {} up to {:.4} at most",
                                        Num(b.mu_left.0),
                                        Num(m)
                                    )
                                }
                                false => {
                                    format!(
                                        "no flank's friction above {:.4}, the lows kept",
                                        Num(m)
                                    )
                                }
                            };
                            let _ = writeln!(
                                out,
                                "  a narrower friction range: {narrower} (a {:.2} deg V then works)",
                                Num(lock_angle_deg(p.rotation, cut)),
                            );
                        }
                        None => {
                            let _ = writeln!(
                                out,
                                "  no friction range from {lows} does: even single frictions leave \
                             no V that holds these loads"
                            );
                        }
                    }
                    match o.load_hi_max_n {
                        Some(l) => {
                            let _ = writeln!(
                                out,
                                "  a lighter load: the {:.2} deg V holds loads up to {l:.3} N in these \
                             directions",
                                Num(d.lock_bound_deg),
                                l = Num(l)
                            );
                        }
                        None => {
                            let _ = writeln!(
                                out,
                                "  a different load direction: the {:.2} deg V holds no load in \
                             these directions",
                                Num(d.lock_bound_deg)
                            );
                        }
                    }
                }
            }
            windows => {
                for (lo, hi) in windows {
                    let _ = writeln!(
                        out,
                        "window of included angles: {lo:.2} to {hi:.2} deg",
                        lo = Num(*lo),
                        hi = Num(*hi)
                    );
                }
                if d.searched {
                    let _ = writeln!(
                        out,
                        "  (a rim load under free rotation: the window was searched on a {} deg grid)",
                        crate::locator::SCAN_STEP_DEG
                    );
                }
                if let Some(r) = d.robust {
                    let rho = if r.safety_factor.is_finite() {
                        format!("{:.3}", Num(r.safety_factor))
                    } else {
                        "unbounded".into()
                    };
                    let _ = writeln!(
                        out,
                        "most robust included angle: {:.2} deg, safety factor rho* = {rho} (it \
                     survives every load x rho* with friction mu_lo / rho*, and friction mu_hi \
                     x rho* without locking)",
                        Num(r.included_angle_deg)
                    );
                }
            }
        }
        if let Some(g) = given {
            let _ = writeln!(
                out,
                "your {:.2} deg V: {}",
                Num(g.included_angle_deg),
                describe(&g.verdict, b)
            );
        }
        for s in standard {
            let _ = writeln!(
                out,
                "standard {:.0} deg V-block: {}",
                Num(s.included_angle_deg),
                describe(&s.verdict, b)
            );
        }
        out
    }
}

/// Where the load acts: "at the centre" or "at the rim point 30 deg".
fn load_point(p: &LocatorParams) -> String {
    match p.load_at_rim_deg {
        Some(psi) => format!("at the rim point {} deg", Num(psi)),
        None => "at the centre".to_string(),
    }
}

impl super::VlocatorAnswer {
    /// The verdict in one line, with the mass and load it depends on.
    pub fn headline(&self) -> String {
        match self {
            super::VlocatorAnswer::Point(r) => r.headline(),
            super::VlocatorAnswer::Robust(r) => r.headline(),
        }
    }
}

impl PointReport {
    /// The verdict in one line: `held: V of 90 deg, mu 0.3, m = 1 kg, load 5 N at 0 deg`.
    pub fn headline(&self) -> String {
        let p = &self.inputs;
        format!(
            "{}: V of {:.2} deg, {}, m = {} kg, load {} N at {} deg",
            self.solution.verdict.as_str(),
            Num(p.included_angle_deg()),
            frictions(p.mu_left, p.mu_right),
            Num(p.mass_kg),
            Num(p.load_n),
            Num(p.load_angle_deg)
        )
    }
}

impl RobustReport {
    /// The verdict in one line: the window and the most robust V, or that no single V works,
    /// with the frictions, mass and loads designed over.
    pub fn headline(&self) -> String {
        let b = &self.r#box;
        let flanks = match b.one_friction_range() {
            true => format!("mu {}", range(b.mu_left, "")),
            false => format!(
                "mu {} left, {} right",
                range(b.mu_left, ""),
                range(b.mu_right, "")
            ),
        };
        let over = format!(
            "{flanks} under {} (m = {})",
            range(b.load_n, " N"),
            range(b.mass_kg, " kg")
        );
        let d = &self.design;
        match (d.windows.as_slice(), d.robust) {
            ([], _) => {
                format!("no single V works over {over}: every V that does not lock drops a load")
            }
            (windows, robust) => {
                let spans: Vec<String> = windows
                    .iter()
                    .map(|(lo, hi)| format!("{:.2} to {:.2} deg", Num(*lo), Num(*hi)))
                    .collect();
                let best = robust.map_or(String::new(), |r| {
                    format!("; the most robust is {:.2} deg", Num(r.included_angle_deg))
                });
                format!("V-blocks of {} work over {over}{best}", spans.join(", "))
            }
        }
    }
}

/// The first line of a V-block answer: the disc's mass and weight, on which the verdict
/// depends (the README's V-block example quietly held a 1 kg part, and the README's own 0.4
/// kg shaft got the opposite verdict); the default said as such, with the setting that gives
/// it.
fn part_line(mass_kg: (f64, f64), p: &LocatorParams, mass_default: bool, words: Words) -> String {
    let weight = |m: f64| m * p.gravity_m_s2;
    let default = match mass_default {
        true => format!(
            " (not given: the default; give yours with {})",
            words.name("mass_kg")
        ),
        false => String::new(),
    };
    match mass_kg.0 == mass_kg.1 {
        true => format!(
            "part: m = {} kg{default}, weight W = m g = {:.3} N",
            Num(mass_kg.0),
            Num(weight(mass_kg.0))
        ),
        false => format!(
            "part: m = {} to {} kg{default}, weight W = m g = {:.3} to {:.3} N",
            Num(mass_kg.0),
            Num(mass_kg.1),
            Num(weight(mass_kg.0)),
            Num(weight(mass_kg.1))
        ),
    }
}
