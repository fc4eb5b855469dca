//! Scene files `charts/<name>.toml`: what a chart shows and from which parameters.
//!
//! ```toml
//! title = "Fig. 3: ..."            # the chart's title
//! base = "my-params.toml"          # parameter set, relative to this file (default: built-in paper set)
//! [scene]                          # overrides of the base's [scene] keys
//! force_n = 200.0
//! [dynamics.series]                # overrides of the base's [dynamics.*] keys (scenes that simulate)
//! after_jam_s = 0.3
//! [min_norm]                       # overrides of the base's [min_norm] keys (scenes that solve QPs)
//! [size]                           # picture size in px (default 1000 x 800, or the kind's minimum)
//! width_px = 1000
//! height_px = 900
//! scale = 1.0                      # text, lines, markers and margins enlarged together
//! [chart]                          # the chart kind and its own keys
//! kind = "jam_map"                 # one of ChartSpec::KINDS (charts/kinds.rs)
//! ```
//!
//! The `[chart]` keys of each kind are documented on its settings type (the variants of
//! [`ChartSpec`]) and, for users, in charts/README.md. `[chart]` is read by its `kind` after
//! the rest of the file, so that a wrong key inside it is named with its path and line.
//! Unknown keys are refused everywhere.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

pub use super::kinds::ChartSpec;
use super::overrides::{self, Setting};
use super::print::Ink;
use crate::config::{self, Config, Refusal, keyed, parse_toml};
use crate::dynamics::DynamicsParams;
use crate::error::{Error, Result};
use crate::limits::MAX_TITLE_CHARS;
use crate::minnorm::MinNormSettings;
use crate::scene::Param;
use crate::scene::SceneParams;

/// Picture size in px, and the scale of everything drawn on it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Size {
    /// Width in px, 400..=4000 (default: 1000).
    pub width_px: u32,
    /// Height in px, 300..=4000 (default: 800).
    pub height_px: u32,
    /// Factor on every text size, line width, marker size and margin, 0.5..=4 (default: 1).
    /// The chart is laid out on `width_px / scale` x `height_px / scale` px, which must stay
    /// at least 400 x 300: a 2000 x 1600 px picture at scale 2 is the 1000 x 800 one at twice
    /// the resolution.
    pub scale: f64,
}

impl Default for Size {
    fn default() -> Self {
        Size {
            width_px: 1000,
            height_px: 800,
            scale: 1.0,
        }
    }
}

/// The smallest layout (`width_px / scale` x `height_px / scale`, px) of each chart kind at
/// which no two texts of its built-in scenes overlap and none leaves the picture
/// (`layout_tests::texts_at_the_smallest_size` asserts it). Measured by drawing every built-in
/// scene on a 100 px grid of sizes; below these, 400 x 300 px gave up to thousands of
/// overlaps (stability-matrix 3901). Kinds not listed keep 400 x 300.
pub const MIN_LAYOUT_PX: &[(&str, (u32, u32))] = &[
    ("jam_map", (800, 600)),
    ("convergence", (700, 400)),
    ("time_series", (600, 600)),
    // fig6 needs 800 x 800; fig7a and fig7b fit 500 x 500.
    ("sweep", (800, 800)),
    ("contour_map", (600, 600)),
    ("work_precision", (600, 700)),
    ("stability", (1200, 600)),
    ("universal", (1000, 600)),
    ("vlocator_capacity", (900, 600)),
    ("vlocator_optimum", (600, 1000)),
    ("vlocator_robust", (700, 500)),
    ("jam_probability", (800, 600)),
];

/// The smallest layout of chart kind `kind` ([`MIN_LAYOUT_PX`]), px.
pub fn min_layout_px(kind: &str) -> (u32, u32) {
    MIN_LAYOUT_PX
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or((400, 300), |(_, s)| *s)
}

