//! Model 1: closed-form statics (the corrected Eq. 1-2).
//!
//! The palm slides on the disc, so its push lies on the edge of the palm's friction cone,
//! tilted by alpha_p = atan(mu_palm) towards the hinge. On the disc it is
//! `F (sin(theta - alpha_p), -cos(theta - alpha_p))`, and equilibrium with the ground reaction at A
//! (R_t against the motion, R_n up) gives (Eq. 1 corrected)
//!
//! ```text
//! R_t = F sin(theta - alpha_p)
//! R_n = m g + F cos(theta - alpha_p)
//! ```
//!
//! The ground holds the disc (it jams) while R_t <= mu_g R_n. Dividing by cos alpha_g turns this into
//! `sin(theta - alpha_p - alpha_g) <= m g sin(alpha_g) / F`, so the first angle reached from above
//! where the disc stops is
//!
//! ```text
//! theta_jam = alpha_g + alpha_p + asin(m g sin(alpha_g) / F),   x_jam = r cot(theta_jam / 2).
//! ```
//!
//! ## The palm's thickness
//!
//! A real palm's contact face lies h off the hinge line (half the bar's thickness,
//! `palm_offset_mm`). The face is parallel to the hinge line, so the push, its friction and
//! the ground reaction keep their directions at every palm angle: Eq. 1 and theta_jam do not
//! change. Only where the disc sits does: its centre (x, r) lies r + h from the hinge line,
//! x sin(theta) - r cos(theta) = r + h, so
//!
//! ```text
//! x = r cot(theta / 2) + h / sin(theta),   s_B = x cos(theta) + r sin(theta) = x - h tan(theta / 2)
//! ```
//!
//! with s_B the contact's distance from the hinge along the palm, on which the palm's reach is
//! judged. For mu = 0.4 and h = 0.5 mm the rigid limit moves from r / mu = 25.000 mm to
//! 25.725 mm; the paper's Adams reading with its 1 mm bars, 25.58 mm, lies between.
//!
//! ## Monotone in every uncertain input
//!
//! The inputs that take a range ([`crate::uncertain`]) are mu_ground, mu_palm, m and F. Each
//! moves theta_jam one way only, whatever the others:
//!
//! - mu_palm: theta_jam = atan(mu_p) + (terms without mu_p) grows with it (d atan / d mu =
//!   1 / (1 + mu^2) > 0);
//! - mu_ground: atan(mu_g) grows, and so does sin(atan mu_g) = mu_g / sqrt(1 + mu_g^2) (its
//!   derivative is (1 + mu_g^2)^(-3/2) > 0), hence asin(m g sin(alpha_g) / F) too (asin grows);
//! - m: m g sin(alpha_g) / F grows with m (sin(alpha_g) >= 0), so theta_jam does;
//! - F: the same ratio falls as F grows, so theta_jam falls.
//!
//! Where m g sin(alpha_g) / F reaches 1 the push is too weak (theta_jam = +inf), which is again
//! the end of growing theta_jam. x_jam = r cot(theta/2) + h / sin(theta) falls as theta grows:
//! dx/dtheta = -(2 (r + h) cos^2(theta/2) - h) / sin^2(theta) < 0 while cos^2(theta/2) >
//! h / (2 (r + h)), which is every theta up to 90 deg at least (cos^2(theta/2) >= 1/2 there)
//! and every theta below 180 deg for h = 0. So over a box of inputs theta_jam takes its
//! extremes at two corners: every input at the end that raises theta_jam (high frictions and
//! mass, low push: the earliest jam, nearest the hinge) and the opposite corner (the latest
//! jam, furthest out). What a point of the box answers is theta_jam clamped at the start angle
//! where the disc is held there, and none where the jam lies past the palm or the push is too
//! weak; [`crate::uncertain::range`] derives the interval of those answers from the two
//! corners (`jamchart solve --mu 0.12:0.3`). The status is decided by theta_jam against the
//! start angle and the palm's reach angle (neither depends on these inputs), so it changes at
//! most once per boundary along each input; each breakpoint is where theta_jam crosses that
//! boundary's angle (`reach_angle_rad`, the start angle), found by regula falsi, or by
//! bisection of `status` for the other changes. The tests check the interval against a
//! dense grid of point answers over random boxes (`tests/range_promise.rs`).
//!
//! ## Evaluation: one arctangent per push
//!
//! Each angle of theta_jam is known by its tangent or sine, so each is held as the unit vector
//! (cos, sin) and their sum as the product of unit complex numbers:
//!
//! ```text
//! alpha = atan(mu):          (1, mu) / sqrt(1 + mu^2)
//! beta = asin(k), k < 1:     (sqrt((1 - k)(1 + k)), k),   k = m g sin(alpha_g) / F
//! theta_jam = alpha_g + alpha_p + beta:   (cos, sin) = product of the three
//! tan(theta_jam / 2) = sin / (1 + cos)    ((1 - cos) / sin where cos <= 0)
//! x_jam = r / tan(theta_jam / 2) + h / sin(theta_jam),   s_B = x_jam cos + r sin
//! ```
//!
//! and the start margin mu_g (m g + F cos(phi)) - F sin(phi) takes phi = theta_start -
//! alpha_p the same way. Only theta_jam in degrees needs an arctangent, 2 atan(tan(theta/2)).
//! The trigonometric form above is the oracle of the tests (a few ulp apart); this one takes
//! square roots and divisions where that one takes six transcendental functions, and a batch
//! of pushes lets their chains overlap (`jam_batch`), the same bits as one push alone.

