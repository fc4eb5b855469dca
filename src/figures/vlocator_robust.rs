//! The window of included angles of a V-block that holds every load of a range without
//! self-locking at any friction of a range, against the width of the friction range (centred
//! on a nominal friction), with the most robust angle ([`crate::locator::robust`]).
//!
//! A scene gives the friction range it has (`mu = "0.1:0.25"`): the chart is then drawn around
//! it (ranges centred on its midpoint, up to twice its width) and that range is marked with its
//! design and the standard V-blocks' verdicts over its box. The older form, a centre and the
//! widest width (`mu_center`, `width_max`), draws the ranges alone.

use std::fmt;

use rayon::prelude::*;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::{Deserialize, Serialize, Serializer};

use super::vlocator_capacity::STANDARD_V_DEG;
use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::csv_out::{Dec, dec, to_csv};
use crate::error::{Error, Result};
use crate::locator::{
    BoxVerdict, LocatorParams, RobustBox, RobustDesign, robust_design, verdict_over_box,
};
use crate::uncertain::Uncertain;

/// A closed interval [lo, hi] as a scene writes it: a number (a point), a range `"LO:HI"` (as
/// the flags take it) or `[LO, HI]`. It is written back as a number or `"LO:HI"`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// The low end.
    pub lo: f64,
    /// The high end.
    pub hi: f64,
}

impl Interval {
    /// A point: both ends `v`.
    pub fn point(v: f64) -> Self {
        Interval { lo: v, hi: v }
    }

    /// (lo, hi).
    pub fn ends(self) -> (f64, f64) {
        (self.lo, self.hi)
    }

    /// Both ends finite, lo <= hi and lo >= `min`; else the refusal naming `key`.
    fn check(self, key: &str, min: f64, what: &str) -> Result<()> {
        let Interval { lo, hi } = self;
        if lo.is_finite() && hi.is_finite() && min <= lo && lo <= hi {
            return Ok(());
        }
        Err(Error::invalid(
            key,
            self,
            format!("give {what} as a number or a range \"LO:HI\" with {min} <= LO <= HI"),
        ))
    }
}

impl fmt::Display for Interval {
    /// As it is written: `20`, `0.1:0.25`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let t = crate::settings::number_text;
        match self.lo == self.hi {
            true => f.write_str(&t(self.lo)),
            false => write!(f, "{}:{}", t(self.lo), t(self.hi)),
        }
    }
}

impl Serialize for Interval {
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        match self.lo == self.hi {
            true => s.serialize_f64(self.lo),
            false => s.serialize_str(&self.to_string()),
        }
    }
}

impl<'de> Deserialize<'de> for Interval {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Interval;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number, a range \"LO:HI\" or [LO, HI]")
            }

            fn visit_f64<E: de::Error>(self, v: f64) -> std::result::Result<Interval, E> {
                Ok(Interval::point(v))
            }

            fn visit_i64<E: de::Error>(self, v: i64) -> std::result::Result<Interval, E> {
                Ok(Interval::point(v as f64))
            }

            fn visit_u64<E: de::Error>(self, v: u64) -> std::result::Result<Interval, E> {
                Ok(Interval::point(v as f64))
            }

            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Interval, E> {
                match Uncertain::parse(s).map_err(E::custom)? {
                    Uncertain::Point { value } => Ok(Interval::point(value)),
                    Uncertain::Range { lo, hi } => Ok(Interval { lo, hi }),
                    _ => Err(E::custom(format!(
                        "{s} is a distribution; a robust V-block holds every value of a range: \
                         give LO:HI"
                    ))),
                }
            }

            fn visit_seq<A: SeqAccess<'de>>(
                self,
                mut a: A,
            ) -> std::result::Result<Interval, A::Error> {
                let lo = a
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(0, &self))?;
                let hi = a
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(1, &self))?;
                if a.next_element::<f64>()?.is_some() {
                    return Err(de::Error::invalid_length(3, &self));
                }
                Ok(Interval { lo, hi })
            }
        }
        d.deserialize_any(V)
    }
}

