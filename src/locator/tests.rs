//! V-type locators (unit tests, beside the internals they check): the closed forms against numerical searches, the exact path against
//! clarabel, the verdicts, and the palm scene seen as a V.

use crate::SceneParams;
use crate::locator::{
    self, FailureMode, Flank, LocatorParams, ReferenceCapacity, Rotation, Verdict, capacity,
    capacity_by_enumeration, capacity_clarabel, closed_form_free_centre, held_at, self_locking,
};
use crate::minnorm::qp::solve_clarabel;
use crate::minnorm::{HoldStatus, QpSettings};
use crate::statics;
use proptest::prelude::*;

fn free_v(gamma: f64, mu: f64) -> LocatorParams {
    LocatorParams::default()
        .with_included_angle(gamma)
        .with_mu(mu)
}

prop_compose! {
    /// A V (possibly tilted or overhanging), frictions (sometimes zero or unequal), a load in
    /// any direction, at the centre or (free only) at a rim point.
    fn any_v()(
        a1 in 0.0..150.0_f64,
        frac in 0.05..0.95_f64,
        mu1 in prop_oneof![1 => Just(0.0), 4 => 0.0..0.8_f64],
        mu2 in prop_oneof![1 => Just(0.0), 4 => 0.0..0.8_f64],
        p_over_w in 0.0..5.0_f64,
        phi in -180.0..180.0_f64,
        rim in prop::option::weighted(0.3, -180.0..180.0_f64),
        blocked in prop::bool::weighted(0.4),
    ) -> LocatorParams {
        let a2 = frac * (180.0 - a1);
        let rotation = if blocked { Rotation::Blocked } else { Rotation::Free };
        LocatorParams {
            flank_left_deg: a1,
            flank_right_deg: a2,
            mu_left: mu1,
            mu_right: mu2,
            load_n: p_over_w * 9.806,
            load_angle_deg: phi,
            load_at_rim_deg: if blocked { None } else { rim },
            rotation,
            ..LocatorParams::default()
        }
    }
}

