//! [`DesignQuestion`]: the inverse questions over uncertain inputs ([`crate::design`]), each
//! closed form checked by the nonsmooth simulation (force drive).

use serde::Serialize;

use super::{Keywords, Words};
use crate::config::Config;
use crate::design::{self, Carry, Design, DesignBox, LeastPush};
use crate::dynamics::{Drive, DynamicsParams, Method};
use crate::error::{Error, Result};
use crate::models::{self, ModelKind, ModelSpec, OutsideModel};
use crate::numbers::Num;
use crate::scene::{JamStatus, SceneParams};
use crate::uncertain::UncertainSet;

settings! {
    /// The key of `design`'s target, with the flag that gives it.
    section = "design";
    aliases DESIGN_KEYS {
        /// Target disc position x (from the hinge): carry the part at least this far.
        x_target_mm, flag: Some("x-target"), unit: "mm";
    }
}

/// How far the simulated jam may lie from the closed form's before the answer says so. The
/// nonsmooth force drive meets an independent rigid ODE to 5e-6 (tests/force_drive_rest.rs), so
/// a gap of 0.5 % is the disc's coast at the drive's speed, not the method's error.
pub(super) const COAST_TOLERANCE: f64 = 0.005;

/// `jamchart design`'s question: for a target position, the least push that carries the disc
/// there without jamming at any friction of the box, the largest friction the push allows, and
/// the palm lengths that keep every jam on the palm or end before them.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(try_from = "Keywords")]
pub struct DesignQuestion {
    /// The scene at its nominal values, and the simulation's settings for the checks.
    pub config: Config,
    /// The scene's ranges and distributions (a distribution by its 0.1 % and 99.9 %
    /// quantiles).
    pub uncertain: UncertainSet,
    /// Target disc position x in mm (from the hinge): carry the part at least this far.
    pub x_target_mm: f64,
}

impl DesignQuestion {
    /// The question of `keywords`: `x_target_mm` and every setting of the palm scene (a range
    /// or distribution as text).
    pub fn from_keywords(mut kw: Keywords) -> Result<Self> {
        let x_target_mm = kw.take_number("x_target_mm")?.ok_or_else(|| {
            Error::invalid(
                "x_target_mm",
                "missing",
                "give the target position in mm from the hinge",
            )
        })?;
        let over = kw.into_overrides(crate::settings::palm_family(), &["x_target_mm"])?;
        let (config, uncertain) = super::palm_scene(Default::default(), over)?;
        Ok(DesignQuestion {
            config,
            uncertain,
            x_target_mm,
        })
    }

    /// Values that look like a unit mistake, the answer still given.
    pub fn warnings(&self) -> Vec<String> {
        self.config.scene.unit_warnings()
    }

    /// The box's two corners: each uncertain input at the end that jams earliest (frictions
    /// and mass high, push low) or latest (the other ends); a distribution by its 0.1 %
    /// quantiles.
    fn corners(&self) -> DesignBox {
        let (p, u) = (&self.config.scene, &self.uncertain);
        let pick = |earliest: bool| -> Vec<f64> {
            u.inputs
                .iter()
                .map(|i| {
                    let (lo, hi) = i.value.ends();
                    let high = if i.name == "force_n" {
                        !earliest
                    } else {
                        earliest
                    };
                    if high { hi } else { lo }
                })
                .collect()
        };
        DesignBox {
            earliest: u.apply(p, &pick(true)),
            latest: u.apply(p, &pick(false)),
        }
    }

    /// Answers the question: the design with its simulated checks, or the port's reason where
    /// the scene lies outside the closed form.
    pub fn answer(&self) -> Result<DesignAnswer> {
        let x_t = self.x_target_mm;
        if !(x_t.is_finite() && x_t > 0.0) {
            return Err(Error::invalid(
                "x_target_mm",
                x_t,
                "the target position is a finite distance from the hinge > 0 mm",
            ));
        }
        let b = self.corners();
        for corner in [&b.earliest, &b.latest] {
            corner.validate()?;
        }
        // The closed form answers a push starting at 90 deg or below, as `solve` does: above
        // it the answer is the port's outside_model, with its reason (no input moves the start).
        if let Some(why) = models::outside(ModelKind::Statics, &b.earliest) {
            return Ok(DesignAnswer::Outside {
                status: JamStatus::OutsideModel,
                why,
            });
        }
        let Some(d) = design::design(&b, x_t) else {
            return Err(Error::invalid(
                "x_target_mm",
                x_t,
                format!(
                    "the disc is at x = {:.3} mm already at a right-angled palm (r + h); give a \
                     target beyond it",
                    Num(self
                        .config
                        .scene
                        .disc_position_mm(std::f64::consts::FRAC_PI_2))
                ),
            ));
        };
        let dynamics = &self.config.dynamics;
        let check_least_push = match d.carry {
            Carry::Ahead {
                least_push: LeastPush::Push { force_n },
                ..
            } => Some(check(
                &SceneParams {
                    force_n,
                    ..b.earliest
                },
                dynamics,
            )?),
            _ => None,
        };
        // Simulated on a palm twice the closed form's length, so that a jam past this palm's
        // end is still located: the force drive's disc runs on past the closed form's jam
        // (112.6 mm against 99.3 mm for the 25 mm shaft at mu 0.12, 40 N), and 10 % more palm
        // lost it.
        let check_latest_jam = d
            .palm_length_keeping_jams_on_mm
            .map(|l| {
                let long = SceneParams {
                    palm_length_mm: b.latest.palm_length_mm.max(2.0 * l),
                    ..b.latest
                };
                check(&long, dynamics)
            })
            .transpose()?;
        Ok(DesignAnswer::Design(Box::new(DesignReport {
            design: d,
            earliest_corner: b.earliest,
            latest_corner: b.latest,
            check_least_push,
            check_latest_jam,
            uncertain: self.uncertain.clone(),
        })))
    }
}

