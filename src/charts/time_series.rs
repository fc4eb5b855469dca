//! Chart kind `time_series` (Fig. 5): the simulated disc speed x_dot and position x against
//! time, the jam point P_jam marked with t_jam and x_jam.
//!
//! One simulation ([`crate::dynamics::simulate`]) with the scene's `[dynamics]` settings records
//! the series every `series_dt_s`; set `after_jam_s` in the scene's `[dynamics.series]` so the collapse
//! after the jam is visible. Beside the motion: the speed a rigid disc touching the turning palm
//! would have, r omega / (2 sin^2(theta/2)) (the jam is read where x_dot falls below
//! `jam_speed_ratio` of it), and that disc's position r cot(theta/2).

use plotters::coord::Shift;
use plotters::prelude::*;
use serde::{Deserialize, Serialize};

use super::axes::{DrawResult, PlotAxis, PlotFrame};
use super::spec::Scene;
use super::style::LineKind;
use super::xy::{Curve, CurveStyle, Figure, LabelSide, Mark, Panel, padded_axis};
use super::{DataFile, readoff, scene_subtitle_with};
use crate::csv_out::{Dec, to_csv};
use crate::dynamics::DynamicsParams;
use crate::dynamics::jam::SeriesRow;
use crate::dynamics::system::System;
use crate::error::{Error, Result};
use crate::figures::models::Models;
use crate::grid::AxisScale;
use crate::models::{Detail, ModelSpec};
use crate::scene::{JamStatus, SceneParams};
use crate::statics;

/// `[chart]` keys of `kind = "time_series"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct TimeSeriesSpec {
    /// Sampling interval of the drawn series in s, in [1e-5, 0.1] (default: 0.001; the collapse
    /// at the jam takes a few ms, a pixel of the time axis about 2 ms).
    pub series_dt_s: f64,
}

impl Default for TimeSeriesSpec {
    fn default() -> Self {
        TimeSeriesSpec { series_dt_s: 0.001 }
    }
}

impl super::kinds::Kind for TimeSeriesSpec {
    type Chart = TimeSeries;

    /// Checks the sampling interval.
    fn validate(&self, _scene: &Scene) -> Result<()> {
        let dt = self.series_dt_s;
        // Below 1e-5 s a default run records over 150 000 rows for nothing a picture shows.
        if !(dt.is_finite() && (1e-5..=0.1).contains(&dt)) {
            return Err(Error::invalid(
                "chart.series_dt_s",
                dt,
                "the sampling interval lies in [1e-5, 0.1] s",
            ));
        }
        Ok(())
    }

    fn check_size(&self, scene: &Scene) -> Result<()> {
        let rows = crate::limits::series_rows(
            scene.params.start_angle_deg,
            scene.dynamics.drive.omega_deg_s,
            self.series_dt_s,
        );
        crate::limits::check_items(
            "chart.series_dt_s and dynamics.drive.omega_deg_s",
            rows,
            crate::limits::SERIES_ROW,
        )
    }

    fn compute(
        &self,
        scene: &Scene,
        models: &dyn crate::figures::models::Models,
    ) -> Result<TimeSeries> {
        TimeSeries::compute(scene, self, models)
    }
}

/// One drawn sample: the simulated row and the rigid-disc references at its palm angle.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Sample {
    row: SeriesRow,
    geometric_speed_mm_s: f64,
    touching_x_mm: f64,
}

/// One sample of the simulated time series as CSV: the same columns for `render` (Fig. 5) and
/// `solve --series`.
#[derive(Debug, Serialize)]
struct SeriesCsvRow {
    t_s: Dec,
    theta_deg: Dec,
    x_mm: Dec,
    x_dot_mm_s: Dec,
    geometric_speed_mm_s: Dec,
    touching_x_mm: Dec,
    penetration_mm: Dec,
    normal_n: Dec,
    palm_friction_n: Dec,
    ground_normal_n: Dec,
    ground_friction_n: Dec,
}