proptest! {
    // Saved failures live beside this file (src/locator/tests.proptest-regressions), not in a
    // proptest-regressions/ folder at the top of the tree, and every run replays them.
    #![proptest_config(ProptestConfig {
        cases: 300,
        failure_persistence: Some(Box::new(
            proptest::test_runner::FileFailurePersistence::WithSource("proptest-regressions"),
        )),
        ..ProptestConfig::default()
    })]

    /// The exact capacity (closed form or vertex enumeration) is clarabel's LP optimum.
    #[test]
    fn exact_capacity_matches_clarabel(p in any_v()) {
        let c = capacity(&p);
        let r = capacity_clarabel(&p);
        prop_assume!(r != ReferenceCapacity::Undetermined);
        // clarabel's 1e-8 tolerances on a problem scaled by W.
        prop_assert!(r.agrees(&c, p.weight_n(), 1e-6), "exact {c:?}, clarabel {r:?}, {p:?}");
    }

    /// Under free rotation with a centre load the support-cone closed form and the vertex
    /// enumeration of the LP give the same capacity.
    #[test]
    fn closed_form_capacity_matches_enumeration(p in any_v()) {
        let p = LocatorParams { rotation: Rotation::Free, load_at_rim_deg: None, ..p };
        prop_assume!(!locator::self_locking(&p));
        let (a, b) = (capacity(&p), capacity_by_enumeration(&p));
        prop_assert_eq!(a.unbounded, b.unbounded, "{:?} {:?}", a, b);
        match (a.p_max_n, b.p_max_n) {
            (Some(x), Some(y)) => prop_assert!((x - y).abs() <= 1e-9 * (p.weight_n() + x)),
            (x, y) => prop_assert!(x.is_none() && y.is_none(), "{x:?} {y:?}"),
        }
    }

    /// Held by the exact test exactly where the general contact solver (clarabel) finds
    /// forces, 1 % of P_max (and, beyond it, 1 % of W) away from the capacity boundary.
    #[test]
    fn exact_verdict_matches_clarabel(p in any_v()) {
        let c = capacity(&p);
        prop_assume!(!c.unbounded);
        if let Some(pm) = c.p_max_n {
            for (load, held) in [(0.99 * pm, true), (1.01 * pm + 0.01 * p.weight_n(), false)] {
                let q = LocatorParams { load_n: load, ..p };
                prop_assert_eq!(held_at(&q, load).is_ok(), held);
                let s = solve_clarabel(&locator::contact_problem(&q), &QpSettings::default()).unwrap();
                // clarabel without a verdict (iteration limit on a near-degenerate V, seen at
                // 230 W past an overhanging frictionless flank) is no evidence either way.
                prop_assume!(s.status != HoldStatus::Undetermined);
                let want = if held { HoldStatus::Held } else { HoldStatus::NotHeld };
                prop_assert_eq!(s.status, want, "load {} of P_max {}: {:?}", load, pm, q);
            }
        }
    }

    /// The minimum-norm forces of the exact path are clarabel's.
    #[test]
    fn min_norm_forces_exact_path_matches_clarabel(p in any_v()) {
        let exact = locator::min_norm_forces(&p, &QpSettings::default()).unwrap();
        let clar = locator::min_norm_forces(&p, &QpSettings { fast_path: false, ..QpSettings::default() }).unwrap();
        if let (Some(e), Some(c)) = (exact, clar) {
            // clarabel's stopping tolerances are relative to the solution as well as to the
            // data: a V near self-locking carries flank forces far above W + P (79 kN for a
            // 4.7 N load with a 103 deg overhanging flank, a drawn case, 1.2e-5 apart).
            let largest = e.iter().map(|f| f.normal_n.abs() + f.tangential_up_n.abs()).fold(0.0, f64::max);
            let scale = p.weight_n() + p.load_n + largest;
            for (e, c) in e.iter().zip(&c) {
                for (x, y) in [(e.normal_n, c.normal_n), (e.tangential_up_n, c.tangential_up_n)] {
                    // clarabel stops at 1e-8 of its scaled residuals; with a flank at the edge
                    // of its cone the least-norm point is ill-conditioned and it lands up to
                    // 1e-5 of the load away (1.3e-4 N of 14 N, a drawn case): 1e-4 is its floor.
                    prop_assert!((x - y).abs() <= 1e-4 * scale, "exact {e:?} clarabel {c:?}");
                }
            }
        }
    }
}

/// The closed-form optimum of a free symmetric V under a centre load against the bisection
/// and against a plain scan of rho*(gamma) (0.1 deg steps, refined to 0.001 deg).
#[test]
fn closed_form_optimum_matches_numerical_search() {
    let mut worst: f64 = 0.0;
    for mu in [0.1, 0.3, 0.5] {
        for p_over_w in [0.05, 0.3, 1.0, 3.0] {
            for phi in [0.0, 30.0, 60.0, 90.0, -30.0, 150.0] {
                let Some((g_cf, rho_cf)) = closed_form_free_centre(mu, p_over_w, phi) else {
                    continue;
                };
                if !(2.0..178.0).contains(&g_cf) {
                    continue;
                }
                let mut p = free_v(90.0, mu);
                p.load_n = p_over_w * p.weight_n();
                p.load_angle_deg = phi;
                let o = locator::optimum(&p);
                assert!(!o.at_bound);
                assert!(
                    (o.included_angle_deg - g_cf).abs() < 1e-6,
                    "mu {mu} P/W {p_over_w} phi {phi}: bisection {} closed form {g_cf}",
                    o.included_angle_deg
                );
                assert!((o.safety_factor - rho_cf).abs() < 1e-6 * rho_cf);
                // A coarse scan in 0.1 deg steps, refined in 0.001 deg steps around its best.
                let scan = |from: f64, step: f64, n: usize| {
                    (0..=n)
                        .map(|k| {
                            let g = from + k as f64 * step;
                            (g, locator::balanced_rho(&p.with_included_angle(g)))
                        })
                        .max_by(|a, b| a.1.total_cmp(&b.1))
                        .unwrap()
                };
                let (coarse, _) = scan(1.0, 0.1, 1780);
                let (g_scan, rho_scan) = scan((coarse - 0.1).max(1.0), 0.001, 200);
                // Straight up (phi = 90) rho_hold does not depend on gamma: every V from the
                // crossing on is as good, and the crossing is the narrowest of them.
                if phi != 90.0 {
                    assert!(
                        (g_scan - g_cf).abs() <= 0.0011,
                        "scan {g_scan} closed {g_cf}"
                    );
                }
                // The scan's 0.001 deg steps land up to about 1e-5 below the peak.
                assert!(
                    rho_scan <= rho_cf * (1.0 + 1e-9) && rho_scan >= rho_cf * (1.0 - 1e-4),
                    "scan {rho_scan} closed form {rho_cf}"
                );
                worst = worst.max((o.included_angle_deg - g_cf).abs());
            }
        }
    }
    println!("worst |gamma* bisection - closed form| = {worst:e} deg");
}

