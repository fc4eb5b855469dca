//! The scene shared by all models: parameters, geometry (Eq. 2) and the jam status.
//!
//! Frame (Fig. 1): hinge at the origin, ground on y = 0, palm the ray from the origin at angle
//! theta above +X. The disc of radius r touches both; its centre is (x, r) with
//! x = r cot(theta/2), which is also the distance from the hinge to both contact points.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Parameters of the palm-and-disc scene (TOML section `[scene]`).
///
/// Units are in the names; defaults are the paper's (Section 3.1 and Fig. 3 caption).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SceneParams {
    /// Coulomb friction coefficient at the ground contact A (default: 0.4).
    pub mu_ground: f64,
    /// Coulomb friction coefficient at the palm contact B (default: 0.4).
    pub mu_palm: f64,
    /// Disc radius r in mm (default: 10).
    pub radius_mm: f64,
    /// Disc mass m in kg (default: 1); 0 is a weightless disc.
    pub mass_kg: f64,
    /// Magnitude F of the palm's push in N (default: 200).
    pub force_n: f64,
    /// Gravitational acceleration g in m/s^2 (default: 9.806, the paper's 9806 mm/s^2).
    pub gravity_m_s2: f64,
    /// Palm angle where the push starts, in degrees, in (0, 180) (default: 90). Above 90 deg
    /// the palm's push points upwards and every model answers `outside_model` through
    /// [`crate::models::solve`].
    pub start_angle_deg: f64,
    /// Length of the palm bar in mm (default: 150, the paper's Adams bar). The contact B lies
    /// x mm from the hinge, so a jam beyond the palm's end is never reached.
    pub palm_length_mm: f64,
}

impl Default for SceneParams {
    fn default() -> Self {
        SceneParams {
            mu_ground: 0.4,
            mu_palm: 0.4,
            radius_mm: 10.0,
            mass_kg: 1.0,
            force_n: 200.0,
            // 9806 mm/s^2 in the paper's Adams model; the m/s^2 value keeps x_jam = 24.355 mm.
            gravity_m_s2: 9.806,
            start_angle_deg: 90.0,
            palm_length_mm: 150.0,
        }
    }
}

impl SceneParams {
    /// Checks every field; the error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        finite_at_least(
            "mu_ground",
            self.mu_ground,
            0.0,
            "a friction coefficient must be a finite number >= 0",
        )?;
        finite_at_least(
            "mu_palm",
            self.mu_palm,
            0.0,
            "a friction coefficient must be a finite number >= 0",
        )?;
        finite_positive(
            "radius_mm",
            self.radius_mm,
            "the disc radius must be a finite number > 0 mm",
        )?;
        finite_at_least(
            "mass_kg",
            self.mass_kg,
            0.0,
            "the mass must be a finite number >= 0 kg",
        )?;
        finite_positive(
            "force_n",
            self.force_n,
            "the palm's push must be a finite number > 0 N",
        )?;
        finite_at_least(
            "gravity_m_s2",
            self.gravity_m_s2,
            0.0,
            "gravity must be a finite number >= 0 m/s^2",
        )?;
        let s = self.start_angle_deg;
        if !(s.is_finite() && s > 0.0 && s < 180.0) {
            return Err(Error::invalid(
                "start_angle_deg",
                s,
                "the start angle must lie strictly between 0 and 180 deg",
            ));
        }
        finite_positive(
            "palm_length_mm",
            self.palm_length_mm,
            "the palm length must be a finite number > 0 mm",
        )
    }

    /// Weight m g of the disc in N.
    pub fn weight_n(&self) -> f64 {
        self.mass_kg * self.gravity_m_s2
    }

    /// Friction angle at the ground, atan(mu_ground), in rad.
    pub fn alpha_ground(&self) -> f64 {
        self.mu_ground.atan()
    }

    /// Friction angle at the palm, atan(mu_palm), in rad.
    pub fn alpha_palm(&self) -> f64 {
        self.mu_palm.atan()
    }

    /// Sets both friction coefficients (the paper's single mu).
    pub fn with_mu(mut self, mu: f64) -> Self {
        self.mu_ground = mu;
        self.mu_palm = mu;
        self
    }
}

pub(crate) fn finite_positive(key: &str, v: f64, reason: &str) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(key, v, reason))
    }
}

