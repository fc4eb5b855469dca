use proptest::prelude::*;

use super::*;
use crate::models::Detail;
use crate::statics;

/// The closed form as the grid's jam-point function.
fn st(p: &SceneParams) -> Result<JamPoint> {
    statics_point(p)
}

fn mu_theta(nx: usize, ny: usize) -> GridRequest {
    GridRequest {
        base: SceneParams::default(),
        x: GridAxis::linear(Param::Mu, 0.1, 0.5, nx),
        y: GridAxis::log(Param::ThetaDeg, 10.0, 70.0, ny),
        quantities: vec![Quantity::MarginN],
    }
}

fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool")
        .install(f)
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn opt_bits(v: &[Option<f64>]) -> Vec<Option<u64>> {
    v.iter().map(|x| x.map(f64::to_bits)).collect()
}

/// Regression: two axes of 200,000 samples each passed validation and the process aborted
/// allocating 320 GB; the cell count is now refused before anything is allocated.
#[test]
fn a_grid_too_large_to_allocate_is_refused() {
    let err = mu_theta(200_000, 200_000)
        .validate()
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("chart.x_axis.count * chart.y_axis.count") && err.contains("40000000000"),
        "{err}"
    );
    assert!(mu_theta(8192, 8192).validate().is_ok());
}

/// The grid's results must not depend on how rayon splits the work.
#[test]
fn bit_identical_for_any_thread_count() {
    let margin_req = mu_theta(257, 131);
    let rf_req = GridRequest {
        base: SceneParams::default(),
        x: GridAxis::log(Param::ForceN, 50.0, 10_000.0, 97),
        y: GridAxis::linear(Param::RadiusMm, 10.0, 30.0, 61),
        quantities: vec![
            Quantity::Status,
            Quantity::ThetaJamDeg,
            Quantity::XJamMm,
            Quantity::XRigidMm,
        ],
    };
    let run = |threads| {
        in_pool(threads, || {
            (
                evaluate(&margin_req, st).unwrap(),
                evaluate(&rf_req, st).unwrap(),
            )
        })
    };
    let (m1, r1) = run(1);
    for threads in [2, 3, 7] {
        let (m, r) = run(threads);
        assert_eq!(
            bits(m1.margin_n.as_ref().unwrap()),
            bits(m.margin_n.as_ref().unwrap()),
            "margin differs between 1 and {threads} threads"
        );
        assert_eq!(r1.status, r.status, "status, 1 vs {threads} threads");
        assert_eq!(
            opt_bits(r1.x_jam_mm.as_ref().unwrap()),
            opt_bits(r.x_jam_mm.as_ref().unwrap())
        );
        assert_eq!(
            opt_bits(r1.theta_jam_deg.as_ref().unwrap()),
            opt_bits(r.theta_jam_deg.as_ref().unwrap())
        );
        assert_eq!(
            opt_bits(r1.x_rigid_mm.as_ref().unwrap()),
            opt_bits(r.x_rigid_mm.as_ref().unwrap())
        );
    }
}

#[test]
fn only_requested_quantities_and_index_order() {
    let req = GridRequest {
        quantities: vec![Quantity::XJamMm],
        x: GridAxis::linear(Param::Mu, 0.2, 0.4, 3),
        y: GridAxis::linear(Param::RadiusMm, 10.0, 20.0, 2),
        base: SceneParams::default(),
    };
    let g = evaluate(&req, st).unwrap();
    assert!(g.margin_n.is_none() && g.status.is_none() && g.theta_jam_deg.is_none());
    let x = g.x_jam_mm.as_ref().unwrap();
    assert_eq!(x.len(), 6);
    // Cell (ix = 1, iy = 1) is mu = 0.3, r = 20 mm.
    let want = statics::solve(&SceneParams {
        radius_mm: 20.0,
        ..SceneParams::default().with_mu(0.3)
    })
    .x_jam_mm
    .unwrap();
    let got = x[g.index(1, 1)].unwrap();
    assert!((got - want).abs() <= 1e-12 * want, "{got} vs {want}");
}

#[test]
fn margin_without_theta_axis_is_refused() {
    let req = GridRequest {
        y: GridAxis::linear(Param::ForceN, 50.0, 100.0, 2),
        ..mu_theta(2, 2)
    };
    let msg = evaluate(&req, st).unwrap_err().to_string();
    assert!(msg.contains("theta_deg"), "{msg}");
    let req = GridRequest {
        x: GridAxis::linear(Param::Mu, -0.1, 0.5, 2),
        ..mu_theta(2, 2)
    };
    let msg = evaluate(&req, st).unwrap_err().to_string();
    assert!(msg.contains("mu_ground = -0.1"), "{msg}");
}