/// A 90 deg V is optimal for a sideways load when P / W = mu.
#[test]
fn ninety_degree_v_is_optimal_when_p_over_w_equals_mu() {
    for mu in [0.1, 0.3, 0.5] {
        let mut p = free_v(60.0, mu);
        p.load_n = mu * p.weight_n();
        let o = locator::optimum(&p);
        assert!((o.included_angle_deg - 90.0).abs() < 1e-6, "{o:?}");
        assert!((o.safety_factor - 1.0 / mu).abs() < 1e-6);
    }
}

/// Free rotation, centre load, equal frictions: friction adds nothing unless the V locks.
#[test]
fn free_centre_capacity_does_not_depend_on_friction_unless_locked() {
    for gamma in [50.0, 60.0, 90.0, 120.0, 160.0] {
        for phi in [-60.0, 0.0, 20.0, 45.0, 80.0, 135.0] {
            let mut p = free_v(gamma, 0.0);
            p.load_angle_deg = phi;
            let dry = capacity(&p);
            for mu in [0.1, 0.2, 0.4] {
                let q = p.with_mu(mu);
                if locator::self_locking(&q) {
                    assert!(capacity(&q).unbounded);
                    continue;
                }
                let c = capacity(&q);
                assert_eq!(c.unbounded, dry.unbounded);
                if let (Some(a), Some(b)) = (c.p_max_n, dry.p_max_n) {
                    assert!(
                        (a - b).abs() <= 1e-9 * (a + 1.0),
                        "gamma {gamma} phi {phi} mu {mu}"
                    );
                }
            }
            // Blocked, friction does add capacity to a sideways load.
            if phi == 0.0 {
                let mut b = p.with_mu(0.2);
                b.rotation = Rotation::Blocked;
                if !locator::self_locking(&b) {
                    assert!(capacity(&b).p_max_n.unwrap() > dry.p_max_n.unwrap() * 1.01);
                }
            }
        }
    }
}

/// The self-locking bounds: free tan(gamma/2) < min mu, blocked
/// gamma < atan mu1 + atan mu2; and rho_lock is 1 on them.
#[test]
fn self_locking_bounds() {
    let mut p = LocatorParams {
        mu_left: 0.2,
        mu_right: 0.5,
        ..LocatorParams::default()
    };
    let free_bound = 2.0 * 0.2_f64.atan().to_degrees();
    let blocked_bound = (0.2_f64.atan() + 0.5_f64.atan()).to_degrees();
    for (rotation, bound) in [
        (Rotation::Free, free_bound),
        (Rotation::Blocked, blocked_bound),
    ] {
        p.rotation = rotation;
        assert!(locator::self_locking(&p.with_included_angle(bound - 1e-6)));
        assert!(!locator::self_locking(&p.with_included_angle(bound + 1e-6)));
        assert!((locator::rho_lock(&p.with_included_angle(bound)) - 1.0).abs() < 1e-12);
    }
}

