//! The min-norm model's and the simulation's own lines of a push's text, and what to do about
//! each one's typed reasons, in a face's words.

use std::fmt::Write;
use std::path::Path;

use super::Words;
use super::solve::Trace;
use crate::config::Config;
use crate::dynamics::{CrossCheck, DynamicsSolution, Failure, Method, Refinement};
use crate::minnorm::qp::{Backend, HoldStatus};
use crate::minnorm::{MinNormCheck, PalmSolution};
use crate::numbers::Num;
use crate::scene::JamStatus;

/// What to do about a min-norm answer's typed reason, in terms of the settings that act on it.
fn min_norm_advice(c: &MinNormCheck, words: Words) -> String {
    match *c {
        MinNormCheck::ConeOverused {
            backend: Backend::Clarabel,
            ..
        } => format!(
            "use the exact path: set fast_path = true{} (it solves the palm scene's small \
             programs exactly, inside every cone)",
            match words {
                Words::Flags => " under [min_norm.qp] in --config",
                Words::Keys => "",
            }
        ),
        MinNormCheck::ConeOverused {
            backend: Backend::Exact,
            ..
        } => format!(
            "this is a defect of the exact path: please report the scene; compare with {}, the \
             closed form",
            words.given("model", "statics")
        ),
    }
}

