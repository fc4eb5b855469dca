//! The probability of a jam before x: P(x_jam < x) against the position x along the ground,
//! for a scene whose inputs are distributed (`mu = "normal(0.2,0.03)"`).
//!
//! The answer is [`crate::uncertain::dist`]'s, at every x of the axis: exact by the monotone
//! map where one input is distributed (the closed form's x_jam is monotone in it), else Monte
//! Carlo with its 95 % interval at each x. x_jam is the jam on a long enough palm, so the
//! curve runs past the palm's end; its value there is the probability that the disc jams on
//! the palm at all.

use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::error::{Error, Result};
use crate::models::ModelSpec;
use crate::scene::SceneParams;
use crate::uncertain::UncertainSet;
use crate::uncertain::dist::{self, Before, DistAnswer, DistMethod, DistQuestion};

/// `[chart]` keys of `kind = "jam_probability"`; the distributed inputs are the scene's
/// (`[scene] mu = "normal(0.2,0.03)"`, or `--set mu=normal(0.2,0.03)`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct JamProbabilitySettings {
    /// The lowest position drawn, in mm (default: 0).
    pub x_min_mm: f64,
    /// The highest position drawn, in mm (default: 1.25 times the palm's length, so that the
    /// palm's end and what lies past it show).
    pub x_max_mm: Option<f64>,
    /// Positions drawn, from `x_min_mm` to `x_max_mm` (default: 201; 2 to 2001).
    pub count: usize,
    /// The position the chart reads P off at, in mm: the user's x (default: none).
    pub before_mm: Option<f64>,
    /// Monte Carlo samples where the answer is not exact (default: 100000, as `solve`: P to
    /// +-0.003).
    pub samples: u64,
    /// The Monte Carlo seed (default: 1, as `solve`).
    pub seed: u64,
    /// The distributed inputs, from the scene (not a `[chart]` key).
    #[serde(skip)]
    pub inputs: UncertainSet,
}

impl Default for JamProbabilitySettings {
    fn default() -> Self {
        JamProbabilitySettings {
            x_min_mm: 0.0,
            x_max_mm: None,
            count: 201,
            before_mm: None,
            samples: 100_000,
            seed: 1,
            inputs: UncertainSet::default(),
        }
    }
}

/// Most positions a chart draws: each is a bisection (exact) or a binary search (Monte Carlo).
const MAX_COUNT: usize = 2001;

impl Figure for JamProbabilitySettings {
    type Data = JamProbabilityData;

    /// The read-off at `before_mm` marks the user's x.
    fn marks_scene_value(&self) -> bool {
        self.before_mm.is_some()
    }

    /// Checks the axis and that a distribution is given (a range has no probability).
    fn validate(&self, input: &Input) -> Result<()> {
        self.refuse_ranges()?;
        let (lo, hi) = self.x_range(&input.params);
        if !(lo.is_finite() && hi.is_finite() && lo >= 0.0 && hi > lo) {
            return Err(Error::invalid(
                "chart.x_max_mm",
                hi,
                format!("give 0 <= x_min_mm < x_max_mm (x_min_mm is {lo})"),
            ));
        }
        if !(2..=MAX_COUNT).contains(&self.count) {
            return Err(Error::invalid(
                "chart.count",
                self.count,
                format!("draw 2 to {MAX_COUNT} positions"),
            ));
        }
        if let Some(x) = self.before_mm.filter(|x| !(lo..=hi).contains(x)) {
            return Err(Error::invalid(
                "chart.before_mm",
                x,
                format!("the read-off lies on the axis: give a position in [{lo}, {hi}] mm"),
            ));
        }
        self.question(Vec::new()).validate()
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        // `validate` caps the count and the samples (dist::MAX_SAMPLES).
        Ok(())
    }