/// The palm scene as a V: left flank the palm (a1 = 180 - theta, mu_palm), right flank the
/// ground (a2 = 0, mu_ground), load the palm's push on the edge of its cone at the palm contact.
fn palm_v(s: &SceneParams, theta_deg: f64, rotation: Rotation) -> LocatorParams {
    let a1 = 180.0 - theta_deg;
    let (s1, c1) = a1.to_radians().sin_cos();
    let (n, u) = ([s1, c1], [-c1, s1]);
    let alpha = s.mu_palm.atan();
    let push = [
        alpha.cos() * n[0] - alpha.sin() * u[0],
        alpha.cos() * n[1] - alpha.sin() * u[1],
    ];
    LocatorParams {
        flank_left_deg: a1,
        flank_right_deg: 0.0,
        mu_left: s.mu_palm,
        mu_right: s.mu_ground,
        mass_kg: s.mass_kg,
        gravity_m_s2: s.gravity_m_s2,
        load_n: s.force_n,
        load_angle_deg: push[1].atan2(push[0]).to_degrees(),
        // The palm contact -r n_1.
        load_at_rim_deg: (rotation == Rotation::Free).then(|| (-n[1]).atan2(-n[0]).to_degrees()),
        rotation,
    }
}

/// The held/not-held boundary in theta by bisection (held below it).
fn palm_boundary_deg(s: &SceneParams, rotation: Rotation, lo: f64, hi: f64) -> f64 {
    let held = |t: f64| {
        let p = palm_v(s, t, rotation);
        held_at(&p, p.load_n).is_ok()
    };
    let (mut lo, mut hi) = (lo, hi);
    assert!(held(lo) && !held(hi), "bracket {lo}..{hi}");
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if held(mid) { lo = mid } else { hi = mid }
    }
    lo
}

#[test]
fn blocked_palm_v_boundary_is_the_statics_theta_jam() {
    for (mu_g, mu_p, f) in [
        (0.4, 0.4, 200.0),
        (0.3, 0.3, 50.0),
        (0.2, 0.5, 200.0),
        (0.5, 0.2, 80.0),
    ] {
        let s = SceneParams {
            mu_ground: mu_g,
            mu_palm: mu_p,
            force_n: f,
            ..SceneParams::default()
        };
        let want = statics::theta_jam_rad(&s).to_degrees();
        let got = palm_boundary_deg(&s, Rotation::Blocked, want - 10.0, want + 10.0);
        assert!(
            (got - want).abs() < 1e-6,
            "mu_g {mu_g} mu_p {mu_p} F {f}: V boundary {got} deg, statics {want} deg"
        );
    }
}

#[test]
fn free_palm_v_boundary_is_the_self_locking_wedge_whatever_the_push() {
    for mu in [0.2, 0.4] {
        for f in [20.0, 200.0, 5000.0] {
            let s = SceneParams {
                mu_ground: mu,
                mu_palm: mu,
                force_n: f,
                ..SceneParams::default()
            };
            let want = 2.0 * mu.atan().to_degrees();
            let got = palm_boundary_deg(&s, Rotation::Free, want - 10.0, want + 10.0);
            assert!((got - want).abs() < 1e-6, "mu {mu} F {f}: {got} vs {want}");
        }
    }
}

/// Free rotation, the ground slipperier than the palm (mu_g < mu_p): the moment row makes the
/// ground friction T equal the palm's total friction, so with t = tan(theta/2) the force rows
/// give T = -N_p t and N_ground = W + N_p (N_p the palm's total normal force, F cos alpha_p
/// plus any squeeze N_1). The palm contact needs |mu_p F cos alpha_p - N_p t| <= mu_p N_1, i.e.
/// t <= mu_p and N_p >= 2 mu_p F cos alpha_p / (mu_p + t); the ground needs
/// N_p (t - mu_g) <= mu_g W. The boundary is where the least N_p meets the ground's bound:
///
/// t* = mu_g mu_p (W + 2 F cos alpha_p) / (2 mu_p F cos alpha_p - mu_g W), theta* = 2 atan min(t*, mu_p)
///
/// above the self-locking 2 atan mu_g and moving with F (unlike equal frictions).
#[test]
fn free_palm_v_boundary_with_a_slipperier_ground_follows_the_closed_form() {
    for (mu_g, mu_p) in [(0.2, 0.5), (0.3, 0.4)] {
        for f in [10.0, 50.0, 200.0, 5000.0] {
            let s = SceneParams {
                mu_ground: mu_g,
                mu_palm: mu_p,
                force_n: f,
                ..SceneParams::default()
            };
            let w = s.mass_kg * s.gravity_m_s2;
            let fc = f * mu_p.atan().cos();
            let den = 2.0 * mu_p * fc - mu_g * w;
            let t = if den > 0.0 {
                (mu_g * mu_p * (w + 2.0 * fc) / den).min(mu_p)
            } else {
                mu_p
            };
            let want = 2.0 * t.atan().to_degrees();
            assert!(want > 2.0 * mu_g.atan().to_degrees() + 1e-3);
            let got = palm_boundary_deg(&s, Rotation::Free, want - 10.0, want + 10.0);
            assert!(
                (got - want).abs() < 1e-6,
                "mu_g {mu_g} mu_p {mu_p} F {f}: V boundary {got} deg, closed form {want} deg"
            );
        }
    }
}

