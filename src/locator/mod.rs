//! V-type locators: does a V of two flat flanks hold a disc under a load, how much load can
//! it hold, and which included angle is best (beyond the paper, which claims the optimum
//! angle and shows nothing).
//!
//! # The scene
//!
//! A disc of weight W = m g sits in a V: the left flank rises at a1 above the horizontal, the
//! right one at a2, the included angle is gamma = 180 - a1 - a2 (a symmetric V: a1 = a2 =
//! 90 - gamma/2). A flank may overhang (a1 or a2 above 90) while a1 + a2 < 180. Flank i has
//! friction mu_i. An external force P at direction phi (from +x, counter-clockwise) acts at
//! the centre, or at the rim point at angle psi, where it adds the moment r P sin(phi - psi).
//!
//! In a frame at the disc centre C the flank i touches at -r n_i, with inward normals and
//! tangents up each flank (away from the vertex)
//!
//! ```text
//! n1 = (sin a1, cos a1),  u1 = (-cos a1, sin a1);   n2 = (-sin a2, cos a2),  u2 = (cos a2, sin a2)
//! ```
//!
//! and contact forces f_i = N_i n_i + T_i u_i with N_i >= 0, |T_i| <= mu_i N_i. The normals have
//! no moment about C; n1 x u1 = 1 and n2 x u2 = -1, so the frictions have moments -r T1 and
//! +r T2. The radius cancels from every equation: it is not a parameter.
//!
//! # Free and blocked rotation
//!
//! - **Free** (the physical V-block): Fx, Fy and Mz. The moment row reads
//!   T2 - T1 = M / r (M the load's moment about C): for a centre load the two frictions are
//!   equal, T1 = T2 = T, both up or both down their flanks.
//! - **Blocked** (the paper's translational formulation): a joint carries the moment; only Fx,
//!   Fy, and T1, T2 are independent. The joint carries the moment of a load at a rim point,
//!   so such a load acts as if at the centre.
//!
//! With b the bisector (vertex to centre) and beta = gamma/2, u1 + u2 = 2 cos(beta) b and
//! n1 + n2 = 2 sin(beta) b. For a centre load under free rotation the support the flanks can
//! give is the image of {|T| <= mu1 N1, |T| <= mu2 N2}, the cone spanned by
//!
//! ```text
//! n1,  n2,  n1/mu1 + n2/mu2 +- 2 cos(beta) b
//! ```
//!
//! For equal frictions the last two are (2 sin(beta)/mu -+ 2 cos(beta)) b: along the bisector,
//! inside cone{n1, n2} exactly when tan(beta) > mu. **So friction adds nothing to a free V's
//! capacity under a centre load unless the V self-locks**: the moment row forces the two
//! frictions equal, and equal frictions only push along the bisector, which the normals
//! already cover. (With unequal frictions a flank's friction helps once tan(beta) is below
//! the friction of the lighter-loaded flank.) Under blocked rotation T1 and T2 are free and
//! the cone is cone{n_i +- mu_i u_i}, wider by atan(mu_i) on each side: there friction does add
//! capacity.
//!
//! # Verdict
//!
//! Decided in this order ([`Verdict`]):
//!
//! 1. `wedged`: the V self-locks, i.e. a nonzero set of contact forces strictly inside both
//!    cones balances no load (frictional force closure of the two contacts). Free: the line
//!    between the contacts (perpendicular to b, at beta from each normal) lies inside both
//!    cones, tan(gamma/2) < min(mu1, mu2). Blocked: two cones whose axes are 180 - gamma
//!    apart hold opposite forces, gamma < atan mu1 + atan mu2. Every load is then held, the
//!    part can jam and needs a pull to come out; the minimum-norm forces are only a lower
//!    bound (any squeeze can be added).
//! 2. `slips`: no equilibrium; the [`FailureMode`] says how the part leaves (rolls out over a
//!    flank, slides along one, slips on both, or is pulled off both).
//! 3. `unloaded`: the load cancels the weight (force and moment, to `solve::LIFT_OFF_RTOL`
//!    of the larger), so nothing presses the disc into the V and both flank forces are zero.
//! 4. `lifts_off`: held, but one flank's normal force is zero at the minimum-norm solution,
//!    to `solve::LIFT_OFF_RTOL` of the largest load.
//! 5. `held`.
//!
//! Flags: `friction_held` (held, but with mu = 0 on both flanks it would not be) and
//! `locking_needed` (wedged, and with friction just below the locking friction it would not
//! be held: the V holds only because it locks).
//!
//! # Minimum-norm forces
//!
//! The held part's forces are the least-norm point of the feasible set (unique when it is not
//! empty), solved by the general contact solver ([`crate::minnorm`]): two planar contacts,
//! and a moment joint under blocked rotation (`contact_problem`).
//!
//! # Holding capacity
//!
//! P_max(phi) is the largest P in direction phi for which an equilibrium exists: a
//! feasibility boundary, so it does not depend on which forces the minimum norm picks. It
//! is unbounded when the load pushes into the V (or the V self-locks). The exact path
//! ([`capacity`]): for blocked rotation or a centre load, the support cone above is pointed
//! with extreme rays e_lo, e_hi, and the support the load needs, (0, W) - P (cos phi, sin phi),
//! lies in it iff e_lo x q >= 0 and q x e_hi >= 0: two rows a + b P >= 0, so P_max is the
//! least -a/b over rows with b < 0 (unbounded if none), and the binding ray names the failure
//! mode. Under free rotation with a rim load, T2 = T1 + m P makes the rows affine in (T1, P):
//! P_max is the best vertex of that polygon (`capacity_by_enumeration`, which also checks
//! the closed form). Both are checked against clarabel (`capacity_clarabel`).
//!
//! # The optimum included angle
//!
//! Maximising capacity alone is degenerate: capacity never grows with gamma, so it picks the
//! self-locking bound (2 atan mu under free rotation) with no margin. The balanced
//! criterion ([`fn@optimum`]) asks for the V that survives the largest common proportional error
//! rho in load and friction before it either drops the part (held at load rho P with friction
//! mu / rho, the friction capped just below locking) or locks it (self-locking at friction
//! rho mu): rho* = min(rho_hold, rho_lock), gamma* maximises it. rho_lock grows with gamma
//! (`rho_lock`; free: tan(gamma/2) / min(mu)), rho_hold never grows (it falls for a load with
//! a sideways part and is constant for a pure lift, where every V wider than the crossing
//! survives the same rho*: the optimum then reports that plateau), so gamma* is their
//! crossing. rho* <= 1 means no V that does not lock can hold the load: the optimum says so
//! (`no_v_holds`) rather than offer a V that self-locks at the nominal friction. Closed form for free
//! rotation, equal mu and a centre load (`closed_form_free_centre`): with x = tan(gamma/2),
//! rho_hold = W / (P (|cos phi| x + sin phi)) and rho_lock = x / mu cross at
//!
//! ```text
//! |cos phi| x*^2 + sin phi x* = mu W / P;   sideways (phi = 0): gamma* = 2 atan sqrt(mu W / P)
//! ```
//!
//! so a 90 deg V is optimal when P / W = mu, and rho* = sqrt(W / (mu P)) there.
//!
//! # Under uncertain friction and load
//!
//! [`robust_design`] answers the V-block question over a box of frictions, load magnitudes
//! and directions: the window of included angles that hold every load without locking at any
//! friction, the most robust angle in it, and what would open an empty window. What is
//! monotone (so which points of the box decide) is derived in [`robust`]'s docs.
//!
//! # The palm scene is a V
//!
//! The paper's palm (hinge at the vertex) and ground form a V with a1 = 180 - theta (the
//! palm, mu_palm) and a2 = 0 (the ground, mu_ground), gamma = theta; the palm's push F on the
//! edge of its friction cone acts at the palm contact. Blocked, the held/not-held boundary is
//! the statics' theta_jam; free with equal frictions it is the self-locking 2 atan mu (x = r/mu)
//! whatever the push. Free with a slipperier ground (mu_g < mu_p) the ground binds first and
//! the boundary moves with the push: tan(theta*/2) = mu_g mu_p (W + 2 F cos alpha_p) /
//! (2 mu_p F cos alpha_p - mu_g W) (capped at mu_p), derived in src/locator/tests.rs. (It differs from
//! the min-norm palm model's rolling formulation, whose palm pushes with exactly F cos alpha_p:
//! here the palm contact may also squeeze.)

