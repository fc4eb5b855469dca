//! `jamchart sweep`: x_jam and theta_jam against one or two parameters, without a scene file,
//! into the folder's gallery beside the rendered charts.

use std::path::PathBuf;
use std::str::FromStr;

use clap::Args;
use serde::Deserialize;

use super::args::{SceneArgs, parse_f64};
use super::gallery::{lock_folder, page, typed_command};
use super::render::{RenderFormat, output_paths, write_rendered};
use crate::atomic::Set;
use crate::charts::gallery::Entry;
use crate::charts::scene_uncertain::Uncertainty;
use crate::charts::spec::Size;
use crate::charts::{self, ChartSpec, Scene, axis_label};
use crate::error::{Error, Result};
use crate::figures::contour_map::ContourMapSettings;
use crate::figures::sweep::SweepSettings;
use crate::figures::sweep_layers::{SweepLayer, SweepPanel};

use crate::grid::{AxisScale, GridAxis};
use crate::models::ModelKind;
use crate::scene::Param;

/// Flags of `sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// The swept parameter(s): PARAM=MIN:MAX, optionally :COUNT and :log.
    #[arg(
        value_name = "PARAM=MIN:MAX",
        required = true,
        num_args = 1..=2,
        long_help = axes_long_help()
    )]
    pub axes: Vec<AxisArg>,
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Output directory (created if missing).
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// File name of the outputs, without extension [default: sweep_PARAM or map_PARAM_PARAM].
    #[arg(long, value_name = "NAME")]
    pub name: Option<String>,
    /// Pictures to write; the data file is always written.
    #[arg(long, value_enum, default_value_t = RenderFormat::Both)]
    pub format: RenderFormat,
    /// Read the chart off at your own value of the swept parameter(s): x_jam and theta_jam
    /// there, lines to the axes and the values printed. The value is the flag's, e.g. `sweep
    /// mu=0.1:0.5 --mu 0.27 --read-off`; a map reads off at both flags' values.
    #[arg(long)]
    pub read_off: bool,
    #[command(flatten)]
    pub quiet: super::progress::Quiet,
}

/// The parameters a sweep varies: every axis parameter but the palm angle (a sweep's panels
/// are the jam's angle and position).
fn sweep_params() -> impl Iterator<Item = Param> {
    Param::all().filter(|p| *p != Param::ThetaDeg)
}

/// `--help` of the axes, its list of parameters made from [`Param::all`] with each one's
/// quantity and unit, so that a new scene parameter is listed with no edit here.
fn axes_long_help() -> String {
    let params: Vec<String> = sweep_params()
        .map(|p| {
            let d = p.decl();
            let sets = match d.sets {
                [] if p == Param::PushRatio => ", sets force_n = push_ratio m g".to_string(),
                [] => String::new(),
                keys => format!(", sets {}", keys.join(" and ")),
            };
            let (key, what) = (p.as_str(), d.quantity);
            format!("  {key:<16} {what} {} ({}){sets}", d.symbol, d.unit)
        })
        .collect();
    format!(
        "The swept parameter(s): PARAM=MIN:MAX, optionally :COUNT and :log.\n\n\
         One axis draws x_jam and theta_jam against it (NAME.csv); two draw a map of x_jam \
         over both, the first across (NAME.json). COUNT defaults to 201 samples (101 per axis \
         of a map). E.g. mu=0.1:0.5 or force_n=50:10000:log radius_mm=10:30.\n\n\
         PARAM is one of:\n{}",
        params.join("\n")
    )
}

/// `PARAM=MIN:MAX[:COUNT][:log]` as typed.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisArg {
    param: Param,
    min: f64,
    max: f64,
    count: Option<usize>,
    scale: AxisScale,
}

