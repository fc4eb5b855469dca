//! Radau IIA of order 5 with simplified Newton iterations, an embedded error estimate and
//! Gustafsson's predictive step control (Hairer & Wanner, Solving ODEs II, Section IV.8; code
//! RADAU5).
//!
//! The stage increments Z = (z_1, z_2, z_3), z_i = Y_i - y_0, solve
//! `Z = h (A (x) I) F(Z)`. The simplified Newton iteration uses the Jacobian J at the step start:
//! `(I - h A (x) J) dZ = -Z + h (A (x) I) F(Z)`, a dense 3n x 3n system (RADAU5 diagonalises A
//! into one real and one complex n x n system; at n <= 3 the direct LU is as cheap and simpler).
//! Every vector and matrix of a step has its size in its type (nalgebra's fixed-size matrices,
//! 3n given by [`StageDim`]), so a step allocates nothing.
//! The error estimate is RADAU5's
//! `err = (I - h g0 J)^-1 [g0 h f(y_0) + g0 (e_1 z_1 + e_2 z_2 + e_3 z_3)]`, refined once with
//! f(y_0 + err) after a rejection. As in RADAU5 the user's tolerances are mapped to
//! rtol' = 0.1 rtol^(2/3), atol' = rtol' atol / rtol, because the estimate is of lower order.

use nalgebra::allocator::Allocator;
use nalgebra::{Const, DefaultAllocator, DimMin, DimName, OMatrix, OVector, SMatrix, SVector};

use super::{
    DenseStep, Observer, OdeSystem, Outcome, Stats, StepLoop, Tolerances, initial_step, scaled_norm,
};

const SQ6: f64 = 2.449_489_742_783_178;

/// The implicit Radau IIA method of order 5.
#[derive(Debug, Clone, Copy, Default)]
pub struct Radau5;

struct Coeffs {
    c: [f64; 3],
    a: [[f64; 3]; 3],
    /// RADAU5's dd_i (the error estimate's weights, before the factor g0).
    dd: [f64; 3],
    /// 1 / g0, the real eigenvalue of A^-1.
    u1: f64,
}

fn coeffs() -> Coeffs {
    let u1 = {
        let g0 = (6.0 + 81f64.cbrt() - 9f64.cbrt()) / 30.0;
        1.0 / g0
    };
    Coeffs {
        c: [(4.0 - SQ6) / 10.0, (4.0 + SQ6) / 10.0, 1.0],
        a: [
            [
                (88.0 - 7.0 * SQ6) / 360.0,
                (296.0 - 169.0 * SQ6) / 1800.0,
                (-2.0 + 3.0 * SQ6) / 225.0,
            ],
            [
                (296.0 + 169.0 * SQ6) / 1800.0,
                (88.0 + 7.0 * SQ6) / 360.0,
                (-2.0 - 3.0 * SQ6) / 225.0,
            ],
            [(16.0 - SQ6) / 36.0, (16.0 + SQ6) / 36.0, 1.0 / 9.0],
        ],
        dd: [
            -(13.0 + 7.0 * SQ6) / 3.0,
            (-13.0 + 7.0 * SQ6) / 3.0,
            -1.0 / 3.0,
        ],
        u1,
    }
}

/// The size 3n of the stacked stage system of n equations, as a nalgebra dimension (a type: the
/// stable compiler cannot compute 3n from a generic n).
pub trait StageDim {
    /// 3n.
    type Stages: DimName + DimMin<Self::Stages, Output = Self::Stages>;
}

macro_rules! stage_dims {
    ($($n:literal => $m:literal),*) => {
        $(impl StageDim for Const<$n> {
            type Stages = Const<$m>;
        })*
    };
}
stage_dims!(1 => 3, 2 => 6, 3 => 9, 4 => 12);

/// The stage system's dimension for `N` equations.
type Stages<const N: usize> = <Const<N> as StageDim>::Stages;

/// LU factors of a square matrix with partial pivoting (nalgebra's), or None when it is
/// singular or not finite.
fn factor<D>(a: OMatrix<f64, D, D>) -> Option<nalgebra::LU<f64, D, D>>
where
    D: DimName + DimMin<D, Output = D>,
    DefaultAllocator: Allocator<D, D> + Allocator<D>,
{
    if !a.iter().all(|v| v.is_finite()) {
        return None;
    }
    Some(a.lu()).filter(|lu| lu.is_invertible())
}

/// The collocation polynomial of one step: y(t0 + s h) = y0 + P(s), P(0) = 0, P(c_i) = z_i.
struct Collocation<'a, const N: usize> {
    t0: f64,
    h: f64,
    y0: &'a [f64; N],
    /// Newton divided differences on the nodes 0, c1, c2, 1, per component: [d1, d2, d3].
    dd: &'a [[f64; 3]; N],
    c: [f64; 3],
}

impl<const N: usize> Collocation<'_, N> {
    fn increment(&self, s: f64, i: usize) -> f64 {
        let [c1, c2, _] = self.c;
        let d = self.dd[i];
        s * (d[0] + (s - c1) * (d[1] + (s - c2) * d[2]))
    }
}

