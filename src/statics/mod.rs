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
//! boundary's angle (`SceneParams::reach_angle`, the start angle), found by regula falsi, or by
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
//! square roots and divisions where that one takes six transcendental functions.
//!
//! ## Many pushes at once, the same bits
//!
//! The arithmetic is written once, over `N` lanes (`Many<N>`): every step is one IEEE
//! operation per lane (+, -, *, /, sqrt, never a fused multiply-add), the arctangent too
//! (Cephes' rational function instead of libm's call), and the status is chosen from values
//! all computed, not reached by branches. A single push is `N = 1`; an array of pushes goes 16
//! at a time, which the compiler turns into vector instructions (AVX2 where the processor
//! has it, chosen at run time). A lane's result is the same bits as the push alone, on every
//! machine, so a chart, the CLI and the Python package agree to the last bit.

use std::f64::consts::PI;

use serde::Serialize;

use self::lanes::{Many, Mask, atan};
use crate::scene::{JamStatus, Param, SceneParams};

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

mod lanes;
pub mod reference;

/// The closed-form jam angle in rad, alpha_g + alpha_p + asin(m g sin(alpha_g) / F), before the
/// statuses are decided; +infinity when the push can never move the disc (m g sin(alpha_g) >= F).
pub(crate) fn theta_jam_rad(p: &SceneParams) -> f64 {
    verdict(&Push::of(p)).theta_jam.one()
}

/// An angle held as its cosine and sine (`N` of them, one per lane): the friction angles and
/// their sum are composed by multiplying unit complex numbers, so the closed form takes no
/// trigonometric function but one arctangent for the angle it reports.
#[derive(Debug, Clone, Copy)]
struct Turn<const N: usize = 1> {
    cos: Many<N>,
    sin: Many<N>,
}

impl Turn {
    /// The angle `theta` (rad).
    fn of(theta: f64) -> Self {
        let (sin, cos) = theta.sin_cos();
        Turn {
            cos: cos.into(),
            sin: sin.into(),
        }
    }
}

impl<const N: usize> Turn<N> {
    /// The friction angle atan(mu): (1, mu) / sqrt(1 + mu^2), or (1/mu, 1) where 1 + mu^2
    /// would overflow.
    #[inline(always)]
    fn friction(mu: Many<N>) -> Self {
        let huge = mu.gt(1e150);
        let cos = 1.0 / huge.select(mu, (1.0 + mu * mu).sqrt());
        Turn {
            cos,
            sin: huge.select(1.0, mu * cos),
        }
    }

    /// The angle asin(s) for s in [0, 1]: (sqrt((1 - s)(1 + s)), s).
    #[inline(always)]
    fn arcsine(s: Many<N>) -> Self {
        Turn {
            cos: ((1.0 - s) * (1.0 + s)).sqrt(),
            sin: s,
        }
    }

    /// The sum of both angles.
    #[inline(always)]
    fn plus(self, o: Self) -> Self {
        Turn {
            cos: self.cos * o.cos - self.sin * o.sin,
            sin: self.sin * o.cos + self.cos * o.sin,
        }
    }

    /// This angle less `o`.
    #[inline(always)]
    fn minus(self, o: Self) -> Self {
        Turn {
            cos: self.cos * o.cos + self.sin * o.sin,
            sin: self.sin * o.cos - self.cos * o.sin,
        }
    }

    /// tan(theta / 2): sin / (1 + cos), or (1 - cos) / sin where cos <= 0, so that neither
    /// form subtracts nearly equal numbers.
    #[inline(always)]
    fn half_tan(self) -> Many<N> {
        let right = self.cos.gt(0.0);
        right.select(self.sin, 1.0 - self.cos) / right.select(1.0 + self.cos, self.sin)
    }

    /// The angle in rad, in [0, 2 pi): 2 atan(tan(theta / 2)), a half turn added below the
    /// axis.
    #[inline(always)]
    fn angle(self) -> Many<N> {
        let half = atan(self.half_tan());
        2.0 * half.lt(0.0).select(half + PI, half)
    }

