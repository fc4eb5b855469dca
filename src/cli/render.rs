//! `jamchart render`: scenes to SVG, PNG and data files.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use rayon::prelude::*;

use crate::atomic::{Content, Output, Set, Writes};
use crate::charts::overrides::Setting;
use crate::charts::{self, Formats, Paper, Rendered, Scene, SceneSource};
use crate::error::{Error, Result};

use super::Done;
use super::gallery::{self, shell_word};
use super::manifest;
use super::progress::{self, Quiet};
use super::terminal;
use crate::ask::{ReadOff, Words};

/// Flags of `render`.
#[derive(Debug, Clone, Args)]
pub struct RenderArgs {
    /// Scenes: built-in names, scene files or folders of them (default: every built-in scene).
    ///
    /// `jamchart scenes` lists the built-in ones (fig3, fig6, ...). A path to NAME.toml adds a
    /// scene of your own (its keys: `jamchart scenes --keys`); a folder adds every *.toml in it.
    #[arg(value_name = "SCENE", value_parser = SceneArg, hide_possible_values = true)]
    pub scenes: Vec<String>,
    /// Output directory (created if missing).
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Pictures to write; the data file (.csv or .json) is always written.
    #[arg(long, value_enum, default_value_t = RenderFormat::Both)]
    pub format: RenderFormat,
    /// Sheet of paper for --format pdf; left out, the page is the chart's size (1 px = 1 pt).
    ///
    /// The chart is fitted onto the sheet, portrait, within half-inch (36 pt) margins,
    /// centred across and at the top: a4 is 595 x 842 pt, letter 612 x 792 pt.
    #[arg(long, value_enum, value_name = "SIZE")]
    pub paper: Option<Paper>,
    /// Override a scene key in every scene rendered, e.g. mu_palm=0.6 (repeatable).
    ///
    /// A bare key is a key of the scene, min_norm or dynamics sections (`jamchart settings`
    /// lists them; mu sets both frictions); other keys take their section:
    /// chart.x_axis.count=51, size.width_px=2000, title="...". The value is TOML; a bare word
    /// is a string.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<Setting>,
    /// Read every map and sweep off at your own value, e.g. mu=0.27 (repeatable).
    ///
    /// The value becomes the scene's, as --set would make it, and the chart draws its read-off
    /// there: the 1-2-3 lines of a jam map, universal chart or contour map, the lines to the
    /// axes of a sweep, with theta_jam and x_jam printed. KEY is a scene parameter: mu,
    /// mu_ground, mu_palm, radius_mm, force_n, push_ratio (F / (m g)), ... A contour map reads
    /// off at both its axes' values: give one --read-off for each. A chart without a
    /// read-off says so on stderr.
    #[arg(long = "read-off", value_name = "KEY=VALUE")]
    pub read_off: Vec<ReadOff>,
    /// Folder whose scene files replace the built-in scenes (names then refer to its files).
    #[arg(long, value_name = "DIR")]
    pub scenes_dir: Option<PathBuf>,
    /// Also write DIR/SHA256SUMS, the SHA-256 of each picture, to lock them (see --check).
    ///
    /// In sha256sum's format (like charts/SHA256SUMS), listing this run's pictures and no
    /// others. Commit it beside your scenes, then run the same command with --check in CI.
    #[arg(long, conflicts_with = "check")]
    pub bless: bool,
    /// Re-render and compare with DIR/SHA256SUMS, writing nothing into DIR.
    ///
    /// Exit 0 when every picture has its blessed bytes. Exit 1 naming each picture that
    /// changed, that is in the manifest but was not rendered, or that was rendered but is not
    /// in the manifest, with how each one's data moved; nothing is written anywhere, and the
    /// report says how to look at the new pictures (the same command with another --out and
    /// without --check) and how to accept them (--bless). Exit 2 for bad input (no manifest,
    /// an unknown scene).
    #[arg(long)]
    pub check: bool,
    #[command(flatten)]
    pub quiet: Quiet,
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
    /// PDF only, for print: the SVG's drawing on one page (1 px = 1 pt, or fitted onto
    /// --paper), text as outlines.
    Pdf,
}

/// A scene argument: any text (a scene file or folder too), with the built-in scene names as
/// its possible values, which the shell completions offer (`jamchart render fi<TAB>`).
#[derive(Debug, Clone, Copy)]
struct SceneArg;

impl clap::builder::TypedValueParser for SceneArg {
    type Value = String;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> std::result::Result<String, clap::Error> {
        clap::builder::StringValueParser::new().parse_ref(cmd, arg, value)
    }