/// The hoisted kernel of `req` against `statics::reference::margin_n` cell by cell:
/// |diff| <= 1e-12 (|F| + m g), worst case reported.
fn assert_margin_matches_statics(req: &GridRequest) {
    let g = evaluate(req, st).unwrap();
    let m = g.margin_n.as_ref().unwrap();
    let theta_on_x = req.x.param == Param::ThetaDeg;
    let mut worst = (0.0_f64, 0.0, 0.0);
    for (iy, &yv) in g.y_values.iter().enumerate() {
        for (ix, &xv) in g.x_values.iter().enumerate() {
            let p = req.grid().cell(xv, Some(yv));
            let t = if theta_on_x { xv } else { yv };
            let d = (m[g.index(ix, iy)] - statics::reference::margin_n(&p, t.to_radians())).abs();
            if d > worst.0 {
                worst = (d, xv, yv);
            }
        }
    }
    let tol = 1e-12 * (req.base.force_n + req.base.weight_n());
    assert!(
        worst.0 <= tol,
        "worst |diff| {} N at {} = {}, {} = {}",
        worst.0,
        req.x.param.as_str(),
        worst.1,
        req.y.param.as_str(),
        worst.2
    );
}

/// The oracle over mu (mu_ground = mu_palm), over mu_ground with mu_palm = 0.7 and over mu_palm
/// with mu_ground = 0.25: a kernel that swapped the two frictions passes only the first. The
/// mu_palm grid puts theta on x, the branch no chart uses.
#[test]
fn hoisted_margin_matches_statics() {
    let theta = |n| GridAxis::log(Param::ThetaDeg, 10.0, 70.0, n);
    assert_margin_matches_statics(&mu_theta(101, 89));
    assert_margin_matches_statics(&GridRequest {
        base: SceneParams {
            mu_palm: 0.7,
            ..SceneParams::default()
        },
        x: GridAxis::linear(Param::MuGround, 0.1, 0.9, 53),
        y: theta(47),
        quantities: vec![Quantity::MarginN],
    });
    assert_margin_matches_statics(&GridRequest {
        base: SceneParams {
            mu_ground: 0.25,
            ..SceneParams::default()
        },
        x: theta(43),
        y: GridAxis::linear(Param::MuPalm, 0.1, 0.9, 37),
        quantities: vec![Quantity::MarginN],
    });
}

proptest! {
    /// The margin changes sign at the closed-form theta_jam: >= 0 just below, <= 0 just above
    /// (unequal ground and palm frictions, so a kernel that swapped them fails).
    #[test]
    fn margin_changes_sign_at_theta_jam(
        mu_g in 0.05f64..1.0, mu_p in 0.0f64..1.0, force in 20.0f64..5000.0,
    ) {
        let p = SceneParams { force_n: force, mu_ground: mu_g, mu_palm: mu_p, ..SceneParams::default() };
        let s = statics::solve(&p);
        prop_assume!(s.status == JamStatus::Jams);
        let tj = s.theta_jam_deg.unwrap();
        let k = margin::MarginCoeffs::new(&p);
        let at = |deg: f64| { let (sn, c) = deg.to_radians().sin_cos(); k.at(c, sn) };
        // 1e-6 deg either side: far beyond rounding, far below any chart's resolution.
        prop_assert!(at(tj - 1e-6) > 0.0, "below: {}", at(tj - 1e-6));
        prop_assert!(at(tj + 1e-6) < 0.0, "above: {}", at(tj + 1e-6));
    }
}

proptest! {
    /// Any valid grid gives finite numbers in every requested cell (no NaN/inf reaches a chart).
    #[test]
    fn every_cell_is_finite(
        mu_lo in 0.0f64..1.0, mu_span in 0.01f64..2.0,
        t_lo in 0.0f64..170.0, t_span in 0.1f64..10.0,
        mass in 0.0f64..50.0, force in 0.5f64..1e5,
    ) {
        let base = SceneParams { mass_kg: mass, force_n: force, ..SceneParams::default() };
        let req = GridRequest {
            base,
            x: GridAxis::linear(Param::Mu, mu_lo, mu_lo + mu_span, 7),
            y: GridAxis::linear(Param::ThetaDeg, t_lo, t_lo + t_span, 5),
            quantities: vec![Quantity::MarginN, Quantity::Status, Quantity::ThetaJamDeg, Quantity::XJamMm, Quantity::XRigidMm],
        };
        let g = evaluate(&req, st).unwrap();
        prop_assert!(g.margin_n.unwrap().iter().all(|v| v.is_finite()));
        for v in [g.theta_jam_deg.unwrap(), g.x_jam_mm.unwrap(), g.x_rigid_mm.unwrap()] {
            prop_assert!(v.iter().flatten().all(|v| v.is_finite()));
        }
    }
}

