//! The dynamic simulation against the closed form, where physics says they agree.

use jamchart::JamStatus;
use jamchart::SceneParams;
use jamchart::dynamics::{Drive, DynamicsParams, DynamicsSolution, Failure, Method};

use crate::common::PAPER_ADAMS_X_JAM_MM_MU_0_4;
use crate::common::port::{simulate, statics};

/// k such that the IMPACT force k delta^2.2 reaches 200 N at penetration `delta_mm`.
fn stiffness_for(delta_mm: f64) -> f64 {
    200.0 / delta_mm.powf(2.2)
}

fn run(scene: &SceneParams, p: &DynamicsParams) -> DynamicsSolution {
    simulate(scene, p, None).expect("valid parameters")
}

fn x_jam(s: &DynamicsSolution) -> f64 {
    assert_eq!(s.status, JamStatus::Jams, "{s:?}");
    s.x_jam_mm.expect("a jam has a position")
}

fn assert_rel(name: &str, got: f64, want: f64, rel: f64) {
    let e = (got - want).abs() / want.abs();
    assert!(
        e <= rel,
        "{name}: got {got:.5}, want {want:.5} within {:.2} %, off by {:.3} %",
        rel * 100.0,
        e * 100.0
    );
}

#[test]
fn motion_drive_at_the_defaults_jams_within_1_5_percent_of_r_over_mu() {
    // The accuracy asked of the dynamics: solve --model dynamics --mu 0.4 within 1.5 % of 25.0 mm.
    // The compliant contact makes the disc lag the palm, so it jams a little short of r/mu
    // (24.75 mm).
    let s = run(&SceneParams::default(), &DynamicsParams::default());
    assert_rel("x_jam", x_jam(&s), 25.0, 0.015);
    assert!(s.x_jam_error_mm.unwrap() < 1e-4, "{s:?}");
    assert!(
        s.t_jam_s.unwrap() > 1.5 && s.t_jam_s.unwrap() < 1.6,
        "{s:?}"
    );
}

#[test]
fn motion_drive_with_a_stiff_contact_jams_within_0_5_percent_of_r_over_mu() {
    // Penetration 0.01 mm at 200 N.
    let p = DynamicsParams {
        contact: jamchart::dynamics::ContactLaw {
            stiffness_n_per_mm_e: stiffness_for(0.01),
            ..Default::default()
        },
        ..Default::default()
    };
    let s = run(&SceneParams::default(), &p);
    assert_rel("x_jam", x_jam(&s), 25.0, 0.005);
}

#[test]
fn force_drive_at_200_n_jams_within_1_percent_of_the_closed_form() {
    let scene = SceneParams::default();
    let closed = statics(&scene).x_jam_mm.unwrap();
    assert!((closed - 24.355).abs() < 1e-3);
    let p = DynamicsParams {
        drive: jamchart::dynamics::DriveSettings {
            mode: Drive::Force,
            ..Default::default()
        },
        ..Default::default()
    };
    let s = run(&scene, &p);
    assert_rel("x_jam", x_jam(&s), closed, 0.01);
    // The force drive follows Fig. 7b: a weaker push jams earlier, as the closed form says. At
    // 30 deg/s the disc coasts past the closed form's angle on its inertia (the net braking force
    // grows from zero there): 22.85 mm against 22.58 mm; at 10 deg/s the coast shrinks.
    let weak = SceneParams {
        force_n: 50.0,
        ..scene
    };
    let closed_weak = statics(&weak).x_jam_mm.unwrap();
    let slow = DynamicsParams {
        drive: jamchart::dynamics::DriveSettings {
            omega_deg_s: 10.0,
            ..p.drive
        },
        ..p
    };
    assert_rel(
        "x_jam at 50 N",
        x_jam(&run(&weak, &slow)),
        closed_weak,
        0.01,
    );
    let fast = x_jam(&run(&weak, &p));
    assert!(
        fast > closed_weak,
        "inertia carries the disc past: {fast} vs {closed_weak}"
    );
}

