//! The palm's thickness (a scene parameter declared once, honoured by every model): the palm's face
//! lies h off the hinge line (`palm_offset_mm`). The forces keep their directions, so theta_jam
//! does not change and the disc sits h / sin(theta) further out (derivation in `src/statics.rs`).
//! Every model honours it; the closed form is the oracle.

use jamchart::dynamics::{DynamicsParams, Method};
use jamchart::{JamStatus, SceneParams};

use crate::common::PAPER_ADAMS_X_JAM_MM_MU_0_4;
use crate::common::port::{min_norm, simulate, statics};

fn with_offset(h: f64) -> SceneParams {
    SceneParams {
        palm_offset_mm: h,
        ..Default::default()
    }
}

/// The figures: mu 0.4, h = 0.5 mm puts the rigid limit at 25.725 mm, and the paper's
/// Adams reading with its 1 mm bars (25.58 mm) lies between 25.0 (h = 0) and that.
#[test]
fn half_a_millimetre_moves_the_rigid_limit_to_25_725_mm() {
    let thin = statics(&with_offset(0.0));
    let thick = statics(&with_offset(0.5));
    let x0 = thin.x_rigid_mm.unwrap();
    let x1 = thick.x_rigid_mm.unwrap();
    assert!((x0 - 25.0).abs() < 1e-9, "{x0}");
    assert!((x1 - 25.725).abs() < 5e-4, "{x1}");
    let paper = PAPER_ADAMS_X_JAM_MM_MU_0_4;
    assert!(x0 < paper && paper < x1, "{x0} < {paper} < {x1}");
    // theta_jam does not move; x_jam moves by h / sin(theta_jam).
    let (t0, t1) = (thin.theta_jam_deg.unwrap(), thick.theta_jam_deg.unwrap());
    assert_eq!(t0, t1);
    let shift = 0.5 / t0.to_radians().sin();
    let dx = thick.x_jam_mm.unwrap() - thin.x_jam_mm.unwrap();
    assert!(
        (dx - shift).abs() < 1e-12 * shift.max(1.0),
        "{dx} vs {shift}"
    );
}

/// The min-norm model solves the same forces at the same angles, so it agrees with the closed
/// form for any offset, in theta and in x.
#[test]
fn min_norm_agrees_with_the_closed_form_for_any_offset() {
    for (mu, h, f) in [(0.4, 0.5, 200.0), (0.15, 2.0, 50.0), (0.6, 0.1, 1000.0)] {
        let p = SceneParams {
            force_n: f,
            palm_offset_mm: h,
            ..SceneParams::default().with_mu(mu)
        };
        let cf = statics(&p);
        let mn = min_norm(&p, &Default::default()).unwrap();
        assert_eq!(mn.status, cf.status, "mu {mu} h {h}");
        let (xc, xm) = (cf.x_jam_mm.unwrap(), mn.x_jam_mm.unwrap());
        assert!((xc - xm).abs() < 1e-6 * xc, "mu {mu} h {h}: {xc} vs {xm}");
    }
}

/// The rigid simulation (nonsmooth, motion drive) locks up at the offset's rigid limit, and the
/// compliant one lies short of it by its contact's compliance, as with no offset.
#[test]
fn the_simulations_jam_at_the_offset_rigid_limit() {
    let scene = with_offset(0.5);
    let x_rigid = statics(&scene).x_rigid_mm.unwrap();
    let mut rigid = DynamicsParams::default();
    rigid.integrator.method = Method::Nonsmooth;
    let ns = simulate(&scene, &rigid, None).unwrap();
    assert_eq!(ns.status, JamStatus::Jams, "{ns:?}");
    let x = ns.x_jam_mm.unwrap();
    assert!((x - x_rigid).abs() < 1e-3 * x_rigid, "{x} vs {x_rigid}");
    let radau = simulate(&scene, &DynamicsParams::default(), None).unwrap();
    let xr = radau.x_jam_mm.unwrap();
    assert!(xr < x_rigid && xr > 0.98 * x_rigid, "{xr} vs {x_rigid}");
}

/// The palm's reach is judged where the disc touches it, s_B = x - h tan(theta/2): a jam whose
/// disc position lies past the palm's end can still touch the palm.
#[test]
fn reach_is_judged_at_the_contact_on_the_palm() {
    let mut p = with_offset(3.0);
    let s = statics(&p);
    let (x, theta) = (s.x_jam_mm.unwrap(), s.theta_jam_deg.unwrap().to_radians());
    let s_b = x - 3.0 * (0.5 * theta).tan();
    assert!((p.contact_distance_mm(theta) - s_b).abs() < 1e-9);
    // A palm ending between s_B and x still reaches the jam.
    p.palm_length_mm = 0.5 * (s_b + x);
    assert_eq!(statics(&p).status, JamStatus::Jams);
    let mn = min_norm(&p, &Default::default()).unwrap();
    assert_eq!(mn.status, JamStatus::Jams);
    // One shorter than s_B does not.
    p.palm_length_mm = s_b - 0.01;
    assert_eq!(statics(&p).status, JamStatus::BeyondReach);
    let mn = min_norm(&p, &Default::default()).unwrap();
    assert_eq!(mn.status, JamStatus::BeyondReach);
    // The reach angle inverts s_B.
    let reach = p.reach_angle();
    assert!((p.contact_distance_mm(reach) - p.palm_length_mm).abs() < 1e-9);
}

/// A sweep over the offset is an axis like any scene parameter, through the declaration.
#[test]
fn the_offset_is_a_sweep_axis_and_a_flag() {
    let dir = tempfile::tempdir().unwrap();
    let bin = env!("CARGO_BIN_EXE_jamchart");
    let o = std::process::Command::new(bin)
        .current_dir(dir.path())
        .args(["sweep", "palm_offset_mm=0:1:5", "--format", "svg"])
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let csv = std::fs::read_to_string(dir.path().join("out/sweep_palm_offset_mm.csv")).unwrap();
    assert!(csv.lines().count() >= 6, "{csv}");
    let o = std::process::Command::new(bin)
        .args(["solve", "--palm-offset", "0.5", "--format", "json"])
        .output()
        .unwrap();
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["inputs"]["palm_offset_mm"], 0.5);
    let x = v["results"][0]["x_rigid_mm"].as_f64().unwrap();
    assert!((x - 25.725).abs() < 5e-4, "{x}");
}
