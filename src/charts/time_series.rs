//! Chart kind `time_series` (Fig. 5): the simulated disc speed x_dot and position x against
//! time, the jam point P_jam marked with t_jam and x_jam, beside the rigid disc touching the
//! turning palm; drawn from [`TimeSeriesData`].

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::picture::Picture;
use super::readoff::{Axis, Fixed, Named, PanelSeries, ParamKey, ReadOffData, Sweep, SweepPanel};
use super::scene_subtitle_with;
use super::style::LineKind;
use super::xy::{Curve, CurveStyle, Figure, LabelSide, Mark, Panel, padded_axis};
use crate::figures::time_series::{Sample, TimeSeriesData, TimeSeriesSettings};
use crate::grid::AxisScale;

/// A time series ready to draw: its data and its two panels.
#[derive(Debug, Clone)]
pub struct TimeSeries {
    data: TimeSeriesData,
    figure: Figure,
}

impl Picture for TimeSeries {
    type Settings = TimeSeriesSettings;

    /// Lays out the two panels.
    fn new(data: TimeSeriesData, title: &str) -> Self {
        let (p, d) = (&data.params, &data.dynamics);
        let samples = &data.samples;
        let t_end = samples.last().map_or(1.0, |s| s.t_s.0);
        let t_axis = PlotAxis::new(0.0, t_end, AxisScale::Linear, "time t (s)");
        let pick = |f: fn(&Sample) -> f64| samples.iter().map(|s| (s.t_s.0, f(s))).collect();
        let ratio = d.jam_reading.jam_speed_ratio;
        let speed_curves = vec![
            Curve {
                label: "simulated disc (speed ẋ, position x)".into(),
                style: CurveStyle::Line(LineKind::Solid),
                points: pick(|s| s.x_dot_mm_s.0),
            },
            Curve {
                label: "rigid disc touching the palm: r·ω/(2·sin²(θ/2)), r·cot(θ/2)".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: pick(|s| s.geometric_speed_mm_s.0),
            },
            Curve {
                label: format!("jam threshold: {ratio} of the rigid disc's speed"),
                style: CurveStyle::Line(LineKind::Dotted),
                points: samples
                    .iter()
                    .map(|s| (s.t_s.0, ratio * s.geometric_speed_mm_s.0))
                    .collect(),
            },
        ];
        // The speed panel shows the motion up to a little above the simulated peak: the rigid
        // disc's speed grows without bound as the palm closes.
        let v_max = samples
            .iter()
            .map(|s| s.x_dot_mm_s.0)
            .fold(0.0_f64, f64::max);
        let mut speed = Panel {
            x: t_axis.clone(),
            y: PlotAxis::new(
                0.0,
                1.35 * v_max.max(1e-9),
                AxisScale::Linear,
                "disc speed ẋ (mm/s)",
            ),
            curves: speed_curves,
            marks: Vec::new(),
            tags: Vec::new(),
        };
        let mut x_curves = vec![
            Curve {
                label: "simulated disc (speed ẋ, position x)".into(),
                style: CurveStyle::Line(LineKind::Solid),
                points: pick(|s| s.x_mm.0),
            },
            Curve {
                label: "rigid disc touching the palm: r·ω/(2·sin²(θ/2)), r·cot(θ/2)".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: pick(|s| s.touching_x_mm.0),
            },
        ];
        let mut x_values: Vec<f64> = samples.iter().map(|s| s.x_mm.0).collect();
        if let Some(xr) = data.x_rigid_mm {
            x_curves.push(Curve {
                label: format!("F → ∞ limit r/μ = {xr:.2} mm (closed form)"),
                style: CurveStyle::Line(LineKind::Level),
                points: vec![(0.0, xr), (t_end, xr)],
            });
            x_values.push(xr);
        }
        let x_top = x_values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mut position = Panel {
            x: t_axis,
            y: padded_axis(
                x_values.into_iter().chain([x_top * 1.12]),
                "disc position x (mm)",
            ),
            curves: x_curves,
            marks: Vec::new(),
            tags: Vec::new(),
        };
        if let Some((tj, xj)) = data.jam {
            let v = interpolate(samples, tj, |s| s.x_dot_mm_s.0);
            // Labels at the left end of the guides, where the motion has not yet risen.
            speed.marks.push(Mark {
                at: (tj, v),
                text: format!("P_jam: t_jam = {tj:.4} s, ẋ = {v:.2} mm/s"),
                side: LabelSide::GuideStart { above: true },
                guides: true,
            });
            position.marks.push(Mark {
                at: (tj, xj),
                text: format!("P_jam: t_jam = {tj:.4} s, x_jam = {xj:.3} mm"),
                side: LabelSide::GuideStart { above: false },
                guides: true,
            });
        }
        let theta = data
            .theta_jam_deg
            .map_or("-".into(), |t| format!("{t:.3}°"));
        let figure = Figure {
            title: title.to_string(),
            subtitle: scene_subtitle_with(
                &format!(
                    "simulation, {} drive at ω = {} deg/s, {} rtol {:e}",
                    d.drive.mode.as_str(),
                    d.drive.omega_deg_s,
                    d.integrator.method.as_str(),
                    d.integrator.rtol
                ),
                p,
                &[],
            ),
            panels: vec![speed, position],
            notes: vec![format!(
                "Status {}: the jam P_jam is read where ẋ falls below {ratio} of the rigid disc's \
                 speed (θ_jam = {theta}); after it the palm squeezes the held disc, which creeps.",
                data.status
            )],
        };
        TimeSeries { data, figure }
    }

