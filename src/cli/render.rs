//! `jamchart render`: scenes to SVG, PNG and data files.

use std::fmt::Write;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::atomic::write_atomic;
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

/// Writes the rendered files of one scene into `out`; returns their paths.
pub fn write_rendered(out: &Path, r: &Rendered) -> Result<Vec<PathBuf>> {
    let mut files = vec![(r.data.extension, &r.data.bytes)];
    files.extend(r.svg.as_ref().map(|b| ("svg", b)));
    files.extend(r.png.as_ref().map(|b| ("png", b)));
    let mut paths = Vec::new();
    for (ext, bytes) in files {
        let path = out.join(format!("{}.{ext}", r.name));
        write_atomic(&path, bytes)?;
        paths.push(path);
    }
    Ok(paths)
}

pub fn run(a: &RenderArgs) -> Result<String> {
    let scenes = load_scenes(&a.scenes_dir, &a.scenes)?;
    std::fs::create_dir_all(&a.out)
        .map_err(|e| Error::io("create the output directory", &a.out, e))?;
    // A bar only for a person watching: not in CI logs, not into pipes.
    let show = std::io::stderr().is_terminal() && std::env::var_os("CI").is_none();
    let bar = if show {
        ProgressBar::new(scenes.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    let formats = Formats::from(a.format);
    let written: Vec<Result<Vec<PathBuf>>> = scenes
        .par_iter()
        .map(|s| {
            let paths = charts::render(s, formats).and_then(|r| write_rendered(&a.out, &r));
            bar.inc(1);
            paths
        })
        .collect();
    bar.finish_and_clear();
    let mut text = String::new();
    for (scene, paths) in scenes.iter().zip(written) {
        let list: Vec<String> = paths?.iter().map(|p| p.display().to_string()).collect();
        let _ = writeln!(text, "{}: {}", scene.name, list.join(" "));
    }
    Ok(text)
}