/// `[chart]` keys of `kind = "vlocator_robust"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VlocatorRobustSettings {
    /// The V's tilt, rotation, load point and weight (default: [`LocatorParams::default`]);
    /// the included angle is the unknown, the frictions and the load come from the keys below.
    #[serde(default)]
    pub locator: LocatorParams,
    /// The friction range on both flanks, `"LO:HI"` (e.g. `"0.1:0.25"`): the chart draws
    /// ranges centred on its midpoint up to twice its width and marks this one (default:
    /// none; then `mu_center` and `width_max` give the ranges).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu: Option<Interval>,
    /// The nominal friction mu0 the ranges are centred on (both flanks), without `mu`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mu_center: Option<f64>,
    /// The widest friction range drawn: [mu0 - w/2, mu0 + w/2] up to w = `width_max`
    /// (<= 2 mu0, so the range stays >= 0); with `mu`, at least its width (default: twice
    /// its width, within [mu0, 2 mu0]; required without `mu`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub width_max: Option<f64>,
    /// Range widths drawn, from 0 to `width_max` (2 to 201; default: 51).
    #[serde(default = "default_count")]
    pub count: usize,
    /// The load magnitude in N, a number or a range `"LO:HI"`.
    pub load_n: Interval,
    /// The load direction in deg from +x (0 sideways, 90 lifts), a number or a range
    /// `"LO:HI"` at most 360 apart (default: 0).
    #[serde(default = "sideways")]
    pub load_angle_deg: Interval,
}

fn default_count() -> usize {
    51
}

fn sideways() -> Interval {
    Interval::point(0.0)
}

/// Most range widths a chart draws: each is a robust design (a few ms with a direction range).
const MAX_COUNT: usize = 201;

impl Figure for VlocatorRobustSettings {
    type Data = VlocatorRobustData;

    /// The V-block's parameters are `[chart.locator]`'s, not the palm scene's.
    fn takes_scene(&self) -> bool {
        false
    }

    /// The V-block's own, with the friction range and the loads the chart is drawn for (the
    /// locator's frictions and load are not used); the flank angles only for a tilted V (the
    /// included angle is what the chart finds).
    fn parameters(&self, _input: &Input) -> (&'static str, toml::Table) {
        let mut t = toml::Table::try_from(self.locator).unwrap_or_default();
        for k in ["mu_left", "mu_right", "load_n", "load_angle_deg"] {
            t.remove(k);
        }
        if self.locator.flank_left_deg == self.locator.flank_right_deg {
            t.remove("flank_left_deg");
            t.remove("flank_right_deg");
        }
        let mut put = |k: &str, v: toml::Value| t.insert(k.to_string(), v);
        match self.mu {
            Some(mu) => put("mu", mu.to_string().into()),
            None => put("mu_center", self.center().into()),
        };
        put("width_max", self.width_max().into());
        put("load_n", self.load_n.to_string().into());
        put("load_angle_deg", self.load_angle_deg.to_string().into());
        ("V-block", t)
    }

