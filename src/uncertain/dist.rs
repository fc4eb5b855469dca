//! Probabilities and quantiles of the jam position under distributed inputs.
//!
//! The quantity is x_jam where the disc jams on a long enough palm (the closed form's jam, at
//! the start position where the disc is held there or cannot be moved; a model's own answer),
//! and "jams before x" means x_jam < x: the disc stops short of x.
//!
//! ## Exact, by the monotone map
//!
//! With the closed form and one distributed input U, x_jam = X(U) is monotone (the statics
//! docs, "Monotone in every uncertain input"), so its quantiles are the input's mapped:
//! Q_x(q) = X(Q_U(q)) where X rises with U and X(Q_U(1 - q)) where it falls; and P(x_jam < x)
//! = q* or 1 - q* with X(Q_U(q*)) = x, q* found by bisection in probability to 1e-15 (halving
//! the input's value instead leaves a wide distribution's P coarse: [`exact`]).
//!
//! ## Monte Carlo
//!
//! Otherwise (several inputs, or a model other than the closed form) the inputs are sampled by
//! their inverse CDFs (a range as uniform), `CHUNK` samples per chunk. Each chunk's generator
//! is ChaCha8 seeded with the seed and its stream set to the chunk's index, so every sample
//! depends on the seed and its own index only: the answer is bit-identical for any thread count.
//! P is given with its 95 % interval p +- 1.96 sqrt(p (1 - p) / n); a quantile with the 95 %
//! interval of the order statistics at ranks n q +- 1.96 sqrt(n q (1 - q)).

use serde::Serialize;

use super::{Flow, UncertainSet};
use crate::error::{Error, Result};
use crate::models::{self, ModelSpec};
use crate::scene::SceneParams;
use crate::statics;

/// Samples per generator stream.
pub(crate) const CHUNK: usize = 1024;

/// Most Monte Carlo samples one answer takes: 1e7 closed-form samples take about a second per
/// core and 80 MB; a simulation takes far longer per sample.
pub(crate) const MAX_SAMPLES: u64 = 10_000_000;

/// 1.96: the two-sided 95 % point of the normal.
const Z95: f64 = 1.96;

/// What is asked of the distribution.
#[derive(Debug, Clone, PartialEq)]
pub struct DistQuestion {
    /// Positions x in mm for P(x_jam < x).
    pub before_mm: Vec<f64>,
    /// Probabilities q in (0, 1) for the quantiles of x_jam.
    pub quantiles: Vec<f64>,
    /// Monte Carlo samples (when it is not exact), at most `MAX_SAMPLES`.
    pub samples: u64,
    /// The generator's seed.
    pub seed: u64,
}

/// How the answer was reached.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "method", rename_all = "snake_case")]
pub enum DistMethod {
    /// By the monotone map of one input's distribution: no sampling error.
    Exact,
    /// Monte Carlo.
    MonteCarlo {
        /// Samples drawn.
        samples: u64,
        /// The seed.
        seed: u64,
        /// Samples without a jam position (too weak, or a model without an answer): counted
        /// as not jamming before any x, left out of the quantiles.
        without_jam: u64,
    },
}

/// A probability or a quantile with its 95 % interval (equal ends when exact).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// The 95 % interval's low end.
    pub lo: f64,
    /// The 95 % interval's high end.
    pub hi: f64,
}

/// P(x_jam < x) at one x.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Before {
    /// The position x in mm.
    pub x_mm: f64,
    /// The probability.
    pub probability: Estimate,
}

/// One quantile of x_jam.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quantile {
    /// The probability q.
    pub q: f64,
    /// x_jam in mm with P(x_jam <= it) = q.
    pub x_jam_mm: Estimate,
}

/// The distribution's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DistAnswer {
    /// Exact or Monte Carlo.
    #[serde(flatten)]
    pub method: DistMethod,
    /// P(x_jam < x) for each asked x.
    pub before: Vec<Before>,
    /// The asked quantiles whose jam position lies within what a double holds.
    pub quantiles: Vec<Quantile>,
    /// The asked quantiles q whose x_jam (or an end of its 95 % interval) lies beyond
    /// [`f64::MAX`] mm, past every position a double holds: frictions so small (below about
    /// 5e-308) that the disc jams nowhere within reach. An outcome, not an error: `solve --mu
    /// 'lognormal(5e-324,1)'` answers its box, and its default quantiles say this.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub beyond_every_position: Vec<f64>,
}

