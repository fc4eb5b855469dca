//! [`ReadOff`]: the user's own point on every map and sweep (`render --read-off KEY=VALUE`,
//! `jamchart.render(read_off={KEY: VALUE})`).
//!
//! The value becomes the scene's (as `--set` would make it) and the chart draws its read-off
//! there: the 1-2-3 lines of a jam map, universal or contour map, the lines to the axes of a
//! sweep, with the closed form's theta_jam and x_jam printed. A key is any scene parameter an
//! axis can vary ([`Param::all`], `theta_deg` aside), so `push_ratio` (F / (m g), which
//! sets force_n from the scene's mass and gravity) is one too.

use std::str::FromStr;

use super::Words;
use crate::charts::Scene;
use crate::error::{Error, Result};
use crate::scene::Param;

/// One read-off, `KEY=VALUE` as typed: a scene parameter and the user's value of it.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOff {
    param: Param,
    value: f64,
    typed: String,
}

/// The parameters `--read-off` takes: every axis parameter but the palm angle (that is what a
/// chart reads off, not a property of the part).
fn read_off_params() -> impl Iterator<Item = Param> {
    Param::all().filter(|p| *p != Param::ThetaDeg)
}

impl FromStr for ReadOff {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let names = || {
            read_off_params()
                .map(Param::as_str)
                .collect::<Vec<_>>()
                .join(", ")
        };
        let (key, raw) = s
            .split_once('=')
            .ok_or_else(|| format!("'{s}' is not KEY=VALUE (e.g. mu=0.27)"))?;
        let param = Param::named(key.trim())
            .filter(|p| *p != Param::ThetaDeg)
            .ok_or_else(|| format!("'{s}': {} is not one of {}", key.trim(), names()))?;
        let value = crate::settings::decl::parse_f64(raw).map_err(|e| format!("'{s}': {e}"))?;
        if let Some(why) = param.decl().check.refuse(value) {
            return Err(format!("'{s}': {} = {} {why}", param.as_str(), raw.trim()));
        }
        Ok(ReadOff {
            param,
            value,
            typed: s.trim().to_string(),
        })
    }
}

impl std::fmt::Display for ReadOff {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.typed)
    }
}

impl ReadOff {
    /// Sets each read-off's value in `scene` and turns its chart's read-off on; the warnings
    /// for the user, in `words`: a chart with no read-off, or one with its own parameters
    /// (V-block charts), a value off the chart's axis.
    pub fn apply_all(
        scene: &mut Scene,
        read_offs: &[ReadOff],
        words: Words,
    ) -> Result<Vec<String>> {
        if read_offs.is_empty() {
            return Ok(Vec::new());
        }
        let typed: Vec<String> = read_offs
            .iter()
            .map(|r| format!("{} {r}", flag(words)))
            .collect();
        let typed = typed.join(" ");
        if !scene.chart.takes_scene() {
            return Ok(vec![format!(
                "scene {} has no read-off of the palm scene ({typed}): a V-block chart has its \
             own parameters",
                scene.name
            )]);
        }
        for r in read_offs {
            scene.params = r.param.apply(scene.params, r.value);
            // The value alone passed its check; what it makes of the scene (push_ratio times the
            // weight as force_n) is checked here.
            scene.params.validate().map_err(|e| {
                Error::invalid(flag(words), r, format!("in scene {}, {e}", scene.name))
            })?;
        }
        scene.validate_chart()?;
        if !scene.chart.enable_read_off() {
            return Ok(vec![format!(
                "scene {} ({}) draws no read-off; {typed} only sets the scene's values",
                scene.name,
                scene.chart.kind()
            )]);
        }
        Ok(off_the_axes(scene, read_offs, words))
    }
}

/// How a face names the read-off: `--read-off` on the command line, `read_off` elsewhere.
fn flag(words: Words) -> &'static str {
    match words {
        Words::Flags => "--read-off",
        Words::Keys => "read_off",
    }
}

/// One warning per read-off whose value lies off the chart's axis of its parameter (or of a
/// parameter it sets: `mu` on a `mu_ground` axis): the chart draws no read-off there.
fn off_the_axes(scene: &Scene, read_offs: &[ReadOff], words: Words) -> Vec<String> {
    let axes = scene.chart.param_axes();
    read_offs
        .iter()
        .filter_map(|r| {
            let (key, a) = axes.iter().find(|(_, a)| {
                a.param == r.param || r.param.decl().sets.contains(&a.param.as_str())
            })?;
            let (lo, hi) = (a.min.min(a.max), a.min.max(a.max));
            (!(lo..=hi).contains(&r.value)).then(|| {
                let set = match words {
                    Words::Flags => "--set ",
                    Words::Keys => "set ",
                };
                format!(
                    "{} {r} is off scene {}'s chart.{key} ({} from {lo} to {hi}): the chart \
                     draws no read-off; give a value on the axis or widen it ({set}chart.{key}.min=... \
                     / max=...)",
                    flag(words),
                    scene.name,
                    a.param.as_str(),
                )
            })
        })
        .collect()
}
