//! The palm scene as a contact problem, in two formulations, and theta_jam by bracketing and
//! bisection on the held / not-held boundary. The physics is derived in the module docs of
//! [`crate::minnorm`].

use serde::Serialize;

use super::contact::{Contact, ContactProblem, Joint, Space, Wrench};
use super::qp::{self, Backend, ContactSolution, HoldStatus, QpSettings};
use crate::error::Result;
use crate::scene::{JamStatus, SceneParams};
use crate::settings::Check;

choice! {
    /// How the disc's moment is carried.
    pub enum Formulation {
        /// The paper's: contact A at the ground; the disc rides a translational joint that
        /// carries the moment; the palm's push is a known load on the edge of its friction cone,
        /// and the closing palm blocks the disc's way back to the hinge (a frictionless one-way
        /// stop along +X).
        Translational = "translational",
        /// Beyond the paper: the disc may rotate; contacts at A and at the palm B, whose normal
        /// push F cos(atan mu_palm) is given and whose friction is unknown. Rolling is possible.
        Rolling = "rolling",
    }
}

impl Formulation {
    /// Whether this formulation holds the disc at some palm angle > 0: with any friction when
    /// a joint carries the moment; with friction at both contacts when the disc may roll
    /// (held iff tan(theta/2) <= min(mu_p, mu_g (1 + m g / N)), module docs).
    pub fn can_jam(self, p: &SceneParams) -> bool {
        match self {
            Formulation::Translational => p.mu_ground + p.mu_palm > 0.0,
            Formulation::Rolling => p.mu_ground > 0.0 && p.mu_palm > 0.0,
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

settings! {
    /// Settings of the minimum-norm model.
    section = "min_norm";
    pub struct MinNormSettings {
        /// Min-norm formulation: how the disc's moment is carried.
        ///
        /// translational (the paper's): the disc rides a translational joint that carries the
        /// moment; rolling: the disc may rotate and friction at the ground and the palm carries it.
        formulation: Formulation = Formulation::Translational, flag: Some("formulation"),
            value_name: "FORMULATION";
        /// Width at which the bisection on the held / not-held boundary stops.
        // Not below 1e-15 rad: there the bisection of an angle of order one stalls in f64.
        bisection_tol_rad: f64 = 1e-9, quantity: "bisection tolerance", unit: "rad",
            check: Check::Closed(1e-15, 0.1);
        /// The program's settings (section `[min_norm.qp]`).
        qp: QpSettings = QpSettings::default();
    }
}

impl MinNormSettings {
    /// Checks every field; the error names the TOML key and the value.
    pub fn validate(&self) -> Result<()> {
        self.check_declared()
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
    /// Why the answer is `inaccurate`, if it is.
    pub cross_check: Option<MinNormCheck>,
}

/// How far past its friction cone a held solution may load a contact, relative:
/// |f_t| <= (1 + CONE_EXCESS) mu f_n. The bisection resolves theta_jam to 1e-8 of itself
/// (`RELATIVE_RESOLUTION`), and a cone overused by a fraction d holds the disc past its jam by
/// about that fraction of the angle: clarabel at its default tolerances overused the palm's
/// cone by 4.8e-5 at a push of 1/2000 of the weight (rolling) and landed 5.9e-5 (0.0026 deg)
/// off, and by a factor 4.7 at mu = 1e-9 (`clarabel_overusing_a_friction_cone_is_flagged`).
/// The exact path stays within 7e-6 (at mu = 1e-9, where its jam is 3.6e-6 off the closed
/// form).
pub(crate) const CONE_EXCESS: f64 = 1e-5;

/// Why a min-norm answer is not a trusted jam: typed reasons with their numbers.
///
/// JSON: the snake_case variant name under `reason`, beside its fields.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "reason", rename_all = "snake_case")]
#[allow(missing_docs)] // each variant's doc names its fields and their units
pub enum MinNormCheck {
    /// The held solution at the jam loads contact `contact` (index in the formulation's
    /// contacts) to `utilisation` of its friction cone, more than 1 + `allowed_excess`: the
    /// solver `backend` met its feasibility tolerance with forces outside the cone, so the
    /// disc counts as held past where it slips.
    ConeOverused {
        contact: usize,
        utilisation: f64,
        allowed_excess: f64,
        backend: Backend,
    },
}

impl std::fmt::Display for MinNormCheck {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            MinNormCheck::ConeOverused {
                contact,
                utilisation,
                allowed_excess,
                backend,
            } => write!(
                f,
                "the held forces at the jam load contact {} to {} of its friction cone (more \
                 than 1 + {allowed_excess:e}): {} let them leave the cone within its tolerance",
                contact + 1,
                // A cone of mu near 0 makes any tangential force an unbounded multiple of it.
                match utilisation.is_finite() {
                    true => crate::numbers::fixed(utilisation, 6),
                    false => "an unbounded multiple".into(),
                },
                match backend {
                    Backend::Exact => "the exact path",
                    Backend::Clarabel => "clarabel",
                }
            ),
        }
    }
}

/// Below 0.1 rad the bisection stops at this fraction of the angle instead of
/// `bisection_tol_rad` (default 1e-9 rad, itself 1e-8 of 0.1 rad): the agreement with the
/// closed form stays within 1e-6 relative for any mu > 0.
pub(crate) const RELATIVE_RESOLUTION: f64 = 1e-8;

/// A search for theta_jam: the scene, the settings, the answer so far and the held angles met.
pub(super) struct Search<'a> {
    pub(super) p: &'a SceneParams,
    pub(super) s: &'a MinNormSettings,
    out: PalmSolution,
    /// The last two held angles solved and their friction utilisation.
    pub(super) trail: HeldTrail,
}

/// The last two held angles of a search, latest first, each with the largest friction
/// utilisation |f_t| / (mu f_n) of its contacts: the palm scene is held up to theta_jam, where
/// a cone binds (utilisation 1, module docs), so the two give a secant estimate of theta_jam
/// that a column's next cell starts from ([`super::column`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct HeldTrail {
    pub(super) points: [Option<(f64, f64)>; 2],
}