    fn data(&self) -> &TimeSeriesData {
        &self.data
    }

    /// The gallery's read-off ([`ReadOffData::Panels`]): at the pointer's time, the
    /// simulated disc's speed, position and palm angle and the rigid disc's speed and
    /// position (straight between samples, as drawn), beside the jam (status, t_jam, x_jam,
    /// theta_jam); names as in the data file.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let [speed, position] = self.figure.panels.as_slice() else {
            return None;
        };
        let [f0, f1] = *frames else { return None };
        let col = |f: fn(&Sample) -> f64| self.data.samples.iter().map(f);
        let column = |f: fn(&Sample) -> f64| col(f).map(Some).collect();
        let panel = |frame, y: &PlotAxis, quantity| SweepPanel {
            frame,
            y: Axis::of(quantity, y),
            quantity,
            x: Axis::of("t_s", &speed.x),
            sweep: 0,
        };
        let (t_jam, x_jam) = self.data.jam.unzip();
        let series = |label: &str, columns| PanelSeries {
            label: label.into(),
            mu: None,
            columns: Named(columns),
        };
        Some(ReadOffData::Panels {
            model: "simulation",
            panels: vec![
                panel(f0, &speed.y, "x_dot_mm_s"),
                panel(f1, &position.y, "x_mm"),
            ],
            sweeps: vec![Sweep {
                param: "t_s",
                at: col(|s| s.t_s.0).collect(),
                fixed: Named(vec![
                    ("status", Fixed::Status(self.data.status)),
                    ("t_jam_s", Fixed::Number(t_jam)),
                    ("x_jam_mm", Fixed::Number(x_jam)),
                    ("theta_jam_deg", Fixed::Number(self.data.theta_jam_deg)),
                ]),
                series: vec![
                    series(
                        "simulated disc",
                        vec![
                            ("x_dot_mm_s", column(|s| s.x_dot_mm_s.0)),
                            ("x_mm", column(|s| s.x_mm.0)),
                            ("theta_deg", column(|s| s.theta_deg.0)),
                        ],
                    ),
                    series(
                        "rigid disc",
                        vec![
                            ("geometric_speed_mm_s", column(|s| s.geometric_speed_mm_s.0)),
                            ("touching_x_mm", column(|s| s.touching_x_mm.0)),
                        ],
                    ),
                ],
                param_key: ParamKey::First,
            }],
        })
    }

    /// Draws the two panels.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

/// `f` interpolated linearly in time at `t` (the nearest end outside the samples).
fn interpolate(samples: &[Sample], t: f64, f: fn(&Sample) -> f64) -> f64 {
    let i = samples.partition_point(|s| s.t_s.0 < t);
    match (
        i.checked_sub(1).and_then(|j| samples.get(j)),
        samples.get(i),
    ) {
        (Some(a), Some(b)) if b.t_s.0 > a.t_s.0 => {
            let w = (t - a.t_s.0) / (b.t_s.0 - a.t_s.0);
            f(a) + w * (f(b) - f(a))
        }
        (Some(a), _) => f(a),
        (None, Some(b)) => f(b),
        (None, None) => 0.0,
    }
}