    /// The disc's position x = r cot(theta/2) + h / sin(theta) in mm, radius `r` and palm
    /// offset `h` in mm, where the palm stands at this angle
    /// ([`SceneParams::disc_position_mm`]).
    #[inline(always)]
    fn disc_position_mm(self, r: Many<N>, h: Many<N>) -> Many<N> {
        let base = r / self.half_tan();
        // Without a palm offset in any lane (the paper's palm), no lane divides by sin.
        match h.0.iter().all(|&h| h == 0.0) {
            true => base,
            false => h.eq(0.0).select(base, base + h / self.sin),
        }
    }

    /// The contact's distance s_B = x cos(theta) + r sin(theta) in mm from the hinge along
    /// the palm, with the disc at `x` ([`crate::scene::contact_distance_at_mm`]).
    #[inline(always)]
    fn contact_distance_mm(self, r: Many<N>, h: Many<N>, x: Many<N>) -> Many<N> {
        h.eq(0.0).select(x, x * self.cos + r * self.sin)
    }
}

/// The friction angles alpha_g = atan(mu_ground) and alpha_p = atan(mu_palm) as [`Turn`]s.
#[derive(Clone, Copy)]
struct Frictions<const N: usize = 1> {
    ground: Turn<N>,
    palm: Turn<N>,
}

impl<const N: usize> Frictions<N> {
    #[inline(always)]
    fn of(mu_ground: Many<N>, mu_palm: Many<N>) -> Self {
        Frictions {
            ground: Turn::friction(mu_ground),
            palm: Turn::friction(mu_palm),
        }
    }
}

/// The start angle in deg and rad and as a [`Turn`], and where the disc sits there (`N` of
/// each, one per lane): what a batch whose pushes share the start angle, the radius, the palm
/// offset and the palm length takes from its first push.
#[derive(Debug, Clone, Copy)]
struct Start<const N: usize = 1> {
    deg: Many<N>,
    rad: Many<N>,
    turn: Turn<N>,
    /// The disc's position in mm at the start angle.
    x_mm: Many<N>,
    /// The disc starts past the palm's end: the palm never touches it.
    beyond: Mask<N>,
}

/// What the closed form reads of `N` pushes (one lane each), in [`SceneParams`]'s units: the
/// scene fields [`Push::INPUTS`], then what the start derives from them ([`Start`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Push<const N: usize = 1> {
    inputs: [Many<N>; Push::INPUTS.len()],
    start: Start<N>,
}

impl Push {
    /// The scene fields the closed form reads, in the order of [`Push`]'s inputs.
    const INPUTS: [Param; 9] = [
        Param::MuGround,
        Param::MuPalm,
        Param::MassKg,
        Param::GravityMS2,
        Param::ForceN,
        Param::RadiusMm,
        Param::PalmOffsetMm,
        Param::PalmLengthMm,
        Param::StartAngleDeg,
    ];

    /// The inputs [`Push::derive`] derives the start from: the start angle, the radius, the
    /// palm offset and length.
    pub(crate) const START_INPUTS: [usize; 4] = [RADIUS, OFFSET, LENGTH, START];

    /// The push of scene `p`.
    pub(crate) fn of(p: &SceneParams) -> Self {
        let inputs = [
            p.mu_ground,
            p.mu_palm,
            p.mass_kg,
            p.gravity_m_s2,
            p.force_n,
            p.radius_mm,
            p.palm_offset_mm,
            p.palm_length_mm,
            p.start_angle_deg,
        ];
        let mut push = Push {
            inputs: inputs.map(Many::from),
            start: Start {
                deg: 0.0.into(),
                rad: 0.0.into(),
                turn: Turn::of(0.0),
                x_mm: 0.0.into(),
                beyond: Mask::splat(false),
            },
        };
        push.derive(0, true);
        push
    }
}

/// Where [`Push::INPUTS`] holds the radius, the palm's offset and length, and the start angle.
const RADIUS: usize = input_of(Param::RadiusMm);
const OFFSET: usize = input_of(Param::PalmOffsetMm);
const LENGTH: usize = input_of(Param::PalmLengthMm);
const START: usize = input_of(Param::StartAngleDeg);