/// The closed-form capacity map of a symmetric V (`capacity_map`'s fast path) answers every
/// cell as the exact path does: the same unboundedness and failure mode, P_max / W within 1e-12
/// relative, over both axis orders, frictions from none to self-locking at every angle, and
/// load directions that hit 0, +-90 and 180 deg exactly, on maps the calling thread makes
/// alone and maps the thread pool shares. Cells whose bracket |cos phi| x +
/// sin phi lies within 1e-9 of zero (P_max beyond 1e9 W, where the exact path's tolerance
/// decides) are skipped and counted; the worst error is printed.
#[test]
fn symmetric_v_closed_form_matches_the_exact_path() {
    use crate::locator::{self, LocatorParams};
    let (mut worst, mut compared, mut skipped) = (0.0_f64, 0, 0);
    // Every friction on maps small enough for one thread; one friction on maps the thread
    // pool shares.
    let small = [0.0, 0.3, 0.8, 3.0].map(|mu| (mu, [89, 145]));
    let shared = (0.3, [401, 401]);
    const {
        assert!(401 * 401 > super::locator::PARALLEL_CELLS);
        assert!(89 * 145 < super::locator::PARALLEL_CELLS);
    }
    for (mu, [n_gamma, n_phi]) in small.into_iter().chain([shared]) {
        for gamma_on_x in [true, false] {
            let base = LocatorParams {
                mass_kg: 2.5,
                ..LocatorParams::default()
            }
            .with_mu(mu);
            let gamma = GridAxis::linear(LocatorParam::IncludedAngleDeg, 2.0, 178.0, n_gamma);
            let phi = GridAxis::linear(LocatorParam::LoadAngleDeg, -180.0, 180.0, n_phi);
            let (x, y) = match gamma_on_x {
                true => (gamma, phi),
                false => (phi, gamma),
            };
            let grid = Grid {
                base,
                x,
                y: Some(y),
            };
            assert!(locator::symmetric::applies(&grid.base));
            let fast = capacity_map(&grid).unwrap();
            let exact = grid.map(|p| Ok((locator::capacity(p), *p))).unwrap();
            assert_eq!(fast.x_values, exact.x_values);
            assert_eq!(fast.y_values, exact.y_values);
            let fast = fast.p_max_over_w.iter().zip(&fast.failure_mode);
            for ((&f, &f_mode), (e, p)) in fast.zip(&exact.values) {
                let (s, c) = p.load_angle_deg.to_radians().sin_cos();
                let x = (0.5 * p.included_angle_deg().to_radians()).tan();
                if (c.abs() * x + s).abs() < 1e-9 || c.abs() < 1e-9 {
                    skipped += 1;
                    continue;
                }
                assert_eq!(f_mode, e.failure_mode, "{p:?}: {f} vs {e:?}");
                assert_eq!(f_mode.is_none(), e.unbounded, "{p:?}: {f} vs {e:?}");
                match e.p_max_over_w {
                    Some(b) => {
                        let err = ((f - b) / b).abs();
                        assert!(err < 1e-12, "{p:?}: {f} vs {e:?}");
                        worst = worst.max(err);
                    }
                    None => assert!(f.is_nan(), "{p:?}: {f} vs {e:?}"),
                }
                compared += 1;
            }
        }
    }
    println!(
        "closed form vs exact: {compared} cells, worst P_max error {worst:.1e}, {skipped} skipped"
    );
    assert!(
        compared > 340_000 && skipped < compared / 50,
        "{compared} {skipped}"
    );
}

/// A V the closed form does not cover (tilted, unequal frictions, blocked, a rim load) is
/// answered by the exact path, cell for cell.
#[test]
fn capacity_map_falls_back_to_the_exact_path() {
    use crate::locator::{self, LocatorParams, Rotation};
    let d = LocatorParams::default();
    for base in [
        LocatorParams {
            flank_left_deg: 50.0,
            ..d
        },
        LocatorParams { mu_left: 0.2, ..d },
        LocatorParams {
            rotation: Rotation::Blocked,
            ..d
        },
        LocatorParams {
            load_at_rim_deg: Some(30.0),
            ..d
        },
    ] {
        assert!(!locator::symmetric::applies(&base), "{base:?}");
        let grid = Grid {
            base,
            x: GridAxis::linear(LocatorParam::IncludedAngleDeg, 20.0, 160.0, 15),
            y: Some(GridAxis::linear(
                LocatorParam::LoadAngleDeg,
                -80.0,
                80.0,
                17,
            )),
        };
        let exact = grid.map(|p| Ok(locator::capacity(p))).unwrap();
        let map = capacity_map(&grid).unwrap();
        assert_eq!(
            (map.x_values, map.y_values),
            (exact.x_values, exact.y_values)
        );
        let cells = map.p_max_over_w.iter().zip(&map.failure_mode);
        for ((&over_w, &mode), e) in cells.zip(&exact.values) {
            let e_over_w = e.p_max_over_w.map_or(f64::NAN.to_bits(), f64::to_bits);
            assert_eq!(
                (over_w.to_bits(), mode),
                (e_over_w, e.failure_mode),
                "{e:?}"
            );
        }
        assert_eq!(map.failure_mode.len(), exact.values.len());
    }
}

