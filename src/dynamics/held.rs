//! A disc held by a stalled force-limited palm: where the rigid statics end a run early.
//!
//! # Held for good
//!
//! A force-limited palm ([`super::Drive::Force`]) that cannot slide the disc stalls at its
//! limit: its normal push reaches N_max = F cos(atan mu_p) and the palm stops turning (it never
//! backs off). Whether a disc at rest there can ever move again is a question for the rigid
//! statics, not for the integrator. To slide outwards past a stalled palm the disc slips at both
//! contacts, so both frictions oppose it, and the push it needs is the corrected Eq. 1 solved
//! for the palm's normal push N (W = m g, alpha = atan mu):
//!
//! ```text
//! N (sin theta - mu_p cos theta) = mu_g (W + N (cos theta + mu_p sin theta))
//! N_slide(theta) = mu_g W / (sin theta (1 - mu_g mu_p) - cos theta (mu_g + mu_p))
//!                = W sin(alpha_g) cos(alpha_p) / sin(theta - alpha_g - alpha_p)
//! ```
//!
//! infinite at and below the self-locking wedge. N_max < N_slide(theta) is the closed form's
//! jam condition, sin(theta - alpha_g - alpha_p) < m g sin(alpha_g) / F ([`crate::statics`]).
//! While it holds the disc stays where it is: the drive pushes with N_max at most, and the palm
//! can only close further, to smaller theta, where sin(theta - alpha_g - alpha_p) is smaller
//! still (theta <= 90 deg: a push starting above it is outside the model) and N_slide larger.
//! A disc held at one angle is held at every angle the palm can reach, so nothing changes
//! again until the end of the push.
//!
//! Which friction: a disc at rest must break the static friction, one sliding slowly is braked
//! by the dynamic; the test takes the smaller of mu_s and mu_d at each contact, so it holds
//! either way (by default they are equal). Which angle: the rigid palm's touching the disc at
//! its position x ([`System::touching_theta`]). The compliant palm has turned past it by its
//! penetration, to a smaller theta where N_slide is larger, so at the touching angle the rigid
//! disc and the compliant one are both held.
//!
//! # When the run ends
//!
//! The jam detector ([`super::jam`]) watches a force-driven run for this before it arms (once
//! the disc has reached 0.9 of the palm's speed, the jam reading owns the run): the disc is held
//! when, at every step end of a confirmation window (the jam's: 0.25 deg of commanded palm
//! turn, or two periods of the disc on the contact's stiffness if longer, against the
//! transients of first contact), the palm is stalled (its push in the drive's band, N >= (1 -
//! b) N_max), the disc is at rest (slower than the force drive's rest speed 2 V_d,
//! [`super::jam::rest_speed_mm_s`]) and N_max < N_slide. The run then stops, or `after_jam_s`
//! after the start if later (a never-armed disc's jam is at the start), and reads as the full
//! run did: a disc that never armed is `jammed_at_start`, and `too_weak` when the push is below
//! the least push that slides it at any angle ([`super::simulate`]). The full run only added
//! the regularised friction's creep (it has no true stiction, so a held disc creeps below V_s)
//! up to t_end = theta_0 / omega, 3 s at the defaults; DOPRI5, its step held at its stability
//! limit by the stalled contact, took 50,787 and 65,681 steps to get there for the stability
//! matrix's `barely_moves` and `too_weak` (`tests/dynamics_verdicts.rs`,
//! `a_disc_held_by_a_stalled_palm_ends_the_run`, prints the steps now).

use super::contact::FrictionLaw;
use super::system::System;

/// The palm turn (deg) after a candidate jam within which the disc must not recover; a held
/// disc must stay held over the same turn (the jam detector's confirmation window).
pub const CONFIRM_DEG: f64 = 0.25;

/// The palm's normal push (N) that slides a disc of weight `weight_n` (N) at palm angle `theta`
/// (rad) against the frictions `mu_ground` and `mu_palm` at both contacts: the corrected Eq. 1
/// solved for the push (module docs), infinite at and below the self-locking wedge.
pub(crate) fn sliding_push_n(weight_n: f64, mu_ground: f64, mu_palm: f64, theta: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    let denom = s * (1.0 - mu_ground * mu_palm) - c * (mu_ground + mu_palm);
    if denom > 0.0 {
        mu_ground * weight_n / denom
    } else {
        f64::INFINITY
    }
}

