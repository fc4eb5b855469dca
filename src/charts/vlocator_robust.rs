//! Chart kind `vlocator_robust`: the window of included angles of a V-block that holds every
//! load of a range without self-locking at any friction of a range, against the width of the
//! friction range, with the most robust angle and the standard 60/90/120 deg V-blocks marked;
//! drawn from [`VlocatorRobustData`].

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff::{Axis, Fixed, Named, PanelSeries, ParamKey, ReadOffData, Sweep, SweepPanel};
use super::style::{self, LineKind};
use super::vlocator_capacity::{level_text, locator_subtitle};
use super::xy::{Curve, CurveStyle, Figure, LabelSide, Mark, Panel, Tag};
use crate::figures::vlocator_capacity::STANDARD_V_DEG;
use crate::figures::vlocator_robust::{GivenRange, VlocatorRobustData, VlocatorRobustSettings};
use crate::grid::AxisScale;
use crate::locator::{
    BoxVerdict, DroppedLoad, FailureMode, RobustBox, RobustDesign, lock_angle_deg,
};
use crate::numbers::Num;

/// A robust-design chart ready to draw.
#[derive(Debug, Clone)]
pub struct VlocatorRobust {
    data: VlocatorRobustData,
    title: String,
}

impl Picture for VlocatorRobust {
    type Settings = VlocatorRobustSettings;

    fn new(data: VlocatorRobustData, title: &str) -> Self {
        VlocatorRobust {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &VlocatorRobustData {
        &self.data
    }

    /// What the gallery's read-off needs ([`ReadOffData::Panels`]): the frame,
    /// and per width the friction range and the design as the CSV names them (the first
    /// window; `null` where no V works), the box's loads as fixed inputs.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let fig = self.figure();
        let (p, frame) = (fig.panels.first()?, *frames.first()?);
        let panel = SweepPanel {
            frame,
            // The pointer's y is read against the most robust angle (the crosshair lands on it).
            y: Axis::of("included_angle_deg", &p.y),
            quantity: "robust_deg",
            x: Axis::of("mu_width", &p.x),
            sweep: 0,
        };
        let d = &self.data.designs;
        let col = |v: &dyn Fn(&RobustDesign) -> Option<f64>| d.iter().map(v).collect();
        let boxes: Vec<RobustBox> = self
            .data
            .widths
            .iter()
            .map(|&w| self.data.settings.box_of(w))
            .collect();
        let mu = |side: fn(&RobustBox) -> f64| boxes.iter().map(|b| Some(side(b))).collect();
        let series = PanelSeries {
            label: "robust design".into(),
            mu: None,
            columns: Named(vec![
                ("mu_lo", mu(|b| b.mu_left.0)),
                ("mu_hi", mu(|b| b.mu_left.1)),
                ("lock_bound_deg", col(&|d| Some(d.lock_bound_deg))),
                ("window_lo_deg", col(&|d| d.windows.first().map(|w| w.0))),
                ("window_hi_deg", col(&|d| d.windows.first().map(|w| w.1))),
                (
                    "robust_deg",
                    col(&|d| d.robust.map(|r| r.included_angle_deg)),
                ),
                (
                    "safety_factor",
                    col(&|d| d.robust.map(|r| r.safety_factor).filter(|r| r.is_finite())),
                ),
            ]),
        };
        let s = &self.data.settings;
        let (load, angle) = (s.load_n, s.load_angle_deg);
        Some(ReadOffData::Panels {
            model: "vlocator",
            panels: vec![panel],
            sweeps: vec![Sweep {
                param: "mu_width",
                at: self.data.widths.clone(),
                fixed: Named(vec![
                    ("mu_center", Fixed::Number(Some(s.center()))),
                    ("load_n", Fixed::Range([load.lo, load.hi])),
                    ("load_angle_deg", Fixed::Range([angle.lo, angle.hi])),
                ]),
                series: vec![series],
                param_key: ParamKey::First,
            }],
        })
    }

    /// Draws the panel.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure().draw(root)
    }
}

