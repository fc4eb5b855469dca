//! Settings of the dynamic simulation, one struct per role, one TOML section each:
//! `[dynamics.drive]`, `[dynamics.contact]`, `[dynamics.friction]`, `[dynamics.integrator]`,
//! `[dynamics.verification]`, `[dynamics.jam_reading]`, `[dynamics.series]`.
//!
//! Defaults are the paper's Adams model (Section 4) with Adams' documented IMPACT defaults where
//! the paper's printed contact parameters are garbled (crate docs, Corrections to the paper).
//! Files written before the roles (flat `[dynamics]` keys) are refused with each key's new
//! place named, e.g. `dynamics.contact.stiffness_n_per_mm_e`.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::limits::{MIN_NONSMOOTH_STEP_DEG, MIN_TOLERANCE};
use crate::scene::{SceneParams, finite_positive};
use crate::settings::decl::Check;

choice! {
    /// How the palm is driven.
    pub enum Drive {
        /// Prescribed angular velocity omega (the paper's Adams model): pushes with any force, so
        /// the jam tends to the rigid limit r/mu.
        Motion = "motion",
        /// A speed drive with a force limit: turns at omega until the palm's elastic push reaches
        /// F cos(atan mu_palm), then stalls without backing off, so the jam tends to the closed
        /// form at finite F.
        Force = "force",
    }
}

choice! {
    /// The time integrator.
    pub enum Method {
        /// Radau IIA of order 5 (Hairer's RADAU5): implicit, L-stable, analytic Jacobian.
        Radau5 = "radau5",
        /// Dormand-Prince 5(4) (Hairer's DOPRI5): explicit, adaptive, dense output of order 4.
        Dopri5 = "dopri5",
        /// Rigid contacts with exact Coulomb friction, time-stepped at the velocity-impulse level
        /// (Moreau-Jean); no contact stiffness, true stiction (`super::nonsmooth`).
        Nonsmooth = "nonsmooth",
    }
}

choice! {
    /// How the disc may move in the nonsmooth method.
    pub enum DiscMotion {
        /// The paper's: on a translational joint, no rotation (the joint takes the moment).
        Slides = "slides",
        /// Free in the plane: x, y and rotation, unilateral contacts at the ground and the palm.
        Rolls = "rolls",
    }
}

settings! {
    /// How the palm is driven.
    section = "dynamics.drive";
    pub struct DriveSettings {
        /// Palm drive: motion or force.
        ///
        /// motion: prescribed omega, pushes as hard as needed (the paper's Adams model; jams near
        /// r/mu). force: turns at omega until its push reaches --force, then stalls (jams near
        /// the closed form at that force).
        mode: Drive = Drive::Motion, flag: Some("drive"), value_name: "DRIVE";
        /// Palm closing speed omega (the paper's 30 deg/s).
        omega_deg_s: f64 = 30.0, flag: Some("omega"), symbol: "ω", quantity: "palm speed",
            unit: "deg/s", check: Check::Above(0.0);
        /// Width of the force drive's limit band, as a fraction of the limit.
        ///
        /// The speed falls from omega to 0 while the push rises from 99 % to 100 % of the limit.
        force_band: f64 = 0.01, quantity: "force band", unit: "-", check: Check::Open(0.0, 1.0);
    }
}

settings! {
    /// The palm-disc contact: Adams' IMPACT law, force k delta^e with damping up to c_max.
    section = "dynamics.contact";
    pub struct ContactLaw {
        /// IMPACT contact stiffness k.
        ///
        /// The penetration at a force P is (P/k)^(1/e): about 60 um at 200 N with Adams' default.
        stiffness_n_per_mm_e: f64 = 1e5, flag: Some("stiffness"), symbol: "k",
            quantity: "contact stiffness", unit: "N/mm^e", check: Check::Above(0.0);
        /// IMPACT force exponent e (Adams' default).
        exponent: f64 = 2.2, flag: Some("exponent"), symbol: "e", quantity: "IMPACT exponent",
            unit: "-", check: Check::AtLeast(1.0), value_name: "E";
        /// IMPACT maximum damping c_max (Adams' default).
        damping_n_s_per_mm: f64 = 10.0, flag: Some("damping"), symbol: "c_max",
            quantity: "contact damping", unit: "N s/mm", check: Check::AtLeast(0.0),
            value_name: "N*S/MM";
        /// Penetration at which the damping reaches c_max.
        // 0.01 mm: Adams' default penetration depth of full damping.
        damping_depth_mm: f64 = 0.01, flag: Some("damping-depth"), symbol: "d",
            quantity: "damping depth", unit: "mm", check: Check::Above(0.0);
    }
}

