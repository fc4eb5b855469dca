//! `jamchart solve` over ranges and distributions: the closed form's exact box answer from its
//! corners, the other models' by sampling ([`crate::uncertain::range`]); text and JSON printed
//! from the typed answers.

use std::fmt::Write;

use clap::Args;
use serde::Serialize;

use super::args::{OutputFormat, parse_count, parse_f64};
use crate::config::Config;
use crate::error::Result;
use crate::models::{self, ModelKind};
use crate::numbers::Num;
use crate::scene::{JamStatus, SceneParams};
use crate::uncertain::UncertainSet;
use crate::uncertain::dist::{self, DistAnswer, DistMethod, DistQuestion, Estimate};
use crate::uncertain::range::{self, Corner, End, InputEnds, RangeAnswer, RangeMethod, Reached};

settings! {
    /// The flags of `solve` for distributed inputs, by the key the messages of its question
    /// name.
    section = "solve";
    aliases DIST_FLAGS {
        before_mm, flag: Some("before");
        quantiles, flag: Some("quantiles");
        samples, flag: Some("samples");
    }
}

/// Flags of `solve` for distributed inputs (ignored without one). Each takes a negative number
/// as its value, to refuse it naming the flag (clap otherwise read `--samples -1` as an unknown
/// flag `-1`).
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Uncertain inputs")]
pub struct DistArgs {
    /// Positions x (mm) for the probability that the disc jams before x (x_jam < x).
    ///
    /// With a distributed input (e.g. --mu normal(0.2,0.03)); a comma-separated list.
    #[arg(long = flag!(DIST_FLAGS, before_mm), value_name = "MM", value_delimiter = ',', value_parser = parse_f64,
          allow_negative_numbers = true)]
    pub before_mm: Vec<f64>,
    /// Probabilities q in (0, 1) of the quantiles of x_jam printed with a distributed input.
    #[arg(long = flag!(DIST_FLAGS, quantiles), value_name = "Q", value_delimiter = ',', value_parser = parse_f64,
          default_value = DEFAULT_QUANTILES, allow_negative_numbers = true)]
    pub quantiles: Vec<f64>,
    /// Monte Carlo samples where the answer is not exact.
    #[arg(long = flag!(DIST_FLAGS, samples), value_name = "N", long_help = samples_help(), value_parser = parse_count,
          allow_negative_numbers = true)]
    pub samples: Option<u64>,
    /// Seed of the Monte Carlo samples: the same seed gives the same answer on any number of
    /// threads.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 1,
        allow_negative_numbers = true
    )]
    pub seed: u64,
}

/// The quantiles printed unless --quantiles says otherwise.
const DEFAULT_QUANTILES: &str = "0.05,0.5,0.95";

/// Checks the distribution flags before anything is computed, whether or not an input is
/// distributed: `--before nan` was accepted silently with no distributed input. Where none is,
/// the flags have no effect and a warning says so (the answer is still given: a script that
/// passes them to every run keeps working).
pub(super) fn check_distribution_flags(d: &DistArgs, uncertain: &UncertainSet) -> Result<()> {
    DistQuestion {
        before_mm: d.before_mm.clone(),
        quantiles: d.quantiles.clone(),
        samples: d.samples.unwrap_or(STATICS_SAMPLES),
        seed: d.seed,
    }
    .validate()?;
    if uncertain.inputs.iter().any(|i| i.value.is_distribution()) {
        return Ok(());
    }
    let default = default_quantiles();
    let unused: Vec<&str> = [
        (!d.before_mm.is_empty(), "--before"),
        (d.quantiles != default, "--quantiles"),
        (d.samples.is_some(), "--samples"),
    ]
    .into_iter()
    .filter_map(|(given, flag)| given.then_some(flag))
    .collect();
    if !unused.is_empty() {
        super::warn(&[format!(
            "{} {} no effect without a distributed input (e.g. --mu normal(0.2,0.03))",
            unused.join(", "),
            if unused.len() == 1 { "has" } else { "have" }
        )]);
    }
    Ok(())
}

