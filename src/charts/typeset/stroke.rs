//! Anti-aliased wide strokes for the PNG: slanted lines and curves without steps.
//!
//! plotters draws a line wider than 1 px as a polygon whose corners are truncated to whole
//! pixels and fills it without anti-aliasing, so every slanted curve of a chart showed stair
//! steps. [`coverage`] instead gives each pixel the part of it the stroke covers: a stroke
//! `w` px wide is the set of points within `w / 2` of the polyline (round joins and caps), and a
//! pixel whose centre lies `d` from the polyline is covered `clamp(w / 2 + 1/2 - d, 0, 1)`, the
//! exact area for a straight edge crossing the pixel parallel to a side and a close one at any
//! slope. Across a stroke these coverages sum to its width, so a line keeps its weight.
//!
//! Pixel centres are at whole coordinates, as plotters' 1 px lines have them. Only basic
//! IEEE-754 operations on `f64` are used (`+ - * /`, `sqrt`, comparisons; Rust never fuses them
//! into FMA unasked), on one thread, with no SIMD and no run-time CPU feature detection, so
//! the coverages are the same bits on every machine and thread count.

use super::Px;

/// The coverage in 0..=1 of each pixel a stroke `width_px` wide along `points` touches, inside
/// a canvas `size` px, in row order; pixels with coverage 0 are left out.
pub fn coverage(points: &[Px], width_px: u32, size: (u32, u32)) -> Vec<(Px, f64)> {
    let r = f64::from(width_px) / 2.0;
    // Pixels whose centre is farther than r + 1/2 are not touched.
    let reach = (r + 0.5).ceil() as i32;
    let (w, h) = (size.0 as i32, size.1 as i32);
    let (Some(x0), Some(x1)) = (
        points.iter().map(|p| p.0).min(),
        points.iter().map(|p| p.0).max(),
    ) else {
        return Vec::new();
    };
    let y0 = points.iter().map(|p| p.1).min().unwrap_or(0);
    let y1 = points.iter().map(|p| p.1).max().unwrap_or(0);
    let (bx0, by0) = ((x0 - reach).max(0), (y0 - reach).max(0));
    let (bx1, by1) = ((x1 + reach).min(w - 1), (y1 + reach).min(h - 1));
    if bx0 > bx1 || by0 > by1 {
        return Vec::new();
    }
    let bw = (bx1 - bx0 + 1) as usize;
    let bh = (by1 - by0 + 1) as usize;
    // The largest coverage of each pixel of the box over all segments (round joins: a pixel
    // near a joint is covered once, not once per segment), kept in the TILE x TILE tiles the
    // stroke touches. A curve across a whole chart touches a small part of its bounding box,
    // whose dense copy was megabytes to zero and fault in: each page faulted twice (read as
    // the shared zero page, then written), and while another thread of the process ran (the
    // cells CSV written beside the drawing) every such fault flushed the other core's TLB.
    let (tiles_x, tiles_y) = (bw.div_ceil(TILE), bh.div_ceil(TILE));
    let mut tiles: Vec<Option<Box<[f64; TILE * TILE]>>> = vec![None; tiles_x * tiles_y];
    let segments: Vec<(Px, Px)> = if points.len() == 1 {
        vec![(points[0], points[0])]
    } else {
        points.windows(2).map(|s| (s[0], s[1])).collect()
    };
    for (a, b) in segments {
        let sx0 = (a.0.min(b.0) - reach).max(bx0);
        let sx1 = (a.0.max(b.0) + reach).min(bx1);
        let sy0 = (a.1.min(b.1) - reach).max(by0);
        let sy1 = (a.1.max(b.1) + reach).min(by1);
        for y in sy0..=sy1 {
            let (ty, ly) = (((y - by0) as usize) / TILE, ((y - by0) as usize) % TILE);
            for x in sx0..=sx1 {
                let c = (r + 0.5 - distance((x, y), a, b)).clamp(0.0, 1.0);
                if c == 0.0 {
                    continue;
                }
                let (tx, lx) = (((x - bx0) as usize) / TILE, ((x - bx0) as usize) % TILE);
                let tile =
                    tiles[ty * tiles_x + tx].get_or_insert_with(|| Box::new([0.0; TILE * TILE]));
                let cell = &mut tile[ly * TILE + lx];
                if c > *cell {
                    *cell = c;
                }
            }
        }
    }
    let mut out = Vec::new();
    for row in 0..bh {
        let (ty, ly) = (row / TILE, row % TILE);
        for tx in 0..tiles_x {
            let Some(tile) = &tiles[ty * tiles_x + tx] else {
                continue;
            };
            let width = TILE.min(bw - tx * TILE);
            for (lx, &c) in tile[ly * TILE..ly * TILE + width].iter().enumerate() {
                if c > 0.0 {
                    let p = (bx0 + (tx * TILE + lx) as i32, by0 + row as i32);
                    out.push((p, c));
                }
            }
        }
    }
    out
}

