//! The parallel grid evaluator: any function of a parameter set over one or two axes.
//!
//! [`Grid`] is generic over the [`ParamSet`] it varies (the palm scene's [`SceneParams`], a
//! V-locator's parameters, ...): [`Grid::map`] evaluates a function of the cell's parameters in
//! parallel (rayon) and returns the cells in index order `iy * nx + ix` (x fastest); a sweep is
//! a one-axis grid and `at_values` the same at a list of values. Each cell is computed by the
//! same instructions whatever thread runs it and whatever the chunking, so the result is
//! bit-identical for any thread count (a test says so): no reductions across cells, no fused
//! multiply-adds chosen by the compiler.
//!
//! For the palm scene a [`GridRequest`] names the [`Quantity`]s wanted and [`evaluate`] computes
//! only those: the statics margin by a fast kernel (`margin::MarginCoeffs`), the jam point (status,
//! theta_jam, x_jam) by any model of the port ([`crate::models`]), passed in as the function
//! that answers one scene so that charts can count the calls.

mod axis;
mod locator;
mod margin;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use axis::{AxisScale, GridAxis};
pub use locator::{CapacityCells, LocatorParam, capacity_map};

use crate::error::{Error, Result};
use crate::models::{self, ModelKind, ModelSpec, Solution};
use crate::scene::{JamStatus, Param, SceneParams};

/// A set of parameters a grid can vary, one named parameter per axis.
pub trait ParamSet: Copy + Send + Sync {
    /// The parameters an axis can vary (their snake_case names are TOML keys).
    type Param: Copy + PartialEq + Send + Sync;
    /// `self` with `param` set to `value`.
    fn with(self, param: Self::Param, value: f64) -> Self;
    /// [`ParamSet::with`] of `param`, the parameter looked up once: what a loop over many
    /// cells calls.
    fn setter(param: Self::Param) -> impl Fn(Self, f64) -> Self + Sync {
        move |s: Self, v| s.with(param, v)
    }
    /// Checks every field; the error names the key and the value.
    fn validate(&self) -> Result<()>;
    /// The snake_case name of `param`, for messages and data files.
    fn param_name(param: Self::Param) -> &'static str;
    /// Checks that two axes can vary `x` and `y` together (they differ already), e.g. that
    /// neither is derived from the other; Ok by default.
    fn check_axes(_x: Self::Param, _y: Self::Param) -> Result<()> {
        Ok(())
    }
}

/// At most this many cells in one grid: 2^26, 512 MiB per quantity, far beyond any chart's
/// resolution; an axis alone may have up to 2^24 samples.
pub(crate) const MAX_CELLS: usize = 1 << 26;

/// A parameter set varied over one axis (a sweep) or two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid<S: ParamSet> {
    /// The parameters every cell starts from; the axes overwrite theirs.
    pub base: S,
    /// Horizontal axis (index ix, fastest in memory).
    pub x: GridAxis<S::Param>,
    /// Vertical axis (index iy); None for a sweep.
    pub y: Option<GridAxis<S::Param>>,
}

/// The cells of an evaluated grid, in index order `iy * nx + ix`.
#[derive(Debug, Clone, PartialEq)]
pub struct Cells<T> {
    /// Horizontal sample values.
    pub x_values: Vec<f64>,
    /// Vertical sample values (one value, NaN, for a sweep: it has a single row).
    pub y_values: Vec<f64>,
    /// One value per cell.
    pub values: Vec<T>,
}

impl<S: ParamSet> Grid<S> {
    /// Checks the axes, the cell count, and the parameters at the grid's corners (every
    /// parameter is monotone along its axis, so the corners bound the whole grid).
    pub fn validate(&self) -> Result<()> {
        self.x.validate("chart.x_axis")?;
        let mut cells = self.x.count;
        if let Some(y) = &self.y {
            y.validate("chart.y_axis")?;
            cells = cells.saturating_mul(y.count);
            if y.param == self.x.param {
                return Err(Error::invalid(
                    "chart.y_axis.param",
                    S::param_name(y.param),
                    "the two axes must vary different parameters",
                ));
            }
            S::check_axes(self.x.param, y.param)?;
        }
        if cells > MAX_CELLS {
            return Err(Error::invalid(
                "chart.x_axis.count * chart.y_axis.count",
                cells,
                format!(
                    "a grid has at most {MAX_CELLS} cells (8 bytes each per quantity); \
                     lower the counts"
                ),
            ));
        }
        self.base.validate()?;
        let ys = match &self.y {
            Some(y) => vec![Some(y.min), Some(y.max)],
            None => vec![None],
        };
        for xv in [self.x.min, self.x.max] {
            for &yv in &ys {
                self.cell(xv, yv).validate()?;
            }
        }
        Ok(())
    }