/// Monte Carlo samples of the closed form unless --samples says otherwise: 100,000 take a few
/// ms and give P to +-0.003.
const STATICS_SAMPLES: u64 = 100_000;

/// Monte Carlo samples of min-norm and the simulation unless --samples says otherwise.
const MODEL_SAMPLES: u64 = 2_000;

/// Monte Carlo of `spec`, with a progress bar on a terminal where it is estimated to take more
/// than a few seconds ([`super::progress::long_work`]).
fn sampled(
    spec: &crate::models::ModelSpec,
    config: &Config,
    uncertain: &UncertainSet,
    ask: &DistQuestion,
) -> Result<DistAnswer> {
    let bar = std::sync::OnceLock::new();
    let answer = dist::monte_carlo_observed(spec, &config.scene, uncertain, ask, &|p| match p {
        dist::Progress::Started {
            samples,
            estimated_cpu_s,
        } => drop(bar.set(super::progress::long_work(samples, estimated_cpu_s))),
        dist::Progress::Drawn(k) => bar.get().iter().for_each(|b| b.inc(k)),
    });
    bar.get().iter().for_each(|b| b.finish_and_clear());
    answer
}

/// The long help of --samples, with the counts of the code.
fn samples_help() -> String {
    format!(
        "Monte Carlo samples where the answer is not exact (unset: {STATICS_SAMPLES} for the \
         statics, {MODEL_SAMPLES} for min-norm and dynamics).\n\nThe statics are exact (the \
         monotone map) where one distribution is the only uncertain input (no range beside it) \
         and its support keeps some friction; several inputs or the other models are sampled, \
         with 95 % intervals printed. At most {}.",
        dist::MAX_SAMPLES
    )
}

/// One model's answer over the box, and over the distribution where an input has one: the
/// record `solve --format json` prints for it (and the Python package returns).
#[derive(Serialize)]
pub(crate) struct Record {
    pub(crate) model: &'static str,
    #[serde(flatten)]
    pub(crate) range: RangeAnswer,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(crate) distribution: Option<DistAnswer>,
}

/// The JSON document of `solve --format json` with uncertain inputs.
#[derive(Serialize)]
struct Document<'a> {
    /// The scene at the nominal values.
    inputs: &'a SceneParams,
    uncertain: &'a UncertainSet,
    results: Vec<Record>,
}

/// Answers the box of `uncertain` around `config` with each of `models`, in `format`.
pub(super) fn run(
    models: Vec<ModelKind>,
    distribution: &DistArgs,
    format: OutputFormat,
    config: &Config,
    uncertain: &UncertainSet,
) -> Result<String> {
    let results = models
        .into_iter()
        .map(|kind| answer(kind, config, uncertain, distribution))
        .collect::<Result<Vec<Record>>>()?;
    Ok(match format {
        OutputFormat::Json => {
            let doc = Document {
                inputs: &config.scene,
                uncertain,
                results,
            };
            serde_json::to_string_pretty(&doc).expect("plain structs serialise") + "\n"
        }
        OutputFormat::Text => text(&config.scene, uncertain, &results),
    })
}