/// Watches a force-driven disc that never armed for the stalled palm holding it for good.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct HeldWatch {
    /// The end (s) of the confirmation window begun at the first step end of the current run of
    /// held step ends.
    until: Option<f64>,
}

impl HeldWatch {
    /// Sees the state `y` at a step end `t`: true once the disc has been held at every step end
    /// over the confirmation window (module docs: the jam's, 0.25 deg of commanded palm turn,
    /// or two periods of the disc on the contact if longer).
    pub fn see(&mut self, sys: &System, y: &[f64], t: f64, rest_speed_mm_s: f64) -> bool {
        if !held_now(sys, y, rest_speed_mm_s) {
            self.until = None;
            return false;
        }
        let delta = sys.geometry(y).penetration;
        let window =
            (CONFIRM_DEG.to_radians() / sys.omega).max(2.0 * sys.impact.period_s(sys.mass, delta));
        t >= *self.until.get_or_insert(t + window)
    }

    /// The end of the confirmation window under way, if the disc is held.
    pub fn until(&self) -> Option<f64> {
        self.until
    }
}

/// Whether the state `y` = (theta, x, v) shows the disc held for good by the stalled palm
/// (module docs): the push in the drive's band, the disc slower than `rest_speed_mm_s`, and the
/// limit below the push that slides the disc at its position.
fn held_now(sys: &System, y: &[f64], rest_speed_mm_s: f64) -> bool {
    let limit = sys.normal_limit;
    if y[2].abs() >= rest_speed_mm_s || sys.evaluate(y, None).normal < (1.0 - sys.band) * limit {
        return false;
    }
    let least = |law: &FrictionLaw| law.mu_static.min(law.mu_dynamic);
    let theta = sys.touching_theta(y[1]);
    limit
        < sliding_push_n(
            sys.weight,
            least(&sys.ground_friction),
            least(&sys.palm_friction),
            theta,
        )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::SceneParams;

    /// The two forms of N_slide agree, and N_slide equals the closed form's push limit at
    /// theta_jam: the jam condition of the statics is N_max < N_slide.
    #[test]
    fn the_sliding_push_is_the_closed_forms_jam_condition() {
        for (mu_g, mu_p, f) in [(0.4, 0.4, 200.0), (0.15, 0.6, 20.0), (1.0, 0.1, 50.0)] {
            let scene = SceneParams {
                mu_ground: mu_g,
                mu_palm: mu_p,
                force_n: f,
                ..SceneParams::default()
            };
            let (ag, ap) = (scene.alpha_ground(), scene.alpha_palm());
            let w = scene.weight_n();
            for theta_deg in [50.0, 70.0, 89.0] {
                let theta = f64::to_radians(theta_deg);
                if theta <= ag + ap {
                    assert_eq!(sliding_push_n(w, mu_g, mu_p, theta), f64::INFINITY);
                    continue;
                }
                let a = sliding_push_n(w, mu_g, mu_p, theta);
                let b = w * ag.sin() * ap.cos() / (theta - ag - ap).sin();
                assert!(
                    (a - b).abs() <= 1e-12 * b,
                    "{mu_g} {mu_p} {theta_deg}: {a} vs {b}"
                );
            }
            let jam = crate::statics::theta_jam_rad(&scene);
            let n = sliding_push_n(w, mu_g, mu_p, jam);
            let n_max = f * ap.cos();
            assert!(
                (n - n_max).abs() <= 1e-9 * n_max,
                "{mu_g} {mu_p}: {n} vs {n_max}"
            );
        }
    }

    /// The touching angle inverts the touching position, with and without a palm offset,
    /// from near the hinge line to the start at 90 deg.
    #[test]
    fn the_touching_angle_inverts_the_touching_position() {
        for offset in [0.0, 0.5, 5.0] {
            let scene = SceneParams {
                palm_offset_mm: offset,
                ..SceneParams::default()
            };
            let sys = System::new(&scene, &crate::dynamics::DynamicsParams::default());
            for theta_deg in [1.0, 20.0, 44.6, 89.0, 90.0] {
                let theta = f64::to_radians(theta_deg);
                let back = sys.touching_theta(sys.touching_x(theta));
                assert!(
                    (back - theta).abs() < 1e-12,
                    "h = {offset}: {theta_deg} -> {back}"
                );
            }
        }
    }
}