pub(crate) fn finite_at_least(key: &str, v: f64, min: f64, reason: &str) -> Result<()> {
    if v.is_finite() && v >= min {
        Ok(())
    } else {
        Err(Error::invalid(key, v, reason))
    }
}

/// Disc position x (hinge to contact A, equal to hinge to contact B) in mm at palm angle
/// `theta` (rad): Eq. 2 simplified, x = r cot(theta/2).
pub fn disc_position_mm(radius_mm: f64, theta: f64) -> f64 {
    radius_mm / (0.5 * theta).tan()
}

/// Palm angle (rad) at which the disc sits at position `x_mm`: the inverse of
/// [`disc_position_mm`], theta = 2 atan(r / x).
pub fn palm_angle_at(radius_mm: f64, x_mm: f64) -> f64 {
    2.0 * (radius_mm / x_mm).atan()
}

/// What a model concludes about one push, as data a chart can colour.
///
/// JSON spellings are the snake_case names; the statics decide them in the order listed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JamStatus {
    /// theta_jam <= 0: both frictions are zero and the disc slides to the hinge's far side.
    NeverJams,
    /// The push is too weak ever to move the disc: F <= m g sin(atan mu_ground), the least push
    /// that slides it (the palm's push must overcome the ground friction it adds itself).
    TooWeak,
    /// The disc is held already at the start angle: it jams as soon as the palm touches it.
    JammedAtStart,
    /// The jam point lies beyond the palm's end, so the palm loses the disc first.
    BeyondReach,
    /// The disc slides, then jams at theta_jam.
    Jams,
    /// A simulation's answer failed its cross-check against the quasi-static limit or its error
    /// estimate (too loose a tolerance); its numbers are reported but must not be trusted.
    Inaccurate,
    /// A simulation's integrator gave up before the jam (the time and reason are reported).
    IntegratorFailed,
    /// The scene lies outside what this model represents (a typed reason says why); the other
    /// models may still answer it.
    OutsideModel,
}

impl JamStatus {
    /// The JSON spelling, e.g. `jammed_at_start`.
    pub fn as_str(self) -> &'static str {
        match self {
            JamStatus::NeverJams => "never_jams",
            JamStatus::TooWeak => "too_weak",
            JamStatus::JammedAtStart => "jammed_at_start",
            JamStatus::BeyondReach => "beyond_reach",
            JamStatus::Jams => "jams",
            JamStatus::Inaccurate => "inaccurate",
            JamStatus::IntegratorFailed => "integrator_failed",
            JamStatus::OutsideModel => "outside_model",
        }
    }
}

impl std::fmt::Display for JamStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_tangents_eq2_simplifies() {
        // Eq. 2 as printed: r(1 + cos t)/tan t + r sin t; the crate docs say it equals r cot(t/2).
        for deg in [10.0_f64, 30.0, 44.646, 60.0, 89.0, 120.0] {
            let t = deg.to_radians();
            let r = 10.0;
            let eq2 = r * (1.0 + t.cos()) / t.tan() + r * t.sin();
            let x = disc_position_mm(r, t);
            assert!(
                (eq2 - x).abs() < 1e-12 * x.abs().max(1.0),
                "{deg}: {eq2} vs {x}"
            );
            assert!((palm_angle_at(r, x) - t).abs() < 1e-14);
        }
    }

    #[test]
    fn status_text_is_its_json_spelling() {
        use JamStatus::*;
        for s in [
            NeverJams,
            TooWeak,
            JammedAtStart,
            BeyondReach,
            Jams,
            Inaccurate,
            IntegratorFailed,
            OutsideModel,
        ] {
            assert_eq!(serde_json::to_value(s).unwrap(), s.as_str(), "{s:?}");
        }
    }

    #[test]
    fn validate_names_the_key() {
        let p = SceneParams {
            radius_mm: -1.0,
            ..Default::default()
        };
        let msg = p.validate().unwrap_err().to_string();
        assert!(msg.contains("radius_mm") && msg.contains("-1"), "{msg}");
        let p = SceneParams {
            start_angle_deg: 180.0,
            ..Default::default()
        };
        assert!(
            p.validate()
                .unwrap_err()
                .to_string()
                .contains("start_angle_deg")
        );
        let p = SceneParams {
            mu_palm: f64::NAN,
            ..Default::default()
        };
        assert!(
            p.validate()
                .unwrap_err()
                .to_string()
                .contains("mu_palm = NaN")
        );
        assert!(SceneParams::default().validate().is_ok());
    }
}