    fn possible_values(
        &self,
    ) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        let names = charts::builtin::SCENES.iter().map(|(name, _)| *name);
        Some(Box::new(names.map(clap::builder::PossibleValue::new)))
    }
}

impl RenderArgs {
    /// The pictures to make: `--format`, on `--paper` for a PDF. A paper without a PDF is
    /// refused (it would be ignored).
    fn formats(&self) -> Result<Formats> {
        match (self.format, self.paper) {
            (RenderFormat::Pdf, paper) => Ok(Formats::Pdf(paper)),
            (format, None) => Ok(format.formats()),
            (format, Some(paper)) => Err(Error::invalid(
                "--paper",
                paper,
                format!(
                    "a sheet of paper is for a PDF, and --format {} writes none; add --format pdf",
                    format.name()
                ),
            )),
        }
    }
}

impl RenderFormat {
    /// Its name on the command line.
    fn name(self) -> String {
        self.to_possible_value()
            .map(|v| v.get_name().to_string())
            .unwrap_or_default()
    }

    /// The pictures it asks for.
    pub(crate) fn formats(self) -> Formats {
        match self {
            RenderFormat::Svg => Formats::Svg,
            RenderFormat::Png => Formats::Png,
            RenderFormat::Both => Formats::Both,
            RenderFormat::Pdf => Formats::Pdf(None),
        }
    }
}

/// The scenes named in `wanted` (all known ones when empty): a known name (built in, or in
/// `dir` when given), a scene file, or a folder of scene files.
pub fn scene_sources(wanted: &[String], dir: Option<&Path>) -> Result<Vec<SceneSource>> {
    let known = match dir {
        Some(d) => charts::scene_files(d)?,
        None => charts::builtin::scene_names()
            .into_iter()
            .map(SceneSource::BuiltIn)
            .collect(),
    };
    if let Some(d) = dir
        && known.is_empty()
    {
        return Err(nothing_to_render(d));
    }
    if wanted.is_empty() {
        return Ok(known);
    }
    let mut sources: Vec<SceneSource> = Vec::new();
    for w in wanted {
        let path = Path::new(w);
        if let Some(s) = known.iter().find(|s| s.name() == *w) {
            sources.push(s.clone());
        } else if path.is_dir() {
            sources.extend(charts::scene_files(path)?);
        } else if path.is_file() || w.ends_with(".toml") {
            sources.push(SceneSource::File(path.to_path_buf()));
        } else {
            let names: Vec<String> = known.iter().map(SceneSource::name).collect();
            return Err(Error::invalid(
                "scene",
                w,
                format!(
                    "unknown scene; the known scenes are {}, or give a scene file or folder by path",
                    names.join(", ")
                ),
            ));
        }
    }
    // A scene named twice is drawn once: two renders would write the same files at once.
    let mut unique: Vec<SceneSource> = Vec::new();
    for s in sources {
        match unique.iter().find(|u| u.name() == s.name()) {
            Some(u) if *u == s => {}
            Some(u) => {
                return Err(Error::invalid(
                    "scene",
                    s.name(),
                    format!(
                        "two scenes of this name ({u:?} and {s:?}) would write the same files; \
                         rename one"
                    ),
                ));
            }
            None => unique.push(s),
        }
    }
    match wanted.iter().find(|w| Path::new(w).is_dir()) {
        Some(folder) if unique.is_empty() => Err(nothing_to_render(Path::new(folder))),
        _ => Ok(unique),
    }
}

/// A folder with no scene file: rendering nothing and exiting 0 would hide the mistake.
fn nothing_to_render(dir: &Path) -> Error {
    Error::invalid(
        "scenes folder",
        dir.display(),
        "holds no scene files (NAME.toml): nothing to render; give the folder of the scenes, or \
         leave out --scenes-dir for the built-in ones",
    )
}

/// The scenes named in `wanted` (see [`scene_sources`]) with `settings` applied, loaded and
/// validated before anything is drawn.
pub fn load_scenes(
    wanted: &[String],
    dir: Option<&Path>,
    settings: &[Setting],
) -> Result<Vec<Scene>> {
    scene_sources(wanted, dir)?
        .iter()
        .map(|s| s.load(settings))
        .collect()
}

