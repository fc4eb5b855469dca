//! The parallel grid evaluator: a model over any two scene parameters.
//!
//! A [`GridRequest`] names a base [`SceneParams`], two [`GridAxis`] and the [`Quantity`]s wanted;
//! [`evaluate`] computes only those, in parallel (rayon), and returns them in index order
//! `iy * nx + ix` (x fastest). Each cell is computed by the same instructions whatever thread runs
//! it and whatever the chunking, so the result is bit-identical for any thread count (a test says
//! so): no reductions across cells, no fused multiply-adds chosen by the compiler.
//!
//! The statics margin has a fast kernel (see [`MarginCoeffs`]); the jam point (status, theta_jam, x_jam)
//! comes from any [`PointModel`], so the min-norm and dynamics models plug in by implementing it.

mod axis;
mod margin;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use axis::{AxisScale, GridAxis, GridParam};
pub use margin::MarginCoeffs;

use crate::error::{Error, Result};
use crate::model::{JamStatus, SceneParams};
use crate::statics;

/// A quantity a grid can compute per cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// The statics jam margin mu_g R_n - R_t in N at the cell's palm angle (needs a
    /// `theta_deg` axis): > 0 jammed, < 0 sliding.
    MarginN,
    /// The model's [`JamStatus`] of the push.
    Status,
    /// The model's theta_jam in deg.
    ThetaJamDeg,
    /// The model's x_jam in mm.
    XJamMm,
    /// The statics F -> infinity limit of x_jam in mm, r cot((alpha_g + alpha_p)/2) (r/mu for
    /// equal frictions): what x_jam tends to as the push grows.
    XRigidMm,
}

/// What a model says about one push: the part of its solution a grid or chart needs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JamPoint {
    /// Outcome of the push.
    pub status: JamStatus,
    /// Palm angle at the jam in deg (None when the model gives none).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm (None when the model gives none).
    pub x_jam_mm: Option<f64>,
}

/// A model that answers one push; the grid calls it once per cell, from several threads.
///
/// The min-norm and dynamics models plug into grids and charts by implementing this.
pub trait PointModel: Sync {
    /// The jam point for scene `p` (already validated).
    fn jam_point(&self, p: &SceneParams) -> JamPoint;
}

/// The closed-form statics ([`statics::solve`]) as a [`PointModel`].
#[derive(Debug, Clone, Copy, Default)]
pub struct Statics;

impl PointModel for Statics {
    fn jam_point(&self, p: &SceneParams) -> JamPoint {
        let s = statics::solve(p);
        JamPoint {
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
        }
    }
}

/// A model a scene can name for its jam points (`model = "statics"`).
///
/// The min-norm and dynamics models join as variants once they implement [`PointModel`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ModelName {
    /// The closed-form statics.
    #[default]
    Statics,
}

impl ModelName {
    /// The model itself.
    pub fn point_model(self) -> &'static dyn PointModel {
        match self {
            ModelName::Statics => &Statics,
        }
    }
}

/// What to evaluate: the base scene, the two axes and the quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct GridRequest {
    /// The scene every cell starts from; the axes overwrite their parameters.
    pub base: SceneParams,
    /// Horizontal axis (index ix, fastest in memory).
    pub x: GridAxis,
    /// Vertical axis (index iy).
    pub y: GridAxis,
    /// The quantities to compute; the others stay `None` in the result.
    pub quantities: Vec<Quantity>,
}

/// The evaluated grid; each present vector has `nx * ny` cells in index order `iy * nx + ix`.
#[derive(Debug, Clone, PartialEq)]
pub struct GridResult {
    /// Horizontal sample values.
    pub x_values: Vec<f64>,
    /// Vertical sample values.
    pub y_values: Vec<f64>,
    /// Statics jam margin in N, if requested.
    pub margin_n: Option<Vec<f64>>,
    /// Jam status, if requested.
    pub status: Option<Vec<JamStatus>>,
    /// theta_jam in deg, if requested (None where the model gives none).
    pub theta_jam_deg: Option<Vec<Option<f64>>>,
    /// x_jam in mm, if requested (None where the model gives none).
    pub x_jam_mm: Option<Vec<Option<f64>>>,
    /// Statics F -> infinity limit of x_jam in mm, if requested.
    pub x_rigid_mm: Option<Vec<Option<f64>>>,
}

impl GridResult {
    /// Number of horizontal samples.
    pub fn nx(&self) -> usize {
        self.x_values.len()
    }

    /// Number of vertical samples.
    pub fn ny(&self) -> usize {
        self.y_values.len()
    }