#[test]
fn verdicts_in_order() {
    // A 30 deg V with mu 0.3 locks (tan 15 deg = 0.27 < 0.3).
    let s = locator::solve(&free_v(30.0, 0.3)).unwrap();
    assert_eq!(s.verdict, Verdict::Wedged);
    assert!(s.self_locking && s.forces.is_some());
    assert!(!s.locking_needed, "the weight alone sits in any 30 deg V");
    // Pulling sideways at 2 W out of a 90 deg V: P_max = W / tan 45 = W, it rolls over the
    // right flank (the load points to -x: the disc is pulled towards the left flank).
    let mut p = free_v(90.0, 0.3);
    p.load_n = 2.0 * p.weight_n();
    p.load_angle_deg = 180.0;
    let s = locator::solve(&p).unwrap();
    assert_eq!(
        s.verdict,
        Verdict::Slips {
            mode: FailureMode::RollsOverLeft
        }
    );
    assert!(s.forces.is_none());
    assert!((s.capacity.p_max_over_w.unwrap() - 1.0).abs() < 1e-12);
    // On a floor against a wall, unloaded: the wall carries nothing.
    let p = LocatorParams {
        flank_left_deg: 0.0,
        flank_right_deg: 90.0,
        ..LocatorParams::default()
    };
    let s = locator::solve(&p).unwrap();
    assert_eq!(
        s.verdict,
        Verdict::LiftsOff {
            flank: Flank::Right
        }
    );
    // Held, and held only thanks to friction: blocked, a sideways push beyond the dry capacity.
    let mut p = free_v(90.0, 0.3);
    p.rotation = Rotation::Blocked;
    p.load_n = 1.2 * p.weight_n();
    let s = locator::solve(&p).unwrap();
    assert_eq!(s.verdict, Verdict::Held);
    assert!(s.friction_held && !s.locking_needed);
    // Wedged and needing it: a 20 deg V (locks at mu 0.3) pulled sideways at 10 W.
    let mut p = free_v(20.0, 0.3);
    p.load_n = 10.0 * p.weight_n();
    let s = locator::solve(&p).unwrap();
    assert_eq!(s.verdict, Verdict::Wedged);
    assert!(s.locking_needed && s.friction_held);
}

#[test]
fn bad_input_names_the_key_and_value() {
    let cases = [
        (
            LocatorParams {
                flank_left_deg: -5.0,
                ..LocatorParams::default()
            },
            "flank_left_deg",
            "-5",
        ),
        (
            LocatorParams {
                flank_left_deg: 100.0,
                flank_right_deg: 80.0,
                ..LocatorParams::default()
            },
            "flank_left_deg + flank_right_deg",
            "180",
        ),
        (
            LocatorParams {
                mu_right: -0.1,
                ..LocatorParams::default()
            },
            "mu_right",
            "-0.1",
        ),
        (
            LocatorParams {
                load_n: f64::NAN,
                ..LocatorParams::default()
            },
            "load_n",
            "NaN",
        ),
    ];
    for (p, key, value) in cases {
        let msg = locator::solve(&p).unwrap_err().to_string();
        assert!(msg.contains(key) && msg.contains(value), "{msg}");
    }
}

