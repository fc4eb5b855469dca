//! The universal chart: one jam chart for every part, theta_jam and x_jam / r over the friction
//! and the push over the weight.
//!
//! The closed form depends on the part only through two numbers (Eq. 1 corrected):
//!
//! ```text
//! theta_jam = alpha_g + alpha_p + asin(sin(alpha_g) / (F / (m g))),   x_jam / r = cot(theta_jam / 2)
//! ```
//!
//! so theta_jam over (mu, F / (m g)) holds for any radius, mass, push and gravity, and
//! x_jam / r is a function of theta_jam alone: one family of iso-lines carries both. A palm
//! face h off the hinge line adds h / sin(theta_jam) to x_jam. The part's own palm reach, L / r,
//! is the iso-line theta_jam = theta_reach (jams beyond it lie past the palm's end).
//!
//! The cells are the closed-form statics through the model port, on a palm long enough to
//! reach every jam (the reach is the scene's, its own line), so that a cell's theta_jam does
//! not depend on the part; a cell held at the start carries the start angle, which keeps the
//! field continuous across that boundary.

use contour::ContourBuilder;
use serde::{Deserialize, Serialize};

use super::cells::{self, CellsTable, HasCells};
use super::contours::{Traced, grid_lines, lines_at};
use super::models::Models;
use super::{At, DataFormat, Figure, FigureData, Input};
use crate::csv_out::Column;
use crate::error::{Error, Result};
use crate::grid::{GridAxis, GridRequest, Quantity};
use crate::models::ModelKind;
use crate::scene::Param;
use crate::scene::{JamStatus, SceneParams};

/// `[chart]` keys of `kind = "universal"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct UniversalSettings {
    /// Horizontal axis: a friction, `mu` (both contacts), `mu_ground` or `mu_palm` (the other
    /// stays the scene's).
    pub x_axis: GridAxis,
    /// Vertical axis: `push_ratio`, the push over the weight F / (m g) (log recommended).
    pub y_axis: GridAxis,
    /// Spacing of the thin theta_jam iso-lines in deg (default: 1).
    #[serde(default = "default_step")]
    pub theta_step_deg: f64,
    /// Spacing of the labelled iso-lines in deg; the bands between them are shaded (default:
    /// 5).
    #[serde(default = "default_label_step")]
    pub label_step_deg: f64,
    /// Ranges of the x axis' friction, the push or the mass, from the scene (`mu =
    /// "0.12:0.3"`): drawn as the box of (friction, F / (m g)) they span, its earliest-jam and
    /// latest-jam corners read off (not a `[chart]` key; default: none).
    #[serde(skip)]
    pub range: crate::uncertain::UncertainSet,
}

fn default_step() -> f64 {
    1.0
}

