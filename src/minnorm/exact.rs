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
//!
//! The systems are small and a map solves millions of them, so they are solved in place on
//! buffers each thread keeps (`dense`), with nalgebra's arithmetic in nalgebra's order: the
//! answers are bit for bit those of nalgebra's `DMatrix` LU. The empty set's KKT matrix is
//! the leading block of every other set's, whose LU extends its LU (`dense::lu_bordered`).

use std::cell::Cell;

use nalgebra::{DMatrix, DVector};

use super::contact::{ConeKind, Lowered, Space};
use super::dense::{amax, lu_bordered, lu_in_place, lu_solve, mul_vec};

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

/// The sizes of a lowered problem: unknowns (`n`, the first `n_contact` of them contact
/// forces), equalities and cone rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Shape {
    n: usize,
    n_contact: usize,
    m_e: usize,
    m_g: usize,
}

impl Shape {
    fn of(low: &Lowered) -> Self {
        let (m_e, n) = low.eq.shape();
        Shape {
            n,
            n_contact: low.n_contact_vars,
            m_e,
            m_g: low.cone_rows.nrows(),
        }
    }
}

/// The palm scene's problems: the translational formulation (a ground contact, the way-back
/// stop and the joint: 4 unknowns, 3 equalities, 3 cone rows) and the rolling one (two
/// frictional contacts and a prescribed push: 4, 4, 4). A map solves millions of them, and
/// with their sizes known the compiler unrolls their small loops.
const PALM_SHAPES: [Shape; 2] = [
    Shape {
        n: 4,
        n_contact: 3,
        m_e: 3,
        m_g: 3,
    },
    Shape {
        n: 4,
        n_contact: 4,
        m_e: 4,
        m_g: 4,
    },
];

/// Solves a problem for which [`applies`] holds: the optimum in the scaled variables (None:
/// infeasible, the body is not held) and the number of active sets tried.
pub(crate) fn solve_lowered(low: &Lowered) -> (Option<DVector<f64>>, u32) {
    let shape = Shape::of(low);
    let mut scratch = SCRATCH.take();
    let ws = &mut Workspace::new(&mut scratch, shape);
    let answer = if shape == PALM_SHAPES[0] {
        solve_in(low, ws, PALM_SHAPES[0])
    } else if shape == PALM_SHAPES[1] {
        solve_in(low, ws, PALM_SHAPES[1])
    } else {
        solve_in(low, ws, shape)
    };
    SCRATCH.set(scratch);
    answer
}

/// [`solve_lowered`] with its buffers, for a problem of shape `sh`.
#[inline(always)]
fn solve_in(low: &Lowered, ws: &mut Workspace<'_>, sh: Shape) -> (Option<DVector<f64>>, u32) {
    let Shape { n, m_e, m_g, .. } = sh;
    let optimum = |ws: &Workspace<'_>| Some(DVector::from_column_slice(&ws.sol[..n]));
    if determined(low, ws, sh) {
        // The equalities fix every variable: no freedom is left to minimise over.
        let held = cones_hold(low, sh, &ws.sol[..n], 0, ws.values, ws.terms);
        return (if held { optimum(ws) } else { None }, 1);
    }
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
            // The size of the KKT system, known to the compiler for the first two sizes.
            let point = match size {
                0 => kkt_point(low, sh, mask, ws, n + m_e),
                1 => kkt_point(low, sh, mask, ws, n + m_e + 1),
                _ => kkt_point(low, sh, mask, ws, n + m_e + size),
            };
            match point {
                KktPoint::Optimal => return (optimum(ws), tried),
                KktPoint::Rejected { regular } => independent |= mask == 0 && regular,
            }
        }
    }
    (None, tried)
}

/// What the KKT system of one active set gives.
enum KktPoint {
    /// The optimum (in the workspace's `sol`): feasible, with non-negative multipliers.
    Optimal,
    /// Not the optimum; `regular`: its KKT matrix was solved by LU (not by least squares).
    Rejected { regular: bool },
}

/// The buffers a workspace is cut from: every buffer is written before it is read, so they are
/// reused as they are.
#[derive(Default)]
struct Scratch {
    values: Vec<f64>,
    swaps: Vec<(usize, usize)>,
}

thread_local! {
    /// This thread's buffers for the exact path, reused by every problem it solves: a map
    /// solves millions of problems of a few unknowns, and allocating their buffers cost more
    /// than their arithmetic. A nested solve (none today) would find it empty and allocate.
    static SCRATCH: Cell<Scratch> = Cell::new(Scratch::default());
}

