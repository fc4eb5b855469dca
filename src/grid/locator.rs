//! The V-locator's parameters ([`LocatorParams`]) as a [`ParamSet`]: what a locator grid's
//! axes can vary.

use serde::{Deserialize, Serialize};

use rayon::prelude::*;

use super::{Cells, Grid, GridAxis, ParamSet};
use crate::error::Result;
use crate::locator::symmetric::{self, LoadDirection, LoadDirections, Row, SymmetricV, Vs};
use crate::locator::{self, Capacity, FailureMode, LocatorParams};

/// A V-locator parameter a grid axis can vary. TOML spellings are the snake_case names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LocatorParam {
    /// Included angle gamma in deg; the V turns about its bisector (tilt kept).
    IncludedAngleDeg,
    /// Direction phi of the load in deg from +x.
    LoadAngleDeg,
    /// Both flank frictions.
    Mu,
    /// The load P in N.
    LoadN,
    /// The load as a multiple of the weight, P / W (sets P).
    LoadOverW,
}

impl LocatorParam {
    /// The snake_case name.
    pub fn as_str(self) -> &'static str {
        match self {
            LocatorParam::IncludedAngleDeg => "included_angle_deg",
            LocatorParam::LoadAngleDeg => "load_angle_deg",
            LocatorParam::Mu => "mu",
            LocatorParam::LoadN => "load_n",
            LocatorParam::LoadOverW => "load_over_w",
        }
    }
}

impl ParamSet for LocatorParams {
    type Param = LocatorParam;

    fn with(self, param: LocatorParam, value: f64) -> Self {
        match param {
            LocatorParam::IncludedAngleDeg => self.with_included_angle_same_tilt(value),
            LocatorParam::LoadAngleDeg => LocatorParams {
                load_angle_deg: value,
                ..self
            },
            LocatorParam::Mu => self.with_mu(value),
            LocatorParam::LoadN => LocatorParams {
                load_n: value,
                ..self
            },
            LocatorParam::LoadOverW => LocatorParams {
                load_n: value * self.weight_n(),
                ..self
            },
        }
    }

    fn validate(&self) -> Result<()> {
        LocatorParams::validate(self)
    }

    fn param_name(param: LocatorParam) -> &'static str {
        param.as_str()
    }
}

/// The holding capacity over a locator grid, an array per answer: what a chart or an array
/// user reads off, in 9 bytes a cell ([`Capacity`] takes 40). P_max in N is W times
/// `p_max_over_w`.
#[derive(Debug, Clone, PartialEq)]
pub struct CapacityCells {
    /// Horizontal sample values.
    pub x_values: Vec<f64>,
    /// Vertical sample values (one value, NaN, for a sweep: it has a single row).
    pub y_values: Vec<f64>,
    /// P_max / W of each cell in index order, dimensionless; NaN where the cell has no
    /// largest load held: every load is held (`failure_mode` None, as numpy's maps write it)
    /// or none is.
    pub p_max_over_w: Vec<f64>,
    /// How the part leaves just beyond P_max (at every load where none is held), per cell;
    /// None where every load is held.
    pub failure_mode: Vec<Option<FailureMode>>,
}

impl CapacityCells {
    /// The cells of `cells`, each [`Capacity`] in its arrays.
    fn of(cells: Cells<Capacity>) -> Self {
        CapacityCells {
            p_max_over_w: cells
                .values
                .iter()
                .map(|c| c.p_max_over_w.unwrap_or(f64::NAN))
                .collect(),
            failure_mode: cells.values.iter().map(|c| c.failure_mode).collect(),
            x_values: cells.x_values,
            y_values: cells.y_values,
        }
    }
}

/// Cells from which a closed-form capacity map is shared among the thread pool's threads.
/// Below, the calling thread does it alone: a map of 200 x 200 cells takes about 1 ns a cell
/// on one core, and waking the pool for it made it half as slow again on a 2-core machine
/// (`cargo bench --bench locator`); from 400 x 400 the pool's threads pay for their wake.
pub(super) const PARALLEL_CELLS: usize = 1 << 17;

/// The holding capacity over a locator grid, in index order, validated first: by the closed
/// form of a symmetric V (`locator::symmetric`) when the grid varies the included
/// angle and the load direction of a V it applies to, otherwise by the exact path
/// ([`crate::locator::capacity`]) per cell. The closed form does its trigonometry once per
/// axis sample; a test checks it against the exact path cell by cell.
pub fn capacity_map(grid: &Grid<LocatorParams>) -> Result<CapacityCells> {
    use LocatorParam::{IncludedAngleDeg, LoadAngleDeg};
    let exact = || {
        grid.map(|p| Ok(locator::capacity(p)))
            .map(CapacityCells::of)
    };
    let axes = grid.y.map(|y| (grid.x.param, y.param));
    let gamma_on_x = match axes {
        Some((IncludedAngleDeg, LoadAngleDeg)) => true,
        Some((LoadAngleDeg, IncludedAngleDeg)) => false,
        _ => return exact(),
    };
    if !symmetric::applies(&grid.base) {
        return exact();
    }
    grid.validate()?;
    let x_values = grid.x.values();
    let y_values = grid.y.as_ref().map_or_else(Vec::new, GridAxis::values);
    let v_of = |g: f64| SymmetricV::of(&grid.base.with(IncludedAngleDeg, g));
    let nx = x_values.len();
    let n = nx * y_values.len();
    // Each row is written once, straight into the map's memory: the kernel writes every cell
    // of its row, so no placeholder pass comes first.
    let mut over_w = Vec::with_capacity(n);
    let mut mode = Vec::with_capacity(n);
    let (over_w_rows, mode_rows) = (
        &mut over_w.spare_capacity_mut()[..n],
        &mut mode.spare_capacity_mut()[..n],
    );
    let (vs, ds);
    let kernel: &(dyn Fn(f64, Row) + Sync) = match gamma_on_x {
        true => {
            vs = Vs::new(&x_values.iter().map(|&g| v_of(g)).collect::<Vec<_>>());
            &|phi, row| LoadDirection::new(phi).capacities(&vs, row)
        }
        false => {
            let each: Vec<LoadDirection> =
                x_values.iter().map(|&p| LoadDirection::new(p)).collect();
            ds = LoadDirections::new(&each);
            &|gamma, row| v_of(gamma).capacities(&ds, row)
        }
    };
    let row = |((over_w, mode), &y): ((&mut [_], &mut [_]), &f64)| kernel(y, Row { over_w, mode });
    match n < PARALLEL_CELLS {
        true => over_w_rows
            .chunks_mut(nx)
            .zip(mode_rows.chunks_mut(nx))
            .zip(&y_values)
            .for_each(row),
        false => over_w_rows
            .par_chunks_mut(nx)
            .zip(mode_rows.par_chunks_mut(nx))
            .zip(&y_values)
            .for_each(row),
    }
    // SAFETY: the rows cover both arrays' first n elements, and each row's kernel wrote every
    // cell of it.
    unsafe {
        over_w.set_len(n);
        mode.set_len(n);
    }
    Ok(CapacityCells {
        x_values,
        y_values,
        p_max_over_w: over_w,
        failure_mode: mode,
    })
}