impl Size {
    /// The default width or height raised to chart kind `kind`'s minimum layout where that is
    /// larger (a stability chart needs 1200 px wide): a scene without a `[size]` section must
    /// draw, not be refused for a size its author never wrote. A size the author wrote that is
    /// not the default is kept, and checked.
    fn default_at_least(self, kind: &str) -> Size {
        let (min_w, min_h) = min_layout_px(kind);
        let d = Size::default();
        let grow = |v: u32, default: u32, min: u32| match v == default {
            true => v.max((f64::from(min) * self.scale).ceil() as u32),
            false => v,
        };
        Size {
            width_px: grow(self.width_px, d.width_px, min_w),
            height_px: grow(self.height_px, d.height_px, min_h),
            ..self
        }
    }

    /// Refuses a layout smaller than chart kind `kind` needs ([`MIN_LAYOUT_PX`]), naming the
    /// key that is short.
    fn check_for(&self, kind: &str) -> Result<()> {
        let (min_w, min_h) = min_layout_px(kind);
        let (w, h) = (
            f64::from(self.width_px) / self.scale,
            f64::from(self.height_px) / self.scale,
        );
        let short = [
            ("size.width_px", self.width_px, w, min_w),
            ("size.height_px", self.height_px, h, min_h),
        ];
        match short
            .into_iter()
            .find(|(_, _, v, min)| *v < f64::from(*min) - 0.5)
        {
            Some((key, value, _, _)) => Err(Error::invalid(
                key,
                value,
                format!(
                    "a {kind} chart needs at least {min_w} x {min_h} px (times size.scale) \
                     for its texts not to overlap or clip"
                ),
            )),
            None => Ok(()),
        }
    }

    fn validate(&self) -> Result<()> {
        // Below these the margins, labels and legends no longer fit.
        if !(400..=4000).contains(&self.width_px) {
            return Err(Error::invalid(
                "size.width_px",
                self.width_px,
                "must be 400..=4000 px",
            ));
        }
        if !(300..=4000).contains(&self.height_px) {
            return Err(Error::invalid(
                "size.height_px",
                self.height_px,
                "must be 300..=4000 px",
            ));
        }
        // Half size still draws a 1 px line; beyond 4 nothing gains.
        if !(0.5..=4.0).contains(&self.scale) {
            return Err(Error::invalid("size.scale", self.scale, "must be 0.5..=4"));
        }
        let (w, h) = (
            f64::from(self.width_px) / self.scale,
            f64::from(self.height_px) / self.scale,
        );
        if w < 399.5 || h < 299.5 {
            return Err(Error::invalid(
                "size.scale",
                self.scale,
                format!(
                    "leaves {w:.0} x {h:.0} px for the layout, below 400 x 300: raise width_px \
                     and height_px or lower scale"
                ),
            ));
        }
        Ok(())
    }
}

/// A scene file as written.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    /// Required; read as optional so that its absence is one mistake of the file's report,
    /// not the only one.
    title: Option<String>,
    base: Option<PathBuf>,
    #[serde(default)]
    scene: toml::Table,
    #[serde(default)]
    dynamics: toml::Table,
    #[serde(default)]
    min_norm: toml::Table,
    #[serde(default)]
    size: Size,
    /// `style = "colour" | "print"`: the ink (default: colour).
    #[serde(default)]
    style: Ink,
    /// Read by kind after the rest ([`read_chart`]), so that a wrong key inside it is named
    /// with its path (serde keeps none inside an internally tagged enum).
    chart: toml::Table,
}

/// A loaded, validated scene: everything needed to compute and draw it.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The scene's name (file stem), e.g. `fig3`.
    pub name: String,
    /// The chart title.
    pub title: String,
    /// The base parameter set with the scene's overrides applied.
    pub params: SceneParams,
    /// The base `[min_norm]` settings with the scene's overrides (used only by charts that
    /// draw min-norm solutions).
    pub min_norm: MinNormSettings,
    /// The base `[dynamics]` settings with the scene's overrides (used only by charts that
    /// simulate).
    pub dynamics: DynamicsParams,
    /// Picture size.
    pub size: Size,
    /// The ink: colour, or greys for a black-and-white print (default: colour).
    pub style: Ink,
    /// Chart kind and settings.
    pub chart: ChartSpec,
    /// The ranges and distributions of `[scene]` (the parameters hold their nominal values),
    /// given to the chart by [`Scene::validate_chart`] at the values it is drawn with.
    pub(crate) uncertain: super::scene_uncertain::Uncertainty,
    /// The title as written, its `[chart]` keys filled ([`super::title`]): `title` is it with
    /// the scene's values in place of its `[scene]` keys.
    pub(crate) title_as_written: String,
}

