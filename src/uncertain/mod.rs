//! Inputs known only within a range or by a distribution: a friction "0.12 to 0.3", a push
//! "30 to 50 N".
//!
//! ## Syntax
//!
//! A value of a setting that takes uncertainty (a flag, `--set KEY=VALUE`, a scene or parameter
//! file's string `mu = "0.12:0.3"`) is one of
//!
//! | written              | meaning                                                              |
//! |----------------------|----------------------------------------------------------------------|
//! | `0.3`                | a point: the value as before                                         |
//! | `0.12:0.3`           | a range LOW:HIGH: every value in it is possible, none more likely    |
//! | `uniform(0.12,0.3)`  | uniformly distributed on [LOW, HIGH]                                  |
//! | `normal(0.2,0.03)`   | normal with mean 0.2 and standard deviation 0.03, truncated at 0      |
//! | `lognormal(0.2,0.25)`| lognormal with median 0.2 and log standard deviation 0.25: ln X is    |
//! |                      | normal with mean ln 0.2 and standard deviation 0.25                   |
//!
//! A range asks for the worst case (the answer's interval over the range); a distribution asks
//! for probabilities and quantiles as well. Which settings take it is declared once, with the
//! setting (`uncertain: true` in `settings!`): the frictions, the push and the mass of the palm
//! scene, the frictions and the load of the V-locator. Every other setting refuses it.
//!
//! ## Validation
//!
//! A reversed range (`0.3:0.12`), an empty one (`0.3:0.3`: write `0.3`), a range end or a mean
//! or median outside the setting's valid values (a negative friction), a non-positive standard
//! deviation and non-finite numbers are refused naming the setting as written.
//!
//! ## The nominal value
//!
//! Every uncertain input also has a point, its nominal value, which the point path (charts'
//! built-in scenes, the parameters shown) keeps: the midpoint of a range or uniform, the mean
//! of a normal, the median of a lognormal.

pub mod dist;
pub mod range;
mod table;

use std::fmt;

use statrs::function::erf::{erfc, erfc_inv};

use crate::error::{Error, Result};
use crate::settings::Decl;
pub(crate) use table::take;

/// The worked example of the range, distribution and `design` tests, shared with the
/// uncertainty benchmark.
#[cfg(test)]
pub(crate) mod shaft;

/// What an observer of long work ([`dist::Progress`]) answers: go on, or stop (the work then
/// ends with [`Error::Stopped`] within one chunk per thread).
pub type Flow = std::ops::ControlFlow<()>;

/// One input's uncertainty: a point, a range (worst case) or a distribution.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Uncertain {
    /// A single value.
    Point {
        /// The value.
        value: f64,
    },
    /// Every value in [lo, hi] possible, none more likely: the answer is an interval.
    Range {
        /// Low end.
        lo: f64,
        /// High end (> lo).
        hi: f64,
    },
    /// Uniform on [lo, hi].
    Uniform {
        /// Low end.
        lo: f64,
        /// High end (> lo).
        hi: f64,
    },
    /// Normal with this mean and standard deviation, truncated at 0 (a friction, a push or a
    /// mass is never negative).
    Normal {
        /// Mean of the untruncated normal (> 0).
        mean: f64,
        /// Standard deviation of the untruncated normal (> 0).
        sd: f64,
    },
    /// Lognormal: ln X normal with mean ln(median) and standard deviation sigma.
    LogNormal {
        /// Median (> 0).
        median: f64,
        /// Standard deviation of ln X (> 0).
        sigma: f64,
    },
}

/// The spelling of each distribution's name in the syntax, with its two parameters.
pub(crate) const FORMS: &str = "a number, LOW:HIGH, uniform(LOW,HIGH), normal(MEAN,SD) or \
                     lognormal(MEDIAN,SIGMA)";

/// The distributions' names as written (in any case): `normal(0.2,0.03)`.
pub(crate) const DISTRIBUTION_NAMES: [&str; 3] = ["uniform", "normal", "lognormal"];

