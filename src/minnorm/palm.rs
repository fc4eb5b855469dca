//! The palm scene as a contact problem, in two formulations, and theta_jam by bracketing and
//! bisection on the held / not-held boundary. The physics is derived in the module docs of
//! [`crate::minnorm`].

use serde::{Deserialize, Serialize};

use super::contact::{Contact, ContactProblem, Joint, Space, Wrench};
use super::qp::{self, Backend, ContactSolution, HoldStatus, QpSettings};
use crate::error::{Error, Result};
use crate::model::{JamStatus, SceneParams, disc_position_mm, palm_angle_at};

/// How the disc's moment is carried.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Formulation {
    /// The paper's: contact A at the ground; the disc rides a translational joint that carries
    /// the moment; the palm's push is a known load on the edge of its friction cone, and the
    /// closing palm blocks the disc's way back to the hinge (a frictionless one-way stop along +X).
    Translational,
    /// Beyond the paper: the disc may rotate; contacts at A and at the palm B, whose normal push
    /// F cos(atan mu_palm) is given and whose friction is unknown. Rolling is possible.
    Rolling,
}

impl Formulation {
    /// The spelling used in JSON, TOML and on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            Formulation::Translational => "translational",
            Formulation::Rolling => "rolling",
        }
    }

    /// Names of the contacts, in the order of [`palm_problem`]'s contacts.
    pub fn contact_names(self) -> &'static [&'static str] {
        match self {
            Formulation::Translational => &["A (ground)", "B (palm blocks the way back)"],
            Formulation::Rolling => &["A (ground)", "B (palm)"],
        }
    }
}

/// Settings of the minimum-norm model (TOML section `[min_norm]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MinNormSettings {
    /// How the disc's moment is carried: "translational" (the paper's) or "rolling"
    /// (default: translational).
    pub formulation: Formulation,
    /// Width in rad at which the bisection on the held / not-held boundary stops
    /// (default: 1e-9).
    pub bisection_tol_rad: f64,
    /// The program's settings (section `[min_norm.qp]`).
    pub qp: QpSettings,
}

impl Default for MinNormSettings {
    fn default() -> Self {
        MinNormSettings {
            formulation: Formulation::Translational,
            bisection_tol_rad: 1e-9,
            qp: QpSettings::default(),
        }
    }
}

impl MinNormSettings {
    /// Checks every field; the error names the TOML key and the value.
    pub fn validate(&self) -> Result<()> {
        let t = self.bisection_tol_rad;
        // 1e-15 rad: below it the bisection of an angle of order one stalls in f64.
        if !(t.is_finite() && (1e-15..=0.1).contains(&t)) {
            return Err(Error::invalid(
                "min_norm.bisection_tol_rad",
                t,
                "the bisection tolerance lies in [1e-15, 0.1] rad, e.g. 1e-9",
            ));
        }
        self.qp.validate()
    }
}

/// The contact problem of the palm scene at palm angle `theta` (rad), in a frame at the disc's
/// centre (so lever arms are r, whatever x), lengths in mm, forces in N.
pub fn palm_problem(p: &SceneParams, theta: f64, formulation: Formulation) -> ContactProblem {
    let r = p.radius_mm;
    let (s, c) = theta.sin_cos();
    // Inward normal at the palm contact B and the unit vector along the palm (away from the hinge).
    let n_b = [s, -c];
    let u = [c, s];
    let b = [-r * s, r * c];
    let ground = Contact::planar([0.0, -r], [0.0, 1.0], p.mu_ground);
    let weight = Wrench::force_at([0.0; 3], [0.0, -p.weight_n(), 0.0]);
    let (sa, ca) = p.alpha_palm().sin_cos();
    match formulation {
        Formulation::Translational => {
            // The sliding palm's push on the edge of its cone; its friction points to the hinge.
            let push = [
                p.force_n * (ca * n_b[0] - sa * u[0]),
                p.force_n * (ca * n_b[1] - sa * u[1]),
                0.0,
            ];
            // The palm closes, so the disc cannot move back towards the hinge: a frictionless
            // one-way stop along the joint's axis (it carries no weight and no friction).
            let way_back = Contact::planar(b, [1.0, 0.0], 0.0);
            ContactProblem {
                space: Space::Planar,
                contacts: vec![ground, way_back],
                joints: vec![Joint::Moment {
                    axis: [0.0, 0.0, 1.0],
                }],
                load: weight.plus(Wrench::force_at([b[0], b[1], 0.0], push)),
            }
        }
        Formulation::Rolling => ContactProblem {
            space: Space::Planar,
            contacts: vec![
                ground,
                Contact::planar(b, n_b, p.mu_palm).with_normal_force(p.force_n * ca),
            ],
            joints: Vec::new(),
            load: weight,
        },
    }
}