/// Model `kind`'s answer over the box of `uncertain` around `config`, and over the
/// distribution where an input has one, as `d` asks.
pub(crate) fn answer(
    kind: ModelKind,
    config: &Config,
    uncertain: &UncertainSet,
    d: &DistArgs,
) -> Result<Record> {
    let has_distribution = uncertain.inputs.iter().any(|i| i.value.is_distribution());
    let spec = kind.with(&config.min_norm, &config.dynamics);
    let ask = DistQuestion {
        before_mm: d.before_mm.clone(),
        quantiles: d.quantiles.clone(),
        samples: d.samples.unwrap_or(match kind {
            ModelKind::Statics => STATICS_SAMPLES,
            _ => MODEL_SAMPLES,
        }),
        seed: d.seed,
    };
    ask.validate()?;
    let distribution = match has_distribution {
        false => None,
        true if kind == ModelKind::Statics => match dist::exact(&config.scene, uncertain, &ask) {
            Some(x) => Some(x),
            None => Some(sampled(&spec, config, uncertain, &ask)?),
        },
        true => Some(sampled(&spec, config, uncertain, &ask)?),
    };
    let range = match kind {
        ModelKind::Statics => range::closed_form(&config.scene, uncertain)?,
        _ => range::sampled(&spec, &config.scene, uncertain)?,
    };
    Ok(Record {
        model: kind.as_str(),
        range,
        distribution,
    })
}

/// The quantiles asked unless --quantiles says otherwise.
pub(crate) fn default_quantiles() -> Vec<f64> {
    DEFAULT_QUANTILES
        .split(',')
        .map(|q| q.parse().expect("a number"))
        .collect()
}

fn text(p: &SceneParams, uncertain: &UncertainSet, results: &[Record]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "scene: r = {} mm, g = {} m/s^2, start at {} deg, palm {} mm; nominal mu_ground = {}, \
         mu_palm = {}, m = {} kg, F = {} N",
        Num(p.radius_mm),
        Num(p.gravity_m_s2),
        Num(p.start_angle_deg),
        Num(p.palm_length_mm),
        Num(p.mu_ground),
        Num(p.mu_palm),
        Num(p.mass_kg),
        Num(p.force_n)
    );
    let _ = writeln!(s, "uncertain: {}", uncertain.describe());
    for note in uncertain.box_notes() {
        let _ = writeln!(s, "  {note}");
    }
    for r in results {
        let a = &r.range;
        let how = match a.method {
            RangeMethod::Corners => "exact: theta_jam is monotone in every input, so the box is \
                                answered from its corners"
                .to_string(),
            RangeMethod::Sampled { samples } => format!(
                "sampled at {samples} points of a grid over the box: the range of the samples, \
                 not a bound"
            ),
        };
        let _ = writeln!(s, "\n{} over the box ({how}):", r.model);
        let names: Vec<&str> = a.inputs.iter().map(|i| i.name).collect();
        let at = |c: &Corner| {
            let v: Vec<String> = names
                .iter()
                .zip(&c.values)
                .map(|(n, v)| format!("{n} = {}", round(*v)))
                .collect();
            v.join(", ")
        };
        let point = match a.method {
            RangeMethod::Corners => "corner",
            RangeMethod::Sampled { .. } => "sample",
        };
        match (a.theta_jam_deg, a.x_jam_mm, a.reached) {
            (Some([t0, t1]), Some([x0, x1]), Some([low, high])) => {
                let _ = writeln!(
                    s,
                    "  theta_jam from {t0:.3} to {t1:.3} deg, x_jam from {x0:.3} to {x1:.3} mm, \
                     over the points that jam on the palm or are held at the start",
                    t0 = Num(t0),
                    t1 = Num(t1),
                    x0 = Num(x0),
                    x1 = Num(x1)
                );
                for (what, c, how, t, x) in [
                    (
                        "earliest jam (nearest the hinge)",
                        &a.earliest,
                        high,
                        t1,
                        x0,
                    ),
                    ("latest jam (furthest out)", &a.latest, low, t0, x1),
                ] {
                    let reached = match how {
                        Reached::Corner => format!("at the {point} {}, {}", at(c), c.status),
                        Reached::HeldAtStart => format!(
                            "held at the start where the push just moves the disc; the corner \
                             {} is {}",
                            at(c),
                            c.status
                        ),
                        Reached::PalmEnd => {
                            format!("at the palm's end; the corner {} is {}", at(c), c.status)
                        }
                    };
                    let _ = writeln!(
                        s,
                        "  {what}: theta_jam = {t:.3} deg, x_jam = {x:.3} mm, {reached}",
                        t = Num(t),
                        x = Num(x)
                    );
                }
            }
            _ if a.statuses == [JamStatus::OutsideModel] => {
                if let Some(why) = models::outside(ModelKind::Statics, p) {
                    let _ = writeln!(s, "  not run: {why}");
                }
            }
            _ => {
                let _ = writeln!(
                    s,
                    "  no point of the box jams on the palm or is held at the start"
                );
                let _ = writeln!(
                    s,
                    "  the {point}s where it would jam earliest and latest: {}, {}; {}, {}",
                    at(&a.earliest),
                    a.earliest.status,
                    at(&a.latest),
                    a.latest.status
                );
            }
        }
        let others = if a.inputs.len() > 1 {
            " (the other inputs at their nominal values)"
        } else {
            ""
        };
        for i in &a.inputs {
            let _ = writeln!(s, "  {}{others}", segments_text(i));
        }
        let seen: Vec<&str> = a.statuses.iter().map(|s| s.as_str()).collect();
        let _ = writeln!(s, "  statuses in the box: {}", seen.join(", "));
        if let Some(d) = &r.distribution {
            distribution_text(&mut s, d);
        }
    }
    s
}