/// The files of one scene in `out`: data first (a map's cells CSV beside its JSON), then the
/// pictures `formats` asks for.
pub fn output_paths(
    out: &Path,
    name: &str,
    chart: &charts::ChartSpec,
    formats: Formats,
) -> Vec<PathBuf> {
    let mut exts = chart.data_extensions();
    exts.extend(formats.svg().then_some("svg"));
    exts.extend(formats.png().then_some("png"));
    exts.extend(formats.pdf().then_some("pdf"));
    exts.iter()
        .map(|ext| out.join(format!("{name}.{ext}")))
        .collect()
}

/// The command that renders scene `name` as this run did: the scene by its built-in name, else
/// the scene arguments as given (a file or folder), with the run's `--set`, `--scenes-dir`,
/// `--format` and `--paper` (where not the defaults) and `--out`.
fn reproduce_command(a: &RenderArgs, name: &str) -> String {
    let builtin = a.scenes_dir.is_none() && charts::builtin_scene_names().iter().any(|n| n == name);
    let mut words = vec!["jamchart".to_string(), "render".to_string()];
    if builtin {
        words.push(name.to_string());
    } else {
        words.extend(a.scenes.iter().cloned());
    }
    if let Some(dir) = &a.scenes_dir {
        words.push("--scenes-dir".into());
        words.push(dir.display().to_string());
    }
    for s in &a.set {
        words.push("--set".into());
        words.push(s.to_string());
    }
    for r in &a.read_off {
        words.push("--read-off".into());
        words.push(r.to_string());
    }
    if a.format != RenderFormat::Both {
        words.push("--format".into());
        words.push(a.format.name());
    }
    if let Some(paper) = a.paper {
        words.push("--paper".into());
        words.push(paper.to_string());
    }
    words.push("--out".into());
    words.push(a.out.display().to_string());
    words
        .iter()
        .map(|w| shell_word(w))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A map's cells CSV is written to its file as it is made.
impl Writes for charts::CellsCsv {
    fn write_into(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        self.write(out)
    }
}

/// The path of scene `name`'s file with extension `ext` in `out`.
fn file_path(out: &Path, name: &str, ext: &str) -> PathBuf {
    out.join(format!("{name}.{ext}"))
}

/// The files of rendered scene `r` in `out`: paths and contents, data first.
fn files_of<'a>(out: &Path, r: &'a Rendered) -> Vec<(PathBuf, Content<'a>)> {
    let bytes = |b: Option<&'a Vec<u8>>| b.map(|b| Content::Bytes(b));
    let all = [
        (r.data.extension, bytes(Some(&r.data.bytes))),
        (
            charts::CellsCsv::EXTENSION,
            r.cells.as_ref().map(|c| Content::Writer(c)),
        ),
        ("svg", bytes(r.svg.as_ref())),
        ("png", bytes(r.png.as_ref())),
        ("pdf", bytes(r.pdf.as_ref())),
    ];
    all.into_iter()
        .filter_map(|(ext, c)| Some((file_path(out, &r.name, ext), c?)))
        .collect()
}

/// Writes the rendered files of all scenes and `extra` files into `out` as `set` (begun with
/// every one of their paths), all or none; returns the paths per scene.
pub fn write_rendered(
    set: Set,
    out: &Path,
    rendered: &[Rendered],
    extra: &[(PathBuf, &[u8])],
) -> Result<Vec<Vec<PathBuf>>> {
    let per_scene: Vec<Vec<(PathBuf, Content)>> =
        rendered.iter().map(|r| files_of(out, r)).collect();
    commit_rendered(set, &per_scene, extra)?;
    Ok(paths_per_scene(&per_scene))
}

/// Stages the files of `per_scene` (but those staged already, while their scene was drawn)
/// and `extra` in `set`, and commits it.
fn commit_rendered(
    set: Set,
    per_scene: &[Vec<(PathBuf, Content)>],
    extra: &[(PathBuf, &[u8])],
) -> Result<()> {
    let outputs: Vec<Output> = per_scene
        .iter()
        .flatten()
        .filter(|(path, _)| !set.has(path))
        .map(|(path, content)| Output {
            path,
            content: *content,
        })
        .chain(extra.iter().map(|(path, bytes)| Output::bytes(path, bytes)))
        .collect();
    set.stage_all(&outputs)?;
    set.commit()
}

fn paths_per_scene(per_scene: &[Vec<(PathBuf, Content)>]) -> Vec<Vec<PathBuf>> {
    per_scene
        .iter()
        .map(|files| files.iter().map(|(p, _)| p.clone()).collect())
        .collect()
}

