//! The simulation called directly, before the port's "outside the model" rule: what it says
//! of a scene the port keeps from it.

use jamchart::JamStatus;
use jamchart::SceneParams;
use jamchart::dynamics::{CrossCheck, DynamicsParams, DynamicsSolution, Method, simulate};

/// The default settings with the integrator `method`.
fn by(method: Method) -> DynamicsParams {
    DynamicsParams {
        integrator: jamchart::dynamics::IntegratorSettings {
            method,
            ..Default::default()
        },
        ..Default::default()
    }
}

fn run(scene: &SceneParams, p: &DynamicsParams) -> DynamicsSolution {
    simulate(scene, p, None).expect("valid parameters")
}

/// A start angle that rounds to 0 rad (5e-324 deg) puts the disc at no finite distance along
/// the palm: it is beyond reach before any step, by both methods, as the closed form says
/// (the run integrated a disc at infinity and called its x_jam = inf mm inaccurate). The
/// paper's start still runs.
#[test]
fn a_disc_at_no_finite_distance_is_beyond_reach_before_any_step() {
    let far = SceneParams {
        start_angle_deg: 5e-324,
        ..SceneParams::default()
    };
    assert_eq!(
        jamchart::statics::solve(&far).status,
        JamStatus::BeyondReach
    );
    for method in [Method::Radau5, Method::Nonsmooth] {
        let p = by(method);
        let s = run(&far, &p);
        assert_eq!(s.status, JamStatus::BeyondReach, "{method:?}: {s:?}");
        assert!(
            s.x_jam_mm.is_none() && s.cross_check.is_none() && s.steps == 0,
            "{s:?}"
        );
        assert!(run(&SceneParams::default(), &p).steps > 0, "{method:?}");
    }
}

/// Regression: above 90 deg the palm's push points upwards and lifts the disc, which no model
/// here represents: `--mu 1 --start-angle 120` was `beyond_reach` after launching the disc at
/// 14 m/s through 3.7 mm of penetration, and `--mass 1e6 --start-angle 179.999` jammed 4.7 mm
/// inside where a rigid disc could touch the palm. Both methods say `outside_model` now.
#[test]
fn a_palm_that_lifts_the_disc_is_outside_the_model() {
    let cases = [
        SceneParams {
            start_angle_deg: 120.0,
            ..SceneParams::default().with_mu(1.0)
        },
        SceneParams {
            mass_kg: 1e6,
            start_angle_deg: 179.999,
            ..SceneParams::default()
        },
    ];
    for scene in cases {
        for method in [Method::Radau5, Method::Nonsmooth] {
            let p = by(method);
            let s = run(&scene, &p);
            assert_eq!(
                s.status,
                JamStatus::OutsideModel,
                "{method:?} {scene:?}: {s:?}"
            );
            let Some(CrossCheck::LiftsOff { theta_deg }) = s.cross_check else {
                panic!("{s:?}");
            };
            assert!(theta_deg > 90.0, "{theta_deg}");
        }
    }
    // At 90 deg and below the palm presses the disc down: no lift-off.
    for mu in [0.15, 0.6, 1.0] {
        let p = by(Method::Nonsmooth);
        let s = run(&SceneParams::default().with_mu(mu), &p);
        assert_ne!(s.status, JamStatus::OutsideModel, "mu {mu}: {s:?}");
    }
}
