//! The closed-form statics against the corrected Table 1, hand derivations and its invariants.

use jamchart::paper::TABLE1;
use jamchart::scene::disc_position_mm;
use jamchart::statics;
use jamchart::statics::reference::margin_n;
use jamchart::{JamStatus, SceneParams};
use proptest::prelude::*;

/// Rows of tests/golden/table1.csv: (mu, theta_deg, x_mm, paper_theta_deg, paper_x_mm).
fn golden_table1() -> Vec<[f64; 5]> {
    include_str!("../../tests/golden/table1.csv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("mu,"))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3], v[4]]
        })
        .collect()
}

#[test]
fn table1_corrected_matches_golden_to_1e9() {
    let rows = golden_table1();
    assert_eq!(rows.len(), 7);
    let mut worst = 0.0_f64;
    for [mu, theta, x, ..] in rows {
        let s = statics::solve(&SceneParams::default().with_mu(mu));
        assert_eq!(s.status, JamStatus::Jams, "mu = {mu}");
        let dt = (s.theta_jam_deg.unwrap() - theta).abs();
        let dx = (s.x_jam_mm.unwrap() - x).abs();
        worst = worst.max(dt).max(dx);
        // The golden values carry 9 decimals: agreement to 1e-9 absolute, rounding included.
        assert!(
            dt < 1e-9 && dx < 1e-9,
            "mu = {mu}: dtheta {dt:e} deg, dx {dx:e} mm"
        );
    }
    eprintln!("worst difference to golden Table 1: {worst:e}");
}

#[test]
fn paper_table1_is_our_theta_truncated_and_x_of_that_theta() {
    // Corrections to the paper (crate docs): the printed theta is the closed form to 0.1 deg (we find: truncated, not rounded) and
    // the printed x is r cot(theta/2) of it; the mu = 0.30 row's x is the known erratum.
    for [mu, theta, _, paper_theta, paper_x] in golden_table1() {
        assert!(
            ((theta * 10.0).floor() / 10.0 - paper_theta).abs() < 1e-9,
            "mu = {mu}"
        );
        let x_of_printed = disc_position_mm(10.0, 0.0, paper_theta.to_radians());
        let printed_ok = (x_of_printed - paper_x).abs() < 0.006;
        assert_eq!(
            printed_ok,
            (mu - 0.30).abs() > 1e-9,
            "mu = {mu}: {x_of_printed} vs {paper_x}"
        );
    }
    // The crate's copy of the paper's numbers is the one the golden file was checked against.
    for (row, [mu, _, _, paper_theta, paper_x]) in TABLE1.iter().zip(golden_table1()) {
        assert!((row.mu - mu).abs() < 1e-12);
        assert!((row.statics_theta_jam_deg - paper_theta).abs() < 1e-12);
        assert!((row.statics_x_jam_mm - paper_x).abs() < 1e-12);
        assert_eq!(row.erratum.is_some(), (mu - 0.30).abs() < 1e-9);
    }
}

fn assert_jam(p: &SceneParams, theta_deg: f64, x_mm: f64) {
    let s = statics::solve(p);
    assert_eq!(s.status, JamStatus::Jams, "{p:?}");
    let (t, x) = (s.theta_jam_deg.unwrap(), s.x_jam_mm.unwrap());
    assert!((t - theta_deg).abs() < 1e-10, "theta {t} vs {theta_deg}");
    assert!((x - x_mm).abs() < 1e-9 * x_mm, "x {x} vs {x_mm}");
}

