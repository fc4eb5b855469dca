//! Anti-aliasing in a few levels, so that a chart's PNG keeps a palette.

use plotters_backend::{BackendColor, BackendStyle, DrawingBackend, rasterizer};

use super::stroke;
use super::{Drawn, Px, Restyled};

/// Anti-aliasing levels of a PNG pixel: coverage is rounded to k / 8. Eight keep text and
/// slanted lines smooth to the eye while the colours of a chart stay within a 256-entry palette.
pub const COVERAGE_LEVELS: f64 = 8.0;

/// A bitmap backend whose anti-aliased pixels take one of [`COVERAGE_LEVELS`] coverages.
///
/// Lines wider than 1 px that are not along a row or column (curves, slanted lines, open
/// markers) are anti-aliased by [`stroke::coverage`]; 1 px lines, polygon edges and circles are
/// rasterised by plotters' own rasteriser. Either way each pixel goes through this backend's
/// `draw_pixel`, which rounds the alpha before blending; straight 1 px lines and filled
/// rectangles go to the inner backend's fast paths with the colour's alpha rounded.
pub struct Quantise<DB>(pub DB);

fn quantised(c: BackendColor) -> BackendColor {
    BackendColor {
        alpha: round(c.alpha.clamp(0.0, 1.0) * COVERAGE_LEVELS) / COVERAGE_LEVELS,
        rgb: c.rgb,
    }
}

/// `f64::round` of `x` in 0..=COVERAGE_LEVELS (or NaN), without a call to libm: a call per
/// anti-aliased pixel. The whole part converts exactly, the fraction is exact, and a half
/// rounds up, away from zero, as `round` does.
fn round(x: f64) -> f64 {
    if !(0.0..=COVERAGE_LEVELS).contains(&x) {
        return x.round();
    }
    let whole = x as u64 as f64;
    // -0 stays -0, as `round` keeps it.
    let rounded = if x - whole >= 0.5 { whole + 1.0 } else { whole };
    rounded.copysign(x)
}

impl<DB: DrawingBackend> Quantise<DB> {
    /// An anti-aliased stroke along `points` ([`stroke::coverage`]).
    fn stroke<S: BackendStyle>(&mut self, points: &[Px], style: &S) -> Drawn<DB> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let size = self.0.get_size();
        for (p, c) in stroke::coverage(points, style.stroke_width(), size) {
            self.draw_pixel(p, color.mix(c))?;
        }
        Ok(())
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
        if style.stroke_width() > 1 && !stroke::axis_aligned(&[from, to]) {
            return self.stroke(&[from, to], style);
        }
        rasterizer::draw_line(self, from, to, style)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = Px>>(
        &mut self,
        path: I,
        s: &S,
    ) -> Drawn<DB> {
        let points: Vec<Px> = path.into_iter().collect();
        if s.stroke_width() > 1 && !stroke::axis_aligned(&points) {
            return self.stroke(&points, s);
        }
        // plotters' default: 1 px segments, or the polygon of a wide axis-aligned stroke.
        if s.stroke_width() == 1 {
            for seg in points.windows(2) {
                self.draw_line(seg[0], seg[1], s)?;
            }
            return Ok(());
        }
        let outline = rasterizer::polygonize(&points, s.stroke_width());
        self.fill_polygon(outline, &s.color())
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

#[cfg(test)]
mod tests {
    use plotters::prelude::{BLACK, BitMapBackend, Color};

    use super::*;

    /// Every coverage a pixel may have rounds as `f64::round` rounds it: each multiple of
    /// 1/1024 of the levels, the halves, and the floats next to them.
    #[test]
    fn coverage_rounds_as_std() {
        let mut xs: Vec<f64> = (0..=8 * 1024).map(|i| f64::from(i) / 1024.0).collect();
        let (down, up) = (
            |v: f64| f64::from_bits(v.to_bits() - 1),
            |v: f64| f64::from_bits(v.to_bits() + 1),
        );
        for k in 0..=8 {
            let half = f64::from(k) + 0.5;
            xs.extend([half, down(half), up(half), up(f64::from(k))]);
        }
        xs.extend([0.49999999999999994, 7.999999999999999, f64::NAN, -0.0]);
        for x in xs {
            assert_eq!(round(x).to_bits(), x.round().to_bits(), "{x}");
        }
    }

    /// Regression for "lines are not anti-aliased (visible steps)": a slanted 2 px
    /// curve drawn through the PNG's backend used to be plotters' polygon, filled at full
    /// strength, so each pixel was ink or paper; now its edges are blended.
    #[test]
    fn slanted_wide_paths_are_blended_into_the_paper() {
        let mut rgb = vec![255u8; 100 * 50 * 3];
        {
            let mut b = Quantise(BitMapBackend::with_buffer(&mut rgb, (100, 50)));
            b.draw_path(
                [(10, 10), (50, 25), (90, 40)],
                &Color::stroke_width(&BLACK, 2),
            )
            .unwrap();
            b.present().unwrap();
        }
        let blended = rgb
            .chunks_exact(3)
            .filter(|p| p[0] > 0 && p[0] < 255)
            .count();
        assert!(blended > 80, "{blended} blended pixels");
    }
}
