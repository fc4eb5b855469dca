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
//! scale = 1.0                      # text, lines, markers and margins enlarged together
//! [chart]                          # the chart kind and its own keys
//! kind = "jam_map"                 # jam_map | sweep | contour_map | convergence | time_series | work_precision
//!                                  # | vlocator_capacity | vlocator_optimum
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
use super::vlocator_capacity::VlocatorCapacitySpec;
use super::vlocator_optimum::VlocatorOptimumSpec;
use super::work_precision::WorkPrecisionSpec;
use crate::config::{
    Config, array_for_table, cut_quotes, keyed, not_a_table, parse_toml, seq_for_struct,
};
use crate::dynamics::DynamicsParams;
use crate::error::{Error, Result};
use crate::grid::GridParam;
use crate::limits;
use crate::minnorm::MinNormSettings;
use crate::model::SceneParams;

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
    /// Holding capacity of a V-locator over included angle and load direction.
    VlocatorCapacity(VlocatorCapacitySpec),
    /// Optimum included angle of a V-locator against load direction and load.
    VlocatorOptimum(VlocatorOptimumSpec),
    /// The stability matrix: case by method, coloured by class.
    Stability(StabilitySpec),
}

impl ChartSpec {
    /// The `kind` key: jam_map, sweep, contour_map, convergence, time_series, work_precision,
    /// vlocator_capacity, vlocator_optimum or stability.
    pub fn kind(&self) -> &'static str {
        match self {
            ChartSpec::JamMap(_) => "jam_map",
            ChartSpec::Sweep(_) => "sweep",
            ChartSpec::ContourMap(_) => "contour_map",
            ChartSpec::Convergence(_) => "convergence",
            ChartSpec::TimeSeries(_) => "time_series",
            ChartSpec::WorkPrecision(_) => "work_precision",
            ChartSpec::Stability(_) => "stability",
            ChartSpec::VlocatorCapacity(_) => "vlocator_capacity",
            ChartSpec::VlocatorOptimum(_) => "vlocator_optimum",
        }
    }

    /// The extension of the data file behind this kind of chart: `json` for maps, `csv` else.
    pub fn data_extension(&self) -> &'static str {
        match self {
            ChartSpec::JamMap(_)
            | ChartSpec::ContourMap(_)
            | ChartSpec::VlocatorCapacity(_)
            | ChartSpec::VlocatorOptimum(_) => "json",
            _ => "csv",
        }
    }
}

/// A scene file as written.
#[derive(Debug, Clone, Serialize, Deserialize)]
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
    ///
    /// An axis `mu` sets both frictions, so it is refused when the scene's frictions differ
    /// (say `--set mu_palm=0.6` on fig3): the chart would draw mu_palm = mu while the read-off
    /// used 0.6.
    pub fn validate_chart(&self) -> Result<()> {
        let axes: Vec<(&str, GridParam)> = match &self.chart {
            ChartSpec::JamMap(s) => vec![("x_axis", s.x_axis.param), ("y_axis", s.y_axis.param)],
            ChartSpec::Sweep(s) => vec![("axis", s.axis.param)],
            ChartSpec::ContourMap(s) => {
                vec![("x_axis", s.x_axis.param), ("y_axis", s.y_axis.param)]
            }
            _ => Vec::new(),
        };
        let p = &self.params;
        if let Some((axis, _)) = axes.iter().find(|(_, q)| *q == GridParam::Mu)
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
        match &self.chart {
            ChartSpec::JamMap(s) => s.validate(&self.params),
            ChartSpec::Sweep(s) => s.validate(&self.params),
            ChartSpec::ContourMap(s) => s.validate(&self.params),
            ChartSpec::Convergence(s) => s.validate(),
            ChartSpec::TimeSeries(s) => s.validate(),
            ChartSpec::WorkPrecision(s) => s.validate(),
            ChartSpec::Stability(s) => s.validate(),
            ChartSpec::VlocatorCapacity(s) => s.validate(),
            ChartSpec::VlocatorOptimum(s) => s.validate(),
        }?;
        check_size(self)
    }
}

