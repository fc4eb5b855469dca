//! The answer over a box of inputs: the interval of theta_jam and x_jam, which end of each input
//! makes the jam come earliest or latest, and where the status changes.
//!
//! The closed form answers exactly from the box's corners: theta_jam is monotone in every
//! uncertain input (the proof is in [`crate::statics`], "Monotone in every uncertain input"),
//! so its extremes over the box lie at the corner with every input at its theta-raising end
//! (the earliest jam, nearest the hinge) and the opposite corner (the latest). x_jam falls as
//! theta_jam grows up to the angle [`x_turn_rad`] (180 deg without a palm offset), so its
//! extremes are the corners' as well, or x at that angle when the interval of theta crosses it.
//! The status changes are found by bisection along each input (the others at their nominal
//! values) to 1e-9 of the range's width: the status is monotone along each input (each status
//! holds on one stretch), so a walk from the low end's status to the high end's bisects each
//! change in turn, with the cheap [`statics::status`] (no past-palm extras).
//!
//! The other models answer the box by sampling it: a grid of [`SAMPLES_PER_INPUT`] values per
//! input (at most [`MAX_GRID`] points), whose range of answers is reported, not a bound.

use serde::Serialize;

use super::UncertainSet;
use crate::error::Result;
use crate::models::{self, ModelSpec};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// Values per input when a model other than the closed form samples the box.
pub const SAMPLES_PER_INPUT: usize = 9;

/// Largest sampling grid: with more inputs each gets fewer values (at least 2, its ends).
pub const MAX_GRID: usize = 81;

/// Which end of an input's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum End {
    /// The low end.
    Low,
    /// The high end.
    High,
}

/// How the box was answered.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "method", rename_all = "snake_case")]
pub enum Method {
    /// Exactly, from the corners (closed form, monotone).
    Corners,
    /// By evaluating the model at `samples` points of a grid over the box.
    Sampled {
        /// How many points.
        samples: usize,
    },
}

/// The statuses along one input's range, the other inputs at their nominal values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputEnds {
    /// The setting as written (`mu`, `force_n`).
    pub name: &'static str,
    /// Low end of its box (a distribution's 0.1 % quantile).
    pub lo: f64,
    /// High end of its box (a distribution's 99.9 % quantile).
    pub hi: f64,
    /// The end at which the jam comes earliest (largest theta_jam, nearest the hinge).
    pub earliest_at: End,
    /// The status on each stretch of the range, in order from `lo`.
    pub segments: Vec<Segment>,
}

/// A stretch of one input's range with one status.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Segment {
    /// Where it starts.
    pub from: f64,
    /// Where it ends.
    pub to: f64,
    /// The status there.
    pub status: JamStatus,
}

/// One point of the box and the answer there.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Corner {
    /// Each input's value, in the order of the inputs.
    pub values: Vec<f64>,
    /// The status there.
    pub status: JamStatus,
    /// theta_jam in deg: for the closed form where the disc jams on a long enough palm (also
    /// when the status is beyond_reach), for a sampled model its own answer.
    pub theta_jam_deg: Option<f64>,
    /// x_jam in mm, as for `theta_jam_deg`.
    pub x_jam_mm: Option<f64>,
}

/// The answer over the box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RangeAnswer {
    /// Exact from the corners, or sampled.
    #[serde(flatten)]
    pub method: Method,
    /// Where the jam comes earliest (largest theta_jam, smallest x_jam).
    pub earliest: Corner,
    /// Where the jam comes latest (smallest theta_jam, largest x_jam).
    pub latest: Corner,
    /// The interval [min, max] of theta_jam in deg over the box (None where no point jams).
    pub theta_jam_deg: Option<[f64; 2]>,
    /// The interval [min, max] of x_jam in mm over the box.
    pub x_jam_mm: Option<[f64; 2]>,
    /// Each input's ends and statuses.
    pub inputs: Vec<InputEnds>,
    /// Every status met in the box, in the order of [`JamStatus::ALL`].
    pub statuses: Vec<JamStatus>,
}

/// The palm angle in rad up to which x_jam = r cot(theta/2) + h / sin(theta) falls as theta
/// grows: dx/dtheta = -(2 (r + h) cos^2(theta/2) - h) / sin^2(theta) < 0 while
/// cos^2(theta/2) > h / (2 (r + h)), which holds up to 90 deg at least and to 180 deg for h = 0.
pub fn x_turn_rad(p: &SceneParams) -> f64 {
    let (r, h) = (p.radius_mm, p.palm_offset_mm);
    2.0 * (h / (2.0 * (r + h))).sqrt().acos()
}

