//! Dormand-Prince 5(4) with FSAL, a PI step-size controller and 4th-order dense output
//! (Hairer, Norsett & Wanner, Solving ODEs I, Section II.5; code DOPRI5).

use super::{
    DenseStep, Failure, Observer, OdeSystem, Outcome, Stats, StepLoop, Tolerances, initial_step,
    scaled_norm,
};

const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// Accepted steps between two stiffness tests (Hairer's NSTIFF, default 1000): the test costs
/// two norms, but an explicit method needs hundreds of steps before stiffness shows in them.
const STIFFNESS_TEST_EVERY: u64 = 1000;

/// h * |lambda| above which a step is counted stiff: 3.25, Hairer's bound, just inside the
/// boundary of DOPRI5's stability region on the negative real axis (about 3.3).
const STIFF_H_LAMBDA: f64 = 3.25;

/// Stiff steps in a row that stop the integration (Hairer's 15): a transient leaves the region
/// boundary within a few steps, a stiff problem keeps the step on it.
const STIFF_STEPS_TO_STOP: u32 = 15;

/// Non-stiff tests in a row that clear the count of stiff ones (Hairer's 6).
const NONSTIFF_STEPS_TO_CLEAR: u32 = 6;

/// The explicit Dormand-Prince 5(4) method.
#[derive(Debug, Clone, Copy, Default)]
pub struct Dopri5;

/// Accepted steps over which the pace of a stretch held at the stability limit is read: the
/// largest step of the last 64 to 128 (two blocks of 64), so that the controller's wandering
/// about the limit from one step to the next does not pass for the pace.
const PACE_BLOCK: u32 = 64;

/// Hairer's stiffness test (Solving ODEs II, Section IV.2; code DOPRI5): an estimate of
/// h * |lambda| along the step, from the last two stages, which sit at the same time t + h;
/// and the pace of a stretch it finds held at the stability limit.
#[derive(Debug, Default)]
struct StiffnessTest {
    stiff_in_a_row: u32,
    nonstiff_in_a_row: u32,
    /// The largest step of the current block of `PACE_BLOCK` held steps, and of the block
    /// before it, in the units of t.
    pace_blocks: [f64; 2],
    /// Held steps in the current block.
    in_block: u32,
}

impl StiffnessTest {
    /// Judges the accepted step number `accepted` of size `h`: `f_end` = f(t + h, y1) at the
    /// solution, `f_stage6` = f(t + h, y_stage6). Returns whether the step size has been held
    /// at DOPRI5's stability limit for `STIFF_STEPS_TO_STOP` tests in a row.
    fn is_stiff(
        &mut self,
        accepted: u64,
        h: f64,
        f_end: &[f64],
        f_stage6: &[f64],
        y1: &[f64],
        y_stage6: &[f64],
    ) -> bool {
        if !accepted.is_multiple_of(STIFFNESS_TEST_EVERY) && self.stiff_in_a_row == 0 {
            return false;
        }
        let sq = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>();
        let (num, den) = (sq(f_end, f_stage6), sq(y1, y_stage6));
        let h_lambda = if den > 0.0 {
            h * (num / den).sqrt()
        } else {
            0.0
        };
        if h_lambda > STIFF_H_LAMBDA {
            self.nonstiff_in_a_row = 0;
            self.stiff_in_a_row += 1;
        } else {
            self.nonstiff_in_a_row += 1;
            if self.nonstiff_in_a_row >= NONSTIFF_STEPS_TO_CLEAR {
                *self = StiffnessTest::default();
            }
        }
        let stiff = self.stiff_in_a_row >= STIFF_STEPS_TO_STOP;
        if stiff {
            self.pace_blocks[0] = self.pace_blocks[0].max(h);
            self.in_block += 1;
            if self.in_block == PACE_BLOCK {
                self.pace_blocks = [0.0, self.pace_blocks[0]];
                self.in_block = 0;
            }
        }
        stiff
    }

    /// The fewest steps a run held at the stability limit still needs from `t` to `end`: the
    /// time left at the pace held now, the largest step of the last `PACE_BLOCK` to
    /// 2 `PACE_BLOCK` held steps. While the stiffness does not relax the limit does not grow
    /// (on a contact pressed ever harder it shrinks), so the run needs at least that many:
    /// a verdict drawn from this number is one the run would have borne out.
    fn fewest_steps_to(&self, t: f64, end: f64) -> f64 {
        let pace = self.pace_blocks[0].max(self.pace_blocks[1]);
        (end - t) / pace
    }
}

struct Dense<'a, const N: usize> {
    t0: f64,
    h: f64,
    r: &'a [[f64; N]; 5],
}

impl<const N: usize> DenseStep for Dense<'_, N> {
    fn t_start(&self) -> f64 {
        self.t0
    }
    fn t_end(&self) -> f64 {
        self.t0 + self.h
    }
    fn eval(&self, t: f64, out: &mut [f64]) {
        let s = (t - self.t0) / self.h;
        let s1 = 1.0 - s;
        let r = self.r;
        for (i, o) in out.iter_mut().enumerate() {
            *o = r[0][i] + s * (r[1][i] + s1 * (r[2][i] + s * (r[3][i] + s1 * r[4][i])));
        }
    }
}

