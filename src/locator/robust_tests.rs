//! The robust V-block against its closed form and against a brute-force grid of the exact
//! locator over the box.

use crate::locator::{
    LocatorParams, RobustBox, RobustDesign, Rotation, held_at, robust_design, self_locking,
};

/// W of the default disc (1 kg at 9.806 m/s^2), N.
const W: f64 = 9.806;

fn free_base() -> LocatorParams {
    LocatorParams::default()
}

/// Whether the V of `gamma` works at every point of a grid over the box: `n` frictions per
/// flank, three masses, `n` magnitudes and one direction per 0.25 deg (the brute force).
fn works_on_grid(base: &LocatorParams, b: &RobustBox, gamma: f64, n: usize) -> bool {
    let lin = |(lo, hi): (f64, f64), k: usize, m: usize| {
        if m == 0 {
            lo
        } else {
            lo + (hi - lo) * k as f64 / m as f64
        }
    };
    let m_phi = ((b.load_angle_deg.1 - b.load_angle_deg.0) / 0.25).ceil() as usize;
    let v = base.with_included_angle_same_tilt(gamma);
    for (i1, i2) in (0..=n).flat_map(|i| (0..=n).map(move |j| (i, j))) {
        let q = LocatorParams {
            mu_left: lin(b.mu_left, i1, n),
            mu_right: lin(b.mu_right, i2, n),
            ..v
        };
        if self_locking(&q) {
            return false;
        }
        for m in 0..=2 {
            for j in 0..=n {
                for k in 0..=m_phi {
                    let p = lin(b.load_n, j, n);
                    let q = LocatorParams {
                        mass_kg: lin(b.mass_kg, m, 2),
                        load_n: p,
                        load_angle_deg: lin(b.load_angle_deg, k, m_phi),
                        ..q
                    };
                    if held_at(&q, p).is_err() {
                        return false;
                    }
                }
            }
        }
    }
    true
}

/// Asserts the design `d` over `b` is one window whose angles (`steps` + 1 of them) all work on
/// a brute-force grid of `n` values per input, and that 0.1 deg outside either edge some grid
/// point fails (or the angles end there); returns the window.
fn assert_one_window_on_grid(
    base: &LocatorParams,
    b: &RobustBox,
    d: &RobustDesign,
    steps: usize,
    n: usize,
) -> (f64, f64) {
    assert_eq!(d.windows.len(), 1, "{b:?} {d:?}");
    let (lo, hi) = d.windows[0];
    for k in 0..=steps {
        let g = lo + (hi - lo) * k as f64 / steps as f64;
        assert!(
            works_on_grid(base, b, g, n),
            "{g} deg of {b:?} fails on the grid"
        );
    }
    let step = 0.1;
    assert!(
        lo - step < 1.0 || !works_on_grid(base, b, lo - step, 4),
        "{b:?}: {lo}"
    );
    // A tilted V reaches at most 180 - |a1 - a2| (a flank at 0 deg).
    let widest = 179.0_f64.min(180.0 - (base.flank_left_deg - base.flank_right_deg).abs());
    assert!(
        hi + step > widest || !works_on_grid(base, b, hi + step, 4),
        "{b:?}: {hi}"
    );
    (lo, hi)
}

/// Free symmetric V, sideways centre load P, friction range: the window is
/// [2 atan mu_hi, 2 atan(W / P)] and the robust angle 2 atan sqrt(mu_hi W / P) with
/// rho* = sqrt(W / (mu_hi P)) (module docs of `robust`).
#[test]
fn robust_window_matches_the_closed_form_for_a_sideways_load() {
    let mut worst: f64 = 0.0;
    for (mu, p) in [
        ((0.12, 0.3), 5.0),
        ((0.05, 0.2), 1.0),
        ((0.3, 0.6), 3.0),
        ((0.1, 0.1), 9.0),
    ] {
        let b = RobustBox::both_flanks(&free_base(), mu, (p, p), (0.0, 0.0));
        let d = robust_design(&free_base(), &b);
        let want_lo = 2.0 * mu.1.atan().to_degrees();
        let want_hi = 2.0 * (W / p).atan().to_degrees();
        assert_eq!(d.windows.len(), 1, "{b:?}: {d:?}");
        let (lo, hi) = d.windows[0];
        let r = d.robust.unwrap();
        let want_g = 2.0 * (mu.1 * W / p).sqrt().atan().to_degrees();
        let want_rho = (W / (mu.1 * p)).sqrt();
        for (got, want) in [
            (lo, want_lo),
            (hi, want_hi),
            (r.included_angle_deg, want_g),
            (r.safety_factor, want_rho),
        ] {
            worst = worst.max((got - want).abs());
        }
        assert!(d.opening.is_none());
    }
    // Bisection to 1e-15 deg; the arc cover adds nothing for one direction.
    assert!(worst < 1e-7, "worst {worst:e}");
}

