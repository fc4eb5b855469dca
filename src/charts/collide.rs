//! Boxes on the picture: whether a label's box meets a drawn line or another box.
//!
//! Hand-written rather than taken from `geo`: two predicates on integer pixel boxes do not
//! justify a geometry crate and its dependency tree, and the clipping test (Liang-Barsky) is
//! a dozen lines whose tests are below.

/// An axis-aligned box in backend pixels, corners included.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PxBox {
    /// Left edge.
    pub x0: i32,
    /// Top edge.
    pub y0: i32,
    /// Right edge.
    pub x1: i32,
    /// Bottom edge.
    pub y1: i32,
}

impl PxBox {
    /// The box of `w` x `h` px centred at `at`, grown by `pad` on every side (a
    /// [`super::axes::boxed_text`] centred there).
    pub fn centred(at: (i32, i32), (w, h): (u32, u32), pad: i32) -> PxBox {
        let (w, h) = (w as i32, h as i32);
        let (x0, y0) = (at.0 - w / 2, at.1 - h / 2);
        PxBox {
            x0: x0 - pad,
            y0: y0 - pad,
            x1: x0 + w + pad,
            y1: y0 + h + pad,
        }
    }

    /// Whether the two boxes share an area (touching edges do not count).
    pub fn overlaps(&self, o: &PxBox) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    /// Whether the box lies inside `w` x `h` px from the origin.
    #[cfg(test)]
    pub fn inside(&self, (w, h): (u32, u32)) -> bool {
        self.x0 >= 0 && self.y0 >= 0 && self.x1 <= w as i32 && self.y1 <= h as i32
    }

