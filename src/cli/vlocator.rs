//! `jamchart vlocator`: flags -> [`VlocatorQuestion`] -> [`crate::ask::VlocatorAnswer`] ->
//! text or JSON.

use clap::Args;

use super::args::{VlocatorFormat, parse_f64};
use crate::ask::{VlocatorQuestion, Words};
use crate::error::{Error, Result};
use crate::settings::flags::{Flags, LocatorSet};

/// Flags of `vlocator`: the V's geometry, then the declared locator settings
/// ([`crate::settings`]: frictions, disc, load, rotation).
#[derive(Debug, Clone, Args)]
pub struct VlocatorArgs {
    /// Included angle of a symmetric V in deg, in (0, 180) [default: 90 deg].
    ///
    /// With a range (a design over the box) it is your V, whose verdict is added (`given_v`);
    /// left out, no V of your own is judged.
    #[arg(
        long = flag!(crate::ask::GEOMETRY_KEYS, included_angle_deg),
        value_name = "DEG",
        allow_hyphen_values = true,
        conflicts_with = "flank_angles",
        value_parser = parse_f64
    )]
    pub included_angle: Option<f64>,
    /// Flank angles a1,a2 above the horizontal in deg (left, right).
    ///
    /// Each in [0, 180) with a1 + a2 < 180; above 90 a flank overhangs. The included angle
    /// is 180 - a1 - a2 [default: 45,45]. With a range it is your V, judged over the box
    /// (`given_v`); left out, no V of your own is judged.
    #[arg(
        long = flag!(crate::ask::GEOMETRY_KEYS, flank_angles),
        value_name = "A1,A2",
        value_delimiter = ',',
        // "-5,40" is not a number: without this clap reads it as a flag.
        allow_hyphen_values = true,
        value_parser = parse_f64
    )]
    pub flank_angles: Option<Vec<f64>>,
    #[command(flatten)]
    pub locator: Flags<LocatorSet>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = VlocatorFormat::Text)]
    pub format: VlocatorFormat,
    /// Not a V-block setting, taken only to be refused with the reason ([`NO_RADIUS`]): the
    /// palm commands' `--radius` typed here got a bare "unexpected argument".
    #[arg(
        long,
        alias = "radius-mm",
        hide = true,
        value_name = "MM",
        allow_hyphen_values = true
    )]
    pub radius: Option<String>,
}

/// Why `vlocator` takes no radius: each flank's reaction (its normal force and its friction)
/// acts at the contact, whose direction from the centre is the flank's normal whatever the
/// radius, so every balance of forces and of moments about the centre scales the radius out.
const NO_RADIUS: &str = "vlocator takes no radius: a V-block's verdict does not depend on the \
     part's radius (the flanks touch it along their normals through its centre, at any size); \
     give its weight with --mass and the loads with --load and --load-angle";

/// Runs `vlocator`: the text or JSON answer.
pub fn run(args: &VlocatorArgs) -> Result<String> {
    if let Some(r) = &args.radius {
        return Err(Error::invalid("--radius", r, NO_RADIUS));
    }
    let question = VlocatorQuestion::new(
        args.included_angle,
        args.flank_angles.as_deref(),
        &args.locator.overrides(),
    )?;
    super::warn(&question.warnings());
    let answer = question.answer()?;
    Ok(match args.format {
        VlocatorFormat::Json => super::json(&answer),
        VlocatorFormat::Text => answer.text(Words::Flags),
    })
}
