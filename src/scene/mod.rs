//! The scene shared by all models: parameters, geometry (Eq. 2) and the jam status.
//!
//! Frame (Fig. 1): hinge at the origin, ground on y = 0, palm the ray from the origin at angle
//! theta above +X. The disc of radius r touches both; its centre is (x, r) with
//! x = r cot(theta/2), which is also the distance from the hinge to both contact points. A palm
//! whose face lies h off the hinge line (its thickness) puts the disc at
//! x = r cot(theta/2) + h / sin(theta) ([`disc_position_mm`]).

mod param;

pub use param::Param;
pub(crate) use param::Setter;

use crate::error::{Error, Result};
use crate::settings::decl::{Check, Decl, Declared};

settings! {
    /// Parameters of the palm-and-disc scene.
    ///
    /// Units are in the names; defaults are the paper's (Section 3.1 and Fig. 3 caption).
    section = "scene";
    pub struct SceneParams {
        /// Coulomb friction coefficient at the ground contact A.
        mu_ground: f64 = 0.4, flag: Some("mu-ground"), symbol: "μ_ground",
            quantity: "ground friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
        /// Coulomb friction coefficient at the palm contact B.
        mu_palm: f64 = 0.4, flag: Some("mu-palm"), symbol: "μ_palm",
            quantity: "palm friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
        /// Disc radius r.
        radius_mm: f64 = 10.0, flag: Some("radius"), symbol: "r", quantity: "disc radius",
            unit: "mm", check: Check::Above(0.0);
        /// Disc mass m; 0 is a weightless disc.
        mass_kg: f64 = 1.0, flag: Some("mass"), symbol: "m", quantity: "disc mass",
            unit: "kg", check: Check::AtLeast(0.0), uncertain: true;
        /// Palm push F: the magnitude of the palm's force on the disc while it slides.
        ///
        /// F -> infinity is a palm driven by prescribed motion.
        force_n: f64 = 200.0, flag: Some("force"), symbol: "F", quantity: "palm push",
            unit: "N", check: Check::Above(0.0), uncertain: true;
        /// Gravitational acceleration g (the paper's 9806 mm/s^2).
        // 9.806, not 9.81: the paper's Adams model has 9806 mm/s^2, which keeps x_jam = 24.355 mm.
        gravity_m_s2: f64 = 9.806, flag: Some("gravity"), symbol: "g", quantity: "gravity",
            unit: "m/s²", check: Check::AtLeast(0.0), value_name: "M/S^2";
        /// Palm angle where the push starts, in (0, 180).
        ///
        /// Above 90 deg the palm's push points upwards and can lift the disc: every model
        /// answers outside_model there.
        start_angle_deg: f64 = 90.0, flag: Some("start-angle"), symbol: "θ_start",
            quantity: "start angle of the palm", unit: "deg", check: Check::Open(0.0, 180.0);
        /// Length of the palm bar: a jam beyond its end is never reached.
        ///
        /// The contact B lies x mm from the hinge along the palm (x - h tan(theta/2) with a palm
        /// offset h).
        /// The paper's Adams bar is 150 mm.
        palm_length_mm: f64 = 150.0, flag: Some("palm-length"), symbol: "L_palm",
            quantity: "palm length", unit: "mm", check: Check::Above(0.0);
        /// Offset h of the palm's contact face from the hinge line (half the bar's thickness).
        ///
        /// The forces keep their directions, so theta_jam does not change; the disc sits
        /// h / sin(theta) further out: x = r cot(theta/2) + h / sin(theta). 0 is the paper's
        /// theory; its 1 mm bars give 0.5.
        palm_offset_mm: f64 = 0.0, flag: Some("palm-offset"), symbol: "h",
            quantity: "palm offset", unit: "mm", check: Check::AtLeast(0.0);
    }
}

settings! {
    /// The scene's aliases: `mu` sets both frictions (the paper's single mu).
    section = "scene";
    aliases SCENE_ALIASES {
        /// Friction coefficient at both contacts (the paper's single mu).
        ///
        /// --mu-ground or --mu-palm given as well take precedence for their contact.
        mu = 0.4, sets: &["mu_ground", "mu_palm"], flag: Some("mu"), symbol: "μ",
            quantity: "friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
    }
}

impl SceneParams {
    /// Checks every field; the error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        self.check_declared()
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

    /// Disc position x in mm (hinge to the ground contact A) where the disc touches the palm
    /// at palm angle `theta` (rad): x = r cot(theta/2) + h / sin(theta) (`disc_position_mm`
    /// with this scene's radius and palm offset).
    pub fn disc_position_mm(&self, theta: f64) -> f64 {
        disc_position_mm(self.radius_mm, self.palm_offset_mm, theta)
    }

