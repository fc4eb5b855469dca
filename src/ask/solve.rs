//! [`SolveQuestion`]: where does the part jam, by which models; for one push, or over the box
//! of its ranges and distributions (the interval, P(jam before x), the quantiles).

use std::path::PathBuf;

use serde::Serialize;
use smallvec::SmallVec;

use super::{Keywords, Words};
use crate::config::Config;
use crate::dynamics::{DynamicsParams, DynamicsSolution};
use crate::error::{Error, Result};
use crate::minnorm::qp::{HoldStatus, TracePoint};
use crate::models::{self, Detail, ModelKind, ModelSpec, Outcome, Solution};
use crate::scene::SceneParams;
use crate::settings::Decl;
use crate::uncertain::Flow;
use crate::uncertain::UncertainSet;
use crate::uncertain::dist::{self, DistAnswer, DistQuestion, Progress};
use crate::uncertain::range::{self, RangeAnswer};

settings! {
    /// The keys of a distribution's question, with the flags of `solve` that give them.
    section = "solve";
    aliases DIST_KEYS {
        /// Positions x to give P(x_jam < x) at: the probability that the part jams before
        /// reaching each (a distributed input only).
        before_mm, flag: Some("before"), unit: "mm";
        /// Probabilities (0 to 1) to give the quantiles of x_jam at (a distributed input
        /// only; default 0.05, 0.5, 0.95).
        quantiles, flag: Some("quantiles"), unit: "-";
        /// Monte Carlo samples where the answer is sampled (default 100,000 for the closed
        /// form, 2,000 for the other models).
        samples, flag: Some("samples"), unit: "-";
    }
}

/// Monte Carlo samples of the closed form unless asked otherwise: 100,000 take a few ms and
/// give P to +-0.003.
pub(crate) const STATICS_SAMPLES: u64 = 100_000;

/// Monte Carlo samples of min-norm and the simulation unless asked otherwise.
pub(crate) const MODEL_SAMPLES: u64 = 2_000;

/// The quantiles asked unless the question says otherwise.
const DEFAULT_QUANTILES: [f64; 3] = [0.05, 0.5, 0.95];

/// Sampling interval of a simulation's time series in s: 0.2 ms resolves the collapse at the
/// jam (a few ms).
const SERIES_DT_S: f64 = 2e-4;

/// The models a question asks, in the order they answer: each at most once, so held without
/// an allocation.
pub type Models = SmallVec<[ModelKind; ModelKind::ALL.len()]>;

/// What is asked of a distributed input: probabilities, quantiles, and the Monte Carlo's
/// samples and seed where the answer is not exact.
#[derive(Debug, Clone, PartialEq)]
pub struct DistAsk {
    /// Positions x in mm for P(x_jam < x) (default: none).
    pub before_mm: Vec<f64>,
    /// Probabilities q in (0, 1) of the quantiles of x_jam (default: 0.05, 0.5, 0.95, held
    /// without an allocation).
    pub quantiles: SmallVec<[f64; 3]>,
    /// Monte Carlo samples where the answer is not exact (default: 100,000 for the statics,
    /// 2,000 for min-norm and dynamics).
    pub samples: Option<u64>,
    /// The Monte Carlo's seed: the same seed gives the same answer on any number of threads
    /// (default: 1).
    pub seed: u64,
}

impl Default for DistAsk {
    fn default() -> Self {
        DistAsk {
            before_mm: Vec::new(),
            quantiles: SmallVec::from(DEFAULT_QUANTILES),
            samples: None,
            seed: 1,
        }
    }
}

impl DistAsk {
    /// The question to the distribution's code for model `kind` (its default sample count).
    fn for_model(&self, kind: ModelKind) -> DistQuestion {
        DistQuestion {
            before_mm: self.before_mm.clone(),
            quantiles: self.quantiles.to_vec(),
            samples: self.samples.unwrap_or(match kind {
                ModelKind::Statics => STATICS_SAMPLES,
                _ => MODEL_SAMPLES,
            }),
            seed: self.seed,
        }
    }

    /// Checks the question, whether or not an input is distributed: a count in range,
    /// probabilities in (0, 1), finite positions, none given twice.
    pub fn validate(&self) -> Result<()> {
        let samples = self.samples.unwrap_or(STATICS_SAMPLES);
        DistQuestion::check(samples, &self.quantiles, &self.before_mm)
    }

