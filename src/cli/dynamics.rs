//! The dynamic simulation on the command line: its flags (merged over the `[dynamics]` section
//! of the TOML file), its record and lines of text for `solve`, and the `--series` CSV.

use std::fmt::Write as _;
use std::path::Path;

use clap::Args;
use serde::Serialize;

use super::args::parse_f64;
use crate::atomic::write_atomic;
use crate::config::Config;
use crate::dynamics::nonsmooth::DiscMotion;
use crate::dynamics::{
    CrossCheck, Drive, DynamicsParams, DynamicsSolution, Failure, Method, Refinement,
};
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
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "DEG/S",
        help_heading = "Dynamics"
    )]
    pub omega: Option<f64>,
    /// IMPACT contact stiffness k in N/mm^e [default: 1e5].
    ///
    /// The penetration at a force P is (P/k)^(1/e): about 60 um at 200 N with the defaults.
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "N/MM^E",
        help_heading = "Dynamics"
    )]
    pub stiffness: Option<f64>,
    /// IMPACT force exponent e, >= 1 [default: 2.2].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "E",
        help_heading = "Dynamics"
    )]
    pub exponent: Option<f64>,
    /// IMPACT maximum damping c_max in N s/mm [default: 10].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "N*S/MM",
        help_heading = "Dynamics"
    )]
    pub damping: Option<f64>,
    /// Penetration in mm at which the damping reaches c_max [default: 0.01].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "MM",
        help_heading = "Dynamics"
    )]
    pub damping_depth: Option<f64>,
    /// Static friction coefficient at both contacts [default: the dynamic mu].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "MU",
        help_heading = "Dynamics"
    )]
    pub mu_static: Option<f64>,
    /// Stiction transition velocity V_s in mm/s [default: 0.1].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "MM/S",
        help_heading = "Dynamics"
    )]
    pub stiction_velocity: Option<f64>,
    /// Friction transition velocity V_d in mm/s, > V_s [default: 0.2].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "MM/S",
        help_heading = "Dynamics"
    )]
    pub friction_velocity: Option<f64>,
    /// Offset of the palm's face from the hinge line in mm (half the bar's thickness) [default: 0].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "MM",
        help_heading = "Dynamics"
    )]
    pub palm_offset: Option<f64>,
    /// Method: radau5 (implicit), dopri5 (explicit) or nonsmooth (rigid) [default: radau5].
    ///
    /// radau5 and dopri5 integrate the compliant IMPACT contact with regularised friction;
    /// nonsmooth time-steps rigid contacts with exact Coulomb friction (true stiction; the jam is
    /// the lock-up of the motion-driven palm).
    #[arg(long, value_name = "METHOD", help_heading = "Dynamics")]
    pub method: Option<Method>,
    /// Palm turn per step of the nonsmooth method in deg, in (0, 1] [default: 0.1 motion drive,
    /// 0.01 force drive].
    ///
    /// The motion drive's lock-up is located inside its step: 0.1 deg puts x_jam within 3e-5 of
    /// r/mu for mu = 0.15-0.45. The force drive's disc comes to rest at a step end, and a slow
    /// push needs 0.01 deg for 0.1 %.
    #[arg(
        long,
        allow_negative_numbers = true,
        value_name = "DEG",
        help_heading = "Dynamics"
    )]
    pub nonsmooth_step: Option<f64>,
    /// How the disc moves in the nonsmooth method: slides or rolls [default: slides].
    ///
    /// slides: the paper's translational joint (no rotation); rolls: free in the plane (x, y,
    /// rotation) with unilateral contacts at the ground and the palm.
    #[arg(long, value_name = "MOTION", help_heading = "Dynamics")]
    pub disc: Option<DiscMotion>,
    /// Relative tolerance per step, in (0, 1) [default: 1e-6].
    ///
    /// Looser than 1e-2 is always reported inaccurate.
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
        value_name = "RTOL",
        help_heading = "Dynamics"
    )]
    pub rtol: Option<f64>,
    /// Absolute tolerance per step in rad, mm, mm/s, in (0, 1) [default: rtol].
    #[arg(
        long,
        allow_negative_numbers = true, value_parser = parse_f64,
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
        allow_negative_numbers = true, value_parser = parse_f64,
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
        if let Some(v) = self.disc {
            d.disc = v;
        }
        if let Some(v) = self.mu_static {
            d.mu_static_ground = Some(v);
            d.mu_static_palm = Some(v);
        }
        if let Some(v) = self.atol {
            d.atol = Some(v);
        }
        if let Some(v) = self.nonsmooth_step {
            d.nonsmooth_step_deg = Some(v);
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

/// What to do when the palm lifts the disc (a start above 90 deg, in every model).
pub const LIFTS_DISC_ADVICE: &str = "start the push at 90 deg or below (--start-angle): above it \
     the palm's push points upwards and lifts the disc, which no model here represents";

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
        "nonsmooth_step_deg" => "--nonsmooth-step",
        "disc" => "--disc",
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
    /// Rows written to the series.
    #[serde(skip_serializing_if = "Option::is_none")]
    series_rows: Option<usize>,
    /// Where the series ends and why ([`series_end`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    series_end: Option<String>,
    settings: &'a DynamicsParams,
    /// What to do about a `cross_check` or `failure`, naming the flags that act on it.
    #[serde(skip_serializing_if = "Option::is_none")]
    advice: Option<String>,
}