settings! {
    /// Adams' regularised Coulomb friction at both contacts; the dynamic coefficients are the
    /// scene's mu_ground and mu_palm.
    section = "dynamics.friction";
    pub struct FrictionLaw {
        /// Static friction coefficient at the ground (unset: the scene's mu_ground).
        mu_static_ground: Option<f64> = None, quantity: "static ground friction", unit: "-",
            check: Check::AtLeast(0.0);
        /// Static friction coefficient at the palm (unset: the scene's mu_palm).
        mu_static_palm: Option<f64> = None, quantity: "static palm friction", unit: "-",
            check: Check::AtLeast(0.0);
        /// Stiction transition velocity V_s (the paper's).
        stiction_velocity_mm_s: f64 = 0.1, flag: Some("stiction-velocity"), symbol: "V_s",
            quantity: "stiction velocity", unit: "mm/s", check: Check::Above(0.0);
        /// Friction transition velocity V_d, above V_s (the paper's).
        friction_velocity_mm_s: f64 = 0.2, flag: Some("friction-velocity"), symbol: "V_d",
            quantity: "friction velocity", unit: "mm/s", check: Check::Above(0.0);
    }
}

settings! {
    /// The friction law's alias: `mu_static` sets both static coefficients.
    section = "dynamics.friction";
    aliases FRICTION_ALIASES {
        /// Static friction coefficient at both contacts (unset: the dynamic mu).
        mu_static, sets: &["mu_static_ground", "mu_static_palm"], flag: Some("mu-static"),
            quantity: "static friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU";
    }
}

settings! {
    /// The time integrator and its tolerances.
    section = "dynamics.integrator";
    pub struct IntegratorSettings {
        /// Method: radau5 (implicit), dopri5 (explicit) or nonsmooth (rigid).
        ///
        /// radau5 and dopri5 integrate the compliant IMPACT contact with regularised friction;
        /// nonsmooth time-steps rigid contacts with exact Coulomb friction (true stiction; the
        /// jam is the lock-up of the motion-driven palm).
        method: Method = Method::Radau5, flag: Some("method"), value_name: "METHOD";
        /// Relative tolerance per step. Looser than 1e-2 is always reported inaccurate.
        rtol: f64 = 1e-6, flag: Some("rtol"), quantity: "relative tolerance", unit: "-",
            check: Check::CloseOpen(MIN_TOLERANCE, 1.0), value_name: "RTOL";
        /// Absolute tolerance per step in the state's units: rad, mm, mm/s (unset: rtol).
        atol: Option<f64> = None, flag: Some("atol"), quantity: "absolute tolerance",
            unit: "-", check: Check::CloseOpen(MIN_TOLERANCE, 1.0), value_name: "ATOL";
        /// Step limit of the integrator.
        // DOPRI5 needs about 1e6 steps at the stiffest contacts; beyond that it is hopeless.
        max_steps: u64 = 2_000_000, quantity: "step limit", check: Check::CountAtLeast(1);
        /// Palm turn per step of the nonsmooth method, 1.8e-11 to 1 (unset: 0.1 deg with the motion
        /// drive, 0.01 deg with the force drive).
        ///
        /// The motion drive's lock-up is located inside its step, so 0.1 deg puts x_jam within
        /// 3e-5 of r/mu for mu = 0.15-0.45. The force drive's disc comes to rest at a step end,
        /// and a slow push needs 0.01 deg for 0.1 %.
        nonsmooth_step_deg: Option<f64> = None, flag: Some("nonsmooth-step"),
            quantity: "nonsmooth step", unit: "deg",
            check: Check::Closed(MIN_NONSMOOTH_STEP_DEG, 1.0);
        /// How the disc moves in the nonsmooth method: slides or rolls.
        ///
        /// slides: the paper's translational joint (no rotation); rolls: free in the plane (x,
        /// y, rotation) with unilateral contacts at the ground and the palm. The other methods
        /// only slide.
        disc: DiscMotion = DiscMotion::Slides, flag: Some("disc"), value_name: "MOTION";
    }
}

