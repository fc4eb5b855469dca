//! Model 2: minimum-norm contact forces (Section 3.2, Eqs. 3-7), a general solver and the palm
//! scene.
//!
//! # The program
//!
//! A body touches its surroundings at point contacts i (position p_i, inward unit normal n_i,
//! friction mu_i) and may have bilateral joints k (a force along d_k through q_k, or a moment
//! about a_k). With contact forces f_i = f_n n_i + f_t t_i (t1 = z x n in the plane; t1, t2 a
//! tangent basis in space) and joint reactions lambda_k, Eqs. 3-6 read
//!
//! ```text
//! minimise   phi^2 = sum_i |f_i|^2                                (Eq. 4)
//! subject to sum_i T_i f_i + sum_k J_k lambda_k + W_e = 0        (Eq. 3, first row)
//!            f_n,i >= 0,  |f_t,i| <= mu_i f_n,i                   (Eq. 3, cones)
//! T_i = [n  t; p x n  p x t]  (Eq. 5),   W_e = [F, r x F] summed over loads  (Eq. 6)
//! ```
//!
//! Planar problems keep the rows (Fx, Fy, Mz) and the cone |f_t| <= mu f_n is exact as two
//! linear rows; spatial problems keep the paper's six rows and the cone is second-order,
//! ||(f_t1, f_t2)|| <= mu f_n. A contact may have its normal force prescribed (a push of known
//! size whose friction is unknown). **Joint reactions do not enter the objective**: phi is the
//! norm of the contact forces, as in Eq. 4; a joint is an ideal constraint of the model, not a
//! contact whose force the principle should spread. The program is convex with a strictly
//! convex objective in the contact forces, so they are unique when they exist. The body is
//! *held* exactly when the program is feasible: an infeasible program is the status
//! [`HoldStatus::NotHeld`], never an error; only bad input (a zero or non-finite normal,
//! negative friction, no contacts, a NaN load) is [`crate::Error::InvalidValue`], naming the
//! contact index and the value.
//!
//! `qp` solves it with clarabel (P = 2I, so clarabel's objective is phi^2 and its per-iteration
//! trace is the data of the paper's Fig. 4). A private exact path (active-set enumeration with
//! dense KKT solves, `exact.rs`) answers small planar problems, at most 8 cone rows, when
//! [`QpSettings::fast_path`] is set; it is tested against clarabel. Both work on a scaled copy
//! (forces by the largest load, lever arms by the farthest point), so a verdict means the same
//! for 1e-9 N and 1e12 N. clarabel decides "held" to 1e-8 of the largest load, so a contact
//! whose forces are that much smaller than the largest load has its cone judged at tolerance
//! level. The exact path judges each friction cone to 1e-10 of that contact's own forces, with a
//! roundoff floor of 16 machine epsilons of the largest force: a friction of 1e-9, or a palm
//! pushing with 1e-6 of the weight, still has its boundary found to a few ppm.
//!
//! In the palm scene clarabel converges in about five iterations, as in Fig. 4. In (b) the
//! equalities fix the forces (below), so phi^2 is the same at every iteration and the residuals
//! carry the convergence; in (a) the way-back stop adds an unknown and the iterates reach the
//! Eq. 1 minimum from inside the cones.
//!
//! # The palm scene, in a frame at the disc centre C
//!
//! At palm angle theta the ground contact A is at (0, -r) with normal (0, 1) and t_A = (-1, 0)
//! (towards the hinge); the palm contact B is at -r n_B with n_B = (sin theta, -cos theta) and
//! t_B = u = (cos theta, sin theta) along the palm, away from the hinge. Moments are taken about
//! C, so lever arms are r, and theta -> 0 (x -> infinity) stays well conditioned; equilibrium
//! does not depend on the moment point, so this is Eq. 5 with r measured from C, not from the
//! hinge (the paper's Eq. 7 mixes the two; crate docs, Corrections to the paper).
//!
//! ## (a) Translational (the paper's)
//!
//! Contact A at the ground (mu_g); a translational joint carries the moment Mz (a moment joint,
//! free in sign). The palm slides, so its push is a known load F on the edge of its friction
//! cone, F (cos alpha_p n_B - sin alpha_p u), at B. And the palm closes: the disc, riding its
//! joint along X, cannot move back towards the hinge without the gap to the palm closing, so the
//! palm also acts as a frictionless one-way stop along +X (a contact with normal (1, 0) and
//! mu = 0; it carries no weight and no friction).
//!
//! Where the push drives the disc forward (R_t >= 0) the stop is idle, the force rows fix the
//! ground force and the minimum is trivial (crate docs, Corrections): f_t,A = F sin(theta - alpha_p) = R_t and
//! f_n,A = m g + F cos(theta - alpha_p) = R_n, exactly the corrected Eq. 1; the joint takes what
//! the two frictions leave of the moment, lambda = r (R_t - F sin alpha_p). Held is then
//! R_n >= 0 and R_t <= mu_g R_n: the Eq. 1 test. Where the sliding palm's own friction drags the
//! disc back (R_t < 0, possible below alpha_p) the ground and the stop share the backward
//! force, f_t,A = R_t / 2 and the stop pushes -R_t / 2 at the minimum norm while the ground's cone allows,
//! and the disc is always held: the stop takes what the ground cannot. So held is exactly the
//! statics' one-sided test R_t <= mu_g R_n at every angle, the held angles below the start are
//! [0, theta_jam] with the closed form's theta_jam for any mu_g and mu_p, and at the jam the
//! forces are Eq. 1 with the stop idle.
//!
//! Without the stop (the paper's Eq. 3 with its two-sided cone alone) the lower edge
//! R_t >= -mu_g R_n would bind for mu_p > mu_g, the held angles would shrink to a band above
//! the drag-back region, a start below it would read never_jams and mu_g = 0 < mu_p would never
//! jam, unlike the statics and the simulation. A frictional stop at B (the palm free to push
//! harder than F along its cone) gives the same held set below 90 deg, but above it its
//! normal lifts and the palm would carry part of the disc's weight, which a pushing palm does
//! not: hence a frictionless stop along the joint's axis.

