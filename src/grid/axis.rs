//! One axis of a grid: which parameter it varies, over which range, how finely; and the palm
//! scene's parameters ([`GridParam`]) as a [`ParamSet`].

use serde::{Deserialize, Serialize};

use super::ParamSet;
use crate::error::{Error, Result};
use crate::model::SceneParams;

/// A scene parameter a grid axis can vary. TOML/JSON spellings are the snake_case names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GridParam {
    /// The paper's single mu: sets mu_ground and mu_palm together.
    Mu,
    /// Friction coefficient at the ground contact A.
    MuGround,
    /// Friction coefficient at the palm contact B.
    MuPalm,
    /// Disc radius r in mm (the mass stays as set: the paper's Fig. 7a).
    RadiusMm,
    /// Disc mass m in kg.
    MassKg,
    /// Palm push F in N.
    ForceN,
    /// Gravitational acceleration g in m/s^2.
    GravityMS2,
    /// Palm angle where the push starts, in deg.
    StartAngleDeg,
    /// Palm length in mm.
    PalmLengthMm,
    /// The palm angle theta in deg at which the margin is evaluated: not a scene parameter but the
    /// state of the push, so it only feeds [`super::Quantity::MarginN`].
    ThetaDeg,
}

impl GridParam {
    /// The snake_case name, as in TOML and in CSV headers.
    pub fn as_str(self) -> &'static str {
        match self {
            GridParam::Mu => "mu",
            GridParam::MuGround => "mu_ground",
            GridParam::MuPalm => "mu_palm",
            GridParam::RadiusMm => "radius_mm",
            GridParam::MassKg => "mass_kg",
            GridParam::ForceN => "force_n",
            GridParam::GravityMS2 => "gravity_m_s2",
            GridParam::StartAngleDeg => "start_angle_deg",
            GridParam::PalmLengthMm => "palm_length_mm",
            GridParam::ThetaDeg => "theta_deg",
        }
    }

    /// The value of this parameter in `p` (mu reads mu_ground); None for [`GridParam::ThetaDeg`].
    pub fn get(self, p: &SceneParams) -> Option<f64> {
        Some(match self {
            GridParam::Mu | GridParam::MuGround => p.mu_ground,
            GridParam::MuPalm => p.mu_palm,
            GridParam::RadiusMm => p.radius_mm,
            GridParam::MassKg => p.mass_kg,
            GridParam::ForceN => p.force_n,
            GridParam::GravityMS2 => p.gravity_m_s2,
            GridParam::StartAngleDeg => p.start_angle_deg,
            GridParam::PalmLengthMm => p.palm_length_mm,
            GridParam::ThetaDeg => return None,
        })
    }

    /// `p` with this parameter set to `v`; [`GridParam::ThetaDeg`] leaves `p` unchanged.
    pub fn apply(self, mut p: SceneParams, v: f64) -> SceneParams {
        match self {
            GridParam::Mu => return p.with_mu(v),
            GridParam::MuGround => p.mu_ground = v,
            GridParam::MuPalm => p.mu_palm = v,
            GridParam::RadiusMm => p.radius_mm = v,
            GridParam::MassKg => p.mass_kg = v,
            GridParam::ForceN => p.force_n = v,
            GridParam::GravityMS2 => p.gravity_m_s2 = v,
            GridParam::StartAngleDeg => p.start_angle_deg = v,
            GridParam::PalmLengthMm => p.palm_length_mm = v,
            GridParam::ThetaDeg => {}
        }
        p
    }
}

impl ParamSet for SceneParams {
    type Param = GridParam;

    fn with(self, param: GridParam, value: f64) -> Self {
        param.apply(self, value)
    }

    fn validate(&self) -> Result<()> {
        SceneParams::validate(self)
    }

    fn param_name(param: GridParam) -> &'static str {
        param.as_str()
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
/// `P` is the parameter type of the [`ParamSet`] the axis varies: [`GridParam`] for the palm
/// scene (the default), the locator's for a V-locator.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridAxis<P = GridParam> {
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