impl Uncertain {
    /// Parses the syntax of the module docs; numbers must be finite. The range check against
    /// the setting is `Uncertain::check`.
    pub fn parse(text: &str) -> std::result::Result<Uncertain, String> {
        let t = text.trim();
        let number = |s: &str| -> std::result::Result<f64, String> {
            let v = crate::settings::decl::parse_f64(s)?;
            if v.is_finite() {
                Ok(v)
            } else {
                Err(format!("{} is not a finite number", s.trim()))
            }
        };
        if let Some((name, rest)) = t.split_once('(') {
            let inner = rest
                .strip_suffix(')')
                .ok_or_else(|| format!("{t}: a ')' is missing; write {FORMS}"))?;
            let (a, b) = inner.split_once(',').ok_or_else(|| {
                format!("{t}: give two numbers in the parentheses, e.g. {name}(0.2,0.03)")
            })?;
            let (a, b) = (number(a)?, number(b)?);
            return match name.trim().to_ascii_lowercase().as_str() {
                "uniform" => Ok(Uncertain::Uniform { lo: a, hi: b }),
                "normal" => Ok(Uncertain::Normal { mean: a, sd: b }),
                "lognormal" => Ok(Uncertain::LogNormal {
                    median: a,
                    sigma: b,
                }),
                other => Err(format!(
                    "{t}: '{other}' is not a distribution; write {FORMS}"
                )),
            };
        }
        if let Some((a, b)) = t.split_once(':') {
            return Ok(Uncertain::Range {
                lo: number(a)?,
                hi: number(b)?,
            });
        }
        crate::settings::decl::parse_f64(t).map(|value| Uncertain::Point { value })
    }

    /// Whether this is more than a point.
    pub fn is_uncertain(&self) -> bool {
        !matches!(self, Uncertain::Point { .. })
    }

    /// Whether it has a distribution (probabilities and quantiles mean something).
    pub fn is_distribution(&self) -> bool {
        matches!(
            self,
            Uncertain::Uniform { .. } | Uncertain::Normal { .. } | Uncertain::LogNormal { .. }
        )
    }

    /// The point the point path keeps: a range's or uniform's midpoint, a normal's mean, a
    /// lognormal's median.
    pub fn nominal(&self) -> f64 {
        match *self {
            Uncertain::Point { value } => value,
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => 0.5 * (lo + hi),
            Uncertain::Normal { mean, .. } => mean,
            Uncertain::LogNormal { median, .. } => median,
        }
    }

    /// The ends of the box this input spans: a range's or uniform's ends, a distribution's
    /// `TAIL` and 1 - `TAIL` quantiles, a point twice.
    pub fn ends(&self) -> (f64, f64) {
        match *self {
            Uncertain::Point { value } => (value, value),
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => (lo, hi),
            _ => (self.quantile(TAIL), self.quantile(1.0 - TAIL)),
        }
    }

    /// The value below which a fraction `p` in [0, 1] of the input lies (the inverse CDF); a
    /// range is read as uniform.
    pub fn quantile(&self, p: f64) -> f64 {
        match *self {
            Uncertain::Point { value } => value,
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => lo + p * (hi - lo),
            Uncertain::Normal { mean, sd } => {
                // Truncated at 0: the untruncated CDF's share above 0 is rescaled to [0, 1].
                let below = std_normal_cdf(-mean / sd);
                // Above the median, by the upper tail (1 - p)(1 - below): below + p (1 - below)
                // loses the tail's digits near p = 1 and can round to 1 (an infinite quantile:
                // normal(0.05,0.05) was refused as reaching inf).
                let z = match p <= 0.5 {
                    true => std_normal_quantile(below + p * (1.0 - below)),
                    false => -std_normal_quantile((1.0 - p) * (1.0 - below)),
                };
                (mean + sd * z).max(0.0)
            }
            Uncertain::LogNormal { median, sigma } => {
                median * (sigma * std_normal_quantile(p)).exp()
            }
        }
    }

    /// The fraction of the input at or below `x` (the CDF); a range is read as uniform.
    pub fn cdf(&self, x: f64) -> f64 {
        match *self {
            Uncertain::Point { value } => f64::from(u8::from(x >= value)),
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => {
                ((x - lo) / (hi - lo)).clamp(0.0, 1.0)
            }
            Uncertain::Normal { mean, sd } => {
                if x <= 0.0 {
                    return 0.0;
                }
                let below = std_normal_cdf(-mean / sd);
                ((std_normal_cdf((x - mean) / sd) - below) / (1.0 - below)).clamp(0.0, 1.0)
            }
            Uncertain::LogNormal { median, sigma } => {
                if x <= 0.0 {
                    return 0.0;
                }
                std_normal_cdf((x / median).ln() / sigma)
            }
        }
    }

