//! [`VlocatorQuestion`]: a disc in a V-block, its verdict, forces, capacity and optimum angle;
//! over a box of frictions, masses and loads, the V that holds it everywhere.

use serde::Serialize;

use super::{Keywords, Words};
use crate::error::{Error, Result};
use crate::locator::{self, LocatorParams, LocatorSolution};
use crate::uncertain::UncertainSet;

settings! {
    /// The V's geometry keys, with the flags that give them: each sets both flank angles (a
    /// symmetric V, or the two given).
    section = "locator";
    aliases GEOMETRY_KEYS {
        /// The two flank angles from the horizontal, left and right (an asymmetric V).
        flank_angles, flag: Some("flank-angles"), unit: "deg",
            sets: &["flank_left_deg", "flank_right_deg"];
        /// The V's included angle (a symmetric V): both flanks at (180 - angle) / 2 from
        /// the horizontal.
        included_angle_deg, flag: Some("included-angle"), unit: "deg",
            sets: &["flank_left_deg", "flank_right_deg"];
    }
}

/// `jamchart vlocator`'s question: a disc of weight m g in a V of two flat flanks under an
/// external load. With ranges (frictions, mass, load, its direction) it asks for the V that
/// holds the disc over the whole box instead.
#[derive(Debug, Clone, serde::Deserialize)]
#[serde(try_from = "Keywords")]
pub struct VlocatorQuestion {
    /// The V, the disc and the load, at the ranges' nominal values.
    pub params: LocatorParams,
    /// The ranges (a distribution is refused by the answer: a robust V holds every value).
    pub uncertain: UncertainSet,
    /// Whether the V's geometry was given: over a box, its verdict is added (`given_v`).
    pub given_v: bool,
    /// Whether the disc's mass is the default 1 kg, not given: the verdict depends on it, so
    /// the answer leads with it.
    pub mass_default: bool,
}

impl VlocatorQuestion {
    /// The question of a symmetric V's `included_angle_deg` or the two `flank_angles` (deg,
    /// left and right; neither: the default 90 deg V) and `over`, a table of the locator's
    /// settings shaped like a chart scene's (`{locator: {mu: ..., load_n: ...}}`); checked.
    pub fn new(
        included_angle_deg: Option<f64>,
        flank_angles: Option<&[f64]>,
        over: &toml::Table,
    ) -> Result<Self> {
        let mut p = LocatorParams::default();
        if let Some(g) = included_angle_deg {
            if !(g.is_finite() && g > 0.0 && g < 180.0) {
                return Err(Error::invalid(
                    "included_angle_deg",
                    g,
                    "the included angle of a V lies in (0, 180) deg",
                ));
            }
            p = p.with_included_angle(g);
        }
        if let Some(a) = flank_angles {
            let [a1, a2] = a[..] else {
                let text: Vec<String> = a.iter().map(f64::to_string).collect();
                return Err(Error::invalid(
                    "flank_angles",
                    text.join(","),
                    "give two angles, left and right, e.g. 30,60",
                ));
            };
            p.flank_left_deg = a1;
            p.flank_right_deg = a2;
        }
        let mut over = over
            .get("locator")
            .and_then(toml::Value::as_table)
            .cloned()
            .unwrap_or_default();
        let mass_default = !over.contains_key("mass_kg");
        let uncertain = crate::uncertain::take(&mut over, crate::settings::locator_family())?;
        let params: LocatorParams = crate::config::overlay(&p, &over, "locator")?;
        params.validate()?;
        Ok(VlocatorQuestion {
            params,
            uncertain,
            given_v: included_angle_deg.is_some() || flank_angles.is_some(),
            mass_default,
        })
    }

    /// The question of `keywords`: `included_angle_deg` or `flank_angles` (a list of two), and
    /// every setting of the V-locator (`mu`, `mass_kg`, `load_n`, ...; a range as text).
    pub fn from_keywords(mut kw: Keywords) -> Result<Self> {
        let included = kw.take_number("included_angle_deg")?;
        let flanks = kw.take_numbers("flank_angles")?;
        if included.is_some() && flanks.is_some() {
            return Err(Error::Conflict {
                flag: "flank_angles",
                message: "included_angle_deg and flank_angles both set the V: give a symmetric \
                          V by included_angle_deg or both flanks by flank_angles"
                    .into(),
            });
        }
        let over = kw.into_overrides(
            crate::settings::locator_family(),
            &["included_angle_deg", "flank_angles"],
        )?;
        let mut table = toml::Table::new();
        if let Some(locator) = over.get("locator") {
            table.insert("locator".into(), locator.clone());
        }
        VlocatorQuestion::new(included, flanks.as_deref(), &table)
    }

    /// Values that look like a unit mistake, the answer still given.
    pub fn warnings(&self) -> Vec<String> {
        self.params.unit_warnings()
    }

    /// Answers the question: the V's verdict, or over a box the robust design.
    pub fn answer(&self) -> Result<VlocatorAnswer> {
        let p = &self.params;
        if !self.uncertain.is_empty() {
            let given = self.given_v.then(|| p.included_angle_deg());
            return super::vlocator_robust::answer(p, &self.uncertain, given, self.mass_default)
                .map(VlocatorAnswer::Robust);
        }
        Ok(VlocatorAnswer::Point(PointReport {
            solution: locator::solve(p)?,
            inputs: *p,
            mass_default: self.mass_default,
        }))
    }
}

impl TryFrom<Keywords> for VlocatorQuestion {
    type Error = Error;

    fn try_from(kw: Keywords) -> Result<Self> {
        VlocatorQuestion::from_keywords(kw)
    }
}

/// The answer to a [`VlocatorQuestion`]; its serde form is `jamchart vlocator --format
/// json`'s document.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum VlocatorAnswer {
    /// One V under one load.
    Point(PointReport),
    /// The V that works over a box.
    Robust(super::RobustReport),
}

impl VlocatorAnswer {
    /// The command line's report, in `words`.
    pub fn text(&self, words: Words) -> String {
        match self {
            VlocatorAnswer::Point(r) => r.text(words),
            VlocatorAnswer::Robust(r) => r.text(words),
        }
    }
}

/// One V's answer: the verdict, forces, capacity and optimum, then the inputs.
#[derive(Debug, Clone, Serialize)]
pub struct PointReport {
    /// What the locator model says of the V under the load.
    #[serde(flatten)]
    pub solution: LocatorSolution,
    /// The V, the disc and the load.
    pub inputs: LocatorParams,
    /// The disc's mass is the default 1 kg, not given: the text says so (the document's
    /// `inputs` hold the mass either way).
    #[serde(skip)]
    pub mass_default: bool,
}