use std::f64::consts::PI;

use serde::Serialize;

use crate::scene::{JamStatus, SceneParams};

/// Ground reaction at contact A for a palm angle, from the corrected Eq. 1.
#[cfg(test)]
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub(crate) struct GroundReaction {
    /// Tangential reaction R_t in N, positive against the disc's motion (towards the hinge).
    pub r_t_n: f64,
    /// Normal reaction R_n in N, positive up.
    pub r_n_n: f64,
    /// Jam margin mu_g R_n - R_t in N: positive where the ground holds the disc (jammed),
    /// negative where the disc slides.
    pub margin_n: f64,
    /// R_n < 0: the palm would lift the disc off the ground, and the model does not apply.
    pub lifts_off: bool,
}

/// Ground reaction and jam margin at palm angle `theta` (rad), with the palm sliding.
#[cfg(test)]
pub(crate) fn ground_reaction(p: &SceneParams, theta: f64) -> GroundReaction {
    reaction_at(p, p.alpha_palm(), theta)
}

/// [`ground_reaction`] with the palm's friction angle `alpha_palm` (rad) given.
#[cfg(test)]
fn reaction_at(p: &SceneParams, alpha_palm: f64, theta: f64) -> GroundReaction {
    let phi = theta - alpha_palm;
    let r_t = p.force_n * phi.sin();
    let r_n = p.weight_n() + p.force_n * phi.cos();
    GroundReaction {
        r_t_n: r_t,
        r_n_n: r_n,
        margin_n: p.mu_ground * r_n - r_t,
        lifts_off: r_n < 0.0,
    }
}

/// The jam margin mu_g R_n - R_t in N at palm angle `theta` (rad); see [`ground_reaction`].
#[cfg(test)]
pub(crate) fn margin_n(p: &SceneParams, theta: f64) -> f64 {
    ground_reaction(p, theta).margin_n
}

/// [`margin_n`] at the palm angle `theta` less the palm's friction angle, both as [`Turn`]s:
/// mu_g (m g + F cos(phi)) - F sin(phi) with phi = theta - alpha_p.
fn margin_at(p: &SceneParams, phi: Turn) -> f64 {
    p.mu_ground * (p.weight_n() + p.force_n * phi.cos) - p.force_n * phi.sin
}

/// The closed-form answer for one push.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StaticsSolution {
    /// Outcome, decided in the order beyond_reach (the disc starts past the palm's end),
    /// never_jams, too_weak, jammed_at_start, beyond_reach (the jam lies past it), jams.
    pub status: JamStatus,
    /// Palm angle at the jam in degrees (the start angle if jammed at start; None if it never jams
    /// or the jam is beyond reach).
    pub theta_jam_deg: Option<f64>,
    /// Disc position at the jam in mm, r cot(theta_jam/2) + h / sin(theta_jam) (None as for
    /// `theta_jam_deg`).
    pub x_jam_mm: Option<f64>,
    /// The F -> infinity limit of theta_jam in degrees, alpha_g + alpha_p: what a palm driven by
    /// prescribed motion reaches (the classic self-locking wedge).
    pub theta_rigid_deg: f64,
    /// The F -> infinity limit of x_jam in mm, r cot(theta_rigid/2) + h / sin(theta_rigid); r/mu
    /// for equal frictions and no palm offset.
    pub x_rigid_mm: Option<f64>,
    /// Palm angle in degrees above which R_n < 0 (the palm lifts the disc), None if it never does.
    pub lift_off_above_deg: Option<f64>,
    /// The push passes through the lift-off region between the start angle and the jam.
    pub lifts_off: bool,
    /// For `beyond_reach` with a jam past the palm's end: where it would jam on a longer palm
    /// and what would bring it onto this one (None otherwise).
    pub past_palm: Option<PastPalm>,
}