    /// The palm angle (rad) at which the disc sits at `x_mm`: the inverse of
    /// [`SceneParams::disc_position_mm`] (`palm_angle_at`).
    pub fn palm_angle_at(&self, x_mm: f64) -> f64 {
        palm_angle_at(self.radius_mm, self.palm_offset_mm, x_mm)
    }

    /// The palm angle (rad) below which the contact B lies past the palm's end: where
    /// s_B = r cot(theta/2) + h cot(theta) = L. With t = tan(theta/2) that is
    /// h t^2 + 2 L t - (2 r + h) = 0, so t = (2 r + h) / (L + sqrt(L^2 + h (2 r + h))), which
    /// is r / L for h = 0.
    ///
    /// t is a ratio of lengths, so it is computed on the lengths over the largest of them: at
    /// r = 1e308, 2 r overflowed and h (2 r + h) was 0 x inf = NaN for h = 0, and a NaN reach
    /// sent the min-norm search into a scene beyond the palm (a search that never ended).
    pub fn reach_angle(&self) -> f64 {
        let (r, h, l) = (self.radius_mm, self.palm_offset_mm, self.palm_length_mm);
        let scale = r.max(h).max(l);
        let (r, h, l) = (r / scale, h / scale, l / scale);
        2.0 * ((2.0 * r + h) / (l + l.hypot((h * (2.0 * r + h)).sqrt()))).atan()
    }

    /// Values that are valid but likely a unit mistake, one sentence each naming the key (and
    /// its flag): a friction coefficient above 2 (a percentage?), a radius under 0.5 mm
    /// (metres?), a palm shorter than the radius (cm?), a mass heavier than a steel bar of the
    /// disc's radius 10 m long (grams?), a start angle under 3 deg (radians?). The caller prints them as warnings; the answer is still computed.
    pub fn unit_warnings(&self) -> Vec<String> {
        let family = SCENE_ALIASES.iter().chain(Self::DECLS);
        let mut out = friction_warnings(
            family.clone(),
            &[("mu_ground", self.mu_ground), ("mu_palm", self.mu_palm)],
        );
        if self.radius_mm < 0.5 {
            out.push(likely_mistake(
                family.clone(),
                "radius_mm",
                self.radius_mm,
                "mm is under 0.5 mm; the radius is in mm, not metres",
            ));
        }
        if self.palm_length_mm < self.radius_mm {
            out.push(likely_mistake(
                family.clone(),
                "palm_length_mm",
                self.palm_length_mm,
                &format!(
                    "mm is shorter than the disc's radius ({} mm); the length is in mm, not cm",
                    crate::numbers::Num(self.radius_mm)
                ),
            ));
        }
        // A radius in metres makes any mass look heavy: its own warning says what is wrong.
        let bar_m = steel_bar_length_m(self.mass_kg, self.radius_mm);
        if bar_m > STEEL_BAR_LIMIT_M && self.radius_mm >= 0.5 {
            // A mass near the float range overflowed the rounding to 0.1 m ("inf m long"), or
            // the length itself on a thin part; from 1e15 m on a tenth of a metre is no digit.
            let shown = match bar_m < 1e15 {
                true => crate::numbers::Num((bar_m * 10.0).round() / 10.0).to_string(),
                false => crate::numbers::sig(bar_m, 4),
            };
            let bar = match bar_m.is_finite() {
                true => format!("as much as a steel bar of this radius {shown} m long"),
                false => format!(
                    "more than a steel bar of this radius {:.1e} m long",
                    f64::MAX
                ),
            };
            out.push(likely_mistake(
                family.clone(),
                "mass_kg",
                self.mass_kg,
                &format!("kg weighs {bar}; the mass is in kg, not grams"),
            ));
        }
        if self.start_angle_deg < 3.0 {
            out.push(likely_mistake(
                family,
                "start_angle_deg",
                self.start_angle_deg,
                "deg is under 3 deg; the angle is in degrees, not radians",
            ));
        }
        out
    }

    /// Distance in mm from the hinge along the palm to the contact B at palm angle `theta`
    /// (rad), `contact_distance_mm`.
    pub fn contact_distance_mm(&self, theta: f64) -> f64 {
        contact_distance_mm(self.radius_mm, self.palm_offset_mm, theta)
    }

