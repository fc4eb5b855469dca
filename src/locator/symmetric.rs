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

use super::exact::FailureMode;
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
    /// The flanks' friction mu: the V self-locks where x < mu, and then every load is held.
    mu: f64,
}

impl SymmetricV {
    /// The V of `p` (a symmetric V, see [`applies`]), its included angle taken as the exact
    /// path takes it (180 - a1 - a2), so the two decide self-locking alike.
    pub fn of(p: &LocatorParams) -> Self {
        let x = (0.5 * p.included_angle_deg().to_radians()).tan();
        SymmetricV {
            tan_half_gamma: x,
            mu: p.mu_left,
        }
    }

    /// Whether the V self-locks (x < mu): every load is held.
    fn locks(&self) -> bool {
        self.tan_half_gamma < self.mu
    }

    /// The capacity under a load in direction `d`, one cell at a time, as a row holds it
    /// (P_max / W or NaN, and the failure mode): the reference the row kernels are tested
    /// against.
    #[cfg(test)]
    fn capacity(&self, d: &LoadDirection) -> (f64, Option<FailureMode>) {
        let bracket = d.cos_abs * self.tan_half_gamma + d.sin;
        match self.locks() || bracket <= 0.0 {
            true => (f64::NAN, None),
            false => (1.0 / bracket, Some(d.mode)),
        }
    }
}

/// A row of a capacity map as the row kernels write it, a column per answer: P_max / W of
/// each cell (NaN where every load is held) and how the part leaves past it (None there).
/// The two slices are as long as each other.
pub struct Row<'a> {
    /// P_max / W, dimensionless; NaN where the cell is unbounded.
    pub over_w: &'a mut [MaybeUninit<f64>],
    /// How the part leaves just beyond P_max; None where the cell is unbounded.
    pub mode: &'a mut [MaybeUninit<Option<FailureMode>>],
}

impl Row<'_> {
    /// Fills the row from its cells' brackets |cos phi| x + sin phi (`bracket(i)`), whether
    /// their V locks (`locks(i)`) and their failure mode (`mode(i)`): unbounded where the V
    /// locks or the bracket is <= 0, otherwise P_max / W = 1 / bracket. Compiled for AVX2
    /// where the processor has it (four cells a vector instead of two: the same IEEE
    /// operations, no fused multiply-add, so the same bits).
    #[inline(always)]
    fn fill(
        self,
        bracket: impl Fn(usize) -> f64,
        locks: impl Fn(usize) -> bool,
        mode: impl Fn(usize) -> FailureMode,
    ) {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the processor has AVX2, checked just above.
            return unsafe { self.fill_avx2(bracket, locks, mode) };
        }
        self.fill_in(bracket, locks, mode);
    }

    /// [`Row::fill`] compiled for AVX2.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn fill_avx2(
        self,
        bracket: impl Fn(usize) -> f64,
        locks: impl Fn(usize) -> bool,
        mode: impl Fn(usize) -> FailureMode,
    ) {
        self.fill_in(bracket, locks, mode);
    }

    /// [`Row::fill`]: one pass for P_max / W, then one for the modes, each a plain loop
    /// with selects, not branches, that vectorises.
    #[inline(always)]
    fn fill_in(
        self,
        bracket: impl Fn(usize) -> f64,
        locks: impl Fn(usize) -> bool,
        mode: impl Fn(usize) -> FailureMode,
    ) {
        let n = self.over_w.len().min(self.mode.len());
        let (over_w, modes) = (&mut self.over_w[..n], &mut self.mode[..n]);
        for (i, o) in over_w.iter_mut().enumerate() {
            let b = bracket(i);
            let bounded = !(locks(i) | (b <= 0.0));
            o.write(if bounded { 1.0 / b } else { f64::NAN });
        }
        // SAFETY: the loop above wrote every cell of `over_w`.
        let over_w = unsafe { &*(over_w as *const [MaybeUninit<f64>] as *const [f64]) };
        // A bounded cell's 1 / bracket is never NaN (the bracket is > 0 there).
        for (i, (m, o)) in modes.iter_mut().zip(over_w).enumerate() {
            m.write((!o.is_nan()).then_some(mode(i)));
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
        // A load straight up (cos phi zero but for the rounding of a right angle in
        // radians) is bounded at P_max = W, where it cancels the weight: beyond it the part
        // leaves both flanks, as the exact path says (`exact::capacity`).
        let up = cos.abs() <= f64::EPSILON && sin > 0.0;
        LoadDirection {
            sin,
            cos_abs: cos.abs(),
            mode: match (up, cos > 0.0) {
                (true, _) => FailureMode::PulledOut,
                (false, true) => FailureMode::RollsOverRight,
                (false, false) => FailureMode::RollsOverLeft,
            },
        }
    }
}