/// The buffers of one problem's KKT solves, sized for its largest active set and reused for
/// every set tried: a held palm problem tries four, a map solves millions.
struct Workspace<'a> {
    /// A KKT matrix, column-major, for the least-squares solve.
    kkt: &'a mut [f64],
    /// The LU factors of the set's KKT matrix and their row swaps.
    lu: &'a mut [f64],
    swaps: &'a mut [(usize, usize)],
    /// The LU factors of the empty set's KKT matrix, the leading block of every other set's,
    /// its swaps and their number.
    base_lu: &'a mut [f64],
    base_swaps: &'a mut [(usize, usize)],
    n_base_swaps: usize,
    /// Right-hand side, solution (z, then the equalities' and the active rows' multipliers)
    /// and the residual of a solve.
    rhs: &'a mut [f64],
    sol: &'a mut [f64],
    residual: &'a mut [f64],
    /// Each cone row's value g . z and its terms sum |g_j z_j|.
    values: &'a mut [f64],
    terms: &'a mut [f64],
}

impl<'a> Workspace<'a> {
    /// `scratch` grown as needed and cut into buffers for the KKT systems of `sh`, up to
    /// every cone row active.
    fn new(scratch: &'a mut Scratch, sh: Shape) -> Self {
        let b = sh.n + sh.m_e;
        let k = b + sh.m_g;
        let len = 2 * k * k + b * b + 3 * k + 2 * sh.m_g;
        if scratch.values.len() < len {
            scratch.values.resize(len, 0.0);
        }
        if scratch.swaps.len() < k + b {
            scratch.swaps.resize(k + b, (0, 0));
        }
        let (swaps, base_swaps) = scratch.swaps.split_at_mut(k);
        let (kkt, rest) = scratch.values.split_at_mut(k * k);
        let (lu, rest) = rest.split_at_mut(k * k);
        let (base_lu, rest) = rest.split_at_mut(b * b);
        let (rhs, rest) = rest.split_at_mut(k);
        let (sol, rest) = rest.split_at_mut(k);
        let (residual, rest) = rest.split_at_mut(k);
        let (values, rest) = rest.split_at_mut(sh.m_g);
        Workspace {
            kkt,
            lu,
            swaps,
            base_lu,
            base_swaps: &mut base_swaps[..b],
            n_base_swaps: 0,
            rhs,
            sol,
            residual,
            values,
            terms: &mut rest[..sh.m_g],
        }
    }
}

/// Whether the equalities are square and regular and fix the solution (then in `sol`): the
/// palm scene's rolling formulation, whose minimum is trivial.
#[inline(always)]
fn determined(low: &Lowered, ws: &mut Workspace<'_>, sh: Shape) -> bool {
    let n = sh.n;
    if sh.m_e != n {
        return false;
    }
    let lu = &mut ws.lu[..n * n];
    lu.copy_from_slice(&low.eq.as_slice()[..n * n]);
    let swaps = lu_in_place(lu, n, ws.swaps);
    let z = &mut ws.sol[..n];
    z.copy_from_slice(&low.eq_rhs.as_slice()[..n]);
    lu_solve(lu, n, &ws.swaps[..swaps], z) && equalities_hold(low, sh, z, ws.residual)
}

#[inline(always)]
fn equalities_hold(low: &Lowered, sh: Shape, z: &[f64], residual: &mut [f64]) -> bool {
    let (n, m_e) = (sh.n, sh.m_e);
    let (z, residual) = (&z[..n], &mut residual[..m_e]);
    mul_vec::<false>(&low.eq.as_slice()[..m_e * n], z, residual);
    for (r, e) in residual.iter_mut().zip(&low.eq_rhs.as_slice()[..m_e]) {
        *r -= e;
    }
    z.iter().all(|v| v.is_finite()) && amax(residual) <= TOL * (1.0 + amax(z))
}