/// A V-block for the 25 mm shaft: a 30 N sideways load over mu 0.12 to 0.3, 0.4 kg. No V
/// works (mu_hi P = 9 N > W = 3.92 N); narrowing the friction to mu <= W / P = 0.131 opens it,
/// or the narrowest V that does not lock (2 atan 0.3 = 33.4 deg) holds loads up to
/// W / mu_hi = 13.1 N.
#[test]
fn no_single_v_works_for_the_25mm_shaft_and_the_tool_says_what_opens_it() {
    let base = LocatorParams {
        mass_kg: 0.4,
        ..free_base()
    };
    let w = base.weight_n();
    let b = RobustBox::both_flanks(&base, (0.12, 0.3), (30.0, 30.0), (0.0, 0.0));
    let d = robust_design(&base, &b);
    assert!(d.windows.is_empty() && d.robust.is_none(), "{d:?}");
    let o = d.opening.unwrap();
    assert!((o.mu_hi_max.unwrap() - w / 30.0).abs() < 1e-9, "{o:?}");
    assert!((o.load_hi_max_n.unwrap() - w / 0.3).abs() < 1e-6, "{o:?}");
    assert!((d.lock_bound_deg - 2.0 * 0.3_f64.atan().to_degrees()).abs() < 1e-12);
    assert!(d.dropped_at_lock_bound.is_some());
}

/// The window against a brute-force grid of the exact locator over the box, for free and
/// blocked, tilted and symmetric Vs, load ranges in magnitude and direction: every angle of
/// the window works at every grid point (never a V that fails in the box), and 0.1 deg
/// outside either edge some grid point fails.
#[test]
fn robust_window_matches_a_brute_force_grid_over_the_box() {
    let cases = [
        (free_base(), (0.1, 0.3), (2.0, 6.0), (-20.0, 20.0)),
        (free_base(), (0.2, 0.25), (0.0, 4.0), (0.0, 60.0)),
        (
            LocatorParams {
                rotation: Rotation::Blocked,
                ..free_base()
            },
            (0.1, 0.4),
            (2.0, 8.0),
            (-10.0, 30.0),
        ),
        (
            LocatorParams {
                flank_left_deg: 55.0,
                flank_right_deg: 35.0,
                ..free_base()
            },
            (0.15, 0.3),
            (1.0, 3.0),
            (150.0, 200.0),
        ),
    ];
    for (base, mu, load_n, load_angle_deg) in cases {
        let b = RobustBox::both_flanks(&base, mu, load_n, load_angle_deg);
        let d = robust_design(&base, &b);
        let (lo, hi) = assert_one_window_on_grid(&base, &b, &d, 10, 6);
        let r = d.robust.unwrap();
        assert!(
            r.safety_factor >= 1.0 && (lo..=hi).contains(&r.included_angle_deg),
            "{r:?}"
        );
    }
}

/// An empty window is empty on the brute-force grid too: no included angle (0.5 deg steps)
/// works at every grid point of the box (blocked, mu 0.1 to 0.4, 5 to 15 N from -10 to 30
/// deg; the narrowest V that does not lock drops 15 N at 23 deg).
#[test]
fn an_empty_robust_window_is_empty_on_the_brute_force_grid() {
    let base = LocatorParams {
        rotation: Rotation::Blocked,
        ..free_base()
    };
    let b = RobustBox::both_flanks(&base, (0.1, 0.4), (5.0, 15.0), (-10.0, 30.0));
    let d = robust_design(&base, &b);
    assert!(d.windows.is_empty(), "{d:?}");
    let any = (2..358)
        .map(|k| k as f64 * 0.5)
        .find(|&g| works_on_grid(&base, &b, g, 4));
    assert_eq!(any, None);
    // What opens it does: the V of 2 atan mu_hi_max holds the box with mu up to mu_hi_max.
    let o = d.opening.unwrap();
    let mu_hi = o.mu_hi_max.unwrap();
    let narrower = RobustBox {
        mu_left: (0.1, mu_hi * (1.0 - 1e-6)),
        mu_right: (0.1, mu_hi * (1.0 - 1e-6)),
        ..b
    };
    assert_eq!(robust_design(&base, &narrower).windows.len(), 1);
    let lighter = RobustBox {
        load_n: (5.0, o.load_hi_max_n.unwrap() * (1.0 - 1e-6)),
        ..b
    };
    assert_eq!(robust_design(&base, &lighter).windows.len(), 1);
}

