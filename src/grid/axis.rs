//! One axis of a grid: which parameter it varies, over which range, how finely; and the palm
//! scene's parameters ([`Param`]) as a [`ParamSet`].

use serde::{Deserialize, Serialize};

use super::ParamSet;
use crate::error::{Error, Result};
use crate::scene::{Param, SceneParams};

impl ParamSet for SceneParams {
    type Param = crate::scene::Param;

    fn with(self, param: Param, value: f64) -> Self {
        param.apply(self, value)
    }

    fn setter(param: Param) -> impl Fn(Self, f64) -> Self + Sync {
        param.setter()
    }

    fn validate(&self) -> Result<()> {
        SceneParams::validate(self)
    }

    fn param_name(param: Param) -> &'static str {
        param.as_str()
    }

    /// `push_ratio` sets the push from the cell's weight, so it cannot share a grid with the
    /// push, the mass or gravity: the order of the axes would decide the cell.
    fn check_axes(x: Param, y: Param) -> Result<()> {
        let derived = [Param::ForceN, Param::MassKg, Param::GravityMS2];
        for (a, b) in [(x, y), (y, x)] {
            if a == Param::PushRatio && derived.contains(&b) {
                return Err(Error::invalid(
                    "x_axis/y_axis",
                    format!("push_ratio with {}", b.as_str()),
                    "push_ratio sets force_n from the mass and gravity; vary it against \
                     another parameter",
                ));
            }
        }
        Ok(())
    }
}

/// How the samples of an axis are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AxisScale {
    /// Equal steps in the value.
    #[default]
    Linear,
    /// Equal steps in the logarithm of the value (min > 0).
    Log,
}

/// One grid axis: `count` samples of `param` from `min` to `max` inclusive.
///
/// `P` is the parameter type of the `ParamSet` the axis varies: [`Param`] for the palm
/// scene (the default), the locator's for a V-locator.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridAxis<P = Param> {
    /// The parameter varied along this axis.
    pub param: P,
    /// First sample, in the parameter's unit.
    pub min: f64,
    /// Last sample, in the parameter's unit (> min).
    pub max: f64,
    /// Number of samples, >= 2.
    pub count: usize,
    /// Spacing of the samples (default: linear).
    #[serde(default)]
    pub scale: AxisScale,
}

impl<P: Copy> GridAxis<P> {
    /// A linear axis.
    pub fn linear(param: P, min: f64, max: f64, count: usize) -> Self {
        GridAxis {
            param,
            min,
            max,
            count,
            scale: AxisScale::Linear,
        }
    }

    /// A logarithmic axis.
    pub fn log(param: P, min: f64, max: f64, count: usize) -> Self {
        GridAxis {
            scale: AxisScale::Log,
            ..Self::linear(param, min, max, count)
        }
    }

    /// Checks the range; `key` names the axis in the message (e.g. `x_axis`).
    pub fn validate(&self, key: &str) -> Result<()> {
        if !(self.min.is_finite() && self.max.is_finite() && self.min < self.max) {
            return Err(Error::invalid(
                &format!("{key}.min/max"),
                format!("{}..{}", self.min, self.max),
                "an axis needs finite min < max",
            ));
        }
        if self.scale == AxisScale::Log && self.min <= 0.0 {
            return Err(Error::invalid(
                &format!("{key}.min"),
                self.min,
                "a log axis needs min > 0",
            ));
        }
        // Every sample, not just the ends: the samples are min + (max - min) t or
        // min (max/min)^t, finite for every t in [0, 1] exactly when the span is. A sweep of
        // force_n from 1e-300 to 1e300 on a log axis once wrote 39 rows without a force.
        let (span, what) = match self.scale {
            AxisScale::Linear => (self.max - self.min, "max - min"),
            AxisScale::Log => (self.max / self.min, "max / min"),
        };
        if !span.is_finite() {
            return Err(Error::invalid(
                &format!("{key}.min/max"),
                format!("{}..{}", self.min, self.max),
                format!(
                    "{what} overflows a 64-bit float, so the samples between the ends would not \
                     be numbers; narrow the range"
                ),
            ));
        }
        // 2^24 samples per axis keeps a grid's index arithmetic and memory sane.
        if !(2..=1 << 24).contains(&self.count) {
            return Err(Error::invalid(
                &format!("{key}.count"),
                self.count,
                "an axis needs between 2 and 16777216 samples",
            ));
        }
        Ok(())
    }

    /// The value of sample `i` (0 = min, count - 1 = max exactly).
    pub fn value(&self, i: usize) -> f64 {
        if i + 1 >= self.count {
            return self.max;
        }
        let t = i as f64 / (self.count - 1) as f64;
        match self.scale {
            AxisScale::Linear => self.min + (self.max - self.min) * t,
            AxisScale::Log => self.min * (self.max / self.min).powf(t),
        }
    }

    /// All sample values in order.
    pub fn values(&self) -> Vec<f64> {
        (0..self.count).map(|i| self.value(i)).collect()
    }
}
