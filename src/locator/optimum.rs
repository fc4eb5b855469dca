//! The balanced optimum included angle: the V that survives the largest common proportional
//! error rho in load and friction before it drops the part or locks it.

use serde::Serialize;

use super::exact;
use super::params::{LocatorParams, Rotation};

/// The narrowest V the search tries, deg: narrower is no fixture.
pub const OPT_MIN_DEG: f64 = 1.0;
/// The widest V the search tries, deg (a flat V is one contact); a tilted V also keeps both
/// flank angles >= 0.
pub const OPT_MAX_DEG: f64 = 179.0;

/// rho is searched within [1 / RHO_LIMIT, RHO_LIMIT]: beyond it a V is called unbounded.
const RHO_LIMIT: f64 = 1e6;

/// Just below the locking friction: the cone is still pointed there, 1e-9 relative.
const UNLOCKED: f64 = 1.0 - 1e-9;

/// The criterion that picks the optimum angle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Criterion {
    /// Maximise rho* = min(rho_hold, rho_lock).
    Balanced,
}

/// The optimum included angle of a V for a load, flank tilt and friction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Optimum {
    /// Always `Criterion::Balanced`.
    pub criterion: Criterion,
    /// gamma* in deg.
    pub included_angle_deg: f64,
    /// rho* at gamma*: the common factor on load and friction the V survives (<= 1: no V
    /// that does not lock can hold the load).
    pub safety_factor: f64,
    /// gamma* lies at the end of the search range `OPT_MIN_DEG`, `OPT_MAX_DEG` (e.g.
    /// no load: the widest V is safest).
    pub at_bound: bool,
    /// rho* <= 1: every V that does not self-lock drops the load at the nominal friction, so
    /// no V works; `included_angle_deg` is then only the least bad compromise (one that
    /// self-locks at the nominal friction), not an answer.
    pub no_v_holds: bool,
    /// The widest V (deg) that survives the same rho* when the optimum is not unique: rho_hold
    /// is constant (a pure lift, where every V holds the same) and every V from gamma* up to
    /// this angle does as well. None when gamma* is the only optimum.
    pub plateau_to_deg: Option<f64>,
}

/// Relative tolerance within which another V's rho* counts as the optimum's: the bisections
/// resolve rho to far below it, so a difference this small is not a better V.
const PLATEAU_RTOL: f64 = 1e-9;

/// `p` with both frictions multiplied by `k`.
fn friction_scaled(p: &LocatorParams, k: f64) -> LocatorParams {
    LocatorParams {
        mu_left: p.mu_left * k,
        mu_right: p.mu_right * k,
        ..*p
    }
}

/// rho_lock: the factor on both frictions at which the V starts to self-lock (infinite if it
/// never does). Free: tan(gamma/2) / min(mu1, mu2). Blocked: the root of
/// atan(rho mu1) + atan(rho mu2) = gamma,
/// rho = 2 sin gamma / (s cos gamma + sqrt(s^2 cos^2 gamma + 4 mu1 mu2 sin^2 gamma)), s = mu1 + mu2
/// (tan(gamma/2) / mu for equal frictions).
pub fn rho_lock(p: &LocatorParams) -> f64 {
    let gamma = p.included_angle_deg().to_radians();
    let (m1, m2) = (p.mu_left, p.mu_right);
    match p.rotation {
        Rotation::Free => (0.5 * gamma).tan() / m1.min(m2),
        Rotation::Blocked => {
            let (s, c) = gamma.sin_cos();
            let sum = m1 + m2;
            let den = sum * c + (sum * sum * c * c + 4.0 * m1 * m2 * s * s).sqrt();
            if den > 0.0 {
                2.0 * s / den
            } else {
                f64::INFINITY
            }
        }
    }
}

/// `p` with friction just below the locking friction (`p` itself if that is above 1).
pub fn just_unlocked(p: &LocatorParams) -> LocatorParams {
    friction_scaled(p, (rho_lock(p) * UNLOCKED).min(1.0))
}