    /// The parameters of the cell at `(xv, yv)`.
    pub fn cell(&self, xv: f64, yv: Option<f64>) -> S {
        self.cells()(xv, yv)
    }

    /// [`Grid::cell`] with the axes' parameters looked up once, for a loop over the cells (a
    /// lookup by name per cell was 9 % of `render fig7c`).
    fn cells(&self) -> impl Fn(f64, Option<f64>) -> S + Sync + '_ {
        let set_x = S::setter(self.x.param);
        let set_y = self.y.as_ref().map(|y| S::setter(y.param));
        move |xv, yv| {
            let p = set_x(self.base, xv);
            match (&set_y, yv) {
                (Some(set_y), Some(v)) => set_y(p, v),
                _ => p,
            }
        }
    }

    /// `f` of every cell's parameters, in parallel, in index order; validated first. The first
    /// error in index order is returned.
    pub fn map<T: Send>(&self, f: impl Fn(&S) -> Result<T> + Sync) -> Result<Cells<T>> {
        self.validate()?;
        let x_values = self.x.values();
        let y_values = self.y.as_ref().map_or(vec![f64::NAN], GridAxis::values);
        let nx = x_values.len();
        let has_y = self.y.is_some();
        let cell = self.cells();
        let values: Vec<Result<T>> = (0..nx * y_values.len())
            .into_par_iter()
            .map(|i| {
                let yv = has_y.then(|| y_values[i / nx]);
                f(&cell(x_values[i % nx], yv))
            })
            .collect();
        Ok(Cells {
            values: values.into_iter().collect::<Result<_>>()?,
            x_values,
            y_values,
        })
    }
}

impl<S: ParamSet + Sync> Grid<S> {
    /// `f` of each column's cells (x fixed, y ascending), columns in parallel; the cells are
    /// returned in index order, validated first. A column is one call, so a model may carry each
    /// cell's answer to the next (the min-norm bisection brackets its jam from its neighbours)
    /// and the values do not depend on the thread count. `f` returns one value per cell of its
    /// column; the first error in column order is returned.
    pub fn map_columns<T: Send>(
        &self,
        f: impl Fn(&[S]) -> Result<Vec<T>> + Sync,
    ) -> Result<Cells<T>> {
        self.validate()?;
        let x_values = self.x.values();
        let y_values = self.y.as_ref().map_or(vec![f64::NAN], GridAxis::values);
        let has_y = self.y.is_some();
        let cell = self.cells();
        let columns: Vec<Result<Vec<T>>> = x_values
            .par_iter()
            .map(|&xv| {
                let scenes: Vec<S> = y_values
                    .iter()
                    .map(|&yv| cell(xv, has_y.then_some(yv)))
                    .collect();
                f(&scenes)
            })
            .collect();
        let mut columns = columns
            .into_iter()
            .map(|c| c.map(Vec::into_iter))
            .collect::<Result<Vec<_>>>()?;
        let mut values = Vec::with_capacity(x_values.len() * y_values.len());
        for _ in &y_values {
            for column in &mut columns {
                values.push(column.next().expect("one value per cell of the column"));
            }
        }
        Ok(Cells {
            values,
            x_values,
            y_values,
        })
    }
}

/// `f` at `base` with `param` set to each of `values`, in parallel, in order: a sweep at given
/// points (e.g. the paper's Table 1 mu values). The first error in order is returned.
pub(crate) fn at_values<S: ParamSet, T: Send>(
    base: &S,
    param: S::Param,
    values: &[f64],
    f: impl Fn(&S) -> Result<T> + Sync,
) -> Result<Vec<T>> {
    let out: Vec<Result<T>> = values
        .par_iter()
        .map(|&v| f(&base.with(param, v)))
        .collect();
    out.into_iter().collect()
}

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

