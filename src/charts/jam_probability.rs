//! Chart kind `jam_probability`: P(jam before x) against the disc position x for a distributed
//! input, with the palm's end and the user's x marked and P read off there; drawn from
//! [`JamProbabilityData`]. A Monte Carlo answer draws its 95 % interval beside the curve; an
//! exact one says that it has none.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff::{Axis, Fixed, Named, PanelSeries, ParamKey, ReadOffData, Sweep, SweepPanel};
use super::style::{self, LineKind};
use super::xy::{Curve, CurveStyle, Figure, LabelSide, Mark, Panel, Tag};
use crate::figures::jam_probability::{JamProbabilityData, JamProbabilitySettings};
use crate::grid::AxisScale;
use crate::scene::Param;
use crate::uncertain::dist::{Before, DistMethod};

/// A probability chart ready to draw.
#[derive(Debug, Clone)]
pub struct JamProbability {
    data: JamProbabilityData,
    title: String,
}

impl Picture for JamProbability {
    type Settings = JamProbabilitySettings;

    fn new(data: JamProbabilityData, title: &str) -> Self {
        JamProbability {
            data,
            title: title.to_string(),
        }
    }

    fn data(&self) -> &JamProbabilityData {
        &self.data
    }

    /// What the gallery's read-off needs (kind `panels`): P and its 95 % interval at every
    /// drawn x, the distribution as a fixed input.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let fig = self.figure();
        let (p, frame) = (fig.panels.first()?, *frames.first()?);
        let panel = SweepPanel {
            frame,
            y: Axis::of("probability", &p.y),
            quantity: "probability",
            x: Axis::of("x_mm", &p.x),
            sweep: 0,
        };
        let c = &self.data.curve;
        let col = |f: fn(&Before) -> f64| c.iter().map(|b| Some(f(b))).collect();
        let series = PanelSeries {
            label: "P(jam before x)".into(),
            mu: None,
            columns: Named(vec![
                ("probability", col(|b| b.probability.value)),
                ("probability_lo", col(|b| b.probability.lo)),
                ("probability_hi", col(|b| b.probability.hi)),
            ]),
        };
        let distribution = Fixed::Text(self.data.distribution.describe());
        Some(ReadOffData::Panels {
            model: "statics",
            panels: vec![panel],
            sweeps: vec![Sweep {
                param: "x_mm",
                at: c.iter().map(|b| b.x_mm).collect(),
                fixed: Named(vec![("distribution", distribution)]),
                series: vec![series],
                param_key: ParamKey::First,
            }],
        })
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure().draw(root)
    }
}

/// P as printed on the chart: four decimals, as `solve` prints it.
fn prob(v: f64) -> String {
    format!("{v:.4}")
}