fn default_label_step() -> f64 {
    5.0
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

/// The frictions a universal chart's x axis may vary.
const FRICTIONS: [Param; 3] = [Param::Mu, Param::MuGround, Param::MuPalm];

impl Figure for UniversalSettings {
    type Data = UniversalData;

    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// The read-off marks the scene's friction and F / (m g).
    fn marks_scene_value(&self) -> bool {
        true
    }

    /// The read-off is always drawn where the scene's point lies on the chart.
    fn enable_read_off(&mut self) -> bool {
        true
    }

    fn validate(&self, input: &Input) -> Result<()> {
        if !FRICTIONS.contains(&self.x_axis.param) {
            return Err(Error::invalid(
                "chart.x_axis.param",
                self.x_axis.param.as_str(),
                "a universal chart's x axis is a friction: mu, mu_ground or mu_palm",
            ));
        }
        if self.y_axis.param != Param::PushRatio {
            return Err(Error::invalid(
                "chart.y_axis.param",
                self.y_axis.param.as_str(),
                "a universal chart's y axis is push_ratio, the push over the weight F / (m g)",
            ));
        }
        if input.params.weight_n() <= 0.0 {
            return Err(Error::invalid(
                "mass_kg",
                input.params.mass_kg,
                "the push over the weight F / (m g) needs a weight: set mass_kg and \
                 gravity_m_s2 above 0",
            ));
        }
        for (key, v) in [
            ("chart.theta_step_deg", self.theta_step_deg),
            ("chart.label_step_deg", self.label_step_deg),
        ] {
            if !(v.is_finite() && (0.1..=90.0).contains(&v)) {
                return Err(Error::invalid(key, v, "give a step in [0.1, 90] deg"));
            }
        }
        self.check_range()?;
        self.request(&input.params).validate()
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::UNIVERSAL_CELL)
    }

    fn compute(&self, input: &Input, models: &dyn Models) -> Result<UniversalData> {
        let p = input.params;
        let model = ModelKind::Statics.with(&input.min_norm, &input.dynamics);
        let g = super::models::evaluate(models, &model, &self.request(&p))?;
        let statuses = g.status.unwrap_or_default();
        let thetas = g.theta_jam_deg.unwrap_or_default();
        // theta_jam per cell in deg: the start angle where held at the start, 0 where it
        // never jams (no friction), NaN outside the model.
        let theta: Vec<f64> = statuses
            .iter()
            .zip(&thetas)
            .map(|(s, t)| match s {
                JamStatus::Jams | JamStatus::JammedAtStart => t.unwrap_or(f64::NAN),
                JamStatus::TooWeak => p.start_angle_deg,
                JamStatus::NeverJams => 0.0,
                _ => f64::NAN,
            })
            .collect();
        let x_over_r = statuses
            .iter()
            .zip(&theta)
            .map(|(s, t)| (*s == JamStatus::Jams).then(|| cot_half(*t)))
            .collect();
        // Where the scene's own part (its r and palm offset) would jam, on a long enough palm.
        let x_jam_mm = statuses
            .iter()
            .zip(&theta)
            .map(|(s, t)| (*s == JamStatus::Jams).then(|| p.disc_position_mm(t.to_radians())))
            .collect();
        // The status of the scene's own part on its own palm, as `solve` gives it: the field
        // above is on a palm long enough for every jam, where a jam past this palm's end (left
        // of the reach line) is `jams`, not `beyond_reach`.
        let on_palm = GridRequest {
            base: p,
            quantities: vec![Quantity::Status],
            ..self.request(&p)
        };
        let status_here = super::models::evaluate(models, &model, &on_palm)?
            .status
            .unwrap_or_default();
        let (xa, ya) = (&self.x_axis, &self.y_axis);
        let b = ContourBuilder::new(g.x_values.len(), g.y_values.len(), true);
        let field = theta_field(&theta);
        let (lo, hi) = theta
            .iter()
            .filter(|t| t.is_finite())
            .fold((f64::MAX, f64::MIN), |(a, b), t| (a.min(*t), b.max(*t)));
        let levels = |step: f64| -> Vec<f64> {
            if lo > hi {
                return Vec::new();
            }
            let first = (lo / step).floor() as i64 + 1;
            (first..)
                .map(|k| k as f64 * step)
                .take_while(|v| *v < hi)
                .collect()
        };
        let iso_lines = lines_at(&b, &field, &levels(self.theta_step_deg))
            .into_iter()
            .map(|l| IsoLine {
                theta_jam_deg: l.threshold(),
                x_jam_over_r: cot_half(l.threshold()),
                paths: Traced::over(grid_lines(&l.into_inner().0, xa, ya), xa, ya),
            })
            .collect();
        let reach_deg = p.reach_angle().to_degrees();
        let reach_line = b
            .lines(&field, &[reach_deg])
            .unwrap_or_default()
            .into_iter()
            .flat_map(|l| grid_lines(&l.into_inner().0, xa, ya))
            .collect();
        let read_off = match (xa.param.get(&p), Param::PushRatio.get(&p)) {
            (Some(mu), Some(push_ratio)) => {
                let long = self.request(&p).base;
                let on_long = models.jam_point(&model, &long)?;
                Some(UniversalReadOff {
                    at: At {
                        params: [xa.param, Param::PushRatio],
                        at: [mu, push_ratio],
                        point: models.jam_point(&model, &p)?,
                    },
                    theta_on_a_long_palm_deg: on_long
                        .theta_jam_deg
                        .filter(|_| on_long.status == JamStatus::Jams),
                })
            }
            _ => None,
        };
        let range = match self.range.is_empty() {
            true => None,
            false => Some(Box::new(self.range_ends(&p, models)?)),
        };
        Ok(UniversalData {
            params: p,
            settings: self.clone(),
            iso_lines: IsoLines {
                point: [xa.param.as_str(), ya.param.as_str()],
                lines: iso_lines,
            },
            labelled_theta_jam_deg: levels(self.label_step_deg),
            palm_reach: PalmReach {
                l_over_r: p.palm_length_mm / p.radius_mm,
                theta_reach_deg: reach_deg,
                paths: Traced::over(reach_line, xa, ya),
            },
            read_off,
            range,
            cells: UniversalCells {
                x: g.x_values,
                push_ratio: g.y_values,
                param: xa.param,
                status: status_here.iter().map(|s| s.index()).collect(),
                held: statuses
                    .iter()
                    .map(|s| matches!(s, JamStatus::JammedAtStart | JamStatus::TooWeak))
                    .collect(),
                theta_jam_deg: thetas,
                theta_field: theta,
                x_over_r,
                x_jam_mm,
            },
        })
    }
}

