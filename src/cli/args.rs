//! Flags shared by subcommands, and their merge over a TOML parameter file.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use crate::config::Config;
use crate::error::Result;
use crate::models::ModelKind;

/// Scene flags: each overrides the same key of `--config FILE` (or of the defaults).
#[derive(Debug, Clone, Default, Args)]
pub struct SceneArgs {
    /// TOML parameter file (e.g. config/paper.toml); flags override it.
    ///
    /// Sections and keys as in config/paper.toml; unknown keys are refused. Without it the
    /// defaults (the paper's parameters) apply.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Friction coefficient at both contacts (sets --mu-ground and --mu-palm).
    ///
    /// The paper's single mu; --mu-ground or --mu-palm given as well take precedence for their
    /// contact. Dimensionless, >= 0 [default: 0.4]
    #[arg(long, value_name = "MU", allow_negative_numbers = true, value_parser = parse_f64)]
    pub mu: Option<f64>,
    /// Friction coefficient at the ground contact A [default: 0.4].
    #[arg(long, value_name = "MU", allow_negative_numbers = true, value_parser = parse_f64)]
    pub mu_ground: Option<f64>,
    /// Friction coefficient at the palm contact B [default: 0.4].
    #[arg(long, value_name = "MU", allow_negative_numbers = true, value_parser = parse_f64)]
    pub mu_palm: Option<f64>,
    /// Disc radius r in mm [default: 10].
    #[arg(long, value_name = "MM", allow_negative_numbers = true, value_parser = parse_f64)]
    pub radius: Option<f64>,
    /// Palm push F in N [default: 200].
    ///
    /// The magnitude of the palm's force on the disc while it slides; F -> infinity is a palm
    /// driven by prescribed motion.
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_f64)]
    pub force: Option<f64>,
    /// Disc mass m in kg [default: 1].
    #[arg(long, value_name = "KG", allow_negative_numbers = true, value_parser = parse_f64)]
    pub mass: Option<f64>,
    /// Gravitational acceleration g in m/s^2 [default: 9.806].
    #[arg(long, value_name = "M/S^2", allow_negative_numbers = true, value_parser = parse_f64)]
    pub gravity: Option<f64>,
    /// Palm angle where the push starts, in deg, in (0, 180) [default: 90].
    ///
    /// Above 90 deg every model answers outside_model: the palm's push points upwards there and
    /// can lift the disc.
    #[arg(long, value_name = "DEG", allow_negative_numbers = true, value_parser = parse_f64)]
    pub start_angle: Option<f64>,
    /// Palm length in mm; a jam beyond its end is never reached [default: 150].
    #[arg(long, value_name = "MM", allow_negative_numbers = true, value_parser = parse_f64)]
    pub palm_length: Option<f64>,
}

impl SceneArgs {
    /// Defaults, then the file, then these flags, then the other flags of the command (`more`);
    /// validated before anything is computed.
    pub fn resolve_with(&self, more: impl FnOnce(&mut Config)) -> Result<Config> {
        let mut config = match &self.config {
            Some(path) => Config::load(path)?,
            None => Config::default(),
        };
        let s = &mut config.scene;
        if let Some(mu) = self.mu {
            s.mu_ground = mu;
            s.mu_palm = mu;
        }
        let overrides = [
            (self.mu_ground, &mut s.mu_ground),
            (self.mu_palm, &mut s.mu_palm),
            (self.radius, &mut s.radius_mm),
            (self.force, &mut s.force_n),
            (self.mass, &mut s.mass_kg),
            (self.gravity, &mut s.gravity_m_s2),
            (self.start_angle, &mut s.start_angle_deg),
            (self.palm_length, &mut s.palm_length_mm),
        ];
        for (flag, field) in overrides {
            if let Some(v) = flag {
                *field = v;
            }
        }
        more(&mut config);
        config.validate()?;
        Ok(config)
    }
}

/// The flag that sets a TOML key, for error messages.
pub fn flag_for_key(key: &str) -> Option<&'static str> {
    Some(match key {
        "mu_ground" => "--mu-ground or --mu",
        "mu_palm" => "--mu-palm or --mu",
        "radius_mm" => "--radius",
        "force_n" => "--force",
        "mass_kg" => "--mass",
        "gravity_m_s2" => "--gravity",
        "start_angle_deg" => "--start-angle",
        "palm_length_mm" => "--palm-length",
        "tolerances" => "--tolerances",
        "converged_rtol" => "--converged-rtol",
        "min_norm_tolerances" => "--min-norm-tolerances",
        "penetrations_um" => "--penetrations",
        "methods" => "--methods",
        "nonsmooth_steps_deg" => "--nonsmooth-steps",
        "converged_step_deg" => "--converged-step",
        "max_steps" => "--max-steps",
        "cells_per_axis" => "--map-cells",
        "cases" => "--cases",
        "runs" => "--runs",
        key => return super::dynamics::flag_for_key(key),
    })
}

/// Parses a number flag, refusing text that overflows to infinity or underflows to zero, so that
/// a message quotes what was written (`1e400`), never what it became (`inf`).
///
/// The words `inf`, `infinity` and `nan` are passed on: each setting's `validate` says whether
/// it takes them.
pub fn parse_f64(s: &str) -> std::result::Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("{} is not a number", crate::error::cut(s)))?;
    match crate::config::float_range_problem(s.trim(), v) {
        Some(problem) => Err(format!("{} {problem}", crate::error::cut(s))),
        None => Ok(v),
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
        Some(clap::builder::PossibleValue::new(name).help(help))
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