/// The JSON keys of `s`, simulated with `config`'s `[dynamics]`, its series written to `series`.
pub fn record<'a>(
    s: &'a DynamicsSolution,
    config: &'a Config,
    series: Option<&Path>,
) -> Record<'a> {
    Record {
        solution: s,
        series: series.map(|p| p.display().to_string()),
        series_rows: series.map(|_| s.series.len()),
        series_end: series.map(|_| series_end(config, s)),
        settings: &config.dynamics,
        advice: advice(s),
    }
}

/// Where the time series ends and why: the jam's confirmation, `after_jam_s` after the jam, the
/// palm closing (theta = 0, before the time asked for), the palm's end, or the integrator
/// giving up.
pub fn series_end(config: &Config, s: &DynamicsSolution) -> String {
    let t = s.simulated_s;
    let closes_s = config.scene.start_angle_deg / config.dynamics.omega_deg_s;
    let after = config.dynamics.after_jam_s;
    let closed = t >= closes_s * (1.0 - 1e-9);
    if let Some(f) = &s.failure {
        return format!(
            "stops at t = {t:.4} s: the integrator gave up at t = {:.4} s",
            f.t_s()
        );
    }
    match s.t_jam_s {
        Some(jam) if closed && jam + after > t * (1.0 + 1e-9) => format!(
            "stops at t = {t:.4} s: the palm closed (theta = 0), {:.4} s after the jam instead of \
             the {after} s asked for (--after-jam)",
            t - jam
        ),
        Some(jam) if after > 0.0 => format!(
            "stops at t = {t:.4} s: {:.4} s after the jam, as asked (--after-jam)",
            t - jam
        ),
        Some(_) => format!(
            "stops at t = {t:.4} s: at the jam's confirmation (--after-jam S records S s more)"
        ),
        None if closed => {
            format!("stops at t = {t:.4} s: the palm closed (theta = 0) with no jam")
        }
        None if s.status == JamStatus::BeyondReach => format!(
            "stops at t = {t:.4} s: the disc reached the palm's end ({} mm) with no jam",
            config.scene.palm_length_mm
        ),
        None => format!("stops at t = {t:.4} s ({})", s.status),
    }
}

/// Writes the time series of `s`, simulated for `config`, to `path` as CSV (atomically), with
/// the columns of render's fig5.csv.
pub fn write_series(config: &Config, s: &DynamicsSolution, path: &Path) -> Result<()> {
    let csv = crate::charts::time_series::series_csv(&config.scene, &config.dynamics, &s.series);
    write_atomic(path, &csv)
}

