//! The two inks a chart is drawn in: colour (default) and a greyscale print style.
//!
//! The print style is not a second set of drawing code: every chart draws as usual through
//! [`Grey`], a backend that turns each colour it is given into a grey before passing it on.
//! Every distinction a chart makes is already made without colour too (dash patterns, widths,
//! marker shapes and fills, see [`super::style`]), so the greys only have to keep light fills
//! light and coloured strokes dark:
//!
//! - fills (bands, regions, filled markers) take their luma (ITU-R BT.601), so a sequential
//!   colour map stays a monotone grey ramp and its colour bar still reads;
//! - strokes (curves, outlines, grid lines) take their luma darkened by their chroma, so a
//!   light grey grid line stays light while an orange or sky-blue curve prints dark;
//! - text is passed on unchanged (it is black).

use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};
use serde::{Deserialize, Serialize};

use super::typeset::Restyled;

/// The scene's top-level `style`: the ink every part of the chart is drawn in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Ink {
    /// Okabe-Ito curves and markers, viridis bands (default).
    #[default]
    Colour,
    /// Black and greys only, for a black-and-white print.
    Print,
}

/// A backend that draws on `DB` in the given ink: in greys for [`Ink::Print`], unchanged for
/// [`Ink::Colour`] (so that every chart goes through the same stack of backends).
pub struct Grey<DB>(pub DB, pub Ink);

impl<DB> Grey<DB> {
    /// `to_grey` in print, no change in colour.
    fn tone(&self, to_grey: ToGrey) -> ToGrey {
        match self.1 {
            Ink::Colour => |c| c,
            Ink::Print => to_grey,
        }
    }
}

/// The luma of `c` in 0..=255 (BT.601 weights).
fn luma((r, g, b): (u8, u8, u8)) -> f64 {
    0.299 * r as f64 + 0.587 * g as f64 + 0.114 * b as f64
}

/// A fill's grey: its luma.
pub fn fill_grey(c: (u8, u8, u8)) -> (u8, u8, u8) {
    let v = luma(c).round() as u8;
    (v, v, v)
}

/// A stroke's grey: its luma, darkened by up to 60 % for a fully saturated colour (greys keep
/// their luma).
pub fn stroke_grey(c: (u8, u8, u8)) -> (u8, u8, u8) {
    let (hi, lo) = (c.0.max(c.1).max(c.2), c.0.min(c.1).min(c.2));
    let chroma = (hi - lo) as f64 / 255.0;
    let v = (luma(c) * (1.0 - 0.6 * chroma)).round() as u8;
    (v, v, v)
}

/// A colour-to-grey map: [`fill_grey`] or [`stroke_grey`].
type ToGrey = fn((u8, u8, u8)) -> (u8, u8, u8);

fn recolour<S: BackendStyle>(s: &S, grey: ToGrey) -> Restyled {
    let c = s.color();
    Restyled {
        color: BackendColor {
            alpha: c.alpha,
            rgb: grey(c.rgb),
        },
        width: s.stroke_width(),
    }
}

fn by_fill(fill: bool) -> ToGrey {
    if fill { fill_grey } else { stroke_grey }
}

impl<DB: DrawingBackend> DrawingBackend for Grey<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = BackendColor {
            alpha: color.alpha,
            rgb: self.tone(stroke_grey)(color.rgb),
        };
        self.0.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0
            .draw_line(from, to, &recolour(style, self.tone(stroke_grey)))
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let s = recolour(style, self.tone(by_fill(fill)));
        self.0.draw_rect(upper_left, bottom_right, &s, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0
            .draw_path(path, &recolour(style, self.tone(stroke_grey)))
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let s = recolour(style, self.tone(by_fill(fill)));
        self.0.draw_circle(center, radius, &s, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0
            .fill_polygon(vert, &recolour(style, self.tone(fill_grey)))
    }

    fn draw_text<TStyle: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &TStyle,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.0.draw_text(text, style, pos)
    }

    fn estimate_text_size<TStyle: BackendTextStyle>(
        &self,
        text: &str,
        style: &TStyle,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        self.0.estimate_text_size(text, style)
    }

    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (w, h): (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if self.1 == Ink::Colour {
            return self.0.blit_bitmap(pos, (w, h), src);
        }
        let grey: Vec<u8> = src
            .chunks_exact(3)
            .flat_map(|p| {
                let (v, _, _) = fill_grey((p[0], p[1], p[2]));
                [v, v, v]
            })
            .collect();
        self.0.blit_bitmap(pos, (w, h), &grey)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn greys_stay_greys_and_colours_print_dark_as_strokes() {
        assert_eq!(stroke_grey((190, 190, 190)), (190, 190, 190));
        assert_eq!(fill_grey((255, 255, 255)), (255, 255, 255));
        // Okabe-Ito orange: light as a fill, dark as a curve.
        let (f, _, _) = fill_grey((230, 159, 0));
        let (s, _, _) = stroke_grey((230, 159, 0));
        assert!(s < 100 && f > 150, "{s} {f}");
    }

    #[test]
    fn band_colours_stay_a_monotone_grey_ramp() {
        let greys: Vec<u8> = super::super::style::band_colors(9)
            .iter()
            .map(|c| fill_grey((c.0, c.1, c.2)).0)
            .collect();
        assert!(greys.windows(2).all(|w| w[0] > w[1]), "{greys:?}");
    }
}
