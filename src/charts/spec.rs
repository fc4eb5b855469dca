//! Scene files `charts/<name>.toml`: what a chart shows and from which parameters.
//!
//! ```toml
//! title = "Fig. 3: ..."            # the chart's title
//! base = "my-params.toml"          # parameter set, relative to this file (default: built-in paper set)
//! [scene]                          # overrides of the base's [scene] keys
//! force_n = 200.0
//! [dynamics]                       # overrides of the base's [dynamics] keys (scenes that simulate)
//! after_jam_s = 0.3
//! [min_norm]                       # overrides of the base's [min_norm] keys (scenes that solve QPs)
//! [size]                           # picture size in px (default 1000 x 800)
//! width_px = 1000
//! height_px = 900
//! [chart]                          # the chart kind and its own keys
//! kind = "jam_map"                 # jam_map | sweep | contour_map | convergence | time_series | work_precision
//! ```
//!
//! The `[chart]` keys of each kind are documented on [`JamMapSpec`], [`SweepSpec`],
//! [`ContourMapSpec`], [`ConvergenceSpec`], [`TimeSeriesSpec`] and [`WorkPrecisionSpec`].
//! Unknown keys are refused everywhere.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::contour_map::ContourMapSpec;
use super::convergence::ConvergenceSpec;
use super::jam_map::JamMapSpec;
use super::overrides::{self, Setting};
use super::stability::StabilitySpec;
use super::sweep::SweepSpec;
use super::time_series::TimeSeriesSpec;
use super::work_precision::WorkPrecisionSpec;
use crate::config::{Config, parse_toml};
use crate::dynamics::DynamicsParams;
use crate::error::{Error, Result};
use crate::minnorm::MinNormSettings;
use crate::model::SceneParams;

/// Picture size in px.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Size {
    /// Width in px, 400..=4000 (default: 1000).
    pub width_px: u32,
    /// Height in px, 300..=4000 (default: 800).
    pub height_px: u32,
}

impl Default for Size {
    fn default() -> Self {
        Size {
            width_px: 1000,
            height_px: 800,
        }
    }
}

impl Size {
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
        Ok(())
    }
}

/// The chart kind and its settings (`[chart]`, tagged by `kind`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ChartSpec {
    /// A jam/slide map over a parameter and the palm angle (Fig. 3).
    JamMap(JamMapSpec),
    /// theta_jam and x_jam against one parameter (Figs. 6, 7a, 7b).
    Sweep(SweepSpec),
    /// Iso-lines of x_jam and theta_jam over two parameters (Fig. 7c).
    ContourMap(ContourMapSpec),
    /// The min-norm program's convergence trace at theta_jam (Fig. 4).
    Convergence(ConvergenceSpec),
    /// The simulated disc speed and position against time (Fig. 5).
    TimeSeries(TimeSeriesSpec),
    /// Error of x_jam against cost per integrator, and the min-norm tolerance against its
    /// error (the accuracy study).
    WorkPrecision(WorkPrecisionSpec),
    /// The stability matrix: case by method, coloured by class.
    Stability(StabilitySpec),
}

impl ChartSpec {
    /// The `kind` key: jam_map, sweep, contour_map, convergence, time_series, work_precision or
    /// stability.
    pub fn kind(&self) -> &'static str {
        match self {
            ChartSpec::JamMap(_) => "jam_map",
            ChartSpec::Sweep(_) => "sweep",
            ChartSpec::ContourMap(_) => "contour_map",
            ChartSpec::Convergence(_) => "convergence",
            ChartSpec::TimeSeries(_) => "time_series",
            ChartSpec::WorkPrecision(_) => "work_precision",
            ChartSpec::Stability(_) => "stability",
        }
    }
}

/// A scene file as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    title: String,
    base: Option<PathBuf>,
    #[serde(default)]
    scene: toml::Table,
    #[serde(default)]
    dynamics: toml::Table,
    #[serde(default)]
    min_norm: toml::Table,
    #[serde(default)]
    size: Size,
    chart: ChartSpec,
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
    /// Chart kind and settings.
    pub chart: ChartSpec,
}

