//! Radau IIA of order 5 with simplified Newton iterations, an embedded error estimate and
//! Gustafsson's predictive step control (Hairer & Wanner, Solving ODEs II, Section IV.8; code
//! RADAU5).
//!
//! The stage increments Z = (z_1, z_2, z_3), z_i = Y_i - y_0, solve
//! `Z = h (A (x) I) F(Z)`. The simplified Newton iteration uses a Jacobian J of an earlier
//! state: `(I - h A (x) J) dZ = -Z + h (A (x) I) F(Z)`. As in RADAU5 this 3n x 3n system is
//! solved in the eigenbasis of A^-1 (W = (T^-1 (x) I) Z, T^-1 A^-1 T = diag(gamma, alpha +- i
//! beta)): one real n x n system `(gamma/h I - J)` and one complex `((alpha + i beta)/h I - J)`,
//! a fraction of the dense 3n x 3n LU's work. Every vector and matrix of a step has its size in
//! its type, so a step allocates nothing.
//!
//! J and the two factorisations are kept from step to step as RADAU5 keeps them: J is
//! evaluated anew only when the Newton iteration converged slowly (contraction theta above
//! `THETA_KEEP_JACOBIAN`), or after a rejection of a step that did not use a fresh one; the
//! matrices are factored anew only when the step size changes, and a step size that would
//! grow by a factor in [1, 1.2] is held (where J is kept too) so that the factorisations serve
//! again.
//!
//! The error estimate is RADAU5's
//! `err = (I - h g0 J)^-1 [g0 h f(y_0) + g0 (e_1 z_1 + e_2 z_2 + e_3 z_3)]`, refined once with
//! f(y_0 + err) after a rejection. As in RADAU5 the user's tolerances are mapped to
//! rtol' = 0.1 rtol^(2/3), atol' = rtol' atol / rtol, because the estimate is of lower order.

use nalgebra::{Complex, Const, DimMin, SMatrix, SVector};

use super::{
    DenseStep, Observer, OdeSystem, Outcome, Stats, StepLoop, Tolerances, initial_step, scaled_norm,
};

const SQ6: f64 = 2.449_489_742_783_178;

/// The implicit Radau IIA method of order 5.
#[derive(Debug, Clone, Copy, Default)]
pub struct Radau5;

struct Coeffs {
    c: [f64; 3],
    /// The Butcher matrix A (the iteration works with its eigenvalues; a test checks them).
    #[cfg(test)]
    a: [[f64; 3]; 3],
    /// RADAU5's dd_i (the error estimate's weights, before the factor g0).
    dd: [f64; 3],
    /// 1 / g0, the real eigenvalue of A^-1.
    u1: f64,
    /// alpha + i beta, the complex eigenvalue of A^-1.
    alpha: f64,
    beta: f64,
}

/// RADAU5's eigenvectors of A^-1: T^-1 A^-1 T = [[gamma, 0, 0], [0, alpha, -beta],
/// [0, beta, alpha]] (a test checks it against the coefficients).
const T: [[f64; 3]; 3] = [
    [
        9.123_239_487_089_294e-2,
        -0.141_255_295_020_954_2,
        -3.002_919_410_514_742_4e-2,
    ],
    [
        0.241_717_932_707_107,
        0.204_129_352_293_799_93,
        0.382_942_112_757_261_9,
    ],
    [0.966_048_182_615_093, 1.0, 0.0],
];

/// T^-1.
const TI: [[f64; 3]; 3] = [
    [
        4.325_579_890_063_155,
        0.339_199_251_815_809_87,
        0.541_770_539_935_874_9,
    ],
    [
        -4.178_718_591_551_905,
        -0.327_682_820_761_062_4,
        0.476_623_554_500_550_45,
    ],
    [
        -0.502_872_634_945_786_9,
        2.571_926_949_855_605,
        -0.596_039_204_828_224_9,
    ],
];

/// Contraction of the Newton iteration up to which J is kept for the next step (RADAU5's
/// THET, default 0.001): a Newton iteration that contracts this fast gains nothing from a
/// fresh J.
const THETA_KEEP_JACOBIAN: f64 = 0.001;

