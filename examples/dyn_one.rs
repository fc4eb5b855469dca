use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let mu: f64 = a[1].parse().unwrap();
    let k: f64 = a[2].parse().unwrap();
    let drive = if a[3] == "force" {
        Drive::Force
    } else {
        Drive::Motion
    };
    let m: f64 = a[4].parse().unwrap();
    let w: f64 = a[5].parse().unwrap();
    let method = if a[6] == "dopri5" {
        Method::Dopri5
    } else {
        Method::Radau5
    };
    let sc = SceneParams {
        mass_kg: m,
        ..SceneParams::default().with_mu(mu)
    };
    for rtol in a[7].split(',').map(|s| s.parse::<f64>().unwrap()) {
        let p = DynamicsParams {
            stiffness_n_per_mm_e: k,
            drive,
            omega_deg_s: w,
            rtol,
            method,
            ..Default::default()
        };
        let t = std::time::Instant::now();
        let s = simulate(&sc, &p, None).unwrap();
        println!(
            "{rtol:e}: {:?} x {:?} th {:?} t {:?} steps {} rej {} disc {} {:.2} ms",
            s.status,
            s.x_jam_mm,
            s.theta_jam_deg,
            s.t_jam_s,
            s.steps,
            s.rejected_steps,
            s.discarded_candidates,
            t.elapsed().as_secs_f64() * 1e3
        );
    }
}
