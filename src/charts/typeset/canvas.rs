//! The PNG's drawing surface: an RGB8 buffer that plotters draws on as it draws on its
//! `BitMapBackend`, pixel for pixel, with each pixel written in place.
//!
//! plotters' bitmap backend fills a vertical run a pixel at a time through its generic pixel
//! format (an index, a bounds check and a match per byte): a jam map's region is filled by
//! plotters' polygon sweep in vertical runs, and that was 10 M instructions of `render fig3`'s
//! 30 M of drawing. Here a run is written in a loop of its own. Every other operation makes
//! the bytes plotters-bitmap 0.3.7 makes, in its order: opaque fills set the colour, blends go
//! through its 8-pixel word blend and its per-byte `blend` where it uses them (the two round
//! differently, so which one a pixel takes matters); the chart hashes check it.

use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, DrawingBackend, DrawingErrorKind, rasterizer,
};

/// An RGB8 buffer `size` px (width, height), row after row, drawn on by plotters.
pub struct Canvas<'a> {
    rgb: &'a mut [u8],
    size: (u32, u32),
}

impl<'a> Canvas<'a> {
    /// The canvas over `rgb`, which holds `size.0 * size.1` pixels of 3 bytes.
    pub fn new(rgb: &'a mut [u8], size: (u32, u32)) -> Self {
        assert_eq!(
            rgb.len(),
            3 * size.0 as usize * size.1 as usize,
            "an RGB8 buffer of the canvas's size"
        );
        Canvas { rgb, size }
    }

    fn width(&self) -> i32 {
        self.size.0 as i32
    }

    /// The rectangle spanned by corners `a` and `b` (the larger ones exclusive), clipped to
    /// the canvas: (x0, y0, x1, y1), or None when empty.
    fn clip(&self, a: BackendCoord, b: BackendCoord) -> Option<(i32, i32, i32, i32)> {
        let (w, h) = (self.size.0 as i32, self.size.1 as i32);
        let (x0, y0) = (a.0.min(b.0).max(0), a.1.min(b.1).max(0));
        let (x1, y1) = (a.0.max(b.0).min(w), a.1.max(b.1).min(h));
        (x0 < x1 && y0 < y1).then_some((x0, y0, x1, y1))
    }

    /// plotters-bitmap's `fill_rect_fast`: every pixel of the rectangle set to `rgb`.
    fn fill_rect(&mut self, a: BackendCoord, b: BackendCoord, (r, g, b_): (u8, u8, u8)) {
        let Some((x0, y0, x1, y1)) = self.clip(a, b) else {
            return;
        };
        let w = self.width();
        // Sixteen pixels of the colour, copied at once (a grey is one byte: a plain fill).
        let mut pattern = [0u8; 48];
        for px in pattern.chunks_exact_mut(3) {
            px.copy_from_slice(&[r, g, b_]);
        }
        for y in y0..y1 {
            let start = 3 * (y * w + x0) as usize;
            let row = &mut self.rgb[start..start + 3 * (x1 - x0) as usize];
            if r == g && g == b_ {
                row.fill(r);
                continue;
            }
            let mut pieces = row.chunks_exact_mut(pattern.len());
            for piece in &mut pieces {
                piece.copy_from_slice(&pattern);
            }
            let rest = pieces.into_remainder();
            let n = rest.len();
            rest.copy_from_slice(&pattern[..n]);
        }
    }

    /// plotters-bitmap's `fill_vertical_line_fast`: pixels (x, y0..=y1) set to `rgb`.
    fn fill_column(&mut self, x: i32, (y0, y1): (i32, i32), rgb: (u8, u8, u8)) {
        let (w, h) = (self.width(), self.size.1 as i32);
        if x < 0 || x >= w {
            return;
        }
        let (y0, y1) = (y0.min(y1).max(0), y0.max(y1).min(h - 1));
        if y0 > y1 {
            return;
        }
        let stride = 3 * w as usize;
        let first = 3 * (y0 * w + x) as usize;
        let rows = (y1 - y0) as usize + 1;
        let column = &mut self.rgb[first..first + stride * (rows - 1) + 3];
        // A pixel every `stride` bytes, written through a pointer: a bounds check and a slice
        // per pixel took as long as the rest of the polygon's fill.
        let at = column.as_mut_ptr();
        for k in 0..rows {
            // SAFETY: k * stride + 2 <= stride * (rows - 1) + 2 < column.len(), so the three
            // bytes lie in `column`, which is borrowed mutably here.
            unsafe {
                let px = at.add(k * stride);
                *px = rgb.0;
                *px.add(1) = rgb.1;
                *px.add(2) = rgb.2;
            }
        }
    }