impl From<&Sample> for SeriesCsvRow {
    fn from(s: &Sample) -> Self {
        let r = &s.row;
        SeriesCsvRow {
            t_s: Dec(r.t_s),
            theta_deg: Dec(r.theta_deg),
            x_mm: Dec(r.x_mm),
            x_dot_mm_s: Dec(r.x_dot_mm_s),
            geometric_speed_mm_s: Dec(s.geometric_speed_mm_s),
            touching_x_mm: Dec(s.touching_x_mm),
            penetration_mm: Dec(r.penetration_mm),
            normal_n: Dec(r.normal_n),
            palm_friction_n: Dec(r.palm_friction_n),
            ground_normal_n: Dec(r.ground_normal_n),
            ground_friction_n: Dec(r.ground_friction_n),
        }
    }
}

/// The samples of `rows` with the palm's geometric speed and touching position of scene `p`.
fn samples(p: &SceneParams, d: &DynamicsParams, rows: &[SeriesRow]) -> Vec<Sample> {
    let sys = System::new(p, d);
    rows.iter()
        .map(|r| {
            let th = r.theta_deg.to_radians();
            Sample {
                row: *r,
                geometric_speed_mm_s: sys.geometric_speed(th),
                touching_x_mm: sys.touching_x(th),
            }
        })
        .collect()
}

/// The time series `rows` of scene `p` as CSV, one row per sample, units in the header.
pub fn series_csv(p: &SceneParams, d: &DynamicsParams, rows: &[SeriesRow]) -> Vec<u8> {
    to_csv(samples(p, d, rows).iter().map(SeriesCsvRow::from))
}

/// The computed time series.
#[derive(Debug, Clone)]
pub struct TimeSeries {
    figure: Figure,
    samples: Vec<Sample>,
    /// The marked jam (t_jam in s, x_jam in mm), if the simulation jams.
    jam: Option<(f64, f64)>,
    /// The simulation's status and theta_jam (deg), for the read-off.
    status: JamStatus,
    theta_jam_deg: Option<f64>,
}

impl TimeSeries {
    /// Runs the simulation and lays out the two panels.
    pub fn compute(scene: &Scene, spec: &TimeSeriesSpec, models: &dyn Models) -> Result<Self> {
        let (p, d) = (&scene.params, &scene.dynamics);
        let spec = ModelSpec::Dynamics {
            params: *d,
            series_dt_s: Some(spec.series_dt_s),
        };
        let sol = models.solve(&spec, p)?;
        let failed = |reason: String| Error::ModelFailed {
            scene: scene.name.clone(),
            model: "simulation",
            reason,
        };
        let Detail::Dynamics(sol) = sol.detail else {
            return Err(failed(format!("it cannot run this scene ({})", sol.status)));
        };
        // A failed run would be drawn as empty panels: the render fails instead, saying why.
        if let Some(f) = &sol.failure {
            return Err(failed(format!("the integrator gave up: {f}")));
        }
        if sol.series.len() < 2 {
            return Err(failed(format!(
                "it recorded {} samples (status {})",
                sol.series.len(),
                sol.status
            )));
        }
        let samples = samples(p, d, &sol.series);
        let t_end = samples.last().map_or(1.0, |s| s.row.t_s);
        let t_axis = PlotAxis::new(0.0, t_end, AxisScale::Linear, "time t (s)");
        let pick = |f: fn(&Sample) -> f64| samples.iter().map(|s| (s.row.t_s, f(s))).collect();
        let ratio = d.jam_reading.jam_speed_ratio;
        let speed_curves = vec![
            Curve {
                label: "simulated disc (speed ẋ, position x)".into(),
                style: CurveStyle::Line(LineKind::Solid),
                points: pick(|s| s.row.x_dot_mm_s),
            },
            Curve {
                label: "rigid disc touching the palm: r·ω/(2·sin²(θ/2)), r·cot(θ/2)".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: pick(|s| s.geometric_speed_mm_s),
            },
            Curve {
                label: format!("jam threshold: {ratio} of the rigid disc's speed"),
                style: CurveStyle::Line(LineKind::Dotted),
                points: samples
                    .iter()
                    .map(|s| (s.row.t_s, ratio * s.geometric_speed_mm_s))
                    .collect(),
            },
        ];
        // The speed panel shows the motion up to a little above the simulated peak: the rigid
        // disc's speed grows without bound as the palm closes.
        let v_max = samples
            .iter()
            .map(|s| s.row.x_dot_mm_s)
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
        let rigid = statics::solve(p).x_rigid_mm;
        let mut x_curves = vec![
            Curve {
                label: "simulated disc (speed ẋ, position x)".into(),
                style: CurveStyle::Line(LineKind::Solid),
                points: pick(|s| s.row.x_mm),
            },
            Curve {
                label: "rigid disc touching the palm: r·ω/(2·sin²(θ/2)), r·cot(θ/2)".into(),
                style: CurveStyle::Line(LineKind::Dashed),
                points: pick(|s| s.touching_x_mm),
            },
        ];
        let mut x_values: Vec<f64> = samples.iter().map(|s| s.row.x_mm).collect();
        if let Some(xr) = rigid.filter(|x| x.is_finite()) {
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
        if let (Some(tj), Some(xj)) = (sol.t_jam_s, sol.x_jam_mm) {
            let v = interpolate(&samples, tj, |s| s.row.x_dot_mm_s);
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
        let theta = sol.theta_jam_deg.map_or("-".into(), |t| format!("{t:.3}°"));
        let figure = Figure {
            title: scene.title.clone(),
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
                sol.status
            )],
        };
        Ok(TimeSeries {
            figure,
            samples,
            jam: sol.t_jam_s.zip(sol.x_jam_mm),
            status: sol.status,
            theta_jam_deg: sol.theta_jam_deg,
        })
    }