/// The closed form over the box of `set` around `p` (which holds the nominal values).
pub fn closed_form(p: &SceneParams, set: &UncertainSet) -> RangeAnswer {
    let ends: Vec<(f64, f64)> = set.inputs.iter().map(|i| i.value.ends()).collect();
    let nominal: Vec<f64> = set.inputs.iter().map(|i| i.value.nominal()).collect();
    let theta_at = |v: &[f64]| statics::theta_jam_rad(&set.apply(p, v));
    // The direction of each input: theta_jam at its ends, the others nominal. The proof says
    // the sign does not depend on the others.
    let earliest_at: Vec<End> = ends
        .iter()
        .enumerate()
        .map(|(i, &(lo, hi))| {
            let mut v = nominal.clone();
            v[i] = lo;
            let t_lo = theta_at(&v);
            v[i] = hi;
            if theta_at(&v) >= t_lo {
                End::High
            } else {
                End::Low
            }
        })
        .collect();
    let pick = |early: bool| -> Vec<f64> {
        ends.iter()
            .zip(&earliest_at)
            .map(|(&(lo, hi), e)| if (*e == End::High) == early { hi } else { lo })
            .collect()
    };
    let corner = |values: Vec<f64>| {
        let q = set.apply(p, &values);
        let theta = statics::theta_jam_rad(&q);
        let jam = (theta.is_finite() && theta > 0.0).then_some(theta);
        Corner {
            status: statics::status(&q),
            theta_jam_deg: jam.map(f64::to_degrees),
            x_jam_mm: jam.map(|t| q.disc_position_mm(t)),
            values,
        }
    };
    let earliest = corner(pick(true));
    let latest = corner(pick(false));
    let theta_jam_deg = match (latest.theta_jam_deg, earliest.theta_jam_deg) {
        (Some(a), Some(b)) => Some([a, b]),
        (Some(a), None) => Some([a, a]),
        _ => None,
    };
    let x_jam_mm = theta_jam_deg.map(|[a, b]| {
        let x_hi = p.disc_position_mm(a.to_radians());
        let turn = x_turn_rad(p);
        let x_lo = if b.to_radians() > turn {
            p.disc_position_mm(turn)
        } else {
            p.disc_position_mm(b.to_radians())
        };
        [x_lo.min(x_hi), x_hi.max(x_lo)]
    });
    let at_nominal = set.apply(p, &nominal);
    let inputs: Vec<InputEnds> = set
        .inputs
        .iter()
        .enumerate()
        .map(|(i, input)| InputEnds {
            name: input.name,
            lo: ends[i].0,
            hi: ends[i].1,
            earliest_at: earliest_at[i],
            segments: walk(ends[i], |x| {
                // The nominal scene with input i at x: no vector per evaluation.
                let mut q = at_nominal;
                for k in &input.keys {
                    q.set_real(k, x);
                }
                q
            }),
        })
        .collect();
    // Every status in the box lies on the diagonal from the latest corner to the earliest:
    // the status is decided by theta_jam (and the start, which no input changes), which is
    // monotone along it. With one input the diagonal is that input's range.
    let statuses = if let [only] = inputs.as_slice() {
        distinct(only.segments.iter().map(|s| s.status))
    } else {
        let (a, b) = (pick(false), pick(true));
        let diagonal = walk((0.0, 1.0), |t| {
            let v: Vec<f64> = a.iter().zip(&b).map(|(a, b)| a + t * (b - a)).collect();
            set.apply(p, &v)
        });
        distinct(diagonal.iter().map(|s| s.status))
    };
    RangeAnswer {
        method: Method::Corners,
        earliest,
        latest,
        theta_jam_deg,
        x_jam_mm,
        inputs,
        statuses,
    }
}