impl VlocatorRobust {
    fn figure(&self) -> Figure {
        let s = &self.data.settings;
        let (c, wmax) = (Num(s.center()), s.width_max());
        let x = PlotAxis::new(
            0.0,
            wmax,
            AxisScale::Linear,
            format!(
                "width w of the friction range (-): μ from {c} − w/2 to {c} + w/2, both flanks"
            ),
        );
        let y = self.angle_axis();
        let mut curves = Vec::new();
        let given = self.data.given.as_ref().map(|g| {
            let i = g.index;
            let name = format!("μ {}", range_text((g.mu_lo, g.mu_hi)));
            (g, self.data.widths[i], &self.data.designs[i], name)
        });
        // The window as a band over the widths, under every line: each stretch of widths
        // with a window (a second window of a width, where there is one, a band of its own).
        // Drawn as one black bar per width it read as a comb.
        curves.extend(window_bands(&self.data.widths, &self.data.designs));
        // The range given over the band.
        if let Some((_, w, _, name)) = &given {
            curves.push(Curve {
                label: format!("your range, {name} (w = {})", Num(*w)),
                style: CurveStyle::Line(RANGE_LINE),
                points: vec![(*w, y.min), (*w, y.max)],
            });
        }
        let lock: Vec<(f64, f64)> = self
            .data
            .widths
            .iter()
            .zip(&self.data.designs)
            .map(|(&w, d)| (w, d.lock_bound_deg))
            .collect();
        curves.push(Curve {
            label: "2 atan μ_hi: narrower locks at the top friction".into(),
            style: CurveStyle::Line(LineKind::Dashed),
            points: lock,
        });
        let robust: Vec<(f64, f64)> = self
            .data
            .widths
            .iter()
            .zip(&self.data.designs)
            .filter_map(|(&w, d)| d.robust.map(|r| (w, r.included_angle_deg)))
            .collect();
        if !robust.is_empty() {
            curves.push(Curve {
                label: "most robust γ (largest common factor ρ* on loads and friction)".into(),
                // Purple dots: apart from the band it runs through.
                style: CurveStyle::Line(LineKind::Level),
                points: robust,
            });
        }
        let mut tags = Vec::new();
        let shown: Vec<f64> = STANDARD_V_DEG
            .into_iter()
            .filter(|g| (y.min..=y.max).contains(g))
            .collect();
        for &g in &shown {
            curves.push(Curve {
                label: format!("standard V-blocks {}", degrees(&shown)),
                style: CurveStyle::Line(LineKind::Dotted),
                points: vec![(0.0, g), (wmax, g)],
            });
            tags.push(Tag {
                // Just above its line, whatever the zoom.
                at: (wmax, g + TAG_RISE * (y.max - y.min)),
                text: format!("{g:.0}° V"),
                left: true,
            });
        }
        let mut marks = Vec::new();
        let (a0, a1) = s.load_angle_deg.ends();
        let directions = match a0 == a1 {
            true => format!("{}°", level_text(a0)),
            false => format!("{}° to {}°", level_text(a0), level_text(a1)),
        };
        let mut notes = vec![format!(
            "Loads {} N at {directions}; a V works when it holds every load at the lowest friction and \
             does not lock at the highest.",
            range_text(s.load_n.ends()),
        )];
        if let Some((g, w, d, name)) = &given {
            marks.extend(given_marks(name, *w, d, &x, &y));
            notes.extend(self.given_notes(name, g, d));
        }
        // Where the range given has no window, its reason says it all.
        let given_closed = given.as_ref().is_some_and(|g| g.2.windows.is_empty());
        if let Some(w) = self.closes().filter(|_| !given_closed) {
            notes.push(format!(
                "No V works from a range width of {} on (no band).",
                super::style::fmt_num(w, 3)
            ));
        }
        Figure {
            title: self.title.clone(),
            // The frictions are the x axis' ranges, not curves "as marked".
            subtitle: locator_subtitle(&s.locator, "loads as noted", false)
                .replace("μ on both flanks as marked", "μ ranges on the x axis"),
            panels: vec![Panel {
                x,
                y,
                curves,
                marks,
                tags,
            }],
            notes,
        }
    }

