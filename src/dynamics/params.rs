//! Settings of the dynamic simulation (TOML section `[dynamics]`).

use serde::{Deserialize, Serialize};

use super::nonsmooth::DiscMotion;
use crate::error::{Error, Result};
use crate::model::{SceneParams, finite_at_least, finite_positive};

/// How the palm is driven.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Drive {
    /// Prescribed angular velocity omega (the paper's Adams model): pushes with any force, so the
    /// jam tends to the rigid limit r/mu.
    Motion,
    /// A speed drive with a force limit: turns at omega until the palm's elastic push reaches
    /// F cos(atan mu_palm), then stalls without backing off, so the jam tends to the closed form
    /// at finite F.
    Force,
}

impl Drive {
    /// The JSON spelling.
    pub fn as_str(self) -> &'static str {
        match self {
            Drive::Motion => "motion",
            Drive::Force => "force",
        }
    }
}

/// The time integrator.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Radau IIA of order 5 (Hairer's RADAU5): implicit, L-stable, analytic Jacobian.
    Radau5,
    /// Dormand-Prince 5(4) (Hairer's DOPRI5): explicit, adaptive, dense output of order 4.
    Dopri5,
    /// Rigid contacts with exact Coulomb friction, time-stepped at the velocity-impulse level
    /// (Moreau-Jean); no contact stiffness, true stiction ([`super::nonsmooth`]).
    Nonsmooth,
}

impl Method {
    /// The JSON spelling.
    pub fn as_str(self) -> &'static str {
        match self {
            Method::Radau5 => "radau5",
            Method::Dopri5 => "dopri5",
            Method::Nonsmooth => "nonsmooth",
        }
    }
}

/// Parameters of the Adams-like model and of its integration (section `[dynamics]`).
///
/// Defaults are the paper's Adams model (Section 4) with Adams' documented IMPACT defaults where
/// the paper's printed contact parameters are garbled (crate docs, Corrections to the paper).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DynamicsParams {
    /// Palm drive, `motion` or `force` (default: motion, the paper's).
    pub drive: Drive,
    /// Palm closing speed omega in deg/s, > 0 (default: 30, the paper's).
    pub omega_deg_s: f64,
    /// IMPACT stiffness k in N/mm^e, > 0 (default: 1e5, Adams' default: about 60 um of
    /// penetration at 200 N).
    pub stiffness_n_per_mm_e: f64,
    /// IMPACT force exponent e, >= 1 (default: 2.2, Adams' default).
    pub exponent: f64,
    /// IMPACT maximum damping c_max in N s/mm, >= 0 (default: 10, Adams' default).
    pub damping_n_s_per_mm: f64,
    /// IMPACT penetration at which the damping reaches c_max, in mm, > 0 (default: 0.01,
    /// Adams' default).
    pub damping_depth_mm: f64,
    /// Static friction coefficient at the ground (default: the scene's mu_ground).
    pub mu_static_ground: Option<f64>,
    /// Static friction coefficient at the palm (default: the scene's mu_palm).
    pub mu_static_palm: Option<f64>,
    /// Stiction transition velocity V_s in mm/s, > 0 (default: 0.1, the paper's).
    pub stiction_velocity_mm_s: f64,
    /// Friction transition velocity V_d in mm/s, > V_s (default: 0.2, the paper's).
    pub friction_velocity_mm_s: f64,
    /// Offset of the palm's contact face from the hinge line in mm (the bar's half thickness),
    /// >= 0 (default: 0, the paper's theory; its 1 mm bars would give 0.5).
    pub palm_offset_mm: f64,
    /// Width of the force drive's limit band as a fraction of the limit, in (0, 1) (default: 0.01:
    /// the speed falls from omega to 0 while the push rises from 99 % to 100 % of the limit).
    pub force_band: f64,
    /// Time integrator (default: radau5).
    pub method: Method,
    /// Relative tolerance per step, in (0, 1) (default: 1e-6).
    pub rtol: f64,
    /// Absolute tolerance per step in the state's units (rad, mm, mm/s), in (0, 1) (default: the
    /// value of rtol).
    pub atol: Option<f64>,
    /// Run a second time at a tenth of rtol and atol to estimate the error of x_jam (default:
    /// true).
    pub verify: bool,
    /// Largest estimated relative error of x_jam before the answer is called inaccurate, in
    /// (0, 1) (default: 1e-3, 25 um at the default jam).
    pub max_jam_error: f64,
    /// Jam when the disc's speed falls below this fraction of the geometric speed
    /// r omega / (2 sin^2(theta/2)), in (0, arm_ratio) (default: 0.5).
    pub jam_speed_ratio: f64,
    /// The jam detector arms once the disc's speed has reached this fraction of the geometric
    /// speed, in (jam_speed_ratio, 1] (default: 0.9).
    pub arm_speed_ratio: f64,
    /// Simulated time after the jam in s, >= 0, for the time series (default: 0).
    pub after_jam_s: f64,
    /// Step limit of the integrator, >= 1 (default: 2000000).
    pub max_steps: u64,
    /// Palm turn per time step of the nonsmooth method in deg, in (0, 1] (default: 0.1 with the
    /// motion drive, 0.01 with the force drive). The motion drive's lock-up is located inside
    /// its step by bisection, so at 0.1 deg x_jam lies within 3e-5 of r/mu for mu = 0.15-0.45 in
    /// about 0.15 ms (0.25 ms verified); the force drive's rest is read at a step end and a slow
    /// push needs the finer step (at 0.5 deg/s, 0.1 deg is 0.1-0.4 % off and often flagged).
    pub nonsmooth_step_deg: Option<f64>,
    /// How the disc may move in the nonsmooth method: `slides` (the paper's translational
    /// joint) or `rolls` (free in the plane) (default: slides). The other methods only slide.
    pub disc: DiscMotion,
}

