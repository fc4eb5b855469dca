//! The outer rings of a region `value >= threshold` on a grid: the `contour` crate's
//! `ContourBuilder::contours` at one threshold, smoothed, holes left out, point for point.
//!
//! The crate's marching squares calls its stitcher for every cell, an empty case too (a
//! `lazy_static` table read and an empty `Vec` collected per cell): 17 M instructions for
//! `render fig3`'s 401 x 401 jam region, a tenth of the run, for rings of a few thousand points.
//! Here a cell whose four corners lie on one side is passed over, and the others stitch as the
//! crate stitches them (d3-contour's algorithm): the same rings in the same order, each point
//! the same f64 (`rings_are_the_contour_crates` checks it against the crate).

use std::collections::HashMap;
use std::collections::VecDeque;
use std::collections::hash_map::Entry;

/// A point in the crate's grid coordinates (sample i at the centre of cell [i, i + 1]).
type Pt = (f64, f64);

/// Each marching-squares case's segments, (start, end) in cell units: the crate's table.
const CASES: [&[[Pt; 2]]; 16] = [
    &[],
    &[[(1.0, 1.5), (0.5, 1.0)]],
    &[[(1.5, 1.0), (1.0, 1.5)]],
    &[[(1.5, 1.0), (0.5, 1.0)]],
    &[[(1.0, 0.5), (1.5, 1.0)]],
    &[[(1.0, 1.5), (0.5, 1.0)], [(1.0, 0.5), (1.5, 1.0)]],
    &[[(1.0, 0.5), (1.0, 1.5)]],
    &[[(1.0, 0.5), (0.5, 1.0)]],
    &[[(0.5, 1.0), (1.0, 0.5)]],
    &[[(1.0, 1.5), (1.0, 0.5)]],
    &[[(0.5, 1.0), (1.0, 0.5)], [(1.5, 1.0), (1.0, 1.5)]],
    &[[(1.5, 1.0), (1.0, 0.5)]],
    &[[(0.5, 1.0), (1.5, 1.0)]],
    &[[(1.0, 1.5), (1.5, 1.0)]],
    &[[(0.5, 1.0), (1.0, 1.5)]],
    &[],
];

/// Cells whose corners are compared at once, a byte each in a u64.
const WORD: usize = 8;

/// An open run of stitched segments, from the point of key `start` to that of key `end`.
struct Fragment {
    start: usize,
    end: usize,
    ring: VecDeque<Pt>,
}

/// Segments joined into rings, in the crate's order: a ring is done when its last segment
/// closes it.
struct Stitcher {
    /// Points per row of keys: the crate's `(dx + 1) * 4`.
    row_keys: f64,
    fragments: Vec<Option<Fragment>>,
    free: Vec<usize>,
    by_start: HashMap<usize, usize>,
    by_end: HashMap<usize, usize>,
    rings: Vec<Vec<Pt>>,
}

impl Stitcher {
    /// The crate's key of a point (half-cell coordinates as an index).
    fn key(&self, p: Pt) -> usize {
        (p.0 * 2.0 + p.1 * self.row_keys) as usize
    }

    fn insert(&mut self, f: Fragment) -> usize {
        match self.free.pop() {
            Some(i) => {
                self.fragments[i] = Some(f);
                i
            }
            None => {
                self.fragments.push(Some(f));
                self.fragments.len() - 1
            }
        }
    }

    fn take(&mut self, i: usize) -> Fragment {
        self.free.push(i);
        self.fragments[i].take().expect("a live fragment")
    }

    fn fragment(&mut self, i: usize) -> &mut Fragment {
        self.fragments[i].as_mut().expect("a live fragment")
    }