    fn validate(&self, _input: &Input) -> Result<()> {
        self.locator.validate()?;
        match (self.mu, self.mu_center) {
            (Some(mu), None) => {
                mu.check("chart.mu", 0.0, "the friction range")?;
                if mu.hi <= 0.0 {
                    return Err(Error::invalid(
                        "chart.mu",
                        mu,
                        "a friction range reaches above 0: give LO:HI with HI > 0",
                    ));
                }
            }
            (Some(mu), Some(c)) => {
                return Err(Error::invalid(
                    "chart.mu_center",
                    c,
                    format!(
                        "give the friction range once: mu = \"{mu}\" (the ranges are centred on \
                         its midpoint), or mu_center and width_max without mu"
                    ),
                ));
            }
            (None, None) => {
                return Err(Error::invalid(
                    "chart.mu",
                    "none",
                    "give the friction range, e.g. mu = \"0.1:0.25\" (or mu_center and \
                     width_max)",
                ));
            }
            (None, Some(c)) => {
                if !(c.is_finite() && c > 0.0) {
                    return Err(Error::invalid(
                        "chart.mu_center",
                        c,
                        "the nominal friction is a finite number > 0",
                    ));
                }
                if self.width_max.is_none() {
                    return Err(Error::invalid(
                        "chart.width_max",
                        "none",
                        "with mu_center give the widest range drawn, width_max (or give the \
                         range itself, mu = \"LO:HI\")",
                    ));
                }
            }
        }
        let (c, w) = (self.center(), self.width_max());
        if !(w.is_finite() && w > 0.0 && w <= 2.0 * c) {
            return Err(Error::invalid(
                "chart.width_max",
                w,
                format!("give a width in (0, 2 mu_center] = (0, {}]", 2.0 * c),
            ));
        }
        if let Some(mu) = self.mu.filter(|mu| w < mu.hi - mu.lo) {
            return Err(Error::invalid(
                "chart.width_max",
                w,
                format!(
                    "the chart must reach the range's width {}: give at least that",
                    mu.hi - mu.lo
                ),
            ));
        }
        if !(2..=MAX_COUNT).contains(&self.count) {
            return Err(Error::invalid(
                "chart.count",
                self.count,
                format!("draw 2 to {MAX_COUNT} widths"),
            ));
        }
        self.load_n.check("chart.load_n", 0.0, "the load in N")?;
        let a = self.load_angle_deg;
        a.check(
            "chart.load_angle_deg",
            f64::MIN,
            "the load direction in deg",
        )?;
        if a.hi - a.lo > 360.0 {
            return Err(Error::invalid(
                "chart.load_angle_deg",
                a,
                "give a direction range at most 360 deg apart",
            ));
        }
        Ok(())
    }

    fn check_size(&self, _input: &Input) -> Result<()> {
        // `validate` caps the count; the memory is a few numbers per width.
        Ok(())
    }

    /// One robust design per width, in parallel, in index order; the locator's own model, so
    /// nothing goes through `models`.
    fn compute(&self, _input: &Input, _models: &dyn Models) -> Result<VlocatorRobustData> {
        let widths = self.widths();
        let designs = widths
            .par_iter()
            .map(|&w| robust_design(&self.locator, &self.box_of(w)))
            .collect();
        let given = self.mu.map(|mu| {
            let b = self.box_of(mu.hi - mu.lo);
            GivenRange {
                mu_lo: mu.lo,
                mu_hi: mu.hi,
                index: widths.iter().position(|&w| w == mu.hi - mu.lo).unwrap_or(0),
                standard_v_blocks: STANDARD_V_DEG
                    .into_iter()
                    .map(|g| StandardV {
                        included_angle_deg: g,
                        verdict: verdict_over_box(&self.locator, &b, g),
                    })
                    .collect(),
            }
        });
        Ok(VlocatorRobustData {
            settings: self.clone(),
            widths,
            designs,
            given,
        })
    }
}

impl VlocatorRobustSettings {
    /// The friction the ranges are centred on: the midpoint of `mu`, or `mu_center`.
    pub fn center(&self) -> f64 {
        match (self.mu, self.mu_center) {
            (Some(mu), _) => 0.5 * (mu.lo + mu.hi),
            (None, c) => c.unwrap_or(f64::NAN),
        }
    }

    /// The widest range drawn: `width_max`, or twice `mu`'s width (the range given in the
    /// middle of the axis) within [mu0, 2 mu0] (a point friction still gets ranges around it).
    pub fn width_max(&self) -> f64 {
        match (self.width_max, self.mu) {
            (Some(w), _) => w,
            (None, Some(mu)) => {
                let w = mu.hi - mu.lo;
                (2.0 * w).max(self.center()).min(2.0 * self.center())
            }
            (None, None) => f64::NAN,
        }
    }

