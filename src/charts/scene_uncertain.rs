//! Ranges and distributions in a scene file's `[scene]` (`mu = "0.12:0.3"`) or given with
//! `--set mu=0.12:0.3`.
//!
//! They are taken out before the scene is read, each replaced by its nominal value (the
//! midpoint of a range, see [`crate::uncertain`]), so the scene's parameters stay plain
//! numbers. A sweep draws them as its band ([`super::sweep_band`]), as `jamchart sweep --mu
//! 0.12:0.3` does; a jam map shades its uncertain cells, the universal chart draws the box they
//! span with its ends read off, the probability chart takes distributions; every other kind
//! refuses them naming the setting as written, since its chart has no place for a band.
//!
//! A single value given later replaces an uncertain one at the keys it sets, as a later key
//! replaces an earlier one anywhere: `--set mu=0.3` over the file's `mu = "normal(0.2,0.03)"`,
//! and a value set after the scene was read (`render --read-off mu=0.25`, Python's
//! `read_off`), which [`attach`] finds where the scene no longer holds the input's nominal
//! value. A chart that then has nothing left to draw (a probability without a distribution)
//! says which value replaced which.

use super::overrides::Setting;
use super::{ChartSpec, Scene};
use crate::error::{Error, Result};
use crate::settings::Numbers;
use crate::uncertain::{self, UncertainSet};
use std::path::Path;

/// The uncertain inputs of a scene, how each was given, and what single values replaced.
#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Uncertainty {
    /// The inputs: the file's with `--set` over them, less what single values replaced.
    set: UncertainSet,
    /// How each input was given, by name: `--set mu`, `scene.mu` or a flag (`--mu`).
    written: Vec<(&'static str, String)>,
    /// What single values replaced, for a chart left with nothing to draw.
    replaced: Vec<Replaced>,
}

/// An uncertain input a single value replaced: `--set mu=0.3` over `scene.mu =
/// normal(0.2,0.03)`.
#[derive(Debug, Clone, PartialEq)]
struct Replaced {
    /// Where the single value came from, as an error's key: `--set mu`, `--read-off`.
    by: String,
    /// The single value as given: `0.3`, `mu_ground=0.25, mu_palm=0.25`.
    value: String,
    /// The input it replaced: `scene.mu = normal(0.2,0.03)`.
    input: String,
    /// A distribution about the single value, for the advice: `mu=normal(0.3,0.03)`.
    instead: String,
}

impl Replaced {
    /// A probability chart left with no distribution: which value replaced which, and what
    /// to give instead.
    fn leaves_no_distribution(&self, scene: &str) -> Error {
        Error::invalid(
            &self.by,
            &self.value,
            format!(
                "it replaces {}, and scene {scene} draws the probability of a jam under a \
                 distributed input, which leaves none: give a distribution instead, e.g. \
                 --set {}",
                self.input, self.instead
            ),
        )
    }
}

/// A distribution of `name` about `v`, for advice: the spread of `old` where it is a normal
/// or lognormal, else a tenth of `v`.
fn about(name: &str, v: f64, old: crate::uncertain::Uncertain) -> String {
    use crate::uncertain::Uncertain;
    let t = crate::settings::number_text;
    match old {
        Uncertain::Normal { sd, .. } => format!("{name}=normal({},{})", t(v), t(sd)),
        Uncertain::LogNormal { sigma, .. } => format!("{name}=lognormal({},{})", t(v), t(sigma)),
        _ => format!("{name}=normal({},{})", t(v), t(0.1 * v)),
    }
}

impl Uncertainty {
    /// The inputs of a command's flags (`jamchart sweep --mu 0.12:0.3`), each named by its flag.
    pub(crate) fn of_flags(set: UncertainSet) -> Uncertainty {
        let written = (set.inputs.iter())
            .map(|i| (i.name, first_flag(i.name)))
            .collect();
        Uncertainty {
            set,
            written,
            replaced: Vec::new(),
        }
    }

    /// The inputs left.
    pub(crate) fn set(&self) -> &UncertainSet {
        &self.set
    }

    /// Input `name` as the user wrote it: `--set mu`, `scene.mu` or `--mu`.
    fn written(&self, name: &str) -> String {
        written_in(&self.written, name)
    }

    /// Whether the chart's band, range or inputs come from here: something was uncertain,
    /// whether or not a single value replaced it since (a band written in `[chart]` itself is
    /// left alone otherwise).
    fn owns_the_chart(&self) -> bool {
        !self.set.is_empty() || !self.replaced.is_empty()
    }

