//! Speed of a full simulation to the jam at 1e-4 relative error in x_jam (goal:
//! < 5 ms at the defaults, < 50 ms with a contact that penetrates 1 um at 200 N), on one core.
//!
//! For each method the loosest tolerance of a ladder whose x_jam is within 1e-4 of a reference
//! (and stays so at the two next tighter rungs) is timed: the median of 21 runs, without and
//! with the verification run that `solve` does by default (which also runs the rigid contact for
//! the model's uncertainty). Run: `cargo bench --bench dynamics`; the nonsmooth method alone:
//! `cargo bench --bench dynamics -- nonsmooth`.
//!
//! First, `jamchart render` of every built-in scene against `jamchart render fig3` (goal: at most
//! 12x), whole processes, interleaved round by round so that the machine's load falls on both
//! alike: the median of the rounds' ratios. `cargo bench --bench dynamics -- render` runs only
//! that.

mod common;

use jamchart::dynamics::{Drive, DynamicsParams, DynamicsSolution, Method};
use jamchart::{Detail, JamStatus, ModelSpec, SceneParams};

const TARGET: f64 = 1e-4;
const RUNS: usize = 21;
const LADDER: [f64; 9] = [1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8];

/// One simulation through the model port: the dynamics' own answer (`Err` for invalid
/// parameters; a scene outside the model has none and is not timed here).
fn simulate(scene: &SceneParams, p: &DynamicsParams) -> jamchart::Result<DynamicsSolution> {
    let spec = ModelSpec::Dynamics {
        params: *p,
        series_dt_s: None,
    };
    match jamchart::solve(&spec, scene)?.detail {
        Detail::Dynamics(s) => Ok(*s),
        other => panic!("the simulation did not run: {other:?}"),
    }
}

fn x_jam(scene: &SceneParams, p: &DynamicsParams) -> Option<f64> {
    let s = simulate(scene, p).ok()?;
    (s.status == JamStatus::Jams)
        .then_some(s.x_jam_mm)
        .flatten()
}

fn median_ms(scene: &SceneParams, p: &DynamicsParams) -> f64 {
    1e3 * common::median_s(RUNS, || {
        std::hint::black_box(simulate(scene, p).ok());
    })
}

/// `render` of every built-in scene against `render fig3`: medians of 7 interleaved rounds.
fn render_ratio() {
    const ROUNDS: usize = 7;
    let out = tempfile::tempdir().expect("a temporary folder");
    let (mut all, mut fig3) = (Vec::new(), Vec::new());
    for _ in 0..ROUNDS {
        all.push(common::render_s(&[], out.path()));
        fig3.push(common::render_s(&["fig3"], out.path()));
    }
    let ratios = all.iter().zip(&fig3).map(|(a, b)| a / b).collect();
    println!(
        "render (every scene) {:.0} ms, render fig3 {:.1} ms: ratio {:.1}x (goal at most 12x), \
         medians of {ROUNDS} interleaved rounds, wall time",
        common::median(all) * 1e3,
        common::median(fig3) * 1e3,
        common::median(ratios)
    );
}

