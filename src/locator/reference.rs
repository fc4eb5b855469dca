//! The reference for the exact path: the capacity LP solved by clarabel, one program per load
//! direction (what a loop of one LP per map cell costs).

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};

use super::exact::{Capacity, LoadLine};
use super::params::{LocatorParams, Rotation};

/// What clarabel says about max P.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ReferenceCapacity {
    /// P_max in N.
    Bounded(f64),
    /// Every load in the direction is held (dual infeasible).
    Unbounded,
    /// No load >= 0 is held (primal infeasible).
    NoneHeld,
    /// clarabel stopped without a verdict.
    Undetermined,
}

impl ReferenceCapacity {
    /// Whether the exact `c` agrees: same kind, P_max within `rtol` of W + P_max.
    pub fn agrees(&self, c: &Capacity, weight_n: f64, rtol: f64) -> bool {
        match (self, c.p_max_n, c.unbounded) {
            (ReferenceCapacity::Bounded(r), Some(e), false) => {
                (r - e).abs() <= rtol * (weight_n + r.abs())
            }
            (ReferenceCapacity::Unbounded, None, true) => true,
            (ReferenceCapacity::NoneHeld, None, false) => true,
            _ => false,
        }
    }
}

/// max P over (N1, T1, N2, T2, P) subject to equilibrium (force rows; the moment row
/// -T1 + T2 = P m1 under free rotation) and N_i >= 0, |T_i| <= mu_i N_i, P >= 0.
pub fn capacity_clarabel(p: &LocatorParams) -> ReferenceCapacity {
    let f = p.frame();
    let line = LoadLine::new(p);
    let w = p.weight_n();
    // Variables scaled by W: x = (N1, T1, N2, T2, P) / W.
    let n = 5;
    let mut rows: Vec<[f64; 5]> = vec![
        [f.n[0][0], f.u[0][0], f.n[1][0], f.u[1][0], -line.q1[0]],
        [f.n[0][1], f.u[0][1], f.n[1][1], f.u[1][1], -line.q1[1]],
    ];
    let mut rhs = vec![line.q0[0] / w, line.q0[1] / w];
    if p.rotation == Rotation::Free {
        rows.push([0.0, -1.0, 0.0, 1.0, -line.m1]);
        rhs.push(0.0);
    }
    let m_eq = rows.len();
    let mu = p.mu();
    // Cone rows g x >= 0, written as A x + s = 0 with s = g x >= 0, A = -g.
    let cone: [[f64; 5]; 7] = [
        [1.0, 0.0, 0.0, 0.0, 0.0],
        [mu[0], -1.0, 0.0, 0.0, 0.0],
        [mu[0], 1.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, mu[1], -1.0, 0.0],
        [0.0, 0.0, mu[1], 1.0, 0.0],
        [0.0, 0.0, 0.0, 0.0, 1.0],
    ];
    rows.extend(cone.iter().map(|r| r.map(|v| -v)));
    rhs.extend([0.0; 7]);
    let (mut ri, mut ci, mut vals) = (Vec::new(), Vec::new(), Vec::new());
    for c in 0..n {
        for (r, row) in rows.iter().enumerate() {
            if row[c] != 0.0 {
                ri.push(r);
                ci.push(c);
                vals.push(row[c]);
            }
        }
    }
    let a = CscMatrix::new_from_triplets(rows.len(), n, ri, ci, vals);
    let pm = CscMatrix::zeros((n, n));
    let q = [0.0, 0.0, 0.0, 0.0, -1.0];
    let cones = [
        SupportedConeT::ZeroConeT(m_eq),
        SupportedConeT::NonnegativeConeT(7),
    ];
    let settings = DefaultSettings {
        verbose: false,
        max_threads: 1,
        ..DefaultSettings::default()
    };
    let Ok(mut solver) = DefaultSolver::new(&pm, &q, &a, &rhs, &cones, settings) else {
        return ReferenceCapacity::Undetermined;
    };
    solver.solve();
    match solver.solution.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => {
            ReferenceCapacity::Bounded(solver.solution.x[4] * w)
        }
        SolverStatus::DualInfeasible | SolverStatus::AlmostDualInfeasible => {
            ReferenceCapacity::Unbounded
        }
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
            ReferenceCapacity::NoneHeld
        }
        _ => ReferenceCapacity::Undetermined,
    }
}
