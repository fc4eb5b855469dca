//! The one visual style of every chart: embedded font, colours, line kinds and markers.
//!
//! Colour-blind safe: curves and markers take the Okabe-Ito palette, filled bands a sequential
//! part of viridis. Every distinction is also made without colour, so a greyscale print still
//! reads: curves differ by dash pattern and width, point sets by marker shape and fill.

use std::sync::Once;

use plotters::coord::CoordTranslate;
use plotters::prelude::*;
use plotters::style::FontStyle;

/// The font family every chart uses. Charts are drawn through [`super::typeset::Typeset`], which
/// sets all text in the embedded DejaVu Sans (outlines in the SVG, so no viewer needs the font);
/// [`init_fonts`] also binds the name for plotters' own text path.
pub const FONT: &str = "DejaVu Sans";

/// DejaVu Sans 2.37 (Debian fonts-dejavu-core), licence in `assets/fonts/LICENSE-DejaVu.txt`.
/// Embedded so that no system font is ever looked up and the pixels are the same everywhere.
pub(super) static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Registers the embedded font with plotters (once per process; later calls do nothing).
pub fn init_fonts() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // The bytes are a valid TTF shipped in the repository; a failure here is a build defect
        // that the chart hash test catches at once.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, DEJAVU_SANS);
    });
}

// Text sizes are the height in px from the font's ascent line to its descent line (1.164 em of
// DejaVu Sans; digits and capitals are 0.63 of it), at `[size] scale = 1`.

/// Title text size in px.
pub const TITLE_PX: f64 = 22.0;
/// Axis label text size in px.
pub const LABEL_PX: f64 = 17.0;
/// Tick label and legend text size in px.
pub const TICK_PX: f64 = 16.0;
/// Annotation text size in px.
pub const NOTE_PX: f64 = 15.0;

/// Ink for curves, text and frames.
pub const INK: RGBColor = RGBColor(0, 0, 0);
/// Major grid lines.
pub const GRID_MAJOR: RGBColor = RGBColor(190, 190, 190);
/// Minor grid lines.
pub const GRID_MINOR: RGBColor = RGBColor(228, 228, 228);
/// The jammed region of a map: a light tint of Okabe-Ito vermillion (#D55E00), dark enough to
/// stay apart from white in greyscale (luma about 200).
pub const JAM_FILL: RGBColor = RGBColor(240, 190, 160);

/// The shaded band of an uncertain input on a sweep, and the robust V-block's window of
/// included angles: Okabe-Ito sky blue (#56B4E9) at 30 % on white, light enough that the
/// band's dashed edges and the black curve read over it, and a light grey (luma 225) in print.
pub const BAND_FILL: RGBColor = RGBColor(204, 232, 248);

/// The Okabe-Ito palette (Okabe and Ito, "Color Universal Design", 2008): black, orange, sky
/// blue, bluish green, yellow, blue, vermillion, reddish purple.
pub const OKABE_ITO: [RGBColor; 8] = [
    RGBColor(0, 0, 0),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 158, 115),
    RGBColor(240, 228, 66),
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(204, 121, 167),
];
/// The sliding region of a map.
pub const SLIDE_FILL: RGBColor = RGBColor(255, 255, 255);
/// Background of labels drawn over data.
pub const PAPER: RGBColor = RGBColor(255, 255, 255);

/// A text style of the chart font.
pub fn text(size_px: f64) -> TextStyle<'static> {
    (FONT, size_px).into_font().color(&INK)
}

/// Viridis (matplotlib's perceptually uniform map) at t = 0, 1/8, ..., 1.
const VIRIDIS: [(u8, u8, u8); 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];