    /// The crate's `IsoRingBuilder::stitch` of one segment of the cell at (x, y).
    fn stitch(&mut self, [a, b]: [Pt; 2], x: f64, y: f64) {
        let (start, end) = ((a.0 + x, a.1 + y), (b.0 + x, b.1 + y));
        let (start_key, end_key) = (self.key(start), self.key(end));
        if let Some(f_ix) = self.by_end.remove(&start_key) {
            if let Some(g_ix) = self.by_start.remove(&end_key) {
                if f_ix == g_ix {
                    let mut f = self.take(f_ix);
                    f.ring.push_back(end);
                    self.rings.push(f.ring.into());
                } else {
                    let mut f = self.take(f_ix);
                    let g = self.take(g_ix);
                    f.ring.extend(g.ring);
                    let (s, e) = (f.start, g.end);
                    let ix = self.insert(Fragment {
                        start: s,
                        end: e,
                        ring: f.ring,
                    });
                    self.by_start.insert(s, ix);
                    self.by_end.insert(e, ix);
                }
            } else {
                let f = self.fragment(f_ix);
                f.ring.push_back(end);
                f.end = end_key;
                self.by_end.insert(end_key, f_ix);
            }
        } else if let Entry::Occupied(o) = self.by_start.entry(end_key) {
            let f_ix = o.remove();
            let f = self.fragment(f_ix);
            f.ring.push_front(start);
            f.start = start_key;
            self.by_start.insert(start_key, f_ix);
        } else {
            let ix = self.insert(Fragment {
                start: start_key,
                end: end_key,
                ring: VecDeque::from([start, end]),
            });
            self.by_start.insert(start_key, ix);
            self.by_end.insert(end_key, ix);
        }
    }
}

/// The crate's closed rings of `values >= threshold` over an `nx` x `ny` grid (x fastest),
/// before smoothing, in the order they close.
fn rings(values: &[f64], threshold: f64, nx: usize, ny: usize) -> Vec<Vec<Pt>> {
    let mut s = Stitcher {
        row_keys: ((nx + 1) * 4) as f64,
        fragments: Vec::new(),
        free: Vec::new(),
        by_start: HashMap::new(),
        by_end: HashMap::new(),
        rings: Vec::new(),
    };
    // Whether each sample is inside (1) or not (0), on a grid with a border of outside samples
    // around it: sample (ix, iy) at row iy + 1, column ix + 1; a word's room past the end.
    let w = nx + 2;
    let mut inside = vec![0u8; w * (ny + 2) + WORD];
    for (row, values) in inside[w..].chunks_exact_mut(w).zip(values.chunks_exact(nx)) {
        for (flag, v) in row[1..=nx].iter_mut().zip(values) {
            *flag = u8::from(*v >= threshold);
        }
    }
    let word = |row: &[u8], i: usize| {
        u64::from_le_bytes(*row[i..].first_chunk::<WORD>().expect("a word's room"))
    };
    // Cell (x, y) has corners (x, y + 1) t0, (x + 1, y + 1) t1, (x + 1, y) t2 and (x, y) t3,
    // as the crate reads them; cells run from -1 to n - 1 so that rings close at the border.
    // Where the corners of WORD cells in a row are all inside or all outside, none of them
    // has a segment: they are passed over at once.
    for (y, below_at) in (-1..).zip((0..=ny).map(|r| r * w)) {
        let (below, above) = (&inside[below_at..], &inside[below_at + w..]);
        let mut i = 0;
        while i <= nx {
            let (b, a) = (word(below, i), word(above, i));
            if (a ^ b) | (a ^ word(above, i + 1)) | (b ^ word(below, i + 1)) == 0 {
                i += WORD;
                continue;
            }
            for i in i..(i + WORD).min(nx + 1) {
                let case = usize::from(above[i])
                    | usize::from(above[i + 1]) << 1
                    | usize::from(below[i + 1]) << 2
                    | usize::from(below[i]) << 3;
                let x = i as f64 - 1.0;
                for &segment in CASES[case] {
                    s.stitch(segment, x, f64::from(y));
                }
            }
            i += WORD;
        }
    }
    s.rings
}

/// The crate's `smoooth_linear`: each point on a cell edge moved to where the values on the
/// edge cross `threshold`, linearly.
fn smooth(ring: &mut [Pt], values: &[f64], threshold: f64, nx: usize, ny: usize) {
    for p in ring.iter_mut() {
        let (x, y) = *p;
        let (xt, yt) = (x.trunc() as usize, y.trunc() as usize);
        let ix = yt * nx + xt;
        if ix < values.len() {
            let v1 = values[ix];
            if x > 0.0 && x < nx as f64 && (xt as f64 - x).abs() < f64::EPSILON {
                let v0 = values[yt * nx + xt - 1];
                p.0 = x + (threshold - v0) / (v1 - v0) - 0.5;
            }
            if y > 0.0 && y < ny as f64 && (yt as f64 - y).abs() < f64::EPSILON {
                let v0 = values[(yt - 1) * nx + xt];
                p.1 = y + (threshold - v0) / (v1 - v0) - 0.5;
            }
        }
    }
}