settings! {
    /// The second run that estimates the error of x_jam.
    section = "dynamics.verification";
    pub struct Verification {
        /// Run a second time at a tenth of rtol and atol to estimate the error of x_jam.
        ///
        /// --no-verify skips it.
        verify: bool = true, flag: Some("no-verify");
        /// Largest estimated relative error of x_jam before the answer is called inaccurate
        /// (1e-3: 25 um at the default jam).
        max_jam_error: f64 = 1e-3, quantity: "largest jam error", unit: "-",
            check: Check::Open(0.0, 1.0);
    }
}

settings! {
    /// How the regularised simulation reads the jam off the disc's speed.
    section = "dynamics.jam_reading";
    pub struct JamReading {
        /// The speed collapse: the disc's speed falls below this fraction of the geometric speed
        /// r omega / (2 sin^2(theta/2)), in (0, arm_speed_ratio); the jam with the motion drive,
        /// where the palm stalls with the force drive (the disc then coasts to rest).
        // Half the geometric speed: the collapse is steep, so the reading barely depends on it.
        jam_speed_ratio: f64 = 0.5, quantity: "jam speed ratio", unit: "-",
            check: Check::Open(0.0, 1.0);
        /// The jam detector arms once the disc's speed has reached this fraction of the
        /// geometric speed, in (jam_speed_ratio, 1].
        arm_speed_ratio: f64 = 0.9, quantity: "arming speed ratio", unit: "-",
            check: Check::OpenClosed(0.0, 1.0);
    }
}

settings! {
    /// The time series the simulation records.
    section = "dynamics.series";
    pub struct SeriesSettings {
        /// Simulated time after the jam, for the time series; at most an hour (a push lasts
        /// seconds and the collapse after a jam a fraction of one: fig5 shows 0.2 s).
        after_jam_s: f64 = 0.0, flag: Some("after-jam"), quantity: "time after the jam",
            unit: "s", check: Check::Closed(0.0, 3600.0);
    }
}

/// Parameters of the Adams-like model and of its integration (section `[dynamics]`), by role.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DynamicsParams {
    /// How the palm is driven (`[dynamics.drive]`).
    pub drive: DriveSettings,
    /// The palm-disc contact law (`[dynamics.contact]`).
    pub contact: ContactLaw,
    /// The friction law at both contacts (`[dynamics.friction]`).
    pub friction: FrictionLaw,
    /// The integrator (`[dynamics.integrator]`).
    pub integrator: IntegratorSettings,
    /// The error estimate by a second run (`[dynamics.verification]`).
    pub verification: Verification,
    /// Where the jam is read (`[dynamics.jam_reading]`).
    pub jam_reading: JamReading,
    /// The time series (`[dynamics.series]`).
    pub series: SeriesSettings,
}

/// The nonsmooth method's default step with the motion drive in deg: the lock-up is located
/// inside its step, so x_jam lies within 3e-5 of r/mu for mu = 0.15-0.45 (the palm ends each step
/// inside the disc by the second order of the step; 0.3 deg is 2.7e-4 off, 1 deg 3.1e-3; at
/// 30 deg/s, printed by `the_step_figures_of_the_nonsmooth_docs`).
pub const MOTION_STEP_DEG: f64 = 0.1;

/// The nonsmooth method's default step with the force drive in deg: the disc comes to rest at a
/// step end, and a slow push (0.5 deg/s; mu 0.2-0.4, F 50 and 200 N) lands up to 0.26 % off
/// the converged rest at 0.1 deg, within 2.9e-5 at 0.01 (`the_step_figures_of_the_nonsmooth_docs`).
pub const FORCE_STEP_DEG: f64 = 0.01;