/// Where a scene comes from: built into the binary, or a file of the user's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SceneSource {
    /// A built-in scene (`super::builtin::SCENES`), by name.
    BuiltIn(String),
    /// A scene file; the scene is named after the file stem.
    File(PathBuf),
}

impl SceneSource {
    /// The scene's name: the built-in name or the file stem.
    pub fn name(&self) -> String {
        match self {
            SceneSource::BuiltIn(n) => n.clone(),
            SceneSource::File(p) => p
                .file_stem()
                .map_or_else(|| p.display().to_string(), |s| s.to_string_lossy().into()),
        }
    }

    /// Reads, overrides (`--set`) and validates the scene.
    ///
    /// A `base` is relative to the scene file's folder (to the current folder for a built-in
    /// scene); without one the built-in paper set (config/paper.toml) is the base.
    pub fn load(&self, settings: &[Setting]) -> Result<Scene> {
        let name = self.name();
        match self {
            SceneSource::BuiltIn(n) => {
                let text = super::builtin::scene_text(n).ok_or_else(|| {
                    Error::invalid(
                        "scene",
                        n,
                        format!(
                            "not a built-in scene; they are {}",
                            super::builtin::scene_names().join(", ")
                        ),
                    )
                })?;
                let label = PathBuf::from(format!("<built-in charts/{n}.toml>"));
                parse_scene(name, text, &label, Path::new(""), settings)
            }
            SceneSource::File(path) => {
                let text = crate::config::read_text(path)?;
                let dir = path.parent().unwrap_or(Path::new(""));
                parse_scene(name, &text, path, dir, settings)
            }
        }
    }
}

/// The scene names in `dir` (the stems of its `*.toml` files), sorted.
pub fn scene_names(dir: &Path) -> Result<Vec<String>> {
    Ok(scene_files(dir)?.iter().map(SceneSource::name).collect())
}

/// The scene files `dir/*.toml`, sorted by name.
pub fn scene_files(dir: &Path) -> Result<Vec<SceneSource>> {
    let entries = std::fs::read_dir(dir).map_err(|e| Error::io("read", dir, e))?;
    let mut files = Vec::new();
    for entry in entries {
        let path = entry.map_err(|e| Error::io("read", dir, e))?.path();
        if path.extension().is_some_and(|e| e == "toml") && path.file_stem().is_some() {
            files.push(SceneSource::File(path));
        }
    }
    files.sort_by_key(SceneSource::name);
    Ok(files)
}

/// Loads and validates scene `name` from `dir/<name>.toml`.
pub fn load_scene(dir: &Path, name: &str) -> Result<Scene> {
    SceneSource::File(dir.join(format!("{name}.toml"))).load(&[])
}

