//! The dynamic simulation on the command line: its flags (merged over the `[dynamics]` section
//! of the TOML file), its record and lines of text for `solve`, and the `--series` CSV.

use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use crate::atomic::write_atomic;
use crate::config::Config;
use crate::dynamics::{CrossCheck, DynamicsParams, DynamicsSolution, Failure, Method, Refinement};
use crate::error::Result;
use crate::numbers::Num;
use crate::scene::JamStatus;
use crate::settings::flags::{DynamicsSet, Flags};

/// Dynamics flags: each a declared setting of `[dynamics.*]` ([`crate::settings`]).
pub type DynamicsArgs = Flags<DynamicsSet>;

/// What to do when the palm lifts the disc (a start above 90 deg, in every model).
pub const LIFTS_DISC_ADVICE: &str = "start the push at 90 deg or below (--start-angle): above it \
     the palm's push points upwards and lifts the disc, which no model here represents";

/// What `solve` adds to a simulation's answer in its JSON: the series file and the
/// `[dynamics]` settings in force, so that the answer can be reproduced.
#[derive(Debug, Serialize)]
pub struct Record<'a> {
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
    let closes_s = config.scene.start_angle_deg / config.dynamics.drive.omega_deg_s;
    let after = config.dynamics.series.after_jam_s;
    let closed = t >= closes_s * (1.0 - 1e-9);
    if let Some(f) = &s.failure {
        return format!(
            "stops at t = {t:.4} s: the integrator gave up at t = {:.4} s",
            Num(f.t_s()),
            t = Num(t)
        );
    }
    match s.t_jam_s {
        Some(jam) if closed && jam + after > t * (1.0 + 1e-9) => format!(
            "stops at t = {t:.4} s: the palm closed (theta = 0), {:.4} s after the jam instead of \
             the {after} s asked for (--after-jam)",
            Num(t - jam),
            t = Num(t)
        ),
        Some(jam) if after > 0.0 => format!(
            "stops at t = {t:.4} s: {:.4} s after the jam, as asked (--after-jam)",
            Num(t - jam),
            t = Num(t)
        ),
        Some(_) => format!(
            "stops at t = {t:.4} s: at the jam's confirmation (--after-jam S records S s more)",
            t = Num(t)
        ),
        None if closed => {
            format!(
                "stops at t = {t:.4} s: the palm closed (theta = 0) with no jam",
                t = Num(t)
            )
        }
        None if s.status == JamStatus::BeyondReach => format!(
            "stops at t = {t:.4} s: the disc reached the palm's end ({} mm) with no jam",
            config.scene.palm_length_mm,
            t = Num(t)
        ),
        None => format!("stops at t = {t:.4} s ({})", s.status, t = Num(t)),
    }
}

/// Writes the time series of `s`, simulated for `config`, to `path` as CSV (atomically), with
/// the columns of render's fig5.csv.
pub fn write_series(config: &Config, s: &DynamicsSolution, path: &Path) -> Result<()> {
    let csv = crate::figures::time_series::series_csv(&config.scene, &config.dynamics, &s.series);
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
        let _ = writeln!(
            s,
            "  (untrusted) theta_jam = {t:.3} deg, x_jam = {x:.3} mm",
            t = Num(t),
            x = Num(x)
        );
    }
    if let Some(t) = d.t_jam_s {
        let _ = writeln!(
            s,
            "  t_jam     = {t:.4} s     time of the jam from the start of the push",
            t = Num(t)
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
             {xr:.3} mm; the contact's unknown compliance moves the jam, the integrator does not",
            u = Num(u),
            xr = Num(xr)
        );
    }
    if let (Some(t), Some(_)) = (d.physical_until_s, d.series.last()) {
        let _ = writeln!(
            s,
            "  the series is physical up to t = {t:.4} s: after the lock-up a real palm stops, \
             the simulated one presses on into the disc",
            t = Num(t)
        );
    }
    if let (Some(x), Some(t)) = (d.x_half_speed_mm, d.t_half_speed_s) {
        let _ = writeln!(
            s,
            "  the disc's speed fell to half the palm's at x = {x:.3} mm, t = {t:.4} s: the \
             palm stalled there and the disc coasted on to rest",
            x = Num(x),
            t = Num(t)
        );
    }
    if let Some(x) = d.x_stiction_mm {
        let _ = writeln!(
            s,
            "  ground contact enters stiction (slip < V_s) at x = {x:.3} mm",
            x = Num(x)
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
            Num(l.theta_deg),
            Num(l.push_n)
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
                 (--omega) so that it does not strike the disc",
                x_jam_rigid_mm = Num(x_jam_rigid_mm)
            ),
            CrossCheck::RigidDisagrees {
                rigid_status,
                x_jam_rigid_mm,
                ..
            } => match x_jam_rigid_mm {
                Some(x) => format!(
                    "the rigid contact's answer ({rigid_status} at {x:.3} mm, --method \
                     nonsmooth) holds without compliance; give --stiffness of the real contact \
                     and compare",
                    x = Num(x)
                ),
                None => format!(
                    "the rigid contact's answer ({rigid_status}, --method nonsmooth) holds \
                     without compliance; give --stiffness of the real contact and compare"
                ),
            },
            CrossCheck::ContactModelDependent { x_jam_rigid_mm, .. } => format!(
                "the rigid contact's {x_jam_rigid_mm:.3} mm (--method nonsmooth) is the answer \
                 without compliance; give --stiffness of the real contact, and check --mass \
                 (a heavy disc presses a soft contact millimetres deep)",
                x_jam_rigid_mm = Num(x_jam_rigid_mm)
            ),
            CrossCheck::NotAtRest { .. } => "use --method nonsmooth: its rigid disc comes to \
                 rest exactly, with no creep"
                .to_string(),
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
        Failure::Stiff { .. } => "use --method radau5, an implicit method built for stiff \
             problems (an explicit method's step is limited by the stiffness, not the accuracy)"
            .to_string(),
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
