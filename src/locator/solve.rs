//! The verdict for one load: the exact feasibility test, the minimum-norm flank forces from the
//! general contact solver, and the flags.

use serde::Serialize;

use super::exact::{self, Capacity, FailureMode, LoadLine};
use super::optimum::{self, Optimum};
use super::params::{Flank, LocatorParams, Rotation};
use crate::error::Result;
use crate::minnorm::{self, Contact, ContactProblem, HoldStatus, Joint, QpSettings, Space, Wrench};

/// A flank's normal force is "zero" below this fraction of the largest load (W or P): far
/// above both solvers' decision levels (1e-10 exact path, 1e-8 clarabel), far below any force
/// a fixture designer reads.
pub const LIFT_OFF_RTOL: f64 = 1e-6;

/// The disc's radius in the contact problem, mm. It cancels: every moment about the centre is
/// r times a force, and the forces do not depend on it.
const UNIT_RADIUS_MM: f64 = 1.0;

/// What the V does with the part under the given load, in the order it is decided.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The V self-locks: every load is held, the part can jam and needs a pull to come out;
    /// the minimum-norm forces are only a lower bound.
    Wedged,
    /// No equilibrium: the part leaves the V as `mode` says.
    Slips {
        /// How it leaves.
        mode: FailureMode,
    },
    /// Held, but `flank`'s normal force is zero at the minimum-norm solution (to
    /// `LIFT_OFF_RTOL` of the largest load): the part rests on one flank.
    LiftsOff {
        /// The flank that carries nothing.
        flank: Flank,
    },
    /// Weight and load cancel (force and moment, to `LIFT_OFF_RTOL` of the larger): nothing
    /// presses the disc into the V, both flank forces are zero, and any further lift takes it
    /// out. Not `held`: the V does nothing here.
    Unloaded,
    /// Held on both flanks.
    Held,
}

impl Verdict {
    /// `wedged`, `slips`, `lifts_off`, `unloaded` or `held`.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Wedged => "wedged",
            Verdict::Slips { .. } => "slips",
            Verdict::LiftsOff { .. } => "lifts_off",
            Verdict::Unloaded => "unloaded",
            Verdict::Held => "held",
        }
    }

    /// Whether the part stays in the V (held, lifts off, unloaded or wedged).
    pub fn holds(self) -> bool {
        !matches!(self, Verdict::Slips { .. })
    }
}

/// One flank's minimum-norm contact force.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FlankForce {
    /// Which flank.
    pub flank: Flank,
    /// Normal force in N (>= 0: the flank pushes).
    pub normal_n: f64,
    /// Friction force in N, positive up the flank (away from the vertex).
    pub tangential_up_n: f64,
    /// The force's x component in N.
    pub fx_n: f64,
    /// The force's y component in N.
    pub fy_n: f64,
    /// Friction utilisation |T| / (mu N): 1 at the point of slipping (0 where mu = 0).
    pub utilisation: f64,
}

/// A verdict by its name alone (`Verdict::as_str`).
fn verdict_name<S: serde::Serializer>(v: &Verdict, s: S) -> std::result::Result<S::Ok, S::Error> {
    s.serialize_str(v.as_str())
}

/// Everything the locator model says about one V and load.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LocatorSolution {
    /// The verdict under the given load (serialised by its name: `held`, `slips`, ...).
    #[serde(serialize_with = "verdict_name")]
    pub verdict: Verdict,
    /// The V self-locks (frictional force closure of the two contacts).
    pub self_locking: bool,
    /// Held only because the V self-locks: just below the locking friction it would drop it.
    pub locking_needed: bool,
    /// Held only because of friction: with mu = 0 on both flanks it would not be.
    pub friction_held: bool,
    /// Minimum-norm forces, left then right (None when there is no equilibrium).
    pub forces: Option<[FlankForce; 2]>,
    /// Holding capacity in the load's direction (and at its point).
    pub capacity: Capacity,
    /// The balanced optimum included angle for this load, flank tilt and friction.
    pub optimum: Optimum,
}

/// Verdict, forces, capacity and optimum for `p` (validated here).
pub fn solve(p: &LocatorParams) -> Result<LocatorSolution> {
    p.validate()?;
    let self_locking = exact::self_locking(p);
    let held = exact::held_at(p, p.load_n);
    let scale = p.weight_n().max(p.load_n);
    let unloaded = net_load_is_zero(p, scale);
    let forces = match held {
        // No net load: the minimum-norm forces are zero (the solver reports no verdict for a
        // zero right-hand side, which printed "no equilibrium" beside `held`).
        Ok(()) if unloaded => Some(zero_forces()),
        Ok(()) => min_norm_forces(p, &QpSettings::default())?,
        Err(_) => None,
    };
    let verdict = match (self_locking, held, &forces) {
        (true, _, _) => Verdict::Wedged,
        (false, Err(mode), _) => Verdict::Slips { mode },
        // Zero forces on both flanks: neither held nor a lift-off from one of them.
        (false, Ok(()), Some(_)) if unloaded => Verdict::Unloaded,
        (false, Ok(()), Some(f)) => Flank::BOTH
            .into_iter()
            .find(|fl| f[fl.index()].normal_n <= LIFT_OFF_RTOL * scale)
            .map_or(Verdict::Held, |flank| Verdict::LiftsOff { flank }),
        // The general solver disagrees only at the boundary, to its tolerance: held there.
        (false, Ok(()), None) => Verdict::Held,
    };
    let holds = verdict.holds();
    let frictionless = p.with_mu(0.0);
    let friction_held = holds && exact::held_at(&frictionless, p.load_n).is_err();
    let locking_needed =
        self_locking && exact::held_at(&optimum::just_unlocked(p), p.load_n).is_err();
    Ok(LocatorSolution {
        verdict,
        self_locking,
        locking_needed,
        friction_held,
        forces,
        capacity: exact::capacity(p),
        optimum: optimum::optimum(p),
    })
}