    /// The keys given away from their defaults.
    fn given(&self) -> Vec<&'static str> {
        [
            (!self.before_mm.is_empty(), "before_mm"),
            (self.quantiles[..] != DEFAULT_QUANTILES, "quantiles"),
            (self.samples.is_some(), "samples"),
        ]
        .into_iter()
        .filter_map(|(given, key)| given.then_some(key))
        .collect()
    }
}

/// `jamchart solve`'s question: a scene, the models to answer it, and what to ask of its
/// distributions.
///
/// With no range or distribution it is one push: each model's [`Solution`]. With some it is
/// the box they span: the closed form answers it exactly from its corners (theta_jam is
/// monotone in every input) and one distribution exactly by the monotone map; several
/// distributions, a range beside one, or the other models are sampled.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(try_from = "Keywords")]
pub struct SolveQuestion {
    /// The scene at its nominal values, and the models' settings.
    pub config: Config,
    /// The scene's ranges and distributions (empty: one push).
    pub uncertain: UncertainSet,
    /// The models, in the order they answer (default: the statics).
    pub models: Models,
    /// What to ask of a distributed input (ignored without one).
    pub distribution: DistAsk,
    /// Record clarabel's convergence trace at the min-norm jam (the paper's Fig. 4).
    pub trace: bool,
    /// Write the simulation's time series to this CSV file (every 0.2 ms; the columns of
    /// `render fig5`), atomically. Never from keywords: a face that writes files sets it.
    pub series: Option<PathBuf>,
}

impl SolveQuestion {
    /// One push of `config`'s scene by the closed form.
    pub fn new(config: Config, uncertain: UncertainSet) -> Self {
        SolveQuestion {
            config,
            uncertain,
            models: smallvec::smallvec![ModelKind::Statics],
            distribution: DistAsk::default(),
            trace: false,
            series: None,
        }
    }

    /// One push of `scene` by the closed form, every other setting at its default: the
    /// question [`SolveQuestion::from_numbers`] makes of a scene's numbers, so that a face
    /// that holds an answer's scene can ask it again.
    pub fn of_scene(scene: SceneParams) -> Self {
        let config = Config {
            scene,
            ..Config::default()
        };
        Self::new(config, UncertainSet::default())
    }

    /// The question of `keywords`: every setting of the palm scene and its models (`mu`,
    /// `radius_mm`, `rtol`, ...; a range or distribution as text), `push_ratio` (sets
    /// force_n = push_ratio m g), `model` (`statics`, `min-norm`, `dynamics` or `all`),
    /// `before_mm`, `quantiles`, `samples`, `seed` and `trace`.
    pub fn from_keywords(mut kw: Keywords) -> Result<Self> {
        Self::refuse_two_pushes(&kw.0.keys().map(String::as_str).collect::<Vec<_>>())?;
        let models = match kw.take_name("model")? {
            None => smallvec::smallvec![ModelKind::Statics],
            Some(name) => models_named(&name)?,
        };
        let mut distribution = DistAsk::default();
        if let Some(v) = kw.take_numbers("before_mm")? {
            distribution.before_mm = v;
        }
        if let Some(v) = kw.take_numbers("quantiles")? {
            distribution.quantiles = v.into();
        }
        distribution.samples = kw.take_count("samples", 1)?;
        if let Some(seed) = kw.take_count("seed", 0)? {
            distribution.seed = seed;
        }
        let trace = kw.take_switch("trace")?.unwrap_or(false);
        let push_ratio = kw.take_number("push_ratio")?;
        let over = kw.into_overrides(crate::settings::palm_family(), &OWN_KEYS)?;
        let (mut config, uncertain) = super::palm_scene(Default::default(), over)?;
        if let Some(ratio) = push_ratio {
            push_by_ratio(&mut config, &uncertain, ratio)?;
        }
        let question = SolveQuestion {
            config,
            uncertain,
            models,
            distribution,
            trace,
            series: None,
        };
        question.check()?;
        Ok(question)
    }

