//! The V-locator's parameters (TOML section `[locator]`) and the V's unit vectors.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::scene::{finite_at_least, finite_positive};

/// How the V carries the moment about the disc centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Rotation {
    /// The disc may rotate: the flank frictions carry the moment (the physical V-block; three
    /// equations Fx, Fy, Mz).
    #[default]
    Free,
    /// A joint carries the moment (the paper's translational formulation; two equations).
    Blocked,
}

impl Rotation {
    /// The TOML and flag spelling.
    pub fn as_str(self) -> &'static str {
        match self {
            Rotation::Free => "free",
            Rotation::Blocked => "blocked",
        }
    }
}

/// One flank of the V.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Flank {
    /// The flank rising to the left of the vertex, at angle a1 above the horizontal.
    Left,
    /// The flank rising to the right of the vertex, at angle a2 above the horizontal.
    Right,
}

impl Flank {
    /// Both flanks, left first (the order of every per-flank array).
    pub const BOTH: [Flank; 2] = [Flank::Left, Flank::Right];

    /// "left" or "right".
    pub fn as_str(self) -> &'static str {
        match self {
            Flank::Left => "left",
            Flank::Right => "right",
        }
    }

    /// 0 for the left flank, 1 for the right.
    pub fn index(self) -> usize {
        self as usize
    }

    /// The other flank.
    pub fn other(self) -> Flank {
        match self {
            Flank::Left => Flank::Right,
            Flank::Right => Flank::Left,
        }
    }
}

/// A disc of weight W = m g in a V of two flat flanks, loaded by P at direction phi.
///
/// Angles in deg; the disc's radius does not enter (every moment about the centre is r times a
/// force), so it is not a parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LocatorParams {
    /// Left flank angle a1 above the horizontal in deg, in [0, 180) (default: 45, a 90 deg V).
    /// Above 90 the flank overhangs.
    pub flank_left_deg: f64,
    /// Right flank angle a2 above the horizontal in deg, in [0, 180), with a1 + a2 in (0, 180)
    /// (default: 45).
    pub flank_right_deg: f64,
    /// Coulomb friction coefficient on the left flank, >= 0 (default: 0.3, dry steel on steel).
    pub mu_left: f64,
    /// Coulomb friction coefficient on the right flank, >= 0 (default: 0.3).
    pub mu_right: f64,
    /// Disc mass m in kg, > 0 (default: 1).
    pub mass_kg: f64,
    /// Gravitational acceleration g in m/s^2, > 0 (default: 9.806).
    pub gravity_m_s2: f64,
    /// Magnitude P of the external force in N, >= 0 (default: 0, no load).
    pub load_n: f64,
    /// Direction phi of the external force in deg from +x, counter-clockwise (default: 0,
    /// sideways towards the right flank; -90 pushes straight down).
    pub load_angle_deg: f64,
    /// Where the force acts: at the rim point at angle psi (deg from +x about the centre),
    /// adding the moment r P sin(phi - psi); absent, at the centre (default: centre). Only
    /// with free rotation: a blocked V's joint carries every moment.
    pub load_at_rim_deg: Option<f64>,
    /// Free or blocked rotation (default: free).
    pub rotation: Rotation,
}

impl Default for LocatorParams {
    fn default() -> Self {
        LocatorParams {
            flank_left_deg: 45.0,
            flank_right_deg: 45.0,
            mu_left: 0.3,
            mu_right: 0.3,
            mass_kg: 1.0,
            gravity_m_s2: 9.806,
            load_n: 0.0,
            load_angle_deg: 0.0,
            load_at_rim_deg: None,
            rotation: Rotation::Free,
        }
    }
}

impl LocatorParams {
    /// A symmetric V of included angle `gamma_deg` (a1 = a2 = 90 - gamma/2), other fields kept.
    pub fn with_included_angle(mut self, gamma_deg: f64) -> Self {
        self.flank_left_deg = 90.0 - 0.5 * gamma_deg;
        self.flank_right_deg = self.flank_left_deg;
        self
    }

    /// The same V turned to included angle `gamma_deg` about its bisector (the tilt
    /// (a1 - a2)/2 is kept).
    pub fn with_included_angle_same_tilt(mut self, gamma_deg: f64) -> Self {
        let tilt = 0.5 * (self.flank_left_deg - self.flank_right_deg);
        self.flank_left_deg = 90.0 - 0.5 * gamma_deg + tilt;
        self.flank_right_deg = 90.0 - 0.5 * gamma_deg - tilt;
        self
    }