    /// What is wrong with it whatever input it describes, in words: a number that is not
    /// finite, a reversed or empty range, a spread or centre that is not above 0. `check`
    /// refuses these first; a face that builds one (Python's `jamchart.normal`) refuses them
    /// when it is made.
    pub fn shape_error(&self) -> Option<String> {
        let t = crate::settings::number_text;
        let (a, b) = match *self {
            Uncertain::Point { value } => (value, value),
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => (lo, hi),
            Uncertain::Normal { mean, sd } => (mean, sd),
            Uncertain::LogNormal { median, sigma } => (median, sigma),
        };
        if let Some(v) = [a, b].into_iter().find(|v| !v.is_finite()) {
            return Some(format!("{} is not a finite number", t(v)));
        }
        match *self {
            Uncertain::Point { .. } => None,
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } if lo > hi => {
                let (l, h) = (t(lo), t(hi));
                Some(format!(
                    "the range is reversed ({l} > {h}); write LOW:HIGH, e.g. {h}:{l}"
                ))
            }
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } if lo == hi => Some(
                format!("the range is empty; for a single value write {}", t(lo)),
            ),
            Uncertain::Range { .. } | Uncertain::Uniform { .. } => None,
            Uncertain::Normal {
                mean: centre_value,
                sd: spread_value,
            }
            | Uncertain::LogNormal {
                median: centre_value,
                sigma: spread_value,
            } => {
                let (centre, spread) = self.parameter_names();
                if spread_value <= 0.0 {
                    return Some(format!("{spread} must be > 0 (it is {})", t(spread_value)));
                }
                (centre_value <= 0.0).then(|| {
                    format!(
                        "{centre} must be > 0 (it is {}): the distribution lives on positive \
                         values",
                        t(centre_value)
                    )
                })
            }
        }
    }

    /// A normal's or lognormal's two parameters in words (centre, spread).
    fn parameter_names(&self) -> (&'static str, &'static str) {
        match self {
            Uncertain::LogNormal { .. } => ("its median", "its log standard deviation sigma"),
            _ => ("its mean", "its standard deviation"),
        }
    }

    /// Checks it against `decl`'s valid values; the error names the setting (`decl.key`, the
    /// CLI adds its flag) and quotes the value as written.
    pub(crate) fn check(&self, decl: &Decl) -> Result<()> {
        let refuse = |why: String| Err(Error::invalid(decl.key, self, why));
        // Each number as short as it reads back (`1e-308`, not 308 zeros).
        let t = crate::settings::number_text;
        let must = |what: &str, v: f64| -> Result<()> {
            match decl.check.refuse(v) {
                None => Ok(()),
                Some(why) => refuse(format!("{what} {} {why}", t(v))),
            }
        };
        match *self {
            Uncertain::Point { value } => decl.check_real(value),
            Uncertain::Range { lo, hi } | Uncertain::Uniform { lo, hi } => {
                if let Some(why) = self.shape_error() {
                    return refuse(why);
                }
                must("its low end", lo)?;
                must("its high end", hi)
            }
            Uncertain::Normal { .. } | Uncertain::LogNormal { .. }
                if decl.check.refuse(-1.0).is_none() =>
            {
                refuse(format!(
                    "{} takes negative values, and normal and lognormal inputs are truncated \
                     at 0; give a range LOW:HIGH or uniform(LOW,HIGH)",
                    decl.key
                ))
            }
            Uncertain::Normal { mean, .. } | Uncertain::LogNormal { median: mean, .. } => {
                let (centre, spread) = self.parameter_names();
                if let Some(why) = self.shape_error() {
                    return refuse(why);
                }
                must(centre, mean)?;
                // Every value a draw or the box can take must be a valid value too:
                // lognormal(0.2,1e300) reached mu = inf, where the closed form said theta_jam =
                // 182.8 deg at x = -0.245 mm with exit 0.
                // A normal is truncated at 0 by design (its lowest value is 0 however wide);
                // a lognormal's lowest value underflows to 0 when sigma is huge.
                let lowest = matches!(self, Uncertain::LogNormal { .. }).then_some(REACH);
                for p in lowest.into_iter().chain([1.0 - REACH]) {
                    let v = self.quantile(p);
                    if let Some(why) = decl.check.refuse(v) {
                        let which = if p < 0.5 { "lowest" } else { "highest" };
                        return refuse(format!(
                            "the {which} value a sample can take is {v:e}, and each {why}; \
                             narrow {spread}"
                        ));
                    }
                }
                Ok(())
            }
        }
    }
}

