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

use std::mem::MaybeUninit;

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

    /// The capacity under a load in direction `d`, for a disc of weight `weight_n` N, one
    /// cell at a time: the reference the row kernels are tested against.
    #[cfg(test)]
    fn capacity(&self, d: &LoadDirection, weight_n: f64) -> Capacity {
        let bracket = d.cos_abs * self.tan_half_gamma + d.sin;
        cell(self.locks, bracket, 1.0 / bracket, d.mode, weight_n)
    }
}

/// One cell of the closed form: unbounded where the V `locks` or the `bracket` |cos phi| x +
/// sin phi is <= 0, otherwise P_max / W = `over_w` (1 / bracket, computed by the caller so that
/// a row's divisions run together) leaving by `mode`. Written without branches: a branch per
/// field cost a store per padding byte.
#[inline(always)]
fn cell(locks: bool, bracket: f64, over_w: f64, mode: FailureMode, weight_n: f64) -> Capacity {
    let bounded = !(locks || bracket <= 0.0);
    Capacity {
        p_max_n: bounded.then_some(over_w * weight_n),
        p_max_over_w: bounded.then_some(over_w),
        unbounded: !bounded,
        failure_mode: bounded.then_some(mode),
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

/// Cells a row kernel takes at once: eight brackets, their reciprocals, then their cells, with
/// no bounds checks and no branch on the row's length between them.
const LANES: usize = 8;

/// The Vs along a map's axis of included angles, as flat arrays for the row kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct Vs {
    /// x = tan(gamma / 2) of each V.
    tan_half_gamma: Vec<f64>,
    /// Whether each V self-locks.
    locks: Vec<bool>,
}

impl Vs {
    /// The Vs of `vs`.
    pub fn new(vs: &[SymmetricV]) -> Self {
        Vs {
            tan_half_gamma: vs.iter().map(|v| v.tan_half_gamma).collect(),
            locks: vs.iter().map(|v| v.locks).collect(),
        }
    }
}

/// The directions along a map's axis of load directions, as flat arrays for the row kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDirections {
    /// sin phi of each direction.
    sin: Vec<f64>,
    /// |cos phi| of each direction.
    cos_abs: Vec<f64>,
    /// How the part leaves past P_max in each direction.
    mode: Vec<FailureMode>,
}

impl LoadDirections {
    /// The directions of `ds`.
    pub fn new(ds: &[LoadDirection]) -> Self {
        LoadDirections {
            sin: ds.iter().map(|d| d.sin).collect(),
            cos_abs: ds.iter().map(|d| d.cos_abs).collect(),
            mode: ds.iter().map(|d| d.mode).collect(),
        }
    }
}

impl LoadDirection {
    /// [`SymmetricV::capacity`] of every V of `vs` under this direction, into `out` (as long
    /// as `vs`): a row of a map with the included angle on x, bit for bit the cells'.
    pub fn capacities(&self, vs: &Vs, weight_n: f64, out: &mut [MaybeUninit<Capacity>]) {
        let bracket = |x: f64| self.cos_abs * x + self.sin;
        let mut outs = out.chunks_exact_mut(LANES);
        let mut xs = vs.tan_half_gamma.chunks_exact(LANES);
        let mut locks = vs.locks.chunks_exact(LANES);
        for ((o, x), l) in (&mut outs).zip(&mut xs).zip(&mut locks) {
            let b: [f64; LANES] = std::array::from_fn(|j| bracket(x[j]));
            lanes(o, &b, |j| l[j], |_| self.mode, weight_n);
        }
        let rest = outs.into_remainder().iter_mut();
        for ((o, &x), &l) in rest.zip(xs.remainder()).zip(locks.remainder()) {
            let b = bracket(x);
            o.write(cell(l, b, 1.0 / b, self.mode, weight_n));
        }
    }
}