/// A scene from its text: `path` names it in errors, `dir` resolves its `base`.
fn parse_scene(
    name: String,
    text: &str,
    path: &Path,
    dir: &Path,
    settings: &[Setting],
) -> Result<Scene> {
    // Ranges and distributions out first, each replaced by its nominal value; a sweep draws
    // them as its band below.
    let taken = super::scene_uncertain::take(text, path, settings)?;
    let (text, settings) = (taken.text.as_deref().unwrap_or(text), &taken.settings[..]);
    // The file as written first, so that its own mistakes carry their line.
    let mut file: SceneFile = parse_toml(text, path)?;
    if !settings.is_empty() {
        let mut table: toml::Table = parse_toml(text, path)?;
        let settings = &axis_spelt_as(table.get("chart"), settings);
        overrides::apply(&mut table, settings)?;
        file = SceneFile::deserialize(toml::Value::Table(table)).map_err(|e| {
            let typed: Vec<String> = settings.iter().map(Setting::to_string).collect();
            Error::invalid(
                "--set",
                typed.join(" "),
                format!(
                    "scene {name} does not take it: {}; its keys: jamchart scenes --keys",
                    e.message().trim()
                ),
            )
        })?;
    }
    let title = file.title.clone().unwrap_or_default();
    let title_missing = file.title.is_none().then(|| Error::Config {
        path: path.to_path_buf(),
        line: 1,
        column: 1,
        message: "title is missing: a required key (title = \"...\", the chart's title)".into(),
    });
    let title_as_written = super::title::fill_chart_keys(&title, &file.chart)?;
    let chart = read_chart(&file.chart).map_err(|r| {
        let set: Vec<String> = settings
            .iter()
            .filter(|s| s.key.starts_with("chart."))
            .map(Setting::to_string)
            .collect();
        if set.is_empty() {
            // A sweep's x axis may be written under its old key.
            let key = match file.chart.contains_key(OLD_AXIS_KEY) {
                true => r
                    .key
                    .replacen("chart.x_axis", &format!("chart.{OLD_AXIS_KEY}"), 1),
                false => r.key.clone(),
            };
            let (line, column) = config::key_line_column(text, &key).unwrap_or((1, 1));
            Error::Config {
                path: path.to_path_buf(),
                line,
                column,
                message: r.message,
            }
        } else {
            Error::invalid(
                "--set",
                set.join(" "),
                format!(
                    "scene {name} does not take it: {}; its keys: jamchart scenes --keys",
                    r.message
                ),
            )
        }
    });
    let base = match (&file.base, &chart) {
        (Some(b), Ok(_)) => Config::load(&dir.join(b))?,
        // The chart's own mistake comes before a base that does not load.
        (Some(b), Err(_)) => {
            Config::load(&dir.join(b)).unwrap_or_else(|_| super::builtin::paper_config())
        }
        (None, _) => super::builtin::paper_config(),
    };
    // A refused or invalid key written in this file is named with its file, line and column
    // (a key from --set or the base file keeps its own message).
    let locate = |section: &str, e: Error| -> Error {
        let key = match &e {
            Error::Refused { key, .. } | Error::InvalidValue { key, .. } => key.clone(),
            _ => return e,
        };
        // A value from --set is not in the file: its own message names it.
        if settings
            .iter()
            .any(|s| s.key == key || s.key == format!("{section}.{key}"))
        {
            return e;
        }
        let dotted = if key.contains('.') {
            key
        } else {
            format!("{section}.{key}")
        };
        match config::key_line_column(text, &dotted) {
            Some((line, column)) => Error::Config {
                path: path.to_path_buf(),
                line,
                column,
                message: e.file_message(),
            },
            None => e,
        }
    };
    let mut errors: Vec<Error> = title_missing.into_iter().collect();
    let params = section(
        &base.scene,
        &file.scene,
        "scene",
        SceneParams::validate,
        &locate,
    );
    let min_norm = section(
        &base.min_norm,
        &file.min_norm,
        "min_norm",
        MinNormSettings::validate,
        &locate,
    );
    let dynamics = section(
        &base.dynamics,
        &file.dynamics,
        "dynamics",
        DynamicsParams::validate,
        &locate,
    );
    let size = file.size.validate().map_err(|e| locate("size", e));
    // Every section's mistake in one report, in file order (a later missing x_axis was
    // reported before an earlier typo in [scene]).
    let chart = ok_or_keep(chart, &mut errors);
    let params = params.map_err(|e| errors.extend(e)).ok();
    let min_norm = min_norm.map_err(|e| errors.extend(e)).ok();
    let dynamics = dynamics.map_err(|e| errors.extend(e)).ok();
    ok_or_keep(size, &mut errors);
    let (Some(chart), Some(params), Some(min_norm), Some(dynamics), true) =
        (chart, params, min_norm, dynamics, errors.is_empty())
    else {
        return Err(Error::in_file_order(path, errors));
    };
    let mut scene = Scene {
        name,
        title,
        params,
        min_norm,
        dynamics,
        size: file.size.default_at_least(chart.kind()),
        style: file.style,
        chart,
        uncertain: taken.uncertainty,
        title_as_written,
    };
    scene.validate_chart()?;
    Ok(scene)
}