/// The scene's counts against [`crate::limits`]: memory and output estimated from the grid
/// cells, sweep points or series rows, and the lengths of its lists.
fn check_size(scene: &Scene) -> Result<()> {
    const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";
    let cells =
        |x: &crate::grid::GridAxis, y: &crate::grid::GridAxis| x.count as f64 * y.count as f64;
    match &scene.chart {
        ChartSpec::JamMap(s) => {
            limits::check_items(CELLS, cells(&s.x_axis, &s.y_axis), limits::JAM_MAP_CELL)
        }
        ChartSpec::ContourMap(s) => {
            let levels = [
                ("chart.x_jam_levels_mm", s.x_jam_levels_mm.len()),
                ("chart.theta_jam_levels_deg", s.theta_jam_levels_deg.len()),
            ];
            for (key, n) in levels {
                if n > limits::MAX_LEVELS {
                    return Err(Error::invalid(
                        key,
                        format!("{n} levels"),
                        format!("at most {} levels", limits::MAX_LEVELS),
                    ));
                }
            }
            limits::check_items(CELLS, cells(&s.x_axis, &s.y_axis), limits::CONTOUR_MAP_CELL)
        }
        ChartSpec::Sweep(s) => {
            limits::check_items("chart.axis.count", s.axis.count as f64, limits::SWEEP_POINT)
        }
        ChartSpec::TimeSeries(s) => {
            let rows = limits::series_rows(
                scene.params.start_angle_deg,
                scene.dynamics.omega_deg_s,
                s.series_dt_s,
            );
            limits::check_items(
                "chart.series_dt_s and dynamics.omega_deg_s",
                rows,
                limits::SERIES_ROW,
            )
        }
        ChartSpec::WorkPrecision(s) => {
            let lists = [
                ("chart.tolerances", s.tolerances.len()),
                ("chart.min_norm_tolerances", s.min_norm_tolerances.len()),
            ];
            for (key, n) in lists {
                if n > limits::MAX_TOLERANCES {
                    return Err(Error::invalid(
                        key,
                        format!("{n} tolerances"),
                        format!("at most {} tolerances", limits::MAX_TOLERANCES),
                    ));
                }
            }
            Ok(())
        }
        ChartSpec::Convergence(_) => Ok(()),
        // Its cases are names from the fixed matrix (checked by validate): at most its 26 rows.
        ChartSpec::Stability(_) => Ok(()),
        // A contoured map as the contour map is (its cells hold less: two capacities).
        ChartSpec::VlocatorCapacity(s) => {
            limits::check_count(
                "chart.levels_over_w",
                s.levels_over_w.len(),
                limits::MAX_LEVELS,
                "levels",
            )?;
            let n = s.x_axis.count as f64 * s.y_axis.count as f64;
            limits::check_items(CELLS, n, limits::CONTOUR_MAP_CELL)
        }
        // At most five curves (one per marker) of two sweeps.
        ChartSpec::VlocatorOptimum(s) => {
            let n = (s.direction_axis.count + s.load_axis.count) as f64 * s.mus.len() as f64;
            limits::check_items(
                "chart.direction_axis.count + chart.load_axis.count",
                n,
                limits::SWEEP_POINT,
            )
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
    let hint = format!("the keys are those of [{section}] in config/paper.toml");
    let merged = toml::Value::Table(table);
    let value: T = serde_path_to_error::deserialize(merged.clone()).map_err(|e| {
        let key = e.path().to_string();
        if let Some(k) = seq_for_struct::<T>(&merged, &key) {
            let written = value_at(overrides, &k).map_or(String::new(), toml::Value::to_string);
            return Error::Unsupported(not_a_table(&format!("{section}.{k}"), &written));
        }
        let written = value_at(overrides, &key).map(toml::Value::to_string);
        let key = format!("{section}.{key}");
        let message = cut_quotes(e.into_inner().message().trim());
        Error::Unsupported(format!(
            "{}; {hint}",
            keyed(Some(&key), written.as_deref(), &message)
        ))
    })?;
    if let Some(key) = array_for_table(&toml::Value::Table(overrides.clone()), &value, section) {
        let written = value_at(overrides, key.split_once('.').map_or("", |(_, k)| k));
        let written = written.map_or(String::new(), toml::Value::to_string);
        return Err(Error::Unsupported(not_a_table(&key, &written)));
    }
    Ok(value)
}

/// The value at a dotted key of a table (array indices are not followed).
fn value_at<'a>(t: &'a toml::Table, key: &str) -> Option<&'a toml::Value> {
    let (head, rest) = match key.split_once('.') {
        Some((h, r)) => (h, Some(r)),
        None => (key, None),
    };
    match (t.get(head)?, rest) {
        (v, None) => Some(v),
        (toml::Value::Table(inner), Some(r)) => value_at(inner, r),
        (v, Some(_)) => Some(v),
    }
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

    /// Regression (issue 13): a `[dynamics]` override of the wrong type said `invalid dynamics
    /// = invalid type: unit variant, expected string only`; an array stood in for a table.
    #[test]
    fn overrides_of_the_wrong_type_name_the_key_and_value() {
        let t: toml::Table = toml::from_str("rtol = \"x\"\n").unwrap();
        let msg = apply_overrides(DynamicsParams::default(), &t, "dynamics")
            .unwrap_err()
            .to_string();
        assert!(msg.starts_with("dynamics.rtol = \"x\": "), "{msg}");
        let t: toml::Table = toml::from_str("qp = [1, 2]\n").unwrap();
        let msg = apply_overrides(MinNormSettings::default(), &t, "min_norm")
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("min_norm.qp = [1, 2]: expected a table"),
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
