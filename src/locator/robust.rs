//! The robust V-block: the included angles that hold every load of a box (friction ranges,
//! mass range, load magnitude range, load direction range) without self-locking at any
//! friction in it, and the most robust of them.
//!
//! # What is monotone, so which points of the box decide
//!
//! The left flank's friction ranges over [mu1_lo, mu1_hi], the right one's over
//! [mu2_lo, mu2_hi] (independently; one range on both flanks is the case mu1 = mu2); the
//! disc's mass over [m_lo, m_hi] (its weight W = m g); the load P over [P_lo, P_hi] in N, its
//! direction phi over [phi_lo, phi_hi] in deg. A V of included angle gamma (the V turned about
//! its bisector, its tilt and rotation kept) *works* when at every point of the box it holds
//! the part and does not self-lock.
//!
//! 1. **Locking is decided at both highs.** Free: locks iff tan(gamma/2) < min(mu1, mu2);
//!    blocked: iff gamma < atan mu1 + atan mu2. Both grow with each friction, so the V locks
//!    somewhere in the box iff it locks with each flank at its high: gamma >= gamma_lock =
//!    2 atan min(mu1_hi, mu2_hi) free, atan mu1_hi + atan mu2_hi blocked (2 atan mu_hi for one
//!    range on both).
//! 2. **Holding is decided at both lows, and at both ends of the weight.** The equilibrium
//!    conditions do not involve mu except in |T_i| <= mu_i N_i, which only loosen as mu_i grows:
//!    forces that hold at the lows hold at any larger friction of either flank. So a V that
//!    does not lock holds every friction of the box iff it holds with each flank at its low.
//!    Equilibrium is linear and homogeneous in the flank forces, the weight W and the load
//!    l = P (cos phi, sin phi): the (W, l) that a V holds form a convex cone. The box is
//!    [W_lo, W_hi] times the loads of item 3, whose hull is spanned by both ends of W with the
//!    loads' hull points, so a V holds the box iff it holds item 3's loads at W_lo and at W_hi.
//! 3. **Load magnitudes: the ends decide; directions: the arc.** The loads l = P (cos phi,
//!    sin phi) that a V holds form a convex set H (the projection of the polyhedron of
//!    equilibrium forces; a rim load's moment r P sin(phi - psi) is linear in l too). The box's
//!    loads form an annular sector, whose convex hull is spanned by the two inner corners
//!    P_lo (cos phi, sin phi) at phi_lo, phi_hi and the outer arc at P_hi (for a span up to
//!    180 deg the inner arc lies between the inner chord and the outer arc; beyond, inside the
//!    outer arc's hull). So the sector lies in H iff those points do. The outer arc is covered
//!    exactly, not sampled: between two arc points dphi apart, the arc lies in the triangle of
//!    the two points and the tangents' crossing at P_hi / cos(dphi/2); each triangle's three
//!    corners are tested (`ARC_STEP_DEG`, 0.5 deg apart, so a V is refused for a load at most
//!    1 / cos(0.25 deg) - 1 = 1e-5 above P_hi: conservative, never optimistic).
//! 4. **Included angle.** Locking: the V works only at gamma >= gamma_lock. Holding: for a
//!    centre load (any rotation) or blocked rotation, the support cone (cone{n1, n2} free and
//!    not locking; cone{n_i +- mu u_i} blocked) shrinks as gamma grows, each normal n_i turning
//!    towards the other with the tilt kept: the cones are nested, so a V that holds a load
//!    holds it at every narrower angle. **The window is then one interval
//!    [gamma_lock, gamma_hold]**, both ends found by bisection (to 1e-9 deg). For a rim load
//!    under free rotation nothing says so: the window is searched on a `SCAN_STEP_DEG`, 0.25 deg grid
//!    and each edge bisected (a window narrower than the grid step can be missed; the answer
//!    says it was searched).
//!
//! # The most robust angle
//!
//! As for the point design ([`crate::locator::optimum()`]), robust means: survives the largest common
//! proportional error rho before it fails either way, applied to the whole box. rho_lock is
//! the factor on the highs at which the V starts to lock (free: tan(gamma/2) / mu_hi); rho_hold
//! the largest factor for which the V holds every load of the box scaled by rho at the lows'
//! frictions / rho (capped just below locking), at both ends of the weight. rho* = min(rho_lock, rho_hold) and gamma_robust
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
//! (item 4). [`Opening`] says what opens it: the largest cap mu_hi' on the flanks' upper
//! frictions (each flank's range cut at it, the lows kept) for which the V just wide enough not
//! to lock at the cut highs holds the box, and the largest P_hi' that the V of gamma_lock holds
//! over the directions and weights.

