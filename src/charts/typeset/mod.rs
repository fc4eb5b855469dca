//! Text set by us, not by plotters: glyphs at their true advance, the same in PNG and SVG, and
//! the `[size] scale` that enlarges a whole chart.
//!
//! [`Typeset`] wraps a plotters backend. Every call goes to the inner backend with coordinates,
//! line widths and radii multiplied by the scale; `draw_text` and `estimate_text_size` are
//! answered here from the embedded DejaVu Sans with [`ab_glyph`]:
//!
//! - Layout is done in the font's own units (integers for DejaVu): advances plus kerning, so a
//!   run is as wide at 15 px as at 30 px and no glyph is rounded to a whole pixel. plotters'
//!   own path drew each glyph's ink box at the truncated pen position and dropped the glyph's
//!   left side bearing (`rect.min.x`): narrow glyphs with a wide bearing ("i", "1") were pulled
//!   left, which is the "fricti on" and "1 0 mm" once seen in the charts.
//! - Anchors are typographic: the text box runs from the font's ascent line (`VPos::Top`) to its
//!   descent line (`VPos::Bottom`); `VPos::Center` puts the middle of that box, which is about
//!   the middle of the capitals and digits, on the anchor. A size is the box's height in px
//!   (ab_glyph's `PxScale`: ascent minus descent, 1.164 em for DejaVu Sans).
//! - PNG: each glyph is rasterised at its fractional position and its coverage blended pixel by
//!   pixel; rotations by quarter turns map pixels onto pixels exactly.
//! - SVG: each glyph used is written once as a `<path>` in `<defs>` (its TrueType outline in
//!   font units, quadratic curves, exact integers) and each text run as a `<g>` of `<use>`s at
//!   the pens' positions (a text drawn more than once, as a table's cells, is defined once and
//!   placed by one `<use>` each). The picture no longer needs DejaVu Sans on the viewer's machine and
//!   looks the same in every browser and editor. Chosen over an embedded font subset because
//!   no maintained subsetting crate is at hand offline, a `@font-face` is ignored by some SVG
//!   tools (Inkscape, librsvg before 2.52), and outlines of the few glyphs a chart uses are
//!   smaller than a font file. The text stays readable to screen readers and search through
//!   `aria-label`. plotters' SVG backend can write only `<text>`, `<polyline>` and `<polygon>`
//!   with integer points, so text is first written as a numbered `<text>` placeholder, in
//!   drawing order (what is drawn later still covers it), and [`SvgText::finish`] replaces it.
//!
//! [`Quantise`] sits under the PNG's [`Typeset`]: every anti-aliased pixel (text, lines,
//! polygon edges, circles) is blended at one of [`quantise::COVERAGE_LEVELS`] coverages, so that line art
//! keeps few colours and the PNG can be stored indexed ([`super::output::encode_png`]). Under
//! it, [`Canvas`] is the RGB buffer: plotters' bitmap backend, byte for byte, with its long
//! runs written in place.

mod canvas;
mod quantise;
mod stroke;
mod svg;

use std::cell::RefCell;
use std::rc::Rc;
use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, GlyphId, Outline, OutlinedGlyph, PxScale, ScaleFont, point};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
    FontTransform,
};

pub use canvas::Canvas;
pub use quantise::Quantise;

/// A backend pixel.
type Px = BackendCoord;
/// What a drawing call on backend `DB` returns.
type Drawn<DB> = Result<(), DrawingErrorKind<<DB as DrawingBackend>::ErrorType>>;
pub use svg::SvgText;

use super::collide::PxBox;
use super::style;
use super::tape::{self, Tape};

/// The embedded DejaVu Sans, parsed once.
fn font() -> &'static FontRef<'static> {
    static FONT: OnceLock<FontRef<'static>> = OnceLock::new();
    FONT.get_or_init(|| {
        // The bytes are the TTF shipped in the repository: a parse failure is a build defect
        // that every chart test catches at once.
        FontRef::try_from_slice(style::DEJAVU_SANS).expect("the embedded DejaVu Sans parses")
    })
}

