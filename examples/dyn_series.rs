use jamchart::dynamics::*;
use jamchart::model::SceneParams;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let after: f64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(0.05);
    let drive = if args.get(2).map(|s| s.as_str()) == Some("force") {
        Drive::Force
    } else {
        Drive::Motion
    };
    let p = DynamicsParams {
        after_jam_s: after,
        drive,
        ..Default::default()
    };
    let s = simulate(&SceneParams::default(), &p, Some(5e-4)).unwrap();
    println!(
        "{:?} x_jam {:?} t {:?} xs {:?} ts {:?}",
        s.status, s.x_jam_mm, s.t_jam_s, s.x_stiction_mm, s.t_stiction_s
    );
    let tj = s.t_jam_s.unwrap_or(0.0);
    for r in s
        .series
        .iter()
        .filter(|r| (r.t_s - tj).abs() < 0.06 || r.t_s < 0.01)
        .step_by(4)
    {
        println!(
            "{:.4} {:.3} {:.4} {:.4} pen {:.4} N {:.2} fB {:.2} Rn {:.2} fA {:.2}",
            r.t_s,
            r.theta_deg,
            r.x_mm,
            r.x_dot_mm_s,
            r.penetration_mm,
            r.normal_n,
            r.palm_friction_n,
            r.ground_normal_n,
            r.ground_friction_n
        );
    }
}