/// The index of `param` in [`Push::INPUTS`], at compile time: a parameter the closed form
/// does not read fails the build.
const fn input_of(param: Param) -> usize {
    let mut i = 0;
    while i < Push::INPUTS.len() {
        if crate::settings::decl::same(Push::INPUTS[i].as_str(), param.as_str()) {
            return i;
        }
        i += 1;
    }
    panic!("the closed form does not read this parameter")
}

impl<const N: usize> Push<N> {
    /// `N` copies of push `q`.
    pub(crate) fn splat(q: Push) -> Self {
        let one = |v: Many<1>| Many::from(v.one());
        let s = q.start;
        Push {
            inputs: q.inputs.map(one),
            start: Start {
                deg: one(s.deg),
                rad: one(s.rad),
                turn: Turn {
                    cos: one(s.turn.cos),
                    sin: one(s.turn.sin),
                },
                x_mm: one(s.x_mm),
                beyond: Mask::splat(s.beyond.get(0)),
            },
        }
    }

    /// The index of the input that scene field `key` sets; None for a field the closed
    /// form does not read.
    pub(crate) fn input(key: &str) -> Option<usize> {
        Push::INPUTS.iter().position(|p| p.as_str() == key)
    }

    /// The lanes of input `i` ([`Self::input`]); after writing those of
    /// [`Push::START_INPUTS`], call [`Self::derive`] for each lane written.
    #[inline(always)]
    pub(crate) fn input_mut(&mut self, i: usize) -> &mut [f64; N] {
        &mut self.inputs[i].0
    }

    /// Lane `j`'s start ([`Start`]) from its inputs; its angle in rad and as a [`Turn`] only
    /// if `angle` (its start angle changed).
    pub(crate) fn derive(&mut self, j: usize, angle: bool) {
        let s = &mut self.start;
        if angle {
            let deg = self.inputs[START].0[j];
            let rad = deg.to_radians();
            // Right angles exact: a cosine of 90 deg of 6.1e-17 put the contact of a palm
            // 1e300 mm off the hinge line 6.1e283 mm along it, past its end.
            let (sin, cos) = crate::scene::sin_cos_deg(deg);
            (s.deg.0[j], s.rad.0[j]) = (deg, rad);
            (s.turn.cos.0[j], s.turn.sin.0[j]) = (cos, sin);
        }
        let turn: Turn<1> = Turn {
            cos: s.turn.cos.0[j].into(),
            sin: s.turn.sin.0[j].into(),
        };
        let [r, h, l] = [RADIUS, OFFSET, LENGTH].map(|i| Many::<1>::from(self.inputs[i].0[j]));
        let x = turn.disc_position_mm(r, h);
        s.x_mm.0[j] = x.one();
        s.beyond
            .set(j, turn.contact_distance_mm(r, h, x).gt(l).get(0));
    }

    /// Lane `j` set to push `q`.
    pub(crate) fn set(&mut self, j: usize, q: &Push) {
        for (input, v) in self.inputs.iter_mut().zip(q.inputs) {
            input.0[j] = v.one();
        }
        let (s, t) = (&mut self.start, &q.start);
        (s.deg.0[j], s.rad.0[j]) = (t.deg.one(), t.rad.one());
        (s.turn.cos.0[j], s.turn.sin.0[j]) = (t.turn.cos.one(), t.turn.sin.one());
        s.x_mm.0[j] = t.x_mm.one();
        s.beyond.set(j, t.beyond.get(0));
    }

    /// The start angle of lane `j` in deg.
    pub(crate) fn start_deg(&self, j: usize) -> f64 {
        self.start.deg.0[j]
    }