/// The most extreme probabilities a draw or an answer reads a distribution at: the smallest
/// step of a double below 1, and its mirror.
pub(crate) const REACH: f64 = f64::EPSILON / 2.0;

/// The tail probability cut off at each end when a distribution stands for a box (0.1 %): the
/// interval answer of a normal or lognormal input covers its 0.1 % to 99.9 % quantiles.
pub(crate) const TAIL: f64 = 1e-3;

impl fmt::Display for Uncertain {
    /// As it is written: `0.12:0.3`, `normal(0.2,0.03)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Each number as short as it reads back: `1e300`, not its 301 digits.
        let t = crate::settings::number_text;
        match *self {
            Uncertain::Point { value } => write!(f, "{}", t(value)),
            Uncertain::Range { lo, hi } => write!(f, "{}:{}", t(lo), t(hi)),
            Uncertain::Uniform { lo, hi } => write!(f, "uniform({},{})", t(lo), t(hi)),
            Uncertain::Normal { mean, sd } => write!(f, "normal({},{})", t(mean), t(sd)),
            Uncertain::LogNormal { median, sigma } => {
                write!(f, "lognormal({},{})", t(median), t(sigma))
            }
        }
    }
}

/// The standard normal CDF, Phi(z) = erfc(-z / sqrt 2) / 2.
fn std_normal_cdf(z: f64) -> f64 {
    0.5 * erfc(-z / std::f64::consts::SQRT_2)
}

/// The standard normal quantile, Phi^-1(p) = -sqrt 2 erfc^-1(2 p).
fn std_normal_quantile(p: f64) -> f64 {
    -std::f64::consts::SQRT_2 * erfc_inv(2.0 * p)
}

/// One uncertain input of a scene: the settings it sets (one draw for all of them: `mu` sets
/// both frictions to the same value), the name it was written with, and its uncertainty.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct UncertainInput {
    /// The setting as the user wrote it (`mu`, `force_n`); the CLI adds its flag.
    pub name: &'static str,
    /// The fields it sets (both frictions for `mu`).
    #[serde(skip)]
    pub keys: Vec<&'static str>,
    /// Its uncertainty.
    #[serde(flatten)]
    pub value: Uncertain,
}

/// The uncertain inputs of one scene, in declaration order; empty for a point scene.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
#[serde(transparent)]
pub struct UncertainSet {
    /// Each input.
    pub inputs: Vec<UncertainInput>,
}

impl UncertainSet {
    /// No input is uncertain: the point path.
    pub fn is_empty(&self) -> bool {
        self.inputs.is_empty()
    }

    /// `params` with input `i` set to `values[i]` for every i (its keys all to the same value).
    pub fn apply<P: crate::settings::Numbers + Copy>(&self, params: &P, values: &[f64]) -> P {
        let mut p = *params;
        for (input, &v) in self.inputs.iter().zip(values) {
            for k in &input.keys {
                let set = p.set_real(k, v);
                debug_assert!(set, "{k} is a number field");
            }
        }
        p
    }

    /// This set (from a file) with `later` (from flags) over it: a key that `given` (the later
    /// overrides, aliases not yet expanded) sets, as a point or not, leaves this set's inputs.
    pub(crate) fn override_by(&mut self, given: &toml::Table, later: UncertainSet) {
        if self.inputs.is_empty() {
            self.inputs = later.inputs;
            return;
        }
        let mut keys: Vec<&str> = given.keys().map(String::as_str).collect();
        for d in crate::settings::all().filter(|d| given.contains_key(d.key)) {
            keys.extend(d.sets.iter().copied());
        }
        for input in &mut self.inputs {
            input.keys.retain(|k| !keys.contains(k));
        }
        self.inputs.retain(|i| !i.keys.is_empty());
        self.inputs.extend(later.inputs);
    }

