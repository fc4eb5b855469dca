//! The contour map (Fig. 7c): iso-lines of x_jam and theta_jam over two parameters.
//!
//! The grid evaluator computes x_jam (and theta_jam, and the F -> infinity limit r/mu when the
//! "settle" line is asked for) on every cell; the `contour` crate traces the iso-lines. The
//! settle line is where x_jam comes within `settle_pct` % of its limit: beyond it the push
//! force no longer matters.

use contour::ContourBuilder;
use serde::{Deserialize, Serialize};

use super::cells::{self, CellsTable, HasCells};
use super::contours::{Traced, grid_lines_among, lines_at};
use super::models::{self, Models};
use super::{At, DataFormat, Figure, FigureData, Input};
use crate::csv_out::Column;
use crate::error::{Error, Result};
use crate::grid::{GridAxis, GridRequest, Quantity};
use crate::models::ModelKind;
use crate::scene::{JamStatus, Param, SceneParams};

/// `[chart]` keys of `kind = "contour_map"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContourMapSettings {
    /// Horizontal axis (a scene parameter).
    pub x_axis: GridAxis,
    /// Vertical axis (a scene parameter).
    pub y_axis: GridAxis,
    /// x_jam iso-line levels in mm, increasing; the bands between them are shaded (default:
    /// about eight round levels over the map's range).
    #[serde(default)]
    pub x_jam_levels_mm: Vec<f64>,
    /// theta_jam iso-line levels in deg (default: none).
    #[serde(default)]
    pub theta_jam_levels_deg: Vec<f64>,
    /// Draw where x_jam comes within this many percent of its F -> infinity limit
    /// (default: none; the paper's Fig. 7b discussion suggests 1).
    #[serde(default)]
    pub settle_pct: Option<f64>,
    /// The model whose x_jam and theta_jam are contoured (default: statics; the settle line's
    /// limit r/mu is always the statics').
    #[serde(default)]
    pub model: ModelKind,
    /// Draw the read-off at the scene's own values of both axes' parameters: line 1 up from
    /// the x axis, line 2 across from the y axis, and 3, the model's x_jam and theta_jam
    /// there, printed (default: false; `render fig7c --read-off force_n=150 --read-off
    /// radius_mm=12`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub read_off: bool,
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

impl Figure for ContourMapSettings {
    type Data = ContourMapData;

    /// Checks the axes and levels.
    fn validate(&self, input: &Input) -> Result<()> {
        if [self.x_axis.param, self.y_axis.param].contains(&Param::ThetaDeg) {
            return Err(Error::invalid(
                "chart.x_axis/y_axis",
                "theta_deg",
                "a contour map varies scene parameters",
            ));
        }
        let increasing =
            |v: &[f64]| v.windows(2).all(|w| w[0] < w[1]) && v.iter().all(|x| x.is_finite());
        if !increasing(&self.x_jam_levels_mm) {
            return Err(Error::invalid(
                "chart.x_jam_levels_mm",
                format!("{:?}", self.x_jam_levels_mm),
                "give finite, increasing levels",
            ));
        }
        if !increasing(&self.theta_jam_levels_deg) {
            return Err(Error::invalid(
                "chart.theta_jam_levels_deg",
                format!("{:?}", self.theta_jam_levels_deg),
                "levels must increase",
            ));
        }
        if let Some(s) = self.settle_pct
            && !(s.is_finite() && s > 0.0 && s < 100.0)
        {
            return Err(Error::invalid(
                "chart.settle_pct",
                s,
                "must lie in (0, 100) %",
            ));
        }
        // The settle line's label and legend read "F ≈ ...", "to the right": true only when the
        // push force runs along x (x_jam falls towards r/mu as F grows).
        if self.settle_pct.is_some() && self.x_axis.param != Param::ForceN {
            return Err(Error::invalid(
                "chart.settle_pct",
                format!("x_axis.param = {}", self.x_axis.param.as_str()),
                "the settle line needs force_n on the x axis; drop settle_pct or put force_n on x",
            ));
        }
        self.request(&input.params).validate()
    }

    fn param_axes(&self) -> Vec<(&'static str, GridAxis)> {
        vec![("x_axis", self.x_axis), ("y_axis", self.y_axis)]
    }

    /// With the read-off, the chart marks the scene's values of both axes' parameters.
    fn marks_scene_value(&self) -> bool {
        self.read_off
    }