    /// plotters-bitmap's RGB `blend_rect_fast`: the rectangle blended towards `rgb` by
    /// `alpha`, eight pixels (three words) at a time in 16-bit lanes, the rest of each row
    /// (at least one pixel) byte by byte with [`blend`].
    fn blend_rect(
        &mut self,
        a: BackendCoord,
        b: BackendCoord,
        (r, g, b_): (u8, u8, u8),
        alpha: f64,
    ) {
        let alpha = alpha.clamp(0.0, 1.0);
        if alpha == 0.0 {
            return;
        }
        let Some((x0, y0, x1, y1)) = self.clip(a, b) else {
            return;
        };
        let a = (256.0 * alpha).floor() as u64;
        // Four 16-bit lanes, the first lowest.
        let lanes = |c: [u8; 4]| {
            c.iter()
                .rev()
                .fold(0u64, |acc, &v| acc << 16 | u64::from(v))
        };
        // The even bytes of each word of eight pixels (r g b r g b r g | b r g ...), and the odd.
        let even = [[r, b_, g, r], [b_, g, r, b_], [g, r, b_, g]].map(lanes);
        let odd = [[g, r, b_, g], [r, b_, g, r], [b_, g, r, b_]].map(lanes);
        const HIGH: u64 = 0xff00_ff00_ff00_ff00;
        const LOW: u64 = 0x00ff_00ff_00ff_00ff;
        let w = self.width();
        let count = (x1 - x0) as usize;
        let words = (count - 1) / 8;
        for y in y0..y1 {
            let start = 3 * (y * w + x0) as usize;
            let row = &mut self.rgb[start..start + 3 * count];
            let (wide, rest) = row.split_at_mut(24 * words);
            for eight in wide.chunks_exact_mut(24) {
                for (k, word) in eight.chunks_exact_mut(8).enumerate() {
                    let d = u64::from_le_bytes(word.try_into().expect("8 bytes"));
                    let h = (((d >> 8) & LOW) * (256 - a) + odd[k] * a) & HIGH;
                    let l = (((d & LOW) * (256 - a) + even[k] * a) & HIGH) >> 8;
                    word.copy_from_slice(&(h | l).to_le_bytes());
                }
            }
            for px in rest.chunks_exact_mut(3) {
                blend(&mut px[0], r, a);
                blend(&mut px[1], g, a);
                blend(&mut px[2], b_, a);
            }
        }
    }
}

/// plotters-bitmap's blend of one byte towards `new` by `a` / 256, rounded towards `prev`.
fn blend(prev: &mut u8, new: u8, a: u64) {
    if new > *prev {
        *prev += (u64::from(new - *prev) * a / 256) as u8
    } else {
        *prev -= (u64::from(*prev - new) * a / 256) as u8
    }
}