impl HeldTrail {
    /// The largest friction utilisation of a held solution.
    pub(super) fn utilisation(sol: &ContactSolution) -> f64 {
        sol.forces.iter().map(|f| f.utilisation).fold(0.0, f64::max)
    }

    fn push(&mut self, theta: f64, utilisation: f64) {
        self.points = [Some((theta, utilisation)), self.points[0]];
    }

    /// d(utilisation)/d(theta) in 1/rad by the secant of the two points; None unless positive
    /// and finite (utilisation grows towards the jam).
    pub(super) fn slope(&self) -> Option<f64> {
        let [Some((t1, u1)), Some((t0, u0))] = self.points else {
            return None;
        };
        let slope = (u1 - u0) / (t1 - t0);
        (slope.is_finite() && slope > 0.0).then_some(slope)
    }

    /// Where the utilisation reaches 1 by the secant through the latest point, in rad.
    pub(super) fn root(&self, slope: f64) -> Option<f64> {
        let (t, u) = self.points[0]?;
        let root = t + (1.0 - u) / slope;
        root.is_finite().then_some(root)
    }
}

impl Search<'_> {
    pub(super) fn eval(&mut self, theta: f64) -> Result<Option<ContactSolution>> {
        let sol = qp::solve(&palm_problem(self.p, theta, self.s.formulation), &self.s.qp)?;
        self.out.solves += 1;
        self.out.iterations += sol.iterations;
        self.out.backend = sol.backend;
        match sol.status {
            HoldStatus::Held => {
                self.trail.push(theta, HeldTrail::utilisation(&sol));
                Ok(Some(sol))
            }
            HoldStatus::NotHeld => Ok(None),
            HoldStatus::Undetermined => {
                self.out.undetermined_solves += 1;
                Ok(None)
            }
        }
    }

    pub(super) fn jam_at(
        &mut self,
        status: JamStatus,
        theta: f64,
        sol: ContactSolution,
    ) -> PalmSolution {
        self.out.status = status;
        self.out.theta_jam_deg = Some(theta.to_degrees());
        let x = self.p.disc_position_mm(theta);
        self.out.x_jam_mm = x.is_finite().then_some(x);
        let over = sol
            .forces
            .iter()
            .enumerate()
            .map(|(i, f)| (i, f.utilisation))
            .filter(|&(_, u)| u > 1.0 + CONE_EXCESS)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((contact, utilisation)) = over {
            self.out.cross_check = Some(MinNormCheck::ConeOverused {
                contact,
                utilisation,
                allowed_excess: CONE_EXCESS,
                backend: sol.backend,
            });
            self.out.status = JamStatus::Inaccurate;
        }
        self.out.at_jam = Some(sol);
        self.out.clone()
    }
}