impl TryFrom<Keywords> for DesignQuestion {
    type Error = Error;

    fn try_from(kw: Keywords) -> Result<Self> {
        DesignQuestion::from_keywords(kw)
    }
}

/// A closed-form answer and the nonsmooth simulation of the same scene.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct SimCheck {
    /// The scene's push, N, and friction (both), at which it was simulated.
    pub force_n: f64,
    /// mu_ground, mu_palm simulated.
    pub mu: (f64, f64),
    /// x_jam by the closed form, mm.
    pub x_jam_closed_form_mm: Option<f64>,
    /// x_jam by the nonsmooth simulation (force drive), mm.
    pub x_jam_nonsmooth_mm: Option<f64>,
    /// The simulation's status: `jammed_at_start` where the disc did not move (a push a
    /// hair above the least that moves it moves the disc by less than the run resolves).
    pub nonsmooth_status: JamStatus,
    /// The simulated jam when the disc coasts past the closed form's by more than 0.5 %, mm:
    /// a palm sized by the closed form would lose it at the drive's speed.
    pub coasts_to_mm: Option<f64>,
}

/// The nonsmooth simulation (force drive) of `p`, against its closed form.
fn check(p: &SceneParams, dynamics: &DynamicsParams) -> Result<SimCheck> {
    let mut d = *dynamics;
    d.integrator.method = Method::Nonsmooth;
    d.drive.mode = Drive::Force;
    let spec = ModelSpec::Dynamics {
        params: d,
        series_dt_s: None,
    };
    let sim = models::solve(&spec, p)?;
    let x_jam_closed_form_mm = crate::statics::solve(p).x_jam_mm;
    let coasts_to_mm = match (x_jam_closed_form_mm, sim.x_jam_mm) {
        (Some(x_cf), Some(x_sim)) if x_sim > x_cf * (1.0 + COAST_TOLERANCE) => Some(x_sim),
        _ => None,
    };
    Ok(SimCheck {
        force_n: p.force_n,
        mu: (p.mu_ground, p.mu_palm),
        x_jam_closed_form_mm,
        x_jam_nonsmooth_mm: sim.x_jam_mm,
        nonsmooth_status: sim.status,
        coasts_to_mm,
    })
}

/// The answer to a [`DesignQuestion`]; its serde form is `jamchart design --format json`'s
/// document.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum DesignAnswer {
    /// The design over the box, with its checks.
    Design(Box<DesignReport>),
    /// The scene lies outside the closed form: its status and the port's reason.
    Outside {
        /// Always `outside_model`.
        status: JamStatus,
        /// Why.
        #[serde(flatten)]
        why: OutsideModel,
    },
}

impl DesignAnswer {
    /// The command line's report, in `words`.
    pub fn text(&self, words: Words) -> String {
        match self {
            DesignAnswer::Design(r) => r.text(words),
            DesignAnswer::Outside { why, .. } => {
                format!("design: outside_model\n  not run: {why}\n")
            }
        }
    }
}

/// The design over the box, the corners it was made at and the simulated checks.
#[derive(Debug, Clone, Serialize)]
pub struct DesignReport {
    /// The least push, the largest friction, the palm lengths.
    pub design: Design,
    /// The corner that jams earliest: frictions and mass high, push low.
    pub earliest_corner: SceneParams,
    /// The corner that jams latest: frictions and mass low, push high.
    pub latest_corner: SceneParams,
    /// The least push simulated at the earliest corner.
    pub check_least_push: Option<SimCheck>,
    /// The latest jam simulated at the latest corner.
    pub check_latest_jam: Option<SimCheck>,
    /// The ranges and distributions designed over.
    pub uncertain: UncertainSet,
}