    /// The smallest width at which no V works, if any.
    fn closes(&self) -> Option<f64> {
        self.data
            .widths
            .iter()
            .zip(&self.data.designs)
            .find(|(_, d)| d.windows.is_empty())
            .map(|(&w, _)| w)
    }

    /// The included-angle axis over the angles drawn (windows, lock bound, most robust), with
    /// room around them, at whole multiples of 10 deg within [0, 180]: a window of a few
    /// degrees was a few pixels on the whole 0 to 180 deg. A standard V-block at the top gets
    /// room for its tag.
    fn angle_axis(&self) -> PlotAxis {
        let angles = self.data.designs.iter().flat_map(|d| {
            let windows = d.windows.iter().flat_map(|&(lo, hi)| [lo, hi]);
            let robust = d.robust.map(|r| r.included_angle_deg);
            windows.chain([d.lock_bound_deg]).chain(robust)
        });
        let (lo, hi) = angles
            .filter(|a| a.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), a| {
                (lo.min(a), hi.max(a))
            });
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 180.0) };
        let pad = (0.1 * (hi - lo)).max(ANGLE_PAD_DEG);
        let lo = (10.0 * ((lo - pad) / 10.0).floor()).max(0.0);
        let mut hi = (10.0 * ((hi + pad) / 10.0).ceil()).min(180.0);
        if STANDARD_V_DEG.iter().any(|g| hi - 6.0 < *g && *g <= hi) {
            hi = (hi + 10.0).min(180.0);
        }
        PlotAxis::new(lo, hi, AxisScale::Linear, "included angle γ (deg)")
    }

    /// The notes on the range given: why no V works and what would open a window, and the
    /// standard V-blocks over its box.
    fn given_notes(&self, name: &str, g: &GivenRange, d: &RobustDesign) -> Vec<String> {
        let s = &self.data.settings;
        let mut notes = Vec::new();
        if d.windows.is_empty() {
            let mut why = format!(
                // No-break spaces keep "μ = 0.1" on one line of the wrapped note.
                "No V works for {name}: every V that does not lock at μ\u{a0}=\u{a0}{} \
                 (γ\u{a0}≥\u{a0}{:.2}°) {} at μ\u{a0}=\u{a0}{}.",
                Num(g.mu_hi),
                d.lock_bound_deg,
                d.dropped_at_lock_bound
                    .map_or("drops a load".to_string(), |l| drops(&l)),
                Num(g.mu_lo)
            );
            if let Some(o) = d.opening {
                let mut opens = Vec::new();
                if let Some(m) = o.mu_hi_max {
                    let lock = lock_angle_deg(s.locator.rotation, (m, m));
                    opens.push(format!("μ stays below {:.4} (a {lock:.2}° V)", Num(m)));
                }
                if let Some(p) = o.load_hi_max_n {
                    opens.push(format!(
                        "the load below {:.3} N (the {:.2}° V)",
                        Num(p),
                        d.lock_bound_deg
                    ));
                }
                if !opens.is_empty() {
                    why.push_str(&format!(" A window opens if {}.", opens.join(" or ")));
                }
            }
            notes.push(why);
        }
        // The V-blocks with the same verdict named together (a dropped load by how the part
        // leaves; `jamchart vlocator` gives each load).
        let mut verdicts: Vec<(Option<FailureMode>, bool, Vec<f64>)> = Vec::new();
        for v in &g.standard_v_blocks {
            let key = match v.verdict {
                BoxVerdict::Works => (None, false),
                BoxVerdict::Locks { .. } => (None, true),
                BoxVerdict::Drops { load } => (Some(load.mode), false),
            };
            match verdicts.iter_mut().find(|(m, l, _)| (*m, *l) == key) {
                Some((_, _, gs)) => gs.push(v.included_angle_deg),
                None => verdicts.push((key.0, key.1, vec![v.included_angle_deg])),
            }
        }
        let said: Vec<String> = verdicts
            .iter()
            .map(|(mode, locks, gs)| {
                let s = if gs.len() == 1 { "s" } else { "" };
                let what = match (mode, locks) {
                    (Some(m), _) => format!("drop{s} a load (the part {})", m.describe()),
                    (None, true) => format!("self-lock{s}"),
                    (None, false) => format!("work{s}"),
                };
                format!("{} {what}", degrees(gs))
            })
            .collect();
        notes.push(format!(
            "Standard V-blocks over {name}: {}.",
            said.join("; ")
        ));
        notes
    }
}

