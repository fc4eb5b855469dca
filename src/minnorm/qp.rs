//! The minimum-norm program on clarabel (Eqs. 3-4), its settings and its solution.
//!
//! clarabel minimises `1/2 x' P x + q' x` subject to `A x + s = b`, `s` in a product of cones.
//! With `P = 2 I` on the contact variables, `q = 0`, the objective is exactly phi^2 of Eq. 4 (in
//! the scaled variables; the trace reports it in N^2). Equilibrium and prescribed normal forces
//! are a zero cone; the friction cones are non-negative rows (planar) or second-order cones
//! (spatial).

use std::cell::RefCell;
use std::sync::{Arc, Mutex};

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};
use nalgebra::DVector;
use serde::{Deserialize, Serialize};

use super::contact::{ConeKind, ContactProblem, Lowered, Space};
use super::exact;
use crate::error::{Error, Result};
use crate::limits::MIN_TOLERANCE;
use crate::settings::Check;

settings! {
    /// Settings of the minimum-norm program.
    section = "min_norm.qp";
    pub struct QpSettings {
        /// Use the exact active-set path for small planar problems (at most 8 friction rows),
        /// and clarabel for everything else. The exact path is tested against clarabel.
        fast_path: bool = true;
        /// clarabel's iteration limit (the palm scene needs about 8-12).
        max_iter: u32 = 50, quantity: "iteration limit", check: Check::CountAtLeast(1);
        /// clarabel's primal and dual feasibility tolerance, relative.
        // clarabel's own defaults: the problem is scaled to forces and lever arms of order one.
        tol_feas: f64 = 1e-8, quantity: "feasibility tolerance", unit: "-",
            check: Check::CloseOpen(MIN_TOLERANCE, 1.0);
        /// clarabel's duality-gap tolerance, absolute and relative.
        tol_gap: f64 = 1e-8, quantity: "duality-gap tolerance", unit: "-",
            check: Check::CloseOpen(MIN_TOLERANCE, 1.0);
        /// clarabel's infeasibility-certificate tolerance, absolute and relative.
        tol_infeas: f64 = 1e-8, quantity: "infeasibility tolerance", unit: "-",
            check: Check::CloseOpen(MIN_TOLERANCE, 1.0);
    }
}

impl QpSettings {
    /// Checks every field; the error names the TOML key and the value.
    pub fn validate(&self) -> Result<()> {
        self.check_declared()
    }
}

/// The program's settings are a section inside `[min_norm]`: checked with it, never a flag.
impl crate::settings::Value for QpSettings {
    const KIND: crate::settings::Kind = crate::settings::Kind::Section;
    fn check(&self, _decl: &crate::settings::Decl) -> Result<()> {
        self.check_declared()
    }
    fn text(&self) -> String {
        String::new()
    }
}

/// Whether the contacts can hold the body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HoldStatus {
    /// Forces exist that satisfy equilibrium inside every friction cone (the body is held:
    /// in the palm scene, it jams).
    Held,
    /// No such forces: the program is infeasible, the body moves.
    NotHeld,
    /// The solver stopped without a verdict (iteration limit, numerical trouble).
    Undetermined,
}

/// clarabel's own termination status, kept beside the [`HoldStatus`] it was read as (the
/// spellings are clarabel's `SolverStatus` names in snake_case).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
#[allow(missing_docs)] // clarabel's SolverStatus documents each
pub enum ClarabelStatus {
    Unsolved,
    Solved,
    PrimalInfeasible,
    DualInfeasible,
    AlmostSolved,
    AlmostPrimalInfeasible,
    AlmostDualInfeasible,
    MaxIterations,
    MaxTime,
    NumericalError,
    InsufficientProgress,
    CallbackTerminated,
}

impl From<SolverStatus> for ClarabelStatus {
    fn from(s: SolverStatus) -> Self {
        match s {
            SolverStatus::Unsolved => ClarabelStatus::Unsolved,
            SolverStatus::Solved => ClarabelStatus::Solved,
            SolverStatus::PrimalInfeasible => ClarabelStatus::PrimalInfeasible,
            SolverStatus::DualInfeasible => ClarabelStatus::DualInfeasible,
            SolverStatus::AlmostSolved => ClarabelStatus::AlmostSolved,
            SolverStatus::AlmostPrimalInfeasible => ClarabelStatus::AlmostPrimalInfeasible,
            SolverStatus::AlmostDualInfeasible => ClarabelStatus::AlmostDualInfeasible,
            SolverStatus::MaxIterations => ClarabelStatus::MaxIterations,
            SolverStatus::MaxTime => ClarabelStatus::MaxTime,
            SolverStatus::NumericalError => ClarabelStatus::NumericalError,
            SolverStatus::InsufficientProgress => ClarabelStatus::InsufficientProgress,
            SolverStatus::CallbackTerminated => ClarabelStatus::CallbackTerminated,
        }
    }
}

/// Which solver produced a solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Backend {
    /// The interior-point solver clarabel (the reference).
    Clarabel,
    /// The exact active-set path for small planar problems.
    Exact,
}

