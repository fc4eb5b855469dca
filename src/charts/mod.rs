//! Design charts: scenes (`charts/<name>.toml`) computed from the grid and models, drawn with
//! plotters to byte-identical SVG and PNG, with the data behind each chart.
//!
//! A scene is loaded ([`spec::load_scene`]), its chart computes only what its layers draw
//! (`Chart::compute`), then one backend-generic `draw` produces both the SVG and the PNG.
//! Bytes depend only on the scene: the font is embedded and text set by `typeset`, the PNG has no
//! metadata (`output::encode_png`), nothing is random and every number that feeds a pixel is
//! computed the same way for any thread count.
//!
//! Chart kinds, one module each: `jam_map` (Fig. 3), `sweep` (Figs. 6, 7a, 7b),
//! `contour_map` (Fig. 7c), `universal` (theta_jam and x_jam / r over mu and F / (m g), for any
//! part), `convergence` (Fig. 4), `time_series` (Fig. 5),
//! `work_precision` (the accuracy study), `stability` (the stability matrix),
//! `vlocator_capacity`, `vlocator_optimum` and `vlocator_robust` (V-type locators,
//! [`crate::locator`]); `error_time` draws `jamchart accuracy`'s wall-time chart, which is not
//! a scene. The x-y kinds draw through `xy`, stacked x-y
//! panels. Min-norm programs and simulations are called through `models::Models`, so a test
//! can count them: a scene computes only what it draws.
//!
//! ## Where the other models plug in
//!
//! - Points of a model on a sweep (Fig. 6: min-norm points, simulation points with motion and
//!   force drive): one `sweep_layers::SweepLayer` variant and its arm in
//!   `sweep_layers::series`, returning `sweep_layers::Series` of markers; legend, panels, data file
//!   and hashes follow.
//! - A model over a map (jam map boundary and read-off, contour map): nothing to do here. Maps
//!   name any model of the port ([`crate::models::ModelKind`]: `model = "min_norm"`) and call
//!   it per cell through `models::Models::solve`.
//! - A new chart kind: what it computes in `figures/<kind>.rs` (its `[chart]` settings,
//!   implementing `figures::Figure` with its checks and `compute` through the model
//!   port, and a `Serialize` data type implementing `figures::FigureData`, whose serde
//!   form is the data file), how it looks in `charts/<kind>.rs` (implementing `picture::Picture`:
//!   a backend-generic `draw` of that data and its gallery read-off; x-y panels through `xy`, as
//!   `convergence` and `time_series` do), then one line in the list of `kinds.rs`, which
//!   generates [`ChartSpec`], `Chart` and their dispatch. A scene `charts/<name>.toml` is built
//!   in by `build.rs`; its keys go in charts/README.md (`tests/scene_docs.rs` checks it).
//!
//! Beside the kinds: `axes` draws frames and ticks that `ticks` places, `colorbar` the colour bar of a
//! filled map, `labels` words
//! the axes and subtitles, `contours` maps the contour crate's geometry to plot space,
//! `data` holds the data files, `readoff` what the gallery's read-off embeds (every kind:
//! plotting areas as drawn, axes, data) and `gallery` writes `index.html`.

pub(crate) mod axes;
pub(crate) mod builtin;
pub(crate) mod collide;
pub(crate) mod colorbar;
pub(crate) mod contour_map;

pub(crate) mod convergence;
pub(crate) mod data;
pub(crate) mod error_time;
pub(crate) mod gallery;
pub(crate) mod jam_map;
pub(crate) mod jam_probability;
mod kinds;
pub(crate) mod labels;
pub(crate) mod legend;

pub(crate) mod output;
pub(crate) mod overrides;
pub(crate) mod picture;
pub(crate) mod point_read_off;
pub(crate) mod print;
pub(crate) mod readoff;
pub(crate) mod scene_uncertain;
pub(crate) mod spec;
pub(crate) mod stability;
pub(crate) mod style;
pub(crate) mod sweep;
pub(crate) mod sweep_band;
mod tape;
pub(crate) mod ticks;
pub(crate) mod time_series;
mod title;
pub(crate) mod typeset;
pub(crate) mod universal;
pub(crate) mod vlocator_capacity;
pub(crate) mod vlocator_optimum;
pub(crate) mod vlocator_robust;
pub(crate) mod work_precision;
pub(crate) mod xy;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::atomic::Content;
use crate::error::{Error, Result};
pub(crate) use crate::figures::contours::{grid_lines, grid_polygons};
use axes::DrawResult;
pub(crate) use builtin::SCENE_KEYS;
pub use builtin::scene_names as builtin_scene_names;
#[cfg(feature = "serve")]
pub(crate) use gallery::READ_OFF_JS as GALLERY_JS;