    /// Whether the segment from `a` to `b` passes through the box (Liang-Barsky clipping).
    pub fn meets_segment(&self, a: (i32, i32), b: (i32, i32)) -> bool {
        let (ax, ay) = (f64::from(a.0), f64::from(a.1));
        let (dx, dy) = (f64::from(b.0) - ax, f64::from(b.1) - ay);
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let edges = [
            (-dx, ax - f64::from(self.x0)),
            (dx, f64::from(self.x1) - ax),
            (-dy, ay - f64::from(self.y0)),
            (dy, f64::from(self.y1) - ay),
        ];
        for (p, q) in edges {
            if p == 0.0 {
                if q < 0.0 {
                    return false;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
                if t0 > t1 {
                    return false;
                }
            }
        }
        true
    }

    /// Whether any segment of the polyline `points` passes through the box.
    pub fn meets_polyline(&self, points: &[(i32, i32)]) -> bool {
        match points {
            [p] => self.meets_segment(*p, *p),
            _ => points.windows(2).any(|w| self.meets_segment(w[0], w[1])),
        }
    }
}

/// Where a label goes: the top-left corner of its text and its box.
pub type Placed = ((i32, i32), PxBox);

/// Where a label of `w` x `h` px (its box grown by `pad`) goes beside the point `at`: the first
/// of the four corners around it, `gap` px off (below right, above right, above left, below
/// left), whose box lies inside `frame` and meets none of `lines` and none of `boxes`, or, as
/// the error, the first corner when none is free (a caller may then try the label in another
/// shape). Each is the box's top-left text corner and the box.
pub fn place_beside(
    at: (i32, i32),
    size: (u32, u32),
    (gap, pad): (i32, i32),
    frame: &PxBox,
    lines: &[Vec<(i32, i32)>],
    boxes: &[PxBox],
) -> Result<Placed, Placed> {
    let free = |b: &PxBox| {
        b.x0 >= frame.x0
            && b.y0 >= frame.y0
            && b.x1 <= frame.x1
            && b.y1 <= frame.y1
            && !lines.iter().any(|l| b.meets_polyline(l))
            && !boxes.iter().any(|o| b.overlaps(o))
    };
    let corners = corners(at, size, (gap, pad));
    corners.into_iter().find(|(_, b)| free(b)).ok_or(corners[0])
}

/// The four corners around `at` of [`place_beside`], in its order: each text corner and box.
fn corners(at: (i32, i32), (w, h): (u32, u32), (gap, pad): (i32, i32)) -> [Placed; 4] {
    let (w, h) = (w as i32, h as i32);
    [
        (at.0 + gap, at.1 + gap),
        (at.0 + gap, at.1 - gap - h),
        (at.0 - gap - w, at.1 - gap - h),
        (at.0 - gap - w, at.1 + gap),
    ]
    .map(|(x0, y0)| {
        let b = PxBox {
            x0: x0 - pad,
            y0: y0 - pad,
            x1: x0 + w + pad,
            y1: y0 + h + pad,
        };
        ((x0, y0), b)
    })
}

/// Where a tag of `w` x `h` px (its box grown by `pad`) goes on the axis-parallel segment
/// `a`-`b`: half-way along, else the first of a few other places along it, else the same
/// places just beside it (above a horizontal segment, right of a vertical one, then the
/// other side), whose box meets none of `lines` and none of `boxes` (labels drawn already);
/// half-way along when none is free. Returns the tag's centre and box.
pub fn place_along(
    a: (i32, i32),
    b: (i32, i32),
    size: (u32, u32),
    pad: i32,
    lines: &[Vec<(i32, i32)>],
    boxes: &[PxBox],
) -> ((i32, i32), PxBox) {
    // Beside: the box clears the segment (and a curve that lies along it) by 2 px.
    let (w, h) = (size.0 as i32, size.1 as i32);
    let side = if a.0 == b.0 {
        (w / 2 + pad + 2, 0)
    } else {
        (0, -(h / 2 + pad + 2))
    };
    let along = |t: f64, k: i32| {
        let at = |p: i32, q: i32| p + (t * f64::from(q - p)).round() as i32;
        let mid = (at(a.0, b.0) + k * side.0, at(a.1, b.1) + k * side.1);
        (mid, PxBox::centred(mid, size, pad))
    };
    let ts = [0.5, 0.3, 0.7, 0.15, 0.85];
    [0, 1, -1]
        .into_iter()
        .flat_map(|k| ts.into_iter().map(move |t| (t, k)))
        .map(|(t, k)| along(t, k))
        .find(|(_, tag)| {
            !lines.iter().any(|l| tag.meets_polyline(l)) && !boxes.iter().any(|b| tag.overlaps(b))
        })
        .unwrap_or_else(|| along(0.5, 0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: on fig7a's lower panel theta_jam does not depend on r, so the
    /// read-off's line 2 runs along the flat curve and every place along it was on the curve:
    /// step tag "2" sat on it, half-way. The tag now goes just beside the line, clear of it.
    #[test]
    fn a_step_tag_on_a_line_along_a_flat_curve_goes_beside_it() {
        let (a, b) = ((500, 200), (100, 200));
        let curve = vec![(100, 200), (900, 200)];
        let (mid, tag) = place_along(a, b, (8, 13), 3, std::slice::from_ref(&curve), &[]);
        assert!(!tag.meets_polyline(&curve), "{tag:?} meets the curve");
        assert!(
            tag.y1 < 200 && mid.0 == 300,
            "{mid:?} {tag:?}: above, half-way"
        );
        // With no curve in the way it stays on the line, half-way.
        assert_eq!(place_along(a, b, (8, 13), 3, &[], &[]).0, (300, 200));
        // A label over the line half-way: the tag goes to the next place along it.
        let label = PxBox::centred((300, 200), (40, 13), 3);
        let (mid, tag) = place_along(a, b, (8, 13), 3, &[], &[label]);
        assert!(!tag.overlaps(&label) && mid.1 == 200, "{mid:?}");
    }

    /// Regression: fig7b's read-off value sat below right of the point on the
    /// lower panel, where the falling theta_jam curve runs on: its white box covered the curve.
    /// The label now takes the first corner around the point that the curve leaves free.
    #[test]
    fn a_label_beside_a_point_leaves_a_falling_curve_free() {
        let frame = PxBox {
            x0: 0,
            y0: 0,
            x1: 400,
            y1: 300,
        };
        // Falls to the right through the point (200, 150), as theta_jam over F does.
        let curve = vec![(0, 50), (200, 150), (400, 250)];
        let ((x, y), b) = place_beside(
            (200, 150),
            (120, 15),
            (8, 3),
            &frame,
            std::slice::from_ref(&curve),
            &[],
        )
        .unwrap();
        assert!(!b.meets_polyline(&curve), "{b:?}");
        // Below right (the old place) is taken by the curve: above right is chosen.
        assert_eq!((x, y), (208, 150 - 8 - 15));
        // Nothing free: the first corner.
        let wall = vec![(0, 0), (400, 300), (0, 300), (400, 0), (0, 0)];
        let (c, _) = place_beside((200, 150), (120, 15), (8, 3), &frame, &[wall], &[]).unwrap_err();
        assert_eq!(c, (208, 158));
    }

    const B: PxBox = PxBox {
        x0: 10,
        y0: 10,
        x1: 20,
        y1: 20,
    };

    #[test]
    fn segments_through_beside_and_inside_the_box() {
        assert!(B.meets_segment((15, 0), (15, 30)), "straight through");
        assert!(B.meets_segment((0, 0), (30, 30)), "diagonal through");
        assert!(B.meets_segment((12, 12), (14, 14)), "inside");
        assert!(!B.meets_segment((25, 0), (25, 30)), "beside");
        assert!(!B.meets_segment((0, 25), (25, 40)), "below, slanted");
        assert!(!B.meets_segment((0, 0), (8, 30)), "left, ending short");
        assert!(B.meets_polyline(&[(0, 15), (5, 15), (12, 15)]));
        assert!(!B.meets_polyline(&[(0, 0), (0, 30), (30, 31)]));
    }

    #[test]
    fn boxes_overlap_only_when_they_share_area() {
        let right = PxBox {
            x0: 20,
            x1: 30,
            ..B
        };
        assert!(!B.overlaps(&right), "touching edges");
        let shifted = PxBox {
            x0: 19,
            x1: 29,
            ..B
        };
        assert!(B.overlaps(&shifted) && shifted.overlaps(&B));
        assert!(B.inside((20, 20)) && !B.inside((19, 40)));
        assert_eq!(PxBox::centred((15, 15), (10, 10), 0), B);
    }
}