/// The minimum-norm answer for the palm scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PalmSolution {
    /// Outcome, with the statics' meanings.
    pub status: JamStatus,
    /// Palm angle at the jam in degrees: the held end of the final bisection bracket (the start
    /// angle if jammed at start; None if it never jams or the jam is beyond reach).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm, r cot(theta_jam/2).
    pub x_jam_mm: Option<f64>,
    /// The formulation solved.
    pub formulation: Formulation,
    /// Minimum-norm programs solved.
    pub solves: u32,
    /// Solver iterations summed over all solves (see [`ContactSolution::iterations`]).
    pub iterations: u32,
    /// Solves that ended undetermined (counted as not held by the bisection).
    pub undetermined_solves: u32,
    /// The solver that answered the last solve (the exact path unless it is switched off).
    pub backend: Backend,
    /// The held solution at theta_jam (the contact forces at the jam), if the disc jams or is
    /// jammed at start.
    pub at_jam: Option<ContactSolution>,
}

/// The sideways part of the push, F sin(theta), as a fraction of the largest load (F or m g)
/// below which the search for a held angle stops: there a jam cannot be told from the solvers'
/// tolerance (1e-8 of the largest load for clarabel, 1e-10 for the exact path; ten times
/// clarabel's). The smallest angle searched is asin(1e-7 max(F, m g) / F) >= 1e-7 rad
/// (x > 2e7 r); a jam further out is reported as never_jams (the statics call it beyond_reach;
/// only mu below about 1e-7 max(1, m g / F) gets there).
pub const FLOOR_PUSH_FRACTION: f64 = 1e-7;

/// The smallest palm angle searched, in rad; see [`FLOOR_PUSH_FRACTION`].
pub fn theta_floor_rad(p: &SceneParams) -> f64 {
    (FLOOR_PUSH_FRACTION * p.force_n.max(p.weight_n()) / p.force_n)
        .min(1.0)
        .asin()
}

struct Search<'a> {
    p: &'a SceneParams,
    s: &'a MinNormSettings,
    out: PalmSolution,
}

impl Search<'_> {
    fn eval(&mut self, theta: f64) -> Result<Option<ContactSolution>> {
        let sol = qp::solve(&palm_problem(self.p, theta, self.s.formulation), &self.s.qp)?;
        self.out.solves += 1;
        self.out.iterations += sol.iterations;
        self.out.backend = sol.backend;
        match sol.status {
            HoldStatus::Held => Ok(Some(sol)),
            HoldStatus::NotHeld => Ok(None),
            HoldStatus::Undetermined => {
                self.out.undetermined_solves += 1;
                Ok(None)
            }
        }
    }

    fn jam_at(mut self, status: JamStatus, theta: f64, sol: ContactSolution) -> PalmSolution {
        self.out.status = status;
        self.out.theta_jam_deg = Some(theta.to_degrees());
        let x = disc_position_mm(self.p.radius_mm, theta);
        self.out.x_jam_mm = x.is_finite().then_some(x);
        self.out.at_jam = Some(sol);
        self.out
    }
}

/// Solves the palm scene by the minimum-norm model. The held angles below the start are one
/// interval, [0, theta_jam] (module docs), so: held at the start angle -> jammed at start; held
/// at the palm's reach (x = palm length) -> bisect [reach, start] to `bisection_tol_rad`;
/// otherwise held at [`theta_floor_rad`] -> beyond reach, else never jams. `p` and `s` are
/// validated here.
pub fn solve(p: &SceneParams, s: &MinNormSettings) -> Result<PalmSolution> {
    p.validate()?;
    s.validate()?;
    let mut search = Search {
        p,
        s,
        out: PalmSolution {
            status: JamStatus::NeverJams,
            theta_jam_deg: None,
            x_jam_mm: None,
            formulation: s.formulation,
            solves: 0,
            iterations: 0,
            undetermined_solves: 0,
            backend: Backend::Clarabel,
            at_jam: None,
        },
    };
    let start = p.start_angle_deg.to_radians();
    if let Some(sol) = search.eval(start)? {
        return Ok(search.jam_at(JamStatus::JammedAtStart, start, sol));
    }
    let reach = palm_angle_at(p.radius_mm, p.palm_length_mm);
    if reach < start
        && let Some(mut held) = search.eval(reach)?
    {
        let (mut lo, mut hi) = (reach, start);
        while hi - lo > s.bisection_tol_rad {
            let mid = 0.5 * (lo + hi);
            match search.eval(mid)? {
                Some(sol) => {
                    lo = mid;
                    held = sol;
                }
                None => hi = mid,
            }
        }
        return Ok(search.jam_at(JamStatus::Jams, lo, held));
    }
    // Not held within reach: theta_jam lies below it. Only the status is wanted, and one solve
    // at the floor tells it (below the floor "held" is a decision at the solvers' tolerance).
    let floor = theta_floor_rad(p);
    if floor < reach.min(start) && search.eval(floor)?.is_some() {
        search.out.status = JamStatus::BeyondReach;
    }
    Ok(search.out)
}

/// The palm scene at one angle `theta_deg` solved by clarabel, with its convergence trace
/// (the data of the paper's Fig. 4).
pub fn trace_at(p: &SceneParams, theta_deg: f64, s: &MinNormSettings) -> Result<ContactSolution> {
    p.validate()?;
    s.validate()?;
    qp::solve_clarabel(
        &palm_problem(p, theta_deg.to_radians(), s.formulation),
        &s.qp,
    )
}
