//! Inverse questions of the palm scene under uncertain inputs (issue 19): the least push that
//! carries the disc to a target position without jamming, the largest friction a push allows,
//! and the palm length that keeps the jam on the palm, each over a box of inputs.
//!
//! # What is monotone
//!
//! The closed form ([`crate::statics`]) jams the disc at
//! theta_jam = alpha_g + alpha_p + asin(m g sin(alpha_g) / F), alpha = atan mu, at
//! x = r cot(theta/2) + h / sin(theta). The palm closes from the start angle, so the disc
//! moves out (x grows, theta falls) until theta reaches theta_jam. theta_jam grows with each
//! friction and with the mass and falls with the push, so over a box of inputs:
//!
//! - the disc jams **earliest** (smallest x_jam) at mu_hi, m_hi, F_lo: that corner decides
//!   whether it reaches a target;
//! - it jams **latest** (largest x_jam, farthest along the palm) at mu_lo, m_lo, F_hi: that
//!   corner decides the palm length.
//!
//! # Closed forms
//!
//! A target x_t is reached iff theta_jam <= theta_t, with theta_t the palm angle that puts the
//! disc at x_t (theta_t = 2 atan(r / x_t) for h = 0, else by bisection of the monotone
//! x(theta) on (0, 90] deg). With a = theta_t - alpha_g - alpha_p:
//!
//! ```text
//! least push:        F_min = m g sin(alpha_g) / sin(a)                (a in (0, 90 deg); a >= 90: any
//!                                                                      push that moves the disc)
//! largest mu_ground: tan(alpha_g,max) = sin(c) / (cos(c) + m g / F),  c = theta_t - alpha_p
//! palm length:       L = x_jam - h tan(theta_jam / 2) at the latest jam
//! ```
//!
//! (the second from sin(c - alpha_g) = (m g / F) sin(alpha_g)). a <= 0 means the friction
//! wedge locks before the target whatever the push: no push carries the disc there, an answer
//! and not an error. The largest common friction (mu_ground = mu_palm) has no closed form; it
//! is the root of 2 atan(mu) + asin(m g sin(atan mu) / F) = theta_t, found by bisection
//! (theta_jam grows with mu).

use serde::Serialize;

use crate::scene::SceneParams;
use crate::statics;

/// The corners of the input box that decide (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignBox {
    /// Jams earliest: mu_hi, m_hi, F_lo.
    pub earliest: SceneParams,
    /// Jams latest: mu_lo, m_lo, F_hi.
    pub latest: SceneParams,
}

/// The least push that carries the disc to the target at every point of the box.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum LeastPush {
    /// F_min in N (at the earliest corner's friction and mass).
    Push {
        /// F_min in N.
        force_n: f64,
    },
    /// Any push that moves the disc reaches it (a >= 90 deg): more than m g sin(alpha_g).
    AnyPushThatMoves {
        /// m g sin(alpha_g) in N.
        least_moving_n: f64,
    },
    /// The friction wedge locks before the target whatever the push: theta_t <= alpha_g +
    /// alpha_p.
    WedgeLocksFirst {
        /// alpha_g + alpha_p in deg (the rigid jam angle).
        theta_rigid_deg: f64,
        /// The farthest any push carries the disc, mm (the rigid limit).
        x_rigid_mm: f64,
    },
}

/// The answers to the three inverse questions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Design {
    /// The target disc position, mm.
    pub x_target_mm: f64,
    /// The palm angle that puts the disc there, deg.
    pub theta_target_deg: f64,
    /// The target lies past the palm's end (contact beyond `palm_length_mm`): no push carries
    /// the disc there on this palm.
    pub target_past_palm: bool,
    /// The least push over the box.
    pub least_push: LeastPush,
    /// The largest ground friction that lets the box's lowest push (and heaviest disc, palm
    /// friction at its top) reach the target; None when none >= 0 does.
    pub mu_ground_max: Option<f64>,
    /// The largest common friction (ground = palm) for the same; None when none >= 0 does.
    pub mu_max: Option<f64>,
    /// The palm length that keeps the latest jam on the palm, mm; None when the latest corner
    /// never jams (frictionless) or only at infinity.
    pub palm_length_needed_mm: Option<f64>,
    /// The latest jam's position, mm (with `palm_length_needed_mm`).
    pub x_jam_latest_mm: Option<f64>,
}