    /// What the box is for each distributed input, one sentence each: a normal or lognormal
    /// stands for its central 1 - 2 `TAIL` (99.8 %), from its `TAIL` to its 1 - `TAIL`
    /// quantile (a normal's mean +- 3.09 sd); a uniform for its whole support; a range is its
    /// own box and needs no sentence.
    pub fn box_notes(&self) -> Vec<String> {
        let pct = |p: f64| crate::numbers::sig(100.0 * p, 3);
        let num = |v: f64| crate::numbers::sig(v, 4);
        self.inputs
            .iter()
            .filter(|i| i.value.is_distribution())
            .map(|i| {
                let (lo, hi) = i.value.ends();
                let (name, value, lo, hi) = (i.name, i.value, num(lo), num(hi));
                match i.value {
                    Uncertain::Uniform { .. } => {
                        format!("the box takes {name} = {value} whole: {lo} to {hi}")
                    }
                    _ => format!(
                        "the box takes {name} = {value} as its central {} %: {lo} to {hi} (its \
                         {} % and {} % quantiles)",
                        pct(1.0 - 2.0 * TAIL),
                        pct(TAIL),
                        pct(1.0 - TAIL)
                    ),
                }
            })
            .collect()
    }

    /// `name = value` for each input, joined by `, `: how the text answers show them.
    pub fn describe(&self) -> String {
        let parts: Vec<String> = self
            .inputs
            .iter()
            .map(|i| format!("{} = {}", i.name, i.value))
            .collect();
        parts.join(", ")
    }
}

/// `each` of `n` samples of `set`'s inputs (its values in declaration order) drawn with
/// `seed` as the tests' `dist::draw` draws them, in parallel: the values it returns, sorted by
/// `f64::total_cmp`, the samples without one left out; on an error, the error of a sample
/// (the rest are not drawn). `drawn` is told each chunk's size as it is done, from its thread.
///
/// Every sample's value depends on the seed and its index alone, and the sorted list on the
/// values alone, so it is the same for any thread count. Each chunk of [`dist::CHUNK`]
/// samples writes its values into its own slot of one list of `n` (8 bytes a sample, the
/// peak: no per-chunk lists, no list of options), which is then closed up and sorted in
/// parallel in place.
pub(crate) fn sorted_samples(
    set: &UncertainSet,
    seed: u64,
    n: u64,
    drawn: &(dyn Fn(u64) -> Flow + Sync),
    each: impl Fn(&[f64]) -> Result<Option<f64>> + Sync,
) -> Result<Vec<f64>> {
    use rand_chacha::ChaCha8Rng;
    use rand_core::{Rng, SeedableRng};
    use rayon::prelude::*;
    let n = usize::try_from(n).map_err(|_| Error::invalid("samples", n, "is too many"))?;
    let mut xs = vec![0.0; n];
    let kept: Vec<usize> = xs
        .par_chunks_mut(dist::CHUNK)
        .enumerate()
        .map(|(c, slot)| {
            // Asked to stop: the chunks not yet begun are not drawn.
            if drawn(0).is_break() {
                return Err(Error::Stopped);
            }
            let mut rng = ChaCha8Rng::seed_from_u64(seed);
            rng.set_stream(c as u64);
            let mut values = Vec::with_capacity(set.inputs.len());
            let mut k = 0;
            for _ in 0..slot.len() {
                values.clear();
                let draws = set
                    .inputs
                    .iter()
                    .map(|i| i.value.quantile(dist::unit(rng.next_u64())));
                values.extend(draws);
                if let Some(x) = each(&values)? {
                    slot[k] = x;
                    k += 1;
                }
            }
            match drawn(slot.len() as u64) {
                Flow::Continue(()) => Ok(k),
                Flow::Break(()) => Err(Error::Stopped),
            }
        })
        .collect::<Result<_>>()?;
    // Close up: chunk c's k values move down to follow the values of the chunks before it.
    let mut len = 0;
    for (c, k) in kept.into_iter().enumerate() {
        let start = c * dist::CHUNK;
        xs.copy_within(start..start + k, len);
        len += k;
    }
    xs.truncate(len);
    // Values equal under total_cmp have the same bits: the unstable sort's order is the order.
    xs.par_sort_unstable_by(f64::total_cmp);
    Ok(xs)
}

#[cfg(test)]
mod dist_tests;
#[cfg(test)]
mod range_tests;
#[cfg(test)]
mod tests;
