//! Equations of motion of the palm and the disc, right-hand side and analytic Jacobian.
//!
//! State y = (theta, x, v): palm angle (rad), disc centre abscissa (mm), disc speed (mm/s).
//! With t = (cos theta, sin theta) along the palm and n = (sin theta, -cos theta) its normal
//! towards the disc, the palm's contact face is the line {p : p . n = h} (h the offset):
//!
//! ```text
//! delta     = r + h + r cos theta - x sin theta         penetration (mm)
//! s_B       = x cos theta + r sin theta                 contact distance from the hinge (mm)
//! delta_dot = -(v sin theta + s_B theta_dot)            (mm/s)
//! u_B       = v cos theta - theta_dot h                 slip of the disc on the palm's face along t (mm/s)
//! N         = IMPACT(delta, delta_dot)                  palm normal force on the disc (N)
//! mu_B      = mu_palm(u_B),   mu_A = mu_ground(v)       Adams friction laws (signed)
//! P_x       = N (sin theta - mu_B cos theta)            palm force on the disc along X (N)
//! R_n       = m g + N (cos theta + mu_B sin theta)      joint reaction (N), Eq. 1 corrected
//! m v_dot   = P_x - mu_A |R_n|                          (v_dot in mm/s^2 = 1000 N/kg)
//! ```
//!
//! With delta = 0 these are the paper's Eq. 2 (x = r cot(theta/2) for h = 0) and, at constant
//! speed with the palm sliding, the corrected Eq. 1. The slip u_B is measured at the palm's face
//! (the foot of the perpendicular from the disc centre), where the palm's material moves along t
//! at theta_dot h; measured at the disc's surface, a millimetre-deep penetration after the jam
//! would drag the palm's material past the disc at omega delta and keep the palm contact from
//! sticking. The drive sets theta_dot:
//!
//! * motion: theta_dot = -omega;
//! * force: theta_dot = -omega (1 - STEP(N, (1 - b) N_max, 0, N_max, 1)) with the contact's
//!   normal force N (IMPACT, below) and N_max = F cos(atan mu_palm). This is a massless palm on a self-locking
//!   speed drive with a force limit: it turns at omega until the push reaches the limit, then
//!   stalls without backing off. The limit is on the normal force, so the palm's total push
//!   N / cos(alpha_p) saturates at F while it slides, as in the closed form. It senses the whole
//!   contact force, damping included (sensing the elastic part alone let the
//!   first impact push 10 N against a 3.55 N limit); since the damping part depends on
//!   theta_dot, theta_dot solves that equation at each evaluation (`force_drive`).

use super::contact::{FrictionLaw, ImpactLaw, step};
use super::integrators::OdeSystem;
use super::params::{Drive, DynamicsParams};
use crate::dynamics::MM_PER_M;
use crate::scene::SceneParams;

/// The system in the units of the state; built once per simulation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct System {
    /// r in mm.
    pub radius: f64,
    /// h in mm.
    pub offset: f64,
    /// m in kg.
    pub mass: f64,
    /// m g in N.
    pub weight: f64,
    /// omega in rad/s.
    pub omega: f64,
    pub drive: Drive,
    /// N_max = F cos(atan mu_palm) in N (force drive).
    pub normal_limit: f64,
    /// b, the width of the force limit band as a fraction of N_max.
    pub band: f64,
    pub impact: ImpactLaw,
    pub palm_friction: FrictionLaw,
    pub ground_friction: FrictionLaw,
}

/// Forces and kinematics at one state, for the series and for the Jacobian.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Forces {
    /// theta_dot in rad/s.
    pub theta_dot: f64,
    /// delta in mm.
    pub penetration: f64,
    /// N in N.
    pub normal: f64,
    /// Palm friction on the disc along -t, mu_B N, in N.
    pub palm_friction: f64,
    /// R_n in N.
    pub ground_normal: f64,
    /// Ground friction on the disc along X, -mu_A |R_n|, in N.
    pub ground_friction: f64,
    /// v_dot in mm/s^2.
    pub accel: f64,
}

/// The palm's geometry at one state (see [`System::geometry`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// delta in mm (negative: the palm is clear of the disc).
    pub penetration: f64,
    /// s_B in mm.
    pub contact_distance: f64,
    /// The disc speed a rigid contact would impose, [`System::geometric_speed`], in mm/s.
    pub geometric_speed: f64,
}

type Grad = [f64; 3];

