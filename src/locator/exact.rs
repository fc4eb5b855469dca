//! The exact path: held or not, and the holding capacity, by the support cone (a closed form)
//! or by vertex enumeration of the two-variable LP (free rotation with a rim load).

use serde::Serialize;

use super::params::{Flank, Frame, LocatorParams, Rotation, V2, cross};

/// How the part leaves the V when the load is not held.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FailureMode {
    /// Leaves the right flank and rolls (pivots) over the left one: free rotation only.
    RollsOverLeft,
    /// Leaves the left flank and rolls over the right one: free rotation only.
    RollsOverRight,
    /// Leaves the right flank and slides along the left one.
    SlidesAlongLeft,
    /// Leaves the left flank and slides along the right one.
    SlidesAlongRight,
    /// Slips on both flanks at once (free rotation: friction at both flanks at its limit).
    SlidesOnBoth,
    /// Leaves both flanks: the load pulls the disc out of the V.
    PulledOut,
}

impl FailureMode {
    /// The JSON spelling, e.g. `rolls_over_left`.
    pub fn as_str(self) -> &'static str {
        match self {
            FailureMode::RollsOverLeft => "rolls_over_left",
            FailureMode::RollsOverRight => "rolls_over_right",
            FailureMode::SlidesAlongLeft => "slides_along_left",
            FailureMode::SlidesAlongRight => "slides_along_right",
            FailureMode::SlidesOnBoth => "slides_on_both",
            FailureMode::PulledOut => "pulled_out",
        }
    }

    /// A phrase for a person, e.g. "rolls out over the left flank".
    pub fn describe(self) -> &'static str {
        match self {
            FailureMode::RollsOverLeft => "rolls out over the left flank",
            FailureMode::RollsOverRight => "rolls out over the right flank",
            FailureMode::SlidesAlongLeft => "slides out along the left flank",
            FailureMode::SlidesAlongRight => "slides out along the right flank",
            FailureMode::SlidesOnBoth => "slips on both flanks",
            FailureMode::PulledOut => "is pulled out of the V, off both flanks",
        }
    }

    fn rolls_over(f: Flank) -> Self {
        match f {
            Flank::Left => FailureMode::RollsOverLeft,
            Flank::Right => FailureMode::RollsOverRight,
        }
    }

    fn slides_along(f: Flank) -> Self {
        match f {
            Flank::Left => FailureMode::SlidesAlongLeft,
            Flank::Right => FailureMode::SlidesAlongRight,
        }
    }
}

/// The holding capacity in one load direction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Capacity {
    /// P_max in N: the largest load held; None when unbounded or when no load >= 0 is held.
    pub p_max_n: Option<f64>,
    /// P_max / W, dimensionless (None with `p_max_n`).
    pub p_max_over_w: Option<f64>,
    /// Every load in this direction is held (it pushes into the V, or the V self-locks).
    pub unbounded: bool,
    /// How the part leaves just beyond P_max (at every load when none is held); None when
    /// unbounded.
    pub failure_mode: Option<FailureMode>,
}

/// Relative tolerance of the exact tests, against the largest force in the problem: 1e4
/// machine epsilons, far below clarabel's 1e-8.
pub(crate) const TOL: f64 = 1e-12;

/// [`TOL`] times the sum of `terms` (forces in N), without overflow: near the top of the
/// float range the sum alone is inf, and an infinite tolerance held every load (a sideways load
/// of 9e307 N was `held`); there each term is scaled before it is added. Below it, the same
/// bits as `TOL * (a + b + ...)`.
pub(crate) fn tol_of<const N: usize>(terms: [f64; N]) -> f64 {
    let sum: f64 = terms.iter().sum();
    if sum.is_finite() {
        TOL * sum
    } else {
        terms.iter().map(|t| TOL * t).sum()
    }
}

/// The support the flanks must give at load P: force q0 + P q1 in N and moment / r equal to
/// P m1 in N (the negative of weight and load).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LoadLine {
    pub q0: V2,
    pub q1: V2,
    pub m1: f64,
}