/// Whether every cone row holds at `z`, given the active set `active` (a bit per row);
/// `values` and `terms` are buffers of a value per cone row.
///
/// An inactive row `g . z >= 0` decides the verdict: it is judged to TOL of its own terms
/// sum |g_j z_j|, so a contact is judged on its own forces however small they are against the
/// largest load, and never below the roundoff floor ROW_ROUNDOFF of the largest force. An
/// active row is an equality of the KKT system: judged to TOL of the largest force, it rejects
/// the least-squares point of an inconsistent set (an overdetermined KKT system whose
/// multipliers blow up passes the residual test relative to them).
#[inline(always)]
fn cones_hold(
    low: &Lowered,
    sh: Shape,
    z: &[f64],
    active: u32,
    values: &mut [f64],
    terms: &mut [f64],
) -> bool {
    let (n, m_g) = (sh.n, sh.m_g);
    let (z, values, terms) = (&z[..n], &mut values[..m_g], &mut terms[..m_g]);
    let scale = 1.0 + amax(z);
    let cone_rows = &low.cone_rows.as_slice()[..m_g * n];
    mul_vec::<false>(cone_rows, z, values);
    mul_vec::<true>(cone_rows, z, terms);
    (0..m_g).all(|r| {
        let tol = if active & (1 << r) != 0 {
            TOL * scale
        } else {
            TOL * terms[r] + ROW_ROUNDOFF * scale
        };
        values[r] >= -tol
    })
}

/// The KKT point of the `k`-row KKT system of active set `mask`, if it is feasible with
/// non-negative multipliers (then in the workspace's `sol`).
#[inline(always)]
fn kkt_point(low: &Lowered, sh: Shape, mask: u32, ws: &mut Workspace<'_>, k: usize) -> KktPoint {
    let Shape { n, m_e, m_g, .. } = sh;
    let b = n + m_e;
    let mut rows = [0; MAX_CONE_ROWS];
    for (q, r) in (0..m_g).filter(|r| mask & (1 << r) != 0).enumerate() {
        rows[q] = r;
    }
    let active = &rows[..k - b];
    let lu = &mut ws.lu[..k * k];
    let swaps = if mask == 0 {
        // The first set tried: its factors are every other set's leading block.
        fill_kkt(low, sh, active, lu, k);
        let swaps = lu_in_place(lu, k, ws.swaps);
        ws.base_lu[..k * k].copy_from_slice(lu);
        ws.base_swaps[..swaps].copy_from_slice(&ws.swaps[..swaps]);
        ws.n_base_swaps = swaps;
        swaps
    } else {
        fill_border(low, sh, active, lu, k);
        let base_swaps = &ws.base_swaps[..ws.n_base_swaps];
        match lu_bordered(lu, k, &ws.base_lu[..b * b], b, base_swaps, ws.swaps) {
            Some(swaps) => swaps,
            None => {
                fill_kkt(low, sh, active, lu, k);
                lu_in_place(lu, k, ws.swaps)
            }
        }
    };
    // The right-hand side: the equalities' (scaled) loads.
    let sol = &mut ws.sol[..k];
    sol.fill(0.0);
    sol[n..b].copy_from_slice(&low.eq_rhs.as_slice()[..m_e]);

    let residual = &mut ws.residual[..k];
    let regular =
        lu_solve(lu, k, &ws.swaps[..swaps], sol) && consistent(low, sh, active, sol, residual);
    // A singular or inconsistent system: its least-squares point, if that solves it.
    let solved = regular
        || (least_squares(low, sh, active, ws.kkt, ws.rhs, sol)
            && consistent(low, sh, active, sol, residual));
    if !solved {
        return KktPoint::Rejected { regular: false };
    }
    let bound = -TOL * (1.0 + amax(sol));
    let multipliers_ok = sol[b..].iter().all(|w| -w >= bound);
    let z = &ws.sol[..n];
    if multipliers_ok
        && cones_hold(low, sh, z, mask, ws.values, ws.terms)
        && equalities_hold(low, sh, z, ws.residual)
    {
        KktPoint::Optimal
    } else {
        KktPoint::Rejected { regular }
    }
}
/// Whether `sol` solves the KKT system of the cone rows `active` to roundoff: roundoff grows
/// with the solution (a wedged body's forces and multipliers may be orders above the load),
/// so the test is relative to it. A solution of a singular system that is merely close is
/// caught by the checks of z that follow.
#[inline(always)]
fn consistent(
    low: &Lowered,
    sh: Shape,
    active: &[usize],
    sol: &[f64],
    residual: &mut [f64],
) -> bool {
    kkt_residual(low, sh, active, sol, residual);
    sol.iter().all(|v| v.is_finite()) && amax(residual) <= ROUNDOFF * (1.0 + amax(sol))
}