/// Viridis at `t` in [0, 1], linear between its anchors.
pub fn viridis(t: f64) -> RGBColor {
    let x = t.clamp(0.0, 1.0) * 8.0;
    let i = (x.floor() as usize).min(7);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (p as f64 + (q as f64 - p as f64) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// `n` colours from light to dark for filled bands: viridis from yellow (t = 1) down to
/// t = 0.35, so that black lines and labels on the darkest band still read; darker is larger,
/// in colour and in greyscale alike.
pub fn band_colors(n: usize) -> Vec<RGBColor> {
    (0..n)
        .map(|i| {
            let s = if n > 1 {
                i as f64 / (n - 1) as f64
            } else {
                0.0
            };
            viridis(1.0 - 0.65 * s)
        })
        .collect()
}

/// How a curve is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineKind {
    /// Solid, 2 px: the model's main curve.
    Solid,
    /// Long dashes, 2 px: limits and thresholds.
    Dashed,
    /// Short dashes, 1 px: construction lines.
    Dotted,
    /// Dots, 2 px, reddish purple: a closed-form level drawn beside construction lines (fig5's
    /// r/mu beside its jam threshold, once both thin blue dashes).
    Level,
    /// Dash-dot-like short dashes, 2 px, bluish green: the earliest-jam edge of an uncertain
    /// input's band.
    BandEarliest,
    /// Long-gap dashes, 2 px, orange: the latest-jam edge of the band (once both edges were the
    /// construction lines' thin blue dash, told apart by nothing).
    BandLatest,
    /// The n-th of a family of like curves (one per friction, one per method), 2 px: solid,
    /// then a dash pattern of its own per member ([`FAMILY_DASHES`]), so that the members read
    /// apart in a black-and-white print, where their colours are near-equal greys.
    Family(u8),
}

/// The dash patterns (dash, gap) of [`LineKind::Family`]'s members after the first (solid),
/// in px: long, dotted, medium, short with long gaps, very long; then they repeat.
const FAMILY_DASHES: [(u32, u32); 5] = [(10, 5), (2, 4), (6, 3), (3, 7), (18, 5)];

impl LineKind {
    /// The colour: black for a model's curve, Okabe-Ito vermillion for limits and blue for
    /// construction lines (black reads on every band of a filled map).
    pub fn color(self) -> RGBColor {
        match self {
            LineKind::Solid => INK,
            LineKind::Dashed => OKABE_ITO[6],
            LineKind::Dotted => OKABE_ITO[5],
            LineKind::Level => OKABE_ITO[7],
            LineKind::BandEarliest => OKABE_ITO[3],
            LineKind::BandLatest => OKABE_ITO[1],
            // Black, then the Okabe-Ito colours that read on white (no yellow).
            LineKind::Family(n) => [0, 6, 5, 3, 1, 7, 2].map(|i| OKABE_ITO[i])[n as usize % 7],
        }
    }

    /// The stroke width in px.
    pub fn width(self) -> u32 {
        match self {
            LineKind::Solid
            | LineKind::Dashed
            | LineKind::Level
            | LineKind::BandEarliest
            | LineKind::BandLatest
            | LineKind::Family(_) => 2,
            LineKind::Dotted => 1,
        }
    }

    /// (dash, gap) in px, None for solid.
    pub fn dashes(self) -> Option<(u32, u32)> {
        match self {
            LineKind::Solid => None,
            LineKind::Dashed => Some((10, 6)),
            LineKind::Dotted => Some((4, 4)),
            LineKind::Level => Some((2, 4)),
            LineKind::BandEarliest => Some((6, 3)),
            LineKind::BandLatest => Some((3, 6)),
            LineKind::Family(0) => None,
            LineKind::Family(n) => Some(FAMILY_DASHES[(n as usize - 1) % FAMILY_DASHES.len()]),
        }
    }
}

/// Draws a polyline in `area`'s coordinates with the given line kind.
pub fn draw_line<DB, CT>(
    area: &DrawingArea<DB, CT>,
    points: &[CT::From],
    kind: LineKind,
    color: RGBColor,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>>
where
    DB: DrawingBackend,
    CT: CoordTranslate,
    CT::From: Clone,
{
    draw_line_px(area, points, kind, color, kind.width())
}

/// Marker shapes for point sets; open and filled variants tell sources apart in greyscale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// Open circle.
    Circle,
    /// Filled circle.
    Dot,
    /// Small filled triangle (fits inside an open circle at the same point).
    Triangle,
    /// Filled square.
    Square,
    /// Diagonal cross.
    Cross,
    /// Large open square (drawn around the smaller markers at the same point).
    OpenSquare,
    /// Upright cross (+).
    Plus,
    /// Filled diamond.
    Diamond,
    /// Large open diamond (drawn around a filled diamond at the same point).
    OpenDiamond,
}

impl Marker {
    /// The colour: an Okabe-Ito colour per shape, so a source differs by both.
    pub fn color(self) -> RGBColor {
        match self {
            Marker::Circle => OKABE_ITO[5],
            Marker::Dot => OKABE_ITO[0],
            Marker::Triangle => OKABE_ITO[6],
            // Orange, not the diamond's green: fig6's Adams square sat beside the green
            // motion-drive diamonds, and the V-block chart's mu = 0.4 and 0.5 were both green.
            Marker::Square => OKABE_ITO[1],
            Marker::Cross => OKABE_ITO[7],
            // Black: around the Table 1 circle and triangle (blue, vermillion) at the same
            // point, a third hue apart from both.
            Marker::OpenSquare => OKABE_ITO[0],
            Marker::Plus => OKABE_ITO[2],
            Marker::Diamond => OKABE_ITO[3],
            Marker::OpenDiamond => OKABE_ITO[7],
        }
    }
}

/// The colour of a line drawn with markers on it: the marker's, so that line and markers read
/// as one series and two such lines differ by colour, not by their markers alone
/// (integration-error's radau5 and min-norm curves were both black solid lines).
pub fn marked_line_color(marker: Marker) -> RGBColor {
    marker.color()
}

/// Draws one marker at `at` in `area`'s coordinates.
pub fn draw_marker<DB, CT>(
    area: &DrawingArea<DB, CT>,
    marker: Marker,
    at: CT::From,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>>
where
    DB: DrawingBackend,
    CT: CoordTranslate,
{
    let ink = marker.color();
    let open = ink.stroke_width(2);
    let fill = ink.filled();
    let anchor = EmptyElement::at(at);
    match marker {
        Marker::Circle => area.draw(&(anchor + Circle::new((0, 0), 8, open))),
        Marker::Dot => area.draw(&(anchor + Circle::new((0, 0), 4, fill))),
        Marker::Triangle => area.draw(&(anchor + TriangleMarker::new((0, 0), 5, fill))),
        Marker::Square => area.draw(&(anchor + Rectangle::new([(-5, -5), (5, 5)], fill))),
        Marker::Cross => area.draw(&(anchor + Cross::new((0, 0), 7, ink.stroke_width(3)))),
        Marker::OpenSquare => area.draw(&(anchor + Rectangle::new([(-11, -11), (11, 11)], open))),
        // One path over both bars (back over the centre).
        Marker::Plus => area.draw(
            &(anchor
                + PathElement::new(
                    vec![(-7, 0), (7, 0), (0, 0), (0, -7), (0, 7)],
                    ink.stroke_width(2),
                )),
        ),
        Marker::Diamond => {
            area.draw(&(anchor + Polygon::new(vec![(0, -6), (6, 0), (0, 6), (-6, 0)], fill)))
        }
        Marker::OpenDiamond => area.draw(
            &(anchor
                + PathElement::new(vec![(0, -11), (11, 0), (0, 11), (-11, 0), (0, -11)], open)),
        ),
    }
}

/// Formats `v` with `decimals` digits after the point, never printing "-0".
pub fn fmt_num(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Draws a polyline like [`draw_line`] with `kind`'s dashes but `width_px` wide (a line that
/// must stay visible where it runs on a wider one).
pub fn draw_line_px<DB, CT>(
    area: &DrawingArea<DB, CT>,
    points: &[CT::From],
    kind: LineKind,
    color: RGBColor,
    width_px: u32,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>>
where
    DB: DrawingBackend,
    CT: CoordTranslate,
    CT::From: Clone,
{
    let style = color.stroke_width(width_px);
    match kind.dashes() {
        None => area.draw(&PathElement::new(points.to_vec(), style)),
        Some((dash, gap)) => {
            for e in DashedLineSeries::new(points.iter().cloned(), dash, gap, style) {
                area.draw(&e)?;
            }
            Ok(())
        }
    }
}
