//! The robust V-block: the included angles that hold every load of a box (friction range,
//! load magnitude range, load direction range) without self-locking at any friction in it,
//! and the most robust of them.
//!
//! # What is monotone, so which points of the box decide
//!
//! Both flanks' frictions range over [mu_lo, mu_hi] (independently or together: the answer is
//! the same, see below); the load P over [P_lo, P_hi] in N, its direction phi over
//! [phi_lo, phi_hi] in deg. A V of included angle gamma (the V turned about its bisector, its
//! tilt and rotation kept) *works* when at every point of the box it holds the part and does
//! not self-lock.
//!
//! 1. **Locking is decided at mu_hi.** Free: locks iff tan(gamma/2) < min(mu1, mu2); blocked:
//!    iff gamma < atan mu1 + atan mu2. Both grow with each friction, so the V locks somewhere
//!    in the box iff it locks with both flanks at mu_hi: gamma >= gamma_lock = 2 atan mu_hi.
//! 2. **Holding is decided at mu_lo.** The equilibrium conditions do not involve mu except in
//!    |T_i| <= mu_i N_i, which only loosen as mu_i grows: forces that hold at mu_lo hold at any
//!    larger friction (of either flank). So a V that does not lock holds every friction of the
//!    box iff it holds with both flanks at mu_lo.
//! 3. **Load magnitudes: the ends decide; directions: the arc.** The loads l = P (cos phi,
//!    sin phi) that a V holds form a convex set H (the projection of the polyhedron of
//!    equilibrium forces; a rim load's moment r P sin(phi - psi) is linear in l too). The box's
//!    loads form an annular sector, whose convex hull is spanned by the two inner corners
//!    P_lo (cos phi, sin phi) at phi_lo, phi_hi and the outer arc at P_hi (for a span up to
//!    180 deg the inner arc lies between the inner chord and the outer arc; beyond, inside the
//!    outer arc's hull). So the sector lies in H iff those points do. The outer arc is covered
//!    exactly, not sampled: between two arc points dphi apart, the arc lies in the triangle of
//!    the two points and the tangents' crossing at P_hi / cos(dphi/2); each triangle's three
//!    corners are tested ([`ARC_STEP_DEG`] apart, so a V is refused for a load at most
//!    1 / cos(0.25 deg) - 1 = 1e-5 above P_hi: conservative, never optimistic).
//! 4. **Included angle.** Locking: the V works only at gamma >= gamma_lock. Holding: for a
//!    centre load (any rotation) or blocked rotation, the support cone (cone{n1, n2} free and
//!    not locking; cone{n_i +- mu u_i} blocked) shrinks as gamma grows, each normal n_i turning
//!    towards the other with the tilt kept: the cones are nested, so a V that holds a load
//!    holds it at every narrower angle. **The window is then one interval
//!    [gamma_lock, gamma_hold]**, both ends found by bisection (to 1e-9 deg). For a rim load
//!    under free rotation nothing says so: the window is searched on a [`SCAN_STEP_DEG`] grid
//!    and each edge bisected (a window narrower than the grid step can be missed; the answer
//!    says it was searched).
//!
//! # The most robust angle
//!
//! As for the point design ([`super::optimum`]), robust means: survives the largest common
//! proportional error rho before it fails either way, applied to the whole box. rho_lock is
//! the factor on mu_hi at which the V starts to lock (free: tan(gamma/2) / mu_hi); rho_hold the
//! largest factor for which the V holds every load of the box scaled by rho at friction
//! mu_lo / rho (capped just below locking). rho* = min(rho_lock, rho_hold) and gamma_robust
//! maximises it. In the window both are >= 1, rho_lock grows with gamma and rho_hold does not
//! (item 4), so gamma_robust is their crossing, inside the window, found by bisection. Free,
//! a symmetric V, a centre load sideways (phi = 0) of P: rho_lock = x / mu_hi and
//! rho_hold = W / (P x), x = tan(gamma/2), so
//!
//! ```text
//! window: 2 atan mu_hi <= gamma <= 2 atan(W / P);   gamma_robust = 2 atan sqrt(mu_hi W / P),
//! rho* = sqrt(W / (mu_hi P))
//! ```
//!
//! (the point optimum at the range's top friction; the window is empty when mu_hi P > W).
//!
//! # When no V works
//!
//! The window is empty iff the narrowest V that does not lock, gamma_lock, drops some load
//! (item 4). [`Opening`] says what opens it: the largest upper friction mu_hi' (mu_lo kept)
//! for which the V of 2 atan mu_hi' holds the box, and the largest P_hi' that the V of
//! gamma_lock holds over the directions.