#[test]
fn x_jam_barely_depends_on_mass_and_omega_at_low_omega() {
    // The paper: mass and palm speed have "no sensible effect". What remains is the contact's
    // compliance: a heavier disc needs a harder push near the wedge, so it penetrates more and
    // jams a little earlier. With a stiffer contact the spread shrinks.
    for (delta, max_spread) in [(None, 0.0075), (Some(0.01), 0.0025)] {
        let mut xs = Vec::new();
        for omega in [5.0, 10.0] {
            for mass in [0.5, 1.0, 2.0] {
                let scene = SceneParams {
                    mass_kg: mass,
                    ..Default::default()
                };
                let mut p = DynamicsParams {
                    drive: jamchart::dynamics::DriveSettings {
                        omega_deg_s: omega,
                        ..Default::default()
                    },
                    ..Default::default()
                };
                if let Some(d) = delta {
                    p.contact.stiffness_n_per_mm_e = stiffness_for(d);
                }
                xs.push((omega, mass, x_jam(&run(&scene, &p))));
            }
        }
        let lo = xs.iter().map(|x| x.2).fold(f64::INFINITY, f64::min);
        let hi = xs.iter().map(|x| x.2).fold(0.0, f64::max);
        let spread = (hi - lo) / lo;
        assert!(
            spread <= max_spread,
            "penetration {delta:?}: spread {spread:.4} over {xs:?}"
        );
        for (_, _, x) in &xs {
            assert_rel("x_jam", *x, 25.0, 0.016);
        }
    }
}

#[test]
fn both_integrators_agree_at_a_tight_tolerance() {
    let scene = SceneParams::default();
    for drive in [Drive::Force, Drive::Motion] {
        let p = DynamicsParams {
            drive: jamchart::dynamics::DriveSettings {
                mode: drive,
                ..Default::default()
            },
            integrator: jamchart::dynamics::IntegratorSettings {
                rtol: 1e-9,
                ..Default::default()
            },
            verification: jamchart::dynamics::Verification {
                verify: false,
                ..Default::default()
            },
            ..Default::default()
        };
        let a = x_jam(&run(&scene, &p));
        let b = x_jam(&run(
            &scene,
            &DynamicsParams {
                integrator: jamchart::dynamics::IntegratorSettings {
                    method: Method::Dopri5,
                    ..p.integrator
                },
                ..p
            },
        ));
        assert!(
            (a - b).abs() <= 1e-6 * a,
            "{drive:?}: radau5 {a} vs dopri5 {b}"
        );
    }
}

/// Regression: a stiff method at a loose tolerance can report success with a wrong answer (another
/// library's Radau has been seen 69 % off). At rtol 0.05-0.5 our methods give x_jam at 10-14 mm and
/// 33-169 mm (truth 24.5-25.0 mm, 58 % short to 574 % long; see the module docs of `dynamics`),
/// caught by the tolerance cap, the cross-checks and the verification run. Every answer that says
/// `jams` must be right within 1 %.
#[test]
fn loose_tolerances_never_give_a_trusted_wrong_answer() {
    let scene = SceneParams::default();
    let cases = [
        (Drive::Motion, 1e5, Method::Radau5),
        (Drive::Motion, 1e5, Method::Dopri5),
        (Drive::Motion, stiffness_for(1e-3), Method::Radau5),
        (Drive::Force, 1e5, Method::Radau5),
        (Drive::Force, 1e5, Method::Dopri5),
    ];
    for (drive, k, method) in cases {
        let base = DynamicsParams {
            drive: jamchart::dynamics::DriveSettings {
                mode: drive,
                ..Default::default()
            },
            contact: jamchart::dynamics::ContactLaw {
                stiffness_n_per_mm_e: k,
                ..Default::default()
            },
            integrator: jamchart::dynamics::IntegratorSettings {
                max_steps: 100_000,
                ..Default::default()
            },
            ..Default::default()
        };
        let truth = x_jam(&run(
            &scene,
            &DynamicsParams {
                integrator: jamchart::dynamics::IntegratorSettings {
                    rtol: 1e-9,
                    ..base.integrator
                },
                ..base
            },
        ));
        for rtol in [0.5, 0.2, 0.1, 0.05, 0.01, 3e-3, 1e-3] {
            let s = run(
                &scene,
                &DynamicsParams {
                    integrator: jamchart::dynamics::IntegratorSettings {
                        rtol,
                        method,
                        ..base.integrator
                    },
                    ..base
                },
            );
            if s.status == JamStatus::Jams {
                assert_rel(
                    &format!("{drive:?} k {k:e} {method:?} rtol {rtol}"),
                    x_jam(&s),
                    truth,
                    0.01,
                );
            } else {
                assert!(
                    matches!(
                        s.status,
                        JamStatus::Inaccurate | JamStatus::IntegratorFailed
                    ),
                    "{drive:?} {method:?} rtol {rtol}: {s:?}"
                );
            }
        }
    }
}