impl UniversalSettings {
    /// Refuses a range the chart has no axis for: it draws ranges of its x axis' friction,
    /// `force_n` and `mass_kg` (the last two through F / (m g)).
    pub fn check_range(&self) -> Result<()> {
        let x = self.x_axis.param.as_str();
        match self
            .range
            .inputs
            .iter()
            .find(|i| ![x, "force_n", "mass_kg"].contains(&i.name))
        {
            Some(i) => Err(Error::invalid(
                &format!("scene.{}", i.name),
                i.value,
                format!(
                    "a universal chart draws a range along its axes: give one for {x} (its x \
                     axis), force_n or mass_kg (through F / (m g)), or draw this one on a sweep"
                ),
            )),
            None => Ok(()),
        }
    }

    /// The box of the scene's ranges on the chart and the closed form at its earliest-jam and
    /// latest-jam corners ([`crate::uncertain::range::ends`]).
    fn range_ends(&self, p: &SceneParams, models: &dyn Models) -> Result<UniversalRange> {
        let model = crate::models::ModelSpec::Statics;
        let ends = crate::uncertain::range::ends(p, &self.range)?;
        let x = self.x_axis.param;
        let corner = |values: &[f64]| -> Result<RangeEnd> {
            let q = self.range.apply(p, values);
            let long = models.jam_point(&model, &self.request(&q).base)?;
            let (mu, push_ratio) = (x.get(&q), Param::PushRatio.get(&q));
            Ok(RangeEnd {
                at: At {
                    params: [x, Param::PushRatio],
                    at: [mu.unwrap_or(f64::NAN), push_ratio.unwrap_or(f64::NAN)],
                    point: models.jam_point(&model, &q)?,
                },
                theta_on_a_long_palm_deg: long
                    .theta_jam_deg
                    .filter(|_| long.status == JamStatus::Jams),
            })
        };
        let (earliest, latest) = (corner(&ends.earliest.values)?, corner(&ends.latest.values)?);
        let span = |a: f64, b: f64| [a.min(b), a.max(b)];
        Ok(UniversalRange {
            given: self.range.describe(),
            x: span(earliest.at.at[0], latest.at.at[0]),
            push_ratio: span(earliest.at.at[1], latest.at.at[1]),
            earliest,
            latest,
        })
    }

    fn request(&self, base: &SceneParams) -> GridRequest {
        GridRequest {
            // A palm long enough for every jam: the field must not depend on the part; the
            // scene's own reach is its own line.
            base: SceneParams {
                palm_length_mm: f64::MAX,
                ..*base
            },
            x: self.x_axis,
            y: self.y_axis,
            quantities: vec![Quantity::Status, Quantity::ThetaJamDeg],
        }
    }
}

/// theta_jam per cell as the contour crate needs it: finite everywhere, a cell outside the
/// model far below every level.
pub(crate) fn theta_field(theta: &[f64]) -> Vec<f64> {
    theta
        .iter()
        .map(|t| if t.is_finite() { *t } else { -1e3 })
        .collect()
}