    /// [`SolveQuestion::from_keywords`] of keys that are each given a number (`mu = 0.3,
    /// radius_mm = 12`): the same question, or the same refusal. A key given twice keeps its
    /// last number, as in [`Keywords`].
    ///
    /// Numbers of `[scene]`, its aliases and `push_ratio` (the common question: one push of
    /// the closed form) are checked and set in place on the default config, whose other
    /// sections hold nothing to check; a Python loop of scalar calls spent most of its time
    /// on the keyword map and on checking the defaults of every section. Any other key goes
    /// through the keyword map. The question is [`SolveQuestion::of_scene`] of its scene.
    pub fn from_numbers(numbers: &[(&str, f64)]) -> Result<Self> {
        let general = || {
            let pairs = numbers
                .iter()
                .map(|&(k, x)| (k.into(), toml::Value::Float(x)));
            Self::from_keywords(Keywords::new(pairs))
        };
        let mut scene: SmallVec<[(&'static Decl, f64); 12]> = SmallVec::new();
        let mut push_ratio = None;
        for (i, &(key, x)) in numbers.iter().enumerate() {
            if numbers[..i].iter().any(|&(k, _)| k == key) {
                return general();
            }
            match crate::config::scene_decls().find(|d| d.key == key) {
                Some(decl) => scene.push((decl, x)),
                None if key == "push_ratio" => push_ratio = Some(x),
                None => return general(),
            }
        }
        if push_ratio.is_some() {
            let keys: Vec<&str> = numbers.iter().map(|&(k, _)| k).collect();
            Self::refuse_two_pushes(&keys)?;
        }
        // The keyword map's order, where its first refusal is found. Each number checked
        // against its setting is the whole scene checked: the other fields hold their
        // defaults, and an alias checks its number as each field it sets does
        // (`a_question_of_scene_numbers_has_nothing_else_to_check`).
        scene.sort_unstable_by_key(|&(decl, _)| decl.key);
        for &(decl, x) in &scene {
            decl.check_real(x)?;
        }
        // The question of the default scene, its numbers set: `of_scene` of the scene they
        // make. Nothing beyond the scene to check: the default min-norm and dynamics settings
        // and the default distribution's question are valid as they are.
        let mut question = SolveQuestion::of_scene(SceneParams::default());
        if crate::config::set_scene_numbers(&mut question.config.scene, &scene).is_none() {
            return general();
        }
        if let Some(ratio) = push_ratio {
            push_by_ratio(&mut question.config, &question.uncertain, ratio)?;
        }
        Ok(question)
    }

    /// Refuses `keys` (a question's keys, or a face's) that set the push two ways: `force_n`
    /// and `push_ratio` together.
    pub fn refuse_two_pushes(keys: &[&str]) -> Result<()> {
        match keys.contains(&"force_n") && keys.contains(&"push_ratio") {
            true => Err(Error::Conflict {
                flag: "push_ratio",
                message: "force_n and push_ratio both set the push: give one of them".into(),
            }),
            false => Ok(()),
        }
    }

    /// Checks what the question asks beyond its scene (the scene is checked as it is built):
    /// the distribution's question, whether or not an input is distributed; a trace or a
    /// series, which follow one push.
    pub fn check(&self) -> Result<()> {
        self.distribution.validate()?;
        if !self.uncertain.is_empty() {
            for (asked, key) in [(self.trace, "trace"), (self.series.is_some(), "series")] {
                if asked {
                    return Err(Error::invalid(
                        key,
                        "given",
                        "a trace or a series follows one push; give single values with it, \
                         not a range or a distribution",
                    ));
                }
            }
        }
        if self.series.is_some() && !self.models.contains(&ModelKind::Dynamics) {
            return Err(Error::invalid(
                "series",
                "given",
                "a time series comes from the dynamics: ask model dynamics",
            ));
        }
        Ok(())
    }

    /// What the user may have got wrong, with the answer still given: a value that looks like
    /// a unit mistake ([`SceneParams::unit_warnings`]), then [`SolveQuestion::unused_warning`].
    pub fn warnings(&self, words: Words) -> Vec<String> {
        let mut out = self.config.scene.unit_warnings();
        out.extend(self.unused_warning(words));
        out
    }

    /// A distribution's key given without a distributed input: it has no effect, and the
    /// answer is still given (a script that passes it to every run keeps working).
    pub fn unused_warning(&self, words: Words) -> Option<String> {
        let distributed = self
            .uncertain
            .inputs
            .iter()
            .any(|i| i.value.is_distribution());
        let unused = self.distribution.given();
        if distributed || unused.is_empty() {
            return None;
        }
        let names: Vec<String> = unused.iter().map(|k| words.name(k)).collect();
        let example = match words {
            Words::Flags => "--mu normal(0.2,0.03)",
            Words::Keys => "mu = \"normal(0.2,0.03)\"",
        };
        Some(format!(
            "{} {} no effect without a distributed input (e.g. {example})",
            names.join(", "),
            if names.len() == 1 { "has" } else { "have" }
        ))
    }

    /// The outcome of the question's one answer, where it is known without the answer's
    /// record: one push, asked of one model that gives its outcome alone
    /// ([`crate::models::outcome`]: the closed form). Its model, status, theta_jam and x_jam
    /// are those of [`SolveQuestion::answer`]'s record to the bit, and a question that
    /// `answer` refuses is refused; a face that shows the record asks `answer` when it is
    /// read. None for any other question.
    pub fn outcome(&self) -> Result<Option<Outcome>> {
        self.check()?;
        let ([kind], true) = (&self.models[..], self.uncertain.is_empty()) else {
            return Ok(None);
        };
        models::outcome(
            &kind.with(&self.config.min_norm, &self.config.dynamics),
            &self.config.scene,
        )
    }

    /// Answers the question.
    pub fn answer(&self) -> Result<SolveAnswer> {
        self.answer_observed(&|_| Flow::Continue(()))
    }

    /// [`SolveQuestion::answer`], telling `progress` how a Monte Carlo goes (its estimate,
    /// then each chunk of samples as it is drawn, from any thread); `progress` answering
    /// [`Flow::Break`] stops the draws (a face's Ctrl-C), and the answer is
    /// [`Error::Stopped`].
    pub fn answer_observed(
        &self,
        progress: &(dyn Fn(Progress) -> Flow + Sync),
    ) -> Result<SolveAnswer> {
        self.check()?;
        if !self.uncertain.is_empty() {
            let results = self
                .models
                .iter()
                .map(|&kind| self.box_record(kind, progress))
                .collect::<Result<Vec<BoxRecord>>>()?;
            return Ok(SolveAnswer::Box(BoxAnswer {
                inputs: self.config.scene,
                uncertain: self.uncertain.clone(),
                results,
            }));
        }
        if let Some(path) = &self.series {
            // Before the simulation runs: a path that will be refused is refused now, and a
            // series too long to hold is refused by its estimate.
            crate::atomic::check_all([path.as_path()])?;
            let rows = crate::limits::series_rows(
                self.config.scene.start_angle_deg,
                self.config.dynamics.drive.omega_deg_s,
                SERIES_DT_S,
            );
            crate::limits::check_items("--omega (omega_deg_s)", rows, crate::limits::SERIES_ROW)?;
        }
        let mut results = Vec::with_capacity(self.models.len());
        for &kind in &self.models {
            let mut spec = kind.with(&self.config.min_norm, &self.config.dynamics);
            if let ModelSpec::Dynamics { series_dt_s, .. } = &mut spec {
                *series_dt_s = self.series.as_ref().map(|_| SERIES_DT_S);
            }
            let solution = models::solve(&spec, &self.config.scene)?;
            results.push(self.push_record(solution)?);
        }
        Ok(SolveAnswer::Push(Box::new(PushAnswer {
            inputs: self.config.scene,
            results,
            config: self.config.clone(),
            series: self.series.clone(),
        })))
    }

    /// What the question asks of one model's answer beyond the port: a trace, a series.
    fn push_record(&self, solution: Solution) -> Result<PushRecord> {
        let trace = match &solution.detail {
            Detail::MinNorm(s) if self.trace => {
                let theta_deg = s.theta_jam_deg.unwrap_or(self.config.scene.start_angle_deg);
                let traced = crate::minnorm::palm::trace_at(
                    &self.config.scene,
                    theta_deg,
                    &self.config.min_norm,
                )?;
                Some(Trace {
                    trace_theta_deg: theta_deg,
                    trace_status: traced.status,
                    trace: traced.trace,
                })
            }
            _ => None,
        };
        let dynamics = match &solution.detail {
            Detail::Dynamics(d) => {
                if let Some(path) = &self.series {
                    let csv = crate::figures::time_series::series_csv(
                        &self.config.scene,
                        &self.config.dynamics,
                        &d.series,
                    );
                    crate::atomic::write_atomic(path, &csv)?;
                }
                Some(Box::new(DynamicsRecord::of(
                    d,
                    &self.config,
                    self.series.as_deref(),
                )))
            }
            _ => None,
        };
        Ok(PushRecord {
            solution,
            trace,
            dynamics,
        })
    }

    /// Model `kind`'s answer over the box, and over the distribution where an input has one.
    fn box_record(
        &self,
        kind: ModelKind,
        progress: &(dyn Fn(Progress) -> Flow + Sync),
    ) -> Result<BoxRecord> {
        let scene = &self.config.scene;
        let has_distribution = self
            .uncertain
            .inputs
            .iter()
            .any(|i| i.value.is_distribution());
        let spec = kind.with(&self.config.min_norm, &self.config.dynamics);
        let ask = self.distribution.for_model(kind);
        ask.validate()?;
        let sampled = || dist::monte_carlo_observed(&spec, scene, &self.uncertain, &ask, progress);
        let distribution = match has_distribution {
            false => None,
            true if kind == ModelKind::Statics => match dist::exact(scene, &self.uncertain, &ask) {
                Some(x) => Some(x),
                None => Some(sampled()?),
            },
            true => Some(sampled()?),
        };
        let range = match kind {
            ModelKind::Statics => range::closed_form(scene, &self.uncertain)?,
            _ => range::sampled(&spec, scene, &self.uncertain)?,
        };
        Ok(BoxRecord {
            model: kind.as_str(),
            range,
            distribution,
        })
    }
}

/// The question's own keys, besides the settings.
const OWN_KEYS: [&str; 8] = [
    "model",
    "before_mm",
    "quantiles",
    "samples",
    "seed",
    "trace",
    "push_ratio",
    "series",
];

impl TryFrom<Keywords> for SolveQuestion {
    type Error = Error;

    fn try_from(kw: Keywords) -> Result<Self> {
        SolveQuestion::from_keywords(kw)
    }
}

/// The models named `name`: one of the port's (`min_norm` spelt either way), or `all`.
fn models_named(name: &str) -> Result<Models> {
    if name == "all" {
        return Ok(ModelKind::ALL.into());
    }
    ModelKind::ALL
        .into_iter()
        .find(|k| k.as_str() == name || k.as_str().replace('-', "_") == name)
        .map(|k| smallvec::smallvec![k])
        .ok_or_else(|| {
            let names: Vec<&str> = ModelKind::ALL.iter().map(|k| k.as_str()).collect();
            Error::invalid(
                "model",
                name,
                format!("the models are {} (or all)", names.join(", ")),
            )
        })
}

/// Sets the push from `ratio` = F / (m g), refused with an uncertain mass or push (the ratio
/// is of one weight).
fn push_by_ratio(config: &mut Config, uncertain: &UncertainSet, ratio: f64) -> Result<()> {
    let decl = crate::scene::Param::PushRatio.decl();
    decl.check_real(ratio)?;
    if let Some(i) = uncertain.inputs.iter().find(|i| {
        i.keys
            .iter()
            .any(|k| matches!(*k, "mass_kg" | "force_n" | "gravity_m_s2"))
    }) {
        return Err(Error::invalid(
            "push_ratio",
            crate::settings::number_text(ratio),
            format!(
                "{} is uncertain, and push_ratio sets force_n from one weight; give force_n's \
                 range instead",
                i.name
            ),
        ));
    }
    config.scene = crate::scene::Param::PushRatio.apply(config.scene, ratio);
    config.scene.validate()
}

/// The answer to a [`SolveQuestion`]: one push's, or the box's.
///
/// Its serde form is `jamchart solve --format json`'s document.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum SolveAnswer {
    /// One push: each model's solution.
    Push(Box<PushAnswer>),
    /// A box of pushes: each model's interval, and the distribution's probabilities.
    Box(BoxAnswer),
}

impl SolveAnswer {
    /// The command line's report, in `words`.
    pub fn text(&self, words: Words) -> String {
        match self {
            SolveAnswer::Push(a) => a.text(words),
            SolveAnswer::Box(a) => a.text(words),
        }
    }