fn main() {
    render_ratio();
    if std::env::args().any(|a| a == "render") {
        return;
    }
    nonsmooth();
    // `cargo bench --bench dynamics -- nonsmooth` stops here.
    if std::env::args().any(|a| a == "nonsmooth") {
        return;
    }
    let scene = SceneParams::default();
    let scenarios = [
        ("defaults (k = 1e5 N/mm^2.2, ~59 um at 200 N)", 1e5),
        (
            "stiff (1 um at 200 N, k = 7.96e8 N/mm^2.2)",
            200.0 / 1e-3_f64.powf(2.2),
        ),
    ];
    println!(
        "| scenario | method | rtol | x_jam [mm] | reference | rel. error | median [ms] | with verify [ms] |"
    );
    println!("|---|---|---:|---:|---|---:|---:|---:|");
    for (name, k) in scenarios {
        let base = DynamicsParams {
            contact: jamchart::dynamics::ContactLaw {
                stiffness_n_per_mm_e: k,
                ..Default::default()
            },
            verification: jamchart::dynamics::Verification {
                verify: false,
                ..Default::default()
            },
            ..Default::default()
        };
        let reference = |m: Method| {
            x_jam(
                &scene,
                &DynamicsParams {
                    integrator: jamchart::dynamics::IntegratorSettings {
                        method: m,
                        rtol: 1e-10,
                        ..base.integrator
                    },
                    ..base
                },
            )
        };
        let (rr, rd) = (reference(Method::Radau5), reference(Method::Dopri5));
        for method in [Method::Radau5, Method::Dopri5] {
            // The other method's reference where it exists (DOPRI5 gives up on the stiff contact).
            let other = if method == Method::Radau5 {
                rd.map(|x| (Method::Dopri5, x))
                    .or(rr.map(|x| (Method::Radau5, x)))
            } else {
                rr.map(|x| (Method::Radau5, x))
            };
            let Some((ref_method, xr)) = other else {
                println!("| {name} | {} | - | no reference | | | |", method.as_str());
                continue;
            };
            let errs: Vec<Option<f64>> = LADDER
                .iter()
                .map(|&rtol| {
                    x_jam(
                        &scene,
                        &DynamicsParams {
                            integrator: jamchart::dynamics::IntegratorSettings {
                                method,
                                rtol,
                                ..base.integrator
                            },
                            ..base
                        },
                    )
                    .map(|x| (x - xr).abs() / xr)
                })
                .collect();
            let ok = |i: usize| errs.get(i).copied().flatten().is_some_and(|e| e <= TARGET);
            let Some(i) =
                (0..LADDER.len()).find(|&i| ok(i) && (i + 1..(i + 3).min(LADDER.len())).all(ok))
            else {
                println!(
                    "| {name} | {} | none reaches {TARGET:e} | | | | |",
                    method.as_str()
                );
                continue;
            };
            let p = DynamicsParams {
                integrator: jamchart::dynamics::IntegratorSettings {
                    method,
                    rtol: LADDER[i],
                    ..base.integrator
                },
                ..base
            };
            let t = median_ms(&scene, &p);
            let tv = median_ms(
                &scene,
                &DynamicsParams {
                    verification: jamchart::dynamics::Verification {
                        verify: true,
                        ..p.verification
                    },
                    ..p
                },
            );
            let x = x_jam(&scene, &p).unwrap_or(f64::NAN);
            println!(
                "| {name} | {} | {:e} | {x:.6} | {} at 1e-10 | {:.1e} | {t:.3} | {tv:.3} |",
                method.as_str(),
                LADDER[i],
                ref_method.as_str(),
                errs[i].unwrap_or(f64::NAN)
            );
        }
    }
}

/// The nonsmooth method (goal: well under 1 ms per run): the median of 21 runs at its
/// default step for several frictions and both drives, without and with the check at twice the
/// step, and how far x_jam lies from the rigid limit (motion: r/mu; force: the closed form, which
/// the disc's inertia passes at 30 deg/s). Motion drive, mu 0.15 / 0.3 / 0.45, medians of three
/// benches each, back to back on the same shared machine: before the lock-up was located inside
/// its step (0.01 deg, 4000-7300 steps) 1.32 / 1.06 / 0.75 ms, 1.99 / 1.57 / 1.13 ms verified;
/// after (0.1 deg, 420-730 steps) 0.17 / 0.14 / 0.11 ms, 0.27 / 0.22 / 0.17 ms verified: 7.0-7.7
/// times faster (6.7-7.3 verified).
fn nonsmooth() {
    println!(
        "\n| nonsmooth | mu | drive | steps | x_jam [mm] | reference [mm] | rel. | median [ms] | with verify [ms] |"
    );
    println!("|---|---:|---|---:|---:|---:|---:|---:|---:|");
    for drive in [Drive::Motion, Drive::Force] {
        for mu in [0.15, 0.3, 0.45] {
            let scene = SceneParams::default().with_mu(mu);
            let p = DynamicsParams {
                drive: jamchart::dynamics::DriveSettings {
                    mode: drive,
                    ..Default::default()
                },
                integrator: jamchart::dynamics::IntegratorSettings {
                    method: Method::Nonsmooth,
                    ..Default::default()
                },
                verification: jamchart::dynamics::Verification {
                    verify: false,
                    ..Default::default()
                },
                ..Default::default()
            };
            let s = simulate(&scene, &p).expect("valid");
            let reference = match drive {
                Drive::Motion => scene.radius_mm / mu,
                Drive::Force => jamchart::solve(&ModelSpec::Statics, &scene)
                    .expect("valid")
                    .x_jam_mm
                    .unwrap_or(f64::NAN),
            };
            let x = s.x_jam_mm.unwrap_or(f64::NAN);
            let t = median_ms(&scene, &p);
            let tv = median_ms(
                &scene,
                &DynamicsParams {
                    verification: jamchart::dynamics::Verification {
                        verify: true,
                        ..p.verification
                    },
                    ..p
                },
            );
            println!(
                "| default step {} deg | {mu} | {} | {} | {x:.4} | {reference:.4} | {:+.2e} | {t:.3} | {tv:.3} |",
                p.nonsmooth_step_deg(),
                drive.as_str(),
                s.steps,
                (x - reference) / reference
            );
        }
    }
}
