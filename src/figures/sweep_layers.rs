//! The layers a sweep can draw, each turned into [`Series`] of [`SeriesPoint`]s, and the
//! panels ([`SweepPanel`]) that plot one quantity of every series.
//!
//! To add a model's points: add a variant to [`SweepLayer`], say in [`validate`] which swept
//! parameters it supports, and return its series from [`series`] by calling the model (through
//! `Models`) at the points it should be drawn, a [`Curve`] naming them; the chart gives the
//! curve its line or marker.
//!
//! The min-norm points sit at the Table 1 mu values, beside the paper's; the simulation points
//! sit halfway between them ([`SIMULATION_MU`]), so that no marker hides another (at
//! mu = 0.4 the paper's two values, ours and a simulation's would lie within 3 px).

use serde::{Deserialize, Serialize};

use super::Input;
use super::models::Models;
use crate::dynamics::{Drive, DynamicsParams};
use crate::error::{Error, Result};
use crate::grid::{self, GridAxis};
use crate::minnorm::{Formulation, MinNormSettings};
use crate::models::{self, Detail, ModelSpec, Solution};
use crate::paper::{ADAMS_X_JAM_MM_MU_0_4, TABLE1};
use crate::scene::Param;
use crate::scene::{JamStatus, disc_position_mm};
use crate::study::{self, Why};

/// The mu values of the simulation points: halfway between Table 1's 0.15, 0.20, ..., 0.45.
pub const SIMULATION_MU: [f64; 6] = [0.175, 0.225, 0.275, 0.325, 0.375, 0.425];

/// A layer of a sweep (`layers` in `[chart]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepLayer {
    /// The closed-form statics curve.
    Statics,
    /// The F -> infinity limit (a palm driven by motion): theta = atan mu_g + atan mu_p,
    /// x = r cot(theta/2), r/mu for equal frictions (the statics' `theta_rigid_deg`,
    /// `x_rigid_mm`); labelled when constant along the sweep. `rigid_limit` is read as `rigid`
    /// (its name before).
    #[serde(alias = "rigid_limit")]
    Rigid,
    /// The paper's Table 1 (both models as printed), the mu = 0.30 erratum marked (mu sweeps).
    PaperTable1,
    /// The paper's Adams result x_jam = 25.58 mm at mu = 0.4 (mu sweeps).
    PaperAdams,
    /// Min-norm jam points, translational formulation (the paper's), at the Table 1 mu values
    /// (mu sweeps).
    MinNorm,
    /// Min-norm jam points, rolling formulation, at the Table 1 mu values (mu sweeps); for equal
    /// frictions they lie on the F -> infinity limit.
    MinNormRolling,
    /// Simulated jams, motion drive, at [`SIMULATION_MU`] (mu sweeps).
    SimulationMotion,
    /// Simulated jams, force drive saturating at the scene's F, at [`SIMULATION_MU`] (mu sweeps).
    SimulationForce,
}

/// A quantity plotted in one panel of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepPanel {
    /// x_jam in mm.
    XJamMm,
    /// theta_jam in deg.
    ThetaJamDeg,
}

impl SweepPanel {
    /// The quantity's name in the data (`x_jam_mm`, `theta_jam_deg`).
    pub fn key(self) -> &'static str {
        match self {
            SweepPanel::XJamMm => "x_jam_mm",
            SweepPanel::ThetaJamDeg => "theta_jam_deg",
        }
    }

    /// The quantity at point `p`.
    pub fn value(self, p: &SeriesPoint) -> Option<f64> {
        match self {
            SweepPanel::XJamMm => p.x_jam_mm,
            SweepPanel::ThetaJamDeg => p.theta_jam_deg,
        }
    }
}

/// Which curve or point set a series is: its layer's name in the data file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Curve {
    /// The closed-form statics.
    Statics,
    /// The F -> infinity limit.
    Rigid,
    /// Table 1's force analysis, as printed.
    PaperTable1ForceAnalysis,
    /// Table 1's minimum norm, as printed.
    PaperTable1MinNorm,
    /// Table 1's erratum row (its x as printed).
    PaperTable1Erratum,
    /// The paper's Adams result.
    PaperAdams,
    /// Min-norm jam points, translational joint.
    MinNorm,
    /// Min-norm jam points, a rolling disc.
    MinNormRolling,
    /// Simulated jams, motion drive.
    SimulationMotion,
    /// Simulated jams, force drive.
    SimulationForce,
    /// A band's earliest-jam edge.
    BandEarliest,
    /// A band's latest-jam edge.
    BandLatest,
}

