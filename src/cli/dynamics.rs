//! The dynamic simulation on the command line: its flags (merged over the `[dynamics]` section
//! of the TOML file), its record and lines of text for `solve`, and the `--series` CSV.

use std::fmt::Write as _;
use std::path::Path;

use clap::Args;
use serde::Serialize;

use crate::atomic::write_atomic;
use crate::config::Config;
use crate::dynamics::{Drive, DynamicsParams, DynamicsSolution, Method};
use crate::error::Result;
use crate::model::JamStatus;

/// Dynamics flags: each overrides the same key of the `[dynamics]` section.
#[derive(Debug, Clone, Default, Args)]
pub struct DynamicsArgs {
    /// Palm drive for the dynamics: motion or force [default: motion].
    ///
    /// motion: prescribed omega, pushes as hard as needed (the paper's Adams model; jams near
    /// r/mu). force: turns at omega until its push reaches --force, then stalls (jams near the
    /// closed form at that force).
    #[arg(long, value_name = "DRIVE", help_heading = "Dynamics")]
    pub drive: Option<Drive>,
    /// Palm closing speed omega in deg/s [default: 30].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "DEG/S",
        help_heading = "Dynamics"
    )]
    pub omega: Option<f64>,
    /// IMPACT contact stiffness k in N/mm^e [default: 1e5].
    ///
    /// The penetration at a force P is (P/k)^(1/e): about 60 um at 200 N with the defaults.
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "N/MM^E",
        help_heading = "Dynamics"
    )]
    pub stiffness: Option<f64>,
    /// IMPACT force exponent e, >= 1 [default: 2.2].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "E",
        help_heading = "Dynamics"
    )]
    pub exponent: Option<f64>,
    /// IMPACT maximum damping c_max in N s/mm [default: 10].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "N*S/MM",
        help_heading = "Dynamics"
    )]
    pub damping: Option<f64>,
    /// Penetration in mm at which the damping reaches c_max [default: 0.01].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MM",
        help_heading = "Dynamics"
    )]
    pub damping_depth: Option<f64>,
    /// Static friction coefficient at both contacts [default: the dynamic mu].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MU",
        help_heading = "Dynamics"
    )]
    pub mu_static: Option<f64>,
    /// Stiction transition velocity V_s in mm/s [default: 0.1].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MM/S",
        help_heading = "Dynamics"
    )]
    pub stiction_velocity: Option<f64>,
    /// Friction transition velocity V_d in mm/s, > V_s [default: 0.2].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MM/S",
        help_heading = "Dynamics"
    )]
    pub friction_velocity: Option<f64>,
    /// Offset of the palm's face from the hinge line in mm (half the bar's thickness) [default: 0].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "MM",
        help_heading = "Dynamics"
    )]
    pub palm_offset: Option<f64>,
    /// Integrator: radau5 (implicit) or dopri5 (explicit) [default: radau5].
    #[arg(long, value_name = "METHOD", help_heading = "Dynamics")]
    pub method: Option<Method>,
    /// Relative tolerance per step, in (0, 1) [default: 1e-6].
    ///
    /// Looser than 1e-2 is always reported inaccurate.
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "RTOL",
        help_heading = "Dynamics"
    )]
    pub rtol: Option<f64>,
    /// Absolute tolerance per step in rad, mm, mm/s, in (0, 1) [default: rtol].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "ATOL",
        help_heading = "Dynamics"
    )]
    pub atol: Option<f64>,
    /// Skip the second run at a tenth of the tolerances that estimates the error of x_jam.
    #[arg(long, help_heading = "Dynamics")]
    pub no_verify: bool,
    /// Simulated time after the jam in s, for --series [default: 0].
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "S",
        help_heading = "Dynamics"
    )]
    pub after_jam: Option<f64>,
}

