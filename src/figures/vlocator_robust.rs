//! The window of included angles of a V-block that holds every load of a range without
//! self-locking at any friction of a range, against the width of the friction range (centred
//! on a nominal friction), with the most robust angle ([`crate::locator::robust`]).

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::{DataFormat, Figure, FigureData, Input, Models};
use crate::csv_out::{Dec, dec, to_csv};
use crate::error::{Error, Result};
use crate::locator::{LocatorParams, RobustBox, RobustDesign, robust_design};

/// `[chart]` keys of `kind = "vlocator_robust"`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VlocatorRobustSettings {
    /// The V's tilt, rotation, load point and weight (default: [`LocatorParams::default`]);
    /// the included angle is the unknown, the frictions and the load come from the keys below.
    #[serde(default)]
    pub locator: LocatorParams,
    /// The nominal friction mu0 the ranges are centred on (both flanks).
    pub mu_center: f64,
    /// The widest friction range drawn: [mu0 - w/2, mu0 + w/2] up to w = `width_max`
    /// (<= 2 mu0, so the range stays >= 0).
    pub width_max: f64,
    /// Range widths drawn, from 0 to `width_max` (2 to 201).
    pub count: usize,
    /// The load magnitude range [lo, hi] in N.
    pub load_n: [f64; 2],
    /// The load direction range [lo, hi] in deg from +x (0 sideways, 90 lifts).
    pub load_angle_deg: [f64; 2],
}

/// Most range widths a chart draws: each is a robust design (a few ms with a direction range).
const MAX_COUNT: usize = 201;

impl Figure for VlocatorRobustSettings {
    type Data = VlocatorRobustData;

    /// The V-block's parameters are `[chart.locator]`'s, not the palm scene's.
    fn takes_scene(&self) -> bool {
        false
    }

    fn validate(&self, _input: &Input) -> Result<()> {
        self.locator.validate()?;
        let (c, w) = (self.mu_center, self.width_max);
        if !(c.is_finite() && c > 0.0) {
            return Err(Error::invalid(
                "chart.mu_center",
                c,
                "the nominal friction is a finite number > 0",
            ));
        }
        if !(w.is_finite() && w > 0.0 && w <= 2.0 * c) {
            return Err(Error::invalid(
                "chart.width_max",
                w,
                format!("give a width in (0, 2 mu_center] = (0, {}]", 2.0 * c),
            ));
        }
        if !(2..=MAX_COUNT).contains(&self.count) {
            return Err(Error::invalid(
                "chart.count",
                self.count,
                format!("draw 2 to {MAX_COUNT} widths"),
            ));
        }
        let [p0, p1] = self.load_n;
        if !(p0.is_finite() && p1.is_finite() && 0.0 <= p0 && p0 <= p1) {
            return Err(Error::invalid(
                "chart.load_n",
                format!("[{p0}, {p1}]"),
                "give [lo, hi] in N with 0 <= lo <= hi",
            ));
        }
        let [a0, a1] = self.load_angle_deg;
        if !(a0.is_finite() && a1.is_finite() && a0 <= a1 && a1 - a0 <= 360.0) {
            return Err(Error::invalid(
                "chart.load_angle_deg",
                format!("[{a0}, {a1}]"),
                "give [lo, hi] in deg with lo <= hi, at most 360 apart",
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
        let widths: Vec<f64> = (0..self.count)
            .map(|k| self.width_max * k as f64 / (self.count - 1) as f64)
            .collect();
        let designs = widths
            .par_iter()
            .map(|&w| robust_design(&self.locator, &self.box_of(w)))
            .collect();
        Ok(VlocatorRobustData {
            settings: self.clone(),
            widths,
            designs,
        })
    }
}

impl VlocatorRobustSettings {
    /// The box at friction-range width `w`.
    pub fn box_of(&self, w: f64) -> RobustBox {
        let c = self.mu_center;
        RobustBox::both_flanks(
            &self.locator,
            ((c - 0.5 * w).max(0.0), c + 0.5 * w),
            (self.load_n[0], self.load_n[1]),
            (self.load_angle_deg[0], self.load_angle_deg[1]),
        )
    }
}

/// The computed robust designs, one per friction-range width: the data file is a row per
/// width (its CSV data file).
#[derive(Debug, Clone, Serialize)]
pub struct VlocatorRobustData {
    /// The settings it was computed with.
    pub settings: VlocatorRobustSettings,
    /// The friction-range widths, from 0 to `width_max`.
    pub widths: Vec<f64>,
    /// The robust design at each width ([`VlocatorRobustSettings::box_of`]).
    pub designs: Vec<RobustDesign>,
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
            let b = self.settings.box_of(w);
            let win = d.windows.first();
            Row {
                mu_width: Dec(w),
                mu_lo: Dec(b.mu_left.0),
                mu_hi: Dec(b.mu_left.1),
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
