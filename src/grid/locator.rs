//! The V-locator's parameters ([`LocatorParams`]) as a [`ParamSet`]: what a locator grid's
//! axes can vary.

use serde::{Deserialize, Serialize};

use rayon::prelude::*;

use super::{Cells, Grid, GridAxis, ParamSet};
use crate::error::Result;
use crate::locator::symmetric::{self, LoadDirection, LoadDirections, SymmetricV, Vs};
use crate::locator::{self, Capacity, LocatorParams};

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

/// The holding capacity over a locator grid, in index order, validated first: by the closed
/// form of a symmetric V (`locator::symmetric`) when the grid varies the included
/// angle and the load direction of a V it applies to, otherwise by the exact path
/// ([`crate::locator::capacity`]) per cell. The closed form does its trigonometry once per
/// axis sample; a test checks it against the exact path cell by cell.
pub fn capacity_map(grid: &Grid<LocatorParams>) -> Result<Cells<Capacity>> {
    use LocatorParam::{IncludedAngleDeg, LoadAngleDeg};
    let axes = grid.y.map(|y| (grid.x.param, y.param));
    let gamma_on_x = match axes {
        Some((IncludedAngleDeg, LoadAngleDeg)) => true,
        Some((LoadAngleDeg, IncludedAngleDeg)) => false,
        _ => return grid.map(|p| Ok(locator::capacity(p))),
    };
    if !symmetric::applies(&grid.base) {
        return grid.map(|p| Ok(locator::capacity(p)));
    }
    grid.validate()?;
    let x_values = grid.x.values();
    let y_values = grid.y.as_ref().map_or_else(Vec::new, GridAxis::values);
    let v_of = |g: f64| SymmetricV::of(&grid.base.with(IncludedAngleDeg, g));
    let weight_n = grid.base.weight_n();
    let nx = x_values.len();
    let n = nx * y_values.len();
    // Each row is written once, straight into the map's memory: the kernel writes every cell
    // of its row (`capacities`), so no placeholder pass over the 40-byte cells comes first.
    let mut values = Vec::with_capacity(n);
    let rows = values.spare_capacity_mut()[..n].par_chunks_mut(nx);
    match gamma_on_x {
        true => {
            let vs = Vs::new(&x_values.iter().map(|&g| v_of(g)).collect::<Vec<_>>());
            rows.zip(&y_values)
                .for_each(|(row, &phi)| LoadDirection::new(phi).capacities(&vs, weight_n, row));
        }
        false => {
            let ds: Vec<LoadDirection> = x_values.iter().map(|&p| LoadDirection::new(p)).collect();
            let ds = LoadDirections::new(&ds);
            rows.zip(&y_values)
                .for_each(|(row, &g)| v_of(g).capacities(&ds, weight_n, row));
        }
    }
    // SAFETY: the rows cover values[..n], and each row's kernel wrote every cell of it.
    unsafe { values.set_len(n) };
    Ok(Cells {
        x_values,
        y_values,
        values,
    })
}
