//! Adaptive time integrators for small dense systems: explicit Dormand-Prince 5(4) and implicit
//! Radau IIA of order 5, both after Hairer, Norsett & Wanner (DOPRI5) and Hairer & Wanner
//! (RADAU5), "Solving Ordinary Differential Equations" I and II.
//!
//! Hand-written rather than taken from a crate: our systems have 2-3 components and a budget of
//! a few milliseconds per simulation, so a generic solver's per-call overhead and its build time
//! (diffsol: about 7.5 minutes for a clean release build) buy nothing here. Both methods are
//! checked against published reference solutions (Robertson, Van der Pol with mu = 1e3) in the
//! tests of this module.
//!
//! An integration is driven by an [`Observer`] that sees each accepted step through its dense
//! output and may stop the run (event location is the observer's job). Giving up is an
//! [`Outcome`], never a panic.

mod dopri5;
mod radau5;
#[cfg(test)]
mod tests;

pub use dopri5::Dopri5;
pub use radau5::Radau5;

use serde::Serialize;

/// A system y' = f(t, y) of `N` equations with its Jacobian.
///
/// The size is a constant of the type, so that every vector and matrix of a step lives on the
/// stack in arrays and nalgebra's fixed-size types: our systems have 1 to 4 equations, and a
/// heap allocation per step cost more than the step's algebra.
pub trait OdeSystem<const N: usize> {
    /// Writes f(t, y) into `dy`.
    fn rhs(&self, t: f64, y: &[f64; N], dy: &mut [f64; N]);
    /// Writes d f / d y into `jac` (row i holds the gradient of f_i); only implicit methods
    /// call it.
    fn jacobian(&self, t: f64, y: &[f64; N], jac: &mut [[f64; N]; N]);
}

/// Error control and limits shared by the methods.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance per step.
    pub rtol: f64,
    /// Absolute tolerance per step, in the state's units.
    pub atol: f64,
    /// Largest step (same unit as t).
    pub max_step: f64,
    /// Step limit (accepted and rejected together).
    pub max_steps: u64,
}

/// Work done by one integration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (error test or Newton failure).
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub rhs_evals: u64,
    /// Jacobian evaluations.
    pub jacobian_evals: u64,
}

/// How an integration ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Reached the end time.
    Finished,
    /// The observer stopped it at this time.
    Stopped { t: f64 },
    /// The method gave up.
    Failed(Failure),
}

/// Why an integrator gave up, with the numbers needed to act (diffsol's style of stop reasons).
///
/// JSON: the snake_case variant name under `reason`, beside its fields.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
#[allow(missing_docs)] // each variant's doc names its fields (times in s)
pub enum Failure {
    /// The step budget ran out: `steps` attempts (accepted and rejected) by simulated time `t_s`.
    StepLimit { t_s: f64, steps: u64 },
    /// The step controller asked for a step of `h_s` s (or NaN) at `t_s`, too small to advance
    /// the time in floating point.
    StepSizeTooSmall { t_s: f64, h_s: f64 },
    /// DOPRI5 stopped at `t_s` after `steps` accepted steps because it could not finish within
    /// its step budget: Hairer's stiffness test (h * |lambda| estimated from the last two
    /// stages stayed above 3.25 for 15 accepted steps in a row) found its step held at the
    /// explicit method's stability limit, and at the pace held there it still needed at least
    /// `steps_needed` steps (attempts), more than the budget had left. The run would have met
    /// its step limit; this says so sooner. An implicit method is built for this.
    Stiff {
        t_s: f64,
        steps: u64,
        steps_needed: u64,
    },
    /// The nonsmooth method found no contact impulses that obey the contact laws at `t_s`
    /// although the drive could give way.
    NoConsistentContact { t_s: f64 },
}

impl Failure {
    /// Simulated time in s where the integration stopped.
    pub fn t_s(&self) -> f64 {
        match *self {
            Failure::StepLimit { t_s, .. }
            | Failure::Stiff { t_s, .. }
            | Failure::StepSizeTooSmall { t_s, .. }
            | Failure::NoConsistentContact { t_s } => t_s,
        }
    }
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // A time past 1e15 s (a palm at 1e-300 deg/s) printed with all its digits.
        let t_s = crate::numbers::Num(self.t_s());
        match *self {
            Failure::StepLimit { steps, .. } => {
                write!(f, "step limit of {steps} reached at t = {t_s:.4} s")
            }
            Failure::Stiff {
                steps,
                steps_needed,
                ..
            } => write!(
                f,
                "the problem is stiff at t = {t_s:.4} s: the explicit method's step is held at \
                 its stability limit, where it needs at least {steps_needed} more steps, more \
                 than its step limit leaves (stopped after {steps} steps)"
            ),
            Failure::StepSizeTooSmall { h_s, .. } => {
                write!(f, "step size {h_s:.3e} s too small at t = {t_s:.4} s")
            }
            Failure::NoConsistentContact { .. } => write!(
                f,
                "no contact impulses obey the contact laws at t = {t_s:.4} s"
            ),
        }
    }
}