/// Regression: a load that cancels the weight (`vlocator --mu 0.3 --load 9.806 --load-angle
/// 90`) printed `held` next to "flank forces: none (no equilibrium)", and then `held` beside
/// zero forces, though nothing presses the disc into the V. With no net load the equilibrium is
/// the trivial one: both flank forces are zero, and the verdict says the disc is unloaded.
#[test]
fn zero_net_load_is_unloaded_with_zero_forces() {
    let p = LocatorParams {
        load_n: 9.806,
        load_angle_deg: 90.0,
        ..free_v(90.0, 0.3)
    };
    let s = locator::solve(&p).unwrap();
    assert_eq!(s.verdict, Verdict::Unloaded);
    assert_eq!(s.verdict.as_str(), "unloaded");
    let forces = s
        .forces
        .expect("zero net load has an equilibrium: zero flank forces");
    for f in forces {
        assert!(
            f.normal_n.abs() < 1e-9 && f.tangential_up_n.abs() < 1e-9,
            "{f:?}"
        );
    }
}

/// Regression: blocked rotation with a load at a rim point was refused,
/// though the joint carries the load's moment and the answer is well defined: the load acts
/// as if at the centre. The verdict, forces and capacity now equal the centre load's.
#[test]
fn blocked_rotation_with_a_rim_load_acts_as_at_the_centre() {
    let centre = LocatorParams {
        rotation: Rotation::Blocked,
        load_n: 5.0,
        load_angle_deg: 20.0,
        ..LocatorParams::default()
    };
    let rim = LocatorParams {
        load_at_rim_deg: Some(30.0),
        ..centre
    };
    let (a, b) = (
        locator::solve(&centre).unwrap(),
        locator::solve(&rim).unwrap(),
    );
    assert_eq!(a.verdict, b.verdict);
    assert_eq!(a.capacity, b.capacity);
    let (fa, fb) = (a.forces.unwrap(), b.forces.unwrap());
    for i in 0..2 {
        assert!(
            (fa[i].normal_n - fb[i].normal_n).abs() <= 1e-6 * centre.weight_n(),
            "{fa:?} {fb:?}"
        );
        assert!(
            (fa[i].tangential_up_n - fb[i].tangential_up_n).abs() <= 1e-6 * centre.weight_n(),
            "{fa:?} {fb:?}"
        );
    }
}

/// Regression: when no V that does not self-lock holds the load
/// (rho* <= 1), the optimum offered a V that self-locks at the nominal friction (17.06 deg at
/// mu 0.15) as if it were an answer. It now says no V works.
#[test]
fn no_v_that_does_not_lock_holds_a_heavy_sideways_load() {
    let p = LocatorParams {
        mu_left: 0.15,
        mu_right: 0.15,
        load_n: 1000.0,
        load_angle_deg: 0.0,
        ..LocatorParams::default()
    };
    let o = locator::optimum(&p);
    assert!(o.safety_factor <= 1.0, "{o:?}");
    assert!(o.no_v_holds, "{o:?}");
    let light = LocatorParams { load_n: 1.0, ..p };
    assert!(!locator::optimum(&light).no_v_holds);
}

/// Regression: for a pure lift rho_hold does not depend on the angle (the
/// docs said it falls), so every V wider than the crossing survives the same rho*; the
/// optimum reported the narrowest with `at_bound: false` as if it were the only one. It now
/// reports the plateau up to the widest V.
#[test]
fn a_pure_lift_reports_the_plateau_of_equally_good_vs() {
    let p = LocatorParams {
        mu_left: 0.3,
        mu_right: 0.3,
        load_n: 5.0,
        load_angle_deg: 90.0,
        ..LocatorParams::default()
    };
    let o = locator::optimum(&p);
    let widest = o.plateau_to_deg.unwrap_or_else(|| panic!("{o:?}"));
    assert!(widest > o.included_angle_deg + 10.0, "{o:?}");
    let wide = p.with_included_angle_same_tilt(widest);
    let rho_wide = locator::balanced_rho(&wide);
    assert!(
        (rho_wide - o.safety_factor).abs() <= 1e-6 * o.safety_factor,
        "{rho_wide} {o:?}"
    );
    // A sideways load has a unique optimum.
    let side = LocatorParams {
        load_angle_deg: 0.0,
        ..p
    };
    assert_eq!(locator::optimum(&side).plateau_to_deg, None);
}