use serde::Serialize;

use super::exact::{self, FailureMode};
use super::optimum::{OPT_MAX_DEG, OPT_MIN_DEG, rho_lock};
use super::params::{LocatorParams, Rotation};

/// Step of the outer arc's cover, deg: the load is overstated by at most
/// 1 / cos(ARC_STEP_DEG / 2) - 1 = 9.5e-6 between two arc points.
pub const ARC_STEP_DEG: f64 = 0.5;

/// Grid step of the window search where the window is not known to be one interval (a rim
/// load under free rotation), deg.
pub const SCAN_STEP_DEG: f64 = 0.25;

/// Bisections of an angle bracket of at most 178 deg: 60 halvings reach below 1e-15 deg.
const ANGLE_BISECTIONS: usize = 60;

/// The uncertain inputs of a V-block: closed intervals (lo <= hi; lo == hi is a point).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RobustBox {
    /// Friction coefficient of both flanks, each anywhere in [lo, hi] (independently).
    pub mu: (f64, f64),
    /// Load magnitude P in N.
    pub load_n: (f64, f64),
    /// Load direction phi in deg from +x, counter-clockwise (hi - lo <= 360).
    pub load_angle_deg: (f64, f64),
}

/// A load of the box that a V drops: where it fails and how the part leaves.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DroppedLoad {
    /// Its magnitude in N (on the outer arc possibly up to 1e-5 above P_hi, see
    /// [`ARC_STEP_DEG`]).
    pub load_n: f64,
    /// Its direction in deg.
    pub load_angle_deg: f64,
    /// How the part leaves the V.
    pub mode: FailureMode,
}

/// The most robust included angle in the window.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RobustAngle {
    /// gamma_robust in deg.
    pub included_angle_deg: f64,
    /// rho* there: the common factor on the box's loads and frictions the V survives (>= 1).
    pub safety_factor: f64,
    /// gamma_robust is an end of the window (rho_hold and rho_lock do not cross in it).
    pub at_window_end: bool,
}

/// What would open an empty window.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Opening {
    /// The largest upper friction (lower end kept) for which some V works; None when even a
    /// point friction mu_lo does not let any V hold the loads.
    pub mu_hi_max: Option<f64>,
    /// The largest upper load in N (directions and lower load kept) that the narrowest V that
    /// does not lock (`lock_bound_deg`) holds; None when it holds no load of the directions.
    pub load_hi_max_n: Option<f64>,
}

/// The robust design of a V-block over a box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobustDesign {
    /// gamma_lock = the narrowest V that does not lock at mu_hi, deg (2 atan mu_hi).
    pub lock_bound_deg: f64,
    /// The windows of included angle (deg, lo <= hi) that work over the whole box; empty when
    /// no V does. One interval unless searched (`searched`).
    pub windows: Vec<(f64, f64)>,
    /// The window was searched on a grid ([`SCAN_STEP_DEG`]) because it is not known to be
    /// one interval (a rim load under free rotation).
    pub searched: bool,
    /// The most robust angle (None when no V works).
    pub robust: Option<RobustAngle>,
    /// The load that the narrowest V that does not lock drops (None when it holds them all).
    pub dropped_at_lock_bound: Option<DroppedLoad>,
    /// What would open the window (None when it is open).
    pub opening: Option<Opening>,
}

/// A V of the box's family: `base` (tilt, rotation, weight, load point) turned to `gamma_deg`.
fn v_at(base: &LocatorParams, gamma_deg: f64) -> LocatorParams {
    base.with_included_angle_same_tilt(gamma_deg)
}