/// Renders every scene in parallel, with a progress bar for a person watching; the first
/// failure in scene order, so the message does not depend on the thread count. Given a set and
/// its folder, each map's cells CSV is staged in it while the map is drawn.
fn render_scenes(
    scenes: &[Scene],
    formats: Formats,
    quiet: Quiet,
    staging: Option<(&Set, &Path)>,
) -> Result<Vec<Rendered>> {
    let bar = progress::bar(
        quiet,
        scenes.len() as u64,
        "render {bar:30} {pos}/{len} scenes",
    );
    // The stability matrix's slowest simulations are the longest single jobs of a render: begun
    // first, they no longer finish alone after the rest (render of every built-in scene, 2
    // threads: 0.79 -> 0.77 s wall). The answers keep the scenes' order.
    let mut order: Vec<usize> = (0..scenes.len()).collect();
    order.sort_by_key(|&i| !matches!(scenes[i].chart, charts::ChartSpec::Stability(_)));
    let mut rendered: Vec<(usize, Result<Rendered>)> = order
        .into_par_iter()
        .map(|i| {
            let r = match staging {
                Some((set, out)) => charts::render_with(&scenes[i], formats, &|ext, content| {
                    let path = file_path(out, &scenes[i].name, ext);
                    set.stage(Output {
                        path: &path,
                        content,
                    })
                }),
                None => charts::render(&scenes[i], formats),
            };
            bar.inc(1);
            (i, r)
        })
        .collect();
    bar.finish_and_clear();
    rendered.sort_by_key(|(i, _)| *i);
    rendered.into_iter().map(|(_, r)| r).collect()
}

pub fn run(a: &RenderArgs) -> Result<Done> {
    let mut scenes = load_scenes(&a.scenes, a.scenes_dir.as_deref(), &a.set)?;
    for s in &mut scenes {
        super::warn(&ReadOff::apply_all(s, &a.read_off, Words::Flags)?);
    }
    for s in &scenes {
        let named: Vec<String> = (s.params.unit_warnings().into_iter())
            .map(|w| format!("scene {}: {w}", s.name))
            .collect();
        super::warn(&named);
        super::warn(&s.unused_settings(&a.set));
    }
    let formats = a.formats()?;
    let manifest_path = a.out.join(manifest::MANIFEST);
    if a.check {
        // The manifest is read before anything is computed.
        if crate::config::regular_or_missing(&manifest_path)?.is_none() {
            return Err(Error::NoManifest {
                path: manifest_path,
            });
        }
        let text = crate::config::read_regular(
            &manifest_path,
            crate::config::MAX_INPUT_BYTES,
            "give the manifest that render --bless wrote",
        )?;
        let blessed = manifest::parse(&text, &manifest_path)?;
        let rendered = render_scenes(&scenes, formats, a.quiet, None)?;
        return check(&manifest_path, &blessed, &rendered).map(|d| quieted(d, a.quiet));
    }
    // Every output path is checked before anything is computed; the set of files is begun
    // (its folder made) so that each map's cells CSV is written while the map is drawn.
    let planned: Vec<PathBuf> = scenes
        .iter()
        .flat_map(|s| output_paths(&a.out, &s.name, &s.chart, formats))
        .chain(std::iter::once(a.out.join("index.html")))
        .chain(a.bless.then(|| manifest_path.clone()))
        .collect();
    let set = Set::begin(planned.iter().map(PathBuf::as_path))?;
    let rendered = render_scenes(&scenes, formats, a.quiet, Some((&set, &a.out)))?;
    let index = a.out.join("index.html");
    let entries: Vec<charts::gallery::Entry> = scenes
        .iter()
        .zip(&rendered)
        .map(|(scene, r)| charts::gallery::Entry {
            read_off: r.read_off.as_deref(),
            ..charts::gallery::Entry::of_scene(
                scene,
                files_of(Path::new(""), r)
                    .iter()
                    .map(|(p, _)| p.display().to_string())
                    .collect(),
                reproduce_command(a, &scene.name),
            )
        })
        .collect();
    // The page lists every chart in the folder: the previous page's sections of charts not
    // drawn now, and the pictures of other runs; built and written under the folder's lock,
    // so that a writer into the same folder at once adds to it instead of overwriting it.
    let lock = gallery::lock_folder(&a.out)?;
    let html = gallery::page(&a.out, &entries)?;
    // The pictures are hashed only for the manifest (a SHA-256 of each picture was 2.4 % of
    // `render fig3`'s instructions, after the pictures and on one thread).
    let hashes = a.bless.then(|| manifest::hashes(&rendered));
    let manifest_text = hashes.as_ref().map(manifest::text);
    let mut extra = vec![(index.clone(), html.as_bytes())];
    if let Some(text) = &manifest_text {
        extra.push((manifest_path.clone(), text.as_bytes()));
    }
    let per_scene: Vec<Vec<(PathBuf, Content)>> =
        rendered.iter().map(|r| files_of(&a.out, r)).collect();
    commit_rendered(set, &per_scene, &extra)?;
    drop(lock);
    let written = paths_per_scene(&per_scene);
    let mut text = String::new();
    for (scene, paths) in scenes.iter().zip(written) {
        let list: Vec<String> = paths.iter().map(|p| terminal::path(p)).collect();
        let _ = writeln!(text, "{}: {}", scene.name, list.join(" "));
    }
    let _ = writeln!(text, "gallery: {}", terminal::path(&index));
    if let Some(hashes) = &hashes {
        let _ = writeln!(
            text,
            "manifest: {} ({} blessed)",
            terminal::path(&manifest_path),
            pictures(hashes.len())
        );
    }
    Ok(quieted(Done::Ok(text), a.quiet))
}