    /// P(x_jam < x) at every x of the axis and at `before_mm`, exact where it can be.
    fn compute(&self, input: &Input, _models: &dyn Models) -> Result<JamProbabilityData> {
        let p = input.params;
        let (lo, hi) = self.x_range(&p);
        let xs: Vec<f64> = (0..self.count)
            .map(|k| lo + (hi - lo) * k as f64 / (self.count - 1) as f64)
            .collect();
        // The read-off and the palm's end apart from the axis' positions, so that none is
        // asked twice (a question refuses that); Monte Carlo draws the same samples again.
        let curve = self.answer(&p, xs)?;
        let marks: Vec<f64> = self
            .before_mm
            .into_iter()
            .chain([p.palm_length_mm])
            .collect();
        let marked = self.answer(&p, marks)?;
        let (read_off, on_palm) = match (self.before_mm, &marked.before[..]) {
            (Some(_), [r, e]) => (Some(*r), *e),
            (_, [.., e]) => (None, *e),
            _ => unreachable!("the palm's end is always asked"),
        };
        Ok(JamProbabilityData {
            params: p,
            settings: self.clone(),
            distribution: self.inputs.clone(),
            method: curve.method,
            curve: curve.before,
            read_off,
            on_palm,
        })
    }
}

impl JamProbabilitySettings {
    /// Refuses inputs without a distribution: none at all, or a range (it says what is
    /// possible, not how likely); the error names the range as `scene.KEY`.
    pub fn refuse_ranges(&self) -> Result<()> {
        let hint = "give a distribution in [scene], e.g. mu = \"normal(0.2,0.03)\", or \
                    --set mu=normal(0.2,0.03)";
        if self.inputs.is_empty() {
            return Err(Error::invalid(
                "chart.kind",
                "jam_probability",
                format!("draws the probability of a jam under a distributed input; {hint}"),
            ));
        }
        match self
            .inputs
            .inputs
            .iter()
            .find(|i| !i.value.is_distribution())
        {
            Some(r) => {
                let flag = crate::settings::flag_for(r.name)
                    .and_then(|f| f.split(" or ").next().map(str::to_string))
                    .unwrap_or_else(|| format!("--{}", r.name));
                Err(Error::invalid(
                    &format!("scene.{}", r.name),
                    r.value,
                    format!(
                        "a range says what is possible, not how likely: it has no \
                         probability; give a distribution, e.g. uniform({lo},{hi}), or draw \
                         the range as a band on a sweep (jamchart sweep ... {flag} {v})",
                        lo = r.value.ends().0,
                        hi = r.value.ends().1,
                        v = r.value
                    ),
                ))
            }
            None => Ok(()),
        }
    }

    /// The drawn positions' ends in mm.
    pub fn x_range(&self, p: &SceneParams) -> (f64, f64) {
        (
            self.x_min_mm,
            self.x_max_mm.unwrap_or(1.25 * p.palm_length_mm),
        )
    }

    fn question(&self, before_mm: Vec<f64>) -> DistQuestion {
        DistQuestion {
            before_mm,
            quantiles: Vec::new(),
            samples: self.samples,
            seed: self.seed,
        }
    }

    /// The closed form's exact answer where it applies (one distributed input), else Monte
    /// Carlo of the closed form.
    fn answer(&self, p: &SceneParams, before_mm: Vec<f64>) -> Result<DistAnswer> {
        let ask = self.question(before_mm);
        match dist::exact(p, &self.inputs, &ask) {
            Some(a) => Ok(a),
            None => dist::monte_carlo(&ModelSpec::Statics, p, &self.inputs, &ask),
        }
    }
}

/// The computed probabilities: its serde form is the data file.
#[derive(Debug, Clone, Serialize)]
pub struct JamProbabilityData {
    /// The scene's parameters (each distributed input at its nominal value).
    pub params: SceneParams,
    /// The settings it was computed with.
    pub settings: JamProbabilitySettings,
    /// The distributed inputs.
    pub distribution: UncertainSet,
    /// Exact, or Monte Carlo with its samples and seed.
    pub method: DistMethod,
    /// P(x_jam < x) with its 95 % interval (equal ends when exact) at each drawn x.
    pub curve: Vec<Before>,
    /// P at the user's x (`before_mm`).
    pub read_off: Option<Before>,
    /// P at the palm's end: the probability that the disc jams on the palm.
    pub on_palm: Before,
}

impl FigureData for JamProbabilityData {
    const FORMAT: DataFormat = DataFormat::Json;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::uncertain::shaft::shaft_25mm;