/// A jam that lies past the palm's end: where it would be and what would bring it onto the palm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PastPalm {
    /// The palm angle in deg where the disc would jam on a long enough palm.
    pub theta_jam_deg: f64,
    /// The disc position in mm at that jam, r cot(theta_jam/2) + h / sin(theta_jam).
    pub x_jam_mm: f64,
    /// The least palm length in mm that reaches the jam: the contact's distance from the hinge
    /// along the palm there, x - h tan(theta_jam / 2).
    pub palm_length_needed_mm: f64,
    /// The least factor on both friction coefficients that brings the jam onto this palm
    /// (theta_jam grows with either friction, so the jam moves towards the hinge); None when no
    /// factor up to 1e6 does, or the push then becomes too weak first.
    pub friction_factor_needed: Option<f64>,
}

/// The closed-form jam angle in rad, alpha_g + alpha_p + asin(m g sin(alpha_g) / F), before the
/// statuses are decided; +infinity when the push can never move the disc (m g sin(alpha_g) >= F).
pub(crate) fn theta_jam_rad(p: &SceneParams) -> f64 {
    Core::of(p).theta_jam
}

/// An angle held as its cosine and sine: the friction angles and their sum are composed by
/// multiplying unit complex numbers, so the closed form takes no trigonometric function but
/// one arctangent for the angle it reports.
#[derive(Debug, Clone, Copy)]
struct Turn {
    cos: f64,
    sin: f64,
}

impl Turn {
    /// The angle 0.
    const ZERO: Turn = Turn { cos: 1.0, sin: 0.0 };

    /// The angle `theta` (rad).
    fn of(theta: f64) -> Self {
        let (sin, cos) = theta.sin_cos();
        Turn { cos, sin }
    }

    /// The friction angle atan(mu): (1, mu) / sqrt(1 + mu^2), or (1/mu, 1) where 1 + mu^2
    /// would overflow.
    fn friction(mu: f64) -> Self {
        if mu > 1e150 {
            return Turn {
                cos: 1.0 / mu,
                sin: 1.0,
            };
        }
        let cos = 1.0 / (1.0 + mu * mu).sqrt();
        Turn { cos, sin: mu * cos }
    }

    /// The angle asin(s) for s in [0, 1]: (sqrt((1 - s)(1 + s)), s).
    fn arcsine(s: f64) -> Self {
        Turn {
            cos: ((1.0 - s) * (1.0 + s)).sqrt(),
            sin: s,
        }
    }

    /// The sum of both angles.
    fn plus(self, o: Turn) -> Turn {
        Turn {
            cos: self.cos * o.cos - self.sin * o.sin,
            sin: self.sin * o.cos + self.cos * o.sin,
        }
    }

    /// This angle less `o`.
    fn minus(self, o: Turn) -> Turn {
        Turn {
            cos: self.cos * o.cos + self.sin * o.sin,
            sin: self.sin * o.cos - self.cos * o.sin,
        }
    }

    /// tan(theta / 2): sin / (1 + cos), or (1 - cos) / sin where cos <= 0, so that neither
    /// form subtracts nearly equal numbers.
    fn half_tan(self) -> f64 {
        match self.cos > 0.0 {
            true => self.sin / (1.0 + self.cos),
            false => (1.0 - self.cos) / self.sin,
        }
    }

    /// The angle in rad, in [0, 2 pi): 2 atan(tan(theta / 2)), a half turn added below the
    /// axis.
    fn angle(self) -> f64 {
        let half = self.half_tan().atan();
        match half < 0.0 {
            true => 2.0 * (half + PI),
            false => 2.0 * half,
        }
    }

    /// The disc's position x = r cot(theta/2) + h / sin(theta) in mm where the palm stands
    /// at this angle ([`SceneParams::disc_position_mm`]).
    fn disc_position_mm(self, p: &SceneParams) -> f64 {
        let base = p.radius_mm / self.half_tan();
        match p.palm_offset_mm == 0.0 {
            true => base,
            false => base + p.palm_offset_mm / self.sin,
        }
    }

    /// The contact's distance s_B = x cos(theta) + r sin(theta) in mm from the hinge along
    /// the palm, with the disc at `x` ([`crate::scene::contact_distance_at_mm`]).
    fn contact_distance_mm(self, p: &SceneParams, x: f64) -> f64 {
        match p.palm_offset_mm == 0.0 {
            true => x,
            false => x * self.cos + p.radius_mm * self.sin,
        }
    }
}

/// The friction angles alpha_g = atan(mu_ground) and alpha_p = atan(mu_palm) as [`Turn`]s,
/// each computed once per scene.
#[derive(Clone, Copy)]
struct Frictions {
    ground: Turn,
    palm: Turn,
}

impl Frictions {
    fn of(p: &SceneParams) -> Self {
        let ground = Turn::friction(p.mu_ground);
        // Equal frictions (the paper's one mu) have one angle: one square root, the same bits.
        let palm = match p.mu_palm.to_bits() == p.mu_ground.to_bits() {
            true => ground,
            false => Turn::friction(p.mu_palm),
        };
        Frictions { ground, palm }
    }