impl LoadLine {
    pub(crate) fn new(p: &LocatorParams) -> Self {
        Self::at(p, p.load_angle_deg)
    }

    /// The support line of `p` for a load in direction `load_angle_deg` (deg) instead of
    /// p's own.
    pub(crate) fn at(p: &LocatorParams, load_angle_deg: f64) -> Self {
        let phi = load_angle_deg.to_radians();
        let (s, c) = phi.sin_cos();
        // A load at rim point psi has the moment r P sin(phi - psi) about the centre.
        let m = p
            .load_at_rim_deg
            .map_or(0.0, |psi| (phi - psi.to_radians()).sin());
        LoadLine {
            q0: [0.0, p.weight_n()],
            q1: [-c, -s],
            m1: -m,
        }
    }

    pub(crate) fn force_at(&self, load_n: f64) -> V2 {
        [
            self.q0[0] + load_n * self.q1[0],
            self.q0[1] + load_n * self.q1[1],
        ]
    }
}

/// Whether the V self-locks (wedges): a nonzero set of contact forces strictly inside both
/// cones balances no load. Free: tan(gamma/2) < min(mu1, mu2); blocked:
/// gamma < atan mu1 + atan mu2.
pub fn self_locking(p: &LocatorParams) -> bool {
    let gamma = p.included_angle_deg().to_radians();
    match p.rotation {
        Rotation::Free => (0.5 * gamma).tan() < p.mu_left.min(p.mu_right),
        Rotation::Blocked => gamma < p.mu_left.atan() + p.mu_right.atan(),
    }
}

/// A pointed cone of support forces in the plane: lo and hi are its clockwise-most and
/// counter-clockwise-most rays, each with the mode in which the part leaves past it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PlaneCone {
    lo: (V2, FailureMode),
    hi: (V2, FailureMode),
}

impl PlaneCone {
    /// The support cone of a V that does not self-lock, for blocked rotation (any load) or
    /// free rotation with a centre load; None otherwise.
    ///
    /// Blocked: cone{n_i +- mu_i u_i}. Free, centre load: the moment row makes both frictions
    /// T, so the cone is the image of {|T| <= mu1 N1, |T| <= mu2 N2}: cone{n1, n2,
    /// n1/mu1 + n2/mu2 +- (u1 + u2)} (the last two only when both mu > 0).
    pub(crate) fn of(p: &LocatorParams, f: &Frame) -> Option<Self> {
        if self_locking(p) {
            return None;
        }
        Self::of_unlocked(p, f)
    }

