//! [`RenderQuestion`]: a scene drawn with a face's overrides and read-offs
//! (`jamchart render SCENE --set KEY=VALUE --read-off KEY=VALUE`, `jamchart.render(scene,
//! **keywords)`, `GET /api/v1/render/SCENE.svg?KEY=VALUE`).

use super::{Keywords, ReadOff, Words};
use crate::charts::overrides::Setting;
use crate::charts::{self, Formats, Rendered, SceneSource};
use crate::error::{Error, Result};

/// A chart to draw: a scene, the values that replace its settings and where to read it off.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderQuestion {
    /// The scene: built in (by name) or a file.
    pub scene: SceneSource,
    /// Its settings replaced, as `--set` replaces them: a bare key of the scene's settings
    /// (`mu`, `radius_mm`: `jamchart settings` lists them) or a dotted key of the scene file
    /// (`chart.x_axis.count`, `size.width_px`).
    pub settings: Vec<Setting>,
    /// Where every map and sweep is read off.
    pub read_offs: Vec<ReadOff>,
}

/// A drawn chart, with what its user should know about the question.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderAnswer {
    /// The pictures and the data behind them.
    pub rendered: Rendered,
    /// The chart kind (`universal`, `jam_map`, ...).
    pub kind: String,
    /// What the chart could not honour (a read-off it has no place for), in the face's words.
    pub warnings: Vec<String>,
}

impl RenderQuestion {
    /// Scene `scene` (a built-in name) with `keywords`: each key replaces a setting of the
    /// scene (a dotted key its place in the scene file), but `set`, a table of more such keys
    /// (`{"chart.x_axis.count": 51}`), and `read_off`, a table of parameter to value
    /// (`{"mu": 0.27}`).
    pub fn builtin(scene: &str, keywords: Keywords) -> Result<Self> {
        if !charts::builtin_scene_names().iter().any(|n| n == scene) {
            return Err(Error::invalid(
                "scene",
                scene,
                format!(
                    "not a built-in scene; they are {}",
                    charts::builtin_scene_names().join(", ")
                ),
            ));
        }
        Self::of(SceneSource::BuiltIn(scene.to_string()), keywords)
    }

    /// [`RenderQuestion::builtin`] for any scene source (a scene file too).
    pub fn of(scene: SceneSource, mut keywords: Keywords) -> Result<Self> {
        let mut read_offs = Vec::new();
        if let Some(table) = keywords.take("read_off") {
            let toml::Value::Table(table) = table else {
                return Err(Error::invalid(
                    "read_off",
                    table,
                    "give a table of parameter to value, e.g. {mu = 0.27}",
                ));
            };
            for (key, value) in table {
                let text = format!("{key}={}", super::keywords::shown(&value));
                let read_off = text
                    .parse::<ReadOff>()
                    .map_err(|reason| Error::invalid(&format!("read_off.{key}"), value, reason))?;
                read_offs.push(read_off);
            }
        }
        let mut settings = Vec::new();
        if let Some(table) = keywords.take("set") {
            let toml::Value::Table(table) = table else {
                return Err(Error::invalid(
                    "set",
                    table,
                    "give a table of scene-file key to value, e.g. {\"chart.x_axis.count\" = 51}",
                ));
            };
            settings.extend(table.into_iter().map(|(key, value)| Setting { key, value }));
        }
        settings.extend((keywords.0.into_iter()).map(|(key, value)| Setting { key, value }));
        Ok(RenderQuestion {
            scene,
            settings,
            read_offs,
        })
    }

    /// Refuses a question that would read a file: a scene file, or a `base` (a scene's
    /// parameter file). For a face whose users may not reach the file system (a server).
    pub fn sealed(&self) -> Result<()> {
        if let SceneSource::File(path) = &self.scene {
            return Err(Error::invalid(
                "scene",
                path.display(),
                "give a built-in scene by name",
            ));
        }
        match self
            .settings
            .iter()
            .find(|s| s.key.split('.').next() == Some("base"))
        {
            Some(s) => Err(Error::invalid(
                &s.key,
                &s.value,
                "a scene's base reads a file; set the scene's values by key instead",
            )),
            None => Ok(()),
        }
    }

    /// Draws the chart in `formats`; the read-offs' warnings in `words`.
    pub fn answer(&self, formats: Formats, words: Words) -> Result<RenderAnswer> {
        let mut scene = self.scene.load(&self.settings)?;
        let warnings = ReadOff::apply_all(&mut scene, &self.read_offs, words)?;
        let kind = scene.chart.kind().to_string();
        Ok(RenderAnswer {
            rendered: charts::render(&scene, formats)?,
            kind,
            warnings,
        })
    }
}