/// A guess at theta_jam from neighbouring answers: the bisection's bracket is sought around
/// `theta_rad`, `width_rad` to each side at first and four times wider at each miss.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct JamGuess {
    pub theta_rad: f64,
    pub width_rad: f64,
}

/// Widenings of a [`JamGuess`] bracket before the search falls back to the palm's reach and the
/// start angle: 4^12 = 1.7e7 times the first width covers any bracket from 1e-7 rad up.
const GUESS_WIDENINGS: u32 = 12;

/// Solves the palm scene by the minimum-norm model. The held angles below the start are one
/// interval, [0, theta_jam] (module docs), so: held at the start angle -> jammed at start; held
/// at the palm's reach (x = palm length) -> bisect [reach, start] to `bisection_tol_rad`
/// (relative below 0.1 rad, `RELATIVE_RESOLUTION`); otherwise beyond reach if the formulation
/// can jam at all, else never jams. A disc starting past the palm's end is beyond reach; one held
/// at the start and at 90 deg + alpha_g + alpha_p (below 180 deg) is too weak to move. `p` and `s` are validated
/// here.
pub fn solve(p: &SceneParams, s: &MinNormSettings) -> Result<PalmSolution> {
    solve_near(p, s, None)
}

/// [`solve`], with the bisection bracketed around `guess` when one is given: a held angle
/// `lo` and a not-held angle `hi` strictly between the palm's reach and the start angle bracket
/// theta_jam, because the held angles are one interval [0, theta_jam] (module docs); that also
/// decides the status (jams) without solving at the reach and the start. A guess whose bracket
/// reaches either end falls back to [`solve`]'s search. The answer is the held end of a bracket
/// of the same width as [`solve`]'s, so both lie within `bisection_tol_rad` (relative below
/// 0.1 rad) of the same boundary.
pub(crate) fn solve_near(
    p: &SceneParams,
    s: &MinNormSettings,
    guess: Option<JamGuess>,
) -> Result<PalmSolution> {
    p.validate()?;
    s.validate()?;
    solve_from(&mut Search::new(p, s), guess)
}

impl<'a> Search<'a> {
    /// A search that has solved nothing yet; `p` and `s` are taken as valid.
    pub(super) fn new(p: &'a SceneParams, s: &'a MinNormSettings) -> Self {
        Search {
            p,
            s,
            trail: HeldTrail::default(),
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
                cross_check: None,
            },
        }
    }
}

