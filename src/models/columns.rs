//! Many pushes at once, as columns: N values of one or more scene parameters in, the status,
//! theta_jam and x_jam of each out, written into buffers the caller owns.
//!
//! A binding (numpy arrays) hands its arrays over as they are and gets its answers without a
//! copy; every answer is [`super::solve`]'s, in the same order for any thread count. The
//! closed form answers each push without building a [`super::Solution`] (no clock read, no
//! detail); the other models go through [`super::solve`], min-norm pushes that differ in one
//! parameter only a column at a time ([`super::solve_column`]).

use rayon::prelude::*;

use super::{ModelSpec, outside, solve, solve_column};
use crate::error::{Error, Result};
use crate::grid::GridParam;
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// N pushes: a base scene and the parameters that vary, each a column of N values (or of one,
/// taken by every push).
#[derive(Debug, Clone)]
pub struct Pushes<'a> {
    /// The scene every push starts from.
    pub base: SceneParams,
    /// The parameters that vary and their values, in their units (`mu` sets both frictions).
    pub columns: Vec<(GridParam, &'a [f64])>,
}

/// Where the answers go, one element per push; each slice N long.
#[derive(Debug)]
pub struct Answers<'a> {
    /// The status, as its index in [`JamStatus::NAMES`].
    pub status: &'a mut [u8],
    /// theta_jam in deg, NaN where the model gives none.
    pub theta_jam_deg: &'a mut [f64],
    /// x_jam in mm, NaN where the model gives none.
    pub x_jam_mm: &'a mut [f64],
}

impl Pushes<'_> {
    /// The number of pushes: the longest column (1 without columns).
    pub fn len(&self) -> usize {
        self.columns.iter().map(|(_, v)| v.len()).max().unwrap_or(1)
    }

    /// Whether there is no push (a column of no values).
    pub fn is_empty(&self) -> bool {
        self.columns.iter().any(|(_, v)| v.is_empty())
    }

    /// Push `i`'s scene.
    fn scene(&self, i: usize) -> SceneParams {
        self.columns.iter().fold(self.base, |p, (param, values)| {
            let v = if values.len() == 1 {
                values[0]
            } else {
                values[i]
            };
            param.apply(p, v)
        })
    }

    /// Checks the columns' lengths and that each parameter is a scene parameter.
    fn validate(&self, n: usize) -> Result<()> {
        for (param, values) in &self.columns {
            if *param == GridParam::ThetaDeg {
                return Err(Error::invalid(
                    param.as_str(),
                    "a column",
                    "the palm angle is the state of a push, not a parameter of its scene",
                ));
            }
            if values.len() != n && values.len() != 1 {
                return Err(Error::invalid(
                    param.as_str(),
                    format!("{} values", values.len()),
                    format!("every column has {n} values, or one for every push"),
                ));
            }
        }
        Ok(())
    }
}

/// Pushes answered per task of the thread pool: large enough that a closed-form answer
/// (about 0.1 us) outweighs the task, small enough that 2 threads share a map of 10^4.
const CHUNK: usize = 512;

/// Answers every push of `pushes` with the model of `spec`, writing into `out`.
///
/// Every scene is checked first: `Err` names the first invalid parameter and value (and
/// nothing is solved), as [`super::solve`] would for that push alone.
pub fn solve_into(spec: &ModelSpec, pushes: &Pushes, out: Answers) -> Result<()> {
    let n = pushes.len();
    let lens = [
        out.status.len(),
        out.theta_jam_deg.len(),
        out.x_jam_mm.len(),
    ];
    if lens.iter().any(|&l| l != n) {
        return Err(Error::invalid(
            "answers",
            format!("{lens:?} elements"),
            format!("each answer buffer holds one element per push ({n})"),
        ));
    }
    pushes.validate(n)?;
    spec.validate()?;
    (0..n)
        .into_par_iter()
        .with_min_len(CHUNK)
        .try_for_each(|i| pushes.scene(i).validate())?;
    let answer = |i: usize| -> Result<(JamStatus, Option<f64>, Option<f64>)> {
        let p = pushes.scene(i);
        Ok(match spec {
            _ if let Some(_why) = outside(spec.kind(), &p) => (JamStatus::OutsideModel, None, None),
            ModelSpec::Statics => statics::jam(&p),
            _ => {
                let s = solve(spec, &p)?;
                (s.status, s.theta_jam_deg, s.x_jam_mm)
            }
        })
    };
    let chunk = match spec {
        ModelSpec::Statics => CHUNK,
        ModelSpec::MinNorm(_) => column_len(pushes, n),
        // A simulation outweighs any task: spread them one by one.
        ModelSpec::Dynamics { .. } => 1,
    };
    let Answers {
        status,
        theta_jam_deg,
        x_jam_mm,
    } = out;
    let write = |start: usize, s: &mut [u8], t: &mut [f64], x: &mut [f64]| -> Result<()> {
        let answers: Vec<_> = match spec {
            // A column of min-norm pushes searches each from its neighbours' answers.
            ModelSpec::MinNorm(_) => {
                let scenes: Vec<SceneParams> =
                    (start..start + s.len()).map(|i| pushes.scene(i)).collect();
                solve_column(spec, &scenes)?
                    .into_iter()
                    .map(|s| (s.status, s.theta_jam_deg, s.x_jam_mm))
                    .collect()
            }
            _ => (start..start + s.len())
                .map(answer)
                .collect::<Result<_>>()?,
        };
        for (k, (st, th, xj)) in answers.into_iter().enumerate() {
            s[k] = st.index();
            t[k] = th.unwrap_or(f64::NAN);
            x[k] = xj.unwrap_or(f64::NAN);
        }
        Ok(())
    };
    status
        .par_chunks_mut(chunk)
        .zip(theta_jam_deg.par_chunks_mut(chunk))
        .zip(x_jam_mm.par_chunks_mut(chunk))
        .enumerate()
        .try_for_each(|(c, ((s, t), x))| write(c * chunk, s, t, x))
}

/// How many min-norm pushes to search as one column: a run of neighbours (a map's column of
/// N / 2 threads' worth, at most 64, so that a search starts near its answer and both threads
/// share the work).
fn column_len(pushes: &Pushes, n: usize) -> usize {
    let varying = pushes.columns.iter().filter(|(_, v)| v.len() > 1).count();
    match varying {
        0 | 1 => n.div_ceil(2).clamp(1, 64),
        _ => 1,
    }
}