/// rho_hold: the largest factor rho for which the V holds the load rho P with friction mu / rho,
/// the friction capped just below locking (a V that holds only by locking has failed the
/// other way). Found by bisection in log rho, held being monotone in rho.
pub fn rho_hold(p: &LocatorParams) -> f64 {
    let k_lock = rho_lock(p) * UNLOCKED;
    // Every V tested differs from p in its frictions only: one support line for all of them.
    let line = exact::LoadLine::new(p);
    let held = |rho: f64| {
        let q = friction_scaled(p, (1.0 / rho).min(k_lock));
        exact::PreparedV::new(&q)
            .held_on(&line, rho * p.load_n)
            .is_ok()
    };
    // A load scaled past the largest float made the support NaN (`--load 9e307`); held at
    // the top of the float range it pushes into the V, and rho is unbounded (see
    // `robust::rho_hold_box`).
    let top = f64::MAX / p.load_n.max(1.0);
    let (lo, hi) = (1.0 / RHO_LIMIT, RHO_LIMIT.min(top));
    if held(hi) {
        return f64::INFINITY;
    }
    if !held(lo) {
        return 0.0;
    }
    // 80 halvings of the log bracket: far below one ulp of rho.
    super::bisect_bracket((lo, hi), 80, |a, b| (a * b).sqrt(), held).0
}

/// rho* = min(rho_hold, rho_lock) of the V `p`.
pub fn balanced_rho(p: &LocatorParams) -> f64 {
    rho_hold(p).min(rho_lock(p))
}

/// The balanced optimum: gamma* maximising rho* over the included angle, the V turned about
/// its bisector (tilt kept).
///
/// rho_lock grows with gamma and rho_hold does not (a wider V holds less, or, for a pure
/// lift, the same), so gamma* is where they cross, found by bisection; without a crossing it
/// is an end of the range. Where rho_hold is constant every wider V survives the same rho*:
/// `plateau_to_deg` says so.
pub fn optimum(p: &LocatorParams) -> Optimum {
    let tilt = 0.5 * (p.flank_left_deg - p.flank_right_deg).abs();
    let hi = OPT_MAX_DEG.min(180.0 - 2.0 * tilt);
    let lo = OPT_MIN_DEG.min(hi);
    let at = |g: f64| p.with_included_angle_same_tilt(g);
    // Hold outlasts lock: the optimum is wider.
    let wider = |g: f64| {
        let v = at(g);
        rho_hold(&v) >= rho_lock(&v)
    };
    let done = |g: f64, at_bound| {
        let rho = balanced_rho(&at(g));
        let widest = balanced_rho(&at(hi));
        let plateau = g < hi && rho.is_finite() && widest >= rho * (1.0 - PLATEAU_RTOL);
        Optimum {
            criterion: Criterion::Balanced,
            included_angle_deg: g,
            safety_factor: rho,
            at_bound,
            no_v_holds: rho <= 1.0,
            plateau_to_deg: plateau.then_some(hi),
        }
    };
    if wider(hi) {
        return done(hi, true);
    }
    if !wider(lo) {
        return done(lo, true);
    }
    // 60 halvings of at most 178 deg: below 1e-15 deg.
    let (a, _) = super::bisect_bracket((lo, hi), 60, |a, b| 0.5 * (a + b), wider);
    done(a, false)
}

/// The closed-form optimum of a symmetric V under free rotation, equal frictions mu and a
/// centre load P at direction phi (deg): (gamma* in deg, rho*), None when the crossing does
/// not exist (no load, or a load pushing into the V).
///
/// Not locking, friction adds nothing, so the V holds P <= W / (|cos phi| x + sin phi) with
/// x = tan(gamma/2) (the load inside the cone of the two normals), rho_hold = that over P,
/// and rho_lock = x / mu. They cross where |cos phi| x^2 + sin phi x = mu W / P:
///
/// ```text
/// x* = (-sin phi + sqrt(sin^2 phi + 4 |cos phi| mu W / P)) / (2 |cos phi|),  gamma* = 2 atan x*,
/// rho* = x* / mu
/// ```
///
/// For a sideways load (phi = 0): gamma* = 2 atan sqrt(mu W / P), so a 90 deg V is optimal
/// when P / W = mu.
#[cfg(test)]
pub fn closed_form_free_centre(mu: f64, p_over_w: f64, phi_deg: f64) -> Option<(f64, f64)> {
    let (s, c) = phi_deg.to_radians().sin_cos();
    let c = c.abs();
    if !(mu > 0.0 && p_over_w > 0.0) {
        return None;
    }
    let k = mu / p_over_w;
    let x = if c > 1e-12 {
        (-s + (s * s + 4.0 * c * k).sqrt()) / (2.0 * c)
    } else if s > 0.0 {
        k / s
    } else {
        return None;
    };
    Some((2.0 * x.atan().to_degrees(), x / mu))
}
