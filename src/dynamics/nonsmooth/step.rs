//! The problem of one time step: contact impulses with exact Coulomb friction, solved by
//! enumerating the contact modes.
//!
//! Unknowns z = (P_NA, P_TA, P_NB, P_TB, theta_dot): normal and tangential impulses at the
//! ground A and the palm B (kg mm/s) and the palm's angular speed over the step (rad/s). The
//! relative velocities after the step are affine in z,
//!
//! ```text
//! U = b + A P + c theta_dot,   b = J v_free,  A = J M^-1 J^T (the Delassus matrix),
//! ```
//!
//! with U = (U_NA, U_TA, U_NB, U_TB). Each contact is open, sticking or sliding one way, and the
//! drive runs, pushes at its limit or holds; each choice of modes gives five linear equations,
//! and a choice is the answer when its solution satisfies the inequalities of its modes (the
//! signs of Coulomb's law and of Signorini's condition). There are at most 4 x 4 x 3 = 48
//! choices and the previous step's is tried first, so almost every step is one 5x5 solve.
//! When no choice is consistent the motion-driven palm cannot turn without entering the disc:
//! a lock-up.

use crate::dynamics::MM_PER_M;
use crate::dynamics::{DiscMotion, Drive, DynamicsParams};
use crate::scene::SceneParams;

/// Height (mm) above the ground beyond which the disc has left it: far above round-off.
pub(super) const LIFT_MM: f64 = 1e-9;

/// A contact's mode over one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactMode {
    /// No impulse; the gap may stay open.
    Open,
    /// Touching, no slip: |P_T| <= mu_s P_N.
    Stick,
    /// Touching and slipping in the +t direction: P_T = -mu P_N.
    SlidePositive,
    /// Touching and slipping in the -t direction: P_T = +mu P_N.
    SlideNegative,
}

/// The drive's mode over one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DriveMode {
    /// theta_dot = -omega; the palm's normal impulse stays at or below its limit.
    Runs,
    /// The palm's normal impulse is at its limit; it turns at a speed in [-omega, 0].
    AtLimit,
    /// theta_dot = 0 and the palm's normal impulse is at or above its limit (a self-locking
    /// drive does not back off).
    Holds,
    /// theta_dot = 0 with the palm's normal impulse below its limit: the last resort when a disc
    /// coming to rest in the wedge would, at the limit, turn the palm back, and running would
    /// need more than the limit. A self-locking drive stops rather than back off. Never carried
    /// over to the next step's first guess.
    Stalls,
}

const CONTACT_MODES: [ContactMode; 4] = [
    ContactMode::Stick,
    ContactMode::SlidePositive,
    ContactMode::SlideNegative,
    ContactMode::Open,
];

/// The modes of one step: ground, palm, drive.
pub type Modes = (ContactMode, ContactMode, DriveMode);

/// The data of one step's problem.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepProblem {
    /// b: relative velocities (U_NA, U_TA, U_NB, U_TB) of the free motion, in mm/s.
    pub b: [f64; 4],
    /// A: the Delassus matrix J M^-1 J^T in mm/s per kg mm/s.
    pub a: [[f64; 4]; 4],
    /// c: how each relative velocity depends on theta_dot, in mm/rad.
    pub c: [f64; 4],
    /// Gaps at the start of the step divided by the step (g_A / h, g_B / h), in mm/s.
    pub gap_rate: [f64; 2],
    /// Dynamic friction coefficients (ground, palm).
    pub mu: [f64; 2],
    /// Static friction coefficients (ground, palm).
    pub mu_static: [f64; 2],
    /// omega in rad/s.
    pub omega: f64,
    /// The palm's normal impulse limit over the step (kg mm/s); infinite for the motion drive.
    pub push_limit: f64,
}

/// The answer of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepSolution {
    /// (P_NA, P_TA, P_NB, P_TB) in kg mm/s.
    pub impulse: [f64; 4],
    /// theta_dot over the step in rad/s.
    pub theta_dot: f64,
    /// Relative velocities after the step (U_NA, U_TA, U_NB, U_TB) in mm/s.
    pub velocity: [f64; 4],
    pub modes: Modes,
}

