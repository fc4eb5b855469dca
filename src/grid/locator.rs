//! The V-locator's parameters ([`LocatorParams`]) as a [`ParamSet`]: what a locator grid's
//! axes can vary.

use serde::{Deserialize, Serialize};

use rayon::prelude::*;

use super::{Cells, Grid, GridAxis, ParamSet};
use crate::error::Result;
use crate::locator::symmetric::{self, LoadDirection, SymmetricV};
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
/// form of a symmetric V ([`crate::locator::symmetric`]) when the grid varies the included
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
    let (gammas, phis) = match gamma_on_x {
        true => (&x_values, &y_values),
        false => (&y_values, &x_values),
    };
    let vs: Vec<SymmetricV> = gammas
        .iter()
        .map(|&g| SymmetricV::of(&grid.base.with(IncludedAngleDeg, g)))
        .collect();
    let ds: Vec<LoadDirection> = phis.iter().map(|&phi| LoadDirection::new(phi)).collect();
    let weight_n = grid.base.weight_n();
    let nx = x_values.len();
    let mut values = vec![PLACEHOLDER; nx * y_values.len()];
    values.par_chunks_mut(nx).enumerate().for_each(|(iy, row)| {
        for (ix, cell) in row.iter_mut().enumerate() {
            *cell = match gamma_on_x {
                true => vs[ix].capacity(&ds[iy], weight_n),
                false => vs[iy].capacity(&ds[ix], weight_n),
            };
        }
    });
    Ok(Cells {
        x_values,
        y_values,
        values,
    })
}

/// What every cell of [`capacity_map`]'s closed-form path holds before it is computed.
const PLACEHOLDER: Capacity = Capacity {
    p_max_n: None,
    p_max_over_w: None,
    unbounded: false,
    failure_mode: None,
};
