//! The answer over a box of inputs: the interval of theta_jam and x_jam, where each of its ends
//! is reached, and where the status changes.
//!
//! ## What the interval promises
//!
//! Every point of the box answers inside it, and each end is a value some point answers (or
//! the limit of such values): the interval of theta_jam and x_jam over the points that answer
//! one, those that jam on the palm or are held at the start (a held disc answers the start
//! angle). A point beyond the palm's reach, too weak to be moved or never jamming answers none,
//! and the statuses say where those lie. The same meaning for every model: the closed form
//! computes the interval exactly from the box's corners, the other models report the range of
//! their samples' answers.
//!
//! ## Why the closed form's interval is exact
//!
//! Write theta* for the closed form's raw angle alpha_g + alpha_p + asin(m g sin(alpha_g) / F)
//! (+inf where m g sin(alpha_g) >= F), S for the start angle and rho for the palm's reach angle
//! ([`SceneParams::reach_angle`], the contact at the palm's end). Neither S nor rho depends on
//! an input that takes a range, and S <= 90 deg wherever the closed form answers (above it the
//! port answers `outside_model` at every point of the box). A point answers ([`statics`]):
//!
//! | theta*                      | status            | theta_jam |
//! |-----------------------------|-------------------|-----------|
//! | 0 (no friction at all)      | never_jams        | none      |
//! | in (0, rho)                 | beyond_reach      | none      |
//! | in [rho, S)                 | jams              | theta*    |
//! | in [S, inf)                 | jammed_at_start   | S         |
//! | inf, alpha_g + alpha_p < 90 | too_weak          | none      |
//! | inf, alpha_g + alpha_p >= 90| jammed_at_start   | S         |
//!
//! (The margin at the start, which the statics check as well, adds nothing for S <= 90 deg:
//! with psi = S - alpha_g - alpha_p <= 90 deg, sin(psi) <= m g sin(alpha_g) / F iff psi <=
//! asin(m g sin(alpha_g) / F), i.e. theta* >= S.) So the answer is min(theta*, S) wherever
//! theta* >= rho: a non-decreasing function of theta*, clamped at the start.
//!
//! theta* is monotone in every input (the proof is in [`crate::statics`], "Monotone in every
//! uncertain input"): over the box it is least at the corner with every input at its
//! theta-lowering end (the latest jam, [`End`]) and greatest at the opposite corner (the
//! earliest). The points where it is finite form a down-set of the box (m g sin(alpha_g) / F
//! grows towards the earliest corner), so they are connected, and theta* is continuous there:
//! it takes every value from the latest corner's up to its supremum. Hence, with the two
//! corners' answers:
//!
//! - **The highest theta_jam** (the earliest jam, smallest x_jam) is the earliest corner's
//!   answer where it jams or is held. Where that corner is too weak but the latest is not, it is
//!   S: approaching the push that just moves the disc, asin(...) tends to 90 deg, so theta*
//!   tends to alpha_g + alpha_p + 90 deg > 90 deg >= S (alpha_g > 0 wherever a push is too
//!   weak), and the points there are held at the start ([`Reached::HeldAtStart`]). Where the
//!   earliest corner jams beyond the palm or never jams, theta* < rho at every point and no
//!   point answers; likewise where every point is too weak.
//! - **The lowest theta_jam** (the latest jam, largest x_jam) is the latest corner's answer
//!   where it jams or is held. Where its jam lies beyond the palm (or it never jams) while the
//!   highest answer exists, theta* passes rho on its way up, so the jam at the palm's end, rho,
//!   is answered ([`Reached::PalmEnd`]). Where the latest corner is too weak, every point is
//!   too weak or held at the start by a locked wedge: S.
//! - **x_jam** = r cot(theta/2) + h / sin(theta) falls as theta grows on (0, 90 deg] (dx/dtheta
//!   < 0 there, the statics docs), so its interval is x at the two ends of theta's, swapped.
//!
//! `hull` is this rule on two corners' answers; the sweep band calls it at each swept value.
//! `tests/range_promise.rs` checks it on random boxes against a dense grid of point answers.
//!
//! ## The status changes
//!
//! Found along each input (the others at their nominal values) to 1e-9 of the range's width:
//! the status is monotone along each input (each status holds on one stretch), so a walk goes
//! from the low end's status to the high end's, change by change. A change between jams and
//! beyond_reach (or jammed_at_start) lies where theta_jam crosses the palm's reach angle (or
//! the start angle): Eq. 2 solved for the input gives it in closed form for the push, the mass
//! and the palm's friction, by Newton's method in the friction angle for the ground's friction
//! (`invert`, derived in its docs), and the statuses a hair either side of it confirm it
//! (regula falsi on theta_jam, then bisection of the status, where they do not); other changes
//! are bisected with the cheap `statics::status` (no past-palm extras), at most 30 halvings
//! and never below the spacing of floats (a range 1e-8 wide at 3.6 is 45 floats wide). So a
//! range answer over one input costs its two corners, a root and two statuses per change
//! (`cargo bench --bench uncertain` prints it against a point answer).
//!
//! The other models answer the box by sampling it: a grid of `SAMPLES_PER_INPUT` values per
//! input (at most `MAX_GRID` points), whose range of answers is reported, not a bound.

