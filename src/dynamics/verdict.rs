//! Why a simulation's answer is not a trusted `jams`: typed reasons with their numbers.
//!
//! Each reason states a fact about the physics or the numerics; what to do about it is the
//! caller's business (the command line turns each into advice that names its flag).

use serde::Serialize;

use crate::scene::JamStatus;

/// A reason to distrust a simulated jam, with the numbers needed to act.
///
/// JSON: the snake_case variant name under `reason`, beside its fields.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
#[allow(missing_docs)] // each variant's doc names its fields and their units
pub enum CrossCheck {
    /// The relative tolerance `rtol` is looser than `loosest`, beyond which no check can vouch
    /// for the answer.
    LooseTolerance { rtol: f64, loosest: f64 },
    /// A second run (`check`) ended with `check_status` instead of `status`.
    VerificationDisagrees {
        check: Refinement,
        status: JamStatus,
        check_status: JamStatus,
    },
    /// x_jam moved by `error_mm` (more than `allowed_rel` of x_jam) in the second run `check`.
    ErrorEstimate {
        error_mm: f64,
        allowed_rel: f64,
        check: Refinement,
    },
    /// The jam at `x_jam_mm` lies beyond the self-locking limit `x_rigid_mm` (plus the disc's
    /// coasting distance `coast_mm` and the contact's give), which no push can pass. The palm
    /// drives the disc at `geometric_speed_mm_s` at the wedge, against the stiction transition
    /// velocity `stiction_velocity_mm_s`: a palm slow against V_s lets the regularised friction
    /// slide the disc on, below the speed the jam is read at.
    PastWedge {
        x_jam_mm: f64,
        x_rigid_mm: f64,
        coast_mm: f64,
        geometric_speed_mm_s: f64,
        stiction_velocity_mm_s: f64,
    },
    /// The force-limited drive's push stayed at `push_n`, below its limit `limit_n`, while the
    /// disc stopped at `theta_deg`: nothing held the disc there.
    StoppedBelowForceLimit {
        theta_deg: f64,
        push_n: f64,
        limit_n: f64,
    },
    /// The disc stood still at `x_jam_mm` while the palm pushed with `push_n` at `theta_deg`,
    /// more than twice the `needed_n` that slides it against static friction. With the disc's
    /// geometric speed `geometric_speed_mm_s` at the jam against the stiction transition
    /// velocity `stiction_velocity_mm_s`: the regularised friction holds a disc that creeps
    /// below V_s, so a palm slow against V_s stops the disc early.
    HeldBelowSlidingPush {
        x_jam_mm: f64,
        theta_deg: f64,
        push_n: f64,
        needed_n: f64,
        geometric_speed_mm_s: f64,
        stiction_velocity_mm_s: f64,
    },
    /// The palm lifts the disc off the ground at `theta_deg` (above 90 deg its push points up):
    /// no model here represents a disc in the air. The simulation called directly says so for a
    /// start above 90 deg before any step; through the model port ([`crate::models::solve`])
    /// such a start is answered for every model by `OutsideModel::PalmLiftsDisc` first.
    LiftsOff { theta_deg: f64 },
    /// The palm lost the disc and struck it again before the jam at `x_jam_mm`: the disc was
    /// knocked ahead, and where it jams depends on a restitution and a contact stiffness nobody
    /// knows (the rigid, plastic contact says `x_jam_rigid_mm`).
    KnockedAhead { x_jam_mm: f64, x_jam_rigid_mm: f64 },
    /// The rigid contact (the nonsmooth method) answers `rigid_status` (at `x_jam_rigid_mm`,
    /// if it stops the disc) where the compliant contact says `status` (at `x_jam_mm`): e.g.
    /// a motion-driven palm started near the wedge pushes a rigid disc on to the lock-up,
    /// which the compliant contact reads as a disc that never moved.
    RigidDisagrees {
        status: JamStatus,
        x_jam_mm: Option<f64>,
        rigid_status: JamStatus,
        x_jam_rigid_mm: Option<f64>,
    },
    /// The force-driven disc had not come to rest (its speed below `rest_speed_mm_s`) when the
    /// run ended at `simulated_s`; its speed collapsed (the palm stalled) at `x_half_speed_mm`,
    /// and it was still moving.
    NotAtRest {
        x_half_speed_mm: f64,
        simulated_s: f64,
        rest_speed_mm_s: f64,
    },
    /// The compliant contact's jam at `x_jam_mm` lies more than `allowed_rel` from the rigid
    /// contact's `x_jam_rigid_mm`: the answer is the contact stiffness's (or the mass's), not the
    /// geometry's and friction's.
    ContactModelDependent {
        x_jam_mm: f64,
        x_jam_rigid_mm: f64,
        allowed_rel: f64,
    },
}

/// The second run that checks a simulation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[allow(missing_docs)] // each variant's doc names its field and its unit
pub enum Refinement {
    /// RADAU5 or DOPRI5 at a tenth of the tolerances: this relative tolerance.
    Tolerance { rtol: f64 },
    /// The nonsmooth method at twice the step (a first-order method: the difference estimates
    /// the error of the finer run): this palm turn per step in deg.
    Step { step_deg: f64 },
}

