//! `jamchart solve`: flags -> [`SolveQuestion`] -> [`SolveAnswer`] -> text or JSON.

use std::path::PathBuf;

use clap::Args;

use super::args::{DistArgs, ModelChoice, OutputFormat, SceneArgs};
use crate::ask::{DistAsk, SolveAnswer, SolveQuestion, Words};
use crate::error::{Error, Result};
use crate::models::ModelKind;
use crate::settings::flags::{DynamicsSet, Flags, MinNormSet};

/// Flags of `solve`.
#[derive(Debug, Clone, Args)]
pub struct SolveArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    #[command(flatten)]
    pub dynamics: Flags<DynamicsSet>,
    /// Write the dynamics time series to this CSV file (t, theta, x, x_dot, forces, penetration).
    ///
    /// Sampled every 0.2 ms: the data of the paper's Fig. 5. Use --after-jam to see the disc stop.
    #[arg(long, value_name = "FILE.csv", help_heading = "Dynamics")]
    pub series: Option<PathBuf>,
    /// Model to use.
    #[arg(long, value_enum, default_value_t = ModelChoice::One(ModelKind::Statics))]
    pub model: ModelChoice,
    #[command(flatten)]
    pub distribution: DistArgs,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
    #[command(flatten)]
    pub min_norm: Flags<MinNormSet>,
    /// Print the min-norm solver's convergence trace at theta_jam (the paper's Fig. 4).
    ///
    /// clarabel's objective phi^2 (N^2) and relative primal and dual residuals per
    /// interior-point iteration; in JSON the array `trace`.
    #[arg(long)]
    pub trace: bool,
}

pub fn run(a: &SolveArgs) -> Result<String> {
    let (config, uncertain) = a
        .scene
        .resolve_uncertain(&[a.dynamics.overrides(), a.min_norm.overrides()])?;
    let d = &a.distribution;
    let question = SolveQuestion {
        models: a.model.models(),
        distribution: DistAsk {
            before_mm: d.before_mm.clone(),
            quantiles: d.quantiles.as_slice().into(),
            samples: d.samples,
            seed: d.seed,
        },
        trace: a.trace,
        series: a.series.clone(),
        ..SolveQuestion::new(config, uncertain)
    };
    question.distribution.validate()?;
    // The command's own words for what its flags cannot do together, before the question's.
    if !question.uncertain.is_empty() && (a.series.is_some() || a.trace) {
        return Err(Error::Conflict {
            flag: if a.trace { "--trace" } else { "--series" },
            message: "--series and --trace follow one push; give single values with them, not \
                      a range"
                .into(),
        });
    }
    if a.series.is_some() && !question.models.contains(&ModelKind::Dynamics) {
        return Err(Error::Conflict {
            flag: "--series",
            message: "--series needs the dynamics: add --model dynamics".into(),
        });
    }
    // The scene's own warnings were given as it was read.
    super::warn(
        &question
            .unused_warning(Words::Flags)
            .into_iter()
            .collect::<Vec<_>>(),
    );
    let bar = std::sync::OnceLock::new();
    // Ctrl-C ends the process: the bar never stops the work itself.
    let answer = question.answer_observed(&|p| {
        match p {
            crate::ask::Progress::Started {
                samples,
                estimated_cpu_s,
            } => drop(bar.set(super::progress::long_work(samples, estimated_cpu_s))),
            crate::ask::Progress::Drawn(k) => bar.get().iter().for_each(|b| b.inc(k)),
        }
        crate::ask::Flow::Continue(())
    });
    bar.get().iter().for_each(|b| b.finish_and_clear());
    let answer: SolveAnswer = answer?;
    Ok(match a.format {
        OutputFormat::Json => super::json(&answer),
        OutputFormat::Text => answer.text(Words::Flags),
    })
}
