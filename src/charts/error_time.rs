//! The chart of `jamchart accuracy`: error of x_jam against the physical reference, and the
//! integration error, each against the median wall time of one answer (log-log).
//!
//! Wall time differs from machine to machine and run to run, so this chart is drawn from the
//! measured table by `jamchart accuracy --out-dir` and is not a scene: it is kept out of the
//! byte-identity check (`charts/SHA256SUMS`). The counted-cost chart of the integrators is the
//! scene `integration-error` ([`super::work_precision`]).

use plotters::prelude::*;

use super::print::Ink;
use super::style::{self, LineKind, Marker};
use super::xy::{Curve, CurveStyle, Figure, Panel, decade_axis};
use super::{output, scene_subtitle_with};
use crate::error::{Error, Result};
use crate::models::ModelKind;
use crate::scene::SceneParams;
use crate::study::accuracy::{AccuracyReport, AccuracyRow};

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

/// The figure of `report` for `scene`.
pub fn figure(report: &AccuracyReport, scene: &SceneParams) -> Figure {
    let rows = &report.rows;
    let time = |r: &AccuracyRow| r.median_time_s;
    let pts = |f: &dyn Fn(&AccuracyRow) -> bool, y: &dyn Fn(&AccuracyRow) -> Option<f64>| {
        rows.iter()
            .filter(|r| f(r))
            .filter_map(|r| y(r).filter(|v| *v > 0.0).map(|v| (time(r), v)))
            .collect::<Vec<_>>()
    };
    let mut err_curves = vec![
        Curve {
            label: "min-norm by clarabel (tol 1e-2 … 1e-10)".into(),
            style: CurveStyle::LinePoints(LineKind::Dotted, Marker::Triangle),
            points: pts(&|r| r.method == "clarabel", &|r| r.x_rel_error),
        },
        Curve {
            label: "min-norm, exact path".into(),
            style: CurveStyle::Points(Marker::Diamond),
            points: pts(&|r| r.method == "exact", &|r| r.x_rel_error),
        },
    ];
    let mut int_curves = Vec::new();
    let mut keys: Vec<(&str, u64)> = Vec::new();
    for r in rows.iter().filter(|r| r.penetration_um.is_some()) {
        let k = (r.method, r.penetration_um.unwrap_or(0.0).to_bits());
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
        let sel = move |r: &AccuracyRow| {
            r.method == method && r.penetration_um.map(f64::to_bits) == Some(pen)
        };
        err_curves.push(Curve {
            label: label.clone(),
            style: CurveStyle::LinePoints(line, marker),
            points: pts(&sel, &|r| r.x_rel_error),
        });
        int_curves.push(Curve {
            label,
            style: CurveStyle::LinePoints(line, marker),
            points: pts(&sel, &|r| r.integration_error_mm),
        });
    }
    let ns_label = "nonsmooth, rigid contacts (step 0.3 … 0.01 deg)".to_string();
    let ns_style = CurveStyle::LinePoints(LineKind::Dotted, Marker::Plus);
    let ns = |r: &AccuracyRow| r.method == "nonsmooth";
    err_curves.push(Curve {
        label: ns_label.clone(),
        style: ns_style,
        points: pts(&ns, &|r| r.x_rel_error),
    });
    int_curves.push(Curve {
        label: ns_label,
        style: ns_style,
        points: pts(&ns, &|r| r.integration_error_mm),
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
    for r in &report.references {
        notes.push(format!(
            "reference {}: x_jam = {} mm",
            r.kind.as_str(),
            r.x_jam_mm.map_or("-".into(), |x| format!("{x:.6}"))
        ));
    }
    if let Some(s) = rows.iter().find(|r| r.model == ModelKind::Statics) {
        notes.push(format!(
            "statics (the closed form, error 0 by definition): {:.1} us per answer",
            s.median_time_s * 1e6
        ));
    }
    let missing: Vec<String> = rows
        .iter()
        .filter_map(|r| {
            r.reason.as_ref().map(|w| {
                format!(
                    "{} {}{}{}: {}",
                    r.method,
                    r.tolerance.map_or(String::new(), |t| format!("{t:.0e}")),
                    r.step_deg.map_or(String::new(), |h| format!("{h} deg")),
                    r.penetration_um
                        .map_or(String::new(), |p| format!(" {p:.1} um")),
                    w.tag()
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
        title: "Error against run time: x_jam against the physics and against the converged answer"
            .into(),
        subtitle: scene_subtitle_with("every model through the port", scene, &[]),
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

/// The chart as SVG and PNG bytes.
pub fn render(report: &AccuracyReport, scene: &SceneParams) -> Result<(Vec<u8>, Vec<u8>)> {
    style::init_fonts();
    let fig = figure(report, scene);
    let (w, h) = SIZE;
    let err = |m: String| Error::Draw {
        scene: "accuracy (wall time)".into(),
        message: m,
    };
    let svg = output::svg(w, h, 1.0, Ink::Colour, |root| draw_on(&fig, root)).map_err(err)?;
    let png = output::png(w, h, 1.0, Ink::Colour, |root| draw_on(&fig, root)).map_err(err)?;
    Ok((svg, png))
}

fn draw_on<DB: DrawingBackend>(
    fig: &Figure,
    root: &DrawingArea<DB, plotters::coord::Shift>,
) -> std::result::Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    fig.draw(root).map_err(|e| e.to_string())
}