/// The closed form's batches answer every cell of a grid as the cell alone does
/// (`evaluate_closed_form` against `evaluate` with [`statics_point`]), bit for bit, for every
/// ordered pair of parameters an axis can vary (aliases, push ratios, start angles past
/// 90 deg, offsets), each over half to one and a half times its base value (0 to 1 where
/// that is 0), around four scenes that between them meet every status of the closed form; a
/// grid one refuses the other refuses too.
#[test]
fn closed_form_batches_answer_a_grid_as_its_cells() {
    let d = SceneParams::default();
    // The default scene, a push too weak to move the disc, a short palm, no friction.
    let bases = [
        d,
        SceneParams { force_n: 3.0, ..d },
        SceneParams {
            palm_length_mm: 25.0,
            ..d
        },
        SceneParams {
            mu_ground: 0.0,
            mu_palm: 0.0,
            ..d
        },
    ];
    let params: Vec<Param> = Param::all().filter(|&p| p != Param::ThetaDeg).collect();
    let (mut compared, mut refused) = (0, 0);
    let mut seen = std::collections::BTreeSet::new();
    for (base, xp) in bases
        .iter()
        .flat_map(|b| params.iter().map(move |p| (*b, *p)))
    {
        let span = |p: Param| match p.get(&base).unwrap_or(1.0) {
            0.0 => (0.0, 1.0),
            v => (0.5 * v, 1.5 * v),
        };
        for &yp in params.iter().filter(|&&p| p != xp) {
            let ((x0, x1), (y0, y1)) = (span(xp), span(yp));
            let req = GridRequest {
                base,
                x: GridAxis::linear(xp, x0, x1, 7),
                y: GridAxis::linear(yp, y0, y1, 5),
                quantities: vec![Quantity::Status, Quantity::ThetaJamDeg, Quantity::XJamMm],
            };
            let (cells, batches) = (evaluate(&req, st), evaluate_closed_form(&req));
            let (Ok(cells), Ok(batches)) = (&cells, &batches) else {
                assert!(
                    cells.is_err() && batches.is_err(),
                    "{xp:?} {yp:?}: {cells:?} {batches:?}"
                );
                refused += 1;
                continue;
            };
            assert_eq!(cells.status, batches.status, "{xp:?} {yp:?}");
            seen.extend(cells.status.iter().flatten().map(|s| s.as_str()));
            for (a, b) in [
                (&cells.theta_jam_deg, &batches.theta_jam_deg),
                (&cells.x_jam_mm, &batches.x_jam_mm),
            ] {
                assert_eq!(
                    opt_bits(a.as_ref().unwrap()),
                    opt_bits(b.as_ref().unwrap()),
                    "{xp:?} {yp:?}"
                );
            }
            compared += 1;
        }
    }
    println!("{compared} grids compared, {refused} refused by both; statuses {seen:?}");
    assert!(
        compared >= 2 * params.len() * (params.len() - 1),
        "{compared} {refused}"
    );
    let statuses = [
        "never_jams",
        "too_weak",
        "jammed_at_start",
        "beyond_reach",
        "jams",
    ];
    assert!(statuses.iter().all(|s| seen.contains(s)), "{seen:?}");
    assert!(seen.contains("outside_model"), "{seen:?}");
}

/// A cell's F -> infinity limit is what `solve` reports in the closed form's detail, and none
/// outside the model (a start past 90 deg), for frictions from none to high and a palm
/// offset.
#[test]
fn the_rigid_point_is_the_closed_forms_detail() {
    let d = SceneParams::default();
    let mut checked = [0, 0];
    for mu in [0.0, 0.1, 0.4, 2.0] {
        for (offset, start) in [(0.0, 90.0), (0.5, 60.0), (0.0, 120.0)] {
            let p = SceneParams {
                mu_ground: mu,
                mu_palm: 0.5 * mu,
                palm_offset_mm: offset,
                start_angle_deg: start,
                ..d
            };
            let want = match models::solve(&ModelSpec::Statics, &p).unwrap().detail {
                Detail::Statics(s) => {
                    Some((s.theta_rigid_deg.to_bits(), s.x_rigid_mm.map(f64::to_bits)))
                }
                _ => None,
            };
            p.validate().unwrap();
            let got = rigid_point(&p).map(|(t, x)| (t.to_bits(), x.map(f64::to_bits)));
            assert_eq!(got, want, "{p:?}");
            checked[usize::from(got.is_some())] += 1;
        }
    }
    assert!(checked[0] > 0 && checked[1] > 0, "{checked:?}");
}
