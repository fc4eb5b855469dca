//! The closed form of the holding capacity of a symmetric V under free rotation with equal
//! flank frictions and a centre load: the fast path of a capacity map.
//!
//! With beta = gamma / 2 and x = tan(beta), the flanks' inward normals are n1 = (cos beta,
//! sin beta) and n2 = (-cos beta, sin beta). For equal frictions and a centre load the moment
//! row makes both frictions equal, and equal frictions push along the bisector only, which
//! the normals already cover (module docs of [`crate::locator`]): unless the V self-locks
//! (x < mu, every load held) the support cone is cone{n1, n2} = {(qx, qy): |qx| <= qy / x}.
//! The support the load P at direction phi needs is q = (-P cos phi, W - P sin phi), so it is
//! held iff P |cos phi| <= (W - P sin phi) / x, i.e.
//!
//! ```text
//! P (|cos phi| x + sin phi) <= W:   P_max / W = 1 / (|cos phi| x + sin phi),
//! ```
//!
//! unbounded when the bracket is <= 0 (the load pushes into the V). Past P_max the support
//! leaves the cone over the flank the load pushes away from: a load towards +x (cos phi > 0)
//! lifts the disc off the left flank and rolls it over the right one.
//!
//! x depends on the column (gamma) and (sin phi, |cos phi|) on the row (phi) of a map over
//! (included angle, load direction), so a cell costs a multiply, an add and a divide: the
//! trigonometry is done once per axis sample, as numpy's broadcasting does. The exact path
//! ([`super::capacity`]) is the oracle (`symmetric_v_closed_form_matches_the_exact_path`).

use super::exact::{Capacity, FailureMode};
use super::params::{LocatorParams, Rotation};

/// Whether the closed form applies to `p`: free rotation, a centre load, equal frictions and
/// a symmetric V (a1 = a2). Compared with `==`: the fast path must give the exact path's
/// answer, so it applies only where the exact path's V is exactly symmetric.
pub fn applies(p: &LocatorParams) -> bool {
    p.rotation == Rotation::Free
        && p.load_at_rim_deg.is_none()
        && p.mu_left == p.mu_right
        && p.flank_left_deg == p.flank_right_deg
}

/// The part of the closed form that depends on the included angle alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SymmetricV {
    /// x = tan(gamma / 2).
    tan_half_gamma: f64,
    /// The V self-locks (x < mu): every load is held.
    locks: bool,
}

impl SymmetricV {
    /// The V of `p` (a symmetric V, see [`applies`]), its included angle taken as the exact
    /// path takes it (180 - a1 - a2), so the two decide self-locking alike.
    pub fn of(p: &LocatorParams) -> Self {
        let x = (0.5 * p.included_angle_deg().to_radians()).tan();
        SymmetricV {
            tan_half_gamma: x,
            locks: x < p.mu_left,
        }
    }

    /// The capacity under a load in direction `d`, for a disc of weight `weight_n` N.
    #[inline]
    pub fn capacity(&self, d: &LoadDirection, weight_n: f64) -> Capacity {
        let bracket = d.cos_abs * self.tan_half_gamma + d.sin;
        if self.locks || bracket <= 0.0 {
            return Capacity {
                p_max_n: None,
                p_max_over_w: None,
                unbounded: true,
                failure_mode: None,
            };
        }
        let over_w = 1.0 / bracket;
        Capacity {
            p_max_n: Some(over_w * weight_n),
            p_max_over_w: Some(over_w),
            unbounded: false,
            failure_mode: Some(d.mode),
        }
    }
}

/// The part of the closed form that depends on the load direction alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadDirection {
    /// sin phi.
    sin: f64,
    /// |cos phi|.
    cos_abs: f64,
    /// How the part leaves past P_max.
    mode: FailureMode,
}

impl LoadDirection {
    /// The direction `phi_deg` (from +x, counter-clockwise).
    pub fn new(phi_deg: f64) -> Self {
        let (sin, cos) = phi_deg.to_radians().sin_cos();
        LoadDirection {
            sin,
            cos_abs: cos.abs(),
            mode: match cos > 0.0 {
                true => FailureMode::RollsOverRight,
                false => FailureMode::RollsOverLeft,
            },
        }
    }
}