    /// Distance in mm from the hinge along the palm to the contact B at the start angle, its
    /// right angles exact (`sin_cos_deg`): r cot(theta/2) + h cot(theta), r at 90 deg
    /// however far the palm's face lies off the hinge line.
    pub fn start_contact_distance_mm(&self) -> f64 {
        let (r, h) = (self.radius_mm, self.palm_offset_mm);
        let (sin, cos) = sin_cos_deg(self.start_angle_deg);
        // cot(theta/2) = (1 + cos) / sin, cot(theta) = cos / sin.
        r * (1.0 + cos) / sin + h * cos / sin
    }
}

/// A warning for each friction coefficient above 2 (a percentage?), as (key, value) of a
/// setting of `family`.
pub(crate) fn friction_warnings(
    family: impl Iterator<Item = &'static Decl> + Clone,
    frictions: &[(&str, f64)],
) -> Vec<String> {
    // Equal frictions (set together by --mu) are one warning, not one per contact.
    let mut out: Vec<String> = Vec::new();
    for (k, (key, mu)) in frictions.iter().enumerate() {
        if *mu <= 2.0 || frictions[..k].iter().any(|(_, m)| m == mu) {
            continue;
        }
        let why = "is above 2, unusual for a friction coefficient; is it a percentage?";
        let same: Vec<&str> = frictions[k + 1..]
            .iter()
            .filter(|(_, m)| m == mu)
            .map(|(other, _)| *other)
            .collect();
        out.push(match same.is_empty() {
            true => likely_mistake(family.clone(), key, *mu, why),
            false => format!(
                "{key} and {} are both {}, above 2, unusual for a friction coefficient; is it a \
                 percentage?",
                same.join(" and "),
                crate::numbers::Num(*mu)
            ),
        });
    }
    out
}

/// A warning that `key` = `value` (a setting of `family`) looks like a unit mistake: "mu_palm
/// (--mu-palm or --mu) = 40 is above 2, ...".
fn likely_mistake(
    family: impl Iterator<Item = &'static Decl> + Clone,
    key: &str,
    value: f64,
    why: &str,
) -> String {
    let flags = family
        .clone()
        .find(|d| d.key == key)
        .and_then(|d| d.flags(family));
    let flag = flags.map_or(String::new(), |f| format!(" ({f})"));
    format!("{key}{flag} = {} {why}", crate::numbers::Num(value))
}

/// Density of steel in kg/m^3: the yardstick of the mass warning (few parts are denser).
const STEEL_DENSITY_KG_M3: f64 = 7850.0;

/// A part heavier than a steel bar of its radius this long (m) is taken for a unit mistake: the
/// paper's 1 kg disc of radius 10 mm is such a bar 0.4 m long, a mass typed in grams (400 for
/// 0.4 kg on a 12.5 mm part) one 103.8 m long.
const STEEL_BAR_LIMIT_M: f64 = 10.0;

/// Length in m of a steel bar of radius `radius_mm` that weighs `mass_kg`.
fn steel_bar_length_m(mass_kg: f64, radius_mm: f64) -> f64 {
    let r_m = radius_mm * 1e-3;
    mass_kg / (STEEL_DENSITY_KG_M3 * std::f64::consts::PI * r_m * r_m)
}

/// Largest start angle any model represents, in deg: above it the palm's push points upwards.
pub(crate) const MAX_START_ANGLE_DEG: f64 = 90.0;

pub(crate) fn finite_positive(key: &str, v: f64, reason: &str) -> Result<()> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::invalid(key, v, reason))
    }
}

/// Disc position x in mm (hinge to the ground contact A) where a disc of radius `radius_mm`
/// touches a palm at angle `theta` (rad) whose face lies `offset_mm` off the hinge line:
///
/// ```text
/// x = r cot(theta/2) + h / sin(theta)            (Eq. 2, simplified, plus the palm's offset)
/// ```
///
/// The centre (x, r) lies r + h from the hinge line: x sin(theta) - r cos(theta) = r + h, and
/// r (1 + cos t) / sin t = r cot(t/2). With h = 0, x is also the distance from the hinge to B.
pub fn disc_position_mm(radius_mm: f64, offset_mm: f64, theta: f64) -> f64 {
    let base = radius_mm / (0.5 * theta).tan();
    if offset_mm == 0.0 {
        base
    } else {
        base + offset_mm / theta.sin()
    }
}

/// Palm angle (rad) at which the disc sits at position `x_mm`: the inverse of
/// [`disc_position_mm`], theta = atan2(r, x) + asin((r + h) / hypot(x, r)) (from
/// x sin(theta) - r cos(theta) = r + h), which is 2 atan(r / x) for h = 0.
pub fn palm_angle_at(radius_mm: f64, offset_mm: f64, x_mm: f64) -> f64 {
    if offset_mm == 0.0 {
        return 2.0 * (radius_mm / x_mm).atan();
    }
    let reach = ((radius_mm + offset_mm) / x_mm.hypot(radius_mm)).min(1.0);
    radius_mm.atan2(x_mm) + reach.asin()
}