/// The dynamics' own lines under the shared status lines of `solve`: jam time, trust, work,
/// and where the series written to `series` ends and why.
pub fn render_details(
    s: &mut String,
    d: &DynamicsSolution,
    config: &Config,
    series: Option<&Path>,
) {
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
    let nonsmooth = d.method == Method::Nonsmooth;
    if let Some(e) = d.x_jam_error_mm {
        let how = if nonsmooth {
            "the change at twice the step, or how finely the jam was located if larger"
        } else {
            "second run at a tenth of the tolerances"
        };
        let _ = writeln!(s, "  x_jam error estimate {e:.2e} mm ({how})");
    }
    if let (Some(xr), Some(u)) = (d.x_jam_rigid_mm, d.model_uncertainty_mm) {
        let _ = writeln!(
            s,
            "  model uncertainty {u:.3} mm: a rigid contact (--method nonsmooth) jams at \
             {xr:.3} mm; the contact's unknown compliance moves the jam, the integrator does not"
        );
    }
    if let (Some(t), Some(_)) = (d.physical_until_s, d.series.last()) {
        let _ = writeln!(
            s,
            "  the series is physical up to t = {t:.4} s: after the lock-up a real palm stops, \
             the simulated one presses on into the disc"
        );
    }
    if let Some(x) = d.x_stiction_mm {
        let _ = writeln!(
            s,
            "  ground contact enters stiction (slip < V_s) at x = {x:.3} mm"
        );
    }
    if let Some(path) = series {
        let _ = writeln!(
            s,
            "  series: {} rows in {}; it {}",
            d.series.len(),
            path.display(),
            series_end(config, d)
        );
    }
    if let Some(m) = d
        .disc_motion
        .filter(|m| m.rolling_steps > 0 || m.free_steps > 0)
    {
        let _ = writeln!(
            s,
            "  while pushed the disc rolled {} steps and slipped on the ground {}; off the palm \
             {}, lifted {}",
            m.rolling_steps, m.slipping_steps, m.free_steps, m.lifted_steps
        );
    }
    if let Some(l) = d.lock_up {
        let _ = writeln!(
            s,
            "  lock-up: the palm cannot turn past {:.3} deg; it pushed with {:.0} N in the last \
             step (a rigid disc needs an unbounded push there)",
            l.theta_deg, l.push_n
        );
    }
    if let Some(c) = &d.cross_check {
        let _ = writeln!(s, "  {}: {c}", d.status);
    }
    if let Some(f) = &d.failure {
        let _ = writeln!(s, "  the integrator gave up: {f}");
    }
    if let Some(a) = advice(d) {
        let _ = writeln!(s, "  advice: {a}");
    }
    if nonsmooth {
        let _ = writeln!(
            s,
            "  {} drive, nonsmooth: {} steps, {} contact-mode solves",
            d.drive.as_str(),
            d.steps,
            d.rhs_evals
        );
    } else {
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
}

/// How many stiction transition velocities the palm must move the disc at for the regularised
/// friction to behave as Coulomb's: below that a held disc creeps at a good part of the palm's
/// speed, and tightening the tolerances changes nothing (V_s sets the error).
const SPEED_PER_STICTION_VELOCITY: f64 = 20.0;

/// What to do about the typed reason of `s`, in terms of the flags that act on it.
fn advice(s: &DynamicsSolution) -> Option<String> {
    if let Some(c) = s.cross_check {
        return Some(match c {
            CrossCheck::LooseTolerance { loosest, .. } => {
                format!("set --rtol to {loosest} or tighter")
            }
            CrossCheck::HeldBelowSlidingPush {
                geometric_speed_mm_s: v,
                stiction_velocity_mm_s: vs,
                ..
            }
            | CrossCheck::PastWedge {
                geometric_speed_mm_s: v,
                stiction_velocity_mm_s: vs,
                ..
            } if v < SPEED_PER_STICTION_VELOCITY * vs => format!(
                "the palm is slow against the stiction transition velocity: lower \
                 --stiction-velocity to {:.2e} mm/s or less (the tolerances do not set this \
                 error), or use --method nonsmooth",
                v / SPEED_PER_STICTION_VELOCITY
            ),
            CrossCheck::VerificationDisagrees {
                check: Refinement::Step { step_deg },
                ..
            }
            | CrossCheck::ErrorEstimate {
                check: Refinement::Step { step_deg },
                ..
            } => format!(
                "lower --nonsmooth-step (now {} deg) and compare the answers",
                step_deg / 2.0
            ),
            CrossCheck::VerificationDisagrees {
                check: Refinement::Tolerance { rtol },
                ..
            }
            | CrossCheck::ErrorEstimate {
                check: Refinement::Tolerance { rtol },
                ..
            } => format!(
                "tighten --rtol (now {:e}) and compare the answers",
                rtol * 10.0
            ),
            CrossCheck::LiftsOff { .. } => LIFTS_DISC_ADVICE.to_string(),
            CrossCheck::KnockedAhead { x_jam_rigid_mm, .. } => format!(
                "design to the rigid contact's {x_jam_rigid_mm:.3} mm (--method nonsmooth), measure \
                 the real contact's --stiffness and --damping, or close the palm slower \
                 (--omega) so that it does not strike the disc"
            ),
            CrossCheck::ContactModelDependent { x_jam_rigid_mm, .. } => format!(
                "the rigid contact's {x_jam_rigid_mm:.3} mm (--method nonsmooth) is the answer \
                 without compliance; give --stiffness of the real contact, and check --mass \
                 (a heavy disc presses a soft contact millimetres deep)"
            ),
            CrossCheck::PastWedge { .. }
            | CrossCheck::StoppedBelowForceLimit { .. }
            | CrossCheck::HeldBelowSlidingPush { .. } => {
                "tighten --rtol and compare the answers".to_string()
            }
        });
    }
    s.failure.map(|f| match f {
        Failure::StepLimit { steps, .. } => format!(
            "raise max_steps in the [dynamics] section of --config (now {steps}), or use \
             --method radau5, which takes far fewer steps on this stiff problem"
        ),
        Failure::NoConsistentContact { .. } => {
            "this is a defect of the nonsmooth method: please report the scene; --method \
             radau5 simulates it with a compliant contact"
                .to_string()
        }
        Failure::StepSizeTooSmall { .. } => {
            "use --method radau5 or a softer --stiffness: the contact is too stiff for the \
             step controller"
                .to_string()
        }
    })
}