    /// The wedge alpha_g + alpha_p is under 90 deg: tan(alpha_g + alpha_p) = (mu_g + mu_p) /
    /// (1 - mu_g mu_p) is finite and positive.
    fn wedge_open(p: &SceneParams) -> bool {
        p.mu_ground * p.mu_palm < 1.0
    }
}

/// The start angle as an angle in rad and a [`Turn`]: what every push of a batch that shares
/// its start angle computes once.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Start {
    rad: f64,
    turn: Turn,
}

impl Start {
    /// The start angle of `p`.
    pub(crate) fn of(p: &SceneParams) -> Self {
        let rad = p.start_angle_deg.to_radians();
        Start {
            rad,
            turn: Turn::of(rad),
        }
    }
}

/// What a push's status rests on besides its start angle: the friction angles and theta_jam,
/// as a [`Turn`] (None when the push is too weak) and in rad (+infinity then).
#[derive(Clone, Copy)]
struct Core {
    frictions: Frictions,
    jam: Option<Turn>,
    theta_jam: f64,
}

impl Core {
    fn of(p: &SceneParams) -> Self {
        let [core] = Self::batch([p]);
        core
    }

    /// The cores of `N` pushes, each lane computed by the same operations as [`Core::of`] (the
    /// same bits), phase by phase across the lanes: a push's square roots, divisions and
    /// arctangent form one chain, and the chains of `N` pushes overlap where one push's would
    /// leave the processor waiting.
    #[inline(always)]
    fn batch<const N: usize>(ps: [&SceneParams; N]) -> [Core; N] {
        let mut cores = [Core {
            frictions: Frictions {
                ground: Turn::ZERO,
                palm: Turn::ZERO,
            },
            jam: None,
            theta_jam: f64::INFINITY,
        }; N];
        for (core, p) in cores.iter_mut().zip(ps) {
            core.frictions = Frictions::of(p);
        }
        for (core, p) in cores.iter_mut().zip(ps) {
            core.jam = jam_turn(p, &core.frictions);
        }
        for core in &mut cores {
            if let Some(jam) = core.jam {
                core.theta_jam = jam.angle();
            }
        }
        cores
    }
}

/// theta_jam = alpha_g + alpha_p + asin(m g sin(alpha_g) / F) as a [`Turn`]; None when the push
/// can never move the disc (m g sin(alpha_g) >= F).
fn jam_turn(p: &SceneParams, a: &Frictions) -> Option<Turn> {
    // m g sin(alpha_g) / F, written so that mu -> infinity stays finite.
    let load_ratio = p.weight_n() * a.ground.sin / p.force_n;
    (load_ratio < 1.0).then(|| a.ground.plus(a.palm).plus(Turn::arcsine(load_ratio)))
}

/// The palm angle in rad at which the contact sits at the palm's end, s_B = L: the status
/// changes between beyond_reach and jams where theta_jam crosses it.
///
/// s_B = x cos(theta) + r sin(theta) = r cot(theta/2) + h cot(theta) falls as theta grows
/// (ds_B/dtheta = -r / (2 sin^2(theta/2)) - h / sin^2(theta) < 0), and with u = tan(theta/2)
/// s_B = L reads h u^2 + 2 L u - (2 r + h) = 0, so u = (2 r + h) / (L + sqrt(L^2 + h (2 r + h)))
/// (r / L without a palm offset). Depends on radius_mm, palm_offset_mm and palm_length_mm only.
pub(crate) fn reach_angle_rad(p: &SceneParams) -> f64 {
    let (r, h, l) = (p.radius_mm, p.palm_offset_mm, p.palm_length_mm);
    2.0 * ((2.0 * r + h) / (l + (l * l + h * (2.0 * r + h)).sqrt())).atan()
}

/// The F -> infinity limit of the jam: `(theta_rigid_deg, x_rigid_mm)`.
///
/// theta_rigid = alpha_g + alpha_p (the self-locking wedge), x_rigid = r cot(theta_rigid / 2) +
/// h / sin(theta_rigid) in mm (r/mu for equal frictions and h = 0); None when the wedge is
/// closed (frictionless) or x_rigid is not finite. Depends on mu_ground, mu_palm, radius_mm and
/// palm_offset_mm only.
pub(crate) fn rigid_limit(p: &SceneParams) -> (f64, Option<f64>) {
    rigid_limit_from(p, &Frictions::of(p))
}

/// [`rigid_limit`] from the scene's friction angles.
fn rigid_limit_from(p: &SceneParams, a: &Frictions) -> (f64, Option<f64>) {
    let wedge = a.ground.plus(a.palm);
    let angle = wedge.angle();
    let x_rigid = finite_or_none(wedge.disc_position_mm(p)).filter(|_| angle > 0.0);
    (angle.to_degrees(), x_rigid)
}

