//! theta_jam along a line of scenes, each cell's boundary found from its neighbours' answers.
//!
//! Along a map's column (one parameter fixed, the other stepping through its samples) theta_jam
//! is a smooth function of the sample index k wherever the disc jams. A bisection from the
//! palm's reach to the start angle costs log2((start - reach) / tol) solves, about 31 at the
//! default 1e-9 rad, plus the two that decide the status; bracketing it around the neighbours'
//! extrapolation still costs log2(bracket / tol), about 14 solves a cell on the design map
//! (`cargo bench --bench maps`).
//!
//! A held solution says more than "held": the palm scene is held up to theta_jam, where a
//! friction cone binds (module docs of [`crate::minnorm`]), so the largest friction
//! utilisation u(theta) = |f_t| / (mu f_n) of a held solution rises to 1 at theta_jam, smoothly
//! on the held side. Each cell therefore searches by a safeguarded Newton iteration on
//! u(theta) = 1 from the held side:
//!
//! 1. the root is predicted by cubic extrapolation of the previous cells' roots (its miss is
//!    their fourth difference), and u's slope by linear extrapolation of theirs;
//! 2. a first solve a little below the prediction (twice the last miss) is held and gives u
//!    there; Newton with the predicted slope aims just below the root (a quarter of the
//!    tolerance), the secant through the two held angles corrects it;
//! 3. a solve one tolerance above the highest held angle that is not held closes the bracket.
//!
//! So a smooth column costs about three solves a cell. Newton only chooses where to solve: the
//! answer is, as [`super::palm::solve`]'s, the held end of a bracket [held, not held] no wider
//! than `bisection_tol_rad` (relative below 0.1 rad), strictly between the reach and the start
//! angle, which decides the status `jams` as well because the held angles are one interval
//! [0, theta_jam]. Both answers lie within that tolerance of the same boundary. A Newton step
//! that leaves the bracket is replaced by its midpoint, a bracket that reaches the reach or the
//! start falls back to the bracketed bisection and then to the full search, and a column is
//! solved in order, so the answers do not depend on how columns are spread over threads.

use super::palm::{self, JamGuess, MinNormSettings, PalmSolution, RELATIVE_RESOLUTION, Search};
use crate::error::Result;
use crate::scene::{JamStatus, SceneParams};

/// First bracket half-width in rad when the neighbours cannot say yet how far their
/// extrapolation misses: 1e-3 rad (0.06 deg), a map step's change of theta_jam at a few hundred
/// samples per axis.
const FIRST_WIDTH_RAD: f64 = 1e-3;

/// Solves of one Newton search before it gives up for the bracketed bisection: a bisection of
/// any bracket between 0 and pi to 1e-15 rad takes fewer.
const MAX_NEWTON_SOLVES: u32 = 64;

/// The closing step's length in tolerances: lo + t rounds to within an ulp of lo (2e-7 of a
/// 1e-9 rad tolerance at 1 rad), so a whole one could miss the width by that.
const CLOSING: f64 = 0.999;

/// Previous cells' roots (rad) and utilisation slopes (1/rad), latest first, while they jam.
#[derive(Debug, Default)]
struct Neighbours {
    roots: Vec<f64>,
    slopes: Vec<f64>,
    /// How far the last prediction missed its cell's root, in rad.
    miss_rad: Option<f64>,
}

impl Neighbours {
    fn predicted_root(&self) -> Option<f64> {
        match self.roots[..] {
            [a, b, c, d, ..] => Some(4.0 * a - 6.0 * b + 4.0 * c - d),
            [a, b, c] => Some(3.0 * a - 3.0 * b + c),
            [a, b] => Some(2.0 * a - b),
            [a] => Some(a),
            [] => None,
        }
    }

    fn predicted_slope(&self) -> Option<f64> {
        match self.slopes[..] {
            [a, b, ..] => Some(2.0 * a - b).filter(|s| *s > 0.0).or(Some(a)),
            [a] => Some(a),
            [] => None,
        }
    }

    fn record(&mut self, root: Option<f64>, slope: Option<f64>, predicted: Option<f64>) {
        let (Some(root), Some(slope)) = (root, slope) else {
            *self = Neighbours::default();
            return;
        };
        self.miss_rad = predicted.map(|q| (root - q).abs());
        self.roots.insert(0, root);
        self.roots.truncate(4);
        self.slopes.insert(0, slope);
        self.slopes.truncate(2);
    }
}