fn axpy(a: f64, x: &Grad, y: &Grad) -> Grad {
    [a * x[0] + y[0], a * x[1] + y[1], a * x[2] + y[2]]
}

fn scale(a: f64, x: &Grad) -> Grad {
    [a * x[0], a * x[1], a * x[2]]
}

impl System {
    /// Builds the system from validated parameters.
    pub fn new(scene: &SceneParams, d: &DynamicsParams) -> System {
        let law = |mu_d: f64, mu_s: Option<f64>| FrictionLaw {
            mu_static: mu_s.unwrap_or(mu_d),
            mu_dynamic: mu_d,
            v_static: d.friction.stiction_velocity_mm_s,
            v_dynamic: d.friction.friction_velocity_mm_s,
        };
        System {
            radius: scene.radius_mm,
            offset: scene.palm_offset_mm,
            mass: scene.mass_kg,
            weight: scene.weight_n(),
            omega: d.drive.omega_deg_s.to_radians(),
            drive: d.drive.mode,
            normal_limit: scene.force_n * scene.alpha_palm().cos(),
            band: d.drive.force_band,
            impact: ImpactLaw {
                stiffness: d.contact.stiffness_n_per_mm_e,
                exponent: d.contact.exponent,
                damping: d.contact.damping_n_s_per_mm,
                depth: d.contact.damping_depth_mm,
            },
            palm_friction: law(scene.mu_palm, d.friction.mu_static_palm),
            ground_friction: law(scene.mu_ground, d.friction.mu_static_ground),
        }
    }

    /// Disc position (mm) where the palm at `theta` (rad) just touches it: delta = 0.
    pub fn touching_x(&self, theta: f64) -> f64 {
        (self.radius * (1.0 + theta.cos()) + self.offset) / theta.sin()
    }

    /// The palm angle (rad, in (0, pi)) at which the palm just touches a disc at `x` (mm): the
    /// inverse of [`System::touching_x`]. r cos theta - x sin theta = -(r + h) is
    /// R cos(theta + phi) = -(r + h) with R = sqrt(r^2 + x^2), phi = atan2(x, r).
    pub fn touching_theta(&self, x: f64) -> f64 {
        let r = self.radius;
        (-(r + self.offset) / r.hypot(x)).clamp(-1.0, 1.0).acos() - x.atan2(r)
    }

    /// The speed (mm/s) at which the disc must move to stay in touch with the palm turning at
    /// omega: -omega d/dtheta of [`System::touching_x`] = omega (r + (r + h) cos theta) / sin^2 theta,
    /// which is r omega / (2 sin^2(theta/2)) for h = 0.
    pub fn geometric_speed(&self, theta: f64) -> f64 {
        let (s, c) = theta.sin_cos();
        self.geometric_speed_at(s, c)
    }

    /// Contact distance s_B from the hinge along the palm, in mm, for state `y`.
    pub fn contact_distance(&self, y: &[f64]) -> f64 {
        let (s, c) = y[0].sin_cos();
        self.contact_distance_at(y[1], s, c)
    }

    /// s_B = x cos theta + r sin theta in mm, given sin theta and cos theta.
    fn contact_distance_at(&self, x: f64, s: f64, c: f64) -> f64 {
        x * c + self.radius * s
    }

    /// delta = r + h + r cos theta - x sin theta in mm, given sin theta and cos theta.
    fn penetration_at(&self, x: f64, s: f64, c: f64) -> f64 {
        let (r, h) = (self.radius, self.offset);
        r + h + r * c - x * s
    }

    /// [`System::geometric_speed`] given sin theta and cos theta.
    fn geometric_speed_at(&self, s: f64, c: f64) -> f64 {
        self.omega * (self.radius + (self.radius + self.offset) * c) / (s * s)
    }

    /// The palm's geometry at state `y`, from one sin_cos: what the jam reading looks at after
    /// every step (the forces cost a `powf` more and are not needed there).
    pub fn geometry(&self, y: &[f64]) -> Geometry {
        let (s, c) = y[0].sin_cos();
        Geometry {
            penetration: self.penetration_at(y[1], s, c),
            contact_distance: self.contact_distance_at(y[1], s, c),
            geometric_speed: self.geometric_speed_at(s, c),
        }
    }

    /// Forces at state `y`, and, if `jac` is given, the Jacobian d f / d y (row-major 3x3).
    pub fn evaluate(&self, y: &[f64], jac: Option<&mut [f64]>) -> Forces {
        // Two copies of the body: the one without a Jacobian drops the gradients' arithmetic,
        // about half of it (the right-hand side of every step of every integrator).
        match jac {
            Some(j) => self.evaluate_inline(y, Some(j)),
            None => self.evaluate_inline(y, None),
        }
    }

