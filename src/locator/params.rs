//! The V-locator's parameters (TOML section `[locator]`) and the V's unit vectors.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::settings::decl::{Check, Declared};

choice! {
    /// How the V carries the moment about the disc centre.
    pub enum Rotation {
        /// The disc may rotate: the flank frictions carry the moment (the physical V-block;
        /// three equations Fx, Fy, Mz).
        Free = "free",
        /// A joint carries the moment (the paper's translational formulation; two equations).
        Blocked = "blocked",
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

settings! {
    /// A disc of weight W = m g in a V of two flat flanks, loaded by P at direction phi.
    ///
    /// Angles in deg; the disc's radius does not enter (every moment about the centre is r
    /// times a force), so it is not a parameter.
    section = "locator";
    pub struct LocatorParams {
        /// Left flank angle a1 above the horizontal, in [0, 180); above 90 the flank overhangs
        /// (45: a 90 deg V).
        flank_left_deg: f64 = 45.0, symbol: "a1", quantity: "left flank angle", unit: "deg",
            check: Check::CloseOpen(0.0, 180.0);
        /// Right flank angle a2 above the horizontal, in [0, 180), with a1 + a2 in (0, 180).
        flank_right_deg: f64 = 45.0, symbol: "a2", quantity: "right flank angle", unit: "deg",
            check: Check::CloseOpen(0.0, 180.0);
        /// Coulomb friction coefficient on the left flank (0.3: dry steel on steel).
        mu_left: f64 = 0.3, flag: Some("mu-left"), symbol: "μ_left",
            quantity: "left flank friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
        /// Coulomb friction coefficient on the right flank.
        mu_right: f64 = 0.3, flag: Some("mu-right"), symbol: "μ_right",
            quantity: "right flank friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
        /// Disc mass m.
        mass_kg: f64 = 1.0, flag: Some("mass"), symbol: "m", quantity: "disc mass", unit: "kg",
            check: Check::Above(0.0), uncertain: true;
        /// Gravitational acceleration g (capacities are given per weight, so > 0).
        gravity_m_s2: f64 = 9.806, flag: Some("gravity"), symbol: "g", quantity: "gravity",
            unit: "m/s²", check: Check::Above(0.0), value_name: "M/S^2";
        /// Magnitude P of the external force (0: no load); turn it with --load-angle.
        load_n: f64 = 0.0, flag: Some("load"), symbol: "P", quantity: "load", unit: "N",
            check: Check::AtLeast(0.0), uncertain: true;
        /// Direction phi of the external force from +x, counter-clockwise.
        ///
        /// 0 pushes sideways towards the right flank, -90 straight down into the V, 90 lifts.
        load_angle_deg: f64 = 0.0, flag: Some("load-angle"), symbol: "φ",
            quantity: "load direction", unit: "deg", check: Check::Finite, uncertain: true;
        /// Apply the force at the rim point at this angle from +x about the centre (unset: at
        /// the centre).
        ///
        /// It then adds the moment r P sin(phi - psi). Under blocked rotation the joint carries
        /// that moment, so the load acts as if at the centre.
        load_at_rim_deg: Option<f64> = None, flag: Some("load-at-rim"), symbol: "ψ",
            quantity: "rim point", unit: "deg", check: Check::Finite;
        /// Whether the disc may rotate in the V: free (a real V-block) or blocked (a joint
        /// carries the moment).
        rotation: Rotation = Rotation::Free, flag: Some("rotation"), value_name: "ROTATION";
    }
}

settings! {
    /// The locator's aliases: `mu` sets both flank frictions.
    section = "locator";
    aliases LOCATOR_ALIASES {
        /// Friction coefficient on both flanks.
        ///
        /// --mu-left or --mu-right given as well take precedence for their flank.
        mu = 0.3, sets: &["mu_left", "mu_right"], flag: Some("mu"), symbol: "μ",
            quantity: "flank friction coefficient", unit: "-", check: Check::AtLeast(0.0),
            value_name: "MU", uncertain: true;
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

    /// Values that are valid but likely a unit mistake (see
    /// [`crate::scene::SceneParams::unit_warnings`]): a friction above 2, an included angle
    /// under 3 deg (radians?).
    pub fn unit_warnings(&self) -> Vec<String> {
        let mut out = crate::scene::friction_warnings(
            LOCATOR_ALIASES.iter().chain(Self::DECLS),
            &[("mu_left", self.mu_left), ("mu_right", self.mu_right)],
        );
        let gamma = self.included_angle_deg();
        if gamma < 3.0 {
            out.push(format!(
                "the included angle (--included-angle) = {gamma:.3} deg is under 3 deg; angles \
                 are in degrees, not radians"
            ));
        }
        out
    }

    /// Checks every field (each against its declared range, then the V's geometry); the
    /// error names the TOML key and the offending value.
    pub fn validate(&self) -> Result<()> {
        self.check_declared()?;
        // Capacities are given per weight: a weight that underflows to 0 or overflows printed
        // `P_max = 0.000 N = NaN W` (m = g = 1e-300).
        let w = self.weight_n();
        if !(w.is_finite() && w >= f64::MIN_POSITIVE) {
            return Err(Error::invalid(
                "mass_kg * gravity_m_s2",
                format!("{} * {} = {w}", self.mass_kg, self.gravity_m_s2),
                "the weight m g must be a positive number within the range of a 64-bit float \
                 (capacities are given per weight); scale mass or gravity",
            ));
        }
        // The net force P + W once overflowed inside the solver, whose message named its
        // internal key `load.force_n`.
        if !(self.load_n + w).is_finite() {
            return Err(Error::invalid(
                "load_n + mass_kg * gravity_m_s2",
                format!("{} + {w}", self.load_n),
                "the load and the weight together overflow a 64-bit float; scale both down (the \
                 verdict depends on their ratio only)",
            ));
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