/// Solves the scene in closed form. `p` must have passed [`SceneParams::validate`].
pub(crate) fn solve(p: &SceneParams) -> StaticsSolution {
    let start = Start::of(p);
    let core = Core::of(p);
    let frictions = core.frictions;
    let lift_off_above = lift_off_angle(p, frictions.palm.angle());
    let lifts_off = lift_off_above.is_some_and(|t| t < start.rad);

    let (theta_rigid_deg, x_rigid_mm) = rigid_limit_from(p, &frictions);
    let mut out = StaticsSolution {
        status: JamStatus::Jams,
        theta_jam_deg: None,
        x_jam_mm: None,
        theta_rigid_deg,
        x_rigid_mm,
        lift_off_above_deg: lift_off_above.map(f64::to_degrees),
        lifts_off,
        past_palm: None,
    };

    let decision = decide_with(p, &core, &start);
    (out.status, out.theta_jam_deg, out.x_jam_mm) = jam_of(p, &start, &decision);
    if let Decision::PastPalm {
        theta_jam,
        x_jam,
        s_b,
    } = decision
    {
        out.past_palm = (x_jam.is_finite() && s_b.is_finite()).then(|| PastPalm {
            theta_jam_deg: theta_jam.to_degrees(),
            x_jam_mm: x_jam,
            palm_length_needed_mm: s_b,
            friction_factor_needed: friction_factor_to_reach(p),
        });
    }
    out
}

/// A status, theta_jam in deg and x_jam in mm (None where there is none): [`solve`]'s answer
/// without its extras (lift-off, rigid limit, the jam past the palm), what a batch of pushes
/// needs.
pub(crate) type Jam = (JamStatus, Option<f64>, Option<f64>);

/// The [`Jam`]s of `N` pushes, each the same bits as [`solve`]'s, their arithmetic overlapping
/// ([`Core::batch`]); `starts` gives each push's start angle, so that a batch whose pushes
/// share it computes it once. Each push must have passed [`SceneParams::validate`].
#[inline]
pub(crate) fn jam_batch<const N: usize>(ps: [&SceneParams; N], starts: [&Start; N]) -> [Jam; N] {
    let cores = Core::batch(ps);
    let mut jams = [(JamStatus::Jams, None, None); N];
    for (i, jam) in jams.iter_mut().enumerate() {
        *jam = jam_of(ps[i], starts[i], &decide_with(ps[i], &cores[i], starts[i]));
    }
    jams
}

/// The status, theta_jam (deg) and x_jam (mm) of decision `d` for `p`.
fn jam_of(p: &SceneParams, start: &Start, d: &Decision) -> Jam {
    match *d {
        Decision::JammedAtStart => (
            JamStatus::JammedAtStart,
            Some(p.start_angle_deg),
            finite_or_none(start.turn.disc_position_mm(p)),
        ),
        Decision::Jams { theta_jam, x_jam } => {
            (JamStatus::Jams, Some(theta_jam.to_degrees()), Some(x_jam))
        }
        _ => (d.status(), None, None),
    }
}

/// The closed form's status alone: [`solve`]'s `status` without the extras (no lift-off
/// angle, rigid limit or past-palm bisection), for scans that only need the verdict, such
/// as the status breakpoints of a range answer. `p` must have passed validation.
pub(crate) fn status(p: &SceneParams) -> JamStatus {
    decide_with(p, &Core::of(p), &Start::of(p)).status()
}

/// The verdict of the closed form and the numbers it rests on, before [`solve`] adds its extras.
enum Decision {
    /// A status with no jam angle: beyond the palm from the start, never jams, too weak.
    Bare(JamStatus),
    /// Held where the palm first touches the disc.
    JammedAtStart,
    /// The jam at `theta_jam` (rad), `x_jam` (mm) lies past the palm's end (contact `s_b` mm).
    PastPalm {
        theta_jam: f64,
        x_jam: f64,
        s_b: f64,
    },
    /// Jams on the palm at `theta_jam` (rad), `x_jam` (mm).
    Jams { theta_jam: f64, x_jam: f64 },
}

impl Decision {
    /// The status it decides.
    fn status(&self) -> JamStatus {
        match self {
            Decision::Bare(status) => *status,
            Decision::JammedAtStart => JamStatus::JammedAtStart,
            Decision::PastPalm { .. } => JamStatus::BeyondReach,
            Decision::Jams { .. } => JamStatus::Jams,
        }
    }
}