    #[inline(always)]
    fn evaluate_inline(&self, y: &[f64], jac: Option<&mut [f64]>) -> Forces {
        let (theta, x, v) = (y[0], y[1], y[2]);
        let (s, c) = theta.sin_cos();
        let (r, h) = (self.radius, self.offset);
        let delta = self.penetration_at(x, s, c);
        let g_delta: Grad = [-(x * c + r * s), -s, 0.0];
        let s_b = self.contact_distance_at(x, s, c);
        let g_sb: Grad = [r * c - x * s, c, 0.0];

        let elastic = self.impact.elastic(delta);
        let (theta_dot, g_td) = match self.drive {
            Drive::Motion => (-self.omega, [0.0; 3]),
            Drive::Force => self.force_drive(elastic, delta, &g_delta, v, s, c, s_b, &g_sb),
        };
        let rate = -(v * s + s_b * theta_dot);
        // d rate = -(v c dtheta + s dv + theta_dot d s_B + s_B d theta_dot)
        let mut g_rate = axpy(theta_dot, &g_sb, &scale(s_b, &g_td));
        g_rate[0] += v * c;
        g_rate[2] += s;
        let g_rate = scale(-1.0, &g_rate);

        let imp = self.impact.force(delta, rate, elastic);
        let n = imp.normal;
        let g_n = axpy(imp.d_delta, &g_delta, &scale(imp.d_rate, &g_rate));

        let u_b = v * c - theta_dot * h;
        let mut g_ub = scale(-h, &g_td);
        g_ub[0] -= v * s;
        g_ub[2] += c;
        let (mu_b, dmu_b) = self.palm_friction.coefficient(u_b);
        let g_mub = scale(dmu_b, &g_ub);

        let px_k = s - mu_b * c;
        let mut g_pxk = scale(-c, &g_mub);
        g_pxk[0] += c + mu_b * s;
        let p_x = n * px_k;
        let g_px = axpy(px_k, &g_n, &scale(n, &g_pxk));

        let py_k = c + mu_b * s;
        let mut g_pyk = scale(s, &g_mub);
        g_pyk[0] += -s + mu_b * c;
        let r_n = self.weight + n * py_k;
        let g_rn = axpy(py_k, &g_n, &scale(n, &g_pyk));

        let (mu_a, dmu_a) = self.ground_friction.coefficient(v);
        let f_a = -mu_a * r_n.abs();
        let mut g_fa = scale(-mu_a * r_n.signum(), &g_rn);
        g_fa[2] -= dmu_a * r_n.abs();

        let k = MM_PER_M / self.mass;
        let accel = k * (p_x + f_a);
        if let Some(j) = jac {
            j[..3].copy_from_slice(&g_td);
            j[3..6].copy_from_slice(&[0.0, 0.0, 1.0]);
            let g_acc = scale(k, &axpy(1.0, &g_px, &g_fa));
            j[6..9].copy_from_slice(&g_acc);
        }
        Forces {
            theta_dot,
            penetration: delta,
            normal: n,
            palm_friction: mu_b * n,
            ground_normal: r_n,
            ground_friction: f_a,
            accel,
        }
    }

