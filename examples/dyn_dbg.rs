use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let rtol: f64 = args[1].parse().unwrap();
    let k: f64 = args[2].parse().unwrap();
    let method = if args[3] == "dopri5" {
        Method::Dopri5
    } else {
        Method::Radau5
    };
    let p = DynamicsParams {
        rtol,
        method,
        stiffness_n_per_mm_e: k,
        after_jam_s: 0.0,
        ..Default::default()
    };
    let s = simulate(&SceneParams::default(), &p, Some(2e-4)).unwrap();
    println!(
        "{:?} x {:?} t {:?} sim {} steps {} disc {}",
        s.status, s.x_jam_mm, s.t_jam_s, s.simulated_s, s.steps, s.discarded_candidates
    );
    for r in s.series.iter().step_by(2).take(200) {
        println!(
            "{:.4} {:.3} {:.4} {:.4} pen {:.5} N {:.2} Rn {:.2} fA {:.2}",
            r.t_s,
            r.theta_deg,
            r.x_mm,
            r.x_dot_mm_s,
            r.penetration_mm,
            r.normal_n,
            r.ground_normal_n,
            r.ground_friction_n
        );
    }
}