#[test]
fn one_frictionless_contact_by_hand() {
    // By hand, (a) mu_p = 0: the palm pushes along its normal (sin t, -cos t), tilted t from the
    // vertical, so a weightless disc is held iff tan t <= mu_g. (b) mu_g = 0: the ground holds only if
    // R_t = F sin(t - alpha_p) <= 0, i.e. t <= alpha_p, whatever the weight. With the other mu = 1/2
    // both give tan t = 1/2, tan(t/2) = sqrt(5) - 2 and x = r cot(t/2) = r (2 + sqrt 5).
    let d = SceneParams::default();
    let weightless_frictionless_palm = SceneParams {
        mu_ground: 0.5,
        mu_palm: 0.0,
        mass_kg: 0.0,
        ..d
    };
    let frictionless_ground = SceneParams {
        mu_ground: 0.0,
        mu_palm: 0.5,
        ..d
    };
    for p in [weightless_frictionless_palm, frictionless_ground] {
        assert_jam(
            &p,
            0.5_f64.atan().to_degrees(),
            10.0 * (2.0 + 5.0_f64.sqrt()),
        );
    }
}

#[test]
fn frictionless_palm_heavy_disc_by_hand() {
    // By hand: mu_g = 1 (alpha_g = 45 deg), mu_p = 0, m g = 100 sqrt(2) N, F = 200 N:
    // m g sin(45)/F = 1/2, so theta_jam = 45 + 30 = 75 deg and x_jam = 10 cot(37.5 deg).
    let p = SceneParams {
        mu_ground: 1.0,
        mu_palm: 0.0,
        mass_kg: 100.0 * 2.0_f64.sqrt(),
        gravity_m_s2: 1.0,
        ..Default::default()
    };
    assert_jam(&p, 75.0, 10.0 / 37.5_f64.to_radians().tan());
}

#[test]
fn unequal_frictions_are_not_symmetric_with_weight() {
    // Only the ground friction multiplies the weight, so swapping mu_g and mu_p moves the jam.
    // Values from the closed form evaluated independently in Python (see golden/table1.csv).
    let p = SceneParams::default();
    let a = SceneParams {
        mu_ground: 0.2,
        mu_palm: 0.6,
        ..p
    };
    let b = SceneParams {
        mu_ground: 0.6,
        mu_palm: 0.2,
        ..p
    };
    assert_jam(&a, 42.824629310097855, 25.500857467852253);
    assert_jam(&b, 43.719170021856705, 24.92657316295565);
}

#[test]
fn statuses_in_their_order() {
    let d = SceneParams::default();
    assert_eq!(statics::solve(&d.with_mu(0.0)).status, JamStatus::NeverJams);
    // A start below theta_jam: held from the start.
    let s = statics::solve(&SceneParams {
        start_angle_deg: 40.0,
        ..d
    });
    assert_eq!(s.status, JamStatus::JammedAtStart);
    assert_eq!(s.theta_jam_deg, Some(40.0));
    // mu = 0.01 jams at x ~ 1000 mm, beyond a 150 mm palm.
    let s = statics::solve(&d.with_mu(0.01));
    assert_eq!(s.status, JamStatus::BeyondReach);
    assert_eq!((s.theta_jam_deg, s.x_jam_mm), (None, None));
    // A push too weak to move the disc at all: m g sin(alpha)/F >= 1 (a status of its
    // own; it was jammed_at_start, indistinguishable from a disc that jams at once).
    let s = statics::solve(&SceneParams { force_n: 1.0, ..d });
    assert_eq!(s.status, JamStatus::TooWeak);
}

#[test]
fn lift_off_is_flagged_when_the_start_is_past_it() {
    // Weightless disc, frictionless palm: R_n = F cos(theta) < 0 above 90 deg.
    let p = SceneParams {
        mass_kg: 0.0,
        mu_palm: 0.0,
        start_angle_deg: 120.0,
        ..Default::default()
    };
    let s = statics::solve(&p);
    assert!(s.lifts_off);
    assert!((s.lift_off_above_deg.unwrap() - 90.0).abs() < 1e-9);
    assert!(!statics::solve(&SceneParams::default()).lifts_off);
}

