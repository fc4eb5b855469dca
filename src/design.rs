//! Inverse questions of the palm scene under uncertain inputs: the least push that carries the
//! disc to a target position without jamming, the largest friction a push allows, and the palm
//! lengths that keep every jam on the palm or end before any, each over a box of inputs.
//!
//! # What is monotone
//!
//! The closed form ([`crate::statics`]) jams the disc at
//! theta_jam = alpha_g + alpha_p + asin(m g sin(alpha_g) / F), alpha = atan mu, at
//! x = r cot(theta/2) + h / sin(theta). The palm closes from the start angle, so the disc
//! moves out (x grows, theta falls) until theta reaches theta_jam; where theta_jam is at or
//! above the start angle the disc is held where the palm first touches it. theta_jam grows with
//! each friction and with the mass and falls with the push, so over a box of inputs:
//!
//! - the disc jams **earliest** (smallest x_jam) at mu_hi, m_hi, F_lo: that corner decides
//!   whether it reaches a target, and the palm length that ends before every jam;
//! - it jams **latest** (largest x_jam, farthest along the palm) at mu_lo, m_lo, F_hi: that
//!   corner decides the palm length that keeps every jam on the palm.
//!
//! # Closed forms
//!
//! A target x_t is reached iff theta_jam <= theta_t, with theta_t the palm angle that puts the
//! disc at x_t (theta_t = 2 atan(r / x_t) for h = 0, else by bisection of the monotone
//! x(theta) on (0, 90] deg). A target at or behind the disc's start, x_t <= x(start), is
//! reached before the palm moves, whatever the push and the friction ([`Carry::StartsPast`]).
//! With a = theta_t - alpha_g - alpha_p:
//!
//! ```text
//! least push:        F_min = m g sin(alpha_g) / sin(a)                (a in (0, 90 deg); a >= 90: any
//!                                                                      push that moves the disc)
//! largest mu_ground: tan(alpha_g,max) = sin(c) / (cos(c) + m g / F),  c = theta_t - alpha_p
//! keeps jams on:     L >= s_B(min(theta_jam, start)) at the latest corner
//! ends before jams:  L <  s_B(theta_jam) at the earliest corner (and L >= s_B(start) to touch
//!                    the disc at all); none where that corner is held at the start
//! ```
//!
//! (the second from sin(c - alpha_g) = (m g / F) sin(alpha_g); s_B = x - h tan(theta / 2) is
//! the contact's distance along the palm). a <= 0 means the friction wedge locks before the
//! target whatever the push: no push carries the disc there, an answer and not an error; m g
//! sin(alpha_g) = 0 (no weight, no ground friction) means any push does, down to 0 N. F_min is
//! then refined to the least push whose closed-form jam reaches the target, as the point answer
//! computes it: at subnormal frictions sin(alpha_g) and the push keep a few digits, and the
//! formula's push jammed at 27.72 deg against a target at 28.07. The largest common friction
//! (mu_ground = mu_palm) has no closed form; it is the root of 2 atan(mu) + asin(m g sin(atan
//! mu) / F) = theta_t, found by bisection (theta_jam grows with mu).
//!
//! The closed form represents a push that starts at 90 deg or below ([`crate::models`]); the
//! caller answers a scene outside it as the model port does.

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

/// The least push that carries the disc to a palm angle (a target) at every point of the box.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum LeastPush {
    /// F_min in N (at the earliest corner's friction and mass): this push jams the disc at the
    /// target, a stronger one beyond it.
    Push {
        /// F_min in N.
        force_n: f64,
    },
    /// Any push that moves the disc reaches it (a >= 90 deg, or no weight or ground friction
    /// to overcome): more than m g sin(alpha_g), which may be 0 N.
    AnyPushThatMoves {
        /// m g sin(alpha_g) in N.
        least_moving_n: f64,
    },
    /// The least push lies below `least_normal_n` = 2.2e-308 N, the smallest double that keeps
    /// all 53 bits (at subnormal frictions m g sin(alpha_g) is subnormal, and so is F_min): it
    /// has a few bits only, the least double that reaches the target jams up to 1.3 % past it
    /// (40.533 mm for a 40 mm target), and no simulation moves a disc by it. Every push of at
    /// least `least_normal_n` carries the disc to the target at every point of the box.
    BelowNormal {
        /// The smallest normal double, N: `f64::MIN_POSITIVE`.
        least_normal_n: f64,
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

/// How the disc gets to the target.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "carry", rename_all = "snake_case")]
pub enum Carry {
    /// The disc starts at or past the target (x_t <= x(start)): it is there before the palm
    /// moves, whatever the push and the friction, and held there if it jams at once.
    StartsPast {
        /// Where the disc starts, x(start) in mm.
        x_start_mm: f64,
    },
    /// The target lies ahead of the disc: what carries it there.
    Ahead {
        /// The least push over the box.
        least_push: LeastPush,
        /// The largest ground friction that lets the box's lowest push (and heaviest disc, palm
        /// friction at its top) reach the target; None when none >= 0 does.
        mu_ground_max: Option<f64>,
        /// The largest common friction (ground = palm) for the same; None when none >= 0 does.
        mu_max: Option<f64>,
    },
}

/// The palm length that ends before every jam of the box, so that the palm loses the disc
/// before it can jam.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum AvoidJams {
    /// A palm shorter than `below_mm`, and at least `touches_mm` long to reach the disc at the
    /// start: the earliest jam's contact lies past its end, and every later jam further out.
    ShorterThan {
        /// The contact's distance along the palm at the earliest jam, mm.
        below_mm: f64,
        /// The earliest jam's position, mm.
        x_jam_earliest_mm: f64,
        /// The contact's distance at the start, mm: a shorter palm never touches the disc.
        touches_mm: f64,
    },
    /// No friction at the earliest corner: no point of the box jams on any palm.
    AnyPalm,
    /// None: at the earliest corner the disc is held where the palm first touches it (or the
    /// push cannot move it), so every palm that reaches the disc holds it.
    None,
}