    /// Each lane's status (its index in [`JamStatus::NAMES`]), theta_jam in deg and x_jam in
    /// mm, NaN where none: [`solve`]'s answer, the same bits, for each push valid by
    /// [`SceneParams::validate`]; and if asked, where each would jam on a long enough palm
    /// ([`solve`]'s `past_palm.x_jam_mm`, NaN for a push with no jam past the palm).
    #[inline(always)]
    pub(crate) fn answer(
        &self,
        status: &mut [u8; N],
        theta_deg: &mut [f64; N],
        x_mm: &mut [f64; N],
        past_palm_x_mm: Option<&mut [f64; N]>,
    ) {
        let v = verdict(self);
        let (theta, x) = v.answer(self.start.deg);
        // A whole number below 2^8 plus 2^52 holds itself in the low bits of its mantissa:
        // the byte read off in vector lanes, where `as u8` (saturating) clamps and converts
        // one lane at a time.
        let codes = v.status + 4_503_599_627_370_496.0;
        for (s, code) in status.iter_mut().zip(codes.0) {
            *s = code.to_bits() as u8;
        }
        (*theta_deg, *x_mm) = (theta.0, x.0);
        if let Some(past) = past_palm_x_mm {
            *past = past_palm_lanes(&v).select(v.x_jam, f64::NAN).0;
        }
    }
}

/// The closed form's verdict on `N` pushes and the numbers it rests on, lane by lane.
#[derive(Debug, Clone, Copy)]
struct Verdict<const N: usize = 1> {
    /// Each push's status as its index in [`JamStatus::NAMES`] (a whole number).
    status: Many<N>,
    /// The disc starts past the palm's end (beyond_reach from the start).
    beyond_at_start: Mask<N>,
    /// theta_jam in rad, alpha_g + alpha_p + asin(m g sin(alpha_g) / F); +infinity when the
    /// push is too weak ever to move the disc.
    theta_jam: Many<N>,
    /// The disc's position at theta_jam in mm (computed whatever the status).
    x_jam: Many<N>,
    /// The contact's distance from the hinge at theta_jam in mm.
    s_b: Many<N>,
    /// The disc's position at the start angle in mm.
    x_start: Many<N>,
}

impl<const N: usize> Verdict<N> {
    /// theta_jam in deg and x_jam in mm, NaN where the status has none: the start angle
    /// `start_deg` and the disc's place there when held at the start, the jam when it jams.
    #[inline(always)]
    fn answer(&self, start_deg: Many<N>) -> (Many<N>, Many<N>) {
        let is = |s: JamStatus| self.status.eq(f64::from(s.index()));
        let (held, jams) = (is(JamStatus::JammedAtStart), is(JamStatus::Jams));
        let x_start = self.x_start.is_finite().select(self.x_start, f64::NAN);
        let theta = held.select(
            start_deg,
            jams.select(self.theta_jam.map(f64::to_degrees), f64::NAN),
        );
        let x = held.select(x_start, jams.select(self.x_jam, f64::NAN));
        (theta, x)
    }
}

