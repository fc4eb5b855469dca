//! Adams' contact laws: the IMPACT normal force and the velocity-regularised Coulomb friction,
//! each with its derivatives for the analytic Jacobian.
//!
//! Adams' `STEP(x, x0, h0, x1, h1)` is the cubic blend
//!
//! ```text
//! STEP = h0                                   x <= x0
//!      = h0 + (h1 - h0) s^2 (3 - 2 s),        s = (x - x0)/(x1 - x0), x0 < x < x1
//!      = h1                                   x >= x1
//! ```
//!
//! whose slope vanishes at both ends, so every law below is continuously differentiable.

/// Adams' STEP function and its derivative d STEP / dx.
pub fn step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> (f64, f64) {
    if x <= x0 {
        (h0, 0.0)
    } else if x >= x1 {
        (h1, 0.0)
    } else {
        let w = x1 - x0;
        let s = (x - x0) / w;
        let a = h1 - h0;
        (
            h0 + a * s * s * (3.0 - 2.0 * s),
            a * 6.0 * s * (1.0 - s) / w,
        )
    }
}

/// Adams' IMPACT force between the palm and the disc.
///
/// With penetration delta (mm) and its rate delta_dot (mm/s, positive while closing):
///
/// ```text
/// N = max(0, k delta^e + STEP(delta, 0, 0, d, c_max) delta_dot)   delta > 0
///   = 0                                                           delta <= 0
/// ```
///
/// k in N/mm^e, c_max in N s/mm, d in mm: the damping ramps in over the first d of penetration
/// so that the force is continuous at first touch, and the max(0, .) keeps the contact from
/// pulling while it separates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactLaw {
    /// k in N/mm^e.
    pub stiffness: f64,
    /// e (>= 1).
    pub exponent: f64,
    /// c_max in N s/mm.
    pub damping: f64,
    /// d in mm.
    pub depth: f64,
}

/// The IMPACT force and its partial derivatives.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ImpactForce {
    /// N in newtons.
    pub normal: f64,
    /// dN/d delta in N/mm.
    pub d_delta: f64,
    /// dN/d delta_dot in N s/mm.
    pub d_rate: f64,
}

impl ImpactLaw {
    /// The elastic force k delta^e in N and its slope in N/mm (zero without contact).
    pub fn elastic(&self, delta: f64) -> (f64, f64) {
        if delta <= 0.0 {
            return (0.0, 0.0);
        }
        let p = self.stiffness * delta.powf(self.exponent - 1.0);
        (p * delta, self.exponent * p)
    }

    /// Period in s of a disc of `mass_kg` oscillating on the contact at penetration `delta`
    /// (mm): T = 2 pi sqrt(m / k) with k the elastic slope in N/m; 0 without contact.
    pub fn period_s(&self, mass_kg: f64, delta: f64) -> f64 {
        let (_, stiffness_n_per_mm) = self.elastic(delta);
        if stiffness_n_per_mm > 0.0 {
            std::f64::consts::TAU * (mass_kg / (super::MM_PER_M * stiffness_n_per_mm)).sqrt()
        } else {
            0.0
        }
    }

    /// The normal force at penetration `delta` (mm) closing at `rate` (mm/s); `elastic` is
    /// [`ImpactLaw::elastic`] at `delta`, which the caller computes once (the force drive needs it
    /// too, and it costs a `powf`).
    pub fn force(&self, delta: f64, rate: f64, elastic: (f64, f64)) -> ImpactForce {
        if delta <= 0.0 {
            return ImpactForce::default();
        }
        let (elastic, d_elastic) = elastic;
        let (c, dc) = step(delta, 0.0, 0.0, self.depth, self.damping);
        let n = elastic + c * rate;
        if n <= 0.0 {
            return ImpactForce::default();
        }
        ImpactForce {
            normal: n,
            d_delta: d_elastic + dc * rate,
            d_rate: c,
        }
    }
}