impl DrawingBackend for Canvas<'_> {
    type ErrorType = std::convert::Infallible;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }

    fn draw_pixel(
        &mut self,
        p: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        if p.0 < 0 || p.1 < 0 || p.0 as u32 >= self.size.0 || p.1 as u32 >= self.size.1 {
            return Ok(());
        }
        let at = 3 * (p.1 as usize * self.size.0 as usize + p.0 as usize);
        let (r, g, b) = color.rgb;
        let px = &mut self.rgb[at..at + 3];
        if color.alpha >= 1.0 - 1.0 / 256.0 {
            px.copy_from_slice(&[r, g, b]);
        } else if color.alpha > 0.0 {
            // plotters' floor of alpha * 256; for a positive value the conversion truncates
            // to the same integer without a call to libm.
            let a = (color.alpha * 256.0) as u64;
            blend(&mut px[0], r, a);
            blend(&mut px[1], g, a);
            blend(&mut px[2], b, a);
        }
        Ok(())
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if (from.0 == to.0 || from.1 == to.1) && style.stroke_width() == 1 {
            let end = (to.0 + 1, to.1 + 1);
            if color.alpha < 1.0 {
                self.blend_rect(from, end, color.rgb, color.alpha);
            } else if from.1 == to.1 {
                self.fill_rect(from, end, color.rgb);
            } else {
                self.fill_column(from.0, (from.1, to.1), color.rgb);
            }
            return Ok(());
        }
        rasterizer::draw_line(self, from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if !fill {
            return rasterizer::draw_rect(self, upper_left, bottom_right, style, fill);
        }
        if color.alpha < 1.0 {
            self.blend_rect(upper_left, bottom_right, color.rgb, color.alpha);
        } else {
            self.fill_rect(upper_left, bottom_right, color.rgb);
        }
        Ok(())
    }

    /// plotters-bitmap's copy of an RGB8 image `size` px onto the canvas at `pos`, clipped.
    fn blit_bitmap(
        &mut self,
        pos: BackendCoord,
        (sw, sh): (u32, u32),
        src: &[u8],
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let (dw, dh) = (self.size.0 as i32, self.size.1 as i32);
        let (x1, y1) = ((pos.0 + sw as i32).min(dw), (pos.1 + sh as i32).min(dh));
        let (x0, y0) = (pos.0.max(0), pos.1.max(0));
        if x0 >= x1 || y0 >= y1 {
            return Ok(());
        }
        // The source's rows and columns that land on the canvas: plotters takes them from the
        // source's far end (its bottom-right), as here.
        let (sx, sy) = (sw as i32 + x0 - x1, sh as i32 + y0 - y1);
        let len = 3 * (x1 - x0) as usize;
        for row in 0..(y1 - y0) {
            let to = 3 * ((y0 + row) * dw + x0) as usize;
            let from = 3 * ((sy + row) * sw as i32 + sx) as usize;
            self.rgb[to..to + len].copy_from_slice(&src[from..from + len]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use plotters::prelude::BitMapBackend;
    use plotters_backend::BackendColor;

    use super::*;

    /// A colour with alpha `a`.
    fn ink(rgb: (u8, u8, u8), alpha: f64) -> BackendColor {
        BackendColor { alpha, rgb }
    }

    /// The same calls on plotters' bitmap backend and on the canvas, over a background that is
    /// not uniform (blends round from what lies under them): the same bytes.
    fn same_as_plotters(draw: impl Fn(&mut dyn FnMut(Op))) {
        let (w, h) = (37u32, 23u32);
        let background: Vec<u8> = (0..3 * w * h).map(|i| (i * 7 % 251) as u8).collect();
        let (mut theirs, mut ours) = (background.clone(), background);
        {
            let mut b = BitMapBackend::with_buffer(&mut theirs, (w, h));
            draw(&mut |op| op.apply(&mut b));
            b.present().unwrap();
        }
        {
            let mut c = Canvas::new(&mut ours, (w, h));
            draw(&mut |op| op.apply(&mut c));
        }
        assert_eq!(ours, theirs);
    }

    /// One drawing call.
    #[derive(Clone, Copy)]
    enum Op {
        Pixel(BackendCoord, BackendColor),
        Line(BackendCoord, BackendCoord, BackendColor, u32),
        Rect(BackendCoord, BackendCoord, BackendColor, bool),
        Polygon([BackendCoord; 5], BackendColor),
        Blit(BackendCoord, (u32, u32)),
    }

    impl Op {
        fn apply<DB: DrawingBackend>(self, b: &mut DB) {
            let style = |c: BackendColor, width: u32| super::super::Restyled { color: c, width };
            match self {
                Op::Pixel(p, c) => b.draw_pixel(p, c).ok(),
                Op::Line(f, t, c, w) => b.draw_line(f, t, &style(c, w)).ok(),
                Op::Rect(a, z, c, fill) => b.draw_rect(a, z, &style(c, 1), fill).ok(),
                Op::Polygon(v, c) => b.fill_polygon(v, &style(c, 1)).ok(),
                Op::Blit(p, size) => {
                    let src: Vec<u8> = (0..3 * size.0 * size.1)
                        .map(|i| (i * 13 % 256) as u8)
                        .collect();
                    b.blit_bitmap(p, size, &src).ok()
                }
            };
        }
    }

    #[test]
    fn the_canvas_draws_the_bytes_of_plotters_bitmap_backend() {
        let colours = [
            (0, 0, 0),
            (230, 159, 0),
            (86, 180, 233),
            (255, 255, 255),
            (9, 200, 17),
        ];
        let alphas = [1.0, 0.999, 0.875, 0.5, 0.3, 0.125, 0.0, 1.5, -0.2];
        let points = [
            (-3, 4),
            (0, 0),
            (5, 7),
            (36, 22),
            (40, 30),
            (12, 12),
            (20, 3),
            (8, 19),
        ];
        for rgb in colours {
            for alpha in alphas {
                let c = ink(rgb, alpha);
                same_as_plotters(|op| {
                    for &p in &points {
                        op(Op::Pixel(p, c));
                        for &q in &points {
                            // Horizontal, vertical and slanted lines, 1 and 3 px wide; rows
                            // of 1 to 45 pixels (the 8-pixel words and their rest).
                            op(Op::Line(p, (q.0, p.1), c, 1));
                            op(Op::Line(p, (p.0, q.1), c, 1));
                            op(Op::Line(p, q, c, 1));
                            op(Op::Line(p, q, c, 3));
                            op(Op::Rect(p, q, c, true));
                            op(Op::Rect(p, q, c, false));
                        }
                    }
                    op(Op::Polygon(
                        [(2, 2), (30, 5), (34, 20), (10, 18), (4, 9)],
                        c,
                    ));
                    op(Op::Polygon(
                        [(-5, 1), (40, 2), (20, 30), (15, 10), (1, 25)],
                        c,
                    ));
                    op(Op::Blit((3, 4), (5, 6)));
                    op(Op::Blit((-2, -3), (9, 8)));
                    op(Op::Blit((33, 20), (9, 8)));
                });
            }
        }
    }
}