pub use data::DataFile;
pub(crate) use kinds::Chart;
pub use kinds::ChartSpec;
pub(crate) use labels::{
    axis_label, param_symbol, param_unit, scene_subtitle, scene_subtitle_with,
};
pub use output::Paper;
pub use overrides::Setting;
pub use print::Ink;
pub use spec::Size;
pub(crate) use spec::scene_files;
pub use spec::{Scene, SceneSource, load_scene, scene_names};

/// The chart format: the first 12 hex digits of the SHA-256 of `charts/SHA256SUMS`, the built-in
/// charts' hashes. `jamchart --version` prints it; it changes whenever the bytes of any built-in
/// chart do (a drawing, font, encoder or scene change), so a user whose own charts' hashes
/// changed can tell whether jamchart's drawing did. `tests/chart_hashes.rs` fails until it is
/// set to the manifest's hash after a re-bless (`sha256sum charts/SHA256SUMS | cut -c1-12`).
pub const CHART_FORMAT: &str = "0f023b4a8dcd";

/// Which pictures to produce.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formats {
    /// SVG only.
    Svg,
    /// PNG only.
    Png,
    /// SVG and PNG.
    Both,
    /// PDF only (for print; made from the SVG drawing by svg2pdf, so it embeds no font), on
    /// the chart's own size or fitted onto a sheet of paper.
    Pdf(Option<Paper>),
}

impl Formats {
    /// Whether an SVG is wanted.
    pub fn svg(self) -> bool {
        matches!(self, Formats::Svg | Formats::Both)
    }
    /// Whether a PNG is wanted.
    pub fn png(self) -> bool {
        matches!(self, Formats::Png | Formats::Both)
    }
    /// Whether a PDF is wanted.
    pub fn pdf(self) -> bool {
        matches!(self, Formats::Pdf(_))
    }
}

/// One rendered scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Rendered {
    /// Scene name.
    pub name: String,
    /// SVG bytes, if requested.
    pub svg: Option<Vec<u8>>,
    /// PNG bytes, if requested.
    pub png: Option<Vec<u8>>,
    /// PDF bytes, if requested.
    pub pdf: Option<Vec<u8>>,
    /// The data behind the chart.
    pub data: DataFile,
    /// A map's cells as long-format CSV (one row per cell), beside its JSON: written to its
    /// file as it is made ([`CellsCsv::write`]), never held whole in memory.
    pub cells: Option<CellsCsv>,
    /// What the gallery's read-off needs as the page embeds it: `readoff::ReadOffData`'s
    /// compact JSON, numbers at 7 significant digits; None where the frames do not match the
    /// drawing.
    pub read_off: Option<String>,
    /// The computed figure the pictures and files were made from.
    pub computed: Computed,
    /// The pictures' size in px (width, height): what a PDF on paper is fitted from.
    pub size_px: (u32, u32),
}

/// A computed chart: the figure's typed data, as its kind computed it.
#[derive(Clone)]
pub struct Computed(std::sync::Arc<Chart>);

impl Computed {
    /// The figure's typed data as its serde form, every number as computed (the data file
    /// rounds them to 7 significant digits): what a face hands its user without reading the
    /// file back.
    pub fn data(&self) -> serde_json::Value {
        self.0.data_value()
    }
}

impl std::fmt::Debug for Computed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Computed(..)")
    }
}

impl PartialEq for Computed {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0) || self.data() == other.data()
    }
}

/// A map's cells CSV, made from its computed chart when it is written.
#[derive(Clone)]
pub struct CellsCsv(std::sync::Arc<Chart>);

impl CellsCsv {
    /// The file extension.
    pub const EXTENSION: &str = "csv";

    /// Writes the CSV to `out` as it is made, a row buffer at a time (`csv_out::write_grid_cells`).
    pub fn write(&self, out: &mut dyn std::io::Write) -> std::io::Result<()> {
        match self.0.cells() {
            Some(table) => table.write(out),
            None => Ok(()),
        }
    }

    /// The whole CSV in memory.
    pub fn to_bytes(&self) -> Vec<u8> {
        self.0.cells().map(|t| t.to_bytes()).unwrap_or_default()
    }
}

impl std::fmt::Debug for CellsCsv {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("CellsCsv(..)")
    }
}

impl PartialEq for CellsCsv {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0) || self.to_bytes() == other.to_bytes()
    }
}

impl Chart {
    /// Computes what `scene`'s chart draws, with the model the scene names.
    pub fn of_scene(scene: &Scene) -> Result<Chart> {
        Self::of_scene_with(scene, &crate::figures::models::Live)
    }

    /// [`Chart::of_scene`], min-norm programs and simulations through `models`.
    pub(crate) fn of_scene_with(
        scene: &Scene,
        models: &dyn crate::figures::models::Models,
    ) -> Result<Chart> {
        Chart::compute(&scene.chart, &scene.input(), &scene.title, models)
            .map_err(|e| e.in_scene(&scene.name))
    }

    /// Draws on any plotters backend.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        root.fill(&WHITE)?;
        self.draw_kind(root)
    }
}

