use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    let mut worst = 0.0f64;
    for mu in [0.15, 0.25, 0.4, 0.6] {
        for k in [1e5, 5.02e6, 7.96e8] {
            for drive in [Drive::Motion, Drive::Force] {
                for (m, w) in [(1.0, 30.0), (0.2, 10.0), (5.0, 90.0)] {
                    let sc = SceneParams {
                        mass_kg: m,
                        ..SceneParams::default().with_mu(mu)
                    };
                    let base = DynamicsParams {
                        stiffness_n_per_mm_e: k,
                        drive,
                        omega_deg_s: w,
                        ..Default::default()
                    };
                    let r = simulate(&sc, &DynamicsParams { rtol: 1e-9, ..base }, None).unwrap();
                    for method in [Method::Radau5, Method::Dopri5] {
                        if method == Method::Dopri5 && k > 1e7 {
                            continue;
                        }
                        for rtol in [1e-3, 1e-4] {
                            let s = simulate(
                                &sc,
                                &DynamicsParams {
                                    rtol,
                                    method,
                                    ..base
                                },
                                None,
                            )
                            .unwrap();
                            let err = match (s.x_jam_mm, r.x_jam_mm) {
                                (Some(a), Some(b)) => (a - b).abs() / b,
                                _ => f64::NAN,
                            };
                            if s.status == jamchart::JamStatus::Jams {
                                worst = worst.max(err);
                            }
                            let flag = if s.status == jamchart::JamStatus::Jams
                                && (s.status != r.status || err > 2e-3)
                            {
                                "  <<<"
                            } else {
                                ""
                            };
                            println!(
                                "mu {mu} k {k:e} {drive:?} m {m} w {w} {method:?} {rtol:e}: {:?} {:?} ref {:?} {:?} err {err:.1e} steps {}{flag}",
                                s.status, s.x_jam_mm, r.status, r.x_jam_mm, s.steps
                            );
                        }
                    }
                }
            }
        }
    }
    println!("worst {worst:e}");
}