/// `done` without its report of what went well under --quiet (only errors and warnings are
/// printed then); a failed check keeps its report, which is the error.
fn quieted(done: Done, quiet: Quiet) -> Done {
    match done {
        Done::Ok(_) if quiet.quiet => Done::Ok(String::new()),
        other => other,
    }
}

/// `n` pictures, in the singular for one.
fn pictures(n: usize) -> String {
    match n {
        1 => "1 picture".into(),
        _ => format!("{n} pictures"),
    }
}

/// What changed between a data file as it was (`before`) and as rendered now, for a failed
/// check: the first fields of a JSON file whose values moved (old -> new), or the first
/// differing row of a CSV file and how many rows differ. None when the bytes are the same.
fn data_change(before: &[u8], now: &[u8]) -> Option<String> {
    if before == now {
        return None;
    }
    if let (Ok(a), Ok(b)) = (
        serde_json::from_slice::<serde_json::Value>(before),
        serde_json::from_slice::<serde_json::Value>(now),
    ) {
        let mut moved = Vec::new();
        json_changes("", &a, &b, &mut moved);
        let n = moved.len();
        moved.truncate(3);
        return Some(format!(
            "the data changed too ({n} field{}): {}{}",
            if n == 1 { "" } else { "s" },
            moved.join(", "),
            if n > 3 { ", ..." } else { "" }
        ));
    }
    let (a, b) = (
        String::from_utf8_lossy(before),
        String::from_utf8_lossy(now),
    );
    let (a, b): (Vec<&str>, Vec<&str>) = (a.lines().collect(), b.lines().collect());
    let differing = (0..a.len().max(b.len()))
        .filter(|&i| a.get(i) != b.get(i))
        .collect::<Vec<_>>();
    let first = *differing.first()?;
    Some(format!(
        "the data changed too ({} of {} rows; first at line {}: {} -> {})",
        differing.len(),
        b.len(),
        first + 1,
        crate::error::cut(a.get(first).unwrap_or(&"(none)")),
        crate::error::cut(b.get(first).unwrap_or(&"(none)"))
    ))
}

/// The leaf fields of `a` and `b` (under the path `at`) that differ, as `path: old -> new`.
fn json_changes(at: &str, a: &serde_json::Value, b: &serde_json::Value, out: &mut Vec<String>) {
    use serde_json::Value;
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for (k, v) in x {
                json_changes(
                    &format!("{at}/{k}"),
                    v,
                    y.get(k).unwrap_or(&Value::Null),
                    out,
                );
            }
            for (k, v) in y.iter().filter(|(k, _)| !x.contains_key(*k)) {
                json_changes(&format!("{at}/{k}"), &Value::Null, v, out);
            }
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            for (i, (v, w)) in x.iter().zip(y).enumerate() {
                json_changes(&format!("{at}[{i}]"), v, w, out);
            }
        }
        _ if a == b => {}
        (Value::Array(x), Value::Array(y)) => {
            out.push(format!("{at}: {} items -> {}", x.len(), y.len()))
        }
        _ => out.push(format!(
            "{at}: {} -> {}",
            crate::error::cut(&a.to_string()),
            crate::error::cut(&b.to_string())
        )),
    }
}

