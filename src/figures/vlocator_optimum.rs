//! A V-locator's optimum included angle: the balanced optimum gamma* of a V and its safety
//! factor rho* against the load direction (at a given P / W) and against P / W (at a given
//! direction), one curve per friction coefficient ([`crate::locator::optimum`]).

use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::error::{Error, Result};
use crate::grid::{Grid, GridAxis, LocatorParam};
use crate::locator::{self, LocatorParams, Optimum};

/// Most friction curves: each has a marker of its own, and the chart has five.
pub const MAX_MUS: usize = 5;

/// `[chart]` keys of `kind = "vlocator_optimum"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VlocatorOptimumSettings {
    /// The V's tilt, rotation, load point and weight (default: [`LocatorParams::default`]);
    /// the included angle is the unknown, the axes and `mus` set the rest.
    #[serde(default)]
    pub locator: LocatorParams,
    /// One curve per friction coefficient (both flanks), increasing.
    pub mus: Vec<f64>,
    /// Upper panels: the load direction axis (`load_angle_deg`).
    pub direction_axis: GridAxis<LocatorParam>,
    /// P / W of the upper panels.
    pub p_over_w: f64,
    /// Lower panels: the load axis (`load_over_w`), at the locator's load direction.
    pub load_axis: GridAxis<LocatorParam>,
}

impl Figure for VlocatorOptimumSettings {
    type Data = VlocatorOptimumData;

    /// The V-block's parameters are `[chart.locator]`'s, not the palm scene's.
    fn takes_scene(&self) -> bool {
        false
    }

    /// Checks the axes, the frictions and the load.
    fn validate(&self, _input: &Input) -> Result<()> {
        if self.direction_axis.param != LocatorParam::LoadAngleDeg {
            return Err(Error::invalid(
                "chart.direction_axis.param",
                self.direction_axis.param.as_str(),
                "use load_angle_deg",
            ));
        }
        if self.load_axis.param != LocatorParam::LoadOverW {
            return Err(Error::invalid(
                "chart.load_axis.param",
                self.load_axis.param.as_str(),
                "use load_over_w",
            ));
        }
        let m = &self.mus;
        if m.is_empty()
            || m.len() > MAX_MUS
            || !m.windows(2).all(|w| w[0] < w[1])
            || !m.iter().all(|v| v.is_finite() && *v > 0.0)
        {
            return Err(Error::invalid(
                "chart.mus",
                format!("{m:?}"),
                format!("give 1 to {MAX_MUS} increasing frictions > 0"),
            ));
        }
        if !(self.p_over_w.is_finite() && self.p_over_w > 0.0) {
            return Err(Error::invalid(
                "chart.p_over_w",
                self.p_over_w,
                "the load of the direction panels is a finite P / W > 0",
            ));
        }
        for mu in m {
            for g in self.grids(*mu) {
                g.validate()?;
            }
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        // At most five curves (one per marker) of two sweeps.
        let n = (self.direction_axis.count + self.load_axis.count) as f64 * self.mus.len() as f64;
        // Work, not only memory: each point is a search over the included angle.
        let max = crate::limits::MAX_OPTIMUM_POINTS;
        if n > max as f64 {
            return Err(Error::invalid(
                "chart.direction_axis.count + chart.load_axis.count",
                format!("{n} optima ({} mus)", self.mus.len()),
                format!(
                    "a V-block optimum chart computes at most {max} optima (about 25 s on 2 \
                     cores); lower the counts or the number of mus"
                ),
            ));
        }
        crate::limits::check_items(
            "chart.direction_axis.count + chart.load_axis.count",
            n,
            crate::limits::SWEEP_POINT,
        )
    }

    /// The optimum at every sample of both sweeps, through the grid; the locator's own model,
    /// so nothing goes through `models`.
    fn compute(&self, _input: &Input, _models: &dyn Models) -> Result<VlocatorOptimumData> {
        let mut curves = Vec::with_capacity(self.mus.len());
        let (mut directions, mut loads) = (Vec::new(), Vec::new());
        for &mu in &self.mus {
            let [by_dir, by_load] = self.grids(mu);
            let d = by_dir.map(|p| Ok(locator::optimum(p)))?;
            let l = by_load.map(|p| Ok(locator::optimum(p)))?;
            directions = d.x_values;
            loads = l.x_values;
            curves.push(MuCurves {
                mu,
                by_direction: d.values,
                by_load: l.values,
            });
        }
        Ok(VlocatorOptimumData {
            settings: self.clone(),
            load_angle_deg: directions,
            load_over_w: loads,
            curves,
        })
    }
}

impl VlocatorOptimumSettings {
    /// The two sweeps at friction `mu`: over the direction, over the load.
    fn grids(&self, mu: f64) -> [Grid<LocatorParams>; 2] {
        let base = self.locator.with_mu(mu);
        let at_load = LocatorParams {
            load_n: self.p_over_w * base.weight_n(),
            ..base
        };
        [
            Grid {
                base: at_load,
                x: self.direction_axis,
                y: None,
            },
            Grid {
                base,
                x: self.load_axis,
                y: None,
            },
        ]
    }
}

/// One friction's two sweeps.
#[derive(Debug, Clone, Serialize)]
pub struct MuCurves {
    /// The friction coefficient of both flanks.
    pub mu: f64,
    /// Optimum per load direction (the direction axis' values), at P / W = `p_over_w`.
    pub by_direction: Vec<Optimum>,
    /// Optimum per P / W (the load axis' values), at the locator's load direction.
    pub by_load: Vec<Optimum>,
}

/// The computed optimum chart: its serde form is its data file.
#[derive(Debug, Clone, Serialize)]
pub struct VlocatorOptimumData {
    /// The settings it was computed with (locator, frictions, axes, P / W of the direction
    /// sweep).
    #[serde(flatten)]
    pub settings: VlocatorOptimumSettings,
    /// The load directions of the direction sweep, deg.
    pub load_angle_deg: Vec<f64>,
    /// The loads P / W of the load sweep.
    pub load_over_w: Vec<f64>,
    /// Both sweeps per friction, in the order of `mus`.
    pub curves: Vec<MuCurves>,
}

impl FigureData for VlocatorOptimumData {
    const FORMAT: DataFormat = DataFormat::Json;
}