/// One contact's force, in its own frame (n, t1, t2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactForce {
    /// Normal force f_n in N (>= 0: the contact pushes).
    pub normal_n: f64,
    /// Tangential force in N along t1 = z x n (planar) and t2 = n x t1 (spatial only; 0 in the
    /// plane and for frictionless contacts).
    pub tangential_n: [f64; 2],
    /// The force in the problem's frame, in N.
    pub world_n: [f64; 3],
    /// Friction utilisation |f_t| / (mu f_n): 0 free of friction, 1 at the point of slipping
    /// (0 where mu = 0 or f_n is below 1e-9 of the largest load).
    pub utilisation: f64,
}

/// One interior-point iteration, from clarabel's termination callback (the data of Fig. 4).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TracePoint {
    /// Iteration number, 0 for the starting point.
    pub iteration: u32,
    /// Primal objective phi^2 = sum of squared contact forces, in N^2 (Eq. 4).
    pub objective_n2: f64,
    /// Relative primal residual (equilibrium and cones), dimensionless.
    pub res_primal: f64,
    /// Relative dual residual, dimensionless.
    pub res_dual: f64,
}

/// The answer of the minimum-norm program.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactSolution {
    /// Held, not held, or undetermined.
    pub status: HoldStatus,
    /// Minimum-norm contact forces, one per contact in input order (empty unless held).
    pub forces: Vec<ContactForce>,
    /// Joint reactions, one per joint: N for forces, N mm for moments (empty unless held).
    pub joint_reactions: Vec<f64>,
    /// phi^2 in N^2 (0 unless held).
    pub objective_n2: f64,
    /// Norm of the force rows of the equilibrium residual, in N (0 unless held).
    pub residual_force_n: f64,
    /// Norm of the moment rows of the equilibrium residual, in N mm (0 unless held).
    pub residual_moment_nmm: f64,
    /// Interior-point iterations (clarabel) or active sets tried (exact path).
    pub iterations: u32,
    /// Which solver answered.
    pub backend: Backend,
    /// Per-iteration trace (clarabel only; empty for the exact path).
    pub trace: Vec<TracePoint>,
    /// clarabel's own status (None for the exact path): which stop an `undetermined` was.
    pub clarabel_status: Option<ClarabelStatus>,
}

/// Solves the minimum-norm program: the exact path where it applies and `fast_path` is set,
/// clarabel otherwise. `Err` only for invalid input; infeasibility is [`HoldStatus::NotHeld`].
pub fn solve(problem: &ContactProblem, settings: &QpSettings) -> Result<ContactSolution> {
    LOWERED.with_borrow_mut(|low| {
        problem.lower_into(low)?;
        if settings.fast_path && exact::applies(low) {
            return Ok(match exact::solve_lowered(low) {
                (Some(z), tried) => assemble(low, &z, Backend::Exact, tried),
                (None, tried) => {
                    ContactSolution::not_held(HoldStatus::NotHeld, Backend::Exact, tried)
                }
            });
        }
        solve_lowered(low, settings)
    })
}

thread_local! {
    /// The last problem [`solve`] lowered on this thread, whose buffers the next one reuses:
    /// a map's search solves millions of problems of the same shape.
    static LOWERED: RefCell<Lowered> = RefCell::new(Lowered::default());
}

/// Solves with clarabel whatever the size, recording the per-iteration trace.
pub fn solve_clarabel(problem: &ContactProblem, settings: &QpSettings) -> Result<ContactSolution> {
    solve_lowered(&problem.lower()?, settings)
}