/// The outline of glyph `id` in font units, read from the font once per thread: a chart's
/// PNG sets a few dozen glyphs hundreds of times, and reading the outline from the font's
/// tables each time was a fifth of its text.
fn outline(id: GlyphId) -> Option<Outline> {
    thread_local! {
        static OUTLINES: RefCell<std::collections::HashMap<GlyphId, Option<Outline>>> =
            RefCell::default();
    }
    OUTLINES.with_borrow_mut(|o| o.entry(id).or_insert_with(|| font().outline(id)).clone())
}

/// A run of text laid out in font units: each glyph and its pen position, and the advance.
struct Run {
    glyphs: Vec<(GlyphId, f32)>,
    advance: f32,
}

impl Run {
    fn new(text: &str) -> Run {
        let f = font();
        let mut pen = 0.0f32;
        let mut prev: Option<GlyphId> = None;
        let glyphs = text
            .chars()
            .map(|c| {
                let id = f.glyph_id(c);
                if let Some(p) = prev {
                    pen += f.kern_unscaled(p, id);
                }
                let at = pen;
                pen += f.h_advance_unscaled(id);
                prev = Some(id);
                (id, at)
            })
            .collect();
        Run {
            glyphs,
            advance: pen,
        }
    }

    /// The anchor's offset in font units: (x of the anchor from the run's start, y of the
    /// baseline below the anchor).
    fn anchor(&self, h: HPos, v: VPos) -> (f32, f32) {
        let f = font();
        let (ascent, descent) = (f.ascent_unscaled(), f.descent_unscaled());
        let x = match h {
            HPos::Left => 0.0,
            HPos::Center => self.advance / 2.0,
            HPos::Right => self.advance,
        };
        let y = match v {
            VPos::Top => ascent,
            VPos::Center => (ascent + descent) / 2.0,
            VPos::Bottom => descent,
        };
        (x, y)
    }
}

/// px per font unit for a text `size_px` tall (ascent to descent).
fn px_per_unit(size_px: f64) -> f64 {
    size_px / f64::from(font().height_unscaled())
}

/// The width and height in px of `text` at `size_px` (the box [`Typeset`] anchors).
pub fn text_size(text: &str, size_px: f64) -> (u32, u32) {
    let run = Run::new(text);
    let w = f64::from(run.advance) * px_per_unit(size_px);
    (w.round() as u32, size_px.round() as u32)
}

/// A text run as set on a picture: its text, size and box in the chart's (logical) px, from
/// the font's ascent line to its descent line and from the pen's start to its advance.
#[derive(Debug, Clone, PartialEq)]
pub struct TextBox {
    /// The text.
    pub text: String,
    /// Its size in px (ascent to descent).
    pub size_px: f64,
    /// Its box.
    pub rect: PxBox,
}

thread_local! {
    /// The text boxes [`Typeset`] set on this thread, while [`record_texts`] runs.
    static TEXTS: Tape<TextBox> = const { RefCell::new(None) };
}

/// Runs `draw` and returns, beside its result, the box of every text it set, in drawing order
/// (the layout tests: no two overlap, all inside the picture).
#[cfg(test)]
pub fn record_texts<R>(draw: impl FnOnce() -> R) -> (R, Vec<TextBox>) {
    tape::record(&TEXTS, draw)
}

/// The box of `text` at `size_px` anchored at `at` as `anchor` says, turned by `t`: what
/// [`Typeset::draw_text`] covers, in the same logical px as `at`.
fn text_box(text: &str, size_px: f64, at: Px, anchor: (HPos, VPos), t: &FontTransform) -> PxBox {
    let run = Run::new(text);
    let f = font();
    let (ax, bl) = run.anchor(anchor.0, anchor.1);
    let k = px_per_unit(size_px);
    let x = [-ax, run.advance - ax].map(|u| f64::from(u) * k);
    let y = [bl - f.ascent_unscaled(), bl - f.descent_unscaled()].map(|v| f64::from(v) * k);
    // The corners turned as glyph cells are (a quarter turn about the anchor).
    let corners = [(x[0], y[0]), (x[1], y[0]), (x[0], y[1]), (x[1], y[1])].map(|(u, v)| match t {
        FontTransform::None => (u, v),
        FontTransform::Rotate90 => (-v, u),
        FontTransform::Rotate180 => (-u, -v),
        FontTransform::Rotate270 => (v, -u),
    });
    let lo = |i: fn(&(f64, f64)) -> f64| corners.iter().map(i).fold(f64::INFINITY, f64::min);
    let hi = |i: fn(&(f64, f64)) -> f64| corners.iter().map(i).fold(f64::NEG_INFINITY, f64::max);
    let px = |v: f64, o: i32| (v + f64::from(o)).round() as i32;
    PxBox {
        x0: px(lo(|c| c.0), at.0),
        y0: px(lo(|c| c.1), at.1),
        x1: px(hi(|c| c.0), at.0),
        y1: px(hi(|c| c.1), at.1),
    }
}