use serde::Serialize;

use super::exact::{self, FailureMode};
use super::optimum::{OPT_MAX_DEG, OPT_MIN_DEG, rho_lock};
use super::params::{LocatorParams, Rotation};

/// Step of the outer arc's cover, deg: the load is overstated by at most
/// 1 / cos(ARC_STEP_DEG / 2) - 1 = 9.5e-6 between two arc points.
pub(crate) const ARC_STEP_DEG: f64 = 0.5;

/// Grid step of the window search where the window is not known to be one interval (a rim
/// load under free rotation), deg.
pub(crate) const SCAN_STEP_DEG: f64 = 0.25;

/// Bisections of an angle bracket of at most 178 deg: 60 halvings reach below 1e-15 deg.
const ANGLE_BISECTIONS: usize = 60;

/// The uncertain inputs of a V-block: closed intervals (lo <= hi; lo == hi is a point).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RobustBox {
    /// Friction coefficient of the left flank, anywhere in [lo, hi].
    pub mu_left: (f64, f64),
    /// Friction coefficient of the right flank, anywhere in [lo, hi] (independently of the
    /// left).
    pub mu_right: (f64, f64),
    /// Disc mass m in kg (lo > 0); the weight is m g at the V's gravity.
    pub mass_kg: (f64, f64),
    /// Load magnitude P in N.
    pub load_n: (f64, f64),
    /// Load direction phi in deg from +x, counter-clockwise (hi - lo <= 360).
    pub load_angle_deg: (f64, f64),
}

impl RobustBox {
    /// One friction range `mu` on both flanks, the disc of `base`, loads `load_n` in
    /// directions `load_angle_deg`.
    pub fn both_flanks(
        base: &LocatorParams,
        mu: (f64, f64),
        load_n: (f64, f64),
        load_angle_deg: (f64, f64),
    ) -> Self {
        RobustBox {
            mu_left: mu,
            mu_right: mu,
            mass_kg: (base.mass_kg, base.mass_kg),
            load_n,
            load_angle_deg,
        }
    }

    /// `v` with each flank's lowest friction, where holding is decided (item 2).
    pub fn at_lows(&self, v: &LocatorParams) -> LocatorParams {
        LocatorParams {
            mu_left: self.mu_left.0,
            mu_right: self.mu_right.0,
            ..*v
        }
    }

    /// `v` with each flank's highest friction, where locking is decided (item 1).
    pub fn at_highs(&self, v: &LocatorParams) -> LocatorParams {
        LocatorParams {
            mu_left: self.mu_left.1,
            mu_right: self.mu_right.1,
            ..*v
        }
    }

    /// The masses that decide holding (item 2): both ends, or the one when they are equal.
    fn masses(&self) -> impl Iterator<Item = f64> {
        let (lo, hi) = self.mass_kg;
        std::iter::once(lo).chain((hi != lo).then_some(hi))
    }

    /// Whether one friction range holds on both flanks.
    pub fn one_friction_range(&self) -> bool {
        self.mu_left == self.mu_right
    }
}

/// gamma_lock in deg: the narrowest V (turned about its bisector) that does not self-lock with
/// frictions `mu` (left, right): 2 atan min(mu) free, atan mu1 + atan mu2 blocked (item 1).
pub(crate) fn lock_angle_deg(rotation: Rotation, (m1, m2): (f64, f64)) -> f64 {
    match rotation {
        Rotation::Free => 2.0 * m1.min(m2).atan().to_degrees(),
        Rotation::Blocked => (m1.atan() + m2.atan()).to_degrees(),
    }
}

