//! Flags shared by subcommands, and their merge over a TOML parameter file.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use crate::config::Config;
use crate::error::Result;
use crate::models::ModelKind;
pub use crate::settings::decl::{parse_count, parse_count_usize, parse_f64};
use crate::settings::flags::{Flags, SceneSet};
use crate::uncertain::UncertainSet;

/// Scene flags over `--config FILE`: each flag is a declared setting of `[scene]`
/// ([`crate::settings`]), and overrides the same key of the file (or of the defaults).
#[derive(Debug, Clone, Default, Args)]
pub struct SceneArgs {
    /// TOML parameter file (e.g. config/paper.toml); flags override it.
    ///
    /// Sections and keys as in config/paper.toml (`jamchart settings` lists them); unknown keys
    /// are refused. Without it the defaults (the paper's parameters) apply.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    #[command(flatten)]
    pub flags: Flags<SceneSet>,
}

impl SceneArgs {
    /// Defaults, then the file, then these flags, then the `more` flags of the command (each a
    /// table shaped like a parameter file); validated before anything is computed. A range or a
    /// distribution is refused: `command` answers a point.
    pub fn resolve(&self, more: &[toml::Table], command: &str) -> Result<Config> {
        let (config, uncertain) = self.resolve_uncertain(more)?;
        match uncertain.inputs.first() {
            None => Ok(config),
            Some(i) => Err(crate::error::Error::invalid(
                i.name,
                i.value,
                format!(
                    "{command} takes a single value; a range or a distribution is answered by \
                     solve and sweep"
                ),
            )),
        }
    }

    /// As [`SceneArgs::resolve`], with the ranges and distributions of `[scene]` (file, then
    /// flags) taken out: the config holds their nominal values.
    pub fn resolve_uncertain(&self, more: &[toml::Table]) -> Result<(Config, UncertainSet)> {
        let base = match &self.config {
            Some(path) => Config::load_uncertain(path)?,
            None => (Config::default(), UncertainSet::default()),
        };
        let mut over = self.flags.overrides();
        for m in more {
            crate::settings::merge(&mut over, m);
        }
        let (config, uncertain) = crate::ask::palm_scene(base, over)?;
        super::warn(&config.scene.unit_warnings());
        Ok((config, uncertain))
    }
}

/// Which model answers `solve`: one of the port's models by its name, or all of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelChoice {
    /// One model.
    One(ModelKind),
    /// Every model that is built.
    All,
}

impl ModelChoice {
    /// The models to run, in the order they are printed.
    pub fn models(self) -> crate::ask::Models {
        match self {
            ModelChoice::One(k) => smallvec::smallvec![k],
            ModelChoice::All => ModelKind::ALL.into(),
        }
    }
}

/// The choices follow [`ModelKind::ALL`], so a model registered in the port is a choice here.
impl ValueEnum for ModelChoice {
    fn value_variants<'a>() -> &'a [Self] {
        static CHOICES: std::sync::LazyLock<Vec<ModelChoice>> = std::sync::LazyLock::new(|| {
            let one = ModelKind::ALL.into_iter().map(ModelChoice::One);
            one.chain([ModelChoice::All]).collect()
        });
        &CHOICES
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let (name, help) = match self {
            ModelChoice::One(k) => (k.as_str(), k.summary()),
            ModelChoice::All => ("all", "every model, with a line on which to design to"),
        };
        // The spelling of scene files and settings (`min_norm`) is taken too.
        let value = clap::builder::PossibleValue::new(name).help(help);
        Some(match name.contains('-') {
            true => value.alias(name.replace('-', "_")),
            false => value,
        })
    }
}

/// Output of `solve`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum OutputFormat {
    /// A short human summary with units.
    Text,
    /// One JSON object: {"inputs": {...}, "results": [...]}.
    Json,
}

/// Output of `vlocator`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VlocatorFormat {
    /// A short human summary with units.
    Text,
    /// One JSON object: {"verdict", "self_locking", "locking_needed", "friction_held",
    /// "forces", "capacity", "optimum", "inputs"}.
    Json,
}

/// Output of `table`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableFormat {
    /// A Markdown table.
    Text,
    /// Comma-separated values with a header row.
    Csv,
    /// A JSON array of rows.
    Json,
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
    #[arg(long = flag!(crate::ask::DIST_KEYS, before_mm), value_name = "MM", value_delimiter = ',', value_parser = parse_f64,
          allow_hyphen_values = true)]
    pub before_mm: Vec<f64>,
    /// Probabilities q in (0, 1) of the quantiles of x_jam printed with a distributed input.
    #[arg(long = flag!(crate::ask::DIST_KEYS, quantiles), value_name = "Q", value_delimiter = ',', value_parser = parse_f64,
          default_value = DEFAULT_QUANTILES, allow_hyphen_values = true)]
    pub quantiles: Vec<f64>,
    /// Monte Carlo samples where the answer is not exact.
    #[arg(long = flag!(crate::ask::DIST_KEYS, samples), value_name = "N", long_help = samples_help(), value_parser = parse_count,
          allow_hyphen_values = true)]
    pub samples: Option<u64>,
    /// Seed of the Monte Carlo samples: the same seed gives the same answer on any number of
    /// threads.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 1,
        allow_hyphen_values = true,
        value_parser = parse_count
    )]
    pub seed: u64,
}

/// The quantiles printed unless --quantiles says otherwise: the question's default
/// ([`crate::ask::DistAsk`]), written for clap.
const DEFAULT_QUANTILES: &str = "0.05,0.5,0.95";

/// The long help of --samples, with the counts of the code.
fn samples_help() -> String {
    format!(
        "Monte Carlo samples where the answer is not exact (unset: {} for the \
         statics, {} for min-norm and dynamics).\n\nThe statics are exact (the \
         monotone map) where one distribution is the only uncertain input (no range beside it) \
         and its support keeps some friction; several inputs or the other models are sampled, \
         with 95 % intervals printed. At most {}.",
        crate::ask::STATICS_SAMPLES,
        crate::ask::MODEL_SAMPLES,
        crate::uncertain::dist::MAX_SAMPLES
    )
}

#[cfg(test)]
mod tests {
    /// The flag's default is written out for clap's help; it must be the question's.
    #[test]
    fn the_default_quantiles_are_the_questions() {
        let flag: Vec<f64> = super::DEFAULT_QUANTILES
            .split(',')
            .map(|q| q.parse().unwrap())
            .collect();
        assert_eq!(flag, crate::ask::DistAsk::default().quantiles.to_vec());
    }
}