/// The side of a tile of [`coverage`]'s store, in px: 32 x 32 f64 is two pages.
const TILE: usize = 32;

/// The distance from pixel centre `p` to the segment `a`-`b`.
fn distance(p: Px, a: Px, b: Px) -> f64 {
    let (px, py) = (f64::from(p.0 - a.0), f64::from(p.1 - a.1));
    let (dx, dy) = (f64::from(b.0 - a.0), f64::from(b.1 - a.1));
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 {
        0.0
    } else {
        ((px * dx + py * dy) / len2).clamp(0.0, 1.0)
    };
    let (ex, ey) = (px - t * dx, py - t * dy);
    (ex * ex + ey * ey).sqrt()
}

/// Whether every segment of `points` runs along a pixel row or column: such a stroke has no
/// steps, and plotters' own fill keeps it crisp (a 2 px rule anti-aliased would smear over
/// three rows at half strength).
pub fn axis_aligned(points: &[Px]) -> bool {
    points
        .windows(2)
        .all(|s| s[0].0 == s[1].0 || s[0].1 == s[1].1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression for "lines are not anti-aliased (visible steps)": a 2 px line at
    /// a slant used to be a truncated polygon filled at full strength, so every pixel it
    /// touched was either ink or paper. Now the pixels along its edges are partly covered, and
    /// the ink across the line sums to its width.
    #[test]
    fn slanted_wide_lines_are_anti_aliased() {
        let cells = coverage(&[(10, 10), (90, 40)], 2, (100, 100));
        let partial = cells.iter().filter(|(_, c)| *c > 0.05 && *c < 0.95).count();
        assert!(partial > 80, "{partial} partly covered pixels");
        // Down column x = 50 (the line's middle), the coverages sum to the width measured
        // vertically: w / cos(slope) = 2 * hypot(80, 30) / 80.
        let column: f64 = cells
            .iter()
            .filter(|(p, _)| p.0 == 50)
            .map(|(_, c)| c)
            .sum();
        let expected = 2.0 * (80.0f64.hypot(30.0)) / 80.0;
        assert!((column - expected).abs() < 0.05, "{column} vs {expected}");
    }

    /// The tiles give what one dense box of coverages gives, pixel for pixel and in row order,
    /// for strokes that cross tile edges, the canvas edge and themselves.
    #[test]
    fn tiled_coverage_is_the_dense_boxs() {
        let dense = |points: &[Px], width_px: u32, size: (u32, u32)| {
            let r = f64::from(width_px) / 2.0;
            let mut out = Vec::new();
            for y in 0..size.1 as i32 {
                for x in 0..size.0 as i32 {
                    let c = points
                        .windows(2)
                        .map(|s| (r + 0.5 - distance((x, y), s[0], s[1])).clamp(0.0, 1.0))
                        .fold(0.0f64, f64::max);
                    if c > 0.0 {
                        out.push(((x, y), c));
                    }
                }
            }
            out
        };
        let curves: [&[Px]; 3] = [
            &[(3, 90), (40, 31), (41, 33), (97, 2)],
            &[(-5, 10), (70, 64), (10, 64), (64, -3), (64, 120)],
            &[(31, 31), (32, 32), (33, 33), (95, 95)],
        ];
        for (points, w) in curves.iter().zip([1, 3, 6]) {
            assert_eq!(
                coverage(points, w, (100, 100)),
                dense(points, w, (100, 100))
            );
        }
    }

    #[test]
    fn strokes_are_clipped_to_the_canvas_and_joints_covered_once() {
        let cells = coverage(&[(-20, 5), (5, 5), (5, 200)], 3, (10, 10));
        assert!(
            cells
                .iter()
                .all(|((x, y), c)| (0..10).contains(x) && (0..10).contains(y) && *c <= 1.0)
        );
        assert!(coverage(&[(-50, -50), (-40, -30)], 2, (10, 10)).is_empty());
        assert!(axis_aligned(&[(0, 0), (5, 0), (5, 9)]) && !axis_aligned(&[(0, 0), (5, 1)]));
    }
}