impl DistQuestion {
    /// Checks the question; the error names the flag's key.
    pub fn validate(&self) -> Result<()> {
        Self::check(self.samples, &self.quantiles, &self.before_mm)
    }

    /// [`DistQuestion::validate`] of a question's parts, borrowed: a question that holds
    /// them checks them without a copy.
    pub(crate) fn check(samples: u64, quantiles: &[f64], before_mm: &[f64]) -> Result<()> {
        if samples == 0 || samples > MAX_SAMPLES {
            return Err(Error::invalid(
                "samples",
                samples,
                format!("the Monte Carlo sample count must be in [1, {MAX_SAMPLES}]"),
            ));
        }
        for (key, n) in [
            ("quantiles", quantiles.len()),
            ("before_mm", before_mm.len()),
        ] {
            if n > crate::limits::MAX_PROBES {
                return Err(Error::invalid(
                    key,
                    format!("{n} values"),
                    format!(
                        "give at most {} (a chart of the distribution reads more)",
                        crate::limits::MAX_PROBES
                    ),
                ));
            }
        }
        if let Some(q) = quantiles.iter().find(|q| !(**q > 0.0 && **q < 1.0)) {
            return Err(Error::invalid("quantiles", q, "each must lie in (0, 1)"));
        }
        // A quantile or a position asked twice was printed twice; the list is the user's, so
        // say so.
        if let Some(q) = given_twice(quantiles) {
            return Err(Error::invalid(
                "quantiles",
                crate::numbers::Num(q),
                "is given twice; give each probability once",
            ));
        }
        if let Some(x) = given_twice(before_mm) {
            return Err(Error::invalid(
                "before_mm",
                crate::numbers::Num(x),
                "is given twice; give each position once",
            ));
        }
        if let Some(x) = before_mm.iter().find(|x| !x.is_finite()) {
            return Err(Error::invalid(
                "before_mm",
                x,
                "must be a finite position in mm",
            ));
        }
        Ok(())
    }
}

/// The first value of `xs` that an earlier one repeats.
fn given_twice(xs: &[f64]) -> Option<f64> {
    (1..xs.len())
        .find(|&i| xs[..i].contains(&xs[i]))
        .map(|i| xs[i])
}

/// The closed form's jam position in mm on a long enough palm: at theta_jam, or at the start
/// where the disc is held there or the push is too weak to move it; None when it never jams.
/// Monotone in every input, as theta_jam is (the clamp at the start keeps it so).
fn raw_x(p: &SceneParams) -> Option<f64> {
    let t = statics::theta_jam_rad(p).min(p.start_angle_deg.to_radians());
    (t > 0.0).then(|| p.disc_position_mm(t))
}

/// Probabilities at the ends of the support the exact answer reads: the distribution's 1e-12
/// and 1 - 1e-12 quantiles.
const EXACT_TAIL: f64 = 1e-12;

/// Halvings of the bisection in probability for P(x_jam < x): 2^-50 < 1e-15, below the digits
/// a probability is printed with.
const EXACT_HALVINGS: usize = 50;

/// Halvings of the input's value within the probability bisection's last bracket, after
/// which P is F_U at the crossing: 60 reach neighbouring floats from any bracket, so a P of
/// 1e-12 keeps its seven digits (the probability's 1e-15 alone left it 1e-4 off in the
/// jam-probability chart's tail).
const EXACT_VALUE_HALVINGS: usize = 60;