    /// The flat index of cell (ix, iy).
    pub fn index(&self, ix: usize, iy: usize) -> usize {
        iy * self.nx() + ix
    }
}

/// At most this many cells in one grid: 2^26, 512 MiB per quantity, far beyond any chart's
/// resolution; an axis alone may have up to 2^24 samples.
pub const MAX_CELLS: usize = 1 << 26;

impl GridRequest {
    /// Checks the axes, the base scene and the scene at the corners of the grid.
    pub fn validate(&self) -> Result<()> {
        self.x.validate("x_axis")?;
        self.y.validate("y_axis")?;
        let cells = self.x.count.saturating_mul(self.y.count);
        if cells > MAX_CELLS {
            return Err(Error::invalid(
                "x_axis.count * y_axis.count",
                cells,
                format!(
                    "a grid has at most {MAX_CELLS} cells (8 bytes each per quantity); \
                     lower the counts"
                ),
            ));
        }
        if self.x.param == self.y.param {
            return Err(Error::invalid(
                "y_axis.param",
                self.y.param.as_str(),
                "the two axes must vary different parameters",
            ));
        }
        self.base.validate()?;
        // Every parameter is monotone along its axis, so the corners bound the whole grid.
        for (xv, yv) in [self.x.min, self.x.max]
            .into_iter()
            .flat_map(|xv| [(xv, self.y.min), (xv, self.y.max)])
        {
            self.cell_params(xv, yv).validate()?;
        }
        for axis in [&self.x, &self.y] {
            if axis.param == GridParam::ThetaDeg && !(axis.min >= 0.0 && axis.max <= 180.0) {
                return Err(Error::invalid(
                    "theta_deg axis",
                    format!("{}..{}", axis.min, axis.max),
                    "the palm angle axis must lie within 0..180 deg",
                ));
            }
        }
        let has_theta = [self.x.param, self.y.param].contains(&GridParam::ThetaDeg);
        if self.quantities.contains(&Quantity::MarginN) && !has_theta {
            return Err(Error::invalid(
                "quantities",
                "margin_n",
                "the margin needs a theta_deg axis (the palm angle at which it is evaluated)",
            ));
        }
        Ok(())
    }

    fn cell_params(&self, xv: f64, yv: f64) -> SceneParams {
        self.y.param.apply(self.x.param.apply(self.base, xv), yv)
    }
}

/// Evaluates the requested quantities over the grid with `model`, in parallel.
///
/// The margin always comes from the closed-form statics (it is that model's quantity); the jam
/// point from `model`. Bit-identical for any rayon thread count.
pub fn evaluate(req: &GridRequest, model: &dyn PointModel) -> Result<GridResult> {
    req.validate()?;
    let x_values = req.x.values();
    let y_values = req.y.values();
    let wants = |q| req.quantities.contains(&q);
    let margin_n = wants(Quantity::MarginN).then(|| margin::margin_grid(req, &x_values, &y_values));

    let jam_wanted =
        wants(Quantity::Status) || wants(Quantity::ThetaJamDeg) || wants(Quantity::XJamMm);
    let points: Option<Vec<JamPoint>> =
        jam_wanted.then(|| per_cell(req, &x_values, &y_values, |p| model.jam_point(p)));
    let x_rigid_mm = wants(Quantity::XRigidMm)
        .then(|| per_cell(req, &x_values, &y_values, |p| statics::rigid_limit(p).1));
    let pick = |q: Quantity| points.as_ref().filter(|_| wants(q));
    Ok(GridResult {
        margin_n,
        status: pick(Quantity::Status).map(|v| v.iter().map(|p| p.status).collect()),
        theta_jam_deg: pick(Quantity::ThetaJamDeg)
            .map(|v| v.iter().map(|p| p.theta_jam_deg).collect()),
        x_jam_mm: pick(Quantity::XJamMm).map(|v| v.iter().map(|p| p.x_jam_mm).collect()),
        x_rigid_mm,
        x_values,
        y_values,
    })
}

/// `f` of every cell's scene, in parallel, in index order `iy * nx + ix`.
fn per_cell<T: Send>(
    req: &GridRequest,
    xs: &[f64],
    ys: &[f64],
    f: impl Fn(&SceneParams) -> T + Sync,
) -> Vec<T> {
    let nx = xs.len();
    (0..nx * ys.len())
        .into_par_iter()
        .map(|i| f(&req.cell_params(xs[i % nx], ys[i / nx])))
        .collect()
}

#[cfg(test)]
mod tests;
