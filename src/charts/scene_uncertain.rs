//! Ranges and distributions in a scene file's `[scene]` (`mu = "0.12:0.3"`) or given with
//! `--set mu=0.12:0.3`.
//!
//! They are taken out before the scene is read, each replaced by its nominal value (the
//! midpoint of a range, see [`crate::uncertain`]), so the scene's parameters stay plain
//! numbers. A sweep draws them as its band ([`super::sweep_band`]), as `jamchart sweep --mu
//! 0.12:0.3` does; a jam map shades its uncertain cells, the universal chart draws the box they
//! span with its ends read off, the probability chart takes distributions; every other kind
//! refuses them naming the setting as written, since its chart has no place for a band.

use super::overrides::Setting;
use super::{ChartSpec, Scene};
use crate::error::{Error, Result};
use crate::uncertain::{self, UncertainSet};
use std::path::Path;

/// A scene's text and `--set` settings with their uncertain values taken out.
pub(super) struct Taken {
    /// The scene text with nominal values in `[scene]`; None when it gave no range.
    pub text: Option<String>,
    /// The settings, each range or distribution replaced by its nominal value.
    pub settings: Vec<Setting>,
    /// The uncertain inputs, `--set` over the file.
    pub set: UncertainSet,
    /// The inputs' names that came from `--set` (the others are the file's).
    from_set: Vec<&'static str>,
}

/// Takes the ranges and distributions out of `text`'s `[scene]` and out of `settings`.
pub(super) fn take(text: &str, path: &Path, settings: &[Setting]) -> Result<Taken> {
    let decls = crate::config::scene_decls;
    let (new_text, mut set) = crate::config::take_scene_uncertain(text, path)?;
    let (mut given, mut from_flags) = (toml::Table::new(), UncertainSet::default());
    let mut out = Vec::with_capacity(settings.len());
    for s in settings {
        let key = s.key.strip_prefix("scene.").unwrap_or(&s.key);
        let mut one = toml::Table::new();
        one.insert(key.to_string(), s.value.clone());
        let taken = uncertain::take(&mut one, decls())
            .map_err(|e| Error::invalid(&format!("--set {}", s.key), &s.value, e.to_string()))?;
        let value = one.remove(key).unwrap_or_else(|| s.value.clone());
        if !taken.is_empty() {
            given.insert(key.to_string(), value.clone());
        }
        from_flags.inputs.extend(taken.inputs);
        out.push(Setting {
            key: s.key.clone(),
            value,
        });
    }
    let from_set = from_flags.inputs.iter().map(|i| i.name).collect();
    set.override_by(&given, from_flags);
    Ok(Taken {
        text: new_text,
        settings: out,
        set,
        from_set,
    })
}

/// Gives `scene` the band of `taken`'s inputs (a sweep), or refuses them (any other kind).
pub(super) fn attach(scene: &mut Scene, taken: &Taken) -> Result<()> {
    let Some(first) = taken.set.inputs.first() else {
        return Ok(());
    };
    let written = if taken.from_set.contains(&first.name) {
        format!("--set {}", first.name)
    } else {
        format!("scene.{}", first.name)
    };
    let as_written = |e| match e {
        Error::InvalidValue { value, reason, .. } => Error::InvalidValue {
            key: written.clone(),
            value,
            reason,
        },
        e => e,
    };
    let band = |param| crate::figures::band::from_uncertain(&scene.params, &taken.set, param);
    match &mut scene.chart {
        ChartSpec::Sweep(spec) => {
            spec.band = band(spec.axis.param).map_err(as_written)?;
            Ok(())
        }
        // Its regions are the statics' margin, monotone in every uncertain input.
        ChartSpec::JamMap(spec) => {
            spec.band = band(spec.x_axis.param).map_err(as_written)?;
            Ok(())
        }
        // The box of (friction, F / (m g)) the ranges span, its ends read off.
        ChartSpec::Universal(spec) => {
            spec.range = taken.set.clone();
            spec.check_range().map_err(as_written)
        }
        // Its curve is the distribution's answer: a range has none.
        ChartSpec::JamProbability(spec) => {
            spec.inputs = taken.set.clone();
            spec.refuse_ranges().map_err(|e| match e {
                Error::InvalidValue { key, value, reason } => {
                    let name = key.strip_prefix("scene.").unwrap_or(&key);
                    let key = match taken.from_set.contains(&name) {
                        true => format!("--set {name}"),
                        false => key.clone(),
                    };
                    Error::InvalidValue { key, value, reason }
                }
                e => e,
            })
        }
        chart => {
            let flag = crate::settings::flag_for(first.name)
                .and_then(|f| f.split(" or ").next().map(str::to_string))
                .unwrap_or_else(|| format!("--{}", first.name));
            Err(Error::invalid(
                &written,
                first.value,
                format!(
                    "scene {} is a {} chart, which draws single values; a range or a \
                     distribution is drawn as a band on a sweep (kind = \"sweep\", or jamchart \
                     sweep PARAM=MIN:MAX {flag} {}) and as an uncertain region on a jam map \
                     (kind = \"jam_map\")",
                    scene.name,
                    chart.kind(),
                    first.value
                ),
            ))
        }
    }
}