#[test]
fn the_outcomes_that_are_not_jams() {
    // Too heavy for the force-limited palm: it stalls at once.
    let heavy = SceneParams {
        mass_kg: 100.0,
        ..Default::default()
    };
    let force = DynamicsParams {
        drive: jamchart::dynamics::DriveSettings {
            mode: Drive::Force,
            ..Default::default()
        },
        ..Default::default()
    };
    // Too heavy for the force-limited palm (F = 200 N below m g sin(atan mu) = 364 N): too
    // weak, a status of its own (it was jammed_at_start).
    let s = run(&heavy, &force);
    assert_eq!(s.status, JamStatus::TooWeak, "{s:?}");
    // Started below theta_jam (44.6 deg): jammed where the push starts, within 1e-9 deg.
    let early = SceneParams {
        start_angle_deg: 40.0,
        ..Default::default()
    };
    let s = run(&early, &force);
    assert_eq!(s.status, JamStatus::JammedAtStart, "{s:?}");
    let theta = s.theta_jam_deg.expect("a jam at the start has an angle");
    assert!(
        (theta - 40.0).abs() < 1e-9,
        "theta_jam = {theta} deg, expected the start angle 40 deg within 1e-9 deg"
    );
    // Self-locking from the start: 2 atan(1.5) = 112.6 deg > 90 deg.
    let s = run(
        &SceneParams::default().with_mu(1.5),
        &DynamicsParams::default(),
    );
    assert_eq!(s.status, JamStatus::JammedAtStart, "{s:?}");
    // Frictionless: the disc leaves the 150 mm palm.
    let s = run(
        &SceneParams::default().with_mu(0.0),
        &DynamicsParams::default(),
    );
    assert_eq!(s.status, JamStatus::BeyondReach, "{s:?}");
    // A step budget too small is a status with the time and the reason, not a panic.
    let p = DynamicsParams {
        integrator: jamchart::dynamics::IntegratorSettings {
            max_steps: 20,
            ..Default::default()
        },
        ..Default::default()
    };
    let s = run(&SceneParams::default(), &p);
    assert_eq!(s.status, JamStatus::IntegratorFailed);
    let f = s.failure.expect("a failure says why");
    assert!(
        matches!(f, Failure::StepLimit { steps: 20, .. }) && f.t_s() > 0.0,
        "{f:?}"
    );
}

#[test]
fn the_series_ends_at_the_jam_and_shows_the_disc_stop() {
    let p = DynamicsParams {
        series: jamchart::dynamics::SeriesSettings { after_jam_s: 0.02 },
        ..Default::default()
    };
    let s = simulate(&SceneParams::default(), &p, Some(1e-3)).unwrap();
    let t_jam = s.t_jam_s.unwrap();
    assert!(s.series.len() > 1500, "{}", s.series.len());
    assert!(s.series.windows(2).all(|w| w[1].t_s > w[0].t_s));
    let last = s.series.last().unwrap();
    assert!(last.t_s >= t_jam + 0.02 - 1e-3, "{} vs {t_jam}", last.t_s);
    // After the jam the disc creeps at a fraction of a mm/s while the palm presses hard.
    assert!(last.x_dot_mm_s < 0.5 && last.normal_n > 1000.0, "{last:?}");
    assert!(
        s.series
            .iter()
            .all(|r| r.x_mm.is_finite() && r.normal_n >= 0.0)
    );
}

#[test]
fn the_papers_1_mm_bar_brings_the_jam_near_its_adams_result() {
    // The paper's Adams model pushes with 1 mm thick bars, so the palm's face lies 0.5 mm off the
    // hinge line; the paper reads x_jam = 25.58 mm (Section 5). Our model gives 25.47 mm with the
    // offset (24.75 mm without): within 1 % of the paper's number, which the paper's own reading
    // of "an instability of the velocity" off a plot cannot beat.
    let scene = SceneParams {
        palm_offset_mm: 0.5,
        ..Default::default()
    };
    let x = x_jam(&run(&scene, &DynamicsParams::default()));
    assert_rel(
        "x_jam with a 0.5 mm offset",
        x,
        PAPER_ADAMS_X_JAM_MM_MU_0_4,
        0.01,
    );
}

