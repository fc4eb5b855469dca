//! `jamchart vlocator` with a friction or load range: the robust V-block
//! ([`crate::locator::robust`]), the window of included angles that works over the whole box.

use std::fmt::Write;

use serde::Serialize;

use super::vlocator::VlocatorFormat;
use crate::error::{Error, Result};
use crate::locator::{
    BoxVerdict, LocatorParams, RobustBox, RobustDesign, robust_design, verdict_over_box,
};
use crate::numbers::Num;
use crate::uncertain::{Uncertain, UncertainSet};

/// The standard V-blocks the answer checks, deg.
const STANDARD_V_DEG: [f64; 3] = [60.0, 90.0, 120.0];

/// The box of `p`'s nominal V from the uncertain inputs: a friction range on both flanks
/// (`mu`), a load range (`load_n`) and a direction range (`load_angle_deg`); every other
/// uncertain input is refused naming it.
pub fn robust_box(p: &LocatorParams, uncertain: &UncertainSet) -> Result<RobustBox> {
    let mut b = RobustBox {
        mu: (p.mu_left, p.mu_right),
        load_n: (p.load_n, p.load_n),
        load_angle_deg: (p.load_angle_deg, p.load_angle_deg),
    };
    one_friction_range(p, uncertain)?;
    for i in &uncertain.inputs {
        let Uncertain::Range { lo, hi } = i.value else {
            return Err(Error::invalid(
                i.name,
                i.value,
                "a robust V-block holds every value of a range: give LOW:HIGH (a \
                 distribution's probabilities are not asked here)",
            ));
        };
        match i.name {
            "mu" if i.keys.len() == 2 => b.mu = (lo, hi),
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
                    "a robust V-block takes ranges of --mu (both flanks), --load and \
                     --load-angle; give this one as a number",
                ));
            }
        }
    }
    Ok(b)
}

/// Refuses friction that is not one range on both flanks, naming the flank flag that breaks
/// it: `--mu 0.2:0.4 --mu-left 0.3` named `--mu` (and showed "0.3 left, 0.3 right", the range's
/// midpoint 0.30000000000000004 beside 0.3), where the conflict is `--mu-left`.
fn one_friction_range(p: &LocatorParams, uncertain: &UncertainSet) -> Result<()> {
    const FLANKS: [&str; 2] = ["mu_left", "mu_right"];
    let value = |k: &str| match uncertain.inputs.iter().find(|i| i.name == k) {
        Some(i) => i.value.to_string(),
        None => Num(if k == "mu_left" {
            p.mu_left
        } else {
            p.mu_right
        })
        .to_string(),
    };
    let refuse = |k: &str, why: String| {
        let flag = format!("--{}", k.replace('_', "-"));
        Err(Error::invalid(
            k,
            value(k),
            format!(
                "{why}; a robust V-block takes one friction range for both flanks: give --mu \
                 LOW:HIGH alone, without {flag} (unequal flanks are not searched)"
            ),
        ))
    };
    let side = |k: &str| k.trim_start_matches("mu_").to_string();
    for i in &uncertain.inputs {
        match i.name {
            // --mu's range with a flank's own flag beside it: that flank keeps its own value.
            "mu" => {
                if let Some(k) = FLANKS.into_iter().find(|k| !i.keys.contains(k)) {
                    let why = format!(
                        "--{} {} keeps the {} flank off --mu's range {}",
                        k.replace('_', "-"),
                        value(k),
                        side(k),
                        i.value
                    );
                    return refuse(k, why);
                }
            }
            k if FLANKS.contains(&k) => {
                return refuse(k, format!("a range on the {} flank alone", side(k)));
            }
            _ => {}
        }
    }
    if p.mu_left != p.mu_right {
        // Point frictions that differ: the flank that is not at its default was given.
        let k = match p.mu_left == LocatorParams::default().mu_left {
            true => "mu_right",
            false => "mu_left",
        };
        let why = format!(
            "the flanks' frictions differ ({} left, {} right)",
            Num(p.mu_left),
            Num(p.mu_right)
        );
        return refuse(k, why);
    }
    Ok(())
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
fn describe(v: &BoxVerdict) -> String {
    match v {
        BoxVerdict::Works => "works: holds every load at every friction, never locks".into(),
        BoxVerdict::Locks { mu } => format!("self-locks at mu = {mu}"),
        BoxVerdict::Drops { load } => format!(
            "drops {:.3} N at {:.2} deg (at the lowest friction): the part {}",
            Num(load.load_n),
            Num(load.load_angle_deg),
            load.mode.describe()
        ),
    }
}

fn range(lo: f64, hi: f64, unit: &str) -> String {
    if lo == hi {
        format!("{lo}{unit}")
    } else {
        format!("{lo} to {hi}{unit}")
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
    let at = super::vlocator::load_point(p);
    let _ = writeln!(
        out,
        "robust V-block over mu {} (both flanks), load {} at {} {at}; W = {:.3} N, {} rotation",
        range(b.mu.0, b.mu.1, ""),
        range(b.load_n.0, b.load_n.1, " N"),
        range(b.load_angle_deg.0, b.load_angle_deg.1, " deg"),
        Num(p.weight_n()),
        p.rotation.as_str()
    );
    let _ = writeln!(
        out,
        "a V works when it holds every load at the lowest friction, mu = {}, and does not \
         self-lock at the highest, mu = {} (narrower than {:.2} deg locks)",
        b.mu.0,
        b.mu.1,
        Num(d.lock_bound_deg)
    );
    match d.windows.as_slice() {
        [] => {
            let _ = writeln!(
                out,
                "no single V works over this range: every V that does not lock at mu = {} \
                 drops a load",
                b.mu.1
            );
            if let Some(load) = d.dropped_at_lock_bound {
                let _ = writeln!(
                    out,
                    "  the narrowest V that does not lock, {:.2} deg, {}",
                    Num(d.lock_bound_deg),
                    describe(&BoxVerdict::Drops { load })
                );
            }
            if let Some(o) = d.opening {
                let _ = writeln!(out, "what would open a window:");
                match o.mu_hi_max {
                    Some(m) => {
                        let _ = writeln!(
                            out,
                            "  a narrower friction range: mu from {} up to {m:.4} at most (a \
                             {:.2} deg V then works)",
                            b.mu.0,
                            Num(2.0 * m.atan().to_degrees()),
                            m = Num(m)
                        );
                    }
                    None => {
                        let _ = writeln!(
                            out,
                            "  no friction range from mu = {} does: even a single friction \
                             leaves no V that holds these loads",
                            b.mu.0
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
            describe(&g.verdict)
        );
    }
    for s in standard {
        let _ = writeln!(
            out,
            "standard {:.0} deg V-block: {}",
            Num(s.included_angle_deg),
            describe(&s.verdict)
        );
    }
    out
}
