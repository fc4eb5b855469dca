//! The textbook closed form, written as the paper's equations read: the oracle the lane code
//! of [`super`] is tested against (as [`crate::locator`] keeps its own reference solver).
//!
//! Six transcendental functions a push where the lane code takes one arctangent; slower and a
//! few ulp apart, but each line is an equation of the module docs: the ground reaction of the
//! corrected Eq. 1, the jam margin, and theta_jam = atan(mu_g) + atan(mu_p) + asin(m g
//! sin(atan mu_g) / F) with x_jam = r cot(theta_jam / 2) + h / sin(theta_jam) (Eq. 2).

use serde::Serialize;

use crate::scene::SceneParams;

/// theta_jam in rad by the trigonometric closed form; None where the push can never move the
/// disc (m g sin(alpha_g) >= F). The statuses (the start, the palm's reach) are not decided
/// here.
pub fn theta_jam_rad(p: &SceneParams) -> Option<f64> {
    let alpha_g = p.mu_ground.atan();
    let load = p.weight_n() * alpha_g.sin() / p.force_n;
    (load < 1.0).then(|| alpha_g + p.mu_palm.atan() + load.asin())
}

/// The disc's position x in mm at palm angle `theta` (rad): r cot(theta / 2) + h / sin(theta)
/// (Eq. 2, with the palm's offset h).
pub fn x_mm(p: &SceneParams, theta: f64) -> f64 {
    p.radius_mm / (theta / 2.0).tan() + p.palm_offset_mm / theta.sin()
}

/// Ground reaction at contact A for a palm angle, from the corrected Eq. 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GroundReaction {
    /// Tangential reaction R_t in N, positive against the disc's motion (towards the hinge).
    pub r_t_n: f64,
    /// Normal reaction R_n in N, positive up.
    pub r_n_n: f64,
    /// Jam margin mu_g R_n - R_t in N: positive where the ground holds the disc (jammed),
    /// negative where the disc slides.
    pub margin_n: f64,
    /// R_n < 0: the palm would lift the disc off the ground, and the model does not apply.
    pub lifts_off: bool,
}

/// Ground reaction and jam margin at palm angle `theta` (rad), with the palm sliding.
pub fn ground_reaction(p: &SceneParams, theta: f64) -> GroundReaction {
    reaction_at(p, p.alpha_palm(), theta)
}

/// [`ground_reaction`] with the palm's friction angle `alpha_palm` (rad) given.
fn reaction_at(p: &SceneParams, alpha_palm: f64, theta: f64) -> GroundReaction {
    let phi = theta - alpha_palm;
    let r_t = p.force_n * phi.sin();
    let r_n = p.weight_n() + p.force_n * phi.cos();
    GroundReaction {
        r_t_n: r_t,
        r_n_n: r_n,
        margin_n: p.mu_ground * r_n - r_t,
        lifts_off: r_n < 0.0,
    }
}

/// The jam margin mu_g R_n - R_t in N at palm angle `theta` (rad); see [`ground_reaction`].
pub fn margin_n(p: &SceneParams, theta: f64) -> f64 {
    ground_reaction(p, theta).margin_n
}