/// Growth of the step size within which the step is held and the factorisations reused
/// (RADAU5's QUOT1 and QUOT2, defaults 1 and 1.2): a factorisation costs more than the few
/// per cent of step it would gain.
const HOLD_STEP: (f64, f64) = (1.0, 1.2);

/// [a b c] x for a 3 x 3 matrix and the three stage vectors, component by component.
fn mul3<const N: usize>(m: &[[f64; 3]; 3], x: &[[f64; N]; 3]) -> [[f64; N]; 3] {
    std::array::from_fn(|k| {
        std::array::from_fn(|i| m[k][0] * x[0][i] + m[k][1] * x[1][i] + m[k][2] * x[2][i])
    })
}

fn coeffs() -> Coeffs {
    let (c81, c9) = (81f64.cbrt(), 9f64.cbrt());
    let u1 = 1.0 / ((6.0 + c81 - c9) / 30.0);
    let (alpha, beta) = ((12.0 - c81 + c9) / 60.0, (c81 + c9) * 3f64.sqrt() / 60.0);
    let norm = alpha * alpha + beta * beta;
    Coeffs {
        c: [(4.0 - SQ6) / 10.0, (4.0 + SQ6) / 10.0, 1.0],
        #[cfg(test)]
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
        alpha: alpha / norm,
        beta: beta / norm,
    }
}

/// LU factors of an n x n matrix with partial pivoting (nalgebra's), or None when it is
/// singular or not finite.
fn factor<T: nalgebra::ComplexField<RealField = f64> + Copy, const N: usize>(
    a: SMatrix<T, N, N>,
) -> Option<nalgebra::LU<T, Const<N>, Const<N>>>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
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
fn divided_differences<const N: usize>(c: [f64; 3], z: &[[f64; N]; 3], out: &mut [[f64; 3]; N]) {
    let [c1, c2, c3] = c;
    for i in 0..N {
        let (z1, z2, z3) = (z[0][i], z[1][i], z[2][i]);
        let f01 = z1 / c1;
        let f12 = (z2 - z1) / (c2 - c1);
        let f23 = (z3 - z2) / (c3 - c2);
        let f012 = (f12 - f01) / c2;
        let f123 = (f23 - f12) / (c3 - c1);
        out[i] = [f01, f012, (f123 - f012) / c3];
    }
}

/// The real and the complex system of one step size, factored: `gamma/h I - J` and
/// `(alpha + i beta)/h I - J`.
struct Factors<const N: usize>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
{
    /// The step size they were factored for.
    h: f64,
    real: nalgebra::LU<f64, Const<N>, Const<N>>,
    complex: nalgebra::LU<Complex<f64>, Const<N>, Const<N>>,
}

impl<const N: usize> Factors<N>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
{
    /// Factors both systems for step `h` and Jacobian `jac`; None if either is singular.
    fn new(cf: &Coeffs, jac: &[[f64; N]; N], h: f64) -> Option<Factors<N>> {
        let real = SMatrix::<f64, N, N>::from_fn(|i, j| {
            let id = if i == j { cf.u1 / h } else { 0.0 };
            id - jac[i][j]
        });
        let eig = Complex::new(cf.alpha / h, cf.beta / h);
        let complex = SMatrix::<Complex<f64>, N, N>::from_fn(|i, j| {
            let id = if i == j { eig } else { Complex::new(0.0, 0.0) };
            id - Complex::new(jac[i][j], 0.0)
        });
        Some(Factors {
            h,
            real: factor(real)?,
            complex: factor(complex)?,
        })
    }

