//! Chart kind `sweep` (Figs. 6, 7a, 7b): x_jam and theta_jam against one scene parameter,
//! drawn from [`SweepData`] ([`crate::figures::sweep`]): each panel plots one quantity of
//! every series, a curve or a marker per point as its [`Curve`] says, under an uncertain
//! input's shaded band.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axes::{self, DrawResult, PlotAxis, PlotFrame};
use super::collide::{self, PxBox};
use super::labels::scene_subtitle_given;
use super::legend::{self, LegendEntry, LegendGroup, Swatch};
use super::picture::Picture;
use super::readoff::{Axis, QuantityPanel, ReadOffData, SweepSeries};
use super::style::{self, LineKind, Marker};
use super::sweep_band;
use super::{axis_label, param_symbol, param_unit};
use crate::figures::band::BandRow;
use crate::figures::sweep::{SweepData, SweepSettings};
use crate::figures::sweep_layers::{Curve, Series, SeriesPoint, SweepLayer, SweepPanel};
use crate::grid::AxisScale;
use crate::scene::JamStatus;
use crate::scene::Param;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SeriesStyle {
    /// A curve through the points.
    Line(LineKind),
    /// A marker at each point.
    Points(Marker),
}

impl SeriesStyle {
    /// The line or marker of curve `c`.
    fn of(c: Curve) -> Self {
        use SeriesStyle::{Line, Points};
        match c {
            Curve::Statics => Line(LineKind::Solid),
            Curve::Rigid => Line(LineKind::Dashed),
            Curve::BandEarliest => Line(LineKind::BandEarliest),
            Curve::BandLatest => Line(LineKind::BandLatest),
            Curve::PaperTable1ForceAnalysis => Points(Marker::Circle),
            Curve::PaperTable1MinNorm => Points(Marker::Triangle),
            Curve::PaperTable1Erratum => Points(Marker::Cross),
            Curve::PaperAdams => Points(Marker::Square),
            Curve::MinNorm => Points(Marker::OpenSquare),
            Curve::MinNormRolling => Points(Marker::Plus),
            Curve::SimulationMotion => Points(Marker::Diamond),
            Curve::SimulationForce => Points(Marker::OpenDiamond),
        }
    }
}

/// A panel's quantity, as its axis is labelled.
fn panel_label(panel: SweepPanel) -> &'static str {
    match panel {
        SweepPanel::XJamMm => "disc position at the jam x_jam (mm)",
        SweepPanel::ThetaJamDeg => "palm angle at the jam θ_jam (deg)",
    }
}

/// A sweep ready to draw.
#[derive(Debug, Clone)]
pub struct Sweep {
    data: SweepData,
    title: String,
}

impl Picture for Sweep {
    type Settings = SweepSettings;

