//! A V-locator's holding capacity map: P_max / W of a V over its included angle and the load
//! direction, on the locator's exact path ([`crate::locator::capacity`]), with the included
//! angle below which it self-locks and what the standard V-blocks hold sideways.

use serde::{Deserialize, Serialize};

use super::cells::{self, CellsTable, HasCells};
use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::csv_out::Column;
use crate::error::{Error, Result};
use crate::grid::{Grid, GridAxis, LocatorParam};
use crate::locator::{self, Capacity, LocatorParams, Rotation};

/// The standard V-blocks a fixture designer buys, included angle in deg.
pub const STANDARD_V_DEG: [f64; 3] = [60.0, 90.0, 120.0];

/// A capacity standing for "unbounded", in multiples of W: above every level a map may draw.
pub const UNBOUNDED_OVER_W: f64 = 1e3;

/// `[chart]` keys of `kind = "vlocator_capacity"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VlocatorCapacitySettings {
    /// The V, friction, rotation and load point (default: [`LocatorParams::default`]); the
    /// axes set the included angle and the load direction.
    #[serde(default)]
    pub locator: LocatorParams,
    /// Horizontal axis: `included_angle_deg`.
    pub x_axis: GridAxis<LocatorParam>,
    /// Vertical axis: `load_angle_deg`.
    pub y_axis: GridAxis<LocatorParam>,
    /// Capacity iso-lines, multiples of W, increasing; the bands between them are shaded.
    pub levels_over_w: Vec<f64>,
}

const CELLS: &str = "chart.x_axis.count * chart.y_axis.count";

impl Figure for VlocatorCapacitySettings {
    type Data = VlocatorCapacityData;

    /// The V-block's parameters are `[chart.locator]`'s, not the palm scene's.
    fn takes_scene(&self) -> bool {
        false
    }

    /// Checks the axes and levels (and the locator at the grid's corners).
    fn validate(&self, _input: &Input) -> Result<()> {
        if self.x_axis.param != LocatorParam::IncludedAngleDeg {
            return Err(Error::invalid(
                "chart.x_axis.param",
                self.x_axis.param.as_str(),
                "the capacity map has the included angle on x: use included_angle_deg",
            ));
        }
        if self.y_axis.param != LocatorParam::LoadAngleDeg {
            return Err(Error::invalid(
                "chart.y_axis.param",
                self.y_axis.param.as_str(),
                "the capacity map has the load direction on y: use load_angle_deg",
            ));
        }
        let l = &self.levels_over_w;
        if l.is_empty()
            || !l.windows(2).all(|w| w[0] < w[1])
            || !l
                .iter()
                .all(|v| v.is_finite() && *v > 0.0 && *v < UNBOUNDED_OVER_W)
        {
            return Err(Error::invalid(
                "chart.levels_over_w",
                format!("{l:?}"),
                "give increasing levels in (0, 1000) W",
            ));
        }
        self.grid().validate()
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        // A contoured map as the contour map is (its cells hold less: two capacities).
        crate::limits::check_count(
            "chart.levels_over_w",
            self.levels_over_w.len(),
            crate::limits::MAX_LEVELS,
            "levels",
        )?;
        let cells = self.x_axis.count as f64 * self.y_axis.count as f64;
        crate::limits::check_items(CELLS, cells, crate::limits::VLOCATOR_CAPACITY_CELL)
    }

    /// P_max / W on every cell by the exact path, through the grid; the locator's own model,
    /// so nothing goes through `models`.
    fn compute(&self, _input: &Input, _models: &dyn Models) -> Result<VlocatorCapacityData> {
        // Where the V locks every load is held; the capacity of the V just unlocked lets the
        // iso-lines run on under the locking band instead of piling up on its edge.
        let cells = self.grid().map(|p| {
            let unlocked = locator::capacity(&locator::just_unlocked(p));
            Ok((locator::capacity(p), unlocked))
        })?;
        let over_w = |c: &Capacity| match (c.unbounded, c.p_max_over_w) {
            (true, _) => None,
            (false, v) => Some(v.unwrap_or(0.0)),
        };
        let (x, y) = (&self.x_axis, &self.y_axis);
        // What a standard V holds sideways, where the map has both its angle and sideways.
        let sideways = match (y.min..=y.max).contains(&0.0) {
            true => STANDARD_V_DEG
                .into_iter()
                .filter(|g| (x.min..=x.max).contains(g))
                .map(|g| StandardV {
                    included_angle_deg: g,
                    sideways: locator::capacity(&self.locator.with_included_angle_same_tilt(g)),
                })
                .collect(),
            false => Vec::new(),
        };
        Ok(VlocatorCapacityData {
            settings: self.clone(),
            weight_n: self.locator.weight_n(),
            self_locking_below_included_angle_deg: locking_angle_deg(&self.locator),
            standard_v_blocks: sideways,
            cells: VlocatorCapacityCells {
                p_max_over_w: cells.values.iter().map(|c| over_w(&c.0)).collect(),
                unlocked_over_w: cells.values.iter().map(|c| over_w(&c.1)).collect(),
                included_angle_deg: cells.x_values,
                load_angle_deg: cells.y_values,
            },
        })
    }
}