/// Solves each scene of `scenes` in order by the minimum-norm model, each search started from
/// the theta_jam its neighbours predict. `Err` only for invalid input.
pub fn solve_column(scenes: &[SceneParams], s: &MinNormSettings) -> Result<Vec<PalmSolution>> {
    s.validate()?;
    let mut out = Vec::with_capacity(scenes.len());
    let mut near = Neighbours::default();
    for p in scenes {
        p.validate()?;
        let mut search = Search::new(p, s);
        let predicted = near.predicted_root();
        let tol = |theta: f64| s.bisection_tol_rad.min(RELATIVE_RESOLUTION * theta.abs());
        let width = |q: f64| {
            near.miss_rad
                .map_or(FIRST_WIDTH_RAD, |m| 2.0 * m)
                .max(16.0 * tol(q))
        };
        let newton = match (predicted, near.predicted_slope()) {
            (Some(q), Some(slope)) => newton(&mut search, q, width(q), slope)?,
            _ => None,
        };
        let sol = match newton {
            Some((lo, held)) => search.jam_at(JamStatus::Jams, lo, held),
            None => {
                let guess = predicted.map(|q| JamGuess {
                    theta_rad: q,
                    width_rad: width(q),
                });
                palm::solve_from(&mut search, guess)?
            }
        };
        // Where it jams, the root of u = 1 by the secant through the last two held angles:
        // far closer to theta_jam than the bisection's tolerance.
        let jams = sol.status == JamStatus::Jams;
        let slope = search.trail.slope().filter(|_| jams);
        let root = slope.and_then(|m| search.trail.root(m));
        near.record(root, slope, predicted);
        out.push(sol);
    }
    Ok(out)
}

/// theta_jam by Newton on u(theta) = 1 from the held side, started `width` below `guess` with
/// `slope` as du/dtheta: the held end of a bracket no wider than the bisection's tolerance and
/// its solution, or None if the search would touch the reach or the start angle.
fn newton(
    search: &mut Search,
    guess: f64,
    width: f64,
    slope: f64,
) -> Result<Option<(f64, super::ContactSolution)>> {
    let (reach, start) = (
        search.p.reach_angle(),
        search.p.start_angle_deg.to_radians(),
    );
    let bisection_tol = search.s.bisection_tol_rad;
    let tol = |theta: f64| bisection_tol.min(RELATIVE_RESOLUTION * theta);
    let mut held: Option<(f64, super::ContactSolution)> = None;
    let mut free: Option<f64> = None;
    let (mut width, mut slope) = (width, slope);
    let mut trial = guess - width;
    // Newton's aim is trusted until a step meant to close the bracket lands held.
    let mut trusted = true;
    let mut closing = false;
    for _ in 0..MAX_NEWTON_SOLVES {
        if !(trial > reach && trial < start) {
            return Ok(None);
        }
        match search.eval(trial)? {
            Some(sol) => {
                trusted &= !closing;
                held = Some((trial, sol));
                // Two held angles of this search: their secant is u's slope here.
                if let Some(m) = search.trail.slope() {
                    slope = m;
                }
            }
            None => free = Some(free.map_or(trial, |f: f64| f.min(trial))),
        }
        let Some((lo, _)) = &held else {
            // Not held below the guess: the root lies lower, seek further down.
            width *= 4.0;
            trial = guess - width;
            continue;
        };
        let (lo, t) = (*lo, tol(*lo));
        if let Some(hi) = free
            && hi - lo <= t
        {
            return Ok(held);
        }
        let aim = (trusted && search.trail.points[0].is_some_and(|(a, _)| a == lo))
            .then(|| search.trail.root(slope))
            .flatten()
            .filter(|r| *r > lo);
        let hi = free.unwrap_or(f64::INFINITY);
        closing = aim.is_some_and(|r| r - lo <= 0.5 * t);
        trial = match aim {
            // The root is within half a tolerance: the step above closes the bracket (a hair
            // short of a whole tolerance, so that rounding lo + t cannot leave it wider).
            Some(r) if r - lo <= 0.5 * t => lo + CLOSING * t,
            Some(r) if r - 0.25 * t < hi => r - 0.25 * t,
            _ if hi.is_finite() => 0.5 * (lo + hi),
            _ => {
                width *= 4.0;
                lo + width
            }
        };
    }
    Ok(None)
}