    fn new(data: SweepData, title: &str) -> Self {
        Sweep {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &SweepData {
        &self.data
    }

    /// One plotting area of `frames` per panel with its quantity, the x axis, and every
    /// series' points.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        if frames.len() != self.data.settings.panels.len() {
            return None;
        }
        let a = &self.data.settings.x_axis;
        let x = PlotAxis::new(a.min, a.max, a.scale, axis_label(a.param));
        let panels: Vec<_> = self
            .data
            .settings
            .panels
            .iter()
            .zip(frames)
            .map(|(panel, frame)| QuantityPanel {
                frame: *frame,
                y: Axis::of(panel.key(), &self.panel_axis(*panel)),
                quantity: panel.key(),
            })
            .collect();
        let series = (self.data.series.iter())
            .map(|s| SweepSeries {
                label: s.label.clone(),
                layer: s.curve.name(),
                line: s.curve.is_line(),
                at: s.points.iter().map(|p| p.at).collect(),
                x_jam_mm: s.points.iter().map(|p| p.x_jam_mm).collect(),
                theta_jam_deg: s.points.iter().map(|p| p.theta_jam_deg).collect(),
            })
            .collect();
        Some(ReadOffData::Sweep {
            x: Axis::of(a.param.as_str(), &x),
            panels,
            series,
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        let h = root.dim_in_pixel().1 as i32;
        let entries = self.legend();
        let groups = self.legend_groups();
        let rows = match &groups {
            Some(g) => legend::grouped_rows_needed(root, g)?,
            None => legend::rows_needed(root, &entries)?,
        };
        let legend_top = h - 12 - rows * legend::ROW_PX;
        let a = &self.data.settings.x_axis;
        let x = PlotAxis::new(a.min, a.max, a.scale, axis_label(a.param));
        let panels = &self.data.settings.panels;
        for (panel, m) in panels
            .iter()
            .zip(axes::stacked(h, legend_top, panels.len()))
        {
            let y = self.panel_axis(*panel);
            let chart = axes::build_chart(root, &x, &y, m)?;
            // Under the grid and every curve: the band is the background the curves are read on.
            sweep_band::draw(&chart, &self.data.band, *panel, (&x, &y))?;
            axes::draw_grid(&chart, &x, &y)?;
            let area = chart.plotting_area();
            self.draw_read_off_lines(root, &chart, (&x, &y), *panel)?;
            // The labels drawn so far: the read-off's step numbers and answer keep clear of them.
            let mut placed = Vec::new();
            for s in &self.data.series {
                let pts: Vec<(f64, f64)> = s
                    .points
                    .iter()
                    .filter_map(|p| panel.value(p).map(|v| (x.to_plot(p.at), y.to_plot(v))))
                    .collect();
                match SeriesStyle::of(s.curve) {
                    SeriesStyle::Line(k) => style::draw_line(area, &pts, k, k.color())?,
                    SeriesStyle::Points(mk) => {
                        for p in pts {
                            style::draw_marker(area, mk, p)?;
                        }
                    }
                }
                placed.extend(self.annotate(root, &chart, (&x, &y), *panel, s)?);
            }
            placed.extend(self.draw_palm_end(root, &chart, (&x, &y), *panel)?);
            self.draw_read_off(root, &chart, (&x, &y), *panel, &placed)?;
            axes::draw_frame(root, &chart, &x, &y)?;
        }
        let sub = scene_subtitle_given(self.source(), &self.data.params, &[a.param], &self.given());
        axes::draw_header(root, &self.title, &sub)?;
        match &groups {
            Some(g) => legend::draw_grouped_legend(root, g, legend_top),
            None => legend::draw_legend(root, &entries, legend_top),
        }
    }
}

/// The boxes of the labels a drawing step drew, or its drawing error.
type Labels<DB> = Result<Vec<PxBox>, DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

impl Sweep {
    /// In the x_jam panel, the palm's end as a dotted purple level where it lies on the panel's scale
    /// (a jam beyond it is never reached): x = L, where the contact is at the palm's end for a
    /// palm face on the hinge line (h = 0; with an offset the line would bend, so it is left
    /// out) and the palm length is not the swept parameter. Returns its label's box.
    fn draw_palm_end<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        (x, y): (&PlotAxis, &PlotAxis),
        panel: SweepPanel,
    ) -> Labels<DB> {
        let l = self.data.params.palm_length_mm;
        let shown = panel == SweepPanel::XJamMm
            && self.data.params.palm_offset_mm == 0.0
            && self.data.settings.x_axis.param != Param::PalmLengthMm
            && (y.min..=y.max).contains(&l);
        if !shown {
            return Ok(Vec::new());
        }
        let line = [
            (x.to_plot(x.min), y.to_plot(l)),
            (x.to_plot(x.max), y.to_plot(l)),
        ];
        let kind = LineKind::Level;
        style::draw_line(chart.plotting_area(), &line, kind, kind.color())?;
        let at = axes::pixel(chart, x, y, x.min, l);
        let s = format!("palm's end L = {} mm: no jam above", style::fmt_num(l, 1));
        let pos = Pos::new(HPos::Left, VPos::Bottom);
        let label = axes::boxed_text_placed(root, &s, (at.0 + 8, at.1 - 4), pos, style::TICK_PX)?;
        Ok(vec![label])
    }

    /// The read-off at the scene's value in `panel`, in numbered steps as a jam map's, over
    /// its lines ([`Sweep::draw_read_off_lines`]): a dot on each point, the step numbers 1 and
    /// 2 on their lines, and (3) the value printed beside the upper dot where no curve runs,
    /// inside the plot, in two lines where one does not fit. Nothing of it covers the labels
    /// `placed`.
    fn draw_read_off<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        (x, y): (&PlotAxis, &PlotAxis),
        panel: SweepPanel,
        placed: &[PxBox],
    ) -> DrawResult<DB> {
        let Some((v, points, parts)) = self.read_off_in(panel, (x, y)) else {
            return Ok(());
        };
        let at = |a: f64, b: f64| axes::pixel(chart, x, y, a, b);
        let (corner, bottom, left) = (at(v, points[0]), at(v, y.min), at(x.min, points[0]));
        let across: Vec<[(i32, i32); 2]> =
            points.iter().map(|q| [at(v, *q), at(x.min, *q)]).collect();
        for q in &points {
            root.draw(&Circle::new(at(v, *q), 5, style::INK.filled()))?;
        }
        // Every curve of the panel: the step numbers and the value's box cover none.
        let lines: Vec<Vec<(i32, i32)>> = self
            .data
            .series
            .iter()
            .map(|c| {
                let pts = c.points.iter();
                pts.filter_map(|sp| panel.value(sp).map(|val| at(sp.at, val)))
                    .collect()
            })
            .collect();
        let (lo, hi) = (at(x.min, y.min), at(x.max, y.max));
        let frame = PxBox {
            x0: lo.0,
            y0: hi.1,
            x1: hi.0,
            y1: lo.1,
        };
        // The value's box first (it has four places, the step numbers many): it covers no
        // curve, none of the read-off's own lines and no label; on one line where that fits
        // beside the point, else in its parts one under another.
        let mut own_lines = lines.clone();
        own_lines.push(vec![bottom, corner]);
        own_lines.extend(across.iter().map(|l| l.to_vec()));
        let pad = (8, axes::BOX_PAD);
        let one = vec![parts.join(" ")];
        let mut first = None;
        let mut answer = None;
        for text in [&one, &parts] {
            let size = axes::lines_size(root, text, style::NOTE_PX)?;
            match collide::place_beside(corner, size, pad, &frame, &own_lines, placed) {
                Ok(free) => {
                    answer = Some((text, free));
                    break;
                }
                Err(corner) => {
                    first.get_or_insert((text, corner));
                }
            }
        }
        // No corner is free: the one-line label's first corner.
        let (text, (text_at, text_box)) = answer.or(first).expect("a shape was tried");
        // The step numbers on their lines, clear of the curves, the labels and the value.
        let taken: Vec<PxBox> = placed.iter().copied().chain([text_box]).collect();
        let tag_font = style::text(style::TICK_PX);
        for (n, (a, b)) in [("1", (bottom, corner)), ("2", (corner, left))] {
            let size = root.estimate_text_size(n, &tag_font)?;
            let (mid, _) = collide::place_along(a, b, size, axes::BOX_PAD, &lines, &taken);
            axes::tag(root, n, mid)?;
        }
        axes::boxed_lines(root, text, text_at, style::NOTE_PX)
    }