/// The settings of `[section]`: `base` with the file's `table` merged in and validated; on a
/// mistake, each key's own (a key read alone over the base), so that a typo and a wrong value
/// in one section are both reported (serde stops at the first), each placed by `locate`.
fn section<T: serde::Serialize + serde::de::DeserializeOwned>(
    base: &T,
    table: &toml::Table,
    name: &str,
    validate: impl Fn(&T) -> Result<()>,
    locate: &dyn Fn(&str, Error) -> Error,
) -> std::result::Result<T, Vec<Error>> {
    let read =
        |t: &toml::Table| config::overlay(base, t, name).and_then(|v| validate(&v).map(|_| v));
    let whole = match read(table) {
        Ok(v) => return Ok(v),
        Err(e) => e,
    };
    let each: Vec<Error> = (table.iter())
        .filter_map(|(k, v)| read(&toml::Table::from_iter([(k.clone(), v.clone())])).err())
        .map(|e| locate(name, e))
        .collect();
    // A mistake only the keys together make (none alone is refused) is the whole's.
    Err(match each.is_empty() {
        true => vec![locate(name, whole)],
        false => each,
    })
}

/// `r`'s value, or None with its error kept in `errors`.
fn ok_or_keep<T>(r: Result<T>, errors: &mut Vec<Error>) -> Option<T> {
    r.map_err(|e| errors.push(e)).ok()
}

impl Scene {
    /// What the scene's figure is computed from besides its settings.
    pub fn input(&self) -> crate::figures::Input {
        crate::figures::Input {
            params: self.params,
            min_norm: self.min_norm,
            dynamics: self.dynamics,
        }
    }

    /// What `--set` changed that this scene does not show, one sentence per key: a `[scene]`
    /// key of a V-locator chart (it has its own parameters) or a key the chart varies along an
    /// axis.
    pub fn unused_settings(&self, settings: &[Setting]) -> Vec<String> {
        let axes = self.chart.param_axes();
        settings
            .iter()
            .filter_map(|s| {
                let param = Param::named(&s.key)?;
                if !self.chart.takes_scene() {
                    return Some(format!(
                        "scene {} does not take --set {s}: a V-block chart has its own \
                         parameters (--set chart.locator.KEY=VALUE)",
                        self.name
                    ));
                }
                if self.chart.marks_scene_value() {
                    return None;
                }
                let (axis, _) = axes.iter().map(|(k, a)| (k, a.param)).find(|(_, q)| {
                    *q == param
                        || q.decl().sets.contains(&param.as_str())
                        || param.decl().sets.contains(&q.as_str())
                })?;
                Some(format!(
                    "scene {} varies {} along chart.{axis}, so --set {s} does not show on it",
                    self.name,
                    param.as_str()
                ))
            })
            .collect()
    }

    /// Gives the chart what the scene's values decide, then checks its settings against them:
    /// called when the scene is read and again after anything changed its values (a
    /// `--read-off`).
    ///
    /// The chart takes the uncertain inputs a single value has not replaced since
    /// (`charts::scene_uncertain::attach`: a band at the scene's values, the universal
    /// chart's box, the probability chart's distributions) and the title its values in place
    /// of the keys it names (`charts::title`). An axis `mu` sets both frictions, so it is refused when the scene's frictions differ
    /// (say `--set mu_palm=0.6` on fig3): the chart would draw mu_palm = mu while the read-off
    /// used 0.6.
    pub fn validate_chart(&mut self) -> Result<()> {
        super::scene_uncertain::attach(self)?;
        self.title = super::title::fill_scene_keys(
            &self.title_as_written,
            &self.params,
            self.uncertain.set(),
        )?;
        self.validate_title()?;
        self.size.check_for(self.chart.kind())?;
        let p = &self.params;
        if let Some((axis, _)) = self
            .chart
            .param_axes()
            .into_iter()
            .find(|(_, a)| a.param == Param::Mu)
            && p.mu_ground != p.mu_palm
        {
            return Err(Error::invalid(
                &format!("chart.{axis}.param"),
                "mu",
                format!(
                    "a mu axis sets both frictions, but this scene has mu_ground = {} and \
                     mu_palm = {}; vary one of them instead, e.g. --set chart.{axis}.param=mu_ground",
                    p.mu_ground, p.mu_palm
                ),
            ));
        }
        let input = self.input();
        self.chart.validate(&input)?;
        self.chart.check_size(&input)
    }
}