impl StepProblem {
    /// Relative velocities for impulses `p` and palm speed `theta_dot`.
    pub fn velocity(&self, p: &[f64; 4], theta_dot: f64) -> [f64; 4] {
        let mut u = self.b;
        for (i, ui) in u.iter_mut().enumerate() {
            *ui += self.a[i].iter().zip(p).map(|(a, p)| a * p).sum::<f64>() + self.c[i] * theta_dot;
        }
        u
    }

    /// Solves the step: the first consistent choice of modes, `first` tried first. None is a
    /// lock-up: no impulses satisfy the contact laws.
    pub fn solve(&self, first: Modes) -> Option<StepSolution> {
        let drives: &[DriveMode] = if self.push_limit.is_finite() {
            &[DriveMode::Runs, DriveMode::AtLimit, DriveMode::Holds]
        } else {
            &[DriveMode::Runs]
        };
        if first.2 != DriveMode::Stalls
            && let Some(s) = self.try_modes(first)
        {
            return Some(s);
        }
        let last: &[DriveMode] = if self.push_limit.is_finite() {
            &[DriveMode::Stalls]
        } else {
            &[]
        };
        for &d in drives.iter().chain(last) {
            for g in CONTACT_MODES {
                for p in CONTACT_MODES {
                    let m = (g, p, d);
                    if m != first
                        && let Some(s) = self.try_modes(m)
                    {
                        return Some(s);
                    }
                }
            }
        }
        None
    }

    /// The solution for one choice of modes, if it is consistent.
    pub fn try_modes(&self, modes: Modes) -> Option<StepSolution> {
        let (ground, palm, drive) = modes;
        if !self.push_limit.is_finite() && drive != DriveMode::Runs {
            return None;
        }
        // Rows: contact A (normal, tangential), contact B (normal, tangential), drive.
        let mut m = [[0.0; 6]; 5];
        for (k, mode) in [ground, palm].into_iter().enumerate() {
            let (rn, rt) = (2 * k, 2 * k + 1);
            match mode {
                ContactMode::Open => {
                    m[rn][rn] = 1.0;
                    m[rt][rt] = 1.0;
                }
                _ => {
                    // U_N + g / h = 0: the gap closes exactly at the end of the step.
                    m[rn][..4].copy_from_slice(&self.a[rn]);
                    m[rn][4] = self.c[rn];
                    m[rn][5] = -self.b[rn] - self.gap_rate[k];
                    if mode == ContactMode::Stick {
                        m[rt][..4].copy_from_slice(&self.a[rt]);
                        m[rt][4] = self.c[rt];
                        m[rt][5] = -self.b[rt];
                    } else {
                        let sigma = if mode == ContactMode::SlidePositive {
                            1.0
                        } else {
                            -1.0
                        };
                        m[rt][rt] = 1.0;
                        m[rt][rn] = sigma * self.mu[k];
                    }
                }
            }
        }
        match drive {
            DriveMode::Runs => {
                m[4][4] = 1.0;
                m[4][5] = -self.omega;
            }
            DriveMode::AtLimit => {
                m[4][2] = 1.0;
                m[4][5] = self.push_limit;
            }
            DriveMode::Holds | DriveMode::Stalls => m[4][4] = 1.0,
        }
        let z = solve5(m)?;
        let p = [z[0], z[1], z[2], z[3]];
        let theta_dot = z[4];
        let u = self.velocity(&p, theta_dot);
        let scale_p = 1e-9 * (1.0 + p.iter().fold(0.0_f64, |a, x| a.max(x.abs())));
        let scale_u = 1e-9
            * (1.0
                + u.iter()
                    .chain(&self.b)
                    .chain(&self.gap_rate)
                    .fold(0.0_f64, |a, x| a.max(x.abs())));
        for (k, mode) in [ground, palm].into_iter().enumerate() {
            let (pn, pt) = (p[2 * k], p[2 * k + 1]);
            let (un, ut) = (u[2 * k], u[2 * k + 1]);
            let ok = match mode {
                ContactMode::Open => un + self.gap_rate[k] >= -scale_u,
                ContactMode::Stick => {
                    pn >= -scale_p && pt.abs() <= self.mu_static[k] * pn.max(0.0) + scale_p
                }
                ContactMode::SlidePositive => pn >= -scale_p && ut >= -scale_u,
                ContactMode::SlideNegative => pn >= -scale_p && ut <= scale_u,
            };
            if !ok {
                return None;
            }
        }
        let ok = match drive {
            DriveMode::Runs => p[2] <= self.push_limit + scale_p,
            // The palm may turn back by what gives back its penetration from the step before
            // (each step closes the gap with the geometry of its start, so the palm ends a step
            // up to the second order of the step inside the disc: 2e-6 mm at 0.1 deg), and by
            // 1e-6 omega for round-off: without it a disc at rest at the limit had no consistent
            // mode.
            DriveMode::AtLimit => {
                let give_back = if self.c[2] > 0.0 {
                    (-self.gap_rate[1]).max(0.0) / self.c[2]
                } else {
                    0.0
                };
                theta_dot <= 1e-6 * self.omega + give_back * (1.0 + 1e-6)
                    && theta_dot >= -self.omega * (1.0 + 1e-6)
            }
            DriveMode::Holds => p[2] >= self.push_limit - scale_p,
            DriveMode::Stalls => p[2] >= -scale_p && p[2] <= self.push_limit + scale_p,
        };
        ok.then_some(StepSolution {
            impulse: p,
            theta_dot,
            velocity: u,
            modes,
        })
    }
}