/// Where a scene comes from: built into the binary, or a file of the user's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SceneSource {
    /// A built-in scene ([`super::builtin::SCENES`]), by name.
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
                let text = std::fs::read_to_string(path).map_err(|e| Error::io("read", path, e))?;
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
    // The file as written first, so that its own mistakes carry their line.
    let mut file: SceneFile = parse_toml(text, path)?;
    if !settings.is_empty() {
        let mut table: toml::Table = parse_toml(text, path)?;
        overrides::apply(&mut table, settings)?;
        file = SceneFile::deserialize(toml::Value::Table(table)).map_err(|e| {
            let typed: Vec<String> = settings.iter().map(Setting::to_string).collect();
            Error::invalid(
                "--set",
                typed.join(" "),
                format!(
                    "scene {name} does not take it: {}; its keys are in charts/README.md",
                    e.message().trim()
                ),
            )
        })?;
    }
    let base = match &file.base {
        Some(b) => Config::load(&dir.join(b))?,
        None => super::builtin::paper_config(),
    };
    let params: SceneParams = apply_overrides(base.scene, &file.scene, "scene")?;
    params.validate()?;
    let min_norm: MinNormSettings = apply_overrides(base.min_norm, &file.min_norm, "min_norm")?;
    min_norm.validate()?;
    let dynamics: DynamicsParams = apply_overrides(base.dynamics, &file.dynamics, "dynamics")?;
    dynamics.validate()?;
    file.size.validate()?;
    let scene = Scene {
        name,
        title: file.title,
        params,
        min_norm,
        dynamics,
        size: file.size,
        chart: file.chart,
    };
    scene.validate_chart()?;
    Ok(scene)
}

impl Scene {
    /// Checks the chart's settings against the scene's parameters.
    pub fn validate_chart(&self) -> Result<()> {
        match &self.chart {
            ChartSpec::JamMap(s) => s.validate(&self.params),
            ChartSpec::Sweep(s) => s.validate(&self.params),
            ChartSpec::ContourMap(s) => s.validate(&self.params),
            ChartSpec::Convergence(s) => s.validate(),
            ChartSpec::TimeSeries(s) => s.validate(),
            ChartSpec::WorkPrecision(s) => s.validate(),
            ChartSpec::Stability(s) => s.validate(),
        }
    }
}

/// `base` with the keys of the override table of `[section]` replaced; unknown keys are refused.
///
/// Keys the base leaves out (optional settings such as `dynamics.atol`) are known by the
/// section's struct, which refuses typos when the merged table is read back.
fn apply_overrides<T>(base: T, overrides: &toml::Table, section: &str) -> Result<T>
where
    T: Serialize + serde::de::DeserializeOwned,
{
    let mut table = toml::Table::try_from(base).expect("settings serialise to a table");
    for (key, value) in overrides {
        table.insert(key.clone(), value.clone());
    }
    T::deserialize(toml::Value::Table(table)).map_err(|e| {
        Error::invalid(
            section,
            e.message().trim(),
            format!(
                "a [{section}] override is unknown or has the wrong type; the keys are those of \
                 [{section}] in config/paper.toml"
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overrides_replace_only_their_keys_and_refuse_typos() {
        let mut t = toml::Table::new();
        t.insert("force_n".into(), toml::Value::Float(50.0));
        let p = apply_overrides(SceneParams::default(), &t, "scene").unwrap();
        assert_eq!(p.force_n, 50.0);
        assert_eq!(p.radius_mm, 10.0);
        t.insert("radus_mm".into(), toml::Value::Float(5.0));
        let msg = apply_overrides(SceneParams::default(), &t, "scene")
            .unwrap_err()
            .to_string();
        assert!(msg.contains("scene") && msg.contains("radus_mm"), "{msg}");
    }

    #[test]
    fn dynamics_override_replaces_its_key_and_refuses_typos() {
        let mut t = toml::Table::new();
        t.insert("after_jam_s".into(), toml::Value::Float(0.2));
        let d = apply_overrides(DynamicsParams::default(), &t, "dynamics").unwrap();
        assert!((d.after_jam_s - 0.2).abs() < 1e-15);
        // An optional key the base leaves out is still known.
        t.insert("atol".into(), toml::Value::Float(1e-7));
        let d = apply_overrides(DynamicsParams::default(), &t, "dynamics").unwrap();
        assert_eq!(d.atol, Some(1e-7));
        t.insert("after_jam".into(), toml::Value::Float(0.2));
        let msg = apply_overrides(DynamicsParams::default(), &t, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("dynamics") && msg.contains("after_jam"),
            "{msg}"
        );
    }

    #[test]
    fn unknown_chart_key_is_refused_with_its_line() {
        let text = "title = \"t\"\n[chart]\nkind = \"sweep\"\npanls = []\n";
        let msg = parse_toml::<SceneFile>(text, Path::new("s.toml"))
            .unwrap_err()
            .to_string();
        assert!(msg.contains("panls"), "{msg}");
    }
}