/// The Vs along a map's axis of included angles, as flat arrays for the row kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct Vs {
    /// x = tan(gamma / 2) of each V.
    tan_half_gamma: Vec<f64>,
    /// The flanks' friction of each V (each locks where its x < mu): compared in the row
    /// kernel as numbers, which vectorises where a row of flags would be widened lane by lane.
    mu: Vec<f64>,
}

impl Vs {
    /// The Vs of `vs`.
    pub fn new(vs: &[SymmetricV]) -> Self {
        Vs {
            tan_half_gamma: vs.iter().map(|v| v.tan_half_gamma).collect(),
            mu: vs.iter().map(|v| v.mu).collect(),
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
    /// `SymmetricV::capacity` of every V of `vs` under this direction, into `out` (as long
    /// as `vs`): a row of a map with the included angle on x, bit for bit the cells'.
    pub fn capacities(&self, vs: &Vs, out: Row) {
        let n = out.over_w.len();
        let (x, mu) = (&vs.tan_half_gamma[..n], &vs.mu[..n]);
        out.fill(
            |i| self.cos_abs * x[i] + self.sin,
            |i| x[i] < mu[i],
            |_| self.mode,
        );
    }
}

impl SymmetricV {
    /// `SymmetricV::capacity` of this V under every direction of `ds`, into `out` (as long
    /// as `ds`): a row of a map with the load direction on x, bit for bit the cells'.
    pub fn capacities(&self, ds: &LoadDirections, out: Row) {
        let n = out.over_w.len();
        let (cos_abs, sin, mode) = (&ds.cos_abs[..n], &ds.sin[..n], &ds.mode[..n]);
        let x = self.tan_half_gamma;
        out.fill(|i| cos_abs[i] * x + sin[i], |_| self.locks(), |i| mode[i]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form of a symmetric V, which the capacity maps use, says what the exact
    /// path says of a load straight up beyond the weight: the part leaves both flanks
    /// (`locator::tests::a_load_straight_up_beyond_the_weight_pulls_the_part_out`).
    #[test]
    fn a_load_straight_up_pulls_the_part_out() {
        for (phi, mode) in [
            (90.0, FailureMode::PulledOut),
            (-270.0, FailureMode::PulledOut),
            (89.0, FailureMode::RollsOverRight),
            (91.0, FailureMode::RollsOverLeft),
        ] {
            assert_eq!(LoadDirection::new(phi).mode, mode, "{phi}");
        }
        let v = SymmetricV::of(&LocatorParams::default());
        assert_eq!(
            v.capacity(&LoadDirection::new(90.0)),
            (1.0, Some(FailureMode::PulledOut))
        );
    }

    /// A row kernel's cells are [`SymmetricV::capacity`]'s bit for bit, along either axis, for
    /// rows shorter and longer than its lanes: Vs that lock and that do not, loads into the V
    /// (unbounded), along it and away from it, and a bracket of exactly 0.
    #[test]
    fn row_kernels_give_the_cells_bit_for_bit() {
        let base = LocatorParams::default().with_mu(0.4);
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
                    mu: 0.4,
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
            let bits = |(over_w, mode): (f64, Option<FailureMode>)| (over_w.to_bits(), mode);
            let (mut over_w, mut mode) = (Vec::new(), Vec::new());
            let mut check =
                |n: usize,
                 fill: &dyn Fn(Row),
                 want: &dyn Fn(usize) -> (f64, Option<FailureMode>)| {
                    over_w.resize(n, MaybeUninit::uninit());
                    mode.resize(n, MaybeUninit::uninit());
                    fill(Row {
                        over_w: &mut over_w,
                        mode: &mut mode,
                    });
                    for j in 0..n {
                        // SAFETY: `capacities` wrote every cell of the row.
                        let got = unsafe { (over_w[j].assume_init(), mode[j].assume_init()) };
                        assert_eq!(bits(got), bits(want(j)), "cell {j} of {n}");
                    }
                };
            for d in &ds {
                let fill = |row: Row| d.capacities(&Vs::new(&vs), row);
                check(vs.len(), &fill, &|j| vs[j].capacity(d));
            }
            for v in &vs {
                let fill = |row: Row| v.capacities(&LoadDirections::new(&ds), row);
                check(ds.len(), &fill, &|j| v.capacity(&ds[j]));
            }
        }
    }
}