/// The nonsmooth method's default step with the motion drive in deg: the lock-up is located
/// inside its step, so x_jam lies within 3e-5 of r/mu for mu = 0.15-0.45 (the palm ends each step
/// inside the disc by the second order of the step; 0.3 deg is 3e-4 off, 1 deg 3e-3).
pub const MOTION_STEP_DEG: f64 = 0.1;

/// The nonsmooth method's default step with the force drive in deg: the disc comes to rest at a
/// step end, and a slow push (0.5 deg/s) lands 0.1-0.4 % off at 0.1 deg, within 0.1 % at 0.01.
pub const FORCE_STEP_DEG: f64 = 0.01;

impl Default for DynamicsParams {
    fn default() -> Self {
        DynamicsParams {
            drive: Drive::Motion,
            omega_deg_s: 30.0,
            stiffness_n_per_mm_e: 1e5,
            exponent: 2.2,
            damping_n_s_per_mm: 10.0,
            // 0.01 mm: Adams' default penetration depth of full damping.
            damping_depth_mm: 0.01,
            mu_static_ground: None,
            mu_static_palm: None,
            stiction_velocity_mm_s: 0.1,
            friction_velocity_mm_s: 0.2,
            palm_offset_mm: 0.0,
            force_band: 0.01,
            method: Method::Radau5,
            rtol: 1e-6,
            atol: None,
            verify: true,
            max_jam_error: 1e-3,
            // Half the geometric speed: the collapse is steep, so the reading barely depends on it.
            jam_speed_ratio: 0.5,
            arm_speed_ratio: 0.9,
            after_jam_s: 0.0,
            // DOPRI5 needs about 1e6 steps at the stiffest contacts; beyond that it is hopeless.
            max_steps: 2_000_000,
            nonsmooth_step_deg: None,
            disc: DiscMotion::Slides,
        }
    }
}