    /// The verdict in one line.
    pub fn headline(&self) -> String {
        match self {
            SolveAnswer::Push(a) => a.headline(),
            SolveAnswer::Box(a) => a.headline(),
        }
    }
}

/// One push's answers.
#[derive(Debug, Clone, Serialize)]
pub struct PushAnswer {
    /// The scene answered.
    pub inputs: SceneParams,
    /// Each model's answer, in the order asked.
    pub results: Vec<PushRecord>,
    /// The models' settings the scene was answered with.
    #[serde(skip)]
    pub config: Config,
    /// Where the time series was written, if it was.
    #[serde(skip)]
    pub series: Option<PathBuf>,
}

/// One model's answer to a push: the port's solution, and what the question asked of it
/// beyond (a min-norm trace; a simulation's settings, series and advice).
#[derive(Debug, Clone, Serialize)]
pub struct PushRecord {
    /// The port's answer.
    #[serde(flatten)]
    pub solution: Solution,
    /// clarabel's trace at the jam, where asked.
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub trace: Option<Trace>,
    /// A simulation's settings, series and advice (boxed: an answer of the other models does
    /// not carry its room).
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<Box<DynamicsRecord>>,
}

/// clarabel's convergence trace at one palm angle (the paper's Fig. 4).
#[derive(Debug, Clone, Serialize)]
pub struct Trace {
    /// The palm angle traced in deg: theta_jam, or the start angle when there is no jam.
    pub trace_theta_deg: f64,
    /// clarabel's verdict there.
    pub trace_status: HoldStatus,
    /// Its objective and residuals per interior-point iteration.
    pub trace: Vec<TracePoint>,
}

/// What a simulation's answer adds: the series written, the `[dynamics]` settings in force (so
/// that the answer can be reproduced) and what to do about a typed reason.
#[derive(Debug, Clone, Serialize)]
pub struct DynamicsRecord {
    /// The series file.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series: Option<String>,
    /// Rows written to the series.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_rows: Option<usize>,
    /// Where the series ends and why.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub series_end: Option<String>,
    /// The simulation's settings.
    pub settings: DynamicsParams,
    /// What to do about a `cross_check` or `failure`, naming the flags that act on it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub advice: Option<String>,
}

impl DynamicsRecord {
    fn of(s: &DynamicsSolution, config: &Config, series: Option<&std::path::Path>) -> Self {
        DynamicsRecord {
            series: series.map(|p| p.display().to_string()),
            series_rows: series.map(|_| s.series.len()),
            series_end: series.map(|_| super::solve_text::series_end(config, s, Words::Flags)),
            settings: config.dynamics,
            advice: super::solve_text::dynamics_advice(s, Words::Flags),
        }
    }
}

/// The answers over the box of a scene's ranges and distributions.
#[derive(Debug, Clone, Serialize)]
pub struct BoxAnswer {
    /// The scene at the nominal values.
    pub inputs: SceneParams,
    /// The ranges and distributions.
    pub uncertain: UncertainSet,
    /// Each model's answer, in the order asked.
    pub results: Vec<BoxRecord>,
}

/// One model's answer over the box, and over the distribution where an input has one.
#[derive(Debug, Clone, Serialize)]
pub struct BoxRecord {
    /// The model that answered.
    pub model: &'static str,
    /// The interval of theta_jam and x_jam over the box.
    #[serde(flatten)]
    pub range: RangeAnswer,
    /// P(x_jam < x) and the quantiles, with a distributed input.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distribution: Option<DistAnswer>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`SolveQuestion::from_numbers`] checks each number given against its own setting and
    /// nothing else: that is the whole question checked only while the defaults of every
    /// section and of the distribution's question are valid, and an alias refuses what each
    /// field it sets refuses.
    #[test]
    fn a_question_of_scene_numbers_has_nothing_else_to_check() {
        Config::default().validate().unwrap();
        SolveQuestion::new(Config::default(), UncertainSet::default())
            .check()
            .unwrap();
        for alias in crate::config::scene_decls().filter(|d| !d.sets.is_empty()) {
            for key in alias.sets {
                let field = crate::config::scene_decls()
                    .find(|d| d.key == *key)
                    .unwrap();
                assert_eq!(alias.check, field.check, "{} sets {key}", alias.key);
            }
        }
    }
}
