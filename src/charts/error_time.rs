//! The chart of `jamchart accuracy`: error of x_jam against the physical reference, and the
//! integration error, each against the median wall time of one answer (log-log).
//!
//! Wall time differs from machine to machine and run to run, so this chart is drawn from the
//! measured table by `jamchart accuracy --out-dir` and is not a scene: it is kept out of the
//! byte-identity check (`charts/SHA256SUMS`). The counted-cost chart of the integrators is the
//! scene `integration-error` ([`super::work_precision`]).
//!
//! Its read-off in the gallery page that `accuracy --out-dir` writes is of kind `points`
//! ([`super::readoff`]): each panel's drawn points (median wall time, error) name their row of
//! `accuracy.csv` ([`ErrorTimeData::rows`]), so the page shows the row of the point nearest
//! the pointer, cell for cell as the file has it.

use plotters::prelude::*;

use super::axes::{PlotFrame, record_frames};
use super::print::Ink;
use super::readoff::{Axis, PointsPanel, ReadOffData, Rows};
use super::style::{self, LineKind, Marker};
use super::xy::{Curve, CurveStyle, Figure, Panel, decade_axis};
use super::{output, scene_subtitle_with};
use crate::error::{Error, Result};
use crate::figures::error_time::{ErrorTimeData, ErrorTimeRow};
use crate::models::ModelKind;

/// The chart's title.
pub const TITLE: &str =
    "Error against run time: x_jam against the physics and against the converged answer";

/// Picture size in px.
const SIZE: (u32, u32) = (1100, 1100);

const MARKERS: [Marker; 6] = [
    Marker::Dot,
    Marker::Square,
    Marker::Circle,
    Marker::Cross,
    Marker::Plus,
    Marker::Diamond,
];

/// The y value of row `r` on the error panel (0) or the integration panel (1), where the
/// figure draws it: the error panel holds the min-norm rows and the simulations, the
/// integration panel the simulations; a zero or missing error is not drawn (log axes).
fn drawn_y(panel: usize, r: &ErrorTimeRow) -> Option<f64> {
    let simulated = r.penetration_um.is_some() || r.method == "nonsmooth";
    let y = match panel {
        0 if simulated || r.method == "clarabel" || r.method == "exact" => r.x_rel_error,
        1 if simulated => r.integration_error_mm,
        _ => None,
    };
    y.map(|v| v.0).filter(|v| *v > 0.0)
}