impl Dopri5 {
    /// Integrates from (t0, y0) to t_end; `y0` holds the last accepted state on return.
    pub fn integrate<const N: usize, S: OdeSystem<N> + ?Sized>(
        &self,
        sys: &S,
        t0: f64,
        y0: &mut [f64; N],
        t_end: f64,
        tol: &Tolerances,
        obs: &mut dyn Observer,
    ) -> (Outcome, Stats) {
        let n = N;
        let mut st = Stats::default();
        let mut k = [[0.0; N]; 7];
        let mut r = [[0.0; N]; 5];
        let mut ys = [0.0; N];
        let mut y1 = [0.0; N];
        let mut err = [0.0; N];
        sys.rhs(t0, y0, &mut k[0]);
        st.rhs_evals += 1;
        let mut h = initial_step(sys, t0, y0, &k[0], 5.0, tol, &mut st.rhs_evals);
        let mut lp = StepLoop::new(t0, st);
        let (safe, beta, fac_min, fac_max) = (0.9, 0.04, 0.2, 10.0);
        let expo1 = 0.2 - beta * 0.75;
        let mut facold: f64 = 1e-4;
        let mut stiffness = StiffnessTest::default();
        loop {
            h = match lp.begin_step(t_end, h, tol) {
                Ok(h) => h,
                Err(end) => return (end, lp.stats),
            };
            let t = lp.t;
            let stage = |ys: &mut [f64; N], k: &[[f64; N]; 7], coef: &[(usize, f64)]| {
                for i in 0..n {
                    ys[i] = y0[i] + h * coef.iter().map(|&(j, a)| a * k[j][i]).sum::<f64>();
                }
            };
            stage(&mut ys, &k, &[(0, A21)]);
            sys.rhs(t + C2 * h, &ys, &mut k[1]);
            stage(&mut ys, &k, &[(0, A31), (1, A32)]);
            sys.rhs(t + C3 * h, &ys, &mut k[2]);
            stage(&mut ys, &k, &[(0, A41), (1, A42), (2, A43)]);
            sys.rhs(t + C4 * h, &ys, &mut k[3]);
            stage(&mut ys, &k, &[(0, A51), (1, A52), (2, A53), (3, A54)]);
            sys.rhs(t + C5 * h, &ys, &mut k[4]);
            stage(
                &mut ys,
                &k,
                &[(0, A61), (1, A62), (2, A63), (3, A64), (4, A65)],
            );
            sys.rhs(t + h, &ys, &mut k[5]);
            stage(
                &mut y1,
                &k,
                &[(0, A71), (2, A73), (3, A74), (4, A75), (5, A76)],
            );
            let (head, tail) = k.split_at_mut(6);
            sys.rhs(t + h, &y1, &mut tail[0]);
            lp.stats.rhs_evals += 6;
            for i in 0..n {
                err[i] = h
                    * (E1 * head[0][i]
                        + E3 * head[2][i]
                        + E4 * head[3][i]
                        + E5 * head[4][i]
                        + E6 * head[5][i]
                        + E7 * tail[0][i]);
            }
            let e = scaled_norm(&err, y0, &y1, tol);
            if !e.is_finite() {
                lp.reject();
                h *= 0.1;
                continue;
            }
            let fac11 = e.powf(expo1);
            if e <= 1.0 {
                let fac = (fac11 / facold.powf(beta) / safe).clamp(1.0 / fac_max, 1.0 / fac_min);
                let hnew = h / fac;
                facold = e.max(1e-4);
                for i in 0..n {
                    let dy = y1[i] - y0[i];
                    let bspl = h * k[0][i] - dy;
                    r[0][i] = y0[i];
                    r[1][i] = dy;
                    r[2][i] = bspl;
                    r[3][i] = dy - h * k[6][i] - bspl;
                    r[4][i] = h
                        * (D1 * k[0][i]
                            + D3 * k[2][i]
                            + D4 * k[3][i]
                            + D5 * k[4][i]
                            + D6 * k[5][i]
                            + D7 * k[6][i]);
                }
                // ys still holds the sixth stage, at t + h like y1.
                let stiff = stiffness.is_stiff(lp.stats.steps + 1, h, &k[6], &k[5], &y1, &ys);
                let dense = Dense { t0: t, h, r: &r };
                h = match lp.accept_step(&dense, h, hnew, &y1, y0, obs) {
                    Ok(hnew) => hnew.min(tol.max_step),
                    Err(stopped) => return (stopped, lp.stats),
                };
                // A stiff problem is still solved, at the price of steps held at the stability
                // limit: give up only when the fewest steps that pace needs to the end (t_end,
                // or where the observer expects to stop) exceed what is left of the step budget.
                // So `Stiff` says what the run would have met, its step limit, only sooner; an
                // answer within reach is never thrown away.
                if stiff {
                    let used = lp.stats.steps + lp.stats.rejected;
                    let budget = tol.max_steps.saturating_sub(used) as f64;
                    let end = obs.horizon().map_or(t_end, |t| t.min(t_end));
                    let needed = stiffness.fewest_steps_to(lp.t, end);
                    if needed > budget {
                        let failure = Failure::Stiff {
                            t_s: lp.t,
                            steps: lp.stats.steps,
                            // Saturates for an infinite need (a pace of zero).
                            steps_needed: needed.ceil() as u64,
                        };
                        return (Outcome::Failed(failure), lp.stats);
                    }
                }
                k.swap(0, 6);
            } else {
                lp.reject();
                h /= (fac11 / safe).min(1.0 / fac_min);
            }
        }
    }
}