//! ## (b) Rolling (beyond the paper)
//!
//! The disc may rotate: no joint, so the moment must be carried by the friction at A and B.
//! What is the palm then? A known load on the edge of its cone (as in (a)) would leave only
//! the two unknowns of A for three equations: the moment row demands the ground friction equal
//! the palm's, F sin(alpha_p) = F sin(theta - alpha_p), true at one angle only, and the
//! program is infeasible almost everywhere. That load assumes the palm slides, which is
//! exactly what a jam stops. So B is a **contact whose normal push is given**,
//! N = F cos(alpha_p) (the normal part of the paper's push, so (a) and (b) press equally
//! hard), with unknown friction s within |s| <= mu_p N. Unknowns f_n,A, f_t,A, s; three
//! equations; the minimum is again trivial. About C the normal forces have no moment:
//!
//! ```text
//! Mz:  -r f_t,A - r s = 0      =>  s = -f_t,A (equal frictions, both towards the hinge)
//! Fx:  -f_t,A + N sin(theta) + s cos(theta) = 0  =>  f_t,A = N tan(theta/2)
//! Fy:  f_n,A - N cos(theta) + s sin(theta) - m g = 0  =>  f_n,A = N + m g
//! ```
//!
//! (using sin(theta) / (1 + cos(theta)) = tan(theta/2) and tan(theta/2) sin(theta) = 1 - cos(theta)).
//! Held iff tan(theta/2) <= mu_p and N tan(theta/2) <= mu_g (N + m g):
//!
//! ```text
//! theta_jam(b) = 2 atan( min(mu_p, mu_g (1 + m g / (F cos alpha_p))) ),  x_jam(b) = r cot(theta_jam/2)
//! ```
//!
//! For equal frictions the palm binds and theta_jam(b) = 2 atan(mu), x_jam(b) = r / mu, whatever
//! F and m: the self-locking wedge, the F -> infinity limit of (a) (43.603 deg, 25.000 mm for
//! mu = 0.4, against (a)'s 44.646 deg, 24.355 mm). A free disc jams later (further out) than one
//! that may only translate, because between the two angles it can still roll on the ground
//! while slipping at the palm; and its jam does not depend on the push. Only when
//! mu_g (1 + m g / N) < mu_p does the ground bind, and then weight delays slipping at A. The
//! held angles below the start are [0, theta_jam(b)].
//!
//! ## theta_jam
//!
//! Held at the start angle: jammed at start. Otherwise the held angles below the start are
//! one interval [0, theta_jam] in both formulations (above). If the disc is held at the palm's
//! reach (x = palm length) the boundary lies between the reach and the start, and the bracket
//! is bisected to `bisection_tol_rad` (relative below 0.1 rad); theta_jam is its held end. If
//! not, the jam lies beyond the reach whenever theta_jam > 0, which the derivations above give
//! without a solve: with any friction in (a), with friction at both contacts in (b); otherwise
//! the disc never jams. A disc that starts past the palm's end is beyond reach. In (a), a disc
//! held at the start and also at 90 deg + alpha_g + alpha_p, where the push slides it best (the
//! margin there is mu_g m g - F / cos alpha_g), is held at every angle: the push is too weak to
//! move it, F <= m g sin(alpha_g).

mod column;
#[cfg(test)]
mod column_tests;
pub(crate) mod contact;
mod dense;
mod exact;
pub(crate) mod palm;
#[cfg(test)]
mod palm_tests;
pub(crate) mod qp;
#[cfg(test)]
mod random_planar;
#[cfg(test)]
mod solver_tests;
pub(crate) mod tolerance;

pub(crate) use column::solve_column;
pub(crate) use contact::{Contact, ContactProblem, Joint, Space, Wrench};
pub use palm::{Formulation, MinNormCheck, MinNormSettings, PalmSolution};
pub(crate) use qp::solve;
pub use qp::{
    Backend, ClarabelStatus, ContactForce, ContactSolution, HoldStatus, QpSettings, TracePoint,
};
pub use tolerance::ToleranceRow;