    fn enable_read_off(&mut self) -> bool {
        self.read_off = true;
        true
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        let levels = [
            ("chart.x_jam_levels_mm", self.x_jam_levels_mm.len()),
            (
                "chart.theta_jam_levels_deg",
                self.theta_jam_levels_deg.len(),
            ),
        ];
        for (key, n) in levels {
            crate::limits::check_at_most(key, n, crate::limits::MAX_LEVELS, "levels")?;
        }
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::CONTOUR_MAP_CELL)
    }

    /// Evaluates the grid quantities the lines need and traces them.
    fn compute(&self, input: &Input, models: &dyn Models) -> Result<ContourMapData> {
        let p = &input.params;
        let model = self.model.with(&input.min_norm, &input.dynamics);
        let grid = models::evaluate(models, &model, &self.request(p))?;
        let gap_pct: Option<Vec<Option<f64>>> = match (&grid.x_jam_mm, &grid.x_rigid_mm) {
            (Some(x), Some(r)) => Some(
                x.iter()
                    .zip(r)
                    .map(|(x, r)| Some(100.0 * (r.as_ref()? - x.as_ref()?) / r.as_ref()?))
                    .collect(),
            ),
            _ => None,
        };
        let (xa, ya) = (&self.x_axis, &self.y_axis);
        let b = ContourBuilder::new(grid.nx(), grid.ny(), true);
        // Lines run among the cells that jam: at a cell without one they end.
        let jammed: Vec<bool> = (grid.x_jam_mm.as_deref().unwrap_or_default().iter())
            .map(Option::is_some)
            .collect();
        // Finite values and levels cannot fail; nothing is traced if they ever did.
        let lines = |values: &[f64], levels: &[f64]| -> Vec<IsoLine> {
            lines_at(&b, values, levels)
                .into_iter()
                .map(|l| {
                    let level = l.threshold();
                    let paths = grid_lines_among(&l.into_inner().0, xa, ya, &jammed);
                    IsoLine {
                        level,
                        paths: Traced::over(paths, xa, ya),
                    }
                })
                .collect()
        };
        let xj = dense_x_jam(grid.x_jam_mm.as_deref().unwrap_or_default());
        let mut settings = self.clone();
        if settings.x_jam_levels_mm.is_empty() {
            settings.x_jam_levels_mm = round_levels(&xj);
        }
        let x_jam_mm = lines(&xj, &settings.x_jam_levels_mm);
        let theta_jam_deg = grid
            .theta_jam_deg
            .as_deref()
            .map(|tj| lines(&dense_x_jam(tj), &settings.theta_jam_levels_deg))
            .unwrap_or_default();
        let gap_to_x_rigid_pct = match (&gap_pct, settings.settle_pct) {
            // No jam or no limit: far from settled (the line ends there all the same).
            (Some(gap), Some(pct)) => {
                let dense: Vec<f64> = gap.iter().map(|g| g.unwrap_or(100.0)).collect();
                lines(&dense, &[pct])
            }
            _ => Vec::new(),
        };
        let read_off = match (settings.read_off, xa.param.get(p), ya.param.get(p)) {
            (true, Some(x), Some(y)) => Some(At {
                params: [xa.param, ya.param],
                at: [x, y],
                point: models.jam_point(&model, p)?,
            }),
            _ => None,
        };
        Ok(ContourMapData {
            params: *p,
            settings,
            iso_lines: IsoLines {
                point: [xa.param.as_str(), ya.param.as_str()],
                x_jam_mm,
                theta_jam_deg,
                gap_to_x_rigid_pct,
            },
            read_off,
            cells: ContourMapCells {
                params: [xa.param, ya.param],
                x: grid.x_values,
                y: grid.y_values,
                status: (grid.status.unwrap_or_default().iter())
                    .map(|s| s.index())
                    .collect(),
                x_jam_mm: grid.x_jam_mm,
                theta_jam_deg: grid.theta_jam_deg,
                gap_to_x_rigid_pct: gap_pct,
            },
        })
    }
}

impl ContourMapSettings {
    fn request(&self, base: &SceneParams) -> GridRequest {
        // The status says why a cell has no x_jam (the blank's legend, the cells CSV).
        let mut quantities = vec![Quantity::Status, Quantity::XJamMm];
        if !self.theta_jam_levels_deg.is_empty() {
            quantities.push(Quantity::ThetaJamDeg);
        }
        if self.settle_pct.is_some() {
            quantities.push(Quantity::XRigidMm);
        }
        GridRequest {
            base: *base,
            x: self.x_axis,
            y: self.y_axis,
            quantities,
        }
    }
}

/// About eight round levels (steps of 1, 2 or 5 times a power of ten) strictly inside the range
/// of the jammed cells of `values`; one level in the middle when the range is flat.
fn round_levels(values: &[f64]) -> Vec<f64> {
    let jammed = values.iter().copied().filter(|v| *v != NO_JAM);
    let (lo, hi) = jammed.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    if lo >= hi {
        return vec![if lo < f64::MAX { lo } else { 1.0 }];
    }
    let raw = (hi - lo) / 8.0;
    let decade = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * decade)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * decade);
    let first = (lo / step).floor() as i64 + 1;
    (first..)
        .map(|k| k as f64 * step)
        .take_while(|v| *v < hi)
        .collect()
}

