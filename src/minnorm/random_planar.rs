//! Random planar contact problems, shared by the solver tests and the benchmark (which
//! measures the exact path's agreement with clarabel on many of them).

// Through `bench_support`, which the benchmark sees too (the crate's unit tests see it as well).
use jamchart::bench_support::{
    Contact, ContactProblem, Joint, Space, Wrench, solve_clarabel, solve_program as solve,
};
use jamchart::minnorm::{ContactSolution, HoldStatus, QpSettings};
use proptest::prelude::*;

prop_compose! {
    /// A planar problem: 1-3 contacts on a circle, random normals and frictions, a random load,
    /// sometimes a moment joint and a prescribed normal push.
    pub fn planar_problem()(
        contacts in prop::collection::vec(
            (0.0..std::f64::consts::TAU, -1.2..1.2_f64, prop_oneof![1 => Just(0.0), 3 => 0.05..1.5_f64]),
            1..=3,
        ),
        radius in 1.0..100.0_f64,
        fx in -100.0..100.0_f64,
        fy in -100.0..100.0_f64,
        mz in -1.0..1.0_f64,
        joint in prop::bool::weighted(0.3),
        push in prop::option::weighted(0.2, 1.0..100.0_f64),
    ) -> ContactProblem {
        let mut cs: Vec<Contact> = contacts
            .iter()
            .map(|&(phi, tilt, mu)| {
                let (s, c) = phi.sin_cos();
                // The normal points roughly inward (to the centre), tilted by up to 1.2 rad.
                let (ts, tc) = (phi + std::f64::consts::PI + tilt).sin_cos();
                Contact::planar([radius * c, radius * s], [tc, ts], mu)
            })
            .collect();
        if let Some(n) = push {
            cs[0] = cs[0].with_normal_force(n);
        }
        ContactProblem {
            space: Space::Planar,
            contacts: cs,
            joints: if joint { vec![Joint::Moment { axis: [0.0, 0.0, 1.0] }] } else { vec![] },
            load: Wrench { force_n: [fx, fy, 0.0], moment_nmm: [0.0, 0.0, mz * 100.0 * radius] },
        }
    }
}

/// Largest load component in N (moments over the farthest contact).
pub fn load_scale(p: &ContactProblem) -> f64 {
    let r = p
        .contacts
        .iter()
        .map(|c| c.position_mm[0].hypot(c.position_mm[1]))
        .fold(1.0, f64::max);
    let f = &p.load.force_n;
    f[0].hypot(f[1])
        .max(p.load.moment_nmm[2].abs() / r)
        .max(1.0)
}

/// The problem with every friction coefficient scaled by `k`.
pub fn with_mu_scaled(p: &ContactProblem, k: f64) -> ContactProblem {
    let mut q = p.clone();
    for c in &mut q.contacts {
        c.mu *= k;
    }
    q
}

/// The exact path and clarabel on one problem, side by side.
#[derive(Debug)]
pub struct Comparison {
    pub exact: ContactSolution,
    pub clarabel: ContactSolution,
    /// The exact path's verdict with every mu scaled by 1 - 1e-4 and 1 + 1e-4: where both agree
    /// the verdict is robust, otherwise the problem sits on the held / not-held boundary.
    pub robust: Option<HoldStatus>,
    /// Largest difference of a force component when both hold, relative to the larger of the
    /// load and phi (0 otherwise).
    pub force_diff_rel: f64,
    /// (phi^2 exact - phi^2 clarabel) / phi^2 when both hold: > 0 would mean the exact path
    /// missed the minimum.
    pub objective_excess_rel: f64,
}

/// Solves `p` by both backends and compares them.
pub fn compare(p: &ContactProblem) -> Comparison {
    let settings = QpSettings::default();
    let exact = solve(p, &settings).expect("valid problem");
    let clarabel = solve_clarabel(p, &settings).expect("valid problem");
    let lo = solve(&with_mu_scaled(p, 1.0 - 1e-4), &settings)
        .expect("valid")
        .status;
    let hi = solve(&with_mu_scaled(p, 1.0 + 1e-4), &settings)
        .expect("valid")
        .status;
    let (mut force_diff_rel, mut objective_excess_rel) = (0.0, 0.0);
    if exact.status == HoldStatus::Held && clarabel.status == HoldStatus::Held {
        let scale = load_scale(p).max(exact.objective_n2.sqrt());
        for (a, b) in exact.forces.iter().zip(&clarabel.forces) {
            let d = (a.normal_n - b.normal_n)
                .abs()
                .max((a.tangential_n[0] - b.tangential_n[0]).abs());
            force_diff_rel = f64::max(force_diff_rel, d / scale);
        }
        objective_excess_rel = (exact.objective_n2 - clarabel.objective_n2)
            / clarabel.objective_n2.max(f64::MIN_POSITIVE);
    }
    Comparison {
        exact,
        clarabel,
        robust: (lo == hi).then_some(lo),
        force_diff_rel,
        objective_excess_rel,
    }
}