/// Decides the status in the order beyond_reach (start), never_jams, too_weak,
/// jammed_at_start, beyond_reach (jam past the palm), jams, from the scene's friction angles
/// and its start angle.
#[inline]
fn decide_with(p: &SceneParams, core: &Core, start: &Start) -> Decision {
    // A disc that starts beyond the palm's end is never touched, whatever the friction.
    let at_start = start.turn.disc_position_mm(p);
    if start.turn.contact_distance_mm(p, at_start) > p.palm_length_mm {
        return Decision::Bare(JamStatus::BeyondReach);
    }
    let Some(jam) = core.jam else {
        // Too weak: no angle slides the disc, not even 90 deg + alpha_g + alpha_p where the
        // push slides it best. When that angle lies past 180 deg (mu_g mu_p >= 1) the wedge
        // self-locks at every palm angle whatever the push, and the disc is jammed at the
        // start instead.
        return match Frictions::wedge_open(p) {
            true => Decision::Bare(JamStatus::TooWeak),
            false => Decision::JammedAtStart,
        };
    };
    let theta_jam = core.theta_jam;
    if theta_jam <= 0.0 {
        return Decision::Bare(JamStatus::NeverJams);
    }
    // The margin is checked at the start as well: with a heavy disc and a start near 180 deg the
    // ground may hold beyond the second root of the margin, above theta_jam.
    if theta_jam >= start.rad || margin_at(p, start.turn.minus(core.frictions.palm)) >= 0.0 {
        return Decision::JammedAtStart;
    }
    let x_jam = jam.disc_position_mm(p);
    // x_jam may overflow to +inf for a vanishing wedge angle; that is beyond any palm.
    let s_b = jam.contact_distance_mm(p, x_jam);
    if x_jam.is_nan() || s_b.is_nan() || s_b > p.palm_length_mm {
        return Decision::PastPalm {
            theta_jam,
            x_jam,
            s_b,
        };
    }
    Decision::Jams { theta_jam, x_jam }
}

/// The least factor k >= 1 on both frictions for which the jam lies on the palm (the contact
/// within `palm_length_mm` of the hinge), by bisection to 1e-9 relative: theta_jam grows
/// monotonically with k (alpha_g, alpha_p and asin(m g sin(alpha_g) / F) all do), so the
/// contact distance falls with k. None if even k = 1e6 leaves the jam past the palm or the push
/// becomes too weak before the jam reaches the palm.
fn friction_factor_to_reach(p: &SceneParams) -> Option<f64> {
    let scaled = |k: f64| SceneParams {
        mu_ground: k * p.mu_ground,
        mu_palm: k * p.mu_palm,
        ..*p
    };
    let on_palm = |k: f64| {
        let q = scaled(k);
        let t = theta_jam_rad(&q);
        t.is_finite() && q.contact_distance_mm(t) <= p.palm_length_mm
    };
    let (mut lo, mut hi) = (1.0, 2.0);
    while !on_palm(hi) {
        if hi > 1e6 || theta_jam_rad(&scaled(hi)).is_infinite() {
            return None;
        }
        (lo, hi) = (hi, 2.0 * hi);
    }
    while hi - lo > 1e-9 * hi {
        let mid = 0.5 * (lo + hi);
        if on_palm(mid) { hi = mid } else { lo = mid }
    }
    Some(hi)
}

/// Palm angle (rad) above which R_n = m g + F cos(theta - alpha_p) < 0, if below 180 deg.
fn lift_off_angle(p: &SceneParams, alpha_palm: f64) -> Option<f64> {
    let k = p.weight_n() / p.force_n;
    if k >= 1.0 {
        return None;
    }
    let t = alpha_palm + (-k).acos();
    (t < std::f64::consts::PI).then_some(t)
}