/// One accepted step, seen through its dense output.
pub trait DenseStep {
    /// Start of the step.
    fn t_start(&self) -> f64;
    /// End of the step.
    fn t_end(&self) -> f64;
    /// The interpolated solution at `t` in [t_start, t_end], written into `out`.
    fn eval(&self, t: f64, out: &mut [f64]);
}

/// Whether to go on after a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Control {
    Continue,
    /// Stop; the integration reports [`Outcome::Stopped`] at this time.
    Stop(f64),
}

/// Watches accepted steps (events, output).
pub trait Observer {
    fn on_step(&mut self, step: &dyn DenseStep) -> Control;

    /// The time by which the observer expects to stop the run, if it knows one before t_end
    /// (an integrator deciding whether it can finish judges its remaining work to there).
    fn horizon(&self) -> Option<f64> {
        None
    }
}

/// The bookkeeping of an adaptive step loop, shared by the methods (their error estimates, step
/// controllers and dense outputs stay their own).
pub(crate) struct StepLoop {
    /// Time of the last accepted state.
    pub t: f64,
    /// Whether the last attempt was rejected.
    pub last_rejected: bool,
    pub stats: Stats,
}

impl StepLoop {
    pub fn new(t0: f64, stats: Stats) -> StepLoop {
        StepLoop {
            t: t0,
            last_rejected: false,
            stats,
        }
    }

    /// Checks before a step attempt of size `h`: `Err` ends the integration (`Finished` at t_end,
    /// `Failed` at the step limit or on a step too small or NaN), `Ok` is `h` clamped so as not to
    /// pass t_end.
    pub fn begin_step(&self, t_end: f64, h: f64, tol: &Tolerances) -> Result<f64, Outcome> {
        let t = self.t;
        // A step that lands a rounding error short of t_end leaves a sliver that is no step.
        if t_end - t <= 1e-14 * t.abs().max(1.0) {
            return Err(Outcome::Finished);
        }
        if self.stats.steps + self.stats.rejected >= tol.max_steps {
            let steps = tol.max_steps;
            return Err(Outcome::Failed(Failure::StepLimit { t_s: t, steps }));
        }
        let h = h.min(t_end - t);
        // Also true for a NaN step.
        if h.is_nan() || h <= 1e-14 * t.abs().max(1.0) {
            return Err(Outcome::Failed(Failure::StepSizeTooSmall {
                t_s: t,
                h_s: h,
            }));
        }
        Ok(h)
    }

    /// Counts a rejected attempt (error test or Newton failure).
    pub fn reject(&mut self) {
        self.stats.rejected += 1;
        self.last_rejected = true;
    }

    /// Accepts the step `dense` of size `h` that ends at `y1`: counts it, shows it to the
    /// observer and moves (t, `y`) to its end. Returns the next step, `h_new` capped at `h` after
    /// a rejection (a step size that just failed does not grow at once), or `Err(Stopped)` if the
    /// observer stops the integration.
    pub fn accept_step<const N: usize>(
        &mut self,
        dense: &dyn DenseStep,
        h: f64,
        h_new: f64,
        y1: &[f64; N],
        y: &mut [f64; N],
        obs: &mut dyn Observer,
    ) -> Result<f64, Outcome> {
        let h_new = if self.last_rejected {
            h_new.min(h)
        } else {
            h_new
        };
        self.last_rejected = false;
        self.stats.steps += 1;
        let control = obs.on_step(dense);
        self.t += h;
        *y = *y1;
        match control {
            Control::Stop(t) => Err(Outcome::Stopped { t }),
            Control::Continue => Ok(h_new),
        }
    }
}

/// RMS norm of `e` scaled by atol + rtol max(|a|, |b|).
pub(crate) fn scaled_norm(e: &[f64], a: &[f64], b: &[f64], tol: &Tolerances) -> f64 {
    let n = e.len() as f64;
    let s: f64 = e
        .iter()
        .zip(a.iter().zip(b))
        .map(|(ei, (ai, bi))| {
            let sc = tol.atol + tol.rtol * ai.abs().max(bi.abs());
            (ei / sc).powi(2)
        })
        .sum();
    (s / n).sqrt()
}

/// Hairer's starting step guess for a method of order `order`.
pub(crate) fn initial_step<const N: usize, S: OdeSystem<N> + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64; N],
    f0: &[f64; N],
    order: f64,
    tol: &Tolerances,
    evals: &mut u64,
) -> f64 {
    let d0 = scaled_norm(y0, y0, y0, tol);
    let d1 = scaled_norm(f0, y0, y0, tol);
    let mut h0 = if d0 < 1e-10 || d1 < 1e-10 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h0 = h0.min(tol.max_step);
    let y1: [f64; N] = std::array::from_fn(|i| y0[i] + h0 * f0[i]);
    let mut f1 = [0.0; N];
    sys.rhs(t0 + h0, &y1, &mut f1);
    *evals += 1;
    let df: [f64; N] = std::array::from_fn(|i| f1[i] - f0[i]);
    let d2 = scaled_norm(&df, y0, y0, tol) / h0;
    let dm = d1.max(d2);
    let h1 = if dm <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / dm).powf(1.0 / (order + 1.0))
    };
    (100.0 * h0).min(h1).min(tol.max_step)
}