/// What a model says about one push: the part of its [`Solution`] a grid or chart needs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct JamPoint {
    /// Outcome of the push.
    pub status: JamStatus,
    /// Palm angle at the jam in deg (None when the model gives none).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm (None when the model gives none).
    pub x_jam_mm: Option<f64>,
}

impl From<&Solution> for JamPoint {
    fn from(s: &Solution) -> Self {
        JamPoint {
            status: s.status,
            theta_jam_deg: s.theta_jam_deg,
            x_jam_mm: s.x_jam_mm,
        }
    }
}

/// The closed-form jam point of `p`, through the port ([`models::solve`]) so that its "outside
/// the model" rule applies: a sweep that called the statics directly drew a jam for a push
/// starting above 90 deg, where `solve` says `outside_model`.
pub fn statics_point(p: &SceneParams) -> Result<JamPoint> {
    models::solve(&ModelSpec::Statics, p).map(|s| JamPoint::from(&s))
}

/// The closed form's F -> infinity limit of a valid scene `p` (theta_rigid in deg, x_rigid in
/// mm) under the port's rules, as [`models::solve`] reports it in the closed form's detail: a
/// scene outside the closed form (`models::outside`) has none. A test checks it against that
/// detail. The scene is a cell of a grid whose corners were checked ([`Grid::validate`]):
/// checking every cell's scene again was 9 % of `render fig7c`'s instructions.
pub(crate) fn rigid_point(p: &SceneParams) -> Option<(f64, Option<f64>)> {
    // What `models::solve` reports as the closed form's detail, without solving for the jam.
    let outside = models::outside(ModelKind::Statics, p).is_some();
    (!outside).then(|| crate::statics::rigid_limit(p))
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
    #[cfg(test)]
    pub fn index(&self, ix: usize, iy: usize) -> usize {
        iy * self.nx() + ix
    }
}

impl GridRequest {
    /// The generic grid of this request.
    pub fn grid(&self) -> Grid<SceneParams> {
        Grid {
            base: self.base,
            x: self.x,
            y: Some(self.y),
        }
    }

    /// Checks the axes, the base scene and the scene at the corners of the grid.
    pub fn validate(&self) -> Result<()> {
        self.grid().validate()?;
        for axis in [&self.x, &self.y] {
            if axis.param == Param::ThetaDeg && !(axis.min >= 0.0 && axis.max <= 180.0) {
                return Err(Error::invalid(
                    "theta_deg axis",
                    format!("{}..{}", axis.min, axis.max),
                    "the palm angle axis must lie within 0..180 deg",
                ));
            }
        }
        let has_theta = [self.x.param, self.y.param].contains(&Param::ThetaDeg);
        if self.quantities.contains(&Quantity::MarginN) && !has_theta {
            return Err(Error::invalid(
                "quantities",
                "margin_n",
                "the margin needs a theta_deg axis (the palm angle at which it is evaluated)",
            ));
        }
        Ok(())
    }
}

/// Evaluates the requested quantities over the grid, in parallel; `jam_point` answers one
/// scene (any model of the port, e.g. `|p| Ok(JamPoint::from(&models::solve(&spec, p)?))`).
///
/// The margin always comes from the closed-form statics (it is that model's quantity); the jam
/// point from `jam_point`, called only when a jam quantity is wanted. Bit-identical for any
/// rayon thread count.
pub fn evaluate(
    req: &GridRequest,
    jam_point: impl Fn(&SceneParams) -> Result<JamPoint> + Sync,
) -> Result<GridResult> {
    evaluate_with(req, JamPoints::Cells(&jam_point))
}

/// [`evaluate`] with the jam points answered a column at a time (x fixed, y ascending, columns
/// in parallel): `jam_column` answers one column's scenes in order, so a model may carry each
/// cell's answer to the next (the min-norm model: [`models::solve_column`]). Bit-identical for
/// any rayon thread count, as a column is one call.
pub fn evaluate_columns(
    req: &GridRequest,
    jam_column: impl Fn(&[SceneParams]) -> Result<Vec<JamPoint>> + Sync,
) -> Result<GridResult> {
    evaluate_with(req, JamPoints::Columns(&jam_column))
}