/// The V (its frictions set by the caller) holds every load of the sector
/// [p_lo, p_hi] x [phi_lo, phi_hi] (item 3 of the module docs), or the first load it drops.
pub fn holds_sector(
    v: &LocatorParams,
    load_n: (f64, f64),
    angle_deg: (f64, f64),
) -> Result<(), DroppedLoad> {
    Sector::new(v, angle_deg).held_by(v, load_n)
}

/// The load directions a sector is tested at (item 3 of the module docs) and their support
/// lines, made once for every V of one weight and load point: [`rho_hold_box`] tests the same
/// directions some 60 times per V, and making each direction's line (a sin and cos) was most
/// of the `vlocator-robust` and `vlocator-optimum` charts' time.
struct Sector {
    /// The arc's step between two test directions, deg.
    step_deg: f64,
    /// (direction in deg, its line, which load magnitude is tested there), in test order.
    tests: Vec<(f64, exact::LoadLine, Magnitude)>,
}

/// Which load of a sector [p_lo, p_hi] is tested in one direction.
#[derive(Clone, Copy)]
enum Magnitude {
    /// p_lo, at the arc's ends.
    Low,
    /// p_hi, along the arc.
    High,
    /// Where the tangents at two arc points d apart cross: p_hi / cos(d / 2).
    Apex,
}

impl Sector {
    /// The directions of the sector `angle_deg` for Vs of `v`'s weight and load point.
    fn new(v: &LocatorParams, (a, b): (f64, f64)) -> Self {
        let span = b - a;
        let n = (span / ARC_STEP_DEG).ceil().max(1.0) as usize;
        let d = span / n as f64;
        let mut tests = Vec::with_capacity(2 * n + 3);
        let mut test = |phi: f64, m: Magnitude| {
            tests.push((phi, exact::LoadLine::at(v, phi), m));
        };
        test(a, Magnitude::Low);
        test(b, Magnitude::Low);
        test(a, Magnitude::High);
        for k in 1..=n {
            let phi = if k == n { b } else { a + k as f64 * d };
            test(phi, Magnitude::High);
            if span > 0.0 {
                test(phi - 0.5 * d, Magnitude::Apex);
            }
        }
        Sector { step_deg: d, tests }
    }

    /// The V `v` (same weight and load point as the sector's, its frictions set by the caller)
    /// holds every load of [p_lo, p_hi] in the sector's directions, or the first it drops.
    fn held_by(&self, v: &LocatorParams, (p_lo, p_hi): (f64, f64)) -> Result<(), DroppedLoad> {
        // The V is the same for every load: its frame and cone once (exact::PreparedV).
        let prepared = exact::PreparedV::new(v);
        let apex = p_hi / (0.5 * self.step_deg.to_radians()).cos();
        for (phi, line, m) in &self.tests {
            let p = match m {
                Magnitude::Low => p_lo,
                Magnitude::High => p_hi,
                Magnitude::Apex => apex,
            };
            prepared.held_on(line, p).map_err(|mode| DroppedLoad {
                load_n: p,
                load_angle_deg: *phi,
                mode,
            })?;
        }
        Ok(())
    }
}

/// What one V does over a whole box.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum BoxVerdict {
    /// Holds every load at every friction and never locks.
    Works,
    /// Self-locks at the box's top friction `mu`.
    Locks {
        /// The friction, mu_hi.
        mu: f64,
    },
    /// Drops a load of the box at its lowest friction.
    Drops {
        /// The load it drops.
        load: DroppedLoad,
    },
}