    /// Both frictions set to `mu`.
    pub fn with_mu(mut self, mu: f64) -> Self {
        self.mu_left = mu;
        self.mu_right = mu;
        self
    }

    /// Included angle gamma = 180 - a1 - a2 in deg.
    pub fn included_angle_deg(&self) -> f64 {
        180.0 - self.flank_left_deg - self.flank_right_deg
    }

    /// The disc's weight W = m g in N.
    pub fn weight_n(&self) -> f64 {
        self.mass_kg * self.gravity_m_s2
    }

    /// The friction coefficients, left first.
    pub fn mu(&self) -> [f64; 2] {
        [self.mu_left, self.mu_right]
    }

    /// Checks every field; the error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        for (key, a) in [
            ("flank_left_deg", self.flank_left_deg),
            ("flank_right_deg", self.flank_right_deg),
        ] {
            if !(a.is_finite() && (0.0..180.0).contains(&a)) {
                return Err(Error::invalid(
                    key,
                    a,
                    "a flank angle lies in [0, 180) deg above the horizontal",
                ));
            }
        }
        let sum = self.flank_left_deg + self.flank_right_deg;
        if !(sum > 0.0 && sum < 180.0) {
            return Err(Error::invalid(
                "flank_left_deg + flank_right_deg",
                sum,
                "two flanks hold a disc only if a1 + a2 lies in (0, 180) deg (included angle \
                 180 - a1 - a2 in (0, 180))",
            ));
        }
        for (key, mu) in [("mu_left", self.mu_left), ("mu_right", self.mu_right)] {
            finite_at_least(
                key,
                mu,
                0.0,
                "a friction coefficient is a finite number >= 0",
            )?;
        }
        finite_positive(
            "mass_kg",
            self.mass_kg,
            "the mass is a finite number > 0 kg",
        )?;
        finite_positive(
            "gravity_m_s2",
            self.gravity_m_s2,
            "gravity is a finite number > 0 m/s^2 (capacities are given per weight)",
        )?;
        finite_at_least(
            "load_n",
            self.load_n,
            0.0,
            "the load is a finite number >= 0 N; turn it with load_angle_deg",
        )?;
        if !self.load_angle_deg.is_finite() {
            return Err(Error::invalid(
                "load_angle_deg",
                self.load_angle_deg,
                "the load direction is a finite angle in deg",
            ));
        }
        if let Some(psi) = self.load_at_rim_deg {
            if !psi.is_finite() {
                return Err(Error::invalid(
                    "load_at_rim_deg",
                    psi,
                    "the rim point is a finite angle in deg",
                ));
            }
            if self.rotation == Rotation::Blocked {
                return Err(Error::invalid(
                    "load_at_rim_deg",
                    psi,
                    "a blocked V carries every moment in its joint, so the load acts as if at \
                     the centre; leave the rim point out or use rotation = free",
                ));
            }
        }
        Ok(())
    }

    /// The V's unit vectors in a frame at the disc centre.
    pub(crate) fn frame(&self) -> Frame {
        Frame::new(self.flank_left_deg, self.flank_right_deg)
    }
}

/// A plane vector.
pub(crate) type V2 = [f64; 2];

/// a x b (z component).
pub(crate) fn cross(a: V2, b: V2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

/// The V's unit vectors: inward normals n_i (the direction a flank pushes the disc) and
/// tangents u_i up each flank, away from the vertex.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Frame {
    /// n_1 = (sin a1, cos a1), n_2 = (-sin a2, cos a2).
    pub n: [V2; 2],
    /// u_1 = (-cos a1, sin a1), u_2 = (cos a2, sin a2).
    pub u: [V2; 2],
}

impl Frame {
    pub(crate) fn new(a1_deg: f64, a2_deg: f64) -> Self {
        let (s1, c1) = a1_deg.to_radians().sin_cos();
        let (s2, c2) = a2_deg.to_radians().sin_cos();
        Frame {
            n: [[s1, c1], [-s2, c2]],
            u: [[-c1, s1], [c2, s2]],
        }
    }

    /// Solves N1 n1 + N2 n2 = r for (N1, N2); det = n1 x n2 = sin(a1 + a2) > 0.
    pub(crate) fn normal_split(&self, r: V2) -> [f64; 2] {
        let det = cross(self.n[0], self.n[1]);
        [cross(r, self.n[1]) / det, cross(self.n[0], r) / det]
    }
}