    /// Drops from each input the keys where `params` no longer hold its nominal value: a
    /// single value set there after the scene was read replaced it. An input left with one
    /// key of an alias's two takes that key's name (`mu_palm`, not `mu`).
    fn narrow<P: Numbers>(&mut self, params: &P) {
        for input in &mut self.set.inputs {
            let nominal = input.value.nominal();
            // Exact: the reader wrote the nominal value itself into the scene.
            let (kept, moved): (Vec<&'static str>, Vec<&'static str>) =
                (input.keys.iter()).partition(|k| params.real(k).is_none_or(|v| v == nominal));
            if moved.is_empty() {
                continue;
            }
            let mut values: Vec<(&str, f64)> = (moved.iter())
                .filter_map(|k| Some((*k, params.real(k)?)))
                .collect();
            // Both keys of the input's alias at one value: the alias, as a read-off gives it.
            if kept.is_empty() && moved.len() > 1 && values.windows(2).all(|w| w[0].1 == w[1].1) {
                values.truncate(1);
                values[0].0 = input.name;
            }
            let text: Vec<String> = (values.iter())
                .map(|(k, v)| format!("{k}={}", crate::settings::number_text(*v)))
                .collect();
            let (k, v) = values.first().copied().unwrap_or((input.name, nominal));
            self.replaced.push(Replaced {
                // A value set after the scene was read: a read-off's (`--read-off`, Python's
                // `read_off`), the only change made to a read scene.
                by: "--read-off".into(),
                value: text.join(", "),
                input: format!(
                    "{} = {}",
                    written_in(&self.written, input.name),
                    input.value
                ),
                instead: about(k, v, input.value),
            });
            input.keys = kept;
            rename_to_its_key(input);
        }
        self.set.inputs.retain(|i| !i.keys.is_empty());
    }
}

