//! Contour-crate geometry over a map: the bands and iso-lines that the `contour` crate traces
//! on a grid, in the axes' own coordinates (the value on a linear axis, its ln on a log axis:
//! what a chart strokes), written in the axes' units.

use geo_types::{MultiLineString, MultiPolygon};
use serde::ser::{Serialize, SerializeSeq, Serializer};

use crate::grid::{AxisScale, GridAxis};

/// Polylines or rings in the axes' own coordinates (ln of the value on a log axis).
pub type Paths = Vec<Vec<(f64, f64)>>;

/// Paths traced over a map, with the scales that turn them into axis values: their serde form
/// is the polylines of `[x, y]` axis values.
#[derive(Debug, Clone, Default)]
pub struct Traced {
    /// The paths in the axes' own coordinates.
    pub paths: Paths,
    /// The x and y axes' scales.
    pub scales: [AxisScale; 2],
}

impl Traced {
    /// `paths` traced over the axes `xa` and `ya`.
    pub fn over<P>(paths: Paths, xa: &GridAxis<P>, ya: &GridAxis<P>) -> Self {
        Traced {
            paths,
            scales: [xa.scale, ya.scale],
        }
    }
}

impl Serialize for Traced {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let [sx, sy] = self.scales;
        let mut seq = s.serialize_seq(Some(self.paths.len()))?;
        for p in &self.paths {
            let values: Vec<[f64; 2]> = p
                .iter()
                .map(|&(u, v)| [axis_value(u, sx), axis_value(v, sy)])
                .collect();
            seq.serialize_element(&values)?;
        }
        seq.end()
    }
}

/// The axis value of coordinate `u` on an axis of scale `scale` (ln of the value on a log axis).
pub fn axis_value(u: f64, scale: AxisScale) -> f64 {
    match scale {
        AxisScale::Log => u.exp(),
        AxisScale::Linear => u,
    }
}

/// The `contour` crate's iso-lines of `values` at each of `levels`, in order, the levels traced
/// in parallel: the crate passes over the whole grid for each level, one after another, and a
/// level's lines do not depend on the others' (the universal chart's iso-lines were a third of
/// `render universal`'s instructions, on one core). Finite values and levels cannot fail;
/// nothing is traced if they ever did.
pub fn lines_at(
    builder: &contour::ContourBuilder,
    values: &[f64],
    levels: &[f64],
) -> Vec<contour::Line> {
    use rayon::prelude::*;
    levels
        .par_iter()
        .flat_map_iter(|&level| builder.lines(values, &[level]).unwrap_or_default())
        .collect()
}

/// The exterior rings of contour polygons, mapped from the contour crate's grid coordinates to
/// the axes' own coordinates (ln for log axes). The crate puts sample i at the centre of cell [i, i + 1].
pub fn grid_polygons<P>(
    mp: &MultiPolygon<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
) -> Vec<Vec<(f64, f64)>> {
    mp.0.iter()
        .map(|poly| {
            poly.exterior()
                .0
                .iter()
                .map(|c| (grid_to_axis(c.x, xa), grid_to_axis(c.y, ya)))
                .collect()
        })
        .collect()
}

/// The rings, in the axes' own coordinates, around the cells of an `xa` x `ya` grid where `mask` holds (x
/// fastest); none when no cell does. A jam map's cells past the palm's end and a universal
/// chart's cells held at the start are traced by it.
pub fn mask_rings<P>(mask: &[bool], xa: &GridAxis<P>, ya: &GridAxis<P>) -> Vec<Vec<(f64, f64)>> {
    if !mask.contains(&true) {
        return Vec::new();
    }
    let values: Vec<f64> = mask.iter().map(|b| f64::from(u8::from(*b))).collect();
    region_rings(&values, 0.5, xa, ya)
}

/// The outer rings, in the axes' own coordinates, of the region where `values` (an `xa` x
/// `ya` grid, x fastest) are at least `threshold`: the exteriors of the `contour` crate's
/// smoothed contour polygons at that threshold, traced without its pass over every cell
/// (`iso_rings`). None when the grid's size is not the axes'.
pub fn region_rings<P>(
    values: &[f64],
    threshold: f64,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
) -> Vec<Vec<(f64, f64)>> {
    super::iso_rings::exteriors(values, threshold, xa.count, ya.count)
        .into_iter()
        .map(|ring| {
            ring.into_iter()
                .map(|(x, y)| (grid_to_axis(x, xa), grid_to_axis(y, ya)))
                .collect()
        })
        .collect()
}

