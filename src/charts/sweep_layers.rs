//! The layers a sweep can draw, each turned into [`Series`].
//!
//! To add a model's points (the min-norm solutions, the simulation's jams with motion or force
//! drive): add a variant to [`SweepLayer`], say in [`validate`] which swept parameters it
//! supports, and return its series from [`series`] by calling the model at the points it should
//! be drawn (e.g. the Table 1 mu values). Nothing else changes: panels, legend, data file and
//! hashes follow.

use serde::{Deserialize, Serialize};

use super::style::{LineKind, Marker};
use super::sweep::{Series, SeriesPoint, SeriesStyle, SweepSpec};
use crate::error::{Error, Result};
use crate::grid::{GridParam, PointModel, Statics};
use crate::model::{SceneParams, disc_position_mm};
use crate::paper::{ADAMS_X_JAM_MM_MU_0_4, TABLE1};
use crate::statics;

/// A layer of a sweep (`layers` in `[chart]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepLayer {
    /// The closed-form statics curve.
    Statics,
    /// The F -> infinity limit (a palm driven by motion): theta = atan mu_g + atan mu_p,
    /// x = r cot(theta/2), r/mu for equal frictions; labelled when constant along the sweep.
    RigidLimit,
    /// The paper's Table 1 (both models as printed), the mu = 0.30 erratum marked (mu sweeps).
    PaperTable1,
    /// The paper's Adams result x_jam = 25.58 mm at mu = 0.4 (mu sweeps).
    PaperAdams,
}

/// Checks that `layer` can be drawn on `spec`'s sweep.
pub fn validate(layer: SweepLayer, spec: &SweepSpec) -> Result<()> {
    let paper = matches!(layer, SweepLayer::PaperTable1 | SweepLayer::PaperAdams);
    if paper && spec.axis.param != GridParam::Mu {
        return Err(Error::invalid(
            "chart.layers",
            format!("{layer:?}"),
            "the paper's points are printed against mu: use them on a sweep of param = \"mu\"",
        ));
    }
    Ok(())
}

/// The series of `layer` over `spec`'s axis with base scene `p`.
pub fn series(layer: SweepLayer, spec: &SweepSpec, p: &SceneParams) -> Vec<Series> {
    let param = spec.axis.param;
    let at = |v: f64| param.apply(*p, v);
    match layer {
        SweepLayer::Statics => vec![Series {
            layer: "statics",
            label: "closed-form statics (corrected Eq. 1)".into(),
            style: SeriesStyle::Line(LineKind::Solid),
            points: spec
                .axis
                .values()
                .into_iter()
                .map(|v| {
                    let j = Statics.jam_point(&at(v));
                    point(v, j.x_jam_mm, j.theta_jam_deg)
                })
                .collect(),
            flat_names: Some(["x_jam", "θ_jam"]),
            callout: None,
        }],
        SweepLayer::RigidLimit => {
            let points: Vec<SeriesPoint> = spec
                .axis
                .values()
                .into_iter()
                .map(|v| {
                    let s = statics::solve(&at(v));
                    point(v, s.x_rigid_mm, Some(s.theta_rigid_deg))
                })
                .collect();
            vec![Series {
                layer: "rigid_limit",
                label: "F → ∞ limit (palm driven by motion): x = r/μ, θ = 2·atan μ".into(),
                style: SeriesStyle::Line(LineKind::Dashed),
                points,
                flat_names: Some(["threshold r/μ", "threshold 2·atan μ"]),
                callout: None,
            }]
        }
        SweepLayer::PaperTable1 => table1(),
        SweepLayer::PaperAdams => vec![Series {
            layer: "paper_adams",
            label: format!(
                "paper's Adams simulation: x_jam = {ADAMS_X_JAM_MM_MU_0_4} mm at μ = 0.4"
            ),
            style: SeriesStyle::Points(Marker::Square),
            // The paper prints x only; its theta would be 2 atan(r/x), not a printed number.
            points: vec![point(0.4, Some(ADAMS_X_JAM_MM_MU_0_4), None)],
            flat_names: None,
            callout: Some(format!("Adams {ADAMS_X_JAM_MM_MU_0_4} mm")),
        }],
    }
}

fn point(at: f64, x_jam_mm: Option<f64>, theta_jam_deg: Option<f64>) -> SeriesPoint {
    SeriesPoint {
        at,
        x_jam_mm,
        theta_jam_deg,
    }
}

/// Table 1 as printed: force analysis (circles), minimum norm (triangles), and the x values of
/// the erratum row as crosses (its theta values are consistent and stay in the main sets).
fn table1() -> Vec<Series> {
    let (mut force, mut min_norm, mut erratum) = (Vec::new(), Vec::new(), Vec::new());
    for row in TABLE1 {
        let bad = row.erratum.is_some();
        let keep_x = |x: f64| (!bad).then_some(x);
        force.push(point(
            row.mu,
            keep_x(row.statics_x_jam_mm),
            Some(row.statics_theta_jam_deg),
        ));
        min_norm.push(point(
            row.mu,
            keep_x(row.min_norm_x_jam_mm),
            Some(row.min_norm_theta_jam_deg),
        ));
        if bad {
            erratum.push(point(row.mu, Some(row.statics_x_jam_mm), None));
        }
    }
    let mut out = vec![
        Series {
            layer: "paper_table1_force_analysis",
            label: "paper Table 1, force analysis".into(),
            style: SeriesStyle::Points(Marker::Circle),
            points: force,
            flat_names: None,
            callout: None,
        },
        Series {
            layer: "paper_table1_min_norm",
            label: "paper Table 1, minimum norm".into(),
            style: SeriesStyle::Points(Marker::Triangle),
            points: min_norm,
            flat_names: None,
            callout: None,
        },
    ];
    if let Some(e) = erratum.first().cloned() {
        let theta = TABLE1
            .iter()
            .find(|r| r.erratum.is_some())
            .map_or(0.0, |r| r.statics_theta_jam_deg);
        // Table 1 is for the paper's r = 10 mm.
        let consistent = disc_position_mm(10.0, theta.to_radians());
        out.push(Series {
            layer: "paper_table1_erratum",
            label: format!(
                "Table 1 erratum at μ = {:.2}: x = {:.2} mm printed, r·cot({theta}°/2) = {consistent:.2} mm",
                e.at,
                e.x_jam_mm.unwrap_or(0.0)
            ),
            style: SeriesStyle::Points(Marker::Cross),
            points: erratum,
            flat_names: None,
            callout: Some(format!("erratum: printed {:.2} mm, consistent {consistent:.2} mm", e.x_jam_mm.unwrap_or(0.0))),
        });
    }
    out
}