/// A pixel cell (u, v) relative to a rotation centre on a pixel corner, turned by `t`.
fn turn(t: &FontTransform, (u, v): (i32, i32)) -> (i32, i32) {
    match t {
        FontTransform::None => (u, v),
        FontTransform::Rotate90 => (-v - 1, u),
        FontTransform::Rotate180 => (-u - 1, -v - 1),
        FontTransform::Rotate270 => (v, -u - 1),
    }
}

/// The degrees of `t` in SVG's sense (clockwise on screen), as plotters' `transform` turns.
fn degrees(t: &FontTransform) -> i32 {
    match t {
        FontTransform::None => 0,
        FontTransform::Rotate90 => 90,
        FontTransform::Rotate180 => 180,
        FontTransform::Rotate270 => 270,
    }
}

/// How [`Typeset`] puts text on its backend.
enum TextOut {
    /// Glyph coverage blended pixel by pixel (bitmaps).
    Raster,
    /// Placeholders on the backend, outlines collected here (SVG).
    Outlines(Rc<RefCell<SvgText>>),
}

/// A style with a given colour and stroke width (also the print style's recoloured strokes).
pub(super) struct Restyled {
    /// The colour.
    pub color: BackendColor,
    /// The stroke width in px.
    pub width: u32,
}

impl BackendStyle for Restyled {
    fn color(&self) -> BackendColor {
        self.color
    }
    fn stroke_width(&self) -> u32 {
        self.width
    }
}

/// A backend that typesets text itself and draws everything `scale` times larger on `inner`.
///
/// Charts see a drawing `scale` times smaller than the picture (the logical size), so the same
/// layout in px fills a picture of any resolution: a 2000 px wide picture at scale 2 is the
/// 1000 px one at twice the resolution. At scale 1 every call but text reaches `inner`
/// unchanged.
pub struct Typeset<DB> {
    inner: DB,
    scale: f64,
    text: TextOut,
}

impl<DB: DrawingBackend> Typeset<DB> {
    /// Text rasterised onto `inner` (a bitmap).
    pub fn raster(inner: DB, scale: f64) -> Self {
        Typeset {
            inner,
            scale,
            text: TextOut::Raster,
        }
    }

    /// Text as outlines: `inner` (plotters' SVG backend) gets placeholders, `runs` the glyphs;
    /// call [`SvgText::finish`] on the SVG afterwards.
    pub fn outlines(inner: DB, scale: f64, runs: Rc<RefCell<SvgText>>) -> Self {
        Typeset {
            inner,
            scale,
            text: TextOut::Outlines(runs),
        }
    }

    fn px(&self, p: BackendCoord) -> BackendCoord {
        if self.scale == 1.0 {
            return p;
        }
        (
            (f64::from(p.0) * self.scale).round() as i32,
            (f64::from(p.1) * self.scale).round() as i32,
        )
    }

    fn pxs<I: IntoIterator<Item = Px>>(&self, points: I) -> Vec<Px> {
        points.into_iter().map(|p| self.px(p)).collect()
    }

    fn style<S: BackendStyle>(&self, s: &S) -> Restyled {
        let w = s.stroke_width();
        let width = if w == 0 || self.scale == 1.0 {
            w
        } else {
            ((f64::from(w) * self.scale).round() as u32).max(1)
        };
        Restyled {
            color: s.color(),
            width,
        }
    }