/// Regression: the integrators reported "step size 8.9e-16 too small" at t = t_end = 3 s (the
/// palm flat) whenever their last step landed a rounding error short of t_end, so a disc the
/// palm could never move (too small for the contact's penetration, or too heavy) came out as
/// `integrator_failed` instead of `jammed_at_start`.
#[test]
fn a_rounding_sliver_before_the_end_is_not_an_integrator_failure() {
    let d = SceneParams::default();
    let tiny = SceneParams {
        radius_mm: 1e-3,
        ..d
    };
    let heavy = SceneParams { mass_kg: 1e6, ..d };
    for scene in [tiny, heavy] {
        for method in [Method::Radau5, Method::Dopri5] {
            let p = DynamicsParams {
                integrator: jamchart::dynamics::IntegratorSettings {
                    method,
                    ..Default::default()
                },
                ..Default::default()
            };
            let s = run(&scene, &p);
            assert!(s.failure.is_none(), "{method:?} {scene:?}: {:?}", s.failure);
            // The compliant contact reads jammed_at_start where the motion-driven rigid contact
            // pushes the disc on to the lock-up (the 1 um disc sinks deeper into the contact
            // than it is big; the 1e6 kg disc is too heavy for the contact's push): that
            // disagreement is flagged instead of trusted.
            let flagged = matches!(
                s.cross_check,
                Some(jamchart::dynamics::CrossCheck::RigidDisagrees {
                    status: JamStatus::JammedAtStart,
                    ..
                })
            );
            assert!(
                s.status == JamStatus::JammedAtStart
                    || (s.status == JamStatus::Inaccurate && flagged),
                "{method:?} {scene:?}: {s:?}"
            );
        }
    }
}

/// Regression: the confirmation window always included the flight time of a bounce,
/// 2 v_geo / (mu_g g), which grows as 1 / (mu sin^2(theta/2)): at mu <= 0.2 the palm ground on
/// the stuck disc for up to a second, DOPRI5 ran out of its 2,000,000 steps (integrator_failed
/// after 1.1 s of CPU) and RADAU5 reached the end of the run unconfirmed. The flight term now
/// applies only after a bounce; two periods of the contact's oscillation guard a soft contact.
#[test]
fn low_friction_jams_are_confirmed_by_both_integrators() {
    for mu in [0.1, 0.15, 0.2] {
        let scene = SceneParams::default().with_mu(mu);
        let radau = x_jam(&run(&scene, &DynamicsParams::default()));
        let dopri = x_jam(&run(
            &scene,
            &DynamicsParams {
                integrator: jamchart::dynamics::IntegratorSettings {
                    method: Method::Dopri5,
                    ..Default::default()
                },
                ..Default::default()
            },
        ));
        assert_rel(&format!("dopri5 vs radau5 at mu {mu}"), dopri, radau, 1e-4);
        // Motion drive: near the self-locking wedge r / mu.
        assert_rel(&format!("radau5 at mu {mu}"), radau, 10.0 / mu, 0.03);
    }
}

/// A soft undamped contact throws the disc ahead of the palm again and again; a slowdown while
/// the contact compresses or while the disc is in flight is not a jam (it confirmed falsely at
/// x = 10.1 mm when the window was shortened without the contact's period).
#[test]
fn a_bouncing_disc_is_not_taken_for_jammed() {
    let scene = SceneParams::default().with_mu(0.1);
    let p = DynamicsParams {
        contact: jamchart::dynamics::ContactLaw {
            stiffness_n_per_mm_e: 1e3,
            damping_n_s_per_mm: 0.0,
            ..Default::default()
        },
        ..Default::default()
    };
    let s = run(&scene, &p);
    assert!(s.discarded_candidates > 0, "{s:?}");
    assert_rel("soft undamped contact", x_jam(&s), 100.0, 0.02);
}

/// Regression: a force-driven disc at mu = 0.1 coasts 6.6 mm past the wedge r / mu = 100 mm on
/// its inertia (the coasting bound v_geo^2 / (2 mu_g g) is 36 mm there), and that converged
/// answer was called inaccurate by a fixed 5 % margin.
#[test]
fn coasting_past_the_wedge_is_not_called_inaccurate() {
    let scene = SceneParams::default().with_mu(0.1);
    let p = DynamicsParams {
        drive: jamchart::dynamics::DriveSettings {
            mode: Drive::Force,
            ..Default::default()
        },
        ..Default::default()
    };
    let x = x_jam(&run(&scene, &p));
    assert!(x > 100.0 && x < 110.0, "x_jam {x} mm");
}