impl FromStr for AxisArg {
    type Err = String;

    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let usage = || format!("'{s}' is not PARAM=MIN:MAX[:COUNT][:log] (e.g. mu=0.1:0.5)");
        let (name, range) = s.split_once('=').ok_or_else(usage)?;
        let param = Param::deserialize(toml::Value::String(name.trim().to_string()))
            .map_err(|e| format!("'{s}': {}", e.message().trim()))?;
        // Numbers as the flags read them: `1e-400` is refused, never read as 0.
        let number = |p: Option<&str>| match p {
            Some(p) => parse_f64(p).map_err(|e| format!("'{s}': {e}")),
            None => Err(usage()),
        };
        let mut parts = range.split(':');
        let (min, max) = (number(parts.next())?, number(parts.next())?);
        let (mut count, mut scale) = (None, None);
        for p in parts {
            let twice = |what: &str| format!("'{s}' gives the {what} twice; give it once");
            match p.trim() {
                "log" | "linear" if scale.is_some() => return Err(twice("scale")),
                "log" => scale = Some(AxisScale::Log),
                "linear" => scale = Some(AxisScale::Linear),
                _ if count.is_some() => return Err(twice("count")),
                n => count = Some(n.parse().map_err(|_| usage())?),
            }
        }
        let a = AxisArg {
            param,
            min,
            max,
            count,
            scale: scale.unwrap_or(AxisScale::Linear),
        };
        a.check().map_err(|e| format!("'{s}': {e}"))?;
        Ok(a)
    }
}

impl AxisArg {
    /// The axis and its ends checked as the user wrote them (`radius_mm=0:10` once named the
    /// flag --radius, and a log axis from 1e-320 was checked only at its ends).
    fn check(&self) -> std::result::Result<(), String> {
        let name = self.param.as_str();
        self.axis(2)
            .validate(name)
            .map_err(|e| e.to_string().replace(&format!("{name}."), ""))?;
        for v in [self.min, self.max] {
            if let Some(why) = self.param.decl().check.refuse(v) {
                return Err(format!(
                    "{name} = {} {why}",
                    crate::error::cut(&v.to_string())
                ));
            }
        }
        Ok(())
    }

    fn axis(&self, default_count: usize) -> GridAxis {
        GridAxis {
            param: self.param,
            min: self.min,
            max: self.max,
            count: self.count.unwrap_or(default_count),
            scale: self.scale,
        }
    }
}

/// The scene `sweep` draws: a sweep for one axis, a contour map of x_jam for two.
pub fn scene(a: &SweepArgs) -> Result<Scene> {
    let (config, uncertain) = a.scene.resolve_uncertain(&[])?;
    if let (Some(i), [_, _]) = (uncertain.inputs.first(), a.axes.as_slice()) {
        return Err(Error::invalid(
            i.name,
            i.value,
            "a contour map of x_jam over two axes draws one value per cell, so it takes single \
             values: sweep one axis to draw the band, or render a jam map scene (kind = \
             \"jam_map\", e.g. jamchart render fig3 --set mass_kg=1:8) for the uncertain region",
        ));
    }
    let (chart, default_name, title) = match a.axes.as_slice() {
        [x] => {
            let axis = x.axis(201);
            let chart = ChartSpec::Sweep(SweepSettings {
                x_axis: axis,
                panels: vec![SweepPanel::XJamMm, SweepPanel::ThetaJamDeg],
                layers: vec![SweepLayer::Statics, SweepLayer::Rigid],
                read_off: a.read_off,
                // Drawn from the scene's uncertain inputs below.
                band: None,
            });
            let title = format!("Jam point against {}", axis_label(axis.param));
            (chart, format!("sweep_{}", axis.param.as_str()), title)
        }
        [x, y] => {
            let (x_axis, y_axis) = (x.axis(101), y.axis(101));
            let chart = ChartSpec::ContourMap(ContourMapSettings {
                x_axis,
                y_axis,
                x_jam_levels_mm: Vec::new(),
                theta_jam_levels_deg: Vec::new(),
                settle_pct: None,
                model: ModelKind::Statics,
                read_off: a.read_off,
            });
            let (px, py) = (x_axis.param.as_str(), y_axis.param.as_str());
            let title = format!(
                "Jam position x_jam over {} and {}",
                charts::param_symbol(x_axis.param),
                charts::param_symbol(y_axis.param)
            );
            (chart, format!("map_{px}_{py}"), title)
        }
        _ => unreachable!("clap takes one or two axes"),
    };
    let mut scene = Scene {
        name: a.name.clone().unwrap_or(default_name),
        title_as_written: title.clone(),
        title,
        params: config.scene,
        min_norm: config.min_norm,
        dynamics: config.dynamics,
        size: Size::default(),
        style: Default::default(),
        chart,
        uncertain: Uncertainty::of_flags(uncertain),
    };
    scene.validate_chart()?;
    Ok(scene)
}