/// x_jam / r = cot(theta / 2) for theta in deg.
pub fn cot_half(theta_deg: f64) -> f64 {
    1.0 / (0.5 * theta_deg.to_radians()).tan()
}

/// The computed universal chart: its serde form is its data file (the cells go to the CSV
/// beside it, summarised under `cells`).
#[derive(Debug, Clone, Serialize)]
pub struct UniversalData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The settings it was computed with.
    #[serde(flatten)]
    pub settings: UniversalSettings,
    /// Every theta_jam iso-line, each with its x_jam / r.
    pub iso_lines: IsoLines,
    /// The labelled levels in deg (the edges of the shaded bands).
    pub labelled_theta_jam_deg: Vec<f64>,
    /// The scene palm's reach: the iso-line where the contact reaches the palm's end.
    pub palm_reach: PalmReach,
    /// The scene's own part on the chart.
    pub read_off: Option<UniversalReadOff>,
    /// The box of the scene's ranges and its two extreme corners (with ranges).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<Box<UniversalRange>>,
    /// The cells: status, theta_jam and x_jam / r.
    #[serde(serialize_with = "cells::summary_of")]
    pub cells: UniversalCells,
}

impl FigureData for UniversalData {
    const FORMAT: DataFormat = DataFormat::Json;
    const CELLS: bool = true;

    fn cells(&self) -> Option<CellsTable<'_>> {
        Some(self.cells.table())
    }
}

/// The theta_jam iso-lines and the two parameters their points give.
#[derive(Debug, Clone, Serialize)]
pub struct IsoLines {
    /// The names of a point's x and y.
    pub point: [&'static str; 2],
    /// The lines, lowest level first.
    pub lines: Vec<IsoLine>,
}

/// One theta_jam iso-line.
#[derive(Debug, Clone, Serialize)]
pub struct IsoLine {
    /// Its level in deg.
    pub theta_jam_deg: f64,
    /// x_jam / r along it, cot(theta_jam / 2).
    pub x_jam_over_r: f64,
    /// Its paths.
    pub paths: Traced,
}

/// The scene palm's reach on the chart.
#[derive(Debug, Clone, Serialize)]
pub struct PalmReach {
    /// L / r.
    pub l_over_r: f64,
    /// The palm angle in deg at which the contact reaches the palm's end.
    pub theta_reach_deg: f64,
    /// The iso-line theta_jam = theta_reach.
    pub paths: Traced,
}

/// The scene's own part read off the chart: the friction and F / (m g), the closed form's
/// answer for its own palm, and theta_jam on a long enough palm (the field's value).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct UniversalReadOff {
    /// The scene's friction and F / (m g), and the answer there.
    #[serde(flatten)]
    pub at: At<2>,
    /// theta_jam in deg on a long enough palm, if it jams there.
    #[serde(rename = "theta_jam_on_a_long_palm_deg")]
    pub theta_on_a_long_palm_deg: Option<f64>,
}

/// The box of the scene's ranges on a universal chart: by monotonicity (the proof is in
/// [`crate::statics`]) every jam of the box lies between its two extreme corners'.
#[derive(Debug, Clone, Serialize)]
pub struct UniversalRange {
    /// The ranges as given, e.g. `mu = 0.12:0.3`.
    pub given: String,
    /// The friction's span on the x axis [lo, hi].
    pub x: [f64; 2],
    /// The span of F / (m g) [lo, hi].
    pub push_ratio: [f64; 2],
    /// The corner where the jam comes earliest (nearest the hinge).
    pub earliest: RangeEnd,
    /// The corner where it comes latest.
    pub latest: RangeEnd,
}

/// One extreme corner of a range's box: where it lies on the chart, the closed form's answer
/// for the scene's own palm, and theta_jam on a long enough palm.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct RangeEnd {
    /// The corner's friction and F / (m g), and the answer there.
    #[serde(flatten)]
    pub at: At<2>,
    /// theta_jam in deg on a long enough palm, if it jams there.
    #[serde(rename = "theta_jam_on_a_long_palm_deg")]
    pub theta_on_a_long_palm_deg: Option<f64>,
}