use serde::Serialize;

use super::UncertainSet;
use crate::error::Result;
use crate::models::{self, ModelKind, ModelSpec};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// Values per input when a model other than the closed form samples the box.
pub(crate) const SAMPLES_PER_INPUT: usize = 9;

/// Largest sampling grid: with more inputs each gets fewer values (at least 2, its ends).
pub(crate) const MAX_GRID: usize = 81;

/// Halvings of a bisection of the status along an input: 2^-30 < 1e-9 of the range's width.
const HALVINGS: usize = 30;

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
pub enum RangeMethod {
    /// Exactly, from the corners (closed form, monotone).
    Corners,
    /// By evaluating the model at `samples` points of a grid over the box.
    Sampled {
        /// How many points.
        samples: usize,
    },
}

/// How an end of the interval is reached (module docs, "Why the closed form's interval is
/// exact").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Reached {
    /// By the corner given beside it (for a sampled model, the sample): its own answer.
    Corner,
    /// The corner is too weak to move the disc; the points where the push just moves it are
    /// held at the start angle.
    HeldAtStart,
    /// The corner's jam lies past the palm's end (or it never jams); the points between jam
    /// exactly at the palm's end, at the reach angle.
    PalmEnd,
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

/// One point of the box and the model's answer there, as the port gives it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Corner {
    /// Each input's value, in the order of the inputs.
    pub values: Vec<f64>,
    /// The status there.
    pub status: JamStatus,
    /// theta_jam in deg where the disc jams on the palm or is held at the start (the start
    /// angle); None otherwise.
    pub theta_jam_deg: Option<f64>,
    /// x_jam in mm, as for `theta_jam_deg`.
    pub x_jam_mm: Option<f64>,
    /// Where a corner whose jam lies past the palm's end (`beyond_reach`) would jam on a long
    /// enough palm, the palm length that reaches it and the friction factor that brings it
    /// onto this palm (the closed form's, as `solve` gives it for the point); None otherwise.
    pub past_palm: Option<statics::PastPalm>,
}

/// The answer over the box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RangeAnswer {
    /// Exact from the corners, or sampled.
    #[serde(flatten)]
    pub method: RangeMethod,
    /// The corner with every input at its theta-raising end (sampled: the sample with the
    /// largest theta_jam, or the first sample when none answers).
    pub earliest: Corner,
    /// The opposite corner (sampled: the sample with the smallest theta_jam).
    pub latest: Corner,
    /// The interval [min, max] of theta_jam in deg over the points that jam on the palm or are
    /// held at the start (None where no point does).
    pub theta_jam_deg: Option<[f64; 2]>,
    /// The interval [min, max] of x_jam in mm over the same points.
    pub x_jam_mm: Option<[f64; 2]>,
    /// How the interval's ends are reached: [the lowest theta_jam (at `latest`), the highest
    /// (at `earliest`)]; None with the interval.
    pub reached: Option<[Reached; 2]>,
    /// Each input's ends and statuses.
    pub inputs: Vec<InputEnds>,
    /// Every status met in the box, in the order of [`JamStatus::ALL`].
    pub statuses: Vec<JamStatus>,
}

/// The interval of a box from the closed form's answers at its two extreme corners (`hull`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub(crate) struct Hull {
    /// [min, max] of theta_jam in deg over the box's answering points.
    pub theta_jam_deg: [f64; 2],
    /// [min, max] of x_jam in mm over the same points.
    pub x_jam_mm: [f64; 2],
    /// How [the lowest theta_jam, the highest] are reached.
    pub reached: [Reached; 2],
}