    /// The marked jam point (t_jam in s, x_jam in mm), if the simulation jams.
    #[cfg(test)]
    pub fn jam(&self) -> Option<(f64, f64)> {
        self.jam
    }

    /// The series as CSV, with the rigid-disc references.
    pub fn data_file(&self, _scene: &Scene) -> DataFile {
        DataFile::csv(to_csv(self.samples.iter().map(SeriesCsvRow::from)))
    }

    /// The gallery's read-off ([`readoff`], kind `panels`): at the pointer's time, the
    /// simulated disc's speed, position and palm angle and the rigid disc's speed and
    /// position (straight between samples, as drawn), beside the jam (status, t_jam, x_jam,
    /// theta_jam); names as in the data file.
    pub fn read_off(&self, frames: &[PlotFrame]) -> Option<serde_json::Value> {
        let [speed, position] = self.figure.panels.as_slice() else {
            return None;
        };
        let [f0, f1] = frames else { return None };
        let col = |f: fn(&Sample) -> f64| readoff::column(self.samples.iter().map(f));
        let x = readoff::axis("t_s", &speed.x);
        let (t_jam, x_jam) = self.jam.unzip();
        Some(serde_json::json!({
            "kind": "panels",
            "model": "simulation",
            "panels": [
                readoff::sweep_panel(f0, x.clone(), readoff::axis("x_dot_mm_s", &speed.y), "x_dot_mm_s", 0),
                readoff::sweep_panel(f1, x, readoff::axis("x_mm", &position.y), "x_mm", 0),
            ],
            "sweeps": [{
                "param": "t_s",
                "at": col(|s| s.row.t_s),
                "fixed": {
                    "status": self.status,
                    "t_jam_s": t_jam,
                    "x_jam_mm": x_jam,
                    "theta_jam_deg": self.theta_jam_deg,
                },
                "series": [
                    {
                        "label": "simulated disc",
                        "x_dot_mm_s": col(|s| s.row.x_dot_mm_s),
                        "x_mm": col(|s| s.row.x_mm),
                        "theta_deg": col(|s| s.row.theta_deg),
                    },
                    {
                        "label": "rigid disc",
                        "geometric_speed_mm_s": col(|s| s.geometric_speed_mm_s),
                        "touching_x_mm": col(|s| s.touching_x_mm),
                    },
                ],
            }],
        }))
    }

    /// Draws the two panels.
    pub fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

/// `f` interpolated linearly in time at `t` (the nearest end outside the samples).
fn interpolate(samples: &[Sample], t: f64, f: fn(&Sample) -> f64) -> f64 {
    let i = samples.partition_point(|s| s.row.t_s < t);
    match (
        i.checked_sub(1).and_then(|j| samples.get(j)),
        samples.get(i),
    ) {
        (Some(a), Some(b)) if b.row.t_s > a.row.t_s => {
            let w = (t - a.row.t_s) / (b.row.t_s - a.row.t_s);
            f(a) + w * (f(b) - f(a))
        }
        (Some(a), _) => f(a),
        (None, Some(b)) => f(b),
        (None, None) => 0.0,
    }
}