    /// [`PlaneCone::of`] for a V known not to self-lock.
    fn of_unlocked(p: &LocatorParams, f: &Frame) -> Option<Self> {
        if p.rotation == Rotation::Free && p.load_at_rim_deg.is_some() {
            return None;
        }
        let mu = p.mu();
        let [n1, n2] = f.n;
        let along = |a: V2, s: f64, d: V2| [a[0] + s * d[0], a[1] + s * d[1]];
        let gens: [(V2, FailureMode); 4] = match p.rotation {
            Rotation::Blocked => {
                let (l, r) = (
                    FailureMode::slides_along(Flank::Left),
                    FailureMode::slides_along(Flank::Right),
                );
                [
                    (along(n1, -mu[0], f.u[0]), l),
                    (along(n1, mu[0], f.u[0]), l),
                    (along(n2, -mu[1], f.u[1]), r),
                    (along(n2, mu[1], f.u[1]), r),
                ]
            }
            Rotation::Free => {
                let roll = |fl| (f.n[Flank::index(fl)], FailureMode::rolls_over(fl));
                if mu[0] > 0.0 && mu[1] > 0.0 {
                    let m = along([n1[0] / mu[0], n1[1] / mu[0]], 1.0 / mu[1], n2);
                    let u = [f.u[0][0] + f.u[1][0], f.u[0][1] + f.u[1][1]];
                    [
                        roll(Flank::Left),
                        roll(Flank::Right),
                        (along(m, -1.0, u), FailureMode::SlidesOnBoth),
                        (along(m, 1.0, u), FailureMode::SlidesOnBoth),
                    ]
                } else {
                    // Without friction on a flank both frictions vanish: the normals alone.
                    [
                        roll(Flank::Left),
                        roll(Flank::Right),
                        roll(Flank::Left),
                        roll(Flank::Right),
                    ]
                }
            }
        };
        // A cone that does not self-lock spans less than 180 deg, so "clockwise of" orders its
        // generators: g is clockwise of h iff g x h > 0. Just wider than the locking angle it
        // spans 180 deg less a rounding error, and two of its generators are opposite (with
        // unequal frictions, `n1 / mu1 + n2 / mu2 - (u1 + u2)` and n2): their cross product's
        // sign was rounding, and the cone came out as its complement (a 22.62 deg V with mu
        // 0.2 / 0.225 dropped its own weight). So the clockwise end is sought only among the
        // generators clockwise of n1 + n2, which lies inside the cone, and the other end on the
        // other side: no two generators compared are near opposite.
        let inside = [n1[0] + n2[0], n1[1] + n2[1]];
        let nonzero = gens.into_iter().filter(|(g, _)| g[0] != 0.0 || g[1] != 0.0);
        let (mut lo, mut hi) = (None::<(V2, FailureMode)>, None::<(V2, FailureMode)>);
        for g in nonzero {
            let side = cross(inside, g.0);
            if side <= 0.0 && lo.is_none_or(|l| cross(g.0, l.0) > 0.0) {
                lo = Some(g);
            }
            if side >= 0.0 && hi.is_none_or(|h| cross(h.0, g.0) > 0.0) {
                hi = Some(g);
            }
        }
        let unit = |(g, m): (V2, FailureMode)| {
            // sqrt, not hypot: the generators are of order one, and hypot costs a map's time.
            let l = (g[0] * g[0] + g[1] * g[1]).sqrt();
            ([g[0] / l, g[1] / l], m)
        };
        Some(PlaneCone {
            lo: unit(lo?),
            hi: unit(hi?),
        })
    }

    /// The two half-plane rows a + b P >= 0 (N) of the support q0 + P q1, with their modes.
    fn rows(&self, line: &LoadLine) -> [(f64, f64, FailureMode); 2] {
        let (lo, hi) = (self.lo.0, self.hi.0);
        [
            (cross(lo, line.q0), cross(lo, line.q1), self.lo.1),
            (cross(line.q0, hi), cross(line.q1, hi), self.hi.1),
        ]
    }

    /// Held at `load_n`, or how the part leaves.
    fn held_at(&self, line: &LoadLine, load_n: f64) -> Result<(), FailureMode> {
        let q = line.force_at(load_n);
        let tol = tol_of([q[0].abs(), q[1].abs(), load_n, line.q0[1]]);
        let [lo, hi] = self.rows(line).map(|(a, b, m)| (a + b * load_n >= -tol, m));
        match (lo, hi) {
            ((true, _), (true, _)) => Ok(()),
            ((false, _), (false, _)) => Err(FailureMode::PulledOut),
            ((false, m), _) | (_, (false, m)) => Err(m),
        }
    }

    fn capacity(&self, line: &LoadLine) -> Capacity {
        let rows = self.rows(line).map(|(a, b, m)| ([b, a], m));
        interval_capacity(&rows, line.q0[1])
    }
}