impl Scene {
    /// Checks the title: not blank (`--set title=` drew a chart without a heading) and at most
    /// [`crate::limits::MAX_TITLE_CHARS`] characters.
    fn validate_title(&self) -> Result<()> {
        let why = if self.title.trim().is_empty() {
            "a chart needs a title; write what it shows".to_string()
        } else if self.title.chars().nth(MAX_TITLE_CHARS).is_some() {
            format!("a title is one line: at most {MAX_TITLE_CHARS} characters")
        } else {
            return Ok(());
        };
        Err(Error::invalid("title", format!("\"{}\"", self.title), why))
    }
}

/// A sweep's key for its x axis before every chart kind named its x axis `x_axis`: still read
/// as `x_axis`, so that scene files and `--set chart.axis.count=51` written for it keep
/// working (both keys at once are refused).
const OLD_AXIS_KEY: &str = "axis";

/// Whether `chart` is a sweep's `[chart]`.
fn is_sweep(chart: Option<&toml::Value>) -> bool {
    chart
        .and_then(|c| c.get("kind"))
        .and_then(toml::Value::as_str)
        == Some("sweep")
}

/// A sweep's `[chart]` with its x axis under [`OLD_AXIS_KEY`] moved to `x_axis`.
fn read_old_axis_key(chart: &mut toml::Table) -> std::result::Result<(), Refusal> {
    let Some(axis) = chart.remove(OLD_AXIS_KEY) else {
        return Ok(());
    };
    if chart.contains_key("x_axis") {
        let key = format!("chart.{OLD_AXIS_KEY}");
        return Err(Refusal {
            message: keyed(
                Some(&key),
                None,
                "the old spelling of chart.x_axis, which is given as well: keep x_axis",
            ),
            key,
        });
    }
    chart.insert("x_axis".into(), axis);
    Ok(())
}

/// `settings` with a sweep's x axis spelt as the scene file's `[chart]` spells it, so that
/// `--set chart.axis.count=51` sets a file's `x_axis` and `--set chart.x_axis.count=51` an old
/// file's `axis`, instead of adding a second axis beside it.
fn axis_spelt_as(chart: Option<&toml::Value>, settings: &[Setting]) -> Vec<Setting> {
    let old = chart.is_some_and(|c| c.get(OLD_AXIS_KEY).is_some());
    let (from, to) = match old {
        true => ("x_axis", OLD_AXIS_KEY),
        false => (OLD_AXIS_KEY, "x_axis"),
    };
    let respelt = |key: &str| {
        let rest = key.strip_prefix("chart.")?.strip_prefix(from)?;
        (rest.is_empty() || rest.starts_with('.')).then(|| format!("chart.{to}{rest}"))
    };
    (settings.iter())
        .map(|s| match respelt(&s.key).filter(|_| is_sweep(chart)) {
            Some(key) => Setting {
                key,
                value: s.value.clone(),
            },
            None => s.clone(),
        })
        .collect()
}