impl Curve {
    /// The layer's name in the data file (`statics`, `paper_adams`, ...).
    pub fn name(self) -> &'static str {
        match self {
            Curve::Statics => "statics",
            Curve::Rigid => "rigid",
            Curve::PaperTable1ForceAnalysis => "paper_table1_force_analysis",
            Curve::PaperTable1MinNorm => "paper_table1_min_norm",
            Curve::PaperTable1Erratum => "paper_table1_erratum",
            Curve::PaperAdams => "paper_adams",
            Curve::MinNorm => "min_norm",
            Curve::MinNormRolling => "min_norm_rolling",
            Curve::SimulationMotion => "simulation_motion",
            Curve::SimulationForce => "simulation_force",
            Curve::BandEarliest => "band_earliest",
            Curve::BandLatest => "band_latest",
        }
    }

    /// Whether it is a curve through its points (else a point set).
    pub fn is_line(self) -> bool {
        matches!(
            self,
            Curve::Statics | Curve::Rigid | Curve::BandEarliest | Curve::BandLatest
        )
    }

    /// Whether it is the paper's own numbers.
    pub fn is_paper(self) -> bool {
        self.name().starts_with("paper_")
    }
}

/// One point of a series: the swept value and the quantities (None where not given).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeriesPoint {
    /// The swept parameter's value.
    pub at: f64,
    /// x_jam in mm.
    pub x_jam_mm: Option<f64>,
    /// theta_jam in deg.
    pub theta_jam_deg: Option<f64>,
    /// The model's verdict at the point (None for a limit or a printed number).
    pub status: Option<JamStatus>,
    /// x_jam in mm on a long enough palm where the closed form's jam lies past this palm's end
    /// (`beyond_reach`, where `x_jam_mm` is empty: no jam on this palm); None otherwise.
    pub past_palm_x_jam_mm: Option<f64>,
}

/// A curve or point set of one layer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    /// Which curve it is.
    pub curve: Curve,
    /// What it shows, for a legend.
    pub label: String,
    /// The points, in order of the swept value.
    pub points: Vec<SeriesPoint>,
    /// Names of a curve's value in the x_jam and theta_jam panels, for a curve that is flat
    /// in a panel (thresholds, constants).
    pub flat_names: Option<[&'static str; 2]>,
    /// A note about its first point (e.g. what is wrong with it).
    pub callout: Option<String>,
}

/// Checks that `layer` can be drawn on a sweep along `axis`.
pub fn validate(layer: SweepLayer, axis: &GridAxis) -> Result<()> {
    let at_mu = !matches!(layer, SweepLayer::Statics | SweepLayer::Rigid);
    if at_mu && axis.param != Param::Mu {
        return Err(Error::invalid(
            "chart.layers",
            format!("{layer:?}"),
            "the paper's points and the model points sit at the paper's mu values: use them on \
             a sweep of param = \"mu\"",
        ));
    }
    Ok(())
}

/// The series of `layer` along `axis` for `scene`, its model points computed by `models`.
pub fn series(
    layer: SweepLayer,
    axis: &GridAxis,
    scene: &Input,
    models: &dyn Models,
) -> Result<Vec<Series>> {
    Ok(match layer {
        SweepLayer::Statics => vec![Series {
            curve: Curve::Statics,
            label: "closed-form statics (corrected Eq. 1)".into(),
            points: closed_form(axis, scene, |v, s| closed_form_point(v, &s))?,
            flat_names: Some(["x_jam", "θ_jam"]),
            callout: None,
        }],
        SweepLayer::Rigid => {
            let points = closed_form(axis, scene, |v, s| SeriesPoint {
                // The closed form's verdict at the point: why a row is empty.
                status: Some(s.status),
                ..match s.detail {
                    Detail::Statics(s) => point(v, s.x_rigid_mm, Some(s.theta_rigid_deg)),
                    _ => point(v, None, None),
                }
            })?;
            vec![Series {
                curve: Curve::Rigid,
                label: "F → ∞ limit (palm driven by motion): x = r/μ, θ = 2·atan μ".into(),
                points,
                flat_names: Some(["threshold r/μ", "threshold 2·atan μ"]),
                callout: None,
            }]
        }
        SweepLayer::PaperTable1 => table1(),
        SweepLayer::PaperAdams => vec![Series {
            curve: Curve::PaperAdams,
            label: format!("Adams simulation: x_jam = {ADAMS_X_JAM_MM_MU_0_4} mm at μ = 0.4"),
            // The paper prints x only; its theta would be 2 atan(r/x), not a printed number.
            points: vec![point(0.4, Some(ADAMS_X_JAM_MM_MU_0_4), None)],
            flat_names: None,
            callout: Some(format!("Adams {ADAMS_X_JAM_MM_MU_0_4} mm")),
        }],
        SweepLayer::MinNorm => vec![min_norm(scene, models, Formulation::Translational)?],
        SweepLayer::MinNormRolling => vec![min_norm(scene, models, Formulation::Rolling)?],
        SweepLayer::SimulationMotion => vec![simulation(scene, models, Drive::Motion)?],
        SweepLayer::SimulationForce => vec![simulation(scene, models, Drive::Force)?],
    })
}