/// Capacity from rows c\[0\] P + c\[1\] >= 0 in one unknown P >= 0 (N); `weight_n` scales the
/// tolerance and P_max / W.
fn interval_capacity(rows: &[([f64; 2], FailureMode)], weight_n: f64) -> Capacity {
    let tol = TOL * weight_n;
    let (mut lower, mut upper) = (0.0_f64, None::<(f64, FailureMode)>);
    let mut broken = None;
    for &([b, a], m) in rows {
        if b.abs() <= TOL {
            if a < -tol {
                broken = Some(m);
            }
        } else if b > 0.0 {
            lower = lower.max(-a / b);
        } else if upper.is_none_or(|(u, _)| -a / b < u) {
            upper = Some((-a / b, m));
        }
    }
    let none_held = |m| Capacity {
        p_max_n: None,
        p_max_over_w: None,
        unbounded: false,
        failure_mode: Some(m),
    };
    if let Some(m) = broken {
        return none_held(m);
    }
    match upper {
        None => Capacity {
            p_max_n: None,
            p_max_over_w: None,
            unbounded: true,
            failure_mode: None,
        },
        Some((u, m)) if u < lower - tol.max(TOL * u.abs()) || u < -tol => none_held(m),
        Some((u, m)) => {
            let u = u.max(0.0);
            Capacity {
                p_max_n: Some(u),
                p_max_over_w: Some(u / weight_n),
                unbounded: false,
                failure_mode: Some(m),
            }
        }
    }
}

/// What a row of the free LP bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Row {
    /// N_i >= 0.
    Normal(Flank),
    /// mu_i N_i -+ T_i >= 0.
    Edge(Flank),
    /// P >= 0.
    Load,
}

/// The mode in which the part leaves when rows `a` and `b` bind (free rotation).
fn mode_of(a: Row, b: Row) -> FailureMode {
    use Row::{Edge, Load, Normal};
    match (a, b) {
        (Normal(i) | Edge(i), Normal(j) | Edge(j)) if i == j => FailureMode::rolls_over(i.other()),
        (Edge(_), Edge(_)) => FailureMode::SlidesOnBoth,
        (Normal(_), Normal(_)) => FailureMode::PulledOut,
        (Normal(_), Edge(j)) | (Edge(j), Normal(_)) => FailureMode::slides_along(j),
        (Load, r) | (r, Load) => match r {
            Normal(i) => FailureMode::rolls_over(i.other()),
            Edge(i) => FailureMode::slides_along(i),
            Load => FailureMode::PulledOut,
        },
    }
}

/// An affine expression c\[0\] t + c\[1\] P + c\[2\] in the free LP's unknowns: t = T_1 (N) and
/// the load P (N).
type Affine = [f64; 3];

/// The rows of free rotation: with T_2 = T_1 + m (the moment row) and N from the force rows,
/// N_i >= 0 and |T_i| <= mu_i N_i, plus P >= 0.
fn free_rows(p: &LocatorParams, f: &Frame, line: &LoadLine) -> [(Affine, Row); 7] {
    let t1: Affine = [1.0, 0.0, 0.0];
    let t2: Affine = [1.0, line.m1, 0.0];
    // R = Q_F - T1 u1 - T2 u2, per coefficient; then N = split(R) coefficient by coefficient.
    let q = [[0.0, line.q1[0], line.q0[0]], [0.0, line.q1[1], line.q0[1]]];
    let r: [Affine; 2] = std::array::from_fn(|d| {
        std::array::from_fn(|k| q[d][k] - t1[k] * f.u[0][d] - t2[k] * f.u[1][d])
    });
    let mut n = [[0.0; 3]; 2];
    for k in 0..3 {
        let s = f.normal_split([r[0][k], r[1][k]]);
        n[0][k] = s[0];
        n[1][k] = s[1];
    }
    let mu = p.mu();
    let edge = |i: usize, t: Affine, s: f64| -> Affine {
        std::array::from_fn(|k| mu[i] * n[i][k] + s * t[k])
    };
    use Flank::{Left, Right};
    [
        (n[0], Row::Normal(Left)),
        (n[1], Row::Normal(Right)),
        (edge(0, t1, -1.0), Row::Edge(Left)),
        (edge(0, t1, 1.0), Row::Edge(Left)),
        (edge(1, t2, -1.0), Row::Edge(Right)),
        (edge(1, t2, 1.0), Row::Edge(Right)),
        ([0.0, 1.0, 0.0], Row::Load),
    ]
}