impl VlocatorCapacitySettings {
    fn grid(&self) -> Grid<LocatorParams> {
        Grid {
            base: self.locator,
            x: self.x_axis,
            y: Some(self.y_axis),
        }
    }
}

/// The computed capacity map: its serde form is its data file (the cells go to the CSV
/// beside it, summarised under `cells`).
#[derive(Debug, Clone, Serialize)]
pub struct VlocatorCapacityData {
    /// The settings it was computed with (locator, axes, levels).
    #[serde(flatten)]
    pub settings: VlocatorCapacitySettings,
    /// The disc's weight W = m g in N.
    pub weight_n: f64,
    /// The included angle below which the V self-locks, deg ([`locking_angle_deg`]).
    pub self_locking_below_included_angle_deg: f64,
    /// The standard V-blocks on the map's angles, with their capacity at `[chart.locator]`'s
    /// load direction (sideways, phi = 0, by default); none when the map's load directions
    /// leave sideways out.
    pub standard_v_blocks: Vec<StandardV>,
    /// P_max / W per cell.
    #[serde(serialize_with = "cells::summary_of")]
    pub cells: VlocatorCapacityCells,
}

impl FigureData for VlocatorCapacityData {
    const FORMAT: DataFormat = DataFormat::Json;
    const CELLS: bool = true;

    fn cells(&self) -> Option<CellsTable<'_>> {
        Some(self.cells.table())
    }
}

/// A standard V-block and what it holds sideways.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StandardV {
    /// Its included angle in deg ([`STANDARD_V_DEG`]).
    pub included_angle_deg: f64,
    /// Its capacity at `[chart.locator]`'s load direction (sideways, phi = 0, by default).
    pub sideways: Capacity,
}

/// A capacity map's cells (x fastest, index `iy * nx + ix`).
#[derive(Debug, Clone)]
pub struct VlocatorCapacityCells {
    /// The included angles in deg.
    pub included_angle_deg: Vec<f64>,
    /// The load directions in deg from +x.
    pub load_angle_deg: Vec<f64>,
    /// P_max / W (None: unbounded, every load held).
    pub p_max_over_w: Vec<Option<f64>>,
    /// P_max / W of the same V with friction just below locking
    /// (`locator::just_unlocked`): where the V locks, the capacity the iso-lines follow
    /// under the locking band; elsewhere `p_max_over_w`. Not in the CSV.
    pub unlocked_over_w: Vec<Option<f64>>,
}

impl HasCells for VlocatorCapacityCells {
    fn table(&self) -> CellsTable<'_> {
        let axes = [
            (
                LocatorParam::IncludedAngleDeg.as_str(),
                &self.included_angle_deg[..],
            ),
            (
                LocatorParam::LoadAngleDeg.as_str(),
                &self.load_angle_deg[..],
            ),
        ];
        CellsTable::new(
            axes,
            &[("p_max_over_w", Column::Sparse(&self.p_max_over_w))],
        )
    }
}

/// The included angle below which a symmetric V with `p`'s friction self-locks, deg:
/// 2 atan(min mu) free, atan mu1 + atan mu2 blocked.
pub fn locking_angle_deg(p: &LocatorParams) -> f64 {
    match p.rotation {
        Rotation::Free => 2.0 * p.mu_left.min(p.mu_right).atan().to_degrees(),
        Rotation::Blocked => (p.mu_left.atan() + p.mu_right.atan()).to_degrees(),
    }
}