impl DynamicsArgs {
    /// Writes the given flags over `config.dynamics`.
    pub fn apply(&self, config: &mut Config) {
        let d = &mut config.dynamics;
        if let Some(v) = self.drive {
            d.drive = v;
        }
        if let Some(v) = self.method {
            d.method = v;
        }
        if let Some(v) = self.mu_static {
            d.mu_static_ground = Some(v);
            d.mu_static_palm = Some(v);
        }
        if let Some(v) = self.atol {
            d.atol = Some(v);
        }
        if self.no_verify {
            d.verify = false;
        }
        let overrides = [
            (self.omega, &mut d.omega_deg_s),
            (self.stiffness, &mut d.stiffness_n_per_mm_e),
            (self.exponent, &mut d.exponent),
            (self.damping, &mut d.damping_n_s_per_mm),
            (self.damping_depth, &mut d.damping_depth_mm),
            (self.stiction_velocity, &mut d.stiction_velocity_mm_s),
            (self.friction_velocity, &mut d.friction_velocity_mm_s),
            (self.palm_offset, &mut d.palm_offset_mm),
            (self.rtol, &mut d.rtol),
            (self.after_jam, &mut d.after_jam_s),
        ];
        for (flag, field) in overrides {
            if let Some(v) = flag {
                *field = v;
            }
        }
    }
}

/// The flag that sets a `[dynamics]` key, for error messages.
pub fn flag_for_key(key: &str) -> Option<&'static str> {
    Some(match key {
        "omega_deg_s" => "--omega",
        "stiffness_n_per_mm_e" => "--stiffness",
        "exponent" => "--exponent",
        "damping_n_s_per_mm" => "--damping",
        "damping_depth_mm" => "--damping-depth",
        "mu_static_ground" | "mu_static_palm" => "--mu-static",
        "stiction_velocity_mm_s" => "--stiction-velocity",
        "friction_velocity_mm_s" => "--friction-velocity",
        "palm_offset_mm" => "--palm-offset",
        "rtol" => "--rtol",
        "atol" => "--atol",
        "after_jam_s" => "--after-jam",
        _ => return None,
    })
}

/// The dynamics' own JSON keys in `solve`'s record: the solution's, the series file and the
/// `[dynamics]` settings in force, so that the answer can be reproduced.
#[derive(Debug, Serialize)]
pub struct Record<'a> {
    #[serde(flatten)]
    solution: &'a DynamicsSolution,
    #[serde(skip_serializing_if = "Option::is_none")]
    series: Option<String>,
    settings: &'a DynamicsParams,
}

/// The JSON keys of `s`, simulated with `settings`, its series written to `series`.
pub fn record<'a>(
    s: &'a DynamicsSolution,
    settings: &'a DynamicsParams,
    series: Option<&Path>,
) -> Record<'a> {
    Record {
        solution: s,
        series: series.map(|p| p.display().to_string()),
        settings,
    }
}

/// Writes the time series of `s`, simulated for `config`, to `path` as CSV (atomically), with
/// the columns of render's fig5.csv.
pub fn write_series(config: &Config, s: &DynamicsSolution, path: &Path) -> Result<()> {
    let csv = crate::charts::time_series::series_csv(&config.scene, &config.dynamics, &s.series);
    write_atomic(path, &csv)
}

/// The dynamics' own lines under the shared status lines of `solve`: jam time, trust, work.
pub fn render_details(s: &mut String, d: &DynamicsSolution) {
    if d.status == JamStatus::Inaccurate
        && let (Some(t), Some(x)) = (d.theta_jam_deg, d.x_jam_mm)
    {
        let _ = writeln!(s, "  (untrusted) theta_jam = {t:.3} deg, x_jam = {x:.3} mm");
    }
    if let Some(t) = d.t_jam_s {
        let _ = writeln!(
            s,
            "  t_jam     = {t:.4} s     time of the jam from the start of the push"
        );
    }
    if let Some(e) = d.x_jam_error_mm {
        let _ = writeln!(
            s,
            "  x_jam error estimate {e:.2e} mm (second run at a tenth of the tolerances)"
        );
    }
    if let Some(x) = d.x_stiction_mm {
        let _ = writeln!(
            s,
            "  ground contact enters stiction (slip < V_s) at x = {x:.3} mm"
        );
    }
    if let Some(c) = &d.cross_check {
        let _ = writeln!(s, "  inaccurate: {c}");
    }
    if let Some(f) = &d.failure {
        let _ = writeln!(
            s,
            "  the integrator gave up at t = {:.4} s: {}",
            f.t_s, f.reason
        );
    }
    let _ = writeln!(
        s,
        "  {} drive, {}: {} steps ({} rejected), {} rhs and {} Jacobian evaluations",
        d.drive.as_str(),
        d.method.as_str(),
        d.steps,
        d.rejected_steps,
        d.rhs_evals,
        d.jacobian_evals
    );
}