/// The range given, read off: its verdict beside the top of its line, and its most robust
/// angle with lines to the axes or, where no V works, the narrowest V that does not lock (the
/// lock bound), which drops a load. The window's ends and rho* are in the verdict, the reason
/// in the notes: a long label in the plot hid the band it lay on.
fn given_marks(name: &str, w: f64, d: &RobustDesign, x: &PlotAxis, y: &PlotAxis) -> [Mark; 2] {
    let verdict = match d.windows.first() {
        Some(&(lo, hi)) => format!("{name}: γ from {lo:.2}° to {hi:.2}° works"),
        None => format!("{name}: no V works"),
    };
    let (at, text) = match d.robust {
        Some(r) => (
            r.included_angle_deg,
            format!(
                "most robust {:.2}° (ρ* = {})",
                r.included_angle_deg,
                rho_text(r.safety_factor)
            ),
        ),
        None => (
            d.lock_bound_deg,
            format!(
                "{:.2}°: the narrowest V that does not lock drops {}",
                d.lock_bound_deg,
                d.dropped_at_lock_bound
                    .map_or("a load".to_string(), |l| format!(
                        "{} N",
                        level_text(l.load_n)
                    ))
            ),
        ),
    };
    // Near the top of the line, where the band does not reach (the axis has room above and below
    // them), or near its foot where a standard V-block's tag sits in the top fifth.
    let span = y.max - y.min;
    let tag_at_top = STANDARD_V_DEG
        .iter()
        .any(|g| (y.min..=y.max).contains(g) && *g + TAG_RISE * span > y.max - 0.2 * span);
    let height = match tag_at_top {
        true => y.min + 0.04 * span,
        false => y.max - 0.04 * span,
    };
    [
        Mark {
            at: (w, height),
            text: verdict,
            side: LabelSide::OnLine {
                right: w <= 0.5 * (x.min + x.max),
            },
            guides: false,
        },
        Mark {
            at: (w, at),
            text,
            side: LabelSide::GuideStart { above: true },
            guides: true,
        },
    ]
}

/// The window of included angles as bands over the widths: the outline of each stretch of
/// widths that have a k-th window (k = 0, 1, ...), along its low ends and back along its high
/// ends. A stretch of one width is drawn a quarter of the widths' step either side of it.
fn window_bands(widths: &[f64], designs: &[RobustDesign]) -> Vec<Curve> {
    let step = match widths {
        [a, b, ..] => (b - a).abs(),
        _ => 0.0,
    };
    let most = designs.iter().map(|d| d.windows.len()).max().unwrap_or(0);
    let mut bands = Vec::new();
    for k in 0..most {
        let mut i = 0;
        while i < designs.len() {
            if designs[i].windows.len() <= k {
                i += 1;
                continue;
            }
            let start = i;
            while i < designs.len() && designs[i].windows.len() > k {
                i += 1;
            }
            let run: Vec<(f64, (f64, f64))> = (start..i)
                .map(|j| (widths[j], designs[j].windows[k]))
                .collect();
            let run = match run[..] {
                [(w, win)] => vec![(w - step / 4.0, win), (w + step / 4.0, win)],
                _ => run,
            };
            let low = run.iter().map(|&(w, (lo, _))| (w, lo));
            let high = run.iter().rev().map(|&(w, (_, hi))| (w, hi));
            bands.push(Curve {
                label: "window: holds every load, never locks".into(),
                style: CurveStyle::Band(style::BAND_FILL),
                points: low.chain(high).collect(),
            });
        }
    }
    bands
}