/// The figure of `data`.
pub fn figure(data: &ErrorTimeData) -> Figure {
    let rows = &data.rows;
    let time = |r: &ErrorTimeRow| r.median_time_s.0;
    let pts = |f: &dyn Fn(&ErrorTimeRow) -> bool, panel: usize| {
        rows.iter()
            .filter(|r| f(r))
            .filter_map(|r| drawn_y(panel, r).map(|v| (time(r), v)))
            .collect::<Vec<_>>()
    };
    let mut err_curves = vec![
        Curve {
            label: "min-norm by clarabel (tol 1e-2 … 1e-10)".into(),
            style: CurveStyle::LinePoints(LineKind::Dotted, Marker::Triangle),
            points: pts(&|r| r.method == "clarabel", 0),
        },
        Curve {
            label: "min-norm, exact path".into(),
            style: CurveStyle::Points(Marker::Diamond),
            points: pts(&|r| r.method == "exact", 0),
        },
    ];
    let mut int_curves = Vec::new();
    let mut keys: Vec<(&str, u64)> = Vec::new();
    for r in rows.iter().filter(|r| r.penetration_um.is_some()) {
        let k = (r.method, r.penetration_um.map_or(0.0, |p| p.0).to_bits());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    let pens: Vec<u64> = {
        let mut v: Vec<u64> = keys.iter().map(|k| k.1).collect();
        v.dedup();
        v.sort_by(|a, b| f64::from_bits(*b).total_cmp(&f64::from_bits(*a)));
        v.dedup();
        v
    };
    for (method, pen) in keys {
        let line = if method == "radau5" {
            LineKind::Solid
        } else {
            LineKind::Dashed
        };
        let i = pens.iter().position(|p| *p == pen).unwrap_or(0);
        let marker = MARKERS[i % MARKERS.len()];
        let label = format!(
            "{method}, contact {:.1} um at F (rtol 1e-2 … 1e-8)",
            f64::from_bits(pen)
        );
        let sel = move |r: &ErrorTimeRow| {
            r.method == method && r.penetration_um.map(|p| p.0.to_bits()) == Some(pen)
        };
        err_curves.push(Curve {
            label: label.clone(),
            style: CurveStyle::LinePoints(line, marker),
            points: pts(&sel, 0),
        });
        int_curves.push(Curve {
            label,
            style: CurveStyle::LinePoints(line, marker),
            points: pts(&sel, 1),
        });
    }
    let ns_label = "nonsmooth, rigid contacts (step 0.3 … 0.01 deg)".to_string();
    let ns_style = CurveStyle::LinePoints(LineKind::Dotted, Marker::Plus);
    let ns = |r: &ErrorTimeRow| r.method == "nonsmooth";
    err_curves.push(Curve {
        label: ns_label.clone(),
        style: ns_style,
        points: pts(&ns, 0),
    });
    int_curves.push(Curve {
        label: ns_label,
        style: ns_style,
        points: pts(&ns, 1),
    });
    err_curves.retain(|c| !c.points.is_empty());
    int_curves.retain(|c| !c.points.is_empty());
    // The closed form (a fraction of a microsecond) is a note, not a point: it would stretch
    // the time axis over three empty decades.
    let all_times = rows
        .iter()
        .filter(|r| r.model != ModelKind::Statics)
        .map(time);
    let panel = |curves: Vec<Curve>, ylabel: &str| Panel {
        x: decade_axis(all_times.clone(), "median wall time of one answer (s)"),
        y: decade_axis(
            curves.iter().flat_map(|c| c.points.iter().map(|p| p.1)),
            ylabel,
        ),
        curves,
        marks: Vec::new(),
        tags: Vec::new(),
    };
    let mut notes = vec![
        "Wall time is measured (median of the runs), so this picture differs between machines \
         and is not hash-checked; the counted-cost chart is the scene 'integration-error'."
            .to_string(),
    ];
    for r in &data.references {
        notes.push(format!(
            "reference {}: x_jam = {} mm",
            r.kind.as_str(),
            r.x_jam_mm.map_or("-".into(), |x| format!("{x:.6}"))
        ));
    }
    if let Some(s) = rows.iter().find(|r| r.model == ModelKind::Statics) {
        notes.push(format!(
            "statics (the closed form, error 0 by definition): {:.1} us per answer",
            s.median_time_s.0 * 1e6
        ));
    }
    let missing: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            r.reason.map(|tag| {
                format!(
                    "{} {}{}{}: {tag}",
                    r.method,
                    r.tolerance
                        .map_or(String::new(), |t| format!("{:.0e}", t.0)),
                    r.step_deg.map_or(String::new(), |h| format!("{} deg", h.0)),
                    r.penetration_um
                        .map_or(String::new(), |p| format!(" {:.1} um", p.0)),
                )
            })
        })
        .collect();
    if !missing.is_empty() {
        notes.push(format!(
            "not drawn ({}): {}",
            missing.len(),
            missing
                .iter()
                .take(8)
                .cloned()
                .collect::<Vec<_>>()
                .join("; ")
        ));
    }
    Figure {
        title: TITLE.into(),
        subtitle: scene_subtitle_with("every model through the port", &data.params, &[]),
        panels: vec![
            panel(
                err_curves,
                "relative error of x_jam against the reference (-)",
            ),
            panel(int_curves, "integration error of x_jam (mm)"),
        ],
        notes,
    }
}

/// The chart as drawn: its pictures and the gallery's read-off.
pub struct Drawn {
    /// The SVG picture.
    pub svg: Vec<u8>,
    /// The PNG picture.
    pub png: Vec<u8>,
    /// The read-off ([`read_off`]) as compact JSON, numbers rounded as every chart's are.
    pub read_off: String,
}

/// The chart of `data` as SVG and PNG, and its read-off from the PNG's frames (both pictures
/// are one drawing at one size).
pub fn render(data: &ErrorTimeData) -> Result<Drawn> {
    style::init_fonts();
    let fig = figure(data);
    let (w, h) = SIZE;
    let err = |m: String| Error::Draw {
        scene: "accuracy (wall time)".into(),
        message: m,
    };
    let svg = output::svg(w, h, 1.0, Ink::Colour, |root| draw_on(&fig, root)).map_err(err)?;
    let (png, frames) =
        record_frames(|| output::png(w, h, 1.0, Ink::Colour, |root| draw_on(&fig, root)));
    Ok(Drawn {
        svg,
        png: png.map_err(err)?,
        read_off: read_off(data, &fig, &frames).to_json(),
    })
}

/// The gallery's read-off ([`ReadOffData::Points`]): in each panel the drawn point nearest
/// the pointer, with its row of `accuracy.csv`. Without a frame per panel (nothing drawn) the
/// panels are empty and the page reads nothing.
pub fn read_off(data: &ErrorTimeData, fig: &Figure, frames: &[PlotFrame]) -> ReadOffData {
    let params = ["x_rel_error", "integration_error_mm"];
    let panels = (fig.panels.iter().zip(frames).enumerate())
        .map(|(k, (p, f))| {
            let points: Vec<_> = (data.rows.iter().enumerate())
                .filter_map(|(i, r)| drawn_y(k, r).map(|y| (r.median_time_s.0, y, i)))
                .collect();
            let x = Axis::of("median_time_s", &p.x);
            PointsPanel::new(*f, x, Axis::of(params[k], &p.y), &points)
        })
        .collect();
    ReadOffData::Points {
        crosshair: true,
        cell: None,
        panels,
        rows: Rows::Accuracy(data.rows.clone()),
    }
}