/// Solves the 5x5 system in the augmented matrix `m` by Gaussian elimination with partial
/// pivoting; None when it is singular (that choice of modes does not fix the unknowns).
fn solve5(mut m: [[f64; 6]; 5]) -> Option<[f64; 5]> {
    let norm = m
        .iter()
        .flat_map(|r| r[..5].iter())
        .fold(0.0_f64, |a, x| a.max(x.abs()));
    for col in 0..5 {
        let piv = (col..5).max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))?;
        if m[piv][col].abs() <= 1e-13 * norm {
            return None;
        }
        m.swap(col, piv);
        let pivot_row = m[col];
        for row in m.iter_mut().skip(col + 1) {
            let f = row[col] / pivot_row[col];
            if f != 0.0 {
                for (r, p) in row.iter_mut().zip(&pivot_row).skip(col) {
                    *r -= f * p;
                }
            }
        }
    }
    let mut z = [0.0; 5];
    for row in (0..5).rev() {
        let s: f64 = (row + 1..5).map(|k| m[row][k] * z[k]).sum();
        z[row] = (m[row][5] - s) / m[row][row];
    }
    Some(z)
}

/// The step length in s for a palm turn of `step_deg` at omega.
pub fn step_s(params: &DynamicsParams) -> f64 {
    params.nonsmooth_step_deg().to_radians() / params.drive.omega_deg_s.to_radians()
}

/// The constants of one simulation, in kg, mm, s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Stepper {
    /// r in mm.
    pub radius: f64,
    /// The palm face's offset h in mm.
    pub offset: f64,
    /// g in mm/s^2.
    pub gravity: f64,
    /// M^-1 = (1/m, 1/m, 1/I) in 1/kg and 1/(kg mm^2); 1/I = 0 when the disc only slides.
    pub inv_mass: [f64; 3],
    pub mu: [f64; 2],
    pub mu_static: [f64; 2],
    /// omega in rad/s.
    pub omega: f64,
    /// The palm's normal impulse limit over a step in kg mm/s (infinite: motion drive).
    pub push_limit: f64,
    /// The step in s.
    pub dt: f64,
}

/// One step's problem and what is needed to turn its answer into velocities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Built {
    pub problem: StepProblem,
    /// J: rows U_NA, U_TA, U_NB, U_TB; columns x_dot, y_dot, phi_dot.
    pub jac: [[f64; 3]; 4],
    /// v + dt M^-1 f_ext in mm/s and rad/s.
    pub v_free: [f64; 3],
    /// (g_A, g_B) in mm.
    pub gaps: [f64; 2],
    /// s_B, the contact's distance from the hinge, in mm.
    pub contact_distance: f64,
}

