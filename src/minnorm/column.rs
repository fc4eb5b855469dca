//! theta_jam along a line of scenes, each bisection bracketed from its neighbours' answers.
//!
//! Along a map's column (one parameter fixed, the other stepping through its samples) theta_jam
//! is a smooth function of the sample index k wherever the disc jams. A bisection from the
//! palm's reach to the start angle costs log2((start - reach) / tol) solves, about 31 at the
//! default 1e-9 rad, plus the two that decide the status. From the three previous jams the next
//! is predicted by quadratic extrapolation, theta(k) ~ 3 theta(k-1) - 3 theta(k-2) +
//! theta(k-3), whose error is the third difference of theta along the column; the bracket is
//! sought that far (twice the last prediction's miss, at least 16 bisection widths) around the
//! prediction and widened
//! fourfold at each miss ([`super::palm::solve_near`]), so a smooth column costs two solves for
//! the bracket and log2(width / tol) to bisect it. The held angles are one interval
//! [0, theta_jam] (module docs of [`crate::minnorm`]), so a bracket strictly inside
//! (reach, start) decides the status as well; a bracket that reaches either end falls back to
//! the full search. Each answer lies within the bisection's tolerance of the same boundary as
//! [`super::palm::solve`]'s, and a column is solved in order, so the answers do not depend on
//! how columns are spread over threads.

use super::palm::{self, JamGuess, MinNormSettings, PalmSolution, RELATIVE_RESOLUTION};
use crate::error::Result;
use crate::scene::{JamStatus, SceneParams};

/// First bracket half-width in rad when only one neighbour has jammed: 1e-3 rad (0.06 deg), a
/// map step's change of theta_jam at a few hundred samples per axis.
const FIRST_WIDTH_RAD: f64 = 1e-3;

/// Solves each scene of `scenes` in order by the minimum-norm model, bracketing each bisection
/// around the theta_jam its neighbours predict. `Err` only for invalid input.
pub fn solve_column(scenes: &[SceneParams], s: &MinNormSettings) -> Result<Vec<PalmSolution>> {
    let mut out = Vec::with_capacity(scenes.len());
    // theta_jam in rad of the previous scenes, latest first, while they jam; the last miss.
    let mut jams: Vec<f64> = Vec::with_capacity(3);
    let mut miss_rad = FIRST_WIDTH_RAD;
    for p in scenes {
        // Quadratic extrapolation where three neighbours jammed: its miss is the third
        // difference of theta along the column.
        let predicted = match jams[..] {
            [a, b, c, ..] => Some(3.0 * a - 3.0 * b + c),
            [a, b] => Some(2.0 * a - b),
            [a] => Some(a),
            [] => None,
        };
        let guess = predicted.map(|theta_rad| JamGuess {
            theta_rad,
            width_rad: (2.0 * miss_rad).max(
                16.0 * s
                    .bisection_tol_rad
                    .min(RELATIVE_RESOLUTION * theta_rad.abs()),
            ),
        });
        let sol = palm::solve_near(p, s, guess)?;
        let theta = (sol.status == JamStatus::Jams)
            .then_some(sol.theta_jam_deg)
            .flatten()
            .map(f64::to_radians);
        miss_rad = match (theta, predicted) {
            (Some(t), Some(q)) if jams.len() >= 2 => (t - q).abs(),
            _ => FIRST_WIDTH_RAD,
        };
        match theta {
            Some(t) => {
                jams.insert(0, t);
                jams.truncate(3);
            }
            None => jams.clear(),
        }
        out.push(sol);
    }
    Ok(out)
}