    /// Where the read-off lies in `panel`, if it is drawn there: the swept value, its points
    /// (the band's two ends, upper first, or the closed form's value) and step 3's answer,
    /// printed beside the upper one, in parts for a label too long for one line.
    fn read_off_in(
        &self,
        panel: SweepPanel,
        (x, y): (&PlotAxis, &PlotAxis),
    ) -> Option<(f64, Vec<f64>, Vec<String>)> {
        let (v, points, parts) = if let Some(r) = &self.data.read_off_band {
            let (lo, hi) = r.interval(panel)?;
            (r.at, vec![hi, lo], self.band_answer(r, panel))
        } else {
            let p = self.data.read_off.as_ref()?;
            let q = panel.value(p)?;
            let s = match panel {
                SweepPanel::XJamMm => format!("3: x_jam = {} mm", style::fmt_num(q, 3)),
                SweepPanel::ThetaJamDeg => format!("3: θ_jam = {}°", style::fmt_num(q, 3)),
            };
            (p.at, vec![q], vec![s])
        };
        let on = (x.min..=x.max).contains(&v) && points.iter().all(|q| (y.min..=y.max).contains(q));
        on.then_some((v, points, parts))
    }

    /// The read-off's dotted lines in `panel`: 1 up from the axis to the upper point, 2 across
    /// from each point to the left axis. Drawn under the curves' labels, which stay legible
    /// on their white boxes where a line passes them.
    fn draw_read_off_lines<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        (x, y): (&PlotAxis, &PlotAxis),
        panel: SweepPanel,
    ) -> DrawResult<DB> {
        let Some((v, points, _)) = self.read_off_in(panel, (x, y)) else {
            return Ok(());
        };
        let at = |a: f64, b: f64| axes::pixel(chart, x, y, a, b);
        let up = [at(v, y.min), at(v, points[0])];
        let across = points.iter().map(|q| [at(v, *q), at(x.min, *q)]);
        for line in std::iter::once(up).chain(across) {
            style::draw_line_px(root, &line, LineKind::Dotted, style::INK, 2)?;
        }
        Ok(())
    }

    /// The models behind the drawn layers, for the subtitle.
    fn source(&self) -> &'static str {
        let has = |f: fn(&SweepLayer) -> bool| self.data.settings.layers.iter().any(f);
        let min_norm = has(|l| matches!(l, SweepLayer::MinNorm | SweepLayer::MinNormRolling));
        let sim = has(|l| {
            matches!(
                l,
                SweepLayer::SimulationMotion | SweepLayer::SimulationForce
            )
        });
        match (min_norm, sim) {
            (false, false) => "closed-form statics (corrected Eq. 1)",
            (true, false) => "closed-form statics and min-norm",
            (false, true) => "closed-form statics and simulation",
            (true, true) => "closed form, min-norm and simulation",
        }
    }

    pub(super) fn legend(&self) -> Vec<LegendEntry> {
        let mut e: Vec<LegendEntry> = self
            .data
            .series
            .iter()
            .filter(|s| self.drawn(s))
            .map(|s| self.legend_entry(s))
            .collect();
        e.extend(self.band_entry());
        e.extend(self.read_off_entry());
        e
    }

    /// Whether series `s` has a value in one of the drawn panels: a legend never names a line
    /// that is not drawn (the latest-jam edge of a band wholly past the palm's end kept an
    /// entry, with no line anywhere).
    fn drawn(&self, s: &Series) -> bool {
        s.points.iter().any(|p| {
            self.data
                .settings
                .panels
                .iter()
                .any(|panel| panel.value(p).is_some())
        })
    }

    /// The shaded band's legend entry, if anything is shaded.
    fn band_entry(&self) -> Option<LegendEntry> {
        let label = &self.data.settings.band.as_ref()?.label;
        sweep_band::legend_entry(&self.data.band, label)
    }

    /// The read-off's legend entry when it is drawn (a legend never names a line that is not
    /// drawn: off the axis, or no jam there).
    fn read_off_entry(&self) -> Option<LegendEntry> {
        let a = &self.data.settings.x_axis;
        let (v, what) = match (&self.data.read_off_band, &self.data.read_off) {
            (Some(r), _) if r.x_jam_mm.is_some() => {
                (r.at, "the band's ends: earliest and latest jam")
            }
            (None, Some(p)) if p.x_jam_mm.is_some() => (p.at, "closed form"),
            _ => return None,
        };
        if !(a.min..=a.max).contains(&v) {
            return None;
        }
        Some(LegendEntry::new(
            Swatch::Stroke(LineKind::Dotted, style::INK, 2),
            format!(
                "read-off lines 1-2-3 at {} ({what})",
                super::labels::param_value(a.param, v)
            ),
        ))
    }

    /// The band's inputs as the subtitle names them, each in place of its nominal value:
    /// `μ = 0.12 to 0.3 (curves at 0.21)`.
    fn given(&self) -> Vec<(Param, String)> {
        let Some(band) = &self.data.settings.band else {
            return Vec::new();
        };
        let p = &self.data.params;
        band.inputs
            .iter()
            .filter_map(|i| {
                let k = Param::named(&i.name)?;
                let unit = match param_unit(k) {
                    "-" => String::new(),
                    u => format!(" {u}"),
                };
                let at = k
                    .get(p)
                    .map_or(String::new(), |v| format!(" (curves at {v}{unit})"));
                Some((k, format!("{} = {}{unit}{at}", param_symbol(k), i.span)))
            })
            .collect()
    }

    /// Where each corner of the band takes its inputs: `μ = 0.3`; empty without inputs.
    fn corner(&self, earliest: bool) -> String {
        let Some(band) = &self.data.settings.band else {
            return String::new();
        };
        let values: Vec<String> = band
            .inputs
            .iter()
            .filter_map(|i| {
                let k = Param::named(&i.name)?;
                Some(super::labels::param_value(
                    k,
                    if earliest { i.earliest } else { i.latest },
                ))
            })
            .collect();
        values.join(", ")
    }

    /// Step 3 of the read-off with a band in `panel`: the shaded interval there, each end
    /// with its corner and why it ends there (the earliest or latest jam, the palm's end past
    /// which the latest corner jams, the start where the earliest is held or too weak); one
    /// part per end, for a label too long for one line.
    fn band_answer(&self, r: &BandRow, panel: SweepPanel) -> Vec<String> {
        let (e, l) = (&r.earliest, &r.latest);
        let (ce, cl) = (self.corner(true), self.corner(false));
        let end = |p: &SeriesPoint, at: &str, jams: &str| match p.status {
            Some(JamStatus::Jams) => format!("{jams}, {at}"),
            Some(JamStatus::BeyondReach) | Some(JamStatus::NeverJams) => {
                format!("the palm's end: {at} jams past it")
            }
            Some(JamStatus::JammedAtStart) => format!("held at the start, {at}"),
            Some(JamStatus::TooWeak) => format!("the start: {at} cannot move it"),
            Some(other) => format!("{at}: {}", other.as_str().replace('_', " ")),
            None => at.to_string(),
        };
        let (early, late) = (end(e, &ce, "earliest"), end(l, &cl, "latest"));
        let f = |v: f64| style::fmt_num(v, 3);
        match (panel, r.interval(panel)) {
            (SweepPanel::XJamMm, Some((lo, hi))) => vec![
                format!("3: x_jam {} mm ({early})", f(lo)),
                format!("to {} mm ({late})", f(hi)),
            ],
            (SweepPanel::ThetaJamDeg, Some((lo, hi))) => vec![
                format!("3: θ_jam {}° ({early})", f(hi)),
                format!("to {}° ({late})", f(lo)),
            ],
            (_, None) => vec!["3: no jam on the palm over the band".into()],
        }
    }

    /// A series' legend entry, saying where a curve has no jam and why (a curve that just
    /// stops would read as "no data"): "no jam for μ < 0.148: beyond_reach".
    fn legend_entry(&self, s: &Series) -> LegendEntry {
        let sw = match SeriesStyle::of(s.curve) {
            SeriesStyle::Line(k) => Swatch::Line(k),
            SeriesStyle::Points(m) => Swatch::Marker(m),
        };
        let mut e = LegendEntry::new(sw, s.label.clone());
        if let Some(gaps) = self.gaps(s) {
            e.label = format!("{}; {gaps}", e.label);
        }
        e
    }

    /// The runs of points of a curve whose verdict is not `jams`, as text, or None.
    fn gaps(&self, s: &Series) -> Option<String> {
        if !s.curve.is_line() {
            return None;
        }
        let param = self.data.settings.x_axis.param;
        let fmt = |v: f64| style::fmt_num(v, 3);
        let mut runs: Vec<(JamStatus, f64, f64)> = Vec::new();
        let mut prev = None;
        for p in &s.points {
            // A gap is a point with no value drawn (the rigid limit is drawn at every point).
            let empty = p.x_jam_mm.is_none() && p.theta_jam_deg.is_none();
            if let Some(st) = p.status.filter(|st| *st != JamStatus::Jams && empty) {
                match runs.last_mut() {
                    Some(last) if prev == Some(st) => last.2 = p.at,
                    _ => runs.push((st, p.at, p.at)),
                }
            }
            prev = p.status;
        }
        if runs.is_empty() {
            return None;
        }
        let text: Vec<String> = runs
            .iter()
            .map(|(st, a, b)| {
                let why = match st {
                    JamStatus::BeyondReach => format!(
                        "past the palm's end (L = {} mm)",
                        self.data.params.palm_length_mm
                    ),
                    other => other.as_str().replace('_', " "),
                };
                let unit = super::param_unit(param);
                let unit = if unit == "-" {
                    String::new()
                } else {
                    format!(" {unit}")
                };
                format!(
                    "{why} at {} = {}–{}{unit}",
                    super::param_symbol(param),
                    fmt(*a),
                    fmt(*b)
                )
            })
            .collect();
        Some(format!("no jam {}", text.join(", ")))
    }

    /// The legend in two groups when the paper's numbers are drawn beside the models: the
    /// paper's (layers `paper_*`) and the tool's; None with one group (a plain legend).
    fn legend_groups(&self) -> Option<Vec<LegendGroup>> {
        let (paper, ours): (Vec<&Series>, Vec<&Series>) =
            self.data.series.iter().partition(|s| s.curve.is_paper());
        if paper.is_empty() || ours.is_empty() {
            return None;
        }
        let group = |heading: &str, series: Vec<&Series>| LegendGroup {
            heading: heading.into(),
            entries: series
                .into_iter()
                .filter(|s| self.drawn(s))
                .map(|s| self.legend_entry(s))
                .collect(),
        };
        Some(vec![
            group("this tool's models", ours),
            group("the paper's numbers", paper),
        ])
    }

    /// The panel's y axis over every series' values and the shaded band (which may run to the
    /// palm's end, beyond every curve).
    fn panel_axis(&self, panel: SweepPanel) -> PlotAxis {
        let shaded = self.data.band.iter().filter_map(|r| r.interval(panel));
        let vals: Vec<f64> = self
            .data
            .series
            .iter()
            .flat_map(|s| s.points.iter().filter_map(|p| panel.value(p)))
            .chain(shaded.flat_map(|(lo, hi)| [lo, hi]))
            .collect();
        let lo = vals.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = vals.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (lo, hi) = if lo.is_finite() && hi.is_finite() {
            (lo, hi)
        } else {
            (0.0, 1.0)
        };
        // 8 % headroom, and at least +-1 unit so that a constant quantity still gets an axis.
        let pad = (0.08 * (hi - lo)).max(1.0);
        PlotAxis::new(lo - pad, hi + pad, AxisScale::Linear, panel_label(panel))
    }
}