/// The closed form's answer at each sample of `axis`, through the port
/// ([`models::solve`]) so that its "outside the model" rule applies: the statics and F -> infinity
/// layers once called the statics directly and drew a jam for a push starting above 90 deg,
/// where `solve` says `outside_model`. A point outside the model is an empty row; a sweep
/// outside it at every point would be an empty chart and fails instead, with the reason.
///
/// Each answer is made into its point by `keep` as it comes: a whole `Solution` per point was
/// most of a long sweep's memory (1.4 kB per point at 200,000 points).
pub(super) fn closed_form(
    axis: &GridAxis,
    scene: &Input,
    keep: impl Fn(f64, Solution) -> SeriesPoint,
) -> Result<Vec<SeriesPoint>> {
    let param = axis.param;
    let values = axis.values();
    let mut points = Vec::with_capacity(values.len());
    let (mut first_outside, mut all_outside) = (None, true);
    for (i, v) in values.into_iter().enumerate() {
        let s = models::solve(&ModelSpec::Statics, &param.apply(scene.params, v))?;
        match &s.detail {
            Detail::Outside(why) if i == 0 => first_outside = Some(why.to_string()),
            Detail::Outside(_) => {}
            _ => all_outside = false,
        }
        points.push(keep(v, s));
    }
    if let (Some(why), true) = (first_outside, all_outside) {
        return Err(Error::ModelFailed {
            scene: String::new(),
            model: "closed-form statics",
            reason: format!(
                "at each of its {} points, {} = {} to {} (first: {why}); its sweep would be empty",
                points.len(),
                param.as_str(),
                axis.min,
                axis.max
            ),
        });
    }
    Ok(points)
}

/// The Table 1 mu values, ascending.
fn table1_mu() -> Vec<f64> {
    let mut mu: Vec<f64> = TABLE1.iter().map(|r| r.mu).collect();
    mu.sort_by(f64::total_cmp);
    mu
}

/// A jam point when the model says `jams`, an empty one otherwise (the data file shows it).
fn jam_point(mu: f64, status: JamStatus, x: Option<f64>, theta: Option<f64>) -> SeriesPoint {
    let jams = status == JamStatus::Jams;
    SeriesPoint {
        status: Some(status),
        ..point(mu, x.filter(|_| jams), theta.filter(|_| jams))
    }
}

/// `spec`'s jam points at the mu values `mu`, a sweep through the grid (in parallel; each point
/// is independent, so the result does not depend on the thread count).
///
/// A layer whose model failed at every point (the integrator gave up, the model does not
/// represent the scene, a cross-check refused the answer) would be drawn as nothing: the
/// render fails instead, naming the scene, the model (`model`) and the first point's reason, as
/// a time series does. A layer where the model answers "no jam" is physics and stays empty.
/// Where it failed at some points only, the second value is a note for the chart naming them,
/// so that a gap is never read as "no jam".
fn model_points(
    scene: &Input,
    models: &dyn Models,
    spec: &ModelSpec,
    mu: &[f64],
    model: &'static str,
) -> Result<(Vec<SeriesPoint>, Option<String>)> {
    let answers = grid::at_values(&scene.params, Param::Mu, mu, |p| {
        let s = models.solve(spec, p)?;
        let failure = study::why(&s).filter(|w| !matches!(w, Why::NoJam { .. }));
        let point = jam_point(p.mu_ground, s.status, s.x_jam_mm, s.theta_jam_deg);
        Ok((point, failure))
    })?;
    let failed = |(p, f): &(SeriesPoint, Option<Why>)| p.x_jam_mm.is_none() && f.is_some();
    if !answers.is_empty() && answers.iter().all(failed) {
        let (first, why) = &answers[0];
        let why = why.as_ref().map_or(String::new(), |w| w.to_string());
        return Err(Error::ModelFailed {
            scene: String::new(),
            model,
            reason: format!(
                "at each of its {} points, mu = {} to {} (first, at mu = {}: {why}); its sweep \
                 layer would be empty",
                answers.len(),
                mu.iter().copied().reduce(f64::min).unwrap_or_default(),
                mu.iter().copied().reduce(f64::max).unwrap_or_default(),
                first.at
            ),
        });
    }
    let missing: Vec<String> = answers
        .iter()
        .filter(|a| failed(a))
        .map(|(p, _)| p.at.to_string())
        .collect();
    let note = (!missing.is_empty()).then(|| {
        format!(
            "{model}: no answer at μ = {} (jamchart solve says why)",
            missing.join(", ")
        )
    });
    Ok((answers.into_iter().map(|(p, _)| p).collect(), note))
}