/// Decides the pushes `q` in the order beyond_reach (start), never_jams, too_weak,
/// jammed_at_start, beyond_reach (jam past the palm), jams.
///
/// Every quantity is computed whatever the status and the status chosen last, so that the
/// decision is a choice of values, not a branch: a batch decides its pushes lane by lane.
#[inline(always)]
fn verdict<const N: usize>(q: &Push<N>) -> Verdict<N> {
    let [mu_g, mu_p, mass, gravity, force, r, h, l, _] = &q.inputs;
    let (mu_g, mu_p, mass, gravity, force, r, h, l) =
        (*mu_g, *mu_p, *mass, *gravity, *force, *r, *h, *l);
    let start = &q.start;
    // A disc that starts beyond the palm's end is never touched, whatever the friction.
    let (x_start, beyond_at_start) = (start.x_mm, start.beyond);
    let weight_n = mass * gravity;
    // Equal frictions (the paper's one mu) have one angle: the same bits, half the work.
    let equal = mu_g
        .0
        .iter()
        .zip(&mu_p.0)
        .all(|(g, p)| g.to_bits() == p.to_bits());
    let a = match equal {
        true => {
            let ground = Turn::friction(mu_g);
            Frictions {
                ground,
                palm: ground,
            }
        }
        false => Frictions::of(mu_g, mu_p),
    };
    // m g sin(alpha_g) / F, written so that mu -> infinity stays finite.
    let load_ratio = weight_n * a.ground.sin / force;
    let moves = load_ratio.lt(1.0);
    let jam = a.ground.plus(a.palm).plus(Turn::arcsine(load_ratio));
    let theta_jam = moves.select(jam.angle(), f64::INFINITY);
    // The jam margin mu_g R_n - R_t at the start, phi = theta_start - alpha_p: with a heavy
    // disc and a start near 180 deg the ground may hold beyond the margin's second root,
    // above theta_jam.
    let phi = start.turn.minus(a.palm);
    let margin = mu_g * (weight_n + force * phi.cos) - force * phi.sin;
    let held = theta_jam.ge(start.rad) | margin.ge(0.0);
    let x_jam = jam.disc_position_mm(r, h);
    // x_jam may overflow to +inf for a vanishing wedge angle; that is beyond any palm.
    let s_b = jam.contact_distance_mm(r, h, x_jam);
    let past = x_jam.is_nan() | s_b.is_nan() | s_b.gt(l);
    let wedge_open = (mu_g * mu_p).lt(1.0);
    let never = theta_jam.le(0.0);
    // The status as its index, chosen lane by lane in the order of the decision. Too weak: no
    // angle slides the disc, not even 90 deg + alpha_g + alpha_p where the push slides it
    // best; when that angle lies past 180 deg (mu_g mu_p >= 1, a closed wedge) the wedge
    // self-locks at every palm angle whatever the push: jammed at the start instead.
    let code = |s: JamStatus| f64::from(s.index());
    let status = beyond_at_start.select(
        code(JamStatus::BeyondReach),
        moves.select(
            never.select(
                code(JamStatus::NeverJams),
                held.select(
                    code(JamStatus::JammedAtStart),
                    past.select(code(JamStatus::BeyondReach), code(JamStatus::Jams)),
                ),
            ),
            wedge_open.select(code(JamStatus::TooWeak), code(JamStatus::JammedAtStart)),
        ),
    );
    Verdict {
        status,
        beyond_at_start,
        theta_jam,
        x_jam,
        s_b,
        x_start,
    }
}

/// The F -> infinity limit of the jam: `(theta_rigid_deg, x_rigid_mm)`.
///
/// theta_rigid = alpha_g + alpha_p (the self-locking wedge), x_rigid = r cot(theta_rigid / 2) +
/// h / sin(theta_rigid) in mm (r/mu for equal frictions and h = 0); None when the wedge is
/// closed (frictionless) or x_rigid is not finite. Depends on mu_ground, mu_palm, radius_mm and
/// palm_offset_mm only.
pub(crate) fn rigid_limit(p: &SceneParams) -> (f64, Option<f64>) {
    let a = Frictions::<1>::of(p.mu_ground.into(), p.mu_palm.into());
    let wedge = a.ground.plus(a.palm);
    let angle = wedge.angle().one();
    let x = wedge.disc_position_mm(p.radius_mm.into(), p.palm_offset_mm.into());
    (
        angle.to_degrees(),
        finite_or_none(x.one()).filter(|_| angle > 0.0),
    )
}

/// Solves the scene in closed form. `p` must have passed [`SceneParams::validate`].
pub(crate) fn solve(p: &SceneParams) -> StaticsSolution {
    let push = Push::of(p);
    let v = verdict(&push);
    let lift_off_above = lift_off_angle(p, Turn::friction(p.mu_palm.into()).angle().one());
    let (theta_rigid_deg, x_rigid_mm) = rigid_limit(p);
    let (status, theta_jam_deg, x_jam_mm) = outcome_of(&push, &v);
    StaticsSolution {
        status,
        theta_jam_deg,
        x_jam_mm,
        theta_rigid_deg,
        x_rigid_mm,
        lift_off_above_deg: lift_off_above.map(f64::to_degrees),
        lifts_off: lift_off_above.is_some_and(|t| t < push.start.rad.one()),
        past_palm: past_palm(&v).map(|(theta_jam, x_jam, s_b)| PastPalm {
            theta_jam_deg: theta_jam.to_degrees(),
            x_jam_mm: x_jam,
            palm_length_needed_mm: s_b,
            friction_factor_needed: friction_factor_to_reach(p),
        }),
    }
}

