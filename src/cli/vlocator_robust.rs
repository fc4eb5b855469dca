//! `jamchart vlocator` with a friction or load range: the robust V-block
//! ([`crate::locator::robust`]), the window of included angles that works over the whole box.

use std::fmt::Write;

use serde::Serialize;

use super::args::VlocatorFormat;
use crate::error::{Error, Result};
use crate::locator::{
    BoxVerdict, DroppedLoad, LocatorParams, RobustBox, RobustDesign, lock_angle_deg, robust_design,
    verdict_over_box,
};
use crate::numbers::Num;
use crate::uncertain::{Uncertain, UncertainSet};

/// The standard V-blocks the answer checks, deg.
const STANDARD_V_DEG: [f64; 3] = [60.0, 90.0, 120.0];

/// The box of `p`'s nominal V from the uncertain inputs: a friction range on both flanks
/// (`mu`) or on each (`mu_left`, `mu_right`; a flank given as a number keeps it), a mass range
/// (`mass_kg`), a load range (`load_n`) and a direction range (`load_angle_deg`). A
/// distribution is refused naming it: a robust V holds every value of a range.
pub fn robust_box(p: &LocatorParams, uncertain: &UncertainSet) -> Result<RobustBox> {
    let point = |v: f64| (v, v);
    let mut b = RobustBox {
        mu_left: point(p.mu_left),
        mu_right: point(p.mu_right),
        mass_kg: point(p.mass_kg),
        load_n: point(p.load_n),
        load_angle_deg: point(p.load_angle_deg),
    };
    for i in &uncertain.inputs {
        let Uncertain::Range { lo, hi } = i.value else {
            return Err(Error::invalid(
                i.name,
                i.value,
                "a robust V-block holds every value of a range: give LOW:HIGH (a \
                 distribution's probabilities are not asked here)",
            ));
        };
        for key in &i.keys {
            match *key {
                "mu_left" => b.mu_left = (lo, hi),
                "mu_right" => b.mu_right = (lo, hi),
                "mass_kg" => b.mass_kg = (lo, hi),
                "load_n" => b.load_n = (lo, hi),
                "load_angle_deg" if hi - lo <= 360.0 => b.load_angle_deg = (lo, hi),
                "load_angle_deg" => {
                    return Err(Error::invalid(
                        i.name,
                        i.value,
                        "a direction range spans at most 360 deg",
                    ));
                }
                _ => {
                    return Err(Error::invalid(
                        i.name,
                        i.value,
                        "a robust V-block takes ranges of --mu, --mu-left, --mu-right, --mass, \
                         --load and --load-angle; give this one as a number",
                    ));
                }
            }
        }
    }
    // Each corner's weight and load are checked as the point's are (within the float range).
    LocatorParams {
        mass_kg: b.mass_kg.1,
        load_n: b.load_n.1,
        ..*p
    }
    .validate()?;
    Ok(b)
}

/// The JSON document of the robust answer.
#[derive(Serialize)]
struct Report<'a> {
    r#box: &'a RobustBox,
    design: &'a RobustDesign,
    /// The user's own V (--included-angle or --flank-angles), if given.
    given_v: Option<GivenV>,
    standard_v_blocks: Vec<GivenV>,
    inputs: &'a LocatorParams,
}

/// One V's verdict over the box.
#[derive(Serialize)]
struct GivenV {
    included_angle_deg: f64,
    verdict: BoxVerdict,
}

/// The robust answer, text or JSON. `given` is the user's own included angle, if any.
pub fn run(
    p: &LocatorParams,
    uncertain: &UncertainSet,
    given: Option<f64>,
    format: VlocatorFormat,
) -> Result<String> {
    let b = robust_box(p, uncertain)?;
    let d = robust_design(p, &b);
    let check = |g: f64| GivenV {
        included_angle_deg: g,
        verdict: verdict_over_box(p, &b, g),
    };
    let given_v = given.map(check);
    let standard: Vec<GivenV> = STANDARD_V_DEG.into_iter().map(check).collect();
    Ok(match format {
        VlocatorFormat::Json => {
            let report = Report {
                r#box: &b,
                design: &d,
                given_v,
                standard_v_blocks: standard,
                inputs: p,
            };
            let mut text = serde_json::to_string_pretty(&report).expect("the report serialises");
            text.push('\n');
            text
        }
        VlocatorFormat::Text => text(p, &b, &d, given_v.as_ref(), &standard),
    })
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
fn text(
    p: &LocatorParams,
    b: &RobustBox,
    d: &RobustDesign,
    given: Option<&GivenV>,
    standard: &[GivenV],
) -> String {
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
    let weight = |m: f64| m * p.gravity_m_s2;
    let disc = match b.mass_kg.0 == b.mass_kg.1 {
        true => format!("W = {:.3} N", Num(weight(b.mass_kg.0))),
        false => format!(
            "m {} (W = {:.3} to {:.3} N)",
            range(b.mass_kg, " kg"),
            Num(weight(b.mass_kg.0)),
            Num(weight(b.mass_kg.1))
        ),
    };
    let _ = writeln!(
        out,
        "robust V-block over {flanks}, load {} at {} {at}; {disc}, {} rotation",
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
                                format!("mu from {} up to {:.4} at most", Num(b.mu_left.0), Num(m))
                            }
                            false => {
                                format!("no flank's friction above {:.4}, the lows kept", Num(m))
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

/// Where the load acts: "at the centre" or "at the rim point 30 deg".
pub(super) fn load_point(p: &LocatorParams) -> String {
    match p.load_at_rim_deg {
        Some(psi) => format!("at the rim point {} deg", Num(psi)),
        None => "at the centre".to_string(),
    }
}