impl Stepper {
    /// The constants for valid parameters.
    pub fn new(scene: &SceneParams, params: &DynamicsParams) -> Stepper {
        let dt = step_s(params);
        let (m, r) = (scene.mass_kg, scene.radius_mm);
        let mu = [scene.mu_ground, scene.mu_palm];
        Stepper {
            radius: r,
            offset: scene.palm_offset_mm,
            gravity: scene.gravity_m_s2 * MM_PER_M,
            inv_mass: [
                1.0 / m,
                1.0 / m,
                match params.integrator.disc {
                    DiscMotion::Slides => 0.0,
                    DiscMotion::Rolls => 2.0 / (m * r * r),
                },
            ],
            mu,
            mu_static: [
                params.friction.mu_static_ground.unwrap_or(mu[0]),
                params.friction.mu_static_palm.unwrap_or(mu[1]),
            ],
            omega: params.drive.omega_deg_s.to_radians(),
            // N_max in kg mm/s^2 (1 N = 1000 kg mm/s^2), as an impulse over one step.
            push_limit: match params.drive.mode {
                Drive::Motion => f64::INFINITY,
                Drive::Force => scene.force_n * scene.alpha_palm().cos() * MM_PER_M * dt,
            },
            dt,
        }
    }

    /// The step's problem at configuration `q`, velocity `v` and palm angle `theta`.
    pub fn build(&self, q: &[f64; 3], v: &[f64; 3], theta: f64) -> Built {
        let (r, h, dt) = (self.radius, self.offset, self.dt);
        let (s, c) = theta.sin_cos();
        let s_b = q[0] * c + q[1] * s;
        let jac = [[0.0, 1.0, 0.0], [1.0, 0.0, r], [s, -c, 0.0], [c, s, -r]];
        let v_free = [v[0], v[1] - dt * self.gravity, v[2]];
        let mut b = [0.0; 4];
        let mut a = [[0.0; 4]; 4];
        for i in 0..4 {
            b[i] = (0..3).map(|k| jac[i][k] * v_free[k]).sum();
            for j in 0..4 {
                a[i][j] = (0..3)
                    .map(|k| jac[i][k] * self.inv_mass[k] * jac[j][k])
                    .sum();
            }
        }
        let gaps = [q[1] - r, self.palm_gap(q, s, c)];
        Built {
            problem: StepProblem {
                b,
                a,
                c: [0.0, 0.0, s_b, -h],
                gap_rate: [gaps[0] / dt, gaps[1] / dt],
                mu: self.mu,
                mu_static: self.mu_static,
                omega: self.omega,
                push_limit: self.push_limit,
            },
            jac,
            v_free,
            gaps,
            contact_distance: s_b,
        }
    }

    /// Moves the disc along the ground out of the palm at palm angle `theta`, when it lags
    /// inside it (g_B < 0): x by -g_B / sin theta.
    pub fn touch_palm(&self, q: &mut [f64; 3], theta: f64) {
        let (s, c) = theta.sin_cos();
        let gap = self.palm_gap(q, s, c);
        if gap < 0.0 {
            q[0] -= gap / s;
        }
    }

    /// The palm's gap g_B = x sin theta - y cos theta - r - h in mm at configuration `q`, with
    /// `s`, `c` the sine and cosine of the palm angle.
    fn palm_gap(&self, q: &[f64; 3], s: f64, c: f64) -> f64 {
        q[0] * s - q[1] * c - self.radius - self.offset
    }

    /// Velocities after the step for impulses `p`: v+ = v_free + M^-1 J^T P.
    pub fn velocities(&self, built: &Built, p: &[f64; 4]) -> [f64; 3] {
        let mut v = built.v_free;
        for (k, vk) in v.iter_mut().enumerate() {
            *vk += self.inv_mass[k] * (0..4).map(|i| built.jac[i][k] * p[i]).sum::<f64>();
        }
        v
    }
}
