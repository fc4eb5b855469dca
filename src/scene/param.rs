//! A named parameter of the palm scene: any number of `[scene]`, the alias `mu` (both
//! frictions), the push over the weight `push_ratio`, or the palm angle `theta_deg`: what a grid
//! axis varies, a read-off names, a Python array or a column of pushes sets.

use serde::{Deserialize, Serialize};

use super::SceneParams;
use crate::settings::{self, Check, Decl, Kind};

/// A scene field's setter, [`SceneParams::real_setter`].
pub(crate) type Setter = fn(&mut SceneParams, f64) -> bool;

/// A scene parameter, named by its TOML key: any number of `[scene]`, the alias `mu` (both
/// frictions), `push_ratio` or the palm angle `theta_deg`. Its symbol, unit and axis
/// label come from its declaration (`crate::settings`), so a new scene parameter is an axis
/// with no edit here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Param {
    key: &'static str,
}

/// The palm angle theta in deg at which the margin is evaluated: not a scene parameter but the
/// state of the push, so it only feeds a margin map ([`crate::grid::Quantity::MarginN`]).
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

/// The parameters code names; any other declared one is reached by [`Param::named`].
#[allow(non_upper_case_globals)]
impl Param {
    /// The paper's single mu: sets mu_ground and mu_palm together.
    pub const Mu: Param = Param { key: "mu" };
    /// Friction coefficient at the ground contact A.
    pub const MuGround: Param = Param { key: "mu_ground" };
    /// Friction coefficient at the palm contact B.
    pub const MuPalm: Param = Param { key: "mu_palm" };
    /// Disc radius r in mm (the mass stays as set: the paper's Fig. 7a).
    pub const RadiusMm: Param = Param { key: "radius_mm" };
    /// Disc mass m in kg.
    pub const MassKg: Param = Param { key: "mass_kg" };
    /// Palm push F in N.
    pub const ForceN: Param = Param { key: "force_n" };
    /// Gravitational acceleration g in m/s^2.
    pub const GravityMS2: Param = Param {
        key: "gravity_m_s2",
    };
    /// Length of the palm in mm.
    pub const PalmLengthMm: Param = Param {
        key: "palm_length_mm",
    };
    /// Palm angle in deg where the push starts.
    pub const StartAngleDeg: Param = Param {
        key: "start_angle_deg",
    };
    /// Offset h of the palm's face from the hinge line in mm.
    pub const PalmOffsetMm: Param = Param {
        key: "palm_offset_mm",
    };
    /// The palm angle theta in deg (margin maps only).
    pub const ThetaDeg: Param = Param { key: "theta_deg" };
    /// The push over the weight, F / (m g); sets force_n.
    pub const PushRatio: Param = Param { key: "push_ratio" };
}

impl Param {
    /// The parameter named `key`: a number of `[scene]`, an alias of it, or `theta_deg`.
    pub fn named(key: &str) -> Option<Param> {
        Self::all().find(|p| p.key == key)
    }

    /// Every parameter an axis can vary, in declaration order.
    pub fn all() -> impl Iterator<Item = Param> {
        settings::palm_family()
            .filter(|d| d.section == "scene")
            .filter(|d| matches!(d.kind, Kind::Real) || !d.sets.is_empty())
            .chain([&THETA, &PUSH_RATIO])
            .map(|d| Param { key: d.key })
    }

    /// The declaration: symbol, unit, quantity.
    pub(crate) fn decl(self) -> &'static Decl {
        if self.key == THETA.key {
            return &THETA;
        }
        if self.key == PUSH_RATIO.key {
            return &PUSH_RATIO;
        }
        settings::find(self.key).expect("a Param names a declared setting")
    }

    /// The snake_case name, as in TOML and in CSV headers.
    pub const fn as_str(self) -> &'static str {
        self.key
    }

    /// The value of this parameter in `p` (an alias reads its first key; `push_ratio` is
    /// F / (m g), None for a weightless disc); None for [`Param::ThetaDeg`].
    pub fn get(self, p: &SceneParams) -> Option<f64> {
        if self == Param::PushRatio {
            let w = p.weight_n();
            return (w > 0.0).then(|| p.force_n / w);
        }
        let d = self.decl();
        p.real(d.sets.first().copied().unwrap_or(d.key))
    }

    /// `p` with this parameter set to `v` (an alias sets each of its keys; `push_ratio` sets
    /// force_n = v m g); [`Param::ThetaDeg`] leaves `p` unchanged.
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

    /// [`Param::apply`] with the declaration and the fields it sets looked up once.
    pub(crate) fn setter(self) -> impl Fn(SceneParams, f64) -> SceneParams + Sync {
        let push_ratio = self == Param::PushRatio;
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

impl Serialize for Param {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.serialize_str(self.key)
    }
}

impl<'de> Deserialize<'de> for Param {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Param::named(&name).ok_or_else(|| {
            // Each name in backticks, as serde's own "unknown variant" writes them: the file's
            // message reads the list from there ("muu is not one of ." had none).
            let names: Vec<String> = Param::all().map(|p| format!("`{}`", p.as_str())).collect();
            serde::de::Error::custom(format!(
                "unknown variant `{}`, expected one of {}",
                crate::error::cut(&name),
                names.join(", ")
            ))
        })
    }
}