/// Held at `load_n` under free rotation (any load point): the interval of t left by the rows,
/// to `tol` in N.
fn free_held_at(rows: &[(Affine, Row)], load_n: f64, tol: f64) -> Result<(), FailureMode> {
    let (mut lo, mut hi) = ((f64::NEG_INFINITY, Row::Load), (f64::INFINITY, Row::Load));
    for &(c, row) in rows {
        let a = c[1] * load_n + c[2];
        if c[0].abs() <= TOL {
            if a < -tol {
                return Err(mode_of(row, row));
            }
        } else if c[0] > 0.0 {
            if -a / c[0] > lo.0 {
                lo = (-a / c[0], row);
            }
        } else if -a / c[0] < hi.0 {
            hi = (-a / c[0], row);
        }
    }
    if lo.0 <= hi.0 + tol {
        Ok(())
    } else {
        Err(mode_of(lo.1, hi.1))
    }
}

/// P_max under free rotation by vertex enumeration of the LP max P over (t, P).
fn free_capacity(rows: &[(Affine, Row)], weight_n: f64) -> Capacity {
    // Scale of every row's values: forces of order W + P.
    let feasible = |t: f64, pl: f64| {
        let tol = tol_of([weight_n, pl.abs(), t.abs()]);
        rows.iter()
            .all(|(c, _)| c[0] * t + c[1] * pl + c[2] >= -tol)
    };
    // A recession direction with dP > 0 lies along some row's line or is (0, 1).
    let recedes =
        |dt: f64, dp: f64| dp > TOL && rows.iter().all(|(c, _)| c[0] * dt + c[1] * dp >= -TOL);
    let mut best: Option<(f64, Row, Row)> = None;
    for (i, (a, ra)) in rows.iter().enumerate() {
        for (b, rb) in &rows[i + 1..] {
            let det = a[0] * b[1] - a[1] * b[0];
            if det.abs() <= TOL * (a[0].hypot(a[1]) * b[0].hypot(b[1])) {
                continue;
            }
            let t = (-a[2] * b[1] + a[1] * b[2]) / det;
            let pl = (-a[0] * b[2] + a[2] * b[0]) / det;
            if feasible(t, pl) && best.is_none_or(|(p, _, _)| pl > p) {
                best = Some((pl, *ra, *rb));
            }
        }
    }
    let Some((pl, ra, rb)) = best else {
        // No vertex is feasible: the weight alone is not held, and neither is any load.
        let m = free_held_at(rows, 0.0, tol_of([weight_n]))
            .err()
            .unwrap_or(FailureMode::PulledOut);
        return Capacity {
            p_max_n: None,
            p_max_over_w: None,
            unbounded: false,
            failure_mode: Some(m),
        };
    };
    let along = rows
        .iter()
        .flat_map(|(c, _)| [[c[1], -c[0]], [-c[1], c[0]]])
        .chain([[0.0, 1.0]]);
    if along.into_iter().any(|[dt, dp]| recedes(dt, dp)) {
        return Capacity {
            p_max_n: None,
            p_max_over_w: None,
            unbounded: true,
            failure_mode: None,
        };
    }
    let pl = pl.max(0.0);
    Capacity {
        p_max_n: Some(pl),
        p_max_over_w: Some(pl / weight_n),
        unbounded: false,
        failure_mode: Some(mode_of(ra, rb)),
    }
}

/// Whether the V holds the part at load `load_n` N (of the direction and point of `p`), or
/// how it leaves. A self-locking V holds every load.
pub fn held_at(p: &LocatorParams, load_n: f64) -> Result<(), FailureMode> {
    PreparedV::new(p).held_at(load_n, p.load_angle_deg)
}

/// A V prepared to test many loads: whether it self-locks, its frame and its support cone,
/// none of which depend on the load, computed once.
///
/// Why: a robust design tests each V at some 80 loads of a box (`robust::holds_sector`), and
/// recomputing the V's sin, cos and tan per load was most of the `vlocator-robust` chart's
/// time, as profiled. [`held_at`] goes through it, so both give the same bits.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PreparedV<'a> {
    p: &'a LocatorParams,
    /// The frame and the cone of a load at the centre (the load's own under blocked
    /// rotation, where a joint carries the moment); None when it self-locks.
    shape: Option<(Frame, Option<PlaneCone>)>,
}