/// `render --check`: the pictures rendered now against the blessed manifest.
fn check(manifest_path: &Path, blessed: &manifest::Hashes, rendered: &[Rendered]) -> Result<Done> {
    let now = manifest::hashes(rendered);
    let diffs = manifest::compare(blessed, &now);
    let shown = terminal::path(manifest_path);
    if diffs.is_empty() {
        let verb = if now.len() == 1 { "matches" } else { "match" };
        return Ok(Done::Ok(format!(
            "{} {verb} {shown}\n",
            pictures(now.len())
        )));
    }
    let mut text = String::new();
    for d in &diffs {
        let _ = match d {
            manifest::Difference::Changed { file, blessed, now } => writeln!(
                text,
                "{file}: changed (blessed {}, now {})",
                &blessed[..blessed.len().min(12)],
                &now[..now.len().min(12)]
            ),
            manifest::Difference::Missing { file } => {
                writeln!(text, "{file}: missing (in the manifest, not rendered now)")
            }
            manifest::Difference::NotBlessed { file } => writeln!(
                text,
                "{file}: not in the manifest (rendered now; --bless adds it)"
            ),
        };
    }
    // Nothing is written, neither into the checked folder nor elsewhere: a check leaves no
    // folder behind. The report says how to look at the new pictures and how to accept them.
    let folder = manifest_path.parent().unwrap_or(Path::new("."));
    for r in rendered {
        let old = folder.join(format!("{}.{}", r.name, r.data.extension));
        if let Some(said) = std::fs::read(&old)
            .ok()
            .and_then(|before| data_change(&before, &r.data.bytes))
        {
            let _ = writeln!(text, "{}.{}: {said}", r.name, r.data.extension);
        }
    }
    let _ = writeln!(
        text,
        "to look at the new pictures, render them into another folder: the same command with \
         another --out and without --check"
    );
    let _ = writeln!(
        text,
        "if the change is meant, accept it: the same command with --bless instead of --check"
    );
    let names: Vec<&str> = diffs.iter().map(manifest::Difference::file).collect();
    Ok(Done::Failed {
        text,
        summary: format!(
            "{} {} from {shown}: {}",
            pictures(diffs.len()),
            if diffs.len() == 1 {
                "differs"
            } else {
                "differ"
            },
            names.join(", ")
        ),
    })
}

/// Flags of `scenes`.
#[derive(Debug, Clone, Args)]
pub struct ScenesArgs {
    /// Scenes to list: names, scene files or folders (default: every built-in scene).
    #[arg(value_name = "SCENE", value_parser = SceneArg, hide_possible_values = true)]
    pub scenes: Vec<String>,
    /// Print the reference of every scene key instead (charts/README.md, built in): the
    /// top-level keys, `[scene]`, `[size]` and each chart kind's `[chart]` keys with an example.
    #[arg(long, conflicts_with = "scenes")]
    pub keys: bool,
}

/// One line per scene: name, chart kind, title.
pub fn list(a: &ScenesArgs) -> Result<String> {
    if a.keys {
        return Ok(charts::SCENE_KEYS.to_string());
    }
    let scenes = load_scenes(&a.scenes, None, &[])?;
    let name_w = scenes.iter().map(|s| s.name.len()).max().unwrap_or(0);
    let kind_w = scenes
        .iter()
        .map(|s| s.chart.kind().len())
        .max()
        .unwrap_or(0);
    let mut text = String::new();
    for s in &scenes {
        let _ = writeln!(
            text,
            "{:name_w$}  {:kind_w$}  {}",
            s.name,
            s.chart.kind(),
            s.title
        );
    }
    Ok(text)
}

#[cfg(test)]
mod tests {
    use super::data_change;

    /// A failed `--check` said only which pictures changed: it now says how the data moved.
    #[test]
    fn a_failed_check_says_how_the_data_changed() {
        let before = br#"{"x_jam_mm": 24.35, "rows": [1, 2], "title": "t"}"#;
        let now = br#"{"x_jam_mm": 26.1, "rows": [1, 2, 3], "title": "t"}"#;
        assert_eq!(
            data_change(before, now).unwrap(),
            "the data changed too (2 fields): /x_jam_mm: 24.35 -> 26.1, /rows: 2 items -> 3"
        );
        let said = data_change(b"mu,x\n0.1,2\n0.2,3\n", b"mu,x\n0.1,2\n0.2,4\n").unwrap();
        assert_eq!(
            said,
            "the data changed too (1 of 3 rows; first at line 3: 0.2,3 -> 0.2,4)"
        );
        assert_eq!(data_change(b"same", b"same"), None);
    }
}