/// The exact answer for the closed form with one distributed input; None when it does not
/// apply (several inputs, a range among them, no distribution, or a support that reaches no
/// friction at all at an end, where the disc never jams).
///
/// P(x_jam < x) is found by bisection in the input's probability first: q* with X(Q_U(q*)) =
/// x, so P = q* (or 1 - q* where X falls). Halving the value over the whole support left a
/// wide distribution's probability coarse: lognormal(0.01,3) reaches mu = 7e-12 to 1.5e7,
/// whose 40 halvings are 1.4e-5 wide, so the frictions below that (1.4 % of the distribution)
/// were one bracket, and P(x_jam < 1e6 mm) and P(x_jam < 1e7 mm) both came out 0.9926 beside
/// a 99 % quantile of 1.05e6 mm. In probability each halving halves the error of P, but only
/// to 1e-15 absolute, coarse for a P of 1e-12 in a tail; so the last bracket's values are
/// halved on to neighbouring floats and P is F_U there (`EXACT_VALUE_HALVINGS`).
pub fn exact(p: &SceneParams, set: &UncertainSet, ask: &DistQuestion) -> Option<DistAnswer> {
    let [input] = &set.inputs[..] else {
        return None;
    };
    let u = input.value;
    if !u.is_distribution() {
        return None;
    }
    let x_at = |q: f64| raw_x(&set.apply(p, &[u.quantile(q)]));
    let (qa, qb) = (EXACT_TAIL, 1.0 - EXACT_TAIL);
    let (xa, xb) = (x_at(qa)?, x_at(qb)?);
    let falls = xb < xa;
    let mut quantiles = Vec::new();
    let mut beyond_every_position = Vec::new();
    for &q in &ask.quantiles {
        match x_at(if falls { 1.0 - q } else { q })? {
            x if x.is_finite() => quantiles.push(Quantile {
                q,
                x_jam_mm: exact_estimate(x),
            }),
            _ => beyond_every_position.push(q),
        }
    }
    let before = ask
        .before_mm
        .iter()
        .map(|&x| {
            let prob = if x <= xa.min(xb) {
                0.0
            } else if x > xa.max(xb) {
                1.0
            } else {
                // The probabilities whose jam lies before x are one stretch of (qa, qb): below
                // q* where x_jam rises with the input, above it where it falls.
                let below = |q: f64| x_at(q).is_some_and(|xq| xq < x);
                let mid = |lo: f64, hi: f64| 0.5 * (lo + hi);
                let (lo, hi) = crate::locator::bisect_bracket((qa, qb), EXACT_HALVINGS, mid, |q| {
                    below(q) != falls
                });
                // On in the value, between the bracket's ends' values (in order: a quantile
                // function rises).
                let below_v = |v: f64| raw_x(&set.apply(p, &[v])).is_some_and(|xv| xv < x);
                let (vlo, vhi) = (u.quantile(lo), u.quantile(hi));
                let (vlo, vhi) =
                    crate::locator::bisect_bracket((vlo, vhi), EXACT_VALUE_HALVINGS, mid, |v| {
                        below_v(v) != falls
                    });
                let f = u.cdf(0.5 * (vlo + vhi));
                if falls { 1.0 - f } else { f }
            };
            Before {
                x_mm: x,
                probability: exact_estimate(prob),
            }
        })
        .collect();
    Some(DistAnswer {
        method: DistMethod::Exact,
        before,
        quantiles,
        beyond_every_position,
    })
}

fn exact_estimate(v: f64) -> Estimate {
    Estimate {
        value: v,
        lo: v,
        hi: v,
    }
}

/// The inputs' values of sample `index` for the seed: the chunk's ChaCha8 stream, advanced to
/// the sample's place in it.
#[cfg(test)]
pub(crate) fn draw(set: &UncertainSet, seed: u64, index: u64) -> Vec<f64> {
    use rand_chacha::ChaCha8Rng;
    use rand_core::{Rng, SeedableRng};

    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index / CHUNK as u64);
    let k = set.inputs.len() as u128;
    // Each sample takes k u64 words, two 32-bit words each.
    rng.set_word_pos(2 * k * u128::from(index % CHUNK as u64));
    set.inputs
        .iter()
        .map(|i| i.value.quantile(unit(rng.next_u64())))
        .collect()
}