impl<const N: usize> DenseStep for Collocation<'_, N> {
    fn t_start(&self) -> f64 {
        self.t0
    }
    fn t_end(&self) -> f64 {
        self.t0 + self.h
    }
    fn eval(&self, t: f64, out: &mut [f64]) {
        let s = (t - self.t0) / self.h;
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.y0[i] + self.increment(s, i);
        }
    }
}

/// Divided differences of (0, 0), (c1, z1), (c2, z2), (1, z3) for each component.
fn divided_differences<const N: usize>(c: [f64; 3], z: &[f64], out: &mut [[f64; 3]; N]) {
    let n = N;
    let [c1, c2, c3] = c;
    for i in 0..n {
        let (z1, z2, z3) = (z[i], z[n + i], z[2 * n + i]);
        let f01 = z1 / c1;
        let f12 = (z2 - z1) / (c2 - c1);
        let f23 = (z3 - z2) / (c3 - c2);
        let f012 = (f12 - f01) / c2;
        let f123 = (f23 - f12) / (c3 - c1);
        out[i] = [f01, f012, (f123 - f012) / c3];
    }
}

impl Radau5 {
    /// Integrates from (t0, y0) to t_end; `y0` holds the last accepted state on return.
    pub fn integrate<const N: usize, S: OdeSystem<N> + ?Sized>(
        &self,
        sys: &S,
        t0: f64,
        y0: &mut [f64; N],
        t_end: f64,
        user: &Tolerances,
        obs: &mut dyn Observer,
    ) -> (Outcome, Stats)
    where
        Const<N>: StageDim + DimMin<Const<N>, Output = Const<N>>,
        DefaultAllocator: Allocator<Stages<N>, Stages<N>> + Allocator<Stages<N>>,
    {
        let n = N;
        let cf = coeffs();
        let rtol = 0.1 * user.rtol.powf(2.0 / 3.0);
        let tol = Tolerances {
            rtol,
            atol: rtol * user.atol / user.rtol,
            ..*user
        };
        let uround = f64::EPSILON;
        let fnewt = (10.0 * uround / rtol).max(0.03f64.min(rtol.sqrt()));
        let (safe, nit, fac_grow, fac_shrink): (f64, usize, f64, f64) = (0.9, 7, 8.0, 5.0);

        let mut st = Stats::default();
        let mut f0 = [0.0; N];
        let mut jac = [[0.0; N]; N];
        // The stages' vectors, stage k's component i at k n + i.
        let mut z = OVector::<f64, Stages<N>>::zeros();
        let mut dz = OVector::<f64, Stages<N>>::zeros();
        let mut fz = OVector::<f64, Stages<N>>::zeros();
        let mut ys = [0.0; N];
        let mut y1 = [0.0; N];
        let mut cont = SVector::<f64, N>::zeros();
        let mut f2 = [0.0; N];
        let mut ddiff = [[0.0; 3]; N];

        sys.rhs(t0, y0, &mut f0);
        st.rhs_evals += 1;
        let mut h = initial_step(sys, t0, y0, &f0, 5.0, &tol, &mut st.rhs_evals);
        let mut lp = StepLoop::new(t0, st);
        let mut need_jac = true;
        // No step accepted yet (so no collocation polynomial to start Newton from).
        let mut first = true;
        let mut faccon: f64 = 1.0;
        let (mut h_acc, mut err_acc) = (h, 1e-2);

        loop {
            h = match lp.begin_step(t_end, h, &tol) {
                Ok(h) => h,
                Err(end) => return (end, lp.stats),
            };
            let t = lp.t;
            if need_jac {
                sys.jacobian(t, y0, &mut jac);
                lp.stats.jacobian_evals += 1;
                need_jac = false;
            }
            // I - h (A (x) J) and u1/h I - J.
            let big = OMatrix::<f64, Stages<N>, Stages<N>>::from_fn(|r, c| {
                let (bi, i, bj, j) = (r / n, r % n, c / n, c % n);
                let id = if bi == bj && i == j { 1.0 } else { 0.0 };
                id - h * cf.a[bi][bj] * jac[i][j]
            });
            let small = SMatrix::<f64, N, N>::from_fn(|i, j| {
                let id = if i == j { cf.u1 / h } else { 0.0 };
                id - jac[i][j]
            });
            let Some((lu_big, lu_small)) = factor::<Stages<N>>(big).zip(factor::<Const<N>>(small))
            else {
                lp.reject();
                h *= 0.5;
                continue;
            };
            // Starting values: the previous collocation polynomial extrapolated, or zero.
            if !first {
                for i in 0..n {
                    let d = ddiff[i];
                    let p = |s: f64| s * (d[0] + (s - cf.c[0]) * (d[1] + (s - cf.c[1]) * d[2]));
                    let p1 = p(1.0);
                    for k in 0..3 {
                        z[k * n + i] = p(1.0 + cf.c[k] * h / h_acc) - p1;
                    }
                }
            } else {
                z.fill(0.0);
            }
            // y0 at the start of the step: the Newton iteration's scale and the dense output's
            // base.
            let y_start = *y0;
            // Simplified Newton iteration.
            let mut converged = false;
            let mut newt = 0usize;
            let (mut dynold, mut thqold): (f64, f64) = (0.0, 0.0);
            faccon = faccon.max(uround).powf(0.8);
            let mut newton_fail: Option<f64> = None;
            while newt < nit {
                for k in 0..3 {
                    for i in 0..n {
                        ys[i] = y0[i] + z[k * n + i];
                    }
                    let mut f = [0.0; N];
                    sys.rhs(t + cf.c[k] * h, &ys, &mut f);
                    fz.rows_mut(k * n, n).copy_from_slice(&f);
                }
                lp.stats.rhs_evals += 3;
                for k in 0..3 {
                    for i in 0..n {
                        let s: f64 = (0..3).map(|j| cf.a[k][j] * fz[j * n + i]).sum();
                        dz[k * n + i] = -z[k * n + i] + h * s;
                    }
                }
                lu_big.solve_mut(&mut dz);
                let dyno = (0..3)
                    .map(|k| {
                        let dz_k = &dz.as_slice()[k * n..(k + 1) * n];
                        scaled_norm(dz_k, &y_start, &y_start, &tol).powi(2)
                    })
                    .sum::<f64>();
                let dyno = (dyno / 3.0).sqrt();
                if !dyno.is_finite() {
                    newton_fail = Some(0.5);
                    break;
                }
                if newt >= 1 {
                    let thq = dyno / dynold;
                    let theta = if newt == 1 {
                        thq
                    } else {
                        (thq * thqold).sqrt()
                    };
                    thqold = thq;
                    if theta < 0.99 {
                        faccon = theta / (1.0 - theta);
                        let rest = (nit - 1 - newt) as f64;
                        let dyth = faccon * dyno * theta.powf(rest) / fnewt;
                        if dyth >= 1.0 {
                            let qnewt = dyth.clamp(1e-4, 20.0);
                            newton_fail = Some(0.8 * qnewt.powf(-1.0 / (4.0 + rest)));
                            break;
                        }
                    } else {
                        newton_fail = Some(0.5);
                        break;
                    }
                }
                dynold = dyno.max(uround);
                for (zi, d) in z.iter_mut().zip(&dz) {
                    *zi += d;
                }
                newt += 1;
                if faccon * dyno <= fnewt {
                    converged = true;
                    break;
                }
            }
            if !converged {
                lp.reject();
                h *= newton_fail.unwrap_or(0.5);
                continue;
            }
            // Error estimate.
            for i in 0..n {
                f2[i] = (cf.dd[0] * z[i] + cf.dd[1] * z[n + i] + cf.dd[2] * z[2 * n + i]) / h;
                cont[i] = f0[i] + f2[i];
                y1[i] = y0[i] + z[2 * n + i];
            }
            lu_small.solve_mut(&mut cont);
            let mut err = scaled_norm(cont.as_slice(), y0, &y1, &tol);
            if err >= 1.0 && (first || lp.last_rejected) {
                for i in 0..n {
                    ys[i] = y0[i] + cont[i];
                }
                let mut f = [0.0; N];
                sys.rhs(t, &ys, &mut f);
                lp.stats.rhs_evals += 1;
                for i in 0..n {
                    cont[i] = f[i] + f2[i];
                }
                lu_small.solve_mut(&mut cont);
                err = scaled_norm(cont.as_slice(), y0, &y1, &tol);
            }
            if !err.is_finite() {
                lp.reject();
                h *= 0.2;
                continue;
            }
            let err = err.max(1e-10);
            let fac = safe.min(safe * (1.0 + 2.0 * nit as f64) / (newt as f64 + 2.0 * nit as f64));
            let mut quot = (err.powf(0.25) / fac).clamp(1.0 / fac_grow, fac_shrink);
            if err < 1.0 {
                if !first {
                    let facgus = (h_acc / h) * (err * err / err_acc).powf(0.25) / safe;
                    quot = quot.max(facgus.clamp(1.0 / fac_grow, fac_shrink));
                }
                h_acc = h;
                err_acc = err.max(1e-2);
                let hnew = (h / quot).min(tol.max_step);
                divided_differences(cf.c, z.as_slice(), &mut ddiff);
                let dense = Collocation {
                    t0: t,
                    h,
                    y0: &y_start,
                    dd: &ddiff,
                    c: cf.c,
                };
                h = match lp.accept_step(&dense, h, hnew, &y1, y0, obs) {
                    Ok(hnew) => hnew,
                    Err(stopped) => return (stopped, lp.stats),
                };
                sys.rhs(lp.t, y0, &mut f0);
                lp.stats.rhs_evals += 1;
                need_jac = true;
                first = false;
            } else {
                lp.reject();
                h = if first { 0.1 * h } else { h / quot };
            }
        }
    }
}
