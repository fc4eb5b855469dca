//! Property: the simulation never panics and never returns NaN or infinity, for any input in
//! range (the integrator may give up, which is a status).

use jamchart::SceneParams;
use jamchart::dynamics::{Drive, DynamicsParams};

use crate::common::port::simulate;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]
    #[test]
    fn no_panic_no_nan(
        mu in 0.0..1.2f64,
        radius in 2.0..30.0f64,
        mass in 0.05..10.0f64,
        force in 5.0..1000.0f64,
        omega in 1.0..120.0f64,
        log_k in 3.0..8.5f64,
        exponent in 1.0..3.0f64,
        offset in 0.0..1.0f64,
        force_drive in any::<bool>(),
    ) {
        let scene = SceneParams { radius_mm: radius, mass_kg: mass, force_n: force, palm_offset_mm: offset, ..SceneParams::default().with_mu(mu) };
        let p = DynamicsParams { drive: jamchart::dynamics::DriveSettings { omega_deg_s: omega, mode: if force_drive { Drive::Force } else { Drive::Motion }, ..Default::default() }, contact: jamchart::dynamics::ContactLaw { stiffness_n_per_mm_e: 10f64.powf(log_k), exponent, ..Default::default() }, integrator: jamchart::dynamics::IntegratorSettings { max_steps: 20_000, ..Default::default() }, ..Default::default() };
        let s = simulate(&scene, &p, None).unwrap();
        for v in [s.theta_jam_deg, s.x_jam_mm, s.t_jam_s, s.x_stiction_mm, s.x_jam_error_mm].into_iter().flatten() {
            prop_assert!(v.is_finite(), "{s:?}");
        }
        prop_assert!(s.simulated_s.is_finite());
        if let Some(f) = &s.failure {
            prop_assert!(f.t_s().is_finite() && !f.to_string().is_empty());
        }
    }
}