/// [`solve`]'s status, theta_jam in deg and x_jam in mm alone, without its extras (the
/// lift-off angle, the rigid limit, the jam past the palm's end). `p` must have passed
/// validation.
pub(crate) fn outcome(p: &SceneParams) -> (JamStatus, Option<f64>, Option<f64>) {
    let push = Push::of(p);
    outcome_of(&push, &verdict(&push))
}

/// The status, theta_jam and x_jam of verdict `v` of `push`: the one reading [`solve`] and
/// [`outcome`] share.
fn outcome_of(push: &Push<1>, v: &Verdict<1>) -> (JamStatus, Option<f64>, Option<f64>) {
    let (theta, x) = v.answer(push.start.deg);
    (
        JamStatus::ALL[v.status.one() as usize],
        finite_or_none(theta.one()),
        finite_or_none(x.one()),
    )
}

/// A `beyond_reach` verdict's jam past the palm's end, where it has one: theta_jam in rad,
/// x_jam and the contact's distance s_B in mm.
fn past_palm(v: &Verdict<1>) -> Option<(f64, f64, f64)> {
    let (theta_jam, x_jam, s_b) = (v.theta_jam.one(), v.x_jam.one(), v.s_b.one());
    past_palm_lanes(v).get(0).then_some((theta_jam, x_jam, s_b))
}

/// Which lanes of a verdict have a jam past the palm's end ([`past_palm`]): beyond_reach by
/// their jam, not from the start, at a finite place.
#[inline(always)]
fn past_palm_lanes<const N: usize>(v: &Verdict<N>) -> Mask<N> {
    let past = v.status.eq(f64::from(JamStatus::BeyondReach.index()));
    past & !v.beyond_at_start & v.x_jam.is_finite() & v.s_b.is_finite()
}