/// A field over an `nx` x `ny` grid (x fastest) with every cell that holds no value given the
/// value of the nearest cell that does (by steps between neighbours, the first found in index
/// order on a tie); `fallback` everywhere when none does.
///
/// For shading bands over a field with holes: the contour crate interpolates between
/// neighbouring cells, so a stand-in value below every level in the holes drew every band
/// between it and the field's value as a thin fringe along each hole's edge (a yellow
/// "< 30 mm" along a blank where x_jam was 80 mm). Filled from its neighbours, a hole's edge
/// only interpolates between values the field has there; the holes are then covered by their
/// own shape ([`mask_rings`]).
pub fn filled_from_neighbours(values: &[Option<f64>], nx: usize, fallback: f64) -> Vec<f64> {
    let mut out: Vec<Option<f64>> = values.to_vec();
    let mut queue: std::collections::VecDeque<usize> =
        (0..out.len()).filter(|&i| out[i].is_some()).collect();
    while let Some(i) = queue.pop_front() {
        let (ix, iy) = (i % nx, i / nx);
        let near = [
            (ix > 0).then(|| i - 1),
            (ix + 1 < nx).then_some(i + 1),
            (iy > 0).then(|| i - nx),
            (i + nx < out.len()).then_some(i + nx),
        ];
        for j in near.into_iter().flatten() {
            if out[j].is_none() {
                out[j] = out[i];
                queue.push_back(j);
            }
        }
    }
    out.into_iter().map(|v| v.unwrap_or(fallback)).collect()
}

/// The axis coordinate (ln for a log axis) of contour-crate grid coordinate `g` on axis `a`.
pub fn grid_to_axis<P>(g: f64, a: &GridAxis<P>) -> f64 {
    let (lo, hi) = match a.scale {
        crate::grid::AxisScale::Linear => (a.min, a.max),
        crate::grid::AxisScale::Log => (a.min.ln(), a.max.ln()),
    };
    lo + (hi - lo) * (g - 0.5) / (a.count - 1) as f64
}

/// Contour-crate polylines mapped to the axes' own coordinates, split where they run along the grid's border.
///
/// The crate closes every ring around the edge of the grid; those pieces are not iso-lines and
/// would be drawn on the frame.
pub fn grid_lines<P>(
    ml: &MultiLineString<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
) -> Vec<Vec<(f64, f64)>> {
    lines_off(ml, xa, ya, |_| false)
}

/// [`grid_lines`] of a field with cells that hold no value (`valued` false, x fastest): a
/// line is also cut where it touches such a cell. Those cells carry a stand-in below every
/// level, so the crate traces each level below its neighbours' values along their edge: lines
/// of the stand-in, not of the field.
pub fn grid_lines_among<P>(
    ml: &MultiLineString<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
    valued: &[bool],
) -> Vec<Vec<(f64, f64)>> {
    let (nx, ny) = (xa.count, ya.count);
    // The cells (1, 2 or 4) around grid point c: a traced point lies on the edge between two
    // cell centres (at integer + 0.5), read within 1e-6 of a cell so that rounding in the
    // crate does not reach into the next row or column.
    let span = |g: f64, n: usize| {
        let g = g - 0.5;
        let near = g.round();
        let (lo, hi) = match (g - near).abs() < 1e-6 {
            true => (near, near),
            false => (g.floor(), g.ceil()),
        };
        let clamp = |v: f64| v.clamp(0.0, (n - 1) as f64) as usize;
        clamp(lo)..=clamp(hi)
    };
    let blank = |c: &geo_types::Coord<f64>| {
        span(c.y, ny)
            .any(|j| span(c.x, nx).any(|i| !valued.get(j * nx + i).copied().unwrap_or(true)))
    };
    lines_off(ml, xa, ya, blank)
}

/// [`grid_lines`], cutting also each segment with an end where `cut` holds.
fn lines_off<P>(
    ml: &MultiLineString<f64>,
    xa: &GridAxis<P>,
    ya: &GridAxis<P>,
    cut: impl Fn(&geo_types::Coord<f64>) -> bool,
) -> Vec<Vec<(f64, f64)>> {
    let (nx, ny) = (xa.count as f64, ya.count as f64);
    let on_border =
        |c: &geo_types::Coord<f64>| c.x <= 0.5 || c.x >= nx - 0.5 || c.y <= 0.5 || c.y >= ny - 0.5;
    let mut out = Vec::new();
    for ls in &ml.0 {
        let mut cur: Vec<(f64, f64)> = Vec::new();
        for w in ls.0.windows(2) {
            if (on_border(&w[0]) && on_border(&w[1])) || cut(&w[0]) || cut(&w[1]) {
                if cur.len() > 1 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
                continue;
            }
            if cur.is_empty() {
                cur.push((grid_to_axis(w[0].x, xa), grid_to_axis(w[0].y, ya)));
            }
            cur.push((grid_to_axis(w[1].x, xa), grid_to_axis(w[1].y, ya)));
        }
        if cur.len() > 1 {
            out.push(cur);
        }
    }
    out
}