/// A value for cells where a model gives no jam: below every level, so they stay unshaded.
pub(crate) const NO_JAM: f64 = -1.0;

/// The lower edge of the lowest band: below every jam's x_jam and theta_jam (both > 0) and
/// above [`NO_JAM`], so that a cell without a jam lies in no band and stays blank.
pub(crate) const LOWEST_BAND_EDGE: f64 = 0.5 * NO_JAM;

/// A quantity per cell as the contour crate needs it: [`NO_JAM`] where there is none.
pub(crate) fn dense_x_jam(v: &[Option<f64>]) -> Vec<f64> {
    v.iter().map(|x| x.unwrap_or(NO_JAM)).collect()
}

/// The computed contour map: its serde form is its data file (the cells go to the CSV beside
/// it, summarised under `cells`).
#[derive(Debug, Clone, Serialize)]
pub struct ContourMapData {
    /// The scene's parameters.
    pub params: SceneParams,
    /// The settings it was computed with, the x_jam levels filled in when left to choose.
    #[serde(flatten)]
    pub settings: ContourMapSettings,
    /// The iso-lines traced.
    pub iso_lines: IsoLines,
    /// The model's jam at the scene's own point (with the read-off).
    pub read_off: Option<At<2>>,
    /// The cells: x_jam and, where asked for, theta_jam and the gap to the rigid limit.
    #[serde(serialize_with = "cells::summary_of")]
    pub cells: ContourMapCells,
}

impl FigureData for ContourMapData {
    const FORMAT: DataFormat = DataFormat::Json;
    const CELLS: bool = true;

    fn cells(&self) -> Option<CellsTable<'_>> {
        Some(self.cells.table())
    }
}

/// A contour map's iso-lines: each a level and its paths.
#[derive(Debug, Clone, Serialize)]
pub struct IsoLines {
    /// The names of a point's x and y.
    pub point: [&'static str; 2],
    /// x_jam iso-lines, levels in mm.
    pub x_jam_mm: Vec<IsoLine>,
    /// theta_jam iso-lines, levels in deg.
    pub theta_jam_deg: Vec<IsoLine>,
    /// The settle line: the gap (x_rigid - x_jam) / x_rigid at `settle_pct` %.
    pub gap_to_x_rigid_pct: Vec<IsoLine>,
}

/// One iso-line.
#[derive(Debug, Clone, Serialize)]
pub struct IsoLine {
    /// Its level, in its quantity's unit.
    pub level: f64,
    /// Its paths.
    pub paths: Traced,
}

/// A contour map's cells (x fastest).
#[derive(Debug, Clone)]
pub struct ContourMapCells {
    /// The x and y parameters.
    pub params: [Param; 2],
    /// The x samples.
    pub x: Vec<f64>,
    /// The y samples.
    pub y: Vec<f64>,
    /// The model's verdict per cell, as its index in [`JamStatus::ALL`]: why a cell without
    /// x_jam has none (past the palm's end, too weak, ...).
    pub status: Vec<u8>,
    /// x_jam in mm where the model gives one.
    pub x_jam_mm: Option<Vec<Option<f64>>>,
    /// theta_jam in deg, when its iso-lines are asked for.
    pub theta_jam_deg: Option<Vec<Option<f64>>>,
    /// (x_rigid - x_jam) / x_rigid in %, with the settle line; None where there is no jam or
    /// no F -> infinity limit.
    pub gap_to_x_rigid_pct: Option<Vec<Option<f64>>>,
}

impl HasCells for ContourMapCells {
    fn table(&self) -> CellsTable<'_> {
        let mut columns = vec![(
            "status",
            Column::Words {
                words: JamStatus::NAMES,
                of: &self.status,
            },
        )];
        columns.extend(
            self.x_jam_mm
                .as_deref()
                .map(|v| ("x_jam_mm", Column::Sparse(v))),
        );
        columns.extend(
            self.theta_jam_deg
                .as_deref()
                .map(|v| ("theta_jam_deg", Column::Sparse(v))),
        );
        columns.extend(
            self.gap_to_x_rigid_pct
                .as_deref()
                .map(|v| ("gap_to_x_rigid_pct", Column::Sparse(v))),
        );
        let [x, y] = self.params;
        CellsTable::new([(x.as_str(), &self.x), (y.as_str(), &self.y)], &columns)
    }
}

#[cfg(test)]
mod round_levels_tests {
    use super::*;

    #[test]
    fn levels_are_round_inside_the_range_and_skip_unjammed_cells() {
        let l = round_levels(&[NO_JAM, 24.3, 31.0, 61.7]);
        assert_eq!(l, [25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 55.0, 60.0]);
        assert_eq!(round_levels(&[3.0, 3.0]), [3.0]);
        assert_eq!(round_levels(&[NO_JAM]), [1.0]);
    }
}
