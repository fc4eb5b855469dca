use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let method = if args.get(1).map(|s| s.as_str()) == Some("dopri5") {
        Method::Dopri5
    } else {
        Method::Radau5
    };
    let rtol: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1e-6);
    let k: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1e5);
    let drive = if args.get(4).map(|s| s.as_str()) == Some("force") {
        Drive::Force
    } else {
        Drive::Motion
    };
    let p = DynamicsParams {
        method,
        rtol,
        stiffness_n_per_mm_e: k,
        drive,
        ..Default::default()
    };
    let t = std::time::Instant::now();
    let s = simulate(&SceneParams::default(), &p, None).unwrap();
    let el = t.elapsed();
    println!(
        "{:?} {:?} x_jam {:?} theta {:?} t {:?} xs {:?} steps {} rej {} rhs {} jac {} disc {} check {:?} fail {:?} {:.3} ms",
        s.status,
        method,
        s.x_jam_mm,
        s.theta_jam_deg,
        s.t_jam_s,
        s.x_stiction_mm,
        s.steps,
        s.rejected_steps,
        s.rhs_evals,
        s.jacobian_evals,
        s.discarded_candidates,
        s.cross_check,
        s.failure,
        el.as_secs_f64() * 1e3
    );
}