impl JamProbability {
    fn figure(&self) -> Figure {
        let d = &self.data;
        let (lo, hi) = d.settings.x_range(&d.params);
        let x = PlotAxis::new(
            lo,
            hi,
            AxisScale::Linear,
            "disc position x along the ground (mm)",
        );
        // A little room above 1 and below 0: a curve at 0 or 1 does not run along the frame.
        let y = PlotAxis::new(
            -0.02,
            1.02,
            AxisScale::Linear,
            "P(jam before x): the disc stops short of x (-)",
        );
        let palm = d.params.palm_length_mm;
        let points = |f: fn(&Before) -> f64, keep: &dyn Fn(f64) -> bool| -> Vec<(f64, f64)> {
            d.curve
                .iter()
                .filter(|b| keep(b.x_mm))
                .map(|b| (b.x_mm, f(b)))
                .collect()
        };
        let how = match d.method {
            DistMethod::Exact => "exact".to_string(),
            DistMethod::MonteCarlo { samples, .. } => format!("Monte Carlo, {samples} samples"),
        };
        let mut curves = vec![Curve {
            label: format!("P(jam before x), {how}"),
            style: CurveStyle::Line(LineKind::Solid),
            // On the palm, and the point at its end so that the two parts meet.
            points: points(|b| b.probability.value, &|x| x <= palm)
                .into_iter()
                .chain([(palm, d.on_palm.probability.value)])
                .collect(),
        }];
        let past = points(|b| b.probability.value, &|x| x > palm);
        if !past.is_empty() {
            curves.push(Curve {
                label: "past the palm's end: where a longer palm would jam it".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: std::iter::once((palm, d.on_palm.probability.value))
                    .chain(past)
                    .collect(),
            });
        }
        if let DistMethod::MonteCarlo { .. } = d.method {
            for edge in [
                points(|b| b.probability.lo, &|_| true),
                points(|b| b.probability.hi, &|_| true),
            ] {
                curves.push(Curve {
                    label: "95 % interval of the Monte Carlo estimate".into(),
                    style: CurveStyle::Line(LineKind::BandEarliest),
                    points: edge,
                });
            }
        }
        let mut tags = Vec::new();
        let mut vertical = |at: f64, label: String, kind: LineKind, text: String, p: f64| {
            curves.push(Curve {
                label,
                style: CurveStyle::Line(kind),
                points: vec![(at, y.min), (at, y.max)],
            });
            // P never falls with x, so the curve leaves the top left of the line and the
            // bottom right of it free: the tag goes where it cannot cover the curve.
            let (ty, left) = if p < 0.5 { (0.93, true) } else { (0.05, false) };
            tags.push(Tag {
                at: (at, ty),
                text,
                left,
            });
        };
        let on_palm = d.on_palm.probability.value;
        vertical(
            palm,
            format!("palm's end, L = {} mm", style::fmt_num(palm, 1)),
            LineKind::Level,
            format!("L = {} mm", style::fmt_num(palm, 1)),
            on_palm,
        );
        let mut marks = Vec::new();
        if let Some(r) = d.read_off {
            let v = r.probability.value;
            vertical(
                r.x_mm,
                format!("your x = {} mm", style::fmt_num(r.x_mm, 1)),
                LineKind::BandLatest,
                format!("x = {} mm", style::fmt_num(r.x_mm, 1)),
                v,
            );
            let interval = match d.method {
                DistMethod::Exact => String::new(),
                DistMethod::MonteCarlo { .. } => format!(
                    " (95 %: {} to {})",
                    prob(r.probability.lo),
                    prob(r.probability.hi)
                ),
            };
            marks.push(Mark {
                at: (r.x_mm, v),
                text: format!(
                    "P(jam before {} mm) = {}{interval}",
                    style::fmt_num(r.x_mm, 1),
                    prob(v)
                ),
                side: LabelSide::GuideStart { above: v < 0.5 },
                guides: true,
            });
        }
        Figure {
            title: self.title.clone(),
            subtitle: self.subtitle(),
            panels: vec![Panel {
                x,
                y,
                curves,
                marks,
                tags,
            }],
            notes: self.notes(),
        }
    }

    /// The source and the distribution, then the scene's other parameters.
    fn subtitle(&self) -> String {
        let d = &self.data;
        let given: Vec<Param> = d
            .distribution
            .inputs
            .iter()
            .filter_map(|i| Param::named(i.name))
            .collect();
        let each: Vec<String> = d
            .distribution
            .inputs
            .iter()
            .map(|i| {
                let symbol = Param::named(i.name).map_or(i.name, super::param_symbol);
                format!("{symbol} ~ {}", i.value)
            })
            .collect();
        let source = format!(
            "closed-form statics (corrected Eq. 1) under {}",
            each.join(", ")
        );
        super::scene_subtitle_with(&source, &d.params, &given)
    }

    /// What the curve means, what the palm's end says, and how sure the answer is.
    fn notes(&self) -> Vec<String> {
        let d = &self.data;
        let mut notes = vec![format!(
            "x_jam is where the disc stops; P(jam before x) is the probability that it stops \
             short of x. At the palm's end it is the probability of a jam on the palm at all: \
             {}; past it the disc leaves the palm with probability {}.",
            prob(d.on_palm.probability.value),
            prob(1.0 - d.on_palm.probability.value)
        )];
        notes.push(match d.method {
            DistMethod::Exact => "Exact: x_jam is monotone in the one distributed input, so P is \
                                  its distribution mapped through the closed form (no sampling \
                                  error, no interval to draw)."
                .to_string(),
            DistMethod::MonteCarlo {
                samples,
                seed,
                without_jam,
            } => format!(
                "Monte Carlo of the closed form, {samples} samples (seed {seed}; {without_jam} \
                 never jam): each P has its 95 % interval p ± 1.96 √(p (1 − p) / n), drawn \
                 around the curve."
            ),
        });
        notes
    }
}
