//! `jamchart solve`: the read-off of theta_jam and x_jam, every model through the port
//! ([`crate::models`]); text and JSON are printed from the typed solutions.

use std::fmt::Write;
use std::path::PathBuf;

use clap::Args;
use serde::Serialize;

use super::args::{ModelChoice, OutputFormat, SceneArgs};
use super::dynamics::{self, DynamicsArgs};
use super::min_norm;
use super::solve_range::{self, DistArgs};
use crate::config::Config;
use crate::design::LeastPush;
use crate::error::{Error, Result};
use crate::models::{self, Detail, ModelKind, ModelSpec, OutsideModel, Solution};
use crate::numbers::{Num, fixed};
use crate::scene::{JamStatus, SceneParams};
use crate::settings::flags::{Flags, MinNormSet};
use crate::statics::{self, StaticsSolution};

/// Sampling interval of `--series` in s: 0.2 ms resolves the collapse at the jam (a few ms).
const SERIES_DT_S: f64 = 2e-4;

/// Flags of `solve`.
#[derive(Debug, Clone, Args)]
pub struct SolveArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub dynamics: DynamicsArgs,
    /// Write the dynamics time series to this CSV file (t, theta, x, x_dot, forces, penetration).
    ///
    /// Sampled every 0.2 ms: the data of the paper's Fig. 5. Use --after-jam to see the disc stop.
    #[arg(long, value_name = "FILE.csv", help_heading = "Dynamics")]
    pub series: Option<PathBuf>,
    /// Model to use.
    #[arg(long, value_enum, default_value_t = ModelChoice::One(ModelKind::Statics))]
    pub model: ModelChoice,
    #[command(flatten)]
    pub distribution: DistArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
    #[command(flatten)]
    pub min_norm: Flags<MinNormSet>,
    /// Print the min-norm solver's convergence trace at theta_jam (the paper's Fig. 4).
    ///
    /// clarabel's objective phi^2 (N^2) and relative primal and dual residuals per
    /// interior-point iteration; in JSON the array `trace`.
    #[arg(long)]
    pub trace: bool,
}

/// One model's answer with what `solve` asked of it beyond the port: the min-norm trace.
struct Answer {
    solution: Solution,
    trace: Option<min_norm::Trace>,
}

/// One model's answer in `solve`'s JSON: the port's form of the solution
/// ([`crate::models::Solution`]), then what `solve` asked beyond it (a min-norm trace; a
/// simulation's series, settings and advice).
#[derive(Serialize)]
struct Record<'a> {
    #[serde(flatten)]
    solution: &'a Solution,
    #[serde(flatten)]
    asked: Asked<'a>,
}

/// What `solve` adds to a model's answer.
#[derive(Serialize)]
#[serde(untagged)]
enum Asked<'a> {
    Nothing {},
    MinNorm(min_norm::Record<'a>),
    Dynamics(dynamics::Record<'a>),
}

/// The JSON document of `solve --format json`.
#[derive(Serialize)]
struct Document<'a> {
    inputs: &'a SceneParams,
    results: Vec<Record<'a>>,
}

pub fn run(a: &SolveArgs) -> Result<String> {
    let (config, uncertain) = a
        .scene
        .resolve_uncertain(&[a.dynamics.overrides(), a.min_norm.overrides()])?;
    solve_range::check_distribution_flags(&a.distribution, &uncertain)?;
    if !uncertain.is_empty() {
        if a.series.is_some() || a.trace {
            return Err(Error::Conflict {
                flag: if a.trace { "--trace" } else { "--series" },
                message: "--series and --trace follow one push; give single values with them, \
                          not a range"
                    .into(),
            });
        }
        return solve_range::run(
            a.model.models(),
            &a.distribution,
            a.format,
            &config,
            &uncertain,
        );
    }
    let kinds = a.model.models();
    if let Some(path) = &a.series {
        if !kinds.contains(&ModelKind::Dynamics) {
            return Err(Error::Conflict {
                flag: "--series",
                message: "--series needs the dynamics: add --model dynamics".into(),
            });
        }
        // Before the simulation runs: a path that will be refused is refused now, and a series
        // too long to hold is refused by its estimate.
        crate::atomic::check_all([path.as_path()])?;
        let rows = crate::limits::series_rows(
            config.scene.start_angle_deg,
            config.dynamics.drive.omega_deg_s,
            SERIES_DT_S,
        );
        crate::limits::check_items("--omega (omega_deg_s)", rows, crate::limits::SERIES_ROW)?;
    }
    let mut answers = Vec::new();
    for kind in kinds {
        let mut spec = kind.with(&config.min_norm, &config.dynamics);
        if let ModelSpec::Dynamics { series_dt_s, .. } = &mut spec {
            *series_dt_s = a.series.as_ref().map(|_| SERIES_DT_S);
        }
        let solution = models::solve(&spec, &config.scene)?;
        let trace = match &solution.detail {
            Detail::MinNorm(s) if a.trace => Some(min_norm::trace(&config, s)?),
            _ => None,
        };
        if let (Detail::Dynamics(s), Some(path)) = (&solution.detail, &a.series) {
            dynamics::write_series(&config, s, path)?;
        }
        answers.push(Answer { solution, trace });
    }
    Ok(match a.format {
        OutputFormat::Json => {
            let doc = Document {
                inputs: &config.scene,
                results: answers.iter().map(|x| record(x, &config, a)).collect(),
            };
            serde_json::to_string_pretty(&doc).expect("plain structs serialise") + "\n"
        }
        OutputFormat::Text => render_text(&config, &answers, a.series.as_deref()),
    })
}

