//! The min-norm model's record for `solve`: its JSON keys and its lines of text.

use std::fmt::Write;
use std::time::Instant;

use clap::ValueEnum;
use serde_json::{Map, Value, json};

use super::args::Model;
use super::solve::ModelRecord;
use crate::config::Config;
use crate::error::Result;
use crate::minnorm::{Formulation, palm};

/// `--formulation`: how the min-norm model carries the disc's moment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormulationArg {
    /// The paper's: a translational joint carries the moment; the palm blocks the way back.
    Translational,
    /// The disc may rotate: friction at the ground and the palm carries the moment.
    Rolling,
}

impl From<FormulationArg> for Formulation {
    fn from(f: FormulationArg) -> Self {
        match f {
            FormulationArg::Translational => Formulation::Translational,
            FormulationArg::Rolling => Formulation::Rolling,
        }
    }
}

/// Solves the scene by the min-norm model; with `trace`, adds clarabel's convergence trace at
/// theta_jam (at the start angle when there is no jam).
pub fn record(config: &Config, trace: bool) -> Result<ModelRecord> {
    let t0 = Instant::now();
    let s = palm::solve(&config.scene, &config.min_norm)?;
    let elapsed_s = t0.elapsed().as_secs_f64();
    let mut details = Map::new();
    details.insert("iterations".into(), json!(s.iterations));
    details.insert("solves".into(), json!(s.solves));
    details.insert("formulation".into(), json!(s.formulation.as_str()));
    details.insert("backend".into(), json!(s.backend));
    details.insert("undetermined_solves".into(), json!(s.undetermined_solves));
    let contacts: Vec<Value> = s
        .at_jam
        .iter()
        .flat_map(|sol| {
            sol.forces
                .iter()
                .zip(s.formulation.contact_names())
                .map(|(f, name)| {
                    json!({
                        "contact": name,
                        "normal_n": f.normal_n,
                        "tangential_n": f.tangential_n[0],
                        "utilisation": f.utilisation,
                    })
                })
        })
        .collect();
    details.insert("contacts_at_jam".into(), Value::Array(contacts));
    if trace {
        let at = s.theta_jam_deg.unwrap_or(config.scene.start_angle_deg);
        let t = palm::trace_at(&config.scene, at, &config.min_norm)?;
        details.insert("trace_theta_deg".into(), json!(at));
        details.insert("trace_status".into(), json!(t.status));
        details.insert("trace".into(), json!(t.trace));
    }
    Ok(ModelRecord {
        model: Model::MinNorm.name(),
        status: s.status,
        theta_jam_deg: s.theta_jam_deg,
        x_jam_mm: s.x_jam_mm,
        elapsed_s,
        details,
        notes: Vec::new(),
    })
}

/// The min-norm lines under the shared status lines of `solve`'s text output.
pub fn render_details(out: &mut String, d: &Map<String, Value>) {
    let num = |k: &str| d.get(k).and_then(Value::as_f64).unwrap_or(0.0);
    let text = |k: &str| d.get(k).and_then(Value::as_str).unwrap_or("").to_string();
    let _ = writeln!(
        out,
        "  formulation {}: {} solves by {} ({} iterations, {} undetermined)",
        text("formulation"),
        num("solves"),
        text("backend"),
        num("iterations"),
        num("undetermined_solves"),
    );
    if let Some(Value::Array(contacts)) = d.get("contacts_at_jam") {
        for c in contacts {
            // Roundoff below the printed digits shows as 0.000, not -0.000.
            let g = |k: &str| {
                let v = c.get(k).and_then(Value::as_f64).unwrap_or(0.0);
                if v.abs() < 5e-4 { 0.0 } else { v }
            };
            let _ = writeln!(
                out,
                "  at the jam, contact {}: f_n = {:.3} N, f_t = {:.3} N, friction utilisation {:.4}",
                c.get("contact").and_then(Value::as_str).unwrap_or("?"),
                g("normal_n"),
                g("tangential_n"),
                g("utilisation"),
            );
        }
    }
    if let Some(Value::Array(points)) = d.get("trace") {
        let _ = writeln!(
            out,
            "  clarabel trace at theta = {:.6} deg ({}):\n  {:>4}  {:>18}  {:>10}  {:>10}",
            num("trace_theta_deg"),
            text("trace_status"),
            "iter",
            "phi^2 [N^2]",
            "res_primal",
            "res_dual"
        );
        for p in points {
            let g = |k: &str| p.get(k).and_then(Value::as_f64).unwrap_or(0.0);
            let _ = writeln!(
                out,
                "  {:>4}  {:>18.9}  {:>10.3e}  {:>10.3e}",
                g("iteration"),
                g("objective_n2"),
                g("res_primal"),
                g("res_dual")
            );
        }
    }
}
