//! `jamchart vlocator`: a disc in a V-block, its verdict, forces, capacity and optimum angle.

use std::fmt::Write;

use clap::Args;
use serde::Serialize;

use super::args::{VlocatorFormat, parse_f64};
use super::vlocator_robust::{self, load_point};
use crate::error::{Error, Result};
use crate::locator::{
    self, Capacity, FlankForce, LocatorParams, LocatorSolution, OPT_MAX_DEG, OPT_MIN_DEG, Optimum,
    Verdict,
};
use crate::numbers::Num;
use crate::settings::flags::{Flags, LocatorSet};
use crate::uncertain::UncertainSet;

settings! {
    /// The V's geometry flags: each sets both flank angles (a symmetric V, or the two given).
    section = "locator";
    aliases GEOMETRY_FLAGS {
        flank_angles, flag: Some("flank-angles"), sets: &["flank_left_deg", "flank_right_deg"];
        included_angle_deg, flag: Some("included-angle"),
            sets: &["flank_left_deg", "flank_right_deg"];
    }
}

/// Flags of `vlocator`: the V's geometry, then the declared locator settings
/// ([`crate::settings`]: frictions, disc, load, rotation).
#[derive(Debug, Clone, Args)]
pub struct VlocatorArgs {
    /// Included angle of a symmetric V in deg, in (0, 180) [default: 90 deg].
    ///
    /// With a range (a design over the box) it is your V, whose verdict is added (`given_v`);
    /// left out, no V of your own is judged.
    #[arg(
        long = flag!(GEOMETRY_FLAGS, included_angle_deg),
        value_name = "DEG",
        allow_negative_numbers = true,
        conflicts_with = "flank_angles",
        value_parser = parse_f64
    )]
    pub included_angle: Option<f64>,
    /// Flank angles a1,a2 above the horizontal in deg (left, right).
    ///
    /// Each in [0, 180) with a1 + a2 < 180; above 90 a flank overhangs. The included angle
    /// is 180 - a1 - a2 [default: 45,45]. With a range it is your V, judged over the box
    /// (`given_v`); left out, no V of your own is judged.
    #[arg(
        long = flag!(GEOMETRY_FLAGS, flank_angles),
        value_name = "A1,A2",
        value_delimiter = ',',
        // "-5,40" is not a number: without this clap reads it as a flag.
        allow_hyphen_values = true,
        value_parser = parse_f64
    )]
    pub flank_angles: Option<Vec<f64>>,
    #[command(flatten)]
    pub locator: Flags<LocatorSet>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = VlocatorFormat::Text)]
    pub format: VlocatorFormat,
}

impl VlocatorArgs {
    /// The parameters with the nominal values of the flags' ranges and distributions, and
    /// those inputs ([`crate::uncertain`]); validated.
    pub fn params_uncertain(&self) -> Result<(LocatorParams, UncertainSet)> {
        let mut p = LocatorParams::default();
        if let Some(g) = self.included_angle {
            if !(g.is_finite() && g > 0.0 && g < 180.0) {
                return Err(Error::invalid(
                    "included_angle_deg",
                    g,
                    "the included angle of a V lies in (0, 180) deg",
                ));
            }
            p = p.with_included_angle(g);
        }
        if let Some(a) = &self.flank_angles {
            let [a1, a2] = a[..] else {
                let text: Vec<String> = a.iter().map(f64::to_string).collect();
                return Err(Error::invalid(
                    "flank_angles",
                    text.join(","),
                    "give two angles, left and right, e.g. 30,60",
                ));
            };
            p.flank_left_deg = a1;
            p.flank_right_deg = a2;
        }
        let over = self.locator.overrides();
        let mut over = over
            .get("locator")
            .and_then(toml::Value::as_table)
            .cloned()
            .unwrap_or_default();
        let uncertain = crate::uncertain::take(&mut over, crate::settings::locator_family())?;
        let p: LocatorParams = crate::config::overlay(&p, &over, "locator")?;
        p.validate()?;
        super::warn(&p.unit_warnings());
        Ok((p, uncertain))
    }
}

/// The JSON document: the verdict, forces, capacity and optimum, then the inputs.
#[derive(Serialize)]
struct Report<'a> {
    verdict: &'static str,
    self_locking: bool,
    locking_needed: bool,
    friction_held: bool,
    forces: Option<&'a [FlankForce; 2]>,
    capacity: &'a Capacity,
    optimum: &'a Optimum,
    inputs: &'a LocatorParams,
}

/// Runs `vlocator`: the text or JSON answer.
pub fn run(args: &VlocatorArgs) -> Result<String> {
    let (p, uncertain) = args.params_uncertain()?;
    if !uncertain.is_empty() {
        let given = (args.included_angle.is_some() || args.flank_angles.is_some())
            .then(|| p.included_angle_deg());
        return vlocator_robust::run(&p, &uncertain, given, args.format);
    }
    let s = locator::solve(&p)?;
    Ok(match args.format {
        VlocatorFormat::Json => {
            let report = Report {
                verdict: s.verdict.as_str(),
                self_locking: s.self_locking,
                locking_needed: s.locking_needed,
                friction_held: s.friction_held,
                forces: s.forces.as_ref(),
                capacity: &s.capacity,
                optimum: &s.optimum,
                inputs: &p,
            };
            let mut text = serde_json::to_string_pretty(&report).expect("the report serialises");
            text.push('\n');
            text
        }
        VlocatorFormat::Text => text(&p, &s),
    })
}

/// The answer for a person, units on every number.
fn text(p: &LocatorParams, s: &LocatorSolution) -> String {
    let mut out = String::new();
    let w = p.weight_n();
    let at = load_point(p);
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
        "weight W = {w:.3} N; load P = {} N at {} deg {at}",
        Num(p.load_n),
        Num(p.load_angle_deg),
        w = Num(w)
    );
    let verdict = match s.verdict {
        Verdict::Wedged => {
            "wedged: the V self-locks; it holds any load, the part can jam and needs a pull to \
             come out"
                .to_string()
        }
        Verdict::Slips { mode } => format!("slips: no equilibrium, the part {}", mode.describe()),
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
             V must hold (--load, --load-angle) to size it"
        );
    }
    out
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
