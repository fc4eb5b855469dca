//! The V-locator's parameters ([`LocatorParams`]) as a [`ParamSet`]: what a locator grid's
//! axes can vary.

use serde::{Deserialize, Serialize};

use super::ParamSet;
use crate::error::Result;
use crate::locator::LocatorParams;

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
