use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    for (m, w) in [
        (0.5, 30.0),
        (1.0, 30.0),
        (2.0, 30.0),
        (1.0, 10.0),
        (1.0, 5.0),
        (1.0, 60.0),
        (0.2, 10.0),
    ] {
        let p = DynamicsParams {
            omega_deg_s: w,
            ..Default::default()
        };
        let sc = SceneParams {
            mass_kg: m,
            ..Default::default()
        };
        let s = simulate(&sc, &p, None).unwrap();
        println!(
            "m {m} w {w}: {:?} {:?} steps {}",
            s.status, s.x_jam_mm, s.steps
        );
    }
    for r in [0.5, 0.2, 0.1, 0.05, 0.01, 3e-3] {
        for method in [Method::Radau5, Method::Dopri5] {
            for (k, drive) in [
                (1e5, Drive::Motion),
                (7.96e8, Drive::Motion),
                (1e5, Drive::Force),
            ] {
                let p = DynamicsParams {
                    rtol: r,
                    method,
                    stiffness_n_per_mm_e: k,
                    drive,
                    ..Default::default()
                };
                let s = simulate(&SceneParams::default(), &p, None).unwrap();
                println!(
                    "rtol {r} {method:?} k {k} {drive:?}: {:?} {:?} steps {} check {:?} fail {:?}",
                    s.status, s.x_jam_mm, s.steps, s.cross_check, s.failure
                );
            }
        }
    }
    let heavy = SceneParams {
        mass_kg: 100.0,
        ..Default::default()
    };
    let s = simulate(
        &heavy,
        &DynamicsParams {
            drive: Drive::Force,
            ..Default::default()
        },
        None,
    )
    .unwrap();
    println!(
        "heavy force: {:?} {:?} steps {}",
        s.status, s.x_jam_mm, s.steps
    );
    let s = simulate(
        &SceneParams::default().with_mu(0.0),
        &DynamicsParams::default(),
        None,
    )
    .unwrap();
    println!("mu 0: {:?} {:?} steps {}", s.status, s.x_jam_mm, s.steps);
    let s = simulate(
        &SceneParams::default().with_mu(0.15),
        &DynamicsParams::default(),
        None,
    )
    .unwrap();
    println!("mu 0.15: {:?} {:?} steps {}", s.status, s.x_jam_mm, s.steps);
    let s = simulate(
        &SceneParams::default().with_mu(1.5),
        &DynamicsParams::default(),
        None,
    )
    .unwrap();
    println!("mu 1.5: {:?} {:?} steps {}", s.status, s.x_jam_mm, s.steps);
}