/// The JSON record of one answer.
fn record<'a>(x: &'a Answer, config: &'a Config, a: &SolveArgs) -> Record<'a> {
    let asked = match &x.solution.detail {
        Detail::MinNorm(_) => x
            .trace
            .as_ref()
            .map_or(Asked::Nothing {}, |t| Asked::MinNorm(min_norm::record(t))),
        Detail::Dynamics(d) => Asked::Dynamics(dynamics::record(d, config, a.series.as_deref())),
        Detail::Statics(_) | Detail::Outside(_) => Asked::Nothing {},
    };
    Record {
        solution: &x.solution,
        asked,
    }
}

/// A statics answer that knows where the jam past the palm's end would be.
fn has_past_palm(d: &Detail) -> bool {
    matches!(d, Detail::Statics(d) if d.past_palm.is_some())
}

/// The statics' own lines: the F -> inf limit and a lift-off warning.
fn render_statics(s: &mut String, d: &StaticsSolution, p: &SceneParams) {
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
             a palm of at least {} mm (--palm-length)",
            fixed(past.theta_jam_deg, 3),
            fixed(past.x_jam_mm, 3),
            fixed(past.palm_length_needed_mm, 3)
        );
        let more = match past.friction_factor_needed {
            Some(k) if p.mu_ground == p.mu_palm => {
                format!("mu >= {:.4} (--mu)", Num(k * p.mu_ground))
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

fn render_text(config: &Config, answers: &[Answer], series: Option<&std::path::Path>) -> String {
    let p = &config.scene;
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
    for x in answers {
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
                let _ = writeln!(s, "  {}", too_weak_advice(p));
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
                let _ = writeln!(
                    s,
                    "  the jam point lies beyond the palm's end ({} mm), or the disc starts past \
                     it: the palm loses the disc first",
                    Num(p.palm_length_mm)
                );
            }
            _ => {}
        }
        match &r.detail {
            Detail::Statics(d) => render_statics(&mut s, d, p),
            Detail::MinNorm(d) => min_norm::render_details(&mut s, d, x.trace.as_ref()),
            Detail::Dynamics(d) => dynamics::render_details(&mut s, d, config, series),
            Detail::Outside(why) => {
                let _ = writeln!(s, "  not run: {why}");
                if let OutsideModel::PalmLiftsDisc { .. } = why {
                    let _ = writeln!(s, "  advice: {}", dynamics::LIFTS_DISC_ADVICE);
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
    if answers.len() > 1 {
        s.push_str(&super::guidance::guidance(
            config,
            answers.iter().map(|x| &x.solution),
        ));
    }
    s
}

/// What it takes to slide a disc the push cannot move: the least push that slides it from the
/// start angle ([`crate::design::least_push`] at the start), which is more than the least push
/// that moves it at all where the wedge would hold it at the start, and none where the wedge
/// alone, atan mu_ground + atan mu_palm, reaches the start angle: more push then only holds it
/// there (at 1000 N as at 20 N for mu 0.9 and a start at 80 deg).
fn too_weak_advice(p: &SceneParams) -> String {
    let moves = statics::least_push_n(p);
    let head = "the push cannot move the disc at any palm angle";
    if !moves.is_finite() {
        // A weight past the float range (--mass 1e308) made the least push inf N.
        return format!(
            "{head}: the weight m g is beyond the range of a 64-bit float, and no finite push \
             moves it"
        );
    }
    match crate::design::least_push(p, p.start_angle_deg.to_radians()) {
        LeastPush::AnyPushThatMoves { .. } => format!(
            "{head}: it takes more than m g sin(atan mu_ground) = {:.4} N (--force), or less \
             ground friction",
            Num(moves)
        ),
        LeastPush::Push { force_n } => format!(
            "{head}: above m g sin(atan mu_ground) = {:.4} N it moves but is held at the start \
             angle; it slides from there above {:.4} N (--force), or with less friction",
            Num(moves),
            Num(force_n)
        ),
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg, ..
        } => format!(
            "{head}, and no push slides it: above m g sin(atan mu_ground) = {:.4} N it moves, \
             but the friction wedge atan mu_ground + atan mu_palm = {:.2} deg holds it at the \
             start angle {} deg; lower the frictions (--mu-ground, --mu-palm) until the wedge is \
             below the start angle{}",
            Num(moves),
            theta_rigid_deg,
            Num(p.start_angle_deg),
            if theta_rigid_deg < 90.0 {
                " or start the palm above the wedge (--start-angle, at most 90 deg)"
            } else {
                ""
            }
        ),
    }
}