impl Sweep {
    /// The flat-curve label and the callout of series `s` in `panel`; returns their boxes.
    fn annotate<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &axes::Chart<DB>,
        (x, y): (&PlotAxis, &PlotAxis),
        panel: SweepPanel,
        s: &Series,
    ) -> Labels<DB> {
        let mut labels = Vec::new();
        let vals: Vec<(f64, f64)> = s
            .points
            .iter()
            .filter_map(|p| panel.value(p).map(|v| (p.at, v)))
            .collect();
        if let (Some(names), Some(&(a0, _)), Some(&(a1, v1))) =
            (s.flat_names, vals.first(), vals.last())
        {
            // Flat to 1e-9 relative over every point (not only the ends): the curve is a
            // constant, worth its number.
            let (lo, hi) = vals
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &(_, v)| {
                    (lo.min(v), hi.max(v))
                });
            if a0 != a1 && hi - lo <= 1e-9 * lo.abs().max(hi.abs()) {
                let (name, unit) = match panel {
                    SweepPanel::XJamMm => (names[0], " mm"),
                    SweepPanel::ThetaJamDeg => (names[1], "°"),
                };
                let px = axes::pixel(chart, x, y, a1, v1);
                let text = format!("{name} = {}{unit}", style::fmt_num(v1, 2));
                // On the side of the line where fewer other points lie, so the box hides none.
                let (mut above, mut below) = (0, 0);
                for other in self.data.series.iter().filter(|o| !std::ptr::eq(*o, s)) {
                    for v in other.points.iter().filter_map(|p| panel.value(p)) {
                        if v > v1 { above += 1 } else { below += 1 }
                    }
                }
                let (dy, vpos) = if above > below {
                    (6, VPos::Top)
                } else {
                    (-6, VPos::Bottom)
                };
                let pos = Pos::new(HPos::Right, vpos);
                let at = (px.0 - 10, px.1 + dy);
                labels.push(axes::boxed_text_placed(
                    root,
                    &text,
                    at,
                    pos,
                    style::NOTE_PX,
                )?);
            }
        }
        if let (Some(note), Some(&(a, v))) = (&s.callout, vals.first()) {
            let px = axes::pixel(chart, x, y, a, v);
            labels.push(axes::boxed_text_placed(
                root,
                note,
                (px.0 + 14, px.1 - 4),
                Pos::new(HPos::Left, VPos::Bottom),
                style::TICK_PX,
            )?);
        }
        Ok(labels)
    }
}