/// How far above its line a standard V-block's tag sits, as a fraction of the angle axis.
const TAG_RISE: f64 = 0.025;

/// Room below and above the angles drawn, deg, at least (then rounded out to 10 deg).
const ANGLE_PAD_DEG: f64 = 3.0;

/// The range given: Okabe-Ito bluish green in medium dashes, apart from the window's band, the
/// vermillion lock bound and the purple robust angle.
const RANGE_LINE: LineKind = LineKind::Family(3);

/// `0.1 to 0.25`, or `20` for a point.
fn range_text((lo, hi): (f64, f64)) -> String {
    match lo == hi {
        true => level_text(lo),
        false => format!("{} to {}", level_text(lo), level_text(hi)),
    }
}

/// `60°, 90° and 120°`.
fn degrees(gs: &[f64]) -> String {
    let each: Vec<String> = gs.iter().map(|g| format!("{g:.0}°")).collect();
    match each.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => each.join(""),
    }
}

/// rho* to two decimals, or "unbounded".
fn rho_text(rho: f64) -> String {
    match rho.is_finite() {
        true => format!("{rho:.2}"),
        false => "unbounded".into(),
    }
}

/// "drops 20 N at 0° (it rolls out over the right flank)", for one V.
fn drops(l: &DroppedLoad) -> String {
    format!(
        "drops {} N at {}° (it {})",
        level_text(l.load_n),
        level_text(l.load_angle_deg),
        l.mode.describe()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charts::builtin::scene_text;
    use crate::figures::vlocator_robust::Interval;
    use crate::locator::robust_design;

    fn built_in() -> VlocatorRobustSettings {
        settings(scene_text("vlocator-robust").unwrap())
    }

    /// The `[chart]` settings of a scene's text.
    fn settings(text: &str) -> VlocatorRobustSettings {
        let table: toml::Table = toml::from_str(text).unwrap();
        let mut chart = table["chart"].as_table().unwrap().clone();
        chart.remove("kind");
        toml::Value::Table(chart).try_into().unwrap()
    }

    /// The chart of settings `s`, computed.
    fn chart(s: &VlocatorRobustSettings) -> VlocatorRobust {
        use crate::figures::Figure as _;
        let input = crate::charts::SceneSource::BuiltIn("vlocator-robust".into())
            .load(&[])
            .unwrap()
            .input();
        s.validate(&input).unwrap();
        let data = s.compute(&input, &crate::figures::models::Live).unwrap();
        VlocatorRobust::new(data, "test")
    }

    /// The window of included angles was drawn as one black bar per width of the friction
    /// range, a comb of 51 bars; it is one band, outlined along every width with a window (its
    /// low ends, then its high ends back), over which the lines are drawn.
    #[test]
    fn the_window_is_one_band_not_a_comb_of_bars() {
        let s = settings(scene_text("vlocator-robust").unwrap());
        let c = chart(&s);
        let fig = c.figure();
        let curves = &fig.panels[0].curves;
        let window: Vec<&Curve> = (curves.iter())
            .filter(|c| c.label.starts_with("window:"))
            .collect();
        assert_eq!(window.len(), 1, "{window:?}");
        assert!(matches!(window[0].style, CurveStyle::Band(_)), "{window:?}");
        let with: Vec<(f64, (f64, f64))> = (c.data.widths.iter().zip(&c.data.designs))
            .filter_map(|(&w, d)| d.windows.first().map(|&win| (w, win)))
            .collect();
        assert!(with.len() > 10, "{} widths with a window", with.len());
        let low: Vec<(f64, f64)> = with.iter().map(|&(w, (lo, _))| (w, lo)).collect();
        let high: Vec<(f64, f64)> = with.iter().rev().map(|&(w, (_, hi))| (w, hi)).collect();
        assert_eq!(window[0].points, [low, high].concat());
        // Under every line: the first curve drawn.
        assert!(std::ptr::eq(window[0], &curves[0]));
    }

    /// The robust chart wanted a centre and a width (0.175 +- 0.075) where the engineer has a
    /// friction range, 0.1 to 0.25; it drew the answer on 0 to 180 deg (for the 25 mm shaft
    /// under 20 N sideways, a window of a few pixels), did not mark the range and did not say
    /// that no V works over it. `mu = "0.1:0.25"` is taken as written: the range's box is
    /// exactly (0.1, 0.25) and its design `vlocator`'s over that box (no window: mu_hi P > W,
    /// `robust` docs), the range is a line at its width, the chart says "no V works" there with
    /// the reason, and the angle axis spans the angles drawn, not 0 to 180 deg.
    #[test]
    fn a_friction_range_is_charted_as_written_and_says_no_v_works() {
        let s = settings(scene_text("vlocator-robust-range").unwrap());
        assert_eq!(s.mu, Some(Interval { lo: 0.1, hi: 0.25 }));
        let c = chart(&s);
        let g = c.data.given.as_ref().expect("the range given");
        let w = c.data.widths[g.index];
        assert_eq!((g.mu_lo, g.mu_hi, w), (0.1, 0.25, 0.25 - 0.1));
        let b = RobustBox::both_flanks(&s.locator, (0.1, 0.25), (20.0, 20.0), (0.0, 0.0));
        assert_eq!(s.box_of(w), b);
        let d = robust_design(&s.locator, &b);
        assert_eq!(c.data.designs[g.index], d);
        // Free V, sideways centre load: the window is empty when mu_hi P > W (0.25 * 20 > 3.92).
        assert!(
            0.25 * 20.0 > s.locator.weight_n() && d.windows.is_empty(),
            "{d:?}"
        );
        let fig = c.figure();
        let p = &fig.panels[0];
        let range = p
            .curves
            .iter()
            .find(|c| c.label.starts_with("your range, μ 0.1 to 0.25"));
        assert_eq!(range.map(|c| c.points[0].0), Some(w), "{:?}", p.curves);
        let texts: Vec<&str> = p.marks.iter().map(|m| m.text.as_str()).collect();
        assert!(texts.contains(&"μ 0.1 to 0.25: no V works"), "{texts:?}");
        let why = fig
            .notes
            .iter()
            .find(|n| n.starts_with("No V works for μ 0.1 to 0.25"));
        let why = why.unwrap_or_else(|| panic!("{:?}", fig.notes));
        assert!(
            why.contains("28.07°") && why.contains("rolls out over the right flank"),
            "{why}"
        );
        // Every angle drawn lies on the axis, and the axis is no wider than they need plus
        // 10 deg of room at each end.
        let angles: Vec<f64> = c.data.designs.iter().map(|d| d.lock_bound_deg).collect();
        let (lo, hi) = angles
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(*v), b.max(*v)));
        assert!(p.y.min <= lo && hi <= p.y.max, "{:?} for {lo}..{hi}", p.y);
        assert!(
            p.y.max - p.y.min <= hi - lo + 20.0,
            "{:?} for {lo}..{hi}",
            p.y
        );
    }

    /// Where a window exists over the range given, the chart reads it off: the window of a
    /// free symmetric V under a sideways centre load P is [2 atan mu_hi, 2 atan(W / P)] and its
    /// most robust angle 2 atan sqrt(mu_hi W / P) (`robust` docs), for mu 0.1 to 0.25, 1 kg,
    /// 20 N.
    #[test]
    fn the_range_given_is_read_off_as_the_closed_form() {
        let text = scene_text("vlocator-robust-range")
            .unwrap()
            .replace("mass_kg = 0.4", "mass_kg = 1.0");
        let s = settings(&text);
        let c = chart(&s);
        let w = s.locator.weight_n();
        let deg = |x: f64| 2.0 * x.atan().to_degrees();
        let (lo, hi, robust) = (deg(0.25), deg(w / 20.0), deg((0.25 * w / 20.0).sqrt()));
        let fig = c.figure();
        let marks = &fig.panels[0].marks;
        let want = format!("μ 0.1 to 0.25: γ from {lo:.2}° to {hi:.2}° works");
        assert_eq!(marks[0].text, want);
        assert!(
            (marks[1].at.1 - robust).abs() < 1e-6,
            "{marks:?} against {robust}"
        );
        assert!(
            marks[1].guides
                && marks[1]
                    .text
                    .starts_with(&format!("most robust {robust:.2}°"))
        );
    }

    /// The older form, a centre and the widest width, still draws the same windows; giving
    /// both forms is refused naming the key.
    #[test]
    fn a_centre_and_a_width_draw_the_same_windows_as_the_range() {
        let text = scene_text("vlocator-robust-range").unwrap();
        let new = settings(text);
        let old = settings(&text.replace(
            "mu = \"0.1:0.25\"",
            "mu_center = 0.175\nwidth_max = 0.3\ncount = 51",
        ));
        let (a, b) = (chart(&new), chart(&old));
        for (w, d) in b.data.widths.iter().zip(&b.data.designs) {
            let i = a
                .data
                .widths
                .iter()
                .position(|v| (v - w).abs() < 1e-12)
                .unwrap();
            let lock = (a.data.designs[i].lock_bound_deg - d.lock_bound_deg).abs();
            assert!(lock < 1e-9, "{w}: {lock}");
            assert_eq!(a.data.designs[i].windows.len(), d.windows.len(), "{w}");
        }
        let mut both = new.clone();
        both.mu_center = Some(0.175);
        let input = crate::charts::SceneSource::BuiltIn("vlocator-robust".into())
            .load(&[])
            .unwrap()
            .input();
        use crate::figures::Figure as _;
        let e = both.validate(&input).unwrap_err().to_string();
        assert!(
            e.contains("chart.mu_center") && e.contains("give the friction range once"),
            "{e}"
        );
    }

    /// The built-in scene's window against the closed form of a free symmetric V under centre
    /// loads within 10 deg of sideways (`robust` docs): it opens at 2 atan mu_hi, its top is
    /// the heaviest load at the most lifting direction, x <= (W / P - sin 10) / cos 10 with
    /// x = tan(gamma/2), and it closes where the two meet.
    #[test]
    fn robust_chart_window_matches_the_closed_form() {
        let s = built_in();
        let w = s.locator.weight_n();
        let (sn, cs) = 10.0_f64.to_radians().sin_cos();
        let x_top = (w / s.load_n.hi - sn) / cs;
        let top = 2.0 * x_top.atan().to_degrees();
        let mut worst: f64 = 0.0;
        for width in s.widths() {
            let b = s.box_of(width);
            let d = robust_design(&s.locator, &b);
            let lock = 2.0 * b.mu_left.1.atan().to_degrees();
            if b.mu_left.1 < x_top * (1.0 - 1e-9) {
                let (lo, hi) = d.windows[0];
                worst = worst.max((lo - lock).abs()).max((hi - top).abs());
            } else if b.mu_left.1 > x_top * (1.0 + 1e-9) {
                assert!(d.windows.is_empty(), "{width}: {d:?}");
            }
        }
        // The arc cover overstates the load by at most 1e-5: the top moves by less than 1e-3 deg.
        assert!(worst < 1e-3, "worst {worst:e} deg");
    }
}