/// [`solve_near`] on a search that may have solved some angles already (they count).
pub(super) fn solve_from(search: &mut Search, guess: Option<JamGuess>) -> Result<PalmSolution> {
    let p = search.p;
    let s = search.s;
    let start = p.start_angle_deg.to_radians();
    let reach = p.reach_angle();
    // A disc that starts beyond the palm's end is never touched.
    if start < reach {
        search.out.status = JamStatus::BeyondReach;
        return Ok(search.out.clone());
    }
    if let Some(g) = guess
        && let Some((lo, hi, held)) = search.bracket(g, reach, start)?
    {
        return search.bisect(lo, hi, held);
    }
    if let Some(sol) = search.eval(start)? {
        // With a joint carrying the moment, held where the push slides the disc best means held
        // at every angle: the push is too weak (module docs). A rolling disc's hold does not
        // depend on the push that way: held at every angle there is a wedge that always locks.
        // Past 180 deg (mu_g mu_p >= 1) the wedge self-locks at every angle: jammed at start.
        let best = std::f64::consts::FRAC_PI_2 + p.alpha_ground() + p.alpha_palm();
        if s.formulation == Formulation::Translational
            && best < std::f64::consts::PI
            && best != start
            && search.eval(best)?.is_some()
        {
            search.out.status = JamStatus::TooWeak;
            return Ok(search.out.clone());
        }
        return Ok(search.jam_at(JamStatus::JammedAtStart, start, sol));
    }
    if reach < start
        && let Some(held) = search.eval(reach)?
    {
        return search.bisect(reach, start, held);
    }
    // Not held within reach: theta_jam lies below it, if it exists. The held angles are
    // [0, theta_jam] (module docs), with theta_jam > 0 whenever the formulation has friction to
    // hold with, so no solve is needed (a solve at an angle of 1e-9 rad would decide at the
    // solvers' tolerance, and called mu = 1e-8 never_jams where the statics say beyond_reach).
    if s.formulation.can_jam(p) {
        search.out.status = JamStatus::BeyondReach;
    }
    Ok(search.out.clone())
}

impl Search<'_> {
    /// A held angle, a not-held angle above it and the held solution, both strictly between
    /// `reach` and `start`, sought around `g`; None if the widening bracket touches either end.
    fn bracket(
        &mut self,
        g: JamGuess,
        reach: f64,
        start: f64,
    ) -> Result<Option<(f64, f64, ContactSolution)>> {
        let mut held: Option<(f64, ContactSolution)> = None;
        let mut free: Option<f64> = None;
        let mut width = g.width_rad;
        for _ in 0..=GUESS_WIDENINGS {
            if held.is_none() {
                let lo = g.theta_rad - width;
                if lo <= reach {
                    return Ok(None);
                }
                match self.eval(lo)? {
                    Some(sol) => held = Some((lo, sol)),
                    None => free = Some(lo),
                }
            }
            if free.is_none() {
                let hi = g.theta_rad + width;
                if hi >= start {
                    return Ok(None);
                }
                match self.eval(hi)? {
                    Some(sol) => held = Some((hi, sol)),
                    None => free = Some(hi),
                }
            }
            if let (Some((lo, _)), Some(hi)) = (&held, free)
                && *lo < hi
            {
                let (lo, sol) = held.expect("checked above");
                return Ok(Some((lo, hi, sol)));
            }
            width *= 4.0;
        }
        Ok(None)
    }

    /// Bisects [lo, hi] (held at `lo`, with solution `held`; not held at `hi`) to
    /// `bisection_tol_rad`, relative below 0.1 rad so that a jam at 1e-9 rad is still found to
    /// 1e-6 of itself (above it the absolute tolerance governs: every chart's jam angle is).
    pub(super) fn bisect(
        &mut self,
        mut lo: f64,
        mut hi: f64,
        mut held: ContactSolution,
    ) -> Result<PalmSolution> {
        while hi - lo > self.s.bisection_tol_rad.min(RELATIVE_RESOLUTION * lo) {
            let mid = 0.5 * (lo + hi);
            match self.eval(mid)? {
                Some(sol) => {
                    lo = mid;
                    held = sol;
                }
                None => hi = mid,
            }
        }
        Ok(self.jam_at(JamStatus::Jams, lo, held))
    }
}

/// The palm scene at one angle `theta_deg` solved by clarabel, with its convergence trace
/// (the data of the paper's Fig. 4).
pub(crate) fn trace_at(
    p: &SceneParams,
    theta_deg: f64,
    s: &MinNormSettings,
) -> Result<ContactSolution> {
    p.validate()?;
    s.validate()?;
    qp::solve_clarabel(
        &palm_problem(p, theta_deg.to_radians(), s.formulation),
        &s.qp,
    )
}