/// Regression: a free V just wider than its locking angle with unequal frictions dropped its own
/// weight (`vlocator --mu-left 0.2 --mu-right 0.225 --included-angle 22.61986494804043` slipped
/// on both flanks). There its support cone spans 180 deg less a rounding error, two generators
/// are opposite, and the sign of their cross product picked the cone's complement. The weight
/// lies 90 deg inside the cone: held at every angle from the locking one up.
#[test]
fn a_v_just_wider_than_its_locking_angle_holds_its_weight() {
    for (mu_left, mu_right) in [(0.2, 0.225), (0.2, 0.4), (0.45, 0.3), (0.1, 0.1)] {
        let lock_deg = 2.0 * f64::atan(f64::min(mu_left, mu_right)).to_degrees();
        for rel in [0.0, 1e-16, 1e-15, 1e-13, 1e-11, 1e-9, 1e-6] {
            let p = LocatorParams {
                mu_left,
                mu_right,
                ..LocatorParams::default()
            }
            .with_included_angle(lock_deg * (1.0 + rel));
            if self_locking(&p) {
                continue;
            }
            assert_eq!(held_at(&p, 0.0), Ok(()), "{mu_left}/{mu_right} at +{rel:e}");
            let s = locator::solve(&p).unwrap();
            assert!(s.verdict.holds(), "{mu_left}/{mu_right} at +{rel:e}: {s:?}");
        }
    }
}

/// `vlocator --mass 1 --load 5 --load-angle 90` said that beyond P_max = W the part "rolls
/// out over the left flank": the two rows of its support cone bind at the same load there,
/// and which one counted was rounding (cos 90 deg is 6.1e-17 in radians). A load straight up
/// beyond W lifts the disc off both flanks, as the verdict at such a load says, for any V,
/// rotation and friction, at the centre or at the rim point straight above it.
#[test]
fn a_load_straight_up_beyond_the_weight_pulls_the_part_out() {
    for (flanks, rotation, rim, mu) in [
        ((45.0, 45.0), Rotation::Free, None, 0.3),
        ((45.0, 45.0), Rotation::Blocked, None, 0.3),
        ((30.0, 60.0), Rotation::Free, None, 0.3),
        ((30.0, 60.0), Rotation::Blocked, None, 0.1),
        ((10.0, 100.0), Rotation::Free, None, 0.0),
        ((45.0, 45.0), Rotation::Free, Some(90.0), 0.3),
        ((20.0, 35.0), Rotation::Free, Some(90.0), 0.2),
    ] {
        let p = LocatorParams {
            flank_left_deg: flanks.0,
            flank_right_deg: flanks.1,
            rotation,
            load_at_rim_deg: rim,
            load_n: 5.0,
            load_angle_deg: 90.0,
            ..LocatorParams::default()
        }
        .with_mu(mu);
        let c = capacity(&p);
        let w = p.weight_n();
        let at = format!("{flanks:?} {rotation:?} rim {rim:?} mu {mu}");
        assert!((c.p_max_n.unwrap() - w).abs() < 1e-9 * w, "{at}: {c:?}");
        assert_eq!(c.failure_mode, Some(FailureMode::PulledOut), "{at}: {c:?}");
        assert_eq!(held_at(&p, 1.5 * w), Err(FailureMode::PulledOut), "{at}");
    }
    // A load a degree off the vertical rolls the part over the flank it leans towards.
    let lean = |phi: f64| {
        let p = LocatorParams {
            load_n: 5.0,
            load_angle_deg: phi,
            ..LocatorParams::default()
        };
        capacity(&p).failure_mode
    };
    assert_eq!(lean(89.0), Some(FailureMode::RollsOverRight));
    assert_eq!(lean(91.0), Some(FailureMode::RollsOverLeft));
}