fn draw_on<DB: DrawingBackend>(
    fig: &Figure,
    root: &DrawingArea<DB, plotters::coord::Shift>,
) -> std::result::Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    fig.draw(root).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{JamStatus, SceneParams};
    use crate::study::ReferenceKind;
    use crate::study::accuracy::{AccuracyReport, AccuracyRow};

    /// A row of `model` and `method` at `time_s` with errors `rel` and `integration_mm`.
    fn row(model: ModelKind, method: &'static str, pen: Option<f64>, at: [f64; 3]) -> AccuracyRow {
        let [time_s, rel, integration_mm] = at;
        AccuracyRow {
            model,
            method,
            tolerance: Some(1e-3),
            penetration_um: pen,
            step_deg: None,
            status: JamStatus::Jams,
            theta_jam_deg: Some(43.6),
            x_jam_mm: Some(25.0),
            reference: ReferenceKind::Rigid,
            reference_status: JamStatus::Jams,
            theta_ref_deg: Some(43.6),
            x_ref_mm: Some(25.0),
            x_error_mm: Some(rel * 25.0),
            x_rel_error: Some(rel),
            theta_error_deg: Some(0.0),
            converged_by: None,
            x_converged_mm: None,
            integration_error_mm: Some(integration_mm),
            median_time_s: time_s,
            runs: 1,
            steps: 1,
            evaluations: 1,
            reason: None,
        }
    }

    /// The page's read-off must name the points the chart draws, no more and no fewer: each
    /// panel's read-off points are exactly the figure's points of that panel (a row the
    /// figure leaves out, the statics at error 0, a zero integration error on a log axis, is
    /// not read), each naming a row with that time and error.
    #[test]
    fn the_read_off_names_exactly_the_drawn_points_and_their_rows() {
        let (s, m, d) = (ModelKind::Statics, ModelKind::MinNorm, ModelKind::Dynamics);
        let report = AccuracyReport {
            references: Vec::new(),
            converged: Vec::new(),
            rows: vec![
                row(s, "closed_form", None, [3e-6, 0.0, 0.0]),
                row(m, "clarabel", None, [1e-4, 1e-7, 0.0]),
                row(m, "exact", None, [2e-4, 1e-9, 0.0]),
                row(d, "radau5", Some(10.0), [1e-3, 1e-3, 1e-5]),
                row(d, "dopri5", Some(1.0), [2e-3, 2e-3, 0.0]),
                row(d, "nonsmooth", None, [3e-3, 3e-4, 1e-6]),
            ],
        };
        let data = ErrorTimeData::of(&report, &SceneParams::default());
        let fig = figure(&data);
        let frame = PlotFrame {
            left: 0.1,
            top: 0.1,
            right: 0.9,
            bottom: 0.4,
        };
        let doc: serde_json::Value =
            serde_json::from_str(&read_off(&data, &fig, &[frame, frame]).to_json()).unwrap();
        let rows = doc["rows"].as_array().unwrap();
        assert_eq!(rows.len(), report.rows.len());
        for (k, panel) in fig.panels.iter().enumerate() {
            let mut drawn: Vec<(f64, f64)> = (panel.curves.iter())
                .flat_map(|c| c.points.clone())
                .collect();
            let mut read: Vec<(f64, f64)> = (doc["panels"][k]["points"].as_array().unwrap())
                .iter()
                .map(|p| {
                    let (x, y, i) = (
                        p[0].as_f64().unwrap(),
                        p[1].as_f64().unwrap(),
                        p[2].as_u64().unwrap(),
                    );
                    let r = &report.rows[i as usize];
                    let want = [r.x_rel_error, r.integration_error_mm][k];
                    assert_eq!((r.median_time_s, want), (x, Some(y)), "panel {k}: {p}");
                    (x, y)
                })
                .collect();
            drawn.sort_by(|a, b| a.0.total_cmp(&b.0));
            read.sort_by(|a, b| a.0.total_cmp(&b.0));
            assert_eq!(read, drawn, "panel {k}");
        }
        assert_eq!(doc["panels"][0]["points"].as_array().unwrap().len(), 5);
        assert_eq!(doc["panels"][1]["points"].as_array().unwrap().len(), 2);
        assert_eq!(rows[3]["median_time_s"], "0.001");
    }
}