fn solve_lowered(low: &Lowered, settings: &QpSettings) -> Result<ContactSolution> {
    let n = low.eq.ncols();
    let p_diag: Vec<usize> = (0..low.n_contact_vars).collect();
    let p =
        CscMatrix::new_from_triplets(n, n, p_diag.clone(), p_diag, vec![2.0; low.n_contact_vars]);
    let q = vec![0.0; n];
    // A x + s = b: equalities as they are; cone rows g x in K as s = -(-g) x.
    let m_eq = low.eq.nrows();
    let m = m_eq + low.cone_rows.nrows();
    let (mut ri, mut ci, mut vals) = (Vec::new(), Vec::new(), Vec::new());
    for c in 0..n {
        for r in 0..m_eq {
            if low.eq[(r, c)] != 0.0 {
                ri.push(r);
                ci.push(c);
                vals.push(low.eq[(r, c)]);
            }
        }
        for r in 0..low.cone_rows.nrows() {
            if low.cone_rows[(r, c)] != 0.0 {
                ri.push(m_eq + r);
                ci.push(c);
                vals.push(-low.cone_rows[(r, c)]);
            }
        }
    }
    let a = CscMatrix::new_from_triplets(m, n, ri, ci, vals);
    let mut b = vec![0.0; m];
    b[..m_eq].copy_from_slice(low.eq_rhs.as_slice());
    let mut cones = vec![SupportedConeT::ZeroConeT(m_eq)];
    cones.extend(low.cones.iter().map(|&(kind, rows)| match kind {
        ConeKind::Nonneg => SupportedConeT::NonnegativeConeT(rows),
        ConeKind::Soc3 => SupportedConeT::SecondOrderConeT(rows),
    }));

    let cs = DefaultSettings {
        verbose: false,
        max_iter: settings.max_iter,
        tol_feas: settings.tol_feas,
        tol_gap_abs: settings.tol_gap,
        tol_gap_rel: settings.tol_gap,
        tol_infeas_abs: settings.tol_infeas,
        tol_infeas_rel: settings.tol_infeas,
        // One thread per solve: parallelism lives in the callers (grids of solves).
        max_threads: 1,
        ..DefaultSettings::default()
    };
    // Dimensions and settings are ours and checked: a refusal here is a bug or misuse.
    let mut solver =
        DefaultSolver::new(&p, &q, &a, &b, &cones, cs).map_err(|e| Error::SolverRefused {
            solver: "clarabel",
            detail: format!("{e:?}"),
        })?;
    let trace = Arc::new(Mutex::new(Vec::new()));
    let sink = Arc::clone(&trace);
    let objective_scale = low.force_scale_n * low.force_scale_n;
    solver.set_termination_callback(move |info: &clarabel::solver::DefaultInfo<f64>| {
        if let Ok(mut t) = sink.lock() {
            t.push(TracePoint {
                iteration: info.iterations,
                objective_n2: info.cost_primal * objective_scale,
                res_primal: info.res_primal,
                res_dual: info.res_dual,
            });
        }
        false
    });
    solver.solve();
    let sol = &solver.solution;
    let trace: Vec<TracePoint> = trace
        .lock()
        .map(|t| t.iter().copied().filter(finite_point).collect())
        .unwrap_or_default();
    let status = match sol.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => HoldStatus::Held,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            HoldStatus::NotHeld
        }
        _ => HoldStatus::Undetermined,
    };
    let x = DVector::from_column_slice(&sol.x);
    let mut out = if status == HoldStatus::Held && x.iter().all(|v| v.is_finite()) {
        assemble(low, &x, Backend::Clarabel, sol.iterations)
    } else {
        let status = if status == HoldStatus::Held {
            HoldStatus::Undetermined
        } else {
            status
        };
        ContactSolution::not_held(status, Backend::Clarabel, sol.iterations)
    };
    out.trace = trace;
    out.clarabel_status = Some(sol.status.into());
    Ok(out)
}

fn finite_point(p: &TracePoint) -> bool {
    p.objective_n2.is_finite() && p.res_primal.is_finite() && p.res_dual.is_finite()
}

impl ContactSolution {
    pub(crate) fn not_held(status: HoldStatus, backend: Backend, iterations: u32) -> Self {
        ContactSolution {
            status,
            forces: Vec::new(),
            joint_reactions: Vec::new(),
            objective_n2: 0.0,
            residual_force_n: 0.0,
            residual_moment_nmm: 0.0,
            iterations,
            backend,
            trace: Vec::new(),
            clarabel_status: None,
        }
    }
}

/// Turns the scaled solution `x` of a held problem into forces in N, residuals and utilisation.
pub(crate) fn assemble(
    low: &Lowered,
    x: &DVector<f64>,
    backend: Backend,
    iterations: u32,
) -> ContactSolution {
    let fs = low.force_scale_n;
    let forces = low
        .contacts
        .iter()
        .map(|c| {
            let f_n = x[c.start] * fs;
            let mut f_t = [0.0; 2];
            for (k, t) in f_t.iter_mut().enumerate().take(c.n_tangent) {
                *t = x[c.start + 1 + k] * fs;
            }
            let world = c.normal * f_n + c.tangent[0] * f_t[0] + c.tangent[1] * f_t[1];
            let tangential = f_t[0].hypot(f_t[1]);
            // A contact carrying next to nothing (below the solvers' 1e-10 to 1e-8 of the largest
            // load) is not slipping: dividing its roundoff by its roundoff would report noise.
            let utilisation = if c.mu > 0.0 && f_n > 1e-9 * fs {
                tangential / (c.mu * f_n)
            } else {
                0.0
            };
            ContactForce {
                normal_n: f_n,
                tangential_n: f_t,
                world_n: world.into(),
                utilisation,
            }
        })
        .collect();
    let joint_reactions = low
        .joint_is_moment
        .iter()
        .enumerate()
        .map(|(k, &is_moment)| {
            let v = x[low.n_contact_vars + k] * fs;
            if is_moment {
                v * low.length_scale_mm
            } else {
                v
            }
        })
        .collect();
    let r = &low.eq * x - &low.eq_rhs;
    let n_f = if low.space == Space::Planar { 2 } else { 3 };
    let res_f = r.rows(0, n_f).norm() * fs;
    let res_m = r.rows(n_f, low.n_equilibrium - n_f).norm() * fs * low.length_scale_mm;
    let phi = x.rows(0, low.n_contact_vars).norm() * fs;
    ContactSolution {
        status: HoldStatus::Held,
        forces,
        joint_reactions,
        objective_n2: phi * phi,
        residual_force_n: res_f,
        residual_moment_nmm: res_m,
        iterations,
        backend,
        trace: Vec::new(),
        clarabel_status: None,
    }
}