/// The closed form's status alone: [`solve`]'s `status` without the extras (no lift-off
/// angle, rigid limit or past-palm bisection), for scans that only need the verdict, such
/// as the status breakpoints of a range answer. `p` must have passed validation.
pub(crate) fn status(p: &SceneParams) -> JamStatus {
    JamStatus::ALL[verdict(&Push::of(p)).status.one() as usize]
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
mod closed_form_tests;

#[cfg(test)]
mod tests {
    use super::*;

    /// A [`Turn`] gives back its angle over the whole circle, within 2 ulp of 2 pi.
    #[test]
    fn a_turn_gives_back_its_angle() {
        for i in 0..=4000 {
            let theta = 2.0 * PI * f64::from(i) / 4001.0;
            let back = Turn::of(theta).angle().one();
            assert!(
                (back - theta).abs() <= 4.0 * f64::EPSILON * PI,
                "{theta}: {back}"
            );
        }
    }

    /// Each input of a push is the scene field it names, read from where [`Push::of`] reads
    /// it, and the start's inputs are where the derivation looks for them.
    #[test]
    fn a_pushs_inputs_are_the_fields_they_name() {
        let mut p = SceneParams::default();
        for (i, param) in Push::INPUTS.iter().enumerate() {
            p = param.apply(p, 1.0 + i as f64);
        }
        let push = Push::of(&p);
        for (i, param) in Push::INPUTS.iter().enumerate() {
            assert_eq!(push.inputs[i].one(), 1.0 + i as f64, "{}", param.as_str());
        }
    }

    /// theta_jam composed from the frictions' unit vectors is the textbook closed form
    /// ([`reference`]: atan(mu_g) + atan(mu_p) + asin(m g sin(atan mu_g) / F)), and x_jam is
    /// r cot(theta/2) + h / sin(theta) at it, both to a few ulp, over frictions, loads and
    /// offsets.
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
                        let composed = theta_jam_rad(&p);
                        let Some(trig) = reference::theta_jam_rad(&p) else {
                            assert!(composed.is_infinite(), "{p:?}");
                            continue;
                        };
                        let d = (composed - trig).abs() / trig.max(1e-300);
                        assert!(
                            d <= 8.0 * f64::EPSILON || composed == trig,
                            "{p:?}: {composed} {trig}"
                        );
                        if composed > 0.0 && composed < PI {
                            let x = verdict(&Push::of(&p)).x_jam.one();
                            let want = reference::x_mm(&p, trig);
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

    /// `solve --palm-offset 1e300` said the disc starts past the palm's end, which would
    /// touch it 6.1e283 mm from the hinge at the start angle 90 deg: the cosine of 90 deg in
    /// radians (6.1e-17) times the offset, from an offset of about 2.3e18 up. At 90 deg the
    /// contact lies r from the hinge whatever the offset, so the disc starts on the palm, and
    /// the jam, 1e300 mm out, lies past the palm's end.
    #[test]
    fn a_palm_far_off_the_hinge_line_touches_the_disc_at_its_radius_at_90_deg() {
        for h in [1e17, 2.3e18, 1e20, 1e300] {
            let p = SceneParams {
                palm_offset_mm: h,
                ..SceneParams::default()
            };
            assert_eq!(p.start_contact_distance_mm(), p.radius_mm, "h = {h:e}");
            let s = solve(&p);
            assert_eq!(s.status, JamStatus::BeyondReach, "h = {h:e}");
            let past = s.past_palm.unwrap_or_else(|| panic!("h = {h:e}: {s:?}"));
            assert!(past.x_jam_mm > h, "h = {h:e}: {past:?}");
        }
        // Other starts keep the bits they had: 60 deg as the radians give it.
        let p = SceneParams {
            palm_offset_mm: 3.0,
            start_angle_deg: 60.0,
            ..SceneParams::default()
        };
        let (sin, cos) = crate::scene::sin_cos_deg(60.0);
        assert_eq!((sin, cos), 60_f64.to_radians().sin_cos());
        let s_b = p.start_contact_distance_mm();
        assert!((s_b - p.contact_distance_mm(60_f64.to_radians())).abs() < 1e-12 * s_b);
    }

    /// A column's past-palm x_jam (no friction factor searched), four pushes in lanes, is
    /// each push's full answer, bit for bit, wherever the full answer has one, and NaN
    /// wherever it has none.
    #[test]
    fn the_past_palm_jam_alone_is_the_full_answers() {
        let mut scenes = Vec::new();
        for mu in [0.0, 1e-9, 0.05, 0.12, 0.3, 0.9, 1.5] {
            for palm_length_mm in [5.0, 30.0, 80.0, 150.0] {
                for (palm_offset_mm, start_angle_deg) in [(0.0, 90.0), (3.0, 60.0), (0.0, 1.0)] {
                    let p = SceneParams {
                        palm_length_mm,
                        palm_offset_mm,
                        start_angle_deg,
                        force_n: 40.0,
                        ..SceneParams::default().with_mu(mu)
                    };
                    scenes.push(p);
                }
            }
        }
        let mut past = 0;
        for four in scenes.chunks_exact(4) {
            let mut lanes = Push::<4>::splat(Push::of(&four[0]));
            for (j, p) in four.iter().enumerate() {
                lanes.set(j, &Push::of(p));
            }
            let (mut s, mut t, mut x, mut lanes_past) = ([0; 4], [0.0; 4], [0.0; 4], [0.0; 4]);
            lanes.answer(&mut s, &mut t, &mut x, Some(&mut lanes_past));
            for (p, x) in four.iter().zip(lanes_past) {
                let full = solve(p).past_palm.map(|q| q.x_jam_mm.to_bits());
                assert_eq!(
                    Some(x).filter(|x| !x.is_nan()).map(f64::to_bits),
                    full,
                    "{p:?}"
                );
                past += usize::from(full.is_some());
            }
        }
        assert_eq!(scenes.len() % 4, 0, "every scene in a batch");
        assert!(past >= 5, "{past} scenes with a jam past the palm");
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
            let s_b = p.contact_distance_mm(p.reach_angle());
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
        let g = reference::ground_reaction(&p, 90_f64.to_radians());
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
