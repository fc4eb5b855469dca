//! Anti-aliasing in a few levels, so that a chart's PNG keeps a palette.

use plotters_backend::{BackendColor, BackendStyle, DrawingBackend, rasterizer};

use super::{Drawn, Px, Restyled};

/// Anti-aliasing levels of a PNG pixel: coverage is rounded to k / 8. Eight keep text and
/// slanted lines smooth to the eye while the colours of a chart stay within a 256-entry palette.
pub const COVERAGE_LEVELS: f64 = 8.0;

/// A bitmap backend whose anti-aliased pixels take one of [`COVERAGE_LEVELS`] coverages.
///
/// Lines, polygon edges and circles are rasterised by plotters' own rasteriser through this
/// backend's `draw_pixel`, which rounds the alpha before blending; straight 1 px lines and
/// filled rectangles go to the inner backend's fast paths with the colour's alpha rounded.
pub struct Quantise<DB>(pub DB);

fn quantised(c: BackendColor) -> BackendColor {
    BackendColor {
        alpha: (c.alpha.clamp(0.0, 1.0) * COVERAGE_LEVELS).round() / COVERAGE_LEVELS,
        rgb: c.rgb,
    }
}

impl<DB: DrawingBackend> DrawingBackend for Quantise<DB> {
    type ErrorType = DB::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.0.get_size()
    }

    fn ensure_prepared(&mut self) -> Drawn<DB> {
        self.0.ensure_prepared()
    }

    fn present(&mut self) -> Drawn<DB> {
        self.0.present()
    }

    fn draw_pixel(&mut self, p: Px, color: BackendColor) -> Drawn<DB> {
        let c = quantised(color);
        if c.alpha == 0.0 {
            return Ok(());
        }
        self.0.draw_pixel(p, c)
    }

    fn draw_line<S: BackendStyle>(&mut self, from: Px, to: Px, style: &S) -> Drawn<DB> {
        if (from.0 == to.0 || from.1 == to.1) && style.stroke_width() == 1 {
            let s = Restyled {
                color: quantised(style.color()),
                width: 1,
            };
            return self.0.draw_line(from, to, &s);
        }
        rasterizer::draw_line(self, from, to, style)
    }

    fn draw_rect<S: BackendStyle>(&mut self, ul: Px, br: Px, style: &S, fill: bool) -> Drawn<DB> {
        if fill {
            let s = Restyled {
                color: quantised(style.color()),
                width: style.stroke_width(),
            };
            return self.0.draw_rect(ul, br, &s, true);
        }
        rasterizer::draw_rect(self, ul, br, style, false)
    }
}