/// The palm angle in rad at which the disc sits at `x_mm`: 2 atan(r / x) for h = 0, else by
/// bisection on (0, 90] deg, where x(theta) falls; None when x_mm is below x(90 deg) = r + h.
pub fn theta_at_position(p: &SceneParams, x_mm: f64) -> Option<f64> {
    let right = std::f64::consts::FRAC_PI_2;
    if x_mm < p.disc_position_mm(right) {
        return None;
    }
    if p.palm_offset_mm == 0.0 {
        return Some(2.0 * (p.radius_mm / x_mm).atan());
    }
    let (mut lo, mut hi) = (0.0_f64, right);
    // 200 halvings: below one ulp of pi / 2.
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if p.disc_position_mm(mid) > x_mm {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(hi)
}

/// theta_jam of the common friction `mu` (ground = palm) of `p`, rad (infinite if too weak).
fn theta_jam_common(p: &SceneParams, mu: f64) -> f64 {
    statics::theta_jam_rad(&SceneParams {
        mu_ground: mu,
        mu_palm: mu,
        ..*p
    })
}

/// The three inverse answers for target `x_target_mm` over the box `b`; None when the target
/// lies before x(90 deg) = r + h (the disc starts beyond it).
pub fn design(b: &DesignBox, x_target_mm: f64) -> Option<Design> {
    let e = &b.earliest;
    let theta_t = theta_at_position(e, x_target_mm)?;
    let target_past_palm = e.contact_distance_mm(theta_t) > e.palm_length_mm;
    let (ag, ap) = (e.alpha_ground(), e.alpha_palm());
    let a = theta_t - ag - ap;
    let least_moving_n = e.weight_n() * ag.sin();
    let least_push = if a <= 0.0 {
        let (theta_rigid_deg, x_rigid) = statics::rigid_limit(e);
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg,
            x_rigid_mm: x_rigid.unwrap_or(f64::INFINITY),
        }
    } else if a >= std::f64::consts::FRAC_PI_2 {
        LeastPush::AnyPushThatMoves { least_moving_n }
    } else {
        LeastPush::Push {
            force_n: least_moving_n / a.sin(),
        }
    };
    let k = e.weight_n() / e.force_n;
    let c = theta_t - ap;
    let tan_g = c.sin() / (c.cos() + k);
    let mu_ground_max = (c > 0.0 && tan_g >= 0.0).then_some(tan_g);
    let reaches = |mu: f64| theta_jam_common(e, mu) <= theta_t;
    let mu_max = reaches(0.0).then(|| {
        let mut hi = 1.0;
        while reaches(hi) && hi < 1e6 {
            hi *= 2.0;
        }
        let mut lo = 0.0;
        // 100 halvings: far below any friction's digits.
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if reaches(mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    });
    let l = &b.latest;
    let t_late = statics::theta_jam_rad(l);
    let latest_jams = t_late.is_finite() && t_late > 0.0;
    let x_late = latest_jams.then(|| l.disc_position_mm(t_late));
    let palm = latest_jams
        .then(|| l.contact_distance_mm(t_late))
        .filter(|v| v.is_finite());
    Some(Design {
        x_target_mm,
        theta_target_deg: theta_t.to_degrees(),
        target_past_palm,
        least_push,
        mu_ground_max,
        mu_max,
        palm_length_needed_mm: palm,
        x_jam_latest_mm: x_late.filter(|v| v.is_finite()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::uncertain::shaft_25mm as shaft;

    fn with_mu(p: SceneParams, mu: f64, force_n: f64) -> SceneParams {
        SceneParams {
            mu_ground: mu,
            mu_palm: mu,
            force_n,
            ..p
        }
    }

    /// The least push puts the closed-form jam exactly on the target at the box's top
    /// friction, and any friction of the range then jams at or beyond it (the statics is the
    /// oracle).
    #[test]
    fn least_push_jams_exactly_at_the_target_at_the_top_friction() {
        let b = DesignBox {
            earliest: with_mu(shaft(), 0.3, 40.0),
            latest: with_mu(shaft(), 0.12, 40.0),
        };
        let x_t = 40.0;
        let d = design(&b, x_t).unwrap();
        let LeastPush::Push { force_n } = d.least_push else {
            panic!("{d:?}");
        };
        let at = |mu: f64| statics::solve(&with_mu(shaft(), mu, force_n));
        let x = at(0.3).x_jam_mm.unwrap();
        assert!((x - x_t).abs() < 1e-9, "{x}");
        // Lower frictions jam later (a smaller palm angle), some past the 80 mm palm.
        let theta_t = d.theta_target_deg.to_radians();
        for mu in [0.12, 0.2, 0.25, 0.3] {
            let t = statics::theta_jam_rad(&with_mu(shaft(), mu, force_n));
            assert!(t <= theta_t + 1e-12, "{mu}");
        }
        // Less push jams short of the target at the top friction.
        let short = statics::solve(&with_mu(shaft(), 0.3, 0.99 * force_n));
        assert!(short.x_jam_mm.unwrap() < x_t);
    }

    /// The largest frictions put the jam on the target: mu_ground_max (palm friction kept) in
    /// closed form, and the common mu_max by bisection.
    #[test]
    fn largest_friction_jams_exactly_at_the_target() {
        let p = with_mu(shaft(), 0.2, 40.0);
        let b = DesignBox {
            earliest: p,
            latest: p,
        };
        let d = design(&b, 45.0).unwrap();
        let g = d.mu_ground_max.unwrap();
        let x = statics::solve(&SceneParams { mu_ground: g, ..p })
            .x_jam_mm
            .unwrap();
        assert!((x - 45.0).abs() < 1e-9, "{x}");
        let m = d.mu_max.unwrap();
        let x = statics::solve(&with_mu(p, m, 40.0)).x_jam_mm.unwrap();
        assert!((x - 45.0).abs() < 1e-9, "{x}");
    }

    /// A target past the rigid limit r cot((alpha_g + alpha_p) / 2) is out of reach whatever
    /// the push: the wedge locks first (an answer, not an error).
    #[test]
    fn a_target_past_the_rigid_limit_is_refused_with_the_wedge() {
        let p = with_mu(shaft(), 0.3, 40.0);
        let b = DesignBox {
            earliest: p,
            latest: p,
        };
        // x_rigid = r / mu = 41.7 mm.
        let d = design(&b, 60.0).unwrap();
        assert!(
            matches!(d.least_push, LeastPush::WedgeLocksFirst { x_rigid_mm, .. } if (x_rigid_mm - 12.5 / 0.3).abs() < 1e-9),
            "{d:?}"
        );
    }

    /// The palm length needed is the contact distance of the latest jam (lowest friction,
    /// highest push), the statics' `palm_length_needed_mm` when that jam lies past the palm.
    #[test]
    fn palm_length_needed_is_the_latest_jams_contact_distance() {
        let late = with_mu(shaft(), 0.12, 40.0);
        let b = DesignBox {
            earliest: with_mu(shaft(), 0.3, 40.0),
            latest: late,
        };
        let d = design(&b, 30.0).unwrap();
        let s = statics::solve(&late);
        let want = s
            .past_palm
            .map(|pp| pp.palm_length_needed_mm)
            .unwrap_or_else(|| late.contact_distance_mm(s.theta_jam_deg.unwrap().to_radians()));
        assert!(
            (d.palm_length_needed_mm.unwrap() - want).abs() < 1e-9,
            "{d:?}"
        );
    }
}
