//! The min-norm model in `solve`: its JSON keys, its lines of text and the `--trace`.

use std::fmt::Write;

use serde::Serialize;

use crate::config::Config;
use crate::error::Result;
use crate::minnorm::qp::{Backend, ContactSolution, HoldStatus, TracePoint};
use crate::minnorm::{MinNormCheck, PalmSolution, palm};
use crate::numbers::Num;

/// What `solve --trace` adds to the min-norm model's answer.
#[derive(Debug, Serialize)]
pub struct Record<'a> {
    trace_theta_deg: f64,
    trace_status: HoldStatus,
    trace: &'a [TracePoint],
}

/// clarabel's convergence trace at one palm angle (the paper's Fig. 4), for `--trace`.
#[derive(Debug, Clone)]
pub struct Trace {
    /// The palm angle traced, in deg: theta_jam, or the start angle when there is no jam.
    pub theta_deg: f64,
    /// clarabel's answer there, with its per-iteration trace.
    pub solution: ContactSolution,
}

/// clarabel's trace at the jam of `s` (at the start angle when there is none).
pub fn trace(config: &Config, s: &PalmSolution) -> Result<Trace> {
    let theta_deg = s.theta_jam_deg.unwrap_or(config.scene.start_angle_deg);
    let solution = palm::trace_at(&config.scene, theta_deg, &config.min_norm)?;
    Ok(Trace {
        theta_deg,
        solution,
    })
}

/// The JSON keys of `trace`.
pub fn record(trace: &Trace) -> Record<'_> {
    Record {
        trace_theta_deg: trace.theta_deg,
        trace_status: trace.solution.status,
        trace: &trace.solution.trace,
    }
}

/// What to do about a min-norm answer's typed reason, in terms of the settings that act on it.
fn advice(c: &MinNormCheck) -> String {
    match *c {
        MinNormCheck::ConeOverused {
            backend: Backend::Clarabel,
            ..
        } => "use the exact path: set fast_path = true under [min_norm.qp] in --config (it \
              solves the palm scene's small programs exactly, inside every cone)"
            .to_string(),
        MinNormCheck::ConeOverused {
            backend: Backend::Exact,
            ..
        } => "this is a defect of the exact path: please report the scene; compare with \
              --model statics, the closed form"
            .to_string(),
    }
}

/// The min-norm lines under the shared status lines of `solve`'s text output.
pub fn render_details(out: &mut String, s: &PalmSolution, trace: Option<&Trace>) {
    let _ = writeln!(
        out,
        "  formulation {}: {} solves by {} ({} iterations, {} undetermined)",
        s.formulation.as_str(),
        s.solves,
        backend_name(s.backend),
        s.iterations,
        s.undetermined_solves,
    );
    // Roundoff below the printed digits shows as 0.000, not -0.000.
    let g = |v: f64| if v.abs() < 5e-4 { 0.0 } else { v };
    if let Some(sol) = &s.at_jam {
        for (f, name) in sol.forces.iter().zip(s.formulation.contact_names()) {
            let _ = writeln!(
                out,
                "  at the jam, contact {name}: f_n = {:.3} N, f_t = {:.3} N, friction utilisation {:.4}",
                Num(g(f.normal_n)),
                Num(g(f.tangential_n[0])),
                Num(g(f.utilisation)),
            );
        }
    }
    if let Some(c) = &s.cross_check {
        if let (Some(t), Some(x)) = (s.theta_jam_deg, s.x_jam_mm) {
            let _ = writeln!(
                out,
                "  (untrusted) theta_jam = {t:.3} deg, x_jam = {x:.3} mm",
                t = Num(t),
                x = Num(x)
            );
        }
        let _ = writeln!(out, "  {}: {c}", s.status);
        let _ = writeln!(out, "  advice: {}", advice(c));
    }
    if let Some(t) = trace {
        let _ = writeln!(
            out,
            "  clarabel trace at theta = {:.6} deg ({}):\n  {:>4}  {:>18}  {:>10}  {:>10}",
            Num(t.theta_deg),
            hold_name(t.solution.status),
            "iter",
            "phi^2 [N^2]",
            "res_primal",
            "res_dual"
        );
        for p in &t.solution.trace {
            let _ = writeln!(
                out,
                "  {:>4}  {:>18.9}  {:>10.3e}  {:>10.3e}",
                p.iteration, p.objective_n2, p.res_primal, p.res_dual
            );
        }
    }
}

fn backend_name(b: Backend) -> &'static str {
    match b {
        Backend::Exact => "exact",
        Backend::Clarabel => "clarabel",
    }
}

fn hold_name(h: HoldStatus) -> &'static str {
    match h {
        HoldStatus::Held => "held",
        HoldStatus::NotHeld => "not_held",
        HoldStatus::Undetermined => "undetermined",
    }
}