/// The crate's shoelace sum (twice the signed area; > 0 for an outer ring).
fn area(ring: &[Pt]) -> f64 {
    let n = ring.len();
    let mut area = ring[n - 1].1 * ring[0].0 - ring[n - 1].0 * ring[0].1;
    for i in 1..n {
        area += ring[i - 1].1 * ring[i].0 - ring[i - 1].0 * ring[i].1;
    }
    area
}

/// The exterior rings of `ContourBuilder::new(nx, ny, true).contours(values, &[threshold])`,
/// in its order and its grid coordinates, each closed (its last point its first).
pub fn exteriors(values: &[f64], threshold: f64, nx: usize, ny: usize) -> Vec<Vec<Pt>> {
    if values.len() != nx * ny || values.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::new();
    for mut ring in rings(values, threshold, nx, ny) {
        smooth(&mut ring, values, threshold, nx, ny);
        if area(&ring) > 0.0 {
            // geo_types' Polygon::new closes an open exterior.
            if ring.first() != ring.last() {
                ring.push(ring[0]);
            }
            out.push(ring);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exteriors as the contour crate makes them.
    fn crate_exteriors(values: &[f64], threshold: f64, nx: usize, ny: usize) -> Vec<Vec<Pt>> {
        let builder = contour::ContourBuilder::new(nx, ny, true);
        let contours = builder.contours(values, &[threshold]).unwrap();
        contours
            .iter()
            .flat_map(|c| c.geometry().0.iter())
            .map(|p| p.exterior().0.iter().map(|c| (c.x, c.y)).collect())
            .collect()
    }

    fn bits(rings: &[Vec<Pt>]) -> Vec<Vec<(u64, u64)>> {
        rings
            .iter()
            .map(|r| r.iter().map(|p| (p.0.to_bits(), p.1.to_bits())).collect())
            .collect()
    }

    proptest::proptest! {
        /// Fields of blobs, noise and plateaus on small grids: many rings, holes, rings along
        /// the border and saddles; every point the crate's, bit for bit, in its order.
        #[test]
        fn rings_are_the_contour_crates(
            nx in 1usize..24,
            ny in 1usize..24,
            seed in proptest::prelude::any::<u64>(),
            kind in 0u8..3,
        ) {
            let mut state = seed | 1;
            let mut next = move || {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state
            };
            let values: Vec<f64> = (0..nx * ny)
                .map(|i| {
                    let (x, y) = ((i % nx) as f64, (i / nx) as f64);
                    match kind {
                        0 => (x * 0.7).sin() * (y * 0.5).cos() + (next() % 100) as f64 / 400.0,
                        1 => (next() % 7) as f64 - 3.0,
                        _ => f64::from(u8::from(next() % 3 == 0)),
                    }
                })
                .collect();
            for threshold in [0.0, 0.5, 0.25] {
                proptest::prop_assert_eq!(
                    bits(&exteriors(&values, threshold, nx, ny)),
                    bits(&crate_exteriors(&values, threshold, nx, ny))
                );
            }
        }
    }

    /// The jam map's region over fig3's 401 x 401 grid, a margin that changes sign along a
    /// curve: one ring of the crate's.
    #[test]
    fn a_large_region_is_the_contour_crates() {
        let (nx, ny) = (401, 401);
        let values: Vec<f64> = (0..nx * ny)
            .map(|i| {
                let (x, y) = ((i % nx) as f64 / 400.0, (i / nx) as f64 / 400.0);
                x - 0.3 * (3.0 * y).sin() - 0.2
            })
            .collect();
        let ours = exteriors(&values, 0.0, nx, ny);
        assert_eq!(bits(&ours), bits(&crate_exteriors(&values, 0.0, nx, ny)));
        assert!(!ours.is_empty());
    }
}