impl<'a> PreparedV<'a> {
    pub(crate) fn new(p: &'a LocatorParams) -> Self {
        let shape = (!self_locking(p)).then(|| {
            let f = p.frame();
            let centre = LocatorParams {
                load_at_rim_deg: None,
                ..*p
            };
            (f, PlaneCone::of_unlocked(&centre, &f))
        });
        PreparedV { p, shape }
    }

    /// [`held_at`] for the load `load_n` N in direction `load_angle_deg` (deg), p's load
    /// point kept.
    pub(crate) fn held_at(&self, load_n: f64, load_angle_deg: f64) -> Result<(), FailureMode> {
        self.held_on(&LoadLine::at(self.p, load_angle_deg), load_n)
    }

    /// [`Self::held_at`] on a support line made by [`LoadLine::at`] for a V of the same weight
    /// and load point (lines shared by many Vs are made once: `robust::Sector`,
    /// `optimum::rho_hold`).
    pub(crate) fn held_on(&self, line: &LoadLine, load_n: f64) -> Result<(), FailureMode> {
        let Some((f, cone)) = &self.shape else {
            return Ok(());
        };
        // A rim load turns a free disc only where it has a moment about the centre: at the rim
        // point on its own line (psi = phi, or the far side, whose sin(pi) is 1.2e-16) it acts
        // as at the centre. The free rows' tie-breaks there were rounding: a load straight up
        // at the top of the disc beyond its weight "rolled out over the right flank".
        let turns = self.p.rotation == Rotation::Free && line.m1.abs() > f64::EPSILON;
        match cone {
            Some(cone) if !turns => cone.held_at(line, load_n),
            _ => free_held_at(
                &free_rows(self.p, f, line),
                load_n,
                tol_of([self.p.weight_n(), load_n]),
            ),
        }
    }
}

/// The holding capacity P_max in the load direction (and point) of `p`: the largest P for
/// which an equilibrium exists.
pub fn capacity(p: &LocatorParams) -> Capacity {
    if self_locking(p) {
        return Capacity {
            p_max_n: None,
            p_max_over_w: None,
            unbounded: true,
            failure_mode: None,
        };
    }
    let f = p.frame();
    let line = LoadLine::new(p);
    let c = match PlaneCone::of(p, &f) {
        Some(cone) => cone.capacity(&line),
        None => free_capacity(&free_rows(p, &f, &line), p.weight_n()),
    };
    match c.p_max_n {
        Some(u) if cancels_weight(&line, u, p.weight_n()) => Capacity {
            failure_mode: Some(FailureMode::PulledOut),
            ..c
        },
        _ => c,
    }
}

/// Whether the load `load_n` N of `line` cancels the weight: no force and no moment left
/// for the flanks to carry, to [`TOL`] of the forces.
///
/// At a P_max where it does, the load is straight up and P_max = W (at the centre, or at the
/// rim point straight above it): beyond it the support the part needs points straight down,
/// out of every flank's reach at once, so it lifts off both flanks. Which row bound P_max
/// there was rounding (cos 90 deg is 6.1e-17 in radians): `vlocator --load 5 --load-angle
/// 90` said the part "rolls out over the left flank" beyond P_max = W.
fn cancels_weight(line: &LoadLine, load_n: f64, weight_n: f64) -> bool {
    let q = line.force_at(load_n);
    let tol = tol_of([weight_n, load_n]);
    q[0].abs() <= tol && q[1].abs() <= tol && (line.m1 * load_n).abs() <= tol
}

/// The capacity under free rotation by vertex enumeration of the LP, whatever the load point
/// (the closed form's check, in the tests).
#[cfg(test)]
pub fn capacity_by_enumeration(p: &LocatorParams) -> Capacity {
    let f = p.frame();
    let mut q = *p;
    q.rotation = Rotation::Free;
    free_capacity(&free_rows(&q, &f, &LoadLine::new(&q)), q.weight_n())
}