/// The answers to the inverse questions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Design {
    /// The target disc position, mm.
    pub x_target_mm: f64,
    /// The palm angle that puts the disc there, deg.
    pub theta_target_deg: f64,
    /// The target lies past the palm's end (contact beyond `palm_length_mm`): no push carries
    /// the disc there on this palm.
    pub target_past_palm: bool,
    /// How the disc gets to the target.
    #[serde(flatten)]
    pub carry: Carry,
    /// The least palm length that keeps every jam of the box on the palm, mm: the contact at
    /// the latest jam (at the start where that corner is held there or cannot be moved); None
    /// when the latest corner never jams (frictionless) or only at infinity.
    pub palm_length_keeping_jams_on_mm: Option<f64>,
    /// The latest jam's position, mm (with `palm_length_keeping_jams_on_mm`).
    pub x_jam_latest_mm: Option<f64>,
    /// The palm length that ends before every jam of the box.
    pub palm_length_avoiding_jams: AvoidJams,
}

/// The palm angle in rad at which the disc sits at `x_mm`: 2 atan(r / x) for h = 0, else by
/// bisection on (0, 90] deg, where x(theta) falls; None when x_mm is below x(90 deg) = r + h.
pub(crate) fn theta_at_position(p: &SceneParams, x_mm: f64) -> Option<f64> {
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

/// The least push that makes the disc of `p` jam at palm angle `theta` (rad) or beyond it (the
/// disc reaches x(theta)): the module docs' closed form, refined to the least push whose
/// closed-form jam angle is at most `theta`.
pub(crate) fn least_push(p: &SceneParams, theta: f64) -> LeastPush {
    let a = theta - p.alpha_ground() - p.alpha_palm();
    let least_moving_n = statics::least_push_n(p);
    if a <= 0.0 {
        let (theta_rigid_deg, x_rigid) = statics::rigid_limit(p);
        LeastPush::WedgeLocksFirst {
            theta_rigid_deg,
            x_rigid_mm: x_rigid.unwrap_or(f64::INFINITY),
        }
    } else if a >= std::f64::consts::FRAC_PI_2 || least_moving_n == 0.0 {
        LeastPush::AnyPushThatMoves { least_moving_n }
    } else {
        match least_reaching(p, theta, least_moving_n / a.sin()) {
            // The push is a subnormal double: said as a bound, not as a number it cannot hold.
            force_n if force_n < f64::MIN_POSITIVE => LeastPush::BelowNormal {
                least_normal_n: f64::MIN_POSITIVE,
            },
            force_n => LeastPush::Push { force_n },
        }
    }
}

/// The least push (a double) whose closed-form jam angle for `p` is at most `theta`, from the
/// closed form's `guess` > 0: theta_jam falls as the push grows, in floating point too (a
/// larger divisor never gives a larger quotient), so the status "reaches" is monotone and the
/// bracket [guess / 2, 2 guess] (widened where rounding needs it) is bisected to neighbouring
/// doubles.
fn least_reaching(p: &SceneParams, theta: f64, guess: f64) -> f64 {
    let reaches = |force_n: f64| statics::theta_jam_rad(&SceneParams { force_n, ..*p }) <= theta;
    let (mut lo, mut hi) = (0.5 * guess, 2.0 * guess);
    // 64 doublings or halvings each way: far past any rounding of the closed form.
    for _ in 0..64 {
        if reaches(hi) || !hi.is_finite() {
            break;
        }
        (lo, hi) = (hi, 2.0 * hi);
    }
    for _ in 0..64 {
        if !reaches(lo) || lo == 0.0 {
            break;
        }
        (lo, hi) = (0.5 * lo, lo);
    }
    if !reaches(hi) {
        return guess;
    }
    let mid = |a: f64, b: f64| a + 0.5 * (b - a);
    crate::locator::bisect_bracket((lo, hi), 2200, mid, |f| !reaches(f)).1
}

/// The answers for target `x_target_mm` over the box `b`; None when the target lies before
/// x(90 deg) = r + h, where no disc ever is.
pub fn design(b: &DesignBox, x_target_mm: f64) -> Option<Design> {
    let e = &b.earliest;
    let theta_t = theta_at_position(e, x_target_mm)?;
    let start = e.start_angle_deg.to_radians();
    let target_past_palm = e.contact_distance_mm(theta_t) > e.palm_length_mm;
    let carry = if theta_t >= start {
        Carry::StartsPast {
            x_start_mm: e.disc_position_mm(start),
        }
    } else {
        Carry::Ahead {
            least_push: least_push(e, theta_t),
            mu_ground_max: mu_ground_max(e, theta_t),
            mu_max: mu_max(e, theta_t),
        }
    };
    let l = &b.latest;
    let t_late = statics::theta_jam_rad(l).min(start);
    let latest_jams = t_late > 0.0;
    let x_late = latest_jams.then(|| l.disc_position_mm(t_late));
    let keeping = latest_jams
        .then(|| l.contact_distance_mm(t_late))
        .filter(|v| v.is_finite());
    Some(Design {
        x_target_mm,
        theta_target_deg: theta_t.to_degrees(),
        target_past_palm,
        carry,
        palm_length_keeping_jams_on_mm: keeping,
        x_jam_latest_mm: x_late.filter(|v| v.is_finite()),
        palm_length_avoiding_jams: avoid_jams(e),
    })
}

/// The largest ground friction for which `e`'s push, mass and palm friction reach palm angle
/// `theta_t` (module docs); None when none >= 0 does.
fn mu_ground_max(e: &SceneParams, theta_t: f64) -> Option<f64> {
    let k = e.weight_n() / e.force_n;
    let c = theta_t - e.alpha_palm();
    let tan_g = c.sin() / (c.cos() + k);
    (c > 0.0 && tan_g >= 0.0).then_some(tan_g)
}

/// The largest common friction (ground = palm) for which `e`'s push and mass reach palm angle
/// `theta_t`, by bisection; None when none >= 0 does.
fn mu_max(e: &SceneParams, theta_t: f64) -> Option<f64> {
    let reaches = |mu: f64| theta_jam_common(e, mu) <= theta_t;
    reaches(0.0).then(|| {
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
    })
}

/// The palm length that ends before every jam of a box whose earliest corner is `e`.
fn avoid_jams(e: &SceneParams) -> AvoidJams {
    let start = e.start_angle_deg.to_radians();
    let t = statics::theta_jam_rad(e);
    if t <= 0.0 {
        return AvoidJams::AnyPalm;
    }
    if t >= start {
        return AvoidJams::None;
    }
    let x = e.disc_position_mm(t);
    let below = e.contact_distance_mm(t);
    if !below.is_finite() {
        return AvoidJams::AnyPalm;
    }
    AvoidJams::ShorterThan {
        below_mm: below,
        x_jam_earliest_mm: x,
        touches_mm: e.start_contact_distance_mm(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::scene::JamStatus;
    use crate::uncertain::shaft::shaft_25mm as shaft;

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
        let Carry::Ahead {
            least_push: LeastPush::Push { force_n },
            ..
        } = d.carry
        else {
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
        let Carry::Ahead {
            mu_ground_max: Some(g),
            mu_max: Some(m),
            ..
        } = d.carry
        else {
            panic!("{d:?}");
        };
        let x = statics::solve(&SceneParams { mu_ground: g, ..p })
            .x_jam_mm
            .unwrap();
        assert!((x - 45.0).abs() < 1e-9, "{x}");
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
            matches!(d.carry, Carry::Ahead { least_push: LeastPush::WedgeLocksFirst { x_rigid_mm, .. }, .. } if (x_rigid_mm - 12.5 / 0.3).abs() < 1e-9),
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
            (d.palm_length_keeping_jams_on_mm.unwrap() - want).abs() < 1e-9,
            "{d:?}"
        );
    }

    /// At subnormal frictions the least push is a subnormal double with a few bits: the least
    /// double that reaches a 40 mm target jammed at 40.533 mm (27.72 deg against 28.07) at mu
    /// 1e-323, and the simulation could not move a disc by it. Below the smallest normal double
    /// the least push is answered as that bound, which every push above carries to the target;
    /// above it the least push reaches the target by the closed form's own answer, and one
    /// double less does not.
    #[test]
    fn the_least_push_reaches_the_target_at_subnormal_frictions() {
        for mu_ground in [
            5e-324, 1e-323, 3e-323, 1e-322, 1e-320, 1e-310, 1e-300, 1e-12, 0.1,
        ] {
            for mu_palm in [mu_ground, 0.3] {
                let p = SceneParams {
                    mu_ground,
                    mu_palm,
                    ..SceneParams::default()
                };
                let theta_t = theta_at_position(&p, 40.0).unwrap();
                let at = |force_n: f64| statics::theta_jam_rad(&SceneParams { force_n, ..p });
                match least_push(&p, theta_t) {
                    LeastPush::Push { force_n } => {
                        assert!(force_n >= f64::MIN_POSITIVE, "{p:?}: {force_n}");
                        let less = f64::from_bits(force_n.to_bits() - 1);
                        assert!(at(force_n) <= theta_t, "{p:?}: {force_n}");
                        assert!(at(less) > theta_t, "{p:?}: {less}");
                        // Full digits: the jam lands on the target to 1e-9 of its angle.
                        assert!((at(force_n) - theta_t).abs() <= 1e-9 * theta_t, "{p:?}");
                    }
                    LeastPush::BelowNormal { least_normal_n } => {
                        assert!(mu_ground < 1e-300, "{p:?}");
                        assert_eq!(least_normal_n, f64::MIN_POSITIVE);
                        assert!(at(least_normal_n) <= theta_t, "{p:?}");
                    }
                    other => panic!("{p:?}: {other:?}"),
                }
            }
        }
    }

    /// The two palm lengths against the point answers at the box's corners (the 25 mm shaft,
    /// mu 0.12 to 0.3, 80 mm palm): a palm a hair longer than the length that keeps every jam
    /// on it catches the latest corner's jam, a hair shorter loses it; a palm a hair shorter than
    /// the length that ends before every jam loses the earliest corner's jam (every point of
    /// the box is then beyond_reach), a hair longer catches it. A latest corner held at the
    /// start needs the palm to reach the start, and an earliest corner held there leaves no
    /// palm that avoids the jam.
    #[test]
    fn the_palm_lengths_keep_every_jam_on_or_end_before_all() {
        let b = DesignBox {
            earliest: with_mu(shaft(), 0.3, 40.0),
            latest: with_mu(shaft(), 0.12, 40.0),
        };
        let d = design(&b, 30.0).unwrap();
        let status = |p: &SceneParams, palm_length_mm: f64| {
            statics::solve(&SceneParams {
                palm_length_mm,
                ..*p
            })
            .status
        };
        let keep = d.palm_length_keeping_jams_on_mm.unwrap();
        assert!((keep - 99.261).abs() < 5e-4, "{keep}");
        assert_eq!(status(&b.latest, keep * (1.0 + 1e-9)), JamStatus::Jams);
        assert_eq!(
            status(&b.latest, keep * (1.0 - 1e-9)),
            JamStatus::BeyondReach
        );
        let AvoidJams::ShorterThan {
            below_mm,
            touches_mm,
            ..
        } = d.palm_length_avoiding_jams
        else {
            panic!("{d:?}");
        };
        assert!(
            (below_mm - 39.629).abs() < 5e-4 && (touches_mm - 12.5).abs() < 1e-9,
            "{d:?}"
        );
        for corner in [&b.earliest, &b.latest] {
            assert_eq!(
                status(corner, below_mm * (1.0 - 1e-9)),
                JamStatus::BeyondReach
            );
        }
        assert_eq!(
            status(&b.earliest, below_mm * (1.0 + 1e-9)),
            JamStatus::Jams
        );
        // Held at the start (60 deg) at both corners.
        let held = |p: SceneParams| SceneParams {
            start_angle_deg: 30.0,
            ..p
        };
        let b = DesignBox {
            earliest: held(b.earliest),
            latest: held(b.latest.with_mu(0.3)),
        };
        assert_eq!(statics::solve(&b.latest).status, JamStatus::JammedAtStart);
        let d = design(&b, 45.0).unwrap();
        let start = 30_f64.to_radians();
        let want = b.latest.contact_distance_mm(start);
        assert_eq!(d.palm_length_keeping_jams_on_mm, Some(want));
        assert_eq!(d.palm_length_avoiding_jams, AvoidJams::None);
    }
}