/// The probabilities and quantiles, with the sample count and interval widths of a Monte Carlo.
fn distribution_text(s: &mut String, d: &DistAnswer) {
    let how = match d.method {
        DistMethod::Exact => "exact, by the monotone map of the input's distribution".to_string(),
        DistMethod::MonteCarlo {
            samples,
            seed,
            without_jam,
        } => format!(
            "Monte Carlo, {samples} samples (seed {seed}{}; ranges drawn as uniform), 95 % \
             intervals",
            match without_jam {
                0 => String::new(),
                k => format!(", {k} without a jam position"),
            }
        ),
    };
    let _ = writeln!(s, "  distribution of x_jam on a long enough palm ({how}):");
    let interval = |e: &Estimate, digits: usize| match d.method {
        DistMethod::Exact => String::new(),
        DistMethod::MonteCarlo { .. } => format!(
            " [{:.digits$}, {:.digits$}] (width {:.digits$})",
            Num(e.lo),
            Num(e.hi),
            Num(e.hi - e.lo)
        ),
    };
    for b in &d.before {
        let _ = writeln!(
            s,
            "    P(jams before x = {} mm) = {:.4}{}",
            Num(b.x_mm),
            Num(b.probability.value),
            interval(&b.probability, 4)
        );
    }
    for q in &d.quantiles {
        let _ = writeln!(
            s,
            "    {:>4} % quantile of x_jam = {:.3} mm{}",
            round(100.0 * q.q),
            Num(q.x_jam_mm.value),
            interval(&q.x_jam_mm, 3)
        );
    }
}

/// `mu: beyond_reach for mu < 0.148, jams from 0.148 to 0.3; the jam comes earliest at the
/// high end`.
fn segments_text(i: &InputEnds) -> String {
    let n = i.name;
    let parts: Vec<String> = match &i.segments[..] {
        [one] => vec![format!("{} over the whole range", one.status)],
        segs => segs
            .iter()
            .enumerate()
            .map(|(j, g)| match j {
                _ if g.from == g.to => format!("{} at {n} = {}", g.status, round(g.from)),
                0 => format!("{} for {n} < {}", g.status, round(g.to)),
                _ => format!("{} from {} to {}", g.status, round(g.from), round(g.to)),
            })
            .collect(),
    };
    let end = match i.earliest_at {
        End::Low => "low",
        End::High => "high",
    };
    format!(
        "{n} in [{}, {}]: {}; the jam comes earliest at the {end} end",
        round(i.lo),
        round(i.hi),
        parts.join(", ")
    )
}

/// Four significant digits: a breakpoint found to 1e-9 of the range reads as 0.1484.
fn round(v: f64) -> String {
    crate::numbers::sig(v, 4)
}