    /// The widths drawn: `count` from 0 to `width_max`, and the width of `mu` among them.
    pub fn widths(&self) -> Vec<f64> {
        let wmax = self.width_max();
        let mut widths: Vec<f64> = (0..self.count)
            .map(|k| wmax * k as f64 / (self.count - 1) as f64)
            .collect();
        if let Some(mu) = self.mu {
            let w = mu.hi - mu.lo;
            if let Err(i) = widths.binary_search_by(|v| v.total_cmp(&w)) {
                widths.insert(i, w);
            }
        }
        widths
    }

    /// The friction range of width `w` around the centre: `mu`'s own ends at its width.
    pub fn mu_range(&self, w: f64) -> (f64, f64) {
        match self.mu {
            Some(mu) if w == mu.hi - mu.lo => (mu.lo, mu.hi),
            _ => {
                let c = self.center();
                ((c - 0.5 * w).max(0.0), c + 0.5 * w)
            }
        }
    }

    /// The box at friction-range width `w`.
    pub fn box_of(&self, w: f64) -> RobustBox {
        RobustBox::both_flanks(
            &self.locator,
            self.mu_range(w),
            self.load_n.ends(),
            self.load_angle_deg.ends(),
        )
    }
}

/// The computed robust designs, one per friction-range width: the data file is a row per
/// width (its CSV data file).
#[derive(Debug, Clone, Serialize)]
pub struct VlocatorRobustData {
    /// The settings it was computed with.
    pub settings: VlocatorRobustSettings,
    /// The friction-range widths, from 0 to `width_max` (the width of `mu` among them).
    pub widths: Vec<f64>,
    /// The robust design at each width ([`VlocatorRobustSettings::box_of`]).
    pub designs: Vec<RobustDesign>,
    /// The range given (`mu`), marked on the chart.
    pub given: Option<GivenRange>,
}

/// The friction range a scene gives: where it lies among the widths, and what the standard
/// V-blocks do over its box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GivenRange {
    /// Its low end.
    pub mu_lo: f64,
    /// Its high end.
    pub mu_hi: f64,
    /// Its index among the widths (and designs).
    pub index: usize,
    /// The 60, 90 and 120 deg V-blocks over its box.
    pub standard_v_blocks: Vec<StandardV>,
}

/// One standard V-block's verdict over a box.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StandardV {
    /// Its included angle, deg.
    pub included_angle_deg: f64,
    /// What it does over the box.
    pub verdict: BoxVerdict,
}

/// A CSV row: one friction-range width.
#[derive(Serialize)]
struct Row {
    mu_width: Dec,
    mu_lo: Dec,
    mu_hi: Dec,
    lock_bound_deg: Dec,
    window_lo_deg: Option<Dec>,
    window_hi_deg: Option<Dec>,
    robust_deg: Option<Dec>,
    safety_factor: Option<Dec>,
}

impl FigureData for VlocatorRobustData {
    const FORMAT: DataFormat = DataFormat::Csv;

    /// One row per width; empty window cells where no V works (the first window where
    /// there are several).
    fn csv(&self) -> Vec<u8> {
        let rows = self.widths.iter().zip(&self.designs).map(|(&w, d)| {
            let (mu_lo, mu_hi) = self.settings.mu_range(w);
            let win = d.windows.first();
            Row {
                mu_width: Dec(w),
                mu_lo: Dec(mu_lo),
                mu_hi: Dec(mu_hi),
                lock_bound_deg: Dec(d.lock_bound_deg),
                window_lo_deg: dec(win.map(|w| w.0)),
                window_hi_deg: dec(win.map(|w| w.1)),
                robust_deg: dec(d.robust.map(|r| r.included_angle_deg)),
                safety_factor: dec(d.robust.map(|r| r.safety_factor).filter(|r| r.is_finite())),
            }
        });
        to_csv(rows)
    }
}