/// The memory and file checks name the scene key a sweep fills (`chart.x_axis.count`); the user
/// wrote the count in an axis argument, so the message names that (`COUNT of mu=MIN:MAX:COUNT`).
fn key_as_written(e: Error, a: &SweepArgs) -> Error {
    match e {
        Error::TooLarge {
            key,
            what,
            estimate_bytes,
            limit_bytes,
            limit_source,
        } if key.starts_with("chart.") => {
            let axes: Vec<String> = a
                .axes
                .iter()
                .map(|x| format!("{}=MIN:MAX:COUNT", x.param.as_str()))
                .collect();
            Error::TooLarge {
                key: format!("the COUNT of {}", axes.join(" and ")),
                what,
                estimate_bytes,
                limit_bytes,
                limit_source,
            }
        }
        e => e,
    }
}

pub fn run(a: &SweepArgs) -> Result<String> {
    let scene = scene(a).map_err(|e| key_as_written(e, a))?;
    // The name is a file name: a folder in it would write outside --out, and a control
    // character would reach the terminal and the gallery in every list of the files.
    if scene.name.contains('/')
        || scene.name.starts_with('.')
        || scene.name.is_empty()
        || scene.name.chars().any(char::is_control)
    {
        return Err(crate::error::Error::invalid(
            "--name",
            &scene.name,
            "a file name without folders, control characters or a leading dot; --out gives \
             the folder",
        ));
    }
    let formats = a.format.formats();
    // Every output path is checked before anything is computed.
    let planned = output_paths(&a.out, &scene.name, &scene.chart, formats);
    let index = a.out.join("index.html");
    let set = Set::begin(planned.iter().chain([&index]).map(PathBuf::as_path))?;
    let rendered = charts::render(&scene, formats)?;
    // The sweep joins the folder's gallery as a render does: its section with the parameters,
    // the command that reproduces it and the read-off.
    let files = planned
        .iter()
        .filter_map(|p| Some(p.file_name()?.to_string_lossy().into_owned()))
        .collect();
    let entry = Entry {
        read_off: rendered.read_off.as_deref(),
        ..Entry::of_scene(&scene, files, typed_command())
    };
    // Built and written under the folder's lock, as a render's (see `gallery`).
    let lock = lock_folder(&a.out)?;
    let html = page(&a.out, &[entry])?;
    let extra = [(index.clone(), html.as_bytes())];
    let paths = write_rendered(set, &a.out, std::slice::from_ref(&rendered), &extra)?.concat();
    drop(lock);
    if a.quiet.quiet {
        return Ok(String::new());
    }
    let list: Vec<String> = paths.iter().map(|p| super::terminal::path(p)).collect();
    Ok(format!(
        "{}: {}\ngallery: {}\n",
        scene.name,
        list.join(" "),
        super::terminal::path(&index)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_takes_range_count_and_scale() {
        let a: AxisArg = "force_n=50:10000:31:log".parse().unwrap();
        let g = a.axis(201);
        assert_eq!(
            (g.param, g.count, g.scale),
            (Param::ForceN, 31, AxisScale::Log)
        );
        assert!((g.min - 50.0).abs() < 1e-12 && (g.max - 1e4).abs() < 1e-12);
        assert_eq!("mu=0.1:0.5".parse::<AxisArg>().unwrap().axis(7).count, 7);
        let msg = "radious_mm=1:2".parse::<AxisArg>().unwrap_err();
        assert!(msg.contains("radius_mm"), "{msg}");
        assert!("mu=0.1".parse::<AxisArg>().is_err());
        assert!("mu=0.1:x".parse::<AxisArg>().is_err());
    }
}