    /// The force drive's palm rate theta_dot and its gradient d theta_dot / d y.
    ///
    /// The drive senses the whole normal force N = k delta^e + c(delta) delta_dot, whose
    /// damping part depends on theta_dot through delta_dot = -(v sin theta + s_B theta_dot):
    /// theta_dot solves theta_dot = -omega (1 - w(N(theta_dot))). The right side falls as
    /// theta_dot grows (a slower palm closes the contact slower), so the root in [-omega, 0] is
    /// unique; it is found to round-off ([`rate_root`]), and its gradient by the implicit
    /// function theorem, d theta_dot (1 + omega w' c s_B) = omega w' dN|theta_dot.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn force_drive(
        &self,
        (el, d_el): (f64, f64),
        delta: f64,
        g_delta: &Grad,
        v: f64,
        s: f64,
        c: f64,
        s_b: f64,
        g_sb: &Grad,
    ) -> (f64, Grad) {
        let (damp, d_damp) = if delta > 0.0 {
            step(delta, 0.0, 0.0, self.impact.depth, self.impact.damping)
        } else {
            (0.0, 0.0)
        };
        let normal = |td: f64| el + damp * -(v * s + s_b * td);
        let mut td = rate_root(self.rate_residual(el, damp, v, s, s_b), -self.omega, 0.0);
        let n = normal(td);
        let (w, dw) = self.limit(n);
        td = -self.omega * (1.0 - w);
        if n <= 0.0 || dw == 0.0 {
            return (td, [0.0; 3]);
        }
        // dN at fixed theta_dot: the elastic part, the damping ramp and delta_dot's own terms.
        let rate = -(v * s + s_b * td);
        let mut g_n = scale(d_el + d_damp * rate, g_delta);
        let g_rate = [-(v * c + td * g_sb[0]), -td * g_sb[1], -s - td * g_sb[2]];
        g_n = axpy(damp, &g_rate, &g_n);
        let k = self.omega * dw;
        (td, scale(k / (1.0 + k * damp * s_b), &g_n))
    }

    /// The force drive's STEP w(N) of the normal force N (N) and its slope dw / dN.
    fn limit(&self, n: f64) -> (f64, f64) {
        let lim = self.normal_limit;
        step(n.max(0.0), (1.0 - self.band) * lim, 0.0, lim, 1.0)
    }

    /// The force drive's equation for theta_dot as a residual theta_dot + omega (1 - w(N))
    /// and its slope 1 + omega w'(N) c s_B (>= 1: N falls with theta_dot at the rate c s_B),
    /// given the elastic force `el` (N), the damping `damp` (N s/mm), v, sin theta and s_B.
    fn rate_residual(
        &self,
        el: f64,
        damp: f64,
        v: f64,
        s: f64,
        s_b: f64,
    ) -> impl Fn(f64) -> (f64, f64) + '_ {
        move |td: f64| {
            let (w, dw) = self.limit(el + damp * -(v * s + s_b * td));
            (
                td + self.omega * (1.0 - w),
                1.0 + self.omega * dw * damp * s_b,
            )
        }
    }

    /// The right-hand side f(y) = (theta_dot, v, v_dot).
    pub fn rhs(&self, y: &[f64], dy: &mut [f64]) {
        let f = self.evaluate(y, None);
        dy[0] = f.theta_dot;
        dy[1] = y[2];
        dy[2] = f.accel;
    }
}

/// The root of a nondecreasing `residual` (value and slope) in [lo, hi], to round-off: the
/// float where its sign changes, as bisection finds it (lo if residual(lo) >= 0, hi if
/// residual(hi) <= 0).
///
/// Why not plain bisection: it halves [-omega, 0] down to adjacent floats, some 60 to 110
/// evaluations, and a force-driven simulation calls it at every evaluation of the right-hand side;
/// it was the larger part of the `stability-matrix` chart's time, as profiled. Newton steps from hi
/// (bisection where a step would leave the bracket) take the bracket to its root in a few; once a
/// step no longer moves, floats across the root are probed, so the bracket closes to adjacent
/// floats as bisection's does. The answer is then bisection's last midpoint of that pair. Where the
/// residual's rounding is monotone, this is bisection's answer bit for bit; where it is a staircase
/// (1 - w(N) a few ulps, each ulp omega eps of residual) it may be another sign change within a few
/// omega eps of it, as good a root (a test compares them).
fn rate_root(residual: impl Fn(f64) -> (f64, f64), mut lo: f64, mut hi: f64) -> f64 {
    if residual(lo).0 >= 0.0 {
        return lo;
    }
    let (r_hi, slope_hi) = residual(hi);
    if r_hi <= 0.0 {
        return hi;
    }
    let mut x = hi - r_hi / slope_hi;
    // Newton steps and probes before plain bisection takes over: a few reach round-off, and
    // the budget bounds the loop whatever the residual's rounding does.
    let mut steps_left = NEWTON_BUDGET;
    let mut gallop = 1_i64;
    loop {
        if !(x > lo && x < hi) {
            // A step out of the bracket (at w = 1 the residual is theta_dot itself, and
            // Newton jumps to 0): bisection.
            x = 0.5 * (lo + hi);
        }
        let (r, slope) = residual(x);
        if r < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return mid;
        }
        let newton = x - r / slope;
        x = if steps_left == 0 {
            mid
        } else if newton == x {
            // Converged to x within the residual's round-off: probe across the root, one
            // float away, then two, four, ... (the round-off of omega (1 - w) may hold the
            // residual's sign over a few dozen floats), which closes the bracket where the
            // sign changes.
            steps_left -= 1;
            let probe = crate::numbers::floats_away(x, if r < 0.0 { gallop } else { -gallop });
            gallop *= 2;
            probe
        } else {
            if newton > lo && newton < hi {
                steps_left -= 1;
            }
            gallop = 1;
            newton
        };
    }
}