mod exact;
mod optimum;
pub(crate) mod params;
pub(crate) mod reference;
pub mod robust;
#[cfg(test)]
mod robust_tests;
mod solve;
pub(crate) mod symmetric;
/// Bisects the bracket (lo, hi) where `left(x)` holds on its left part, halving at `mid(lo,
/// hi)` (the arithmetic or the geometric mean) at most `halvings` times; returns the final
/// bracket. It stops once the bracket is two neighbouring floats: every later halving would
/// repeat the last one (mid is lo or hi again), so the bracket is the one the full count gives.
pub(crate) fn bisect_bracket(
    (mut lo, mut hi): (f64, f64),
    halvings: usize,
    mid: impl Fn(f64, f64) -> f64,
    mut left: impl FnMut(f64) -> bool,
) -> (f64, f64) {
    for _ in 0..halvings {
        let m = mid(lo, hi);
        let last = m == lo || m == hi;
        if left(m) {
            lo = m;
        } else {
            hi = m;
        }
        if last {
            break;
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests;

pub use exact::{Capacity, FailureMode, capacity};
#[cfg(test)]
use exact::{capacity_by_enumeration, held_at, self_locking};
#[cfg(test)]
use optimum::closed_form_free_centre;
pub use optimum::{Criterion, Optimum, optimum};
pub(crate) use optimum::{OPT_MAX_DEG, OPT_MIN_DEG, just_unlocked};
#[cfg(test)]
use optimum::{balanced_rho, rho_lock};
pub use params::{Flank, LocatorParams, Rotation};
pub use reference::ReferenceCapacity;
#[cfg(test)]
use reference::capacity_clarabel;
pub(crate) use robust::verdict_over_box;
pub use robust::{
    BoxVerdict, DroppedLoad, Opening, RobustAngle, RobustBox, RobustDesign, robust_design,
};
pub(crate) use robust::{SCAN_STEP_DEG, lock_angle_deg};
pub use solve::{FlankForce, LocatorSolution, Verdict, solve};
#[cfg(test)]
use solve::{contact_problem, min_norm_forces};