/// Log-uniform in [lo, hi].
fn log_range(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

/// Inputs over many decades, with exact zeros for mu and mass now and then.
fn any_scene() -> impl Strategy<Value = SceneParams> {
    let mu = prop_oneof![1 => Just(0.0), 9 => log_range(1e-6, 1e3)];
    let mass = prop_oneof![1 => Just(0.0), 9 => log_range(1e-6, 1e6)];
    (
        (mu.clone(), mu),
        log_range(1e-3, 1e6),
        log_range(1e-9, 1e12),
        mass,
        1e-6..(180.0 - 1e-6),
        log_range(1e-3, 1e7),
    )
        .prop_map(|((mu_g, mu_p), r, f, m, start, palm)| SceneParams {
            mu_ground: mu_g,
            mu_palm: mu_p,
            radius_mm: r,
            force_n: f,
            mass_kg: m,
            start_angle_deg: start,
            palm_length_mm: palm,
            ..Default::default()
        })
}

proptest! {
    #![proptest_config(ProptestConfig { max_global_rejects: 20_000, ..crate::proptest_config(4000) })]

    #[test]
    fn no_nan_or_infinity_reaches_an_output(p in any_scene(), u in 0.0..1.0f64) {
        prop_assert!(p.validate().is_ok());
        let s = statics::solve(&p);
        for v in [s.theta_jam_deg, s.x_jam_mm, s.x_rigid_mm, s.lift_off_above_deg].into_iter().flatten() {
            prop_assert!(v.is_finite(), "{:?} -> {:?}", p, s);
        }
        prop_assert!(s.theta_rigid_deg.is_finite());
        prop_assert_eq!(s.theta_jam_deg.is_some(), s.x_jam_mm.is_some() || s.status == JamStatus::JammedAtStart);
        if s.status == JamStatus::Jams {
            prop_assert!(s.x_jam_mm.unwrap() <= p.palm_length_mm);
            prop_assert!(s.theta_jam_deg.unwrap() < p.start_angle_deg);
        }
        let m = margin_n(&p, u * std::f64::consts::PI);
        prop_assert!(m.is_finite());
    }

    /// The outcome the port gives alone (no extras, no clock) is the full solution's, to the
    /// bit, above the models' start angle too.
    #[test]
    fn the_outcome_alone_is_the_solutions_to_the_bit(p in any_scene()) {
        let spec = crate::models::ModelSpec::Statics;
        let alone = crate::models::outcome(&spec, &p).unwrap().unwrap();
        let full = crate::models::solve(&spec, &p).unwrap().outcome();
        let bits = |o: crate::models::Outcome| {
            (o.model, o.status, o.theta_jam_deg.map(f64::to_bits), o.x_jam_mm.map(f64::to_bits))
        };
        prop_assert_eq!(bits(alone), bits(full), "{:?}", p);
    }

    #[test]
    fn margin_changes_sign_exactly_at_theta_jam(p in any_scene(), u in 0.3..1.0f64) {
        // A long palm and a high start, so that most cases slide before they jam.
        let p = SceneParams { palm_length_mm: 1e300, start_angle_deg: 180.0 * u, ..p };
        let s = statics::solve(&p);
        prop_assume!(s.status == JamStatus::Jams);
        let k = p.weight_n() * p.alpha_ground().sin() / p.force_n;
        // Near k = 1 the margin is flat at theta_jam and its sign there is rounding noise.
        prop_assume!(k < 0.999);
        let t = s.theta_jam_deg.unwrap().to_radians();
        let start = p.start_angle_deg.to_radians();
        // The margin's scale: mu_g R_n + |R_t| is at most (1 + mu_g)(m g + F).
        let scale = (1.0 + p.mu_ground) * (p.weight_n() + p.force_n);
        prop_assert!(margin_n(&p, t).abs() <= 1e-9 * scale, "margin at theta_jam {}", margin_n(&p, t));
        let d = 1e-6 * t.min(start - t);
        prop_assert!(margin_n(&p, t - d) > 0.0, "held just below theta_jam");
        prop_assert!(margin_n(&p, t + d) < 0.0, "slides just above theta_jam");
        for u in [0.05, 0.3, 0.6, 0.95] {
            prop_assert!(margin_n(&p, u * t) > 0.0, "held at {} of theta_jam", u);
            prop_assert!(margin_n(&p, t + u * (start - t)) < 0.0, "slides between jam and start");
        }
    }
}
