//! `jamchart render`: scenes to SVG, PNG and data files.

use std::fmt::Write;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::atomic::{Output, check_all, write_all};
use crate::charts::{self, Formats, Rendered, Scene};
use crate::error::{Error, Result};

/// Flags of `render`.
#[derive(Debug, Clone, Args)]
pub struct RenderArgs {
    /// Scenes to render, by name (default: every scene in --scenes-dir).
    ///
    /// Names are the file stems of the scene files, e.g. fig3 for charts/fig3.toml.
    #[arg(value_name = "SCENE")]
    pub scenes: Vec<String>,
    /// Output directory (created if missing).
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Pictures to write; the data file (.csv or .json) is always written.
    #[arg(long, value_enum, default_value_t = RenderFormat::Both)]
    pub format: RenderFormat,
    /// Directory of the scene files NAME.toml.
    #[arg(long, value_name = "DIR", default_value = "charts")]
    pub scenes_dir: PathBuf,
}

/// Picture formats of `render`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RenderFormat {
    /// SVG only.
    Svg,
    /// PNG only.
    Png,
    /// SVG and PNG.
    Both,
}

impl From<RenderFormat> for Formats {
    fn from(f: RenderFormat) -> Self {
        match f {
            RenderFormat::Svg => Formats::Svg,
            RenderFormat::Png => Formats::Png,
            RenderFormat::Both => Formats::Both,
        }
    }
}

/// The scenes named in `wanted` (all when empty), loaded and validated before anything is drawn.
pub fn load_scenes(dir: &Path, wanted: &[String]) -> Result<Vec<Scene>> {
    let known = charts::scene_names(dir)?;
    if known.is_empty() {
        return Err(Error::invalid(
            "--scenes-dir",
            dir.display(),
            "holds no scene files (NAME.toml): nothing to render; give the folder of the scenes \
             (default: charts)",
        ));
    }
    let mut names = if wanted.is_empty() {
        known.clone()
    } else {
        wanted.to_vec()
    };
    // A scene named twice is drawn once: two renders would write the same files at once.
    let mut seen = std::collections::HashSet::new();
    names.retain(|n| seen.insert(n.clone()));
    for n in &names {
        if !known.contains(n) {
            return Err(Error::invalid(
                "scene",
                n,
                format!("unknown scene; the known scenes are {}", known.join(", ")),
            ));
        }
    }
    names.iter().map(|n| charts::load_scene(dir, n)).collect()
}

/// The files of one scene in `out`: data first, then the pictures `formats` asks for.
pub fn output_paths(
    out: &Path,
    name: &str,
    data_extension: &str,
    formats: Formats,
) -> Vec<PathBuf> {
    let mut exts = vec![data_extension];
    exts.extend(formats.svg().then_some("svg"));
    exts.extend(formats.png().then_some("png"));
    exts.iter()
        .map(|ext| out.join(format!("{name}.{ext}")))
        .collect()
}

/// Writes the rendered files of all scenes into `out` as one set (all or none); returns the
/// paths per scene.
pub fn write_rendered(out: &Path, rendered: &[Rendered]) -> Result<Vec<Vec<PathBuf>>> {
    let mut files: Vec<(PathBuf, &[u8])> = Vec::new();
    let mut paths = Vec::new();
    for r in rendered {
        let all = [
            (r.data.extension, Some(&r.data.bytes)),
            ("svg", r.svg.as_ref()),
            ("png", r.png.as_ref()),
        ];
        let mine: Vec<(PathBuf, &[u8])> = all
            .into_iter()
            .filter_map(|(ext, b)| Some((out.join(format!("{}.{ext}", r.name)), b?.as_slice())))
            .collect();
        paths.push(mine.iter().map(|(p, _)| p.clone()).collect());
        files.extend(mine);
    }
    let set: Vec<Output> = files
        .iter()
        .map(|(path, bytes)| Output { path, bytes })
        .collect();
    write_all(&set)?;
    Ok(paths)
}

pub fn run(a: &RenderArgs) -> Result<String> {
    let scenes = load_scenes(&a.scenes_dir, &a.scenes)?;
    let formats = Formats::from(a.format);
    // Every output path is checked before anything is computed.
    let planned: Vec<PathBuf> = scenes
        .iter()
        .flat_map(|s| output_paths(&a.out, &s.name, s.chart.data_extension(), formats))
        .collect();
    check_all(planned.iter().map(PathBuf::as_path))?;
    // A bar only for a person watching: not in CI logs, not into pipes.
    let show = std::io::stderr().is_terminal() && std::env::var_os("CI").is_none();
    let bar = if show {
        ProgressBar::new(scenes.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    let rendered: Vec<Result<Rendered>> = scenes
        .par_iter()
        .map(|s| {
            let r = charts::render(s, formats);
            bar.inc(1);
            r
        })
        .collect();
    bar.finish_and_clear();
    // The first failure in scene order, so the message does not depend on the thread count.
    let rendered = rendered.into_iter().collect::<Result<Vec<Rendered>>>()?;
    let written = write_rendered(&a.out, &rendered)?;
    let mut text = String::new();
    for (scene, paths) in scenes.iter().zip(written) {
        let list: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
        let _ = writeln!(text, "{}: {}", scene.name, list.join(" "));
    }
    Ok(text)
}