/// A load of the box that a V drops: where it fails and how the part leaves.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DroppedLoad {
    /// Its magnitude in N (on the outer arc possibly up to 1e-5 above P_hi, see
    /// `ARC_STEP_DEG`, 0.5 deg).
    pub load_n: f64,
    /// Its direction in deg.
    pub load_angle_deg: f64,
    /// The disc's mass in kg where it is dropped (an end of the box's mass range).
    pub mass_kg: f64,
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
    /// The window was searched on a grid (`SCAN_STEP_DEG`, 0.25 deg) because it is not known to be
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
pub(crate) fn holds_sector(
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
        // Capped at the largest float: an apex past it made the support inf - inf = NaN.
        let apex = (p_hi / (0.5 * self.step_deg.to_radians()).cos()).min(f64::MAX);
        for (phi, line, m) in &self.tests {
            let p = match m {
                Magnitude::Low => p_lo,
                Magnitude::High => p_hi,
                Magnitude::Apex => apex,
            };
            prepared.held_on(line, p).map_err(|mode| DroppedLoad {
                load_n: p,
                load_angle_deg: *phi,
                mass_kg: v.mass_kg,
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
    /// Self-locks at the box's top frictions.
    Locks {
        /// The left flank's friction, its high.
        mu_left: f64,
        /// The right flank's friction, its high.
        mu_right: f64,
    },
    /// Drops a load of the box at its lowest friction.
    Drops {
        /// The load it drops.
        load: DroppedLoad,
    },
}

/// What the V of `gamma_deg` (`base` turned to it) does over the box: locking at the highs,
/// then every load held at the lows (module docs, items 1 to 3).
pub(crate) fn verdict_over_box(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> BoxVerdict {
    match works(base, b, gamma_deg) {
        Ok(()) => BoxVerdict::Works,
        Err(None) => BoxVerdict::Locks {
            mu_left: b.mu_left.1,
            mu_right: b.mu_right.1,
        },
        Err(Some(load)) => BoxVerdict::Drops { load },
    }
}

/// Whether the V of `gamma_deg` works over the box: no locking at the highs, every load held
/// at the lows and both ends of the weight.
fn works(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> Result<(), Option<DroppedLoad>> {
    let v = v_at(base, gamma_deg);
    if exact::self_locking(&b.at_highs(&v)) {
        return Err(None);
    }
    holds_box(&b.at_lows(&v), b, b.load_n).map_err(Some)
}

/// The V `v` (its frictions set by the caller) holds the loads `load_n` of the box's
/// directions at each end of its mass range (item 2), or the first load it drops.
fn holds_box(v: &LocatorParams, b: &RobustBox, load_n: (f64, f64)) -> Result<(), DroppedLoad> {
    b.masses().try_for_each(|m| {
        let v = LocatorParams { mass_kg: m, ..*v };
        holds_sector(&v, load_n, b.load_angle_deg)
    })
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
/// rho at the lows' frictions / rho (capped just below locking), at each end of the weight, by
/// bisection in log rho.
fn rho_hold_box(v: &LocatorParams, b: &RobustBox) -> f64 {
    const RHO_LIMIT: f64 = 1e6;
    let at_lo = b.at_lows(v);
    let k_lock = if at_lo.mu_left.min(at_lo.mu_right) > 0.0 {
        rho_lock(&at_lo) * (1.0 - 1e-9)
    } else {
        1.0
    };
    // Every V tested here differs from at_lo in its frictions only (per mass).
    let sectors: Vec<(LocatorParams, Sector)> = b
        .masses()
        .map(|m| {
            let at_m = LocatorParams {
                mass_kg: m,
                ..at_lo
            };
            (at_m, Sector::new(&at_m, b.load_angle_deg))
        })
        .collect();
    let held = |rho: f64| {
        let k = (1.0 / rho).min(k_lock);
        sectors.iter().all(|(at_m, sector)| {
            let q = LocatorParams {
                mu_left: at_m.mu_left * k,
                mu_right: at_m.mu_right * k,
                ..*at_m
            };
            sector
                .held_by(&q, (rho * b.load_n.0, rho * b.load_n.1))
                .is_ok()
        })
    };
    // Loads scaled past the largest float made the support NaN (`--load 10:1e308`). Loads
    // held at the top of the float range (by friction divided by as much) push into the V:
    // the support they need turns into the normals' cone as P grows, so a larger factor holds
    // them too, and rho is unbounded as at RHO_LIMIT. (2: room for the arc's apex.)
    let top = f64::MAX / b.load_n.1.max(1.0) / 2.0;
    let (lo, hi) = (1.0 / RHO_LIMIT, RHO_LIMIT.min(top));
    if held(hi) {
        return f64::INFINITY;
    }
    if !held(lo) {
        return 0.0;
    }
    // 60 halvings of the log bracket: rho to 1e-16 relative.
    super::bisect_bracket((lo, hi), ANGLE_BISECTIONS, |a, b| (a * b).sqrt(), held).0
}

/// rho* of the V of `gamma_deg` over the box: min(rho_lock at the highs, rho_hold).
pub(crate) fn box_rho(base: &LocatorParams, b: &RobustBox, gamma_deg: f64) -> f64 {
    let v = v_at(base, gamma_deg);
    lock_factor(&v, b).min(rho_hold_box(&v, b))
}

/// rho_lock of the V `v` at the box's highs (unbounded where a flank has no friction to lock
/// with).
fn lock_factor(v: &LocatorParams, b: &RobustBox) -> f64 {
    if b.mu_left.1.min(b.mu_right.1) > 0.0 {
        rho_lock(&b.at_highs(v))
    } else {
        f64::INFINITY
    }
}

/// The windows: one interval by bisection where holding is monotone in gamma, else a grid
/// search with bisected edges.
fn windows(base: &LocatorParams, b: &RobustBox, monotone: bool) -> Vec<(f64, f64)> {
    let (g_min, g_max) = angle_range(base);
    let ok = |g: f64| works(base, b, g).is_ok();
    let unlocked = |g: f64| !exact::self_locking(&b.at_highs(&v_at(base, g)));
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
    // Hold outlasts lock: the optimum is wider.
    let wider = |g: f64| rho_hold_box(&v(g), b) >= lock_factor(&v(g), b);
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
    // The box with each flank's range cut at `cap` (its low kept).
    let capped = |cap: f64| RobustBox {
        mu_left: (b.mu_left.0, b.mu_left.1.min(cap)),
        mu_right: (b.mu_right.0, b.mu_right.1.min(cap)),
        ..*b
    };
    // The V just wide enough not to lock at the cut highs holds the box at the lows.
    let holds_at_lock = |cap: f64| {
        let c = capped(cap);
        let g = lock_angle_deg(base.rotation, (c.mu_left.1, c.mu_right.1)) * (1.0 + 1e-12) + 1e-12;
        holds_box(&c.at_lows(&v_at(base, g)), &c, c.load_n).is_ok()
    };
    let (cap_lo, cap_hi) = (b.mu_left.0.max(b.mu_right.0), b.mu_left.1.max(b.mu_right.1));
    let mu_hi_max = holds_at_lock(cap_lo).then(|| last_ok_magnitude(cap_lo, cap_hi, holds_at_lock));
    let v = b.at_lows(&v_at(base, lock_deg));
    let holds_up_to = |p: f64| holds_box(&v, b, (b.load_n.0.min(p), p)).is_ok();
    let load_hi_max_n = holds_up_to(0.0).then(|| last_ok_magnitude(0.0, b.load_n.1, holds_up_to));
    Opening {
        mu_hi_max,
        load_hi_max_n,
    }
}

/// Halvings that take any bracket of floats to two neighbouring floats: from the largest
/// float to the smallest subnormal spacing is 1024 + 1074 halvings.
const MAGNITUDE_BISECTIONS: usize = 2100;

/// [`last_ok`] for a friction or a load, whose bracket may span the float range (`--load
/// 10:1e308`): 60 halvings of [0, 1e308] leave a bracket of 1e290. The midpoint is halved
/// before it is summed (a + b overflows there); below, the same bits as (a + b) / 2.
fn last_ok_magnitude(lo: f64, hi: f64, ok: impl Fn(f64) -> bool) -> f64 {
    super::bisect_bracket((lo, hi), MAGNITUDE_BISECTIONS, |a, b| 0.5 * a + 0.5 * b, ok).0
}

/// The robust design of the V `base` (its tilt, rotation, gravity and load point; its included
/// angle, frictions, mass, load and direction are replaced) over the box `b` (checked by the
/// caller: finite, lo <= hi, mu >= 0, m > 0, P >= 0).
pub fn robust_design(base: &LocatorParams, b: &RobustBox) -> RobustDesign {
    let monotone = base.load_at_rim_deg.is_none() || base.rotation == Rotation::Blocked;
    let (g_min, g_max) = angle_range(base);
    let lock_bound_deg =
        lock_angle_deg(base.rotation, (b.mu_left.1, b.mu_right.1)).clamp(g_min, g_max);
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