/// Input `name` as `written` names it, else as a key of the file's `[scene]`.
fn written_in(written: &[(&'static str, String)], name: &str) -> String {
    (written.iter())
        .find(|(n, _)| *n == name)
        .map_or_else(|| format!("scene.{name}"), |(_, w)| w.clone())
}

/// An input left with one key of an alias's two is named after that key: `mu` setting only
/// `mu_palm` is `mu_palm` (a label or message naming `mu` would say both frictions vary).
fn rename_to_its_key(input: &mut uncertain::UncertainInput) {
    if let [key] = input.keys[..]
        && key != input.name
    {
        input.name = key;
    }
}

/// The first flag that sets `name`, e.g. `--mu`, or `--NAME` when none does.
fn first_flag(name: &str) -> String {
    crate::settings::flag_for(name)
        .and_then(|f| f.split(" or ").next().map(str::to_string))
        .unwrap_or_else(|| format!("--{name}"))
}

/// A scene's text and `--set` settings with their uncertain values taken out.
pub(super) struct Taken {
    /// The scene text with nominal values in `[scene]`; None when it gave no range.
    pub text: Option<String>,
    /// The settings, each range or distribution replaced by its nominal value.
    pub settings: Vec<Setting>,
    /// The uncertain inputs, `--set` over the file.
    pub uncertainty: Uncertainty,
}

/// Takes the ranges and distributions out of `text`'s `[scene]` and out of `settings`. A
/// `--set` of a `[scene]` key replaces the file's input at the keys it sets, uncertain or not.
pub(super) fn take(text: &str, path: &Path, settings: &[Setting]) -> Result<Taken> {
    let decls = crate::config::scene_decls;
    let (new_text, mut set) = crate::config::take_scene_uncertain(text, path)?;
    let (mut given, mut from_flags) = (toml::Table::new(), UncertainSet::default());
    let mut points = Vec::new();
    let mut out = Vec::with_capacity(settings.len());
    for s in settings {
        let key = s.key.strip_prefix("scene.").unwrap_or(&s.key);
        let mut one = toml::Table::new();
        one.insert(key.to_string(), s.value.clone());
        let taken = uncertain::take(&mut one, decls())
            .map_err(|e| Error::invalid(&format!("--set {}", s.key), &s.value, e.to_string()))?;
        let value = one.remove(key).unwrap_or_else(|| s.value.clone());
        if decls().any(|d| d.key == key) {
            given.insert(key.to_string(), value.clone());
            if taken.is_empty() {
                points.push((key, s));
            }
        }
        from_flags.inputs.extend(taken.inputs);
        out.push(Setting {
            key: s.key.clone(),
            value,
        });
    }
    // `--set` first: its inputs replace the file's of the same name.
    let mut written: Vec<(&'static str, String)> = (from_flags.inputs.iter())
        .map(|i| (i.name, format!("--set {}", i.name)))
        .collect();
    written.extend(
        set.inputs
            .iter()
            .map(|i| (i.name, format!("scene.{}", i.name))),
    );
    let before = set.clone();
    set.override_by(&given, from_flags);
    // What the points replaced, for a chart left with nothing to draw.
    let replaced = (before.inputs.iter())
        .filter_map(|old| {
            let (k, s) = points.iter().find(|(k, _)| {
                let sets = crate::settings::find(k).map_or(&[][..], |d| d.sets);
                old.keys.iter().any(|o| o == k || sets.contains(o))
            })?;
            Some(Replaced {
                by: format!("--set {}", s.key),
                value: s.value.to_string(),
                input: format!("scene.{} = {}", old.name, old.value),
                instead: about(k, s.value.as_float()?, old.value),
            })
        })
        .collect();
    for input in &mut set.inputs {
        rename_to_its_key(input);
    }
    Ok(Taken {
        text: new_text,
        settings: out,
        uncertainty: Uncertainty {
            set,
            written,
            replaced,
        },
    })
}

/// Gives `scene`'s chart the uncertain inputs its values leave ([`Uncertainty::narrow`]): a
/// sweep or a jam map its band at the scene's values, the universal chart its box, the
/// probability chart its distributions; any other kind refuses them.
pub(super) fn attach(scene: &mut Scene) -> Result<()> {
    scene.uncertain.narrow(&scene.params);
    let u = &scene.uncertain;
    if !u.owns_the_chart() {
        return Ok(());
    }
    let written = |name: &str| u.written(name);
    let as_written = |name: &str| {
        let written = written(name);
        move |e| match e {
            Error::InvalidValue { value, reason, .. } => Error::InvalidValue {
                key: written.clone(),
                value,
                reason,
            },
            e => e,
        }
    };
    let first = u.set.inputs.first();
    let name = first.map_or("", |i| i.name);
    let band = |param| crate::figures::band::from_uncertain(&scene.params, &u.set, param);
    match &mut scene.chart {
        ChartSpec::Sweep(spec) => {
            spec.band = band(spec.x_axis.param).map_err(as_written(name))?;
            Ok(())
        }
        // Its regions are the statics' margin, monotone in every uncertain input.
        ChartSpec::JamMap(spec) => {
            spec.band = band(spec.x_axis.param).map_err(as_written(name))?;
            Ok(())
        }
        // The box of (friction, F / (m g)) the ranges span, its ends read off.
        ChartSpec::Universal(spec) => {
            spec.range = u.set.clone();
            spec.check_range().map_err(as_written(name))
        }
        // Its curve is the distribution's answer: a range has none.
        ChartSpec::JamProbability(spec) => {
            spec.inputs = u.set.clone();
            if let (true, Some(r)) = (u.set.is_empty(), u.replaced.last()) {
                return Err(r.leaves_no_distribution(&scene.name));
            }
            spec.refuse_ranges().map_err(|e| match e {
                Error::InvalidValue { key, value, reason } => {
                    let name = key.strip_prefix("scene.").unwrap_or(&key);
                    let key = match u.written.iter().any(|(n, _)| *n == name) {
                        true => written(name),
                        false => key.clone(),
                    };
                    Error::InvalidValue { key, value, reason }
                }
                e => e,
            })
        }
        _ if first.is_none() => Ok(()),
        // A V-block's chart does not read [scene]: its frictions are its own keys.
        chart if !chart.takes_scene() => {
            let value = first.map(|i| i.value).expect("an input is left");
            Err(Error::invalid(
                &written(name),
                value,
                format!(
                    "scene {} is a V-block's chart ({}), which does not read [scene]: a \
                     V-block's friction range is the key chart.mu of its robust chart (kind = \
                     \"vlocator_robust\"), e.g. --set chart.mu={value}",
                    scene.name,
                    chart.kind(),
                ),
            ))
        }
        chart => {
            let value = first.map(|i| i.value).expect("an input is left");
            let flag = first_flag(name);
            Err(Error::invalid(
                &written(name),
                value,
                format!(
                    "scene {} is a {} chart, which draws single values; a range or a \
                     distribution is drawn as a band on a sweep (kind = \"sweep\", or jamchart \
                     sweep PARAM=MIN:MAX {flag} {value}) and as an uncertain region on a jam \
                     map (kind = \"jam_map\")",
                    scene.name,
                    chart.kind(),
                ),
            ))
        }
    }
}