    fn input() -> Input {
        Input {
            params: shaft_25mm(),
            min_norm: Default::default(),
            dynamics: Default::default(),
        }
    }

    /// The uncertain inputs of a `[scene]` written as TOML.
    fn inputs(scene: &str) -> UncertainSet {
        let mut t: toml::Table = toml::from_str(scene).unwrap();
        crate::uncertain::take(&mut t, crate::config::scene_decls()).unwrap()
    }

    fn compute(s: &JamProbabilitySettings) -> JamProbabilityData {
        s.validate(&input()).unwrap();
        let models = crate::figures::models::Live;
        s.compute(&input(), &models).unwrap()
    }

    /// The chart's read-off is `solve --before`'s exact answer: for the 25 mm shaft with mu
    /// normal(0.2, 0.03), P(x_jam < 50 mm) = 0.1028 (`jamchart solve --radius 12.5 --mass 0.4
    /// --force 40 --palm-length 80 --mu 'normal(0.2,0.03)' --before 50`); the curve never
    /// falls, runs from 0 to 1 and its value at the palm's end lies between.
    #[test]
    fn probability_chart_reads_off_the_exact_answer() {
        let s = JamProbabilitySettings {
            before_mm: Some(50.0),
            // Past the 99.9 % quantile of x_jam (mu 0.2 - 3.09 sd jams at 91 mm on a long palm).
            x_max_mm: Some(150.0),
            inputs: inputs("mu = \"normal(0.2,0.03)\""),
            ..Default::default()
        };
        let d = compute(&s);
        assert_eq!(d.method, DistMethod::Exact);
        let r = d.read_off.unwrap();
        let ask = s.question(vec![50.0]);
        let want = dist::exact(&input().params, &s.inputs, &ask)
            .unwrap()
            .before[0];
        assert!((r.probability.value - want.probability.value).abs() < 1e-12);
        assert!((r.probability.value - 0.1028).abs() < 5e-5, "{r:?}");
        let ps: Vec<f64> = d.curve.iter().map(|b| b.probability.value).collect();
        assert!(ps.windows(2).all(|w| w[0] <= w[1]), "P never falls with x");
        assert_eq!(ps[0], 0.0);
        assert!(*ps.last().unwrap() > 0.999);
        // At the palm's end, the probability of a jam on the palm: below 1, since the low
        // frictions jam past it.
        let on_palm = d.on_palm.probability.value;
        assert!(on_palm > r.probability.value && on_palm < 1.0, "{on_palm}");
    }

    /// Two distributed inputs have no exact answer: the curve is Monte Carlo, with a 95 %
    /// interval that contains the value and is not empty where P is strictly between 0 and 1.
    #[test]
    fn probability_chart_gives_monte_carlo_its_interval() {
        let inputs = inputs("mu = \"normal(0.2,0.03)\"\nforce_n = \"uniform(30,50)\"");
        let s = JamProbabilitySettings {
            samples: 20_000,
            count: 21,
            inputs,
            ..Default::default()
        };
        let d = compute(&s);
        assert!(matches!(d.method, DistMethod::MonteCarlo { .. }));
        let inner: Vec<_> = d
            .curve
            .iter()
            .filter(|b| b.probability.value > 0.0 && b.probability.value < 1.0)
            .collect();
        assert!(!inner.is_empty());
        for b in inner {
            let e = b.probability;
            assert!(e.lo < e.value && e.value < e.hi, "{b:?}");
        }
    }

    /// A range says what is possible, not how likely: the chart refuses it and says what to
    /// write.
    #[test]
    fn probability_chart_refuses_a_range() {
        let s = JamProbabilitySettings {
            inputs: inputs("mu = \"0.12:0.3\""),
            ..Default::default()
        };
        let e = s.validate(&input()).unwrap_err().to_string();
        assert!(
            e.contains("no probability") && e.contains("uniform(0.12,0.3)"),
            "{e}"
        );
        let none = JamProbabilitySettings::default();
        let e = none.validate(&input()).unwrap_err().to_string();
        assert!(e.contains("give a distribution"), "{e}");
    }
}
