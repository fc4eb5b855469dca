//! Chart kind `work_precision` (scene `accuracy`): the dynamics' integrators as integration
//! error of x_jam against counted cost, and the min-norm program's tolerance against its error
//! in theta_jam, drawn from [`WorkPrecisionData`]. The chart says which error it draws and
//! notes the floor of the physical reference, which no tolerance gets under.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axes::{DrawResult, PlotFrame};
use super::convergence::sci;
use super::picture::Picture;
use super::readoff::{Axis, PointsPanel, ReadOffData, Rows};
use super::scene_subtitle_with;
use super::style::{LineKind, Marker};
use super::xy::{Curve, CurveStyle, Figure, Panel, Tag, decade_axis};
use crate::dynamics::Method;
use crate::figures::work_precision::{
    Cost, PrecisionRow, Study, WorkPrecisionData, WorkPrecisionSettings,
};

/// The studies ready to draw: their data and panels.
#[derive(Debug, Clone)]
pub struct WorkPrecision {
    data: WorkPrecisionData,
    figure: Figure,
}

/// The integrators' rows of `data`.
fn integrators(data: &WorkPrecisionData) -> impl Iterator<Item = &PrecisionRow> {
    data.rows.iter().filter(|r| r.study == Study::Integrator)
}

/// The min-norm program's rows of `data`.
fn programs(data: &WorkPrecisionData) -> impl Iterator<Item = &PrecisionRow> {
    data.rows.iter().filter(|r| r.study == Study::MinNorm)
}

impl Picture for WorkPrecision {
    type Settings = WorkPrecisionSettings;