/// Whether weight and load cancel (force and moment about the centre, relative to `scale` in
/// N and N mm at the unit radius, to [`LIFT_OFF_RTOL`]).
fn net_load_is_zero(p: &LocatorParams, scale: f64) -> bool {
    let w = contact_problem(p).load;
    let tol = LIFT_OFF_RTOL * scale;
    w.force_n.iter().all(|c| c.abs() <= tol)
        && w.moment_nmm.iter().all(|c| c.abs() <= tol * UNIT_RADIUS_MM)
}

/// Both flanks carrying nothing.
fn zero_forces() -> [FlankForce; 2] {
    Flank::BOTH.map(|flank| FlankForce {
        flank,
        normal_n: 0.0,
        tangential_up_n: 0.0,
        fx_n: 0.0,
        fy_n: 0.0,
        utilisation: 0.0,
    })
}

/// The V as a [`ContactProblem`]: contacts at -r n_i, weight and load as one wrench, and a
/// moment joint when rotation is blocked.
pub fn contact_problem(p: &LocatorParams) -> ContactProblem {
    let f = p.frame();
    let r = UNIT_RADIUS_MM;
    let contacts = Flank::BOTH
        .iter()
        .map(|fl| {
            let n = f.n[fl.index()];
            Contact::planar([-r * n[0], -r * n[1]], n, p.mu()[fl.index()])
        })
        .collect();
    let line = LoadLine::new(p);
    let phi = p.load_angle_deg.to_radians();
    let at = p.load_at_rim_deg.map_or([0.0; 3], |psi| {
        let (s, c) = psi.to_radians().sin_cos();
        [r * c, r * s, 0.0]
    });
    let load = Wrench::force_at([0.0; 3], [0.0, -line.q0[1], 0.0]).plus(Wrench::force_at(
        at,
        [p.load_n * phi.cos(), p.load_n * phi.sin(), 0.0],
    ));
    let joints = match p.rotation {
        Rotation::Free => Vec::new(),
        Rotation::Blocked => vec![Joint::Moment {
            axis: [0.0, 0.0, 1.0],
        }],
    };
    ContactProblem {
        space: Space::Planar,
        contacts,
        joints,
        load,
    }
}

/// The minimum-norm flank forces by the general contact solver (its exact path where
/// `settings.fast_path`, clarabel otherwise); None when it finds no equilibrium.
pub fn min_norm_forces(
    p: &LocatorParams,
    settings: &QpSettings,
) -> Result<Option<[FlankForce; 2]>> {
    // The solver decides to tolerances of order one newton: loads of 9e307 N or weights of
    // 1e-300 N are solved at unit scale and the forces scaled back (the minimum-norm forces
    // are linear in the load). A power of two, so that both scalings are exact.
    let e = p
        .weight_n()
        .max(p.load_n)
        .log2()
        .round()
        .clamp(-1022.0, 1023.0) as i32;
    let (down, up_scale) = (2f64.powi(-e), 2f64.powi(e));
    let mut problem = contact_problem(p);
    let load = &mut problem.load;
    for c in load.force_n.iter_mut().chain(load.moment_nmm.iter_mut()) {
        *c *= down;
    }
    let sol = minnorm::solve(&problem, settings)?;
    if sol.status != HoldStatus::Held {
        return Ok(None);
    }
    let f = p.frame();
    Ok(Some(std::array::from_fn(|i| {
        let c = &sol.forces[i];
        // The solver's tangent is z x n: up the left flank, down the right one.
        let up = if i == 0 { 1.0 } else { -1.0 };
        let (n, u) = (f.n[i], f.u[i]);
        let tangential_up_n = up * c.tangential_n[0] * up_scale;
        let normal_n = c.normal_n * up_scale;
        FlankForce {
            flank: Flank::BOTH[i],
            normal_n,
            tangential_up_n,
            fx_n: normal_n * n[0] + tangential_up_n * u[0],
            fy_n: normal_n * n[1] + tangential_up_n * u[1],
            utilisation: c.utilisation,
        }
    })))
}