/// `[chart]` read by its `kind` key; the kinds are those of [`super::kinds`].
fn read_chart(table: &toml::Table) -> std::result::Result<ChartSpec, Refusal> {
    let kinds = ChartSpec::KINDS.join(", ");
    let refuse = |written: Option<&toml::Value>, what: String| {
        let key = "chart.kind".to_string();
        let written = written.map(toml::Value::to_string);
        Refusal {
            message: keyed(Some(&key), written.as_deref(), &what),
            key,
        }
    };
    let kind = match table.get("kind") {
        Some(toml::Value::String(k)) => k,
        Some(v) => return Err(refuse(Some(v), format!("expected a kind: {kinds}"))),
        None => return Err(refuse(None, format!("missing; the kinds are {kinds}"))),
    };
    let mut rest = table.clone();
    rest.remove("kind");
    if kind == "sweep" {
        read_old_axis_key(&mut rest)?;
    }
    ChartSpec::read(kind, &rest).unwrap_or_else(|| {
        Err(refuse(
            table.get("kind"),
            format!("not a chart kind; the kinds are {kinds}"),
        ))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene_error(text: &str) -> String {
        parse_scene("s".into(), text, Path::new("s.toml"), Path::new(""), &[])
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn unknown_chart_key_is_refused_with_its_line() {
        let msg = scene_error("title = \"t\"\n[chart]\nkind = \"sweep\"\npanls = []\n");
        assert!(
            msg.starts_with("s.toml:4:9: chart.panls: unknown key; did you mean panels?"),
            "{msg}"
        );
    }

    /// A scene file's mistakes came one at a time, and not in file order: a chart's mistake
    /// was reported before an earlier typo in [scene]. Every section is read and its mistake
    /// reported, by line.
    #[test]
    fn every_sections_mistake_is_reported_in_file_order() {
        let msg = scene_error(
            "title = \"t\"\n[scene]\nraduis_mm = 12.5\n[chart]\nkind = \"contour_map\"\n\
             model = \"statix\"\n\
             y_axis = { param = \"mu\", min = 0.1, max = 0.3, count = 5 }\n",
        );
        let lines: Vec<&str> = msg.lines().collect();
        assert_eq!(lines[0], "2 mistakes in s.toml:", "{msg}");
        assert!(
            lines[1].starts_with("  s.toml:3:13: scene.raduis_mm"),
            "{msg}"
        );
        assert!(lines[2].starts_with("  s.toml:6:9: chart.model"), "{msg}");
    }

    /// One mistake hid the others: a missing title was the whole report, and of a typo and a
    /// wrong value in one section only the first in key order was told (serde stops there). A
    /// misspelt axis parameter read "muu is not one of ." with an empty list.
    #[test]
    fn a_missing_title_and_two_mistakes_of_one_section_are_all_reported() {
        let msg = scene_error(
            "[scene]\nraduis_mm = 12\nmass_kg = true\n[chart]\nkind = \"jam_map\"\n\
             x_axis = { param = \"muu\", min = 0.1, max = 0.5, count = 5 }\n\
             y_axis = { param = \"theta_deg\", min = 10.0, max = 70.0, count = 5 }\n",
        );
        let lines: Vec<&str> = msg.lines().collect();
        assert_eq!(lines[0], "4 mistakes in s.toml:", "{msg}");
        assert!(
            lines[1].starts_with("  s.toml:1:1: title is missing"),
            "{msg}"
        );
        assert!(
            lines[2].starts_with(
                "  s.toml:2:13: scene.raduis_mm = 12: unknown key; did you mean radius_mm?"
            ),
            "{msg}"
        );
        assert!(
            lines[3].starts_with("  s.toml:3:11: scene.mass_kg = true: expected a number"),
            "{msg}"
        );
        assert!(
            lines[4].contains("not one of mu, mu_ground")
                && !lines[4].contains("muu")
                && lines[4].contains("did you mean mu?"),
            "{msg}"
        );
    }

    /// Scene-file errors spoke serde: "unknown field `raduis_mm`, expected one of ..." (without
    /// `mu`, which sets both frictions), "invalid type: string \"heavy\", expected f64",
    /// "unknown variant `statix`, expected one of ...". They speak of keys, numbers and the
    /// words to choose from, with the nearest to a typo.
    #[test]
    fn scene_file_errors_speak_of_keys_numbers_and_choices() {
        let map = "[chart]\nkind = \"contour_map\"\n\
                   x_axis = { param = \"force_n\", min = 10.0, max = 100.0, count = 5 }\n\
                   y_axis = { param = \"mu\", min = 0.1, max = 0.3, count = 5 }\n";
        let typo = scene_error(&format!("title = \"t\"\n[scene]\nraduis_mm = 12.5\n{map}"));
        assert!(
            typo.starts_with(
                "s.toml:3:13: scene.raduis_mm = 12.5: unknown key; did you mean \
                 radius_mm? The keys here: mu, "
            ),
            "{typo}"
        );
        assert!(typo.contains("mu_ground, mu_palm, radius_mm"), "{typo}");
        let heavy = scene_error(&format!(
            "title = \"t\"\n[scene]\nmass_kg = \"heavy\"\n{map}"
        ));
        assert!(
            heavy.ends_with("scene.mass_kg: expected a number, found text")
                && !heavy.contains("heavy"),
            "{heavy}"
        );
        let model = scene_error(&format!("title = \"t\"\n{map}model = \"statix\"\n"));
        assert!(
            model.contains("chart.model: not one of statics, ")
                && !model.contains("statix")
                && model.ends_with("; did you mean statics?"),
            "{model}"
        );
    }

    /// Regression: inside `[chart]`, an internally tagged enum, serde kept no path,
    /// so a wrong type named only `chart`; now every kind's keys are named with their path,
    /// line and value, as the other sections' are.
    #[test]
    fn wrong_type_inside_chart_names_the_key_with_its_path() {
        let map = "kind = \"jam_map\"\n\
                   x_axis = { param = \"mu\", min = 0.1, max = 0.5, count = \"ten\" }\n\
                   y_axis = { param = \"theta_deg\", min = 10.0, max = 70.0, count = 5 }\n";
        let cases = [
            (
                map,
                "s.toml:4:56: chart.x_axis.count: expected a whole number, found text",
            ),
            (
                "kind = \"sweep\"\nx_axis = [1, 2]\n",
                "s.toml:4:10: chart.x_axis: expected a table",
            ),
            // The old spelling of a sweep's x axis is read as x_axis, at its own line.
            (
                "kind = \"sweep\"\naxis = [1, 2]\n",
                "s.toml:4:8: chart.x_axis: expected a table",
            ),
        ];
        for (chart, says) in cases {
            let msg = scene_error(&format!("title = \"t\"\n[chart]\n{chart}"));
            assert!(msg.starts_with(says), "{msg}");
        }
    }

    #[test]
    fn chart_kind_missing_unknown_or_mistyped_lists_the_kinds() {
        for (kind, says) in [
            ("", "chart.kind: missing; the kinds are jam_map, sweep"),
            (
                "kind = \"jam_mop\"\n",
                "chart.kind: not a chart kind; the kinds are",
            ),
            ("kind = 3\n", "chart.kind = 3: expected a kind: jam_map"),
        ] {
            let msg = scene_error(&format!("title = \"t\"\n[chart]\n{kind}"));
            assert!(msg.contains(says), "{msg}");
        }
    }

    /// Every chart kind names its x axis `x_axis`; a sweep's was `axis`. A scene written with
    /// the old key, and `--set chart.axis...` typed for it, still work, whichever key the file
    /// uses; both keys at once are refused.
    #[test]
    fn a_sweeps_old_axis_key_reads_as_x_axis() {
        let axis = "{ param = \"mu\", min = 0.1, max = 0.5, count = 5 }";
        let load = |key: &str, set: &[&str]| {
            let text = format!("title = \"t\"\n[chart]\nkind = \"sweep\"\n{key} = {axis}\n");
            let set: Vec<Setting> = set.iter().map(|s| s.parse().unwrap()).collect();
            parse_scene("s".into(), &text, Path::new("s.toml"), Path::new(""), &set)
        };
        let count = |scene: Scene| match scene.chart {
            ChartSpec::Sweep(s) => s.x_axis.count,
            _ => panic!("a sweep"),
        };
        for key in ["x_axis", "axis"] {
            assert_eq!(count(load(key, &[]).unwrap()), 5, "{key}");
            for set in ["chart.axis.count=7", "chart.x_axis.count=7"] {
                assert_eq!(count(load(key, &[set]).unwrap()), 7, "{key} with {set}");
            }
        }
        let text =
            format!("title = \"t\"\n[chart]\nkind = \"sweep\"\nx_axis = {axis}\naxis = {axis}\n");
        let msg = scene_error(&text);
        assert!(
            msg.starts_with("s.toml:5:8: chart.axis: the old spelling of chart.x_axis"),
            "{msg}"
        );
    }
}