/// Any model over the box by sampling it: a grid of [`SAMPLES_PER_INPUT`] values per input (fewer
/// when the grid would pass [`MAX_GRID`]).
pub fn sampled(spec: &ModelSpec, p: &SceneParams, set: &UncertainSet) -> Result<RangeAnswer> {
    let k = set.inputs.len() as u32;
    let n = (2..=SAMPLES_PER_INPUT)
        .rev()
        .find(|n| n.pow(k) <= MAX_GRID)
        .unwrap_or(2);
    let ends: Vec<(f64, f64)> = set.inputs.iter().map(|i| i.value.ends()).collect();
    let value =
        |i: usize, j: usize| ends[i].0 + (ends[i].1 - ends[i].0) * j as f64 / (n - 1) as f64;
    let mut points = Vec::new();
    let mut grid_index = Vec::new();
    for flat in 0..n.pow(k) {
        let mut rest = flat;
        let index: Vec<usize> = (0..k as usize)
            .map(|_| {
                let j = rest % n;
                rest /= n;
                j
            })
            .collect();
        let v: Vec<f64> = index
            .iter()
            .enumerate()
            .map(|(i, &j)| value(i, j))
            .collect();
        let s = models::solve(spec, &set.apply(p, &v))?;
        points.push((v, s));
        grid_index.push(index);
    }
    let corner = |(v, s): &(Vec<f64>, models::Solution)| Corner {
        values: v.clone(),
        status: s.status,
        theta_jam_deg: s.theta_jam_deg,
        x_jam_mm: s.x_jam_mm,
    };
    let theta = |x: &&(Vec<f64>, models::Solution)| x.1.theta_jam_deg.unwrap_or(f64::NAN);
    let jams: Vec<&(Vec<f64>, models::Solution)> = points
        .iter()
        .filter(|x| x.1.theta_jam_deg.is_some())
        .collect();
    let by_theta = |a: &&&(Vec<f64>, models::Solution), b: &&&(Vec<f64>, models::Solution)| {
        theta(a).total_cmp(&theta(b))
    };
    let earliest = jams
        .iter()
        .max_by(by_theta)
        .map_or_else(|| corner(&points[0]), |x| corner(x));
    let latest = jams
        .iter()
        .min_by(by_theta)
        .map_or_else(|| corner(&points[0]), |x| corner(x));
    let span = |f: fn(&models::Solution) -> Option<f64>| {
        let vals: Vec<f64> = points.iter().filter_map(|x| f(&x.1)).collect();
        (!vals.is_empty()).then(|| {
            let lo = vals.iter().copied().fold(f64::INFINITY, f64::min);
            [lo, vals.iter().copied().fold(f64::NEG_INFINITY, f64::max)]
        })
    };
    let inputs = set
        .inputs
        .iter()
        .enumerate()
        .map(|(i, input)| {
            // The grid line along input i through the others' middle grid values.
            let along: Vec<(f64, JamStatus)> = points
                .iter()
                .zip(&grid_index)
                .filter(|(_, index)| {
                    index
                        .iter()
                        .enumerate()
                        .all(|(j, &g)| j == i || g == (n - 1) / 2)
                })
                .map(|((v, s), _)| (v[i], s.status))
                .collect();
            InputEnds {
                name: input.name,
                lo: ends[i].0,
                hi: ends[i].1,
                earliest_at: earliest_end(&earliest.values, &latest.values, i),
                segments: segments_of(&along),
            }
        })
        .collect();
    Ok(RangeAnswer {
        method: Method::Sampled {
            samples: points.len(),
        },
        theta_jam_deg: span(|s| s.theta_jam_deg),
        x_jam_mm: span(|s| s.x_jam_mm),
        statuses: distinct(points.iter().map(|x| x.1.status)),
        earliest,
        latest,
        inputs,
    })
}

/// Which end of input `i` the earliest sample sits nearer than the latest.
fn earliest_end(earliest: &[f64], latest: &[f64], i: usize) -> End {
    if earliest[i] >= latest[i] {
        End::High
    } else {
        End::Low
    }
}

/// The statuses along `[lo, hi]`, `at(x)` the scene at x, of a status that is monotone along
/// it (each status one stretch, in the order theta_jam passes its thresholds; see the module
/// docs): from the status at `lo`, each change found to 1e-9 of the width, until the status at
/// `hi` is reached. The status alone is asked ([`statics::status`]): `statics::solve` would run
/// its past-palm bisection at every point beyond the palm (issue 19: the range answer took
/// 1450x a point answer).
fn walk((lo, hi): (f64, f64), at: impl Fn(f64) -> SceneParams) -> Vec<Segment> {
    let status = |x: f64| statics::status(&at(x));
    let tol = 1e-9 * (hi - lo);
    let last = status(hi);
    let (mut from, mut here) = (lo, status(lo));
    let mut out = Vec::new();
    // Each status has one stretch, so there are fewer changes than statuses; the bound only
    // guards against a status that is not monotone after all.
    while here != last && out.len() < JamStatus::ALL.len() {
        let (to, next) = change_by_theta((from, hi), tol, here, last, &at).map_or_else(
            || bisect_change((from, hi), tol, here, status),
            |to| (to, last),
        );
        out.push(Segment {
            from,
            to,
            status: here,
        });
        (from, here) = (to, next);
    }
    out.push(Segment {
        from,
        to: hi,
        status: last,
    });
    out
}

