//! The exact fast path: small planar problems solved by enumerating active sets.
//!
//! The planar program is a strictly convex QP in the contact forces with linear constraints,
//! `min 1/2 |f|^2` s.t. `E z = e`, `G z >= 0` (z = contact forces and joint reactions). A point
//! is optimal iff, for some set S of active rows, it solves the KKT system
//!
//! ```text
//! [ P   E'  G_S' ] [ z  ]   [ 0 ]
//! [ E   0   0    ] [ y' ] = [ e ]        (P = I on contact forces, 0 on joints)
//! [ G_S 0   0    ] [ w' ]   [ 0 ]
//! ```
//!
//! with `G z >= 0` and multipliers `w = -w' >= 0`. With at most 8 cone rows there are at most
//! 256 sets; they are tried by increasing size, so a held problem whose optimum is strictly
//! inside its cones costs one small solve (the palm scene (a), whose idle way-back stop is an
//! active row, a few). No set passing
//! the test means the program is infeasible. The KKT matrix may be singular (dependent rows,
//! a joint that duplicates another); it is then solved in the least-squares sense by SVD and
//! accepted only if the residual vanishes. clarabel is the reference: the tests compare both.
//!
//! A set is skipped, unsolved, when its rows outnumber the unknowns the equalities leave free
//! (m_e + |S| > n, the equalities being independent, which the empty set's regular KKT matrix
//! shows): its KKT matrix is singular whatever the numbers. Skipping it loses nothing. The
//! optimum is unique, and if some set's multipliers certify it, so do a set's whose rows,
//! with the equalities', are independent (Caratheodory's theorem for the cone of the active
//! rows), which has at most n - m_e rows and is tried first. Those sets were most of the
//! least-squares solves: every not-held palm problem tried all 8 sets of its 3 cone rows, 4 of
//! them by SVD.

use nalgebra::{DMatrix, DVector};

use super::contact::{ConeKind, Lowered, Space};

/// At most this many cone rows (four frictional planar contacts): 2^8 active sets.
const MAX_CONE_ROWS: usize = 8;
/// Feasibility tolerance in the scaled problem, where loads and lever arms are of order one;
/// far below clarabel's 1e-8 so the fast path is never the less accurate one. Equalities and
/// multipliers are judged relative to the largest force found; a cone row relative to its own
/// terms (see `cones_hold`).
const TOL: f64 = 1e-10;
/// Roundoff floor of a cone row, relative to the largest force found: the error of a small
/// dense solve whose entries are of order one is a few machine epsilons of its largest entry.
// Not TOL: a contact whose forces are far below the largest load (friction of 1e-9, a palm
// pushing with 1/2000 of the weight) has its margin far below TOL, and a tolerance on the
// largest force moved its held / not-held boundary by up to 9 %.
const ROW_ROUNDOFF: f64 = 16.0 * f64::EPSILON;
/// Accepted residual of a KKT solve, relative to the solution: 1e4 machine epsilons.
const ROUNDOFF: f64 = 1e-12;

/// Whether the exact path handles this problem (planar, linear cones, small).
pub(crate) fn applies(low: &Lowered) -> bool {
    low.space == Space::Planar
        && low.cone_rows.nrows() <= MAX_CONE_ROWS
        && low.cones.iter().all(|&(k, _)| k == ConeKind::Nonneg)
}

/// Solves a problem for which [`applies`] holds: the optimum in the scaled variables (None:
/// infeasible, the body is not held) and the number of active sets tried.
pub(crate) fn solve_lowered(low: &Lowered) -> (Option<DVector<f64>>, u32) {
    if let Some(z) = determined(low) {
        // The equalities fix every variable: no freedom is left to minimise over.
        return (cones_hold(low, &z, 0).then_some(z), 1);
    }
    let m_g = low.cone_rows.nrows();
    let (n, m_e) = (low.eq.ncols(), low.eq.nrows());
    let mut tried = 0u32;
    // Whether the equalities are independent (the empty set's KKT matrix is regular): then a
    // set of more than n - m_e rows is singular for any numbers and is skipped (module docs).
    let mut independent = false;
    for size in 0..=m_g {
        if independent && m_e + size > n {
            break;
        }
        for mask in 0u32..(1 << m_g) {
            if mask.count_ones() as usize != size {
                continue;
            }
            tried += 1;
            match kkt_point(low, mask) {
                KktPoint::Optimal(z) => return (Some(z), tried),
                KktPoint::Rejected { regular } => independent |= mask == 0 && regular,
            }
        }
    }
    (None, tried)
}