/// Newton steps and probes [`rate_root`] takes before it falls back to bisection.
const NEWTON_BUDGET: u32 = 24;

impl OdeSystem<3> for System {
    fn rhs(&self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        System::rhs(self, y, dy);
    }
    fn jacobian(&self, _t: f64, y: &[f64; 3], jac: &mut [[f64; 3]; 3]) {
        self.evaluate(y, Some(jac.as_flattened_mut()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jacobian_matches_finite_differences() {
        let scene = SceneParams::default();
        for drive in [Drive::Motion, Drive::Force] {
            let d = DynamicsParams {
                drive: crate::dynamics::DriveSettings {
                    mode: drive,
                    ..Default::default()
                },
                ..Default::default()
            };
            let sys = System::new(&scene, &d);
            // In contact and sliding; in contact near the force limit; in the stiction band.
            let th: f64 = 50_f64.to_radians();
            let states = [
                [th, sys.touching_x(th) - 0.05, 15.0],
                [th, sys.touching_x(th) - 0.0585, 0.15],
                [th, sys.touching_x(th) - 0.03, 0.05],
            ];
            let mut worst: f64 = 0.0;
            for y in states {
                let mut j = [0.0; 9];
                sys.evaluate(&y, Some(&mut j));
                for col in 0..3 {
                    let hstep = 1e-7 * y[col].abs().max(1e-3);
                    let (mut yp, mut ym) = (y, y);
                    yp[col] += hstep;
                    ym[col] -= hstep;
                    let (mut fp, mut fm) = ([0.0; 3], [0.0; 3]);
                    sys.rhs(&yp, &mut fp);
                    sys.rhs(&ym, &mut fm);
                    for row in 0..3 {
                        let fd = (fp[row] - fm[row]) / (2.0 * hstep);
                        let err = (j[3 * row + col] - fd).abs() / fd.abs().max(1.0);
                        worst = worst.max(err);
                        assert!(
                            err < 1e-4,
                            "{drive:?} {y:?} J[{row}][{col}] = {} vs {fd}",
                            j[3 * row + col]
                        );
                    }
                }
            }
            eprintln!("{drive:?}: worst relative Jacobian error {worst:.2e}");
        }
    }

    /// Plain bisection of [lo, hi] to adjacent floats, with its number of evaluations: the
    /// force drive's former root finder, the oracle of [`rate_root`].
    fn bisection(residual: impl Fn(f64) -> (f64, f64), mut lo: f64, mut hi: f64) -> (f64, u32) {
        if residual(lo).0 >= 0.0 {
            return (lo, 1);
        }
        if residual(hi).0 <= 0.0 {
            return (hi, 2);
        }
        let mut evals = 2;
        loop {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                return (mid, evals);
            }
            evals += 1;
            if residual(mid).0 < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }

    /// The force drive bisected its equation for theta_dot to round-off at
    /// every evaluation of the right-hand side, some 60 to 110 halvings, which made
    /// `System::evaluate` the larger part of the `stability-matrix` chart's time. Its Newton
    /// replacement must give bisection's answer bit for bit, across the force limit's band
    /// (N from 0.5 to 1.2 N_max), closing and opening, at several palm speeds, in fewer
    /// evaluations; except where the residual is a staircase at round-off (w within a few
    /// ulps of 1), where either finds a sign change within 4 eps omega of the other's.
    #[test]
    fn force_drive_rate_root_gives_bisections_answer() {
        let scene = SceneParams::default();
        let (mut cases, mut differ, mut interior) = (0, 0, 0);
        let (mut evals_bisection, mut evals_newton) = (0_u64, 0_u64);
        for omega_deg_s in [0.1, 30.0, 3600.0] {
            let d = DynamicsParams {
                drive: crate::dynamics::DriveSettings {
                    mode: Drive::Force,
                    omega_deg_s,
                    ..Default::default()
                },
                ..Default::default()
            };
            let sys = System::new(&scene, &d);
            let imp = sys.impact;
            for k in 0..=70 {
                let n_target = sys.normal_limit * (0.5 + 0.01 * k as f64);
                let delta = (n_target / imp.stiffness).powf(1.0 / imp.exponent);
                for deg in [20.0_f64, 44.0, 63.3, 85.0] {
                    let theta = deg.to_radians();
                    let x = sys.touching_x(theta) - delta / theta.sin();
                    for v in [-20.0, -0.1, 0.0, 1e-3, 0.1, 5.0, 300.0] {
                        let y = [theta, x, v];
                        let (s, _) = theta.sin_cos();
                        let el =
                            imp.elastic(sys.radius + sys.offset + sys.radius * theta.cos() - x * s);
                        let damp = step(delta, 0.0, 0.0, imp.depth, imp.damping).0;
                        let s_b = sys.contact_distance(&y);
                        let res = sys.rate_residual(el.0, damp, v, s, s_b);
                        let (want, n_bis) = bisection(&res, -sys.omega, 0.0);
                        let count = std::cell::Cell::new(0_u32);
                        let got = rate_root(
                            |td| {
                                count.set(count.get() + 1);
                                res(td)
                            },
                            -sys.omega,
                            0.0,
                        );
                        cases += 1;
                        // Interior roots only: at an end both stop after one or two.
                        if n_bis > 2 {
                            interior += 1;
                            evals_bisection += u64::from(n_bis);
                            evals_newton += u64::from(count.get());
                        }
                        if got.to_bits() != want.to_bits() {
                            // Another sign change of a residual that is a staircase at
                            // round-off (1 - w in steps of one ulp): as good a root.
                            let worst = 4.0 * f64::EPSILON * sys.omega;
                            assert!(
                                (got - want).abs() <= worst && res(got).0.abs() <= worst,
                                "{omega_deg_s} deg/s, N {n_target}, {deg} deg, v {v}: \
                                 {got} vs bisection's {want}"
                            );
                            differ += 1;
                        }
                    }
                }
            }
        }
        eprintln!(
            "{cases} states, {interior} with an interior root: bisection {:.1} evaluations \
             each, rate_root {:.1}",
            evals_bisection as f64 / interior as f64,
            evals_newton as f64 / interior as f64
        );
        eprintln!("{differ} of {cases} differ from bisection's bits, each within 4 eps omega");
        // The staircase is rare: bit for bit nearly everywhere.
        assert!(differ * 100 < cases, "{differ} of {cases}");
        assert!(
            evals_newton * 2 < evals_bisection,
            "{evals_newton} vs {evals_bisection}"
        );
    }

    #[test]
    fn geometric_speed_is_the_rate_of_the_touching_position() {
        for h in [0.0, 0.5] {
            let scene = SceneParams {
                palm_offset_mm: h,
                ..Default::default()
            };
            let sys = System::new(&scene, &DynamicsParams::default());
            for deg in [30.0_f64, 45.0, 80.0] {
                let th = deg.to_radians();
                let e = 1e-6;
                let fd = -sys.omega * (sys.touching_x(th + e) - sys.touching_x(th - e)) / (2.0 * e);
                let v = sys.geometric_speed(th);
                assert!((v - fd).abs() < 1e-6 * v, "h = {h}, {deg} deg: {v} vs {fd}");
                if h == 0.0 {
                    let paper = sys.radius * sys.omega / (2.0 * (0.5 * th).sin().powi(2));
                    assert!((v - paper).abs() < 1e-12 * v);
                }
            }
        }
    }

    #[test]
    fn at_rest_in_light_contact_the_forces_are_corrected_eq1() {
        // Palm sliding (u_B >> V_d), no damping: the ground reaction is the corrected Eq. 1.
        let scene = SceneParams::default();
        let d = DynamicsParams {
            contact: crate::dynamics::ContactLaw {
                damping_n_s_per_mm: 0.0,
                ..Default::default()
            },
            ..Default::default()
        };
        let sys = System::new(&scene, &d);
        let th = 60_f64.to_radians();
        let y = [th, sys.touching_x(th) - 0.05, 10.0];
        let f = sys.evaluate(&y, None);
        let push = f.normal / scene.alpha_palm().cos();
        let p = SceneParams {
            force_n: push,
            ..scene
        };
        let g = crate::statics::reference::ground_reaction(&p, th);
        assert!(
            (f.ground_normal - g.r_n_n).abs() < 1e-9 * g.r_n_n,
            "{} vs {}",
            f.ground_normal,
            g.r_n_n
        );
        let p_x = f.accel * scene.mass_kg / MM_PER_M - f.ground_friction;
        assert!(
            (p_x - g.r_t_n).abs() < 1e-9 * g.r_t_n.abs(),
            "{p_x} vs {}",
            g.r_t_n
        );
    }
}
