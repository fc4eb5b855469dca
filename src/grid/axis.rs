//! One axis of a grid: which parameter it varies, over which range, how finely; and the palm
//! scene's parameters ([`GridParam`]) as a [`ParamSet`].

use serde::{Deserialize, Serialize};

use super::ParamSet;
use crate::error::{Error, Result};
use crate::scene::SceneParams;
use crate::settings::{self, Check, Decl, Kind};

/// A scene field's setter, [`SceneParams::real_setter`].
pub(crate) type Setter = fn(&mut SceneParams, f64) -> bool;

/// A scene parameter a grid axis can vary: any number of `[scene]`, the alias `mu` (both
/// frictions) or the palm angle `theta_deg`, named by its TOML key. Its symbol, unit and axis
/// label come from its declaration (`crate::settings`), so a new scene parameter is an axis
/// with no edit here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct GridParam {
    key: &'static str,
}

/// The palm angle theta in deg at which the margin is evaluated: not a scene parameter but the
/// state of the push, so it only feeds [`super::Quantity::MarginN`].
const THETA: Decl = Decl {
    key: "theta_deg",
    section: "scene",
    symbol: "θ",
    quantity: "palm angle",
    unit: "deg",
    doc: "The palm angle at which the jam margin is evaluated.",
    check: Check::Open(0.0, 180.0),
    ..Decl::BASE
};

/// The push over the disc's weight, F / (m g): not a field of the scene but the one number
/// through which the push and the weight enter the closed form (`m g sin(alpha_g) / F`), so
/// an axis of it makes a chart that holds for any part. Setting it sets `force_n` from the
/// cell's mass and gravity.
const PUSH_RATIO: Decl = Decl {
    key: "push_ratio",
    section: "scene",
    symbol: "F/(m g)",
    quantity: "push over weight",
    unit: "-",
    doc: "The palm push over the disc's weight, F / (m g): sets force_n = push_ratio m g.",
    check: Check::Above(0.0),
    ..Decl::BASE
};

/// The parameters code names; any other declared one is reached by [`GridParam::named`].
#[allow(non_upper_case_globals)]
impl GridParam {
    /// The paper's single mu: sets mu_ground and mu_palm together.
    pub const Mu: GridParam = GridParam { key: "mu" };
    /// Friction coefficient at the ground contact A.
    pub const MuGround: GridParam = GridParam { key: "mu_ground" };
    /// Friction coefficient at the palm contact B.
    pub const MuPalm: GridParam = GridParam { key: "mu_palm" };
    /// Disc radius r in mm (the mass stays as set: the paper's Fig. 7a).
    pub const RadiusMm: GridParam = GridParam { key: "radius_mm" };
    /// Disc mass m in kg.
    pub const MassKg: GridParam = GridParam { key: "mass_kg" };
    /// Palm push F in N.
    pub const ForceN: GridParam = GridParam { key: "force_n" };
    /// Gravitational acceleration g in m/s^2.
    pub const GravityMS2: GridParam = GridParam {
        key: "gravity_m_s2",
    };
    /// Length of the palm in mm.
    pub const PalmLengthMm: GridParam = GridParam {
        key: "palm_length_mm",
    };
    /// Offset h of the palm's face from the hinge line in mm.
    pub const PalmOffsetMm: GridParam = GridParam {
        key: "palm_offset_mm",
    };
    /// The palm angle theta in deg (margin maps only).
    pub const ThetaDeg: GridParam = GridParam { key: "theta_deg" };
    /// The push over the weight, F / (m g); sets force_n.
    pub const PushRatio: GridParam = GridParam { key: "push_ratio" };
}

impl GridParam {
    /// The parameter named `key`: a number of `[scene]`, an alias of it, or `theta_deg`.
    pub fn named(key: &str) -> Option<GridParam> {
        Self::all().find(|p| p.key == key)
    }

    /// Every parameter an axis can vary, in declaration order.
    pub fn all() -> impl Iterator<Item = GridParam> {
        settings::palm_family()
            .filter(|d| d.section == "scene")
            .filter(|d| matches!(d.kind, Kind::Real) || !d.sets.is_empty())
            .chain([&THETA, &PUSH_RATIO])
            .map(|d| GridParam { key: d.key })
    }