/// Per-flank friction ranges and a mass range, which `vlocator --mu-left`, `--mu-right` and
/// `--mass` once refused though the help promised them: the window against the brute-force
/// grid (each flank's friction on its own grid, three masses), free and blocked, centre and
/// sideways loads.
#[test]
fn a_window_over_flank_ranges_and_a_mass_range_matches_the_brute_force_grid() {
    let blocked = LocatorParams {
        rotation: Rotation::Blocked,
        ..free_base()
    };
    let cases = [
        // (base, mu_left, mu_right, mass_kg, load_n, load_angle_deg)
        (
            free_base(),
            (0.1, 0.3),
            (0.2, 0.5),
            (0.5, 2.0),
            (2.0, 6.0),
            (-20.0, 20.0),
        ),
        (
            free_base(),
            (0.2, 0.2),
            (0.05, 0.4),
            (1.0, 1.0),
            (0.0, 4.0),
            (0.0, 60.0),
        ),
        (
            blocked,
            (0.1, 0.4),
            (0.3, 0.35),
            (0.8, 1.6),
            (2.0, 8.0),
            (-10.0, 30.0),
        ),
        (
            free_base(),
            (0.15, 0.3),
            (0.15, 0.3),
            (0.3, 3.0),
            (1.0, 3.0),
            (150.0, 200.0),
        ),
    ];
    for (base, mu_left, mu_right, mass_kg, load_n, load_angle_deg) in cases {
        let b = RobustBox {
            mu_left,
            mu_right,
            mass_kg,
            load_n,
            load_angle_deg,
        };
        assert_one_window_on_grid(&base, &b, &robust_design(&base, &b), 8, 4);
    }
}

/// Free symmetric V, sideways centre load P, a mass range and unequal flank ranges: the V
/// locks at the smaller of the highs and holds the lightest disc least, so the window is
/// [2 atan min(mu1_hi, mu2_hi), 2 atan(W_lo / P)].
#[test]
fn a_window_over_a_mass_range_is_the_closed_form_at_the_lightest_disc() {
    let b = RobustBox {
        mu_left: (0.1, 0.25),
        mu_right: (0.12, 0.4),
        mass_kg: (0.6, 2.0),
        load_n: (3.0, 3.0),
        load_angle_deg: (0.0, 0.0),
    };
    let d = robust_design(&free_base(), &b);
    let w_lo: f64 = 0.6 * 9.806;
    let (lo, hi) = d.windows[0];
    assert!(
        (lo - 2.0 * 0.25_f64.atan().to_degrees()).abs() < 1e-9,
        "{d:?}"
    );
    assert!(
        (hi - 2.0 * (w_lo / 3.0).atan().to_degrees()).abs() < 1e-7,
        "{d:?}"
    );
}

/// `holds_sector` recomputed the V's frame and support cone (sin, cos and
/// tan) for each of its some 80 loads, most of the `vlocator-robust` chart's time; it now
/// prepares the V once (`exact::PreparedV`). A V prepared once must answer every load, of
/// every direction and magnitude, exactly as the V prepared for that load alone: free and
/// blocked, centre and rim loads, locking and not, asymmetric frictions.
#[test]
fn a_v_prepared_once_holds_each_load_as_one_prepared_for_it() {
    let mut checked = 0;
    for rotation in [Rotation::Free, Rotation::Blocked] {
        for rim in [None, Some(30.0), Some(-120.0)] {
            for gamma in [20.0, 60.0, 90.0, 140.0] {
                for (mu_l, mu_r) in [(0.0, 0.0), (0.3, 0.3), (0.1, 0.7), (2.0, 2.0)] {
                    let v = LocatorParams {
                        rotation,
                        load_at_rim_deg: rim,
                        mu_left: mu_l,
                        mu_right: mu_r,
                        ..free_base()
                    }
                    .with_included_angle_same_tilt(gamma);
                    let prepared = crate::locator::exact::PreparedV::new(&v);
                    for phi in (-36..=36).map(|k| 5.0 * k as f64) {
                        for p in [0.0, 0.5, 3.0, 9.0, 40.0, 1e3] {
                            let q = LocatorParams {
                                load_n: p,
                                load_angle_deg: phi,
                                ..v
                            };
                            assert_eq!(
                                prepared.held_at(p, phi),
                                held_at(&q, p),
                                "{rotation:?} rim {rim:?} gamma {gamma} mu {mu_l}/{mu_r} \
                                 phi {phi} P {p}"
                            );
                            checked += 1;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(checked, 2 * 3 * 4 * 4 * 73 * 6);
}