/// A point's answer as [`hull`] reads it: its status and, where it answers one, (theta_jam in
/// deg, x_jam in mm).
pub(crate) type PointAnswer = (JamStatus, Option<(f64, f64)>);

/// The interval of theta_jam and x_jam over a box from the closed form's answers at its
/// earliest-jam and latest-jam corners (every input at its theta-raising end, and at the
/// other), by the rule derived in the module docs: a corner that jams or is held answers its
/// own end; a too weak earliest corner gives the start angle, a latest corner beyond the palm
/// or never jamming the palm's end, a too weak latest corner the start angle. `p` is the
/// scene at either corner (the start angle, the radius, the palm offset and its length, which
/// no uncertain input moves). None where no point of the box answers.
pub(crate) fn hull(p: &SceneParams, earliest: PointAnswer, latest: PointAnswer) -> Option<Hull> {
    use JamStatus::{BeyondReach, JammedAtStart, Jams, NeverJams, TooWeak};
    let start = p.start_angle_deg.to_radians();
    let held = (
        p.start_angle_deg,
        p.disc_position_mm(start),
        Reached::HeldAtStart,
    );
    let hi = match earliest {
        (Jams | JammedAtStart, Some((t, x))) => (t, x, Reached::Corner),
        (TooWeak, _) if latest.0 != TooWeak => held,
        _ => return None,
    };
    let lo = match latest {
        (Jams | JammedAtStart, Some((t, x))) => (t, x, Reached::Corner),
        (BeyondReach | NeverJams, _) => {
            let reach = p.reach_angle();
            (
                reach.to_degrees(),
                p.disc_position_mm(reach),
                Reached::PalmEnd,
            )
        }
        (TooWeak, _) => held,
        _ => return None,
    };
    Some(Hull {
        theta_jam_deg: [lo.0, hi.0],
        x_jam_mm: [hi.1, lo.1],
        reached: [lo.2, hi.2],
    })
}

/// The box's two extreme corners and its interval: the part of a [`RangeAnswer`] without the
/// status changes along each input.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct BoxEnds {
    /// Every input at its theta-raising end (the earliest jam), and the answer there.
    pub earliest: Corner,
    /// The opposite corner (the latest jam).
    pub latest: Corner,
    /// The interval, None where no point of the box jams on the palm or is held at the start.
    pub hull: Option<Hull>,
    /// Each input's (low end, high end, the end that raises theta_jam), in the set's order.
    pub inputs: Vec<(f64, f64, End)>,
}

/// The closed form over the box of `set` around `p` (which holds the nominal values).
pub fn closed_form(p: &SceneParams, set: &UncertainSet) -> Result<RangeAnswer> {
    let BoxEnds {
        earliest,
        latest,
        hull,
        inputs: per_input,
    } = ends(p, set)?;
    // A start above 90 deg is outside the model at every point of the box (no input moves it).
    let outside = models::outside(ModelKind::Statics, p).is_some();
    let inputs: Vec<InputEnds> = set
        .inputs
        .iter()
        .zip(&per_input)
        .map(|(input, &(lo, hi, earliest_at))| {
            // With one input its ends are the corners, whose statuses are known.
            let known = (set.inputs.len() == 1).then_some(match earliest_at {
                End::High => (latest.status, earliest.status),
                End::Low => (earliest.status, latest.status),
            });
            let segments = match outside {
                true => vec![Segment {
                    from: lo,
                    to: hi,
                    status: JamStatus::OutsideModel,
                }],
                false => walk((lo, hi), known, Some(&input.keys), |x| {
                    with_input(p, &input.keys, x)
                }),
            };
            InputEnds {
                name: input.name,
                lo,
                hi,
                earliest_at,
                segments,
            }
        })
        .collect();
    // Every status in the box lies on the diagonal from the latest corner to the earliest:
    // the status is decided by theta_jam (and the start, which no input changes), which is
    // monotone along it. With one input the diagonal is that input's range.
    let statuses = match inputs.as_slice() {
        _ if outside => vec![JamStatus::OutsideModel],
        [only] => distinct(only.segments.iter().map(|s| s.status)),
        _ => {
            let (a, b) = (&latest.values, &earliest.values);
            let known = Some((latest.status, earliest.status));
            let diagonal = walk((0.0, 1.0), known, None, |t| {
                let v: Vec<f64> = a.iter().zip(b).map(|(a, b)| a + t * (b - a)).collect();
                set.apply(p, &v)
            });
            distinct(diagonal.iter().map(|s| s.status))
        }
    };
    Ok(RangeAnswer {
        method: RangeMethod::Corners,
        theta_jam_deg: hull.map(|h| h.theta_jam_deg),
        x_jam_mm: hull.map(|h| h.x_jam_mm),
        reached: hull.map(|h| h.reached),
        earliest,
        latest,
        inputs,
        statuses,
    })
}