    /// The declaration: symbol, unit, quantity.
    pub(crate) fn decl(self) -> &'static Decl {
        if self.key == THETA.key {
            return &THETA;
        }
        if self.key == PUSH_RATIO.key {
            return &PUSH_RATIO;
        }
        settings::find(self.key).expect("a GridParam names a declared setting")
    }

    /// The snake_case name, as in TOML and in CSV headers.
    pub fn as_str(self) -> &'static str {
        self.key
    }

    /// The value of this parameter in `p` (an alias reads its first key; `push_ratio` is
    /// F / (m g), None for a weightless disc); None for [`GridParam::ThetaDeg`].
    pub fn get(self, p: &SceneParams) -> Option<f64> {
        if self == GridParam::PushRatio {
            let w = p.weight_n();
            return (w > 0.0).then(|| p.force_n / w);
        }
        let d = self.decl();
        p.real(d.sets.first().copied().unwrap_or(d.key))
    }

    /// `p` with this parameter set to `v` (an alias sets each of its keys; `push_ratio` sets
    /// force_n = v m g); [`GridParam::ThetaDeg`] leaves `p` unchanged.
    pub fn apply(self, p: SceneParams, v: f64) -> SceneParams {
        self.setter()(p, v)
    }

    /// The scene fields this parameter sets (an alias's keys, or its own key) and their
    /// setters: none for `push_ratio` (it sets force_n from the weight) or `theta_deg`, which
    /// are no fields.
    pub(crate) fn fields(self) -> (&'static [&'static str], Vec<Setter>) {
        let d = self.decl();
        let keys = match d.sets {
            [] => std::slice::from_ref(&d.key),
            keys => keys,
        };
        let setters = keys.iter().filter_map(|k| SceneParams::real_setter(k));
        (keys, setters.collect())
    }

    /// [`GridParam::apply`] with the declaration and the fields it sets looked up once.
    pub(crate) fn setter(self) -> impl Fn(SceneParams, f64) -> SceneParams + Sync {
        let push_ratio = self == GridParam::PushRatio;
        // No field to look up for the push ratio: a column of them sets each push's scene
        // through here (`models::columns`).
        let fields = match push_ratio {
            true => Vec::new(),
            false => self.fields().1,
        };
        move |mut p, v| {
            if push_ratio {
                p.force_n = v * p.weight_n();
            }
            for set in &fields {
                set(&mut p, v);
            }
            p
        }
    }
}

impl Serialize for GridParam {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.key)
    }
}

impl<'de> Deserialize<'de> for GridParam {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        GridParam::named(&name).ok_or_else(|| {
            let names: Vec<&str> = GridParam::all().map(GridParam::as_str).collect();
            serde::de::Error::custom(format!(
                "unknown variant `{}`, expected one of {}",
                crate::error::cut(&name),
                names.join(", ")
            ))
        })
    }
}

impl ParamSet for SceneParams {
    type Param = GridParam;

    fn with(self, param: GridParam, value: f64) -> Self {
        param.apply(self, value)
    }

    fn setter(param: GridParam) -> impl Fn(Self, f64) -> Self + Sync {
        param.setter()
    }

    fn validate(&self) -> Result<()> {
        SceneParams::validate(self)
    }

    fn param_name(param: GridParam) -> &'static str {
        param.as_str()
    }

    /// `push_ratio` sets the push from the cell's weight, so it cannot share a grid with the
    /// push, the mass or gravity: the order of the axes would decide the cell.
    fn check_axes(x: GridParam, y: GridParam) -> Result<()> {
        let derived = [GridParam::ForceN, GridParam::MassKg, GridParam::GravityMS2];
        for (a, b) in [(x, y), (y, x)] {
            if a == GridParam::PushRatio && derived.contains(&b) {
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
/// `P` is the parameter type of the `ParamSet` the axis varies: [`GridParam`] for the palm
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