fn finite_or_none(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// The least push in N that can slide the disc: m g sin(atan mu_ground). The palm's push F is
/// most effective at theta = 90 deg + alpha_g + alpha_p, where the corrected Eq. 1 margin is
/// mu_g m g - F / cos(alpha_g); it slides the disc there iff F > m g sin(alpha_g).
pub(crate) fn least_push_n(p: &SceneParams) -> f64 {
    p.weight_n() * p.alpha_ground().sin()
}

/// The closed form against the corrected Table 1, hand derivations and its invariants.
#[cfg(test)]
#[path = "statics_tests.rs"]
mod statics_tests;

#[cfg(test)]
mod tests {
    use super::*;

    /// A [`Turn`] gives back its angle over the whole circle, within 2 ulp of 2 pi.
    #[test]
    fn a_turn_gives_back_its_angle() {
        for i in 0..=4000 {
            let theta = 2.0 * PI * f64::from(i) / 4001.0;
            let back = Turn::of(theta).angle();
            assert!(
                (back - theta).abs() <= 4.0 * f64::EPSILON * PI,
                "{theta}: {back}"
            );
        }
    }

    /// theta_jam composed from the frictions' unit vectors is the trigonometric closed form
    /// atan(mu_g) + atan(mu_p) + asin(m g sin(atan mu_g) / F), and x_jam is r cot(theta/2) +
    /// h / sin(theta) at it, both to a few ulp, over frictions, loads and offsets.
    #[test]
    fn the_composed_closed_form_is_the_trigonometric_one() {
        for mu_g in [0.0, 1e-6, 0.05, 0.2, 0.4, 0.9, 1.7, 40.0, 1e200] {
            for mu_p in [0.0, 0.01, 0.3, 1.2, 8.0] {
                for force in [0.5, 3.0, 40.0, 1e6] {
                    for offset in [0.0, 0.5] {
                        let p = SceneParams {
                            mu_ground: mu_g,
                            mu_palm: mu_p,
                            force_n: force,
                            palm_offset_mm: offset,
                            ..SceneParams::default()
                        };
                        let load = p.weight_n() * mu_g.atan().sin() / force;
                        let composed = theta_jam_rad(&p);
                        if load >= 1.0 {
                            assert!(composed.is_infinite(), "{p:?}");
                            continue;
                        }
                        let trig = mu_g.atan() + mu_p.atan() + load.asin();
                        let d = (composed - trig).abs() / trig.max(1e-300);
                        assert!(
                            d <= 8.0 * f64::EPSILON || composed == trig,
                            "{p:?}: {composed} {trig}"
                        );
                        if composed > 0.0 && composed < PI {
                            let x = Core::of(&p).jam.unwrap().disc_position_mm(&p);
                            let want = p.disc_position_mm(trig);
                            let dx = (x - want).abs() / want;
                            assert!(dx <= 1e-13, "{p:?}: x {x} {want}");
                        }
                    }
                }
            }
        }
    }

    /// Regression: a push too weak ever to move the disc was reported `jammed_at_start`, the
    /// same as a disc that jams as soon as the palm touches it.
    #[test]
    fn a_push_too_weak_to_move_the_disc_is_too_weak_not_jammed() {
        let p = SceneParams::default();
        let least = least_push_n(&p);
        assert!((least - 9.806 * 0.4_f64.atan().sin()).abs() < 1e-12);
        for (f, want) in [
            (0.999 * least, JamStatus::TooWeak),
            (1.001 * least, JamStatus::JammedAtStart),
        ] {
            let s = solve(&SceneParams { force_n: f, ..p });
            assert_eq!(s.status, want, "F = {f}");
        }
    }

    /// Regression: a disc starting past the palm's end (start 1 deg: x = 1145.9 mm on a
    /// 150 mm palm) was `jammed_at_start` at x = 1145.887 mm: the palm never touches it.
    #[test]
    fn a_disc_starting_past_the_palms_end_is_beyond_reach() {
        for mu in [0.0, 0.4, 5.0] {
            let p = SceneParams {
                start_angle_deg: 1.0,
                ..SceneParams::default().with_mu(mu)
            };
            assert_eq!(solve(&p).status, JamStatus::BeyondReach, "mu = {mu}");
        }
    }

    /// Regression: a jam past the palm's end said `beyond_reach` with no number; the
    /// user needed `--palm-length 200` to find where it would jam. The 25 mm shaft: r =
    /// 12.5 mm, m = 0.4 kg, F = 40 N, mu = 0.12, an 80 mm palm.
    #[test]
    fn a_jam_past_the_palm_says_where_and_what_brings_it_on() {
        let p = SceneParams {
            radius_mm: 12.5,
            mass_kg: 0.4,
            force_n: 40.0,
            palm_length_mm: 80.0,
            ..SceneParams::default().with_mu(0.12)
        };
        let s = solve(&p);
        assert_eq!(s.status, JamStatus::BeyondReach);
        let past = s.past_palm.expect("a finite jam past the palm");
        // The same jam as on a palm long enough to reach it.
        let long = solve(&SceneParams {
            palm_length_mm: 1000.0,
            ..p
        });
        assert_eq!(long.status, JamStatus::Jams);
        assert!((long.x_jam_mm.unwrap() - past.x_jam_mm).abs() < 1e-9);
        assert!((long.theta_jam_deg.unwrap() - past.theta_jam_deg).abs() < 1e-9);
        // h = 0: the contact distance is the position.
        assert!((past.palm_length_needed_mm - past.x_jam_mm).abs() < 1e-9);
        // The palm length needed puts the jam just on the palm, a hair less does not.
        let just = |l: f64| {
            solve(&SceneParams {
                palm_length_mm: l,
                ..p
            })
            .status
        };
        assert_eq!(
            just(past.palm_length_needed_mm * (1.0 + 1e-12)),
            JamStatus::Jams
        );
        assert_eq!(
            just(past.palm_length_needed_mm * (1.0 - 1e-9)),
            JamStatus::BeyondReach
        );
        // The friction factor needed brings it onto the 80 mm palm, 1e-6 less does not.
        let k = past
            .friction_factor_needed
            .expect("more friction reaches the palm");
        let with = |k: f64| {
            solve(&SceneParams {
                ..p.with_mu(0.12 * k)
            })
            .status
        };
        assert_eq!(with(k * (1.0 + 1e-8)), JamStatus::Jams);
        assert_eq!(with(k * (1.0 - 1e-6)), JamStatus::BeyondReach);
    }

    /// The status alone is the status of the full solve for every status, on a grid of
    /// frictions, pushes and start angles that meets all of them.
    #[test]
    fn the_status_alone_is_solves_status() {
        let mut seen = Vec::new();
        for mu in [0.0, 0.05, 0.12, 0.3, 0.6, 1.2, 3.0] {
            for force_n in [1.0, 5.0, 40.0, 200.0] {
                for start_angle_deg in [1.0, 18.5, 60.0, 120.0, 179.0] {
                    let p = SceneParams {
                        radius_mm: 12.5,
                        mass_kg: 0.4,
                        force_n,
                        palm_length_mm: 80.0,
                        start_angle_deg,
                        ..SceneParams::default().with_mu(mu)
                    };
                    let want = solve(&p).status;
                    assert_eq!(status(&p), want, "{p:?}");
                    seen.push(want);
                }
            }
        }
        for s in [
            JamStatus::BeyondReach,
            JamStatus::NeverJams,
            JamStatus::TooWeak,
            JamStatus::JammedAtStart,
            JamStatus::Jams,
        ] {
            assert!(seen.contains(&s), "the grid meets {s:?}");
        }
    }

    /// The reach angle puts the contact at the palm's end, with and without a palm offset.
    #[test]
    fn the_reach_angle_puts_the_contact_at_the_palms_end() {
        for (h, l) in [(0.0, 80.0), (0.5, 80.0), (3.0, 30.0), (1.0, 150.0)] {
            let p = SceneParams {
                palm_offset_mm: h,
                palm_length_mm: l,
                ..SceneParams::default()
            };
            let s_b = p.contact_distance_mm(reach_angle_rad(&p));
            assert!((s_b - l).abs() < 1e-9 * l, "h = {h}, L = {l}: s_B = {s_b}");
        }
    }

    #[test]
    fn errata_worked_example() {
        // The crate docs' corrected Eq. 1 example: m = 1 kg, g = 9.806, r = 10 mm, F = 200 N, mu = 0.4.
        let s = solve(&SceneParams::default());
        assert_eq!(s.status, JamStatus::Jams);
        assert!((s.theta_jam_deg.unwrap() - 44.646).abs() < 5e-4);
        assert!((s.x_jam_mm.unwrap() - 24.355).abs() < 5e-4);
        // The F -> infinity threshold of Fig. 7b: r / mu = 25 mm, 2 atan(0.4) = 43.6 deg.
        assert!((s.x_rigid_mm.unwrap() - 25.0).abs() < 1e-12);
        assert!((s.theta_rigid_deg - 43.602818972).abs() < 1e-8);
        assert!(!s.lifts_off);
    }

    #[test]
    fn corrected_eq1_reactions_by_hand() {
        // theta = 90 deg, alpha = 45 deg (mu = 1), m g = 0: the push is F (cos45, -sin45)...
        let p = SceneParams {
            mu_ground: 0.0,
            mu_palm: 1.0,
            mass_kg: 0.0,
            force_n: 2.0_f64.sqrt(),
            ..Default::default()
        };
        let g = ground_reaction(&p, 90_f64.to_radians());
        // ... so R_t = F sin 45 = 1 N and R_n = F cos 45 = 1 N (the palm presses down).
        assert!((g.r_t_n - 1.0).abs() < 1e-12 && (g.r_n_n - 1.0).abs() < 1e-12);
        assert!((g.margin_n + 1.0).abs() < 1e-12);
    }

    #[test]
    fn frictionless_never_jams_and_heavy_disc_never_moves() {
        let s = solve(&SceneParams::default().with_mu(0.0));
        assert_eq!(s.status, JamStatus::NeverJams);
        assert_eq!(s.theta_jam_deg, None);
        let heavy = SceneParams {
            mass_kg: 100.0,
            ..Default::default()
        };
        let s = solve(&heavy);
        assert_eq!(s.status, JamStatus::TooWeak);
        assert_eq!(s.theta_jam_deg, None);
        // Held at the start, but a push that could slide it later: jammed at the start.
        let early = SceneParams {
            start_angle_deg: 40.0,
            ..Default::default()
        };
        let s = solve(&early);
        assert_eq!(s.status, JamStatus::JammedAtStart);
        assert_eq!(s.theta_jam_deg, Some(40.0));
    }
}
