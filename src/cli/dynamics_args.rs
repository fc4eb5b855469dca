//! Flags of the dynamic simulation, merged over the `[dynamics]` section of the TOML file.

use clap::Args;

use crate::config::Config;
use crate::dynamics::{Drive, Method};

/// Dynamics flags: each overrides the same key of the `[dynamics]` section.
#[derive(Debug, Clone, Default, Args)]
pub struct DynamicsArgs {
    /// Palm drive for the dynamics: motion or force [default: motion].
    ///
    /// motion: prescribed omega, pushes as hard as needed (the paper's Adams model; jams near
    /// r/mu). force: turns at omega until its push reaches --force, then stalls (jams near the
    /// closed form at that force).
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "DRIVE",
        help_heading = "Dynamics"
    )]
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
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "METHOD",
        help_heading = "Dynamics"
    )]
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