/// Distance in mm from the hinge along the palm to the contact B at palm angle `theta` (rad):
/// s_B = x cos(theta) + r sin(theta) = r cot(theta/2) + h cot(theta), which is x for h = 0
/// (equal tangents) and x - h tan(theta/2) for an offset palm. The palm's reach is judged on it.
pub fn contact_distance_mm(radius_mm: f64, offset_mm: f64, theta: f64) -> f64 {
    contact_distance_at_mm(
        radius_mm,
        offset_mm,
        theta,
        disc_position_mm(radius_mm, offset_mm, theta),
    )
}

/// sin and cos of an angle given in degrees, both exact at a whole number of right angles
/// (cos 90 deg = 0), as `deg.to_radians().sin_cos()` elsewhere.
///
/// 90 deg in radians is pi/2 rounded to a double, whose cosine is 6.1e-17, not 0; a length
/// multiplied by it is wrong by that fraction of itself: with a palm face 1e300 mm off the
/// hinge line, `solve` said the palm touches the disc 6.1e283 mm from the hinge at the start
/// angle 90 deg, where r cot(45 deg) + h cot(90 deg) = r = 10 mm. An angle that is not a
/// right angle keeps the bits it had, so no chart moves.
pub(crate) fn sin_cos_deg(deg: f64) -> (f64, f64) {
    // A whole number k of right angles: deg / 90 is then exact, and so is 90 k below 2^53 (a
    // product, where fmod's remainder is a loop in libm); beyond, the remainder decides.
    let k = (deg / 90.0).round();
    let quarter = match k.abs() <= 1e14 {
        true => (k * 90.0 == deg).then(|| (k as i64).rem_euclid(4)),
        false => (deg % 90.0 == 0.0).then(|| k.rem_euclid(4.0) as i64),
    };
    let Some(quarter) = quarter else {
        return deg.to_radians().sin_cos();
    };
    match quarter {
        0 => (0.0, 1.0),
        1 => (1.0, 0.0),
        2 => (0.0, -1.0),
        _ => (-1.0, 0.0),
    }
}

/// [`contact_distance_mm`] where the disc's position `x` (mm) at `theta` is known.
pub(crate) fn contact_distance_at_mm(radius_mm: f64, offset_mm: f64, theta: f64, x: f64) -> f64 {
    if offset_mm == 0.0 {
        x
    } else {
        x * theta.cos() + radius_mm * theta.sin()
    }
}