impl std::fmt::Display for Refinement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Refinement::Tolerance { rtol } => write!(f, "a second run at rtol = {rtol:e}"),
            Refinement::Step { step_deg } => {
                write!(f, "a second run at a step of {step_deg:e} deg of palm turn")
            }
        }
    }
}

impl CrossCheck {
    /// The status an answer with this reason gets.
    pub fn status(&self) -> JamStatus {
        match self {
            CrossCheck::LiftsOff { .. } | CrossCheck::KnockedAhead { .. } => {
                JamStatus::OutsideModel
            }
            _ => JamStatus::Inaccurate,
        }
    }
}

impl std::fmt::Display for CrossCheck {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            CrossCheck::LooseTolerance { rtol, loosest } => write!(
                f,
                "rtol = {rtol} is looser than {loosest}: no check can vouch for the answer"
            ),
            CrossCheck::VerificationDisagrees {
                check,
                status,
                check_status,
            } => write!(f, "{check} says {check_status} instead of {status}"),
            CrossCheck::ErrorEstimate {
                error_mm,
                allowed_rel,
                check,
            } => write!(
                f,
                "x_jam moves by {error_mm:.3e} mm (more than {allowed_rel:e} of it) in {check}"
            ),
            CrossCheck::PastWedge {
                x_jam_mm,
                x_rigid_mm,
                coast_mm,
                geometric_speed_mm_s,
                stiction_velocity_mm_s,
            } => write!(
                f,
                "x_jam = {x_jam_mm:.4} mm lies beyond the self-locking limit x_rigid = {x_rigid_mm:.4} mm \
                 that no push can pass (coasting allowance {coast_mm:.3} mm; the palm drives \
                 the disc at {geometric_speed_mm_s:.3} mm/s there, against a stiction \
                 transition velocity of {stiction_velocity_mm_s} mm/s)"
            ),
            CrossCheck::StoppedBelowForceLimit {
                theta_deg,
                push_n,
                limit_n,
            } => write!(
                f,
                "the disc stopped at {theta_deg:.3} deg while the drive's push stayed at \
                 {push_n:.2} N, below its limit {limit_n:.2} N"
            ),
            CrossCheck::HeldBelowSlidingPush {
                x_jam_mm,
                theta_deg,
                push_n,
                needed_n,
                geometric_speed_mm_s,
                stiction_velocity_mm_s,
            } => write!(
                f,
                "the disc stood still at {x_jam_mm:.4} mm while the palm pushed with \
                 {push_n:.2} N at {theta_deg:.3} deg, more than twice the {needed_n:.2} N that \
                 slides it (the palm drives the disc at {geometric_speed_mm_s:.3} mm/s there, \
                 against a stiction transition velocity of {stiction_velocity_mm_s} mm/s)"
            ),
            CrossCheck::LiftsOff { theta_deg } => write!(
                f,
                "the palm lifts the disc off the ground at {theta_deg:.3} deg: above 90 deg its \
                 push points upwards, and no model here represents a disc in the air"
            ),
            CrossCheck::KnockedAhead {
                x_jam_mm,
                x_jam_rigid_mm,
            } => write!(
                f,
                "the palm lost the disc and struck it again before the jam at {x_jam_mm:.3} mm: \
                 the disc was knocked ahead, and where it jams depends on the contact's \
                 stiffness and restitution (a rigid, plastic contact jams at {x_jam_rigid_mm:.3} mm)"
            ),
            CrossCheck::RigidDisagrees {
                status,
                x_jam_mm,
                rigid_status,
                x_jam_rigid_mm,
            } => {
                let at = |x: Option<f64>| x.map(|x| format!(" at {x:.3} mm")).unwrap_or_default();
                write!(
                    f,
                    "the rigid contact says {rigid_status}{} where the compliant contact says \
                     {status}{}",
                    at(x_jam_rigid_mm),
                    at(x_jam_mm)
                )
            }
            CrossCheck::NotAtRest {
                x_half_speed_mm,
                simulated_s,
                rest_speed_mm_s,
            } => write!(
                f,
                "the disc's speed collapsed at {x_half_speed_mm:.3} mm (the palm stalled) but it \
                 had not come to rest (below {rest_speed_mm_s} mm/s) when the run ended at \
                 t = {simulated_s:.4} s"
            ),
            CrossCheck::ContactModelDependent {
                x_jam_mm,
                x_jam_rigid_mm,
                allowed_rel,
            } => write!(
                f,
                "x_jam = {x_jam_mm:.3} mm lies {:.1} % from the rigid contact's {x_jam_rigid_mm:.3} mm \
                 (more than {:.1} %): the compliant contact, not the geometry and friction, sets \
                 the answer",
                100.0 * (x_jam_mm - x_jam_rigid_mm) / x_jam_rigid_mm,
                100.0 * allowed_rel
            ),
        }
    }
}