/// Every number in the docs comes from a test that prints it. The module docs of `dynamics::jam`
/// said that at the defaults (motion drive) the disc creeps at 0.12-0.13 mm/s for about 60 ms after
/// the collapse, and that the stiction reading lies 0.03 mm further out (so it needs
/// `after_jam_s` >= 0.07), but no test printed these numbers. This one measures them from a run
/// with a series: the creep is the disc's speed from where it first falls below V_d (the end of the
/// collapse) to the stiction reading. It falls from 0.130 mm/s to V_s = 0.1 mm/s over 64 ms (not
/// 0.12-0.13 mm/s throughout, as the docs said; they now give the measured figures).
#[test]
fn the_motion_drive_creep_figures_of_the_jam_docs() {
    let p = DynamicsParams {
        series: jamchart::dynamics::SeriesSettings { after_jam_s: 0.1 },
        ..Default::default()
    };
    let s = simulate(&SceneParams::default(), &p, Some(1e-4)).unwrap();
    let (x, t) = (x_jam(&s), s.t_jam_s.unwrap());
    let x_st = s
        .x_stiction_mm
        .expect("the run lasts past the stiction reading");
    let t_st = s.t_stiction_s.unwrap();
    let v_d = p.friction.friction_velocity_mm_s;
    let creep: Vec<f64> = s
        .series
        .iter()
        .filter(|r| r.t_s > t && r.t_s <= t_st)
        .map(|r| r.x_dot_mm_s)
        .skip_while(|v| *v >= v_d)
        .collect();
    let lo = creep.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = creep.iter().copied().fold(0.0, f64::max);
    eprintln!(
        "jam {x:.4} mm at {t:.4} s; stiction reading {x_st:.4} mm at {t_st:.4} s \
         ({:.1} ms later, {:.4} mm further); creep {lo:.4}-{hi:.4} mm/s over {} samples",
        (t_st - t) * 1e3,
        x_st - x,
        creep.len()
    );
    assert!(creep.len() > 10, "{creep:?}");
    let v_s = p.friction.stiction_velocity_mm_s;
    assert!(
        lo >= 0.99 * v_s && lo < 1.01 * v_s,
        "creep ends at {lo} mm/s"
    );
    assert!((0.125..0.135).contains(&hi), "creep starts at {hi} mm/s");
    assert!((0.06..0.07).contains(&(t_st - t)), "{} s", t_st - t);
    assert!((0.025..0.035).contains(&(x_st - x)), "{} mm", x_st - x);
}

/// Every number in the docs comes from a test that prints it. `jam::rest_speed_mm_s` and the
/// `dynamics` module docs said a disc held by the regularised friction creeps at 0.124 mm/s at the
/// defaults' force drive, between V_s and V_d, and cited a test that printed no such number. This
/// one prints the held disc's speed over the 50 ms to 100 ms after the rest (0.1236-0.1239 mm/s)
/// and holds it between V_s and V_d.
#[test]
fn the_force_drive_creep_figure_of_the_docs() {
    let mut p = DynamicsParams {
        series: jamchart::dynamics::SeriesSettings { after_jam_s: 0.1 },
        ..Default::default()
    };
    p.drive.mode = Drive::Force;
    let s = simulate(&SceneParams::default(), &p, Some(1e-4)).unwrap();
    let t = s.t_jam_s.unwrap();
    let held: Vec<f64> = s
        .series
        .iter()
        .filter(|r| r.t_s >= t + 0.05)
        .map(|r| r.x_dot_mm_s)
        .collect();
    let lo = held.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = held.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    eprintln!(
        "force drive: rest at {:.4} mm, {t:.4} s; held disc creeps at {lo:.4}-{hi:.4} mm/s \
         over {} samples 50-100 ms later",
        x_jam(&s),
        held.len()
    );
    assert!(held.len() > 100, "{}", held.len());
    let (v_s, v_d) = (
        p.friction.stiction_velocity_mm_s,
        p.friction.friction_velocity_mm_s,
    );
    assert!(lo > v_s && hi < v_d, "creep {lo}-{hi} mm/s");
    // The figure the docs give, 0.124 mm/s, to its digits.
    assert!(lo > 0.1235 && hi < 0.1245, "creep {lo}-{hi} mm/s");
}
