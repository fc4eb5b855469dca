//! `jamchart design`: the inverse questions over uncertain inputs ([`crate::design`]), each
//! closed form checked by the nonsmooth simulation (force drive).

use std::fmt::Write;

use clap::Args;
use serde::Serialize;

use super::args::{OutputFormat, SceneArgs, parse_f64};
use crate::design::{self, AvoidJams, Carry, Design, DesignBox, LeastPush};
use crate::dynamics::{Drive, DynamicsParams, Method};
use crate::error::{Error, Result};
use crate::models::{self, ModelKind, ModelSpec, OutsideModel};
use crate::numbers::{Num, fixed};
use crate::scene::SceneParams;
use crate::uncertain::UncertainSet;

settings! {
    /// The flag of `design`'s target, by the key its messages name.
    section = "design";
    aliases DESIGN_FLAGS {
        x_target_mm, flag: Some("x-target");
    }
}

/// Flags of `design`.
#[derive(Debug, Clone, Args)]
pub struct DesignArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Target disc position x in mm (from the hinge): carry the part at least this far.
    ///
    /// Above x(90 deg) = r + h, the position at a right-angled palm.
    #[arg(long = flag!(DESIGN_FLAGS, x_target_mm), value_name = "MM", allow_negative_numbers = true,
          value_parser = parse_f64)]
    pub x_target: f64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
}

/// A closed-form answer and the nonsmooth simulation of the same scene.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SimCheck {
    /// The scene's push, N, and friction (both), at which it was simulated.
    pub force_n: f64,
    /// mu_ground, mu_palm simulated.
    pub mu: (f64, f64),
    /// x_jam by the closed form, mm.
    pub x_jam_closed_form_mm: Option<f64>,
    /// x_jam by the nonsmooth simulation (force drive), mm.
    pub x_jam_nonsmooth_mm: Option<f64>,
    /// The simulated jam when the disc coasts past the closed form's by more than
    /// [`COAST_TOLERANCE`], mm: a palm sized by the closed form would lose it at the drive's speed.
    pub coasts_to_mm: Option<f64>,
}

/// The JSON document.
#[derive(Serialize)]
struct Report<'a> {
    design: &'a Design,
    earliest_corner: &'a SceneParams,
    latest_corner: &'a SceneParams,
    check_least_push: Option<SimCheck>,
    check_latest_jam: Option<SimCheck>,
    uncertain: &'a UncertainSet,
}

/// The box's two corners: each uncertain input at the end that jams earliest (frictions and
/// mass high, push low) or latest (the other ends); a distribution by its 0.1 % quantiles.
fn corners(p: &SceneParams, u: &UncertainSet) -> DesignBox {
    let pick = |earliest: bool| -> Vec<f64> {
        u.inputs
            .iter()
            .map(|i| {
                let (lo, hi) = i.value.ends();
                let high = if i.name == "force_n" {
                    !earliest
                } else {
                    earliest
                };
                if high { hi } else { lo }
            })
            .collect()
    };
    DesignBox {
        earliest: u.apply(p, &pick(true)),
        latest: u.apply(p, &pick(false)),
    }
}

/// The nonsmooth simulation (force drive) of `p`, against its closed form.
fn check(p: &SceneParams, dynamics: &DynamicsParams) -> Result<SimCheck> {
    let mut d = *dynamics;
    d.integrator.method = Method::Nonsmooth;
    d.drive.mode = Drive::Force;
    let spec = ModelSpec::Dynamics {
        params: d,
        series_dt_s: None,
    };
    let sim = models::solve(&spec, p)?;
    let x_jam_closed_form_mm = crate::statics::solve(p).x_jam_mm;
    let coasts_to_mm = match (x_jam_closed_form_mm, sim.x_jam_mm) {
        (Some(x_cf), Some(x_sim)) if x_sim > x_cf * (1.0 + COAST_TOLERANCE) => Some(x_sim),
        _ => None,
    };
    Ok(SimCheck {
        force_n: p.force_n,
        mu: (p.mu_ground, p.mu_palm),
        x_jam_closed_form_mm,
        x_jam_nonsmooth_mm: sim.x_jam_mm,
        coasts_to_mm,
    })
}