/// Min-norm points at the Table 1 mu values.
fn min_norm(scene: &Input, models: &dyn Models, formulation: Formulation) -> Result<Series> {
    let s = MinNormSettings {
        formulation,
        ..scene.min_norm
    };
    let model = match formulation {
        Formulation::Translational => "min-norm program",
        Formulation::Rolling => "min-norm program (rolling)",
    };
    let (points, callout) =
        model_points(scene, models, &ModelSpec::MinNorm(s), &table1_mu(), model)?;
    Ok(match formulation {
        Formulation::Translational => Series {
            curve: Curve::MinNorm,
            label: "min-norm model, translational joint (as the paper)".into(),
            points,
            flat_names: None,
            callout,
        },
        Formulation::Rolling => Series {
            curve: Curve::MinNormRolling,
            label: "min-norm model, disc free to roll (on the F → ∞ limit)".into(),
            points,
            flat_names: None,
            callout,
        },
    })
}

/// Simulated jams at [`SIMULATION_MU`] with the scene's `[dynamics]` settings and `drive`.
fn simulation(scene: &Input, models: &dyn Models, drive: Drive) -> Result<Series> {
    let d = DynamicsParams {
        drive: crate::dynamics::DriveSettings {
            mode: drive,
            ..scene.dynamics.drive
        },
        ..scene.dynamics
    };
    let spec = ModelSpec::Dynamics {
        params: d,
        series_dt_s: None,
    };
    let model = match drive {
        Drive::Motion => "simulation (motion drive)",
        Drive::Force => "simulation (force drive)",
    };
    let (points, callout) = model_points(scene, models, &spec, &SIMULATION_MU, model)?;
    Ok(match drive {
        Drive::Motion => Series {
            curve: Curve::SimulationMotion,
            label: format!("simulation, motion drive ω = {} deg/s", d.drive.omega_deg_s),
            points,
            flat_names: None,
            callout,
        },
        Drive::Force => Series {
            curve: Curve::SimulationForce,
            label: format!("simulation, force drive F = {} N", scene.params.force_n),
            points,
            flat_names: None,
            callout,
        },
    })
}

pub(super) fn point(at: f64, x_jam_mm: Option<f64>, theta_jam_deg: Option<f64>) -> SeriesPoint {
    SeriesPoint {
        at,
        x_jam_mm,
        theta_jam_deg,
        status: None,
        past_palm_x_jam_mm: None,
    }
}

/// The closed form's answer `s` at the swept value `at`: its status, its jam, and where a
/// jam past the palm's end would be on a long enough palm.
pub(super) fn closed_form_point(at: f64, s: &Solution) -> SeriesPoint {
    SeriesPoint {
        status: Some(s.status),
        past_palm_x_jam_mm: s.past_palm().map(|p| p.x_jam_mm),
        ..point(at, s.x_jam_mm, s.theta_jam_deg)
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
            curve: Curve::PaperTable1ForceAnalysis,
            label: "Table 1, force analysis".into(),
            points: force,
            flat_names: None,
            callout: None,
        },
        Series {
            curve: Curve::PaperTable1MinNorm,
            label: "Table 1, minimum norm".into(),
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
        let consistent = disc_position_mm(10.0, 0.0, theta.to_radians());
        out.push(Series {
            curve: Curve::PaperTable1Erratum,
            label: format!(
                "Table 1 erratum at μ = {:.2}: x = {:.2} mm printed",
                e.at,
                e.x_jam_mm.unwrap_or(0.0)
            ),
            points: erratum,
            flat_names: None,
            callout: Some(format!(
                "erratum: printed {:.2} mm, consistent {consistent:.2} mm",
                e.x_jam_mm.unwrap_or(0.0)
            )),
        });
    }
    out
}
