//! [`RobustReport`]: the V-block over a box of frictions, masses and loads
//! ([`crate::locator::robust`]), the window of included angles that works over all of it.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::locator::{
    BoxVerdict, LocatorParams, RobustBox, RobustDesign, robust_design, verdict_over_box,
};
use crate::uncertain::{Uncertain, UncertainSet};

/// The standard V-blocks the answer checks, deg.
const STANDARD_V_DEG: [f64; 3] = [60.0, 90.0, 120.0];

/// The box of `p`'s nominal V from the uncertain inputs: a friction range on both flanks
/// (`mu`) or on each (`mu_left`, `mu_right`; a flank given as a number keeps it), a mass range
/// (`mass_kg`), a load range (`load_n`) and a direction range (`load_angle_deg`). A
/// distribution is refused naming it: a robust V holds every value of a range.
pub(super) fn robust_box(p: &LocatorParams, uncertain: &UncertainSet) -> Result<RobustBox> {
    let point = |v: f64| (v, v);
    let mut b = RobustBox {
        mu_left: point(p.mu_left),
        mu_right: point(p.mu_right),
        mass_kg: point(p.mass_kg),
        load_n: point(p.load_n),
        load_angle_deg: point(p.load_angle_deg),
    };
    for i in &uncertain.inputs {
        let Uncertain::Range { lo, hi } = i.value else {
            return Err(Error::invalid(
                i.name,
                i.value,
                "a robust V-block holds every value of a range: give LOW:HIGH (a \
                 distribution's probabilities are not asked here)",
            ));
        };
        for key in &i.keys {
            match *key {
                "mu_left" => b.mu_left = (lo, hi),
                "mu_right" => b.mu_right = (lo, hi),
                "mass_kg" => b.mass_kg = (lo, hi),
                "load_n" => b.load_n = (lo, hi),
                "load_angle_deg" if hi - lo <= 360.0 => b.load_angle_deg = (lo, hi),
                "load_angle_deg" => {
                    return Err(Error::invalid(
                        i.name,
                        i.value,
                        "a direction range spans at most 360 deg",
                    ));
                }
                key => {
                    return Err(Error::Defect(format!(
                        "{key} takes a range, and a robust V-block has no box for it"
                    )));
                }
            }
        }
    }
    // Each corner's weight and load are checked as the point's are (within the float range).
    LocatorParams {
        mass_kg: b.mass_kg.1,
        load_n: b.load_n.1,
        ..*p
    }
    .validate()?;
    Ok(b)
}

/// The robust answer over the box of `uncertain` around `p`; `given` is the user's own
/// included angle, if any.
pub(super) fn answer(
    p: &LocatorParams,
    uncertain: &UncertainSet,
    given: Option<f64>,
    mass_default: bool,
) -> Result<RobustReport> {
    let b = robust_box(p, uncertain)?;
    let design = robust_design(p, &b);
    let check = |g: f64| GivenV {
        included_angle_deg: g,
        verdict: verdict_over_box(p, &b, g),
    };
    Ok(RobustReport {
        given_v: given.map(check),
        standard_v_blocks: STANDARD_V_DEG.into_iter().map(check).collect(),
        r#box: b,
        design,
        inputs: *p,
        mass_default,
    })
}

/// The V-block over a box: the box, the window of included angles and the most robust V, the
/// verdict of the user's V and of the standard ones.
#[derive(Debug, Clone, Serialize)]
pub struct RobustReport {
    /// The frictions, masses, loads and directions designed over.
    pub r#box: RobustBox,
    /// The window, the most robust V, or what would open a window.
    pub design: RobustDesign,
    /// The user's own V (its included angle or flank angles), if given.
    pub given_v: Option<GivenV>,
    /// The standard 60, 90 and 120 deg V-blocks.
    pub standard_v_blocks: Vec<GivenV>,
    /// The nominal V, disc and load.
    pub inputs: LocatorParams,
    /// The disc's mass is the default 1 kg, not given: the text says so (the document's
    /// `inputs` hold the mass either way).
    #[serde(skip)]
    pub mass_default: bool,
}

/// One V's verdict over the box.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct GivenV {
    /// Its included angle in deg.
    pub included_angle_deg: f64,
    /// Works, locks or drops a load.
    pub verdict: BoxVerdict,
}