impl DynamicsParams {
    /// Checks every field (each against its declared range, then the relations between them);
    /// the error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        self.drive.check_declared()?;
        self.contact.check_declared()?;
        self.friction.check_declared()?;
        self.integrator.check_declared()?;
        self.verification.check_declared()?;
        self.jam_reading.check_declared()?;
        self.series.check_declared()?;
        let method = self.integrator.method;
        let runs = [method, method];
        crate::limits::check_steps(
            "dynamics.integrator.max_steps",
            self.integrator.max_steps,
            // The verification run may take as many steps again.
            &runs[..1 + usize::from(self.verification.verify)],
        )?;
        let (vs, vd) = (
            self.friction.stiction_velocity_mm_s,
            self.friction.friction_velocity_mm_s,
        );
        if vd <= vs {
            return Err(Error::invalid(
                "dynamics.friction.friction_velocity_mm_s",
                vd,
                format!("V_d must be above the stiction velocity V_s = {vs} mm/s"),
            ));
        }
        let j = &self.jam_reading;
        if j.jam_speed_ratio >= j.arm_speed_ratio {
            return Err(Error::invalid(
                "dynamics.jam_reading.jam_speed_ratio",
                j.jam_speed_ratio,
                format!("must lie in (0, arm_speed_ratio = {})", j.arm_speed_ratio),
            ));
        }
        if self.integrator.disc == DiscMotion::Rolls && self.integrator.method != Method::Nonsmooth
        {
            return Err(Error::invalid(
                "dynamics.integrator.disc",
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
    /// unset `MOTION_STEP_DEG` with the motion drive and `FORCE_STEP_DEG` with the force drive.
    pub fn nonsmooth_step_deg(&self) -> f64 {
        self.integrator
            .nonsmooth_step_deg
            .unwrap_or(match self.drive.mode {
                Drive::Motion => MOTION_STEP_DEG,
                Drive::Force => FORCE_STEP_DEG,
            })
    }

    /// The absolute tolerance in use (atol, or rtol when unset).
    pub fn atol(&self) -> f64 {
        self.integrator.atol.unwrap_or(self.integrator.rtol)
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
                    contact: crate::dynamics::ContactLaw {
                        stiffness_n_per_mm_e: 0.0,
                        ..d.contact
                    },
                    ..d
                },
            ),
            (
                "exponent",
                DynamicsParams {
                    contact: crate::dynamics::ContactLaw {
                        exponent: -2.0,
                        ..d.contact
                    },
                    ..d
                },
            ),
            (
                "stiction_velocity_mm_s",
                DynamicsParams {
                    friction: crate::dynamics::FrictionLaw {
                        stiction_velocity_mm_s: 0.0,
                        ..d.friction
                    },
                    ..d
                },
            ),
            (
                "friction_velocity_mm_s",
                DynamicsParams {
                    friction: crate::dynamics::FrictionLaw {
                        friction_velocity_mm_s: 0.1,
                        ..d.friction
                    },
                    ..d
                },
            ),
            (
                "omega_deg_s",
                DynamicsParams {
                    drive: crate::dynamics::DriveSettings {
                        omega_deg_s: 0.0,
                        ..d.drive
                    },
                    ..d
                },
            ),
            (
                "rtol",
                DynamicsParams {
                    integrator: crate::dynamics::IntegratorSettings {
                        rtol: 1.0,
                        ..d.integrator
                    },
                    ..d
                },
            ),
            (
                "atol",
                DynamicsParams {
                    integrator: crate::dynamics::IntegratorSettings {
                        atol: Some(0.0),
                        ..d.integrator
                    },
                    ..d
                },
            ),
            (
                "damping_depth_mm",
                DynamicsParams {
                    contact: crate::dynamics::ContactLaw {
                        damping_depth_mm: f64::NAN,
                        ..d.contact
                    },
                    ..d
                },
            ),
            (
                "mu_static_palm",
                DynamicsParams {
                    friction: crate::dynamics::FrictionLaw {
                        mu_static_palm: Some(-0.1),
                        ..d.friction
                    },
                    ..d
                },
            ),
            (
                "jam_speed_ratio",
                DynamicsParams {
                    jam_reading: crate::dynamics::JamReading {
                        jam_speed_ratio: 0.95,
                        ..d.jam_reading
                    },
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
