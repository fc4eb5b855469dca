//! `jamchart solve`: the read-off of theta_jam and x_jam.

use std::fmt::Write;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use serde::Serialize;
use serde_json::{Map, Value, json};

use super::args::{Model, ModelChoice, OutputFormat, SceneArgs};
use super::dynamics::{self, DynamicsArgs};
use super::min_norm;
use crate::config::Config;
use crate::error::{Error, Result};
use crate::model::JamStatus;
use crate::statics;

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
    #[arg(long, value_enum, default_value_t = ModelChoice::Statics)]
    pub model: ModelChoice,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
    /// Min-norm formulation: how the disc's moment is carried.
    ///
    /// translational (the paper's): the disc rides a translational joint that carries the
    /// moment; rolling: the disc may rotate and friction at the ground and the palm carries it.
    /// Overrides [min_norm] formulation of --config [default: translational]
    #[arg(long, value_enum, value_name = "FORMULATION")]
    pub formulation: Option<min_norm::FormulationArg>,
    /// Print the min-norm solver's convergence trace at theta_jam (the paper's Fig. 4).
    ///
    /// clarabel's objective phi^2 (N^2) and relative primal and dual residuals per
    /// interior-point iteration; in JSON the array `trace`.
    #[arg(long)]
    pub trace: bool,
}

/// One model's answer as `solve` prints it; `details` holds the model's own extra keys.
#[derive(Debug, Clone, Serialize)]
pub struct ModelRecord {
    pub model: &'static str,
    pub status: JamStatus,
    pub theta_jam_deg: Option<f64>,
    pub x_jam_mm: Option<f64>,
    pub elapsed_s: f64,
    #[serde(flatten)]
    pub details: Map<String, Value>,
}

pub fn run(a: &SolveArgs) -> Result<String> {
    let config = a.scene.resolve_with(|c| {
        a.dynamics.apply(c);
        if let Some(f) = a.formulation {
            c.min_norm.formulation = f.into();
        }
    })?;
    let models = a.model.models();
    if a.series.is_some() && !models.contains(&Model::Dynamics) {
        return Err(Error::Unsupported(
            "--series needs the dynamics: add --model dynamics".into(),
        ));
    }
    let results = models
        .iter()
        .map(|m| match m {
            Model::Statics => Ok(statics_record(&config)),
            Model::MinNorm => min_norm::record(&config, a.trace),
            Model::Dynamics => dynamics::record(&config, a.series.as_deref()),
        })
        .collect::<Result<Vec<ModelRecord>>>()?;
    Ok(match a.format {
        OutputFormat::Json => {
            let doc = json!({ "inputs": config.scene, "results": results });
            serde_json::to_string_pretty(&doc).expect("plain structs serialise") + "\n"
        }
        OutputFormat::Text => render_text(&config, &results),
    })
}

/// The closed form's record: the statics' keys plus the F -> inf limit and lift-off.
fn statics_record(config: &Config) -> ModelRecord {
    let t0 = Instant::now();
    let s = statics::solve(&config.scene);
    let elapsed_s = t0.elapsed().as_secs_f64();
    let mut details = Map::new();
    details.insert("theta_rigid_deg".into(), json!(s.theta_rigid_deg));
    details.insert("x_rigid_mm".into(), json!(s.x_rigid_mm));
    details.insert("lift_off_above_deg".into(), json!(s.lift_off_above_deg));
    details.insert("lifts_off".into(), json!(s.lifts_off));
    ModelRecord {
        model: Model::Statics.name(),
        status: s.status,
        theta_jam_deg: s.theta_jam_deg,
        x_jam_mm: s.x_jam_mm,
        elapsed_s,
        details,
    }
}

/// The statics' own lines: the F -> inf limit and a lift-off warning.
fn render_statics(s: &mut String, d: &Map<String, Value>) {
    if let (Some(t), Some(x)) = (
        d.get("theta_rigid_deg").and_then(Value::as_f64),
        d.get("x_rigid_mm").and_then(Value::as_f64),
    ) {
        let _ = writeln!(
            s,
            "  x_rigid   = {x:.3} mm, theta_rigid = {t:.3} deg: the limit of an unlimited push \
             (F -> inf, a motion-driven palm)"
        );
    }
    if d.get("lifts_off").and_then(Value::as_bool) == Some(true)
        && let Some(above) = d.get("lift_off_above_deg").and_then(Value::as_f64)
    {
        let _ = writeln!(
            s,
            "  warning: above {above:.3} deg the palm lifts the disc off the ground (R_n < 0); \
             the statics do not hold there"
        );
    }
}

fn render_text(config: &Config, results: &[ModelRecord]) -> String {
    let p = &config.scene;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "scene: mu_ground = {}, mu_palm = {}, r = {} mm, m = {} kg, F = {} N, g = {} m/s^2, \
         start at {} deg, palm {} mm",
        p.mu_ground,
        p.mu_palm,
        p.radius_mm,
        p.mass_kg,
        p.force_n,
        p.gravity_m_s2,
        p.start_angle_deg,
        p.palm_length_mm
    );
    for r in results {
        let _ = writeln!(s, "\n{}: {}", r.model, r.status);
        match (r.status, r.theta_jam_deg, r.x_jam_mm) {
            (JamStatus::Jams, Some(t), Some(x)) => {
                let _ = writeln!(
                    s,
                    "  theta_jam = {t:.3} deg   palm angle at which the disc stops sliding and jams"
                );
                let _ = writeln!(
                    s,
                    "  x_jam     = {x:.3} mm    disc position at the jam (hinge to ground contact)"
                );
            }
            (JamStatus::JammedAtStart, Some(t), x) => {
                let at = x.map_or(String::new(), |x| format!(" (x = {x:.3} mm)"));
                let _ = writeln!(
                    s,
                    "  the disc does not move: it is held already at the start angle {t:.3} deg{at}"
                );
            }
            (JamStatus::NeverJams, ..) => {
                let _ = writeln!(
                    s,
                    "  the disc never jams: without friction it slides for as long as the palm pushes"
                );
            }
            (JamStatus::BeyondReach, ..) => {
                let _ = writeln!(
                    s,
                    "  the jam point lies beyond the palm's end ({} mm): the disc leaves the palm first",
                    p.palm_length_mm
                );
            }
            _ => {}
        }
        match r.model {
            "statics" => render_statics(&mut s, &r.details),
            "min-norm" => min_norm::render_details(&mut s, &r.details),
            "dynamics" => dynamics::render_details(&mut s, r),
            _ => {}
        }
        if r.elapsed_s < 1e-3 {
            let _ = writeln!(s, "  took {:.1} us", r.elapsed_s * 1e6);
        } else {
            let _ = writeln!(s, "  took {:.1} ms", r.elapsed_s * 1e3);
        }
    }
    if results.len() > 1 {
        s.push_str(&super::guidance::guidance(config, results));
    }
    s
}