    /// The physical cell of logical pixel `p`: its top-left and bottom-right pixels.
    fn cell(&self, p: BackendCoord) -> (BackendCoord, BackendCoord) {
        let a = self.px(p);
        let b = self.px((p.0 + 1, p.1 + 1));
        (a, (b.0 - 1, b.1 - 1))
    }
}

impl<DB: DrawingBackend> DrawingBackend for Typeset<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        let (w, h) = self.inner.get_size();
        if self.scale == 1.0 {
            return (w, h);
        }
        (
            (f64::from(w) / self.scale).round() as u32,
            (f64::from(h) / self.scale).round() as u32,
        )
    }

    fn ensure_prepared(&mut self) -> Drawn<DB> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Drawn<DB> {
        self.inner.present()
    }

    fn draw_pixel(&mut self, p: Px, color: BackendColor) -> Drawn<DB> {
        if self.scale == 1.0 {
            return self.inner.draw_pixel(p, color);
        }
        let (a, b) = self.cell(p);
        self.inner.draw_rect(a, b, &color, true)
    }

    fn draw_line<S: BackendStyle>(&mut self, from: Px, to: Px, style: &S) -> Drawn<DB> {
        let s = self.style(style);
        self.inner.draw_line(self.px(from), self.px(to), &s)
    }

    fn draw_rect<S: BackendStyle>(&mut self, ul: Px, br: Px, style: &S, fill: bool) -> Drawn<DB> {
        let s = self.style(style);
        if fill {
            let (a, _) = self.cell(ul);
            let (_, b) = self.cell(br);
            self.inner.draw_rect(a, b, &s, true)
        } else {
            self.inner.draw_rect(self.px(ul), self.px(br), &s, false)
        }
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = Px>>(&mut self, p: I, s: &S) -> Drawn<DB> {
        self.inner.draw_path(self.pxs(p), &self.style(s))
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Drawn<DB> {
        let s = self.style(style);
        let r = (f64::from(radius) * self.scale).round() as u32;
        self.inner.draw_circle(self.px(center), r, &s, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = Px>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Drawn<DB> {
        self.inner.fill_polygon(self.pxs(vert), &self.style(style))
    }

    fn blit_bitmap(&mut self, pos: BackendCoord, (iw, ih): (u32, u32), src: &[u8]) -> Drawn<DB> {
        if self.scale == 1.0 {
            return self.inner.blit_bitmap(pos, (iw, ih), src);
        }
        for dy in 0..ih {
            for dx in 0..iw {
                let i = 3 * (dy * iw + dx) as usize;
                let color = BackendColor {
                    alpha: 1.0,
                    rgb: (src[i], src[i + 1], src[i + 2]),
                };
                self.draw_pixel((pos.0 + dx as i32, pos.1 + dy as i32), color)?;
            }
        }
        Ok(())
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Drawn<DB> {
        let color = style.color();
        if color.alpha == 0.0 || text.is_empty() {
            return Ok(());
        }
        tape::note(&TEXTS, || {
            let anchor = style.anchor();
            let t = style.transform();
            TextBox {
                text: text.to_string(),
                size_px: style.size(),
                rect: text_box(text, style.size(), pos, (anchor.h_pos, anchor.v_pos), &t),
            }
        });
        let size_px = style.size() * self.scale;
        let anchor = style.anchor();
        let t = style.transform();
        let at = self.px(pos);
        match &self.text {
            TextOut::Outlines(runs) => {
                let i = runs.borrow_mut().push(
                    text,
                    size_px,
                    (f64::from(at.0), f64::from(at.1)),
                    (anchor.h_pos, anchor.v_pos),
                    t,
                    color,
                );
                self.inner.draw_text(&i.to_string(), style, at)
            }
            TextOut::Raster => {
                let run = Run::new(text);
                let (ax, bl) = run.anchor(anchor.h_pos, anchor.v_pos);
                let k = px_per_unit(size_px) as f32;
                let scale = PxScale::from(size_px as f32);
                let f = font();
                let mut cells = Vec::new();
                for (id, pen) in run.glyphs {
                    let origin = point((pen - ax) * k, bl * k);
                    // `Font::outline_glyph`, the outline read once.
                    let Some(outline) = outline(id) else {
                        continue;
                    };
                    let glyph = id.with_scale_and_position(scale, origin);
                    let g = OutlinedGlyph::new(glyph, outline, f.as_scaled(scale).scale_factor());
                    let min = g.px_bounds().min;
                    g.draw(|x, y, c| {
                        if c > 0.0 {
                            let u = min.x as i32 + x as i32;
                            let v = min.y as i32 + y as i32;
                            cells.push((turn(&t, (u, v)), c.min(1.0)));
                        }
                    });
                }
                for ((u, v), c) in cells {
                    let p = (at.0 + u, at.1 + v);
                    self.inner.draw_pixel(p, color.mix(f64::from(c)))?;
                }
                Ok(())
            }
        }
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        Ok(text_size(text, style.size()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression for "fricti on": every glyph starts where the previous one's
    /// advance (plus kerning) ends, in font units, so the gaps do not depend on the pixel grid.
    #[test]
    fn glyphs_sit_at_their_advance() {
        let f = font();
        let run = Run::new("friction");
        for w in run.glyphs.windows(2) {
            let (a, pa) = w[0];
            let (b, pb) = w[1];
            let expected = pa + f.h_advance_unscaled(a) + f.kern_unscaled(a, b);
            assert_eq!(pb.to_bits(), expected.to_bits());
        }
        // The width scales exactly with the size.
        let (w15, h15) = text_size("friction coefficient", 15.0);
        let (w30, _) = text_size("friction coefficient", 30.0);
        assert!(
            (i64::from(w30) - 2 * i64::from(w15)).abs() <= 1,
            "{w15} {w30}"
        );
        assert_eq!(h15, 15);
    }

    #[test]
    fn quarter_turns_map_cells_onto_cells() {
        for t in [
            FontTransform::None,
            FontTransform::Rotate90,
            FontTransform::Rotate180,
            FontTransform::Rotate270,
        ] {
            // The four cells around the centre are permuted, never moved away.
            let mut cells: Vec<_> = [(0, 0), (-1, 0), (0, -1), (-1, -1)]
                .into_iter()
                .map(|c| turn(&t, c))
                .collect();
            cells.sort();
            assert_eq!(cells, [(-1, -1), (-1, 0), (0, -1), (0, 0)]);
        }
        assert_eq!(turn(&FontTransform::Rotate270, (5, 0)), (0, -6));
    }

    fn fig7b(settings: &[&str]) -> crate::error::Result<crate::charts::Scene> {
        let settings: Vec<_> = settings.iter().map(|s| s.parse().unwrap()).collect();
        crate::charts::SceneSource::BuiltIn("fig7b".into()).load(&settings)
    }

    fn png_header(png: &[u8]) -> (u32, u32, u8) {
        let be = |i: usize| u32::from_be_bytes(png[i..i + 4].try_into().unwrap());
        (be(16), be(20), png[25])
    }

    /// `[size] scale = 2` on a picture twice as large is the same chart at twice the
    /// resolution: the layout sees the default size, the PNG has the doubled one and stays
    /// indexed; the SVG carries outlines only, no `<text>` and no font name.
    #[test]
    fn scale_two_doubles_the_picture_not_the_layout() {
        let scene = fig7b(&["size.width_px=2000", "size.height_px=1800", "size.scale=2"]).unwrap();
        let r = crate::charts::render(&scene, crate::charts::Formats::Both).unwrap();
        assert_eq!(png_header(r.png.as_deref().unwrap()), (2000, 1800, 3));
        let svg = String::from_utf8(r.svg.unwrap()).unwrap();
        assert!(
            svg.starts_with("<svg width=\"2000\" height=\"1800\""),
            "{}",
            &svg[..80]
        );
        assert!(!svg.contains("<text") && !svg.contains("font-family"));
        assert!(svg.contains("aria-label=\"palm push F (N)\""));
    }

    #[test]
    fn scale_leaving_too_little_room_is_refused_by_name() {
        let e = fig7b(&["size.scale=3"]).unwrap_err().to_string();
        assert!(e.contains("size.scale") && e.contains("333 x 300"), "{e}");
        let e = fig7b(&["size.scale=0.25"]).unwrap_err().to_string();
        assert!(e.contains("size.scale") && e.contains("0.5..=4"), "{e}");
    }
}