/// Where the status changes from `here` straight to `next` on `[a, b]`, to `tol`: the point
/// where theta_jam crosses the angle of that change (the palm's reach angle
/// [`statics::reach_angle_rad`] between beyond_reach and jams, the start angle between jams and
/// jammed_at_start), by regula falsi with the Illinois step (a handful of closed-form angles
/// where bisection of the status took 30 statuses). The upper end of the final bracket, where
/// the status is `next`. None for any other change, or when the statuses either side of the
/// bracket are not `here` and `next` (the margin at the start can hold a disc before theta_jam
/// reaches the start angle), and the caller bisects the status instead. Hand-written: 20 lines
/// against a root-finding crate whose stopping rules do not return the bracket.
fn change_by_theta(
    (mut a, mut b): (f64, f64),
    tol: f64,
    here: JamStatus,
    next: JamStatus,
    at: impl Fn(f64) -> SceneParams,
) -> Option<f64> {
    use JamStatus::{BeyondReach, JammedAtStart, Jams};
    let q = at(a);
    let target = match (here, next) {
        (BeyondReach, Jams) | (Jams, BeyondReach) => statics::reach_angle_rad(&q),
        (Jams, JammedAtStart) | (JammedAtStart, Jams) => q.start_angle_deg.to_radians(),
        _ => return None,
    };
    let g = |x: f64| statics::theta_jam_rad(&at(x)) - target;
    let (mut ga, mut gb) = (g(a), g(b));
    if !(ga.is_finite() && gb.is_finite()) || (ga > 0.0) == (gb > 0.0) {
        return None;
    }
    // Which end stayed on the last step: halving its value when it stays again keeps both
    // ends closing in (Illinois).
    let mut kept_b = None;
    for _ in 0..200 {
        if b - a <= tol {
            break;
        }
        let m = (a * gb - b * ga) / (gb - ga);
        let m = if m > a && m < b { m } else { 0.5 * (a + b) };
        let gm = g(m);
        if gm != 0.0 && (gm > 0.0) == (ga > 0.0) {
            (a, ga) = (m, gm);
            if kept_b == Some(true) {
                gb *= 0.5;
            }
            kept_b = Some(true);
        } else {
            (b, gb) = (m, gm);
            if kept_b == Some(false) {
                ga *= 0.5;
            }
            kept_b = Some(false);
        }
    }
    let status = |x: f64| statics::status(&at(x));
    (b - a <= tol && status(a) == here && status(b) == next).then_some(b)
}

/// Where the status changes from `here` on `[a, b]` (status(a) = here != status(b)), by
/// bisection of the status to `tol`: the upper end of the final bracket and its status.
fn bisect_change(
    (mut a, mut b): (f64, f64),
    tol: f64,
    here: JamStatus,
    status: impl Fn(f64) -> JamStatus,
) -> (f64, JamStatus) {
    while b - a > tol {
        let m = 0.5 * (a + b);
        if status(m) == here { a = m } else { b = m }
    }
    (b, status(b))
}

/// Runs of equal status in `along` (sorted by value), each change placed half-way.
fn segments_of(along: &[(f64, JamStatus)]) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::new();
    for (j, &(x, s)) in along.iter().enumerate() {
        match out.last_mut() {
            Some(last) if last.status == s => last.to = x,
            _ => {
                let from = match j {
                    0 => x,
                    _ => 0.5 * (along[j - 1].0 + x),
                };
                if let Some(last) = out.last_mut() {
                    last.to = from;
                }
                out.push(Segment {
                    from,
                    to: x,
                    status: s,
                });
            }
        }
    }
    out
}

/// The distinct statuses, in the order of [`JamStatus::ALL`].
fn distinct(seen: impl Iterator<Item = JamStatus>) -> Vec<JamStatus> {
    let seen: Vec<JamStatus> = seen.collect();
    JamStatus::ALL
        .iter()
        .copied()
        .filter(|s| seen.contains(s))
        .collect()
}