/// Runs `design`.
pub fn run(args: &DesignArgs) -> Result<String> {
    let (config, uncertain) = args.scene.resolve_uncertain(&[])?;
    let x_t = args.x_target;
    if !(x_t.is_finite() && x_t > 0.0) {
        return Err(Error::invalid(
            "x_target_mm",
            x_t,
            "the target position is a finite distance from the hinge > 0 mm",
        ));
    }
    let b = corners(&config.scene, &uncertain);
    for corner in [&b.earliest, &b.latest] {
        corner.validate()?;
    }
    // The closed form answers a push starting at 90 deg or below, as `solve` does: above it
    // the answer is the port's outside_model, with its reason (no input moves the start).
    if let Some(why) = models::outside(ModelKind::Statics, &b.earliest) {
        return Ok(outside(args.format, &why));
    }
    let Some(d) = design::design(&b, x_t) else {
        return Err(Error::invalid(
            "x_target_mm",
            x_t,
            format!(
                "the disc is at x = {:.3} mm already at a right-angled palm (r + h); give a \
                 target beyond it",
                Num(config.scene.disc_position_mm(std::f64::consts::FRAC_PI_2))
            ),
        ));
    };
    let check_least_push = match d.carry {
        Carry::Ahead {
            least_push: LeastPush::Push { force_n },
            ..
        } => Some(check(
            &SceneParams {
                force_n,
                ..b.earliest
            },
            &config.dynamics,
        )?),
        _ => None,
    };
    // Simulated on a palm twice the closed form's length, so that a jam past this palm's end
    // is still located: the force drive's disc runs on past the closed form's jam (112.6 mm
    // against 99.3 mm for the 25 mm shaft at mu 0.12, 40 N), and 10 % more palm lost it.
    let check_latest_jam = d
        .palm_length_keeping_jams_on_mm
        .map(|l| {
            let long = SceneParams {
                palm_length_mm: b.latest.palm_length_mm.max(2.0 * l),
                ..b.latest
            };
            check(&long, &config.dynamics)
        })
        .transpose()?;
    Ok(match args.format {
        OutputFormat::Json => {
            let report = Report {
                design: &d,
                earliest_corner: &b.earliest,
                latest_corner: &b.latest,
                check_least_push,
                check_latest_jam,
                uncertain: &uncertain,
            };
            let mut s = serde_json::to_string_pretty(&report).expect("the report serialises");
            s.push('\n');
            s
        }
        OutputFormat::Text => text(
            &b,
            &d,
            &uncertain,
            check_least_push.as_ref(),
            check_latest_jam.as_ref(),
        ),
    })
}

/// The answer for a scene outside the closed form: the port's status and reason.
fn outside(format: OutputFormat, why: &OutsideModel) -> String {
    match format {
        OutputFormat::Json => {
            #[derive(Serialize)]
            struct Outside<'a> {
                status: crate::scene::JamStatus,
                #[serde(flatten)]
                why: &'a OutsideModel,
            }
            let doc = Outside {
                status: crate::scene::JamStatus::OutsideModel,
                why,
            };
            serde_json::to_string_pretty(&doc).expect("the answer serialises") + "\n"
        }
        OutputFormat::Text => format!("design: outside_model\n  not run: {why}\n"),
    }
}

/// How far the simulated jam may lie from the closed form's before the answer says so. The
/// nonsmooth force drive meets an independent rigid ODE to 5e-6 (tests/force_drive_rest.rs), so
/// a gap of 0.5 % is the disc's coast at the drive's speed, not the method's error.
const COAST_TOLERANCE: f64 = 0.005;

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
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg,
            x_rigid_mm,
        } => format!(
            "least push: none: at mu_ground {} / mu_palm {} the friction wedge locks at {:.3} deg \
             (x = {x_rigid_mm:.3} mm) before the target whatever the push; lower the friction \
             or move the target nearer",
            Num(e.mu_ground),
            Num(e.mu_palm),
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
        Num(c.mu.0),
        Num(c.mu.1),
        mm(c.x_jam_closed_form_mm),
        mm(c.x_jam_nonsmooth_mm)
    )
}

fn text(
    b: &DesignBox,
    d: &Design,
    u: &UncertainSet,
    push: Option<&SimCheck>,
    late: Option<&SimCheck>,
) -> String {
    let mut out = String::new();
    let over = if u.is_empty() {
        "the given point".to_string()
    } else {
        format!("every value of {}", u.describe())
    };
    let e = &b.earliest;
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
        Num(e.mu_ground),
        Num(e.mu_palm),
        Num(e.mass_kg),
        Num(e.force_n),
        Num(b.latest.mu_ground),
        Num(b.latest.mu_palm),
        Num(b.latest.mass_kg),
        Num(b.latest.force_n)
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
                "the disc starts at x = {:.3} mm, at or past the target: it is there before the \
                 palm moves, whatever the push and the friction (and held there if it jams at \
                 once); no least push or largest friction applies",
                Num(x_start_mm)
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
                if let (Some(x_cf), Some(x_sim)) = (c.x_jam_closed_form_mm, c.x_jam_nonsmooth_mm)
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
            let mu = |v: Option<f64>| v.map_or("none".into(), |m| format!("{m:.4}", m = Num(m)));
            let _ = writeln!(
                out,
                "largest friction for the push F = {} N: mu_ground up to {} (mu_palm {}; closed \
                 form), or mu up to {} on both",
                Num(e.force_n),
                mu(mu_ground_max),
                Num(e.mu_palm),
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
                "palm length that keeps every jam on the palm: none: at the latest corner the \
                 disc never jams"
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