/// [`evaluate`] with the closed-form statics' jam points, answered in batches of cells
/// ([`models::columns::solve_into`]: the axes' values as columns, no scene built and no clock
/// read per cell), each cell's bit for bit as [`models::solve`] gives it alone. A palm-angle
/// axis (a margin map's) is no column of pushes: such a grid's cells go one by one.
pub fn evaluate_closed_form(req: &GridRequest) -> Result<GridResult> {
    if req.x.param == Param::ThetaDeg || req.y.param == Param::ThetaDeg {
        evaluate(req, statics_point)
    } else {
        evaluate_with(req, JamPoints::ClosedForm)
    }
}

/// How a grid's jam points are answered: cell by cell, a column at a time, or by the closed
/// form's batches.
enum JamPoints<'a> {
    Cells(&'a (dyn Fn(&SceneParams) -> Result<JamPoint> + Sync)),
    Columns(&'a (dyn Fn(&[SceneParams]) -> Result<Vec<JamPoint>> + Sync)),
    ClosedForm,
}

/// The closed form's jam point of every cell of `grid` (no palm-angle axis), in index order,
/// validated first ([`evaluate_closed_form`]).
fn closed_form_points(grid: &Grid<SceneParams>) -> Result<Cells<JamPoint>> {
    use models::columns::{Answers, Pushes, solve_into};
    grid.validate()?;
    let x_values = grid.x.values();
    let y_values = grid.y.as_ref().map_or(vec![f64::NAN], GridAxis::values);
    let nx = x_values.len();
    let n = nx * y_values.len();
    let xs: Vec<f64> = (0..n).map(|i| x_values[i % nx]).collect();
    let ys: Vec<f64> = match grid.y {
        Some(_) => (0..n).map(|i| y_values[i / nx]).collect(),
        None => Vec::new(),
    };
    // In the order a cell sets them: x first, then y.
    let mut columns = vec![(grid.x.param, xs.as_slice())];
    if let Some(y) = &grid.y {
        columns.push((y.param, ys.as_slice()));
    }
    let pushes = Pushes {
        base: grid.base,
        columns,
    };
    let (mut status, mut theta, mut x) = (vec![0; n], vec![0.0; n], vec![0.0; n]);
    let out = Answers {
        status: &mut status,
        theta_jam_deg: &mut theta,
        x_jam_mm: &mut x,
        past_palm_x_jam_mm: None,
    };
    solve_into(&ModelSpec::Statics, &pushes, out)?;
    let some = |v: f64| (!v.is_nan()).then_some(v);
    let values = (status.iter().zip(&theta).zip(&x))
        .map(|((&s, &t), &x)| JamPoint {
            status: JamStatus::ALL[usize::from(s)],
            theta_jam_deg: some(t),
            x_jam_mm: some(x),
        })
        .collect();
    Ok(Cells {
        x_values,
        y_values,
        values,
    })
}

fn evaluate_with(req: &GridRequest, jam: JamPoints) -> Result<GridResult> {
    req.validate()?;
    let grid = req.grid();
    let wants = |q| req.quantities.contains(&q);
    let jam_wanted =
        wants(Quantity::Status) || wants(Quantity::ThetaJamDeg) || wants(Quantity::XJamMm);
    let points = jam_wanted
        .then(|| match jam {
            JamPoints::Cells(f) => grid.map(f),
            JamPoints::Columns(f) => grid.map_columns(f),
            JamPoints::ClosedForm => closed_form_points(&grid),
        })
        .transpose()?;
    let x_rigid_mm = wants(Quantity::XRigidMm)
        .then(|| grid.map(|p| Ok(rigid_point(p).and_then(|(_, x)| x))))
        .transpose()?
        .map(|c| c.values);
    let (x_values, y_values) = (req.x.values(), req.y.values());
    let margin_n = wants(Quantity::MarginN).then(|| margin::margin_grid(req, &x_values, &y_values));
    let pick = |q: Quantity| points.as_ref().filter(|_| wants(q)).map(|c| &c.values);
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

#[cfg(test)]
mod tests;