choice! {
    /// What a model concludes about one push, as data a chart can colour.
    ///
    /// The statics decide them in the order listed.
    pub enum JamStatus {
        /// theta_jam <= 0: both frictions are zero and the disc slides to the hinge's far side.
        NeverJams = "never_jams",
        /// The push is too weak ever to move the disc: F <= m g sin(atan mu_ground), the least
        /// push that slides it (the palm's push must overcome the ground friction it adds itself).
        TooWeak = "too_weak",
        /// The disc is held already at the start angle: it jams as soon as the palm touches it.
        JammedAtStart = "jammed_at_start",
        /// The jam point lies beyond the palm's end, so the palm loses the disc first.
        BeyondReach = "beyond_reach",
        /// The disc slides, then jams at theta_jam.
        Jams = "jams",
        /// A simulation's answer failed its cross-check against the quasi-static limit or its
        /// error estimate (too loose a tolerance); its numbers are reported but must not be
        /// trusted.
        Inaccurate = "inaccurate",
        /// A simulation's integrator gave up before the jam (the time and reason are reported).
        IntegratorFailed = "integrator_failed",
        /// The scene lies outside what this model represents (a typed reason says why); the
        /// other models may still answer it.
        OutsideModel = "outside_model",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The right angles are told by a product, not a remainder: every angle is taken as a
    /// whole number of right angles exactly where `deg % 90 == 0`, and gets the same sine and
    /// cosine as the remainder's rule gave, near the limits of a double's integers too.
    #[test]
    fn a_right_angle_is_told_as_the_remainder_tells_it() {
        let by_remainder = |deg: f64| -> (f64, f64) {
            if deg % 90.0 != 0.0 {
                return deg.to_radians().sin_cos();
            }
            match (deg / 90.0).rem_euclid(4.0) as u8 {
                0 => (0.0, 1.0),
                1 => (1.0, 0.0),
                2 => (0.0, -1.0),
                _ => (-1.0, 0.0),
            }
        };
        let mut angles = vec![
            0.0, -0.0, 90.0, -90.0, 180.0, 270.0, 360.0, 450.0, -630.0, 45.0,
        ];
        angles.extend([
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            f64::MIN,
        ]);
        angles.extend([
            1e-300,
            90.0 + 1e-13,
            9e15,
            9.0e15 + 2.0,
            9.1e15,
            1e16,
            1e17 + 16.0,
        ]);
        for k in [1e13, 1e14, 1e14 + 1.0, 1e15 - 1.0, 2f64.powi(53) / 90.0] {
            let k = k.round();
            angles.extend([90.0 * k, 90.0 * k + 1.0, 90.0 * (k + 1.0), -90.0 * k]);
        }
        angles.extend((-2000..2000).map(|i| f64::from(i) * 0.5));
        for deg in angles {
            let (ours, theirs) = (sin_cos_deg(deg), by_remainder(deg));
            assert!(
                ours.0.to_bits() == theirs.0.to_bits() && ours.1.to_bits() == theirs.1.to_bits(),
                "{deg:e}: {ours:?} against {theirs:?}"
            );
        }
    }

    /// `solve --mass 1e308` warned of "a steel bar of this radius inf m long": rounding the
    /// bar's length to 0.1 m overflowed (and on a thin part the length itself does). It gives
    /// the length, or says the bar is longer than any double counts.
    #[test]
    fn a_mass_near_the_float_range_warns_without_inf() {
        for (mass_kg, radius_mm, says) in [
            (
                1e308,
                10.0,
                "as much as a steel bar of this radius 4.055e307 m long",
            ),
            (
                5e307,
                10.0,
                "as much as a steel bar of this radius 2.027e307 m long",
            ),
            (
                f64::MAX,
                0.5,
                "more than a steel bar of this radius 1.8e308 m long",
            ),
        ] {
            let w = SceneParams {
                mass_kg,
                radius_mm,
                ..SceneParams::default()
            }
            .unit_warnings()
            .join("\n");
            assert!(w.contains(says), "{w}");
            assert!(!w.contains("inf"), "{w}");
        }
        let grams = SceneParams {
            mass_kg: 400.0,
            radius_mm: 12.5,
            ..SceneParams::default()
        };
        assert!(grams.unit_warnings().join("\n").contains("103.8 m long"));
    }

    /// The reach at the ends of the float range: a radius of 1e308 gave a NaN reach (2 r
    /// overflowed, then 0 x inf), so a disc far beyond the palm was searched for a jam. Every
    /// reach is an angle in [0, 180] deg, 180 where the disc is out of any palm's reach, and
    /// the paper's scene keeps its 2 atan(r / L).
    #[test]
    fn the_reach_is_an_angle_at_any_length() {
        let lengths = [5e-324, 1e-300, 1e-3, 10.0, 150.0, 1e300, 1e308, f64::MAX];
        for (&r, &l, &h) in lengths.iter().flat_map(|r| {
            lengths
                .iter()
                .flat_map(move |l| [(r, l, &0.0), (r, l, &0.5)])
        }) {
            let p = SceneParams {
                radius_mm: r,
                palm_length_mm: l,
                palm_offset_mm: h,
                ..SceneParams::default()
            };
            let reach = p.reach_angle();
            assert!(
                (0.0..=std::f64::consts::PI).contains(&reach),
                "r {r}, L {l}, h {h}: {reach}"
            );
        }
        let far = SceneParams {
            radius_mm: 1e308,
            ..SceneParams::default()
        };
        assert!((far.reach_angle() - std::f64::consts::PI).abs() < 1e-12);
        let paper = SceneParams::default();
        let want = 2.0 * (paper.radius_mm / paper.palm_length_mm).atan();
        assert!((paper.reach_angle() - want).abs() < 1e-15);
    }

    #[test]
    fn equal_tangents_eq2_simplifies() {
        // Eq. 2 as printed: r(1 + cos t)/tan t + r sin t; the crate docs say it equals r cot(t/2).
        for deg in [10.0_f64, 30.0, 44.646, 60.0, 89.0, 120.0] {
            let t = deg.to_radians();
            let r = 10.0;
            let eq2 = r * (1.0 + t.cos()) / t.tan() + r * t.sin();
            let x = disc_position_mm(r, 0.0, t);
            assert!(
                (eq2 - x).abs() < 1e-12 * x.abs().max(1.0),
                "{deg}: {eq2} vs {x}"
            );
            assert!((palm_angle_at(r, 0.0, x) - t).abs() < 1e-14);
        }
    }

    #[test]
    fn status_text_is_its_json_spelling() {
        assert_eq!(JamStatus::ALL.len(), 8);
        for &s in JamStatus::ALL {
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
