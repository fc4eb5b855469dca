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
mod linalg;
mod radau5;
#[cfg(test)]
mod tests;

pub use dopri5::Dopri5;
pub use radau5::Radau5;

/// A system y' = f(t, y) of `dim()` equations with its Jacobian.
pub trait OdeSystem {
    /// Number of equations.
    fn dim(&self) -> usize;
    /// Writes f(t, y) into `dy`.
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]);
    /// Writes d f / d y (row-major, dim x dim) into `jac`; only implicit methods call it.
    fn jacobian(&self, t: f64, y: &[f64], jac: &mut [f64]);
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
    /// LU decompositions.
    pub decompositions: u64,
}

/// How an integration ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Reached the end time.
    Finished,
    /// The observer stopped it at this time.
    Stopped { t: f64 },
    /// The method gave up at time `t`.
    Failed { t: f64, reason: String },
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
pub(crate) fn initial_step<S: OdeSystem + ?Sized>(
    sys: &S,
    t0: f64,
    y0: &[f64],
    f0: &[f64],
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
    let y1: Vec<f64> = y0.iter().zip(f0).map(|(y, f)| y + h0 * f).collect();
    let mut f1 = vec![0.0; y0.len()];
    sys.rhs(t0 + h0, &y1, &mut f1);
    *evals += 1;
    let df: Vec<f64> = f1.iter().zip(f0).map(|(a, b)| a - b).collect();
    let d2 = scaled_norm(&df, y0, y0, tol) / h0;
    let dm = d1.max(d2);
    let h1 = if dm <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / dm).powf(1.0 / (order + 1.0))
    };
    (100.0 * h0).min(h1).min(tol.max_step)
}