    /// The Newton correction dW of W = T^-1 Z given T^-1 F(Z) (`tf`):
    /// (Lambda / h (x) I - I (x) J) dW = T^-1 F - (Lambda / h) W.
    fn correction(&self, cf: &Coeffs, tf: &[[f64; N]; 3], w: &[[f64; N]; 3]) -> [[f64; N]; 3] {
        let h = self.h;
        let (g, a, b) = (cf.u1 / h, cf.alpha / h, cf.beta / h);
        let mut r1 = SVector::<f64, N>::from_fn(|i, _| tf[0][i] - g * w[0][i]);
        let mut r23 = SVector::<Complex<f64>, N>::from_fn(|i, _| {
            Complex::new(
                tf[1][i] - a * w[1][i] + b * w[2][i],
                tf[2][i] - a * w[2][i] - b * w[1][i],
            )
        });
        self.real.solve_mut(&mut r1);
        self.complex.solve_mut(&mut r23);
        [
            std::array::from_fn(|i| r1[i]),
            std::array::from_fn(|i| r23[i].re),
            std::array::from_fn(|i| r23[i].im),
        ]
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
        Const<N>: DimMin<Const<N>, Output = Const<N>>,
    {
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
        // The stages Z (stage k's component i at [k][i]) and W = T^-1 Z.
        let mut z = [[0.0; N]; 3];
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
        // Whether J was evaluated at the start of the current step (RADAU5's CALJAC).
        let mut jac_fresh = false;
        let mut factors: Option<Factors<N>> = None;
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
                jac_fresh = true;
                factors = None;
            }
            if factors.as_ref().is_none_or(|f| f.h != h) {
                factors = Factors::new(&cf, &jac, h);
            }
            let Some(lu) = factors.as_ref() else {
                lp.reject();
                h *= 0.5;
                need_jac = !jac_fresh;
                continue;
            };
            // Starting values: the previous collocation polynomial extrapolated, or zero.
            if !first {
                for i in 0..N {
                    let d = ddiff[i];
                    let p = |s: f64| s * (d[0] + (s - cf.c[0]) * (d[1] + (s - cf.c[1]) * d[2]));
                    let p1 = p(1.0);
                    for (z_k, c_k) in z.iter_mut().zip(cf.c) {
                        z_k[i] = p(1.0 + c_k * h / h_acc) - p1;
                    }
                }
            } else {
                z = [[0.0; N]; 3];
            }
            let mut w = mul3(&TI, &z);
            // y0 at the start of the step: the Newton iteration's scale and the dense output's
            // base.
            let y_start = *y0;
            // Simplified Newton iteration.
            let mut converged = false;
            let mut newt = 0usize;
            let (mut dynold, mut thqold): (f64, f64) = (0.0, 0.0);
            faccon = faccon.max(uround).powf(0.8);
            let mut theta = THETA_KEEP_JACOBIAN;
            let mut newton_fail: Option<f64> = None;
            while newt < nit {
                let mut fz = [[0.0; N]; 3];
                for k in 0..3 {
                    for i in 0..N {
                        ys[i] = y0[i] + z[k][i];
                    }
                    sys.rhs(t + cf.c[k] * h, &ys, &mut fz[k]);
                }
                lp.stats.rhs_evals += 3;
                let dw = lu.correction(&cf, &mul3(&TI, &fz), &w);
                let dyno = dw
                    .iter()
                    .map(|dw_k| scaled_norm(dw_k, &y_start, &y_start, &tol).powi(2))
                    .sum::<f64>();
                let dyno = (dyno / 3.0).sqrt();
                if !dyno.is_finite() {
                    newton_fail = Some(0.5);
                    break;
                }
                if newt >= 1 {
                    let thq = dyno / dynold;
                    theta = if newt == 1 {
                        thq
                    } else {
                        (thq * thqold).sqrt()
                    };
                    thqold = thq;
                    if theta < 0.99 {
                        faccon = theta / (1.0 - theta);
                        // Iterations left, an integer power as in RADAU5 (a product, not a pow).
                        let rest = (nit - 1 - newt) as i32;
                        let dyth = faccon * dyno * theta.powi(rest) / fnewt;
                        if dyth >= 1.0 {
                            let qnewt = dyth.clamp(1e-4, 20.0);
                            newton_fail = Some(0.8 * qnewt.powf(-1.0 / (4.0 + f64::from(rest))));
                            break;
                        }
                    } else {
                        newton_fail = Some(0.5);
                        break;
                    }
                }
                dynold = dyno.max(uround);
                for (wk, dwk) in w.iter_mut().zip(&dw) {
                    for (wi, d) in wk.iter_mut().zip(dwk) {
                        *wi += d;
                    }
                }
                z = mul3(&T, &w);
                newt += 1;
                if faccon * dyno <= fnewt {
                    converged = true;
                    break;
                }
            }
            if !converged {
                lp.reject();
                h *= newton_fail.unwrap_or(0.5);
                need_jac = !jac_fresh;
                continue;
            }
            // Error estimate.
            for i in 0..N {
                f2[i] = (cf.dd[0] * z[0][i] + cf.dd[1] * z[1][i] + cf.dd[2] * z[2][i]) / h;
                cont[i] = f0[i] + f2[i];
                y1[i] = y0[i] + z[2][i];
            }
            lu.real.solve_mut(&mut cont);
            let mut err = scaled_norm(cont.as_slice(), y0, &y1, &tol);
            if err >= 1.0 && (first || lp.last_rejected) {
                for i in 0..N {
                    ys[i] = y0[i] + cont[i];
                }
                let mut f = [0.0; N];
                sys.rhs(t, &ys, &mut f);
                lp.stats.rhs_evals += 1;
                for i in 0..N {
                    cont[i] = f[i] + f2[i];
                }
                lu.real.solve_mut(&mut cont);
                err = scaled_norm(cont.as_slice(), y0, &y1, &tol);
            }
            if !err.is_finite() {
                lp.reject();
                h *= 0.2;
                need_jac = !jac_fresh;
                continue;
            }
            let err = err.max(1e-10);
            let fac = safe.min(safe * (1.0 + 2.0 * nit as f64) / (newt as f64 + 2.0 * nit as f64));
            // x^(1/4) as two square roots: within an ulp of powf at a fraction of its cost
            // (two calls per step, and the step controller needs no more).
            let fourth_root = |x: f64| x.sqrt().sqrt();
            let mut quot = (fourth_root(err) / fac).clamp(1.0 / fac_grow, fac_shrink);
            if err < 1.0 {
                if !first {
                    let facgus = (h_acc / h) * fourth_root(err * err / err_acc) / safe;
                    quot = quot.max(facgus.clamp(1.0 / fac_grow, fac_shrink));
                }
                h_acc = h;
                err_acc = err.max(1e-2);
                let hnew = (h / quot).min(tol.max_step);
                divided_differences(cf.c, &z, &mut ddiff);
                let dense = Collocation {
                    t0: t,
                    h,
                    y0: &y_start,
                    dd: &ddiff,
                    c: cf.c,
                };
                let h_next = match lp.accept_step(&dense, h, hnew, &y1, y0, obs) {
                    Ok(hnew) => hnew,
                    Err(stopped) => return (stopped, lp.stats),
                };
                sys.rhs(lp.t, y0, &mut f0);
                lp.stats.rhs_evals += 1;
                first = false;
                jac_fresh = false;
                // RADAU5: a Newton iteration that contracted fast keeps J, and a step that
                // would grow by less than 20 % is held, so the factorisations serve again.
                let quick = theta <= THETA_KEEP_JACOBIAN;
                let growth = h_next / h;
                if !(quick && (HOLD_STEP.0..=HOLD_STEP.1).contains(&growth)) {
                    h = h_next;
                }
                need_jac = !quick;
            } else {
                lp.reject();
                h = if first { 0.1 * h } else { h / quot };
                need_jac = !jac_fresh;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    }

    /// The Newton iteration solves in the eigenbasis of A^-1: T^-1 T = I and
    /// A T Lambda = T with Lambda = [[gamma, 0, 0], [0, alpha, -beta], [0, beta, alpha]], the
    /// eigenvalues the factorisations use, to round-off.
    #[test]
    fn t_diagonalises_the_inverse_of_a_into_the_factored_eigenvalues() {
        let cf = coeffs();
        let id = mul(&TI, &T);
        let lambda = [
            [cf.u1, 0.0, 0.0],
            [0.0, cf.alpha, -cf.beta],
            [0.0, cf.beta, cf.alpha],
        ];
        let t_back = mul(&cf.a, &mul(&T, &lambda));
        for i in 0..3 {
            for j in 0..3 {
                let want = if i == j { 1.0 } else { 0.0 };
                assert!(
                    (id[i][j] - want).abs() < 1e-14,
                    "T^-1 T [{i}][{j}] = {}",
                    id[i][j]
                );
                assert!(
                    (t_back[i][j] - T[i][j]).abs() < 1e-14,
                    "A T Lambda [{i}][{j}] = {} vs {}",
                    t_back[i][j],
                    T[i][j]
                );
            }
        }
    }
}