/// What the V of `gamma_deg` (`base` turned to it) does over the box: locking at mu_hi,
/// then every load held at mu_lo (module docs, items 1 to 3).
pub fn verdict_over_box(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> BoxVerdict {
    match works(base, b, gamma_deg) {
        Ok(()) => BoxVerdict::Works,
        Err(None) => BoxVerdict::Locks { mu: b.mu.1 },
        Err(Some(load)) => BoxVerdict::Drops { load },
    }
}

/// Whether the V of `gamma_deg` works over the box: no locking at mu_hi, every load held at
/// mu_lo.
fn works(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> Result<(), Option<DroppedLoad>> {
    let v = v_at(base, gamma_deg);
    if exact::self_locking(&v.with_mu(b.mu.1)) {
        return Err(None);
    }
    holds_sector(&v.with_mu(b.mu.0), b.load_n, b.load_angle_deg).map_err(Some)
}

/// The final bracket (a, b) of a bisection of [lo, hi] where `left(x)` holds on the left
/// part: left(a), not left(b), to below 1e-15 of the bracket.
fn bisect(lo: f64, hi: f64, left: impl Fn(f64) -> bool) -> (f64, f64) {
    super::bisect_bracket((lo, hi), ANGLE_BISECTIONS, |a, b| 0.5 * (a + b), left)
}

/// The largest x in [lo, hi] with `ok(x)`, given ok(lo) and not ok(hi).
fn last_ok(lo: f64, hi: f64, ok: impl Fn(f64) -> bool) -> f64 {
    bisect(lo, hi, ok).0
}

/// The least x in [lo, hi] with `ok(x)`, given not ok(lo) and ok(hi): the upper end of the
/// final bracket, so `ok` holds there.
fn first_ok(lo: f64, hi: f64, ok: impl Fn(f64) -> bool) -> f64 {
    bisect(lo, hi, |x| !ok(x)).1
}

/// The search range of included angles for `base`'s tilt, deg.
fn angle_range(base: &LocatorParams) -> (f64, f64) {
    let tilt = 0.5 * (base.flank_left_deg - base.flank_right_deg).abs();
    let hi = OPT_MAX_DEG.min(180.0 - 2.0 * tilt);
    (OPT_MIN_DEG.min(hi), hi)
}

/// rho_hold over the box: the largest factor rho for which the V holds every load scaled by
/// rho at friction mu_lo / rho (capped just below locking), by bisection in log rho.
fn rho_hold_box(v: &LocatorParams, b: &RobustBox) -> f64 {
    const RHO_LIMIT: f64 = 1e6;
    let at_lo = v.with_mu(b.mu.0);
    let k_lock = if b.mu.0 > 0.0 {
        rho_lock(&at_lo) * (1.0 - 1e-9)
    } else {
        1.0
    };
    // Every V tested here differs from at_lo in its frictions only.
    let sector = Sector::new(&at_lo, b.load_angle_deg);
    let held = |rho: f64| {
        let k = (1.0 / rho).min(k_lock);
        let q = at_lo.with_mu(b.mu.0 * k);
        sector
            .held_by(&q, (rho * b.load_n.0, rho * b.load_n.1))
            .is_ok()
    };
    let (lo, hi) = (1.0 / RHO_LIMIT, RHO_LIMIT);
    if held(hi) {
        return f64::INFINITY;
    }
    if !held(lo) {
        return 0.0;
    }
    // 60 halvings of the log bracket: rho to 1e-16 relative.
    super::bisect_bracket((lo, hi), ANGLE_BISECTIONS, |a, b| (a * b).sqrt(), held).0
}

/// rho* of the V of `gamma_deg` over the box: min(rho_lock at mu_hi, rho_hold).
pub fn box_rho(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> f64 {
    let v = v_at(base, gamma_deg);
    let lock = if b.mu.1 > 0.0 {
        rho_lock(&v.with_mu(b.mu.1))
    } else {
        f64::INFINITY
    };
    lock.min(rho_hold_box(&v, b))
}

/// The windows: one interval by bisection where holding is monotone in gamma, else a grid
/// search with bisected edges.
fn windows(base: &LocatorParams, b: &RobustBox, monotone: bool) -> Vec<(f64, f64)> {
    let (g_min, g_max) = angle_range(base);
    let ok = |g: f64| works(base, b, g).is_ok();
    let unlocked = |g: f64| !exact::self_locking(&v_at(base, g).with_mu(b.mu.1));
    if monotone {
        if !unlocked(g_max) {
            return Vec::new();
        }
        let lock = if unlocked(g_min) {
            g_min
        } else {
            first_ok(g_min, g_max, unlocked)
        };
        if !ok(lock) {
            return Vec::new();
        }
        let top = if ok(g_max) {
            g_max
        } else {
            last_ok(lock, g_max, ok)
        };
        return vec![(lock, top)];
    }
    let n = ((g_max - g_min) / SCAN_STEP_DEG).ceil().max(1.0) as usize;
    let grid: Vec<f64> = (0..=n)
        .map(|k| g_min + (g_max - g_min) * k as f64 / n as f64)
        .collect();
    let flags: Vec<bool> = grid.iter().map(|&g| ok(g)).collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k <= n {
        if !flags[k] {
            k += 1;
            continue;
        }
        let start = k;
        while k < n && flags[k + 1] {
            k += 1;
        }
        let lo = if start == 0 {
            grid[0]
        } else {
            first_ok(grid[start - 1], grid[start], ok)
        };
        let hi = if k == n {
            grid[n]
        } else {
            last_ok(grid[k], grid[k + 1], ok)
        };
        out.push((lo, hi));
        k += 1;
    }
    out
}

/// The most robust angle of a window: where rho_hold and rho_lock cross, by bisection.
fn robust_in(base: &LocatorParams, b: &RobustBox, (lo, hi): (f64, f64)) -> RobustAngle {
    let v = |g: f64| v_at(base, g);
    let lock = |g: f64| {
        if b.mu.1 > 0.0 {
            rho_lock(&v(g).with_mu(b.mu.1))
        } else {
            f64::INFINITY
        }
    };
    // Hold outlasts lock: the optimum is wider.
    let wider = |g: f64| rho_hold_box(&v(g), b) >= lock(g);
    let (g, end) = if wider(hi) {
        (hi, true)
    } else if !wider(lo) {
        (lo, true)
    } else {
        (last_ok(lo, hi, wider), false)
    };
    RobustAngle {
        included_angle_deg: g,
        safety_factor: box_rho(base, b, g),
        at_window_end: end,
    }
}

/// What opens an empty window (module docs, "When no V works").
fn opening(base: &LocatorParams, b: &RobustBox, lock_deg: f64) -> Opening {
    let lock_of = |mu: f64| 2.0 * mu.atan().to_degrees();
    // The V of 2 atan mu (slightly wider, so that it does not lock at mu) holds at mu_lo.
    let holds_at_lock = |mu: f64| {
        let g = lock_of(mu) * (1.0 + 1e-12) + 1e-12;
        let v = v_at(base, g).with_mu(b.mu.0);
        holds_sector(&v, b.load_n, b.load_angle_deg).is_ok()
    };
    let mu_hi_max = holds_at_lock(b.mu.0).then(|| last_ok(b.mu.0, b.mu.1, holds_at_lock));
    let v = v_at(base, lock_deg).with_mu(b.mu.0);
    let holds_up_to = |p: f64| holds_sector(&v, (b.load_n.0.min(p), p), b.load_angle_deg).is_ok();
    let load_hi_max_n = holds_up_to(0.0).then(|| last_ok(0.0, b.load_n.1, holds_up_to));
    Opening {
        mu_hi_max,
        load_hi_max_n,
    }
}

/// The robust design of the V `base` (its tilt, rotation, weight and load point; its included
/// angle, frictions, load and direction are replaced) over the box `b` (checked by the
/// caller: finite, lo <= hi, mu >= 0, P >= 0).
pub fn robust_design(base: &LocatorParams, b: &RobustBox) -> RobustDesign {
    let monotone = base.load_at_rim_deg.is_none() || base.rotation == Rotation::Blocked;
    let (g_min, g_max) = angle_range(base);
    let lock_bound_deg = (2.0 * b.mu.1.atan().to_degrees()).clamp(g_min, g_max);
    let windows = windows(base, b, monotone);
    let dropped_at_lock_bound = works(base, b, lock_bound_deg.max(g_min) * (1.0 + 1e-12))
        .err()
        .flatten();
    let robust = windows
        .iter()
        .map(|&w| robust_in(base, b, w))
        .max_by(|x, y| x.safety_factor.total_cmp(&y.safety_factor));
    let opening = windows
        .is_empty()
        .then(|| opening(base, b, lock_bound_deg * (1.0 + 1e-12)));
    RobustDesign {
        lock_bound_deg,
        windows,
        searched: !monotone,
        robust,
        dropped_at_lock_bound,
        opening,
    }
}
