//! Flags shared by subcommands, and their merge over a TOML parameter file.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use crate::config::Config;
use crate::error::Result;
use crate::models::ModelKind;
pub use crate::settings::decl::{parse_count, parse_f64};
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
        let (base, mut uncertain) = match &self.config {
            Some(path) => Config::load_uncertain(path)?,
            None => (Config::default(), UncertainSet::default()),
        };
        let mut over = self.flags.overrides();
        for m in more {
            crate::settings::merge(&mut over, m);
        }
        if let Some(scene) = over.get_mut("scene").and_then(toml::Value::as_table_mut) {
            let given = crate::uncertain::take(scene, crate::config::scene_decls())?;
            uncertain.override_by(scene, given);
        }
        let config = base.overlay(&over)?;
        config.validate()?;
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
    pub fn models(self) -> Vec<ModelKind> {
        match self {
            ModelChoice::One(k) => vec![k],
            ModelChoice::All => ModelKind::ALL.to_vec(),
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