/// Computes and draws `scene` into the requested formats.
pub fn render(scene: &Scene, formats: Formats) -> Result<Rendered> {
    render_with(scene, formats, &|_, _| Ok(()))
}

/// Takes each file of a scene as soon as it is made: its extension and its content.
pub(crate) type Made<'a> = dyn Fn(&'static str, Content) -> Result<()> + Sync + 'a;

/// [`render`], with `made` called on each file as it is made, from the thread that made it: a
/// caller that writes files writes each there (and its sync starts), beside the rest of the
/// drawing instead of after it (`cargo bench --bench render` times `render fig3`). A map's
/// cells CSV (megabytes, the longest file) is written into the file as it is made; the PDF,
/// made from the SVG last, is not passed. An error of the drawing comes before one of `made`.
pub(crate) fn render_with(scene: &Scene, formats: Formats, made: &Made) -> Result<Rendered> {
    style::init_fonts();
    let chart = std::sync::Arc::new(Chart::of_scene(scene)?);
    let cells = chart.cells().is_some().then(|| CellsCsv(chart.clone()));
    let (w, h) = (scene.size.width_px, scene.size.height_px);
    let draw_err = |m: String| Error::Draw {
        scene: scene.name.clone(),
        message: m,
    };
    let scale = scene.size.scale;
    // A picture, and whether `made` took it: the drawing's error first.
    type Drawn = (Result<Option<(Vec<u8>, Vec<axes::PlotFrame>)>>, Result<()>);
    let hand_over = |ext, picture: &Result<Option<(Vec<u8>, _)>>, write: bool| match picture {
        Ok(Some((bytes, _))) if write => made(ext, Content::Bytes(bytes)),
        _ => Ok(()),
    };
    // The data is built beside the pictures, not after them. The PNG (drawing, palette,
    // filters, deflate) is the longest job: it starts first, on this thread. The cells CSV
    // (megabytes) comes first on a second, so that its sync runs while the SVG and the data
    // file are made. (`render fig3`: the SVG, the data file, then the CSV and its sync made
    // the second thread finish 2-4 ms after the PNG.)
    let ((png, png_made), (cells_made, ((svg, svg_made), (data, data_made)))) = rayon::join(
        || -> Drawn {
            if !formats.png() {
                return (Ok(None), Ok(()));
            }
            let (bytes, frames) = axes::record_frames(|| {
                output::png(w, h, scale, scene.style, |root| {
                    chart.draw(root).map_err(|e| e.to_string())
                })
            });
            let png = bytes.map(|b| Some((b, frames))).map_err(draw_err);
            let png_made = hand_over("png", &png, true);
            (png, png_made)
        },
        || {
            let cells_made = cells
                .as_ref()
                .map_or(Ok(()), |c| made(CellsCsv::EXTENSION, Content::Writer(c)));
            let rest = rayon::join(
                || -> Drawn {
                    // A PDF is made from the SVG drawing.
                    if !formats.svg() && !formats.pdf() {
                        return (Ok(None), Ok(()));
                    }
                    let (bytes, frames) = axes::record_frames(|| {
                        output::svg(w, h, scale, scene.style, |root| {
                            chart.draw(root).map_err(|e| e.to_string())
                        })
                    });
                    let svg = bytes.map(|b| Some((b, frames))).map_err(draw_err);
                    let svg_made = hand_over("svg", &svg, formats.svg());
                    (svg, svg_made)
                },
                || {
                    let data = chart.data_file(&scene.name, &scene.title);
                    let data_made = made(data.extension, Content::Bytes(&data.bytes));
                    (data, data_made)
                },
            );
            (cells_made, rest)
        },
    );
    let (svg, png) = (svg?, png?);
    let pdf = match (&svg, formats) {
        (Some((bytes, _)), Formats::Pdf(paper)) => {
            Some(output::pdf(bytes, (w, h), paper).map_err(draw_err)?)
        }
        _ => None,
    };
    let svg = svg.filter(|_| formats.svg());
    // Both pictures are the same drawing at the same logical size: either one's frames do.
    let frames = png.as_ref().or(svg.as_ref()).map(|(_, f)| f.as_slice());
    let read_off = chart
        .read_off(frames.unwrap_or_default())
        .map(|r| r.to_json());
    for m in [data_made, cells_made, svg_made, png_made] {
        m?;
    }
    Ok(Rendered {
        name: scene.name.clone(),
        svg: svg.map(|(b, _)| b),
        png: png.map(|(b, _)| b),
        pdf,
        data,
        cells,
        read_off,
        computed: Computed(chart),
        size_px: (w, h),
    })
}

#[cfg(test)]
mod layout_tests;
#[cfg(test)]
mod map_colour_tests;
#[cfg(test)]
mod override_tests;
#[cfg(test)]
mod readoff_tests;
#[cfg(test)]
mod series_tests;
#[cfg(test)]
mod tests;