/// A universal chart's cells (x fastest).
#[derive(Debug, Clone)]
pub struct UniversalCells {
    /// The friction on the x axis.
    pub param: Param,
    /// Its samples.
    pub x: Vec<f64>,
    /// The samples of F / (m g).
    pub push_ratio: Vec<f64>,
    /// The status per cell of the scene's own part on its own palm (`solve`'s: a jam past
    /// the palm's end is `beyond_reach`), as its index in [`JamStatus::ALL`].
    pub status: Vec<u8>,
    /// Whether the disc is held at the start (or never moved: too weak), on any palm.
    pub held: Vec<bool>,
    /// theta_jam in deg where the closed form gives one.
    pub theta_jam_deg: Vec<Option<f64>>,
    /// theta_jam as a field over the chart: the start angle where held at the start or too
    /// weak, 0 where it never jams, NaN outside the model.
    pub theta_field: Vec<f64>,
    /// x_jam / r where it jams on a long enough palm (past this palm's end too).
    pub x_over_r: Vec<Option<f64>>,
    /// x_jam in mm of the scene's part (its r and palm offset) where x_over_r is given.
    pub x_jam_mm: Vec<Option<f64>>,
}

impl HasCells for UniversalCells {
    fn table(&self) -> CellsTable<'_> {
        CellsTable::new(
            [
                (self.param.as_str(), &self.x),
                (Param::PushRatio.as_str(), &self.push_ratio),
            ],
            &[
                (
                    "status",
                    Column::Words {
                        words: JamStatus::NAMES,
                        of: &self.status,
                    },
                ),
                ("theta_jam_deg", Column::Sparse(&self.theta_jam_deg)),
                ("x_jam_over_r", Column::Sparse(&self.x_over_r)),
                ("x_jam_mm", Column::Sparse(&self.x_jam_mm)),
            ],
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charts::{ChartSpec, SceneSource};
    use crate::models::{ModelSpec, solve};

    /// The universal chart's cells said `jams` where the scene's part jams past its palm's end
    /// (the 25 mm shaft at mu 0.12: x/r 7.95 > L/r 6.40), where `solve` says beyond_reach, and
    /// gave x/r but not x in mm although r is known. Every cell's status is now `solve`'s for
    /// the scene's part at that friction and push, and its x_jam_mm is where that part jams:
    /// `solve`'s x_jam on the palm, its past-palm x_jam beyond the palm's end.
    #[test]
    fn every_cell_has_the_status_solve_gives_and_x_jam_in_mm() {
        let scene = SceneSource::BuiltIn("universal-range".into())
            .load(&[])
            .unwrap();
        let ChartSpec::Universal(settings) = &scene.chart else {
            panic!("a universal chart")
        };
        let data = settings
            .compute(&scene.input(), &super::super::models::Live)
            .unwrap();
        let c = &data.cells;
        let (mut beyond, mut worst) = (0, 0.0f64);
        for (iy, &ratio) in c.push_ratio.iter().enumerate() {
            for (ix, &mu) in c.x.iter().enumerate() {
                let i = iy * c.x.len() + ix;
                let q = Param::PushRatio.apply(c.param.apply(scene.params, mu), ratio);
                let s = solve(&ModelSpec::Statics, &q).unwrap();
                assert_eq!(
                    JamStatus::NAMES[usize::from(c.status[i])],
                    s.status.as_str(),
                    "mu {mu}, F/(m g) {ratio}"
                );
                let want = match s.status {
                    JamStatus::Jams => s.x_jam_mm,
                    JamStatus::BeyondReach => {
                        beyond += 1;
                        crate::statics::solve(&q).past_palm.map(|p| p.x_jam_mm)
                    }
                    _ => None,
                };
                if let (Some(got), Some(want)) = (c.x_jam_mm[i], want) {
                    worst = worst.max(((got - want) / want).abs());
                }
                assert_eq!(c.x_jam_mm[i].is_some(), want.is_some(), "mu {mu}, {ratio}");
            }
        }
        eprintln!(
            "{beyond} cells beyond the palm's reach; x_jam_mm worst relative error {worst:e}"
        );
        assert!(beyond > 1000, "{beyond}");
        assert!(worst < 1e-9, "{worst:e}");
    }
}