    /// Lays out the panels: the integrators', and the min-norm program's when it has rows.
    fn new(data: WorkPrecisionData, title: &str) -> Self {
        let (p, d, spec) = (&data.params, &data.dynamics, &data.settings);
        let cost = |r: &PrecisionRow| spec.cost.of(r).unwrap_or_default();
        let rel_error = |r: &PrecisionRow| r.rel_error.map(|e| e.0);
        let cost_label = match spec.cost {
            Cost::RhsEvals => "cost: right-hand-side evaluations of one run (-)",
            Cost::Steps => "cost: accepted steps of one run (-)",
        };
        let of = |m: Method| integrators(&data).filter(move |r| r.method == m.as_str());
        let method_curve = |m: Method, line: LineKind, marker: Marker| Curve {
            label: format!(
                "{} (rtol = atol = {} … {})",
                m.as_str(),
                sci_first(&spec.tolerances),
                sci_last(&spec.tolerances)
            ),
            style: CurveStyle::LinePoints(line, marker),
            points: of(m)
                .filter_map(|r| rel_error(r).map(|e| (cost(r), e)))
                .collect(),
        };
        let curves = vec![
            method_curve(Method::Radau5, LineKind::Family(0), Marker::Dot),
            method_curve(Method::Dopri5, LineKind::Family(1), Marker::Square),
        ];
        // The loosest and tightest run of each method named by its tolerance.
        let mut tags = Vec::new();
        for m in [Method::Radau5, Method::Dopri5] {
            let drawn: Vec<&PrecisionRow> = of(m)
                .filter(|r| rel_error(r).is_some_and(|e| e > 0.0))
                .collect();
            let ends = [drawn.first(), drawn.last()];
            for (i, r) in ends.into_iter().flatten().enumerate() {
                tags.push(Tag {
                    at: (cost(r), rel_error(r).unwrap_or(1.0)),
                    text: format!("rtol {}", sci(r.tol.0)),
                    left: m == Method::Radau5 && i == 0,
                });
            }
        }
        let integrator_panel = Panel {
            x: decade_axis(integrators(&data).map(cost), cost_label),
            y: decade_axis(
                curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)),
                "integration error of x_jam, relative (-)",
            ),
            curves,
            marks: Vec::new(),
            tags,
        };
        let mut panels = vec![integrator_panel];
        if programs(&data).next().is_some() {
            let floor_deg = data.min_norm.bisection_tol_rad.to_degrees();
            let pts: Vec<(f64, f64)> = programs(&data)
                .filter_map(|r| r.error_deg.map(|e| (r.tol.0, e.0)))
                .collect();
            let tol_axis = decade_axis(
                programs(&data).map(|r| r.tol.0),
                "clarabel tolerance tol_feas = tol_gap = tol_infeas (-)",
            );
            let floor = Curve {
                label: format!(
                    "bisection width {} rad = {} deg (the search's resolution)",
                    sci(data.min_norm.bisection_tol_rad),
                    sci(floor_deg)
                ),
                style: CurveStyle::Line(LineKind::Dotted),
                points: vec![(tol_axis.min, floor_deg), (tol_axis.max, floor_deg)],
            };
            panels.push(Panel {
                y: decade_axis(
                    pts.iter().map(|p| p.1).chain([floor_deg]),
                    "error of min-norm θ_jam (deg)",
                ),
                x: tol_axis,
                curves: vec![
                    Curve {
                        label: "min-norm by clarabel vs closed form (translational)".into(),
                        // Its own dots, not radau5's black solid line.
                        style: CurveStyle::LinePoints(LineKind::Family(2), Marker::Triangle),
                        points: pts,
                    },
                    floor,
                ],
                marks: Vec::new(),
                tags: Vec::new(),
            });
        }
        let mut notes = vec![
            "Cost is counted, not timed, so the picture is the same on every machine; \
             jamchart accuracy reports median wall times."
                .to_string(),
        ];
        let physical = &data.physical;
        for r in &data.references {
            let off = match (r.x_jam_mm, physical.x_jam_mm) {
                (Some(x), Some(xp)) => format!(
                    ", {:.2} % from the physics ({} x_jam = {xp:.3} mm): the model's floor, \
                     which no tolerance gets under",
                    100.0 * (x - xp).abs() / xp,
                    physical.kind.as_str()
                ),
                _ => String::new(),
            };
            notes.push(format!(
                "reference {} at rtol {}: {} x_jam = {} mm{off}",
                r.method.as_str(),
                sci(r.rtol),
                r.status,
                r.x_jam_mm.map_or("-".into(), |x| format!("{x:.6}"))
            ));
        }
        for r in integrators(&data).filter(|r| r.rel_error.is_none()) {
            notes.push(format!(
                "not drawn: {} at rtol {}: {}",
                r.method,
                sci(r.tol.0),
                r.reason.as_deref().unwrap_or("no error")
            ));
        }
        for r in programs(&data).filter(|r| r.error_deg.is_none()) {
            notes.push(format!(
                "not drawn: min-norm at tol {}: {}",
                sci(r.tol.0),
                r.status
            ));
        }
        let figure = Figure {
            title: title.to_string(),
            subtitle: scene_subtitle_with(
                &format!(
                    "simulation, {} drive, against the other integrator at rtol {}",
                    d.drive.mode.as_str(),
                    sci(spec.reference_rtol)
                ),
                p,
                &[],
            ),
            panels,
            notes,
        };
        WorkPrecision { data, figure }
    }

    fn data(&self) -> &WorkPrecisionData {
        &self.data
    }

    /// The gallery's read-off ([`ReadOffData::Points`]): the run nearest the pointer, an
    /// integrator's (cost, error) or the min-norm program's (tolerance, error), with its row of
    /// the data file. Runs that are not drawn (no error) are not read.
    fn read_off(&self, frames: &[PlotFrame]) -> Option<ReadOffData> {
        let panels = &self.figure.panels;
        if frames.len() != panels.len() || panels.is_empty() {
            return None;
        }
        let cost = self.data.settings.cost;
        let rows = self.data.rows.iter().enumerate();
        let runs: Vec<_> = (rows.clone().filter(|(_, r)| r.study == Study::Integrator))
            .filter_map(|(i, r)| Some((cost.of(r)?, r.rel_error?.0, i)))
            .collect();
        let tolerances: Vec<_> = (rows.filter(|(_, r)| r.study == Study::MinNorm))
            .filter_map(|(i, r)| r.error_deg.map(|e| (r.tol.0, e.0, i)))
            .collect();
        let keys = [
            (cost.key(), "rel_error", runs),
            ("tol", "error_deg", tolerances),
        ];
        let read_off_panels = (panels.iter().zip(frames).zip(keys))
            .map(|((p, f), (x, y, points))| {
                PointsPanel::new(*f, Axis::of(x, &p.x), Axis::of(y, &p.y), &points)
            })
            .collect();
        Some(ReadOffData::Points {
            crosshair: true,
            cell: None,
            panels: read_off_panels,
            rows: Rows::Precision(self.data.rows.clone()),
        })
    }

    /// Draws the panels.
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> DrawResult<DB> {
        self.figure.draw(root)
    }
}

fn sci_first(v: &[f64]) -> String {
    v.iter().copied().reduce(f64::max).map_or("-".into(), sci)
}

fn sci_last(v: &[f64]) -> String {
    v.iter().copied().reduce(f64::min).map_or("-".into(), sci)
}