/// Adams' velocity-regularised Coulomb friction coefficient (contacts and joints alike).
///
/// For slip velocity v (mm/s), signed so that the force is -mu(v) |normal| along v:
///
/// ```text
/// mu(v) = STEP(v, -V_s, -mu_s, V_s, mu_s)                 |v| <= V_s
///       = sign(v) STEP(|v|, V_s, mu_s, V_d, mu_d)         V_s < |v| < V_d
///       = sign(v) mu_d                                    |v| >= V_d
/// ```
///
/// There is no true stiction: mu passes smoothly through 0 at v = 0 with slope
/// 1.5 mu_s / V_s, so a held body creeps at a speed below V_s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLaw {
    /// mu_s.
    pub mu_static: f64,
    /// mu_d.
    pub mu_dynamic: f64,
    /// V_s in mm/s.
    pub v_static: f64,
    /// V_d in mm/s (> V_s).
    pub v_dynamic: f64,
}

impl FrictionLaw {
    /// The signed coefficient mu(v) and its slope d mu / dv in s/mm.
    pub fn coefficient(&self, v: f64) -> (f64, f64) {
        let a = v.abs();
        if a <= self.v_static {
            return step(
                v,
                -self.v_static,
                -self.mu_static,
                self.v_static,
                self.mu_static,
            );
        }
        let (m, dm) = step(
            a,
            self.v_static,
            self.mu_static,
            self.v_dynamic,
            self.mu_dynamic,
        );
        // d/dv [sign(v) m(|v|)] = m'(|v|) for either sign.
        (m.copysign(v), dm)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fd(f: impl Fn(f64) -> f64, x: f64) -> f64 {
        let h = 1e-7 * x.abs().max(1e-3);
        (f(x + h) - f(x - h)) / (2.0 * h)
    }

    #[test]
    fn step_ends_and_midpoint() {
        assert_eq!(step(-1.0, 0.0, 2.0, 1.0, 4.0), (2.0, 0.0));
        assert_eq!(step(2.0, 0.0, 2.0, 1.0, 4.0), (4.0, 0.0));
        let (v, d) = step(0.5, 0.0, 2.0, 1.0, 4.0);
        assert!(
            (v - 3.0).abs() < 1e-15 && (d - 3.0).abs() < 1e-14,
            "{v} {d}"
        );
    }

    #[test]
    fn friction_law_values_and_slopes() {
        let law = FrictionLaw {
            mu_static: 0.5,
            mu_dynamic: 0.4,
            v_static: 0.1,
            v_dynamic: 0.2,
        };
        let mu = |v| law.coefficient(v).0;
        assert!(mu(0.0).abs() < 1e-15);
        assert!((mu(0.1) - 0.5).abs() < 1e-15 && (mu(-0.1) + 0.5).abs() < 1e-15);
        assert!((mu(5.0) - 0.4).abs() < 1e-15 && (mu(-5.0) + 0.4).abs() < 1e-15);
        // Slope at zero slip: 1.5 mu_s / V_s.
        assert!((law.coefficient(0.0).1 - 7.5).abs() < 1e-12);
        for v in [-0.19, -0.15, -0.05, 0.03, 0.12, 0.17, 1.0] {
            let (_, d) = law.coefficient(v);
            let f = fd(mu, v);
            assert!(
                (d - f).abs() < 1e-5 * f.abs().max(1.0),
                "v = {v}: {d} vs {f}"
            );
        }
    }

    #[test]
    fn impact_force_slopes_match_finite_differences() {
        let law = ImpactLaw {
            stiffness: 1e5,
            exponent: 2.2,
            damping: 10.0,
            depth: 0.01,
        };
        let force = |delta: f64, rate: f64| law.force(delta, rate, law.elastic(delta));
        assert_eq!(force(-1e-3, 5.0).normal, 0.0);
        for (delta, rate) in [(0.004, 3.0), (0.02, -1.0), (0.06, 0.5)] {
            let f = force(delta, rate);
            let dd = fd(|d| force(d, rate).normal, delta);
            let dr = fd(|r| force(delta, r).normal, rate);
            assert!(
                (f.d_delta - dd).abs() < 1e-5 * dd.abs(),
                "{delta}: {} vs {dd}",
                f.d_delta
            );
            assert!(
                (f.d_rate - dr).abs() < 1e-6 * dr.abs().max(1.0),
                "{} vs {dr}",
                f.d_rate
            );
        }
        // 200 N at about 59.3 um: the "about 60 um" the docs quote.
        let delta_200 = (200.0_f64 / 1e5).powf(1.0 / 2.2);
        assert!((delta_200 - 0.0593).abs() < 5e-5, "{delta_200}");
    }
}