/// Writes the KKT matrix of the cone rows `active` (k x k, column-major; module docs) to `kkt`.
#[inline(always)]
fn fill_kkt(low: &Lowered, sh: Shape, active: &[usize], kkt: &mut [f64], k: usize) {
    let Shape { n, m_e, m_g, .. } = sh;
    let eq = &low.eq.as_slice()[..m_e * n];
    let cone_rows = &low.cone_rows.as_slice()[..m_g * n];
    let (primal, duals) = kkt[..k * k].split_at_mut(n * k);
    // Column c of the unknowns: the objective's 1 (contact forces only), then column c of
    // the equalities and of each active cone row.
    for (c, column) in primal.chunks_exact_mut(k).enumerate() {
        let (objective, rest) = column.split_at_mut(n);
        objective.fill(0.0);
        if c < sh.n_contact {
            objective[c] = 1.0;
        }
        let (equalities, bordering) = rest.split_at_mut(m_e);
        equalities.copy_from_slice(&eq[c * m_e..(c + 1) * m_e]);
        for (v, &r) in bordering.iter_mut().zip(active) {
            *v = cone_rows[c * m_g + r];
        }
    }
    // The multipliers' columns: a row of the equalities or an active cone row, then zeros.
    for (j, column) in duals.chunks_exact_mut(k).enumerate() {
        let (row, zeros) = column.split_at_mut(n);
        let (matrix, m, r) = match j.checked_sub(m_e) {
            None => (eq, m_e, j),
            Some(a) => (cone_rows, m_g, active[a]),
        };
        for (c, v) in row.iter_mut().enumerate() {
            *v = matrix[c * m + r];
        }
        zeros.fill(0.0);
    }
}

/// Writes the rows and columns of the KKT matrix of the cone rows `active` that border the
/// empty set's (those after its `n + m_e`), the part [`lu_bordered`] reads besides the base.
#[inline(always)]
fn fill_border(low: &Lowered, sh: Shape, active: &[usize], kkt: &mut [f64], k: usize) {
    let Shape { n, m_e, m_g, .. } = sh;
    let cone_rows = &low.cone_rows.as_slice()[..m_g * n];
    let b = n + m_e;
    let (leading, bordering) = kkt[..k * k].split_at_mut(b * k);
    for (c, column) in leading.chunks_exact_mut(k).enumerate() {
        for (v, &r) in column[b..].iter_mut().zip(active) {
            // The equalities' multipliers have no entry in a cone row.
            *v = if c < n { cone_rows[c * m_g + r] } else { 0.0 };
        }
    }
    for (column, &r) in bordering.chunks_exact_mut(k).zip(active) {
        let (row, zeros) = column.split_at_mut(n);
        for (c, v) in row.iter_mut().enumerate() {
            *v = cone_rows[c * m_g + r];
        }
        zeros.fill(0.0);
    }
}

/// `residual` = K sol - rhs for the KKT system of the cone rows `active`, from its blocks.
///
/// Each row sums its non-zero entries' terms in the order of the columns, as the dense
/// product does, and leaves out the terms of its zero entries: adding one changes at most the
/// sign of a zero sum, never its magnitude, and a solution that is not finite is refused
/// before the residual counts. So the largest magnitude, all the test reads, is the dense
/// product's (the tests compare the two).
#[inline(always)]
fn kkt_residual(low: &Lowered, sh: Shape, active: &[usize], sol: &[f64], residual: &mut [f64]) {
    let Shape { n, m_e, m_g, .. } = sh;
    let eq = &low.eq.as_slice()[..m_e * n];
    let cone_rows = &low.cone_rows.as_slice()[..m_g * n];
    let b = n + m_e;
    let (primal, rest) = residual.split_at_mut(n);
    let (equalities, bordering) = rest.split_at_mut(m_e);
    for (c, y) in primal.iter_mut().enumerate() {
        *y = if c < sh.n_contact { sol[c] } else { 0.0 };
        for (&e, &w) in eq[c * m_e..(c + 1) * m_e].iter().zip(&sol[n..b]) {
            *y += e * w;
        }
        for (&r, &w) in active.iter().zip(&sol[b..]) {
            *y += cone_rows[c * m_g + r] * w;
        }
    }
    for (e, y) in equalities.iter_mut().enumerate() {
        *y = row_times(eq, m_e, e, &sol[..n]) - low.eq_rhs[e];
    }
    for (&r, y) in active.iter().zip(bordering) {
        *y = row_times(cone_rows, m_g, r, &sol[..n]);
    }
}