impl DynamicsParams {
    /// Checks every field; the error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        finite_positive(
            "omega_deg_s",
            self.omega_deg_s,
            "the palm speed must be > 0 deg/s",
        )?;
        finite_positive(
            "stiffness_n_per_mm_e",
            self.stiffness_n_per_mm_e,
            "the contact stiffness must be > 0 N/mm^e",
        )?;
        finite_at_least(
            "exponent",
            self.exponent,
            1.0,
            "the IMPACT exponent must be >= 1 (a smaller one has infinite stiffness at first touch)",
        )?;
        finite_at_least(
            "damping_n_s_per_mm",
            self.damping_n_s_per_mm,
            0.0,
            "damping must be >= 0",
        )?;
        finite_positive(
            "damping_depth_mm",
            self.damping_depth_mm,
            "the damping depth must be > 0 mm",
        )?;
        for (key, mu) in [
            ("mu_static_ground", self.mu_static_ground),
            ("mu_static_palm", self.mu_static_palm),
        ] {
            if let Some(mu) = mu {
                finite_at_least(key, mu, 0.0, "friction coefficients are >= 0")?;
            }
        }
        let vs = self.stiction_velocity_mm_s;
        finite_positive("stiction_velocity_mm_s", vs, "V_s must be > 0 mm/s")?;
        let vd = self.friction_velocity_mm_s;
        if !(vd.is_finite() && vd > vs) {
            return Err(Error::invalid(
                "friction_velocity_mm_s",
                vd,
                format!("V_d must be finite and above the stiction velocity V_s = {vs} mm/s"),
            ));
        }
        finite_at_least(
            "palm_offset_mm",
            self.palm_offset_mm,
            0.0,
            "the offset must be >= 0 mm",
        )?;
        open_unit("force_band", self.force_band)?;
        open_unit("rtol", self.rtol)?;
        if let Some(atol) = self.atol {
            open_unit("atol", atol)?;
        }
        open_unit("max_jam_error", self.max_jam_error)?;
        open_unit("arm_speed_ratio", self.arm_speed_ratio).or_else(|e| {
            if self.arm_speed_ratio == 1.0 {
                Ok(())
            } else {
                Err(e)
            }
        })?;
        let j = self.jam_speed_ratio;
        if !(j.is_finite() && j > 0.0 && j < self.arm_speed_ratio) {
            return Err(Error::invalid(
                "jam_speed_ratio",
                j,
                format!(
                    "must lie in (0, arm_speed_ratio = {})",
                    self.arm_speed_ratio
                ),
            ));
        }
        finite_at_least("after_jam_s", self.after_jam_s, 0.0, "must be >= 0 s")?;
        if self.max_steps == 0 {
            return Err(Error::invalid("max_steps", 0, "must be >= 1"));
        }
        let st = self.nonsmooth_step_deg();
        if !(st.is_finite() && st > 0.0 && st <= 1.0) {
            return Err(Error::invalid(
                "nonsmooth_step_deg",
                st,
                "the palm turn per step must lie in (0, 1] deg",
            ));
        }
        if self.disc == DiscMotion::Rolls && self.method != Method::Nonsmooth {
            return Err(Error::invalid(
                "disc",
                "rolls",
                "only the nonsmooth method lets the disc roll",
            ));
        }
        Ok(())
    }

    /// Checks what the simulation needs of the scene beyond [`SceneParams::validate`].
    pub fn validate_scene(&self, scene: &SceneParams) -> Result<()> {
        finite_positive(
            "mass_kg",
            scene.mass_kg,
            "the dynamics need a disc mass > 0 kg",
        )
    }

    /// The nonsmooth method's step in use in deg of palm turn: `nonsmooth_step_deg`, or when
    /// unset [`MOTION_STEP_DEG`] with the motion drive and [`FORCE_STEP_DEG`] with the force drive.
    pub fn nonsmooth_step_deg(&self) -> f64 {
        self.nonsmooth_step_deg.unwrap_or(match self.drive {
            Drive::Motion => MOTION_STEP_DEG,
            Drive::Force => FORCE_STEP_DEG,
        })
    }

    /// The absolute tolerance in use (atol, or rtol when unset).
    pub fn atol(&self) -> f64 {
        self.atol.unwrap_or(self.rtol)
    }
}

impl std::str::FromStr for Drive {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "motion" => Ok(Drive::Motion),
            "force" => Ok(Drive::Force),
            _ => Err(format!("unknown drive '{s}' (expected motion or force)")),
        }
    }
}

impl std::str::FromStr for Method {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "radau5" => Ok(Method::Radau5),
            "dopri5" => Ok(Method::Dopri5),
            "nonsmooth" => Ok(Method::Nonsmooth),
            _ => Err(format!(
                "unknown method '{s}' (expected radau5, dopri5 or nonsmooth)"
            )),
        }
    }
}

fn open_unit(key: &str, v: f64) -> Result<()> {
    if v.is_finite() && v > 0.0 && v < 1.0 {
        Ok(())
    } else {
        Err(Error::invalid(key, v, "must lie strictly between 0 and 1"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bad_setting_is_named() {
        let d = DynamicsParams::default();
        assert!(d.validate().is_ok());
        let cases: Vec<(&str, DynamicsParams)> = vec![
            (
                "stiffness_n_per_mm_e",
                DynamicsParams {
                    stiffness_n_per_mm_e: 0.0,
                    ..d
                },
            ),
            (
                "exponent",
                DynamicsParams {
                    exponent: -2.0,
                    ..d
                },
            ),
            (
                "stiction_velocity_mm_s",
                DynamicsParams {
                    stiction_velocity_mm_s: 0.0,
                    ..d
                },
            ),
            (
                "friction_velocity_mm_s",
                DynamicsParams {
                    friction_velocity_mm_s: 0.1,
                    ..d
                },
            ),
            (
                "omega_deg_s",
                DynamicsParams {
                    omega_deg_s: 0.0,
                    ..d
                },
            ),
            ("rtol", DynamicsParams { rtol: 1.0, ..d }),
            (
                "atol",
                DynamicsParams {
                    atol: Some(0.0),
                    ..d
                },
            ),
            (
                "damping_depth_mm",
                DynamicsParams {
                    damping_depth_mm: f64::NAN,
                    ..d
                },
            ),
            (
                "mu_static_palm",
                DynamicsParams {
                    mu_static_palm: Some(-0.1),
                    ..d
                },
            ),
            (
                "jam_speed_ratio",
                DynamicsParams {
                    jam_speed_ratio: 0.95,
                    ..d
                },
            ),
        ];
        for (key, p) in cases {
            let msg = p.validate().unwrap_err().to_string();
            assert!(msg.contains(key), "{key}: {msg}");
        }
    }
}