/// The box's two extreme corners, answered through the port, and its interval (`hull`):
/// two point answers' work, without the status changes that [`closed_form`] adds.
pub(crate) fn ends(p: &SceneParams, set: &UncertainSet) -> Result<BoxEnds> {
    let per_input: Vec<(f64, f64, End)> = set
        .inputs
        .iter()
        .map(|input| {
            let (lo, hi) = input.value.ends();
            let earliest_at = known_earliest_end(&input.keys).unwrap_or_else(|| {
                // A setting the proof does not cover: the direction by theta_jam at its ends.
                let at = |x: f64| statics::theta_jam_rad(&with_input(p, &input.keys, x));
                if at(hi) >= at(lo) {
                    End::High
                } else {
                    End::Low
                }
            });
            (lo, hi, earliest_at)
        })
        .collect();
    let pick = |early: bool| -> Vec<f64> {
        per_input
            .iter()
            .map(|&(lo, hi, e)| if (e == End::High) == early { hi } else { lo })
            .collect()
    };
    let corner = |values: Vec<f64>| -> Result<Corner> {
        let s = models::solve(&ModelSpec::Statics, &set.apply(p, &values))?;
        Ok(Corner {
            values,
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
            past_palm: s.past_palm(),
        })
    };
    let earliest = corner(pick(true))?;
    let latest = corner(pick(false))?;
    let answer = |c: &Corner| (c.status, c.theta_jam_deg.zip(c.x_jam_mm));
    Ok(BoxEnds {
        hull: hull(p, answer(&earliest), answer(&latest)),
        earliest,
        latest,
        inputs: per_input,
    })
}