/// What the KKT system of one active set gives.
enum KktPoint {
    /// The optimum: feasible, with non-negative multipliers.
    Optimal(DVector<f64>),
    /// Not the optimum; `regular`: its KKT matrix was solved by LU (not by least squares).
    Rejected { regular: bool },
}

/// The unique solution of the equalities when they are square and regular (the palm scene's
/// rolling formulation: the minimum is trivial).
fn determined(low: &Lowered) -> Option<DVector<f64>> {
    if low.eq.nrows() != low.eq.ncols() {
        return None;
    }
    let z = low.eq.clone().lu().solve(&low.eq_rhs)?;
    equalities_hold(low, &z).then_some(z)
}

fn equalities_hold(low: &Lowered, z: &DVector<f64>) -> bool {
    z.iter().all(|v| v.is_finite()) && (&low.eq * z - &low.eq_rhs).amax() <= TOL * (1.0 + z.amax())
}

/// Whether every cone row holds at `z`, given the active set `active` (a bit per row).
///
/// An inactive row `g . z >= 0` decides the verdict: it is judged to TOL of its own terms
/// sum |g_j z_j|, so a contact is judged on its own forces however small they are against the
/// largest load, and never below the roundoff floor ROW_ROUNDOFF of the largest force. An
/// active row is an equality of the KKT system: judged to TOL of the largest force, it rejects
/// the least-squares point of an inconsistent set (an overdetermined KKT system whose
/// multipliers blow up passes the residual test relative to them).
fn cones_hold(low: &Lowered, z: &DVector<f64>, active: u32) -> bool {
    let scale = 1.0 + z.amax();
    let values = &low.cone_rows * z;
    let terms = low.cone_rows.abs() * z.abs();
    (0..values.len()).all(|r| {
        let tol = if active & (1 << r) != 0 {
            TOL * scale
        } else {
            TOL * terms[r] + ROW_ROUNDOFF * scale
        };
        values[r] >= -tol
    })
}

/// The KKT point for active set `mask`, if it is feasible with non-negative multipliers.
fn kkt_point(low: &Lowered, mask: u32) -> KktPoint {
    let n = low.eq.ncols();
    let m_e = low.eq.nrows();
    let active: Vec<usize> = (0..low.cone_rows.nrows())
        .filter(|r| mask & (1 << r) != 0)
        .collect();
    let k = n + m_e + active.len();
    let mut kkt = DMatrix::zeros(k, k);
    for i in 0..low.n_contact_vars {
        kkt[(i, i)] = 1.0;
    }
    for r in 0..m_e {
        for c in 0..n {
            let v = low.eq[(r, c)];
            kkt[(n + r, c)] = v;
            kkt[(c, n + r)] = v;
        }
    }
    for (a, &r) in active.iter().enumerate() {
        for c in 0..n {
            let v = low.cone_rows[(r, c)];
            kkt[(n + m_e + a, c)] = v;
            kkt[(c, n + m_e + a)] = v;
        }
    }
    let mut rhs = DVector::zeros(k);
    rhs.rows_mut(n, m_e).copy_from(&low.eq_rhs);

    // Roundoff grows with the solution (a wedged body's forces and multipliers may be orders
    // above the load): a test relative to it. A solution of a singular system that is merely
    // close is caught by the checks of z below.
    let consistent = |sol: &DVector<f64>| {
        sol.iter().all(|v| v.is_finite())
            && (&kkt * sol - &rhs).amax() <= ROUNDOFF * (1.0 + sol.amax())
    };
    let (sol, regular) = match kkt.clone().lu().solve(&rhs) {
        Some(s) if consistent(&s) => (s, true),
        _ => {
            let rejected = KktPoint::Rejected { regular: false };
            let Ok(s) = kkt.clone().svd(true, true).solve(&rhs, 1e-13) else {
                return rejected;
            };
            if !consistent(&s) {
                return rejected;
            }
            (s, false)
        }
    };
    let z = sol.rows(0, n).into_owned();
    let multipliers_ok = (0..active.len()).all(|a| -sol[n + m_e + a] >= -TOL * (1.0 + sol.amax()));
    if multipliers_ok && cones_hold(low, &z, mask) && equalities_hold(low, &z) {
        KktPoint::Optimal(z)
    } else {
        KktPoint::Rejected { regular }
    }
}