/// Row `r` of the column-major matrix `a` of `m` rows times `x`, summed in column order.
#[inline(always)]
fn row_times(a: &[f64], m: usize, r: usize, x: &[f64]) -> f64 {
    let mut terms = x.iter().enumerate().map(|(c, &v)| a[c * m + r] * v);
    let first = terms.next().unwrap_or(0.0);
    terms.fold(first, |y, t| t + y)
}

/// The least-squares solution by SVD of the KKT system of the cone rows `active`, singular
/// or inconsistent, written to `sol` (`kkt` and `rhs` are buffers for the system); false if
/// the SVD fails.
#[cold]
fn least_squares(
    low: &Lowered,
    sh: Shape,
    active: &[usize],
    kkt: &mut [f64],
    rhs: &mut [f64],
    sol: &mut [f64],
) -> bool {
    let (m_e, n) = (sh.m_e, sh.n);
    let k = sol.len();
    fill_kkt(low, sh, active, kkt, k);
    let rhs = &mut rhs[..k];
    rhs.fill(0.0);
    rhs[n..n + m_e].copy_from_slice(low.eq_rhs.as_slice());
    // nalgebra's SVD iterates without end on a NaN or an infinity: no solution then.
    if !kkt[..k * k].iter().chain(rhs.iter()).all(|v| v.is_finite()) {
        return false;
    }
    let solution = DMatrix::from_column_slice(k, k, &kkt[..k * k])
        .svd(true, true)
        .solve(&DVector::from_column_slice(rhs), 1e-13);
    match solution {
        Ok(s) => {
            sol.copy_from_slice(s.as_slice());
            true
        }
        Err(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::minnorm::contact::{Contact, ContactProblem, Joint, Wrench};
    use proptest::prelude::*;

    proptest! {
        /// The KKT residual from the blocks has the dense product's largest magnitude for any
        /// active set and any solution, signed zeros and exact zeros included.
        #[test]
        fn kkt_residual_from_blocks_matches_the_dense_product(
            contacts in prop::collection::vec(
                (0.0..std::f64::consts::TAU, -1.2..1.2_f64, prop_oneof![Just(0.0), 0.05..1.5_f64]),
                1..=3,
            ),
            joint in any::<bool>(),
            push in prop::option::of(1.0..100.0_f64),
            sol in prop::collection::vec(prop_oneof![Just(0.0), Just(-0.0), -10.0..10.0_f64], 20),
            mask in any::<u32>(),
        ) {
            let mut cs: Vec<Contact> = contacts
                .iter()
                .map(|&(phi, tilt, mu)| {
                    let (ts, tc) = (phi + std::f64::consts::PI + tilt).sin_cos();
                    Contact::planar([10.0 * phi.cos(), 10.0 * phi.sin()], [tc, ts], mu)
                })
                .collect();
            if let Some(f) = push {
                cs[0] = cs[0].with_normal_force(f);
            }
            let problem = ContactProblem {
                space: Space::Planar,
                contacts: cs,
                joints: if joint { vec![Joint::Moment { axis: [0.0, 0.0, 1.0] }] } else { vec![] },
                load: Wrench { force_n: [3.0, -20.0, 0.0], moment_nmm: [0.0, 0.0, 5.0] },
            };
            let low = problem.lower().expect("valid");
            let sh = Shape::of(&low);
            let mask = mask % (1 << sh.m_g);
            let active: Vec<usize> = (0..sh.m_g).filter(|r| mask & (1 << r) != 0).collect();
            let k = sh.n + sh.m_e + active.len();
            let sol = &sol[..k];
            let mut kkt = vec![f64::NAN; k * k];
            fill_kkt(&low, sh, &active, &mut kkt, k);
            let mut dense = vec![0.0; k];
            mul_vec::<false>(&kkt, sol, &mut dense);
            for (d, e) in dense[sh.n..sh.n + sh.m_e].iter_mut().zip(low.eq_rhs.iter()) {
                *d -= e;
            }
            let mut blocks = vec![f64::NAN; k];
            kkt_residual(&low, sh, &active, sol, &mut blocks);
            prop_assert_eq!(amax(&blocks).to_bits(), amax(&dense).to_bits());
            for (b, d) in blocks.iter().zip(&dense) {
                prop_assert_eq!(b.abs().to_bits(), d.abs().to_bits());
            }
        }
    }
}
