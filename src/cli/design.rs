//! `jamchart design`: flags -> [`DesignQuestion`] -> [`crate::ask::DesignAnswer`] -> text or
//! JSON.

use clap::Args;

use super::args::{OutputFormat, SceneArgs, parse_f64};
use crate::ask::{DesignQuestion, Words};
use crate::error::Result;

/// Flags of `design`.
#[derive(Debug, Clone, Args)]
pub struct DesignArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Target disc position x in mm (from the hinge): carry the part at least this far.
    ///
    /// Above x(90 deg) = r + h, the position at a right-angled palm.
    #[arg(long = flag!(crate::ask::DESIGN_KEYS, x_target_mm), value_name = "MM",
          allow_hyphen_values = true, value_parser = parse_f64)]
    pub x_target: f64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OutputFormat::Text)]
    pub format: OutputFormat,
}

/// Runs `design`.
pub fn run(args: &DesignArgs) -> Result<String> {
    let (config, uncertain) = args.scene.resolve_uncertain(&[])?;
    let question = DesignQuestion {
        config,
        uncertain,
        x_target_mm: args.x_target,
    };
    let answer = question.answer()?;
    Ok(match args.format {
        OutputFormat::Json => super::json(&answer),
        OutputFormat::Text => answer.text(Words::Flags),
    })
}