/// The min-norm lines under the shared status lines of a push's text.
pub(super) fn min_norm_lines(
    out: &mut String,
    s: &PalmSolution,
    trace: Option<&Trace>,
    words: Words,
) {
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
        let _ = writeln!(out, "  advice: {}", min_norm_advice(c, words));
    }
    if let Some(t) = trace {
        let _ = writeln!(
            out,
            "  clarabel trace at theta = {:.6} deg ({}):\n  {:>4}  {:>18}  {:>10}  {:>10}",
            Num(t.trace_theta_deg),
            hold_name(t.trace_status),
            "iter",
            "phi^2 [N^2]",
            "res_primal",
            "res_dual"
        );
        for p in &t.trace {
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

/// Where the time series ends and why: the jam's confirmation, `after_jam_s` after the jam, the
/// palm closing (theta = 0, before the time asked for), the palm's end, or the integrator
/// giving up.
pub(crate) fn series_end(config: &Config, s: &DynamicsSolution, words: Words) -> String {
    let t = s.simulated_s;
    let closes_s = config.scene.start_angle_deg / config.dynamics.drive.omega_deg_s;
    let after = config.dynamics.series.after_jam_s;
    let closed = t >= closes_s * (1.0 - 1e-9);
    let after_jam = words.name("after_jam_s");
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
             the {after} s asked for ({after_jam})",
            Num(t - jam),
            t = Num(t)
        ),
        Some(jam) if after > 0.0 => format!(
            "stops at t = {t:.4} s: {:.4} s after the jam, as asked ({after_jam})",
            Num(t - jam),
            t = Num(t)
        ),
        Some(_) => format!(
            "stops at t = {t:.4} s: at the jam's confirmation ({} records S s more)",
            words.given("after_jam_s", "S"),
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

/// The simulation's own lines under the shared status lines of a push's text: jam time, trust,
/// work, and where the series written to `series` ends and why.
pub(super) fn dynamics_lines(
    s: &mut String,
    d: &DynamicsSolution,
    config: &Config,
    series: Option<&Path>,
    words: Words,
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
            "  model uncertainty {u:.3} mm: a rigid contact ({}) jams at {xr:.3} mm; the \
             contact's unknown compliance moves the jam, the integrator does not",
            words.given("method", "nonsmooth"),
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
            crate::error::path_text(path),
            series_end(config, d, words)
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
            "  lock-up: the palm cannot turn past {:.3} deg; it pushed with {} N in the last \
             step (a rigid disc needs an unbounded push there)",
            Num(l.theta_deg),
            // A fast palm's last step can ask more than a double holds.
            crate::numbers::fixed_or_past(l.push_n, 0)
        );
    }
    if let Some(c) = &d.cross_check {
        let _ = writeln!(s, "  {}: {c}", d.status);
    }
    if let Some(f) = &d.failure {
        let _ = writeln!(s, "  the integrator gave up: {f}");
    }
    if let Some(a) = dynamics_advice(d, words) {
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

/// What to do about the typed reason of `s`, in terms of the settings that act on it.
pub(crate) fn dynamics_advice(s: &DynamicsSolution, words: Words) -> Option<String> {
    let w = |key: &str| words.name(key);
    let nonsmooth = words.given("method", "nonsmooth");
    let radau5 = words.given("method", "radau5");
    if let Some(c) = s.cross_check {
        return Some(match c {
            CrossCheck::LooseTolerance { loosest, .. } => {
                format!("set {} to {loosest} or tighter", w("rtol"))
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
                "the palm is slow against the stiction transition velocity: lower {} to {:.2e} \
                 mm/s or less (the tolerances do not set this error), or use {nonsmooth}",
                w("stiction_velocity_mm_s"),
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
                "lower {} (now {} deg) and compare the answers",
                w("nonsmooth_step_deg"),
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
                "tighten {} (now {:e}) and compare the answers",
                w("rtol"),
                rtol * 10.0
            ),
            CrossCheck::LiftsOff { .. } => super::solve_text::lifts_disc_advice(words),
            CrossCheck::KnockedAhead { x_jam_rigid_mm, .. } => format!(
                "design to the rigid contact's {x_jam_rigid_mm:.3} mm ({nonsmooth}), measure \
                 the real contact's {} and {}, or close the palm slower ({}) so that it does \
                 not strike the disc",
                w("stiffness_n_per_mm_e"),
                w("damping_n_s_per_mm"),
                w("omega_deg_s"),
                x_jam_rigid_mm = Num(x_jam_rigid_mm)
            ),
            CrossCheck::RigidDisagrees {
                rigid_status,
                x_jam_rigid_mm,
                ..
            } => match x_jam_rigid_mm {
                Some(x) => format!(
                    "the rigid contact's answer ({rigid_status} at {x:.3} mm, {nonsmooth}) holds \
                     without compliance; give {} of the real contact and compare",
                    w("stiffness_n_per_mm_e"),
                    x = Num(x)
                ),
                None => format!(
                    "the rigid contact's answer ({rigid_status}, {nonsmooth}) holds without \
                     compliance; give {} of the real contact and compare",
                    w("stiffness_n_per_mm_e")
                ),
            },
            CrossCheck::ContactModelDependent { x_jam_rigid_mm, .. } => format!(
                "the rigid contact's {x_jam_rigid_mm:.3} mm ({nonsmooth}) is the answer without \
                 compliance; give {} of the real contact, and check {} (a heavy disc presses a \
                 soft contact millimetres deep)",
                w("stiffness_n_per_mm_e"),
                w("mass_kg"),
                x_jam_rigid_mm = Num(x_jam_rigid_mm)
            ),
            CrossCheck::NotAtRest { .. } => {
                format!("use {nonsmooth}: its rigid disc comes to rest exactly, with no creep")
            }
            CrossCheck::PastWedge { .. }
            | CrossCheck::StoppedBelowForceLimit { .. }
            | CrossCheck::HeldBelowSlidingPush { .. } => {
                format!("tighten {} and compare the answers", w("rtol"))
            }
        });
    }
    s.failure.map(|f| match f {
        Failure::StepLimit { steps, .. } => format!(
            "raise max_steps{} (now {steps}), or use {radau5}, which takes far fewer steps on \
             this stiff problem",
            words.file_only("dynamics")
        ),
        Failure::Stiff { .. } => format!(
            "use {radau5}, an implicit method built for stiff problems (an explicit method's \
             step is limited by the stiffness, not the accuracy)"
        ),
        Failure::NoConsistentContact { .. } => format!(
            "this is a defect of the nonsmooth method: please report the scene; {radau5} \
             simulates it with a compliant contact"
        ),
        Failure::StepSizeTooSmall { .. } => format!(
            "use {radau5} or a softer {}: the contact is too stiff for the step controller",
            w("stiffness_n_per_mm_e")
        ),
    })
}