/// A u64 to (0, 1): the top 53 bits, offset by half a step so neither end is reached.
pub(super) fn unit(bits: u64) -> f64 {
    ((bits >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
}

/// What one sample of `spec` costs: the default scene's figure ([`crate::limits::per_sample`]),
/// or, dearer, one sample at the nominal values timed (a stiff contact or a slow palm costs a
/// hundred times the default scene's).
fn cost_per_sample(
    spec: &ModelSpec,
    p: &SceneParams,
    set: &UncertainSet,
) -> Result<crate::limits::PerSample> {
    let per = crate::limits::per_sample(spec);
    if matches!(spec, ModelSpec::Statics) {
        return Ok(per);
    }
    let nominal: Vec<f64> = set.inputs.iter().map(|i| i.value.nominal()).collect();
    let t0 = crate::limits::thread_cpu_s();
    models::solve(spec, &set.apply(p, &nominal))?;
    Ok(per.at_least(crate::limits::thread_cpu_s() - t0))
}

/// Monte Carlo: `ask.samples` draws through `spec` (the closed form directly for statics),
/// in parallel, bit-identical for any thread count; refused before any draw when its
/// estimated time is over ten minutes of one core.
pub fn monte_carlo(
    spec: &ModelSpec,
    p: &SceneParams,
    set: &UncertainSet,
    ask: &DistQuestion,
) -> Result<DistAnswer> {
    monte_carlo_observed(spec, p, set, ask, &|_| Flow::Continue(()))
}

/// What a Monte Carlo reports as it goes, for a progress bar.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Progress {
    /// Accepted, before the first draw: how many samples, and their estimated CPU time in s.
    Started {
        /// The samples to draw.
        samples: u64,
        /// What they are estimated to cost on one core, s.
        estimated_cpu_s: f64,
    },
    /// This many more samples are drawn (reported from any thread).
    Drawn(u64),
}

/// [`monte_carlo`], telling `progress` its estimate once accepted and each chunk as it is done;
/// where `progress` answers [`Flow::Break`], the draws stop within a chunk per thread and the
/// answer is [`Error::Stopped`].
pub(crate) fn monte_carlo_observed(
    spec: &ModelSpec,
    p: &SceneParams,
    set: &UncertainSet,
    ask: &DistQuestion,
    progress: &(dyn Fn(Progress) -> Flow + Sync),
) -> Result<DistAnswer> {
    ask.validate()?;
    let per = cost_per_sample(spec, p, set)?;
    crate::limits::check_samples("samples", ask.samples, per)?;
    let started = progress(Progress::Started {
        samples: ask.samples,
        estimated_cpu_s: crate::limits::sampled_cpu_s(ask.samples, per),
    });
    if started.is_break() {
        return Err(crate::error::Error::Stopped);
    }
    let n = ask.samples;
    let xs = super::sorted_samples(
        set,
        ask.seed,
        n,
        &|drawn| progress(Progress::Drawn(drawn)),
        |v| {
            let q = set.apply(p, v);
            Ok(match spec {
                ModelSpec::Statics => raw_x(&q),
                _ => models::solve(spec, &q)?.x_jam_mm,
            })
        },
    )?;
    let without_jam = n - xs.len() as u64;
    let nf = n as f64;
    let before = ask
        .before_mm
        .iter()
        .map(|&x| {
            let k = xs.partition_point(|v| *v < x) as f64;
            let prob = k / nf;
            let half = Z95 * (prob * (1.0 - prob) / nf).sqrt();
            Before {
                x_mm: x,
                probability: Estimate {
                    value: prob,
                    lo: (prob - half).max(0.0),
                    hi: (prob + half).min(1.0),
                },
            }
        })
        .collect();
    let m = xs.len() as f64;
    let at = |rank: f64| xs[(rank.round().max(0.0) as usize).min(xs.len() - 1)];
    // x_jam = r cot(theta_jam / 2) passes 1.8e308 mm where theta_jam is below about 1e-307
    // rad: such a quantile is said to lie beyond every position, not printed as `inf mm [inf,
    // inf] (width NaN)`.
    let (mut quantiles, mut beyond_every_position) = (Vec::new(), Vec::new());
    for &q in ask.quantiles.iter().filter(|_| !xs.is_empty()) {
        let half = Z95 * (m * q * (1.0 - q)).sqrt();
        let x_jam_mm = Estimate {
            value: at(m * q - 0.5),
            lo: at(m * q - 0.5 - half),
            hi: at(m * q - 0.5 + half),
        };
        match [x_jam_mm.value, x_jam_mm.lo, x_jam_mm.hi]
            .iter()
            .all(|x| x.is_finite())
        {
            true => quantiles.push(Quantile { q, x_jam_mm }),
            false => beyond_every_position.push(q),
        }
    }
    Ok(DistAnswer {
        method: DistMethod::MonteCarlo {
            samples: n,
            seed: ask.seed,
            without_jam,
        },
        before,
        quantiles,
        beyond_every_position,
    })
}