impl SymmetricV {
    /// [`SymmetricV::capacity`] of this V under every direction of `ds`, into `out` (as long
    /// as `ds`): a row of a map with the load direction on x, bit for bit the cells'.
    pub fn capacities(
        &self,
        ds: &LoadDirections,
        weight_n: f64,
        out: &mut [MaybeUninit<Capacity>],
    ) {
        let bracket = |cos_abs: f64, sin: f64| cos_abs * self.tan_half_gamma + sin;
        let mut outs = out.chunks_exact_mut(LANES);
        let mut coss = ds.cos_abs.chunks_exact(LANES);
        let mut sins = ds.sin.chunks_exact(LANES);
        let mut modes = ds.mode.chunks_exact(LANES);
        for (((o, c), s), m) in (&mut outs).zip(&mut coss).zip(&mut sins).zip(&mut modes) {
            let b: [f64; LANES] = std::array::from_fn(|j| bracket(c[j], s[j]));
            lanes(o, &b, |_| self.locks, |j| m[j], weight_n);
        }
        let rest = outs.into_remainder().iter_mut();
        let dirs = coss
            .remainder()
            .iter()
            .zip(sins.remainder())
            .zip(modes.remainder());
        for (o, ((&c, &s), &m)) in rest.zip(dirs) {
            let b = bracket(c, s);
            o.write(cell(self.locks, b, 1.0 / b, m, weight_n));
        }
    }
}

/// [`LANES`] cells from their brackets `b`, whether their V `locks(j)` and their `mode(j)`:
/// the reciprocals first, then the cells ([`cell`]).
#[inline(always)]
fn lanes(
    out: &mut [MaybeUninit<Capacity>],
    b: &[f64; LANES],
    locks: impl Fn(usize) -> bool,
    mode: impl Fn(usize) -> FailureMode,
    weight_n: f64,
) {
    let over_w: [f64; LANES] = std::array::from_fn(|j| 1.0 / b[j]);
    for (j, o) in out.iter_mut().enumerate().take(LANES) {
        o.write(cell(locks(j), b[j], over_w[j], mode(j), weight_n));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row kernel's cells are [`SymmetricV::capacity`]'s bit for bit, along either axis, for
    /// rows shorter and longer than its lanes: Vs that lock and that do not, loads into the V
    /// (unbounded), along it and away from it, and a bracket of exactly 0.
    #[test]
    fn row_kernels_give_the_cells_bit_for_bit() {
        let base = LocatorParams::default().with_mu(0.4);
        let weight_n = 3.7;
        for n in [1, 7, 8, 9, 23, 64] {
            let gammas: Vec<f64> = (0..n).map(|i| 5.0 + 170.0 * i as f64 / n as f64).collect();
            let phis: Vec<f64> = (0..n)
                .map(|i| -180.0 + 360.0 * i as f64 / n as f64)
                .collect();
            let vs: Vec<SymmetricV> = gammas
                .iter()
                .map(|&g| SymmetricV::of(&base.with_included_angle_same_tilt(g)))
                .chain([SymmetricV {
                    tan_half_gamma: 1.0,
                    locks: false,
                }])
                .collect();
            let ds: Vec<LoadDirection> = phis
                .iter()
                .map(|&p| LoadDirection::new(p))
                .chain([LoadDirection {
                    sin: -1.0,
                    cos_abs: 1.0,
                    mode: FailureMode::RollsOverLeft,
                }])
                .collect();
            let bits = |c: &Capacity| {
                (
                    c.p_max_n.map(f64::to_bits),
                    c.p_max_over_w.map(f64::to_bits),
                    c.unbounded,
                    c.failure_mode,
                )
            };
            let mut row = vec![MaybeUninit::uninit(); vs.len().max(ds.len())];
            for d in &ds {
                d.capacities(&Vs::new(&vs), weight_n, &mut row[..vs.len()]);
                for (v, got) in vs.iter().zip(&row) {
                    // SAFETY: `capacities` wrote every cell of the row.
                    let got = unsafe { got.assume_init() };
                    assert_eq!(bits(&got), bits(&v.capacity(d, weight_n)), "{v:?} {d:?}");
                }
            }
            for v in &vs {
                v.capacities(&LoadDirections::new(&ds), weight_n, &mut row[..ds.len()]);
                for (d, got) in ds.iter().zip(&row) {
                    // SAFETY: `capacities` wrote every cell of the row.
                    let got = unsafe { got.assume_init() };
                    assert_eq!(bits(&got), bits(&v.capacity(d, weight_n)), "{v:?} {d:?}");
                }
            }
        }
    }
}