/// `p` with every field in `keys` set to `x`.
fn with_input(p: &SceneParams, keys: &[&'static str], x: f64) -> SceneParams {
    let mut q = *p;
    for k in keys {
        q.set_real(k, x);
    }
    q
}

/// The end of an input (setting `keys`) that raises theta_jam, from the proof in
/// [`crate::statics`] ("Monotone in every uncertain input"): the high end of a friction or the
/// mass, the low end of the push (where the push or the mass leaves theta_jam alone, without
/// ground friction or weight, either end is both). None for a key the proof does not cover.
fn known_earliest_end(keys: &[&'static str]) -> Option<End> {
    let raises = |k: &&str| matches!(*k, "mu_ground" | "mu_palm" | "mass_kg");
    if keys.iter().all(raises) {
        Some(End::High)
    } else if keys == ["force_n"] {
        Some(End::Low)
    } else {
        None
    }
}

/// The value of the input setting `keys` at which theta_jam of `p` equals `target` (rad): in
/// closed form for the push, the mass or the palm's friction alone (Eq. 2 solved for it), by
/// Newton's method in the friction angle for the ground's friction, alone or with the palm's
/// (asin(k sin alpha_g) has no inverse in closed form beside alpha_g). None for other keys, or
/// where theta_jam does not reach `target`.
///
/// With alpha_g = atan(mu_g), alpha_p = atan(mu_p) and k = m g / F, Eq. 2 reads
/// theta = alpha_g + alpha_p + asin(k sin alpha_g), so
/// - F = m g sin(alpha_g) / sin(theta - alpha_g - alpha_p), m = F sin(theta - alpha_g -
///   alpha_p) / (g sin alpha_g), both for theta - alpha_g - alpha_p in (0, 90 deg);
/// - mu_p = tan(theta - alpha_g - asin(k sin alpha_g));
/// - for mu_g (c = 1) or mu_g = mu_p (c = 2) the root a of f(a) = c a + asin(k sin a) + b -
///   theta (b = alpha_p or 0) on [0, 90 deg): f' = c + k cos a / sqrt(1 - k^2 sin^2 a) > 0, so
///   f is increasing and Newton's steps, kept inside the bracket, converge.
fn invert(p: &SceneParams, keys: &[&'static str], target: f64, bracket: (f64, f64)) -> Option<f64> {
    use std::f64::consts::FRAC_PI_2;
    let (ag, ap) = (|| p.alpha_ground(), || p.alpha_palm());
    let w = p.weight_n();
    let in_quadrant = |d: f64| (d > 0.0 && d < FRAC_PI_2).then_some(d);
    let x = match keys {
        ["force_n"] => in_quadrant(target - ag() - ap()).map(|d| w * ag().sin() / d.sin()),
        ["mass_kg"] => in_quadrant(target - ag() - ap())
            .filter(|_| p.mu_ground > 0.0)
            .map(|d| p.force_n * d.sin() / (p.gravity_m_s2 * ag().sin())),
        ["mu_palm"] => {
            let ratio = w * ag().sin() / p.force_n;
            (ratio < 1.0)
                .then(|| target - ag() - ratio.asin())
                .and_then(|a| (0.0..FRAC_PI_2).contains(&a).then(|| a.tan()))
        }
        ["mu_ground"] => newton_angle(1.0, ap(), w / p.force_n, target, bracket),
        ["mu_ground", "mu_palm"] | ["mu_palm", "mu_ground"] => {
            newton_angle(2.0, 0.0, w / p.force_n, target, bracket)
        }
        _ => None,
    }?;
    x.is_finite().then_some(x)
}

/// The friction mu = tan(a) in `bracket` (frictions) where c a + asin(k sin a) + b = target, by
/// Newton's method in a, kept inside [0, 90 deg) (bisection where a step would leave it):
/// three or four steps from the first guess, which solves the linear part with asin's argument
/// taken at a = (target - b) / c. None when the root lies outside the bracket or Newton's
/// method does not settle in 60 steps; the caller then falls back to regula falsi.
fn newton_angle(c: f64, b: f64, k: f64, target: f64, (lo, hi): (f64, f64)) -> Option<f64> {
    // Every friction angle lies in [0, 90 deg): the bracket in mu is checked on the answer.
    let (mut a_lo, mut a_hi) = (0.0, std::f64::consts::FRAC_PI_2);
    let guess = (target - b - (k * ((target - b) / c).sin()).min(1.0).asin()) / c;
    let mut a = guess.clamp(a_lo, a_hi);
    for _ in 0..60 {
        let (s, co) = a.sin_cos();
        let ks = k * s;
        if ks >= 1.0 {
            // Too weak here: the root lies below.
            a_hi = a;
            a = 0.5 * (a_lo + a_hi);
            continue;
        }
        let fa = c * a + ks.asin() + b - target;
        let step = fa / (c + k * co / (1.0 - ks * ks).sqrt());
        if fa == 0.0 || step.abs() <= 4.0 * f64::EPSILON * a.abs() {
            let mu = (a - step).clamp(a_lo, a_hi).tan();
            return (mu >= lo && mu <= hi).then_some(mu);
        }
        if fa > 0.0 {
            a_hi = a
        } else {
            a_lo = a
        }
        let next = a - step;
        a = if next > a_lo && next < a_hi {
            next
        } else {
            0.5 * (a_lo + a_hi)
        };
    }
    None
}

/// Any model over the box by sampling it: a grid of `SAMPLES_PER_INPUT` values per input (fewer
/// when the grid would pass `MAX_GRID`).
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
        past_palm: s.past_palm(),
    };
    let theta = |x: &&(Vec<f64>, models::Solution)| x.1.theta_jam_deg.unwrap_or(f64::NAN);
    // The interval's one meaning (module docs): over the samples that jam on the palm or are
    // held at the start; a model's number beside another status (beyond_reach, inaccurate) is
    // left out, and the statuses say it was met.
    let answers = |s: &models::Solution| {
        matches!(s.status, JamStatus::Jams | JamStatus::JammedAtStart)
            && s.theta_jam_deg.is_some()
            && s.x_jam_mm.is_some()
    };
    let jams: Vec<&(Vec<f64>, models::Solution)> =
        points.iter().filter(|x| answers(&x.1)).collect();
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
        let vals: Vec<f64> = jams.iter().filter_map(|x| f(&x.1)).collect();
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
        method: RangeMethod::Sampled {
            samples: points.len(),
        },
        theta_jam_deg: span(|s| s.theta_jam_deg),
        x_jam_mm: span(|s| s.x_jam_mm),
        reached: (!jams.is_empty()).then_some([Reached::Corner; 2]),
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
/// `hi` is reached. `known` gives the statuses at the ends where the caller has them; `keys`
/// the settings `at` moves, when the walk is along one input (its changes are then solved for
/// in closed form, [`invert`]). The status alone is asked ([`statics::status`]):
/// `statics::solve` would run its past-palm bisection at every point beyond the palm (the range
/// answer took 1450x a point answer).
/// The smallest positive double (a subnormal, 4.9e-324): `f64::from_bits(1)`, as a constant.
const SMALLEST_DOUBLE: f64 = 5e-324;

fn walk(
    (lo, hi): (f64, f64),
    known: Option<(JamStatus, JamStatus)>,
    keys: Option<&[&'static str]>,
    at: impl Fn(f64) -> SceneParams,
) -> Vec<Segment> {
    let status = |x: f64| statics::status(&at(x));
    let tol = 1e-9 * (hi - lo);
    let (first, last) = known.unwrap_or_else(|| (status(lo), status(hi)));
    let (mut from, mut here) = (lo, first);
    let mut out = Vec::with_capacity(2);
    // Each status has one stretch, so there are fewer changes than statuses; the bound only
    // guards against a status that is not monotone after all.
    while here != last && out.len() < JamStatus::ALL.len() {
        let (to, next) = match here {
            // never_jams holds only where theta* = 0, with no friction at either contact:
            // along a friction that is its low end alone (any friction above 0 jams
            // somewhere), so the stretch ends where it begins, and the next status is the one
            // just above it (a step of `tol`, at least a float's: along the box's diagonal the
            // first float above 0 can round the frictions back to 0). Bisection put the end at
            // the bracket's last float, 2^-30 of the range: `--mu 0:0.3` said never_jams for
            // mu < 2.794e-10, where `--mu 1e-10` is beyond_reach. Over a subnormal range
            // (`--mu 0:1e-322`) `tol` is 0 and the step is the smallest double; where even
            // that rounds back to no friction, the next status is the far end's.
            JamStatus::NeverJams => {
                let step = tol.max(f64::EPSILON * from.abs()).max(SMALLEST_DOUBLE);
                match status((from + step).min(hi)) {
                    JamStatus::NeverJams => (from, last),
                    next => (from, next),
                }
            }
            _ => change_by_theta((from, hi), tol, here, last, keys, &at)
                .map_or_else(|| bisect_change((from, hi), here, status), |to| (to, last)),
        };
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
/// [`SceneParams::reach_angle`] between beyond_reach and jams, the start angle between jams and
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
    keys: Option<&[&'static str]>,
    at: impl Fn(f64) -> SceneParams,
) -> Option<f64> {
    use JamStatus::{BeyondReach, JammedAtStart, Jams};
    let q = at(a);
    let target = match (here, next) {
        (BeyondReach, Jams) | (Jams, BeyondReach) => q.reach_angle(),
        (Jams, JammedAtStart) | (JammedAtStart, Jams) => q.start_angle_deg.to_radians(),
        _ => return None,
    };
    let status = |x: f64| statics::status(&at(x));
    // Along one input the crossing is solved for; the statuses either side of it (a bracket
    // of `tol` around the root) confirm it, as the bracket's ends do below.
    if let Some(root) = keys.and_then(|k| invert(&q, k, target, (a, b))) {
        let upper = (root + 0.5 * tol).min(b);
        let lower = (upper - tol).max(a);
        if status(lower) == here && status(upper) == next {
            return Some(upper);
        }
    }
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
    (b - a <= tol && status(a) == here && status(b) == next).then_some(b)
}

/// Where the status changes from `here` on `[a, b]` (status(a) = here != status(b)), by
/// bisection of the status ([`HALVINGS`] halvings, fewer where the bracket reaches two
/// neighbouring floats first): the upper end of the final bracket and its status.
fn bisect_change(
    (a, b): (f64, f64),
    here: JamStatus,
    status: impl Fn(f64) -> JamStatus,
) -> (f64, JamStatus) {
    let mid = |a: f64, b: f64| 0.5 * (a + b);
    let (_, b) = crate::locator::bisect_bracket((a, b), HALVINGS, mid, |x| status(x) == here);
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
    let mut met = [false; JamStatus::ALL.len()];
    for s in seen {
        if let Some(i) = JamStatus::ALL.iter().position(|&a| a == s) {
            met[i] = true;
        }
    }
    JamStatus::ALL
        .iter()
        .zip(met)
        .filter_map(|(&s, m)| m.then_some(s))
        .collect()
}
